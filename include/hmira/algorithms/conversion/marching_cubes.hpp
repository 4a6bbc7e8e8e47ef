// hmira/algorithms/conversion/marching_cubes.hpp
// Extracts the iso-surface of a voxel map as a welded, closed, outward-oriented triangle mesh
// (thesis 2.3.3, 6.2): into any mesh that can add vertices and faces, or as an indexed
// triangle list. Parallel with oneTBB, with the same output for every thread count.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/progress.hpp"
#include "../../core/result.hpp"
#include "../../core/uninitialized_vector.hpp"
#include "../../core/vec3.hpp"
#include "../../grids/voxel_grid.hpp"

namespace hmira {

/// Which side of the iso value is the solid: scans (CT, MRI) are usually inside above it, distance fields below.
enum class iso_inside { below, above };
/// The sides' names: "below", "above" (see core/enum_names.hpp).
constexpr auto enum_names(iso_inside) {
    return std::array{std::pair{iso_inside::below, std::string_view("below")},
                      std::pair{iso_inside::above, std::string_view("above")}};
}

/// Options of marching_cubes() and marching_cubes_indexed().
struct marching_cubes_options {
    /// The iso value: finite, and within the samples' range [min, max] (else an error, since
    /// there would be no surface; scans are often inside above a positive iso, see `inside`).
    double iso = 0.0;
    /// Which side of `iso` is inside. Normals point from inside to outside.
    iso_inside inside = iso_inside::below;
    /// Also compute per-vertex normals from the field's gradient (central differences).
    bool normals = false;
    /// Worker threads (0: all available). The output does not depend on it.
    unsigned threads = 0;
    /// Called between z-slices of each of the three passes; returning false cancels the
    /// extraction (error errc::cancelled, "marching_cubes: cancelled").
    progress_function progress = {};
};

/// An indexed triangle list: triangle corners index `positions`; `normals` is empty unless asked for, else one
/// unit normal per position. The arrays are std::vectors whose resize() leaves new elements unwritten
/// (uninitialized_vector), so that the parallel writing pass is the first to touch the output.
template <class S = float>
struct indexed_triangles {
    uninitialized_vector<vec3<S>> positions;                       ///< one per vertex
    uninitialized_vector<std::array<std::uint32_t, 3>> triangles;  ///< vertex indices, counter-clockwise from outside
    uninitialized_vector<vec3<S>> normals;                         ///< empty, or one unit normal per vertex
};

/// What marching_cubes() added to the mesh: its vertices in creation order, its faces, and (when asked for)
/// one unit normal per vertex.
template <class M, class T = default_traits<M>>
struct marching_cubes_output {
    std::vector<typename T::vertex_handle> vertices;  ///< the new vertices, in creation order
    std::vector<typename T::face_handle> faces;       ///< the new triangles, in creation order
    std::vector<vec3<typename T::scalar>> normals;    ///< empty, or one unit normal per new vertex
};

/// Marching cubes of any voxel_grid into an indexed triangle list with positions of type S.
///
/// - One vertex per grid edge whose end samples lie on different sides, shared by the (up to four) cubes
///   around it: the output is welded. Its position interpolates the two samples linearly, kept at least
///   1/512 of the edge away from either, so that a sample equal to `iso` (which counts as inside) never makes
///   two vertices coincide or a triangle degenerate, even in 8-bit data.
/// - Ambiguous faces are decided by the asymptotic decider, the same way from both sides, so the output is a
///   closed, oriented 2-manifold whenever no inside sample lies on the grid's boundary layer; triangles wind
///   counter-clockwise seen from outside. A contour loop that cannot be triangulated without a chord along an
///   ambiguous face (some decisions of cases 10, 12, 13) is fanned around one extra vertex at its mean.
/// - Vertex order: sample rows in (z, y) order; in a row the crossed x-, then y-, then z-edges by increasing
///   x, then the extra vertices of that row's cubes. Triangles follow their cubes in (z, y, x) order.
///
/// \pre none beyond the errors below.
/// \post the order above, identical for every thread count and for builds without TBB.
/// Complexity: O(N) for N samples, in three parallel passes over z-slabs (classify into bit rows; count;
/// write): a compare per sample, a few word operations per cube except on the cubes the surface crosses.
/// Memory: N/8 bytes of bits. The passes stream the samples in memory order (bench/sweep).
/// Errors (invalid_argument): a dimension below 2, spacing not finite and positive, a non-finite iso; a NaN
/// or infinite sample ("marching_cubes: sample (3, 4, 5) is inf; every sample must be finite", the first in
/// (z, y, x) order, `element` its offset i + nx * (j + ny * k)); an iso outside the samples' range
/// ("marching_cubes: iso 0 is outside the samples' range [12, 3071], ..."), which gives no surface; the
/// range is read (one more pass) only when there is no surface, and an iso equal to min or max is accepted.
/// unsupported: more than 2^32 - 1 vertices. cancelled: the progress callback returned false.
template <class S = float, voxel_grid G>
result<indexed_triangles<S>> marching_cubes_indexed(const G& grid, const marching_cubes_options& options = {});

/// Marching cubes into `mesh`, which may already hold other elements: adds the surface's vertices and
/// triangles and returns them. Atomic: the surface is extracted in full (as marching_cubes_indexed(), with the
/// same order and errors) before the mesh is touched; if adding then fails (add_face refuses a triangle, the
/// callback cancels, anything throws), all that was added is erased before returning or rethrowing.
/// \pre none.
/// \post on success, the old elements unchanged plus the returned ones; on any error or exception, the same
/// live elements with the same handles, connectivity, positions and properties as before (index bounds and
/// garbage may grow), if the model can take elements back (halfedge_mutable_mesh, or face_removal_mesh and
/// vertex_removal_mesh; on OpenMesh the status bits erasing needs are requested first). On another
/// mesh_builder a failed add leaves what was added; an exception inside add_face leaves that face as it is.
/// Complexity: that of marching_cubes_indexed(), then O(V + F) serial builder calls. Progress: [0, 0.5] for
/// the extraction, [0.5, 1] for the insertion (about 64 calls). Errors: those of marching_cubes_indexed();
/// cancelled; the mesh's add_face error, naming the triangle.
template <class M, class T = default_traits<M>, voxel_grid G>
    requires mesh_builder<M, T>
result<marching_cubes_output<M, T>> marching_cubes(M& mesh, const G& grid, const marching_cubes_options& options = {});

}  // namespace hmira

#include "detail/marching_cubes_impl.hpp"
