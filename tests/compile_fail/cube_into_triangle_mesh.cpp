// A triangle-only model cannot hold the cube's quads: generate_cube must be rejected at
// compile time, naming polygon_mesh_builder and triangles_only.
#include <hmira/algorithms/generators/platonic_solids.hpp>

#include <array>
#include <span>
#include <vector>

struct my_triangle_mesh {
    std::vector<hmira::vec3<double>> points;
    std::vector<std::array<int, 3>> triangles;
};

template <>
struct hmira::mesh_traits<my_triangle_mesh> {
    using vertex_handle = int;
    using face_handle = int;
    using scalar = double;
#ifndef HMIRA_SNIPPET_OK
    static constexpr bool triangles_only = true;
#endif
    static int add_vertex(my_triangle_mesh& m, hmira::vec3<double> p) {
        m.points.push_back(p);
        return int(m.points.size()) - 1;
    }
    static hmira::result<int> add_face(my_triangle_mesh& m, std::span<const int> vs) {
        if (vs.size() != 3) return hmira::fail(hmira::errc::unsupported, "triangles only");
        m.triangles.push_back({vs[0], vs[1], vs[2]});
        return int(m.triangles.size()) - 1;
    }
};

// The control variant states, as an assertion, that the capability was the only thing missing.
#ifdef HMIRA_SNIPPET_OK
static_assert(hmira::polygon_mesh_builder<my_triangle_mesh>, "without triangles_only the mesh must take polygons");
#endif

int main() {
    my_triangle_mesh m;
    (void)hmira::generate_tetrahedron(m);  // triangles: fine
    (void)hmira::generate_cube(m);         // quads: rejected
}
