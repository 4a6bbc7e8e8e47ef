// validate keeps per-vertex scratch data in arrays, so it needs dense vertex indices: the
// error must name vertex_index_mesh and T::vertex_index.
#include <hmira/algorithms/validation/validate.hpp>

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
    static std::size_t face_index(const my_mesh&, int f) { return std::size_t(f); }
    static std::size_t face_index_bound(const my_mesh& m) { return m.faces.size(); }
    static std::span<const int> face_vertices(const my_mesh& m, int f) { return m.faces[std::size_t(f)]; }
#ifdef HMIRA_SNIPPET_OK
    static std::size_t vertex_index(const my_mesh&, int v) { return std::size_t(v); }
    static std::size_t vertex_index_bound(const my_mesh& m) { return m.points.size(); }
#endif
};

// The control variant states, as an assertion, that the capability was the only thing missing.
#ifdef HMIRA_SNIPPET_OK
static_assert(hmira::validate_mesh<my_mesh>, "with vertex indices supplied validate must accept the mesh");
#endif

int main() {
    my_mesh m;
    (void)hmira::validate(m);
}
