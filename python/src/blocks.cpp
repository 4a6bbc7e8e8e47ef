// python/src/blocks.cpp
// Marching cubes by blocks for hmira.dask: one block of a larger C-ordered volume to keyed
// arrays, and the weld of such blocks into the whole volume's (V, F).
#include "common.hpp"

#include <array>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

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
    hmira::grid_dims dims() const { return size; }
    vec3<double> origin() const { return at; }
    vec3<double> spacing() const { return step; }
    double value(std::size_t i, std::size_t j, std::size_t k) const { return static_cast<double>(samples[i + size[0] * (j + size[1] * k)]); }
    const V* data() const { return samples; }
};

using block_volume = nb::ndarray<nb::ro, nb::ndim<3>, nb::c_contig, nb::device::cpu>;

template <class Scalar, class Container>
nb::ndarray<nb::numpy, Scalar> adopt(Container&& c, std::initializer_list<std::size_t> shape) {
    auto* owned = new Container(std::move(c));
    nb::capsule owner(owned, [](void* p) noexcept { delete static_cast<Container*>(p); });
    return nb::ndarray<nb::numpy, Scalar>(reinterpret_cast<Scalar*>(owned->data()), shape, owner);
}

std::array<double, 3> triple(const std::vector<double>& v, const char* name) {
    if (v.size() != 3) value_error(std::string("marching_cubes_block: ") + name + " needs 3 values, got " + std::to_string(v.size()));
    return {v[0], v[1], v[2]};
}
hmira::grid_dims index_triple(const std::vector<std::size_t>& v, const char* name) {
    if (v.size() != 3) value_error(std::string("marching_cubes_block: ") + name + " needs 3 values, got " + std::to_string(v.size()));
    // Array axes (0, 1, 2) are the grid's (z, y, x).
    return {v[2], v[1], v[0]};
}

nb::tuple marching_cubes_block(const block_volume& volume, double iso, const std::vector<std::size_t>& offset,
                               const std::vector<std::size_t>& whole, const std::vector<double>& spacing,
                               const std::vector<double>& origin, const std::string& inside, unsigned threads) {
    const auto sp = triple(spacing, "spacing"), org = triple(origin, "origin");
    hmira::iso_inside side = hmira::iso_inside::below;
    if (inside == "above") side = hmira::iso_inside::above;
    else if (inside != "below") value_error("marching_cubes_block: inside must be 'below' or 'above', got '" + inside + "'");
    const hmira::grid_block where{.offset = index_triple(offset, "offset"), .whole = index_triple(whole, "whole")};
    const hmira::grid_dims size{volume.shape(2), volume.shape(1), volume.shape(0)};
    const vec3<double> at{org[2], org[1], org[0]}, step{sp[2], sp[1], sp[0]};
    const hmira::marching_cubes_block_options options{.iso = iso, .inside = side, .threads = threads};
    hmira::result<hmira::block_triangles<double>> r = hmira::fail(hmira::errc::invalid_argument, "");
    const auto dt = volume.dtype();
    {
        nb::gil_scoped_release release;
        auto run = [&](auto tag) {
            using V = decltype(tag);
            const c_block<V> g{static_cast<const V*>(volume.data()), size, at, step};
            r = hmira::marching_cubes_block<double>(g, where, options);
        };
        if (dt == nb::dtype<float>()) run(float{});
        else if (dt == nb::dtype<double>()) run(double{});
        else if (dt == nb::dtype<std::uint8_t>()) run(std::uint8_t{});
        else if (dt == nb::dtype<std::uint16_t>()) run(std::uint16_t{});
        else if (dt == nb::dtype<std::int16_t>()) run(std::int16_t{});
        else r = hmira::fail(hmira::errc::invalid_argument, "marching_cubes_block: volume dtype must be float32, float64, uint8, uint16 or int16");
    }
    auto b = take(std::move(r));
    // Back to array axes, as hmira.marching_cubes does for a C-ordered volume: swapping two
    // axes mirrors the surface, so each triangle is reversed to keep its winding.
    for (auto& p : b.positions) std::swap(p.x, p.z);
    for (auto& t : b.triangles) std::swap(t[1], t[2]);
    const std::size_t nv = b.positions.size(), nt = b.triangles.size();
    return nb::make_tuple(adopt<double>(std::move(b.positions), {nv, 3}), adopt<std::uint64_t>(std::move(b.keys), {nv}),
                          adopt<std::int32_t>(std::move(b.triangles), {nt, 3}), adopt<std::uint64_t>(std::move(b.cubes), {nt}));
}

using positions_array = nb::ndarray<const double, nb::ndim<2>, nb::c_contig, nb::device::cpu>;
using keys_array = nb::ndarray<const std::uint64_t, nb::ndim<1>, nb::c_contig, nb::device::cpu>;
using triangles_array = nb::ndarray<const std::int32_t, nb::ndim<2>, nb::c_contig, nb::device::cpu>;

nb::tuple merge_blocks(const std::vector<std::tuple<positions_array, keys_array, triangles_array, keys_array>>& blocks,
                       const std::vector<std::size_t>& whole) {
    const hmira::grid_dims grid = index_triple(whole, "whole");
    std::vector<hmira::block_triangles<double>> in(blocks.size());
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        const auto& [pos, keys, tris, cubes] = blocks[b];
        if (pos.shape(1) != 3 || tris.shape(1) != 3)
            value_error("merge_blocks: block " + std::to_string(b) + ": positions and triangles need 3 columns");
        auto& out = in[b];
        out.positions.resize(pos.shape(0));
        for (std::size_t v = 0; v < pos.shape(0); ++v) out.positions[v] = {pos.data()[3 * v], pos.data()[3 * v + 1], pos.data()[3 * v + 2]};
        out.keys.assign(keys.data(), keys.data() + keys.shape(0));
        out.triangles.resize(tris.shape(0));
        for (std::size_t t = 0; t < tris.shape(0); ++t)
            for (int c = 0; c < 3; ++c) {
                const std::int32_t v = tris.data()[3 * t + c];
                out.triangles[t][c] = v < 0 ? std::numeric_limits<std::uint32_t>::max() : std::uint32_t(v);
            }
        out.cubes.assign(cubes.data(), cubes.data() + cubes.shape(0));
        out.whole = grid;
    }
    hmira::result<hmira::indexed_triangles<double>> r = hmira::fail(hmira::errc::invalid_argument, "");
    {
        nb::gil_scoped_release release;
        r = hmira::merge_blocks(in);
        in = {};
    }
    auto tri = take(std::move(r));
    if (tri.positions.size() > std::size_t(std::numeric_limits<std::int32_t>::max()))
        value_error("merge_blocks: " + std::to_string(tri.positions.size()) + " vertices do not fit int32 face indices");
    const std::size_t nv = tri.positions.size(), nt = tri.triangles.size();
    return nb::make_tuple(adopt<double>(std::move(tri.positions), {nv, 3}), adopt<std::int32_t>(std::move(tri.triangles), {nt, 3}));
}

}  // namespace

void bind_blocks(nb::module_& m) {
    m.def("_marching_cubes_block", &marching_cubes_block, nb::arg("volume"), nb::arg("iso"), nb::kw_only(), nb::arg("offset"),
          nb::arg("whole"), nb::arg("spacing"), nb::arg("origin"), nb::arg("inside") = "below", nb::arg("threads") = 1u,
          "Marching cubes of one C-ordered block (plus one sample of overlap on its high sides) at `offset` in a volume of "
          "shape `whole`: (positions, keys, triangles, cube keys); see hmira.dask.");
    m.def("_merge_blocks", &merge_blocks, nb::arg("blocks"), nb::kw_only(), nb::arg("whole"),
          "Welds (positions, keys, triangles, cube keys) blocks into the whole volume's (vertices, faces); see hmira.dask.");
}

}  // namespace hmira_py
