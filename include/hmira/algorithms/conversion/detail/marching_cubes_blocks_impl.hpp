// hmira/algorithms/conversion/detail/marching_cubes_blocks_impl.hpp
// The definitions of marching_cubes_blocks.hpp's entry points, and the passes of merge_blocks_into()
// (detail::mc_merge). Included at the end of marching_cubes_blocks.hpp.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "../../../grids/dense_grid.hpp"
#include "marching_cubes_direct.hpp"
#include "marching_cubes_extractor.hpp"
#include "parallel.hpp"

namespace hmira {

namespace detail::mc_merge {

/// The chunking of one axis, recovered from the blocks' offsets, and which chunk's block owns
/// the vertices of each sample index: the chunk holding it, except that the last sample
/// belongs to the chunk holding the one before it (a last chunk one sample thick has no cubes,
/// so its block is empty and the block before reaches that sample through its overlap).
struct axis_tiling {
    std::vector<std::size_t> starts;          // chunk starts, increasing from 0
    std::vector<std::uint32_t> owner;         // per sample index: its owning chunk
    std::vector<std::size_t> own_lo, own_hi;  // per chunk: the sample indices it owns, [lo, hi)
};

/// One block's place in the merge: which of its vertices and triangles go where.
struct block_plan {
    std::array<std::size_t, 3> lo{}, hi{};  // owned sample indices per axis, [lo, hi)
    std::size_t rows_y = 0;                 // hi[1] - lo[1]
    // Per owned row (z, y) and axis a, at ((k - lo[2]) * rows_y + (j - lo[1])) * 4 + a: the
    // block's owned vertices there (first index, count) and their first global index.
    std::vector<std::uint32_t> vertex_begin, vertex_count, vertex_start;
    // Per owned cube row, at (k - lo[2]) * rows_y + (j - lo[1]): the same for its triangles.
    std::vector<std::uint32_t> cube_begin, cube_count, cube_start;
    std::size_t at(std::size_t j, std::size_t k) const noexcept { return (k - lo[2]) * rows_y + (j - lo[1]); }
    bool owns_row(std::size_t j, std::size_t k) const noexcept {
        return j >= lo[1] && j < hi[1] && k >= lo[2] && k < hi[2];
    }
};

/// Calls f(j, k, axis, base, begin, end) for each run of `keys` on one sample row (j, k) and
/// axis (keys base + i), walking the rows of a block at `o` of `e` samples in key order:
/// [begin, end) holds the keys of that row and axis, all inside the block (a centre vertex's
/// cube too). No division per key or run. Returns the index of the first key outside the
/// block, or keys.size() when none is.
template <class F>
std::size_t for_each_vertex_run(std::span<const std::uint64_t> keys, const grid_dims& whole, const grid_dims& o,
                                const grid_dims& e, const F& f) {
    const std::uint64_t nx = whole[0], ny = whole[1];
    std::size_t v = 0;
    for (std::size_t k = o[2]; k < o[2] + e[2] && v < keys.size(); ++k)
        for (std::size_t j = o[1]; j < o[1] + e[1] && v < keys.size(); ++j)
            for (std::size_t a = 0; a < 4; ++a) {
                const std::uint64_t base = ((std::uint64_t(k) * ny + j) * 4 + a) * nx;
                const bool cube_row = j + 1 < o[1] + e[1] && k + 1 < o[2] + e[2];
                const std::uint64_t lo = base + o[0], hi = a < 3 ? lo + e[0] : cube_row ? lo + e[0] - 1 : lo;
                if (v < keys.size() && keys[v] < lo) return v;
                std::size_t end = v;
                while (end < keys.size() && keys[end] < hi) ++end;
                if (end > v) f(j, k, a, base, v, end);
                v = end;
            }
    return v;
}

/// The same for the cube keys of a block's triangles, one run per cube row (j, k).
template <class F>
std::size_t for_each_cube_run(std::span<const std::uint64_t> cubes, const grid_dims& whole, const grid_dims& o,
                              const grid_dims& e, const F& f) {
    const std::uint64_t nx = whole[0], ny = whole[1];
    std::size_t t = 0;
    for (std::size_t k = o[2]; k + 1 < o[2] + e[2] && t < cubes.size(); ++k)
        for (std::size_t j = o[1]; j + 1 < o[1] + e[1] && t < cubes.size(); ++j) {
            const std::uint64_t lo = (std::uint64_t(k) * ny + j) * nx + o[0], hi = lo + e[0] - 1;
            if (cubes[t] < lo) return t;
            std::size_t end = t;
            while (end < cubes.size() && cubes[end] < hi) ++end;
            if (end > t) f(j, k, t, end);
            t = end;
        }
    return t;
}

/// Calls body(b) for every block in parallel; the first error in block order, or an empty string.
template <class F>
std::string for_each_block(std::size_t blocks, unsigned threads, const F& body) {
    std::vector<std::string> errors(blocks);
    detail::with_thread_count(threads, [&] {
        detail::parallel_chunks(blocks, 1, [&](std::size_t b0, std::size_t b1) {
            for (std::size_t b = b0; b < b1; ++b) errors[b] = body(b);
        });
    });
    for (const auto& e : errors)
        if (!e.empty()) return e;
    return std::string();
}

/// Checks each block's arrays on their own: lengths that agree, the same whole grid as block 0, a vertex
/// count that fits 32-bit indices, and samples inside the whole grid.
template <class S>
result<void> check_views(std::span<const block_triangles_view<S>> blocks, const grid_dims& whole) {
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        const auto& blk = blocks[b];
        const std::string which = "merge_blocks: block " + std::to_string(b);
        if (blk.keys.size() != blk.positions.size() || blk.cubes.size() != blk.triangles.size())
            return fail(errc::invalid_argument, which + " has " + std::to_string(blk.positions.size()) +
                                                    " positions, " + std::to_string(blk.keys.size()) + " keys, " +
                                                    std::to_string(blk.triangles.size()) + " triangles and " +
                                                    std::to_string(blk.cubes.size()) + " cube keys");
        if (blk.whole != whole)
            return fail(errc::invalid_argument, which + " refers to a whole grid of other dimensions than block 0's");
        if (blk.positions.size() >= std::numeric_limits<std::uint32_t>::max())
            return fail(errc::unsupported, which + " has more than 2^32 - 2 vertices");
        for (int a = 0; a < 3; ++a)
            if (blk.offset[a] >= whole[a] || blk.size[a] == 0 || blk.size[a] > whole[a] - blk.offset[a])
                return fail(errc::invalid_argument, which + ": " + std::to_string(blk.size[a]) + " samples at " +
                                                        std::to_string(blk.offset[a]) + " along " +
                                                        std::string(1, "xyz"[a]) + " do not fit in the whole grid's " +
                                                        std::to_string(whole[a]));
    }
    return {};
}

/// The chunking of each axis, from the blocks' offsets, with each sample's owning chunk.
template <class S>
result<std::array<axis_tiling, 3>> tile_axes(std::span<const block_triangles_view<S>> blocks, const grid_dims& whole) {
    std::array<axis_tiling, 3> tiling;
    for (int a = 0; a < 3; ++a) {
        auto& t = tiling[a];
        for (const auto& blk : blocks) t.starts.push_back(blk.offset[a]);
        std::sort(t.starts.begin(), t.starts.end());
        t.starts.erase(std::unique(t.starts.begin(), t.starts.end()), t.starts.end());
        if (t.starts[0] != 0)
            return fail(errc::invalid_argument,
                        "merge_blocks: the blocks do not tile one grid (no block starts at 0 along " +
                            std::string(1, "xyz"[a]) + ")");
        const std::size_t n = whole[a], chunks = t.starts.size();
        t.owner.resize(n);
        t.own_lo.assign(chunks, 0);
        t.own_hi.assign(chunks, 0);
        for (std::size_t c = 0, s = 0; s < n; ++s) {
            while (c + 1 < chunks && t.starts[c + 1] <= std::min(s, n - 2)) ++c;
            t.owner[s] = std::uint32_t(c);
        }
        for (std::size_t s = n; s-- > 0;) t.own_lo[t.owner[s]] = s;
        for (std::size_t s = 0; s < n; ++s) t.own_hi[t.owner[s]] = s + 1;
    }
    return tiling;
}

/// Which block fills each chunk cell of the tiling, and which cell each block fills.
struct block_cells {
    static constexpr std::uint32_t no_block = std::numeric_limits<std::uint32_t>::max();
    std::size_t mx = 0, my = 0, mz = 0;               // chunks per axis
    std::vector<std::uint32_t> cell_block;            // per cell, at (z * my + y) * mx + x: its block
    std::vector<std::array<std::size_t, 3>> cell_of;  // per block: its cell
};

/// Places every block in its chunk cell: each cell must hold exactly one block, of the chunk's size plus
/// the overlap.
template <class S>
result<block_cells> place_blocks(std::span<const block_triangles_view<S>> blocks,
                                 const std::array<axis_tiling, 3>& tiling, const grid_dims& whole) {
    block_cells out;
    const std::size_t mx = tiling[0].starts.size(), my = tiling[1].starts.size(), mz = tiling[2].starts.size();
    out.mx = mx;
    out.my = my;
    out.mz = mz;
    // Each block fills one chunk cell, so more cells than blocks leave one empty.
    if (double(mx) * double(my) * double(mz) > double(blocks.size()))
        return fail(errc::invalid_argument, "merge_blocks: the blocks do not tile one grid (" +
                                                std::to_string(blocks.size()) + " blocks for " + std::to_string(mx) +
                                                " x " + std::to_string(my) + " x " + std::to_string(mz) + " chunks)");
    out.cell_block.assign(mx * my * mz, block_cells::no_block);
    out.cell_of.resize(blocks.size());
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        std::array<std::size_t, 3> c{};
        for (int a = 0; a < 3; ++a) {
            const auto& st = tiling[a].starts;
            c[a] = std::size_t(std::lower_bound(st.begin(), st.end(), blocks[b].offset[a]) - st.begin());
            const std::size_t want = c[a] + 1 < st.size() ? st[c[a] + 1] - st[c[a]] + 1 : whole[a] - st[c[a]];
            if (blocks[b].size[a] != want)
                return fail(errc::invalid_argument,
                            "merge_blocks: the blocks do not tile one grid (block " + std::to_string(b) + " has " +
                                std::to_string(blocks[b].size[a]) + " samples along " + std::string(1, "xyz"[a]) +
                                " where its chunk and overlap have " + std::to_string(want) + ")");
        }
        auto& slot = out.cell_block[(c[2] * my + c[1]) * mx + c[0]];
        if (slot != block_cells::no_block)
            return fail(errc::invalid_argument, "merge_blocks: blocks " + std::to_string(slot) + " and " +
                                                    std::to_string(b) + " both start at (" +
                                                    std::to_string(blocks[b].offset[0]) + ", " +
                                                    std::to_string(blocks[b].offset[1]) + ", " +
                                                    std::to_string(blocks[b].offset[2]) + ") (the blocks overlap)");
        slot = std::uint32_t(b);
        out.cell_of[b] = c;
    }
    for (std::size_t c = 0; c < out.cell_block.size(); ++c)
        if (out.cell_block[c] == block_cells::no_block)
            return fail(errc::invalid_argument, "merge_blocks: the blocks do not tile one grid (no block starts at (" +
                                                    std::to_string(tiling[0].starts[c % mx]) + ", " +
                                                    std::to_string(tiling[1].starts[c / mx % my]) + ", " +
                                                    std::to_string(tiling[2].starts[c / mx / my]) + "))");
    return out;
}

/// Pass 1 for block `b` in chunk cell `cell`: checks the order of its keys and cube keys, and counts its
/// owned vertices and its triangles per row into `p`. An error message, or an empty string.
template <class S>
std::string plan_block(const block_triangles_view<S>& blk, std::size_t b, const std::array<axis_tiling, 3>& tiling,
                       const std::array<std::size_t, 3>& cell, const grid_dims& whole, block_plan& p) {
    const std::string which = "merge_blocks: block " + std::to_string(b);
    for (int a = 0; a < 3; ++a) {
        p.lo[a] = tiling[a].own_lo[cell[a]];
        p.hi[a] = std::max(p.lo[a], tiling[a].own_hi[cell[a]]);
    }
    p.rows_y = p.hi[1] - p.lo[1];
    const std::size_t rows = p.rows_y * (p.hi[2] - p.lo[2]);
    p.vertex_begin.assign(4 * rows, 0);
    p.vertex_count.assign(4 * rows, 0);
    p.vertex_start.resize(4 * rows);
    p.cube_begin.assign(rows, 0);
    p.cube_count.assign(rows, 0);
    p.cube_start.resize(rows);
    const auto keys = blk.keys;
    for (std::size_t v = 1; v < keys.size(); ++v)
        if (keys[v] <= keys[v - 1]) return which + ": keys do not increase at vertex " + std::to_string(v);
    const std::uint64_t own_x = p.hi[0];
    const std::size_t outside = for_each_vertex_run(
        keys, whole, blk.offset, blk.size,
        [&](std::size_t j, std::size_t k, std::size_t a, std::uint64_t row_base, std::size_t v, std::size_t end) {
            if (!p.owns_row(j, k)) return;
            std::size_t owned_end = v;
            while (owned_end < end && keys[owned_end] < row_base + own_x) ++owned_end;
            p.vertex_begin[4 * p.at(j, k) + a] = std::uint32_t(v);
            p.vertex_count[4 * p.at(j, k) + a] = std::uint32_t(owned_end - v);
        });
    if (outside < keys.size())
        return which + ": vertex " + std::to_string(outside) + " (key " + std::to_string(keys[outside]) +
               ") lies outside the block";
    const auto cubes = blk.cubes;
    for (std::size_t t = 1; t < cubes.size(); ++t)
        if (cubes[t] < cubes[t - 1]) return which + ": cube keys decrease at triangle " + std::to_string(t);
    // The block's cubes are those whose first sample lies in its chunk: with the tiling checked, their rows
    // are owned rows.
    const std::size_t stray = for_each_cube_run(cubes, whole, blk.offset, blk.size,
                                                [&](std::size_t j, std::size_t k, std::size_t t, std::size_t end) {
                                                    p.cube_begin[p.at(j, k)] = std::uint32_t(t);
                                                    p.cube_count[p.at(j, k)] = std::uint32_t(end - t);
                                                });
    if (stray < cubes.size())
        return which + ": triangle " + std::to_string(stray) + " (cube key " + std::to_string(cubes[stray]) +
               ") lies outside the block";
    return {};
}

/// Pass 2: the global start of every block's runs, in the whole grid's order: rows (z, y); in a row, the
/// axes, and for each axis the chunks along x; triangles by cube row, then chunk along x. Each z-slice is
/// summed in parallel, the slices' totals prefix-summed, then each slice swept again to assign. Returns the
/// merged vertex and triangle counts.
inline result<std::pair<std::uint64_t, std::uint64_t>> assign_starts(std::vector<block_plan>& plans,
                                                                     const block_cells& cells,
                                                                     const std::array<axis_tiling, 3>& tiling,
                                                                     const grid_dims& whole, unsigned threads) {
    const std::size_t ny = whole[1], nz = whole[2], mx = cells.mx, my = cells.my;
    std::vector<std::uint64_t> slice_vertices(nz + 1, 0), slice_triangles(nz + 1, 0);
    auto sweep = [&](std::size_t k, bool assign, std::uint64_t vertex_at, std::uint64_t triangle_at) {
        const std::size_t bz = tiling[2].owner[k];
        for (std::size_t j = 0; j < ny; ++j) {
            const std::uint32_t* row_blocks = &cells.cell_block[(bz * my + tiling[1].owner[j]) * mx];
            for (std::size_t a = 0; a < 4; ++a)
                for (std::size_t bx = 0; bx < mx; ++bx) {
                    auto& p = plans[row_blocks[bx]];
                    const std::size_t at = 4 * p.at(j, k) + a;
                    if (assign) p.vertex_start[at] = std::uint32_t(vertex_at);
                    vertex_at += p.vertex_count[at];
                }
            if (j + 1 < ny && k + 1 < nz)
                for (std::size_t bx = 0; bx < mx; ++bx) {
                    auto& p = plans[row_blocks[bx]];
                    if (assign) p.cube_start[p.at(j, k)] = std::uint32_t(triangle_at);
                    triangle_at += p.cube_count[p.at(j, k)];
                }
        }
        return std::pair{vertex_at, triangle_at};
    };
    detail::with_thread_count(threads, [&] {
        detail::parallel_chunks(nz, 8, [&](std::size_t k0, std::size_t k1) {
            for (std::size_t k = k0; k < k1; ++k)
                std::tie(slice_vertices[k + 1], slice_triangles[k + 1]) = sweep(k, false, 0, 0);
        });
    });
    for (std::size_t k = 0; k < nz; ++k) {
        slice_vertices[k + 1] += slice_vertices[k];
        slice_triangles[k + 1] += slice_triangles[k];
    }
    if (slice_vertices[nz] > std::numeric_limits<std::uint32_t>::max())
        return fail(errc::unsupported, "merge_blocks: more than 2^32 - 1 vertices");
    detail::with_thread_count(threads, [&] {
        detail::parallel_chunks(nz, 8, [&](std::size_t k0, std::size_t k1) {
            for (std::size_t k = k0; k < k1; ++k) sweep(k, true, slice_vertices[k], slice_triangles[k]);
        });
    });
    return std::pair{slice_vertices[nz], slice_triangles[nz]};
}

/// What pass 3 reads besides the block it writes: every block, its plan, and the tiling.
template <class S>
struct merge_context {
    std::span<const block_triangles_view<S>> blocks;
    const std::vector<block_plan>& plans;
    const block_cells& cells;
    const std::array<axis_tiling, 3>& tiling;
    grid_dims whole;
};

/// Pass 3, vertices of block `b`: copies its owned vertices to their places in `positions`, and looks up the
/// others in the blocks that own them, checking that both give the same position bit for bit. Sets
/// global[v] to the merged index of its vertex v. An error message, or an empty string.
template <class S>
std::string place_block_vertices(const merge_context<S>& m, std::size_t b, std::span<vec3<S>> positions,
                                 std::uint32_t* global) {
    const auto& blk = m.blocks[b];
    const auto& p = m.plans[b];
    const auto keys = blk.keys;
    const std::size_t mx = m.cells.mx, my = m.cells.my;
    std::string error;
    for_each_vertex_run(
        keys, m.whole, blk.offset, blk.size,
        [&](std::size_t j, std::size_t k, std::size_t a, std::uint64_t row_base, std::size_t v, std::size_t end) {
            if (!error.empty()) return;
            std::size_t q = v;
            if (p.owns_row(j, k)) {
                const std::size_t at = 4 * p.at(j, k) + a;
                const std::uint32_t start = p.vertex_start[at];
                for (const std::size_t owned_end = v + p.vertex_count[at]; q < owned_end; ++q) {
                    global[q] = std::uint32_t(start + (q - v));
                    positions[global[q]] = blk.positions[q];
                }
            }
            // The rest lie on a neighbour's chunk: find each in the owner's run.
            const std::size_t jo = m.tiling[1].owner[j], ko = m.tiling[2].owner[k];
            for (; q < end; ++q) {
                const std::uint32_t owner =
                    m.cells.cell_block[(ko * my + jo) * mx + m.tiling[0].owner[std::size_t(keys[q] - row_base)]];
                const auto& op = m.plans[owner];
                const std::size_t at = 4 * op.at(j, k) + a;
                const auto theirs = m.blocks[owner].keys;
                const auto run = theirs.begin() + op.vertex_begin[at];
                const auto it = std::lower_bound(run, run + op.vertex_count[at], keys[q]);
                if (owner == b || it == run + op.vertex_count[at] || *it != keys[q]) {
                    error = "merge_blocks: the blocks do not tile one grid (vertex key " + std::to_string(keys[q]) +
                            " of block " + std::to_string(b) + " is missing from block " + std::to_string(owner) +
                            ", which owns it)";
                    return;
                }
                const std::size_t w = std::size_t(it - theirs.begin());
                if (std::memcmp(&m.blocks[owner].positions[w], &blk.positions[q], sizeof(vec3<S>)) != 0) {
                    error = "merge_blocks: blocks " + std::to_string(b) + " and " + std::to_string(owner) +
                            " give vertex key " + std::to_string(keys[q]) + " different positions";
                    return;
                }
                global[q] = op.vertex_start[at] + std::uint32_t(w - op.vertex_begin[at]);
            }
        });
    return error;
}

/// Pass 3, triangles of block `b`: writes them at their places in `triangles`, through the merged vertex
/// indices `global`. An error message (a triangle naming a missing vertex), or an empty string.
template <class S>
std::string place_block_triangles(const merge_context<S>& m, std::size_t b,
                                  std::span<std::array<std::uint32_t, 3>> triangles, const std::uint32_t* global) {
    const auto& blk = m.blocks[b];
    const auto& p = m.plans[b];
    const std::size_t nv = blk.keys.size();
    for (std::size_t r = 0; r < p.cube_count.size(); ++r) {
        const std::size_t t0 = p.cube_begin[r], n = p.cube_count[r];
        auto* dst = triangles.data() + p.cube_start[r];
        for (std::size_t t = 0; t < n; ++t) {
            const auto& tri = blk.triangles[t0 + t];
            if (tri[0] >= nv || tri[1] >= nv || tri[2] >= nv) {
                const auto bad = tri[0] >= nv ? tri[0] : tri[1] >= nv ? tri[1] : tri[2];
                return "merge_blocks: block " + std::to_string(b) + " triangle " + std::to_string(t0 + t) +
                       " names vertex " + std::to_string(bad) + " of " + std::to_string(nv);
            }
            dst[t] = {global[tri[0]], global[tri[1]], global[tri[2]]};
        }
    }
    return {};
}

/// Pass 3 for block `b`: its vertices, then its triangles, into `out`.
template <class S>
std::string write_merged_block(const merge_context<S>& m, std::size_t b, const merged_storage<S>& out) {
    // Uninitialised on purpose: every entry is written by place_block_vertices() before it is read.
    const std::unique_ptr<std::uint32_t[]> global(new std::uint32_t[m.blocks[b].keys.size()]);
    if (auto error = place_block_vertices(m, b, out.positions, global.get()); !error.empty()) return error;
    return place_block_triangles(m, b, out.triangles, global.get());
}

}  // namespace detail::mc_merge

template <class S, voxel_grid G>
result<block_triangles<S>> marching_cubes_block(const G& block, const grid_block& where,
                                                const marching_cubes_block_options& options) {
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
    out.whole = where.whole;
    out.offset = where.offset;
    out.size = d;
    if (d[0] < 2 || d[1] < 2 || d[2] < 2) return out;
    if (!std::isfinite(options.iso)) return fail(errc::invalid_argument, who + ": the iso value must be finite");
    if (auto ok = check_grid_geometry(geometry_of(block), "marching_cubes", 2); !ok)
        return fail(ok.error().code, who + ": " + ok.error().message);

    detail::mc::block_tags tags{where.offset, where.whole, &out.keys, &out.cubes, nullptr, false};
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
    return out;
}

template <class S, class Allocate>
result<void> merge_blocks_into(std::span<const block_triangles_view<S>> blocks, Allocate&& allocate,
                               const merge_blocks_options& options) {
    namespace mm = detail::mc_merge;
    if (blocks.empty()) {
        auto none = allocate(std::size_t(0), std::size_t(0));
        if (!none) return none.error();
        return {};
    }
    const grid_dims whole = blocks[0].whole;
    if (auto ok = mm::check_views(blocks, whole); !ok) return ok.error();
    const std::size_t nx = whole[0], ny = whole[1], nz = whole[2];
    if (double(nx) * double(ny) * double(nz) * 4 >= 0x1p63)
        return fail(errc::invalid_argument, "merge_blocks: whole grid too large for 64-bit keys");
    if (nx < 2 || ny < 2 || nz < 2) {
        // No cubes anywhere: every block is empty.
        for (std::size_t b = 0; b < blocks.size(); ++b)
            if (!blocks[b].keys.empty() || !blocks[b].cubes.empty())
                return fail(errc::invalid_argument,
                            "merge_blocks: block " + std::to_string(b) + " has vertices in a grid too thin for cubes");
        auto none = allocate(std::size_t(0), std::size_t(0));
        if (!none) return none.error();
        return {};
    }
    const auto tiling = mm::tile_axes(blocks, whole);
    if (!tiling) return tiling.error();
    const auto cells = mm::place_blocks(blocks, *tiling, whole);
    if (!cells) return cells.error();

    // Pass 1, per block: check its arrays; count its owned vertices and its triangles per row.
    std::vector<mm::block_plan> plans(blocks.size());
    const std::string planned = mm::for_each_block(blocks.size(), options.threads, [&](std::size_t b) {
        return mm::plan_block(blocks[b], b, *tiling, cells->cell_of[b], whole, plans[b]);
    });
    if (!planned.empty()) return fail(errc::invalid_argument, planned);

    // Pass 2: every run's global start, and the merged counts.
    const auto counts = mm::assign_starts(plans, *cells, *tiling, whole, options.threads);
    if (!counts) return counts.error();
    const auto [vertices, triangles] = *counts;
    auto storage = allocate(std::size_t(vertices), std::size_t(triangles));
    if (!storage) return storage.error();
    const merged_storage<S> out = *storage;
    if (out.positions.size() != vertices || out.triangles.size() != triangles)
        return fail(errc::invalid_argument, "merge_blocks: the allocator returned storage of the wrong size");

    // Pass 3, per block: copy its owned vertices in place, look up the others in the blocks that own them,
    // then write its triangles in place.
    const mm::merge_context<S> context{blocks, plans, *cells, *tiling, whole};
    const std::string written = mm::for_each_block(
        blocks.size(), options.threads, [&](std::size_t b) { return mm::write_merged_block(context, b, out); });
    if (!written.empty()) return fail(errc::invalid_argument, written);
    return {};
}

template <class S>
result<indexed_triangles<S>> merge_blocks(std::span<const block_triangles_view<S>> blocks,
                                          const merge_blocks_options& options) {
    indexed_triangles<S> out;
    auto allocate = [&](std::size_t vertices, std::size_t triangles) -> result<merged_storage<S>> {
        // Zeroed, as std::vector would: a slot that blocks which do not tile one grid might
        // leave unwritten then reads as 0, not as whatever the memory held.
        out.positions.resize(vertices, vec3<S>{});
        out.triangles.resize(triangles, std::array<std::uint32_t, 3>{});
        return merged_storage<S>{out.positions, out.triangles};
    };
    if (auto ok = merge_blocks_into(blocks, allocate, options); !ok) return ok.error();
    return out;
}

template <class S>
result<indexed_triangles<S>> merge_blocks(std::span<const block_triangles<S>> blocks,
                                          const merge_blocks_options& options) {
    std::vector<block_triangles_view<S>> views;
    views.reserve(blocks.size());
    for (const auto& b : blocks) views.push_back(view_of(b));
    return merge_blocks(std::span<const block_triangles_view<S>>(views), options);
}

template <class S>
result<indexed_triangles<S>> merge_blocks(const std::vector<block_triangles<S>>& blocks,
                                          const merge_blocks_options& options) {
    return merge_blocks(std::span<const block_triangles<S>>(blocks), options);
}

template <class S, class T, class Fetch>
result<indexed_triangles<S>> marching_cubes_by_slabs(const grid_geometry& whole, std::size_t slab_slices, Fetch&& fetch,
                                                     const marching_cubes_block_options& options) {
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
                if (!next)
                    return fail(errc::invalid_argument,
                                "marching_cubes_by_slabs: the last slab left a vertex unemitted");
                const auto it = std::lower_bound(next->keys.begin(), next->keys.end(), key);
                if (it == next->keys.end() || *it != key)
                    return fail(errc::invalid_argument,
                                "marching_cubes_by_slabs: vertex key " + std::to_string(key) +
                                    " missing from the next slab (fetch returned different samples?)");
                g[c] = std::uint32_t(next_base + std::size_t(it - next->keys.begin()));
            }
            out.triangles.push_back(g);
        }
        pending = {};
        return {};
    };
    // The samples' range, read only while no slab has given a vertex: the whole grid has a
    // surface as soon as one slab has, and an empty result is refused as the whole-grid path
    // refuses it when the iso lies outside the range.
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t k0 = 0; k0 + 1 < nz; k0 += slab_slices) {
        const std::size_t count = std::min(slab_slices + 1, nz - k0);
        samples.clear();
        if (auto r = fetch(k0, count, samples); !r) return r.error();
        if (samples.size() != count * nx * ny)
            return fail(errc::invalid_argument,
                        "marching_cubes_by_slabs: fetch gave " + std::to_string(samples.size()) + " samples for " +
                            std::to_string(count) + " slices of " + std::to_string(nx) + " x " + std::to_string(ny));
        auto view = make_grid_view(std::span<const T>(samples), {{nx, ny, count}, whole.origin, whole.spacing});
        if (!view) return view.error();
        auto blk = marching_cubes_block<S>(*view, {.offset = {0, 0, k0}, .whole = whole.dims}, options);
        if (!blk) return blk.error();
        if (out.positions.empty() && blk->keys.empty())
            for (const T& v : samples) {
                lo = std::min(lo, static_cast<double>(v));
                hi = std::max(hi, static_cast<double>(v));
            }
        // Vertices on the top plane belong to the next slab's rows, unless this is the last.
        const bool last = k0 + count == nz;
        const std::uint64_t top = std::uint64_t(k0 + count - 1) * plane_keys;
        const std::size_t emitted =
            last ? blk->keys.size()
                 : std::size_t(std::lower_bound(blk->keys.begin(), blk->keys.end(), top) - blk->keys.begin());
        const std::size_t base = out.positions.size();
        if (base + emitted > std::numeric_limits<std::uint32_t>::max())
            return fail(errc::unsupported, "marching_cubes_by_slabs: more than 2^32 - 1 vertices");
        if (auto r = flush_pending(&*blk, base); !r) return r.error();
        out.positions.insert(out.positions.end(), blk->positions.begin(),
                             blk->positions.begin() + std::ptrdiff_t(emitted));
        pending = std::move(*blk);
        pending_base = base;
        pending_emitted = emitted;
    }
    if (auto r = flush_pending(nullptr, 0); !r) return r.error();
    if (out.positions.empty() && !(lo <= options.iso && options.iso <= hi))
        return detail::mc::iso_outside_range(options.iso, lo, hi);
    return out;
}

}  // namespace hmira
