// hmira/algorithms/holes/detail/fill_hole_impl.hpp
// The machinery of fill_hole and fill_holes (holes/fill_hole.hpp), and their definitions.
//
// How fill_hole works. Loops of up to `max_dynamic_programming_edges` edges (and longer ones
// whose projection is not simple, up to `max_fallback_dynamic_programming_edges`) are
// triangulated by Liepa's dynamic programme: among the triangulations of the loop that add no
// edge the mesh already has and no degenerate triangle, the one whose largest dihedral bend
// (between patch triangles and with the faces around the loop) is smallest, then whose area is
// smallest. Like Liepa's and CGAL's, the programme takes the bend across an inner edge against
// the best solution of the inner sub-loop, a greedy choice; a pass of edge flips then lowers
// the area wherever that bends no edge more than the patch's largest bend. The loop starts at
// the target of `boundary_halfedge`, as in CGAL's triangulate_hole. Longer loops are
// triangulated in the plane of their Newell normal (triangulate_polygon), which must see them
// as a simple polygon. When no triangulation of the loop's own vertices is valid (every one
// would repeat an existing edge or make a degenerate triangle: a planar rectangle whose
// corners the mesh already joins across, a slit of coincident or collinear vertices), the loop
// is closed by a fan of triangles around one new vertex at its centroid (moved off a
// degenerate position, see fill_hole_result::vertices).
//
// With `refine`, the patch is then refined as in Liepa 2003: each loop vertex gets the mean
// length of its edges as its scale; a patch triangle whose centroid lies farther than
// scale / refine_density from each corner (for the corner's scale and for the centroid's, the
// corners' mean) is split there by split_face, and patch edges whose two facing angles sum to
// more than pi are flipped by flip_edge, until no triangle splits. With `fair` the added
// vertices are then moved so that the uniform Laplacian (membrane) or its square (thin plate)
// vanishes at each of them, the loop (and for the thin plate the ring outside it) held fixed,
// by a Jacobi-preconditioned conjugate-gradient solve. If that solve does not converge, no
// vertex moves and `faired` is false: the patch stays as refined, closed and valid.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <vector>

#include "../../../core/rollback.hpp"
#include "../../../core/vec3.hpp"
#include "../../editing/detail/transaction.hpp"
#include "loop_triangulation.hpp"
#include "refine_and_fair.hpp"

namespace hmira {

namespace detail::holes {
inline std::optional<hmira::error> check_options(const fill_hole_options& o, const std::string& who) {
    if (!(o.refine_density > 0) || !std::isfinite(o.refine_density))
        return fail(errc::invalid_argument, who + ": option refine_density must be finite and > 0");
    if (!(o.fairing_tolerance > 0) || !std::isfinite(o.fairing_tolerance))
        return fail(errc::invalid_argument, who + ": option fairing_tolerance must be finite and > 0");
    return std::nullopt;
}
}  // namespace detail::holes

namespace detail::holes {

/// A model whose raw mutations the editing journal can record and undo
/// (editing/detail/transaction.hpp): fill_hole and fill_holes roll back a cancelled fill on it.
template <class M, class T>
concept journaled_fill = halfedge_index_mesh<M, T> && vertex_index_mesh<M, T> && face_index_mesh<M, T> &&
                         edge_index_mesh<M, T> && requires(const M& m, typename T::halfedge_handle h) {
                             { T::prev(m, h) } -> std::convertible_to<typename T::halfedge_handle>;
                         };

inline const progress_function no_progress{};

/// Centre for the fan of a loop with no triangulation of its own: the loop's centroid, or,
/// when a fan triangle around it would be degenerate (a slit, a centroid on a loop edge's
/// line), the centroid moved by half the mean edge length along the rim faces' mean normal,
/// the Newell normal or an axis, whichever first gives no degenerate triangle. nullopt if none
/// does. O(n).
inline std::optional<vec3<double>> fan_centre(const loop_data& loop) {
    const std::size_t n = loop.size();
    vec3<double> c{}, rim{}, newell{};
    double mean = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const auto& a = loop.p[i];
        const auto& b = loop.p[(i + 1) % n];
        c += a;
        rim += loop.rim[i];
        newell += cross(a, b);
        const auto d = b - a;
        mean += std::sqrt(dot(d, d));
    }
    c = c / double(n);
    mean /= double(n);
    auto fan_ok = [&](const vec3<double>& q) {
        if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z)) return false;
        for (std::size_t i = 0; i < n; ++i) {
            const auto x = cross(loop.p[(i + 1) % n] - loop.p[i], q - loop.p[i]);
            if (dot(x, x) == 0) return false;
        }
        return true;
    };
    if (fan_ok(c)) return c;
    for (const auto& d : {rim, newell, vec3<double>{1, 0, 0}, vec3<double>{0, 1, 0}, vec3<double>{0, 0, 1}}) {
        const double l = std::sqrt(dot(d, d));
        if (!(l > 0)) continue;
        const auto q = c + d * (0.5 * mean / l);
        if (fan_ok(q)) return q;
    }
    return std::nullopt;
}

/// A boundary loop as fill_hole walks it: h[i] runs from v[i] to v[i + 1].
template <class M, class T>
struct hole_loop {
    std::vector<typename T::halfedge_handle> h;
    std::vector<typename T::vertex_handle> v;
};

/// Checks `boundary_halfedge` and walks its loop, refusing a loop of fewer than three edges or
/// one that passes a vertex twice. Changes nothing. O(n log n).
template <class M, class T>
result<hole_loop<M, T>> walk_loop(const M& mesh, typename T::halfedge_handle boundary_halfedge) {
    namespace de = detail::euler;
    using V = typename T::vertex_handle;
    if (!de::usable<M, T>(mesh, boundary_halfedge))
        return fail(errc::invalid_handle,
                    "fill_hole: " + de::name<M, T>("halfedge", mesh, boundary_halfedge) + " does not exist",
                    de::index_of<M, T>(mesh, boundary_halfedge));
    if (T::face(mesh, boundary_halfedge) != T::null_face())
        return fail(errc::topology,
                    "fill_hole: " + de::name<M, T>("halfedge", mesh, boundary_halfedge) + " is not on a boundary",
                    de::index_of<M, T>(mesh, boundary_halfedge));
    hole_loop<M, T> loop;
    // The loop starts at the halfedge's target, as CGAL's does: the programme's greedy bend term
    // makes the result depend on where the loop starts.
    const auto first = T::next(mesh, boundary_halfedge);
    auto x = first;
    do {
        loop.h.push_back(x);
        loop.v.push_back(T::target(mesh, T::opposite(mesh, x)));
        x = T::next(mesh, x);
    } while (x != first);
    const std::size_t n = loop.h.size();
    if (n < 3)
        return fail(errc::topology, "fill_hole: the loop has fewer than three edges",
                    de::index_of<M, T>(mesh, boundary_halfedge));
    std::vector<V> sorted = loop.v;
    std::sort(sorted.begin(), sorted.end(),
              [&](V a, V b) { return T::vertex_index(mesh, a) < T::vertex_index(mesh, b); });
    for (std::size_t i = 1; i < n; ++i)
        if (sorted[i] == sorted[i - 1])
            return fail(errc::topology,
                        "fill_hole: the loop passes " + de::name<M, T>("vertex", mesh, sorted[i]) + " twice",
                        de::index_of<M, T>(mesh, sorted[i]));
    return loop;
}

/// What the triangulation needs to know of the loop: its positions, the pairs of its vertices
/// the mesh already joins (other than along the loop), and the normals of the faces around
/// it. Refuses a loop vertex that is not finite. Changes nothing. O(n valence).
template <class M, class T>
result<loop_data> describe_loop(const M& mesh, const hole_loop<M, T>& hl, long long element) {
    namespace dt = detail::triangle_ops;
    const auto& h = hl.h;
    const auto& v = hl.v;
    const std::size_t n = h.size();
    loop_data loop;
    loop.p.resize(n);
    for (std::size_t i = 0; i < n; ++i) loop.p[i] = dt::position_of<M, T>(mesh, v[i]);
    for (const auto& q : loop.p)
        if (!dt::finite(q)) return fail(errc::invalid_argument, "fill_hole: a loop vertex is not finite", element);
    // Pairs already joined by an edge (other than along the loop) cannot be diagonals.
    std::unordered_map<std::size_t, std::size_t> position_in_loop;
    for (std::size_t i = 0; i < n; ++i) position_in_loop.emplace(T::vertex_index(mesh, v[i]), i);
    loop.joined.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto s = T::vertex_halfedge(mesh, v[i]);
        auto x = s;
        do {
            const auto it = position_in_loop.find(T::vertex_index(mesh, T::target(mesh, x)));
            if (it != position_in_loop.end()) loop.joined[i].push_back(it->second);
            x = T::next(mesh, T::opposite(mesh, x));
        } while (x != s);
        std::sort(loop.joined[i].begin(), loop.joined[i].end());
    }
    // Normal of the face across loop edge (i, i + 1), for the bend at the patch's rim.
    loop.rim.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto o = T::opposite(mesh, h[i]);
        loop.rim[i] = unit_normal(dt::position_of<M, T>(mesh, T::target(mesh, T::opposite(mesh, o))),
                                  dt::position_of<M, T>(mesh, T::target(mesh, o)),
                                  dt::position_of<M, T>(mesh, T::target(mesh, T::next(mesh, o))));
    }
    return loop;
}

/// How a loop is to be closed: triangles (i, k, j) in loop order, i < k < j, in the interval
/// order the construction takes them; or, when no triangulation of the loop's own vertices is
/// valid, a fan around a new vertex at `centre_at`.
struct hole_plan {
    triangle_list tris;
    bool centre = false;
    vec3<double> centre_at{};
};

/// Chooses the triangulation (the dynamic programme, or the projection for a long loop) or
/// the fan. Asks `gate` inside the dynamic programme. Changes nothing. Errors name `element`.
inline result<hole_plan> plan_hole(const loop_data& loop, const fill_hole_options& options, progress_gate& gate,
                                   long long element) {
    const std::size_t n = loop.size();
    hole_plan plan;
    bool programme = n <= options.max_dynamic_programming_edges;
    if (!programme) {
        auto t = triangulate_by_projection(loop);
        if (t)
            plan.tris = std::move(*t);
        else if (n <= options.max_fallback_dynamic_programming_edges)
            programme = true;
        else
            return fail(t.error().code,
                        t.error().message + " (and the loop is longer than max_fallback_dynamic_programming_edges " +
                            std::to_string(options.max_fallback_dynamic_programming_edges) + ")",
                        element);
    }
    if (programme) {
        const double bytes = dynamic_programming_bytes(n);
        if (options.max_memory_bytes > 0 && bytes > double(options.max_memory_bytes))
            return fail(errc::unsupported,
                        "fill_hole: the dynamic programme for a loop of " + std::to_string(n) + " edges needs " +
                            std::to_string(std::uint64_t(bytes / 1048576) + 1) + " MiB, more than the " +
                            std::to_string(options.max_memory_bytes / 1048576) + " MiB allowed",
                        element);
        auto t = triangulate_by_dynamic_programming(loop, gate);
        if (!t) return fail(t.error().code, t.error().message, element);
        plan.tris = std::move(*t);
        // No triangulation of the loop alone adds no existing edge and no degenerate triangle (a
        // rectangle whose corners' neighbours the mesh already joins, a slit): a fan around a
        // new centre vertex makes no existing edge.
        if (plan.tris.empty())
            plan.centre = true;
        else
            reduce_area_by_flips(loop, plan.tris);
    }
    if (plan.centre) {
        auto c = fan_centre(loop);
        if (!c)
            return fail(
                errc::topology,
                "fill_hole: every triangulation of the loop would repeat an edge the mesh already has or make a "
                "degenerate triangle, and so would a fan around any centre tried",
                element);
        plan.centre_at = *c;
    } else {
        auto ordered = in_interval_order(n, plan.tris);
        if (!ordered) return fail(ordered.error().code, ordered.error().message, element);
        plan.tris = std::move(*ordered);
    }
    return plan;
}

/// Liepa's scale of each loop vertex: the mean length of its edges, before the patch adds any.
/// O(n valence).
template <class M, class T>
std::vector<double> loop_scales(const M& mesh, const hole_loop<M, T>& hl, const loop_data& loop) {
    namespace dt = detail::triangle_ops;
    std::vector<double> scale(hl.v.size(), 0.0);
    for (std::size_t i = 0; i < scale.size(); ++i) {
        const auto s0 = T::vertex_halfedge(mesh, hl.v[i]);
        auto x = s0;
        std::size_t edges = 0;
        do {
            const auto d = dt::position_of<M, T>(mesh, T::target(mesh, x)) - loop.p[i];
            scale[i] += std::sqrt(dot(d, d));
            ++edges;
            x = T::next(mesh, T::opposite(mesh, x));
        } while (x != s0);
        scale[i] /= double(edges);
    }
    return scale;
}

/// Closes the loop by a fan around a new vertex at `at`: triangle i is (v[i], v[i + 1], c),
/// that is h[i], then v[i + 1] -> c, then c -> v[i]. Adds the centre and the faces to `out`.
template <class M, class T>
void build_fan(M& mesh, const hole_loop<M, T>& hl, const vec3<double>& at, fill_hole_result<M, T>& out) {
    using H = typename T::halfedge_handle;
    using S = typename T::scalar;
    const auto& h = hl.h;
    const auto& v = hl.v;
    const std::size_t n = h.size();
    const auto c = T::add_vertex(mesh, vec3<S>{S(at.x), S(at.y), S(at.z)});
    out.vertices.push_back(c);
    std::vector<H> spoke(n);  // c -> v[i]
    for (std::size_t i = 0; i < n; ++i) spoke[i] = T::new_edge(mesh, c, v[i]);
    for (std::size_t i = 0; i < n; ++i) {
        const auto f = T::new_face(mesh);
        const auto in = T::opposite(mesh, spoke[(i + 1) % n]);
        T::set_next(mesh, h[i], in);
        T::set_next(mesh, in, spoke[i]);
        T::set_next(mesh, spoke[i], h[i]);
        T::set_face(mesh, h[i], f);
        T::set_face(mesh, in, f);
        T::set_face(mesh, spoke[i], f);
        T::set_face_halfedge(mesh, f, h[i]);
        out.faces.push_back(f);
    }
    T::set_vertex_halfedge(mesh, c, spoke[0]);
}

/// Closes the loop by the triangles `tris` (in interval order): one face over the whole loop,
/// then each interval's sub-loop cut off by a diagonal, top down; what is left of a piece is
/// its triangle. The loop's halfedges already run in the patch's winding. Adds the faces to
/// `out`.
template <class M, class T>
void build_triangles(M& mesh, const hole_loop<M, T>& hl, const triangle_list& tris, fill_hole_result<M, T>& out) {
    using H = typename T::halfedge_handle;
    const auto& h = hl.h;
    const auto& v = hl.v;
    const std::size_t n = h.size();
    const auto g0 = T::new_face(mesh);
    for (const auto x : h) T::set_face(mesh, x, g0);
    T::set_face_halfedge(mesh, g0, h[n - 1]);
    // A piece of interval (i, j): the halfedge v[j] -> v[i] closing it, and its face.
    struct piece {
        std::size_t i, j;
        H close;
        typename T::face_handle face;
    };
    std::unordered_map<std::uint64_t, std::size_t> split_at;
    for (const auto& t : tris) split_at[pair_key(t[0], t[2])] = t[1];
    std::vector<piece> todo{{0, n - 1, h[n - 1], g0}};
    while (!todo.empty()) {
        const piece pc = todo.back();
        todo.pop_back();
        out.faces.push_back(pc.face);
        const auto k = split_at.at(pair_key(pc.i, pc.j));
        H into_k = h[k - 1];  // v[k-1] -> v[k]
        if (k > pc.i + 1) {   // cut (i, k): e = v[k] -> v[i] closes the sub-piece
            const auto e = T::new_edge(mesh, v[k], v[pc.i]);
            const auto eo = T::opposite(mesh, e);
            const auto g = T::new_face(mesh);
            T::set_next(mesh, h[k - 1], e);
            T::set_next(mesh, e, h[pc.i]);
            T::set_next(mesh, pc.close, eo);
            T::set_next(mesh, eo, h[k]);
            T::set_face(mesh, e, g);
            for (std::size_t s = pc.i; s < k; ++s) T::set_face(mesh, h[s], g);
            T::set_face_halfedge(mesh, g, e);
            T::set_face(mesh, eo, pc.face);
            T::set_face_halfedge(mesh, pc.face, pc.close);
            todo.push_back({pc.i, k, e, g});
            into_k = eo;
        }
        if (pc.j > k + 1) {  // cut (k, j): e2 = v[j] -> v[k] closes the sub-piece
            const auto e2 = T::new_edge(mesh, v[pc.j], v[k]);
            const auto e2o = T::opposite(mesh, e2);
            const auto g = T::new_face(mesh);
            T::set_next(mesh, h[pc.j - 1], e2);
            T::set_next(mesh, e2, h[k]);
            T::set_next(mesh, into_k, e2o);
            T::set_next(mesh, e2o, pc.close);
            T::set_face(mesh, e2, g);
            for (std::size_t s = k; s < pc.j; ++s) T::set_face(mesh, h[s], g);
            T::set_face_halfedge(mesh, g, e2);
            T::set_face(mesh, e2o, pc.face);
            T::set_face_halfedge(mesh, pc.face, pc.close);
            todo.push_back({k, pc.j, e2, g});
        }
    }
}

/// Refines the patch in `out` (Liepa 2003) and, with options.fair, fairs the vertices it added.
/// Asks `gate`; a cancellation returns errc::cancelled with the patch half refined.
template <class M, class T>
result<void> refine_and_fair_hole(M& mesh, const hole_loop<M, T>& hl, const hole_plan& plan,
                                  const std::vector<double>& scale, const fill_hole_options& options,
                                  progress_gate& gate, fill_hole_result<M, T>& out) {
    const auto& v = hl.v;
    const std::size_t n = v.size();
    patch<M, T> pt;
    pt.faces = std::move(out.faces);
    pt.vertices = std::move(out.vertices);
    for (std::size_t i = 0; i < n; ++i) pt.scale[T::vertex_index(mesh, v[i])] = scale[i];
    if (plan.centre) {
        double mean = 0;
        for (auto s : scale) mean += s;
        pt.scale[T::vertex_index(mesh, pt.vertices[0])] = mean / double(n);
        for (std::size_t i = 0; i < n; ++i) pt.inner_edges.insert(edge_key<M, T>(mesh, pt.vertices[0], v[i]));
    }
    for (const auto& t : plan.tris) {
        if (t[1] != t[0] + 1) pt.inner_edges.insert(edge_key<M, T>(mesh, v[t[0]], v[t[1]]));
        if (t[2] != t[1] + 1) pt.inner_edges.insert(edge_key<M, T>(mesh, v[t[1]], v[t[2]]));
    }
    if (!refine_patch<M, T>(mesh, pt, options.refine_density, options.max_added_vertices, gate))
        return fail(errc::cancelled, "fill_hole: cancelled");
    out.faces = std::move(pt.faces);
    if (options.fair != fairing::none) {
        const std::size_t budget =
            options.max_fairing_iterations > 0 ? options.max_fairing_iterations : 10 * pt.vertices.size() + 100;
        const auto energy = options.fair == fairing::membrane ? fairing_energy::membrane : fairing_energy::thin_plate;
        const auto solved = fair_patch<M, T>(mesh, pt, energy, options.fairing_tolerance, budget, gate);
        if (solved.cancelled) return fail(errc::cancelled, "fill_hole: cancelled");
        out.faired = solved.converged;
        out.fairing_iterations = solved.iterations;
    }
    out.vertices = std::move(pt.vertices);
    return {};
}

/// fill_hole's work, all mutation through T. `gate` is asked before anything changes (inside
/// the dynamic programme and once before the patch is built) and, when `can_roll_back`, also
/// during refinement and fairing: a cancellation there returns errc::cancelled with the patch
/// half built, for the caller's journal or copy to undo. Every other error leaves the mesh
/// unchanged.
template <class M, class T>
result<fill_hole_result<M, T>> fill_one(M& mesh, typename T::halfedge_handle boundary_halfedge,
                                        const fill_hole_options& options, progress_gate& gate, bool can_roll_back) {
    namespace dt = detail::triangle_ops;
    const long long element = detail::euler::index_of<M, T>(mesh, boundary_halfedge);
    auto walked = walk_loop<M, T>(mesh, boundary_halfedge);
    if (!walked) return walked.error();
    const auto& hl = *walked;
    auto described = describe_loop<M, T>(mesh, hl, element);
    if (!described) return described.error();
    auto plan = plan_hole(*described, options, gate, element);
    if (!plan) return plan.error();
    // Nothing has changed yet: the last point at which a fill that cannot roll back stops.
    if (!gate.advance()) return fail(errc::cancelled, "fill_hole: cancelled");
    progress_gate never(no_progress, 1);
    progress_gate& later = can_roll_back ? gate : never;
    const std::vector<double> scale = options.refine ? loop_scales<M, T>(mesh, hl, *described) : std::vector<double>{};

    fill_hole_result<M, T> out;
    if (plan->centre)
        build_fan<M, T>(mesh, hl, plan->centre_at, out);
    else
        build_triangles<M, T>(mesh, hl, plan->tris, out);
    // The loop's vertices stored boundary halfedges that now have a face.
    for (std::size_t i = 0; i < hl.h.size(); ++i) dt::refresh_vertex_halfedge<M, T>(mesh, hl.v[i], hl.h[i]);
    if (!options.refine) return out;
    if (auto r = refine_and_fair_hole<M, T>(mesh, hl, *plan, scale, options, later, out); !r) return r.error();
    return out;
}

/// The work of fill_hole on one loop estimated in progress blocks (0 for a loop of under three
/// edges). O(1).
inline std::size_t fill_blocks(std::size_t n, const fill_hole_options& o) {
    const std::size_t fairing = o.refine && o.fair != fairing::none ? 3 * fairing_blocks : 0;
    return fairing + (n <= std::max(o.max_dynamic_programming_edges, o.max_fallback_dynamic_programming_edges)
                          ? dynamic_programming_blocks(n) + 1
                          : 2);
}

/// Runs `work` so that a cancellation can be undone: on a journaled copy of the traits when the
/// model has what the journal needs (a cancellation then undoes everything `work` did); else,
/// when a callback can cancel (`asked`) and the model copies, from a copy (mesh_rollback); else
/// directly (a cancellation is then honoured only until the first patch is built). `work` is
/// called as work.template operator()<TT>(can_roll_back) and returns a result.
template <class M, class T, class Work>
auto run_undoable(M& mesh, bool asked, Work&& work) {
    if constexpr (journaled_fill<M, T>) {
        return editing::transact<M, T>(mesh, [&]<class JT>() { return work.template operator()<JT>(true); });
    } else if constexpr (std::copy_constructible<M> && std::is_move_assignable_v<M>) {
        mesh_rollback<M> undo(mesh, asked);
        auto r = work.template operator()<T>(asked);
        if (r) undo.commit();
        return r;
    } else {
        (void)asked;
        return work.template operator()<T>(false);
    }
}

}  // namespace detail::holes

template <class M, class T>
    requires triangle_operable_mesh<M, T>
result<fill_hole_result<M, T>> fill_hole(M& mesh, typename T::halfedge_handle boundary_halfedge,
                                         const fill_hole_options& options) {
    namespace dh = detail::holes;
    if (auto bad = dh::check_options(options, "fill_hole")) return *bad;
    // The loop's length sizes the progress estimate; fill_one checks the halfedge itself.
    std::size_t n = 0;
    if (detail::euler::usable<M, T>(mesh, boundary_halfedge) && T::face(mesh, boundary_halfedge) == T::null_face()) {
        auto x = boundary_halfedge;
        do {
            ++n;
            x = T::next(mesh, x);
        } while (x != boundary_halfedge);
    }
    detail::progress_gate gate(options.progress, dh::fill_blocks(n, options));
    return dh::run_undoable<
        M, T>(mesh, bool(options.progress), [&]<class TT>(bool can_roll_back) -> result<fill_hole_result<M, T>> {
        auto r = dh::fill_one<M, TT>(mesh, boundary_halfedge, options, gate, can_roll_back);
        if (!r) return r.error();
        return fill_hole_result<M, T>{std::move(r->faces), std::move(r->vertices), r->faired, r->fairing_iterations};
    });
}

template <class M, class T>
    requires hole_fillable_mesh<M, T>
result<fill_holes_result> fill_holes(M& mesh, std::size_t max_size, const fill_hole_options& options) {
    namespace dh = detail::holes;
    if (max_size < 3)
        return fail(errc::invalid_argument,
                    "fill_holes: option max_size must be at least 3, got " + std::to_string(max_size));
    if (auto bad = dh::check_options(options, "fill_holes")) return *bad;
    using H = typename T::halfedge_handle;
    std::vector<H> loops;
    std::vector<std::size_t> sizes;
    std::vector<char> seen(T::halfedge_index_bound(mesh), 0);
    std::size_t blocks = 1;
    for (auto x : T::halfedges(mesh)) {
        const H hx = x;
        if (T::face(mesh, hx) != T::null_face() || seen[T::halfedge_index(mesh, hx)]) continue;
        std::size_t len = 0;
        auto y = hx;
        do {
            seen[T::halfedge_index(mesh, y)] = 1;
            ++len;
            y = T::next(mesh, y);
        } while (y != hx);
        loops.push_back(hx);
        sizes.push_back(len);
        blocks += len <= max_size ? dh::fill_blocks(len, options) : 0;
    }
    detail::progress_gate gate(options.progress, blocks);
    return dh::run_undoable<M, T>(
        mesh, bool(options.progress), [&]<class TT>(bool can_roll_back) -> result<fill_holes_result> {
            fill_holes_result out;
            for (std::size_t l = 0; l < loops.size(); ++l) {
                // Later loops are only worth asking about while nothing can be undone, or when
                // everything can.
                const bool ask = can_roll_back || out.filled == 0;
                if (ask && !gate.advance(0)) return fail(errc::cancelled, "fill_holes: cancelled");
                open_hole hole;
                hole.vertex = T::vertex_index(mesh, T::target(mesh, loops[l]));
                hole.edges = sizes[l];
                if (sizes[l] > max_size) {
                    out.open.push_back(std::move(hole));
                    continue;
                }
                detail::progress_gate never(dh::no_progress, 1);
                auto r = dh::fill_one<M, TT>(mesh, loops[l], options, ask ? gate : never, can_roll_back);
                if (!r) {
                    if (r.error().code == errc::cancelled) return fail(errc::cancelled, "fill_holes: cancelled");
                    hole.reason = open_hole_reason::refused;
                    hole.code = r.error().code;
                    hole.message = std::move(r.error().message);
                    out.open.push_back(std::move(hole));
                    continue;
                }
                ++out.filled;
                out.faces_added += r->faces.size();
                out.vertices_added += r->vertices.size();
                if (!r->faired) ++out.unfaired;
            }
            out.skipped = out.open.size();
            return out;
        });
}

}  // namespace hmira
