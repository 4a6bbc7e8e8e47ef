// hmira/algorithms/boolean/detail/segment_crossings.hpp
// Where cut segments cross inside one triangle: a triangle cut by two triangles of a
// self-intersecting mesh (or by one of each mesh where one mesh intersects itself) holds segments
// that cross at a point none of the pairs made, the point where three triangles meet. It is added,
// exactly, as the meeting point of the three planes (or of an edge's line and a plane, or of two
// edges' lines, when a segment lies on an edge of a coplanar triangle), and merged with the points
// already there, so cut_triangle only ever splits segments at points, never at crossings.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include "arrangement.hpp"

namespace hmira::detail::boolean {

/// The line a segment of triangle i lies on, when it came from a coplanar triangle j: an edge of i
/// or of j that holds both its ends. False when the segment does not lie on such an edge.
inline bool segment_edge(const arrangement& arr, const std::vector<soup_triangle>& tris, std::uint32_t i,
                         std::uint32_t j, vid a, vid b, std::array<vid, 2>& edge) {
    const int k = arr.drop[i];
    for (const std::uint32_t t : {i, j})
        for (std::size_t m = 0; m < 3; ++m) {
            const vid p = tris[t].v[m], q = tris[t].v[(m + 1) % 3];
            if (predicates::orient2d(k, arr.points[p], arr.points[q], arr.points[a]) == 0 &&
                predicates::orient2d(k, arr.points[p], arr.points[q], arr.points[b]) == 0) {
                edge = {p, q};
                return true;
            }
        }
    return false;
}

/// True when the coplanar triangles i and j share the plane (j is in arr.coplanar[i]).
inline bool coplanar_pair(const arrangement& arr, std::uint32_t i, std::uint32_t j) {
    return std::find(arr.coplanar[i].begin(), arr.coplanar[i].end(), j) != arr.coplanar[i].end();
}

/// The point where segment x (from the pair i, x[2]) and segment y (from i, y[2]) cross properly
/// inside triangle i. False when a segment of a coplanar pair lies on no edge (not produced).
inline bool crossing_point(const arrangement& arr, const std::vector<soup_triangle>& tris, std::uint32_t i,
                           const std::array<vid, 3>& x, const std::array<vid, 3>& y, exact_point& out) {
    const auto& P = arr.points;
    auto corners = [&](std::uint32_t t) {
        return std::array<point3, 3>{P[tris[t].v[0]].explicit_coordinates(), P[tris[t].v[1]].explicit_coordinates(),
                                     P[tris[t].v[2]].explicit_coordinates()};
    };
    const bool cx = coplanar_pair(arr, i, x[2]), cy = coplanar_pair(arr, i, y[2]);
    std::array<vid, 2> ex{}, ey{};
    if (cx && !segment_edge(arr, tris, i, x[2], x[0], x[1], ex)) return false;
    if (cy && !segment_edge(arr, tris, i, y[2], y[0], y[1], ey)) return false;
    auto pos = [&](vid v) { return P[v].explicit_coordinates(); };
    if (cx && cy) {
        out = exact_point(coplanar_crossing(pos(ex[0]), pos(ex[1]), pos(ey[0]), pos(ey[1]), arr.drop[i]));
    } else if (cx || cy) {
        const std::array<vid, 2>& e = cx ? ex : ey;
        const auto c = corners(cx ? y[2] : x[2]);
        out = exact_point(predicates::line_plane_point{pos(e[0]), pos(e[1]), c[0], c[1], c[2]});
    } else {
        out = exact_point(predicates::three_plane_point{corners(i), corners(x[2]), corners(y[2])});
    }
    return true;
}

/// Adds to every triangle the points where its segments cross each other, merges them with the
/// points already there (the first `explicit_count` of them explicit), and renames every
/// triangle's lists. False when a crossing cannot be constructed (a segment of a coplanar pair off
/// every edge; not produced by the pair stage).
/// Complexity: O(s^2) exact orientations per triangle with s segments, and a sort of all points.
inline bool split_crossings(arrangement& arr, const std::vector<soup_triangle>& tris, std::vector<triangle_cuts>& cuts,
                            std::size_t explicit_count) {
    const std::size_t before = arr.points.size();
    // One point per crossing of two segments' supports, whichever triangle finds it (the three
    // triangles that meet at a point each find it): keyed by the sorted triangles of the pairs.
    std::map<std::array<std::uint32_t, 3>, vid> made;
    for (std::uint32_t i = 0; i < tris.size(); ++i) {
        const int k = arr.drop[i];
        if (k < 0) continue;
        const std::vector<std::array<vid, 3>>& segs = cuts[i].tagged;
        const auto& P = arr.points;
        for (std::size_t m = 0; m < segs.size(); ++m)
            for (std::size_t n = m + 1; n < segs.size(); ++n) {
                const auto &x = segs[m], &y = segs[n];
                if (x[0] == y[0] || x[0] == y[1] || x[1] == y[0] || x[1] == y[1]) continue;
                const int a = predicates::orient2d(k, P[x[0]], P[x[1]], P[y[0]]),
                          b = predicates::orient2d(k, P[x[0]], P[x[1]], P[y[1]]);
                if (a * b >= 0) continue;
                const int c = predicates::orient2d(k, P[y[0]], P[y[1]], P[x[0]]),
                          d = predicates::orient2d(k, P[y[0]], P[y[1]], P[x[1]]);
                if (c * d >= 0) continue;
                std::array<std::uint32_t, 3> key{i, x[2], y[2]};
                std::sort(key.begin(), key.end());
                const bool general = !coplanar_pair(arr, i, x[2]) && !coplanar_pair(arr, i, y[2]);
                if (general) {
                    if (const auto it = made.find(key); it != made.end()) {
                        cuts[i].points.push_back(it->second);
                        continue;
                    }
                }
                exact_point p;
                if (!crossing_point(arr, tris, i, x, y, p)) return false;
                arr.points.push_back(p);
                cuts[i].points.push_back(vid(arr.points.size() - 1));
                if (general) made.emplace(key, vid(arr.points.size() - 1));
            }
    }
    if (arr.points.size() == before) return true;
    const std::vector<vid> map = merge_points(arr.points, explicit_count);
    for (triangle_cuts& c : cuts) {
        for (vid& p : c.points) p = map[p];
        for (auto& s : c.segments) s = {std::min(map[s[0]], map[s[1]]), std::max(map[s[0]], map[s[1]])};
        std::sort(c.points.begin(), c.points.end());
        c.points.erase(std::unique(c.points.begin(), c.points.end()), c.points.end());
    }
    return true;
}

}  // namespace hmira::detail::boolean
