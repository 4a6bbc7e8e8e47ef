// laplacian_smooth and taubin_smooth on every model with halfedge navigation: Taubin keeps a
// sphere's volume within 1% over 10 iterations where plain Laplacian loses more; fixed and
// boundary vertices stay bit for bit; noise goes down; bad options change nothing.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/smoothing/laplacian_smooth.hpp>
#include <hmira/algorithms/subdivision/loop.hpp>

#include "triangle/triangle_support.hpp"

namespace {

using namespace hmira_test;

template <class M>
class smoothing_test : public ::testing::Test {};
TYPED_TEST_SUITE(smoothing_test, all_models);

template <class M, class T = hmira::default_traits<M>>
M unit_sphere() {
    M m;
    EXPECT_TRUE(hmira::generate_icosahedron(m));
    EXPECT_TRUE(hmira::loop_subdivide(m, {.levels = 3}));
    for (auto v : T::vertices(m)) {
        auto p = T::position(m, v);
        const auto l = std::sqrt(double(hmira::dot(p, p)));
        T::set_position(m, v, p / typename T::scalar(l));
    }
    return m;
}

template <class M, class T = hmira::default_traits<M>>
std::vector<std::array<double, 3>> positions(const M& m) {
    std::vector<std::array<double, 3>> out;
    for (auto v : T::vertices(m)) {
        const auto p = T::position(m, v);
        out.push_back({double(p[0]), double(p[1]), double(p[2])});
    }
    return out;
}

TYPED_TEST(smoothing_test, taubin_keeps_a_spheres_volume_within_one_percent_where_laplacian_does_not) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        for (auto w : {hmira::laplacian_weights::uniform, hmira::laplacian_weights::cotangent}) {
            M a = unit_sphere<M>();
            const double v0 = signed_volume(a);
            ASSERT_NEAR(v0, 4.18, 0.05);
            M b = a;
            ASSERT_TRUE(hmira::taubin_smooth(a, {.iterations = 10, .weights = w}));
            EXPECT_GT(signed_volume(a), 0.99 * v0);
            EXPECT_LT(signed_volume(a), 1.01 * v0);
            ASSERT_TRUE(hmira::laplacian_smooth(b, {.iterations = 10, .weights = w}));
            if (w == hmira::laplacian_weights::uniform) {
                EXPECT_LT(signed_volume(b), 0.99 * v0);
            }
        }
    }
}

TYPED_TEST(smoothing_test, boundary_and_fixed_vertices_stay_exactly_and_noise_goes_down) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        for (auto w : {hmira::laplacian_weights::uniform, hmira::laplacian_weights::cotangent}) {
            M m = mesh_from<M>(grid(8, 8, true));
            std::mt19937_64 rng(5);
            std::uniform_real_distribution<double> noise(-0.2, 0.2);
            double before = 0;
            for (auto v : T::vertices(m)) {
                auto p = T::position(m, v);
                p[2] = typename T::scalar(noise(rng));
                T::set_position(m, v, p);
            }
            for (auto v : T::vertices(m)) before += std::fabs(double(T::position(m, v)[2]));
            const auto start = positions(m);
            // Fix vertex 40 (an interior one: (4, 4)) as a feature.
            auto r = hmira::taubin_smooth(m, {.iterations = 5, .weights = w, .fixed_vertices = {40}});
            ASSERT_TRUE(r) << r.error().message;
            EXPECT_EQ(r->moved, 7u * 7u - 1u);
            const auto end = positions(m);
            double after = 0;
            std::size_t i = 0;
            for (auto v : T::vertices(m)) {
                const auto p = T::position(m, v);
                const bool boundary = p[0] == 0 || p[0] == 8 || p[1] == 0 || p[1] == 8;
                if (boundary || T::vertex_index(m, v) == 40) {
                    EXPECT_EQ(end[i], start[i]) << "vertex " << T::vertex_index(m, v);
                } else {
                    EXPECT_NE(end[i], start[i]);
                }
                if (!boundary) after += std::fabs(double(p[2]));
                ++i;
            }
            double before_inner = 0;
            i = 0;
            for (auto v : T::vertices(m)) {
                const auto p = T::position(m, v);
                if (!(p[0] == 0 || p[0] == 8 || p[1] == 0 || p[1] == 8)) before_inner += std::fabs(start[i][2]);
                ++i;
            }
            EXPECT_LT(after, 0.8 * before_inner);
            (void)before;
        }
    }
}

// The steps of one call share their buffers (allocated once per call): k iterations in one
// call must give bit for bit what k calls of one iteration give, with fixed, boundary and
// moving vertices side by side.
TYPED_TEST(smoothing_test, iterations_in_one_call_equal_one_call_per_iteration) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        for (auto w : {hmira::laplacian_weights::uniform, hmira::laplacian_weights::cotangent}) {
            M a = mesh_from<M>(grid(6, 6, true));
            std::mt19937_64 rng(11);
            std::uniform_real_distribution<double> noise(-0.3, 0.3);
            for (auto v : T::vertices(a)) {
                auto p = T::position(a, v);
                p[2] = typename T::scalar(noise(rng));
                T::set_position(a, v, p);
            }
            M b = a, c = a, d = a;
            ASSERT_TRUE(hmira::laplacian_smooth(a, {.iterations = 4, .weights = w, .fixed_vertices = {24}}));
            for (int k = 0; k < 4; ++k) ASSERT_TRUE(hmira::laplacian_smooth(b, {.iterations = 1, .weights = w, .fixed_vertices = {24}}));
            EXPECT_EQ(positions(a), positions(b));
            ASSERT_TRUE(hmira::taubin_smooth(c, {.iterations = 3, .weights = w, .fixed_vertices = {24}}));
            for (int k = 0; k < 3; ++k) ASSERT_TRUE(hmira::taubin_smooth(d, {.iterations = 1, .weights = w, .fixed_vertices = {24}}));
            EXPECT_EQ(positions(c), positions(d));
            EXPECT_NE(positions(a), positions(c));  // the two smoothers did move the vertices
            for (const M* m : {&a, &b, &c, &d}) EXPECT_TRUE(valid_topology(*m));
        }
    }
}

TYPED_TEST(smoothing_test, bad_options_are_refused_and_change_nothing) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        M m = mesh_from<M>(grid(3, 3, true));
        const auto before = take_snapshot(m);
        auto check = [&](auto r, hmira::errc code) {
            ASSERT_FALSE(r);
            EXPECT_EQ(r.error().code, code) << r.error().message;
            EXPECT_EQ(take_snapshot(m), before);
        };
        check(hmira::laplacian_smooth(m, {.lambda = 0}), hmira::errc::invalid_argument);
        check(hmira::laplacian_smooth(m, {.lambda = std::nan("")}), hmira::errc::invalid_argument);
        check(hmira::taubin_smooth(m, {.lambda = 0.5, .mu = -0.4}), hmira::errc::invalid_argument);
        check(hmira::laplacian_smooth(m, {.fixed_vertices = {999}}), hmira::errc::invalid_argument);
        if constexpr (!requires { requires T::triangles_only; }) {
            M q = mesh_from<M>(grid(2, 2));
            auto r = hmira::laplacian_smooth(q, {.weights = hmira::laplacian_weights::cotangent});
            ASSERT_FALSE(r);
            EXPECT_EQ(r.error().code, hmira::errc::topology);
        }
    }
}

}  // namespace
