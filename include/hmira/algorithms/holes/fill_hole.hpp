// hmira/algorithms/holes/fill_hole.hpp
// Hole filling: a boundary loop closed by a triangle patch of minimal dihedral bend, then
// minimal area (Liepa 2003), or, for long loops, by a triangulation of its projection.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <string_view>
#include <unordered_map>
#include <string>
#include <utility>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/progress.hpp"
#include "../../core/result.hpp"
#include "../../core/vec3.hpp"
#include "../editing/detail/transaction.hpp"
#include "../triangle/triangle_common.hpp"
#include "detail/loop_triangulation.hpp"
#include "detail/refine_and_fair.hpp"

namespace hmira {

/// What fill_hole does to the patch's shape after triangulating the loop.
enum class fairing {
    none,        ///< keep the vertices where refinement put them
    membrane,    ///< uniform Laplacian = 0 at each added vertex: a minimal-area-like patch
    thin_plate,  ///< Laplacian of the Laplacian = 0: a patch that continues the surface's slope
};

/// The fairings' names: "none", "membrane", "thin-plate" (see core/enum_names.hpp).
constexpr auto enum_names(fairing) {
    return std::array{std::pair{fairing::none, std::string_view("none")},
                      std::pair{fairing::membrane, std::string_view("membrane")},
                      std::pair{fairing::thin_plate, std::string_view("thin-plate")}};
}

/// How fill_hole triangulates, refines and fairs a loop. The defaults triangulate only.
struct fill_hole_options {
    /// Loops of at most this many edges get Liepa's O(n^3) dynamic programme; longer ones the
    /// O(n^2) triangulation of the loop projected on its best-fit plane.
    std::size_t max_dynamic_programming_edges = 200;
    /// A longer loop whose projection is not a simple polygon (or whose projected triangulation
    /// repeats a mesh edge) still gets the dynamic programme if it has at most this many edges;
    /// otherwise it is refused.
    std::size_t max_fallback_dynamic_programming_edges = 1000;
    /// A loop whose dynamic programme would need more than this many bytes for its tables
    /// (24 n^2 for n edges) is refused before they are allocated; 0 means no limit. The CLI
    /// passes the machine's available memory.
    std::size_t max_memory_bytes = 0;
    /// Refine the patch to the edge density around the hole (Liepa 2003): triangles are split
    /// at their centroid and edges flipped, by split_face and flip_edge, until the patch's edges
    /// are about as long as the mesh edges at the loop.
    bool refine = false;
    /// Liepa's density factor alpha (> 0): a triangle is split while its centroid lies farther
    /// than scale / alpha from its corners. Larger gives a denser patch.
    double refine_density = 1.4142135623730951;
    /// Refinement adds at most this many vertices per hole.
    std::size_t max_added_vertices = 100000;
    /// Fairing of the vertices refinement added (no effect without `refine`).
    fairing fair = fairing::none;
    /// The fairing solve stops at this relative residual (> 0).
    double fairing_tolerance = 1e-10;
    /// The fairing solve gives up after this many conjugate-gradient iterations per
    /// coordinate; 0 means 10 x the number of added vertices + 100.
    std::size_t max_fairing_iterations = 0;
    /// Called with the fraction done: after every 2^16 inner steps of the dynamic programme,
    /// every refinement round and 4096 splits, and about every 2^20 multiply-adds of the fairing
    /// solve (fill_holes: also before each hole). Returning false stops the fill with
    /// errc::cancelled and the mesh as it was (see fill_hole). Empty: none.
    progress_function progress = {};
};

namespace detail::holes {
inline std::optional<hmira::error> check_options(const fill_hole_options& o, const std::string& who) {
    if (!(o.refine_density > 0) || !std::isfinite(o.refine_density))
        return fail(errc::invalid_argument, who + ": option refine_density must be finite and > 0");
    if (!(o.fairing_tolerance > 0) || !std::isfinite(o.fairing_tolerance))
        return fail(errc::invalid_argument, who + ": option fairing_tolerance must be finite and > 0");
    return std::nullopt;
}
}  // namespace detail::holes

/// What fill_hole added.
template <class M, class T = default_traits<M>>
struct fill_hole_result {
    std::vector<typename T::face_handle> faces;  ///< the patch's triangles
    /// The vertices the patch added (inside it): the centre vertex of a loop that has no valid
    /// triangulation of its own vertices (first), then those refinement added.
    std::vector<typename T::vertex_handle> vertices;
    /// Whether the fairing solve converged (true when no fairing was asked for or there was
    /// nothing to fair). When false the added vertices stay where refinement put them.
    bool faired = true;
    std::size_t fairing_iterations = 0;  ///< conjugate-gradient iterations of the slowest coordinate
};

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

/// fill_hole's work, all mutation through T. `gate` is asked before anything changes (inside
/// the dynamic programme and once before the patch is built) and, when `can_roll_back`, also
/// during refinement and fairing: a cancellation there returns errc::cancelled with the patch
/// half built, for the caller's journal to undo. Every other error leaves the mesh unchanged.
template <class M, class T>
result<fill_hole_result<M, T>> fill_one(M& mesh, typename T::halfedge_handle boundary_halfedge, const fill_hole_options& options,
                                        progress_gate& gate, bool can_roll_back) {
    namespace de = detail::euler;
    namespace dt = detail::triangle_ops;
    namespace dh = detail::holes;
    using H = typename T::halfedge_handle;
    using V = typename T::vertex_handle;
    if (!de::usable<M, T>(mesh, boundary_halfedge))
        return fail(errc::invalid_handle, "fill_hole: " + de::name<M, T>("halfedge", mesh, boundary_halfedge) + " does not exist",
                    de::index_of<M, T>(mesh, boundary_halfedge));
    if (T::face(mesh, boundary_halfedge) != T::null_face())
        return fail(errc::topology, "fill_hole: " + de::name<M, T>("halfedge", mesh, boundary_halfedge) + " is not on a boundary",
                    de::index_of<M, T>(mesh, boundary_halfedge));
    // The loop: h[i] runs from v[i] to v[i + 1].
    std::vector<H> h;
    std::vector<V> v;
    {
        // The loop starts at the halfedge's target, as CGAL's does: the programme's greedy
        // bend term makes the result depend on where the loop starts.
        const auto first = T::next(mesh, boundary_halfedge);
        auto x = first;
        do {
            h.push_back(x);
            v.push_back(T::target(mesh, T::opposite(mesh, x)));
            x = T::next(mesh, x);
        } while (x != first);
    }
    const std::size_t n = h.size();
    if (n < 3) return fail(errc::topology, "fill_hole: the loop has fewer than three edges", de::index_of<M, T>(mesh, boundary_halfedge));
    {
        std::vector<V> sorted = v;
        std::sort(sorted.begin(), sorted.end(), [&](V a, V b) { return T::vertex_index(mesh, a) < T::vertex_index(mesh, b); });
        for (std::size_t i = 1; i < n; ++i)
            if (sorted[i] == sorted[i - 1])
                return fail(errc::topology, "fill_hole: the loop passes " + de::name<M, T>("vertex", mesh, sorted[i]) + " twice",
                            de::index_of<M, T>(mesh, sorted[i]));
    }
    dh::loop_data loop;
    loop.p.resize(n);
    for (std::size_t i = 0; i < n; ++i) loop.p[i] = dt::position_of<M, T>(mesh, v[i]);
    for (const auto& q : loop.p)
        if (!dt::finite(q)) return fail(errc::invalid_argument, "fill_hole: a loop vertex is not finite", de::index_of<M, T>(mesh, boundary_halfedge));
    {
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
    }
    // Normal of the face across loop edge (i, i + 1), for the bend at the patch's rim.
    loop.rim.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto o = T::opposite(mesh, h[i]);
        loop.rim[i] = dh::unit_normal(dt::position_of<M, T>(mesh, T::target(mesh, T::opposite(mesh, o))),
                                      dt::position_of<M, T>(mesh, T::target(mesh, o)),
                                      dt::position_of<M, T>(mesh, T::target(mesh, T::next(mesh, o))));
    }

    // triangles (i, k, j) in loop order, i < k < j; none (and `centre`) when no triangulation of
    // the loop's own vertices is valid.
    dh::triangle_list tris;
    bool centre = false;
    {
        bool programme = n <= options.max_dynamic_programming_edges;
        if (!programme) {
            auto t = dh::triangulate_by_projection(loop);
            if (t)
                tris = std::move(*t);
            else if (n <= options.max_fallback_dynamic_programming_edges)
                programme = true;
            else
                return fail(t.error().code,
                            t.error().message +
                                " (and the loop is longer than max_fallback_dynamic_programming_edges " +
                                std::to_string(options.max_fallback_dynamic_programming_edges) + ")",
                            de::index_of<M, T>(mesh, boundary_halfedge));
        }
        if (programme) {
            const double bytes = dh::dynamic_programming_bytes(n);
            if (options.max_memory_bytes > 0 && bytes > double(options.max_memory_bytes))
                return fail(errc::unsupported,
                            "fill_hole: the dynamic programme for a loop of " + std::to_string(n) + " edges needs " +
                                std::to_string(std::uint64_t(bytes / 1048576) + 1) + " MiB, more than the " +
                                std::to_string(options.max_memory_bytes / 1048576) + " MiB allowed",
                            de::index_of<M, T>(mesh, boundary_halfedge));
            auto t = dh::triangulate_by_dynamic_programming(loop, gate);
            if (!t) return fail(t.error().code, t.error().message, de::index_of<M, T>(mesh, boundary_halfedge));
            tris = std::move(*t);
            // No triangulation of the loop alone adds no existing edge and no degenerate
            // triangle (a rectangle whose corners' neighbours the mesh already joins, a slit):
            // a fan around a new centre vertex makes no existing edge.
            if (tris.empty())
                centre = true;
            else
                dh::reduce_area_by_flips(loop, tris);
        }
    }
    vec3<double> centre_at{};
    if (centre) {
        auto c = dh::fan_centre(loop);
        if (!c)
            return fail(errc::topology,
                        "fill_hole: every triangulation of the loop would repeat an edge the mesh already has or make a "
                        "degenerate triangle, and so would a fan around any centre tried",
                        de::index_of<M, T>(mesh, boundary_halfedge));
        centre_at = *c;
    } else {
        auto ordered = dh::in_interval_order(n, tris);
        if (!ordered) return fail(ordered.error().code, ordered.error().message, de::index_of<M, T>(mesh, boundary_halfedge));
        tris = std::move(*ordered);
    }
    // Nothing has changed yet: the last point at which a fill that cannot roll back stops.
    if (!gate.advance()) return fail(errc::cancelled, "fill_hole: cancelled");
    progress_gate never(no_progress, 1);
    progress_gate& later = can_roll_back ? gate : never;

    // Liepa's scale of a loop vertex: the mean length of its edges, before the patch adds any.
    std::vector<double> scale(options.refine ? n : 0, 0.0);
    for (std::size_t i = 0; i < scale.size(); ++i) {
        const auto s0 = T::vertex_halfedge(mesh, v[i]);
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

    fill_hole_result<M, T> out;
    if (centre) {
        // Triangle i is (v[i], v[i + 1], c): h[i], then v[i + 1] -> c, then c -> v[i].
        using S = typename T::scalar;
        const auto c = T::add_vertex(mesh, vec3<S>{S(centre_at.x), S(centre_at.y), S(centre_at.z)});
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
    } else {
        // Build: one face over the whole loop, then cut off each interval's sub-loop by a
        // diagonal, top down; what is left of a piece is its triangle. The loop's halfedges already
        // run in the patch's winding.
        const auto g0 = T::new_face(mesh);
        for (const auto x : h) T::set_face(mesh, x, g0);
        T::set_face_halfedge(mesh, g0, h[n - 1]);
        // close[i * n + j]: the halfedge v[j] -> v[i] closing the piece of interval (i, j), and its face.
        struct piece {
            std::size_t i, j;
            H close;
            typename T::face_handle face;
        };
        std::unordered_map<std::uint64_t, std::size_t> split_at;
        for (const auto& t : tris) split_at[dh::pair_key(t[0], t[2])] = t[1];
        std::vector<piece> todo{{0, n - 1, h[n - 1], g0}};
        while (!todo.empty()) {
            const piece pc = todo.back();
            todo.pop_back();
            out.faces.push_back(pc.face);
            const auto k = split_at.at(dh::pair_key(pc.i, pc.j));
            H into_k = h[k - 1];  // v[k-1] -> v[k]
            H from_i = h[pc.i];   // v[i] -> v[i+1]
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
                from_i = eo;
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
            (void)from_i;
        }
    }
    // The loop's vertices stored boundary halfedges that now have a face.
    for (std::size_t i = 0; i < n; ++i) dt::refresh_vertex_halfedge<M, T>(mesh, v[i], h[i]);
    if (!options.refine) return out;

    dh::patch<M, T> pt;
    pt.faces = std::move(out.faces);
    pt.vertices = std::move(out.vertices);
    for (std::size_t i = 0; i < n; ++i) pt.scale[T::vertex_index(mesh, v[i])] = scale[i];
    if (centre) {
        double mean = 0;
        for (auto s : scale) mean += s;
        pt.scale[T::vertex_index(mesh, pt.vertices[0])] = mean / double(n);
        for (std::size_t i = 0; i < n; ++i) pt.inner_edges.insert(dh::edge_key<M, T>(mesh, pt.vertices[0], v[i]));
    }
    for (const auto& t : tris) {
        if (t[1] != t[0] + 1) pt.inner_edges.insert(dh::edge_key<M, T>(mesh, v[t[0]], v[t[1]]));
        if (t[2] != t[1] + 1) pt.inner_edges.insert(dh::edge_key<M, T>(mesh, v[t[1]], v[t[2]]));
    }
    if (!dh::refine_patch<M, T>(mesh, pt, options.refine_density, options.max_added_vertices, later))
        return fail(errc::cancelled, "fill_hole: cancelled");
    out.faces = std::move(pt.faces);
    if (options.fair != fairing::none) {
        const std::size_t budget = options.max_fairing_iterations > 0 ? options.max_fairing_iterations : 10 * pt.vertices.size() + 100;
        const auto solved = dh::fair_patch<M, T>(mesh, pt,
                                                 options.fair == fairing::membrane ? dh::fairing_energy::membrane : dh::fairing_energy::thin_plate,
                                                 options.fairing_tolerance, budget, later);
        if (solved.cancelled) return fail(errc::cancelled, "fill_hole: cancelled");
        out.faired = solved.converged;
        out.fairing_iterations = solved.iterations;
    }
    out.vertices = std::move(pt.vertices);
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

/// fill_one on a journaled copy of the traits when the model has what the journal needs (a
/// cancellation then undoes everything `work` did), else directly (a cancellation is then
/// honoured only until the first patch is built). `work` is called as work.template
/// operator()<TT>(can_roll_back) and returns a result.
template <class M, class T, class Work>
auto run_undoable(M& mesh, Work&& work) {
    if constexpr (journaled_fill<M, T>)
        return editing::transact<M, T>(mesh, [&]<class JT>() { return work.template operator()<JT>(true); });
    else
        return work.template operator()<T>(false);
}

}  // namespace detail::holes

/// Fills the boundary loop of `boundary_halfedge` (a halfedge with no face) with triangles.
///
/// Loops of up to `options.max_dynamic_programming_edges` edges (and longer ones whose projection
/// is not simple, up to `max_fallback_dynamic_programming_edges`) are triangulated by Liepa's
/// dynamic programme: among the triangulations of the loop that add no edge the mesh already
/// has and no degenerate triangle, the one whose largest dihedral bend (between patch triangles
/// and with the faces around the loop) is smallest, then whose area is smallest. Like Liepa's
/// and CGAL's, the programme takes the bend across an inner edge against the best solution of
/// the inner sub-loop, a greedy choice; a pass of edge flips then lowers the area wherever that
/// bends no edge more than the patch's largest bend. The loop starts at the target of
/// `boundary_halfedge`, as in CGAL's triangulate_hole. Longer loops are triangulated in the
/// plane of their Newell normal (triangulate_polygon), which must see them as a simple
/// polygon. When no triangulation of the loop's own vertices is valid (every one would repeat
/// an existing edge or make a degenerate triangle: a planar rectangle whose corners the mesh
/// already joins across, a slit of coincident or collinear vertices), the loop is closed by a
/// fan of triangles around one new vertex at its centroid (moved off a degenerate position,
/// see fill_hole_result::vertices). New faces are wound like the faces around the hole.
///
/// With `options.refine`, the patch is then refined as in Liepa 2003: each loop vertex gets
/// the mean length of its edges as its scale; a patch triangle whose centroid lies farther than
/// scale / refine_density from each corner (for the corner's scale and for the centroid's, the
/// corners' mean) is split there by split_face, and patch edges whose two facing angles sum to
/// more than pi are flipped by flip_edge, until no triangle splits. With `options.fair` the
/// added vertices are then moved so that the uniform Laplacian (membrane) or its square (thin
/// plate) vanishes at each of them, the loop (and for the thin plate the ring outside it) held
/// fixed, by a Jacobi-preconditioned conjugate-gradient solve. If that solve does not converge,
/// no vertex moves and `faired` is false: the patch stays as refined, closed and valid.
///
/// \pre the mesh is a valid surface; the loop visits each vertex once.
/// \post the loop is closed: V + a, E + (n - 3) + 3a, F + (n - 2) + 2a for a added vertices
/// (a = 0 without refine and centre vertex); genus unchanged; the loop's vertices do not move.
///
/// Cancellation: `options.progress` returning false stops the fill with errc::cancelled. On a
/// model whose raw mutations the editing journal records (every shipped half-edge model), the
/// fill runs as one journaled transaction (editing/detail/transaction.hpp) and a cancellation
/// during refinement or fairing is undone: the mesh is left as it was (live elements, links and
/// positions; the index bounds keep the undone elements as garbage). On other models the
/// callback is obeyed only until the patch is built.
/// Errors (mesh unchanged): errc::invalid_argument for refine_density or fairing_tolerance not
/// finite and > 0; errc::invalid_handle; errc::topology when the halfedge has a face,
/// the loop passes a vertex twice, has fewer than three edges, or every triangulation would
/// duplicate an existing edge or make a degenerate triangle and so would a fan around a centre;
/// errc::unsupported when a loop longer than max_fallback_dynamic_programming_edges has no
/// simple projection, or the dynamic programme would take more than max_memory_bytes;
/// errc::cancelled.
/// Complexity: O(n^3) time and O(n^2) memory by the dynamic programme (plus O(n^2) for the
/// flip pass, typically a few rounds); O(n^2) time, O(n) memory typical for the projected
/// fallback; plus O(n valence) to find edges the patch must not repeat. Refinement: O(a)
/// splits and flips per round, typically a few rounds; fairing O(iterations * a * valence^2),
/// iterations at most `max_fairing_iterations`.
template <class M, class T = default_traits<M>>
    requires triangle_operable_mesh<M, T>
[[nodiscard]] result<fill_hole_result<M, T>> fill_hole(M& mesh, typename T::halfedge_handle boundary_halfedge,
                                                       const fill_hole_options& options = {}) {
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
    return dh::run_undoable<M, T>(mesh, [&]<class TT>(bool can_roll_back) -> result<fill_hole_result<M, T>> {
        auto r = dh::fill_one<M, TT>(mesh, boundary_halfedge, options, gate, can_roll_back);
        if (!r) return r.error();
        return fill_hole_result<M, T>{std::move(r->faces), std::move(r->vertices), r->faired, r->fairing_iterations};
    });
}

/// Why fill_holes left a loop open.
enum class open_hole_reason {
    too_long,  ///< more edges than fill_holes' max_size
    refused,   ///< fill_hole refused it (see open_hole::code and message)
};

/// A loop fill_holes left open, and why.
struct open_hole {
    std::size_t vertex = 0;  ///< index of the loop's first vertex (the target of its first boundary halfedge)
    std::size_t edges = 0;   ///< the loop's length
    open_hole_reason reason = open_hole_reason::too_long;  ///< why it was left open
    errc code = errc::unsupported;  ///< for `refused`: fill_hole's error code
    std::string message;            ///< for `refused`: fill_hole's one-line reason
};

/// What fill_holes did.
struct fill_holes_result {
    std::size_t filled = 0;          ///< loops closed
    std::size_t skipped = 0;         ///< loops left open (longer than max_size, or refused by fill_hole): open.size()
    std::size_t faces_added = 0;     ///< triangles in all patches
    std::size_t vertices_added = 0;  ///< vertices the patches added (centre vertices and refinement)
    std::size_t unfaired = 0;        ///< patches whose fairing solve did not converge (left as refined)
    std::vector<open_hole> open;     ///< each loop left open, in the order the loops were found, with its reason
};

/// A mesh fill_holes can run on: the triangle operators, and halfedge indices to mark the
/// boundary halfedges already visited.
template <class M, class T = default_traits<M>>
concept hole_fillable_mesh = triangle_operable_mesh<M, T> && halfedge_index_mesh<M, T>;

/// Fills every boundary loop of at most `max_size` edges with fill_hole. A loop that is longer,
/// or that fill_hole refuses, is left open and listed in `open` with its reason (each refusal
/// leaves the mesh unchanged).
/// Cancellation: `options.progress` is asked before each loop and within each fill (see
/// fill_hole); returning false gives errc::cancelled. On a model the editing journal supports
/// (every shipped half-edge model) the whole call is one journaled transaction and a
/// cancellation undoes every patch already built: the mesh is left as it was (live elements,
/// links and positions; the undone elements stay behind as garbage). On other models the
/// callback is obeyed only until the first patch is built.
/// Errors (mesh unchanged): errc::invalid_argument for max_size < 3 or an option out of range;
/// errc::cancelled.
/// Complexity: O(H) to find the loops, H the halfedges, plus fill_hole's cost per loop.
template <class M, class T = default_traits<M>>
    requires hole_fillable_mesh<M, T>
[[nodiscard]] result<fill_holes_result> fill_holes(M& mesh, std::size_t max_size, const fill_hole_options& options = {}) {
    namespace dh = detail::holes;
    if (max_size < 3) return fail(errc::invalid_argument, "fill_holes: option max_size must be at least 3, got " + std::to_string(max_size));
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
    return dh::run_undoable<M, T>(mesh, [&]<class TT>(bool can_roll_back) -> result<fill_holes_result> {
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
