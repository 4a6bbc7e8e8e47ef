// hmira/algorithms/conversion/marching_cubes_blocks.hpp
// Marching cubes of a grid too large for memory, one block at a time: each block's vertices
// carry a global key, and merge_blocks() welds the blocks into exactly the whole-grid mesh.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <numeric>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "../../core/result.hpp"
#include "../../core/uninitialized_vector.hpp"
#include "../../core/vec3.hpp"
#include "../../grids/dense_grid.hpp"
#include "../../grids/voxel_grid.hpp"
#include "detail/parallel.hpp"
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
    uninitialized_vector<vec3<S>> positions;                       ///< one per vertex, as the whole grid computes it
    std::vector<std::uint64_t> keys;                               ///< one global key per vertex, increasing
    uninitialized_vector<std::array<std::uint32_t, 3>> triangles;  ///< into positions, counter-clockwise from outside
    std::vector<std::uint64_t> cubes;                     ///< cube key of each triangle, non-decreasing
    grid_dims whole{0, 0, 0};                             ///< dimensions of the whole grid the keys refer to
    grid_dims offset{0, 0, 0};                            ///< global index of the block's sample (0, 0, 0)
    grid_dims size{0, 0, 0};                              ///< the block's samples per axis, overlap included
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
/// block's offset ("marching_cubes_block at (64, 0, 128): marching_cubes: sample (70, 3, 130)
/// is inf; ...", indices in the whole grid), except the iso range: a block may well lie on one
/// side of the surface, so only the caller that sees every block can tell an iso outside the
/// whole grid's range (marching_cubes_by_slabs() does; hmira.dask does it in Python).
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

namespace detail::mc_direct {

// Meshing straight into the whole result, for callers that hold every block in one address
// space (hmira.dask on the threaded scheduler): count_block() on every block, a prefix sum of
// the counts in the whole grid's order (global_layout), then write_block_into() on every block,
// in parallel. No block mesh is kept and nothing is merged; each block's samples are
// classified twice instead.

/// The samples a block owns along each axis, [0, own): its core, plus the grid's last sample
/// when it reaches the end (a last chunk one sample thick owns nothing; see axis_tiling).
inline grid_dims owned_samples(const grid_dims& d, const grid_block& where) noexcept {
    grid_dims own{0, 0, 0};
    if (d[0] < 2 || d[1] < 2 || d[2] < 2) return own;
    for (int a = 0; a < 3; ++a) own[a] = where.offset[a] + d[a] == where.whole[a] ? d[a] : d[a] - 1;
    return own;
}

/// What one block owns, per owned row (j, k) at k * own[1] + j: its vertices per axis (x-, y-,
/// z-edges, centres; at 4 * row + axis) and its cube row's triangles.
struct block_counts {
    grid_dims own{0, 0, 0};                ///< owned samples per axis
    std::vector<std::uint32_t> vertices;   ///< 4 per owned row
    std::vector<std::uint32_t> triangles;  ///< 1 per owned row
    detail::mc::counted_state counted;     ///< the block's counted rows, for write_block_into() to reuse
};

/// The checks of marching_cubes_block(); an empty message when the block may be meshed.
template <voxel_grid G>
std::string check_block(const G& block, const grid_block& where, double iso, const std::string& who) {
    const grid_dims d = block.dims();
    double whole_size = 4;
    for (int a = 0; a < 3; ++a) {
        if (where.offset[a] > where.whole[a] || d[a] > where.whole[a] - where.offset[a])
            return who + ": a block of " + std::to_string(d[a]) + " samples along " + std::string(1, "xyz"[a]) +
                   " does not fit in the whole grid's " + std::to_string(where.whole[a]);
        whole_size *= double(where.whole[a]);
    }
    if (whole_size >= 0x1p63) return who + ": whole grid too large for 64-bit keys";
    if (d[0] < 2 || d[1] < 2 || d[2] < 2) return {};
    if (!std::isfinite(iso)) return who + ": the iso value must be finite";
    if (auto ok = check_grid_geometry(geometry_of(block), "marching_cubes", 2); !ok) return who + ": " + ok.error().message;
    return {};
}

/// Counts what a block owns. O(N) for its N samples (the first two passes of marching cubes).
/// Errors: those of marching_cubes_block().
template <voxel_grid G>
result<block_counts> count_block(const G& block, const grid_block& where, const marching_cubes_block_options& options = {}) {
    const std::string who = "marching_cubes_block at (" + std::to_string(where.offset[0]) + ", " + std::to_string(where.offset[1]) +
                            ", " + std::to_string(where.offset[2]) + ")";
    if (auto bad = check_block(block, where, options.iso, who); !bad.empty()) return fail(errc::invalid_argument, bad);
    block_counts out;
    out.own = owned_samples(block.dims(), where);
    if (out.own[0] == 0) return out;
    detail::mc::block_tags tags{where.offset, where.whole, nullptr, nullptr, nullptr, true};
    const marching_cubes_options mc{.iso = options.iso, .inside = options.inside, .threads = options.threads};
    result<indexed_triangles<double>> tri = fail(errc::invalid_argument, "");
    out.vertices.assign(4 * out.own[1] * out.own[2], 0);
    out.triangles.assign(out.own[1] * out.own[2], 0);
    detail::with_thread_count(options.threads, [&] {
        detail::mc::extractor<G> ex(block, mc);
        ex.set_block(&tags);
        tri = ex.template run<double>();
        if (!tri) return;
        ex.owned_counts(out.own[0], out.own[1], out.own[2], [&](std::size_t j, std::size_t k, const std::uint64_t* v, std::uint64_t t) {
            const std::size_t r = k * out.own[1] + j;
            for (int a = 0; a < 4; ++a) out.vertices[4 * r + std::size_t(a)] = std::uint32_t(v[a]);
            out.triangles[r] = std::uint32_t(t);
        });
        ex.keep_counts(out.counted);
    });
    if (!tri) return fail(tri.error().code, who + ": " + tri.error().message, tri.error().element);
    return out;
}

/// Writes the block's owned vertices and its triangles into `layout`'s whole result, at the
/// places its tables give (built from every block's count_block()). O(N + V + T) for its N
/// samples, V vertices and T triangles; with `counted` (this block's count_block() result,
/// whose counted rows it takes), O(V + T + R) for R rows: the counting is not repeated.
/// Errors: those of marching_cubes_block().
/// \pre the tables were built from this chunking of this grid with the same options, and
/// `counted`, if given, by count_block() of this block.
template <voxel_grid G>
result<void> write_block_into(const G& block, const grid_block& where, detail::mc::global_layout layout,
                              const marching_cubes_block_options& options = {}, block_counts* counted = nullptr) {
    const std::string who = "marching_cubes_block at (" + std::to_string(where.offset[0]) + ", " + std::to_string(where.offset[1]) +
                            ", " + std::to_string(where.offset[2]) + ")";
    if (auto bad = check_block(block, where, options.iso, who); !bad.empty()) return fail(errc::invalid_argument, bad);
    const grid_dims own = owned_samples(block.dims(), where);
    if (own[0] == 0) return {};
    layout.own_x = own[0];
    layout.own_y = own[1];
    layout.own_z = own[2];
    detail::mc::block_tags tags{where.offset, where.whole, nullptr, nullptr, &layout, false};
    const marching_cubes_options mc{.iso = options.iso, .inside = options.inside, .threads = options.threads};
    result<indexed_triangles<double>> tri = fail(errc::invalid_argument, "");
    detail::with_thread_count(options.threads, [&] {
        detail::mc::extractor<G> ex(block, mc);
        ex.set_block(&tags);
        if (counted && !counted->counted.vbase.empty()) ex.reuse_counts(std::move(counted->counted));
        tri = ex.template run<double>();
    });
    if (!tri) return fail(tri.error().code, who + ": " + tri.error().message, tri.error().element);
    return {};
}

/// Writes several blocks into `layout`'s whole result as write_block_into() does each, but
/// row by row: for every local row (j, k), each block's share in turn. Given the blocks of one
/// row of chunks along x (one y and z chunk, the x chunks in order), each sample row's
/// vertices and cube row's triangles are then written in the whole grid's order while their
/// cache lines are hot; block by block, every block writes short runs (one per row, axis and
/// chunk column) far apart. `columns[b]` is block b's chunk along x; `counted[b]`, if not
/// null, block b's count_block() result (its counted rows are taken, as write_block_into()
/// takes them); `counted` may be empty. The result does not depend on the blocks' order.
/// Complexity: that of write_block_into() on each block. Memory: every block's bit rows at once.
/// Errors: those of write_block_into(); invalid_argument for spans of different lengths.
/// \pre as write_block_into(), for every block.
template <voxel_grid G>
result<void> write_blocks_into(std::span<const G> blocks, std::span<const grid_block> wheres, std::span<const std::size_t> columns,
                               const detail::mc::global_layout& layout, const marching_cubes_block_options& options = {},
                               std::span<block_counts* const> counted = {}) {
    const std::size_t n = blocks.size();
    if (wheres.size() != n || columns.size() != n || (!counted.empty() && counted.size() != n))
        return fail(errc::invalid_argument, "write_blocks_into: blocks, places, columns and counts differ in number");
    std::vector<detail::mc::global_layout> layouts(n, layout);
    std::vector<detail::mc::block_tags> tags(n);
    std::vector<std::unique_ptr<detail::mc::extractor<G>>> ex(n);
    const marching_cubes_options mc{.iso = options.iso, .inside = options.inside, .threads = options.threads};
    std::size_t rows_y = 0, rows_z = 0;
    result<void> ok;
    detail::with_thread_count(options.threads, [&] {
        for (std::size_t b = 0; b < n && ok; ++b) {
            const auto& where = wheres[b];
            const std::string who = "marching_cubes_block at (" + std::to_string(where.offset[0]) + ", " +
                                    std::to_string(where.offset[1]) + ", " + std::to_string(where.offset[2]) + ")";
            if (auto bad = check_block(blocks[b], where, options.iso, who); !bad.empty()) {
                ok = fail(errc::invalid_argument, bad);
                return;
            }
            const grid_dims own = owned_samples(blocks[b].dims(), where);
            if (own[0] == 0) continue;  // owns nothing, writes nothing
            layouts[b].column = columns[b];
            layouts[b].own_x = own[0];
            layouts[b].own_y = own[1];
            layouts[b].own_z = own[2];
            tags[b] = {where.offset, where.whole, nullptr, nullptr, &layouts[b], false};
            ex[b] = std::make_unique<detail::mc::extractor<G>>(blocks[b], mc);
            ex[b]->set_block(&tags[b]);
            if (!counted.empty() && counted[b] && !counted[b]->counted.vbase.empty()) ex[b]->reuse_counts(std::move(counted[b]->counted));
            if (auto begun = ex[b]->begin_layout_write(); !begun) {
                ok = fail(begun.error().code, who + ": " + begun.error().message, begun.error().element);
                return;
            }
            rows_y = std::max(rows_y, blocks[b].dims()[1]);
            rows_z = std::max(rows_z, blocks[b].dims()[2]);
        }
        if (!ok) return;
        for (std::size_t k = 0; k < rows_z; ++k)
            for (std::size_t j = 0; j < rows_y; ++j)
                for (std::size_t b = 0; b < n; ++b)
                    if (ex[b] && j < blocks[b].dims()[1] && k < blocks[b].dims()[2]) ex[b]->write_layout_row(j, k);
    });
    return ok;
}

/// The tables of a global_layout, and the whole result's size.
struct layout_tables {
    std::vector<std::uint32_t> vertex_start;    ///< see global_layout
    std::vector<std::uint32_t> triangle_start;  ///< see global_layout
    std::size_t columns = 0;                    ///< chunks along x
    std::uint64_t vertices = 0, triangles = 0;  ///< the whole result's counts
};

/// Prefix sums of every block's counts in the whole grid's order (rows (z, y); per row the
/// axes; per axis the chunks along x, whose starts are `x_starts`). `offsets[b]` is block b's
/// offset. O(R * C) for R sample rows and C chunks along x.
/// Errors (invalid_argument): a block off the x chunking; unsupported: more than 2^32 - 1
/// vertices or triangles.
inline result<layout_tables> make_layout(const grid_dims& whole, std::span<const std::size_t> x_starts,
                                         std::span<const grid_dims> offsets, std::span<const block_counts> counts) {
    layout_tables out;
    out.columns = x_starts.size();
    const std::size_t rows = whole[1] * whole[2], mx = out.columns;
    out.vertex_start.assign(rows * 4 * mx, 0);
    out.triangle_start.assign(rows * mx, 0);
    for (std::size_t b = 0; b < counts.size(); ++b) {
        const auto& c = counts[b];
        const auto column = std::size_t(std::find(x_starts.begin(), x_starts.end(), offsets[b][0]) - x_starts.begin());
        if (column == mx)
            return fail(errc::invalid_argument, "marching_cubes blocks: block " + std::to_string(b) + " is off the x chunking");
        for (std::size_t k = 0; k < c.own[2]; ++k)
            for (std::size_t j = 0; j < c.own[1]; ++j) {
                const std::size_t r = k * c.own[1] + j, g = (offsets[b][2] + k) * whole[1] + offsets[b][1] + j;
                for (std::size_t a = 0; a < 4; ++a) out.vertex_start[(g * 4 + a) * mx + column] = c.vertices[4 * r + a];
                out.triangle_start[g * mx + column] = c.triangles[r];
            }
    }
    // Exclusive prefix sums: the flat order of the tables is the whole grid's order.
    auto prefix = [](std::vector<std::uint32_t>& v) {
        std::uint64_t at = 0;
        for (auto& x : v) {
            const std::uint64_t n = x;
            x = std::uint32_t(at);
            at += n;
            if (at > std::numeric_limits<std::uint32_t>::max()) return at;
        }
        return at;
    };
    out.vertices = prefix(out.vertex_start);
    out.triangles = prefix(out.triangle_start);
    if (out.vertices > std::numeric_limits<std::uint32_t>::max() || out.triangles > std::numeric_limits<std::uint32_t>::max())
        return fail(errc::unsupported, "marching_cubes blocks: more than 2^32 - 1 vertices or triangles");
    return out;
}

}  // namespace detail::mc_direct

/// Options of merge_blocks().
struct merge_blocks_options {
    unsigned threads = 0;  ///< worker threads (0: all); the result does not depend on it
};

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
    bool owns_row(std::size_t j, std::size_t k) const noexcept { return j >= lo[1] && j < hi[1] && k >= lo[2] && k < hi[2]; }
};

/// Calls f(j, k, axis, base, begin, end) for each run of `keys` on one sample row (j, k) and
/// axis (keys base + i), walking the rows of a block at `o` of `e` samples in key order:
/// [begin, end) holds the keys of that row and axis, all inside the block (a centre vertex's
/// cube too). No division per key or run. Returns the index of the first key outside the
/// block, or keys.size() when none is.
template <class F>
std::size_t for_each_vertex_run(std::span<const std::uint64_t> keys, const grid_dims& whole, const grid_dims& o, const grid_dims& e,
                                const F& f) {
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
std::size_t for_each_cube_run(std::span<const std::uint64_t> cubes, const grid_dims& whole, const grid_dims& o, const grid_dims& e,
                              const F& f) {
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

}  // namespace detail::mc_merge

/// Welds blocks by key into one indexed triangle list, written into storage that
/// `allocate(n_vertices, n_triangles)` returns (a merged_storage<S> of exactly those sizes;
/// called once, after the blocks' own arrays and their tiling are checked).
///
/// When the blocks tile a grid (as marching_cubes_block() describes: one block per chunk of a
/// chunking of the grid, each with its one-sample overlap, including the empty blocks of
/// chunks too thin for cubes), the result equals marching_cubes_indexed() of the whole grid
/// element for element: the same vertices in the same order with bit-identical positions,
/// and the same triangles in the same order. The blocks may come in any order.
///
/// How: every vertex is owned by one block, the one whose chunk holds the sample its key
/// names (see detail::mc_merge::axis_tiling for the last sample), so the vertices a block owns
/// are copied without any lookup; only the vertices on a block's high faces, which a neighbour
/// owns, are looked up (a binary search in the neighbour's run of that row and axis) and
/// checked bit for bit. Counting each block's vertices and triangles per row, a prefix sum in
/// the whole grid's row order, then writing, puts everything in place, in parallel.
///
/// Complexity: O(V + T + R + H log V_r) for V block vertices, T triangles, R sample rows of
/// all blocks, H vertices on inner chunk faces and V_r vertices per row; memory 12 bytes per
/// row and axis of every block, 4 per block vertex, besides the output. Parallel over blocks
/// and over z-slices with oneTBB.
/// \pre none (checked below).
/// \post on error, the storage (if it was allocated) holds unspecified values.
/// Errors (invalid_argument): a block whose arrays disagree in length, whose keys do not
/// increase or cube keys decrease, whose triangle names a missing vertex, whose vertices or
/// cubes lie outside its samples, or whose whole-grid dimensions differ from another block's;
/// blocks that do not tile one grid (a chunk without a block, a block of the wrong size); two
/// blocks at one offset (the blocks overlap); two blocks giving one key different positions,
/// or a key missing from the block that owns it; unsupported: more than 2^32 - 1 vertices.
/// The allocator's error is returned as is.
template <class S, class Allocate>
result<void> merge_blocks_into(std::span<const block_triangles_view<S>> blocks, Allocate&& allocate, const merge_blocks_options& options = {}) {
    using detail::mc_merge::axis_tiling;
    using detail::mc_merge::block_plan;
    if (blocks.empty()) {
        auto none = allocate(std::size_t(0), std::size_t(0));
        if (!none) return none.error();
        return {};
    }
    const grid_dims whole = blocks[0].whole;
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        const auto& blk = blocks[b];
        const std::string which = "merge_blocks: block " + std::to_string(b);
        if (blk.keys.size() != blk.positions.size() || blk.cubes.size() != blk.triangles.size())
            return fail(errc::invalid_argument, which + " has " + std::to_string(blk.positions.size()) + " positions, " +
                                                    std::to_string(blk.keys.size()) + " keys, " + std::to_string(blk.triangles.size()) +
                                                    " triangles and " + std::to_string(blk.cubes.size()) + " cube keys");
        if (blk.whole != whole) return fail(errc::invalid_argument, which + " refers to a whole grid of other dimensions than block 0's");
        if (blk.positions.size() >= std::numeric_limits<std::uint32_t>::max())
            return fail(errc::unsupported, which + " has more than 2^32 - 2 vertices");
        for (int a = 0; a < 3; ++a)
            if (blk.offset[a] >= whole[a] || blk.size[a] == 0 || blk.size[a] > whole[a] - blk.offset[a])
                return fail(errc::invalid_argument, which + ": " + std::to_string(blk.size[a]) + " samples at " +
                                                        std::to_string(blk.offset[a]) + " along " + std::string(1, "xyz"[a]) +
                                                        " do not fit in the whole grid's " + std::to_string(whole[a]));
    }
    const std::size_t nx = whole[0], ny = whole[1], nz = whole[2];
    if (double(nx) * double(ny) * double(nz) * 4 >= 0x1p63) return fail(errc::invalid_argument, "merge_blocks: whole grid too large for 64-bit keys");
    if (nx < 2 || ny < 2 || nz < 2) {
        // No cubes anywhere: every block is empty.
        for (std::size_t b = 0; b < blocks.size(); ++b)
            if (!blocks[b].keys.empty() || !blocks[b].cubes.empty())
                return fail(errc::invalid_argument, "merge_blocks: block " + std::to_string(b) + " has vertices in a grid too thin for cubes");
        auto none = allocate(std::size_t(0), std::size_t(0));
        if (!none) return none.error();
        return {};
    }

    // The chunking: the blocks' offsets per axis; every chunk cell must hold exactly one
    // block, of the chunk's size plus the overlap.
    std::array<axis_tiling, 3> tiling;
    for (int a = 0; a < 3; ++a) {
        auto& t = tiling[a];
        for (const auto& blk : blocks) t.starts.push_back(blk.offset[a]);
        std::sort(t.starts.begin(), t.starts.end());
        t.starts.erase(std::unique(t.starts.begin(), t.starts.end()), t.starts.end());
        if (t.starts[0] != 0)
            return fail(errc::invalid_argument, "merge_blocks: the blocks do not tile one grid (no block starts at 0 along " +
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
    const std::size_t mx = tiling[0].starts.size(), my = tiling[1].starts.size(), mz = tiling[2].starts.size();
    // Each block fills one chunk cell, so more cells than blocks leave one empty.
    if (double(mx) * double(my) * double(mz) > double(blocks.size()))
        return fail(errc::invalid_argument, "merge_blocks: the blocks do not tile one grid (" + std::to_string(blocks.size()) +
                                                " blocks for " + std::to_string(mx) + " x " + std::to_string(my) + " x " +
                                                std::to_string(mz) + " chunks)");
    constexpr std::uint32_t no_block = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> cell_block(mx * my * mz, no_block);
    std::vector<std::array<std::size_t, 3>> cell_of(blocks.size());
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        std::array<std::size_t, 3> c{};
        for (int a = 0; a < 3; ++a) {
            const auto& st = tiling[a].starts;
            c[a] = std::size_t(std::lower_bound(st.begin(), st.end(), blocks[b].offset[a]) - st.begin());
            const std::size_t want = c[a] + 1 < st.size() ? st[c[a] + 1] - st[c[a]] + 1 : whole[a] - st[c[a]];
            if (blocks[b].size[a] != want)
                return fail(errc::invalid_argument, "merge_blocks: the blocks do not tile one grid (block " + std::to_string(b) + " has " +
                                                        std::to_string(blocks[b].size[a]) + " samples along " + std::string(1, "xyz"[a]) +
                                                        " where its chunk and overlap have " + std::to_string(want) + ")");
        }
        auto& slot = cell_block[(c[2] * my + c[1]) * mx + c[0]];
        if (slot != no_block)
            return fail(errc::invalid_argument, "merge_blocks: blocks " + std::to_string(slot) + " and " + std::to_string(b) +
                                                    " both start at (" + std::to_string(blocks[b].offset[0]) + ", " +
                                                    std::to_string(blocks[b].offset[1]) + ", " + std::to_string(blocks[b].offset[2]) +
                                                    ") (the blocks overlap)");
        slot = std::uint32_t(b);
        cell_of[b] = c;
    }
    for (std::size_t c = 0; c < cell_block.size(); ++c)
        if (cell_block[c] == no_block)
            return fail(errc::invalid_argument, "merge_blocks: the blocks do not tile one grid (no block starts at (" +
                                                    std::to_string(tiling[0].starts[c % mx]) + ", " +
                                                    std::to_string(tiling[1].starts[c / mx % my]) + ", " +
                                                    std::to_string(tiling[2].starts[c / mx / my]) + "))");

    std::vector<block_plan> plans(blocks.size());
    std::vector<std::string> errors(blocks.size());
    auto each_block = [&](const auto& body) {
        detail::with_thread_count(options.threads, [&] {
            detail::parallel_chunks(blocks.size(), 1, [&](std::size_t b0, std::size_t b1) {
                for (std::size_t b = b0; b < b1; ++b) errors[b] = body(b);
            });
        });
        for (const auto& e : errors)
            if (!e.empty()) return e;
        return std::string();
    };

    // Pass 1, per block: check its arrays; count its owned vertices and its triangles per row.
    const std::string planned = each_block([&](std::size_t b) -> std::string {
        const auto& blk = blocks[b];
        auto& p = plans[b];
        const std::string which = "merge_blocks: block " + std::to_string(b);
        for (int a = 0; a < 3; ++a) {
            p.lo[a] = tiling[a].own_lo[cell_of[b][a]];
            p.hi[a] = std::max(p.lo[a], tiling[a].own_hi[cell_of[b][a]]);
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
        const std::size_t outside = detail::mc_merge::for_each_vertex_run(
            keys, whole, blk.offset, blk.size,
            [&](std::size_t j, std::size_t k, std::size_t a, std::uint64_t row_base, std::size_t v, std::size_t end) {
                if (!p.owns_row(j, k)) return;
                std::size_t owned_end = v;
                while (owned_end < end && keys[owned_end] < row_base + own_x) ++owned_end;
                p.vertex_begin[4 * p.at(j, k) + a] = std::uint32_t(v);
                p.vertex_count[4 * p.at(j, k) + a] = std::uint32_t(owned_end - v);
            });
        if (outside < keys.size())
            return which + ": vertex " + std::to_string(outside) + " (key " + std::to_string(keys[outside]) + ") lies outside the block";
        const auto cubes = blk.cubes;
        for (std::size_t t = 1; t < cubes.size(); ++t)
            if (cubes[t] < cubes[t - 1]) return which + ": cube keys decrease at triangle " + std::to_string(t);
        // The block's cubes are those whose first sample lies in its chunk: with the tiling
        // checked above, their rows are owned rows.
        const std::size_t stray = detail::mc_merge::for_each_cube_run(
            cubes, whole, blk.offset, blk.size, [&](std::size_t j, std::size_t k, std::size_t t, std::size_t end) {
                p.cube_begin[p.at(j, k)] = std::uint32_t(t);
                p.cube_count[p.at(j, k)] = std::uint32_t(end - t);
            });
        if (stray < cubes.size())
            return which + ": triangle " + std::to_string(stray) + " (cube key " + std::to_string(cubes[stray]) + ") lies outside the block";
        return {};
    });
    if (!planned.empty()) return fail(errc::invalid_argument, planned);

    // Pass 2: global starts, in the whole grid's order: rows (z, y); in a row, the axes, and
    // for each axis the chunks along x; triangles by cube row, then chunk along x.
    std::vector<std::uint64_t> slice_vertices(nz + 1, 0), slice_triangles(nz + 1, 0);
    auto sweep = [&](std::size_t k, bool assign, std::uint64_t vertex_at, std::uint64_t triangle_at) {
        const std::size_t bz = tiling[2].owner[k];
        for (std::size_t j = 0; j < ny; ++j) {
            const std::uint32_t* row_blocks = &cell_block[(bz * my + tiling[1].owner[j]) * mx];
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
    detail::with_thread_count(options.threads, [&] {
        detail::parallel_chunks(nz, 8, [&](std::size_t k0, std::size_t k1) {
            for (std::size_t k = k0; k < k1; ++k) std::tie(slice_vertices[k + 1], slice_triangles[k + 1]) = sweep(k, false, 0, 0);
        });
    });
    for (std::size_t k = 0; k < nz; ++k) {
        slice_vertices[k + 1] += slice_vertices[k];
        slice_triangles[k + 1] += slice_triangles[k];
    }
    if (slice_vertices[nz] > std::numeric_limits<std::uint32_t>::max())
        return fail(errc::unsupported, "merge_blocks: more than 2^32 - 1 vertices");
    detail::with_thread_count(options.threads, [&] {
        detail::parallel_chunks(nz, 8, [&](std::size_t k0, std::size_t k1) {
            for (std::size_t k = k0; k < k1; ++k) sweep(k, true, slice_vertices[k], slice_triangles[k]);
        });
    });
    auto storage = allocate(std::size_t(slice_vertices[nz]), std::size_t(slice_triangles[nz]));
    if (!storage) return storage.error();
    const merged_storage<S> out = *storage;
    if (out.positions.size() != slice_vertices[nz] || out.triangles.size() != slice_triangles[nz])
        return fail(errc::invalid_argument, "merge_blocks: the allocator returned storage of the wrong size");

    // Pass 3, per block: copy its owned vertices in place, look up the others in the blocks
    // that own them, then write its triangles in place.
    const std::string written = each_block([&](std::size_t b) -> std::string {
        const auto& blk = blocks[b];
        const auto& p = plans[b];
        const auto keys = blk.keys;
        const std::size_t nv = keys.size();
        // Uninitialised on purpose: every entry is written below before it is read.
        const std::unique_ptr<std::uint32_t[]> global(new std::uint32_t[nv]);
        std::string error;
        detail::mc_merge::for_each_vertex_run(
            keys, whole, blk.offset, blk.size,
            [&](std::size_t j, std::size_t k, std::size_t a, std::uint64_t row_base, std::size_t v, std::size_t end) {
                if (!error.empty()) return;
                std::size_t q = v;
                if (p.owns_row(j, k)) {
                    const std::size_t at = 4 * p.at(j, k) + a;
                    const std::uint32_t start = p.vertex_start[at];
                    for (const std::size_t owned_end = v + p.vertex_count[at]; q < owned_end; ++q) {
                        global[q] = std::uint32_t(start + (q - v));
                        out.positions[global[q]] = blk.positions[q];
                    }
                }
                // The rest lie on a neighbour's chunk: find each in the owner's run.
                const std::size_t jo = tiling[1].owner[j], ko = tiling[2].owner[k];
                for (; q < end; ++q) {
                    const std::uint32_t owner = cell_block[(ko * my + jo) * mx + tiling[0].owner[std::size_t(keys[q] - row_base)]];
                    const auto& op = plans[owner];
                    const std::size_t at = 4 * op.at(j, k) + a;
                    const auto theirs = blocks[owner].keys;
                    const auto run = theirs.begin() + op.vertex_begin[at];
                    const auto it = std::lower_bound(run, run + op.vertex_count[at], keys[q]);
                    if (owner == b || it == run + op.vertex_count[at] || *it != keys[q]) {
                        error = "merge_blocks: the blocks do not tile one grid (vertex key " + std::to_string(keys[q]) + " of block " +
                                std::to_string(b) + " is missing from block " + std::to_string(owner) + ", which owns it)";
                        return;
                    }
                    const std::size_t w = std::size_t(it - theirs.begin());
                    if (std::memcmp(&blocks[owner].positions[w], &blk.positions[q], sizeof(vec3<S>)) != 0) {
                        error = "merge_blocks: blocks " + std::to_string(b) + " and " + std::to_string(owner) + " give vertex key " +
                                std::to_string(keys[q]) + " different positions";
                        return;
                    }
                    global[q] = op.vertex_start[at] + std::uint32_t(w - op.vertex_begin[at]);
                }
            });
        if (!error.empty()) return error;
        for (std::size_t r = 0; r < p.cube_count.size(); ++r) {
            const std::size_t t0 = p.cube_begin[r], n = p.cube_count[r];
            auto* dst = out.triangles.data() + p.cube_start[r];
            for (std::size_t t = 0; t < n; ++t) {
                const auto& tri = blk.triangles[t0 + t];
                if (tri[0] >= nv || tri[1] >= nv || tri[2] >= nv) {
                    const auto bad = tri[0] >= nv ? tri[0] : tri[1] >= nv ? tri[1] : tri[2];
                    return "merge_blocks: block " + std::to_string(b) + " triangle " + std::to_string(t0 + t) + " names vertex " +
                           std::to_string(bad) + " of " + std::to_string(nv);
                }
                dst[t] = {global[tri[0]], global[tri[1]], global[tri[2]]};
            }
        }
        return {};
    });
    if (!written.empty()) return fail(errc::invalid_argument, written);
    return {};
}

/// Welds blocks by key into one indexed triangle list: merge_blocks_into() with the result's
/// own arrays as the storage. Same result, rules, errors and complexity.
template <class S>
result<indexed_triangles<S>> merge_blocks(std::span<const block_triangles_view<S>> blocks, const merge_blocks_options& options = {}) {
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

/// The same for blocks held as block_triangles.
template <class S>
result<indexed_triangles<S>> merge_blocks(std::span<const block_triangles<S>> blocks, const merge_blocks_options& options = {}) {
    std::vector<block_triangles_view<S>> views;
    views.reserve(blocks.size());
    for (const auto& b : blocks) views.push_back(view_of(b));
    return merge_blocks(std::span<const block_triangles_view<S>>(views), options);
}

/// The same for a std::vector of blocks.
template <class S>
result<indexed_triangles<S>> merge_blocks(const std::vector<block_triangles<S>>& blocks, const merge_blocks_options& options = {}) {
    return merge_blocks(std::span<const block_triangles<S>>(blocks), options);
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
/// \pre none. Errors: those of fetch and marching_cubes_block() (a non-finite sample, named
/// by its index in the whole grid); invalid_argument for a geometry check_grid_geometry()
/// refuses or a fetch that returns the wrong sample count, and, after the last slab, for an
/// iso outside the samples' range when there is no surface (as marching_cubes_indexed(); the
/// range is read only from the slabs met while the result is still empty).
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
    // The samples' range, read only while no slab has given a vertex: the whole grid has a
    // surface as soon as one slab has, and an empty result is refused as the whole-grid path
    // refuses it when the iso lies outside the range.
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
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
        if (out.positions.empty() && blk->keys.empty())
            for (const T& v : samples) {
                lo = std::min(lo, static_cast<double>(v));
                hi = std::max(hi, static_cast<double>(v));
            }
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
    if (out.positions.empty() && !(lo <= options.iso && options.iso <= hi)) return detail::mc::iso_outside_range(options.iso, lo, hi);
    return out;
}

}  // namespace hmira
