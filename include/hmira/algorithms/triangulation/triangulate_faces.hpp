// hmira/algorithms/triangulation/triangulate_faces.hpp
// Faces to triangles: face_triangles gives one face's triangles (inner rings included) as
// vertex triples, for writers such as STL; triangulate_faces cuts every face of a mesh.
// The machinery is in detail/triangulate_faces_impl.hpp.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/result.hpp"
#include "../euler/euler_common.hpp"
#include "triangulate_polygon.hpp"

namespace hmira {

// Options: triangulate_polygon_options (triangulate_polygon.hpp), applied to every face.

/// What triangulate_faces did.
struct triangulate_faces_result {
    std::size_t faces_cut = 0;        ///< faces that were not triangles (or had rings)
    std::size_t triangles_added = 0;  ///< faces the mesh gained
};

/// A mesh whose faces face_triangles can read: the outer loop's vertices, positions, indices
/// (to name a refused face). Inner rings are read too where the model has them.
template <class M, class T = default_traits<M>>
concept face_triangulable_mesh = face_vertex_range_mesh<M, T> && positioned_mesh<M, T> && face_index_mesh<M, T>;

/// A mesh triangulate_faces can cut: faces it can read (face_triangulable_mesh) and the Euler
/// operators to add the diagonals.
template <class M, class T = default_traits<M>>
concept triangulable_mesh = face_triangulable_mesh<M, T> && euler_mutable_mesh<M, T>;

/// Cuts every face that is not a triangle, or has inner rings, into triangles
/// (face_triangles), with the Euler operators: a bridge to a ring is makeEkillR, every other
/// diagonal makeEF. Every face is triangulated on paper first, so a refused face leaves the
/// mesh unchanged. With options.delaunay each face's diagonals are the constrained Delaunay
/// ones in its plane.
/// \pre none (every face is checked before the mesh is touched).
/// \post every face is a triangle without rings; V unchanged; the surface is the same point set.
///   Errors (mesh unchanged): those of face_triangles, naming the first refused face.
/// Complexity: O(sum over faces of n_f log n_f) typical, n_f the face's corners: each cut walks
/// the shorter part of its piece. Faces with inner rings: O(n_f) per cut and per bridge.
template <class M, class T = default_traits<M>>
    requires triangulable_mesh<M, T>
[[nodiscard]] result<triangulate_faces_result> triangulate_faces(M& mesh,
                                                                 const triangulate_polygon_options& options = {});

/// The triangles of face f as vertex triples, wound like the face: its outer loop and inner
/// rings projected onto the coordinate plane that the face's Newell normal is closest to, and
/// triangulated there with exact predicates (triangulate_polygon). A triangle without rings
/// comes back as itself. With options.delaunay the diagonals are flipped to the constrained
/// Delaunay triangulation in that plane (triangulate_polygon_options::delaunay).
/// \pre none. \post the mesh is only read.
///   Errors (naming the face): errc::degenerate_face for a loop of fewer than three corners or
///   a face without projected area; errc::topology when the projection is not a simple polygon
///   with holes (self-crossing, repeated corner, ring outside its face);
///   errc::invalid_argument for non-finite coordinates.
/// Complexity: that of triangulate_polygon on the face's corners (O(n log n)).
template <class M, class T = default_traits<M>>
    requires face_triangulable_mesh<M, T>
[[nodiscard]] result<std::vector<std::array<typename T::vertex_handle, 3>>> face_triangles(
    const M& mesh, typename T::face_handle f, const triangulate_polygon_options& options = {});

}  // namespace hmira

#include "detail/triangulate_faces_impl.hpp"
