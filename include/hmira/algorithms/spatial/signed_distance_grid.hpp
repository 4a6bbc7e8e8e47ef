// hmira/algorithms/spatial/signed_distance_grid.hpp
// Volumes from meshes: the signed distance sampled on a grid (full, or exact only in a narrow
// band about the surface), and the offset surface at distance d extracted from it by
// marching cubes.
#pragma once

#include <cstddef>
#include <limits>

#include "../../concepts.hpp"
#include "../../core/result.hpp"
#include "../../grids/dense_grid.hpp"
#include "../../grids/voxel_grid.hpp"
#include "../conversion/marching_cubes.hpp"
#include "signed_distance.hpp"

namespace hmira {

/// Options of signed_distance_grid.
struct signed_distance_grid_options {
    /// Samples farther than this from the surface hold +-band instead of their distance (the
    /// closest-point search stops there); infinity: the full field.
    double band = std::numeric_limits<double>::infinity();
    sign_mode sign = sign_mode::winding_number;  ///< how the inside is decided (signed_distance)
    double beta = 2.0;                           ///< the fast winding number's accuracy
    unsigned threads = 0;                        ///< worker threads (0: all); the grid does not depend on it
};

/// Options of offset.
struct offset_options {
    std::size_t resolution = 128;  ///< grid samples along the longest side of the enlarged bounding box
    double beta = 2.0;             ///< the fast winding number's accuracy
    unsigned threads = 0;          ///< worker threads (0: all); the output does not depend on it
};

/// The signed distance to `mesh` (signed_distance, negative inside) at every sample of a grid
/// of geometry `g`, as values of type V.
/// \pre none. \post sample (i, j, k) holds the signed distance at g.position(i, j, k), clamped
///   to [-band, band]; the same grid for every thread count.
/// Errors: those of check_grid_geometry ("signed_distance_grid: ..."), of signed_distance, and
///   errc::invalid_argument for a band that is not positive.
/// Complexity: O(F log F + N (log F)) for N samples, parallel over rows of samples.
template <class V = float, class M, class T = default_traits<M>>
    requires surface_query_mesh<M, T>
[[nodiscard]] result<dense_grid<V>> signed_distance_grid(const M& mesh, const grid_geometry& g,
                                                         const signed_distance_grid_options& options = {});

/// The surface at signed distance d from `mesh` (outside for d > 0, inside for d < 0): the
/// signed distance on a grid over the mesh's bounding box enlarged by |d| plus three samples,
/// in a narrow band of |d| plus three samples, then marching cubes at iso d (welded, closed,
/// wound outward).
/// \pre none. \post the vertices lie within the grid's interpolation error (about one spacing)
///   of distance d from the surface.
/// Errors: those of signed_distance_grid; errc::invalid_argument for a non-finite d or a
///   resolution below 8; marching_cubes' error when no sample lies at distance d (an inset
///   deeper than the shape is thick).
/// Complexity: O(F log F + N log F) for N = O(resolution^3) samples, then marching cubes' O(N).
template <class M, class T = default_traits<M>>
    requires surface_query_mesh<M, T>
[[nodiscard]] result<indexed_triangles<double>> offset(const M& mesh, double d, const offset_options& options = {});

/// signed_distance_grid and offset over a triangle_set.
///@{
template <class V = float>
[[nodiscard]] result<dense_grid<V>> signed_distance_grid(const triangle_set& surface, const grid_geometry& g,
                                                         const signed_distance_grid_options& options = {});
[[nodiscard]] inline result<indexed_triangles<double>> offset(const triangle_set& surface, double d,
                                                              const offset_options& options = {});
///@}

}  // namespace hmira

#include "detail/signed_distance_grid_impl.hpp"
