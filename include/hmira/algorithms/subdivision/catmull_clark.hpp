// hmira/algorithms/subdivision/catmull_clark.hpp
// Catmull-Clark subdivision of any polygon mesh, boundaries included, built from the local
// operators' links: every edge split at its edge point, then each face cut into quads around a
// new face-centre vertex (make_edge_vertex's, then make_edge_face's links), and the old
// vertices moved.
#pragma once

#include <concepts>
#include <cstddef>
#include <type_traits>

#include "../../core/progress.hpp"
#include "../../core/result.hpp"
#include "../triangle/triangle_common.hpp"

namespace hmira {

/// Options of catmull_clark_subdivide.
struct catmull_clark_options {
    /// Levels of subdivision (the first makes one quad per face corner, each further one
    /// multiplies the faces by 4). At most 10.
    std::size_t levels = 1;
    /// Called between blocks of work with the fraction done; returning false cancels (error
    /// errc::cancelled, "catmull_clark_subdivide: cancelled", mesh unchanged). With a
    /// callback the mesh is copied once before the first change (mesh_rollback), so that a
    /// cancellation can restore it; without one nothing can stop the levels once they have
    /// begun and no copy is made.
    progress_function progress = {};
};

/// What catmull_clark_subdivide did.
struct catmull_clark_result {
    std::size_t vertices = 0;  ///< vertices after the last level
    std::size_t edges = 0;     ///< edges after the last level
    std::size_t faces = 0;     ///< faces after the last level
};

/// A mesh catmull_clark_subdivide can run on: the Euler operators (so polygons of any degree,
/// which excludes triangles-only models), movable positions, dense vertex, edge and face
/// indices for its per-level arrays, and copies (mesh_rollback, to restore the mesh on cancellation).
/// halfedge_mesh, winged_edge_mesh, OpenMesh PolyMesh and CGAL Surface_mesh qualify.
template <class M, class T = default_traits<M>>
concept catmull_clark_subdividable_mesh =
    euler_mutable_mesh<M, T> && position_mutable_mesh<M, T> && vertex_index_mesh<M, T> && edge_index_mesh<M, T> &&
    face_index_mesh<M, T> && std::copy_constructible<M> && std::is_move_assignable_v<M>;

/// Catmull-Clark subdivision, `options.levels` times, on any polygon mesh. Each level puts a
/// face point at each face's centroid; splits each edge at its edge point (the average of its
/// two ends and the two face points beside it; the midpoint on a boundary); joins each face
/// point to the edge points around it, so a face of degree n becomes n quads; and moves each
/// old vertex S of valence n to (Q + 2R + (n - 3) S) / n, with Q the average of the face
/// points around it and R the average of its edges' midpoints.
///
/// Boundaries follow the cubic B-spline of the boundary polygon: a boundary edge point is the
/// edge's midpoint and a boundary vertex moves to 3/4 of itself plus 1/8 of each of its two
/// boundary neighbours, so the boundary curve depends on the boundary alone and two meshes
/// sharing a boundary stay joined. A vertex where two boundary fans meet, and an isolated
/// vertex, stay where they are.
///
/// \pre no face has inner rings; every edge has a face on at least one side, and different
///      faces when it has two.
/// \post per level: V + E + F vertices, 2 E + C edges and C faces (C the sum of the face
///       degrees), every face a quad; genus and boundary loops unchanged. Old vertices keep
///       their handles; faces keep theirs (each old face is one of its quads).
/// Errors (mesh unchanged): errc::unsupported for a face with inner rings (naming it);
/// errc::topology for an edge without faces or with the same face on both sides (naming it);
/// errc::invalid_argument for more than 10 levels, or when the result would need more than
/// 2^31 halfedges; errc::cancelled when options.progress returns false.
/// The mesh and the working arrays are sized for the last level before the first change, so
/// std::bad_alloc comes before any change (a model's user property arrays excepted, which
/// grow element by element).
/// Every new position is a convex combination of old ones and is computed without overflow,
/// coordinates near the largest double included (see detail::subdivision::range_guard).
/// Complexity O(C) per level (every operator is O(1) or O(face degree)), so O(4^levels C);
/// plus O(V + E + F) for the copy when a progress callback is given (core/rollback.hpp).
template <class M, class T = default_traits<M>>
    requires catmull_clark_subdividable_mesh<M, T>
[[nodiscard]] result<catmull_clark_result> catmull_clark_subdivide(M& mesh, const catmull_clark_options& options = {});

}  // namespace hmira

// The machinery (one level, pass by pass) and the definition of catmull_clark_subdivide.
#include "detail/catmull_clark_impl.hpp"
