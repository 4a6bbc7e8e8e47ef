// hmira/algorithms/conversion/detail/triangle_box.hpp
// Exact separating-axis test between a triangle and an axis-aligned box (the 13 axes of
// Akenine-Moller's formulation: 3 box normals, the triangle normal, 9 edge cross products).
// Touching counts as overlapping, so a voxelization built on it is conservative.
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

}  // namespace hmira::detail
