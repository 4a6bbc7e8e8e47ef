// hmira/predicates/intersect3d.hpp
// Exact yes/no intersection tests between points, segments and triangles in space, all closed
// sets: every decision is a sign of orient3d or orient2d on the input coordinates, so no
// intersection point is ever constructed and no tolerance is involved.
//
// Coplanar configurations are decided in the coordinate planes. For objects known to lie in one
// common plane, they meet in space exactly when their projections meet in all three coordinate
// planes: projecting preserves a meeting, and at least one of the projections is one-to-one on
// the plane (or on the line, for collinear input), where a meeting of projections lifts back.
// Degenerate triangles (collinear or coincident corners) and segments (equal ends) are the point
// sets they are: a flat triangle is the union of its edges.
#pragma once

#include <algorithm>

#include "../core/vec3.hpp"
#include "orient2d.hpp"
#include "orient3d.hpp"

namespace hmira::predicates {

/// A point given to the 3D tests. Every coordinate must satisfy in_predicate_range().
using point3 = vec3<double>;

/// orient3d on points: +1 if d is on the side (b - a) x (c - a) points to, -1 opposite, 0 coplanar.
inline int orient3d(const point3& a, const point3& b, const point3& c, const point3& d) noexcept {
    const double pa[3] = {a.x, a.y, a.z}, pb[3] = {b.x, b.y, b.z}, pc[3] = {c.x, c.y, c.z}, pd[3] = {d.x, d.y, d.z};
    return orient3d(pa, pb, pc, pd);
}

namespace detail {

/// orient2d of the projections that drop coordinate k (the other two in cyclic order).
inline int orient2d_drop(int k, const point3& a, const point3& b, const point3& c) noexcept {
    const std::size_t u = std::size_t((k + 1) % 3), v = std::size_t((k + 2) % 3);
    return orient2d(a[u], a[v], b[u], b[v], c[u], c[v]);
}

/// Closed 1D interval overlap of [min(a, b), max(a, b)] and [min(c, d), max(c, d)].
inline bool intervals_meet(double a, double b, double c, double d) noexcept {
    return std::max(std::min(a, b), std::min(c, d)) <= std::min(std::max(a, b), std::max(c, d));
}

/// Closed segments pq and ab meet, in the projection that drops coordinate k.
inline bool segments_meet_2d(int k, const point3& p, const point3& q, const point3& a, const point3& b) noexcept {
    const int o1 = orient2d_drop(k, p, q, a), o2 = orient2d_drop(k, p, q, b);
    if (o1 * o2 > 0) return false;
    const int o3 = orient2d_drop(k, a, b, p), o4 = orient2d_drop(k, a, b, q);
    if (o3 * o4 > 0) return false;
    if (o1 != 0 || o2 != 0 || o3 != 0 || o4 != 0) return true;
    // All four on one line (or a segment is a point): the projected boxes decide.
    const std::size_t u = std::size_t((k + 1) % 3), v = std::size_t((k + 2) % 3);
    return intervals_meet(p[u], q[u], a[u], b[u]) && intervals_meet(p[v], q[v], a[v], b[v]);
}

/// Closed triangle abc contains p, in the projection that drops coordinate k.
inline bool point_in_triangle_2d(int k, const point3& p, const point3& a, const point3& b, const point3& c) noexcept {
    const int o = orient2d_drop(k, a, b, c);
    if (o == 0)
        return segments_meet_2d(k, p, p, a, b) || segments_meet_2d(k, p, p, b, c) || segments_meet_2d(k, p, p, c, a);
    return orient2d_drop(k, a, b, p) * o >= 0 && orient2d_drop(k, b, c, p) * o >= 0 &&
           orient2d_drop(k, c, a, p) * o >= 0;
}

/// Closed segment pq meets closed triangle abc, in the projection that drops coordinate k.
inline bool segment_triangle_2d(int k, const point3& p, const point3& q, const point3& a, const point3& b,
                                const point3& c) noexcept {
    return point_in_triangle_2d(k, p, a, b, c) || point_in_triangle_2d(k, q, a, b, c) ||
           segments_meet_2d(k, p, q, a, b) || segments_meet_2d(k, p, q, b, c) || segments_meet_2d(k, p, q, c, a);
}

}  // namespace detail

/// True if a, b, c lie on one line (or coincide). Exact.
inline bool collinear(const point3& a, const point3& b, const point3& c) noexcept {
    return detail::orient2d_drop(0, a, b, c) == 0 && detail::orient2d_drop(1, a, b, c) == 0 &&
           detail::orient2d_drop(2, a, b, c) == 0;
}

/// True if the closed segments pq and ab share a point. Either may be a single point. Exact.
inline bool segments_intersect(const point3& p, const point3& q, const point3& a, const point3& b) noexcept {
    if (orient3d(p, q, a, b) != 0) return false;
    return detail::segments_meet_2d(0, p, q, a, b) && detail::segments_meet_2d(1, p, q, a, b) &&
           detail::segments_meet_2d(2, p, q, a, b);
}

/// True if p lies on the closed segment ab (a point when a == b). Exact.
inline bool point_on_segment(const point3& p, const point3& a, const point3& b) noexcept {
    return segments_intersect(p, p, a, b);
}

/// True if p lies in the closed triangle abc (any triangle, flat ones included). Exact.
inline bool point_in_triangle(const point3& p, const point3& a, const point3& b, const point3& c) noexcept {
    if (orient3d(a, b, c, p) != 0) return false;
    return detail::point_in_triangle_2d(0, p, a, b, c) && detail::point_in_triangle_2d(1, p, a, b, c) &&
           detail::point_in_triangle_2d(2, p, a, b, c);
}

/// True if the closed segment pq and the closed triangle abc share a point. Exact.
///
/// A segment crossing the plane of a proper triangle meets it when the three orientations of
/// the line pq against the triangle's edges do not disagree in sign; a segment in the plane is
/// decided in the coordinate planes; a flat triangle is the union of its edges.
/// Complexity: O(1): at most 5 orient3d, or some orient2d in coplanar cases.
inline bool segment_intersects_triangle(const point3& p, const point3& q, const point3& a, const point3& b,
                                        const point3& c) noexcept {
    if (collinear(a, b, c))
        return segments_intersect(p, q, a, b) || segments_intersect(p, q, b, c) || segments_intersect(p, q, c, a);
    const int s = orient3d(a, b, c, p), t = orient3d(a, b, c, q);
    if (s * t > 0) return false;
    if (s == 0 && t == 0)
        return detail::segment_triangle_2d(0, p, q, a, b, c) && detail::segment_triangle_2d(1, p, q, a, b, c) &&
               detail::segment_triangle_2d(2, p, q, a, b, c);
    const int o1 = orient3d(p, q, a, b), o2 = orient3d(p, q, b, c), o3 = orient3d(p, q, c, a);
    return !((o1 > 0 || o2 > 0 || o3 > 0) && (o1 < 0 || o2 < 0 || o3 < 0));
}

/// True if the closed triangles abc and def share a point (any triangles, flat ones included).
/// Exact.
///
/// Two triangles meet exactly when an edge of one meets the other: the intersection is convex,
/// and its extreme points lie on the boundary of one of the two. Triangles strictly on one side
/// of the other's plane are rejected first, with three orient3d.
/// Complexity: O(1): at most 6 segment-triangle tests.
inline bool triangles_intersect(const point3& a, const point3& b, const point3& c, const point3& d, const point3& e,
                                const point3& f) noexcept {
    if (!collinear(a, b, c)) {
        const int sd = orient3d(a, b, c, d), se = orient3d(a, b, c, e), sf = orient3d(a, b, c, f);
        if ((sd > 0 && se > 0 && sf > 0) || (sd < 0 && se < 0 && sf < 0)) return false;
    }
    if (!collinear(d, e, f)) {
        const int sa = orient3d(d, e, f, a), sb = orient3d(d, e, f, b), sc = orient3d(d, e, f, c);
        if ((sa > 0 && sb > 0 && sc > 0) || (sa < 0 && sb < 0 && sc < 0)) return false;
    }
    return segment_intersects_triangle(a, b, d, e, f) || segment_intersects_triangle(b, c, d, e, f) ||
           segment_intersects_triangle(c, a, d, e, f) || segment_intersects_triangle(d, e, a, b, c) ||
           segment_intersects_triangle(e, f, a, b, c) || segment_intersects_triangle(f, d, a, b, c);
}

}  // namespace hmira::predicates
