// hmira/algorithms/conversion/detail/triangle_box.hpp
// Separating-axis test between a triangle and an axis-aligned box in floating point (the 13
// axes of Akenine-Moller's formulation: 3 box normals, the triangle normal, 9 edge cross
// products). Touching counts as overlapping; where a box only touches the triangle, rounding
// may decide either way, so the voxelizer widens the tester's intervals (voxelize.hpp).
#pragma once

#include <algorithm>
#include <cmath>

#include "../../../core/vec3.hpp"

namespace hmira::detail {

/// Whether the triangle (a, b, c) meets the closed box of half-size h around `center`.
/// The caller has already checked the three box normals (bounding boxes overlap).
inline bool triangle_box_overlap(const vec3<double>& center, double h, vec3<double> a, vec3<double> b, vec3<double> c) {
    a -= center;
    b -= center;
    c -= center;
    const vec3<double> e[3] = {b - a, c - b, a - c};
    // Plane of the triangle against the box.
    const vec3<double> n = cross(e[0], e[1]);
    const double d = dot(n, a);
    const double rn = h * (std::abs(n.x) + std::abs(n.y) + std::abs(n.z));
    if (d > rn || d < -rn) return false;
    // Cross products of the box axes with the edges. For axis x cross e, the axis is
    // (0, -e.z, e.y); the radius of the box on it is h * (|e.z| + |e.y|).
    for (const auto& ed : e) {
        const double ax[3][3] = {{0, -ed.z, ed.y}, {ed.z, 0, -ed.x}, {-ed.y, ed.x, 0}};
        for (const auto& u : ax) {
            const double pa = u[0] * a.x + u[1] * a.y + u[2] * a.z;
            const double pb = u[0] * b.x + u[1] * b.y + u[2] * b.z;
            const double pc = u[0] * c.x + u[1] * c.y + u[2] * c.z;
            const double r = h * (std::abs(u[0]) + std::abs(u[1]) + std::abs(u[2]));
            if (std::min({pa, pb, pc}) > r || std::max({pa, pb, pc}) < -r) return false;
        }
    }
    return true;
}

/// The same test prepared once per triangle for many boxes of one half-size: the plane and
/// the nine edge axes with the triangle's projection interval widened by the box's radius on
/// each, so a box costs ten dot products with its centre.
class triangle_box_tester {
public:
    triangle_box_tester(const vec3<double>& a, const vec3<double>& b, const vec3<double>& c, double h) : origin_(a) {
        const vec3<double> e[3] = {b - a, c - b, a - c};
        // Projections are taken relative to corner a, as the direct test takes them relative
        // to the box: a box face in the triangle's plane (or through an edge) then ties
        // exactly instead of by how n.a and n.centre happen to round.
        const vec3<double> zero{0, 0, 0}, rb = b - a, rc = c - a;
        add(cross(e[0], e[1]), zero, rb, rc, h);
        for (const auto& ed : e) {
            add({0, -ed.z, ed.y}, zero, rb, rc, h);
            add({ed.z, 0, -ed.x}, zero, rb, rc, h);
            add({-ed.y, ed.x, 0}, zero, rb, rc, h);
        }
    }
    /// Whether the closed box of half-size h around `center` meets the triangle (the box
    /// normals are the caller's: bounding boxes must overlap).
    bool overlaps(const vec3<double>& centre) const noexcept {
        const vec3<double> center = centre - origin_;
        bool ok = true;
        for (int q = 0; q < 10; ++q) {
            const double p = axis_[q].x * center.x + axis_[q].y * center.y + axis_[q].z * center.z;
            ok &= (p >= lo_[q]) & (p <= hi_[q]);
        }
        return ok;
    }

    /// overlaps() for a box whose centre is already known to pass the three axes D x edge (the
    /// edge normals of the triangle's shadow along axis D): the other seven axes only.
    template <int D>
    bool overlaps_off(const vec3<double>& centre) const noexcept {
        const vec3<double> center = centre - origin_;
        bool ok = true;
        for (int q = 0; q < 10; ++q) {
            if (q > 0 && (q - 1) % 3 == D) continue;
            const double p = axis_[q].x * center.x + axis_[q].y * center.y + axis_[q].z * center.z;
            ok &= (p >= lo_[q]) & (p <= hi_[q]);
        }
        return ok;
    }

    /// The plane's part of overlaps() alone: whether the triangle's plane meets the box. Where
    /// the box's shadow along an axis lies inside the triangle's, this decides overlaps().
    bool meets_plane(const vec3<double>& centre) const noexcept {
        const vec3<double> center = centre - origin_;
        const double p = axis_[0].x * center.x + axis_[0].y * center.y + axis_[0].z * center.z;
        return p >= lo_[0] && p <= hi_[0];
    }

    /// Axis q (0: the normal, 1 + 3 e + a: box axis a x edge e), its interval (the triangle's
    /// projection widened by the box's radius) and the corner projections are relative to:
    /// for callers that share the parts of the projection that many boxes have in common.
    ///@{
    const vec3<double>& axis(int q) const noexcept { return axis_[q]; }
    double lo(int q) const noexcept { return lo_[q]; }
    double hi(int q) const noexcept { return hi_[q]; }
    const vec3<double>& origin() const noexcept { return origin_; }
    ///@}

private:
    void add(const vec3<double>& u, const vec3<double>& a, const vec3<double>& b, const vec3<double>& c, double h) {
        const double pa = dot(u, a), pb = dot(u, b), pc = dot(u, c);
        const double r = h * (std::abs(u.x) + std::abs(u.y) + std::abs(u.z));
        // Separated when min(p) - centre > r or max(p) - centre < -r.
        axis_[n_] = u;
        lo_[n_] = std::min({pa, pb, pc}) - r;
        hi_[n_] = std::max({pa, pb, pc}) + r;
        ++n_;
    }
    vec3<double> origin_;
    vec3<double> axis_[10];
    double lo_[10], hi_[10];
    int n_ = 0;
};

}  // namespace hmira::detail
