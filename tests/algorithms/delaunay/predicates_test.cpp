// tests/algorithms/delaunay/predicates_test.cpp
// orient2d and incircle against an exact big-integer reference on adversarial, nearly
// degenerate inputs. This file is compiled twice: with the project flags, and with
// -O3 -ffp-contract=fast -march=native to check that FMA contraction cannot break exactness.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <hmira/predicates/incircle.hpp>
#include <hmira/predicates/orient2d.hpp>

#include "exact_reference.hpp"

namespace {

using hmira::predicates::incircle;
using hmira::predicates::orient2d;
using hmira_test::exact_incircle;
using hmira_test::exact_orient;

// The plain floating-point determinants, to show the inputs really are hard. volatile keeps
// the compiler from fusing or reordering them in this comparison.
int naive_orient(double ax, double ay, double bx, double by, double cx, double cy) {
    volatile double l = (ax - cx) * (by - cy);
    volatile double r = (ay - cy) * (bx - cx);
    const double d = l - r;
    return (d > 0) - (d < 0);
}

TEST(predicates, orient2d_matches_exact_sign_near_a_line_shewchuk_grid) {
    // Points (0.5 + i ulp, 0.5 + j ulp) against the line through (12, 12) and (24, 24).
    const double u = std::ldexp(1.0, -53);
    int naive_wrong = 0;
    for (int i = 0; i < 64; ++i) {
        for (int j = 0; j < 64; ++j) {
            const double ax = 0.5 + i * u, ay = 0.5 + j * u;
            const int expect = exact_orient(ax, ay, 12, 12, 24, 24);
            ASSERT_EQ(orient2d(ax, ay, 12, 12, 24, 24), expect) << i << " " << j;
            ASSERT_EQ(orient2d(12, 12, 24, 24, ax, ay), expect) << i << " " << j;
            ASSERT_EQ(orient2d(24, 24, ax, ay, 12, 12), expect) << i << " " << j;
            ASSERT_EQ(orient2d(12, 12, ax, ay, 24, 24), -expect) << i << " " << j;
            naive_wrong += naive_orient(ax, ay, 12, 12, 24, 24) != expect;
        }
    }
    EXPECT_GT(naive_wrong, 0) << "the grid should defeat plain floating point";
}

TEST(predicates, orient2d_matches_exact_sign_for_random_nearly_collinear_points_with_inexact_differences) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> coord(-1e3, 1e3), t(-2.0, 3.0);
    std::uniform_int_distribution<int> ulps(-8, 8);
    for (int k = 0; k < 20000; ++k) {
        const double ax = coord(rng), ay = coord(rng), bx = coord(rng) * 1e-7, by = coord(rng) * 1e5;
        const double s = t(rng);
        double cx = ax + s * (bx - ax), cy = ay + s * (by - ay);
        cx = std::nextafter(cx, ulps(rng) > 0 ? 1e300 : -1e300);
        for (int m = ulps(rng); m > 0; --m) cy = std::nextafter(cy, 1e300);
        ASSERT_EQ(orient2d(ax, ay, bx, by, cx, cy), exact_orient(ax, ay, bx, by, cx, cy)) << k;
    }
}

TEST(predicates, orient2d_is_zero_exactly_on_collinear_input_and_antisymmetric) {
    std::mt19937_64 rng(11);
    std::uniform_int_distribution<int> small(-1000, 1000);
    for (int k = 0; k < 5000; ++k) {
        // Integer points on a line x = a + i*d: exactly collinear, exactly representable.
        const double a = small(rng), b = small(rng), dx = small(rng), dy = small(rng);
        const int i = small(rng), j = small(rng);
        EXPECT_EQ(orient2d(a, b, a + i * dx, b + i * dy, a + j * dx, b + j * dy), 0);
        const double cx = a + j * dx + 0.5, cy = b + j * dy;
        EXPECT_EQ(orient2d(a, b, a + i * dx, b + i * dy, cx, cy), -orient2d(a + i * dx, b + i * dy, a, b, cx, cy));
    }
}

TEST(predicates, incircle_matches_exact_sign_near_the_unit_circle_translated_far_away) {
    // Three exactly cocircular points, a fourth rounded onto the circle and nudged by ulps,
    // all translated so that the differences are no longer exact.
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> angle(0, 6.283185307179586);
    std::uniform_int_distribution<int> ulps(-3, 3);
    const double offsets[] = {0.0, 1.0 / 3.0, 1e3 + 0.1, 12345.678, 1e6 / 7.0};
    int naive_zero_or_wrong = 0, inside = 0, outside = 0;
    for (double off : offsets) {
        for (int k = 0; k < 3000; ++k) {
            const double t = angle(rng);
            double dx = std::cos(t), dy = std::sin(t);
            for (int m = ulps(rng); m != 0; m += (m > 0 ? -1 : 1)) dx = std::nextafter(dx, m > 0 ? 2.0 : -2.0);
            const double ax = off + 1, ay = off, bx = off, by = off + 1, cx = off - 1, cy = off;
            const double px = off + dx, py = off + dy;
            const int expect = exact_incircle(ax, ay, bx, by, cx, cy, px, py);
            ASSERT_EQ(incircle(ax, ay, bx, by, cx, cy, px, py), expect) << off << " " << k;
            ASSERT_EQ(incircle(bx, by, cx, cy, ax, ay, px, py), expect);
            ASSERT_EQ(incircle(ax, ay, cx, cy, bx, by, px, py), -expect);
            inside += expect > 0;
            outside += expect < 0;
            const double ax_ = ax - px, ay_ = ay - py, bx_ = bx - px, by_ = by - py, cx_ = cx - px, cy_ = cy - py;
            volatile double d = (ax_ * ax_ + ay_ * ay_) * (bx_ * cy_ - cx_ * by_) +
                                (bx_ * bx_ + by_ * by_) * (cx_ * ay_ - ax_ * cy_) +
                                (cx_ * cx_ + cy_ * cy_) * (ax_ * by_ - bx_ * ay_);
            naive_zero_or_wrong += ((d > 0) - (d < 0)) != expect;
        }
    }
    EXPECT_GT(inside, 0);
    EXPECT_GT(outside, 0);
    EXPECT_GT(naive_zero_or_wrong, 0) << "the inputs should defeat plain floating point";
}

TEST(predicates, incircle_is_zero_on_exactly_cocircular_lattice_points) {
    // Pythagorean points on circles of radius 5 and 25 around integer centres.
    const int pts5[][2] = {{5, 0},  {4, 3},   {3, 4},   {0, 5},  {-3, 4}, {-4, 3},
                           {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
    for (double cx0 : {0.0, 1e7, -3.5e8}) {
        for (double cy0 : {0.0, 2.0e6 + 0.5, -77.25}) {
            for (int i = 0; i < 12; ++i)
                for (int j = i + 1; j < 12; ++j)
                    for (int k = j + 1; k < 12; ++k) {
                        const int l = (k + 1) % 12;
                        if (l == i || l == j) continue;
                        EXPECT_EQ(incircle(cx0 + pts5[i][0], cy0 + pts5[i][1], cx0 + pts5[j][0], cy0 + pts5[j][1],
                                           cx0 + pts5[k][0], cy0 + pts5[k][1], cx0 + pts5[l][0], cy0 + pts5[l][1]),
                                  0);
                    }
        }
    }
}

TEST(predicates, incircle_matches_exact_sign_for_random_nearly_cocircular_points) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> coord(-1.0, 1.0), angle(0, 6.283185307179586), scale_exp(-40, 40);
    std::uniform_int_distribution<int> ulps(-4, 4);
    for (int k = 0; k < 20000; ++k) {
        const double s = std::ldexp(1.0, static_cast<int>(scale_exp(rng)));
        const double ox = coord(rng) * s * 100, oy = coord(rng) * s * 100, r = s * (0.5 + coord(rng) * 0.25);
        double q[4][2];
        for (auto& pt : q) {
            const double t = angle(rng);
            pt[0] = ox + r * std::cos(t);
            pt[1] = oy + r * std::sin(t);
        }
        for (int m = ulps(rng); m != 0; m += (m > 0 ? -1 : 1))
            q[3][1] = std::nextafter(q[3][1], m > 0 ? 1e300 : -1e300);
        const int expect = exact_incircle(q[0][0], q[0][1], q[1][0], q[1][1], q[2][0], q[2][1], q[3][0], q[3][1]);
        ASSERT_EQ(incircle(q[0][0], q[0][1], q[1][0], q[1][1], q[2][0], q[2][1], q[3][0], q[3][1]), expect) << k;
    }
}

TEST(predicates, degenerate_input_with_inexact_differences_reaches_the_exact_stage) {
    // Points (t, t) on the diagonal with t of wildly different magnitudes: exactly collinear
    // (orient2d = 0) and, four at a time, exactly "cocircular" (four collinear points lift to
    // coplanar points, incircle = 0), yet no difference is exact, so only the exact stage can
    // answer. Nudging one coordinate by an ulp must give the exact reference's sign.
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> mant(1.0, 2.0);
    std::uniform_int_distribution<int> expo(-60, 60), sgn(0, 1);
    auto t = [&] { return (sgn(rng) ? -1.0 : 1.0) * std::ldexp(mant(rng), expo(rng)); };
    for (int k = 0; k < 3000; ++k) {
        const double a = t(), b = t(), c = t(), d = t();
        ASSERT_EQ(orient2d(a, a, b, b, c, c), 0);
        ASSERT_EQ(incircle(a, a, b, b, c, c, d, d), 0);
        const double dn = std::nextafter(d, 1e300), an = std::nextafter(a, -1e300);
        ASSERT_EQ(orient2d(an, a, b, b, c, c), exact_orient(an, a, b, b, c, c)) << k;
        ASSERT_EQ(orient2d(a, a, b, b, dn, d), exact_orient(a, a, b, b, dn, d)) << k;
        ASSERT_EQ(incircle(a, a, b, b, c, c, dn, d), exact_incircle(a, a, b, b, c, c, dn, d)) << k;
        ASSERT_EQ(incircle(an, a, b, b, c, c, d, d), exact_incircle(an, a, b, b, c, c, d, d)) << k;
    }
}

TEST(predicates, predicates_stay_exact_at_the_ends_of_the_accepted_range) {
    using hmira::predicates::max_magnitude;
    using hmira::predicates::min_magnitude;
    for (double s : {max_magnitude, min_magnitude}) {
        const double u = std::ldexp(1.0, -53);
        for (int i = 0; i < 16; ++i) {
            const double ax = s * (0.5 + i * u), ay = s * 0.5;
            EXPECT_EQ(orient2d(ax, ay, s * 0.75, s * 0.75, s, s), exact_orient(ax, ay, s * 0.75, s * 0.75, s, s));
            EXPECT_EQ(incircle(s, 0, 0, s, -s, 0, ax - s * 0.5, ay + s * 0.5),
                      exact_incircle(s, 0, 0, s, -s, 0, ax - s * 0.5, ay + s * 0.5));
            EXPECT_EQ(incircle(-s, -s, s, -s, s, s, ax, -ay), exact_incircle(-s, -s, s, -s, s, s, ax, -ay));
        }
    }
    EXPECT_TRUE(hmira::predicates::in_predicate_range(0.0));
    EXPECT_TRUE(hmira::predicates::in_predicate_range(-1e54));
    EXPECT_FALSE(hmira::predicates::in_predicate_range(1e55));
    EXPECT_FALSE(hmira::predicates::in_predicate_range(1e-56));
    EXPECT_FALSE(hmira::predicates::in_predicate_range(std::nan("")));
    EXPECT_FALSE(hmira::predicates::in_predicate_range(HUGE_VAL));
}

}  // namespace
