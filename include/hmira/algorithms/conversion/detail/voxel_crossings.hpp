// hmira/algorithms/conversion/detail/voxel_crossings.hpp
// Exact ray crossings for the inside fill of voxelize(): which rays along x through voxel
// centres cross a triangle, and the first voxel centre beyond each crossing.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "../../../core/vec3.hpp"
#include "../../../predicates/orient2d.hpp"

namespace hmira::detail::vox {

// The query point is a voxel centre (i, j, k) moved by (eps, eps^2, eps^3), for an infinitely
// small eps: no ray then passes through an edge or a vertex, and no centre lies on the
// surface, so the parity of crossings is always defined and equal for triangles sharing an
// edge. A centre exactly on the surface thus counts as inside where the surface faces -x and
// outside where it faces +x (on a closed mesh: beyond the crossing in +x).

/// Sign of (v - u) x (p - u) in (y, z) for p = (y, z) + (eps^2, eps^3): exact, never 0 unless
/// u == v.
inline int side_perturbed(double uy, double uz, double vy, double vz, double py, double pz) noexcept {
    const int s = predicates::orient2d(uy, uz, vy, vz, py, pz);
    if (s != 0) return s;
    // d/deps of ey * dz - ez * dy with (dy, dz) = (eps, eps^2) (scaled): -ez first, then ey.
    const double ey = vy - uy, ez = vz - uz;  // signs of differences are exact
    if (ez != 0) return ez > 0 ? -1 : 1;
    return ey > 0 ? 1 : (ey < 0 ? -1 : 0);
}

/// Exact sign of (d - a) . ((b - a) x (c - a)).
inline int orient3d_exact(const vec3<double>& a, const vec3<double>& b, const vec3<double>& c,
                          const vec3<double>& d) noexcept {
    using namespace predicates::detail;
    const expansion<2> bx = exact_diff(b.x, a.x), by = exact_diff(b.y, a.y), bz = exact_diff(b.z, a.z);
    const expansion<2> cx = exact_diff(c.x, a.x), cy = exact_diff(c.y, a.y), cz = exact_diff(c.z, a.z);
    const expansion<2> dx = exact_diff(d.x, a.x), dy = exact_diff(d.y, a.y), dz = exact_diff(d.z, a.z);
    auto minor = [](const expansion<2>& p, const expansion<2>& q, const expansion<2>& r, const expansion<2>& s) {
        expansion<8> l, m;
        expansion_product(p, q, l);
        expansion_product(r, s, m);
        expansion<16> out;
        expansion_diff(l, m, out);
        return out;
    };
    const expansion<16> nx = minor(by, cz, bz, cy), ny = minor(bz, cx, bx, cz), nz = minor(bx, cy, by, cx);
    expansion<64> tx, ty, tz;
    expansion_product(nx, dx, tx);
    expansion_product(ny, dy, ty);
    expansion_product(nz, dz, tz);
    expansion<128> s1;
    expansion_sum(tx, ty, s1);
    expansion<192> s2;
    expansion_sum(s1, tz, s2);
    return sign(s2);
}

/// std::floor of a finite x without a libm call (the x86-64 baseline has no roundsd): from
/// 2^52 on every double is an integer.
inline double floor_exact(double x) noexcept {
    if (!(std::abs(x) < 0x1p52)) return x;
    const double t = double(static_cast<long long>(x));
    return t - double(t > x);
}

/// One triangle, prepared for the crossings of the rays y = j, z = k (voxel units).
struct crossing_triangle {
    vec3<double> a, b, c;
    int orient = 0;  // exact orientation of the (y, z) shadow; 0: seen edge-on, no crossing
    vec3<double> n;  // (b - a) x (c - a), rounded
    double offset = 0, xmin = 0, xmax = 0, ymin = 0, ymax = 0, zmin = 0, zmax = 0;
    // 1 / n.x: first_beyond()'s estimate only needs to be within its tolerance (1e-9
    // relative), so a multiplication replaces two divisions per ray.
    double inv_nx = 0;

    crossing_triangle(const vec3<double>& p0, const vec3<double>& p1, const vec3<double>& p2) : a(p0), b(p1), c(p2) {
        orient = predicates::orient2d(a.y, a.z, b.y, b.z, c.y, c.z);
        n = cross(b - a, c - a);
        offset = dot(n, a);
        inv_nx = 1 / n.x;
        xmin = std::min({a.x, b.x, c.x});
        xmax = std::max({a.x, b.x, c.x});
        ymin = std::min({a.y, b.y, c.y});
        ymax = std::max({a.y, b.y, c.y});
        zmin = std::min({a.z, b.z, c.z});
        zmax = std::max({a.z, b.z, c.z});
    }

    /// Whether the (perturbed) ray through (j, k) crosses the triangle. Requires orient != 0.
    bool crossed_by(double j, double k) const noexcept {
        return side_perturbed(b.y, b.z, c.y, c.z, j, k) == orient &&
               side_perturbed(c.y, c.z, a.y, a.z, j, k) == orient && side_perturbed(a.y, a.z, b.y, b.z, j, k) == orient;
    }

    /// Whether voxel centre (i, j, k), perturbed, lies beyond the crossing in +x. Exact.
    bool beyond(double i, double j, double k) const noexcept {
        const int s = orient3d_exact(a, b, c, {i, j, k});
        // f(p + (eps, ..)) = f(p) + n.x eps + ..., and sign(n.x) == orient.
        return s == 0 || s == orient;
    }

    /// The plane's x along the rays of row k with j in [j0, j1], prepared once per row: x
    /// = base - j * slope, within `tol` of the exact crossing (tol bounds the rounding of n,
    /// offset and these products, a few ulps, by 1e-9 of the magnitudes involved).
    struct row_estimate {
        double base = 0, slope = 0, tol = 0;
    };
    row_estimate along_row(long long k, long long j0, long long j1) const noexcept {
        const double dk = double(k);
        const double jmax = std::max(std::abs(double(j0)), std::abs(double(j1)));
        row_estimate r;
        r.base = (offset - n.z * dk) * inv_nx;
        r.slope = n.y * inv_nx;
        r.tol = 1e-9 * (1.0 + std::max(std::abs(xmin), std::abs(xmax)) +
                        (std::abs(offset) + std::abs(n.y) * jmax + std::abs(n.z * dk)) * std::abs(inv_nx));
        return r;
    }

    /// The first integer i whose centre lies beyond the crossing of ray (j, k), which must
    /// cross the triangle; `r` is along_row(k, ..) for a range holding j. Exact: the rounded
    /// plane gives it unless it lies near an integer.
    long long first_beyond(const row_estimate& r, long long j, long long k) const noexcept {
        const double dj = double(j), dk = double(k);
        double x = r.base - dj * r.slope;
        if (!(x >= xmin - 1 && x <= xmax + 1)) {  // also NaN and infinity
            // Nearly edge-on: search [floor(xmin), ceil(xmax) + 1] exactly (beyond is monotone).
            long long l = static_cast<long long>(std::floor(xmin)), h = static_cast<long long>(std::ceil(xmax)) + 1;
            while (l < h) {
                const long long m = l + (h - l) / 2;
                if (beyond(double(m), dj, dk))
                    h = m;
                else
                    l = m + 1;
            }
            return l;
        }
        x = x < xmin ? xmin : x;  // (ternaries rather than std::clamp: see fast_floor in voxelize.hpp)
        x = x > xmax ? xmax : x;
        const double f = floor_exact(x);
        const double frac = x - f;
        if (frac > r.tol && 1 - frac > r.tol) return static_cast<long long>(f) + 1;
        // Close to integer m = round(x): m itself, or m + 1, is the first beyond.
        const long long m = static_cast<long long>(frac > 0.5 ? f + 1 : f);
        if (!beyond(double(m), dj, dk)) return m + 1;
        if (beyond(double(m - 1), dj, dk)) return m - 1;  // not reached unless x was off by a whole voxel
        return m;
    }

    /// first_beyond() of one ray.
    long long first_beyond(long long j, long long k) const noexcept { return first_beyond(along_row(k, j, j), j, k); }

    /// Calls fn(j, k, along_row(k, ..)) for every ray (j, k) with j in [j0, j1], k in [k0, k1]
    /// crossing the triangle. Per row k the rays crossing it are a run of j (the shadow is
    /// convex) between the two edges the line z = k meets: where the line passes no corner and
    /// both ends lie farther than their rounding from an integer, the rounded ends give the run;
    /// otherwise exact tests find its ends. The run's inside is never tested again.
    template <class Fn>
    void for_each_ray(long long j0, long long j1, long long k0, long long k1, Fn&& fn) const {
        if (orient == 0) return;
        j0 = std::max<long long>(j0, static_cast<long long>(std::ceil(ymin)) - 1);
        j1 = std::min<long long>(j1, static_cast<long long>(std::floor(ymax)) + 1);
        k0 = std::max<long long>(k0, static_cast<long long>(std::ceil(zmin)) - 1);
        k1 = std::min<long long>(k1, static_cast<long long>(std::floor(zmax)) + 1);
        if (j0 > j1 || k0 > k1) return;
        const vec3<double>* p[3] = {&a, &b, &c};
        // An edge's y at z = k, u.y + t (v.y - u.y) with t = (k - u.z) / (v.z - u.z) in [0, 1],
        // is within 11 eps max(|y|) of the exact one (three roundings in t, two in the product,
        // one in the sum); 2^-40 leaves a factor of some 700.
        const double ytol = 0x1p-40 * (1 + std::max(std::abs(ymin), std::abs(ymax)));
        for (long long k = k0; k <= k1; ++k) {
            const double dk = double(k);
            // Where the edges meet the line z = k, rounded: the run's ends up to rounding.
            double ya = std::numeric_limits<double>::infinity(), yb = -ya;
            bool between_corners =
                true;  // the line meets edges only strictly between their corners (exact comparisons)
            for (int e = 0; e < 3; ++e) {
                const vec3<double>& u = *p[e];
                const vec3<double>& v = *p[(e + 1) % 3];
                const double zl = std::min(u.z, v.z), zh = std::max(u.z, v.z);
                if (dk < zl - 1e-9 || dk > zh + 1e-9) continue;
                between_corners &= dk > zl && dk < zh;
                double y;
                if (zh - zl <= 0) {
                    ya = std::min({ya, u.y, v.y});
                    yb = std::max({yb, u.y, v.y});
                    continue;
                }
                const double t = std::clamp((dk - u.z) / (v.z - u.z), 0.0, 1.0);
                y = u.y + t * (v.y - u.y);
                ya = std::min(ya, y);
                yb = std::max(yb, y);
            }
            if (!(ya <= yb)) continue;
            if (between_corners) {
                // The exact run is the integers strictly between the exact ends, which lie
                // within ytol of ya and yb: unless an integer lies that close, the rounded
                // ends settle it.
                const double fa = floor_exact(ya), fb = floor_exact(yb);
                if (ya - fa > ytol && fa + 1 - ya > ytol && yb - fb > ytol && fb + 1 - yb > ytol) {
                    const long long lo = std::max<long long>(j0, static_cast<long long>(fa) + 1);
                    const long long hi = std::min<long long>(j1, static_cast<long long>(fb));
                    if (lo > hi) continue;
                    const row_estimate row = along_row(k, lo, hi);
                    for (long long j = lo; j <= hi; ++j) fn(j, k, row);
                    continue;
                }
            }
            long long lo = std::max<long long>(j0, static_cast<long long>(std::ceil(ya)) - 1);
            long long hi = std::min<long long>(j1, static_cast<long long>(std::floor(yb)) + 1);
            if (lo > hi) continue;
            const double ddk = dk;
            auto inside = [&](long long j) { return crossed_by(double(j), ddk); };
            // Lower end: lo is just below the rounded run, so normally outside.
            if (inside(lo)) {
                while (lo > j0 && inside(lo - 1)) --lo;
            } else {
                ++lo;
                while (lo <= hi && !inside(lo)) ++lo;
                if (lo > hi) continue;
            }
            if (inside(hi)) {
                while (hi < j1 && inside(hi + 1)) ++hi;
            } else {
                --hi;
                while (hi > lo && !inside(hi)) --hi;
            }
            const row_estimate row = along_row(k, lo, hi);
            for (long long j = lo; j <= hi; ++j) fn(j, k, row);
        }
    }
};

}  // namespace hmira::detail::vox
