// hmira/algorithms/editing/detail/bevel_plan.hpp
// What bevel() decides before it changes the mesh, from the original geometry: the selection,
// where every new point goes (slid along an edge or inside a corner), the clamp that keeps
// points from crossing, and which end vertices go. Part of bevel_impl.hpp; not public API.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "editing_common.hpp"

namespace hmira::detail::editing {

/// Everything bevel() decides before changing the mesh (from the original geometry).
template <class M, class T>
struct bevel_plan {
    /// A new vertex slid along an unbevelled edge.
    struct slide {
        typename T::halfedge_handle h;            ///< the unbevelled edge, leaving the end vertex
        double t = 0;                             ///< fraction of the edge from its source; < 0: split with its partner
        double t_back = -1;                       ///< the partner's fraction from the other end, or < 0
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
    std::vector<typename T::halfedge_handle> sel;    ///< one halfedge per bevelled edge
    std::vector<std::size_t> sel_edge;               ///< the index of each bevelled edge
    std::vector<typename T::vertex_handle> touched;  ///< the bevelled edges' ends
    std::vector<bool> removed;                       ///< per touched vertex: it goes
    std::vector<slide> slides;                       ///< the slid vertices
    std::vector<inner> inners;                       ///< the corner vertices
    std::vector<std::array<bool, 2>> end_kept;       ///< per bevelled edge: source / target stays
    int segments = 1;                                ///< bevel_options::segments
    bool share_meeting_points = false;               ///< slides meeting mid-edge share one point (global clamp)
    double requested_width = 0;                      ///< bevel_options::width
    double smallest_width = 0;                       ///< the smallest width used after the clamp
    std::size_t limited_edges = 0;                   ///< bevelled edges with a clamped new vertex
    /// Per bevelled edge: it is a boundary edge (sel holds its halfedge in its one face, the
    /// strip lies in that face and the edge itself stays as the strip's boundary side).
    std::vector<bool> on_boundary;
};

/// The selection: one halfedge per distinct edge (a boundary edge's in its face), with whether
/// the edge is on the boundary, in input order. Steps `progress` once per input edge.
template <class M, class T, class R>
result<std::vector<std::pair<typename T::halfedge_handle, bool>>> bevel_select(const M& mesh, const R& edges,
                                                                               progress_gate& progress) {
    namespace du = ::hmira::detail::euler;
    std::vector<std::pair<typename T::halfedge_handle, bool>> chosen;  // halfedge, on the boundary
    index_set chosen_edges;
    for (auto e0 : edges) {
        if (auto ok = progress.step(); !ok) return ok.error();
        const typename T::edge_handle e = e0;
        if (T::edge_index(mesh, e) >= T::edge_index_bound(mesh) || du::known_removed<M, T>(mesh, e))
            return fail(
                errc::invalid_handle,
                "bevel: edge " + std::to_string(T::edge_index(mesh, e)) + " does not exist (out of range or deleted)",
                static_cast<long long>(T::edge_index(mesh, e)));
        auto h = T::edge_halfedge(mesh, e);
        const bool no_left = T::face(mesh, h) == T::null_face();
        const bool no_right = T::face(mesh, T::opposite(mesh, h)) == T::null_face();
        if (no_left && no_right)
            return fail(errc::unsupported,
                        "bevel: edge " + std::to_string(T::edge_index(mesh, e)) +
                            " has no face on either side (a wire edge); there is no face to hold the strip",
                        static_cast<long long>(T::edge_index(mesh, e)));
        if (no_left) h = T::opposite(mesh, h);  // a boundary edge's strip lies in its one face
        if (chosen_edges.insert(T::edge_index(mesh, e))) chosen.emplace_back(h, no_left || no_right);
    }
    if (chosen.empty()) return fail(errc::invalid_argument, "bevel: no edge selected");
    return chosen;
}

/// What planning one round of bevel() works on: the plan it fills, and its lookups.
template <class M, class T>
struct bevel_planning {
    using H = typename T::halfedge_handle;
    /// A new vertex slid along an unbevelled edge: its offsets per unit width from the corners
    /// that slide it (their mean is used), and the bevelled edges it serves.
    struct slide_offset {
        H h;
        double sum = 0;
        int n = 0;
        std::size_t edge_a, edge_b;
    };
    bevel_plan<M, T> plan;
    index_set bevelled;                                   // edge indices of the bevelled edges
    index_map touched_at;                                 // vertex index -> position in plan.touched
    std::vector<slide_offset> slides;                     // the slides, before the clamp
    index_map slide_at;                                   // halfedge index -> position in slides
    std::vector<std::array<std::size_t, 2>> inner_edges;  // per inner point: its two bevelled edges

    std::size_t edge_of(const M& mesh, H h) const { return T::edge_index(mesh, T::edge(mesh, h)); }
    bool is_bevelled(const M& mesh, H h) const { return bevelled.contains(edge_of(mesh, h)); }
};

/// The chosen edges not yet dropped become the plan's selection; their ends, checked as
/// corners, become plan.touched. errc::unsupported when every edge has been dropped.
template <class M, class T>
result<void> bevel_plan_selection(const M& mesh,
                                  const std::vector<std::pair<typename T::halfedge_handle, bool>>& chosen,
                                  const index_set& dropped, bevel_planning<M, T>& st, progress_gate& progress) {
    namespace du = ::hmira::detail::euler;
    auto& plan = st.plan;
    for (const auto& [h, boundary] : chosen) {
        const auto e = T::edge_index(mesh, T::edge(mesh, h));
        if (dropped.contains(e)) continue;
        st.bevelled.insert(e);
        plan.sel.push_back(h);
        plan.sel_edge.push_back(e);
        plan.on_boundary.push_back(boundary);
    }
    if (plan.sel.empty())
        return fail(errc::unsupported,
                    "bevel: every selected edge would leave a face of zero area "
                    "(its width clamped too far); nothing bevelled");
    progress.add_work(plan.sel.size());
    for (auto h : plan.sel) {
        if (auto ok = progress.step(); !ok) return ok.error();
        for (auto v : {du::source<M, T>(mesh, h), T::target(mesh, h)}) {
            if (auto ok = check_corner_vertex<M, T>(mesh, v, "bevel"); !ok) return ok.error();
            if (st.touched_at.emplace(T::vertex_index(mesh, v), plan.touched.size()) == plan.touched.size())
                plan.touched.push_back(v);
        }
    }
    return {};
}

/// From the original geometry: slides on unbevelled edges, points inside corners between two
/// bevelled edges, and which touched vertices go. Offsets are per unit width; each new point
/// remembers the bevelled edges it serves, for the clamp's count. errc::unsupported for a
/// corner whose edges are collinear.
template <class M, class T>
result<void> bevel_plan_corners(const M& mesh, bevel_planning<M, T>& st, progress_gate& progress) {
    namespace du = ::hmira::detail::euler;
    using H = typename T::halfedge_handle;
    auto& plan = st.plan;
    const auto& touched = plan.touched;
    auto& removed = plan.removed;
    removed.assign(touched.size(), true);
    progress.add_work(touched.size());
    for (std::size_t k = 0; k < touched.size(); ++k) {
        if (auto ok = progress.step(); !ok) return ok.error();
        const auto v = touched[k];
        const auto pv = pos<M, T>(mesh, v);
        const auto hs = outgoing<M, T>(mesh, v);
        const std::size_t d = hs.size();
        std::vector<bool> near(d, false);
        for (std::size_t i = 0; i < d; ++i) {
            const auto a = hs[i], b = hs[(i + 1) % d];
            if (T::face(mesh, b) == T::null_face()) continue;  // the boundary gap is no corner
            const bool ba = st.is_bevelled(mesh, a), bb = st.is_bevelled(mesh, b);
            if (!ba && !bb) continue;
            near[i] = near[(i + 1) % d] = true;
            const auto ua = normalized(pos<M, T>(mesh, T::target(mesh, a)) - pv);
            const auto ub = normalized(pos<M, T>(mesh, T::target(mesh, b)) - pv);
            const double s = norm(cross(ua, ub));
            if (!(s > 1e-9))
                return fail(errc::unsupported,
                            "bevel: the edges of a face corner at " + du::name<M, T>("vertex", mesh, v) +
                                " are collinear; the offset there is undefined",
                            du::index_of<M, T>(mesh, v));
            if (ba && bb) {
                plan.inners.push_back({T::opposite(mesh, a), v, (ua + ub) / s, 0});
                st.inner_edges.push_back({st.edge_of(mesh, a), st.edge_of(mesh, b)});
                continue;
            }
            const H along = ba ? b : a;
            const std::size_t at = st.slide_at.emplace(T::halfedge_index(mesh, along), st.slides.size());
            if (at == st.slides.size())
                st.slides.push_back({along, 0, 0, st.edge_of(mesh, ba ? a : b), index_map::none});
            else
                st.slides[at].edge_b = st.edge_of(mesh, ba ? a : b);
            st.slides[at].sum += 1.0 / s;
            ++st.slides[at].n;
        }
        for (std::size_t i = 0; i < d; ++i)
            if (!near[i]) removed[k] = false;
    }
    // A bevelled boundary edge's strip runs along the boundary up to its ends: they stay.
    for (std::size_t i = 0; i < plan.sel.size(); ++i)
        if (plan.on_boundary[i])
            for (auto v : {du::source<M, T>(mesh, plan.sel[i]), T::target(mesh, plan.sel[i])})
                removed[st.touched_at.find(T::vertex_index(mesh, v))] = false;
    return {};
}

/// The clamp: each new vertex reaches at most half way along the edges it lies on or projects
/// onto (a slid vertex at the far end would collapse the face beside the strip). Sets every
/// new point's width (its own limit, or the smallest of all with clamp_globally), the plan's
/// smallest width and count of limited edges, and pairs the slides from both ends of one edge.
template <class M, class T>
void bevel_plan_widths(const M& mesh, bevel_planning<M, T>& st, const bevel_options& options) {
    namespace du = ::hmira::detail::euler;
    auto& plan = st.plan;
    auto& inners = plan.inners;
    const auto& slides = st.slides;
    // Each new point's own limit, as a width.
    std::vector<double> slide_limit(slides.size()), inner_limit(inners.size(), 1e300);
    std::vector<double> slide_len(slides.size());
    for (std::size_t i = 0; i < slides.size(); ++i) {
        const auto& s = slides[i];
        slide_len[i] = norm(pos<M, T>(mesh, T::target(mesh, s.h)) - pos<M, T>(mesh, du::source<M, T>(mesh, s.h)));
        slide_limit[i] = slide_len[i] / 2 / (s.sum / s.n);
    }
    for (std::size_t i = 0; i < inners.size(); ++i) {
        // The inner point projects onto both bevelled edges at |dir|-scaled distances.
        const auto& in = inners[i];
        for (auto h : {T::opposite(mesh, in.corner), T::next(mesh, in.corner)}) {
            const auto e = pos<M, T>(mesh, T::target(mesh, h)) - pos<M, T>(mesh, in.v);
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
    index_set limited;
    plan.smallest_width = options.width;
    auto note = [&](double w, std::size_t e) {
        plan.smallest_width = std::min(plan.smallest_width, w);
        if (w < options.width && e != index_map::none) limited.insert(e);
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
        inners[i].edges = st.inner_edges[i];
        note(inners[i].width, st.inner_edges[i][0]);
        note(inners[i].width, st.inner_edges[i][1]);
    }
    plan.limited_edges = limited.size();
    // Slides from both ends of one edge are split together: the first carries the second's
    // fraction, the second is dropped (t < 0).
    for (std::size_t i = 0; i < plan.slides.size(); ++i) {
        if (plan.slides[i].t < 0) continue;
        const std::size_t j = st.slide_at.find(T::halfedge_index(mesh, T::opposite(mesh, plan.slides[i].h)));
        if (j == index_map::none || j < i) continue;
        plan.slides[i].t_back = plan.slides[j].t;
        plan.slides[i].edges_back = plan.slides[j].edges;
        plan.slides[j].t = -1.0;
    }
}

/// Plans one round of bevel(): the chosen edges minus the dropped ones, from the mesh as it is.
template <class M, class T>
result<bevel_plan<M, T>> bevel_make_plan(const M& mesh,
                                         const std::vector<std::pair<typename T::halfedge_handle, bool>>& chosen,
                                         const index_set& dropped, const bevel_options& options,
                                         progress_gate& progress) {
    namespace du = ::hmira::detail::euler;
    bevel_planning<M, T> st;
    auto& plan = st.plan;
    plan.segments = options.segments;
    if (auto ok = bevel_plan_selection<M, T>(mesh, chosen, dropped, st, progress); !ok) return ok.error();
    if (auto ok = bevel_plan_corners<M, T>(mesh, st, progress); !ok) return ok.error();
    bevel_plan_widths<M, T>(mesh, st, options);
    // Which ends of each bevelled edge stay (the strip then ends in a point there).
    const auto& sel = plan.sel;
    plan.end_kept.resize(sel.size());
    for (std::size_t i = 0; i < sel.size(); ++i)
        for (int side = 0; side < 2; ++side) {
            const auto v = side == 0 ? du::source<M, T>(mesh, sel[i]) : T::target(mesh, sel[i]);
            // A boundary strip's ends stay, yet its ends are edges (p-u, w-q) for the profile.
            plan.end_kept[i][side] =
                !plan.on_boundary[i] && !plan.removed[st.touched_at.find(T::vertex_index(mesh, v))];
        }
    plan.requested_width = options.width;
    plan.share_meeting_points = !options.clamp_overlap || options.clamp_globally;
    return std::move(plan);
}

}  // namespace hmira::detail::editing
