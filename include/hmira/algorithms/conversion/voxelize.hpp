// hmira/algorithms/conversion/voxelize.hpp
// Turns a mesh into voxels (thesis 2.3.2, 8.4): the voxels its surface touches, and for a
// closed mesh also the voxels inside it. Generic over the mesh; parallel and deterministic.
// The machinery is in detail/voxelize_impl.hpp.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/progress.hpp"
#include "../../core/result.hpp"
#include "../../grids/bit_grid.hpp"
#include "../../grids/voxel_grid.hpp"

namespace hmira {

/// Which voxels voxelize() sets. Pick `centres` to measure volume or to match VTK's
/// vtkPolyDataToImageStencil and scikit-image (the count times pitch^3 is the enclosed volume
/// up to the sampling error); `solid` (the CLI's "conservative") for collision and for a grid
/// that covers the whole shape; `surface` for a shell.
enum class voxelize_mode {
    surface,  ///< the voxels the surface touches (their closed box meets a triangle)
    solid,    ///< surface voxels plus every voxel whose centre lies inside (conservative)
    centres,  ///< exactly the voxels whose centre lies inside the closed mesh
};

/// The modes' names, as the front ends accept them: "conservative" (solid), "centres",
/// "surface" (see core/enum_names.hpp).
constexpr auto enum_names(voxelize_mode) {
    return std::array{std::pair{voxelize_mode::solid, std::string_view("conservative")},
                      std::pair{voxelize_mode::centres, std::string_view("centres")},
                      std::pair{voxelize_mode::surface, std::string_view("surface")}};
}

/// What the solid and centres modes do with a mesh that is not closed (some edge has an odd number of faces).
enum class open_mesh_fill {
    surface_only,    ///< voxelize the surface only and say so in the result (the thesis's choice)
    winding_number,  ///< fill where the generalized winding number is at least 1/2
    fail,            ///< return an error
};

/// Options of voxelize() and voxelize_into().
struct voxelize_options {
    voxelize_mode mode = voxelize_mode::solid;  ///< which voxels to set
    open_mesh_fill open_mesh =
        open_mesh_fill::surface_only;  ///< what the filling modes do with a mesh that is not closed
    /// Accept zero-area triangles (all corners collinear) instead of reporting them; they add
    /// no surface voxels of their own. Faces with a repeated vertex are always an error.
    bool allow_degenerate = false;
    unsigned threads = 0;  ///< worker threads (0: all available); the output does not depend on it
    /// Called between blocks of triangles and of rows; returning false cancels the
    /// voxelization (error errc::cancelled, "voxelize: cancelled").
    progress_function progress = {};
};

/// The voxels, and how they were made.
struct voxelization {
    bit_grid voxels;  ///< the set voxels, on the requested grid
    /// True when the interior was filled (solid or centres mode on a closed mesh, or by winding number).
    bool filled = false;
    std::string note;                      ///< empty, or why a filling mode did otherwise (an open mesh)
    std::size_t triangles = 0;             ///< triangles voxelized (polygons are fanned)
    std::size_t degenerate_triangles = 0;  ///< zero-area triangles met (allowed by the options)
};

/// A mesh voxelize() reads: its faces' vertices, their positions and indices (to name a bad vertex).
template <class M, class T = default_traits<M>>
concept voxelize_mesh = face_vertex_range_mesh<M, T> && positioned_mesh<M, T> && vertex_index_mesh<M, T>;

/// Voxelizes `mesh` into a bit grid of geometry `grid` (sample (i, j, k) = centre of voxel
/// (i, j, k), voxel = the box of one spacing around it). Polygons are fanned into triangles.
/// - Surface voxels (modes surface and solid): every voxel whose closed box meets a triangle,
///   by a separating-axis test in floating point whose intervals are widened past its
///   rounding: no voxel the triangle touches is lost, a single touching corner included; a
///   voxel it misses by less than about 1e-13 of its size (more for a sliver) may be set too.
/// - Inside voxels (modes solid and centres) on a closed mesh (every edge used by an even
///   number of faces, checked by an XOR of edge hashes): every voxel whose centre lies inside,
///   by the parity of the crossings of a ray along x, decided by exact predicates (orient2d
///   for which triangles a ray crosses, orient3d for which side of the crossing a centre lies)
///   with a symbolic perturbation of the centre by (eps, eps^2, eps^3): rays through edges and
///   vertices count once, and a centre exactly on the surface is inside where the surface
///   faces -x. On a mesh that is not closed, see voxelize_options::open_mesh.
/// - Parallel over slabs of z-layers (about 1 MiB of bits each, one thread per slab, the
///   triangles binned to the slabs they reach): the output is the same for every thread count.
/// \pre none: everything is checked. Errors (nothing returned but the error): invalid_argument
///   for an unusable grid or a non-finite position; degenerate_face for a face with fewer than
///   3 vertices or a repeated vertex, or a zero-area triangle unless allow_degenerate; topology
///   for an open mesh with open_mesh = fail; cancelled when `progress` says so.
/// \post voxels has the geometry of `grid`; `mesh` is only read.
/// Complexity: O(F + sum over triangles of the slabs they reach + the voxels in their bounding
/// box) for the surface, plus O(N/64 + sum over triangles of the rays their shadow covers and
/// the rows it spans) for the fill; the winding-number fill costs O(F) per run of empty voxels.
template <class M, class T = default_traits<M>>
    requires voxelize_mesh<M, T>
result<voxelization> voxelize(const M& mesh, const grid_geometry& grid, const voxelize_options& options = {});

/// Same voxels, written into any writable voxel grid of the wanted geometry (1 for a set
/// voxel, 0 elsewhere). \pre none. \post on error `grid` is untouched. Errors: those of
/// voxelize(). Complexity: voxelize()'s plus O(N) writes.
template <class M, class T = default_traits<M>, writable_voxel_grid G>
    requires voxelize_mesh<M, T>
result<voxelization> voxelize_into(const M& mesh, G& grid, const voxelize_options& options = {});

/// A grid of cubic voxels around the mesh's bounding box: `resolution` voxels along its longest
/// side plus `padding` voxels on every side; sample (i, j, k) is voxel (i, j, k)'s centre.
/// Voxels whose closed box touches the surface are set, so a surface lying exactly on the
/// bounding box (a cube's faces) also sets the first padding layer: with padding >= 2 (the
/// default) at least one layer on every side stays empty, which marching cubes needs to close
/// the surface it extracts.
/// Errors: invalid_argument for resolution 0 or a mesh without vertices or with non-finite
/// positions; unsupported for a mesh spanning more than the largest double. O(V).
template <class M, class T = default_traits<M>>
    requires positioned_mesh<M, T>
result<grid_geometry> voxel_grid_around(const M& mesh, std::size_t resolution, std::size_t padding = 2);

/// About how many bytes voxelize() holds at its peak on `grid` for a mesh of `triangles`
/// triangles (polygons fanned): the grid's bits (whole 64-bit words per row, every voxel of
/// the grid, padding included) plus its copy of the triangles and their slab bins (at most
/// 96 bytes per triangle for the grids voxel_grid_around() makes). Callers compare it with
/// the memory they can spare before asking for a large grid: the bits are allocated
/// untouched (each slab clears its own), so an allocation the system cannot back may only
/// fail much later. O(1); saturates at the largest std::uint64_t.
inline std::uint64_t voxelize_memory_estimate(const grid_geometry& grid, std::size_t triangles);

}  // namespace hmira

#include "detail/voxelize_impl.hpp"
