// A face-list mesh that can neither reverse a face nor re-link halfedges cannot be flipped:
// the error must name flip_normals_mesh and the missing face_reversible_mesh capability.
#include <hmira/algorithms/orientation/flip_normals.hpp>

#include <algorithm>
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
    static std::span<const int> face_vertices(const my_mesh& m, int f) { return m.faces[std::size_t(f)]; }
#ifdef HMIRA_SNIPPET_OK
    static void reverse_face(my_mesh& m, int f) { std::ranges::reverse(m.faces[std::size_t(f)]); }
#endif
};

// The control variant states, as an assertion, that the capability was the only thing missing.
#ifdef HMIRA_SNIPPET_OK
static_assert(hmira::flip_normals_mesh<my_mesh>, "with reverse_face supplied the mesh must be flippable");
#endif

int main() {
    my_mesh m;
    hmira::flip_normals(m);
}
