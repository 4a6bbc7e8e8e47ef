// hmira/algorithms/decimation/decimate.hpp
// Quadric error decimation (Garland-Heckbert): edges collapse cheapest first, the cost being
// the squared distance of the new vertex to the planes of the faces it stands for.
#pragma once

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "../../core/progress.hpp"
#include "../../core/result.hpp"
#include "../triangle/triangle_common.hpp"

namespace hmira {

/// Options of decimate. Set at least one of the three targets; with several, it stops at the first reached.
struct decimate_options {
    /// Stop once the mesh has at most this many faces.
    std::optional<std::size_t> target_faces = std::nullopt;
    /// Stop once the mesh has at most this fraction of its (triangulated) faces, in [0, 1].
    std::optional<double> target_ratio = std::nullopt;
    /// Stop before a collapse whose error exceeds this distance in model units (the root of the summed squared
    /// distances to the planes the new vertex stands for, an upper bound of its distance to each of them).
    std::optional<double> max_error = std::nullopt;
    /// Boundary vertices never move and boundary edges never collapse. When false, boundary edges collapse
    /// too, held near their place by planes through them perpendicular to their face.
    bool keep_boundary = true;
    /// Refuse a collapse that turns a remaining face's normal by more than this (degrees, [0, 180]); a face that
    /// would degenerate is always refused. Above 90, so that coarse targets may still turn faces on thin parts.
    double max_normal_angle = 120;
    /// Refuse a collapse making a face with an aspect ratio (longest edge over the height onto it, 1 for an
    /// equilateral triangle) above this unless it was worse. At least 1; infinity (the default): off.
    double max_aspect_ratio = std::numeric_limits<double>::infinity();
    /// Refuse a collapse making a face with an angle under this (degrees, [0, 60]) unless it was worse; 0: off.
    double min_angle = 1;
    /// Vertex indices (T::vertex_index) that neither move nor disappear.
    std::vector<std::size_t> locked_vertices = {};
    /// Weight each face's plane by its area over the mean face area (a large flat face holds the surface as
    /// firmly as the many small faces of a detailed part); false: every plane counts once.
    bool area_weighted = true;
    /// Edges whose two triangles' normals differ by more than this (degrees, [0, 180]) are feature edges.
    std::optional<double> feature_angle = std::nullopt;
    /// More feature edges, by edge index. A feature edge adds to its ends' quadrics the planes through it
    /// perpendicular to its two faces, weighted like them, so that collapses keep the crease in place.
    std::vector<std::size_t> feature_edges = {};
    /// Feature lines keep their shape: a vertex where other than two feature edges meet never moves, one
    /// inside a line moves only onto its neighbour along it, and no other edge joins two feature vertices.
    bool keep_features = false;
    /// Called between blocks of collapses with the fraction done; returning false cancels (errc::cancelled,
    /// "decimate: cancelled") and restores the mesh from a copy (mesh_rollback) made only when one is given.
    progress_function progress = {};
    /// Starting quadrics replacing the planes of faces and edges, 10 finite numbers per vertex index (a_xx a_xy a_xz
    /// a_yy a_yz a_zz b_x b_y b_z c of x^T A x + 2 b.x + c); a run's decimate_result::quadrics given here go on.
    std::vector<double> start_quadrics = {};
    bool return_quadrics = false;  ///< fill decimate_result::quadrics
};
/// Why decimate stopped.
enum class decimate_stop {
    target_faces,  ///< the face target (target_faces or target_ratio) was reached
    max_error,     ///< the cheapest remaining collapse exceeds max_error
    constraints,   ///< no remaining collapse satisfies the constraints and the topology rules
};
/// What decimate did.
struct decimate_result {
    std::size_t faces = 0;                                   ///< faces after
    std::size_t vertices = 0;                                ///< vertices after
    std::size_t collapses = 0;                               ///< edges collapsed
    bool triangulated = false;                               ///< polygon input was triangulated first
    decimate_stop stopped_by = decimate_stop::target_faces;  ///< which condition ended it
    double error = 0;                   ///< the largest error (a distance, see max_error) of a collapse made
    std::string note;                   ///< in words: the triangulation, and why a face target was missed
    std::vector<double> quadrics = {};  ///< return_quadrics: each vertex index's, as start_quadrics (0 if removed)
};
/// A mesh decimate can run on: triangle operators, dense vertex and edge indices (polygons: Euler operators).
template <class M, class T = default_traits<M>>
concept decimatable_mesh = triangle_operable_mesh<M, T> && vertex_index_mesh<M, T> && edge_index_mesh<M, T>;
/// Quadric error decimation (Garland and Heckbert 1997): every edge is queued at the error of its best
/// collapse point (the point that minimises the summed squared distances to the planes of the faces merged
/// into its ends; the best of the two ends and the midpoint when those planes do not pin a point), and the
/// cheapest edge collapses (collapse_edge) until a target is reached; the survivor's edges are re-queued. A
/// collapse refused by the link condition or the options leaves the queue until its neighbourhood changes.
/// Polygon input is triangulated first (the note says so). Deterministic: ties broken by edge index.
///
/// \pre every vertex position is finite.
/// \post the faces are triangles; faces <= the face target when stopped_by is target_faces (one fewer at
///       most: an interior collapse removes two faces). Genus and boundary loops are kept (the link
///       condition); with keep_boundary the boundary vertices keep their positions. Locked vertices keep
///       their handles and positions bit for bit; with keep_features every vertex on a feature line has the
///       position of an input vertex on one. Removed elements are erased the model's way (not compacted).
/// Errors (mesh unchanged): errc::invalid_argument naming the option for no target, a NaN or out-of-range
/// option, a locked vertex or feature edge index out of range, or a non-finite position (naming the vertex);
/// errc::unsupported for polygon input on a model that cannot triangulate (triangles only is fine);
/// errc::cancelled for a cancellation ("decimate: cancelled"); the errors of triangulate_faces.
/// Complexity O(V + E + F) to set up plus O(E log E) to queue every edge; each collapse then costs O(d^2)
/// for the checks and the refused neighbours (d the valence around it) and O(d log E) for the queue
/// updates; plus O(V + E + F) for the copy a progress callback needs (core/rollback.hpp). Memory: 80 bytes of
/// quadric and 1 byte of flags per vertex, about 30 bytes per edge. Cache behaviour: detail/decimate_impl.hpp.
template <class M, class T = default_traits<M>>
    requires decimatable_mesh<M, T>
[[nodiscard]] result<decimate_result> decimate(M& mesh, const decimate_options& options);

}  // namespace hmira

// The machinery (the decimator and the definition of decimate) is kept apart from the interface.
#include "detail/decimate_impl.hpp"
