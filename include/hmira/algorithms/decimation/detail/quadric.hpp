// hmira/algorithms/decimation/detail/quadric.hpp
// Garland-Heckbert error quadrics: the sum of squared distances to a set of planes, kept as a
// symmetric 4x4 matrix (ten numbers), and the point that minimises it.
#pragma once

#include <cmath>
#include <optional>

#include "../../../core/vec3.hpp"

namespace hmira::detail::decimation {

/// Sum over planes n.x + d = 0 (unit n) of (n.x + d)^2, as x^T A x + 2 b.x + c with A
/// symmetric: a_xx a_xy a_xz a_yy a_yz a_zz, b, c.
struct quadric {
    double xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0;
    double bx = 0, by = 0, bz = 0, c = 0;

    /// The plane through p with unit normal n, counted `weight` times. O(1).
    static quadric of_plane(const vec3<double>& n, const vec3<double>& p, double weight = 1) {
        const double d = -dot(n, p);
        return {weight * n.x * n.x, weight * n.x * n.y, weight * n.x * n.z, weight * n.y * n.y, weight * n.y * n.z,
                weight * n.z * n.z, weight * n.x * d,   weight * n.y * d,   weight * n.z * d,   weight * d * d};
    }

    quadric& operator+=(const quadric& q) {
        xx += q.xx, xy += q.xy, xz += q.xz, yy += q.yy, yz += q.yz, zz += q.zz;
        bx += q.bx, by += q.by, bz += q.bz, c += q.c;
        return *this;
    }
    friend quadric operator+(quadric a, const quadric& b) { return a += b; }

    /// The error at p, never negative (rounding can push a zero error below 0). O(1).
    double operator()(const vec3<double>& p) const {
        const double e = p.x * (xx * p.x + 2 * (xy * p.y + xz * p.z + bx)) + p.y * (yy * p.y + 2 * (yz * p.z + by)) +
                         p.z * (zz * p.z + 2 * bz) + c;
        return e > 0 ? e : 0;
    }

    /// The point of least error, or nothing when A is (nearly) singular: the planes do not
    /// pin a point (a flat or cylindrical patch), and the caller falls back to the edge. O(1).
    std::optional<vec3<double>> minimiser() const {
        // Cramer's rule on A x = -b; the cofactors are reused for the determinant.
        const double c00 = yy * zz - yz * yz, c01 = xz * yz - xy * zz, c02 = xy * yz - xz * yy;
        const double det = xx * c00 + xy * c01 + xz * c02;
        const double scale = std::fabs(xx) + std::fabs(yy) + std::fabs(zz);
        // Relative test: a determinant below 1e-9 of the largest possible one means an
        // eigenvalue ratio beyond about 1e-9, where the solution jumps far off the surface.
        if (!(std::fabs(det) > 1e-9 * scale * scale * scale)) return std::nullopt;
        const double c11 = xx * zz - xz * xz, c12 = xy * xz - xx * yz, c22 = xx * yy - xy * xy;
        const double inv = -1.0 / det;
        return vec3<double>{inv * (c00 * bx + c01 * by + c02 * bz), inv * (c01 * bx + c11 * by + c12 * bz),
                            inv * (c02 * bx + c12 * by + c22 * bz)};
    }
};

}  // namespace hmira::detail::decimation
