// hmira/io/volume/raw.hpp
// Raw volumes: the samples alone, x fastest, with dimensions, spacing and sample type given by
// the caller. The simplest exchange with other tools (numpy's tofile/fromfile, VTK's image
// readers) and what the marching-cubes benchmark hands to the peers.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <type_traits>
#include <vector>

#include "../../core/result.hpp"
#include "../../grids/dense_grid.hpp"
#include "../../grids/voxel_grid.hpp"
#include "../detail/files.hpp"

namespace hmira::io {

/// Options of read_raw() and write_raw().
struct raw_options {
    /// Byte order of multi-byte samples in the file.
    bool big_endian = false;
    /// Reading only: largest input read from a non-regular file (pipe, device, FIFO) before
    /// giving up with an error naming the file and the limit; a regular file is read up to
    /// its size. The same limit as read_options::max_input_bytes.
    std::uint64_t max_input_bytes = detail::default_max_input_bytes;
};

namespace detail {

template <class T>
T byteswap_value(T v) {
    unsigned char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
    std::memcpy(&v, b, sizeof(T));
    return v;
}

// Converts `bytes` holding g.size() samples of type T into a dense_grid<T>; NaN is refused.
template <class T>
result<dense_grid<T>> samples_to_grid(const char* bytes, const grid_geometry& g, bool swap, const std::string& name) {
    dense_grid<T> grid(g);
    T* out = grid.data();
    std::memcpy(static_cast<void*>(out), bytes, g.size() * sizeof(T));
    if (swap)
        for (std::size_t n = 0; n < g.size(); ++n) out[n] = byteswap_value(out[n]);
    if constexpr (std::is_floating_point_v<T>) {
        for (std::size_t n = 0; n < g.size(); ++n)
            if (std::isnan(out[n])) {
                const std::size_t i = n % g.dims[0], j = (n / g.dims[0]) % g.dims[1], k = n / (g.dims[0] * g.dims[1]);
                return fail(errc::parse_error,
                            name + ": sample (" + std::to_string(i) + ", " + std::to_string(j) + ", " +
                                std::to_string(k) + ") is NaN",
                            static_cast<long long>(n));
            }
    }
    return grid;
}

}  // namespace detail

/// Reads a raw volume of samples of type T with the geometry `g`.
/// Errors: invalid_argument for an unusable geometry (zero dimension, spacing not positive);
/// io_error if the file cannot be read, or is a non-regular file longer than
/// options.max_input_bytes; parse_error if its size is not exactly
/// g.size() * sizeof(T) bytes (truncated, or the wrong dimensions or type), or a
/// floating-point sample is NaN. O(N).
template <class T>
result<dense_grid<T>> read_raw(const std::filesystem::path& path, const grid_geometry& g,
                               const raw_options& options = {}) {
    static_assert(std::is_arithmetic_v<T>, "read_raw: samples must be a number type");
    if (auto ok = check_grid_geometry(g, "read_raw " + path.string()); !ok) return ok.error();
    auto file = detail::input_file::open(path, options.max_input_bytes);
    if (!file) return file.error();
    const auto bytes = file->text();
    const std::size_t expected = g.size() * sizeof(T);
    if (bytes.size() != expected)
        return fail(errc::parse_error, path.string() + ": holds " + std::to_string(bytes.size()) + " bytes, but " +
                                           std::to_string(g.dims[0]) + " x " + std::to_string(g.dims[1]) + " x " +
                                           std::to_string(g.dims[2]) + " samples of " + std::to_string(sizeof(T)) +
                                           " bytes need " + std::to_string(expected) +
                                           (bytes.size() < expected ? " (truncated file?)" : ""));
    const bool swap = sizeof(T) > 1 && (options.big_endian != (std::endian::native == std::endian::big));
    return detail::samples_to_grid<T>(bytes.data(), g, swap, path.string());
}

/// Writes every sample of `grid` as its value_type, x fastest, atomically (a failed write
/// leaves an existing file unchanged). The geometry is not stored: keep it alongside.
/// Errors: invalid_argument for an empty grid; io_error when writing fails. O(N).
template <voxel_grid G>
result<void> write_raw(const G& grid, const std::filesystem::path& path, const raw_options& options = {}) {
    using V = typename G::value_type;
    const auto g = geometry_of(grid);
    if (auto ok = check_grid_geometry(g, "write_raw " + path.string()); !ok) return ok.error();
    const bool swap = sizeof(V) > 1 && (options.big_endian != (std::endian::native == std::endian::big));
    return detail::write_file_atomically(path, [&](std::ostream& out) {
        std::vector<V> row(g.dims[0]);
        for (std::size_t k = 0; k < g.dims[2]; ++k)
            for (std::size_t j = 0; j < g.dims[1]; ++j) {
                for (std::size_t i = 0; i < g.dims[0]; ++i) {
                    const V v = static_cast<V>(grid.value(i, j, k));
                    row[i] = swap ? detail::byteswap_value(v) : v;
                }
                out.write(reinterpret_cast<const char*>(row.data()),
                          static_cast<std::streamsize>(row.size() * sizeof(V)));
            }
        return bool(out);
    });
}

}  // namespace hmira::io
