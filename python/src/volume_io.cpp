// python/src/volume_io.cpp
// Reading the volumes `hmira mc` reads (.inr, .inr.gz, and .raw with its grid given) into numpy
// with the library's readers, for hmira.read_volume. A volume comes back as an (nx, ny, nz)
// Fortran-ordered array over the reader's own storage (no copy), so volume[i, j, k] is the
// sample at origin + spacing * (i, j, k), as marching_cubes reads it.
#include "common.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <hmira/grids/dense_grid.hpp>
#include <hmira/io/volume/inr.hpp>
#include <hmira/io/volume/raw.hpp>

namespace hmira_py {

namespace {

/// (samples, spacing, origin), the samples an array owning the grid.
template <class T>
nb::tuple volume_tuple(hmira::dense_grid<T>&& grid) {
    const auto g = grid.geometry();
    auto* held = new hmira::dense_grid<T>(std::move(grid));
    nb::capsule owner(held, [](void* p) noexcept { delete static_cast<hmira::dense_grid<T>*>(p); });
    auto samples =
        nb::ndarray<nb::numpy, T, nb::ndim<3>, nb::f_contig>(held->data(), {g.dims[0], g.dims[1], g.dims[2]}, owner);
    return nb::make_tuple(samples, nb::make_tuple(g.spacing.x, g.spacing.y, g.spacing.z),
                          nb::make_tuple(g.origin.x, g.origin.y, g.origin.z));
}

nb::tuple read_inr(const std::string& path) {
    hmira::result<hmira::dense_grid<float>> r = hmira::fail(hmira::errc::invalid_argument, "");
    {
        nb::gil_scoped_release release;
        r = hmira::io::read_inr(path);
    }
    return volume_tuple(take(std::move(r)));
}

template <class T>
nb::tuple read_raw_as(const std::string& path, const hmira::grid_geometry& g, bool big_endian) {
    hmira::result<hmira::dense_grid<T>> r = hmira::fail(hmira::errc::invalid_argument, "");
    {
        nb::gil_scoped_release release;
        hmira::io::raw_options o;
        o.big_endian = big_endian;
        r = hmira::io::read_raw<T>(path, g, o);
    }
    return volume_tuple(take(std::move(r)));
}

nb::tuple read_raw(const std::string& path, const std::vector<std::size_t>& dims, const std::string& type,
                   const std::vector<double>& spacing, const std::vector<double>& origin, bool big_endian) {
    if (dims.size() != 3 || spacing.size() != 3 || origin.size() != 3)
        value_error("read_volume: dims, spacing and origin need 3 values each");
    const hmira::grid_geometry g{
        {dims[0], dims[1], dims[2]}, {origin[0], origin[1], origin[2]}, {spacing[0], spacing[1], spacing[2]}};
    if (type == "uint8") return read_raw_as<std::uint8_t>(path, g, big_endian);
    if (type == "int8") return read_raw_as<std::int8_t>(path, g, big_endian);
    if (type == "uint16") return read_raw_as<std::uint16_t>(path, g, big_endian);
    if (type == "int16") return read_raw_as<std::int16_t>(path, g, big_endian);
    if (type == "uint32") return read_raw_as<std::uint32_t>(path, g, big_endian);
    if (type == "int32") return read_raw_as<std::int32_t>(path, g, big_endian);
    if (type == "float32") return read_raw_as<float>(path, g, big_endian);
    if (type == "float64") return read_raw_as<double>(path, g, big_endian);
    value_error("read_volume: unknown sample type '" + type +
                "' (supported: uint8, int8, uint16, int16, uint32, int32, float32, float64)");
}

}  // namespace

void bind_volume_io(nb::module_& m) {
    m.def("_read_inr", &read_inr, nb::arg("path"),
          "An .inr or .inr.gz volume as (float32 samples (nx, ny, nz), spacing, origin).");
    m.def("_read_raw", &read_raw, nb::arg("path"), nb::kw_only(), nb::arg("dims"), nb::arg("type"), nb::arg("spacing"),
          nb::arg("origin"), nb::arg("big_endian"),
          "A .raw volume (x fastest, no header) as (samples (nx, ny, nz), spacing, origin).");
}

}  // namespace hmira_py
