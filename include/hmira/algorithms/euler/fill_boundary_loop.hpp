// hmira/algorithms/euler/fill_boundary_loop.hpp
// The one pair of operators a surface mesh needs beyond Mantyla's: a boundary loop (which
// hmira counts as a face, standing in for the face of Mantyla's MVFS) becomes a real face,
// and back. Without it no closed mesh could be built from makeV: makeEF on a boundary loop
// always leaves one side boundary.
#pragma once

#include "euler_common.hpp"

namespace hmira {

/// What fill_boundary_loop created: open_face(mesh, face) undoes it.
template <class M, class T = default_traits<M>>
struct fill_boundary_loop_result {
    typename T::face_handle face;  ///< the new face, whose outer loop is the former boundary loop
};

/// What open_face left: fill_boundary_loop(mesh, halfedge) undoes it.
template <class M, class T = default_traits<M>>
struct open_face_result {
    typename T::halfedge_handle halfedge;  ///< a halfedge of the new boundary loop
};

/// Makes the boundary loop through `halfedge` the outer loop of a new face. The Euler
/// characteristic does not change: hmira counts a boundary loop as a face already (see
/// euler_mutable_mesh); this is the surface-model step that closes Mantyla's last face.
///
/// Errors (mesh unchanged): errc::invalid_handle; errc::topology when `halfedge` is not on a
/// boundary loop. Complexity O(loop length), plus O(V_adjacentV) per vertex of the loop that
/// is still on the boundary elsewhere.
template <class M, class T = default_traits<M>>
    requires euler_mutable_mesh<M, T>
result<fill_boundary_loop_result<M, T>> fill_boundary_loop(M& mesh, typename T::halfedge_handle halfedge) {
    namespace de = detail::euler;
    if (!de::usable<M, T>(mesh, halfedge))
        return fail(errc::invalid_handle,
                    "fill_boundary_loop: " + de::name<M, T>("halfedge", mesh, halfedge) + " does not exist",
                    de::index_of<M, T>(mesh, halfedge));
    if (T::face(mesh, halfedge) != T::null_face())
        return fail(errc::topology,
                    "fill_boundary_loop: " + de::name<M, T>("halfedge", mesh, halfedge) + " lies on " +
                        de::name<M, T>("face", mesh, T::face(mesh, halfedge)) + ", not on a boundary loop",
                    de::index_of<M, T>(mesh, halfedge));
    const auto g = T::new_face(mesh);
    auto x = halfedge;
    do {
        T::set_face(mesh, x, g);
        x = T::next(mesh, x);
    } while (x != halfedge);
    T::set_face_halfedge(mesh, g, halfedge);
    x = halfedge;
    do {
        de::prefer_boundary_halfedge<M, T>(mesh, T::target(mesh, x));
        x = T::next(mesh, x);
    } while (x != halfedge);
    return fill_boundary_loop_result<M, T>{g};
}

/// Deletes `face` but keeps its edges: its outer loop becomes a boundary loop (the inverse
/// of fill_boundary_loop). The Euler characteristic does not change.
///
/// Errors (mesh unchanged): errc::invalid_handle; errc::topology when the face has inner
/// rings (a boundary cannot hold them). Complexity O(face degree).
template <class M, class T = default_traits<M>>
    requires euler_mutable_mesh<M, T>
result<open_face_result<M, T>> open_face(M& mesh, typename T::face_handle face) {
    namespace de = detail::euler;
    if (!de::usable<M, T>(mesh, face))
        return fail(errc::invalid_handle, "open_face: " + de::name<M, T>("face", mesh, face) + " does not exist",
                    de::index_of<M, T>(mesh, face));
    if (de::has_rings<M, T>(mesh, face))
        return fail(
            errc::topology,
            "open_face: " + de::name<M, T>("face", mesh, face) + " has inner rings, which a boundary loop cannot hold",
            de::index_of<M, T>(mesh, face));
    const auto start = T::face_halfedge(mesh, face);
    auto x = start;
    do {
        T::set_face(mesh, x, T::null_face());
        const auto v = de::source<M, T>(mesh, x);
        if (T::face(mesh, T::vertex_halfedge(mesh, v)) != T::null_face()) T::set_vertex_halfedge(mesh, v, x);
        x = T::next(mesh, x);
    } while (x != start);
    T::erase_face(mesh, face);
    return open_face_result<M, T>{start};
}

}  // namespace hmira
