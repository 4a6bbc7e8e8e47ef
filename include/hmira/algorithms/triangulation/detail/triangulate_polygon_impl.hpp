// hmira/algorithms/triangulation/detail/triangulate_polygon_impl.hpp
// The checks and steps of triangulate_polygon (see ../triangulate_polygon.hpp for the
// interface): exact orientation tests, the input and simplicity checks, the nesting of the
// holes, and Lawson's flips to the constrained Delaunay triangulation.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <set>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "../../../core/result.hpp"
#include "../../../predicates/incircle.hpp"
#include "../../../predicates/orient2d.hpp"
#include "monotone_partition.hpp"

namespace hmira {

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

/// Work units (corners looked at by the hole checks, and Delaunay flips) allowed per corner,
/// plus a constant: a typical polygon needs a few per corner; past the limit the polygon is
/// refused in bounded time instead of running for hours.
inline constexpr std::size_t work_per_corner = 256;
inline constexpr std::size_t work_base = std::size_t(1) << 26;

/// Lawson's flips: while a diagonal of two triangles has the far corner of one strictly inside
/// the other's circumcircle (exact in-circle test) and the two form a strictly convex
/// quadrilateral, it is replaced by the other diagonal. A side that is not shared, in opposite
/// directions, by exactly two triangles (the loops' edges) is never flipped. Ends with the
/// constrained Delaunay triangulation of the same corners, which maximises the smallest angle.
/// False once `work` passes `limit`.
inline bool flip_to_delaunay(std::span<const point2> p, std::vector<std::array<std::size_t, 3>>& tris,
                             std::size_t& work, std::size_t limit) {
    constexpr std::size_t none = std::size_t(-1);
    const std::size_t sides = 3 * tris.size();
    auto from = [&](std::size_t s) { return tris[s / 3][s % 3]; };
    auto to = [&](std::size_t s) { return tris[s / 3][(s % 3 + 1) % 3]; };
    std::vector<std::size_t> by_key(sides), twin(sides, none);
    for (std::size_t s = 0; s < sides; ++s) by_key[s] = s;
    auto key = [&](std::size_t s) { return std::pair{std::min(from(s), to(s)), std::max(from(s), to(s))}; };
    std::sort(by_key.begin(), by_key.end(),
              [&](std::size_t x, std::size_t y) { return key(x) < key(y) || (key(x) == key(y) && x < y); });
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

/// The refusal of a polygon past the work limit.
inline hmira::error too_intricate(std::size_t corners) {
    return fail(errc::unsupported, "triangulate_polygon: the polygon's " + std::to_string(corners) +
                                       " corners are too intricate to triangulate within the work limit");
}

/// The total number of corners, once every loop has three or more, every index names a point
/// and every coordinate is finite and within the exact predicates' range.
inline result<std::size_t> count_corners(std::span<const point2> points,
                                         std::span<const std::vector<std::size_t>> loops) {
    if (loops.empty()) return fail(errc::degenerate_face, "triangulate_polygon: no outer loop");
    std::size_t total = 0;
    for (std::size_t l = 0; l < loops.size(); ++l) {
        if (loops[l].size() < 3)
            return fail(errc::degenerate_face,
                        "triangulate_polygon: loop " + std::to_string(l) + " has fewer than 3 corners");
        for (auto i : loops[l]) {
            if (i >= points.size())
                return fail(errc::invalid_argument, "triangulate_polygon: loop " + std::to_string(l) + " names point " +
                                                        std::to_string(i) + " of " + std::to_string(points.size()));
            if (!predicates::in_predicate_range(points[i][0]) || !predicates::in_predicate_range(points[i][1]))
                return fail(errc::invalid_argument, "triangulate_polygon: point " + std::to_string(i) +
                                                        " is not finite or out of the exact predicates' range");
        }
        total += loops[l].size();
    }
    return total;
}

/// One edge of a loop: edge `pos` of loop `loop` runs from point a to point b.
struct loop_edge {
    std::size_t loop, pos, a, b;
};

/// Whether the loops are simple and disjoint: no two edges meet except consecutive edges at
/// their shared corner, and no point repeats. A sweep over the corners in (x, y) order keeps
/// the edges that span the sweep line sorted from bottom to top; the first point where two
/// edges meet lies between neighbours in that order (Shamos and Hoey), so testing neighbours
/// finds it in O(n log n).
class simplicity_sweep {
public:
    simplicity_sweep(std::span<const point2> points, std::span<const std::vector<std::size_t>> loops)
        : points_(points), loops_(loops), status_(below{this}) {
        for (std::size_t l = 0; l < loops.size(); ++l) {
            loop_start_.push_back(edges_.size());
            for (std::size_t i = 0, n = loops[l].size(); i < n; ++i)
                edges_.push_back({l, i, loops[l][i], loops[l][(i + 1) % n]});
        }
    }

    result<void> run() {
        for (const auto& e : edges_)
            if (points_[e.a] == points_[e.b])
                return fail(errc::topology, "triangulate_polygon: loop " + std::to_string(e.loop) +
                                                " repeats a point at corner " + std::to_string(e.pos));
        // Corners in (x, y) order; two corners at one point make the polygon not simple.
        std::vector<std::size_t> corners(edges_.size());  // edge i starts at corner i
        for (std::size_t i = 0; i < corners.size(); ++i) corners[i] = i;
        std::sort(corners.begin(), corners.end(), [&](std::size_t i, std::size_t j) {
            const auto& p = points_[edges_[i].a];
            const auto& q = points_[edges_[j].a];
            return lex_before(p, q) || (p == q && i < j);
        });
        for (std::size_t k = 0; k + 1 < corners.size(); ++k)
            if (points_[edges_[corners[k]].a] == points_[edges_[corners[k + 1]].a])
                return not_simple(corners[k], corners[k + 1]);
        where_.assign(edges_.size(), status_.end());
        bad_i_ = bad_j_ = edges_.size();
        for (const auto c : corners) {
            const std::size_t l = edges_[c].loop, k = loops_[l].size();
            const std::size_t into = loop_start_[l] + (edges_[c].pos + k - 1) % k;  // the edge that ends at corner c
            const auto& here = points_[edges_[c].a];
            for (const auto e : {into, c})
                if (hi(e) == here && where_[e] != status_.end()) remove(e);
            for (const auto e : {into, c})
                if (lo(e) == here) {
                    where_[e] = status_.insert(e).first;
                    test_around(e);
                }
            if (bad_i_ != edges_.size()) return not_simple(bad_i_, bad_j_);
        }
        return {};
    }

private:
    /// Whether edge u lies below edge v where both span the sweep line; exact. Ties (edges that
    /// touch, which the neighbour tests then report) fall back to the index, to stay a strict order.
    struct below {
        const simplicity_sweep* s;
        bool operator()(std::size_t u, std::size_t v) const {
            if (u == v) return false;
            const auto &ul = s->lo(u), &ur = s->hi(u), &vl = s->lo(v), &vr = s->hi(v);
            int o;
            if (ul == vl) {
                o = orient(ul, ur, vr);
            } else if (lex_before(ul, vl)) {
                o = orient(ul, ur, vl);
                if (o == 0) o = orient(ul, ur, vr);
            } else {
                o = -orient(vl, vr, ul);
                if (o == 0) o = -orient(vl, vr, ur);
            }
            return o != 0 ? o > 0 : u < v;
        }
    };
    using status_t = std::set<std::size_t, below>;

    const point2& lo(std::size_t e) const {
        const auto& a = points_[edges_[e].a];
        const auto& b = points_[edges_[e].b];
        return lex_before(a, b) ? a : b;
    }
    const point2& hi(std::size_t e) const {
        const auto& a = points_[edges_[e].a];
        const auto& b = points_[edges_[e].b];
        return lex_before(a, b) ? b : a;
    }

    /// Whether edges s and t meet where they should not. Consecutive edges p -> shared -> q
    /// only do when one folds back along the other.
    bool crossing(const loop_edge& s, const loop_edge& t) const {
        const auto& a = points_[s.a];
        const auto& b = points_[s.b];
        const auto& c = points_[t.a];
        const auto& d = points_[t.b];
        const std::size_t k = loops_[s.loop].size();
        const bool after = t.loop == s.loop && t.pos == (s.pos + 1) % k;
        const bool before = t.loop == s.loop && s.pos == (t.pos + 1) % k;
        if (after || before) {
            const auto& shared = after ? b : a;
            const auto& p = after ? a : c;
            const auto& q = after ? d : b;
            return orient(p, shared, q) == 0 && (within(p, shared, q) || within(shared, q, p));
        }
        return segments_meet(a, b, c, d);
    }

    hmira::error not_simple(std::size_t i, std::size_t j) const {
        if (i > j) std::swap(i, j);
        return fail(errc::topology, "triangulate_polygon: the polygon is not simple: edge " +
                                        std::to_string(edges_[i].pos) + " of loop " + std::to_string(edges_[i].loop) +
                                        " meets edge " + std::to_string(edges_[j].pos) + " of loop " +
                                        std::to_string(edges_[j].loop));
    }

    void test(std::size_t u, std::size_t v) {
        if (bad_i_ == edges_.size() && crossing(edges_[u], edges_[v])) {
            bad_i_ = u;
            bad_j_ = v;
        }
    }
    void test_around(std::size_t e) {
        const auto it = where_[e];
        if (it != status_.begin()) test(*std::prev(it), e);
        if (const auto upper = std::next(it); upper != status_.end()) test(e, *upper);
    }
    /// Takes edge e off the sweep line; its two neighbours become neighbours.
    void remove(std::size_t e) {
        test_around(e);
        const auto after = status_.erase(where_[e]);
        where_[e] = status_.end();
        if (after != status_.begin() && after != status_.end()) test(*std::prev(after), *after);
    }

    std::span<const point2> points_;
    std::span<const std::vector<std::size_t>> loops_;
    std::vector<loop_edge> edges_;
    std::vector<std::size_t> loop_start_;
    status_t status_;
    std::vector<typename status_t::iterator> where_;
    std::size_t bad_i_ = 0, bad_j_ = 0;
};

/// Whether the simple loops are wound as documented (outer counter-clockwise, holes clockwise)
/// and every hole lies inside the outer loop and outside the other holes. Each hole costs
/// O(n) (`work` counts it), so this is what bounds polygons with very many holes.
inline result<void> check_nesting(std::span<const point2> points, std::span<const std::vector<std::size_t>> loops,
                                  std::size_t& work, std::size_t limit, std::size_t corners) {
    for (std::size_t l = 0; l < loops.size(); ++l) {
        const int o = loop_orientation(points, loops[l]);
        if (o == 0)
            return fail(errc::topology, "triangulate_polygon: loop " + std::to_string(l) +
                                            " is flat (all corners collinear at its extreme)");
        if ((l == 0) != (o > 0))
            return fail(errc::topology,
                        "triangulate_polygon: loop " + std::to_string(l) +
                            (l == 0 ? " (outer) is not counter-clockwise" : " (a hole) is not clockwise"));
        if (l == 0) continue;
        if (!inside(points, loops[0], points[loops[l][0]]))
            return fail(errc::topology,
                        "triangulate_polygon: hole loop " + std::to_string(l) + " is not inside the outer loop");
        work += loops[0].size();
        for (std::size_t k = 1; k < loops.size(); ++k) {
            if (k != l && inside(points, loops[k], points[loops[l][0]]))
                return fail(errc::topology, "triangulate_polygon: hole loop " + std::to_string(l) +
                                                " lies inside hole loop " + std::to_string(k));
            work += loops[k].size();
        }
        if (work > limit) return too_intricate(corners);
    }
    return {};
}

}  // namespace detail::triangulation

}  // namespace hmira
