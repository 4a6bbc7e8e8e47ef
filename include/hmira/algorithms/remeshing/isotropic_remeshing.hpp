// hmira/algorithms/remeshing/isotropic_remeshing.hpp
// Isotropic remeshing (Botsch and Kobbelt 2004): turns a triangle mesh into one whose edges
// all have about the same length and whose triangles are nearly equilateral, on the same surface.
#pragma once

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/progress.hpp"
#include "../../core/result.hpp"
#include "../triangle/triangle_common.hpp"

namespace hmira {

/// Options of isotropic_remeshing.
struct isotropic_remeshing_options {
    /// The edge length L to reach: edges end up within [4/5 L, 4/3 L]. Required (finite, > 0;
    /// default_target_edge_length() gives the usual choice).
    double target_edge_length = 0;
    /// Rounds of split, collapse, flip and relax-and-project.
    std::size_t iterations = 5;
    /// When set, an interior edge whose two faces' normals differ by more than this angle (in
    /// degrees, in [0, 180]) is a feature edge: kept where it is, like a boundary.
    std::optional<double> feature_angle = std::nullopt;
    /// More feature edges, by edge index (T::edge_index), kept as well.
    std::vector<std::size_t> feature_edges{};
    /// Project every moved vertex back onto the input surface (through an aabb_tree of it).
    bool project = true;
    /// Refuses a target length that would make more triangles than this (the estimate of
    /// estimate_isotropic_remeshing(): the surface area over the area of an equilateral
    /// triangle of side L).
    std::size_t max_faces = std::size_t{1} << 28;
    /// Refuses, before allocating, a target length whose estimated peak memory
    /// (estimate_isotropic_remeshing().bytes) exceeds this many bytes. Front ends pass the
    /// free memory; the default sets no limit.
    std::uint64_t max_bytes = UINT64_MAX;
    /// Called between passes with the fraction done; returning false cancels.
    progress_function progress{};
};

/// What isotropic_remeshing did.
struct isotropic_remeshing_result {
    std::size_t splits = 0;         ///< edge splits
    std::size_t collapses = 0;      ///< edge collapses
    std::size_t flips = 0;          ///< edge flips
    std::size_t feature_edges = 0;  ///< edges kept as features at the start (boundary included)
};

/// A mesh isotropic_remeshing can run on: the triangle operators, dense vertex, edge and face
/// indices for its side tables, and copies (mesh_rollback: a copy taken before the first change
/// is what a failure or a cancellation restores). halfedge_mesh, winged_edge_mesh, OpenMesh's
/// TriMesh and PolyMesh, and CGAL's Surface_mesh qualify.
template <class M, class T = default_traits<M>>
concept remeshable_mesh = triangle_operable_mesh<M, T> && vertex_index_mesh<M, T> && edge_index_mesh<M, T> &&
                          face_index_mesh<M, T> && face_vertex_range_mesh<M, T> && std::copyable<M>;

/// Remeshes a triangle mesh towards edge length L = options.target_edge_length. Each iteration:
/// 1. splits every edge longer than 4/3 L at its midpoint;
/// 2. collapses every edge shorter than 4/5 L unless that makes an edge longer than 4/3 L or
///    turns a triangle over;
/// 3. flips edges that bring vertex valences closer to 6 (4 on the boundary), then, beside
///    boundary and feature vertices, edges whose flip makes the smaller angle of a thin pair of
///    nearly coplanar triangles (below 35 degrees) larger;
/// 4. moves each vertex to the centroid of its neighbours (beside a boundary or feature vertex:
///    of its triangles, weighted by area) within its tangent plane and projects it onto the
///    input surface (closest point in an aabb_tree of the input).
///
/// Boundary edges and feature edges (by options.feature_angle and options.feature_edges) are
/// never collapsed or flipped, and their vertices never move: they are only split at their
/// midpoints, so every boundary and feature polyline keeps its shape and its vertices.
/// Deleted elements stay in models that keep them (halfedge_mesh: collect_garbage()).
/// \pre a triangle mesh (triangulate_faces first otherwise).
/// \post every face is a triangle; boundary and feature vertices of the input are still there,
/// at the same positions.
/// Works at any scale a double holds (see remeshing_min_extent): a mesh far from unit size is
/// remeshed as a copy scaled by a power of two, exactly, and scaled back; vertices that did not
/// move get their input positions back bit for bit.
/// Errors (mesh unchanged), all before any allocation but the last: errc::invalid_argument
/// for a target length that is not a finite positive number or would make more triangles than
/// options.max_faces or need more bytes than options.max_bytes (estimate_isotropic_remeshing,
/// named in the message), a feature angle outside [0, 180], a feature edge index out of
/// range; errc::unsupported for a vertex with a non-finite position or a face that is not a
/// triangle (named), and for a mesh at a scale it refuses (all vertices at one point, or beyond
/// remeshing_min_extent and remeshing_max_coordinate, named); errc::cancelled when
/// options.progress returns false.
/// Complexity O(iterations * (F log F_in)) for F faces at the end, F_in at the start (each
/// projection is a closest-point query, O(log F_in)); O(F + F_in) extra memory.
template <class M, class T = default_traits<M>>
    requires remeshable_mesh<M, T>
[[nodiscard]] result<isotropic_remeshing_result> isotropic_remeshing(M& mesh,
                                                                     const isotropic_remeshing_options& options);

/// The scales isotropic_remeshing works at. Its tests compare squared lengths, and its
/// closest-point projection multiplies four lengths together, which stays a normal double for
/// lengths in about [2^-240, 2^240]; a mesh whose extent (largest side of the bounding box of
/// its edges' ends) lies outside is remeshed as a copy scaled by a power of two (exact) into
/// that range and scaled back. What no scaling can help is refused: a mesh smaller than
/// remeshing_min_extent, about 1e-292, whose coordinates have too few bits left to place new
/// vertices between them (doubles below 2^-1022 lose precision), and a mesh with a coordinate
/// above remeshing_max_coordinate, about 1.1e307, where the points computed between and
/// around its vertices could exceed the largest double.
inline constexpr double remeshing_min_extent = 0x1p-970;
inline constexpr double remeshing_max_coordinate = 0x1p1020;

/// Roughly how many bytes a remeshing run needs per triangle, of the result and of the input:
/// the mesh, the rollback copy of the input and its aabb_tree, with room for a front end's
/// face-vertex copy of the output while it writes (about 190 bytes on halfedge_mesh, rounded up).
inline constexpr double remeshing_bytes_per_triangle = 256;

/// What remeshing a mesh at one target length is expected to make and need.
struct isotropic_remeshing_estimate {
    double triangles = 0;  ///< about how many triangles the result has: surface area over (sqrt(3)/4) L^2
    double bytes = 0;      ///< about the peak memory of the run (remeshing_bytes_per_triangle per triangle)
};

/// The edge length isotropic_remeshing aims at when the caller names none: the mean edge
/// length of the mesh (mean_edge_length(), computed without overflow or underflow at any
/// scale). A mesh without edges gives 1 (any length leaves it as it is).
/// Errors: errc::unsupported for a vertex with a non-finite position (named), for a mesh at a
/// scale isotropic_remeshing refuses (all vertices at one point, or beyond
/// remeshing_min_extent and remeshing_max_coordinate, named), and when every edge has length 0.
/// Complexity O(V + E).
template <class M, class T = default_traits<M>>
    requires remeshable_mesh<M, T>
[[nodiscard]] result<double> default_target_edge_length(const M& mesh);

/// Estimates the result of isotropic_remeshing(mesh, {.target_edge_length = L}) before any
/// allocation: the triangle count from the surface area (computed without underflow, never
/// NaN; +inf when out of range) and the bytes from the result's and the input's triangles.
/// Errors: errc::invalid_argument for a length that is not finite and positive;
/// errc::unsupported for a vertex with a non-finite position (named) and for a mesh at a scale
/// isotropic_remeshing refuses (all vertices at one point, or beyond remeshing_min_extent and
/// remeshing_max_coordinate, named).
/// Complexity O(F) for F faces; O(1) extra memory besides one face's corners.
template <class M, class T = default_traits<M>>
    requires remeshable_mesh<M, T>
[[nodiscard]] result<isotropic_remeshing_estimate> estimate_isotropic_remeshing(const M& mesh, double L);

}  // namespace hmira

// The machinery (scale and range checks, the remesher's passes) and the definitions.
#include "detail/isotropic_remeshing_impl.hpp"
