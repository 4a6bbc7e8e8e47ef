// sqrt3_subdivide on every model that supports the triangle operators: the counts per level,
// valences (old keep theirs, new interior ones have 6), the genus, the octahedron's and a
// single triangle's positions worked out here by hand from Kobbelt's rules, the boundary
// trisected every second level, and refusals that leave the mesh unchanged.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/subdivision/loop.hpp>
#include <hmira/algorithms/subdivision/sqrt3.hpp>

#include "algorithms/subdivision/subdivision_support.hpp"
#include "algorithms/triangle/triangle_support.hpp"

namespace {

using namespace hmira_test;

template <class M>
class sqrt3_test : public ::testing::Test {};
TYPED_TEST_SUITE(sqrt3_test, all_models);

template <class M, class T = hmira::default_traits<M>>
double tolerance() {
    return std::is_same_v<typename T::scalar, double> ? 1e-12 : 1e-5;
}

template <class M, class T = hmira::default_traits<M>>
long long boundary_edges(const M& m) {
    long long n = 0;
    for (auto e : T::edges(m)) {
        const auto h = T::edge_halfedge(m, e);
        n += (T::face(m, h) == T::null_face()) != (T::face(m, T::opposite(m, h)) == T::null_face());
    }
    return n;
}

/// Whether some vertex of the mesh lies within `tol` of p.
template <class M, class T = hmira::default_traits<M>>
bool has_vertex_at(const M& m, hmira::vec3<double> p, double tol) {
    for (auto v : T::vertices(m)) {
        const auto q = T::position(m, v);
        if (std::abs(q[0] - p.x) <= tol && std::abs(q[1] - p.y) <= tol && std::abs(q[2] - p.z) <= tol) return true;
    }
    return false;
}

template <class M, class T = hmira::default_traits<M>>
std::vector<std::array<double, 3>> positions_of(const M& m) {
    std::vector<std::array<double, 3>> out;
    for (auto v : T::vertices(m)) {
        const auto p = T::position(m, v);
        out.push_back({double(p[0]), double(p[1]), double(p[2])});
    }
    return out;
}

TYPED_TEST(sqrt3_test, one_level_on_the_octahedron_gives_kobbelts_positions_counts_and_valences) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        M m;
        ASSERT_TRUE(hmira::generate_octahedron(m));
        std::vector<typename T::vertex_handle> old;
        for (auto v : T::vertices(m)) old.push_back(v);
        auto r = hmira::sqrt3_subdivide(m);
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(valid_topology(m));
        EXPECT_EQ(T::vertex_count(m), 14u);
        EXPECT_EQ(T::edge_count(m), 36u);
        EXPECT_EQ(T::face_count(m), 24u);
        EXPECT_EQ(r->faces, 24u);
        EXPECT_EQ(chi(m), 2);
        // Valence 4: alpha = (4 - 2 cos(pi / 2)) / 9 = 4/9, and the neighbours of an axis
        // point sum to zero, so it moves to 5/9 of itself. New vertices are face centroids.
        for (auto v : T::vertices(m)) {
            const bool is_old = std::find(old.begin(), old.end(), v) != old.end();
            EXPECT_EQ(valence(m, v), is_old ? 4u : 6u);
            const auto p = T::position(m, v);
            std::array<double, 3> a{std::abs(double(p[0])), std::abs(double(p[1])), std::abs(double(p[2]))};
            std::sort(a.begin(), a.end());
            if (is_old) {
                EXPECT_NEAR(a[0], 0, tolerance<M>());
                EXPECT_NEAR(a[1], 0, tolerance<M>());
                EXPECT_NEAR(a[2], 5.0 / 9, tolerance<M>());
            } else {
                for (double c : a) EXPECT_NEAR(c, 1.0 / 3, tolerance<M>());
            }
        }
    }
}

TYPED_TEST(sqrt3_test, levels_triple_the_faces_on_a_torus_and_keep_the_genus) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        M m = mesh_from<M>(triangulated(torus(8, 6)));
        for (int level = 0; level < 3; ++level) {
            const long long v = (long long)T::vertex_count(m), e = (long long)T::edge_count(m),
                            f = (long long)T::face_count(m);
            auto r = hmira::sqrt3_subdivide(m);
            ASSERT_TRUE(r) << r.error().message;
            EXPECT_EQ((long long)T::vertex_count(m), v + f);
            EXPECT_EQ((long long)T::edge_count(m), e + 3 * f);
            EXPECT_EQ((long long)T::face_count(m), 3 * f);
            EXPECT_EQ(chi(m), 0);
            ASSERT_TRUE(valid_topology(m)) << "level " << level + 1;
        }
    }
}

TYPED_TEST(sqrt3_test, two_levels_turn_one_triangle_into_nine_on_the_ternary_b_spline) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        // a = (0, 0), b = (27, 0), c = (0, 27): every point of the two levels is an integer.
        M m = mesh_from<M>(face_list{{{0, 0, 0}, {27, 0, 0}, {0, 27, 0}}, {{0, 1, 2}}});
        auto one = hmira::sqrt3_subdivide(m);
        ASSERT_TRUE(one) << one.error().message;
        ASSERT_TRUE(valid_topology(m));
        // The first level leaves the boundary alone: the corners stay, the centroid joins them.
        EXPECT_EQ(T::vertex_count(m), 4u);
        EXPECT_EQ(T::face_count(m), 3u);
        EXPECT_TRUE(has_vertex_at(m, {0, 0, 0}, 0));
        EXPECT_TRUE(has_vertex_at(m, {9, 9, 0}, tolerance<M>()));

        M twice = mesh_from<M>(face_list{{{0, 0, 0}, {27, 0, 0}, {0, 27, 0}}, {{0, 1, 2}}});
        auto two = hmira::sqrt3_subdivide(twice, {.levels = 2});
        ASSERT_TRUE(two) << two.error().message;
        ASSERT_TRUE(valid_topology(twice));
        EXPECT_EQ(T::vertex_count(twice), 10u);
        EXPECT_EQ(T::edge_count(twice), 18u);
        EXPECT_EQ(T::face_count(twice), 9u);
        EXPECT_EQ(boundary_edges(twice), 9);
        // Corners: (4 u + 19 p + 4 z) / 27. Edge points: (u + 16 a + 10 b) / 27 and
        // (10 a + 16 b + z) / 27. The centroid, of valence 3, is the average of its ring.
        const std::array<hmira::vec3<double>, 10> expected{{{4, 4, 0},
                                                            {19, 4, 0},
                                                            {4, 19, 0},
                                                            {9, 9, 0},
                                                            {10, 1, 0},
                                                            {16, 1, 0},
                                                            {16, 10, 0},
                                                            {10, 16, 0},
                                                            {1, 16, 0},
                                                            {1, 10, 0}}};
        for (const auto& p : expected) EXPECT_TRUE(has_vertex_at(twice, p, 1e-4)) << p.x << ", " << p.y;
        // Each corner keeps one triangle (valence 2), as in a 1-to-9 split; none is folded.
        for (auto v : T::vertices(twice)) {
            const auto p = T::position(twice, v);
            if ((std::abs(p[0] - 4) < 1e-4 && std::abs(p[1] - 4) < 1e-4) || std::abs(p[0] - 19) < 1e-4 ||
                std::abs(p[1] - 19) < 1e-4) {
                EXPECT_EQ(valence(twice, v), 2u) << double(p[0]) << ", " << double(p[1]);
            }
        }
        for (auto f : T::faces(twice)) {
            std::vector<hmira::vec3<double>> c;
            for (auto v : T::face_vertices(twice, f)) {
                const auto p = T::position(twice, v);
                c.push_back({double(p[0]), double(p[1]), double(p[2])});
            }
            ASSERT_EQ(c.size(), 3u);
            EXPECT_GT((c[1].x - c[0].x) * (c[2].y - c[0].y) - (c[1].y - c[0].y) * (c[2].x - c[0].x), 0.5);
        }
    }
}

TYPED_TEST(sqrt3_test, a_flat_grid_stays_flat_and_two_levels_trisect_its_boundary) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        M m = mesh_from<M>(grid(4, 3, true));
        const long long f = (long long)T::face_count(m), b = boundary_edges(m);
        auto r = hmira::sqrt3_subdivide(m, {.levels = 2});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(valid_topology(m));
        EXPECT_EQ(chi(m), 1);
        EXPECT_EQ((long long)T::face_count(m), 9 * f);
        EXPECT_EQ(boundary_edges(m), 3 * b);
        for (auto v : T::vertices(m)) {
            const auto p = T::position(m, v);
            EXPECT_EQ(double(p[2]), 0.0);
            EXPECT_TRUE(p[0] >= 0 && p[0] <= 4 && p[1] >= 0 && p[1] <= 3) << double(p[0]) << ", " << double(p[1]);
            // Away from the corners the cubic B-spline of a straight side is that side.
            const auto s = T::vertex_halfedge(m, v);
            if (T::face(m, s) != T::null_face()) continue;
            if (p[0] >= 1 && p[0] <= 3) {
                EXPECT_TRUE(p[1] == 0 || p[1] == 3) << double(p[0]) << ", " << double(p[1]);
            }
            if (p[1] >= 1 && p[1] <= 2) {
                EXPECT_TRUE(p[0] == 0 || p[0] == 4) << double(p[0]) << ", " << double(p[1]);
            }
        }
    }
}

TYPED_TEST(sqrt3_test, every_model_gives_the_positions_of_halfedge_mesh) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        // One hole: the four triangles of two neighbouring quads.
        const auto shape = without_faces(triangulated(torus(6, 5)), [](std::size_t f) { return f >= 10 && f < 14; });
        M m = mesh_from<M>(shape);
        auto reference = mesh_from<hmira::halfedge_mesh>(shape);
        ASSERT_TRUE(hmira::sqrt3_subdivide(m, {.levels = 2}));
        ASSERT_TRUE(hmira::sqrt3_subdivide(reference, {.levels = 2}));
        ASSERT_TRUE(valid_topology(m));
        const auto got = positions_of(m), want = positions_of(reference);
        ASSERT_EQ(got.size(), want.size());
        // Float models round positions, which can reorder nearly equal ones: match each
        // point to its nearest reference point instead of by sorted index.
        const double tol = std::is_same_v<typename T::scalar, double> ? 1e-12 : 1e-4;
        for (const auto& p : got) {
            double nearest = 1e300;
            for (const auto& q : want)
                nearest =
                    std::min(nearest, std::max({std::abs(p[0] - q[0]), std::abs(p[1] - q[1]), std::abs(p[2] - q[2])}));
            EXPECT_LE(nearest, tol) << p[0] << ", " << p[1] << ", " << p[2];
        }
    }
}

TYPED_TEST(sqrt3_test, too_many_levels_and_quads_are_refused_and_the_mesh_is_unchanged) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        M m = mesh_from<M>(triangulated(torus(16, 16)));
        const auto before = take_snapshot(m);
        // 512 triangles * 3^20: refused before anything is allocated.
        auto r = hmira::sqrt3_subdivide(m, {.levels = 20});
        ASSERT_FALSE(r);
        EXPECT_EQ(r.error().code, hmira::errc::invalid_argument);
        EXPECT_NE(r.error().message.find("2^31"), std::string::npos) << r.error().message;
        EXPECT_EQ(take_snapshot(m), before);
        r = hmira::sqrt3_subdivide(m, {.levels = 21});
        ASSERT_FALSE(r);
        EXPECT_NE(r.error().message.find("levels"), std::string::npos) << r.error().message;
        EXPECT_EQ(take_snapshot(m), before);
        if constexpr (!requires { requires T::triangles_only; }) {
            M q = mesh_from<M>(grid(2, 2));
            const auto quads = take_snapshot(q);
            r = hmira::sqrt3_subdivide(q);
            ASSERT_FALSE(r);
            EXPECT_EQ(r.error().code, hmira::errc::topology);
            EXPECT_NE(r.error().message.find("face 0"), std::string::npos) << r.error().message;
            EXPECT_EQ(take_snapshot(q), quads);
        }
    }
}

TYPED_TEST(sqrt3_test, coordinates_near_the_largest_double_subdivide_to_finite_positions) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        if constexpr (double(std::numeric_limits<typename hmira::default_traits<M>::scalar>::max()) < 1e308) {
            GTEST_SKIP() << "float positions cannot hold 1.7e308";
        } else {
            expect_huge_coordinates_subdivide_like_small_ones<M>(
                [](M& m) { return hmira::sqrt3_subdivide(m, {.levels = 2}); });
        }
    }
}

TYPED_TEST(sqrt3_test, a_cancellation_at_any_call_leaves_the_mesh_unchanged) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        M m;
        ASSERT_TRUE(hmira::generate_icosahedron(m));
        ASSERT_TRUE(hmira::loop_subdivide(m, {.levels = 4}));  // 5120 faces; three sqrt(3) levels make 138240
        // The levels' inputs: (V, E, F) = (2562, 7680, 5120), (7682, 23040, 15360), (23042, 69120, 46080).
        // Instrumented, the first two levels only: the third is two thirds of the work.
        constexpr std::size_t levels = hmira_test::sanitizer_build ? 2 : 3;
        constexpr std::size_t elements = hmira_test::sanitizer_build ? 61444 : 199686;
        expect_cancellation_restores(m, elements, [](M& x, hmira::progress_function p) {
            return hmira::sqrt3_subdivide(x, {.levels = levels, .progress = std::move(p)});
        });
    }
}

}  // namespace
