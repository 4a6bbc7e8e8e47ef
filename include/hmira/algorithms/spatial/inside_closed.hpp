// hmira/algorithms/spatial/inside_closed.hpp
// Exact inside/outside/on-surface test for points against a closed mesh: signed crossings of a
// ray, every branch an exact predicate, rays through edges and vertices resolved by symbolic
// perturbation. For open or broken meshes use a generalised winding number instead.
//
// Options: inside_closed_options. Result: a point_location per point. Requires:
// inside_closed_mesh<M, T>. Entry points: inside_closed(mesh, points, options) and
// inside_closed(mesh, point). The machinery is in detail/inside_closed_impl.hpp.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/progress.hpp"
#include "../../core/result.hpp"
#include "../../core/vec3.hpp"
#include "../triangulation/triangulate_faces.hpp"

namespace hmira {

/// Options of inside_closed over many points.
struct inside_closed_options {
    /// Worker threads over the points (0: all cores; without TBB always one).
    unsigned threads = 0;
    /// Called between blocks of points; returning false cancels (errc::cancelled).
    progress_function progress = {};
};

/// Where a point lies with respect to a closed surface.
enum class point_location {
    outside,     ///< winding number 0
    inside,      ///< winding number not 0 (1 for a closed, outward-oriented, non-overlapping mesh)
    on_surface,  ///< on a face, an edge or a vertex, exactly
};

/// The models inside_closed reads: face loops, positions, vertex and face indices.
template <class M, class T = default_traits<M>>
concept inside_closed_mesh = face_triangulable_mesh<M, T> && vertex_index_mesh<M, T>;

/// For each point, whether it is inside the closed mesh, outside, or exactly on it.
///
/// The winding number of a point is the signed count of the faces that the ray from it along +x
/// crosses (+1 where the face's normal has a positive x component). Every decision is exact:
/// whether the ray passes a face is decided by orient2d in the yz plane, on which side the face
/// lies by orient3d. A ray through an edge or a vertex is decided as if the point were moved by
/// (0, e, e^2) for an infinitesimal e > 0 (simulation of simplicity): the moved ray misses every
/// edge and vertex, each edge is decided the same way by the faces on both its sides, so every
/// crossing is counted exactly once. Faces parallel to the ray are never crossed by the moved ray.
/// A point on the surface itself (closed faces, exactly) is reported as on_surface. Polygon
/// faces are cut as face_triangles does (fanned when they have no simple projection); the
/// diagonals, run both ways, cancel.
///
/// \pre the mesh is closed: every edge is run as often in one direction as in the other (any
///   oriented closed surface, self-intersecting, nested or non-manifold ones included); on an open
///   mesh the answer depends on the ray direction.
/// \post the mesh and the points are only read; one location per point, in order.
/// Errors (nothing returned): errc::invalid_argument naming the vertex or the point with a
/// coordinate not finite or outside predicates::in_predicate_range; errc::cancelled.
/// Complexity: O(F + P F) for F faces (after triangulation) and P points: each point tests every
/// face's box, and the few faces whose yz box holds it with exact predicates.
template <class M, class T = default_traits<M>>
    requires inside_closed_mesh<M, T>
[[nodiscard]] result<std::vector<point_location>> inside_closed(const M& mesh, std::span<const vec3<double>> points,
                                                                const inside_closed_options& options = {});

/// The same for one point.
template <class M, class T = default_traits<M>>
    requires inside_closed_mesh<M, T>
[[nodiscard]] result<point_location> inside_closed(const M& mesh, const vec3<double>& point);

/// The exact winding number of `point` with respect to the closed mesh, by the same crossings;
/// errc::invalid_argument (as above) also when the point lies on the surface, where it has none.
template <class M, class T = default_traits<M>>
    requires inside_closed_mesh<M, T>
[[nodiscard]] result<long long> closed_winding_number(const M& mesh, const vec3<double>& point);

}  // namespace hmira

#include "detail/inside_closed_impl.hpp"
