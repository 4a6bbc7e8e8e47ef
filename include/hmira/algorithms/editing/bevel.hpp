// hmira/algorithms/editing/bevel.hpp
// Edge bevel (thesis 2.2): replace edges by strips of faces (a flat chamfer, or a rounded
// profile of several segments), cutting back the faces on either side, as 3D editors do.
// Built from the Euler operators; bevel_vertices is the vertex-only mode (= truncate).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <numbers>
#include <ranges>
#include <string>
#include <utility>
#include <vector>

#include "detail/editing_common.hpp"
#include "detail/grid_fill.hpp"
#include "truncate.hpp"

namespace hmira {

/// A mesh bevel() can edit: see editable_mesh (Euler operators, positions, indices).
template <class M, class T = default_traits<M>>
concept bevelable_mesh = editable_mesh<M, T>;

/// How wide and how round the bevel is.
struct bevel_options {
    /// Distance, inside each face next to a bevelled edge, from the old edge to the new one
    /// (the "offset" of 3D editors). Finite, > 0.
    double width = 0.1;
    /// Faces across each strip: 1 is a flat chamfer (one quad per edge); more follow a circular
    /// arc tangent to both neighbouring faces. In [1, 64].
    int segments = 1;
    /// Shrink the width where it would overlap: a new vertex reaches at most half way along the
    /// edge it slides on, or the bevelled edges it lies between, so it never passes an existing
    /// vertex or one placed from the edge's other end (at exactly half, points from both ends
    /// coincide, as when all four edges of a square face are bevelled to its centre). Each new
    /// vertex is limited by its own edges only (a local clamp), so one short edge shrinks only
    /// the bevel next to it. Off: the width is used as given.
    bool clamp_overlap = true;
    /// With clamp_overlap: shrink the width uniformly for the whole call to the smallest local
    /// limit instead (every strip equally wide, as before the local clamp).
    bool clamp_globally = false;
    /// Called every 1024 elements stepped through (selected edges, touched vertices and corners
    /// while planning; new points, strips and replaced vertices while building), from the
    /// calling thread; returning false cancels: the mesh is rolled back (or, while planning,
    /// never touched) and the error is errc::cancelled.
    progress_function progress = {};
};

/// What a bevel created.
template <class M, class T = default_traits<M>>
struct bevel_result {
    /// The strip faces, `segments` per bevelled edge (one for a strip whose two end vertices
    /// stay, unless the edge is on the boundary), edge by edge in input order, each from its
    /// F_L side (a boundary edge's: from the side of its face).
    std::vector<typename T::face_handle> strip_faces;
    /// The patches closing vertices where three or more bevelled edges meet (a triangle at a
    /// cube corner; with segments > 1 every face of its grid fill), and vertex-only mode's faces.
    std::vector<typename T::face_handle> vertex_faces;
    std::vector<typename T::vertex_handle> vertices;  ///< every new vertex
    double width = 0;            ///< the smallest width used by any new vertex (after clamping)
    double requested_width = 0;  ///< bevel_options::width
    std::size_t limited_edges = 0;  ///< bevelled edges with at least one new vertex limited by the clamp
    std::size_t bevelled_edges = 0;  ///< distinct edges bevelled (one strip each)
    /// Distinct selected edges not bevelled because a face would have had zero area (as
    /// validate() tests it): with them the strip, a shrunk face next to it or a corner patch
    /// collapses, as where clamped points from both ends of an edge meet. Left as they were.
    std::size_t skipped_edges = 0;
};

namespace detail::editing {

/// Point t in [0, 1] of the circular arc from a to b tangent to a-c and c-b (a rational
/// quadratic Bezier with control point c; exact circle when |a - c| = |b - c|, otherwise a
/// conic in the plane of a, b, c). Degenerate input (c on a or b) stays finite.
inline vec3<double> arc_point(const vec3<double>& a, const vec3<double>& c, const vec3<double>& b, double t) {
    const double cosb = dot(normalized(a - c), normalized(b - c));
    const double beta = std::acos(std::clamp(cosb, -1.0, 1.0));
    const double w = std::sin(beta / 2);
    const double b0 = (1 - t) * (1 - t), b1 = 2 * t * (1 - t) * w, b2 = t * t;
    return (a * b0 + c * b1 + b * b2) / (b0 + b1 + b2);
}

}  // namespace detail::editing

namespace detail::editing {

/// Whether face f has zero area as validate() tests it (the sum of its corners' cross
/// products, in the mesh's scalar, exactly zero), from any corner as a start: never true of a
/// face validate() passes, whichever corner a file lists first. Fewer than 3 corners: true.
template <class M, class T>
bool zero_area_face(const M& mesh, typename T::face_handle f) {
    using S = typename T::scalar;
    std::vector<vec3<S>> ps;
    for (auto v : T::face_vertices(mesh, f)) ps.push_back(static_cast<vec3<S>>(T::position(mesh, v)));
    const std::size_t n = ps.size();
    if (n < 3) return true;
    for (std::size_t start = 0; start < n; ++start) {
        vec3<S> area{};
        for (std::size_t i = 0; i < n; ++i) area += cross(ps[(start + i) % n], ps[(start + i + 1) % n]);
        if (area == vec3<S>{}) return true;
    }
    return false;
}

/// Everything bevel() decides before changing the mesh (from the original geometry).
template <class M, class T>
struct bevel_plan {
    /// A new vertex slid along an unbevelled edge.
    struct slide {
        typename T::halfedge_handle h;  ///< the unbevelled edge, leaving the end vertex
        double t = 0;                   ///< fraction of the edge from its source; < 0: split with its partner
        double t_back = -1;             ///< the partner's fraction from the other end, or < 0
        std::array<std::size_t, 2> edges{};       ///< the bevelled edges (indices) it serves; none: index_map::none
        std::array<std::size_t, 2> edges_back{};  ///< the partner's, when t_back >= 0
    };
    /// A new vertex inside a corner between two bevelled edges.
    struct inner {
        typename T::halfedge_handle corner;  ///< into the end vertex, between two bevelled edges
        typename T::vertex_handle v;         ///< the end vertex
        vec3<double> dir;                    ///< point = pos(v) + dir * width
        double width = 0;                    ///< after the clamp
        std::array<std::size_t, 2> edges{};  ///< the two bevelled edges (indices)
    };
    std::vector<typename T::halfedge_handle> sel;     ///< one halfedge per bevelled edge
    std::vector<std::size_t> sel_edge;                ///< the index of each bevelled edge
    std::vector<typename T::vertex_handle> touched;   ///< the bevelled edges' ends
    std::vector<bool> removed;                        ///< per touched vertex: it goes
    std::vector<slide> slides;                        ///< the slid vertices
    std::vector<inner> inners;                        ///< the corner vertices
    std::vector<std::array<bool, 2>> end_kept;        ///< per bevelled edge: source / target stays
    int segments = 1;                                 ///< bevel_options::segments
    bool share_meeting_points = false;                ///< slides meeting mid-edge share one point (global clamp)
    double requested_width = 0;                       ///< bevel_options::width
    double smallest_width = 0;                        ///< the smallest width used after the clamp
    std::size_t limited_edges = 0;                    ///< bevelled edges with a clamped new vertex
    /// Per bevelled edge: it is a boundary edge (sel holds its halfedge in its one face, the
    /// strip lies in that face and the edge itself stays as the strip's boundary side).
    std::vector<bool> on_boundary;
};

/// Builds the bevel planned in `plan` (see bevel()). Run inside a transaction (T journaled);
/// an inner failure, or a cancel through `progress`, is passed on. `origin` gets, for every new
/// vertex, the indices of the bevelled edges it was made for: (vertex index, edge index) pairs.
template <class M, class T, class Plan, class Out>
result<void> bevel_build(M& mesh, const Plan& plan, Out& out, edit_progress& progress,
                         std::vector<std::pair<std::size_t, std::size_t>>& origin) {
    namespace du = ::hmira::detail::euler;
    using H = typename T::halfedge_handle;
    using V = typename T::vertex_handle;
    const auto& sel = plan.sel;
    const auto& touched = plan.touched;
    const auto& removed = plan.removed;
    const auto& end_kept = plan.end_kept;
    out.width = plan.smallest_width;
    out.requested_width = plan.requested_width;
    out.limited_edges = plan.limited_edges;
    // The ends' positions are the rounded profiles' control points (the ends may be gone and
    // their handles reused by the time the profiles are built).
    std::vector<std::pair<vec3<double>, vec3<double>>> ends(sel.size());
    // Every loop below steps the progress: a cancel is heard within a block of any phase.
    progress.add_work(plan.slides.size() + plan.inners.size() + sel.size() + touched.size());
    for (std::size_t i = 0; i < sel.size(); ++i)
        ends[i] = {pos<M, T>(mesh, du::source<M, T>(mesh, sel[i])), pos<M, T>(mesh, T::target(mesh, sel[i]))};
    // 1. Split the slid edges (once where slides from both ends meet exactly).
    for (const auto& sl : plan.slides) {
        if (auto ok = progress.step(); !ok) return ok.error();
        if (sl.t < 0) continue;  // split with its partner from the other end
        const auto h = sl.h;
        const auto a = pos<M, T>(mesh, du::source<M, T>(mesh, h)), b = pos<M, T>(mesh, T::target(mesh, h));
        const auto s = split_edge<M, T>(mesh, h, lerp(a, b, sl.t));
        if (!s) return s.error();
        out.vertices.push_back(s.value().vertex);
        auto made_for = [&](V v, const std::array<std::size_t, 2>& es) {
            for (auto e : es)
                if (e != index_map::none) origin.emplace_back(T::vertex_index(mesh, v), e);
        };
        made_for(s.value().vertex, sl.edges);
        // Meeting slides share their point in a flat bevel; a rounded one needs both (their end
        // edges would otherwise join the same two vertices twice).
        // Under the local clamp both ends of many short edges reach the middle, where a shared
        // point would close a face next to two strips into a 2-gon: keep both points there.
        if (sl.t_back < 0) continue;
        if (sl.t + sl.t_back == 1.0 && plan.segments == 1 && plan.share_meeting_points) {
            made_for(s.value().vertex, sl.edges_back);
            continue;
        }
        const auto s2 = split_edge<M, T>(mesh, s.value().second, lerp(a, b, 1 - sl.t_back));
        if (!s2) return s2.error();
        out.vertices.push_back(s2.value().vertex);
        made_for(s2.value().vertex, sl.edges_back);
    }
    // 2. Points inside corners between two bevelled edges, hung from the vertex by makeEV.
    for (const auto& in : plan.inners) {
        if (auto ok = progress.step(); !ok) return ok.error();
        const auto r = mev<M, T>(mesh, in.corner, pos<M, T>(mesh, in.v) + in.dir * in.width);
        if (!r) return r.error();
        out.vertices.push_back(r.value().vertex);
        for (auto e : in.edges) origin.emplace_back(T::vertex_index(mesh, r.value().vertex), e);
    }
    // 3. Each bevelled edge: cut the quad (p, v, w, q) off each side, then join the two quads.
    std::vector<H> strip_side(sel.size());  // a halfedge of each strip, on its F_L long side
    //    A boundary edge has one face: its quad (u, w, q, p) is the whole strip, and the edge
    //    stays as the strip's boundary side.
    for (std::size_t i = 0; i < sel.size(); ++i) {
        if (auto ok = progress.step(); !ok) return ok.error();
        const auto h = sel[i], o = T::opposite(mesh, h);
        const auto left = mef<M, T>(mesh, T::prev(mesh, T::prev(mesh, h)), T::next(mesh, h));
        if (!left) return left.error();
        if (plan.on_boundary[i]) {
            strip_side[i] = T::opposite(mesh, left.value().halfedge);
            continue;
        }
        if (auto right = mef<M, T>(mesh, T::prev(mesh, T::prev(mesh, o)), T::next(mesh, o)); !right) return right.error();
        strip_side[i] = T::opposite(mesh, left.value().halfedge);  // q -> p, inside the strip
        if (auto ok = kef<M, T>(mesh, h); !ok) return ok.error();
    }
    // 4. Vertices with nothing left but new neighbours go.
    for (std::size_t k = 0; k < touched.size(); ++k) {
        if (auto ok = progress.step(); !ok) return ok.error();
        if (removed[k]) {
            const auto f = replace_vertex_by_polygon<M, T>(mesh, touched[k]);
            if (!f) return f.error();
            if (f.value() != T::null_face()) out.vertex_faces.push_back(f.value());
        }
    }
    // 5. Rounded profiles (segments > 1): split every end edge once along an arc (B), cut each
    //    strip across (C), and fill each vertex patch bounded by arcs only with a grid (D).
    if (plan.segments == 1) {
        for (auto qp : strip_side) out.strip_faces.push_back(T::face(mesh, qp));
        return {};
    }
    const auto n = static_cast<std::size_t>(plan.segments);
    progress.add_work(sel.size() * (n + 1));
    struct end_edge {
        V a, b;                     // the edge's ends, as first met (from a strip's F_L side)
        vec3<double> v{}, dir{};    // the original end vertex, and the unit edge direction away from it
        int uses = 0;               // strips ending in this edge (2 at a mitre or pass-through)
        H side{};                   // its halfedge in the first such strip (no edge dies before it is split)
        std::vector<V> arc;         // a, the arc points, b
        bool straight = false;      // a boundary strip ends in it: its points are evenly spaced on it
    };
    struct strip_end {
        bool pointed = false;  // the end vertex stayed: the strip ends in it
        V tip{};               // that vertex
        std::size_t edge = 0;  // else: which end edge
        bool reversed = false; // the end edge's a is on this strip's F_R side
    };
    std::vector<end_edge> end_edges;
    std::vector<std::vector<std::size_t>> end_edge_users;  // per end edge: the bevelled edges whose strips end in it
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> end_edge_at;
    std::vector<std::array<strip_end, 2>> strip_ends(sel.size());
    std::vector<typename T::face_handle> strip_face(sel.size());
    auto add_end = [&](std::size_t i, int side, H along, V a, V b) {
        const auto ia = T::vertex_index(mesh, a), ib = T::vertex_index(mesh, b);
        const auto key = std::make_pair(std::min(ia, ib), std::max(ia, ib));
        auto it = end_edge_at.find(key);
        if (it == end_edge_at.end()) {
            const auto& here = side == 0 ? ends[i].first : ends[i].second;
            const auto& there = side == 0 ? ends[i].second : ends[i].first;
            end_edges.push_back({a, b, here, normalized(there - here), 0, along, {}, false});
            end_edge_users.emplace_back();
            it = end_edge_at.emplace(key, end_edges.size() - 1).first;
        }
        auto& ee = end_edges[it->second];
        ++ee.uses;
        end_edge_users[it->second].push_back(plan.sel_edge[i]);
        if (plan.on_boundary[i]) ee.straight = true;
        strip_ends[i][side] = {false, V{}, it->second, ee.a != a};
    };
    for (std::size_t i = 0; i < sel.size(); ++i) {
        if (auto ok = progress.step(); !ok) return ok.error();
        const auto qp = strip_side[i];
        strip_face[i] = T::face(mesh, qp);
        // The strip's loop: q -> p -> (p', or kept s -> p') -> q' -> (q, or kept t -> q); a
        // boundary strip's: q -> p -> u -> w -> q, where u and w stay but p-u and w-q are end
        // edges (end_kept is false for it).
        if (end_kept[i][0]) strip_ends[i][0] = {true, T::target(mesh, T::next(mesh, qp)), 0, false};
        else add_end(i, 0, T::next(mesh, qp), T::target(mesh, qp), T::target(mesh, T::next(mesh, qp)));
        const auto back = T::prev(mesh, qp);
        if (end_kept[i][1]) strip_ends[i][1] = {true, du::source<M, T>(mesh, back), 0, false};
        else add_end(i, 1, back, T::target(mesh, back), du::source<M, T>(mesh, back));
    }
    // Vertex patches whose every side is an end edge get a grid; remember their corners now.
    struct patch { typename T::face_handle face; std::vector<V> corners; };
    std::vector<patch> patches;
    for (auto f : out.vertex_faces) {
        patch pa{f, {}};
        bool all_arcs = true;
        const auto start = T::face_halfedge(mesh, f);
        auto h = start;
        do {
            pa.corners.push_back(T::target(mesh, h));
            const auto a = T::vertex_index(mesh, du::source<M, T>(mesh, h)), b = T::vertex_index(mesh, T::target(mesh, h));
            if (!end_edge_at.contains(std::make_pair(std::min(a, b), std::max(a, b)))) all_arcs = false;
            h = T::next(mesh, h);
        } while (h != start);
        if (all_arcs && pa.corners.size() >= 3) patches.push_back(std::move(pa));
    }
    // B. Split each end edge once. Control point: the end vertex itself where two strips share
    //    the edge (their tangents meet there: the mitre); else the point of the bevelled edge's
    //    line nearest to the end edge's midpoint (a quarter circle at a three-edge corner).
    for (auto& ee : end_edges) {
        const auto pa = pos<M, T>(mesh, ee.a), pb = pos<M, T>(mesh, ee.b);
        // A boundary strip has one face to be tangent to: flat, its control point the end
        // edge's midpoint (arc_point is then linear in t).
        const auto ctrl = ee.straight ? (pa + pb) / 2.0 : ee.uses >= 2 ? ee.v : ee.v + ee.dir * dot((pa + pb) / 2.0 - ee.v, ee.dir);
        auto x = ee.side;
        const bool forward = du::source<M, T>(mesh, x) == ee.a;
        std::vector<V> arc{du::source<M, T>(mesh, x)};
        for (std::size_t j = 1; j < n; ++j) {
            if (auto ok = progress.step(); !ok) return ok.error();
            const double t = double(j) / double(n);
            const auto s = split_edge<M, T>(mesh, x, arc_point(pa, ctrl, pb, forward ? t : 1 - t));
            if (!s) return s.error();
            out.vertices.push_back(s.value().vertex);
            for (auto e : end_edge_users[std::size_t(&ee - end_edges.data())])
                origin.emplace_back(T::vertex_index(mesh, s.value().vertex), e);
            arc.push_back(s.value().vertex);
            x = s.value().second;
        }
        arc.push_back(T::target(mesh, x));
        if (!forward) std::reverse(arc.begin(), arc.end());
        ee.arc = std::move(arc);
    }
    // C. Cut each strip across: the j-th point of one end to the j-th of the other, both counted
    //    from the F_L side (a fan to the vertex at a pointed end). A strip pointed at both ends
    //    has no profile to follow and stays one face.
    for (std::size_t i = 0; i < sel.size(); ++i) {
        auto c = strip_face[i];
        out.strip_faces.push_back(c);
        if (strip_ends[i][0].pointed && strip_ends[i][1].pointed) continue;
        auto point = [&](int side, std::size_t j) {
            const auto& se = strip_ends[i][side];
            if (se.pointed) return se.tip;
            const auto& arc = end_edges[se.edge].arc;
            return se.reversed ? arc[n - j] : arc[j];
        };
        for (std::size_t j = 1; j < n; ++j) {
            if (auto ok = progress.step(); !ok) return ok.error();
            // makeEF's new face runs forward from the first end's point: the uncut rest.
            const auto h0 = into_vertex<M, T>(mesh, c, point(0, j));
            const auto h1 = into_vertex<M, T>(mesh, c, point(1, j));
            const auto cut = mef<M, T>(mesh, h0, h1);
            if (!cut) return cut.error();
            c = cut.value().face;
            out.strip_faces.push_back(c);
        }
    }
    // D. Grid-fill the vertex patches bounded by arcs only.
    for (const auto& pa : patches) {
        if (auto ok = progress.step(); !ok) return ok.error();
        const std::size_t k = pa.corners.size();
        std::vector<std::vector<V>> arcs(k);
        for (std::size_t s = 0; s < k; ++s) {
            // Side s runs from corner s - 1 to corner s (the corners were read as targets).
            const auto from = pa.corners[(s + k - 1) % k];
            const auto a = T::vertex_index(mesh, from), b = T::vertex_index(mesh, pa.corners[s]);
            const auto& ee = end_edges[end_edge_at.at(std::make_pair(std::min(a, b), std::max(a, b)))];
            arcs[s] = ee.arc;
            if (ee.a != from) std::reverse(arcs[s].begin(), arcs[s].end());
        }
        const auto filled = grid_fill<M, T>(mesh, pa.face, arcs);
        if (!filled) return filled.error();
        const auto& g = filled.value();
        // The grid's inner points serve every strip ending in the patch.
        std::vector<std::size_t> patch_edges;
        for (std::size_t s = 0; s < k; ++s) {
            const auto a = T::vertex_index(mesh, pa.corners[(s + k - 1) % k]), b = T::vertex_index(mesh, pa.corners[s]);
            const auto& users = end_edge_users[end_edge_at.at(std::make_pair(std::min(a, b), std::max(a, b)))];
            patch_edges.insert(patch_edges.end(), users.begin(), users.end());
        }
        for (auto v : g.vertices)
            for (auto e : patch_edges) origin.emplace_back(T::vertex_index(mesh, v), e);
        out.vertex_faces.insert(out.vertex_faces.end(), g.faces.begin(), g.faces.end());
        out.vertices.insert(out.vertices.end(), g.vertices.begin(), g.vertices.end());
    }
    return {};
}

}  // namespace detail::editing

/// Bevels the edges in `edges` (a range of edge handles; duplicates count once).
///
/// What happens, edge by edge and vertex by vertex (the behaviour of 3D editors' bevel with
/// the "offset" width):
/// - Each bevelled edge is replaced by a strip: `segments` quads whose long sides lie at
///   `width` from the old edge inside the two faces next to it; those faces shrink.
/// - At an end vertex, every face corner next to a bevelled edge gets a new vertex: on the
///   corner's other edge when that one is not bevelled (slid along it so that its offset from
///   the bevelled edge is `width`; an edge slid from two corners takes the mean), or inside the
///   face at `width` from both edges when both are bevelled.
/// - If every edge of the vertex is bevelled or next to a bevelled edge around it, the vertex
///   goes: its new vertices are joined into one face (a triangle at a cube corner with three
///   bevelled edges), or, with only two of them (a corner of degree 3 with one bevelled edge,
///   as on a cube), into one edge that the remaining face gains, exactly the chamfer of a cube
///   edge. At the boundary, that face or edge closes the corner with one boundary edge.
/// - Otherwise (the vertex also has edges away from the bevel, e.g. a degree-4 vertex of a
///   grid with one bevelled edge) the vertex stays where it is, with those edges, and the
///   strip ends in it: the strip face then has the vertex as a pointed end.
/// V/E/F: a cube edge with segments = 1 gives V + 2, E + 3, F + 1 (8/12/6 -> 10/15/7); with
/// segments = s, V + 2s, E + 3s, F + s.
///
/// Boundary edges (one face) bevel too, as in 3D editors: the strip lies in the one face,
/// between the edge and a new edge at `width` inside it, and the edge stays as the strip's
/// boundary side. Its end vertices stay where they are (the strip runs along the boundary up
/// to them); their corners in the face get new points as above, and the end edges (end
/// vertex to new point) carry a straight, evenly divided profile: the strip is s parallel
/// bands. The boundary keeps its shape, so a flat mesh keeps its area exactly.
/// - One boundary edge whose ends have an unbevelled edge in the face's corner (e.g. inside
///   a grid's side): V + 2s, E + 3s, F + s.
/// - A run of k boundary edges through vertices of degree 3: neighbouring strips share the
///   point slid along the edge between them: V + (k + 1)s, E + (2k + 1)s, F + ks; a whole
///   boundary loop of k edges (corner vertices of degree 2 get a point inside the corner,
///   shared by both strips as a mitre): V + ks, E + 2ks, F + ks.
/// - Where a bevelled boundary edge meets a bevelled interior edge, the vertex stays, the
///   corner between them gets one point inside the face, and the interior strip ends in the
///   vertex (a pointed end, as at a vertex that keeps edges away from the bevel): for the
///   grid vertex of degree 3 with its interior edge and one boundary edge bevelled, and the
///   far ends kept, V + 5 + 2(s - 1), E + 7 + 3(s - 1), F + 2 + (s - 1).
/// - An interior edge ending on the boundary is as before: its end goes when every corner
///   there is next to the bevel, closed by one boundary edge through its two new points.
///
/// With segments = n > 1 the flat result above is rounded:
/// - Every end edge (where a strip meets its end vertex's replacement) is split once into n
///   segments along a circular arc (arc_point). Its control point is the old end vertex where
///   two strips share the end edge (two bevelled edges meeting at a degree-3 vertex, or passing
///   straight through a degree-4 one: the mitre, whose points lie in the plane of both edges),
///   and otherwise the point of the bevelled edge's line nearest to the end edge's midpoint:
///   the old vertex on a cube edge's chamfer, and at a cube corner with three bevelled edges a
///   point that makes the arc a quarter circle of the strip's cylinder.
/// - Each strip is cut across into n faces, joining the j-th arc points of its two ends; at an
///   end vertex that stays the cuts fan out from it. A strip whose two end vertices both stay
///   has no profile to follow and remains one face.
/// - A patch whose every side is an arc (k >= 3 bevelled edges around a removed vertex, as at a
///   cube corner) is filled with a grid of quads (grid fill): with m = floor(n / 2), one m x m
///   quad patch per corner, meeting in a centre vertex (n even), or, for n odd, around a middle
///   k-gon (a triangle at a cube corner) with a strip of m quads between neighbouring patches.
///   Inner points come from Coons patches of the sides, then are projected onto the sphere
///   fitted to the patch's boundary by least squares, when that fit is good (rms distance below
///   1% of the radius, radius below 10 x the patch's diameter); at a cube corner the boundary
///   lies exactly on the sphere of radius `width` around the inner corner, so the patch does
///   too. Otherwise the Coons positions stay.
/// - A patch with straight sides (the vertex also had a face corner away from the bevel) stays
///   one face, its sides carrying the arc points: a non-planar polygon (editors' "cutoff"
///   corner).
/// All 12 edges of a cube with segments = 4 give a rounded cube: 6 + 48 + 8 x 12 faces.
/// No face of zero area is made (zero as validate() tests it: the sum of the corners' cross
/// products exactly zero, from any corner as a start). At the clamp limit new points from both
/// ends of an edge coincide, and new points may fall on one line; a face there would have zero
/// area. The build is then rolled back, one bevelled edge that made a new vertex of each such
/// face is dropped from the selection, and the rest is planned and built again from the
/// unchanged mesh, until no such face remains (each round drops an edge, so at most k rounds;
/// on real meshes two or three). The dropped edges stay as they were: bevelled_edges and
/// skipped_edges count both sides. If every edge is dropped, errc::unsupported (mesh unchanged).
///
/// Boundary edges' strips are listed from the side of their face.
///
/// Complexity O(sum of the end vertices' degrees and the touched faces' degrees) per edge =
/// O(V_adjacentV), plus O(k) expected for the selection and slide lookups of k edges (hash
/// tables), for segments = 1; with n segments add O(k log k) for the end-edge table, O(n^2)
/// per strip (cuts found by walking the strip) and O(k n^3) per patch of k sides (every
/// halfedge of the grid fill is found by walking the current face), for O(k n^2) new elements.
/// Clamp: see bevel_options::clamp_overlap; the result reports the requested width, the
/// smallest width used and how many edges were limited.
/// Atomic: on any error, when an allocation throws, or when options.progress cancels
/// ("bevel: cancelled"), the mesh is unchanged (see
/// detail/transaction.hpp). Errors (mesh unchanged): errc::invalid_argument for options out of range or an empty
/// selection; errc::invalid_handle for a missing edge; errc::unsupported for an edge with no
/// face on either side (a wire edge) or a degenerate corner (collinear edges);
/// errc::topology / errc::non_manifold for end vertices truncate() would reject.
template <class M, class T = default_traits<M>, class R>
    requires bevelable_mesh<M, T> && range_of_handles<R, typename T::edge_handle>
result<bevel_result<M, T>> bevel(M& mesh, const R& edges, const bevel_options& options = {}) {
    namespace de = detail::editing;
    namespace du = detail::euler;
    using H = typename T::halfedge_handle;
    if (!(options.width > 0) || !de::finite(options.width))
        return fail(errc::invalid_argument, "bevel: width must be finite and > 0");
    if (options.segments < 1 || options.segments > 64)
        return fail(errc::invalid_argument, "bevel: segments must lie in [1, 64], got " + std::to_string(options.segments));
    // Planning is as long as building: it steps the progress too, so a cancel is heard early.
    de::edit_progress progress(options.progress, 0, "bevel");
    if constexpr (std::ranges::sized_range<const R>) progress.add_work(std::ranges::size(edges));
    // Selection: one halfedge per distinct edge (a boundary edge's in its face).
    std::vector<std::pair<H, bool>> chosen;  // halfedge, on the boundary
    de::index_set chosen_edges;
    for (auto e0 : edges) {
        if (auto ok = progress.step(); !ok) return ok.error();
        const typename T::edge_handle e = e0;
        if (T::edge_index(mesh, e) >= T::edge_index_bound(mesh) || du::known_removed<M, T>(mesh, e))
            return fail(errc::invalid_handle, "bevel: edge " + std::to_string(T::edge_index(mesh, e)) + " does not exist (out of range or deleted)",
                        static_cast<long long>(T::edge_index(mesh, e)));
        auto h = T::edge_halfedge(mesh, e);
        const bool no_left = T::face(mesh, h) == T::null_face(), no_right = T::face(mesh, T::opposite(mesh, h)) == T::null_face();
        if (no_left && no_right)
            return fail(errc::unsupported, "bevel: edge " + std::to_string(T::edge_index(mesh, e)) +
                                               " has no face on either side (a wire edge); there is no face to hold the strip",
                        static_cast<long long>(T::edge_index(mesh, e)));
        if (no_left) h = T::opposite(mesh, h);  // a boundary edge's strip lies in its one face
        if (chosen_edges.insert(T::edge_index(mesh, e))) chosen.emplace_back(h, no_left || no_right);
    }
    if (chosen.empty()) return fail(errc::invalid_argument, "bevel: no edge selected");
    // Plan and build; an edge that leaves a face of zero area (as validate() tests it) is
    // dropped, and the rest planned and built again (the failed build rolled back): see below.
    de::index_set dropped;
    std::size_t dropped_count = 0;
    for (;;) {
        de::bevel_plan<M, T> plan;
        plan.segments = options.segments;
        auto& sel = plan.sel;
        de::index_set bevelled;
        for (const auto& [h, boundary] : chosen) {
            const auto e = T::edge_index(mesh, T::edge(mesh, h));
            if (dropped.contains(e)) continue;
            bevelled.insert(e);
            sel.push_back(h);
            plan.sel_edge.push_back(e);
            plan.on_boundary.push_back(boundary);
        }
        if (sel.empty())
            return fail(errc::unsupported, "bevel: every selected edge would leave a face of zero area "
                                           "(its width clamped too far); nothing bevelled");
        auto edge_of = [&](H h) { return T::edge_index(mesh, T::edge(mesh, h)); };
        auto is_bev = [&](H h) { return bevelled.contains(edge_of(h)); };
        auto& touched = plan.touched;
        de::index_map touched_at;  // vertex index -> position in touched
        progress.add_work(sel.size());
        for (auto h : sel) {
            if (auto ok = progress.step(); !ok) return ok.error();
            for (auto v : {du::source<M, T>(mesh, h), T::target(mesh, h)}) {
                if (auto ok = de::check_corner_vertex<M, T>(mesh, v, "bevel"); !ok) return ok.error();
                if (touched_at.emplace(T::vertex_index(mesh, v), touched.size()) == touched.size()) touched.push_back(v);
            }
        }

        // Plan, from the original geometry: slides on unbevelled edges, points inside corners
        // between two bevelled edges, which vertices go. Offsets are per unit width; each new
        // point remembers the bevelled edges it serves, for the clamp's count.
        struct slide { H h; double sum = 0; int n = 0; std::size_t edge_a, edge_b; };
        std::vector<slide> slides;
        de::index_map slide_at;  // halfedge index -> position in slides
        auto& inners = plan.inners;
        std::vector<std::array<std::size_t, 2>> inner_edges;
        auto& removed = plan.removed;
        removed.assign(touched.size(), true);
        progress.add_work(touched.size());
        for (std::size_t k = 0; k < touched.size(); ++k) {
            if (auto ok = progress.step(); !ok) return ok.error();
            const auto v = touched[k];
            const auto pv = de::pos<M, T>(mesh, v);
            const auto hs = de::outgoing<M, T>(mesh, v);
            const std::size_t d = hs.size();
            std::vector<bool> near(d, false);
            for (std::size_t i = 0; i < d; ++i) {
                const auto a = hs[i], b = hs[(i + 1) % d];
                if (T::face(mesh, b) == T::null_face()) continue;  // the boundary gap is no corner
                const bool ba = is_bev(a), bb = is_bev(b);
                if (!ba && !bb) continue;
                near[i] = near[(i + 1) % d] = true;
                const auto ua = normalized(de::pos<M, T>(mesh, T::target(mesh, a)) - pv);
                const auto ub = normalized(de::pos<M, T>(mesh, T::target(mesh, b)) - pv);
                const double s = norm(cross(ua, ub));
                if (!(s > 1e-9))
                    return fail(errc::unsupported, "bevel: the edges of a face corner at " + du::name<M, T>("vertex", mesh, v) +
                                                       " are collinear; the offset there is undefined",
                                du::index_of<M, T>(mesh, v));
                if (ba && bb) {
                    inners.push_back({T::opposite(mesh, a), v, (ua + ub) / s, 0});
                    inner_edges.push_back({edge_of(a), edge_of(b)});
                    continue;
                }
                const H along = ba ? b : a;
                const std::size_t at = slide_at.emplace(T::halfedge_index(mesh, along), slides.size());
                if (at == slides.size()) slides.push_back({along, 0, 0, edge_of(ba ? a : b), de::index_map::none});
                else slides[at].edge_b = edge_of(ba ? a : b);
                slides[at].sum += 1.0 / s;
                ++slides[at].n;
            }
            for (std::size_t i = 0; i < d; ++i)
                if (!near[i]) removed[k] = false;
        }
        // A bevelled boundary edge's strip runs along the boundary up to its ends: they stay.
        for (std::size_t i = 0; i < sel.size(); ++i)
            if (plan.on_boundary[i])
                for (auto v : {du::source<M, T>(mesh, sel[i]), T::target(mesh, sel[i])})
                    removed[touched_at.find(T::vertex_index(mesh, v))] = false;
        // Clamp: each new vertex reaches at most half way along the edges it lies on or projects
        // onto (a slid vertex at the far end would collapse the face beside the strip). Its own
        // limit, as a width: `limit` per slide and per inner point.
        std::vector<double> slide_limit(slides.size()), inner_limit(inners.size(), 1e300);
        std::vector<double> slide_len(slides.size());
        for (std::size_t i = 0; i < slides.size(); ++i) {
            const auto& s = slides[i];
            slide_len[i] = norm(de::pos<M, T>(mesh, T::target(mesh, s.h)) - de::pos<M, T>(mesh, du::source<M, T>(mesh, s.h)));
            slide_limit[i] = slide_len[i] / 2 / (s.sum / s.n);
        }
        for (std::size_t i = 0; i < inners.size(); ++i) {
            // The inner point projects onto both bevelled edges at |dir|-scaled distances.
            const auto& in = inners[i];
            for (auto h : {T::opposite(mesh, in.corner), T::next(mesh, in.corner)}) {
                const auto e = de::pos<M, T>(mesh, T::target(mesh, h)) - de::pos<M, T>(mesh, in.v);
                const double along = dot(in.dir, normalized(e));
                if (along > 0) inner_limit[i] = std::min(inner_limit[i], norm(e) / 2 / along);
            }
        }
        double global = options.width;
        if (options.clamp_overlap && options.clamp_globally) {
            for (double l : slide_limit) global = std::min(global, l);
            for (double l : inner_limit) global = std::min(global, l);
        }
        auto used = [&](double limit) { return options.clamp_overlap ? std::min(global, limit) : options.width; };
        de::index_set limited;
        plan.smallest_width = options.width;
        auto note = [&](double w, std::size_t e) {
            plan.smallest_width = std::min(plan.smallest_width, w);
            if (w < options.width && e != de::index_map::none) limited.insert(e);
        };
        for (std::size_t i = 0; i < slides.size(); ++i) {
            const double w = used(slide_limit[i]);
            note(w, slides[i].edge_a);
            note(w, slides[i].edge_b);
            // The fraction of the edge the slide covers, from its source.
            const double t = w * slides[i].sum / slides[i].n / slide_len[i];
            plan.slides.push_back({slides[i].h, t, -1.0, {slides[i].edge_a, slides[i].edge_b}, {}});
        }
        for (std::size_t i = 0; i < inners.size(); ++i) {
            inners[i].width = used(inner_limit[i]);
            inners[i].edges = inner_edges[i];
            note(inners[i].width, inner_edges[i][0]);
            note(inners[i].width, inner_edges[i][1]);
        }
        plan.limited_edges = limited.size();
        // Slides from both ends of one edge are split together: the first carries the second's
        // fraction, the second is dropped (t < 0).
        for (std::size_t i = 0; i < plan.slides.size(); ++i) {
            if (plan.slides[i].t < 0) continue;
            const std::size_t j = slide_at.find(T::halfedge_index(mesh, T::opposite(mesh, plan.slides[i].h)));
            if (j == de::index_map::none || j < i) continue;
            plan.slides[i].t_back = plan.slides[j].t;
            plan.slides[i].edges_back = plan.slides[j].edges;
            plan.slides[j].t = -1.0;
        }
        // Which ends of each bevelled edge stay (the strip then ends in a point there).
        plan.end_kept.resize(sel.size());
        for (std::size_t i = 0; i < sel.size(); ++i)
            for (int side = 0; side < 2; ++side) {
                const auto v = side == 0 ? du::source<M, T>(mesh, sel[i]) : T::target(mesh, sel[i]);
                // A boundary strip's ends stay, yet its ends are edges (p-u, w-q) for the profile.
                plan.end_kept[i][side] = !plan.on_boundary[i] && !removed[touched_at.find(T::vertex_index(mesh, v))];
            }
        plan.requested_width = options.width;
        plan.share_meeting_points = !options.clamp_overlap || options.clamp_globally;
        // Build, then test every face at a new vertex as validate() does (its area vector, the sum
        // of the corners' cross products, exactly zero), from each corner as a start: a face that
        // fails there blames one bevelled edge its new vertices were made for. Any blame rolls the
        // build back; the blamed edges are dropped and the rest planned again from the unchanged
        // mesh. Each round drops at least one edge, so this ends.
        std::vector<std::size_t> blamed;
        auto r = de::transact<M, T>(mesh, [&]<class JT>() -> result<bevel_result<M, T>> {
            bevel_result<M, T> out;
            std::vector<std::pair<std::size_t, std::size_t>> origin;
            if (auto ok = de::bevel_build<M, JT>(mesh, plan, out, progress, origin); !ok) return ok.error();
            std::sort(origin.begin(), origin.end());
            de::index_set seen;
            for (auto v : out.vertices)
                for (auto h : de::outgoing<M, JT>(mesh, v)) {
                    const auto f = JT::face(mesh, h);
                    if (f == JT::null_face() || !seen.insert(JT::face_index(mesh, f))) continue;
                    if (!de::zero_area_face<M, JT>(mesh, f)) continue;
                    std::size_t blame = de::index_map::none;
                    for (auto u : JT::face_vertices(mesh, f)) {
                        const auto at = std::lower_bound(origin.begin(), origin.end(),
                                                     std::pair<std::size_t, std::size_t>{JT::vertex_index(mesh, u), 0});
                        if (at != origin.end() && at->first == JT::vertex_index(mesh, u))
                            blame = std::min(blame, at->second);
                    }
                    if (blame != de::index_map::none) blamed.push_back(blame);
                }
            if (!blamed.empty()) return fail(errc::topology, "bevel: a face would have zero area");
            return out;
        });
        if (r || blamed.empty()) {
            if (r) {
                r.value().skipped_edges = dropped_count;
                r.value().bevelled_edges = sel.size();
            }
            return r;
        }
        for (auto e : blamed)
            if (dropped.insert(e)) ++dropped_count;
    }
}

/// Bevels one edge (see the range overload). A cube edge with segments = 1 gives the chamfer:
/// V + 2, E + 3, F + 1, removing a prism of volume width^2 / 2 x the edge length.
template <class M, class T = default_traits<M>>
    requires bevelable_mesh<M, T>
result<bevel_result<M, T>> bevel(M& mesh, typename T::edge_handle edge, const bevel_options& options = {}) {
    const typename T::edge_handle one[1] = {edge};
    return bevel<M, T>(mesh, one, options);
}

/// Vertex-only bevel, as 3D editors call it: exactly truncate(mesh, vertices, {.distance =
/// options.width}) (cut points at `width` along each edge, clamped at half an edge where both
/// ends are bevelled). Only segments = 1 is supported (errc::unsupported otherwise);
/// clamp_overlap is always on. Returns the new faces in vertex_faces. Errors as truncate().
template <class M, class T = default_traits<M>, class R>
    requires bevelable_mesh<M, T> && range_of_handles<R, typename T::vertex_handle>
result<bevel_result<M, T>> bevel_vertices(M& mesh, const R& vertices, const bevel_options& options = {}) {
    if (options.segments != 1)
        return fail(errc::unsupported, "bevel_vertices: only segments = 1 (a flat cut) is supported in vertex-only mode");
    if (!(options.width > 0) || !detail::editing::finite(options.width))
        return fail(errc::invalid_argument, "bevel_vertices: width must be finite and > 0");
    auto r = truncate<M, T>(mesh, vertices, {.fraction = 1.0 / 3.0, .distance = options.width, .progress = options.progress});
    if (!r) return r.error();
    bevel_result<M, T> out;
    for (auto f : r.value().faces)
        if (f != T::null_face()) out.vertex_faces.push_back(f);
    out.vertices = std::move(r.value().vertices);
    out.width = options.width;
    out.requested_width = options.width;
    return out;
}

}  // namespace hmira
