// hmira/algorithms/triangulation/detail/monotone_partition.hpp
// Triangulation of a plane polygon with holes in O(n log n): a sweep over the corners in
// (x, y) order cuts the polygon into pieces monotone in that order (Lee and Preparata's split
// and merge diagonals, de Berg et al., "Computational Geometry", ch. 3), and each piece is
// triangulated in linear time by the stack algorithm. Every decision is an exact orientation
// test or a comparison of coordinates.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <set>
#include <span>
#include <utility>
#include <vector>

#include "../../../predicates/orient2d.hpp"

namespace hmira {

/// A point of a plane polygon.
using point2 = std::array<double, 2>;

namespace detail::triangulation {

/// The (x, y) order of the sweep: x first, then y. It orders distinct points strictly, as if
/// the plane were turned by an infinitesimal angle so that no two points share an x.
inline bool lex_before(const point2& p, const point2& q) { return p[0] < q[0] || (p[0] == q[0] && p[1] < q[1]); }

/// The corners of all loops, linked in loop order (interior on the left of every edge, as the
/// outer loop is counter-clockwise and the holes clockwise), with their rank in sweep order.
/// `work` counts orientation tests and comparisons, to show the cost grows as n log n.
struct monotone_context {
    std::span<const point2> points;
    std::vector<std::size_t> vid;         ///< corner -> point index
    std::vector<std::size_t> prev, next;  ///< corner -> corner, along its loop
    std::vector<std::size_t> rank;        ///< corner -> position in sweep order
    std::size_t work = 0;

    const point2& at(std::size_t c) const { return points[vid[c]]; }
    int orient(std::size_t a, std::size_t b, std::size_t c) {
        ++work;
        const auto &p = at(a), &q = at(b), &r = at(c);
        return predicates::orient2d(p[0], p[1], q[0], q[1], r[0], r[1]);
    }
    bool before(std::size_t a, std::size_t b) const { return rank[a] < rank[b]; }
};

/// Orders the edges that span the sweep line from bottom to top. An edge is named by its first
/// corner c (it runs c -> next[c]); only edges that run forward in sweep order (interior above
/// them) enter the status. A key of n + v stands for corner v itself, so that a lookup finds
/// the edges around it. Both compared edges span the sweep position of the later of their first
/// corners (edges never cross), so one orientation test of that corner against the other edge
/// decides, exactly.
struct edge_below {
    monotone_context* ctx;
    bool operator()(std::size_t a, std::size_t b) const {
        auto& x = *ctx;
        const std::size_t n = x.vid.size();
        ++x.work;
        if (a >= n && b >= n) return false;
        if (b >= n) return x.orient(a, x.next[a], b - n) > 0;  // corner b - n lies above edge a
        if (a >= n) return x.orient(b, x.next[b], a - n) < 0;  // corner a - n lies below edge b
        if (a == b) return false;
        if (x.before(b, a)) {  // a starts later, within b's span
            const int o = x.orient(b, x.next[b], a);
            return (o != 0 ? o : x.orient(b, x.next[b], x.next[a])) < 0;
        }
        const int o = x.orient(a, x.next[a], b);
        return (o != 0 ? o : x.orient(a, x.next[a], x.next[b])) > 0;
    }
};

/// The corners' types in the sweep.
enum class corner_kind { start, end, split, merge, lower, upper };

inline corner_kind classify(monotone_context& x, std::size_t v) {
    const std::size_t u = x.prev[v], w = x.next[v];
    const bool u_after = x.before(v, u), w_after = x.before(v, w);
    if (u_after && w_after) return x.orient(u, v, w) > 0 ? corner_kind::start : corner_kind::split;
    if (!u_after && !w_after) return x.orient(u, v, w) > 0 ? corner_kind::end : corner_kind::merge;
    return u_after ? corner_kind::upper : corner_kind::lower;  // lower: the boundary runs forward, interior above
}

/// The diagonals that cut the polygon into pieces monotone in sweep order: one from every
/// split corner back to the helper of the edge below it, one from every merge corner forward
/// to the next corner that becomes that helper. The helper of a status edge is the last corner
/// swept whose view down ends on that edge.
class monotone_sweep {
public:
    explicit monotone_sweep(monotone_context& x)
        : x_(x), n_(x.vid.size()), kind_(n_), status_(edge_below{&x}), where_(n_, status_.end()), helper_(n_, n_) {
        for (std::size_t c = 0; c < n_; ++c) kind_[c] = classify(x_, c);
    }

    /// Sweeps the corners in `order`; false if a corner finds no edge below it (invalid input).
    bool run(const std::vector<std::size_t>& order) {
        for (const std::size_t v : order) {
            const std::size_t u = x_.prev[v];
            switch (kind_[v]) {
                case corner_kind::start: open(v); break;
                case corner_kind::end: close(u, v); break;
                case corner_kind::split: {
                    const std::size_t e = below(v);
                    if (e == n_) return false;
                    diagonals.push_back({v, helper_[e]});
                    helper_[e] = v;
                    open(v);
                    break;
                }
                case corner_kind::merge:
                    close(u, v);
                    if (!help_below(v)) return false;
                    break;
                case corner_kind::lower:
                    close(u, v);
                    open(v);
                    break;
                case corner_kind::upper:
                    if (!help_below(v)) return false;
                    break;
            }
        }
        return true;
    }

    std::vector<std::array<std::size_t, 2>> diagonals;

private:
    using status_t = std::set<std::size_t, edge_below>;

    /// The status edge directly below corner v, or n.
    std::size_t below(std::size_t v) const {
        const auto it = status_.lower_bound(n_ + v);
        return it == status_.begin() ? n_ : *std::prev(it);
    }
    /// Edge e ends at corner v: a merge corner that helps it is joined to v.
    void close(std::size_t e, std::size_t v) {
        if (kind_[helper_[e]] == corner_kind::merge) diagonals.push_back({v, helper_[e]});
        status_.erase(where_[e]);
        where_[e] = status_.end();
    }
    /// The edge v -> next[v] starts, helped by v.
    void open(std::size_t v) {
        where_[v] = status_.insert(v).first;
        helper_[v] = v;
    }
    /// Corner v becomes the helper of the edge below it, joined to a merge corner that was.
    bool help_below(std::size_t v) {
        const std::size_t e = below(v);
        if (e == n_) return false;
        if (kind_[helper_[e]] == corner_kind::merge) diagonals.push_back({v, helper_[e]});
        helper_[e] = v;
        return true;
    }

    monotone_context& x_;
    std::size_t n_;
    std::vector<corner_kind> kind_;
    status_t status_;
    std::vector<status_t::iterator> where_;
    std::vector<std::size_t> helper_;
};

/// Which half-turn, counted counter-clockwise from corner v's edge to next[v], the direction
/// from v to s lies in: 0 for [0, pi), 1 for [pi, 2 pi). Exact.
inline int half_turn(monotone_context& x, std::size_t v, std::size_t s) {
    const std::size_t r = x.next[v];
    const int o = x.orient(v, r, s);
    if (o != 0) return o > 0 ? 0 : 1;
    return x.before(v, s) == x.before(v, r) ? 0 : 1;  // along the edge, or straight back
}

/// Whether, seen from corner v, the direction to p comes before the direction to q counter-
/// clockwise, starting at the direction of v's loop edge to next[v]. Exact: the half-turns,
/// then one orientation test.
inline bool turns_before(monotone_context& x, std::size_t v, std::size_t p, std::size_t q) {
    const int hp = half_turn(x, v, p), hq = half_turn(x, v, q);
    if (hp != hq) return hp < hq;
    return x.orient(v, p, q) > 0;
}

/// The monotone pieces: the faces of the loops' edges and the diagonals, each a cycle of
/// corners, counter-clockwise. Around each corner its neighbours are sorted counter-clockwise
/// from next[v] (prev[v] last: the interior lies between them), and a face turns at each corner
/// to the neighbour just clockwise of the one it came from.
inline std::vector<std::vector<std::size_t>> monotone_pieces(monotone_context& x,
                                                             const std::vector<std::array<std::size_t, 2>>& diagonals) {
    const std::size_t n = x.vid.size();
    std::vector<std::size_t> first(n + 1, 0);
    for (std::size_t c = 0; c < n; ++c) first[c + 1] = 2;
    for (const auto& d : diagonals) {
        ++first[d[0] + 1];
        ++first[d[1] + 1];
    }
    for (std::size_t c = 0; c < n; ++c) first[c + 1] += first[c];
    std::vector<std::size_t> around(first[n]), fill(n);
    for (std::size_t c = 0; c < n; ++c) {
        around[first[c]] = x.next[c];
        around[first[c + 1] - 1] = x.prev[c];
        fill[c] = first[c] + 1;
    }
    for (const auto& d : diagonals) {
        around[fill[d[0]]++] = d[1];
        around[fill[d[1]]++] = d[0];
    }
    for (std::size_t c = 0; c < n; ++c)
        if (first[c + 1] - first[c] > 3)
            std::sort(around.begin() + std::ptrdiff_t(first[c] + 1), around.begin() + std::ptrdiff_t(first[c + 1] - 1),
                      [&](std::size_t p, std::size_t q) { return turns_before(x, c, p, q); });
    // Half-edge h = c -> around[h], for every entry but the last (c -> prev[c] runs outside).
    std::vector<char> used(around.size(), 0);
    std::vector<std::vector<std::size_t>> pieces;
    for (std::size_t c = 0; c < n; ++c)
        for (std::size_t h = first[c]; h + 1 < first[c + 1]; ++h) {
            if (used[h]) continue;
            pieces.emplace_back();
            auto& piece = pieces.back();
            std::size_t from = c, g = h;
            while (!used[g]) {
                used[g] = 1;
                piece.push_back(from);
                const std::size_t to = around[g];
                std::size_t k = first[to];
                while (around[k] != from) ++k;
                g = k == first[to] ? first[to + 1] - 1 : k - 1;  // k == first[to] cannot happen inside
                from = to;
            }
        }
    return pieces;
}

/// Appends the triangle of sequence entries p, q (consecutive on one chain, p first) and u
/// (after both, on the other chain or the last corner), counter-clockwise.
inline void emit_triangle(const monotone_context& x, const std::vector<std::size_t>& seq,
                          const std::vector<char>& upper, std::size_t p, std::size_t q, std::size_t u,
                          std::vector<std::array<std::size_t, 3>>& out) {
    if (upper[q])
        out.push_back({x.vid[seq[q]], x.vid[seq[p]], x.vid[seq[u]]});
    else
        out.push_back({x.vid[seq[p]], x.vid[seq[q]], x.vid[seq[u]]});
}

/// Triangulates one piece, a counter-clockwise cycle of corners monotone in sweep order, by the
/// stack algorithm: corners in sweep order, each either closing triangles with the whole stack
/// (other chain) or with the stack's top while the diagonal lies strictly inside (same chain).
/// Appends counter-clockwise triangles of point indices; false if the piece is not monotone.
inline bool triangulate_monotone(monotone_context& x, const std::vector<std::size_t>& piece,
                                 std::vector<std::array<std::size_t, 3>>& out) {
    const std::size_t m = piece.size();
    if (m < 3) return false;
    if (m == 3) {
        out.push_back({x.vid[piece[0]], x.vid[piece[1]], x.vid[piece[2]]});
        return true;
    }
    std::size_t lo = 0, hi = 0;
    for (std::size_t i = 1; i < m; ++i) {
        if (x.before(piece[i], piece[lo])) lo = i;
        if (x.before(piece[hi], piece[i])) hi = i;
    }
    // The lower chain runs forward from lo to hi, the upper one back from hi to lo: merge them.
    std::vector<std::size_t> seq;
    std::vector<char> upper;
    seq.reserve(m);
    upper.reserve(m);
    std::size_t a = (lo + 1) % m, b = (lo + m - 1) % m;  // next on the lower, on the upper chain
    seq.push_back(piece[lo]);
    upper.push_back(0);
    while (a != hi || b != hi) {
        const bool take_lower = b == hi || (a != hi && x.before(piece[a], piece[b]));
        const std::size_t i = take_lower ? a : b;
        if (!x.before(seq.back(), piece[i])) return false;
        seq.push_back(piece[i]);
        upper.push_back(take_lower ? 0 : 1);
        if (take_lower)
            a = (a + 1) % m;
        else
            b = (b + m - 1) % m;
    }
    if (!x.before(seq.back(), piece[hi])) return false;
    seq.push_back(piece[hi]);
    upper.push_back(0);
    const auto emit = [&](std::size_t p, std::size_t q, std::size_t u) { emit_triangle(x, seq, upper, p, q, u, out); };
    std::vector<std::size_t> stack{0, 1};
    for (std::size_t j = 2; j + 1 < m; ++j) {
        if (upper[j] != upper[stack.back()]) {
            while (stack.size() > 1) {
                const std::size_t q = stack.back();
                stack.pop_back();
                emit(stack.back(), q, j);
            }
            stack.clear();
            stack.push_back(j - 1);
            stack.push_back(j);
        } else {
            std::size_t q = stack.back();
            stack.pop_back();
            while (!stack.empty()) {
                const std::size_t p = stack.back();
                const int o = x.orient(seq[p], seq[q], seq[j]);
                if (upper[j] ? o >= 0 : o <= 0) break;
                emit(p, q, j);
                q = p;
                stack.pop_back();
            }
            stack.push_back(q);
            stack.push_back(j);
        }
    }
    while (stack.size() > 1) {
        const std::size_t q = stack.back();
        stack.pop_back();
        emit(stack.back(), q, m - 1);
    }
    return true;
}

/// Triangulates a polygon with holes that is known to be valid: loops simple and disjoint, no
/// point repeated, the outer loop counter-clockwise, holes clockwise and inside it. Sets `out`
/// to the triangles (point indices, counter-clockwise), n + 2h - 2 of them, and adds the
/// orientation tests and comparisons made to `work`. False if the sweep found a corner with no
/// edge below it, or a piece that is not monotone (not expected for valid input).
/// O(n log n) time, O(n) memory.
inline bool monotone_triangulate(std::span<const point2> points, std::span<const std::vector<std::size_t>> loops,
                                 std::vector<std::array<std::size_t, 3>>& out, std::size_t& work) {
    monotone_context x;
    x.points = points;
    for (const auto& loop : loops) {
        const std::size_t base = x.vid.size(), k = loop.size();
        for (std::size_t i = 0; i < k; ++i) {
            x.vid.push_back(loop[i]);
            x.prev.push_back(base + (i + k - 1) % k);
            x.next.push_back(base + (i + 1) % k);
        }
    }
    const std::size_t n = x.vid.size();
    std::vector<std::size_t> order(n);
    for (std::size_t c = 0; c < n; ++c) order[c] = c;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        ++x.work;
        return lex_before(x.at(a), x.at(b));
    });
    x.rank.resize(n);
    for (std::size_t i = 0; i < n; ++i) x.rank[order[i]] = i;
    monotone_sweep sweep(x);
    if (!sweep.run(order)) {
        work += x.work;
        return false;
    }
    const auto pieces = monotone_pieces(x, sweep.diagonals);
    out.clear();
    out.reserve(n + 2 * (loops.size() - 1) - 2);
    bool ok = true;
    for (const auto& piece : pieces)
        if (!triangulate_monotone(x, piece, out)) {
            ok = false;
            break;
        }
    work += x.work;
    return ok && out.size() == n + 2 * (loops.size() - 1) - 2;
}

}  // namespace detail::triangulation
}  // namespace hmira
