// hmira/algorithms/spatial/detail/solid_angle.hpp
// The signed solid angle of one triangle: the term the generalised winding number sums, shared
// by winding_number and voxelize's fill of open meshes.
#pragma once

#include <cmath>

#include "../../../core/vec3.hpp"

namespace hmira::detail::spatial {

/// The signed solid angle of triangle a, b, c seen from the origin (Van Oosterom and
/// Strackee's formula), positive when the triangle winds counter-clockwise seen from the
/// origin's far side: the winding number is the sum over the triangles over 4 pi.
inline double solid_angle(vec3<double> a, vec3<double> b, vec3<double> c) {
    const double la = norm(a), lb = norm(b), lc = norm(c);
    const double num = dot(a, cross(b, c));
    const double den = la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb;
    return 2 * std::atan2(num, den);
}

}  // namespace hmira::detail::spatial
