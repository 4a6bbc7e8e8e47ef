// orient3d gives the sign of the exact determinant: checked against big-integer arithmetic on
// small integers, on points a few ulps off a plane (nextafter), and on large and tiny scales
// where the float filter cannot decide.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <hmira/predicates/orient3d.hpp>

#include "algorithms/delaunay/exact_reference.hpp"

namespace {

using hmira::predicates::orient3d;
using hmira_test::bigint;

/// Exact sign of ((b - a) x (c - a)) . (d - a), by big integers.
int exact_orient3d(const double* a, const double* b, const double* c, const double* d) {
    const auto v = hmira_test::exact_integers({a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2]});
    const bigint ux = v[3] - v[0], uy = v[4] - v[1], uz = v[5] - v[2];
    const bigint wx = v[6] - v[0], wy = v[7] - v[1], wz = v[8] - v[2];
    const bigint tx = v[9] - v[0], ty = v[10] - v[1], tz = v[11] - v[2];
    return (tx * (uy * wz - uz * wy) + ty * (uz * wx - ux * wz) + tz * (ux * wy - uy * wx)).sign();
}

/// The same with __int128, for small integer coordinates: a second, simpler reference.
int int128_orient3d(const double* a, const double* b, const double* c, const double* d) {
    auto i = [](double x) { return static_cast<__int128>(x); };
    const __int128 ux = i(b[0]) - i(a[0]), uy = i(b[1]) - i(a[1]), uz = i(b[2]) - i(a[2]);
    const __int128 wx = i(c[0]) - i(a[0]), wy = i(c[1]) - i(a[1]), wz = i(c[2]) - i(a[2]);
    const __int128 tx = i(d[0]) - i(a[0]), ty = i(d[1]) - i(a[1]), tz = i(d[2]) - i(a[2]);
    const __int128 det = tx * (uy * wz - uz * wy) + ty * (uz * wx - ux * wz) + tz * (ux * wy - uy * wx);
    return (det > 0) - (det < 0);
}

TEST(orient3d, follows_the_right_hand_rule) {
    const double a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {0, 1, 0}, up[3] = {0, 0, 1}, down[3] = {0, 0, -1};
    EXPECT_EQ(orient3d(a, b, c, up), 1);
    EXPECT_EQ(orient3d(a, b, c, down), -1);
    EXPECT_EQ(orient3d(b, a, c, up), -1);
    const double in_plane[3] = {5, -3, 0};
    EXPECT_EQ(orient3d(a, b, c, in_plane), 0);
}

TEST(orient3d, matches_integer_arithmetic_on_small_integer_coordinates) {
    std::mt19937_64 rng(7);
    std::uniform_int_distribution<int> small(-3, 3), big(-(1 << 20), 1 << 20);
    int zeros = 0;
    for (int n = 0; n < 20000; ++n) {
        double p[4][3];
        const bool tiny_range = n % 2 == 0;  // tiny range: many exactly coplanar cases
        for (auto& q : p)
            for (double& x : q) x = tiny_range ? small(rng) : big(rng);
        const int want = int128_orient3d(p[0], p[1], p[2], p[3]);
        zeros += want == 0;
        ASSERT_EQ(orient3d(p[0], p[1], p[2], p[3]), want) << n;
    }
    EXPECT_GT(zeros, 300);  // the degenerate case is exercised
}

TEST(orient3d, decides_points_a_few_ulps_off_a_plane) {
    // Points on the plane x + 2y + 3z = 1 in exact arithmetic are rarely representable, so
    // take three random points, a fourth as an exact-ish combination, and walk it by ulps.
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    int decided_by_exact_stage = 0;
    for (int n = 0; n < 3000; ++n) {
        double a[3], b[3], c[3], d[3];
        for (int k = 0; k < 3; ++k) {
            a[k] = u(rng);
            b[k] = u(rng);
            c[k] = u(rng);
        }
        const double s = u(rng), t = u(rng);
        for (int k = 0; k < 3; ++k) d[k] = a[k] + s * (b[k] - a[k]) + t * (c[k] - a[k]);
        for (int step = -3; step <= 3; ++step) {
            double e[3] = {d[0], d[1], d[2]};
            const int k = n % 3;
            for (int i = 0; i < std::abs(step); ++i) e[k] = std::nextafter(e[k], step > 0 ? 2.0 : -2.0);
            const int want = exact_orient3d(a, b, c, e);
            decided_by_exact_stage += want == 0;
            ASSERT_EQ(orient3d(a, b, c, e), want) << n << ' ' << step;
            // The determinant is alternating: permutations agree.
            ASSERT_EQ(orient3d(b, c, a, e), want);
            ASSERT_EQ(orient3d(b, a, c, e), -want);
        }
    }
    (void)decided_by_exact_stage;
}

TEST(orient3d, is_exact_at_the_ends_of_the_predicate_range) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    for (double scale : {0x1p150, 0x1p-150}) {
        for (int n = 0; n < 500; ++n) {
            double a[3], b[3], c[3], d[3];
            for (int k = 0; k < 3; ++k) {
                a[k] = u(rng) * scale;
                b[k] = u(rng) * scale;
                c[k] = u(rng) * scale;
            }
            for (int k = 0; k < 3; ++k) d[k] = 0.5 * (a[k] + b[k]);  // on line ab, nearly: rounding
            d[n % 3] = std::nextafter(d[n % 3], n % 2 ? 1e300 : -1e300);
            ASSERT_EQ(orient3d(a, b, c, d), exact_orient3d(a, b, c, d)) << scale << ' ' << n;
        }
    }
}

TEST(orient3d, coordinate_form_agrees_with_array_form) {
    const double a[3] = {0.1, 0.2, 0.3}, b[3] = {1.1, 0.7, -0.3}, c[3] = {0.4, 1.9, 0.8}, d[3] = {0.3, 0.3, 2.0};
    EXPECT_EQ(orient3d(a, b, c, d), orient3d(0.1, 0.2, 0.3, 1.1, 0.7, -0.3, 0.4, 1.9, 0.8, 0.3, 0.3, 2.0));
    EXPECT_EQ(orient3d(a, b, c, d), exact_orient3d(a, b, c, d));
}

}  // namespace
