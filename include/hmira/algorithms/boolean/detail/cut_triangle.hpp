// hmira/algorithms/boolean/detail/cut_triangle.hpp
// One input triangle cut by the points and segments where other triangles meet it: a constrained
// triangulation in the triangle's projection plane, over explicit and implicit points, every
// decision an exact predicate (predicates/exact_point.hpp).
//
// Points are inserted by splitting the triangle (or the two triangles of an edge) that holds
// them; a segment is inserted by walking along it, removing the triangles it crosses and
// triangulating the two sides of it, each a chain of vertices that all reach the segment (see
// carve). The triangulation is not Delaunay: the arrangement needs conformity, not shape. The
// triangles are a flat list scanned linearly: O(n) per point and O(n^2) per segment (a scan per
// step of the walk), O(n^3) per triangle for n inserted points and segments, which stays small
// for the usual case of a few cuts per triangle.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "../../../predicates/exact_point.hpp"

namespace hmira::detail::boolean {

using predicates::exact_point;
using predicates::point3;
using vid = std::uint32_t;
using tri3 = std::array<vid, 3>;

/// The axis to drop so that the explicit triangle abc projects without losing area, the one its
/// normal is closest to; -1 when the triangle has no area.
inline int projection_axis(const point3& a, const point3& b, const point3& c) {
    const point3 n{(b.y - a.y) * (c.z - a.z) - (b.z - a.z) * (c.y - a.y),
                   (b.z - a.z) * (c.x - a.x) - (b.x - a.x) * (c.z - a.z),
                   (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)};
    std::array<int, 3> order{0, 1, 2};
    std::sort(order.begin(), order.end(),
              [&](int i, int j) { return std::abs(n[std::size_t(i)]) > std::abs(n[std::size_t(j)]); });
    for (int k : order)
        if (predicates::detail::orient2d_drop(k, a, b, c) != 0) return k;
    return -1;
}

/// The triangulation of one triangle under insertion of points and segments (global point ids).
class cut_triangle {
public:
    /// \pre the corners are distinct points of `points` spanning a triangle with area.
    cut_triangle(const std::vector<exact_point>& points, tri3 corners, int drop)
        : pts_(points), drop_(drop), tris_{corners}, verts_(corners.begin(), corners.end()) {
        sign_ = predicates::orient2d(drop, pts_[corners[0]], pts_[corners[1]], pts_[corners[2]]);
    }

    /// Orientation of three points in the projection, +1 where the input triangle's corners are.
    int orient(vid a, vid b, vid c) const { return sign_ * predicates::orient2d(drop_, pts_[a], pts_[b], pts_[c]); }

    /// Inserts point p, which must lie in the closed triangle. False if it does not.
    bool insert_point(vid p) {
        if (std::find(verts_.begin(), verts_.end(), p) != verts_.end()) return true;
        for (std::size_t i = 0; i < tris_.size(); ++i) {
            const tri3 t = tris_[i];
            const int o[3] = {orient(t[1], t[2], p), orient(t[2], t[0], p), orient(t[0], t[1], p)};
            if (o[0] < 0 || o[1] < 0 || o[2] < 0) continue;
            const int zeros = (o[0] == 0) + (o[1] == 0) + (o[2] == 0);
            if (zeros >= 2) return false;  // on a corner: a distinct id for one point, never made
            verts_.push_back(p);
            if (zeros == 0) {
                tris_[i] = {t[0], t[1], p};
                tris_.push_back({t[1], t[2], p});
                tris_.push_back({t[2], t[0], p});
                return true;
            }
            const std::size_t k = o[0] == 0 ? 0 : (o[1] == 0 ? 1 : 2);  // p on the edge opposite corner k
            split_edge(i, k, p);
            return true;
        }
        return false;
    }

    /// Inserts the segment ab (both ends already inserted). False when it crosses an earlier
    /// segment, which only intersecting input triangles of one mesh produce.
    bool insert_segment(vid a, vid b) {
        if (a == b) return true;
        // Vertices on the open segment split it: collinear, and strictly between its ends.
        std::vector<vid> on;
        for (vid v : verts_) {
            if (v == a || v == b || orient(a, b, v) != 0) continue;
            const int s = predicates::compare_xyz(pts_[a], pts_[v]), t = predicates::compare_xyz(pts_[v], pts_[b]);
            if (s == t && s != 0) on.push_back(v);
        }
        if (!on.empty()) {
            const int dir = predicates::compare_xyz(pts_[a], pts_[b]);
            std::sort(on.begin(), on.end(),
                      [&](vid x, vid y) { return predicates::compare_xyz(pts_[x], pts_[y]) == dir; });
            vid prev = a;
            for (vid v : on) {
                if (!insert_segment(prev, v)) return false;
                prev = v;
            }
            return insert_segment(prev, b);
        }
        constraints_.push_back({std::min(a, b), std::max(a, b)});
        if (has_edge(a, b)) return true;
        return carve(a, b);
    }

    /// The triangles, wound like the input triangle.
    const std::vector<tri3>& triangles() const noexcept { return tris_; }
    /// The inserted segments (split at the vertices on them), each as (smaller id, larger id).
    const std::vector<std::array<vid, 2>>& constraints() const noexcept { return constraints_; }

private:
    /// Splits triangle i at p on the edge opposite its corner k, and the triangle across it.
    void split_edge(std::size_t i, std::size_t k, vid p) {
        const tri3 t = tris_[i];
        const vid x = t[k], y = t[(k + 1) % 3], z = t[(k + 2) % 3];
        tris_[i] = {x, y, p};
        tris_.push_back({x, p, z});
        for (std::size_t j = 0; j < tris_.size(); ++j) {
            const tri3 n = tris_[j];
            for (std::size_t m = 0; m < 3; ++m)
                if (n[m] == z && n[(m + 1) % 3] == y) {
                    const vid w = n[(m + 2) % 3];
                    tris_[j] = {z, p, w};
                    tris_.push_back({p, y, w});
                    return;
                }
        }
    }

    bool has_edge(vid a, vid b) const {
        for (const tri3& t : tris_)
            for (std::size_t m = 0; m < 3; ++m)
                if ((t[m] == a && t[(m + 1) % 3] == b) || (t[m] == b && t[(m + 1) % 3] == a)) return true;
        return false;
    }

    bool is_constraint(vid a, vid b) const {
        const std::array<vid, 2> e{std::min(a, b), std::max(a, b)};
        return std::find(constraints_.begin(), constraints_.end() - 1, e) != constraints_.end() - 1;
    }

    /// Removes the triangles the open segment ab crosses and triangulates the two sides.
    /// \pre no vertex lies on the open segment ab, and ab is not an edge.
    ///
    /// The triangles are found by walking from a along ab, edge by edge. Each crossed edge has one
    /// end left of ab and one right; the left ends, in the order the edges are crossed (repeats in
    /// a row dropped), form the left side, the right ends the right side. A side is not always a
    /// simple polygon: it can pass through one vertex twice around triangles the walk did not
    /// remove, or run out to a vertex whose triangles were all removed and back (a vertex is then
    /// enclosed by the strip). Each such side is triangulated by fill_side, which relies only on
    /// every vertex of the side reaching ab along the part of its crossed edge that lies on that side.
    bool carve(vid a, vid b) {
        std::vector<char> cut(tris_.size(), 0);
        std::vector<vid> left, right;
        auto cross = [&](vid p, vid q) {  // the edge pq, crossed by ab, p left of it
            if (is_constraint(p, q)) return false;
            if (left.empty() || left.back() != p) left.push_back(p);
            if (right.empty() || right.back() != q) right.push_back(q);
            return true;
        };
        // The triangle at a that ab leaves through, and its edge pq opposite a (p left of ab).
        vid p = a, q = a;
        for (std::size_t i = 0; i < tris_.size() && p == a; ++i)
            for (std::size_t m = 0; m < 3; ++m) {
                const vid u = tris_[i][(m + 1) % 3], w = tris_[i][(m + 2) % 3];
                if (tris_[i][m] != a || orient(a, u, b) <= 0 || orient(a, b, w) <= 0) continue;
                cut[i] = 1;
                p = w, q = u;  // counter-clockwise a, u, w: w is left of ab, u right
                break;
            }
        if (p == a || !cross(p, q)) return false;
        // Across each crossed edge to the next triangle, until the one with corner b.
        for (std::size_t steps = 0;; ++steps) {
            if (steps > tris_.size()) return false;  // only a broken triangulation gets here
            std::size_t next = tris_.size(), m = 0;
            for (std::size_t i = 0; i < tris_.size() && next == tris_.size(); ++i)
                for (m = 0; m < 3; ++m)
                    if (tris_[i][m] == p && tris_[i][(m + 1) % 3] == q) {
                        next = i;
                        break;
                    }
            if (next == tris_.size() || cut[next]) return false;
            cut[next] = 1;
            const vid r = tris_[next][(m + 2) % 3];
            if (r == b) break;
            const int side = orient(a, b, r);
            if (side == 0) return false;  // r on the line of ab but not on the segment: impossible
            (side > 0 ? p : q) = r;       // the exit edge keeps the end on the other side
            if (!cross(p, q)) return false;
        }
        std::vector<tri3> kept;
        for (std::size_t i = 0; i < tris_.size(); ++i)
            if (!cut[i]) kept.push_back(tris_[i]);
        // The left side lies left of a->b in the order crossed; the right side left of b->a
        // when read backwards.
        std::reverse(right.begin(), right.end());
        if (!fill_side(a, b, left, kept) || !fill_side(b, a, right, kept)) return false;
        tris_ = std::move(kept);
        return true;
    }

    /// Triangulates the region between the segment pq and the chain `side` (every vertex strictly
    /// left of p->q, ordered from p's end to q's), adding counter-clockwise triangles to `out`.
    ///
    /// Each vertex c of the chain reaches pq by a segment inside the region (part of an edge it
    /// had in the removed triangles), and these segments meet pq in chain order. The triangle
    /// p, q, c is then inside the region and meets no other part of the boundary as soon as it
    /// holds no other chain vertex: a chain edge entering it would have to cut c off from pq, across
    /// c's own segment. Such a c exists: while the triangle p, q, c holds another chain vertex c',
    /// p, q, c' is a triangle of smaller area inside it. Such a c occurs once in the chain (a chain
    /// that leaves c and comes back encloses a vertex inside p, q, c), and splits it in two chains
    /// of the same kind, on the bases pc and cq. Every step is an exact orient; the recursion
    /// depth is at most the chain length n, and each triangle costs O(n) orients per move, at
    /// most n moves (one when, as usual, the first vertex tried is already free).
    bool fill_side(vid p, vid q, const std::vector<vid>& side, std::vector<tri3>& out) const {
        if (side.empty()) return true;
        std::size_t best = 0;
        for (std::size_t moves = 0, moved = 1; moved; ++moves) {
            if (moves > side.size()) return false;  // each move goes to a smaller, nested triangle
            moved = 0;
            const vid c = side[best];
            if (orient(p, q, c) <= 0) return false;  // not a side of the kind described
            for (std::size_t i = 0; i < side.size(); ++i) {
                const vid x = side[i];
                if (x == c || orient(p, q, x) < 0 || orient(q, c, x) < 0 || orient(c, p, x) < 0) continue;
                best = i;
                moved = 1;
                break;
            }
        }
        const vid c = side[best];
        out.push_back({p, q, c});
        const std::vector<vid> before(side.begin(), side.begin() + std::ptrdiff_t(best));
        const std::vector<vid> after(side.begin() + std::ptrdiff_t(best) + 1, side.end());
        return fill_side(p, c, before, out) && fill_side(c, q, after, out);
    }

    const std::vector<exact_point>& pts_;
    int drop_;
    int sign_ = 1;
    std::vector<tri3> tris_;
    std::vector<vid> verts_;
    std::vector<std::array<vid, 2>> constraints_;
};

}  // namespace hmira::detail::boolean
