// hmira/algorithms/triangulation/triangulate_polygon.hpp
// Triangulation of one plane polygon with holes, by hole bridging and ear clipping on exact
// orientation predicates: what triangulate_faces and the STL writer run per face.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "../../core/result.hpp"
#include "../../predicates/orient2d.hpp"

namespace hmira {

/// A point of a plane polygon.
using point2 = std::array<double, 2>;

namespace detail::triangulation {

inline int orient(const point2& a, const point2& b, const point2& c) {
    return predicates::orient2d(a[0], a[1], b[0], b[1], c[0], c[1]);
}

/// Whether c lies on the closed segment a-b, given that a, b, c are collinear.
inline bool within(const point2& a, const point2& b, const point2& c) {
    return std::min(a[0], b[0]) <= c[0] && c[0] <= std::max(a[0], b[0]) && std::min(a[1], b[1]) <= c[1] &&
           c[1] <= std::max(a[1], b[1]);
}

/// Whether the closed segments a-b and c-d share a point. Exact.
inline bool segments_meet(const point2& a, const point2& b, const point2& c, const point2& d) {
    const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
    if (o1 * o2 < 0 && o3 * o4 < 0) return true;
    return (o1 == 0 && within(a, b, c)) || (o2 == 0 && within(a, b, d)) || (o3 == 0 && within(c, d, a)) ||
           (o4 == 0 && within(c, d, b));
}

/// Whether direction a->b leaves vertex a (between a0 = previous and a1 = next) into the
/// polygon's interior, which lies left of its edges. Exact.
inline bool in_cone(const point2& a0, const point2& a, const point2& a1, const point2& b) {
    if (orient(a, a1, a0) >= 0) return orient(a, b, a0) > 0 && orient(b, a, a1) > 0;  // convex corner
    return !(orient(a, b, a1) >= 0 && orient(b, a, a0) >= 0);
}

/// Index of the loop vertex that is lowest, then leftmost: a convex corner of a simple loop.
inline std::size_t extreme(std::span<const point2> p, const std::vector<std::size_t>& loop) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < loop.size(); ++i) {
        const auto& q = p[loop[i]];
        const auto& b = p[loop[best]];
        if (q[1] < b[1] || (q[1] == b[1] && q[0] < b[0])) best = i;
    }
    return best;
}

/// +1 counter-clockwise, -1 clockwise, for a simple loop. Exact.
inline int loop_orientation(std::span<const point2> p, const std::vector<std::size_t>& loop) {
    const std::size_t n = loop.size(), i = extreme(p, loop);
    return orient(p[loop[(i + n - 1) % n]], p[loop[i]], p[loop[(i + 1) % n]]);
}

/// Whether q lies strictly inside the simple loop (crossing number). Exact; q off the loop.
inline bool inside(std::span<const point2> p, const std::vector<std::size_t>& loop, const point2& q) {
    bool in = false;
    for (std::size_t i = 0, n = loop.size(); i < n; ++i) {
        const auto& a = p[loop[i]];
        const auto& b = p[loop[(i + 1) % n]];
        if ((a[1] > q[1]) != (b[1] > q[1])) {
            // Does the edge cross the ray to +x? Sign of orientation, exact.
            const int o = orient(a, b, q);
            if ((b[1] > a[1]) ? o > 0 : o < 0) in = !in;
        }
    }
    return in;
}

}  // namespace detail::triangulation

/// Triangulates a simple plane polygon with holes.
///
/// `loops[0]` is the outer loop, counter-clockwise; every further loop is a hole, clockwise,
/// strictly inside the outer loop and outside the other holes. Loops hold indices into
/// `points`. The triangles (index triples, counter-clockwise) cover the polygon exactly: their
/// areas sum to the polygon's, and no two overlap. Holes are first joined to the outer loop by
/// bridges to a visible vertex, then ears are clipped; every decision is an exact orientation
/// test, so concave and nearly degenerate polygons come out right. Collinear corners give
/// zero-area triangles only where no other ear exists.
///
/// Errors (nothing returned): errc::invalid_argument for a coordinate that is not finite or
/// out of the exact predicates' range, or an index out of range; errc::degenerate_face for a
/// loop of fewer than three vertices; errc::topology when the loops are not simple (two
/// edges meet elsewhere than at their shared corner, or a point repeats), are wound the wrong
/// way, or a hole is not inside the outer loop. The message names the loop.
/// Complexity: O(n^2) for the simplicity check, n the total number of corners; ear clipping
/// O(n^2) for typical polygons, O(n^3) at worst; each bridge O(n) per candidate vertex.
[[nodiscard]] inline result<std::vector<std::array<std::size_t, 3>>> triangulate_polygon(
    std::span<const point2> points, std::span<const std::vector<std::size_t>> loops) {
    namespace dt = detail::triangulation;
    using triangles = std::vector<std::array<std::size_t, 3>>;
    if (loops.empty()) return fail(errc::degenerate_face, "triangulate_polygon: no outer loop");
    std::size_t total = 0;
    for (std::size_t l = 0; l < loops.size(); ++l) {
        if (loops[l].size() < 3)
            return fail(errc::degenerate_face, "triangulate_polygon: loop " + std::to_string(l) + " has fewer than 3 corners");
        for (auto i : loops[l]) {
            if (i >= points.size())
                return fail(errc::invalid_argument, "triangulate_polygon: loop " + std::to_string(l) + " names point " + std::to_string(i) +
                                                        " of " + std::to_string(points.size()));
            if (!predicates::in_predicate_range(points[i][0]) || !predicates::in_predicate_range(points[i][1]))
                return fail(errc::invalid_argument, "triangulate_polygon: point " + std::to_string(i) +
                                                        " is not finite or out of the exact predicates' range");
        }
        total += loops[l].size();
    }
    // Simple: no two edges of any loops meet, except consecutive edges at their shared corner.
    struct seg {
        std::size_t loop, pos, a, b;
    };
    std::vector<seg> segs;
    segs.reserve(total);
    for (std::size_t l = 0; l < loops.size(); ++l)
        for (std::size_t i = 0, n = loops[l].size(); i < n; ++i) segs.push_back({l, i, loops[l][i], loops[l][(i + 1) % n]});
    for (std::size_t i = 0; i < segs.size(); ++i) {
        const auto& s = segs[i];
        const auto& a = points[s.a];
        const auto& b = points[s.b];
        if (a == b)
            return fail(errc::topology, "triangulate_polygon: loop " + std::to_string(s.loop) + " repeats a point at corner " + std::to_string(s.pos));
        for (std::size_t j = i + 1; j < segs.size(); ++j) {
            const auto& t = segs[j];
            const auto& c = points[t.a];
            const auto& d = points[t.b];
            bool bad;
            const std::size_t k = loops[s.loop].size();
            const bool after = t.loop == s.loop && t.pos == (s.pos + 1) % k;
            const bool before = t.loop == s.loop && s.pos == (t.pos + 1) % k;
            if (after || before) {
                // Consecutive edges p -> shared -> q: only a fold back along one line is a crossing.
                const auto& shared = after ? b : a;
                const auto& p = after ? a : c;
                const auto& q = after ? d : b;
                bad = dt::orient(p, shared, q) == 0 && (dt::within(p, shared, q) || dt::within(shared, q, p));
            } else {
                bad = dt::segments_meet(a, b, c, d);
            }
            if (bad)
                return fail(errc::topology, "triangulate_polygon: the polygon is not simple: edge " + std::to_string(s.pos) + " of loop " +
                                                std::to_string(s.loop) + " meets edge " + std::to_string(t.pos) + " of loop " +
                                                std::to_string(t.loop));
        }
    }
    for (std::size_t l = 0; l < loops.size(); ++l) {
        const int o = dt::loop_orientation(points, loops[l]);
        if (o == 0) return fail(errc::topology, "triangulate_polygon: loop " + std::to_string(l) + " is flat (all corners collinear at its extreme)");
        if ((l == 0) != (o > 0))
            return fail(errc::topology, "triangulate_polygon: loop " + std::to_string(l) + (l == 0 ? " (outer) is not counter-clockwise" : " (a hole) is not clockwise"));
        if (l > 0) {
            if (!dt::inside(points, loops[0], points[loops[l][0]]))
                return fail(errc::topology, "triangulate_polygon: hole loop " + std::to_string(l) + " is not inside the outer loop");
            for (std::size_t k = 1; k < loops.size(); ++k)
                if (k != l && dt::inside(points, loops[k], points[loops[l][0]]))
                    return fail(errc::topology, "triangulate_polygon: hole loop " + std::to_string(l) + " lies inside hole loop " + std::to_string(k));
        }
    }

    // Bridge the holes, rightmost first, each to a visible vertex of the growing outer loop.
    std::vector<std::size_t> poly(loops[0].begin(), loops[0].end());
    std::vector<std::size_t> order;
    for (std::size_t l = 1; l < loops.size(); ++l) order.push_back(l);
    auto rightmost = [&](std::size_t l) {
        std::size_t best = 0;
        for (std::size_t i = 1; i < loops[l].size(); ++i) {
            const auto& q = points[loops[l][i]];
            const auto& b = points[loops[l][best]];
            if (q[0] > b[0] || (q[0] == b[0] && q[1] > b[1])) best = i;
        }
        return best;
    };
    std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
        return points[loops[x][rightmost(x)]][0] > points[loops[y][rightmost(y)]][0];
    });
    std::vector<char> bridged(loops.size(), 0);
    for (const auto l : order) {
        const auto& hole = loops[l];
        const std::size_t n = hole.size(), mi = rightmost(l);
        const auto& m = points[hole[mi]];
        const auto& m0 = points[hole[(mi + n - 1) % n]];
        const auto& m1 = points[hole[(mi + 1) % n]];
        std::vector<std::size_t> cand(poly.size());
        for (std::size_t i = 0; i < poly.size(); ++i) cand[i] = i;
        auto d2 = [&](std::size_t i) {
            const auto& q = points[poly[i]];
            return (q[0] - m[0]) * (q[0] - m[0]) + (q[1] - m[1]) * (q[1] - m[1]);
        };
        std::sort(cand.begin(), cand.end(), [&](std::size_t x, std::size_t y) { return d2(x) < d2(y); });
        auto blocked = [&](const point2& v, const std::vector<std::size_t>& loop) {
            for (std::size_t i = 0, k = loop.size(); i < k; ++i) {
                const auto& a = points[loop[i]];
                const auto& b = points[loop[(i + 1) % k]];
                if (a == v || b == v || a == m || b == m) continue;  // edges at the bridge's ends
                if (dt::segments_meet(a, b, v, m)) return true;
            }
            return false;
        };
        std::size_t chosen = poly.size();
        for (const auto i : cand) {
            const std::size_t k = poly.size();
            const auto& v = points[poly[i]];
            if (!dt::in_cone(points[poly[(i + k - 1) % k]], v, points[poly[(i + 1) % k]], m)) continue;
            if (!dt::in_cone(m0, m, m1, v)) continue;
            bool hit = blocked(v, poly);
            for (std::size_t h = 1; h < loops.size() && !hit; ++h)
                if (!bridged[h]) hit = blocked(v, loops[h]);
            if (!hit) {
                chosen = i;
                break;
            }
        }
        if (chosen == poly.size())
            return fail(errc::topology, "triangulate_polygon: no vertex of the outer loop sees hole loop " + std::to_string(l));
        // poly: ... v, [m, hole after m ..., m], v, ...
        std::vector<std::size_t> splice;
        splice.reserve(n + 2);
        for (std::size_t s = 0; s <= n; ++s) splice.push_back(hole[(mi + s) % n]);
        splice.push_back(poly[chosen]);
        poly.insert(poly.begin() + std::ptrdiff_t(chosen) + 1, splice.begin(), splice.end());
        bridged[l] = 1;
    }

    // Ear clipping on the bridged loop (bridge corners appear twice; an ear ignores points at
    // its own corners' positions).
    const std::size_t n = poly.size();
    std::vector<std::size_t> prev(n), next(n);
    for (std::size_t i = 0; i < n; ++i) {
        prev[i] = (i + n - 1) % n;
        next[i] = (i + 1) % n;
    }
    triangles out;
    out.reserve(n - 2);
    auto is_ear = [&](std::size_t i) {
        const auto& a = points[poly[prev[i]]];
        const auto& b = points[poly[i]];
        const auto& c = points[poly[next[i]]];
        if (dt::orient(a, b, c) <= 0) return false;
        for (std::size_t j = next[next[i]]; j != prev[i]; j = next[j]) {
            const auto& q = points[poly[j]];
            if (q == a || q == b || q == c) continue;
            if (dt::orient(a, b, q) >= 0 && dt::orient(b, c, q) >= 0 && dt::orient(c, a, q) >= 0) return false;
        }
        return true;
    };
    std::size_t left = n, i = 0, misses = 0;
    while (left > 3) {
        if (is_ear(i)) {
            out.push_back({poly[prev[i]], poly[i], poly[next[i]]});
            next[prev[i]] = next[i];
            prev[next[i]] = prev[i];
            i = prev[i];
            --left;
            misses = 0;
            continue;
        }
        i = next[i];
        if (++misses > left) {
            // No proper ear: only collinear corners are left to cut (zero-area triangles).
            std::size_t j = i;
            bool cut = false;
            for (std::size_t s = 0; s < left; ++s, j = next[j]) {
                if (dt::orient(points[poly[prev[j]]], points[poly[j]], points[poly[next[j]]]) == 0) {
                    out.push_back({poly[prev[j]], poly[j], poly[next[j]]});
                    next[prev[j]] = next[j];
                    prev[next[j]] = prev[j];
                    i = prev[j];
                    --left;
                    cut = true;
                    break;
                }
            }
            if (!cut) return fail(errc::topology, "triangulate_polygon: no ear left to clip (the polygon is not simple)");
            misses = 0;
        }
    }
    out.push_back({poly[prev[i]], poly[i], poly[next[i]]});
    return out;
}

}  // namespace hmira
