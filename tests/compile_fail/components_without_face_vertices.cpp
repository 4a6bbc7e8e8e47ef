// A mesh that lists faces but cannot say which vertices a face has cannot be split into
// components: the error must name face_vertex_range_mesh and T::face_vertices.
#include <hmira/algorithms/topology/connected_components.hpp>

#include <ranges>
#include <span>
#include <vector>

struct my_mesh {
    std::vector<hmira::vec3<double>> points;
    std::vector<std::vector<int>> faces;
};

template <>
struct hmira::mesh_traits<my_mesh> {
    using vertex_handle = int;
    using face_handle = int;
    using scalar = double;
    static auto vertices(const my_mesh& m) { return std::views::iota(0, int(m.points.size())); }
    static auto faces(const my_mesh& m) { return std::views::iota(0, int(m.faces.size())); }
    static std::size_t vertex_count(const my_mesh& m) { return m.points.size(); }
    static std::size_t face_count(const my_mesh& m) { return m.faces.size(); }
    static std::size_t vertex_index(const my_mesh&, int v) { return std::size_t(v); }
    static std::size_t vertex_index_bound(const my_mesh& m) { return m.points.size(); }
    static std::size_t face_index(const my_mesh&, int f) { return std::size_t(f); }
    static std::size_t face_index_bound(const my_mesh& m) { return m.faces.size(); }
#ifdef HMIRA_SNIPPET_OK
    static std::span<const int> face_vertices(const my_mesh& m, int f) { return m.faces[std::size_t(f)]; }
#endif
};

// The control variant states, as an assertion, that the capability was the only thing missing.
#ifdef HMIRA_SNIPPET_OK
static_assert(hmira::connected_components_mesh<my_mesh>, "with face_vertices supplied components must accept the mesh");
#endif

int main() {
    my_mesh m;
    (void)hmira::connected_components(m);
}
