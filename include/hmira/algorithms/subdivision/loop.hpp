// hmira/algorithms/subdivision/loop.hpp
// Loop subdivision of a triangle mesh, built from the local operators: every edge split at
// its Loop edge point, then the new edges that join an old and a new vertex flipped (1-to-4),
// and the old vertices moved by Loop's vertex rule. Boundaries follow the cubic B-spline.
#pragma once

#include <concepts>
#include <cstddef>
#include <type_traits>

#include "../../core/progress.hpp"
#include "../../core/result.hpp"
#include "../triangle/triangle_common.hpp"

namespace hmira {

/// Options of loop_subdivide.
struct loop_options {
    /// Levels of subdivision (each multiplies the faces by 4).
    std::size_t levels = 1;
    /// Called between blocks of work (every 16384 elements) with the fraction done; returning
    /// false cancels (error errc::cancelled, "loop_subdivide: cancelled", mesh unchanged). With
    /// a callback the mesh is copied once before the first change (mesh_rollback), so that a
    /// cancellation can restore it; without one nothing can stop the levels once they have
    /// begun and no copy is made.
    progress_function progress = {};
};

/// What loop_subdivide did.
struct loop_result {
    std::size_t vertices = 0;  ///< vertices after the last level
    std::size_t edges = 0;     ///< edges after the last level
    std::size_t faces = 0;     ///< faces after the last level
};

/// A mesh loop_subdivide can run on: the triangle operators, dense vertex, edge and face
/// indices for its per-level arrays, and copies (mesh_rollback, to restore the mesh on cancellation).
template <class M, class T = default_traits<M>>
concept loop_subdividable_mesh = triangle_operable_mesh<M, T> && vertex_index_mesh<M, T> && edge_index_mesh<M, T> &&
                                 face_index_mesh<M, T> && std::copy_constructible<M> && std::is_move_assignable_v<M>;

/// Loop subdivision, `options.levels` times. Each level splits every edge at its edge point
/// (3/8 of each end plus 1/8 of each opposite corner; the midpoint on a boundary), flips the
/// new edges that join an old vertex to a new one (so each triangle becomes four), and moves
/// each old vertex by Loop's rule (1 - n beta of itself plus beta of each of its n
/// neighbours, beta = (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n; on a boundary 3/4 of itself
/// and 1/8 of each boundary neighbour; a vertex where two boundary fans meet stays).
///
/// \pre every face is a triangle without rings.
/// \post per level: V + E, E * 2 + 3 F, F * 4; genus and boundary loops unchanged.
/// Errors (mesh unchanged): errc::topology when a face is not a triangle (naming it);
/// errc::invalid_argument for more than 10 levels (a million-fold growth), or when the result
/// would need more than 2^31 halfedges; errc::cancelled when options.progress returns false.
/// The mesh and working arrays are sized for the last
/// level before the first change, so std::bad_alloc comes before any change (user property
/// arrays, which grow element by element, excepted).
/// Every new position is a convex combination of old ones and is computed without overflow,
/// coordinates near the largest double included (see detail::subdivision::range_guard).
/// Complexity O(F) per level (each operator is O(1) or O(valence)), so O(4^levels F); plus
/// O(V + E + F) for the copy when a progress callback is given (core/rollback.hpp).
template <class M, class T = default_traits<M>>
    requires loop_subdividable_mesh<M, T>
[[nodiscard]] result<loop_result> loop_subdivide(M& mesh, const loop_options& options = {});

/// Whether every face of the mesh is a triangle without rings. O(F).
template <class M, class T = default_traits<M>>
    requires triangle_operable_mesh<M, T>
bool is_triangle_mesh(const M& mesh) {
    for (auto f : T::faces(mesh))
        if (!detail::triangle_ops::in_triangle<M, T>(mesh, T::face_halfedge(mesh, f))) return false;
    return true;
}

}  // namespace hmira

// The machinery (the workspace, one level, and the definition of loop_subdivide).
#include "detail/loop_impl.hpp"
