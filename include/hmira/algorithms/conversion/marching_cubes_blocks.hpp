// hmira/algorithms/conversion/marching_cubes_blocks.hpp
// Marching cubes of a grid too large for memory: marching_cubes_by_slabs() reads it a z-slab at a time;
// marching_cubes_block() meshes one block with a global key per vertex, and merge_blocks() welds the
// blocks into exactly the whole-grid mesh. Every path gives marching_cubes_indexed()'s result bit for bit.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "../../core/result.hpp"
#include "../../core/uninitialized_vector.hpp"
#include "../../core/vec3.hpp"
#include "../../grids/voxel_grid.hpp"
#include "marching_cubes.hpp"

namespace hmira {

/// Where a block lies in the whole grid.
struct grid_block {
    grid_dims offset{0, 0, 0};  ///< global index of the block's sample (0, 0, 0)
    grid_dims whole{0, 0, 0};   ///< dimensions of the whole grid
};

/// Options of marching_cubes_block() and marching_cubes_by_slabs(): those of marching_cubes_options without
/// normals (a gradient at a block's border would need a second sample of overlap).
struct marching_cubes_block_options {
    double iso = 0.0;                       ///< the iso value; any finite value
    iso_inside inside = iso_inside::below;  ///< which side of `iso` is inside
    unsigned threads = 0;                   ///< worker threads (0: all); the output does not depend on it
};

/// Options of merge_blocks().
struct merge_blocks_options {
    unsigned threads = 0;  ///< worker threads (0: all); the result does not depend on it
};

/// One block's share of the surface. `keys[v]` names vertex v in the whole grid of dimensions (nx, ny, nz):
/// key = ((k * ny + j) * 4 + a) * nx + i for the crossing on the edge from sample (i, j, k) along axis a
/// (0, 1, 2), and a = 3 for the extra centre vertex of cube (i, j, k). `cubes[t]` is the key
/// (k * ny + j) * nx + i of the cube that made triangle t. Neither depends on the chunking.
template <class S = float>
struct block_triangles {
    uninitialized_vector<vec3<S>> positions;                       ///< one per vertex, as the whole grid computes it
    std::vector<std::uint64_t> keys;                               ///< one global key per vertex, increasing
    uninitialized_vector<std::array<std::uint32_t, 3>> triangles;  ///< into positions, counter-clockwise from outside
    std::vector<std::uint64_t> cubes;                              ///< cube key of each triangle, non-decreasing
    grid_dims whole{0, 0, 0};                                      ///< dimensions of the whole grid the keys refer to
    grid_dims offset{0, 0, 0};                                     ///< global index of the block's sample (0, 0, 0)
    grid_dims size{0, 0, 0};                                       ///< the block's samples per axis, overlap included
};

/// Marching cubes of a grid read a z-slab at a time, with a few slabs in memory at once.
///
/// `fetch(k0, count, samples)` fills the std::vector<T> `samples` with z-slices k0 .. k0 + count - 1 of the
/// whole grid (x fastest, `count * nx * ny` samples) and returns a result<void>. Slabs of `slab_slices` cubes
/// (at least 1) are read with one slice of overlap, meshed by marching_cubes_block() and welded on the fly.
/// \pre none.
/// \post the result equals marching_cubes_indexed() of the whole grid element for element.
/// Complexity: O(N) for N samples, each slice but the slab borders read once. Memory: one slab of samples
/// (slab_slices + 1 slices of T), its bit rows, one slab's block mesh, and the output.
/// Errors: fetch's, as is; those of marching_cubes_block() (a non-finite sample is named by its index in the
/// whole grid); invalid_argument for a geometry check_grid_geometry() refuses, a fetch giving the wrong sample
/// count, and, after the last slab, an iso outside the samples' range when there is no surface (as
/// marching_cubes_indexed(); the range is read only from the slabs met while the result is still empty).
template <class S = float, class T, class Fetch>
result<indexed_triangles<S>> marching_cubes_by_slabs(const grid_geometry& whole, std::size_t slab_slices, Fetch&& fetch,
                                                     const marching_cubes_block_options& options = {});

/// The marching cubes of the cubes whose first sample lies in a block of a larger grid.
///
/// `block` holds the block's samples plus one sample of overlap on its high sides (none where it reaches the
/// end of the whole grid), with the whole grid's origin and spacing: sample (i, j, k) of `block` is sample
/// `where.offset + (i, j, k)` of the whole grid. Blocks whose core ranges tile the grid, each given with that
/// overlap, together contain every cube once. A block with a dimension below 2 has no cubes.
/// \pre none (checked: the block lies inside `where.whole`).
/// \post positions, triangles and decisions are those marching_cubes_indexed() computes on the whole grid,
/// so merge_blocks() of the blocks equals the whole-grid result.
/// Complexity: O(N) for the block's N samples, as marching_cubes_indexed().
/// Errors (invalid_argument): the block does not fit in the whole grid at its offset; the whole grid too
/// large for 64-bit keys; those of marching_cubes_indexed(), prefixed with the block's offset
/// ("marching_cubes_block at (64, 0, 128): marching_cubes: sample (70, 3, 130) is inf; ...", indices in the
/// whole grid), except the iso range: a block may well lie on one side of the surface, so only a caller that
/// sees every block can tell an iso outside the whole grid's range (marching_cubes_by_slabs() does; hmira.dask
/// does it in Python).
template <class S = float, voxel_grid G>
result<block_triangles<S>> marching_cubes_block(const G& block, const grid_block& where,
                                                const marching_cubes_block_options& options = {});

/// What merge_blocks() reads of one block: the arrays of a block_triangles, seen in place, so
/// blocks held elsewhere (numpy arrays, a mapped file) merge without a copy. view_of() makes
/// one from a block_triangles; the arrays must outlive the merge.
template <class S>
struct block_triangles_view {
    std::span<const vec3<S>> positions;                       ///< as block_triangles::positions
    std::span<const std::uint64_t> keys;                      ///< as block_triangles::keys
    std::span<const std::array<std::uint32_t, 3>> triangles;  ///< as block_triangles::triangles
    std::span<const std::uint64_t> cubes;                     ///< as block_triangles::cubes
    grid_dims offset{0, 0, 0};                                ///< as block_triangles::offset
    grid_dims size{0, 0, 0};                                  ///< as block_triangles::size
    grid_dims whole{0, 0, 0};                                 ///< as block_triangles::whole
};

/// A view of `block`'s arrays (valid while `block` is alive and unchanged).
template <class S>
block_triangles_view<S> view_of(const block_triangles<S>& block) noexcept {
    return {block.positions, block.keys, block.triangles, block.cubes, block.offset, block.size, block.whole};
}

/// Where merge_blocks_into() writes the merged mesh: storage the caller provides once the
/// counts are known, every element of which the merge overwrites.
template <class S>
struct merged_storage {
    std::span<vec3<S>> positions;                       ///< exactly the merged vertex count
    std::span<std::array<std::uint32_t, 3>> triangles;  ///< exactly the merged triangle count
};

/// Welds blocks by key into one indexed triangle list, written into storage that
/// `allocate(n_vertices, n_triangles)` returns (a merged_storage<S> of exactly those sizes; called once,
/// after the blocks' own arrays and their tiling are checked).
///
/// When the blocks tile a grid (as marching_cubes_block() describes: one block per chunk of a chunking of the
/// grid, each with its one-sample overlap, including the empty blocks of chunks too thin for cubes), the
/// result equals marching_cubes_indexed() of the whole grid element for element: the same vertices in the
/// same order with bit-identical positions, and the same triangles in the same order. The blocks may come in
/// any order.
///
/// How: every vertex is owned by one block, the one whose chunk holds the sample its key names (see
/// detail::mc_merge::axis_tiling for the last sample), so the vertices a block owns are copied without any
/// lookup; only the vertices on a block's high faces, which a neighbour owns, are looked up (a binary search
/// in the neighbour's run of that row and axis) and checked bit for bit. Counting each block's vertices and
/// triangles per row, a prefix sum in the whole grid's row order, then writing, puts everything in place.
///
/// \pre none (every condition under Errors is checked).
/// \post on error, the storage (if it was allocated) holds unspecified values.
/// Complexity: O(V + T + R + H log V_r) for V block vertices, T triangles, R sample rows of all blocks, H
/// vertices on inner chunk faces and V_r vertices per row; memory 12 bytes per row and axis of every block,
/// 4 per block vertex, besides the output. Parallel over blocks and over z-slices with oneTBB.
/// Errors (invalid_argument): a block whose arrays disagree in length, whose keys do not increase or cube
/// keys decrease, whose triangle names a missing vertex, whose vertices or cubes lie outside its samples, or
/// whose whole-grid dimensions differ from another block's; blocks that do not tile one grid (a chunk without
/// a block, a block of the wrong size); two blocks at one offset (the blocks overlap); two blocks giving one
/// key different positions, or a key missing from the block that owns it; unsupported: more than 2^32 - 1
/// vertices. The allocator's error is returned as is.
template <class S, class Allocate>
result<void> merge_blocks_into(std::span<const block_triangles_view<S>> blocks, Allocate&& allocate,
                               const merge_blocks_options& options = {});

/// Welds blocks by key into one indexed triangle list: merge_blocks_into() with the result's own arrays as
/// the storage. Same result, rules, errors and complexity.
template <class S>
result<indexed_triangles<S>> merge_blocks(std::span<const block_triangles_view<S>> blocks,
                                          const merge_blocks_options& options = {});

/// The same for blocks held as block_triangles.
template <class S>
result<indexed_triangles<S>> merge_blocks(std::span<const block_triangles<S>> blocks,
                                          const merge_blocks_options& options = {});

/// The same for a std::vector of blocks.
template <class S>
result<indexed_triangles<S>> merge_blocks(const std::vector<block_triangles<S>>& blocks,
                                          const merge_blocks_options& options = {});

}  // namespace hmira

#include "detail/marching_cubes_blocks_impl.hpp"
