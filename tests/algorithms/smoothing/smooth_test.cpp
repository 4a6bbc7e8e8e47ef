// laplacian_smooth and taubin_smooth on every model with halfedge navigation: Taubin keeps a
// sphere's volume within 1% over 10 iterations where plain Laplacian loses more; fixed and
// boundary vertices stay bit for bit; noise goes down; bad options change nothing.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/smoothing/laplacian_smooth.hpp>
#include <hmira/algorithms/subdivision/loop.hpp>

#include "algorithms/triangle/triangle_support.hpp"
#include "support/cancel_points.hpp"

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
            for (int k = 0; k < 4; ++k)
                ASSERT_TRUE(hmira::laplacian_smooth(b, {.iterations = 1, .weights = w, .fixed_vertices = {24}}));
            EXPECT_EQ(positions(a), positions(b));
            ASSERT_TRUE(hmira::taubin_smooth(c, {.iterations = 3, .weights = w, .fixed_vertices = {24}}));
            for (int k = 0; k < 3; ++k)
                ASSERT_TRUE(hmira::taubin_smooth(d, {.iterations = 1, .weights = w, .fixed_vertices = {24}}));
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

// The tetrahedron of coordinates near the largest double that made the smoothers write
// infinities: its neighbour differences (1.7e308 - -1.7e308) overflow.
face_list huge_tetrahedron(double c = 1.7e308) {
    return {{{c, c, 0}, {c, -c, 0}, {-c, 0, 0}, {0, 0, c}}, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}}};
}

/// One Laplacian step on the tetrahedron computed in long double (whose range holds the
/// overflowing sums): every vertex has the three others as neighbours; cotangent weights are
/// (cot alpha + cot beta) / 2 of the two triangles beside each edge.
std::vector<std::array<long double, 3>> reference_step(const face_list& g, long double amount, bool cotangent) {
    using P = std::array<long double, 3>;
    std::vector<P> p;
    for (const auto& q : g.points) p.push_back({q.x, q.y, q.z});
    const auto sub = [](const P& a, const P& b) { return P{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; };
    const auto dotp = [](const P& a, const P& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
    const auto cot = [&](const P& a, const P& b, const P& c) {  // at a
        const P u = sub(b, a), w = sub(c, a);
        const P x{u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
        return dotp(u, w) / std::sqrt(dotp(x, x));
    };
    std::vector<P> out;
    for (std::size_t i = 0; i < p.size(); ++i) {
        P sum{0, 0, 0};
        long double total = 0;
        for (std::size_t j = 0; j < p.size(); ++j) {
            if (j == i) continue;
            long double w = 1;
            if (cotangent) {
                w = 0;
                for (const auto& f : g.faces)  // the triangles holding edge ij, at their third corner
                    if (std::count(f.begin(), f.end(), i) && std::count(f.begin(), f.end(), j))
                        for (auto k : f)
                            if (k != i && k != j) w += cot(p[k], p[i], p[j]) / 2;
            }
            for (int d = 0; d < 3; ++d) sum[d] += w * (p[j][d] - p[i][d]);
            total += w;
        }
        P q{};
        for (int d = 0; d < 3; ++d) q[d] = p[i][d] + amount * sum[d] / total;
        out.push_back(q);
    }
    return out;
}

TYPED_TEST(smoothing_test, coordinates_near_the_largest_double_smooth_to_finite_positions) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        if constexpr (double(std::numeric_limits<typename T::scalar>::max()) < 1e308) {
            GTEST_SKIP() << "float positions cannot hold 1.7e308";
        } else {
            const auto g = huge_tetrahedron();
            for (auto w : {hmira::laplacian_weights::uniform, hmira::laplacian_weights::cotangent}) {
                M m = mesh_from<M>(g);
                auto r = hmira::laplacian_smooth(m, {.iterations = 1, .weights = w, .fix_boundary = false});
                ASSERT_TRUE(r) << r.error().message;
                EXPECT_TRUE(valid_topology(m));
                const auto want = reference_step(g, 0.5L, w == hmira::laplacian_weights::cotangent);
                const auto got = positions(m);
                ASSERT_EQ(got.size(), want.size());
                for (std::size_t i = 0; i < got.size(); ++i)
                    for (int d = 0; d < 3; ++d) {
                        ASSERT_TRUE(std::isfinite(got[i][d])) << "vertex " << i;
                        EXPECT_NEAR(got[i][d] / 1e308, double(want[i][d] / 1e308L), 1e-14) << i << ", " << d;
                    }
            }
            // Taubin with the default lambda and mu shrinks this tetrahedron: finite, ten
            // iterations, every coordinate within the input's range.
            M m = mesh_from<M>(g);
            auto r = hmira::taubin_smooth(m, {.iterations = 10, .fix_boundary = false});
            ASSERT_TRUE(r) << r.error().message;
            for (const auto& q : positions(m))
                for (double x : q) EXPECT_LE(std::abs(x), 1.7e308);
            EXPECT_TRUE(valid_topology(m));
        }
    }
}

TYPED_TEST(smoothing_test, a_taubin_step_beyond_the_range_of_double_is_refused_by_vertex_and_changes_nothing) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        if constexpr (double(std::numeric_limits<typename T::scalar>::max()) < 1e308) {
            GTEST_SKIP() << "float positions cannot hold 1.7e308";
        } else {
            // lambda 0.01 barely moves vertex 0; mu = -1 then puts its x near 2 * 1.7e308.
            M m = mesh_from<M>(huge_tetrahedron());
            const auto before = take_snapshot(m);
            for (std::size_t iterations : {1u, 3u}) {
                const hmira::taubin_smooth_options o{
                    .iterations = iterations, .lambda = 0.01, .mu = -1, .fix_boundary = false};
                auto r = hmira::taubin_smooth(m, o);
                ASSERT_FALSE(r);
                EXPECT_EQ(r.error().code, hmira::errc::unsupported) << r.error().message;
                EXPECT_NE(r.error().message.find("taubin_smooth: vertex "), std::string::npos) << r.error().message;
                EXPECT_NE(r.error().message.find("beyond the range of double"), std::string::npos) << r.error().message;
                EXPECT_GE(r.error().element, 0);
                EXPECT_EQ(take_snapshot(m), before);
                EXPECT_TRUE(valid_topology(m));
            }
        }
    }
}

TYPED_TEST(smoothing_test, a_step_on_ordinary_coordinates_is_bit_for_bit_the_umbrella_formula) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        M m = unit_sphere<M>();
        std::mt19937_64 rng(11);
        std::uniform_real_distribution<double> noise(-0.05, 0.05);
        for (auto v : T::vertices(m)) {
            auto p = T::position(m, v);
            for (int d = 0; d < 3; ++d) p[d] += typename T::scalar(noise(rng));
            T::set_position(m, v, p);
        }
        // p + (sum of (p_j - p)) * (lambda / n), neighbour by neighbour, as the smoother has
        // always computed it: the rescaled path for huge coordinates must not change it.
        std::vector<hmira::vec3<double>> want;
        for (auto v : T::vertices(m)) {
            const auto p = hmira::detail::triangle_ops::position_of<M, T>(m, v);
            hmira::vec3<double> sum{};
            double n = 0;
            const auto first = T::vertex_halfedge(m, v);
            auto x = first;
            do {  // around the vertex, as the smoother walks it
                sum += hmira::detail::triangle_ops::position_of<M, T>(m, T::target(m, x)) - p;
                n += 1;
                x = T::next(m, T::opposite(m, x));
            } while (x != first);
            want.push_back(p + sum * (0.5 / n));
        }
        ASSERT_TRUE(hmira::laplacian_smooth(m, {.iterations = 1, .lambda = 0.5}));
        std::size_t k = 0;
        for (auto v : T::vertices(m)) {
            const auto p = T::position(m, v);
            using S = typename T::scalar;
            EXPECT_EQ(p[0], S(want[k].x));
            EXPECT_EQ(p[1], S(want[k].y));
            EXPECT_EQ(p[2], S(want[k].z));
            ++k;
        }
        EXPECT_TRUE(valid_topology(m));
    }
}

TYPED_TEST(smoothing_test, a_cancellation_at_any_call_restores_every_position) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        // A large mesh (a 260 x 260 grid: 68121 vertices, more than one block per step) and a
        // small one run for many steps (12 vertices, 30000 or 40000 steps): the callback comes
        // at least once per 65536 vertices visited either way.
        M big = mesh_from<M>(grid(260, 260, true));
        {
            std::mt19937_64 rng(3);
            std::uniform_real_distribution<double> noise(-0.2, 0.2);
            for (auto v : T::vertices(big)) {
                auto p = T::position(big, v);
                p[2] = typename T::scalar(noise(rng));
                T::set_position(big, v, p);
            }
        }
        M small;
        ASSERT_TRUE(hmira::generate_icosahedron(small));
        struct job {
            const M* mesh;
            std::size_t iterations;
            bool taubin;
        };
        // Instrumented, the small mesh runs 3 and 2 blocks of 65536 vertex visits instead of 5 and 7.
        constexpr std::size_t laplacian_steps = hmira_test::sanitizer_build ? 16384 : 30000;
        constexpr std::size_t taubin_iterations = hmira_test::sanitizer_build ? 6000 : 20000;
        for (const job j :
             {job{&big, 1, true}, job{&small, laplacian_steps, false}, job{&small, taubin_iterations, true}}) {
            const auto before = take_snapshot(*j.mesh);
            const std::size_t steps = j.iterations * (j.taubin ? 2 : 1);
            const std::size_t elements = steps * T::vertex_count(*j.mesh);
            const auto smooth = [&](M& m, hmira::progress_function progress) -> hmira::result<hmira::smooth_result> {
                if (j.taubin)
                    return hmira::taubin_smooth(m, {.iterations = j.iterations, .progress = std::move(progress)});
                return hmira::laplacian_smooth(m, {.iterations = j.iterations, .progress = std::move(progress)});
            };
            int calls_to_finish = 0;
            M done = *j.mesh;
            double last = -1;
            ASSERT_TRUE(smooth(done, [&](double f) {
                EXPECT_GE(f, last);
                EXPECT_LE(f, 1.0);
                last = f;
                ++calls_to_finish;
                return true;
            }));
            EXPECT_GE(std::size_t(calls_to_finish), elements / 65536) << elements << " vertices visited";
            ASSERT_GE(calls_to_finish, 2);
            M plain = *j.mesh;
            ASSERT_TRUE(smooth(plain, {}));
            EXPECT_EQ(take_snapshot(plain), take_snapshot(done));  // the callback changes nothing
            for (const int stop_at : hmira_test::cancel_points(calls_to_finish, 5)) {
                M m = *j.mesh;
                int calls = 0;
                auto r = smooth(m, [&](double) { return ++calls < stop_at; });
                ASSERT_FALSE(r) << "stop at call " << stop_at;
                EXPECT_EQ(r.error().code, hmira::errc::cancelled);
                EXPECT_NE(r.error().message.find("cancelled"), std::string::npos);
                EXPECT_EQ(calls, stop_at);
                EXPECT_EQ(take_snapshot(m), before) << "stop at call " << stop_at;
                EXPECT_TRUE(valid_topology(m));
            }
        }
    }
}

}  // namespace
