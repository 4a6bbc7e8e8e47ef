// hmira/algorithms/subdivision/sqrt3.hpp
// Kobbelt's sqrt(3) subdivision of a triangle mesh, built from the local operators: every
// triangle split 1-to-3 at its centroid, then every old interior edge flipped, so the faces
// triple per level and two levels trisect every edge. Boundaries follow Kobbelt's rule.
#pragma once

#include <concepts>
#include <cstddef>
#include <type_traits>

#include "../../core/progress.hpp"
#include "../../core/result.hpp"
#include "../triangle/triangle_common.hpp"

namespace hmira {

/// Options of sqrt3_subdivide.
struct sqrt3_options {
    /// Levels of subdivision (each multiplies the faces by 3; two levels trisect every edge).
    std::size_t levels = 1;
    /// Called between blocks of work (every 16384 elements) with the fraction done; returning
    /// false cancels (error errc::cancelled, "sqrt3_subdivide: cancelled", mesh unchanged).
    /// With a callback the mesh is copied once before the first change (mesh_rollback), so
    /// that a cancellation can restore it; without one nothing can stop the levels once they
    /// have begun and no copy is made.
    progress_function progress = {};
};

/// What sqrt3_subdivide did.
struct sqrt3_result {
    std::size_t vertices = 0;  ///< vertices after the last level
    std::size_t edges = 0;     ///< edges after the last level
    std::size_t faces = 0;     ///< faces after the last level
};

/// A mesh sqrt3_subdivide can run on: the triangle operators, dense vertex, edge and face
/// indices for its per-level arrays, sizing and error messages, and copies (to restore the
/// mesh on cancellation).
template <class M, class T = default_traits<M>>
concept sqrt3_subdividable_mesh = triangle_operable_mesh<M, T> && vertex_index_mesh<M, T> && edge_index_mesh<M, T> &&
                                  face_index_mesh<M, T> && std::copy_constructible<M> && std::is_move_assignable_v<M>;

/// Kobbelt's sqrt(3) subdivision, `options.levels` times. Each level splits every triangle at
/// its centroid into three, flips every old edge that has a face on both sides (so each new
/// vertex joins the new vertices of its neighbours), and moves each old interior vertex by
/// Kobbelt's rule: 1 - alpha of itself plus alpha / n of each of its n neighbours,
/// alpha = (4 - 2 cos(2 pi / n)) / 9.
///
/// Boundaries (Kobbelt 2000, section 5): boundary edges are never flipped. On the 1st, 3rd,
/// ... level of a call the boundary stays as it is; on the 2nd, 4th, ... level a triangle
/// with a boundary side has that side trisected and joined to its third corner instead of
/// a centroid split, the new points and the boundary vertices following the ternary cubic
/// B-spline of the boundary polygon (1, 16, 10 and 4, 19, 4, over 27). So two levels (or any
/// even number, in one call) trisect every edge, boundary edges included; a vertex where
/// boundary fans meet stays. Split the levels over several calls only in even numbers.
///
/// \pre every face is a triangle without rings.
/// \post per level: V + F, E + 3 F, F * 3; on a trisecting level also V + B, E + B (B the
/// boundary edges, which triple). Genus and boundary loops unchanged.
/// Errors (mesh unchanged): errc::topology when a face is not a triangle (naming it);
/// errc::invalid_argument for more than 20 levels, or when the result would need more than
/// 2^31 halfedges; errc::cancelled when options.progress returns false. The mesh is sized for
/// the last level before the first change, so std::bad_alloc comes before any change (user
/// property arrays excepted). Every new position is a convex combination of old ones and is
/// computed without overflow, coordinates near the largest double included
/// (see detail::subdivision::range_guard).
/// Complexity O(F) per level, so O(3^levels F); plus O(V + E + F) for the copy when a
/// progress callback is given (core/rollback.hpp).
template <class M, class T = default_traits<M>>
    requires sqrt3_subdividable_mesh<M, T>
[[nodiscard]] result<sqrt3_result> sqrt3_subdivide(M& mesh, const sqrt3_options& options = {});

}  // namespace hmira

// The machinery, and the definition of sqrt3_subdivide.
#include "detail/sqrt3_impl.hpp"
