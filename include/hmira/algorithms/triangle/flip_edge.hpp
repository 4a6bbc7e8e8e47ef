// hmira/algorithms/triangle/flip_edge.hpp
// Edge flip: the edge shared by two triangles is replaced by the other diagonal of their
// quadrilateral. The workhorse of Delaunay improvement and remeshing.
#pragma once

#include "triangle_common.hpp"

namespace hmira {

/// Whether flip_edge(mesh, h) may run: the edge of h lies between two distinct triangles
/// (neither a boundary nor a face with inner rings), and the two vertices opposite it are
/// distinct and not already joined by an edge (the flip would make a double edge).
/// Topological only: a flip of a non-convex quadrilateral is allowed and folds the surface.
/// Complexity O(valence of the vertex opposite h).
template <class M, class T = default_traits<M>>
    requires triangle_operable_mesh<M, T>
bool is_flip_ok(const M& mesh, typename T::halfedge_handle h) {
    namespace dt = detail::triangle_ops;
    if (!detail::euler::usable<M, T>(mesh, h)) return false;
    const auto o = T::opposite(mesh, h);
    if (!dt::in_triangle<M, T>(mesh, h) || !dt::in_triangle<M, T>(mesh, o)) return false;
    if (T::face(mesh, h) == T::face(mesh, o)) return false;
    const auto c = T::target(mesh, T::next(mesh, h));
    const auto d = T::target(mesh, T::next(mesh, o));
    if (c == d) return false;
    return dt::find_halfedge<M, T>(mesh, c, d) == T::null_halfedge();
}

namespace detail::triangle_ops {

/// The link changes of flip_edge, without its checks: for callers that established
/// is_flip_ok for a whole batch of edges up front (Loop subdivision). O(1).
template <class M, class T>
void flip_links(M& mesh, typename T::halfedge_handle h) {
    const auto o = T::opposite(mesh, h);
    const auto hn = T::next(mesh, h), hp = T::prev(mesh, h);
    const auto on = T::next(mesh, o), op = T::prev(mesh, o);
    const auto f0 = T::face(mesh, h), f1 = T::face(mesh, o);
    const auto a = T::target(mesh, o), b = T::target(mesh, h);
    const auto c = T::target(mesh, hn), d = T::target(mesh, on);
    const bool a_stores_h = T::vertex_halfedge(mesh, a) == h;
    const bool b_stores_o = T::vertex_halfedge(mesh, b) == o;

    T::set_target(mesh, h, c);
    T::set_target(mesh, o, d);
    T::set_next(mesh, hp, on);
    T::set_next(mesh, on, h);
    T::set_next(mesh, h, hp);
    T::set_next(mesh, op, hn);
    T::set_next(mesh, hn, o);
    T::set_next(mesh, o, op);
    T::set_face(mesh, on, f0);
    T::set_face(mesh, hn, f1);
    T::set_face_halfedge(mesh, f0, h);
    T::set_face_halfedge(mesh, f1, o);
    // Both faces are interior, so a and b keep whatever boundary halfedge they store; only a
    // stored halfedge that now leaves another vertex must change.
    if (a_stores_h) T::set_vertex_halfedge(mesh, a, on);
    if (b_stores_o) T::set_vertex_halfedge(mesh, b, hn);
}

}  // namespace detail::triangle_ops

/// What flip_edge changed.
template <class M, class T = default_traits<M>>
struct flip_edge_result {
    typename T::halfedge_handle
        halfedge;  ///< the flipped edge, now running from the vertex opposite h's twin to the one opposite h
};

/// Flips the edge of h inside the quadrilateral of its two triangles: with h = a->b in
/// triangle (a, b, c) and its twin in (b, a, d), the edge becomes d->c and the triangles
/// (c, a, d) and (d, b, c). Faces, edges and vertices keep their handles.
///
/// Flip is its own inverse: flip_edge(mesh, result.halfedge) restores the connectivity (the
/// edge's halfedges then run the other way).
/// \pre nothing: a refused flip is reported.
/// \post V, E, F unchanged; deg(a), deg(b) - 1; deg(c), deg(d) + 1.
/// Errors (mesh unchanged): errc::invalid_handle for a null or out-of-range halfedge;
/// errc::topology when is_flip_ok(mesh, h) is false.
/// Complexity O(valence of c) for the check, O(1) for the flip.
template <class M, class T = default_traits<M>>
    requires triangle_operable_mesh<M, T>
[[nodiscard]] result<flip_edge_result<M, T>> flip_edge(M& mesh, typename T::halfedge_handle h) {
    namespace de = detail::euler;
    if (!de::usable<M, T>(mesh, h))
        return fail(errc::invalid_handle, "flip_edge: " + de::name<M, T>("halfedge", mesh, h) + " does not exist",
                    de::index_of<M, T>(mesh, h));
    if (!is_flip_ok<M, T>(mesh, h))
        return fail(errc::topology,
                    "flip_edge: the edge of " + de::name<M, T>("halfedge", mesh, h) +
                        " is not between two triangles, or its opposite vertices are already joined",
                    de::index_of<M, T>(mesh, h));
    detail::triangle_ops::flip_links<M, T>(mesh, h);
    return flip_edge_result<M, T>{h};
}

}  // namespace hmira
