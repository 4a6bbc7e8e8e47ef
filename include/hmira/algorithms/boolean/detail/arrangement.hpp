// hmira/algorithms/boolean/detail/arrangement.hpp
// The co-refinement of triangle soups from several meshes: every pair of triangles from different
// meshes that meets is intersected exactly (its segment's ends as explicit or line-plane points),
// and, on request, every pair of one mesh that meets other than along the edge or vertex it shares
// (the rule of self_intersections); coincident points are merged by an exact sort, segments that
// cross inside a triangle are split where they cross (segment_crossings.hpp), and every triangle is
// cut along its segments (cut_triangle.hpp). The result is a set of pieces over exact points, each
// piece inside one input triangle, conforming along every cut.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <vector>

#include "../../../core/progress.hpp"
#include "../../../predicates/intersect3d.hpp"
#include "../../validation/detail/self_intersections_impl.hpp"
#include "cut_triangle.hpp"

namespace hmira::detail::boolean {

/// An input triangle: corners by index into the explicit points, the mesh and face it came from.
struct soup_triangle {
    tri3 v;
    std::uint32_t mesh;
    std::size_t face;
};

/// A piece of the arrangement: a triangle over exact points inside input triangle `source`.
struct piece {
    tri3 v;
    std::uint32_t source;
};

/// The arrangement: exact points (the explicit input points first), pieces, the cut edges, and
/// for each input triangle the triangles of other meshes coplanar with it that it overlaps.
struct arrangement {
    std::vector<exact_point> points;
    std::vector<piece> pieces;
    std::vector<std::array<vid, 2>> cut_edges;  ///< sorted, unique, each (smaller, larger)
    std::vector<std::vector<std::uint32_t>> coplanar;
    std::vector<int> drop;            ///< projection axis of each input triangle, -1 if it has no area
    std::size_t pairs = 0;            ///< candidate pairs of different meshes (boxes overlapping) tested exactly
    std::size_t same_mesh_pairs = 0;  ///< candidate pairs of one mesh tested
    bool self_cut = false;            ///< some triangles of one mesh meet other than where they share corners
};

/// What the pair stage found for one input triangle: points and segments, by point id.
struct triangle_cuts {
    std::vector<vid> points;
    std::vector<std::array<vid, 2>> segments;
    std::vector<std::array<vid, 3>> tagged;  ///< each segment with the other triangle of its pair
};

/// The coplanar crossing of segments pq and ab, given to cross properly in the plane that drops
/// axis k: the line pq meets the plane through ab perpendicular to that coordinate plane.
inline predicates::line_plane_point coplanar_crossing(const point3& p, const point3& q, const point3& a,
                                                      const point3& b, int k) {
    point3 o = a;
    const std::size_t kk = std::size_t(k);
    o[kk] = std::fabs(a[kk]) < 0x1p52 ? a[kk] + 1.0 : 2.0 * a[kk];
    return {p, q, a, b, o};
}

class pair_stage {
public:
    /// `explicit_points` are the first points of arr, kept apart because arr.points grows.
    pair_stage(arrangement& arr, const std::vector<point3>& explicit_points, const std::vector<soup_triangle>& tris,
               std::vector<triangle_cuts>& cuts)
        : arr_(arr), explicit_(explicit_points), tris_(tris), cuts_(cuts) {}

    /// Intersects triangles i and j (both with area) and records the result; triangles of one
    /// mesh only where they meet other than along their shared corners.
    void intersect(std::uint32_t i, std::uint32_t j) {
        const tri3 &t = tris_[i].v, &u = tris_[j].v;
        if (tris_[i].mesh == tris_[j].mesh) {
            if (!self_intersect::triangles_cross({t[0], t[1], t[2]}, {u[0], u[1], u[2]}, explicit_)) return;
            arr_.self_cut = true;
        }
        const point3 &a = pos(t[0]), &b = pos(t[1]), &c = pos(t[2]), &d = pos(u[0]), &e = pos(u[1]), &f = pos(u[2]);
        if (!predicates::triangles_intersect(a, b, c, d, e, f)) return;
        const int sd = predicates::orient3d(a, b, c, d), se = predicates::orient3d(a, b, c, e),
                  sf = predicates::orient3d(a, b, c, f);
        if (sd == 0 && se == 0 && sf == 0) return coplanar(i, j);
        std::vector<vid> found;
        crossings(t, u, found);
        crossings(u, t, found);
        record(i, j, found);
    }

private:
    const point3& pos(vid v) const { return explicit_[v]; }

    vid add(const predicates::line_plane_point& l) {
        arr_.points.emplace_back(l);
        return vid(arr_.points.size() - 1);
    }

    /// Points of the line where x's plane meets y's that lie on x's boundary and in closed y.
    void crossings(const tri3& x, const tri3& y, std::vector<vid>& found) {
        const point3 &d = pos(y[0]), &e = pos(y[1]), &f = pos(y[2]);
        int s[3];
        for (std::size_t m = 0; m < 3; ++m) s[m] = predicates::orient3d(d, e, f, pos(x[m]));
        for (std::size_t m = 0; m < 3; ++m) {
            const point3& p = pos(x[m]);
            if (s[m] == 0 && predicates::point_in_triangle(p, d, e, f)) found.push_back(x[m]);
            const std::size_t n = (m + 1) % 3;
            if (s[m] * s[n] < 0 && predicates::segment_intersects_triangle(p, pos(x[n]), d, e, f))
                found.push_back(add({p, pos(x[n]), d, e, f}));
        }
    }

    /// The extreme points of collinear `found` become a segment (or a point) of both triangles.
    void record(std::uint32_t i, std::uint32_t j, const std::vector<vid>& found) {
        if (found.empty()) return;
        vid lo = found[0], hi = found[0];
        for (vid v : found) {
            if (predicates::compare_xyz(arr_.points[v], arr_.points[lo]) < 0) lo = v;
            if (predicates::compare_xyz(arr_.points[v], arr_.points[hi]) > 0) hi = v;
        }
        for (std::uint32_t k : {i, j}) {
            cuts_[k].points.push_back(lo);
            cuts_[k].points.push_back(hi);
            if (lo != hi) cuts_[k].segments.push_back({lo, hi});
            if (lo != hi) cuts_[k].tagged.push_back({lo, hi, k == i ? j : i});
        }
    }

    /// Coplanar triangles: each one's edges clipped to the other cut both.
    void coplanar(std::uint32_t i, std::uint32_t j) {
        arr_.coplanar[i].push_back(j);
        arr_.coplanar[j].push_back(i);
        const tri3 &t = tris_[i].v, &u = tris_[j].v;
        for (const auto& [x, y] : {std::pair{t, u}, std::pair{u, t}})
            for (std::size_t m = 0; m < 3; ++m) clip_edge(i, j, x[m], x[(m + 1) % 3], y);
    }

    /// The part of edge pq inside the closed triangle y (coplanar with it), as a segment of i and j.
    void clip_edge(std::uint32_t i, std::uint32_t j, vid p, vid q, const tri3& y) {
        const int k = arr_.drop[i];
        const point3 &pp = pos(p), &pq = pos(q);
        std::vector<vid> found;
        for (vid v : {p, q})
            if (predicates::point_in_triangle(pos(v), pos(y[0]), pos(y[1]), pos(y[2]))) found.push_back(v);
        for (std::size_t m = 0; m < 3; ++m) {
            const vid a = y[m], b = y[(m + 1) % 3];
            if (predicates::point_on_segment(pos(a), pp, pq)) found.push_back(a);
            using predicates::detail::orient2d_drop;
            if (orient2d_drop(k, pp, pq, pos(a)) * orient2d_drop(k, pp, pq, pos(b)) < 0 &&
                orient2d_drop(k, pos(a), pos(b), pp) * orient2d_drop(k, pos(a), pos(b), pq) < 0)
                found.push_back(add(coplanar_crossing(pp, pq, pos(a), pos(b), k)));
        }
        record(i, j, found);
    }

    arrangement& arr_;
    const std::vector<point3>& explicit_;
    const std::vector<soup_triangle>& tris_;
    std::vector<triangle_cuts>& cuts_;
};

/// Candidate pairs: triangles of different meshes (of any, with `same_mesh`) whose closed boxes
/// overlap, by a sweep along x.
inline std::vector<std::array<std::uint32_t, 2>> candidate_pairs(const std::vector<exact_point>& pts,
                                                                 const std::vector<soup_triangle>& tris,
                                                                 const std::vector<int>& drop, bool same_mesh = false) {
    std::vector<std::array<point3, 2>> box(tris.size());
    for (std::size_t i = 0; i < tris.size(); ++i) {
        point3 lo = pts[tris[i].v[0]].explicit_coordinates(), hi = lo;
        for (vid v : tris[i].v)
            for (std::size_t k = 0; k < 3; ++k) {
                lo[k] = std::min(lo[k], pts[v].explicit_coordinates()[k]);
                hi[k] = std::max(hi[k], pts[v].explicit_coordinates()[k]);
            }
        box[i] = {lo, hi};
    }
    // The sweep runs along the axis of the largest extent, where boxes overlap least.
    point3 lo{}, hi{};
    for (std::size_t i = 0; i < box.size(); ++i)
        for (std::size_t k = 0; k < 3; ++k) {
            lo[k] = i == 0 ? box[i][0][k] : std::min(lo[k], box[i][0][k]);
            hi[k] = i == 0 ? box[i][1][k] : std::max(hi[k], box[i][1][k]);
        }
    const point3 ext{hi.x - lo.x, hi.y - lo.y, hi.z - lo.z};
    const std::size_t ax = ext.x >= ext.y && ext.x >= ext.z ? 0 : (ext.y >= ext.z ? 1 : 2);
    std::vector<std::uint32_t> order;
    for (std::uint32_t i = 0; i < tris.size(); ++i)
        if (drop[i] >= 0) order.push_back(i);
    std::sort(order.begin(), order.end(), [&](std::uint32_t x, std::uint32_t y) {
        return box[x][0][ax] < box[y][0][ax] || (box[x][0][ax] == box[y][0][ax] && x < y);
    });
    std::vector<std::array<std::uint32_t, 2>> out;
    for (std::size_t n = 0; n < order.size(); ++n) {
        const std::uint32_t x = order[n];
        for (std::size_t m = n + 1; m < order.size() && box[order[m]][0][ax] <= box[x][1][ax]; ++m) {
            const std::uint32_t y = order[m];
            if (!same_mesh && tris[x].mesh == tris[y].mesh) continue;
            bool overlap = true;
            for (std::size_t k = 0; k < 3; ++k)
                overlap = overlap && box[x][0][k] <= box[y][1][k] && box[y][0][k] <= box[x][1][k];
            if (overlap) out.push_back({std::min(x, y), std::max(x, y)});
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

/// Merges coincident points exactly: every id is mapped to the smallest id of its point.
inline std::vector<vid> merge_points(const std::vector<exact_point>& pts) {
    std::vector<vid> order(pts.size()), map(pts.size());
    std::iota(order.begin(), order.end(), vid(0));
    std::sort(order.begin(), order.end(), [&](vid x, vid y) {
        const int s = predicates::compare_xyz(pts[x], pts[y]);
        return s < 0 || (s == 0 && x < y);
    });
    for (std::size_t n = 0; n < order.size();) {
        std::size_t m = n + 1;
        while (m < order.size() && predicates::compare_xyz(pts[order[n]], pts[order[m]]) == 0) ++m;
        for (std::size_t r = n; r < m; ++r) map[order[r]] = order[n];
        n = m;
    }
    return map;
}

/// Adds to every triangle the points other triangles found on the edges it shares with them, so
/// the cuts of neighbours conform. Edges are keyed by their corner ids.
inline void share_edge_points(const arrangement& arr, const std::vector<soup_triangle>& tris,
                              std::vector<triangle_cuts>& cuts) {
    std::map<std::array<vid, 2>, std::vector<vid>> on_edge;
    for (std::size_t i = 0; i < tris.size(); ++i) {
        if (arr.drop[i] < 0) continue;
        const tri3& t = tris[i].v;
        for (vid p : cuts[i].points)
            for (std::size_t m = 0; m < 3; ++m) {
                const vid a = t[m], b = t[(m + 1) % 3];
                if (p == a || p == b) continue;
                if (predicates::orient2d(arr.drop[i], arr.points[a], arr.points[b], arr.points[p]) == 0)
                    on_edge[{std::min(a, b), std::max(a, b)}].push_back(p);
            }
    }
    for (std::size_t i = 0; i < tris.size(); ++i) {
        if (arr.drop[i] < 0) continue;
        const tri3& t = tris[i].v;
        for (std::size_t m = 0; m < 3; ++m) {
            const vid a = t[m], b = t[(m + 1) % 3];
            const auto it = on_edge.find({std::min(a, b), std::max(a, b)});
            if (it != on_edge.end()) cuts[i].points.insert(cuts[i].points.end(), it->second.begin(), it->second.end());
        }
    }
}

inline bool split_crossings(arrangement& arr, const std::vector<soup_triangle>& tris, std::vector<triangle_cuts>& cuts);

/// Builds the arrangement of `tris` over the explicit points `explicit_points` (whose exact
/// duplicates must already be merged), cutting triangles of one mesh by each other too when
/// `same_mesh`. False, with arr partly built, when a triangle's cuts cross each other (without
/// `same_mesh`, intersecting triangles within one mesh) or cancellation was asked.
inline bool build_arrangement(const std::vector<point3>& explicit_points, const std::vector<soup_triangle>& tris,
                              arrangement& arr, progress_gate* gate, bool same_mesh = false) {
    arr.points.assign(explicit_points.begin(), explicit_points.end());
    arr.coplanar.assign(tris.size(), {});
    arr.drop.resize(tris.size());
    for (std::size_t i = 0; i < tris.size(); ++i) {
        const tri3& t = tris[i].v;
        arr.drop[i] = t[0] == t[1] || t[1] == t[2] || t[2] == t[0]
                          ? -1
                          : projection_axis(explicit_points[t[0]], explicit_points[t[1]], explicit_points[t[2]]);
    }
    std::vector<triangle_cuts> cuts(tris.size());
    pair_stage stage(arr, explicit_points, tris, cuts);
    const auto pairs = candidate_pairs(arr.points, tris, arr.drop, same_mesh);
    for (const auto& p : pairs) ++(tris[p[0]].mesh != tris[p[1]].mesh ? arr.pairs : arr.same_mesh_pairs);
    for (std::size_t n = 0; n < pairs.size(); ++n) {
        if (gate && (n & 1023) == 0 && gate->cancelled()) return false;
        stage.intersect(pairs[n][0], pairs[n][1]);
    }
    if (gate && gate->cancelled()) return false;
    // Coincident points become one id; each triangle's lists are renamed and deduplicated.
    const std::vector<vid> map = merge_points(arr.points);
    for (triangle_cuts& c : cuts) {
        for (vid& p : c.points) p = map[p];
        for (auto& s : c.segments) s = {std::min(map[s[0]], map[s[1]]), std::max(map[s[0]], map[s[1]])};
        for (auto& s : c.tagged) s = {map[s[0]], map[s[1]], s[2]};
        std::sort(c.points.begin(), c.points.end());
        c.points.erase(std::unique(c.points.begin(), c.points.end()), c.points.end());
        std::sort(c.segments.begin(), c.segments.end());
        c.segments.erase(std::unique(c.segments.begin(), c.segments.end()), c.segments.end());
    }
    share_edge_points(arr, tris, cuts);
    if (arr.self_cut && !split_crossings(arr, tris, cuts)) return false;
    for (std::size_t i = 0; i < tris.size(); ++i) {
        if (arr.drop[i] < 0) continue;
        if (gate && (i & 255) == 0 && gate->cancelled()) return false;
        if (cuts[i].points.empty()) {
            arr.pieces.push_back({tris[i].v, std::uint32_t(i)});
            continue;
        }
        cut_triangle cut(arr.points, tris[i].v, arr.drop[i]);
        std::sort(cuts[i].points.begin(), cuts[i].points.end());
        cuts[i].points.erase(std::unique(cuts[i].points.begin(), cuts[i].points.end()), cuts[i].points.end());
        for (vid p : cuts[i].points)
            if (!cut.insert_point(p)) return false;
        for (const auto& s : cuts[i].segments)
            if (!cut.insert_segment(s[0], s[1])) return false;
        for (const tri3& t : cut.triangles()) arr.pieces.push_back({t, std::uint32_t(i)});
        arr.cut_edges.insert(arr.cut_edges.end(), cut.constraints().begin(), cut.constraints().end());
    }
    std::sort(arr.cut_edges.begin(), arr.cut_edges.end());
    arr.cut_edges.erase(std::unique(arr.cut_edges.begin(), arr.cut_edges.end()), arr.cut_edges.end());
    return true;
}

}  // namespace hmira::detail::boolean

#include "segment_crossings.hpp"
