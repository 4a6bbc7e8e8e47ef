// docs/own-mesh.md, "When an operation is missing": traits that forgot `position`. The guide
// quotes g++'s answer; tests/docs/CMakeLists.txt checks the quote against the real output.
#include <hmira/algorithms/geometry/vertex_normals.hpp>

#include <array>
#include <ranges>
#include <span>
#include <vector>

struct my_mesh {
    std::vector<std::array<double, 3>> positions;
    std::vector<std::vector<int>> faces;
};

template <>
struct hmira::mesh_traits<my_mesh> {
    using vertex_handle = int;
    using face_handle = int;
    using scalar = double;
    static auto vertices(const my_mesh& m) { return std::views::iota(0, int(m.positions.size())); }
    static auto faces(const my_mesh& m) { return std::views::iota(0, int(m.faces.size())); }
    static std::size_t vertex_count(const my_mesh& m) { return m.positions.size(); }
    static std::size_t face_count(const my_mesh& m) { return m.faces.size(); }
    static std::size_t vertex_index(const my_mesh&, int v) { return std::size_t(v); }
    static std::size_t vertex_index_bound(const my_mesh& m) { return m.positions.size(); }
    static std::span<const int> face_vertices(const my_mesh& m, int f) { return m.faces[std::size_t(f)]; }
#ifdef HMIRA_SNIPPET_OK
    static hmira::vec3<double> position(const my_mesh& m, int v) {
        const auto& p = m.positions[std::size_t(v)];
        return {p[0], p[1], p[2]};
    }
#endif
};

int main() {
    my_mesh m;
    auto normals = hmira::vertex_normals(m);
    return int(normals.size());
}
