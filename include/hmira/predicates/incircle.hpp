// hmira/predicates/incircle.hpp
// Exact in-circle test for Delaunay triangulation: a floating-point filter, Shewchuk's adaptive
// stages B and C, then exact expansion arithmetic. The sign is always that of the exact
// determinant, whatever the compiler flags (see detail/expansion.hpp).
#pragma once

#include <cmath>

#include "detail/expansion.hpp"
#include "orient2d.hpp"

namespace hmira::predicates {
namespace detail {

inline constexpr double iccerrboundA = (10.0 + 96.0 * epsilon) * epsilon;
inline constexpr double iccerrboundB = (4.0 + 48.0 * epsilon) * epsilon;
inline constexpr double iccerrboundC = (44.0 + 576.0 * epsilon) * epsilon * epsilon;

/// Exact sign of the in-circle determinant from the raw coordinates: the last resort.
/// With each difference exact as a 2-component expansion, the determinant is
///   |a-d|^2 * ((b-d) x (c-d)) + |b-d|^2 * ((c-d) x (a-d)) + |c-d|^2 * ((a-d) x (b-d)).
inline int incircle_exact(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                          double dy) noexcept {
    const expansion<2> adx = exact_diff(ax, dx), ady = exact_diff(ay, dy);
    const expansion<2> bdx = exact_diff(bx, dx), bdy = exact_diff(by, dy);
    const expansion<2> cdx = exact_diff(cx, dx), cdy = exact_diff(cy, dy);
    auto cross = [](const expansion<2>& ux, const expansion<2>& uy, const expansion<2>& vx, const expansion<2>& vy) {
        expansion<8> l, r;
        expansion_product(ux, vy, l);
        expansion_product(uy, vx, r);
        expansion<16> d;
        expansion_diff(l, r, d);
        return d;
    };
    auto lift = [](const expansion<2>& ux, const expansion<2>& uy) {
        expansion<8> xx, yy;
        expansion_product(ux, ux, xx);
        expansion_product(uy, uy, yy);
        expansion<16> s;
        expansion_sum(xx, yy, s);
        return s;
    };
    expansion<512> ta, tb, tc;
    expansion_product(lift(adx, ady), cross(bdx, bdy, cdx, cdy), ta);
    expansion_product(lift(bdx, bdy), cross(cdx, cdy, adx, ady), tb);
    expansion_product(lift(cdx, cdy), cross(adx, ady, bdx, bdy), tc);
    expansion<1024> ab;
    expansion_sum(ta, tb, ab);
    expansion<1536> all;
    expansion_sum(ab, tc, all);
    return sign(all);
}

/// |u|^2 * (v x w) for rounded differences, exactly (stage B's term).
inline expansion<32> lifted_cross(double ux, double uy, double vx, double vy, double wx, double wy) noexcept {
    const expansion<4> vw = two_two_diff_products(vx, wy, wx, vy);
    expansion<8> t;
    expansion<16> xx, yy;
    scale_expansion(vw, ux, t);
    scale_expansion(t, ux, xx);
    scale_expansion(vw, uy, t);
    scale_expansion(t, uy, yy);
    expansion<32> r;
    expansion_sum(xx, yy, r);
    return r;
}

/// Stages B and C of the adaptive in-circle test (Shewchuk 1997, section 6), then exact.
/// Kept out of line: the filter in incircle() settles nearly every call.
[[gnu::noinline]] inline int incircle_adaptive(double ax, double ay, double bx, double by, double cx, double cy,
                                               double dx, double dy, double permanent) noexcept {
    const double adx = ax - dx, bdx = bx - dx, cdx = cx - dx;
    const double ady = ay - dy, bdy = by - dy, cdy = cy - dy;

    // Stage B: exact arithmetic on the rounded differences.
    expansion<64> ab;
    expansion_sum(lifted_cross(adx, ady, bdx, bdy, cdx, cdy), lifted_cross(bdx, bdy, cdx, cdy, adx, ady), ab);
    expansion<96> fin;
    expansion_sum(ab, lifted_cross(cdx, cdy, adx, ady, bdx, bdy), fin);
    double det = fin.estimate();
    double errbound = iccerrboundB * permanent;
    if (det >= errbound || -det >= errbound) return (det > 0) - (det < 0);

    const double adxtail = two_diff_tail(ax, dx, adx), adytail = two_diff_tail(ay, dy, ady);
    const double bdxtail = two_diff_tail(bx, dx, bdx), bdytail = two_diff_tail(by, dy, bdy);
    const double cdxtail = two_diff_tail(cx, dx, cdx), cdytail = two_diff_tail(cy, dy, cdy);
    // Exact differences: stage B's expansion is the exact determinant (lattices end here).
    if (adxtail == 0.0 && bdxtail == 0.0 && cdxtail == 0.0 && adytail == 0.0 && bdytail == 0.0 && cdytail == 0.0)
        return sign(fin);

    // Stage C: the first-order terms of the determinant in the difference tails.
    errbound = iccerrboundC * permanent + resulterrbound * std::fabs(det);
    det += ((adx * adx + ady * ady) * ((bdx * cdytail + cdy * bdxtail) - (bdy * cdxtail + cdx * bdytail)) +
            2.0 * (adx * adxtail + ady * adytail) * (bdx * cdy - bdy * cdx)) +
           ((bdx * bdx + bdy * bdy) * ((cdx * adytail + ady * cdxtail) - (cdy * adxtail + adx * cdytail)) +
            2.0 * (bdx * bdxtail + bdy * bdytail) * (cdx * ady - cdy * adx)) +
           ((cdx * cdx + cdy * cdy) * ((adx * bdytail + bdy * adxtail) - (ady * bdxtail + bdx * adytail)) +
            2.0 * (cdx * cdxtail + cdy * cdytail) * (adx * bdy - ady * bdx));
    if (det >= errbound || -det >= errbound) return (det > 0) - (det < 0);

    return incircle_exact(ax, ay, bx, by, cx, cy, dx, dy);
}

}  // namespace detail

/// Sign of the in-circle test: +1 if d lies inside the circle through a, b, c (given in
/// counter-clockwise order), -1 if outside, 0 if the four points are cocircular. For a
/// clockwise a, b, c the sign flips. Exact.
///
/// Complexity: O(1); a few dozen flops unless the points are nearly cocircular, and at worst a
/// few thousand for the exact stage.
/// Preconditions: every coordinate satisfies in_predicate_range() (checked by callers such as
/// delaunay_triangulation; out-of-range input may give a wrong sign).
/// Errors: none.
inline int incircle(double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy) noexcept {
    const double adx = ax - dx, bdx = bx - dx, cdx = cx - dx;
    const double ady = ay - dy, bdy = by - dy, cdy = cy - dy;

    const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
    const double alift = adx * adx + ady * ady;
    const double cdxady = cdx * ady, adxcdy = adx * cdy;
    const double blift = bdx * bdx + bdy * bdy;
    const double adxbdy = adx * bdy, bdxady = bdx * ady;
    const double clift = cdx * cdx + cdy * cdy;

    const double det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
    const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * alift +
                             (std::fabs(cdxady) + std::fabs(adxcdy)) * blift +
                             (std::fabs(adxbdy) + std::fabs(bdxady)) * clift;
    const double errbound = detail::iccerrboundA * permanent;
    if (det > errbound || -det > errbound) return det > 0.0 ? 1 : -1;
    return detail::incircle_adaptive(ax, ay, bx, by, cx, cy, dx, dy, permanent);
}

}  // namespace hmira::predicates
