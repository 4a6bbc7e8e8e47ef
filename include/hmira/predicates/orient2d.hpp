// hmira/predicates/orient2d.hpp
// Exact orientation of three points in the plane: a floating-point filter that decides almost
// every call, then Shewchuk's adaptive stages, then exact expansion arithmetic. The sign is
// always the sign of the exact determinant, whatever the compiler flags (see detail/expansion.hpp).
#pragma once

#include <cmath>

#include "detail/expansion.hpp"

namespace hmira::predicates {

/// Coordinates the predicates accept: 0, or a magnitude in [min_magnitude, max_magnitude].
/// Within that range no intermediate of orient2d or incircle overflows, and none underflows
/// into subnormals, so the error bounds and the exact stages hold. Callers reject the rest.
inline constexpr double max_magnitude = 0x1p180;   // ~1.5e54
inline constexpr double min_magnitude = 0x1p-180;  // ~6.5e-55

/// True if v is finite and 0 or in [min_magnitude, max_magnitude].
inline bool in_predicate_range(double v) noexcept {
    const double a = std::fabs(v);
    return a == 0.0 || (a >= min_magnitude && a <= max_magnitude);
}

namespace detail {

inline constexpr double resulterrbound = (3.0 + 8.0 * epsilon) * epsilon;
inline constexpr double ccwerrboundA = (3.0 + 16.0 * epsilon) * epsilon;
inline constexpr double ccwerrboundB = (2.0 + 12.0 * epsilon) * epsilon;
inline constexpr double ccwerrboundC = (9.0 + 64.0 * epsilon) * epsilon * epsilon;

/// Exact sign of (a-c) x (b-c) from the raw coordinates: the last resort.
inline int orient2d_exact(double ax, double ay, double bx, double by, double cx, double cy) noexcept {
    const expansion<2> acx = exact_diff(ax, cx), acy = exact_diff(ay, cy);
    const expansion<2> bcx = exact_diff(bx, cx), bcy = exact_diff(by, cy);
    expansion<8> l, r;
    expansion_product(acx, bcy, l);
    expansion_product(acy, bcx, r);
    expansion<16> d;
    expansion_diff(l, r, d);
    return sign(d);
}

/// Stages B and C of the adaptive orientation test (Shewchuk 1997, section 6), then exact.
/// Kept out of line: the filter in orient2d() settles nearly every call.
[[gnu::noinline]] inline int orient2d_adaptive(double ax, double ay, double bx, double by, double cx, double cy,
                                               double detsum) noexcept {
    const double acx = ax - cx, bcx = bx - cx, acy = ay - cy, bcy = by - cy;
    // Stage B: exact products of the rounded differences.
    const expansion<4> b = two_two_diff_products(acx, bcy, acy, bcx);
    double det = b.estimate();
    double errbound = ccwerrboundB * detsum;
    if (det >= errbound || -det >= errbound) return (det > 0) - (det < 0);

    const double acxtail = two_diff_tail(ax, cx, acx), bcxtail = two_diff_tail(bx, cx, bcx);
    const double acytail = two_diff_tail(ay, cy, acy), bcytail = two_diff_tail(by, cy, bcy);
    // The differences were exact, so stage B's expansion is the exact determinant.
    if (acxtail == 0.0 && acytail == 0.0 && bcxtail == 0.0 && bcytail == 0.0) return sign(b);

    // Stage C: first-order correction from the difference tails.
    errbound = ccwerrboundC * detsum + resulterrbound * std::fabs(det);
    det += (acx * bcytail + bcy * acxtail) - (acy * bcxtail + bcx * acytail);
    if (det >= errbound || -det >= errbound) return (det > 0) - (det < 0);

    return orient2d_exact(ax, ay, bx, by, cx, cy);
}

}  // namespace detail

/// Sign of the orientation of (a, b, c): +1 if c lies left of the directed line a->b
/// (counter-clockwise turn), -1 if right, 0 if the three points are collinear. Exact.
///
/// Complexity: O(1); a handful of flops unless the points are nearly collinear.
/// Preconditions: every coordinate satisfies in_predicate_range() (checked by callers such as
/// delaunay_triangulation; out-of-range input may give a wrong sign).
/// Errors: none.
inline int orient2d(double ax, double ay, double bx, double by, double cx, double cy) noexcept {
    const double detleft = (ax - cx) * (by - cy);
    const double detright = (ay - cy) * (bx - cx);
    const double det = detleft - detright;
    double detsum;
    if (detleft > 0.0) {
        if (detright <= 0.0) return det > 0.0 ? 1 : (det < 0.0 ? -1 : 0);
        detsum = detleft + detright;
    } else if (detleft < 0.0) {
        if (detright >= 0.0) return det > 0.0 ? 1 : (det < 0.0 ? -1 : 0);
        detsum = -detleft - detright;
    } else {
        return det > 0.0 ? 1 : (det < 0.0 ? -1 : 0);
    }
    const double errbound = detail::ccwerrboundA * detsum;
    if (det >= errbound || -det >= errbound) return det > 0.0 ? 1 : -1;
    return detail::orient2d_adaptive(ax, ay, bx, by, cx, cy, detsum);
}

}  // namespace hmira::predicates
