// newell_normal, face_area_vector and sharp_edges: the one definition of a face's normal and of
// a sharp edge that bevel, the CLI and Python share, checked on solids whose angles are known.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <hmira/algorithms/generators/grid.hpp>
#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/geometry/face_normal.hpp>
#include <hmira/algorithms/geometry/sharp_edges.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "support/models.hpp"

namespace {

using hmira::vec3;

TEST(face_normal, newell_normal_is_twice_the_area_along_the_normal_for_any_degree) {
    // A planar L-shaped hexagon in z = 3 (area 3), counter-clockwise seen from +z.
    const std::vector<vec3<double>> l{{0, 0, 3}, {2, 0, 3}, {2, 1, 3}, {1, 1, 3}, {1, 2, 3}, {0, 2, 3}};
    EXPECT_EQ(hmira::newell_normal(l), (vec3<double>{0, 0, 6}));
    std::vector<vec3<double>> reversed(l.rbegin(), l.rend());
    EXPECT_EQ(hmira::newell_normal(reversed), (vec3<double>{0, 0, -6}));
    // In float it stays float.
    const std::vector<vec3<float>> tri{{0, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const vec3<float> n = hmira::newell_normal(tri);
    EXPECT_EQ(n, (vec3<float>{1, 0, 0}));
}

TEST(face_normal, the_area_vector_of_every_cube_face_has_length_twice_its_area_and_they_cancel) {
    hmira::halfedge_mesh m;
    ASSERT_TRUE(hmira::generate_cube(m));
    double lo = 0, hi = 0;
    for (auto v : m.vertices()) lo = std::min(lo, m.position(v).x), hi = std::max(hi, m.position(v).x);
    const double side = hi - lo;
    ASSERT_GT(side, 0);
    vec3<double> sum{};
    for (auto f : m.faces()) {
        const auto a = hmira::face_area_vector(m, f);
        EXPECT_DOUBLE_EQ(hmira::norm(a), 2 * side * side);
        sum += a;
    }
    EXPECT_EQ(sum, (vec3<double>{0, 0, 0}));  // a closed surface's area vectors cancel
}

TEST(sharp_edges, a_cube_is_sharp_up_to_ninety_degrees_and_an_octahedron_up_to_its_normal_angle) {
    hmira::halfedge_mesh cube, octa;
    ASSERT_TRUE(hmira::generate_cube(cube));
    ASSERT_TRUE(hmira::generate_octahedron(octa));
    EXPECT_EQ(hmira::sharp_edges(cube, 0).size(), 12u);
    EXPECT_EQ(hmira::sharp_edges(cube, 45).size(), 12u);
    EXPECT_EQ(hmira::sharp_edges(cube, 90).size(), 12u);
    EXPECT_EQ(hmira::sharp_edges(cube, 90.001).size(), 0u);
    // The octahedron's dihedral angle is acos(-1/3) = 109.47 degrees, so adjacent normals are
    // 180 - 109.47 = 70.53 degrees apart.
    const double between = 180.0 - std::acos(-1.0 / 3.0) * 180.0 / 3.14159265358979323846;
    EXPECT_EQ(hmira::sharp_edges(octa, between - 0.01).size(), 12u);
    EXPECT_EQ(hmira::sharp_edges(octa, between + 0.01).size(), 0u);
}

TEST(sharp_edges, boundary_edges_are_never_selected_and_flat_ones_only_at_zero) {
    hmira::halfedge_mesh g;
    ASSERT_TRUE(hmira::generate_grid(g, {.columns = 3, .rows = 2}));
    std::size_t interior = 0;
    for (auto e : g.edges()) interior += g.is_boundary(e) ? 0 : 1;
    ASSERT_GT(interior, 0u);
    EXPECT_EQ(hmira::sharp_edges(g, 0).size(), interior);
    EXPECT_EQ(hmira::sharp_edges(g, 1).size(), 0u);
}

}  // namespace
