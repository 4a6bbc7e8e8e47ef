// hmira/algorithms/triangulation/triangulate_polygon.hpp
// Triangulation of one plane polygon with holes, by hole bridging and ear clipping on exact
// orientation predicates: what triangulate_faces and the STL writer run per face.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "../../core/result.hpp"
#include "../../predicates/incircle.hpp"
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

/// An axis-aligned box around the points it holds.
struct box {
    double x0, y0, x1, y1;
};
inline bool overlap(const box& a, const box& b) { return a.x0 <= b.x1 && b.x0 <= a.x1 && a.y0 <= b.y1 && b.y0 <= a.y1; }

/// A bounding-box hierarchy over points, split at the median of the longer side: it follows
/// where the points are, so long curves and dense clusters stay cheap to query, unlike a
/// uniform grid. Every node or point visited adds one to `work`.
class box_tree {
public:
    explicit box_tree(std::vector<box> boxes) : boxes_(std::move(boxes)), order_(boxes_.size()) {
        for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = i;
        nodes_.reserve(2 * (order_.size() / leaf_size + 1));
        if (!order_.empty()) build(0, order_.size());
    }
    std::size_t size() const { return order_.size(); }

    /// Calls f(i) for the points in box q, until f returns true; then returns true. Skips every
    /// node for which skip(its bounds) says that none of its points can matter.
    template <class F, class S>
    bool any_in(const box& q, F&& f, S&& skip, std::size_t& work) const {
        return !order_.empty() && find(0, q, f, skip, work);
    }

private:
    static constexpr std::size_t leaf_size = 8;
    static constexpr std::size_t none = std::size_t(-1);
    struct node {
        box bounds;
        std::size_t begin, end, left = none, right = none;
    };

    std::size_t build(std::size_t begin, std::size_t end) {
        box b = boxes_[order_[begin]];
        for (std::size_t k = begin + 1; k < end; ++k) {
            const auto& c = boxes_[order_[k]];
            b = {std::min(b.x0, c.x0), std::min(b.y0, c.y0), std::max(b.x1, c.x1), std::max(b.y1, c.y1)};
        }
        const std::size_t id = nodes_.size();
        nodes_.push_back({b, begin, end});
        if (end - begin > leaf_size) {
            const bool by_x = b.x1 - b.x0 >= b.y1 - b.y0;
            const std::size_t mid = begin + (end - begin) / 2;
            std::nth_element(order_.begin() + std::ptrdiff_t(begin), order_.begin() + std::ptrdiff_t(mid), order_.begin() + std::ptrdiff_t(end),
                             [&](std::size_t u, std::size_t v) {
                                 const auto& p = boxes_[u];
                                 const auto& q = boxes_[v];
                                 const double cu = by_x ? p.x0 + p.x1 : p.y0 + p.y1, cv = by_x ? q.x0 + q.x1 : q.y0 + q.y1;
                                 return cu < cv || (cu == cv && u < v);
                             });
            const std::size_t l = build(begin, mid);
            const std::size_t r = build(mid, end);
            nodes_[id].left = l;
            nodes_[id].right = r;
        }
        return id;
    }
    template <class F, class S>
    bool find(std::size_t n, const box& q, F& f, S& skip, std::size_t& work) const {
        const auto& nd = nodes_[n];
        ++work;
        if (!overlap(nd.bounds, q) || skip(nd.bounds)) return false;
        if (nd.left == none) {
            for (std::size_t x = nd.begin; x < nd.end; ++x) {
                ++work;
                if (overlap(boxes_[order_[x]], q) && f(order_[x])) return true;
            }
            return false;
        }
        return find(nd.left, q, f, skip, work) || find(nd.right, q, f, skip, work);
    }

    std::vector<box> boxes_;
    std::vector<std::size_t> order_;
    std::vector<node> nodes_;
};

/// Work units (corners looked at by the hole checks, the bridges and the ear tests) allowed
/// per corner, plus a constant: a typical polygon needs a few per corner; past the limit the
/// polygon is refused in bounded time instead of running for hours.
inline constexpr std::size_t work_per_corner = 256;
inline constexpr std::size_t work_base = std::size_t(1) << 26;

/// Lawson's flips: while a diagonal of two triangles has the far corner of one strictly inside
/// the other's circumcircle (exact in-circle test) and the two form a strictly convex
/// quadrilateral, it is replaced by the other diagonal. A side that is not shared, in opposite
/// directions, by exactly two triangles (the loops' edges) is never flipped. Ends with the
/// constrained Delaunay triangulation of the same corners, which maximises the smallest angle.
/// False once `work` passes `limit`.
inline bool flip_to_delaunay(std::span<const point2> p, std::vector<std::array<std::size_t, 3>>& tris, std::size_t& work,
                             std::size_t limit) {
    constexpr std::size_t none = std::size_t(-1);
    const std::size_t sides = 3 * tris.size();
    auto from = [&](std::size_t s) { return tris[s / 3][s % 3]; };
    auto to = [&](std::size_t s) { return tris[s / 3][(s % 3 + 1) % 3]; };
    std::vector<std::size_t> by_key(sides), twin(sides, none);
    for (std::size_t s = 0; s < sides; ++s) by_key[s] = s;
    auto key = [&](std::size_t s) { return std::pair{std::min(from(s), to(s)), std::max(from(s), to(s))}; };
    std::sort(by_key.begin(), by_key.end(), [&](std::size_t x, std::size_t y) { return key(x) < key(y) || (key(x) == key(y) && x < y); });
    work += sides;
    for (std::size_t k = 0; k < sides;) {
        std::size_t e = k + 1;
        while (e < sides && key(by_key[e]) == key(by_key[k])) ++e;
        if (e - k == 2 && from(by_key[k]) == to(by_key[k + 1]) && from(by_key[k]) != to(by_key[k])) {
            twin[by_key[k]] = by_key[k + 1];
            twin[by_key[k + 1]] = by_key[k];
        }
        k = e;
    }
    auto positive = [&](std::size_t a, std::size_t b, std::size_t c) { return orient(p[a], p[b], p[c]) > 0; };
    std::vector<std::size_t> todo;
    for (std::size_t s = 0; s < sides; ++s)
        if (twin[s] != none && s < twin[s]) todo.push_back(s);
    while (!todo.empty()) {
        if (++work > limit) return false;
        const std::size_t s = todo.back();
        todo.pop_back();
        const std::size_t r = twin[s];
        if (r == none) continue;
        const std::size_t t = s / 3, u = r / 3, i = s % 3, j = r % 3;
        // t = (a, b, c) and u = (b, a, d), both counter-clockwise, share the side a-b.
        const std::size_t a = tris[t][i], b = tris[t][(i + 1) % 3], c = tris[t][(i + 2) % 3], d = tris[u][(j + 2) % 3];
        if (!positive(a, b, c) || !positive(b, a, d) || !positive(d, c, a) || !positive(c, d, b)) continue;
        if (predicates::incircle(p[a][0], p[a][1], p[b][0], p[b][1], p[c][0], p[c][1], p[d][0], p[d][1]) <= 0) continue;
        const std::size_t bc = twin[3 * t + (i + 1) % 3], ca = twin[3 * t + (i + 2) % 3];
        const std::size_t ad = twin[3 * u + (j + 1) % 3], db = twin[3 * u + (j + 2) % 3];
        tris[t] = {d, c, a};  // sides d-c (the new diagonal), c-a, a-d
        tris[u] = {c, d, b};  // sides c-d (the new diagonal), d-b, b-c
        const std::size_t outer[4][2] = {{3 * t + 1, ca}, {3 * t + 2, ad}, {3 * u + 1, db}, {3 * u + 2, bc}};
        twin[3 * t] = 3 * u;
        twin[3 * u] = 3 * t;
        for (const auto& [side, other] : outer) {
            twin[side] = other;
            if (other != none) {
                twin[other] = side;
                todo.push_back(side);
            }
        }
    }
    return true;
}

}  // namespace detail::triangulation

/// Options of triangulate_polygon.
struct triangulate_polygon_options {
    /// Flip diagonals until the triangulation is the constrained Delaunay one of the polygon's
    /// corners (Lawson's flips, exact in-circle test): among the triangulations of the same
    /// corners it has the largest smallest angle, so no needless slivers. Costs O(n) typical,
    /// O(n^2) flips at worst (then bounded by the work limit below).
    bool delaunay = false;
};

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
/// way, or a hole is not inside the outer loop. The message names the loop. errc::unsupported
/// for a polygon past the work limit below.
/// Complexity: O(n log n) for the simplicity check (a sweep), n the total number of corners;
/// ear clipping is O(n log n) for typical polygons, since an ear is checked only against the
/// reflex corners in its box (found with a box tree); each hole bridge costs O(n) per
/// candidate vertex. Intricate polygons (many reflex corners inside every ear, or many holes)
/// are refused with errc::unsupported once that work passes 2^26 + 256 n elementary tests, so
/// no input runs unbounded.
[[nodiscard]] inline result<std::vector<std::array<std::size_t, 3>>> triangulate_polygon(
    std::span<const point2> points, std::span<const std::vector<std::size_t>> loops, const triangulate_polygon_options& options = {}) {
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
    const std::size_t work_limit = dt::work_base + dt::work_per_corner * total;
    const auto too_intricate = [&] {
        return fail(errc::unsupported, "triangulate_polygon: the polygon's " + std::to_string(total) +
                                           " corners are too intricate to triangulate within the work limit");
    };
    struct seg {
        std::size_t loop, pos, a, b;
    };
    std::vector<seg> segs;
    std::vector<std::size_t> loop_start;
    segs.reserve(total);
    for (std::size_t l = 0; l < loops.size(); ++l) {
        loop_start.push_back(segs.size());
        for (std::size_t i = 0, n = loops[l].size(); i < n; ++i) segs.push_back({l, i, loops[l][i], loops[l][(i + 1) % n]});
    }
    std::size_t work = 0;
    auto crossing = [&](const seg& s, const seg& t) {
        const auto& a = points[s.a];
        const auto& b = points[s.b];
        const auto& c = points[t.a];
        const auto& d = points[t.b];
        const std::size_t k = loops[s.loop].size();
        const bool after = t.loop == s.loop && t.pos == (s.pos + 1) % k;
        const bool before = t.loop == s.loop && s.pos == (t.pos + 1) % k;
        if (after || before) {
            // Consecutive edges p -> shared -> q: only a fold back along one line is a crossing.
            const auto& shared = after ? b : a;
            const auto& p = after ? a : c;
            const auto& q = after ? d : b;
            return dt::orient(p, shared, q) == 0 && (dt::within(p, shared, q) || dt::within(shared, q, p));
        }
        return dt::segments_meet(a, b, c, d);
    };
    auto not_simple = [&](std::size_t i, std::size_t j) {
        if (i > j) std::swap(i, j);
        return fail(errc::topology, "triangulate_polygon: the polygon is not simple: edge " + std::to_string(segs[i].pos) + " of loop " +
                                        std::to_string(segs[i].loop) + " meets edge " + std::to_string(segs[j].pos) + " of loop " +
                                        std::to_string(segs[j].loop));
    };
    for (const auto& e : segs)
        if (points[e.a] == points[e.b])
            return fail(errc::topology, "triangulate_polygon: loop " + std::to_string(e.loop) + " repeats a point at corner " + std::to_string(e.pos));
    // Corners in (x, y) order; two corners at one point make the polygon not simple.
    auto before_pt = [](const point2& p, const point2& q) { return p[0] < q[0] || (p[0] == q[0] && p[1] < q[1]); };
    std::vector<std::size_t> corners(segs.size());  // edge i starts at corner i
    for (std::size_t i = 0; i < corners.size(); ++i) corners[i] = i;
    std::sort(corners.begin(), corners.end(), [&](std::size_t i, std::size_t j) {
        const auto& p = points[segs[i].a];
        const auto& q = points[segs[j].a];
        return before_pt(p, q) || (p == q && i < j);
    });
    for (std::size_t k = 0; k + 1 < corners.size(); ++k)
        if (points[segs[corners[k]].a] == points[segs[corners[k + 1]].a]) return not_simple(corners[k], corners[k + 1]);
    // A sweep over the corners in that order keeps the edges that span the sweep line sorted
    // from bottom to top. The first point where two edges meet lies between neighbours in that
    // order (Shamos and Hoey), so testing neighbours finds it in O(n log n).
    auto lo = [&](std::size_t e) -> const point2& {
        return before_pt(points[segs[e].a], points[segs[e].b]) ? points[segs[e].a] : points[segs[e].b];
    };
    auto hi = [&](std::size_t e) -> const point2& {
        return before_pt(points[segs[e].a], points[segs[e].b]) ? points[segs[e].b] : points[segs[e].a];
    };
    // Whether edge u lies below edge v where both span the sweep line; exact. Ties (edges that
    // touch, which the neighbour tests then report) fall back to the index, to stay a strict order.
    auto below = [&](std::size_t u, std::size_t v) {
        if (u == v) return false;
        const auto &ul = lo(u), &ur = hi(u), &vl = lo(v), &vr = hi(v);
        int o;
        if (ul == vl) {
            o = dt::orient(ul, ur, vr);
        } else if (before_pt(ul, vl)) {
            o = dt::orient(ul, ur, vl);
            if (o == 0) o = dt::orient(ul, ur, vr);
        } else {
            o = -dt::orient(vl, vr, ul);
            if (o == 0) o = -dt::orient(vl, vr, ur);
        }
        return o != 0 ? o > 0 : u < v;
    };
    std::set<std::size_t, decltype(below)> status(below);
    std::vector<typename std::set<std::size_t, decltype(below)>::iterator> where(segs.size(), status.end());
    std::size_t bad_i = segs.size(), bad_j = segs.size();
    auto test = [&](std::size_t u, std::size_t v) {
        if (bad_i == segs.size() && crossing(segs[u], segs[v])) {
            bad_i = u;
            bad_j = v;
        }
    };
    auto test_around = [&](std::size_t e) {
        const auto it = where[e];
        if (it != status.begin()) {
            const auto lower = std::prev(it);
            test(*lower, e);
        }
        if (const auto upper = std::next(it); upper != status.end()) test(e, *upper);
    };
    for (const auto c : corners) {
        const std::size_t l = segs[c].loop, k = loops[l].size();
        const std::size_t into = loop_start[l] + (segs[c].pos + k - 1) % k;  // the edge that ends at corner c
        const auto& here = points[segs[c].a];
        for (const auto e : {into, c})
            if (hi(e) == here && where[e] != status.end()) {
                test_around(e);
                const auto after = status.erase(where[e]);
                where[e] = status.end();
                if (after != status.begin() && after != status.end()) {
                    const auto lower = std::prev(after);
                    test(*lower, *after);
                }
            }
        for (const auto e : {into, c})
            if (lo(e) == here) {
                where[e] = status.insert(e).first;
                test_around(e);
            }
        if (bad_i != segs.size()) return not_simple(bad_i, bad_j);
    }
    status.clear();
    segs = {};
    for (std::size_t l = 0; l < loops.size(); ++l) {
        const int o = dt::loop_orientation(points, loops[l]);
        if (o == 0) return fail(errc::topology, "triangulate_polygon: loop " + std::to_string(l) + " is flat (all corners collinear at its extreme)");
        if ((l == 0) != (o > 0))
            return fail(errc::topology, "triangulate_polygon: loop " + std::to_string(l) + (l == 0 ? " (outer) is not counter-clockwise" : " (a hole) is not clockwise"));
        if (l > 0) {
            if (!dt::inside(points, loops[0], points[loops[l][0]]))
                return fail(errc::topology, "triangulate_polygon: hole loop " + std::to_string(l) + " is not inside the outer loop");
            work += loops[0].size();
            for (std::size_t k = 1; k < loops.size(); ++k) {
                if (k != l && dt::inside(points, loops[k], points[loops[l][0]]))
                    return fail(errc::topology, "triangulate_polygon: hole loop " + std::to_string(l) + " lies inside hole loop " + std::to_string(k));
                work += loops[k].size();
            }
            if (work > work_limit) return too_intricate();
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
            work += loop.size();
            for (std::size_t i = 0, k = loop.size(); i < k; ++i) {
                const auto& a = points[loop[i]];
                const auto& b = points[loop[(i + 1) % k]];
                if (a == v || b == v || a == m || b == m) continue;  // edges at the bridge's ends
                if (dt::segments_meet(a, b, v, m)) return true;
            }
            return false;
        };
        std::size_t chosen = poly.size();
        work += poly.size();
        for (const auto i : cand) {
            if (work > work_limit) return too_intricate();
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
    // its own corners' positions). Only a corner that is not strictly convex can lie in an ear:
    // of the corners inside a triangle, the one farthest from its base would be reflex. So
    // the test looks up just those corners, by grid cell, which keeps big polygons near-linear.
    const std::size_t n = poly.size();
    std::vector<std::size_t> prev(n), next(n);
    for (std::size_t i = 0; i < n; ++i) {
        prev[i] = (i + n - 1) % n;
        next[i] = (i + 1) % n;
    }
    auto at = [&](std::size_t j) -> const point2& { return points[poly[j]]; };
    auto convex = [&](std::size_t j) { return dt::orient(at(prev[j]), at(j), at(next[j])) > 0; };
    // The listed corners: a box tree over those listed when it was last built, plus a short
    // list of those listed since (a neighbour of a clipped ear that is flat or folded).
    std::vector<char> alive(n, 1), is_listed(n, 0);
    std::vector<std::size_t> in_tree, recent;
    std::size_t dead_in_tree = 0;
    auto point_box = [&](std::size_t j) { return dt::box{at(j)[0], at(j)[1], at(j)[0], at(j)[1]}; };
    auto make_tree = [&] {
        std::vector<dt::box> boxes;
        boxes.reserve(in_tree.size());
        for (const auto j : in_tree) boxes.push_back(point_box(j));
        work += in_tree.size();
        return dt::box_tree(std::move(boxes));
    };
    for (std::size_t j = 0; j < n; ++j)
        if (!convex(j)) {
            is_listed[j] = 1;  // 1: in the tree, 2: in `recent`
            in_tree.push_back(j);
        }
    dt::box_tree tree = make_tree();
    auto relist = [&](std::size_t j) {  // after j's neighbours changed
        const bool reflex_or_flat = !convex(j);
        if (is_listed[j] && !reflex_or_flat) {
            dead_in_tree += is_listed[j] == 1;
            is_listed[j] = 0;
        } else if (!is_listed[j] && reflex_or_flat) {
            is_listed[j] = 2;
            recent.push_back(j);
        }
    };
    auto clip = [&](std::size_t j) {
        next[prev[j]] = next[j];
        prev[next[j]] = prev[j];
        alive[j] = 0;
        dead_in_tree += is_listed[j] == 1;
        is_listed[j] = 0;
        // A neighbour's corner only narrows: a reflex one may turn convex and leave the list; a
        // convex one joins it only by folding flat (rare, so `recent` stays short).
        relist(prev[j]);
        relist(next[j]);
        if (2 * dead_in_tree > in_tree.size() + 64 || recent.size() > 64 + in_tree.size() / 8) {  // rebuild, amortised
            std::erase_if(in_tree, [&](std::size_t k) { return is_listed[k] != 1; });
            for (const auto k : recent)
                if (is_listed[k] == 2) {
                    in_tree.push_back(k);
                    is_listed[k] = 1;
                }
            recent.clear();
            dead_in_tree = 0;
            tree = make_tree();
        }
    };
    triangles out;
    out.reserve(n - 2);
    auto is_ear = [&](std::size_t i) {
        const auto& a = at(prev[i]);
        const auto& b = at(i);
        const auto& c = at(next[i]);
        ++work;
        if (dt::orient(a, b, c) <= 0) return false;
        const double x0 = std::min({a[0], b[0], c[0]}), x1 = std::max({a[0], b[0], c[0]});
        const double y0 = std::min({a[1], b[1], c[1]}), y1 = std::max({a[1], b[1], c[1]});
        auto blocks = [&](std::size_t j) {
            ++work;
            if (!alive[j] || j == prev[i] || j == i || j == next[i]) return false;
            const auto& q = at(j);
            if (q[0] < x0 || q[0] > x1 || q[1] < y0 || q[1] > y1 || q == a || q == b || q == c) return false;
            return dt::orient(a, b, q) >= 0 && dt::orient(b, c, q) >= 0 && dt::orient(c, a, q) >= 0 && !convex(j);
        };
        // A node whose four corners all lie strictly outside one edge of the ear holds no point
        // of it (a half-plane is convex): this keeps thin ears from visiting all of their box.
        auto outside = [&](const dt::box& nb) {
            const point2 k[4] = {{nb.x0, nb.y0}, {nb.x1, nb.y0}, {nb.x0, nb.y1}, {nb.x1, nb.y1}};
            for (const auto* e : {&a, &b, &c}) {
                const auto& f = e == &a ? b : e == &b ? c : a;
                if (dt::orient(*e, f, k[0]) < 0 && dt::orient(*e, f, k[1]) < 0 && dt::orient(*e, f, k[2]) < 0 &&
                    dt::orient(*e, f, k[3]) < 0)
                    return true;
            }
            return false;
        };
        if (tree.any_in(
                dt::box{x0, y0, x1, y1}, [&](std::size_t k) { return is_listed[in_tree[k]] == 1 && blocks(in_tree[k]); }, outside, work))
            return false;
        for (const auto j : recent)
            if (is_listed[j] == 2 && blocks(j)) return false;
        return true;
    };
    std::size_t left = n, i = 0, misses = 0;
    while (left > 3) {
        if (work > work_limit) return too_intricate();
        if (is_ear(i)) {
            out.push_back({poly[prev[i]], poly[i], poly[next[i]]});
            const std::size_t ahead = next[next[i]];
            clip(i);
            i = ahead;
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
                ++work;
                if (dt::orient(at(prev[j]), at(j), at(next[j])) == 0) {
                    out.push_back({poly[prev[j]], poly[j], poly[next[j]]});
                    const std::size_t back = prev[j];
                    clip(j);
                    i = back;
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
    if (options.delaunay && !dt::flip_to_delaunay(points, out, work, work_limit)) return too_intricate();
    return out;
}

}  // namespace hmira
