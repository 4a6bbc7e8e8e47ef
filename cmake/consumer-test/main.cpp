// Builds against the installed package: a plain user mesh, traits, one generic algorithm.
#include <cstdio>
#include <ranges>
#include <span>
#include <vector>

#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/topology/mesh_topology.hpp>

struct user_mesh {
    std::vector<hmira::vec3<double>> points;
    std::vector<std::vector<int>> faces;
};

template <>
struct hmira::mesh_traits<user_mesh> {
    using vertex_handle = int;
    using face_handle = int;
    using scalar = double;
    static auto vertices(const user_mesh& m) { return std::views::iota(0, int(m.points.size())); }
    static auto faces(const user_mesh& m) { return std::views::iota(0, int(m.faces.size())); }
    static std::size_t vertex_count(const user_mesh& m) { return m.points.size(); }
    static std::size_t face_count(const user_mesh& m) { return m.faces.size(); }
    static std::size_t vertex_index(const user_mesh&, int v) { return std::size_t(v); }
    static std::size_t vertex_index_bound(const user_mesh& m) { return m.points.size(); }
    static std::size_t face_index(const user_mesh&, int f) { return std::size_t(f); }
    static std::size_t face_index_bound(const user_mesh& m) { return m.faces.size(); }
    static std::span<const int> face_vertices(const user_mesh& m, int f) { return m.faces[std::size_t(f)]; }
    static int add_vertex(user_mesh& m, hmira::vec3<double> p) {
        m.points.push_back(p);
        return int(m.points.size()) - 1;
    }
    static hmira::result<int> add_face(user_mesh& m, std::span<const int> vs) {
        m.faces.emplace_back(vs.begin(), vs.end());
        return int(m.faces.size()) - 1;
    }
};

int main() {
    user_mesh m;
    if (!hmira::generate_cube(m)) return 1;
    const auto t = hmira::mesh_topology(m);
    std::printf("consumer: cube through installed hmira: V=%zu E=%zu F=%zu chi=%lld\n", t.vertices, t.edges, t.faces,
                t.euler_characteristic);
    return t.euler_characteristic == 2 ? 0 : 1;
}
