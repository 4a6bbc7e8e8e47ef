// hmira/algorithms/boolean/detail/cut_triangle.hpp
// One input triangle cut by the points and segments where other triangles meet it: a constrained
// triangulation in the triangle's projection plane, over explicit and implicit points, every
// decision an exact predicate (predicates/exact_point.hpp).
//
// Points are inserted by splitting the triangle (or the two triangles of an edge) that holds
// them; a segment is inserted by removing the triangles it crosses and triangulating the two
// polygons on either side of it by ear clipping. The triangulation is not Delaunay: the arrangement
// needs conformity, not shape. Per triangle the cost is O(n^2) for n inserted points, which stays
// small for the usual case of a few cuts per triangle.
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

    /// Removes the triangles the open segment ab crosses and fills the two sides by ear clipping.
    /// \pre no vertex lies on the open segment ab, and ab is not an edge.
    bool carve(vid a, vid b) {
        std::vector<char> cut(tris_.size(), 0);
        for (std::size_t i = 0; i < tris_.size(); ++i)
            for (std::size_t m = 0; m < 3; ++m) {
                const vid p = tris_[i][m], q = tris_[i][(m + 1) % 3];
                if (orient(a, b, p) * orient(a, b, q) < 0 && orient(p, q, a) * orient(p, q, b) < 0) {
                    if (is_constraint(p, q)) return false;
                    cut[i] = 1;
                }
            }
        // The boundary of the removed strip: directed edges whose reverse was not removed.
        std::vector<std::array<vid, 2>> edges;
        for (std::size_t i = 0; i < tris_.size(); ++i)
            if (cut[i])
                for (std::size_t m = 0; m < 3; ++m) edges.push_back({tris_[i][m], tris_[i][(m + 1) % 3]});
        std::vector<std::array<vid, 2>> boundary;
        for (const auto& e : edges)
            if (std::find(edges.begin(), edges.end(), std::array<vid, 2>{e[1], e[0]}) == edges.end())
                boundary.push_back(e);
        auto next = [&](vid v) {
            for (const auto& e : boundary)
                if (e[0] == v) return e[1];
            return v;
        };
        std::vector<tri3> kept;
        for (std::size_t i = 0; i < tris_.size(); ++i)
            if (!cut[i]) kept.push_back(tris_[i]);
        // Two loops, each counter-clockwise: a ... b then back along ba, and b ... a then ab.
        for (vid start : {a, b}) {
            const vid stop = start == a ? b : a;
            std::vector<vid> poly{start};
            for (vid v = next(start); v != stop; v = next(v)) {
                if (poly.size() > boundary.size()) return false;  // not a simple strip
                poly.push_back(v);
            }
            poly.push_back(stop);
            if (!ear_clip(poly, kept)) return false;
        }
        tris_ = std::move(kept);
        return true;
    }

    /// Triangulates the simple counter-clockwise polygon by ear clipping, exactly.
    bool ear_clip(std::vector<vid> poly, std::vector<tri3>& out) const {
        while (poly.size() > 3) {
            bool clipped = false;
            for (std::size_t i = 0; i < poly.size() && !clipped; ++i) {
                const std::size_t n = poly.size();
                const vid u = poly[(i + n - 1) % n], v = poly[i], w = poly[(i + 1) % n];
                if (orient(u, v, w) <= 0) continue;
                bool empty = true;
                for (vid x : poly)
                    if (x != u && x != v && x != w && orient(u, v, x) >= 0 && orient(v, w, x) >= 0 &&
                        orient(w, u, x) >= 0) {
                        empty = false;
                        break;
                    }
                if (!empty) continue;
                out.push_back({u, v, w});
                poly.erase(poly.begin() + std::ptrdiff_t(i));
                clipped = true;
            }
            if (!clipped) return false;
        }
        if (poly.size() == 3) {
            if (orient(poly[0], poly[1], poly[2]) <= 0) return false;
            out.push_back({poly[0], poly[1], poly[2]});
        }
        return true;
    }

    const std::vector<exact_point>& pts_;
    int drop_;
    int sign_ = 1;
    std::vector<tri3> tris_;
    std::vector<vid> verts_;
    std::vector<std::array<vid, 2>> constraints_;
};

}  // namespace hmira::detail::boolean
