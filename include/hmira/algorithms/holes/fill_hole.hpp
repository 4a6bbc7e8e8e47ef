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
#include <unordered_map>
#include <string>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/result.hpp"
#include "../../core/vec3.hpp"
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

/// How fill_hole triangulates, refines and fairs a loop. The defaults triangulate only.
struct fill_hole_options {
    /// Loops of at most this many edges get Liepa's O(n^3) dynamic programme; longer ones the
    /// O(n^2) triangulation of the loop projected on its best-fit plane (refused when that
    /// projection is not a simple polygon).
    std::size_t max_dynamic_programming_edges = 200;
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
    std::vector<typename T::face_handle> faces;       ///< the patch's triangles
    std::vector<typename T::vertex_handle> vertices;  ///< the vertices refinement added (inside the patch)
    /// Whether the fairing solve converged (true when no fairing was asked for or there was
    /// nothing to fair). When false the added vertices stay where refinement put them.
    bool faired = true;
    std::size_t fairing_iterations = 0;  ///< conjugate-gradient iterations of the slowest coordinate
};

/// Fills the boundary loop of `boundary_halfedge` (a halfedge with no face) with triangles.
///
/// Loops of up to `options.max_dynamic_programming_edges` edges are triangulated by Liepa's
/// dynamic programme: among the triangulations of the loop that add no edge the mesh already
/// has and no degenerate triangle, the one whose largest dihedral bend (between patch triangles
/// and with the faces around the loop) is smallest, then whose area is smallest. Like Liepa's
/// and CGAL's, the programme takes the bend across an inner edge against the best solution of
/// the inner sub-loop, a greedy choice; a pass of edge flips then lowers the area wherever that
/// bends no edge more than the patch's largest bend. The loop starts at the target of
/// `boundary_halfedge`, as in CGAL's triangulate_hole. Longer loops are triangulated in the
/// plane of their Newell normal (triangulate_polygon), which must see them as a simple
/// polygon. New faces are wound like the faces around the hole.
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
/// (a = 0 without refine); genus unchanged; the loop's vertices do not move.
/// Errors (mesh unchanged): errc::invalid_argument for refine_density or fairing_tolerance not
/// finite and > 0; errc::invalid_handle; errc::topology when the halfedge has a face,
/// the loop passes a vertex twice, has fewer than three edges, or every triangulation would
/// duplicate an existing edge or make a degenerate triangle; errc::unsupported when a long
/// loop's projection is not simple.
/// Complexity: O(n^3) time and O(n^2) memory by the dynamic programme (plus O(n^2) for the
/// flip pass, typically a few rounds); O(n^2) time, O(n) memory typical for the projected
/// fallback; plus O(n valence) to find edges the patch must not repeat. Refinement: O(a)
/// splits and flips per round, typically a few rounds; fairing O(iterations * a * valence^2),
/// iterations at most `max_fairing_iterations`.
template <class M, class T = default_traits<M>>
    requires triangle_operable_mesh<M, T>
[[nodiscard]] result<fill_hole_result<M, T>> fill_hole(M& mesh, typename T::halfedge_handle boundary_halfedge,
                                                       const fill_hole_options& options = {}) {
    namespace de = detail::euler;
    namespace dt = detail::triangle_ops;
    namespace dh = detail::holes;
    using H = typename T::halfedge_handle;
    using V = typename T::vertex_handle;
    if (auto bad = dh::check_options(options, "fill_hole")) return *bad;
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

    // triangles (i, k, j) in loop order, i < k < j.
    dh::triangle_list tris;
    if (n <= options.max_dynamic_programming_edges) {
        tris = dh::triangulate_by_dynamic_programming(loop);
        if (tris.empty())
            return fail(errc::topology,
                        "fill_hole: every triangulation of the loop would repeat an edge the mesh already has "
                        "or make a degenerate triangle",
                        de::index_of<M, T>(mesh, boundary_halfedge));
        dh::reduce_area_by_flips(loop, tris);
    } else {
        auto t = dh::triangulate_by_projection(loop);
        if (!t) return fail(t.error().code, t.error().message, de::index_of<M, T>(mesh, boundary_halfedge));
        tris = std::move(*t);
    }
    {
        auto ordered = dh::in_interval_order(n, tris);
        if (!ordered) return fail(ordered.error().code, ordered.error().message, de::index_of<M, T>(mesh, boundary_halfedge));
        tris = std::move(*ordered);
    }

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

    // Build: one face over the whole loop, then cut off each interval's sub-loop by a
    // diagonal, top down; what is left of a piece is its triangle. The loop's halfedges already
    // run in the patch's winding.
    fill_hole_result<M, T> out;
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
    // The loop's vertices stored boundary halfedges that now have a face.
    for (std::size_t i = 0; i < n; ++i) dt::refresh_vertex_halfedge<M, T>(mesh, v[i], h[i]);
    if (!options.refine) return out;

    dh::patch<M, T> pt;
    pt.faces = std::move(out.faces);
    for (std::size_t i = 0; i < n; ++i) pt.scale[T::vertex_index(mesh, v[i])] = scale[i];
    for (const auto& t : tris) {
        if (t[1] != t[0] + 1) pt.inner_edges.insert(dh::edge_key<M, T>(mesh, v[t[0]], v[t[1]]));
        if (t[2] != t[1] + 1) pt.inner_edges.insert(dh::edge_key<M, T>(mesh, v[t[1]], v[t[2]]));
    }
    dh::refine_patch<M, T>(mesh, pt, options.refine_density, options.max_added_vertices);
    out.faces = std::move(pt.faces);
    if (options.fair != fairing::none) {
        const std::size_t budget = options.max_fairing_iterations > 0 ? options.max_fairing_iterations : 10 * pt.vertices.size() + 100;
        const auto solved = dh::fair_patch<M, T>(mesh, pt,
                                                 options.fair == fairing::membrane ? dh::fairing_energy::membrane : dh::fairing_energy::thin_plate,
                                                 options.fairing_tolerance, budget);
        out.faired = solved.converged;
        out.fairing_iterations = solved.iterations;
    }
    out.vertices = std::move(pt.vertices);
    return out;
}

/// What fill_holes did.
struct fill_holes_result {
    std::size_t filled = 0;       ///< loops closed
    std::size_t skipped = 0;      ///< loops longer than max_size, or refused by fill_hole
    std::size_t faces_added = 0;     ///< triangles in all patches
    std::size_t vertices_added = 0;  ///< vertices refinement added in all patches
    std::size_t unfaired = 0;        ///< patches whose fairing solve did not converge (left as refined)
};

/// A mesh fill_holes can run on: the triangle operators, and halfedge indices to mark the
/// boundary halfedges already visited.
template <class M, class T = default_traits<M>>
concept hole_fillable_mesh = triangle_operable_mesh<M, T> && halfedge_index_mesh<M, T>;

/// Fills every boundary loop of at most `max_size` edges with fill_hole. A loop that fill_hole
/// refuses is left open and counted in `skipped` (each refusal leaves the mesh unchanged).
/// Errors: errc::invalid_argument for max_size < 3 or an option out of range (mesh unchanged).
/// Complexity: O(H) to find the loops, H the halfedges, plus fill_hole's cost per loop.
template <class M, class T = default_traits<M>>
    requires hole_fillable_mesh<M, T>
[[nodiscard]] result<fill_holes_result> fill_holes(M& mesh, std::size_t max_size, const fill_hole_options& options = {}) {
    if (max_size < 3) return fail(errc::invalid_argument, "fill_holes: option max_size must be at least 3, got " + std::to_string(max_size));
    if (auto bad = detail::holes::check_options(options, "fill_holes")) return *bad;
    using H = typename T::halfedge_handle;
    std::vector<H> loops;
    std::vector<std::size_t> sizes;
    std::vector<char> seen(T::halfedge_index_bound(mesh), 0);
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
    }
    fill_holes_result out;
    for (std::size_t l = 0; l < loops.size(); ++l) {
        if (sizes[l] > max_size) {
            ++out.skipped;
            continue;
        }
        auto r = fill_hole<M, T>(mesh, loops[l], options);
        if (!r) {
            ++out.skipped;
            continue;
        }
        ++out.filled;
        out.faces_added += r->faces.size();
        out.vertices_added += r->vertices.size();
        if (!r->faired) ++out.unfaired;
    }
    return out;
}

}  // namespace hmira
