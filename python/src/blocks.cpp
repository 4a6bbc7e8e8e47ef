// python/src/blocks.cpp
// Marching cubes by blocks for hmira.dask: one block of a larger C-ordered volume to keyed
// arrays, and the weld of such blocks into the whole volume's (V, F).
#include "common.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <span>
#include <vector>

#include <nanobind/stl/shared_ptr.h>
#include <nanobind/stl/tuple.h>

#include <hmira/algorithms/conversion/marching_cubes_blocks.hpp>

namespace hmira_py {

namespace {

using hmira::vec3;

/// A C-ordered numpy block seen as a grid whose x is array axis 2 (as hmira.marching_cubes
/// sees a C-ordered volume), with the whole volume's origin and spacing.
template <class V>
struct c_block {
    using value_type = V;
    const V* samples;
    hmira::grid_dims size;
    vec3<double> at, step;
    std::array<std::size_t, 2> rows{};  // samples from one row to the next, and one slice to the next
    hmira::grid_dims dims() const { return size; }
    vec3<double> origin() const { return at; }
    vec3<double> spacing() const { return step; }
    double value(std::size_t i, std::size_t j, std::size_t k) const {
        return static_cast<double>(samples[i + j * rows[0] + k * rows[1]]);
    }
    const V* data() const { return samples; }
    std::array<std::size_t, 2> strides() const { return rows; }
};

template <class Scalar>
nb::ndarray<nb::numpy, Scalar> adopt_array(std::unique_ptr<Scalar[]> data, std::initializer_list<std::size_t> shape) {
    Scalar* p = data.release();
    nb::capsule owner(p, [](void* q) noexcept { delete[] static_cast<Scalar*>(q); });
    return nb::ndarray<nb::numpy, Scalar>(p, shape, owner);
}

std::array<double, 3> triple(const std::vector<double>& v, const char* name) {
    if (v.size() != 3)
        value_error(std::string("marching_cubes_block: ") + name + " needs 3 values, got " + std::to_string(v.size()));
    return {v[0], v[1], v[2]};
}
hmira::grid_dims index_triple(const std::vector<std::size_t>& v, const char* name) {
    if (v.size() != 3)
        value_error(std::string("marching_cubes_block: ") + name + " needs 3 values, got " + std::to_string(v.size()));
    // Array axes (0, 1, 2) are the grid's (z, y, x).
    return {v[2], v[1], v[0]};
}

using part_array = nb::ndarray<nb::ro, nb::ndim<3>, nb::device::cpu>;

/// The block (a chunk plus its one-sample overlap) assembled from the chunk and one-sample
/// slices of its neighbours, in a buffer each thread keeps for its next block: no allocation
/// (and no page faults) per block. The parts may have any strides.
const std::byte* paste(const std::vector<part_array>& parts, const std::vector<std::array<std::size_t, 3>>& at,
                       const std::array<std::size_t, 3>& shape, std::size_t item, std::vector<std::byte>& buffer) {
    const std::size_t total = shape[0] * shape[1] * shape[2] * item;
    if (buffer.size() < total) buffer.resize(total);
    std::byte* out = buffer.data();
    for (std::size_t p = 0; p < parts.size(); ++p) {
        const auto& part = parts[p];
        const auto* src = static_cast<const std::byte*>(part.data());
        const std::int64_t s0 = part.stride(0), s1 = part.stride(1), s2 = part.stride(2);
        const std::size_t n0 = part.shape(0), n1 = part.shape(1), n2 = part.shape(2);
        for (std::size_t z = 0; z < n0; ++z)
            for (std::size_t y = 0; y < n1; ++y) {
                const std::byte* row = src + (std::int64_t(z) * s0 + std::int64_t(y) * s1) * std::int64_t(item);
                std::byte* dst = out + (((at[p][0] + z) * shape[1] + at[p][1] + y) * shape[2] + at[p][2]) * item;
                if (s2 == 1 || n2 == 1)
                    std::memcpy(dst, row, n2 * item);
                else
                    for (std::size_t x = 0; x < n2; ++x)
                        std::memcpy(dst + x * item, row + std::int64_t(x) * s2 * std::int64_t(item), item);
            }
    }
    return out;
}

/// A block's grid and place, checked and pasted from its parts; run(f) calls f(grid, where,
/// options) with the GIL released, for the block's dtype.
struct block_input {
    const std::vector<part_array>& parts;
    std::vector<std::array<std::size_t, 3>> at;
    std::array<std::size_t, 3> shape{};
    hmira::grid_block where;
    hmira::grid_dims size{};
    vec3<double> origin_xyz, step_xyz;
    hmira::marching_cubes_block_options options;

    block_input(const std::vector<part_array>& parts_, double iso, const std::vector<std::vector<std::size_t>>& steps,
                const std::vector<std::size_t>& core, const std::vector<std::size_t>& offset,
                const std::vector<std::size_t>& whole, const std::vector<double>& spacing,
                const std::vector<double>& origin, const std::string& inside, unsigned threads)
        : parts(parts_) {
        const auto sp = triple(spacing, "spacing"), org = triple(origin, "origin");
        const auto side = choice_arg<hmira::iso_inside>(inside, "marching_cubes_block", "inside");
        where = {.offset = index_triple(offset, "offset"), .whole = index_triple(whole, "whole")};
        // The parts: the chunk (step 0, 0, 0) and one-sample slices of the neighbours after it
        // (step 1 on the axes where the neighbour lies), every combination of the steps present.
        if (core.size() != 3 || parts.empty() || steps.size() != parts.size())
            value_error("marching_cubes_block: needs a 3-axis core shape and one step per part");
        shape = {core[0], core[1], core[2]};
        at.resize(parts.size());
        std::size_t seen = 0;
        for (std::size_t p = 0; p < parts.size(); ++p) {
            if (steps[p].size() != 3 || parts[p].dtype() != parts[0].dtype())
                value_error("marching_cubes_block: part " + std::to_string(p) + " has another dtype or a bad step");
            std::size_t bit = 0;
            for (int a = 0; a < 3; ++a) {
                const std::size_t s = steps[p][std::size_t(a)];
                if (s > 1 || parts[p].shape(std::size_t(a)) != (s ? 1 : core[std::size_t(a)]))
                    value_error("marching_cubes_block: part " + std::to_string(p) + " has shape (" +
                                std::to_string(parts[p].shape(0)) + ", " + std::to_string(parts[p].shape(1)) + ", " +
                                std::to_string(parts[p].shape(2)) + ") for step " + std::to_string(a) + " = " +
                                std::to_string(s));
                at[p][std::size_t(a)] = s ? core[std::size_t(a)] : 0;
                if (s) shape[std::size_t(a)] = core[std::size_t(a)] + 1;
                bit = bit * 2 + s;
            }
            if (seen & (std::size_t(1) << bit)) value_error("marching_cubes_block: two parts with one step");
            seen |= std::size_t(1) << bit;
        }
        std::size_t needed = 1;
        for (int a = 0; a < 3; ++a) needed *= shape[std::size_t(a)] > core[std::size_t(a)] ? 2 : 1;
        if (parts.size() != needed || !(seen & 1))
            value_error("marching_cubes_block: " + std::to_string(parts.size()) + " parts where the overlap needs " +
                        std::to_string(needed));
        size = {shape[2], shape[1], shape[0]};
        origin_xyz = {org[2], org[1], org[0]};
        step_xyz = {sp[2], sp[1], sp[0]};
        options = {.iso = iso, .inside = side, .threads = threads};
    }

    /// The parts' first sample when they are views of one array with rows along x, where the
    /// block can be read in place (da.from_array of a numpy array): the chunk, and each
    /// neighbour's slice where the chunk's strides put it. Null when they must be pasted.
    const std::byte* in_place(std::size_t item) const {
        const auto& c = parts[0];
        if (c.stride(2) != 1 || c.stride(1) <= 0 || c.stride(0) <= 0) return nullptr;
        for (std::size_t a = 0; a < 3; ++a)
            if (c.shape(a) < 2) return nullptr;  // a stride along one sample says nothing
        const auto* base = static_cast<const std::byte*>(c.data());
        for (std::size_t p = 1; p < parts.size(); ++p) {
            const std::int64_t shift =
                std::int64_t(at[p][0]) * c.stride(0) + std::int64_t(at[p][1]) * c.stride(1) + std::int64_t(at[p][2]);
            if (static_cast<const std::byte*>(parts[p].data()) != base + shift * std::int64_t(item)) return nullptr;
            for (std::size_t a = 0; a < 3; ++a)
                if (parts[p].shape(a) > 1 && parts[p].stride(a) != c.stride(a)) return nullptr;
        }
        return base;
    }

    /// The block as a grid of V: read in place, or pasted into `buffer` (which must outlive it).
    template <class V>
    c_block<V> grid(std::vector<std::byte>& buffer) const {
        if (const std::byte* base = in_place(sizeof(V))) {
            const std::array<std::size_t, 2> rows{std::size_t(parts[0].stride(1)), std::size_t(parts[0].stride(0))};
            return {reinterpret_cast<const V*>(base), size, origin_xyz, step_xyz, rows};
        }
        const auto* samples = reinterpret_cast<const V*>(paste(parts, at, shape, sizeof(V), buffer));
        return {samples, size, origin_xyz, step_xyz, {size[0], size[0] * size[1]}};
    }

    /// f(grid, where, options) for the block's dtype, with the GIL released; false for a dtype
    /// hmira does not read.
    template <class F>
    bool run(const F& f) const {
        nb::gil_scoped_release release;
        return for_dtype(parts[0].dtype(), [&](auto tag) {
            // Pasted into a buffer each thread keeps for its next block.
            thread_local std::vector<std::byte> buffer;
            f(grid<decltype(tag)>(buffer), where, options);
        });
    }

    /// go(V{}) for a dtype hmira reads; false for another.
    template <class F>
    static bool for_dtype(nb::dlpack::dtype dt, const F& go) {
        if (dt == nb::dtype<float>())
            go(float{});
        else if (dt == nb::dtype<double>())
            go(double{});
        else if (dt == nb::dtype<std::uint8_t>())
            go(std::uint8_t{});
        else if (dt == nb::dtype<std::uint16_t>())
            go(std::uint16_t{});
        else if (dt == nb::dtype<std::int16_t>())
            go(std::int16_t{});
        else
            return false;
        return true;
    }
};

constexpr const char* bad_dtype = "marching_cubes_block: volume dtype must be float32, float64, uint8, uint16 or int16";

nb::tuple marching_cubes_block(const std::vector<part_array>& parts, double iso,
                               const std::vector<std::vector<std::size_t>>& steps, const std::vector<std::size_t>& core,
                               const std::vector<std::size_t>& offset, const std::vector<std::size_t>& whole,
                               const std::vector<double>& spacing, const std::vector<double>& origin,
                               const std::string& inside, unsigned threads) {
    const block_input in(parts, iso, steps, core, offset, whole, spacing, origin, inside, threads);
    hmira::result<hmira::block_triangles<double>> r = hmira::fail(hmira::errc::invalid_argument, bad_dtype);
    in.run([&](const auto& g, const hmira::grid_block& where, const hmira::marching_cubes_block_options& options) {
        r = hmira::marching_cubes_block<double>(g, where, options);
        // Back to array axes, as hmira.marching_cubes does for a C-ordered volume: swapping two
        // axes mirrors the surface, so each triangle is reversed to keep its winding.
        if (r) {
            for (auto& p : r->positions) std::swap(p.x, p.z);
            for (auto& t : r->triangles) std::swap(t[1], t[2]);
        }
    });
    auto b = take(std::move(r));
    const std::size_t nv = b.positions.size(), nt = b.triangles.size();
    return nb::make_tuple(adopt<double>(std::move(b.positions), {nv, 3}), adopt<std::uint64_t>(std::move(b.keys), {nv}),
                          adopt<std::int32_t>(std::move(b.triangles), {nt, 3}),
                          adopt<std::uint64_t>(std::move(b.cubes), {nt}));
}

namespace direct = hmira::detail::mc_direct;

/// What a block owns (detail::mc_direct::count_block), kept opaque for _layout_blocks.
struct counts_holder {
    direct::block_counts counts;
    hmira::grid_dims offset{};
};

counts_holder count_block(const std::vector<part_array>& parts, double iso,
                          const std::vector<std::vector<std::size_t>>& steps, const std::vector<std::size_t>& core,
                          const std::vector<std::size_t>& offset, const std::vector<std::size_t>& whole,
                          const std::vector<double>& spacing, const std::vector<double>& origin,
                          const std::string& inside) {
    const block_input in(parts, iso, steps, core, offset, whole, spacing, origin, inside, 1);
    hmira::result<direct::block_counts> r = hmira::fail(hmira::errc::invalid_argument, bad_dtype);
    in.run([&](const auto& g, const hmira::grid_block& where, const hmira::marching_cubes_block_options& options) {
        r = direct::count_block(g, where, options);
    });
    return {take(std::move(r)), in.where.offset};
}

/// The whole result's tables and its uninitialised arrays, made from every block's counts.
struct layout_holder {
    direct::layout_tables tables;
    hmira::grid_dims whole{};
    std::vector<std::size_t> x_starts;
    std::unique_ptr<double[]> positions;
    std::unique_ptr<std::int32_t[]> triangles;
};

std::shared_ptr<layout_holder> layout_blocks(const std::vector<const counts_holder*>& blocks,
                                             const std::vector<std::size_t>& whole,
                                             const std::vector<std::size_t>& x_chunks) {
    auto out = std::make_shared<layout_holder>();
    out->whole = index_triple(whole, "whole");
    for (std::size_t at = 0, c = 0; c < x_chunks.size(); at += x_chunks[c++]) out->x_starts.push_back(at);
    std::vector<direct::block_counts> counts;
    std::vector<hmira::grid_dims> offsets;
    counts.reserve(blocks.size());
    for (const auto* b : blocks) {
        if (!b) value_error("layout_blocks: a block is None");
        counts.push_back({b->counts.own, b->counts.vertices, b->counts.triangles, {}});  // not the counted rows
        offsets.push_back(b->offset);
    }
    out->tables = take(direct::make_layout(out->whole, out->x_starts, offsets, counts));
    if (out->tables.vertices > std::size_t(std::numeric_limits<std::int32_t>::max()))
        value_error("merge_blocks: " + std::to_string(out->tables.vertices) +
                    " vertices do not fit int32 face indices");
    // Uninitialised on purpose: the blocks write every element (see merge_blocks below).
    out->positions.reset(new double[3 * out->tables.vertices]);
    out->triangles.reset(new std::int32_t[3 * out->tables.triangles]);
    return out;
}

void write_block(const std::vector<part_array>& parts, double iso, const std::vector<std::vector<std::size_t>>& steps,
                 const std::vector<std::size_t>& core, const std::vector<std::size_t>& offset,
                 const std::vector<std::size_t>& whole, const std::vector<double>& spacing,
                 const std::vector<double>& origin, const std::string& inside, layout_holder& layout,
                 counts_holder* counted) {
    const block_input in(parts, iso, steps, core, offset, whole, spacing, origin, inside, 1);
    if (in.where.whole != layout.whole) value_error("write_block: the block's whole grid differs from the layout's");
    const auto& xs = layout.x_starts;
    const auto column = std::size_t(std::find(xs.begin(), xs.end(), in.where.offset[0]) - xs.begin());
    if (column == layout.x_starts.size()) value_error("write_block: the block is off the layout's x chunking");
    const hmira::detail::mc::global_layout g{.vertex_start = layout.tables.vertex_start.data(),
                                             .triangle_start = layout.tables.triangle_start.data(),
                                             .columns = layout.tables.columns,
                                             .column = column,
                                             .positions = layout.positions.get(),
                                             .triangles = reinterpret_cast<std::uint32_t*>(layout.triangles.get()),
                                             .swap_xz = true};
    hmira::result<void> r = hmira::fail(hmira::errc::invalid_argument, bad_dtype);
    in.run([&](const auto& grid, const hmira::grid_block& where, const hmira::marching_cubes_block_options& options) {
        r = direct::write_block_into(grid, where, g, options, counted ? &counted->counts : nullptr);
    });
    check(r);
}

/// write_block() of several chunks at once, row by row in turn (direct::write_blocks_into):
/// given a row of chunks along x, each task writes long runs of the result.
void write_blocks(const std::vector<std::vector<part_array>>& parts, double iso,
                  const std::vector<std::vector<std::vector<std::size_t>>>& steps,
                  const std::vector<std::vector<std::size_t>>& cores,
                  const std::vector<std::vector<std::size_t>>& offsets, const std::vector<std::size_t>& whole,
                  const std::vector<double>& spacing, const std::vector<double>& origin, const std::string& inside,
                  layout_holder& layout, const std::vector<counts_holder*>& counted) {
    const std::size_t n = parts.size();
    if (n == 0 || steps.size() != n || cores.size() != n || offsets.size() != n || counted.size() != n)
        value_error("write_blocks: needs one steps, core, offset and counts per chunk, and at least one chunk");
    std::vector<block_input> in;
    in.reserve(n);
    std::vector<std::size_t> columns;
    std::vector<hmira::grid_block> wheres;
    std::vector<direct::block_counts*> counts;
    const auto& xs = layout.x_starts;
    for (std::size_t b = 0; b < n; ++b) {
        const auto& blk =
            in.emplace_back(parts[b], iso, steps[b], cores[b], offsets[b], whole, spacing, origin, inside, 1);
        if (blk.where.whole != layout.whole)
            value_error("write_blocks: a block's whole grid differs from the layout's");
        if (parts[b][0].dtype() != parts[0][0].dtype()) value_error("write_blocks: the chunks differ in dtype");
        columns.push_back(std::size_t(std::find(xs.begin(), xs.end(), blk.where.offset[0]) - xs.begin()));
        if (columns.back() == xs.size()) value_error("write_blocks: a block is off the layout's x chunking");
        wheres.push_back(blk.where);
        if (!counted[b]) value_error("write_blocks: a chunk's counts are None");
        counts.push_back(&counted[b]->counts);
    }
    const hmira::detail::mc::global_layout g{.vertex_start = layout.tables.vertex_start.data(),
                                             .triangle_start = layout.tables.triangle_start.data(),
                                             .columns = layout.tables.columns,
                                             .positions = layout.positions.get(),
                                             .triangles = reinterpret_cast<std::uint32_t*>(layout.triangles.get()),
                                             .swap_xz = true};
    hmira::result<void> r = hmira::fail(hmira::errc::invalid_argument, bad_dtype);
    {
        nb::gil_scoped_release release;
        block_input::for_dtype(parts[0][0].dtype(), [&](auto tag) {
            using V = decltype(tag);
            std::vector<std::vector<std::byte>> buffers(n);  // for chunks that cannot be read in place
            std::vector<c_block<V>> grids;
            for (std::size_t b = 0; b < n; ++b) grids.push_back(in[b].template grid<V>(buffers[b]));
            r = direct::write_blocks_into(std::span<const c_block<V>>(grids),
                                          std::span<const hmira::grid_block>(wheres),
                                          std::span<const std::size_t>(columns), g, in[0].options,
                                          std::span<direct::block_counts* const>(counts));
        });
    }
    check(r);
}

/// The finished result of a layout: (vertices, faces), taking over its arrays.
nb::tuple layout_result(layout_holder& layout) {
    if (!layout.positions || !layout.triangles) value_error("layout_result: the result was already taken");
    const std::size_t nv = layout.tables.vertices, nt = layout.tables.triangles;
    return nb::make_tuple(adopt_array(std::move(layout.positions), {nv, 3}),
                          adopt_array(std::move(layout.triangles), {nt, 3}));
}

using positions_array = nb::ndarray<const double, nb::ndim<2>, nb::c_contig, nb::device::cpu>;
using keys_array = nb::ndarray<const std::uint64_t, nb::ndim<1>, nb::c_contig, nb::device::cpu>;
using triangles_array = nb::ndarray<const std::int32_t, nb::ndim<2>, nb::c_contig, nb::device::cpu>;

nb::tuple merge_blocks(const std::vector<std::tuple<positions_array, keys_array, triangles_array, keys_array>>& blocks,
                       const std::vector<std::size_t>& whole, const std::vector<std::vector<std::size_t>>& chunks,
                       unsigned threads) {
    const hmira::grid_dims grid = index_triple(whole, "whole");
    if (chunks.size() != 3) value_error("merge_blocks: chunks needs 3 axes, got " + std::to_string(chunks.size()));
    // Chunk starts per grid axis (x is array axis 2), and the blocks in C order of the chunk grid.
    std::array<std::vector<std::size_t>, 3> starts;
    for (int a = 0; a < 3; ++a) {
        std::size_t at = 0;
        for (std::size_t c : chunks[std::size_t(2 - a)]) {
            starts[a].push_back(at);
            at += c;
        }
        if (at != grid[a] || starts[a].empty())
            value_error("merge_blocks: the chunks along array axis " + std::to_string(2 - a) + " sum to " +
                        std::to_string(at) + ", not " + std::to_string(grid[a]));
    }
    if (blocks.size() != starts[0].size() * starts[1].size() * starts[2].size())
        value_error("merge_blocks: " + std::to_string(blocks.size()) + " blocks for " +
                    std::to_string(starts[2].size()) + " x " + std::to_string(starts[1].size()) + " x " +
                    std::to_string(starts[0].size()) + " chunks");
    // The arrays are read in place: (n, 3) float64 rows are vec3<double>, and int32 indices
    // read as uint32 (a negative one becomes too large, which the merge refuses).
    static_assert(sizeof(vec3<double>) == 3 * sizeof(double) &&
                  sizeof(std::array<std::uint32_t, 3>) == 3 * sizeof(std::int32_t));
    std::vector<hmira::block_triangles_view<double>> views(blocks.size());
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        const auto& [pos, keys, tris, cubes] = blocks[b];
        if (pos.shape(1) != 3 || tris.shape(1) != 3)
            value_error("merge_blocks: block " + std::to_string(b) + ": positions and triangles need 3 columns");
        auto& v = views[b];
        v.positions = {reinterpret_cast<const vec3<double>*>(pos.data()), pos.shape(0)};
        v.keys = {keys.data(), keys.shape(0)};
        v.triangles = {reinterpret_cast<const std::array<std::uint32_t, 3>*>(tris.data()), tris.shape(0)};
        v.cubes = {cubes.data(), cubes.shape(0)};
        v.whole = grid;
        // Block b is chunk (b0, b1, b2) in C order over array axes; grid axis a is array axis 2 - a.
        std::size_t rest = b;
        for (int a = 0; a < 3; ++a) {
            const std::size_t c = rest % starts[a].size();
            rest /= starts[a].size();
            v.offset[a] = starts[a][c];
            v.size[a] = c + 1 < starts[a].size() ? starts[a][c + 1] - starts[a][c] + 1 : grid[a] - starts[a][c];
        }
    }
    // The output goes straight into arrays numpy will own, uninitialised: the merge writes
    // every element, in parallel, so nothing is zeroed or copied first. (Not numpy.empty: its
    // huge pages can stall in the kernel's compaction for longer than the merge takes.)
    std::unique_ptr<double[]> positions;
    std::unique_ptr<std::int32_t[]> triangles;
    std::size_t nv = 0, nt = 0;
    auto allocate = [&](std::size_t vertices, std::size_t faces) -> hmira::result<hmira::merged_storage<double>> {
        if (vertices > std::size_t(std::numeric_limits<std::int32_t>::max()))
            return hmira::fail(hmira::errc::unsupported,
                               "merge_blocks: " + std::to_string(vertices) + " vertices do not fit int32 face indices");
        nv = vertices;
        nt = faces;
        positions.reset(new double[3 * nv]);
        triangles.reset(new std::int32_t[3 * nt]);
        return hmira::merged_storage<double>{{reinterpret_cast<vec3<double>*>(positions.get()), nv},
                                             {reinterpret_cast<std::array<std::uint32_t, 3>*>(triangles.get()), nt}};
    };
    hmira::result<void> r;
    {
        nb::gil_scoped_release release;
        r = hmira::merge_blocks_into(std::span<const hmira::block_triangles_view<double>>(views), allocate,
                                     {.threads = threads});
    }
    check(r);
    return nb::make_tuple(adopt_array(std::move(positions), {nv, 3}), adopt_array(std::move(triangles), {nt, 3}));
}

}  // namespace

void bind_blocks(nb::module_& m) {
    const std::string below = name_of(hmira::marching_cubes_block_options{}.inside);
    m.def("_marching_cubes_block", &marching_cubes_block, nb::arg("parts"), nb::arg("iso"), nb::kw_only(),
          nb::arg("steps"), nb::arg("core"), nb::arg("offset"), nb::arg("whole"), nb::arg("spacing"), nb::arg("origin"),
          nb::arg("inside") = below, nb::arg("threads") = 1u,
          "Marching cubes of one chunk of shape `core` at `offset` in a volume of shape `whole`, with its one sample "
          "of overlap on "
          "the high sides given as `parts` (the chunk at step (0, 0, 0), one-sample slices of the neighbours at the "
          "steps "
          "towards them): (positions, keys, triangles, cube keys); see hmira.dask.");
    nb::class_<counts_holder>(m, "_BlockCounts", "What one block owns (hmira.dask, the direct path).");
    nb::class_<layout_holder>(m, "_BlockLayout", "The whole result's layout and arrays (hmira.dask, the direct path).");
    m.def("_count_block", &count_block, nb::arg("parts"), nb::arg("iso"), nb::kw_only(), nb::arg("steps"),
          nb::arg("core"), nb::arg("offset"), nb::arg("whole"), nb::arg("spacing"), nb::arg("origin"),
          nb::arg("inside") = below,
          "Counts what one chunk (given as for _marching_cubes_block) owns of the surface, for _layout_blocks; see "
          "hmira.dask.");
    m.def("_layout_blocks", &layout_blocks, nb::arg("blocks"), nb::kw_only(), nb::arg("whole"), nb::arg("x_chunks"),
          "Lays out the whole result from every chunk's _count_block (any order; `x_chunks`: the chunk sizes along "
          "array axis 2) "
          "and allocates it; see hmira.dask.");
    m.def("_write_block", &write_block, nb::arg("parts"), nb::arg("iso"), nb::kw_only(), nb::arg("steps"),
          nb::arg("core"), nb::arg("offset"), nb::arg("whole"), nb::arg("spacing"), nb::arg("origin"),
          nb::arg("inside") = below, nb::arg("layout"), nb::arg("counted").none() = nb::none(),
          "Writes one chunk's share of the surface straight into a _layout_blocks result, reusing the chunk's "
          "_count_block "
          "(`counted`, whose counted rows it takes) when given; see hmira.dask.");
    m.def("_write_blocks", &write_blocks, nb::arg("parts"), nb::arg("iso"), nb::kw_only(), nb::arg("steps"),
          nb::arg("cores"), nb::arg("offsets"), nb::arg("whole"), nb::arg("spacing"), nb::arg("origin"),
          nb::arg("inside") = below, nb::arg("layout"), nb::arg("counted"),
          "_write_block of several chunks (lists of each chunk's parts, steps, core, offset and _count_block), row by "
          "row in turn, "
          "so that a row of chunks along x writes long runs of the result; see hmira.dask.");
    m.def("_layout_result", &layout_result, nb::arg("layout"),
          "The (vertices, faces) a _layout_blocks result holds once every chunk was written; see hmira.dask.");
    m.def(
        "_merge_blocks", &merge_blocks, nb::arg("blocks"), nb::kw_only(), nb::arg("whole"), nb::arg("chunks"),
        nb::arg("threads") = 0u,
        "Welds (positions, keys, triangles, cube keys) blocks, one per chunk in C order of the chunk grid (`chunks` as "
        "dask.array.Array.chunks), into the whole volume's (vertices, faces), in parallel on `threads` threads (0: "
        "all); see "
        "hmira.dask.");
}

}  // namespace hmira_py
