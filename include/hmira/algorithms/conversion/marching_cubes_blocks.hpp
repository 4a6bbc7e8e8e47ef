// hmira/algorithms/conversion/marching_cubes_blocks.hpp
// Marching cubes of a grid too large for memory, one block at a time: each block's vertices
// carry a global key, and merge_blocks() welds the blocks into exactly the whole-grid mesh.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numeric>
#include <span>
#include <string>
#include <vector>

#include "../../core/result.hpp"
#include "../../core/vec3.hpp"
#include "../../grids/dense_grid.hpp"
#include "../../grids/voxel_grid.hpp"
#include "marching_cubes.hpp"

namespace hmira {

/// Where a block lies in the whole grid.
struct grid_block {
    grid_dims offset{0, 0, 0};  ///< global index of the block's sample (0, 0, 0)
    grid_dims whole{0, 0, 0};   ///< dimensions of the whole grid
};

/// Options of marching_cubes_block(): those of marching_cubes_options without normals (a
/// gradient at a block's border would need a second sample of overlap).
struct marching_cubes_block_options {
    double iso = 0.0;                           ///< the iso value; any finite value
    iso_inside inside = iso_inside::below;      ///< which side of `iso` is inside
    unsigned threads = 0;                       ///< worker threads (0: all); the output does not depend on it
};

/// One block's share of the surface. `keys[v]` names vertex v in the whole grid:
/// for the crossing on the edge from sample (i, j, k) along axis a (0, 1, 2), and for the
/// extra centre vertex of cube (i, j, k) with a = 3, key = ((k * ny + j) * 4 + a) * nx + i in
/// the whole grid's dimensions (nx, ny, nz). `cubes[t]` is the key (k * ny + j) * nx + i of the
/// cube that made triangle t. Neither depends on the chunking.
template <class S = float>
struct block_triangles {
    std::vector<vec3<S>> positions;                       ///< one per vertex, as the whole grid computes it
    std::vector<std::uint64_t> keys;                      ///< one global key per vertex, increasing
    std::vector<std::array<std::uint32_t, 3>> triangles;  ///< indices into positions, counter-clockwise seen from outside
    std::vector<std::uint64_t> cubes;                     ///< cube key of each triangle, non-decreasing
    grid_dims whole{0, 0, 0};                             ///< dimensions of the whole grid the keys refer to
};

/// The marching cubes of the cubes whose first sample lies in a block of a larger grid.
///
/// `block` holds the block's samples plus one sample of overlap on its high sides (none where
/// it reaches the end of the whole grid), with the whole grid's origin and spacing: sample
/// (i, j, k) of `block` is sample `where.offset + (i, j, k)` of the whole grid. Blocks whose
/// core ranges tile the grid, each given with that overlap, together contain every cube once.
/// Positions, triangles and decisions are computed exactly as marching_cubes_indexed() does
/// on the whole grid, so merge_blocks() of the blocks equals the whole-grid result. A block
/// with a dimension below 2 has no cubes and returns an empty result.
///
/// Complexity: O(N) for the block's N samples, as marching_cubes_indexed().
/// \pre none (checked: the block lies inside `where.whole`).
/// Errors (invalid_argument): the block does not fit in the whole grid at its offset; the
/// whole grid too large for 64-bit keys; those of marching_cubes_indexed(), prefixed with the
/// block's offset ("marching_cubes_block at (64, 0, 128): ...").
template <class S = float, voxel_grid G>
result<block_triangles<S>> marching_cubes_block(const G& block, const grid_block& where, const marching_cubes_block_options& options = {}) {
    const grid_dims d = block.dims();
    const std::string who = "marching_cubes_block at (" + std::to_string(where.offset[0]) + ", " +
                            std::to_string(where.offset[1]) + ", " + std::to_string(where.offset[2]) + ")";
    double whole_size = 4;
    for (int a = 0; a < 3; ++a) {
        if (where.offset[a] > where.whole[a] || d[a] > where.whole[a] - where.offset[a])
            return fail(errc::invalid_argument, who + ": a block of " + std::to_string(d[a]) + " samples along " +
                                                    std::string(1, "xyz"[a]) + " does not fit in the whole grid's " +
                                                    std::to_string(where.whole[a]));
        whole_size *= double(where.whole[a]);
    }
    if (whole_size >= 0x1p63) return fail(errc::invalid_argument, who + ": whole grid too large for 64-bit keys");
    block_triangles<S> out;
    if (d[0] < 2 || d[1] < 2 || d[2] < 2) return out;
    if (!std::isfinite(options.iso)) return fail(errc::invalid_argument, who + ": the iso value must be finite");
    if (auto ok = check_grid_geometry(geometry_of(block), "marching_cubes", 2); !ok)
        return fail(ok.error().code, who + ": " + ok.error().message);

    detail::mc::block_tags tags{where.offset, where.whole, &out.keys, &out.cubes};
    const marching_cubes_options mc{.iso = options.iso, .inside = options.inside, .threads = options.threads};
    result<indexed_triangles<S>> tri = fail(errc::invalid_argument, "");
    detail::with_thread_count(options.threads, [&] {
        detail::mc::extractor<G> ex(block, mc);
        ex.set_block(&tags);
        tri = ex.template run<S>();
    });
    if (!tri) return fail(tri.error().code, who + ": " + tri.error().message, tri.error().element);
    out.positions = std::move(tri->positions);
    out.triangles = std::move(tri->triangles);
    out.whole = where.whole;
    return out;
}

/// Welds blocks by key into one indexed triangle list.
///
/// When the blocks tile a grid (as marching_cubes_block() describes), the result equals
/// marching_cubes_indexed() of the whole grid element for element: the same vertices in the
/// same order with bit-identical positions, and the same triangles in the same order. The
/// blocks may come in any order.
///
/// How: a block's keys fall into runs, one per grid row (z, y) and axis, and its cube keys
/// into runs, one per row of cubes; runs of different blocks in one row do not interleave
/// (they cover different x ranges, or repeat the same samples), so sorting the runs, not the
/// elements, orders everything.
///
/// Complexity: O(V + T + R log R) for V block vertices, T triangles and R runs (R <= V + T,
/// typically far fewer); memory O(V + T).
/// \pre none (checked below).
/// Errors (invalid_argument): a block whose arrays disagree in length, whose keys do not
/// increase or cube keys decrease, whose triangle names a missing vertex, or whose whole-grid
/// dimensions differ from another block's; two blocks giving one key different positions; two
/// blocks holding the same cube (the blocks overlap); blocks that do not tile one grid;
/// unsupported: more than 2^32 - 1 vertices.
template <class S>
result<indexed_triangles<S>> merge_blocks(std::span<const block_triangles<S>> blocks) {
    std::size_t n_vertices = 0, n_triangles = 0;
    grid_dims whole{0, 0, 0};
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        const auto& blk = blocks[b];
        const std::string which = "merge_blocks: block " + std::to_string(b);
        if (blk.keys.size() != blk.positions.size() || blk.cubes.size() != blk.triangles.size())
            return fail(errc::invalid_argument, which + " has " + std::to_string(blk.positions.size()) + " positions, " +
                                                    std::to_string(blk.keys.size()) + " keys, " + std::to_string(blk.triangles.size()) +
                                                    " triangles and " + std::to_string(blk.cubes.size()) + " cube keys");
        if (blk.positions.empty() && blk.triangles.empty()) continue;
        if (whole == grid_dims{0, 0, 0}) whole = blk.whole;
        if (blk.whole != whole || whole[0] == 0)
            return fail(errc::invalid_argument, which + " refers to a whole grid of other dimensions than block 0's");
        for (std::size_t v = 1; v < blk.keys.size(); ++v)
            if (blk.keys[v] <= blk.keys[v - 1]) return fail(errc::invalid_argument, which + ": keys do not increase at vertex " + std::to_string(v));
        for (std::size_t t = 1; t < blk.cubes.size(); ++t)
            if (blk.cubes[t] < blk.cubes[t - 1]) return fail(errc::invalid_argument, which + ": cube keys decrease at triangle " + std::to_string(t));
        for (std::size_t t = 0; t < blk.triangles.size(); ++t)
            for (auto v : blk.triangles[t])
                if (v >= blk.positions.size())
                    return fail(errc::invalid_argument, which + " triangle " + std::to_string(t) + " names vertex " + std::to_string(v) +
                                                            " of " + std::to_string(blk.positions.size()));
        n_vertices += blk.positions.size();
        n_triangles += blk.triangles.size();
    }
    indexed_triangles<S> out;
    if (n_vertices == 0 && n_triangles == 0) return out;
    const std::uint64_t nx = whole[0];

    // One run per (block, row); sorted by row, then first key, then block.
    struct run {
        std::uint64_t row, first;
        std::uint32_t block;
        std::size_t begin, end;
    };
    auto runs_of = [&](auto member) {
        std::vector<run> runs;
        for (std::size_t b = 0; b < blocks.size(); ++b) {
            const std::vector<std::uint64_t>& k = blocks[b].*member;
            for (std::size_t v = 0; v < k.size();) {
                std::size_t e = v + 1;
                while (e < k.size() && k[e] / nx == k[v] / nx) ++e;
                runs.push_back({k[v] / nx, k[v], std::uint32_t(b), v, e});
                v = e;
            }
        }
        std::sort(runs.begin(), runs.end(), [](const run& a, const run& b) {
            return a.row != b.row ? a.row < b.row : a.first != b.first ? a.first < b.first : a.block < b.block;
        });
        return runs;
    };

    std::vector<std::vector<std::uint32_t>> global(blocks.size());
    for (std::size_t b = 0; b < blocks.size(); ++b) global[b].resize(blocks[b].keys.size());
    {
        const auto runs = runs_of(&block_triangles<S>::keys);
        out.positions.reserve(n_vertices);
        std::vector<std::uint64_t> row_keys;  // keys written so far in the current row, increasing
        std::size_t row_begin = 0;
        std::uint64_t row = ~std::uint64_t(0);
        for (const run& r : runs) {
            if (r.row != row) {
                row = r.row;
                row_keys.clear();
                row_begin = out.positions.size();
            }
            const auto& blk = blocks[r.block];
            for (std::size_t v = r.begin; v < r.end; ++v) {
                const std::uint64_t key = blk.keys[v];
                if (row_keys.empty() || key > row_keys.back()) {
                    if (out.positions.size() == std::numeric_limits<std::uint32_t>::max())
                        return fail(errc::unsupported, "merge_blocks: more than 2^32 - 1 vertices");
                    global[r.block][v] = std::uint32_t(out.positions.size());
                    out.positions.push_back(blk.positions[v]);
                    row_keys.push_back(key);
                    continue;
                }
                // A key another block already gave: the same vertex.
                const auto it = std::lower_bound(row_keys.begin(), row_keys.end(), key);
                if (it == row_keys.end() || *it != key)
                    return fail(errc::invalid_argument, "merge_blocks: the blocks do not tile one grid (vertex key " + std::to_string(key) +
                                                            " of block " + std::to_string(r.block) + " falls between another block's)");
                const std::size_t g = row_begin + std::size_t(it - row_keys.begin());
                if (std::memcmp(&out.positions[g], &blk.positions[v], sizeof(out.positions[g])) != 0)
                    return fail(errc::invalid_argument, "merge_blocks: two blocks give vertex key " + std::to_string(key) +
                                                            " different positions (block " + std::to_string(r.block) + ")");
                global[r.block][v] = std::uint32_t(g);
            }
        }
    }

    // Triangles in cube order, a cube's own triangles in table order.
    const auto runs = runs_of(&block_triangles<S>::cubes);
    out.triangles.reserve(n_triangles);
    std::uint64_t row = ~std::uint64_t(0), last_cube = 0;
    std::uint32_t last_block = 0;
    for (const run& r : runs) {
        const auto& blk = blocks[r.block];
        if (r.row == row && r.first <= last_cube)
            return fail(errc::invalid_argument, "merge_blocks: blocks " + std::to_string(last_block) + " and " + std::to_string(r.block) +
                                                    " both hold cube " + std::to_string(r.first) + " (the blocks overlap)");
        const auto& map = global[r.block];
        for (std::size_t t = r.begin; t < r.end; ++t) {
            const auto& tri = blk.triangles[t];
            out.triangles.push_back({map[tri[0]], map[tri[1]], map[tri[2]]});
        }
        row = r.row;
        last_cube = blk.cubes[r.end - 1];
        last_block = r.block;
    }
    return out;
}

/// The same for a std::vector of blocks.
template <class S>
result<indexed_triangles<S>> merge_blocks(const std::vector<block_triangles<S>>& blocks) {
    return merge_blocks(std::span<const block_triangles<S>>(blocks));
}

/// Marching cubes of a grid read a z-slab at a time, with a few slabs in memory at once.
///
/// `fetch(k0, count, samples)` fills the std::vector<T> `samples` with z-slices k0 ..
/// k0 + count - 1 of the whole grid (x fastest, `count * nx * ny` samples) and returns a
/// result<void>; its error is returned as is. Slabs of `slab_slices` cubes (at least 1) are
/// read with one slice of overlap, meshed by marching_cubes_block(), and welded on the fly:
/// the result equals marching_cubes_indexed() of the whole grid element for element.
///
/// Memory: one slab of samples (slab_slices + 1 slices of T), its bit rows, one slab's block
/// mesh and the output (sizeof(vec3<S>) per vertex, 12 bytes per triangle).
/// Complexity: O(N) for N samples, each slice but the slab borders read once.
/// \pre none. Errors: those of fetch and marching_cubes_block(); invalid_argument for a
/// geometry check_grid_geometry() refuses or a fetch that returns the wrong sample count.
template <class S = float, class T, class Fetch>
result<indexed_triangles<S>> marching_cubes_by_slabs(const grid_geometry& whole, std::size_t slab_slices, Fetch&& fetch,
                                                     const marching_cubes_block_options& options = {}) {
    if (auto ok = check_grid_geometry(whole, "marching_cubes_by_slabs", 2); !ok) return ok.error();
    slab_slices = std::max<std::size_t>(slab_slices, 1);
    const std::size_t nx = whole.dims[0], ny = whole.dims[1], nz = whole.dims[2];
    const std::uint64_t plane_keys = std::uint64_t(ny) * 4 * nx;  // keys per z-plane of rows
    indexed_triangles<S> out;
    std::vector<T> samples;
    // The previous slab: its triangles wait until the vertices on its top plane, which the
    // next slab emits (so that the vertex order is the whole grid's), have global indices.
    block_triangles<S> pending;
    std::size_t pending_base = 0, pending_emitted = 0;
    auto flush_pending = [&](const block_triangles<S>* next, std::size_t next_base) -> result<void> {
        for (const auto& t : pending.triangles) {
            std::array<std::uint32_t, 3> g;
            for (int c = 0; c < 3; ++c) {
                if (t[c] < pending_emitted) {
                    g[c] = std::uint32_t(pending_base + t[c]);
                    continue;
                }
                const std::uint64_t key = pending.keys[t[c]];
                if (!next) return fail(errc::invalid_argument, "marching_cubes_by_slabs: the last slab left a vertex unemitted");
                const auto it = std::lower_bound(next->keys.begin(), next->keys.end(), key);
                if (it == next->keys.end() || *it != key)
                    return fail(errc::invalid_argument, "marching_cubes_by_slabs: vertex key " + std::to_string(key) +
                                                            " missing from the next slab (fetch returned different samples?)");
                g[c] = std::uint32_t(next_base + std::size_t(it - next->keys.begin()));
            }
            out.triangles.push_back(g);
        }
        pending = {};
        return {};
    };
    for (std::size_t k0 = 0; k0 + 1 < nz; k0 += slab_slices) {
        const std::size_t count = std::min(slab_slices + 1, nz - k0);
        samples.clear();
        if (auto r = fetch(k0, count, samples); !r) return r.error();
        if (samples.size() != count * nx * ny)
            return fail(errc::invalid_argument, "marching_cubes_by_slabs: fetch gave " + std::to_string(samples.size()) + " samples for " +
                                                    std::to_string(count) + " slices of " + std::to_string(nx) + " x " + std::to_string(ny));
        auto view = make_grid_view(std::span<const T>(samples), {{nx, ny, count}, whole.origin, whole.spacing});
        if (!view) return view.error();
        auto blk = marching_cubes_block<S>(*view, {.offset = {0, 0, k0}, .whole = whole.dims}, options);
        if (!blk) return blk.error();
        // Vertices on the top plane belong to the next slab's rows, unless this is the last.
        const bool last = k0 + count == nz;
        const std::uint64_t top = std::uint64_t(k0 + count - 1) * plane_keys;
        const std::size_t emitted =
            last ? blk->keys.size() : std::size_t(std::lower_bound(blk->keys.begin(), blk->keys.end(), top) - blk->keys.begin());
        const std::size_t base = out.positions.size();
        if (base + emitted > std::numeric_limits<std::uint32_t>::max())
            return fail(errc::unsupported, "marching_cubes_by_slabs: more than 2^32 - 1 vertices");
        if (auto r = flush_pending(&*blk, base); !r) return r.error();
        out.positions.insert(out.positions.end(), blk->positions.begin(), blk->positions.begin() + std::ptrdiff_t(emitted));
        pending = std::move(*blk);
        pending_base = base;
        pending_emitted = emitted;
    }
    if (auto r = flush_pending(nullptr, 0); !r) return r.error();
    return out;
}

}  // namespace hmira
