// hmira/algorithms/euler/make_vertex.hpp
// Euler operators makeV / killV (Mantyla's MVFS / KVFS, thesis 2.1.1-2.1.2): the first step
// of building any mesh from nothing, and the last step of taking one apart.
#pragma once

#include "../../core/vec3.hpp"
#include "euler_common.hpp"

namespace hmira {

/// What make_vertex created.
template <class M, class T = default_traits<M>>
struct make_vertex_result {
    typename T::vertex_handle vertex;  ///< the new, isolated vertex
};

/// What kill_vertex removed, enough for make_vertex to put it back.
template <class M, class T = default_traits<M>>
struct kill_vertex_result {
    vec3<typename T::scalar> position;  ///< where the killed vertex was
};

/// makeV (MVFS): a new isolated vertex at `position`: a new shell.
///
/// Mantyla's MVFS also makes a face; a surface mesh has no face without edges, so the shell's
/// face is the vertex's empty boundary loop (see euler_mutable_mesh): V + 1, F + 1, S + 1.
/// Complexity O(1). Never fails.
template <class M, class T = default_traits<M>>
    requires euler_mutable_mesh<M, T>
make_vertex_result<M, T> make_vertex(M& mesh, const vec3<typename T::scalar>& position) {
    return {T::add_vertex(mesh, position)};
}

/// killV (KVFS): removes an isolated vertex (a shell of one vertex): V - 1, F - 1, S - 1.
///
/// Precondition: `vertex` has no edge. Errors: errc::invalid_handle for a handle out of
/// range, errc::topology when the vertex has edges; the mesh is then unchanged.
/// Complexity O(1). The slot stays allocated until the model collects garbage or, on a model
/// that reuses slots (halfedge_mesh, CGAL), a new vertex takes it.
template <class M, class T = default_traits<M>>
    requires euler_mutable_mesh<M, T>
result<kill_vertex_result<M, T>> kill_vertex(M& mesh, typename T::vertex_handle vertex) {
    namespace de = detail::euler;
    if (!de::usable<M, T>(mesh, vertex))
        return fail(errc::invalid_handle, "kill_vertex: " + de::name<M, T>("vertex", mesh, vertex) + " does not exist",
                    de::index_of<M, T>(mesh, vertex));
    if (T::vertex_halfedge(mesh, vertex) != T::null_halfedge())
        return fail(errc::topology,
                    "kill_vertex: " + de::name<M, T>("vertex", mesh, vertex) +
                        " still has edges; only an isolated vertex can be killed (use kill_edge_vertex first)",
                    de::index_of<M, T>(mesh, vertex));
    kill_vertex_result<M, T> out{vec3<typename T::scalar>{}};
    if constexpr (positioned_mesh<M, T>) out.position = T::position(mesh, vertex);
    T::erase_vertex(mesh, vertex);
    return out;
}

}  // namespace hmira
