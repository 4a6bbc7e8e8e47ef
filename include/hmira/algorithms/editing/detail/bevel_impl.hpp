// hmira/algorithms/editing/detail/bevel_impl.hpp
// The machinery of bevel() (see bevel.hpp, which includes this file after its declarations):
// the build from the Euler operators, phase by phase, of the plan made in bevel_plan.hpp, the
// zero-area check that drops an edge and plans again, and the entry points. Not public API.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <ranges>
#include <string>
#include <utility>
#include <vector>

#include "bevel_plan.hpp"
#include "editing_common.hpp"
#include "grid_fill.hpp"
#include "../truncate.hpp"

namespace hmira::detail::editing {

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

// ---------------------------------------------------------------------------------------------
// Build, flat (segments = 1, and the first stage of a rounded bevel)
// ---------------------------------------------------------------------------------------------

/// For every new vertex, the bevelled edges it was made for: (vertex index, edge index) pairs.
using bevel_origins = std::vector<std::pair<std::size_t, std::size_t>>;

template <class M, class T>
void note_origin(const M& mesh, typename T::vertex_handle v, const std::array<std::size_t, 2>& edges,
                 bevel_origins& origin) {
    for (auto e : edges)
        if (e != index_map::none) origin.emplace_back(T::vertex_index(mesh, v), e);
}

/// Step 1: splits the slid edges (once where slides from both ends meet exactly).
template <class M, class T, class Plan, class Out>
result<void> bevel_split_slides(M& mesh, const Plan& plan, Out& out, progress_gate& progress, bevel_origins& origin) {
    namespace du = ::hmira::detail::euler;
    for (const auto& sl : plan.slides) {
        if (auto ok = progress.step(); !ok) return ok.error();
        if (sl.t < 0) continue;  // split with its partner from the other end
        const auto h = sl.h;
        const auto a = pos<M, T>(mesh, du::source<M, T>(mesh, h)), b = pos<M, T>(mesh, T::target(mesh, h));
        const auto s = split_edge<M, T>(mesh, h, lerp(a, b, sl.t));
        if (!s) return s.error();
        out.vertices.push_back(s.value().vertex);
        note_origin<M, T>(mesh, s.value().vertex, sl.edges, origin);
        // Meeting slides share their point in a flat bevel; a rounded one needs both (their end
        // edges would otherwise join the same two vertices twice).
        // Under the local clamp both ends of many short edges reach the middle, where a shared
        // point would close a face next to two strips into a 2-gon: keep both points there.
        if (sl.t_back < 0) continue;
        if (sl.t + sl.t_back == 1.0 && plan.segments == 1 && plan.share_meeting_points) {
            note_origin<M, T>(mesh, s.value().vertex, sl.edges_back, origin);
            continue;
        }
        const auto s2 = split_edge<M, T>(mesh, s.value().second, lerp(a, b, 1 - sl.t_back));
        if (!s2) return s2.error();
        out.vertices.push_back(s2.value().vertex);
        note_origin<M, T>(mesh, s2.value().vertex, sl.edges_back, origin);
    }
    return {};
}

/// Step 2: points inside corners between two bevelled edges, hung from the vertex by makeEV.
template <class M, class T, class Plan, class Out>
result<void> bevel_hang_inners(M& mesh, const Plan& plan, Out& out, progress_gate& progress, bevel_origins& origin) {
    for (const auto& in : plan.inners) {
        if (auto ok = progress.step(); !ok) return ok.error();
        const auto r = mev<M, T>(mesh, in.corner, pos<M, T>(mesh, in.v) + in.dir * in.width);
        if (!r) return r.error();
        out.vertices.push_back(r.value().vertex);
        for (auto e : in.edges) origin.emplace_back(T::vertex_index(mesh, r.value().vertex), e);
    }
    return {};
}

/// Step 3: each bevelled edge: cuts the quad (p, v, w, q) off each side, then joins the two
/// quads. A boundary edge has one face: its quad (u, w, q, p) is the whole strip, and the edge
/// stays as the strip's boundary side. Returns a halfedge of each strip, on its F_L long side.
template <class M, class T, class Plan>
result<std::vector<typename T::halfedge_handle>> bevel_cut_strips(M& mesh, const Plan& plan, progress_gate& progress) {
    const auto& sel = plan.sel;
    std::vector<typename T::halfedge_handle> strip_side(sel.size());
    for (std::size_t i = 0; i < sel.size(); ++i) {
        if (auto ok = progress.step(); !ok) return ok.error();
        const auto h = sel[i], o = T::opposite(mesh, h);
        const auto left = mef<M, T>(mesh, T::prev(mesh, T::prev(mesh, h)), T::next(mesh, h));
        if (!left) return left.error();
        if (plan.on_boundary[i]) {
            strip_side[i] = T::opposite(mesh, left.value().halfedge);
            continue;
        }
        if (auto right = mef<M, T>(mesh, T::prev(mesh, T::prev(mesh, o)), T::next(mesh, o)); !right)
            return right.error();
        strip_side[i] = T::opposite(mesh, left.value().halfedge);  // q -> p, inside the strip
        if (auto ok = kef<M, T>(mesh, h); !ok) return ok.error();
    }
    return strip_side;
}

/// Step 4: vertices with nothing left but new neighbours go, each replaced by one polygon.
template <class M, class T, class Plan, class Out>
result<void> bevel_remove_vertices(M& mesh, const Plan& plan, Out& out, progress_gate& progress) {
    for (std::size_t k = 0; k < plan.touched.size(); ++k) {
        if (auto ok = progress.step(); !ok) return ok.error();
        if (plan.removed[k]) {
            const auto f = replace_vertex_by_polygon<M, T>(mesh, plan.touched[k]);
            if (!f) return f.error();
            if (f.value() != T::null_face()) out.vertex_faces.push_back(f.value());
        }
    }
    return {};
}

// ---------------------------------------------------------------------------------------------
// Build, rounded (segments > 1): split every end edge once along an arc (B), cut each strip
// across (C), and fill each vertex patch bounded by arcs only with a grid (D).
// ---------------------------------------------------------------------------------------------

/// The rounded profiles' bookkeeping: the end edges (where a strip meets its end vertex's
/// replacement), how each strip ends, and the vertex patches to grid-fill.
template <class M, class T>
struct bevel_profiles {
    using V = typename T::vertex_handle;
    using H = typename T::halfedge_handle;
    struct end_edge {
        V a, b;                   // the edge's ends, as first met (from a strip's F_L side)
        vec3<double> v{}, dir{};  // the original end vertex, and the unit edge direction away from it
        int uses = 0;             // strips ending in this edge (2 at a mitre or pass-through)
        H side{};                 // its halfedge in the first such strip (no edge dies before it is split)
        std::vector<V> arc;       // a, the arc points, b
        bool straight = false;    // a boundary strip ends in it: its points are evenly spaced on it
    };
    struct strip_end {
        bool pointed = false;   // the end vertex stayed: the strip ends in it
        V tip{};                // that vertex
        std::size_t edge = 0;   // else: which end edge
        bool reversed = false;  // the end edge's a is on this strip's F_R side
    };
    struct patch {
        typename T::face_handle face;
        std::vector<V> corners;
    };
    std::vector<end_edge> end_edges;
    std::vector<std::vector<std::size_t>> end_edge_users;  // per end edge: the bevelled edges whose strips end in it
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> end_edge_at;
    std::vector<std::array<strip_end, 2>> strip_ends;
    std::vector<typename T::face_handle> strip_face;
    std::vector<patch> patches;

    /// The end edge joining the vertices of indices a and b.
    std::size_t end_edge_between(std::size_t a, std::size_t b) const {
        return end_edge_at.at(std::make_pair(std::min(a, b), std::max(a, b)));
    }
};

/// Records how strip i ends on `side` (0: the source of its bevelled edge) in the end edge a-b
/// (halfedge `along`), creating that end edge on first use. `ends` holds the bevelled edges'
/// original end positions.
template <class M, class T, class Plan>
void bevel_add_end(const M& mesh, const Plan& plan, const std::vector<std::pair<vec3<double>, vec3<double>>>& ends,
                   bevel_profiles<M, T>& pr, std::size_t i, int side, typename T::halfedge_handle along,
                   typename T::vertex_handle a, typename T::vertex_handle b) {
    using V = typename T::vertex_handle;
    const auto ia = T::vertex_index(mesh, a), ib = T::vertex_index(mesh, b);
    const auto key = std::make_pair(std::min(ia, ib), std::max(ia, ib));
    auto it = pr.end_edge_at.find(key);
    if (it == pr.end_edge_at.end()) {
        const auto& here = side == 0 ? ends[i].first : ends[i].second;
        const auto& there = side == 0 ? ends[i].second : ends[i].first;
        pr.end_edges.push_back({a, b, here, normalized(there - here), 0, along, {}, false});
        pr.end_edge_users.emplace_back();
        it = pr.end_edge_at.emplace(key, pr.end_edges.size() - 1).first;
    }
    auto& ee = pr.end_edges[it->second];
    ++ee.uses;
    pr.end_edge_users[it->second].push_back(plan.sel_edge[i]);
    if (plan.on_boundary[i]) ee.straight = true;
    pr.strip_ends[i][side] = {false, V{}, it->second, ee.a != a};
}

/// Finds every strip's two ends (a kept vertex, or an end edge), then the vertex patches whose
/// every side is an end edge (they get a grid; their corners are remembered now).
template <class M, class T, class Plan, class Out>
result<void> bevel_find_profiles(const M& mesh, const Plan& plan,
                                 const std::vector<std::pair<vec3<double>, vec3<double>>>& ends,
                                 const std::vector<typename T::halfedge_handle>& strip_side, const Out& out,
                                 bevel_profiles<M, T>& pr, progress_gate& progress) {
    namespace du = ::hmira::detail::euler;
    const auto& sel = plan.sel;
    const auto& end_kept = plan.end_kept;
    pr.strip_ends.resize(sel.size());
    pr.strip_face.resize(sel.size());
    for (std::size_t i = 0; i < sel.size(); ++i) {
        if (auto ok = progress.step(); !ok) return ok.error();
        const auto qp = strip_side[i];
        pr.strip_face[i] = T::face(mesh, qp);
        // The strip's loop: q -> p -> (p', or kept s -> p') -> q' -> (q, or kept t -> q); a
        // boundary strip's: q -> p -> u -> w -> q, where u and w stay but p-u and w-q are end
        // edges (end_kept is false for it).
        if (end_kept[i][0])
            pr.strip_ends[i][0] = {true, T::target(mesh, T::next(mesh, qp)), 0, false};
        else
            bevel_add_end<M, T>(mesh, plan, ends, pr, i, 0, T::next(mesh, qp), T::target(mesh, qp),
                                T::target(mesh, T::next(mesh, qp)));
        const auto back = T::prev(mesh, qp);
        if (end_kept[i][1])
            pr.strip_ends[i][1] = {true, du::source<M, T>(mesh, back), 0, false};
        else
            bevel_add_end<M, T>(mesh, plan, ends, pr, i, 1, back, T::target(mesh, back), du::source<M, T>(mesh, back));
    }
    for (auto f : out.vertex_faces) {
        typename bevel_profiles<M, T>::patch pa{f, {}};
        bool all_arcs = true;
        const auto start = T::face_halfedge(mesh, f);
        auto h = start;
        do {
            pa.corners.push_back(T::target(mesh, h));
            const auto a = T::vertex_index(mesh, du::source<M, T>(mesh, h)),
                       b = T::vertex_index(mesh, T::target(mesh, h));
            if (!pr.end_edge_at.contains(std::make_pair(std::min(a, b), std::max(a, b)))) all_arcs = false;
            h = T::next(mesh, h);
        } while (h != start);
        if (all_arcs && pa.corners.size() >= 3) pr.patches.push_back(std::move(pa));
    }
    return {};
}

/// B. Splits each end edge once into n segments along an arc. Control point: the end vertex
/// itself where two strips share the edge (their tangents meet there: the mitre); else the
/// point of the bevelled edge's line nearest to the end edge's midpoint (a quarter circle at a
/// three-edge corner).
template <class M, class T, class Out>
result<void> bevel_split_end_edges(M& mesh, std::size_t n, bevel_profiles<M, T>& pr, Out& out, progress_gate& progress,
                                   bevel_origins& origin) {
    namespace du = ::hmira::detail::euler;
    using V = typename T::vertex_handle;
    for (auto& ee : pr.end_edges) {
        const auto pa = pos<M, T>(mesh, ee.a), pb = pos<M, T>(mesh, ee.b);
        // A boundary strip has one face to be tangent to: flat, its control point the end
        // edge's midpoint (arc_point is then linear in t).
        const auto ctrl = ee.straight    ? (pa + pb) / 2.0
                          : ee.uses >= 2 ? ee.v
                                         : ee.v + ee.dir * dot((pa + pb) / 2.0 - ee.v, ee.dir);
        auto x = ee.side;
        const bool forward = du::source<M, T>(mesh, x) == ee.a;
        std::vector<V> arc{du::source<M, T>(mesh, x)};
        for (std::size_t j = 1; j < n; ++j) {
            if (auto ok = progress.step(); !ok) return ok.error();
            const double t = double(j) / double(n);
            const auto s = split_edge<M, T>(mesh, x, arc_point(pa, ctrl, pb, forward ? t : 1 - t));
            if (!s) return s.error();
            out.vertices.push_back(s.value().vertex);
            for (auto e : pr.end_edge_users[std::size_t(&ee - pr.end_edges.data())])
                origin.emplace_back(T::vertex_index(mesh, s.value().vertex), e);
            arc.push_back(s.value().vertex);
            x = s.value().second;
        }
        arc.push_back(T::target(mesh, x));
        if (!forward) std::reverse(arc.begin(), arc.end());
        ee.arc = std::move(arc);
    }
    return {};
}

/// C. Cuts each strip across: the j-th point of one end to the j-th of the other, both counted
/// from the F_L side (a fan to the vertex at a pointed end). A strip pointed at both ends has
/// no profile to follow and stays one face. Lists the strip faces in out.strip_faces.
template <class M, class T, class Out>
result<void> bevel_cut_across(M& mesh, std::size_t n, const bevel_profiles<M, T>& pr, Out& out,
                              progress_gate& progress) {
    for (std::size_t i = 0; i < pr.strip_face.size(); ++i) {
        auto c = pr.strip_face[i];
        out.strip_faces.push_back(c);
        if (pr.strip_ends[i][0].pointed && pr.strip_ends[i][1].pointed) continue;
        auto point = [&](int side, std::size_t j) {
            const auto& se = pr.strip_ends[i][side];
            if (se.pointed) return se.tip;
            const auto& arc = pr.end_edges[se.edge].arc;
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
    return {};
}

/// D. Grid-fills the vertex patches bounded by arcs only; the grid's inner points serve every
/// strip ending in the patch.
template <class M, class T, class Out>
result<void> bevel_fill_patches(M& mesh, const bevel_profiles<M, T>& pr, Out& out, progress_gate& progress,
                                bevel_origins& origin) {
    using V = typename T::vertex_handle;
    for (const auto& pa : pr.patches) {
        if (auto ok = progress.step(); !ok) return ok.error();
        const std::size_t k = pa.corners.size();
        std::vector<std::vector<V>> arcs(k);
        for (std::size_t s = 0; s < k; ++s) {
            // Side s runs from corner s - 1 to corner s (the corners were read as targets).
            const auto from = pa.corners[(s + k - 1) % k];
            const auto& ee =
                pr.end_edges[pr.end_edge_between(T::vertex_index(mesh, from), T::vertex_index(mesh, pa.corners[s]))];
            arcs[s] = ee.arc;
            if (ee.a != from) std::reverse(arcs[s].begin(), arcs[s].end());
        }
        const auto filled = grid_fill<M, T>(mesh, pa.face, arcs);
        if (!filled) return filled.error();
        const auto& g = filled.value();
        std::vector<std::size_t> patch_edges;
        for (std::size_t s = 0; s < k; ++s) {
            const auto a = T::vertex_index(mesh, pa.corners[(s + k - 1) % k]), b = T::vertex_index(mesh, pa.corners[s]);
            const auto& users = pr.end_edge_users[pr.end_edge_between(a, b)];
            patch_edges.insert(patch_edges.end(), users.begin(), users.end());
        }
        for (auto v : g.vertices)
            for (auto e : patch_edges) origin.emplace_back(T::vertex_index(mesh, v), e);
        out.vertex_faces.insert(out.vertex_faces.end(), g.faces.begin(), g.faces.end());
        out.vertices.insert(out.vertices.end(), g.vertices.begin(), g.vertices.end());
    }
    return {};
}

/// Builds the bevel planned in `plan` (see bevel()). Run inside a transaction (T journaled);
/// an inner failure, or a cancel through `progress`, is passed on. `origin` gets, for every new
/// vertex, the indices of the bevelled edges it was made for: (vertex index, edge index) pairs.
template <class M, class T, class Plan, class Out>
result<void> bevel_build(M& mesh, const Plan& plan, Out& out, progress_gate& progress, bevel_origins& origin) {
    namespace du = ::hmira::detail::euler;
    const auto& sel = plan.sel;
    out.width = plan.smallest_width;
    out.requested_width = plan.requested_width;
    out.limited_edges = plan.limited_edges;
    // The ends' positions are the rounded profiles' control points (the ends may be gone and
    // their handles reused by the time the profiles are built).
    std::vector<std::pair<vec3<double>, vec3<double>>> ends(sel.size());
    // Every phase steps the progress: a cancel is heard within a block of any phase.
    progress.add_work(plan.slides.size() + plan.inners.size() + sel.size() + plan.touched.size());
    for (std::size_t i = 0; i < sel.size(); ++i)
        ends[i] = {pos<M, T>(mesh, du::source<M, T>(mesh, sel[i])), pos<M, T>(mesh, T::target(mesh, sel[i]))};
    if (auto ok = bevel_split_slides<M, T>(mesh, plan, out, progress, origin); !ok) return ok.error();
    if (auto ok = bevel_hang_inners<M, T>(mesh, plan, out, progress, origin); !ok) return ok.error();
    const auto strip_side = bevel_cut_strips<M, T>(mesh, plan, progress);
    if (!strip_side) return strip_side.error();
    if (auto ok = bevel_remove_vertices<M, T>(mesh, plan, out, progress); !ok) return ok.error();
    if (plan.segments == 1) {
        for (auto qp : strip_side.value()) out.strip_faces.push_back(T::face(mesh, qp));
        return {};
    }
    const auto n = static_cast<std::size_t>(plan.segments);
    progress.add_work(sel.size() * (n + 1));
    bevel_profiles<M, T> pr;
    if (auto ok = bevel_find_profiles<M, T>(mesh, plan, ends, strip_side.value(), out, pr, progress); !ok)
        return ok.error();
    if (auto ok = bevel_split_end_edges<M, T>(mesh, n, pr, out, progress, origin); !ok) return ok.error();
    if (auto ok = bevel_cut_across<M, T>(mesh, n, pr, out, progress); !ok) return ok.error();
    return bevel_fill_patches<M, T>(mesh, pr, out, progress, origin);
}

/// Builds `plan` in a transaction, then tests every face at a new vertex as validate() does
/// (its area vector, the sum of the corners' cross products, exactly zero), from each corner as
/// a start: a face that fails there blames one bevelled edge its new vertices were made for
/// (added to `blamed`). Any blame rolls the build back (errc::topology).
template <class M, class T>
result<bevel_result<M, T>> bevel_build_checked(M& mesh, const bevel_plan<M, T>& plan, progress_gate& progress,
                                               std::vector<std::size_t>& blamed) {
    return transact<M, T>(mesh, [&]<class JT>() -> result<bevel_result<M, T>> {
        bevel_result<M, T> out;
        bevel_origins origin;
        if (auto ok = bevel_build<M, JT>(mesh, plan, out, progress, origin); !ok) return ok.error();
        std::sort(origin.begin(), origin.end());
        index_set seen;
        for (auto v : out.vertices)
            for (auto h : outgoing<M, JT>(mesh, v)) {
                const auto f = JT::face(mesh, h);
                if (f == JT::null_face() || !seen.insert(JT::face_index(mesh, f))) continue;
                if (!zero_area_face<M, JT>(mesh, f)) continue;
                std::size_t blame = index_map::none;
                for (auto u : JT::face_vertices(mesh, f)) {
                    const auto at = std::lower_bound(origin.begin(), origin.end(),
                                                     std::pair<std::size_t, std::size_t>{JT::vertex_index(mesh, u), 0});
                    if (at != origin.end() && at->first == JT::vertex_index(mesh, u))
                        blame = std::min(blame, at->second);
                }
                if (blame != index_map::none) blamed.push_back(blame);
            }
        if (!blamed.empty()) return fail(errc::topology, "bevel: a face would have zero area");
        return out;
    });
}

}  // namespace hmira::detail::editing

namespace hmira {

template <class M, class T, class R>
    requires bevelable_mesh<M, T> && range_of_handles<R, typename T::edge_handle>
result<bevel_result<M, T>> bevel(M& mesh, const R& edges, const bevel_options& options) {
    namespace de = detail::editing;
    if (!(options.width > 0) || !de::finite(options.width))
        return fail(errc::invalid_argument, "bevel: width must be finite and > 0");
    if (options.segments < 1 || options.segments > 64)
        return fail(errc::invalid_argument,
                    "bevel: segments must lie in [1, 64], got " + std::to_string(options.segments));
    // Planning is as long as building: it steps the progress too, so a cancel is heard early.
    detail::progress_gate progress(options.progress, 0, "bevel");
    if constexpr (std::ranges::sized_range<const R>) progress.add_work(std::ranges::size(edges));
    const auto chosen = de::bevel_select<M, T>(mesh, edges, progress);
    if (!chosen) return chosen.error();
    // Plan and build; an edge that leaves a face of zero area is dropped, and the rest planned
    // and built again from the unchanged mesh (the failed build rolled back). Each round drops
    // at least one edge, so this ends.
    de::index_set dropped;
    std::size_t dropped_count = 0;
    for (;;) {
        const auto plan = de::bevel_make_plan<M, T>(mesh, chosen.value(), dropped, options, progress);
        if (!plan) return plan.error();
        std::vector<std::size_t> blamed;
        auto r = de::bevel_build_checked<M, T>(mesh, plan.value(), progress, blamed);
        if (r || blamed.empty()) {
            if (r) {
                r.value().skipped_edges = dropped_count;
                r.value().bevelled_edges = plan.value().sel.size();
            }
            return r;
        }
        for (auto e : blamed)
            if (dropped.insert(e)) ++dropped_count;
    }
}

template <class M, class T>
    requires bevelable_mesh<M, T>
result<bevel_result<M, T>> bevel(M& mesh, typename T::edge_handle edge, const bevel_options& options) {
    const typename T::edge_handle one[1] = {edge};
    return bevel<M, T>(mesh, one, options);
}

template <class M, class T, class R>
    requires bevelable_mesh<M, T> && range_of_handles<R, typename T::vertex_handle>
result<bevel_result<M, T>> bevel_vertices(M& mesh, const R& vertices, const bevel_options& options) {
    if (options.segments != 1)
        return fail(errc::unsupported,
                    "bevel_vertices: only segments = 1 (a flat cut) is supported in vertex-only mode");
    if (!(options.width > 0) || !detail::editing::finite(options.width))
        return fail(errc::invalid_argument, "bevel_vertices: width must be finite and > 0");
    auto r = truncate<M, T>(mesh, vertices,
                            {.fraction = 1.0 / 3.0, .distance = options.width, .progress = options.progress});
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
