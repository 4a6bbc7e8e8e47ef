// mesh_bounds, surface_area and signed_volume on every model, against values worked out by hand:
// the [-1, 1]^3 cube (quads), the octahedron and the regular tetrahedron, their mirror images by flip_normals,
// the volume's independence of where a closed mesh sits, and the empty mesh.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/geometry/mesh_measures.hpp>
#include <hmira/algorithms/orientation/flip_normals.hpp>

#include "support/models.hpp"

namespace {

using namespace hmira;

template <class M>
class mesh_measures_suite : public ::testing::Test {};
TYPED_TEST_SUITE(mesh_measures_suite, hmira_test::all_models);

template <class M>
double tol() {
    return std::max(1e-12, 64.0 * double(std::numeric_limits<typename default_traits<M>::scalar>::epsilon()));
}

TYPED_TEST(mesh_measures_suite, octahedron_has_area_4_sqrt_3_volume_4_thirds_and_box_minus_one_to_one) {
    TypeParam m;
    ASSERT_TRUE(generate_octahedron(m));
    EXPECT_NEAR(surface_area(m), 4 * std::sqrt(3.0), 8 * tol<TypeParam>());
    EXPECT_NEAR(signed_volume(m), 4.0 / 3.0, 2 * tol<TypeParam>());
    const auto box = mesh_bounds(m);
    ASSERT_TRUE(box);
    EXPECT_EQ(box->min.x, -1.0);
    EXPECT_EQ(box->max.z, 1.0);
}

TYPED_TEST(mesh_measures_suite, cube_has_area_24_volume_8_and_box_minus_one_to_one) {
    if constexpr (polygon_mesh_builder<TypeParam>) {
        TypeParam m;
        ASSERT_TRUE(generate_cube(m));
        EXPECT_NEAR(surface_area(m), 24.0, 24 * tol<TypeParam>());
        EXPECT_NEAR(signed_volume(m), 8.0, 8 * tol<TypeParam>());
        const auto box = mesh_bounds(m);
        ASSERT_TRUE(box);
        EXPECT_EQ(box->min.x, -1.0);
        EXPECT_EQ(box->min.y, -1.0);
        EXPECT_EQ(box->min.z, -1.0);
        EXPECT_EQ(box->max.x, 1.0);
        EXPECT_EQ(box->max.y, 1.0);
        EXPECT_EQ(box->max.z, 1.0);
    } else {
        GTEST_SKIP() << "a triangles-only model: the octahedron case covers it";
    }
}

TYPED_TEST(mesh_measures_suite, flipping_negates_the_volume_and_keeps_the_area) {
    TypeParam m;
    ASSERT_TRUE(generate_tetrahedron(m));
    // The tetrahedron (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1): edge 2 sqrt 2, volume 8/3.
    const double edge = 2 * std::sqrt(2.0);
    EXPECT_NEAR(signed_volume(m), 8.0 / 3.0, tol<TypeParam>());
    EXPECT_NEAR(surface_area(m), std::sqrt(3.0) * edge * edge, 10 * tol<TypeParam>());
    flip_normals(m);
    EXPECT_NEAR(signed_volume(m), -8.0 / 3.0, tol<TypeParam>());
    EXPECT_NEAR(surface_area(m), std::sqrt(3.0) * edge * edge, 10 * tol<TypeParam>());
}

TYPED_TEST(mesh_measures_suite, a_closed_mesh_moved_away_from_the_origin_keeps_its_volume) {
    TypeParam m;
    ASSERT_TRUE(generate_octahedron(m, {.center = {5.0, -3.0, 7.0}}));
    EXPECT_NEAR(signed_volume(m), 4.0 / 3.0, 1e-5);
}

TYPED_TEST(mesh_measures_suite, empty_mesh_has_no_box_and_zero_measures) {
    TypeParam m;
    EXPECT_FALSE(mesh_bounds(m));
    EXPECT_EQ(surface_area(m), 0.0);
    EXPECT_EQ(signed_volume(m), 0.0);
}

}  // namespace
