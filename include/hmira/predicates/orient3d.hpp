// hmira/predicates/orient3d.hpp
// Exact orientation of four points in space: a floating-point filter that decides almost every
// call, then Shewchuk's adaptive stage B, then exact expansion arithmetic. The sign is always
// the sign of the exact determinant, whatever the compiler flags (see detail/expansion.hpp).
#pragma once

#include <cmath>

#include "detail/expansion.hpp"
#include "orient2d.hpp"

namespace hmira::predicates {
namespace detail {

inline constexpr double o3derrboundA = (7.0 + 56.0 * epsilon) * epsilon;
inline constexpr double o3derrboundB = (3.0 + 28.0 * epsilon) * epsilon;

/// u x v . w for vectors given as exact expansions: the exact determinant of three rows.
inline expansion<192> triple_product(const expansion<2> (&u)[3], const expansion<2> (&v)[3],
                                     const expansion<2> (&w)[3]) noexcept {
    auto cross = [](const expansion<2>& a, const expansion<2>& b, const expansion<2>& c, const expansion<2>& d) {
        expansion<8> l, r;
        expansion_product(a, b, l);
        expansion_product(c, d, r);
        expansion<16> out;
        expansion_diff(l, r, out);
        return out;
    };
    // Expanded along u: u.x (v.y w.z - v.z w.y) + u.y (v.z w.x - v.x w.z) + u.z (v.x w.y - v.y w.x).
    expansion<64> tx, ty, tz;
    expansion_product(cross(v[1], w[2], v[2], w[1]), u[0], tx);
    expansion_product(cross(v[2], w[0], v[0], w[2]), u[1], ty);
    expansion_product(cross(v[0], w[1], v[1], w[0]), u[2], tz);
    expansion<128> xy;
    expansion_sum(tx, ty, xy);
    expansion<192> all;
    expansion_sum(xy, tz, all);
    return all;
}

/// Exact sign of (a-d) . ((b-d) x (c-d)) from the raw coordinates: the last resort.
inline int orient3d_exact(const double* a, const double* b, const double* c, const double* d) noexcept {
    expansion<2> ad[3], bd[3], cd[3];
    for (int i = 0; i < 3; ++i) {
        ad[i] = exact_diff(a[i], d[i]);
        bd[i] = exact_diff(b[i], d[i]);
        cd[i] = exact_diff(c[i], d[i]);
    }
    return sign(triple_product(ad, bd, cd));
}

/// Stage B of the adaptive orientation test (Shewchuk 1997, section 6), then exact.
/// Kept out of line: the filter in orient3d() settles nearly every call.
[[gnu::noinline]] inline int orient3d_adaptive(const double* a, const double* b, const double* c, const double* d,
                                               double permanent) noexcept {
    const double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
    const double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
    const double adz = a[2] - d[2], bdz = b[2] - d[2], cdz = c[2] - d[2];
    // Stage B: exact products of the rounded differences.
    expansion<8> adet, bdet, cdet;
    scale_expansion(two_two_diff_products(bdx, cdy, cdx, bdy), adz, adet);
    scale_expansion(two_two_diff_products(cdx, ady, adx, cdy), bdz, bdet);
    scale_expansion(two_two_diff_products(adx, bdy, bdx, ady), cdz, cdet);
    expansion<16> ab;
    expansion_sum(adet, bdet, ab);
    expansion<24> fin;
    expansion_sum(ab, cdet, fin);
    const double det = fin.estimate();
    const double errbound = o3derrboundB * permanent;
    if (det >= errbound || -det >= errbound) return (det > 0) - (det < 0);
    // The differences were exact, so stage B's expansion is the exact determinant.
    bool exact = true;
    for (int i = 0; i < 3 && exact; ++i)
        exact = two_diff_tail(a[i], d[i], a[i] - d[i]) == 0.0 && two_diff_tail(b[i], d[i], b[i] - d[i]) == 0.0 &&
                two_diff_tail(c[i], d[i], c[i] - d[i]) == 0.0;
    if (exact) return sign(fin);
    return orient3d_exact(a, b, c, d);
}

/// Shewchuk's orientation determinant (a-d) . ((b-d) x (c-d)), with the filter: its exact sign.
inline int orient3d_shewchuk(const double* a, const double* b, const double* c, const double* d) noexcept {
    const double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
    const double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
    const double adz = a[2] - d[2], bdz = b[2] - d[2], cdz = c[2] - d[2];
    const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
    const double cdxady = cdx * ady, adxcdy = adx * cdy;
    const double adxbdy = adx * bdy, bdxady = bdx * ady;
    const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
    const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * std::fabs(adz) +
                             (std::fabs(cdxady) + std::fabs(adxcdy)) * std::fabs(bdz) +
                             (std::fabs(adxbdy) + std::fabs(bdxady)) * std::fabs(cdz);
    const double errbound = o3derrboundA * permanent;
    if (det > errbound || -det > errbound) return det > 0.0 ? 1 : -1;
    if (permanent == 0.0) return 0;  // every product is exactly zero, so is the determinant
    return orient3d_adaptive(a, b, c, d, permanent);
}

}  // namespace detail

/// Sign of the orientation of (a, b, c, d): +1 if d lies on the side of the plane through a, b, c
/// that the normal (b - a) x (c - a) points to (a, b, c counter-clockwise seen from d), -1 on the
/// other side, 0 if the four points are coplanar. Exact. This is CGAL's `orientation(a, b, c, d)`
/// and the opposite of Shewchuk's `orient3d`.
///
/// Complexity: O(1); a few dozen flops unless the points are nearly coplanar.
/// Preconditions: every coordinate satisfies in_predicate_range() (within it no intermediate of
/// the exact stages overflows or underflows; out-of-range input may give a wrong sign).
/// Errors: none.
inline int orient3d(const double* a, const double* b, const double* c, const double* d) noexcept {
    return -detail::orient3d_shewchuk(a, b, c, d);
}

/// The same, on coordinates given one by one.
inline int orient3d(double ax, double ay, double az, double bx, double by, double bz, double cx, double cy, double cz,
                    double dx, double dy, double dz) noexcept {
    const double a[3] = {ax, ay, az}, b[3] = {bx, by, bz}, c[3] = {cx, cy, cz}, d[3] = {dx, dy, dz};
    return orient3d(a, b, c, d);
}

}  // namespace hmira::predicates
