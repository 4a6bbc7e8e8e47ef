// hmira/algorithms/euler/split_vertex.hpp
// The general form of makeEV / killEV (thesis 2.1.3-2.1.4): split a vertex in two, the new
// vertex taking over a contiguous fan of the old one's edges and a new edge joining the two;
// and join the two ends of an edge into one vertex again. Region extrusion is built on them.
#pragma once

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "../../core/vec3.hpp"
#include "detail/split_vertex_impl.hpp"
#include "euler_common.hpp"
#include "make_edge_vertex.hpp"

namespace hmira {

/// What split_vertex created: join_vertices(mesh, halfedge) undoes it.
template <class M, class T = default_traits<M>>
struct split_vertex_result {
    typename T::vertex_handle vertex;      ///< the new vertex, holding the moved fan
    typename T::halfedge_handle halfedge;  ///< the new edge, running from the old vertex to the new one
};

/// What join_vertices removed, and where: split_vertex(mesh, h0, h1, position) puts it back
/// (make_edge_vertex(mesh, vertex, position) when h0 is null, i.e. `vertex` became isolated).
template <class M, class T = default_traits<M>>
struct join_vertices_result {
    typename T::vertex_handle vertex;  ///< the surviving vertex (the source of the joined edge)
    /// The corners at `vertex` that bound the fan the removed vertex held, to pass back to
    /// split_vertex; equal when that vertex had degree 1, null if `vertex` is now isolated.
    ///@{
    typename T::halfedge_handle h0, h1;
    ///@}
    vec3<typename T::scalar> position{};  ///< where the removed vertex was
};

/// makeEV (MEV), general form: splits v = target(h0) = target(h1) in two. A new vertex at
/// `position` takes over the edges of v that lie strictly between the corner of h0 and the
/// corner of h1, turning from h0 (an incoming halfedge x is followed by opposite(next(x))),
/// and a new edge joins v to it. Corner h0 then reads `h0 -> new edge -> old next(h0)` and
/// corner h1 reads `h1 -> back -> old next(h1)`, so the new edge lies in face(h0) on one side
/// and face(h1) on the other. With h0 == h1 nothing moves: that is make_edge_vertex(h0), an
/// edge hanging into face(h0). No loop is split or joined and no face changes: V + 1, E + 1;
/// each of face(h0) and face(h1) gains one side.
///
/// Errors (mesh unchanged): errc::invalid_handle for a null or out-of-range corner;
/// errc::topology when the corners end at different vertices, or when h1 is not in h0's
/// rotation (a vertex whose edges form several separate fans).
/// Complexity O(m) for a moved fan of m edges, plus O(V_adjacentV) when the old vertex's
/// boundary gap moves to the new vertex or the precondition fails.
template <class M, class T = default_traits<M>>
    requires euler_mutable_mesh<M, T>
result<split_vertex_result<M, T>> split_vertex(M& mesh, typename T::halfedge_handle h0, typename T::halfedge_handle h1,
                                               const vec3<typename T::scalar>& position) {
    namespace de = detail::euler;
    using H = typename T::halfedge_handle;
    if (!de::usable<M, T>(mesh, h0) || !de::usable<M, T>(mesh, h1))
        return fail(errc::invalid_handle,
                    "split_vertex: corner " + de::name<M, T>("halfedge", mesh, de::usable<M, T>(mesh, h0) ? h1 : h0) +
                        " does not exist",
                    de::index_of<M, T>(mesh, de::usable<M, T>(mesh, h0) ? h1 : h0));
    const auto v = T::target(mesh, h0);
    if (T::target(mesh, h1) != v)
        return fail(errc::topology,
                    "split_vertex: the corners end at different vertices (" + de::name<M, T>("vertex", mesh, v) +
                        " and " + de::name<M, T>("vertex", mesh, T::target(mesh, h1)) +
                        "); both must be corners of the vertex to split",
                    de::index_of<M, T>(mesh, h1));
    if (h0 == h1) {
        // No edge moves: the antenna form.
        const auto r = make_edge_vertex<M, T>(mesh, h0, position);
        if (!r) return r.error();
        return split_vertex_result<M, T>{r->vertex, r->halfedge};
    }
    const auto moved = de::turn_between<M, T>(mesh, h0, h1);  // into v, the last one is h1
    if (moved.empty())
        return fail(errc::topology,
                    "split_vertex: " + de::name<M, T>("halfedge", mesh, h1) + " is not in the rotation of " +
                        de::name<M, T>("halfedge", mesh, h0) + " around " + de::name<M, T>("vertex", mesh, v) +
                        " (the vertex's edges form separate fans)",
                    de::index_of<M, T>(mesh, v));

    const auto f0 = T::face(mesh, h0), f1 = T::face(mesh, h1);
    const auto n0 = T::next(mesh, h0), n1 = T::next(mesh, h1);
    // Stored halfedges, read through the traits before any change (a model may store an
    // incoming halfedge and derive the outgoing one from the links).
    const H stored = T::vertex_halfedge(mesh, v);
    bool stored_moves = false;
    H w_boundary = T::null_halfedge();  // an outgoing halfedge of the new vertex on the boundary
    for (auto x : moved) {
        const auto out = T::opposite(mesh, x);  // leaves the new vertex afterwards
        stored_moves |= out == stored;
        if (w_boundary == T::null_halfedge() && T::face(mesh, out) == T::null_face()) w_boundary = out;
    }

    const auto w = T::add_vertex(mesh, position);
    const auto out = T::new_edge(mesh, v, w);
    const auto back = T::opposite(mesh, out);
    for (auto x : moved) T::set_target(mesh, x, w);
    T::set_next(mesh, h0, out);
    T::set_next(mesh, out, n0);
    T::set_next(mesh, h1, back);
    T::set_next(mesh, back, n1);
    T::set_face(mesh, out, f0);
    T::set_face(mesh, back, f1);
    // The new vertex leaves by the opposites of the moved halfedges and by back (in face(h1));
    // on the boundary it must store a boundary one.
    if (w_boundary == T::null_halfedge() && f1 == T::null_face()) w_boundary = back;
    T::set_vertex_halfedge(mesh, w, w_boundary != T::null_halfedge() ? w_boundary : back);
    // v keeps its stored halfedge unless it moved; a boundary replacement comes first.
    H v_out = stored;
    if (stored_moves) {
        v_out = f0 == T::null_face() ? out : f1 == T::null_face() ? n1 : out;
        T::set_vertex_halfedge(mesh, v, v_out);
        if (T::face(mesh, stored) == T::null_face() && T::face(mesh, v_out) != T::null_face())
            de::prefer_boundary_halfedge<M, T>(mesh, v);
    } else {
        T::set_vertex_halfedge(mesh, v, v_out);
    }
    return split_vertex_result<M, T>{w, out};
}

/// killEV (KEV), general form, the exact inverse of split_vertex wherever the split kept the
/// mesh manifold (distinct corners on different faces of a vertex with at most one boundary
/// gap) and of the antenna form (equal corners): removes the edge of
/// `halfedge` (v -> w) and its target w; every other edge of w moves to v, in the same
/// rotation, so the faces on both sides of the edge lose one side. V - 1, E - 1. With w of
/// degree 1 this is kill_edge_vertex(halfedge).
///
/// Precondition, checked (errc::topology or errc::non_manifold, mesh unchanged): the edge is
/// no loop; v has degree 2 or more (else join from the other end); v and w are joined by no
/// other edge and have no common neighbour (joining them would make a double edge, and for a
/// triangle on the edge collapse that triangle into two sides); the faces on the two sides
/// differ unless both are the boundary, and no other face touches both ends (it would touch
/// the joined vertex twice); and the joined vertex would have at most one boundary gap (two
/// would pinch the surface there). errc::invalid_handle for a null or out-of-range
/// halfedge.
/// Complexity O((d_v + d_w) log(d_v + d_w)) for the degrees of the two ends (the common
/// neighbour check; O(d_v d_w) on a model without vertex indices) plus O(d_v d_w) for the
/// faces touching both ends (degrees are small), plus O(rings of the two
/// faces) where the model has rings.
template <class M, class T = default_traits<M>>
    requires euler_mutable_mesh<M, T>
result<join_vertices_result<M, T>> join_vertices(M& mesh, typename T::halfedge_handle halfedge) {
    namespace de = detail::euler;
    using H = typename T::halfedge_handle;
    const auto h = halfedge;
    if (!de::usable<M, T>(mesh, h))
        return fail(errc::invalid_handle, "join_vertices: " + de::name<M, T>("halfedge", mesh, h) + " does not exist",
                    de::index_of<M, T>(mesh, h));
    const auto o = T::opposite(mesh, h);
    const auto v = T::target(mesh, o), w = T::target(mesh, h);
    if (v == w)
        return fail(errc::topology,
                    "join_vertices: the edge of " + de::name<M, T>("halfedge", mesh, h) + " is a loop at " +
                        de::name<M, T>("vertex", mesh, v),
                    de::index_of<M, T>(mesh, v));
    const auto n = T::next(mesh, h), p = T::prev(mesh, h), q = T::prev(mesh, o), r = T::next(mesh, o);
    if (n == o) {
        // w has degree 1: the plain killEV.
        const auto k = kill_edge_vertex<M, T>(mesh, h);
        if (!k) return k.error();
        return join_vertices_result<M, T>{k->vertex, k->corner, k->corner, k->position};
    }
    if (auto ok = de::join_vertices_refusal<M, T>(mesh, h); !ok) return ok.error();

    const auto fh = T::face(mesh, h), fo = T::face(mesh, o);
    join_vertices_result<M, T> out{v, p, q, vec3<typename T::scalar>{}};
    if constexpr (positioned_mesh<M, T>) out.position = T::position(mesh, w);
    const auto moved = de::turn_between<M, T>(mesh, h, q);  // into w, h excluded
    const H sv = T::vertex_halfedge(mesh, v), sw = T::vertex_halfedge(mesh, w);
    H v_out = sv != h ? sv : n;
    if (!(sv != h && T::face(mesh, sv) == T::null_face())) {
        if (sw != o && T::face(mesh, sw) == T::null_face())
            v_out = sw;
        else if (fh == T::null_face())
            v_out = n;
        else if (fo == T::null_face())
            v_out = r;
    }
    for (auto x : moved) T::set_target(mesh, x, v);
    T::set_next(mesh, p, n);
    T::set_next(mesh, q, r);
    T::set_vertex_halfedge(mesh, v, v_out);
    for (auto [dead, repl, f] : {std::tuple{h, n, fh}, std::tuple{o, r, fo}}) {
        if (f == T::null_face()) continue;
        if (T::face_halfedge(mesh, f) == dead) T::set_face_halfedge(mesh, f, repl);
        de::replace_ring_halfedge<M, T>(mesh, f, dead, repl);
    }
    T::erase_edge(mesh, T::edge(mesh, h));
    T::erase_vertex(mesh, w);
    return out;
}

}  // namespace hmira
