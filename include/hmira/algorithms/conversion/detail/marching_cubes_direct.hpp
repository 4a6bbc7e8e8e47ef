// hmira/algorithms/conversion/detail/marching_cubes_direct.hpp
// Marching cubes of blocks written straight into the whole result (detail::mc_direct), for callers that
// hold every block in one address space (hmira.dask's threaded scheduler). Part of marching_cubes_blocks.hpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "marching_cubes_extractor.hpp"
#include "parallel.hpp"

namespace hmira {

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
    if (auto ok = check_grid_geometry(geometry_of(block), "marching_cubes", 2); !ok)
        return who + ": " + ok.error().message;
    return {};
}

/// Counts what a block owns. O(N) for its N samples (the first two passes of marching cubes).
/// Errors: those of marching_cubes_block().
template <voxel_grid G>
result<block_counts> count_block(const G& block, const grid_block& where,
                                 const marching_cubes_block_options& options = {}) {
    const std::string who = "marching_cubes_block at (" + std::to_string(where.offset[0]) + ", " +
                            std::to_string(where.offset[1]) + ", " + std::to_string(where.offset[2]) + ")";
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
        ex.owned_counts(out.own[0], out.own[1], out.own[2],
                        [&](std::size_t j, std::size_t k, const std::uint64_t* v, std::uint64_t t) {
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
    const std::string who = "marching_cubes_block at (" + std::to_string(where.offset[0]) + ", " +
                            std::to_string(where.offset[1]) + ", " + std::to_string(where.offset[2]) + ")";
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
result<void> write_blocks_into(std::span<const G> blocks, std::span<const grid_block> wheres,
                               std::span<const std::size_t> columns, const detail::mc::global_layout& layout,
                               const marching_cubes_block_options& options = {},
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
            if (!counted.empty() && counted[b] && !counted[b]->counted.vbase.empty())
                ex[b]->reuse_counts(std::move(counted[b]->counted));
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
            return fail(errc::invalid_argument,
                        "marching_cubes blocks: block " + std::to_string(b) + " is off the x chunking");
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
    if (out.vertices > std::numeric_limits<std::uint32_t>::max() ||
        out.triangles > std::numeric_limits<std::uint32_t>::max())
        return fail(errc::unsupported, "marching_cubes blocks: more than 2^32 - 1 vertices or triangles");
    return out;
}

}  // namespace detail::mc_direct

}  // namespace hmira
