// examples/plain_struct_mesh/main.cpp
// docs/own-mesh.md, part 1: hmira's algorithms on a struct of two vectors. Every step checks
// its answer against geometry worked out here, and the program exits non-zero if one is wrong,
// so CI running it is a test.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include <hmira/adapters/adapted_mesh.hpp>
#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/geometry/vertex_normals.hpp>
#include <hmira/algorithms/orientation/flip_normals.hpp>
#include <hmira/algorithms/topology/mesh_topology.hpp>
#include <hmira/algorithms/validation/validate.hpp>

#include "plain_mesh.hpp"

namespace {

int failures = 0;

void check(bool ok, const char* what) {
    std::printf("  [%s] %s\n", ok ? " ok " : "FAIL", what);
    if (!ok) ++failures;
}

// [capabilities]
// What the traits above give, checked by the compiler.
using studio::plain_mesh;
static_assert(hmira::mesh_builder<plain_mesh>);
static_assert(hmira::face_vertex_range_mesh<plain_mesh>);
static_assert(hmira::positioned_mesh<plain_mesh>);
static_assert(hmira::vertex_index_mesh<plain_mesh> && hmira::face_index_mesh<plain_mesh>);
static_assert(hmira::face_reversible_mesh<plain_mesh>);
// What a plain struct does not have: adjacency, and a change counter for indexed adapters.
static_assert(!hmira::vertex_adjacency_mesh<plain_mesh>);
static_assert(!hmira::change_counted_mesh<plain_mesh>);
// The brute-force adapters need only face lists and indices, so they fill the gap.
static_assert(hmira::vertex_adjacency_mesh<hmira::with_brute_force_adjacency<plain_mesh>>);
static_assert(hmira::face_adjacency_mesh<hmira::with_brute_force_adjacency<plain_mesh>>);
// [capabilities]

}  // namespace

int main() {
    // [use]
    studio::plain_mesh mesh;
    auto cube = hmira::generate_cube(mesh);  // writes into your vectors
    if (!cube) {
        std::printf("generate_cube failed: %s\n", cube.error().message.c_str());
        return 1;
    }
    const auto problems = hmira::validate(mesh);
    const auto topo = hmira::mesh_topology(mesh);
    const auto normals = hmira::vertex_normals(mesh);  // indexed by vertex index
    // [use]

    std::printf("plain_struct_mesh: %zu positions, %zu faces\n", mesh.positions.size(), mesh.faces.size());
    check(problems.empty(), "validate() finds no problem");
    std::printf("  V=%zu E=%zu F=%zu chi=%lld genus=%lld\n", topo.vertices, topo.edges, topo.faces,
                topo.euler_characteristic, topo.genus);
    check(topo.vertices == 8 && topo.edges == 12 && topo.faces == 6, "a cube has 8 vertices, 12 edges, 6 faces");
    check(topo.euler_characteristic == 2 && topo.closed(), "a cube is a closed sphere (chi = 2)");

    // A cube corner's normal points along its diagonal, away from the centre.
    bool diagonal = true;
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const auto& p = mesh.positions[v];
        const double s = 1 / std::sqrt(3.0);
        diagonal &= std::abs(normals[v].x - p[0] * s) < 1e-12 && std::abs(normals[v].y - p[1] * s) < 1e-12 &&
                    std::abs(normals[v].z - p[2] * s) < 1e-12;
    }
    check(diagonal, "vertex_normals(): each corner's normal is its diagonal");

    hmira::flip_normals(mesh);  // through your reverse_face
    const auto flipped = hmira::vertex_normals(mesh);
    check(hmira::validate(mesh).empty() && std::abs(flipped[0].x + normals[0].x) < 1e-12,
          "flip_normals() reverses every face; normals turn inward");
    hmira::flip_normals(mesh);

    // [adapt]
    // The struct stores no adjacency; a brute-force adapter scans the faces on each query.
    const auto adapted = hmira::adapt_brute_force(mesh);
    using A = hmira::default_traits<decltype(adapted)>;
    std::vector<int> around_0;
    for (int w : A::adjacent_vertices(adapted, 0)) around_0.push_back(w);
    // [adapt]
    std::printf("  neighbours of vertex 0:");
    for (int w : around_0) std::printf(" %d", w);
    std::printf("\n");
    // Vertex 0 is A = (-1,-1,-1); its neighbours differ from it in exactly one coordinate.
    bool one_axis = around_0.size() == 3;
    for (int w : around_0) {
        int differ = 0;
        for (int k = 0; k < 3; ++k) differ += mesh.positions[static_cast<std::size_t>(w)][k] != mesh.positions[0][k];
        one_axis &= differ == 1;
    }
    check(one_axis, "adapt_brute_force(): a cube corner has the 3 neighbours one edge away");

    std::printf("%s\n", failures == 0 ? "all checks passed" : "SOME CHECKS FAILED");
    return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
