// vertex_normals on every model: flat patches give the plane's normal, symmetric solids give
// radial normals, the two weightings agree with sums worked out here by hand, flipping the
// mesh negates every normal, and vertices without faces get the zero vector.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/geometry/vertex_normals.hpp>
#include <hmira/algorithms/orientation/flip_normals.hpp>

#include "support/checks.hpp"
#include "support/models.hpp"
#include "support/shapes.hpp"

namespace {

using namespace hmira;

template <class M>
class vertex_normals_suite : public ::testing::Test {};
TYPED_TEST_SUITE(vertex_normals_suite, hmira_test::all_models);

constexpr normal_weighting both_weightings[] = {normal_weighting::area, normal_weighting::angle};

::testing::AssertionResult near(const vec3<double>& got, const vec3<double>& want, double tol = 1e-9) {
    if (std::abs(got.x - want.x) <= tol && std::abs(got.y - want.y) <= tol && std::abs(got.z - want.z) <= tol)
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "got (" << got.x << ", " << got.y << ", " << got.z << "), want (" << want.x
                                         << ", " << want.y << ", " << want.z << ")";
}

// Answers are computed in the model's scalar: OpenMesh's meshes use float.
template <class M>
double tol() {
    return std::max(1e-9, 200.0 * double(std::numeric_limits<typename default_traits<M>::scalar>::epsilon()));
}

template <class P>
vec3<double> to_double(const P& p) {
    return {double(p.x), double(p.y), double(p.z)};
}

TYPED_TEST(vertex_normals_suite, every_vertex_of_a_flat_patch_wound_up_gets_plus_z) {
    using M = TypeParam;
    using T = default_traits<M>;
    if constexpr (!vertex_normals_mesh<M>) {
        GTEST_SKIP() << "model lacks face lists, positions or vertex indices";
    } else {
        std::vector<hmira_test::face_list> patches{hmira_test::grid(5, 4, true)};
        if constexpr (polygon_mesh_builder<M>) patches.push_back(hmira_test::grid(5, 4, false));
        for (const auto& patch : patches) {
            M mesh;
            ASSERT_TRUE(hmira_test::add_face_list(mesh, patch));
            ASSERT_TRUE(hmira_test::is_valid(mesh));
            for (auto w : both_weightings) {
                const auto n = vertex_normals(mesh, {.weighting = w});
                ASSERT_EQ(n.size(), T::vertex_index_bound(mesh));
                for (auto v : T::vertices(mesh))
                    EXPECT_TRUE(near(to_double(n[T::vertex_index(mesh, v)]), {0, 0, 1}, tol<M>()));
            }
        }
    }
}

TYPED_TEST(vertex_normals_suite, normals_of_a_centred_regular_solid_point_away_from_the_centre) {
    using M = TypeParam;
    using T = default_traits<M>;
    if constexpr (!vertex_normals_mesh<M> || !mesh_builder<M>) {
        GTEST_SKIP() << "model cannot be built or lacks what vertex_normals needs";
    } else {
        M ico, octa;
        ASSERT_TRUE(generate_icosahedron(ico));
        ASSERT_TRUE(generate_octahedron(octa));
        for (const M* mesh : {&ico, &octa}) {
            ASSERT_TRUE(hmira_test::is_valid(*mesh));
            for (auto w : both_weightings) {
                const auto n = vertex_normals(*mesh, {.weighting = w});
                // Every vertex of a regular solid sees the same ring of faces, so by symmetry its
                // normal is its own direction from the centre.
                for (auto v : T::vertices(*mesh))
                    EXPECT_TRUE(near(to_double(n[T::vertex_index(*mesh, v)]),
                                     normalized(to_double(T::position(*mesh, v))), tol<M>()));
            }
        }
    }
}

// Two faces meet at vertex o along the edge o-c: A = (o, a, c) lies in z = 0 (area 1/2, unit
// normal +z, right angle at o) and B = (o, c, b) lies in x = 0 (area 1, unit normal -x, right
// angle at o). By hand: area-weighted sum at o is (-1, 0, 1/2), angle-weighted is
// (pi/2)(-1, 0, 1), and the unshared corners a and b see one face each.
TYPED_TEST(vertex_normals_suite, weighted_sums_match_a_hand_computed_hinge) {
    using M = TypeParam;
    using T = default_traits<M>;
    if constexpr (!vertex_normals_mesh<M>) {
        GTEST_SKIP() << "model lacks face lists, positions or vertex indices";
    } else {
        hmira_test::face_list hinge{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -2}}, {{0, 1, 2}, {0, 2, 3}}};
        M mesh;
        std::vector<typename T::vertex_handle> v;
        ASSERT_TRUE(hmira_test::add_face_list(mesh, hinge, &v));
        ASSERT_TRUE(hmira_test::is_valid(mesh));
        auto at = [&](const auto& normals, std::size_t i) { return to_double(normals[T::vertex_index(mesh, v[i])]); };
        const double half_pi = std::numbers::pi / 2;

        const auto area = vertex_normals(mesh, {.weighting = normal_weighting::area, .normalize = false});
        EXPECT_TRUE(near(at(area, 0), {-1, 0, 0.5}, tol<M>()));
        EXPECT_TRUE(near(at(area, 1), {0, 0, 0.5}, tol<M>()));
        EXPECT_TRUE(near(at(area, 3), {-1, 0, 0}, tol<M>()));
        EXPECT_TRUE(near(at(area, 2), {-1, 0, 0.5}, tol<M>()));

        const auto angle = vertex_normals(mesh, {.weighting = normal_weighting::angle, .normalize = false});
        EXPECT_TRUE(near(at(angle, 0), {-half_pi, 0, half_pi}, tol<M>()));
        // At a = (1,0,0) the corner of A is 45 degrees; at b = (0,0,-2) the corner of B is atan(1/2).
        EXPECT_TRUE(near(at(angle, 1), {0, 0, std::numbers::pi / 4}, tol<M>()));
        EXPECT_TRUE(near(at(angle, 3), {-std::atan(0.5), 0, 0}, tol<M>()));

        const auto unit = vertex_normals(mesh, {.weighting = normal_weighting::area});
        EXPECT_TRUE(near(at(unit, 0), vec3<double>{-1, 0, 0.5} / std::sqrt(1.25), tol<M>()));
        EXPECT_TRUE(near(to_double(vertex_normals(mesh)[T::vertex_index(mesh, v[0])]),
                         vec3<double>{-1, 0, 1} / std::sqrt(2.0), tol<M>()));
    }
}

// The angle weighting must count a reflex corner of a concave polygon as more than pi: an
// L-shaped hexagon in z = 0 is flat, so every corner must still get +z with full weight.
TYPED_TEST(vertex_normals_suite, a_concave_polygon_gives_its_reflex_corner_an_angle_above_pi) {
    using M = TypeParam;
    using T = default_traits<M>;
    if constexpr (!vertex_normals_mesh<M> || !polygon_mesh_builder<M>) {
        GTEST_SKIP() << "model cannot hold a hexagon or lacks what vertex_normals needs";
    } else {
        hmira_test::face_list ell{{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}},
                                  {{0, 1, 2, 3, 4, 5}}};
        M mesh;
        std::vector<typename T::vertex_handle> v;
        ASSERT_TRUE(hmira_test::add_face_list(mesh, ell, &v));
        ASSERT_TRUE(hmira_test::is_valid(mesh));
        const auto n = vertex_normals(mesh, {.weighting = normal_weighting::angle, .normalize = false});
        EXPECT_TRUE(near(to_double(n[T::vertex_index(mesh, v[3])]), {0, 0, 1.5 * std::numbers::pi}, tol<M>()));
        EXPECT_TRUE(near(to_double(n[T::vertex_index(mesh, v[0])]), {0, 0, std::numbers::pi / 2}, tol<M>()));
    }
}

TYPED_TEST(vertex_normals_suite, flipping_the_mesh_negates_every_vertex_normal) {
    using M = TypeParam;
    using T = default_traits<M>;
    if constexpr (!vertex_normals_mesh<M> || !flip_normals_mesh<M> || !mesh_builder<M>) {
        GTEST_SKIP() << "model cannot flip or lacks what vertex_normals needs";
    } else {
        M mesh;
        auto patch = hmira_test::without_faces(hmira_test::grid(6, 5, true), [](std::size_t f) { return f == 17; });
        for (auto& p : patch.points) p.z = 0.1 * p.x * p.x - 0.2 * p.y;  // curved, so normals differ
        ASSERT_TRUE(hmira_test::add_face_list(mesh, patch));
        ASSERT_TRUE(generate_icosahedron(mesh, {.center = {20, 0, 0}}));
        for (auto w : both_weightings) {
            const auto before = vertex_normals(mesh, {.weighting = w});
            flip_normals(mesh);
            ASSERT_TRUE(hmira_test::is_valid(mesh));
            const auto after = vertex_normals(mesh, {.weighting = w});
            for (auto v : T::vertices(mesh)) {
                const auto i = T::vertex_index(mesh, v);
                EXPECT_TRUE(near(to_double(after[i]), -to_double(before[i]), 10 * tol<M>()));
            }
            flip_normals(mesh);
            ASSERT_TRUE(hmira_test::is_valid(mesh));
        }
    }
}

TYPED_TEST(vertex_normals_suite, a_vertex_without_faces_gets_the_zero_vector_not_nan) {
    using M = TypeParam;
    using T = default_traits<M>;
    if constexpr (!vertex_normals_mesh<M> || !mesh_builder<M>) {
        GTEST_SKIP() << "model cannot be built or lacks what vertex_normals needs";
    } else {
        M mesh;
        ASSERT_TRUE(generate_octahedron(mesh));
        const auto lonely = T::add_vertex(mesh, {5, 5, 5});
        ASSERT_TRUE(hmira_test::is_valid(mesh, {.relaxed = true}));
        for (auto w : both_weightings) {
            const auto n = vertex_normals(mesh, {.weighting = w});
            EXPECT_TRUE(near(to_double(n[T::vertex_index(mesh, lonely)]), {0, 0, 0}, 0.0));
            for (auto v : T::vertices(mesh)) {
                if (v == lonely) continue;
                EXPECT_NEAR(norm(to_double(n[T::vertex_index(mesh, v)])), 1.0, tol<M>());
            }
        }
    }
}

}  // namespace
