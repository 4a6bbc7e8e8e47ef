// hmira/algorithms/subdivision/detail/loop_impl.hpp
// The machinery of loop_subdivide (subdivision/loop.hpp): the per-level workspace, one level
// in its passes, and the entry point's definition.
#pragma once

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <cstddef>
#include <numbers>
#include <string>
#include <vector>

#include "../../../core/rollback.hpp"
#include "../../triangle/flip_edge.hpp"
#include "../../triangle/split_edge.hpp"
#include "cancel_point.hpp"
#include "new_elements.hpp"
#include "range.hpp"
#include "reserve.hpp"

namespace hmira {

namespace detail::subdivision {

/// Loop's vertex weight beta for valence n: (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n.
inline double loop_beta(std::size_t n) {
    const double c = 0.375 + 0.25 * std::cos(2 * std::numbers::pi / double(n));
    return (0.625 - c * c) / double(n);
}

/// The per-level arrays, sized once for the largest level so that no level allocates after
/// the mesh starts changing (29 bytes an old vertex, 4 an old edge, 16 an old face). The edge
/// points go straight into the new vertices, made before the splits: at a million faces,
/// first touching fresh pages costs as much as the arithmetic, so nothing is stored twice.
template <class M, class T>
struct loop_workspace {
    std::vector<vec3<double>> vertex_point;  // the sums of neighbours, then boundary vertices' new positions
    std::vector<std::uint32_t> valence;
    std::vector<std::uint8_t> boundary_edges;            // saturates at 3
    std::vector<typename T::vertex_handle> edge_vertex;  // by old edge index: its new vertex, null once split
    struct triangle {
        std::array<typename T::halfedge_handle, 3> halfedges;  // null for a deleted face
        typename T::halfedge_handle old_corner_cut;            // see loop_level
    };
    std::vector<triangle> triangles;    // by old face index
    std::array<std::size_t, 3> room{};  // the vertex, edge and face index bounds the mesh has capacity for

    void reserve(std::size_t vertex_bound, std::size_t edge_bound, std::size_t face_bound) {
        vertex_point.reserve(vertex_bound);
        valence.reserve(vertex_bound);
        boundary_edges.reserve(vertex_bound);
        edge_vertex.reserve(edge_bound);
        triangles.reserve(face_bound);
    }
};

/// Gathers the halfedges of every face into `w.triangles`, by face index; returns the index
/// of the first face that is not a triangle without rings, -1, or -2 when `go_on` (if given)
/// cancels. Changes nothing in the mesh. O(F).
template <class M, class T>
long long gather_triangles(const M& mesh, loop_workspace<M, T>& w, cancel_point* go_on = nullptr) {
    using H = typename T::halfedge_handle;
    w.triangles.assign(T::face_index_bound(mesh), {{H{}, H{}, H{}}, T::null_halfedge()});
    for (auto f : T::faces(mesh)) {
        const H h0 = T::face_halfedge(mesh, f), h1 = T::next(mesh, h0), h2 = T::next(mesh, h1);
        if (T::next(mesh, h2) != h0 || detail::euler::has_rings<M, T>(mesh, f))
            return (long long)T::face_index(mesh, f);
        w.triangles[T::face_index(mesh, f)].halfedges = {h0, h1, h2};
        if (go_on && !(*go_on)()) return -2;
    }
    return -1;
}

/// What the passes of one Loop level share: the level's index bounds (elements at or above
/// them are new), where new elements come from, and what the first passes found.
template <class M, class T>
struct loop_level_state {
    std::size_t vertex_bound;
    std::size_t edge_bound;
    new_elements<M, T>& make;
    std::size_t old_vertices;
    std::size_t faceless_edges = 0;  // edges without a face on either side, split last
    bool boundary_moves = false;     // some boundary vertex keeps its new position in `sum`
};

/// Edge points (3/8 of each end and 1/8 of each opposite corner; the midpoint on a boundary),
/// computed before any split changes the corners and made into isolated new vertices at once;
/// each old vertex sums its neighbours and counts its edges and boundary edges. False when
/// `go_on` cancels.
template <class M, class T>
bool loop_edge_points(M& mesh, loop_workspace<M, T>& w, loop_level_state<M, T>& s, cancel_point& go_on) {
    namespace dt = detail::triangle_ops;
    using H = typename T::halfedge_handle;
    auto& sum = w.vertex_point;
    for (auto e : T::edges(mesh)) {
        const H h = T::edge_halfedge(mesh, e), o = T::opposite(mesh, h);
        const auto va = T::target(mesh, o), vb = T::target(mesh, h);
        const std::size_t ia = T::vertex_index(mesh, va), ib = T::vertex_index(mesh, vb);
        const auto a = dt::position_of<M, T>(mesh, va), b = dt::position_of<M, T>(mesh, vb);
        sum[ia] += b;
        sum[ib] += a;
        ++w.valence[ia];
        ++w.valence[ib];
        vec3<double> q;
        if (T::face(mesh, h) != T::null_face() && T::face(mesh, o) != T::null_face()) {
            const auto c = dt::position_of<M, T>(mesh, T::target(mesh, T::next(mesh, h)));
            const auto d = dt::position_of<M, T>(mesh, T::target(mesh, T::next(mesh, o)));
            q = (a + b) * 0.375 + (c + d) * 0.125;
        } else {
            q = (a + b) * 0.5;
            s.faceless_edges += T::face(mesh, h) == T::null_face() && T::face(mesh, o) == T::null_face();
            w.boundary_edges[ia] = std::uint8_t(std::min(3, w.boundary_edges[ia] + 1));
            w.boundary_edges[ib] = std::uint8_t(std::min(3, w.boundary_edges[ib] + 1));
        }
        w.edge_vertex[T::edge_index(mesh, e)] = s.make.vertex(q);
        if (!go_on()) return false;
    }
    return true;
}

/// Old vertices: Loop's rule inside; on the boundary (two boundary edges, the stored halfedge
/// a boundary one) 3/4 of itself and 1/8 of each boundary neighbour; a vertex where boundary
/// fans meet, or an isolated one, stays. The edge points are made, so an inner vertex takes
/// its new position at once (nothing reads it again before the end); a boundary vertex reads
/// its boundary neighbours, which are boundary vertices and so still in place, and keeps its
/// result in `sum` until loop_boundary_moves. False when `go_on` cancels.
template <class M, class T>
bool loop_vertex_rule(M& mesh, loop_workspace<M, T>& w, loop_level_state<M, T>& s, cancel_point& go_on) {
    namespace dt = detail::triangle_ops;
    using H = typename T::halfedge_handle;
    auto& sum = w.vertex_point;
    std::array<double, 16> betas{};
    for (std::size_t n = 3; n < betas.size(); ++n) betas[n] = loop_beta(n);
    // The edge points are vertices too now: the pass stops once it has seen every old vertex
    // (on the usual models they come first, in index order), rather than run over them all.
    std::size_t seen = 0;
    for (auto v : T::vertices(mesh)) {
        if (seen == s.old_vertices) break;
        const std::size_t i = T::vertex_index(mesh, v);
        if (i >= s.vertex_bound) continue;  // an edge point, placed already
        ++seen;
        const std::size_t n = w.valence[i];
        if (w.boundary_edges[i] == 0 && n > 0) {
            const auto p = dt::position_of<M, T>(mesh, v);
            const double beta = n < betas.size() && n >= 3 ? betas[n] : loop_beta(n);
            dt::set_position<M, T>(mesh, v, p * (1 - double(n) * beta) + sum[i] * beta);
        } else if (w.boundary_edges[i] == 2) {
            const auto p = dt::position_of<M, T>(mesh, v);
            const H h = T::vertex_halfedge(mesh, v);
            const auto a = dt::position_of<M, T>(mesh, T::target(mesh, h));
            const auto b = dt::position_of<M, T>(mesh, T::target(mesh, T::opposite(mesh, T::prev(mesh, h))));
            sum[i] = p * 0.75 + (a + b) * 0.125;
            s.boundary_moves = true;
        }
        if (!go_on()) return false;
    }
    return true;
}

/// Splits edge h at its edge point, unless it was split already (split_edge's links; the
/// triangles were checked), and records in each triangle beside it the cut that joins the new
/// vertex to an old corner (see loop_split_and_flip).
template <class M, class T>
void loop_split(M& mesh, loop_workspace<M, T>& w, loop_level_state<M, T>& s, typename T::halfedge_handle h) {
    namespace dt = detail::triangle_ops;
    using H = typename T::halfedge_handle;
    const auto is_old = [&](typename T::vertex_handle v) {
        return std::size_t(T::vertex_index(mesh, v)) < s.vertex_bound;
    };
    const std::size_t e = T::edge_index(mesh, T::edge(mesh, h));
    const auto v = w.edge_vertex[e];
    if (v == typename T::vertex_handle{}) return;  // split already
    w.edge_vertex[e] = typename T::vertex_handle{};
    const H o = T::opposite(mesh, h);
    const auto fh = T::face(mesh, h), fo = T::face(mesh, o);
    const bool h_side = fh != T::null_face(), o_side = fo != T::null_face() && fo != fh;
    const H h2 = dt::split_links<M, T>(mesh, h, v, h_side, o_side, s.make);
    if (h_side) {
        const H cut = T::next(mesh, h);
        if (is_old(T::target(mesh, cut))) w.triangles[T::face_index(mesh, fh)].old_corner_cut = cut;
    }
    if (o_side) {
        const H cut = T::next(mesh, T::opposite(mesh, h2));
        if (is_old(T::target(mesh, cut))) w.triangles[T::face_index(mesh, fo)].old_corner_cut = cut;
    }
}

/// The splits, old triangle by old triangle, so that each triangle is finished while its
/// elements are still in cache. A split cuts the triangles beside its edge from the new vertex
/// to their third corner: next(h) on h's side, next(opposite(new halfedge)) on the other. In
/// each old triangle the first split's cut goes to an old corner, while the triangle is still
/// whole (so its face handle is the old one), and every later cut to that first new vertex:
/// exactly one cut per old triangle joins an old and a new vertex, the one the 1-to-4 pattern
/// lacks. Once the triangle's three edges are split, both sides of that cut are triangles whose
/// far corners are new and not yet joined, so is_flip_ok holds and the flip's own checks are
/// skipped. False when `go_on` cancels.
template <class M, class T>
bool loop_split_and_flip(M& mesh, loop_workspace<M, T>& w, loop_level_state<M, T>& s, cancel_point& go_on) {
    namespace dt = detail::triangle_ops;
    using H = typename T::halfedge_handle;
    for (const auto& triangle : w.triangles) {
        const auto& t = triangle.halfedges;
        if (t[0] == H{}) continue;  // a deleted face
        loop_split<M, T>(mesh, w, s, t[0]);
        loop_split<M, T>(mesh, w, s, t[1]);
        loop_split<M, T>(mesh, w, s, t[2]);
        const H cut = triangle.old_corner_cut;
        assert((is_flip_ok<M, T>(mesh, cut)));
        dt::flip_links<M, T>(mesh, cut);
        if (!go_on()) return false;
    }
    return true;
}

/// Edges without a face on either side just gain their vertex. (The bounds still count the
/// unused end of the last blocks: indices at or above edge_bound are skipped.) False when
/// `go_on` cancels.
template <class M, class T>
bool loop_faceless_edges(M& mesh, loop_workspace<M, T>& w, loop_level_state<M, T>& s, cancel_point& go_on) {
    namespace dt = detail::triangle_ops;
    for (auto e : T::edges(mesh)) {
        const std::size_t i = T::edge_index(mesh, e);
        if (i < s.edge_bound && w.edge_vertex[i] != typename T::vertex_handle{}) {
            [[maybe_unused]] const auto new_halfedge =
                dt::split_links<M, T>(mesh, T::edge_halfedge(mesh, e), w.edge_vertex[i], false, false, s.make);
            w.edge_vertex[i] = typename T::vertex_handle{};
        }
        if (!go_on()) return false;
    }
    return true;
}

/// The boundary vertices take the positions loop_vertex_rule kept in `sum`. False when `go_on`
/// cancels.
template <class M, class T>
bool loop_boundary_moves(M& mesh, loop_workspace<M, T>& w, const loop_level_state<M, T>& s, cancel_point& go_on) {
    namespace dt = detail::triangle_ops;
    std::size_t seen = 0;
    for (auto v : T::vertices(mesh)) {
        if (seen == s.old_vertices) break;
        const std::size_t i = T::vertex_index(mesh, v);
        if (i >= s.vertex_bound) continue;
        ++seen;
        if (w.boundary_edges[i] == 2) dt::set_position<M, T>(mesh, v, w.vertex_point[i]);
        if (!go_on()) return false;
    }
    return true;
}

/// One Loop level, on the triangles gather_triangles found; `w` and the mesh have room for it.
/// Returns false when `go_on` cancels, which it does only between elements (the caller then
/// restores its copy).
template <class M, class T>
bool loop_level(M& mesh, loop_workspace<M, T>& w, cancel_point& go_on) {
    const std::size_t vertex_bound = T::vertex_index_bound(mesh);
    const std::size_t edge_bound = T::edge_index_bound(mesh);
    w.vertex_point.assign(vertex_bound, {});
    w.valence.assign(vertex_bound, 0);
    w.boundary_edges.assign(vertex_bound, 0);
    w.edge_vertex.assign(edge_bound, typename T::vertex_handle{});
    // Every new element comes from here (in bulk where the model allows), in the order the
    // traits' adds would make them.
    new_elements<M, T> make(mesh, w.room);
    loop_level_state<M, T> s{vertex_bound, edge_bound, make, T::vertex_count(mesh)};
    if (!loop_edge_points<M, T>(mesh, w, s, go_on)) return false;
    if (!loop_vertex_rule<M, T>(mesh, w, s, go_on)) return false;
    if (!loop_split_and_flip<M, T>(mesh, w, s, go_on)) return false;
    // Most meshes have no faceless edge, and then the pass over the (by now four times as
    // many) edges is skipped.
    if (s.faceless_edges > 0 && !loop_faceless_edges<M, T>(mesh, w, s, go_on)) return false;
    make.finish();
    return !s.boundary_moves || loop_boundary_moves<M, T>(mesh, w, s, go_on);
}

}  // namespace detail::subdivision

template <class M, class T>
    requires loop_subdividable_mesh<M, T>
result<loop_result> loop_subdivide(M& mesh, const loop_options& options) {
    if (options.levels > 10)
        return fail(errc::invalid_argument,
                    "loop_subdivide: option levels must be at most 10, got " + std::to_string(options.levels));
    namespace ds = detail::subdivision;
    // Every level's counts are known: the mesh and the working arrays are sized for the last
    // level before the first change, so nothing allocates once the mesh has started to change.
    std::uint64_t v = T::vertex_count(mesh), e = T::edge_count(mesh), f = T::face_count(mesh);
    const std::uint64_t v0 = v, e0 = e, f0 = f;
    std::uint64_t largest_v = v, largest_e = e, largest_f = f;
    bool overflow = false;
    std::uint64_t elements = 0;  // what the levels count for the progress gate
    for (std::size_t l = 0; l < options.levels; ++l) {
        largest_v = v, largest_e = e, largest_f = f;
        elements += 2 * v + e + 2 * f;
        v = v + e, e = 2 * e + 3 * f, f = 4 * f;
        overflow = overflow || 2 * e >= (std::uint64_t(1) << 31);
    }
    ds::loop_workspace<M, T> work;
    if (!overflow) work.triangles.reserve(T::face_index_bound(mesh) + std::size_t(largest_f - f0));
    if (const long long bad = ds::gather_triangles<M, T>(mesh, work); bad >= 0)
        return fail(errc::topology,
                    "loop_subdivide: face " + std::to_string(bad) + " is not a triangle (triangulate_faces first)",
                    bad);
    if (overflow)
        return fail(errc::invalid_argument,
                    "loop_subdivide: " + std::to_string(options.levels) +
                        " levels would make more than 2^31 halfedges, more than a mesh index holds");
    if (options.levels == 0) return loop_result{T::vertex_count(mesh), T::edge_count(mesh), T::face_count(mesh)};
    const std::size_t vertex_bound = T::vertex_index_bound(mesh) + std::size_t(v - v0);
    const std::size_t edge_bound = T::edge_index_bound(mesh) + std::size_t(e - e0);
    const std::size_t face_bound = T::face_index_bound(mesh) + std::size_t(f - f0);
    ds::reserve_room<M, T>(mesh, vertex_bound, edge_bound, face_bound);
    work.room = {vertex_bound, edge_bound, face_bound};
    [[maybe_unused]] const detail::subdivision::appending_guard<M> appending(mesh);  // new vertices are told by index
    work.reserve(vertex_bound - std::size_t(v - largest_v), edge_bound - std::size_t(e - largest_e),
                 face_bound - std::size_t(f - largest_f));
    detail::progress_gate gate(options.progress, std::size_t(elements / ds::check_every));
    ds::cancel_point go_on{gate};
    // Without a callback nothing can stop a level half way, so there is nothing to copy. With
    // one, a copy taken before the first change is what a cancellation restores.
    mesh_rollback<M> undo(mesh, bool(options.progress));
    ds::range_guard<M, T> range(mesh);
    for (std::size_t l = 0; l < options.levels; ++l) {
        // Level 0's triangles were gathered above; later ones are triangles only (-1) unless cancelled (-2).
        const bool cancelled =
            (l > 0 && ds::gather_triangles<M, T>(mesh, work, &go_on) == -2) || !ds::loop_level<M, T>(mesh, work, go_on);
        if (cancelled) {
            range.dismiss();
            undo.restore();
            return fail(errc::cancelled, "loop_subdivide: cancelled");
        }
    }
    range.restore();
    undo.commit();
    return loop_result{T::vertex_count(mesh), T::edge_count(mesh), T::face_count(mesh)};
}

}  // namespace hmira
