// hmira/algorithms/euler/make_edge_vertex.hpp
// Euler operators makeEV / killEV (Mantyla's MEV / KEV, thesis 2.1.3-2.1.4): grow a new
// vertex out of an existing one on a new edge, and remove such a vertex of degree 1 again.
#pragma once

#include "../../core/vec3.hpp"
#include "euler_common.hpp"

namespace hmira {

/// What make_edge_vertex created.
template <class M, class T = default_traits<M>>
struct make_edge_vertex_result {
    typename T::vertex_handle vertex;      ///< the new vertex, of degree 1
    typename T::halfedge_handle halfedge;  ///< the new edge, running from the old vertex to the new one
};

/// What kill_edge_vertex removed, and where: make_edge_vertex(mesh, corner, position) (or
/// make_edge_vertex(mesh, vertex, position) when `corner` is null) puts it back.
template <class M, class T = default_traits<M>>
struct kill_edge_vertex_result {
    typename T::vertex_handle vertex;  ///< the surviving end of the killed edge
    typename T::halfedge_handle
        corner;  ///< the halfedge into `vertex` the edge hung after; null if `vertex` is now isolated
    vec3<typename T::scalar> position{};  ///< where the killed vertex was
};

/// makeEV (MEV): a new vertex at `position`, joined by a new edge to target(corner).
///
/// `corner` names the corner the edge goes into, unambiguous at a vertex shared by several
/// faces: the loop of `corner` becomes `corner -> new edge -> back -> next(corner)`, so the new
/// edge lies in face(corner) (or in its boundary loop when that face is null).
/// V + 1, E + 1. Complexity O(1).
/// Errors: errc::invalid_handle for a null or out-of-range corner (mesh unchanged).
template <class M, class T = default_traits<M>>
    requires euler_mutable_mesh<M, T>
result<make_edge_vertex_result<M, T>> make_edge_vertex(M& mesh, typename T::halfedge_handle corner,
                                                       const vec3<typename T::scalar>& position) {
    namespace de = detail::euler;
    if (!de::usable<M, T>(mesh, corner))
        return fail(errc::invalid_handle,
                    "make_edge_vertex: corner " + de::name<M, T>("halfedge", mesh, corner) + " does not exist",
                    de::index_of<M, T>(mesh, corner));
    const auto v = T::target(mesh, corner);
    const auto f = T::face(mesh, corner);
    const auto after = T::next(mesh, corner);
    const auto w = T::add_vertex(mesh, position);
    const auto out = T::new_edge(mesh, v, w);
    const auto back = T::opposite(mesh, out);
    T::set_next(mesh, corner, out);
    T::set_next(mesh, out, back);
    T::set_next(mesh, back, after);
    T::set_face(mesh, out, f);
    T::set_face(mesh, back, f);
    T::set_vertex_halfedge(mesh, w, back);
    return make_edge_vertex_result<M, T>{w, out};
}

/// makeEV (MEV) from an isolated vertex: a new vertex at `position` joined to `vertex` by a
/// new edge whose two sides form one boundary loop. V + 1, E + 1. Complexity O(1).
/// Errors: errc::invalid_handle; errc::topology when `vertex` already has edges (then name
/// the corner with the other overload). The mesh is unchanged on error.
template <class M, class T = default_traits<M>>
    requires euler_mutable_mesh<M, T>
result<make_edge_vertex_result<M, T>> make_edge_vertex(M& mesh, typename T::vertex_handle vertex,
                                                       const vec3<typename T::scalar>& position) {
    namespace de = detail::euler;
    if (!de::usable<M, T>(mesh, vertex))
        return fail(errc::invalid_handle,
                    "make_edge_vertex: " + de::name<M, T>("vertex", mesh, vertex) + " does not exist",
                    de::index_of<M, T>(mesh, vertex));
    if (T::vertex_halfedge(mesh, vertex) != T::null_halfedge())
        return fail(errc::topology,
                    "make_edge_vertex: " + de::name<M, T>("vertex", mesh, vertex) +
                        " has edges, so the new edge's place is ambiguous; pass the corner halfedge instead",
                    de::index_of<M, T>(mesh, vertex));
    const auto w = T::add_vertex(mesh, position);
    const auto out = T::new_edge(mesh, vertex, w);
    const auto back = T::opposite(mesh, out);
    T::set_next(mesh, out, back);
    T::set_next(mesh, back, out);
    T::set_face(mesh, out, T::null_face());
    T::set_face(mesh, back, T::null_face());
    T::set_vertex_halfedge(mesh, vertex, out);
    T::set_vertex_halfedge(mesh, w, back);
    return make_edge_vertex_result<M, T>{w, out};
}

/// killEV (KEV): removes the edge of `halfedge` and its target vertex, which must have
/// degree 1 (the inverse of make_edge_vertex: pass its result's `halfedge`). V - 1, E - 1.
///
/// Errors (mesh unchanged): errc::invalid_handle; errc::topology when the target has degree
/// 2 or more, or when the edge alone forms the whole loop of a face or inner ring (killing it
/// would leave a face without edges, which a surface model cannot hold).
/// Complexity O(1), plus O(rings of the face) where the model has inner rings.
template <class M, class T = default_traits<M>>
    requires euler_mutable_mesh<M, T>
result<kill_edge_vertex_result<M, T>> kill_edge_vertex(M& mesh, typename T::halfedge_handle halfedge) {
    namespace de = detail::euler;
    const auto h = halfedge;
    if (!de::usable<M, T>(mesh, h))
        return fail(errc::invalid_handle,
                    "kill_edge_vertex: " + de::name<M, T>("halfedge", mesh, h) + " does not exist",
                    de::index_of<M, T>(mesh, h));
    const auto o = T::opposite(mesh, h);
    const auto w = T::target(mesh, h);
    if (T::next(mesh, h) != o)
        return fail(errc::topology,
                    "kill_edge_vertex: " + de::name<M, T>("vertex", mesh, w) +
                        " has degree 2 or more; only a vertex of degree 1 can be killed with its edge",
                    de::index_of<M, T>(mesh, w));
    const auto f = T::face(mesh, h);
    const auto before = T::prev(mesh, h);
    const auto v = T::target(mesh, o);
    if (before == o && f != T::null_face())
        return fail(errc::topology,
                    "kill_edge_vertex: the edge is the whole loop of " + de::name<M, T>("face", mesh, f) +
                        "; killing it would leave a loop without edges",
                    de::index_of<M, T>(mesh, f));

    kill_edge_vertex_result<M, T> out{v, before == o ? T::null_halfedge() : before, vec3<typename T::scalar>{}};
    if constexpr (positioned_mesh<M, T>) out.position = T::position(mesh, w);
    if (before == o) {
        T::set_vertex_halfedge(mesh, v, T::null_halfedge());
    } else {
        const auto after = T::next(mesh, o);
        T::set_next(mesh, before, after);
        de::replace_vertex_halfedge<M, T>(mesh, v, h, after);
        if (f != T::null_face()) {
            const auto fh = T::face_halfedge(mesh, f);
            if (fh == h || fh == o) T::set_face_halfedge(mesh, f, after);
            de::replace_ring_halfedge<M, T>(mesh, f, h, after);
            de::replace_ring_halfedge<M, T>(mesh, f, o, after);
        }
    }
    T::erase_edge(mesh, T::edge(mesh, h));
    T::erase_vertex(mesh, w);
    return out;
}

}  // namespace hmira
