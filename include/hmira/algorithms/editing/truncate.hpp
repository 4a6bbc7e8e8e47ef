// hmira/algorithms/editing/truncate.hpp
// Vertex truncation (thesis 2.2): cut the corner at a vertex with a plane through new points on
// its edges, replacing the vertex by a new face. Works on one vertex, a set, or all vertices
// (cube -> truncated cube), on every Euler-capable model, built from the Euler operators.
// The machinery is in detail/truncate_impl.hpp.
#pragma once

#include <cstddef>
#include <ranges>
#include <string>
#include <vector>

#include "detail/editing_common.hpp"

namespace hmira {

/// Where the cuts go. Each cut point lies on an edge at `fraction` of the edge's length from
/// the truncated vertex or, when `distance` > 0, at that absolute distance instead.
/// On an edge whose other end is truncated by the same call the cut is clamped to half the
/// edge, so cuts from both ends never cross; at exactly half they meet and share one vertex
/// (cube at 1/2 -> cuboctahedron). Otherwise it is clamped to the whole edge (at 1 the cut
/// point lies on the neighbour, joined to it by an edge of length zero).
struct truncate_options {
    double fraction = 1.0 / 3.0;  ///< in (0, 1); used when distance is 0
    double distance = 0.0;        ///< > 0: absolute distance along each edge, overrides fraction
    /// Called every 1024 cut points and new faces, from the calling thread; returning false
    /// cancels: the mesh is rolled back and the error is errc::cancelled.
    progress_function progress = {};
};

/// What truncating one vertex created.
template <class M, class T = default_traits<M>>
struct truncate_result {
    /// The new face, wound like the faces around it; null for a vertex of degree 2 (the corner
    /// of a single face at the boundary, or between two faces), which is cut by one edge only.
    typename T::face_handle face;
    std::vector<typename T::vertex_handle> vertices;  ///< the cut points, in the new face's order
};

/// What truncating a set of vertices created.
template <class M, class T = default_traits<M>>
struct truncate_set_result {
    std::vector<typename T::face_handle> faces;       ///< one per vertex, in input order (null: degree 2)
    std::vector<typename T::vertex_handle> vertices;  ///< every cut point made (a shared one once)
};

/// A mesh truncate() can edit: see editable_mesh (Euler operators, positions, indices).
template <class M, class T = default_traits<M>>
concept truncatable_mesh = editable_mesh<M, T>;

/// Truncates the vertices in `vertices` (a range of vertex handles; duplicates count once):
/// each is replaced by a new face through cut points on its edges (see truncate_options for
/// where they go and what happens where two cuts meet). A vertex of degree d gives a d-gon;
/// the faces around it gain one vertex each. Per vertex: V + d - 1, E + d, F + 1; a point
/// shared by two meeting cuts saves one vertex and one edge.
///
/// Boundary vertices: the new face closes the corner, with one new boundary edge between the
/// two cut points on the boundary edges. A vertex of degree 2 has no room for a face: its
/// corner is cut off by a single new edge (V + 1, E + 1, F + 0).
///
/// \pre Every vertex exists, has degree 2 or more and at most one boundary gap; options in range.
/// \post On success the mesh is valid with the deltas above. On any error, when an allocation
///      throws, or when options.progress cancels ("truncate: cancelled", errc::cancelled), the
///      mesh is unchanged (see detail/transaction.hpp).
/// Errors: errc::invalid_argument for options out of range; errc::invalid_handle for a missing
/// vertex; errc::topology for an isolated vertex or a vertex of degree 1;
/// errc::non_manifold for a vertex with several boundary gaps.
/// Complexity O(sum of the degrees of the vertices) = O(V_adjacentV) per vertex, plus O(k)
/// expected for the selection of k vertices (hashing).
template <class M, class T = default_traits<M>, class R>
    requires truncatable_mesh<M, T> && range_of_handles<R, typename T::vertex_handle>
result<truncate_set_result<M, T>> truncate(M& mesh, const R& vertices, const truncate_options& options = {});

/// Truncates one vertex of degree d (see the set overload): V + d - 1, E + d, F + 1.
/// Complexity O(V_adjacentV). Errors as for the set overload; the mesh is unchanged on error.
template <class M, class T = default_traits<M>>
    requires truncatable_mesh<M, T>
result<truncate_result<M, T>> truncate(M& mesh, typename T::vertex_handle vertex, const truncate_options& options = {});

/// Truncates every vertex of the mesh (cube -> truncated cube: 24 V, 36 E, 14 F with 8
/// triangles and 6 octagons at fraction 1/3; cuboctahedron at 1/2). Isolated vertices are
/// errors, as in the set overload. Complexity O(V + E) = O(E_all).
template <class M, class T = default_traits<M>>
    requires truncatable_mesh<M, T>
result<truncate_set_result<M, T>> truncate_all(M& mesh, const truncate_options& options = {});

}  // namespace hmira

#include "detail/truncate_impl.hpp"
