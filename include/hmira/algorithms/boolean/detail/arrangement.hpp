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
#include "../../conversion/detail/parallel.hpp"
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

using box3 = std::array<point3, 2>;

inline bool boxes_overlap(const box3& x, const box3& y) {
    return x[0].x <= y[1].x && y[0].x <= x[1].x && x[0].y <= y[1].y && y[0].y <= x[1].y && x[0].z <= y[1].z &&
           y[0].z <= x[1].z;
}

/// A uniform grid over a box, its cells about the size of the boxes it holds; a box is listed in
/// every cell it overlaps (compressed rows). Cell coordinates are a monotone function of a
/// coordinate, so two overlapping boxes share the cell holding the low corner of their overlap,
/// which reports each pair once.
class box_grid {
public:
    box_grid(const box3& region, const std::vector<box3>& box, const std::vector<std::uint32_t>& ids) : lo_(region[0]) {
        // Cells of the mean box size, at most about 2 cells per box in all (1024 per axis).
        point3 mean{};
        for (std::uint32_t i : ids)
            for (std::size_t k = 0; k < 3; ++k) mean[k] += box[i][1][k] - box[i][0][k];
        const double budget = 2.0 * double(ids.size()) + 64;
        double cell = std::max({mean.x, mean.y, mean.z}) / double(std::max<std::size_t>(ids.size(), 1));
        const point3 e{region[1].x - region[0].x, region[1].y - region[0].y, region[1].z - region[0].z};
        if (!(cell > 0)) cell = std::max({e.x, e.y, e.z}) / std::cbrt(budget);
        for (int round = 0; round < 2; ++round) {
            double cells = 1;
            for (std::size_t k = 0; k < 3; ++k) {
                n_[k] = cell > 0 ? std::size_t(std::clamp(std::ceil(e[k] / cell), 1.0, 1024.0)) : 1;
                cells *= double(n_[k]);
            }
            if (cells <= budget) break;
            cell *= std::cbrt(cells / budget);
        }
        for (std::size_t k = 0; k < 3; ++k) inv_[k] = e[k] > 0 ? double(n_[k]) / e[k] : 0.0;
        start_.assign(n_[0] * n_[1] * n_[2] + 1, 0);
        for (std::uint32_t i : ids) each_cell(box[i], [&](std::size_t c) { ++start_[c + 1]; });
        for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
        items_.resize(start_.back());
        std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
        for (std::uint32_t i : ids) each_cell(box[i], [&](std::size_t c) { items_[fill[c]++] = i; });
    }

    /// The cell coordinate of x along axis k, clamped to the grid.
    std::size_t coord(std::size_t k, double x) const {
        const double t = std::floor((x - lo_[k]) * inv_[k]);
        return t <= 0 ? 0 : std::min(n_[k] - 1, std::size_t(t));
    }

    template <class F>
    void each_cell(const box3& b, const F& f) const {
        std::array<std::size_t, 3> from{}, to{};
        for (std::size_t k = 0; k < 3; ++k) from[k] = coord(k, b[0][k]), to[k] = coord(k, b[1][k]);
        for (std::size_t z = from[2]; z <= to[2]; ++z)
            for (std::size_t y = from[1]; y <= to[1]; ++y)
                for (std::size_t x = from[0]; x <= to[0]; ++x) f((z * n_[1] + y) * n_[0] + x);
    }

    /// Calls f(j) once for every listed box j overlapping b (j == i included if listed).
    template <class F>
    void query(const std::vector<box3>& box, const box3& b, const F& f) const {
        each_cell(b, [&](std::size_t c) {
            for (std::size_t n = start_[c]; n < start_[c + 1]; ++n) {
                const box3& o = box[items_[n]];
                if (!boxes_overlap(b, o)) continue;
                std::size_t owner = 0;  // the cell of the overlap's low corner
                for (std::size_t k = 3; k-- > 0;) owner = owner * n_[k] + coord(k, std::max(b[0][k], o[0][k]));
                if (owner == c) f(items_[n]);
            }
        });
    }

private:
    point3 lo_;
    std::array<std::size_t, 3> n_{};
    point3 inv_{};
    std::vector<std::size_t> start_;
    std::vector<std::uint32_t> items_;
};

/// Candidate pairs: triangles of different meshes (of any, with `same_mesh`) whose closed boxes
/// overlap, (smaller, larger), sorted. Without `same_mesh`, the triangles of mesh 1 that reach the
/// overlap of the two meshes' boxes go into a uniform grid and each triangle of mesh 0 asks it;
/// with it, every triangle goes into the grid and asks it, keeping the pairs (i, j) with i < j.
/// The queries run in parallel chunks whose lists are joined in order: the pairs do not depend on
/// the thread count.
inline std::vector<std::array<std::uint32_t, 2>> candidate_pairs(const std::vector<exact_point>& pts,
                                                                 const std::vector<soup_triangle>& tris,
                                                                 const std::vector<int>& drop, bool same_mesh = false) {
    std::vector<box3> box(tris.size());
    std::array<box3, 3> whole{};  // mesh 0, mesh 1, all meshes
    std::array<bool, 3> any{};
    for (std::size_t i = 0; i < tris.size(); ++i) {
        point3 lo = pts[tris[i].v[0]].explicit_coordinates(), hi = lo;
        for (vid v : tris[i].v)
            for (std::size_t k = 0; k < 3; ++k) {
                lo[k] = std::min(lo[k], pts[v].explicit_coordinates()[k]);
                hi[k] = std::max(hi[k], pts[v].explicit_coordinates()[k]);
            }
        box[i] = {lo, hi};
        if (drop[i] < 0) continue;
        const auto grow = [&](std::size_t m) {
            box3& w = whole[m];
            for (std::size_t k = 0; k < 3 && any[m]; ++k)
                w[0][k] = std::min(w[0][k], lo[k]), w[1][k] = std::max(w[1][k], hi[k]);
            if (!any[m]) w = box[i], any[m] = true;
        };
        if (tris[i].mesh <= 1) grow(tris[i].mesh);
        grow(2);
    }
    std::vector<std::array<std::uint32_t, 2>> out;
    std::array<std::vector<std::uint32_t>, 2> ids;  // ids[1] go into the grid, ids[0] ask it
    box3 region{};
    if (same_mesh) {
        if (!any[2]) return out;
        region = whole[2];
        for (std::uint32_t i = 0; i < tris.size(); ++i)
            if (drop[i] >= 0) ids[1].push_back(i);
        ids[0] = ids[1];
    } else {
        if (!any[0] || !any[1] || !boxes_overlap(whole[0], whole[1])) return out;
        for (std::size_t k = 0; k < 3; ++k) {
            region[0][k] = std::max(whole[0][0][k], whole[1][0][k]);
            region[1][k] = std::min(whole[0][1][k], whole[1][1][k]);
        }
        for (std::uint32_t i = 0; i < tris.size(); ++i)
            if (drop[i] >= 0 && tris[i].mesh <= 1 && boxes_overlap(box[i], region)) ids[tris[i].mesh].push_back(i);
    }
    const box_grid grid(region, box, ids[1]);
    const std::size_t grain = 256, chunks = (ids[0].size() + grain - 1) / grain;
    std::vector<std::vector<std::array<std::uint32_t, 2>>> found(chunks);
    parallel_chunks(chunks, 1, [&](std::size_t from, std::size_t to) {
        for (std::size_t c = from; c < to; ++c)
            for (std::size_t n = c * grain; n < std::min(ids[0].size(), (c + 1) * grain); ++n) {
                const std::uint32_t x = ids[0][n];
                grid.query(box, box[x], [&](std::uint32_t y) {
                    if (!same_mesh || x < y) found[c].push_back({std::min(x, y), std::max(x, y)});
                });
            }
    });
    for (const auto& f : found) out.insert(out.end(), f.begin(), f.end());
    std::sort(out.begin(), out.end());
    return out;
}

/// Merges coincident points exactly: every id is mapped to the smallest id of its point. The
/// first `distinct` points are explicit: they are sorted by their coordinates (ties by id) and
/// merged by plain comparison; the constructed points after them are sorted exactly, and each run
/// of equal ones is looked up among the explicit points.
inline std::vector<vid> merge_points(const std::vector<exact_point>& pts, std::size_t explicit_count) {
    std::vector<vid> map(pts.size());
    std::iota(map.begin(), map.end(), vid(0));
    std::vector<vid> order(pts.size() - explicit_count);
    std::iota(order.begin(), order.end(), vid(explicit_count));
    std::sort(order.begin(), order.end(), [&](vid x, vid y) {
        const int s = predicates::compare_xyz(pts[x], pts[y]);
        return s < 0 || (s == 0 && x < y);
    });
    std::vector<vid> given(explicit_count);
    std::iota(given.begin(), given.end(), vid(0));
    std::sort(given.begin(), given.end(), [&](vid x, vid y) {
        const point3 &p = pts[x].explicit_coordinates(), &q = pts[y].explicit_coordinates();
        return p.x < q.x || (p.x == q.x && (p.y < q.y || (p.y == q.y && (p.z < q.z || (p.z == q.z && x < y)))));
    });
    for (std::size_t n = 1; n < given.size(); ++n)
        if (pts[given[n]].explicit_coordinates() == pts[given[n - 1]].explicit_coordinates())
            map[given[n]] = map[given[n - 1]];
    for (std::size_t n = 0; n < order.size();) {
        std::size_t m = n + 1;
        while (m < order.size() && predicates::compare_xyz(pts[order[n]], pts[order[m]]) == 0) ++m;
        const auto at = std::lower_bound(given.begin(), given.end(), order[n],
                                         [&](vid g, vid x) { return predicates::compare_xyz(pts[g], pts[x]) < 0; });
        const vid to = at != given.end() && predicates::compare_xyz(pts[*at], pts[order[n]]) == 0 ? *at : order[n];
        for (std::size_t r = n; r < m; ++r) map[order[r]] = to;
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

inline bool split_crossings(arrangement& arr, const std::vector<soup_triangle>& tris, std::vector<triangle_cuts>& cuts,
                            std::size_t explicit_count);

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
    const std::vector<vid> map = merge_points(arr.points, explicit_points.size());
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
    if (arr.self_cut && !split_crossings(arr, tris, cuts, explicit_points.size())) return false;
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
