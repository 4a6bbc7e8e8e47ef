// hmira/algorithms/validation/self_intersections.hpp
// Which faces of a mesh cut, touch or overlap each other where the connectivity says they should
// not: the check a boolean, a 3D printer or a solver needs before it trusts a surface. Every
// decision is an exact predicate (predicates/intersect3d.hpp); no tolerance anywhere.
//
// Options: self_intersections_options. Result: the sorted list of face pairs. Requires:
// self_intersection_mesh<M, T>. Entry point: self_intersections(mesh, options). The machinery
// (triangles of polygon faces, box sweep, the pair test) is in detail/self_intersections_impl.hpp.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/progress.hpp"
#include "../../core/result.hpp"
#include "../triangulation/triangulate_faces.hpp"

namespace hmira {

/// Options of self_intersections.
struct self_intersections_options {
    /// Worker threads for the pair search (0: all cores; without TBB always one).
    unsigned threads = 0;
    /// Called between blocks of the pair search; returning false cancels (errc::cancelled).
    progress_function progress = {};
};

/// Two faces, by face index, the smaller first.
using face_pair = std::array<std::size_t, 2>;

/// The models self_intersections reads: face loops, positions, vertex and face indices.
template <class M, class T = default_traits<M>>
concept self_intersection_mesh = face_triangulable_mesh<M, T> && vertex_index_mesh<M, T>;

/// Every pair of faces whose closed point sets share a point other than the vertices and edges
/// they share by connectivity. Faces that share an edge are reported when they fold onto each
/// other (coplanar, on the same side of the edge); faces that share one vertex when they meet
/// anywhere else; faces that share nothing when they meet at all, touching included. Two
/// distinct vertices at one position do not count as shared. A face with all three vertices in
/// common with another (a duplicate) is reported.
///
/// Polygon faces are cut into triangles first, as face_triangles does (exact, in the face's
/// projection plane); a face that has no simple projection (self-crossing, no area) is fanned
/// from its first corner instead. Its triangles are not tested against each other.
/// Triangles of zero area (collinear corners) are tested as the segments they are against
/// triangles they share no vertex with; against triangles they share a vertex with they are
/// not tested (validate reports them as zero_area_face).
///
/// \pre none.
/// \post the mesh is only read. The pairs are sorted, without repeats, each {f, g} with f < g,
///   and do not depend on the thread count.
/// Errors (nothing returned): errc::invalid_argument naming the vertex whose coordinate is not
/// finite or outside the exact predicates' range (predicates::in_predicate_range);
/// errc::cancelled when options.progress asks to stop.
/// Complexity: O(T log T + K) for T triangles and K pairs of triangles whose bounding boxes
/// overlap along the sweep axis (the axis of the largest extent) — about T sqrt(T) for a
/// surface — each candidate pair a constant number of exact predicates.
template <class M, class T = default_traits<M>>
    requires self_intersection_mesh<M, T>
[[nodiscard]] result<std::vector<face_pair>> self_intersections(const M& mesh,
                                                                const self_intersections_options& options = {});

}  // namespace hmira

#include "detail/self_intersections_impl.hpp"
