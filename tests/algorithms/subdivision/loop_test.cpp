// loop_subdivide on every model that supports the triangle operators: the counts per level,
// valences (old keep theirs, new interior ones have 6), the genus, a flat grid staying flat,
// and the icosahedron's vertices converging to Loop's limit positions computed here from the
// limit mask. A mesh with a quad is refused and unchanged.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/subdivision/loop.hpp>

#include "algorithms/subdivision/subdivision_support.hpp"
#include "algorithms/triangle/triangle_support.hpp"

namespace {

using namespace hmira_test;

template <class M>
class loop_test : public ::testing::Test {};
TYPED_TEST_SUITE(loop_test, all_models);

TYPED_TEST(loop_test, one_level_on_the_icosahedron_gives_the_textbook_counts_and_valences) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        M m;
        ASSERT_TRUE(hmira::generate_icosahedron(m));
        std::vector<typename T::vertex_handle> old;
        for (auto v : T::vertices(m)) old.push_back(v);
        auto r = hmira::loop_subdivide(m);
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(valid_topology(m));
        EXPECT_EQ(T::vertex_count(m), 42u);
        EXPECT_EQ(T::edge_count(m), 120u);
        EXPECT_EQ(T::face_count(m), 80u);
        EXPECT_EQ(chi(m), 2);
        for (auto v : T::vertices(m)) {
            const bool is_old = std::find(old.begin(), old.end(), v) != old.end();
            EXPECT_EQ(valence(m, v), is_old ? 5u : 6u);
        }
    }
}

TYPED_TEST(loop_test, levels_multiply_faces_by_four_on_a_torus_and_keep_the_genus) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        M m = mesh_from<M>(triangulated(torus(8, 6)));
        long long v = (long long)T::vertex_count(m), e = (long long)T::edge_count(m), f = (long long)T::face_count(m);
        auto r = hmira::loop_subdivide(m, {.levels = 2});
        ASSERT_TRUE(r) << r.error().message;
        for (int l = 0; l < 2; ++l) {
            const long long v2 = v + e, e2 = 2 * e + 3 * f, f2 = 4 * f;
            v = v2, e = e2, f = f2;
        }
        EXPECT_EQ((long long)T::vertex_count(m), v);
        EXPECT_EQ((long long)T::edge_count(m), e);
        EXPECT_EQ((long long)T::face_count(m), f);
        EXPECT_EQ(chi(m), 0);
        EXPECT_TRUE(valid_topology(m));
    }
}

TYPED_TEST(loop_test, a_flat_grid_stays_flat_and_its_boundary_stays_on_the_boundary_lines) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        M m = mesh_from<M>(grid(4, 4, true));
        auto r = hmira::loop_subdivide(m, {.levels = 2});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(valid_topology(m));
        EXPECT_EQ(chi(m), 1);
        for (auto v : T::vertices(m)) {
            const auto p = T::position(m, v);
            EXPECT_EQ(double(p[2]), 0.0);
            const auto s = T::vertex_halfedge(m, v);
            // The boundary follows the cubic B-spline of the square: it rounds the corners, and
            // away from them (beyond one unit) it stays on the sides.
            if (T::face(m, s) == T::null_face()) {
                if (p[0] >= 1 && p[0] <= 3) {
                    EXPECT_TRUE(p[1] == 0 || p[1] == 4) << double(p[0]) << ", " << double(p[1]);
                }
                if (p[1] >= 1 && p[1] <= 3) {
                    EXPECT_TRUE(p[0] == 0 || p[0] == 4) << double(p[0]) << ", " << double(p[1]);
                }
                // Corner (0,0) goes to (1/6, 1/6) in the limit; after two levels it is inside the square.
                EXPECT_TRUE(p[0] >= 0 && p[0] <= 4 && p[1] >= 0 && p[1] <= 4);
            }
        }
    }
}

TYPED_TEST(loop_test, icosahedron_vertices_converge_to_the_limit_positions) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        if constexpr (!std::is_same_v<typename T::scalar, double>) {
            GTEST_SKIP() << "float positions";
        } else {
            M m;
            ASSERT_TRUE(hmira::generate_icosahedron(m));
            // Loop's limit mask for valence n: chi = 1 / (3 / (8 beta) + n) on each neighbour.
            const double n = 5, c = 0.375 + 0.25 * std::cos(2 * std::numbers::pi / n), beta = (0.625 - c * c) / n;
            const double w = 1 / (3 / (8 * beta) + n);
            std::vector<std::pair<typename T::vertex_handle, hmira::vec3<double>>> limits;
            for (auto v : T::vertices(m)) {
                hmira::vec3<double> sum{};
                for (auto u : T::adjacent_vertices(m, v)) sum += T::position(m, u);
                limits.push_back({v, T::position(m, v) * (1 - n * w) + sum * w});
            }
            double prev = 1e9;
            for (int level = 0; level < 5; ++level) {
                double worst = 0;
                for (const auto& [v, lim] : limits) {
                    const auto d = T::position(m, v) - lim;
                    worst = std::max(worst, std::sqrt(hmira::dot(d, d)));
                }
                if (level > 0) {
                    EXPECT_LT(worst, 0.5 * prev)
                        << "level " << level;  // the subdominant eigenvalue at valence 5 is < 1/2
                }
                prev = worst;
                ASSERT_TRUE(hmira::loop_subdivide(m));
                ASSERT_TRUE(valid_topology(m)) << "level " << level + 1;
            }
            EXPECT_LT(prev, 1e-2);
        }
    }
}

TYPED_TEST(loop_test, levels_that_would_overflow_the_indices_are_refused_and_the_mesh_is_unchanged) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        // 8192 triangles * 4^10 = 2^33 faces: refused before anything is allocated.
        M m = mesh_from<M>(triangulated(torus(64, 64)));
        const auto before = take_snapshot(m);
        auto r = hmira::loop_subdivide(m, {.levels = 10});
        ASSERT_FALSE(r);
        EXPECT_EQ(r.error().code, hmira::errc::invalid_argument);
        EXPECT_NE(r.error().message.find("2^31"), std::string::npos) << r.error().message;
        EXPECT_EQ(take_snapshot(m), before);
        r = hmira::loop_subdivide(m, {.levels = 11});
        ASSERT_FALSE(r);
        EXPECT_EQ(take_snapshot(m), before);
    }
}

TYPED_TEST(loop_test, a_mesh_with_a_quad_is_refused_and_unchanged) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        if constexpr (!requires { requires T::triangles_only; }) {
            M m = mesh_from<M>(grid(2, 2));
            const auto before = take_snapshot(m);
            auto r = hmira::loop_subdivide(m);
            ASSERT_FALSE(r);
            EXPECT_EQ(r.error().code, hmira::errc::topology);
            EXPECT_EQ(take_snapshot(m), before);
        }
    }
}

TYPED_TEST(loop_test, coordinates_near_the_largest_double_subdivide_to_finite_positions) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        if constexpr (double(std::numeric_limits<typename hmira::default_traits<M>::scalar>::max()) < 1e308) {
            GTEST_SKIP() << "float positions cannot hold 1.7e308";
        } else {
            expect_huge_coordinates_subdivide_like_small_ones<M>(
                [](M& m) { return hmira::loop_subdivide(m, {.levels = 2}); });
        }
    }
}

TYPED_TEST(loop_test, a_cancellation_at_any_call_leaves_the_mesh_unchanged) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        M m;
        ASSERT_TRUE(hmira::generate_icosahedron(m));
        ASSERT_TRUE(hmira::loop_subdivide(m, {.levels = 4}));  // 5120 faces; three more levels make 327680
        // The levels' inputs: (V, E, F) = (2562, 7680, 5120), (10242, 30720, 20480), (40962, 122880, 81920).
        // Instrumented, the first two levels only: the third is three quarters of the work.
        constexpr std::size_t levels = hmira_test::sanitizer_build ? 2 : 3;
        constexpr std::size_t elements = hmira_test::sanitizer_build ? 76804 : 322566;
        expect_cancellation_restores(m, elements, [](M& x, hmira::progress_function p) {
            return hmira::loop_subdivide(x, {.levels = levels, .progress = std::move(p)});
        });
    }
}

}  // namespace
