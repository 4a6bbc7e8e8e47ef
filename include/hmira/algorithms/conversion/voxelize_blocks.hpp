// hmira/algorithms/conversion/voxelize_blocks.hpp
// Voxelization of a grid too large for memory, one block at a time: the triangles
// are binned to the blocks they touch, each block is filled on its own, and the parity of the
// inside fill is carried into a block from the crossings before it, so every block holds
// exactly the bits voxelize() gives there on the whole grid.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "voxelize.hpp"

namespace hmira {

/// A box of voxels of a larger grid: voxels lo[a] <= i < lo[a] + dims[a] along each axis a.
struct voxel_block {
    std::array<std::size_t, 3> lo{};  ///< first voxel of the block in the whole grid
    grid_dims dims{};                 ///< voxels of the block along x, y, z
};

namespace detail::vox {

inline result<void> check_block(const grid_geometry& grid, const voxel_block& block) {
    static constexpr const char* axis = "xyz";
    for (int a = 0; a < 3; ++a)
        if (block.dims[a] == 0 || block.lo[a] >= grid.dims[a] || block.dims[a] > grid.dims[a] - block.lo[a])
            return fail(errc::invalid_argument, "voxelize_block: block [" + std::to_string(block.lo[a]) + ", " +
                                                    std::to_string(block.lo[a] + block.dims[a]) + ") along " +
                                                    std::string(1, axis[a]) + " is empty or outside the grid's " +
                                                    std::to_string(grid.dims[a]) + " voxels");
    return {};
}

/// The geometry of `block` within `grid`.
inline grid_geometry block_geometry(const grid_geometry& grid, const voxel_block& block) {
    grid_geometry g = grid;
    g.dims = block.dims;
    for (int a = 0; a < 3; ++a) g.origin[a] = grid.origin[a] + double(block.lo[a]) * grid.spacing[a];
    return g;
}

/// Voxelizes one block from gathered triangles and its bins; null bins mean every triangle.
inline result<voxelization> fill_block(const gathered& g, const grid_geometry& grid, const voxel_block& block,
                                       const std::vector<std::uint32_t>* surface,
                                       const std::vector<std::uint32_t>* crossing, const voxelize_options& options) {
    voxelization out{bit_grid::unwritten(block_geometry(grid, block)), false, {}, g.tris.size(), g.degenerate};
    auto job = plan(options, g.closed, out.note, out.filled);
    if (!job) return job.error();
    const std::array<long long, 3> lo{static_cast<long long>(block.lo[0]), static_cast<long long>(block.lo[1]),
                                      static_cast<long long>(block.lo[2])};
    if (!fill_window(g.tris, surface, crossing, lo, out.voxels, *job, options.threads, options.progress))
        return fail(errc::cancelled, "voxelize: cancelled");
    return out;
}

}  // namespace detail::vox

/// The voxels of one block of the grid `grid`: bit for bit what voxelize(mesh, grid, options)
/// sets inside the block, for every mode, without the rest of the grid. The returned grid has
/// the block's geometry (its voxel (0, 0, 0) is voxel block.lo of `grid`). Each block is
/// independent, so blocks can be computed anywhere in any order (hmira.dask.voxelize does).
/// One exception: open_mesh_fill::winding_number decides each run of empty voxels along x by
/// the winding number at its first voxel, which in a block is the block's first voxel when the
/// run starts before it; wherever the winding number does not change along a run (a closed
/// part of the mesh), the result is the same.
///
/// Complexity: O(F) to read the mesh, plus voxelize()'s costs restricted to the block: the
/// surface voxels of the triangles near it and the crossings of the triangles whose shadow
/// meets its rows and that start before its end along x.
/// Errors: those of voxelize(); invalid_argument for a block that is empty or not inside the
/// grid.
template <class M, class T = default_traits<M>>
    requires voxelize_mesh<M, T>
result<voxelization> voxelize_block(const M& mesh, const grid_geometry& grid, const voxel_block& block,
                                    const voxelize_options& options = {}) {
    if (auto ok = check_grid_geometry(grid, "voxelize"); !ok) return ok.error();
    if (auto ok = detail::vox::check_block(grid, block); !ok) return ok.error();
    auto g = detail::vox::gather<M, T>(mesh, grid, options.allow_degenerate);
    if (!g) return g.error();
    // Bins for this block alone: triangles whose box (widened by half a voxel) meets the
    // block, and triangles whose shadow meets its rows and that begin before its end.
    std::vector<std::uint32_t> surface, crossing;
    const double bl[3] = {double(block.lo[0]), double(block.lo[1]), double(block.lo[2])};
    const double bh[3] = {bl[0] + double(block.dims[0]) - 1, bl[1] + double(block.dims[1]) - 1,
                          bl[2] + double(block.dims[2]) - 1};
    for (std::size_t t = 0; t < g->tris.size(); ++t) {
        const auto& tr = g->tris[t];
        double lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min({tr.p[0][a], tr.p[1][a], tr.p[2][a]});
            hi[a] = std::max({tr.p[0][a], tr.p[1][a], tr.p[2][a]});
        }
        bool near = true;
        for (int a = 0; a < 3; ++a) near &= lo[a] - 1 <= bh[a] && hi[a] + 1 >= bl[a];
        if (near) surface.push_back(static_cast<std::uint32_t>(t));
        if (lo[0] - 1 <= bh[0] && lo[1] - 1 <= bh[1] && hi[1] + 1 >= bl[1] && lo[2] - 1 <= bh[2] && hi[2] + 1 >= bl[2])
            crossing.push_back(static_cast<std::uint32_t>(t));
    }
    return detail::vox::fill_block(*g, grid, block, &surface, &crossing, options);
}

/// Voxelizes the whole grid block by block, blocks of `block_size` voxels (smaller at the
/// grid's far ends), and hands each to on_block(const voxel_block&, voxelization&&), in order
/// x fastest, then y, then z; on_block returns false to stop early. The mesh is read once and
/// its triangles binned once: to every block their box meets (surface voxels) and to every
/// row of blocks along x their shadow meets (crossings; a block uses those that begin before
/// its end). Together the blocks equal voxelize(mesh, grid, options), voxel for voxel, with the
/// winding-number caveat of voxelize_block(). Memory: one block's bits plus the bins.
///
/// Complexity: O(F + sum over triangles of the blocks they touch) for the bins, plus per
/// block what voxelize_block() costs. Errors: those of voxelize(); invalid_argument for a zero
/// block size. Nothing is handed over after an error.
template <class M, class T = default_traits<M>, class OnBlock>
    requires voxelize_mesh<M, T>
result<void> voxelize_blocks(const M& mesh, const grid_geometry& grid, const grid_dims& block_size,
                             const voxelize_options& options, OnBlock&& on_block) {
    if (auto ok = check_grid_geometry(grid, "voxelize"); !ok) return ok.error();
    if (block_size[0] == 0 || block_size[1] == 0 || block_size[2] == 0)
        return fail(errc::invalid_argument, "voxelize_blocks: the block size must be at least 1 along every axis");
    auto g = detail::vox::gather<M, T>(mesh, grid, options.allow_degenerate);
    if (!g) return g.error();
    std::size_t nb[3];
    for (int a = 0; a < 3; ++a) nb[a] = (grid.dims[a] + block_size[a] - 1) / block_size[a];
    // The block index range [b0, b1] along axis a of voxel coordinates [lo, hi], clamped.
    auto block_range = [&](int a, double lo, double hi, long long& b0, long long& b1) {
        const double bs = double(block_size[a]);
        b0 = std::max<long long>(0, static_cast<long long>(std::floor(lo / bs)));
        b1 = std::min<long long>(static_cast<long long>(nb[a]) - 1, static_cast<long long>(std::floor(hi / bs)));
        return b0 <= b1;
    };
    std::vector<std::vector<std::uint32_t>> surface(nb[0] * nb[1] * nb[2]), crossing(nb[1] * nb[2]);
    for (std::size_t t = 0; t < g->tris.size(); ++t) {
        const auto& tr = g->tris[t];
        double lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min({tr.p[0][a], tr.p[1][a], tr.p[2][a]}) - 1;
            hi[a] = std::max({tr.p[0][a], tr.p[1][a], tr.p[2][a]}) + 1;
        }
        long long b0[3], b1[3];
        if (!block_range(1, lo[1], hi[1], b0[1], b1[1]) || !block_range(2, lo[2], hi[2], b0[2], b1[2])) continue;
        for (long long bz = b0[2]; bz <= b1[2]; ++bz)
            for (long long by = b0[1]; by <= b1[1]; ++by)
                crossing[std::size_t(bz) * nb[1] + std::size_t(by)].push_back(static_cast<std::uint32_t>(t));
        if (!block_range(0, lo[0], hi[0], b0[0], b1[0])) continue;
        for (long long bz = b0[2]; bz <= b1[2]; ++bz)
            for (long long by = b0[1]; by <= b1[1]; ++by)
                for (long long bx = b0[0]; bx <= b1[0]; ++bx)
                    surface[(std::size_t(bz) * nb[1] + std::size_t(by)) * nb[0] + std::size_t(bx)].push_back(
                        static_cast<std::uint32_t>(t));
    }
    for (std::size_t bz = 0; bz < nb[2]; ++bz)
        for (std::size_t by = 0; by < nb[1]; ++by)
            for (std::size_t bx = 0; bx < nb[0]; ++bx) {
                voxel_block block;
                const std::size_t b[3] = {bx, by, bz};
                for (int a = 0; a < 3; ++a) {
                    block.lo[a] = b[a] * block_size[a];
                    block.dims[a] = std::min(block_size[a], grid.dims[a] - block.lo[a]);
                }
                auto v = detail::vox::fill_block(*g, grid, block, &surface[(bz * nb[1] + by) * nb[0] + bx],
                                                 &crossing[bz * nb[1] + by], options);
                if (!v) return v.error();
                if (!on_block(static_cast<const voxel_block&>(block), std::move(*v))) return {};
            }
    return {};
}

}  // namespace hmira
