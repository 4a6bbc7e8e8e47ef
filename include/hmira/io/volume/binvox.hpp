// hmira/io/volume/binvox.hpp
// Reads and writes .binvox, the run-length-encoded occupancy format most voxel tools read
// (binvox, viewvox, trimesh, binvox-rw-py).
#pragma once

#include <algorithm>
#include <cmath>
#include <charconv>
#include <cstdint>
#include <filesystem>
#include <sstream>
#include <string>
#include <string_view>

#include "../../core/result.hpp"
#include "../../grids/bit_grid.hpp"
#include "../../grids/voxel_grid.hpp"
#include "../detail/files.hpp"

namespace hmira::io {

/// Writes the occupancy of `grid` (a sample is set when its value is non-zero) as binvox 1.
/// Binvox grids are cubes of one spacing: a non-cubic grid is padded with empty voxels up to
/// its largest dimension. Sample (i, j, k) is taken as the centre of voxel (i, j, k); the
/// header's translate/scale map voxel corners back to the grid's coordinates.
/// Errors: invalid_argument for an empty grid or unequal spacing; io_error on a failed write
/// (atomic: an existing file is left as it was). O(N).
template <voxel_grid G>
result<void> write_binvox(const G& grid, const std::filesystem::path& path) {
    const auto g = geometry_of(grid);
    if (auto ok = check_grid_geometry(g, "write_binvox " + path.string()); !ok) return ok.error();
    const double h = g.spacing.x;
    if (std::abs(g.spacing.y - h) > 1e-9 * h || std::abs(g.spacing.z - h) > 1e-9 * h)
        return fail(errc::invalid_argument, "write_binvox " + path.string() + ": binvox needs one spacing on all axes");
    const std::size_t d = std::max({g.dims[0], g.dims[1], g.dims[2]});
    return detail::write_file_atomically(path, [&](std::ostream& out) {
        std::ostringstream head;
        head.precision(17);
        head << "#binvox 1\ndim " << d << ' ' << d << ' ' << d << "\ntranslate " << g.origin.x - 0.5 * h << ' '
             << g.origin.y - 0.5 * h << ' ' << g.origin.z - 0.5 * h << "\nscale " << double(d) * h << "\ndata\n";
        out << head.str();
        // Runs of (value, count <= 255); x slowest, then z, y fastest.
        std::string runs;
        unsigned char value = 0, count = 0;
        auto push = [&](unsigned char v) {
            if (count > 0 && (v != value || count == 255)) {
                runs.push_back(static_cast<char>(value));
                runs.push_back(static_cast<char>(count));
                count = 0;
            }
            value = v;
            ++count;
        };
        for (std::size_t i = 0; i < d; ++i)
            for (std::size_t k = 0; k < d; ++k)
                for (std::size_t j = 0; j < d; ++j) {
                    const bool inside = i < g.dims[0] && j < g.dims[1] && k < g.dims[2] && grid.value(i, j, k) != 0;
                    push(inside ? 1 : 0);
                }
        if (count) {
            runs.push_back(static_cast<char>(value));
            runs.push_back(static_cast<char>(count));
        }
        out.write(runs.data(), static_cast<std::streamsize>(runs.size()));
        return bool(out);
    });
}

/// Options of read_binvox().
struct binvox_options {
    /// Largest input read from a non-regular file (pipe, device, FIFO) before giving up with
    /// an error naming the file and the limit, as read_options::max_input_bytes.
    std::uint64_t max_input_bytes = detail::default_max_input_bytes;
};

/// Parses binvox bytes into an occupancy grid of dims d x d x d: sample (i, j, k) is the
/// centre of voxel (i, j, k), so the origin is translate + scale / (2 d) and the spacing
/// scale / d (what write_binvox writes). The runs are checked to cover exactly d^3 voxels
/// before the grid is allocated, so a short file cannot make a large grid.
/// Errors: parse_error naming the header line or the byte offset: a missing or bad header
/// (dim, translate, scale not finite or not positive), a run of length 0, runs covering
/// fewer or more voxels than d^3, a value other than 0 or 1. Complexity: O(bytes + d^3).
inline result<bit_grid> parse_binvox(std::string_view bytes, const std::string& name) {
    detail::line_reader lines(bytes);
    std::string_view line;
    if (!lines.next(line) || line.substr(0, 8) != "#binvox ")
        return fail(errc::parse_error, name + ":1: not a binvox file (the first line must be '#binvox 1')");
    std::size_t d[3] = {0, 0, 0};
    double translate[3] = {0, 0, 0}, scale = 1;
    bool have_dim = false;
    for (;;) {
        if (!lines.next(line)) return fail(errc::parse_error, name + ": file ends inside the header (no 'data' line)");
        const auto where = name + ":" + std::to_string(lines.line_number());
        std::string_view rest = line;
        const auto key = detail::next_token(rest);
        auto numbers = [&](double* out, int n) -> bool {
            for (int a = 0; a < n; ++a) {
                const auto tok = detail::next_token(rest);
                const auto r = std::from_chars(tok.data(), tok.data() + tok.size(), out[a]);
                if (tok.empty() || r.ec != std::errc() || r.ptr != tok.data() + tok.size() || !std::isfinite(out[a]))
                    return false;
            }
            return detail::next_token(rest).empty();
        };
        if (key == "data") break;
        if (key == "dim") {
            double v[3];
            if (!numbers(v, 3))
                return fail(errc::parse_error,
                            where + ": expected 'dim <d> <d> <d>', found '" + std::string(line.substr(0, 60)) + "'");
            for (int a = 0; a < 3; ++a) {
                if (!(v[a] >= 1 && v[a] <= 1024) || v[a] != std::floor(v[a]))
                    return fail(errc::parse_error,
                                where + ": a binvox dimension must be a whole number from 1 to 1024, found '" +
                                    std::string(line.substr(0, 60)) + "'");
                d[a] = static_cast<std::size_t>(v[a]);
            }
            have_dim = true;
        } else if (key == "translate") {
            if (!numbers(translate, 3))
                return fail(errc::parse_error, where + ": expected 'translate <x> <y> <z>' with finite numbers");
        } else if (key == "scale") {
            if (!numbers(&scale, 1) || !(scale > 0))
                return fail(errc::parse_error, where + ": expected 'scale <s>' with s finite and positive");
        } else if (!key.empty()) {
            return fail(errc::parse_error,
                        where + ": unexpected header line '" + std::string(line.substr(0, 60)) + "'");
        }
    }
    if (!have_dim) return fail(errc::parse_error, name + ": the header has no 'dim' line");
    if (d[0] != d[1] || d[1] != d[2])
        return fail(errc::unsupported, name + ": dims " + std::to_string(d[0]) + " " + std::to_string(d[1]) + " " +
                                           std::to_string(d[2]) + " are not a cube");
    const std::size_t n = d[0] * d[1] * d[2], start = lines.position();
    const std::string_view runs = bytes.substr(start);
    if (runs.size() % 2 != 0)
        return fail(errc::parse_error, name + ": byte offset " + std::to_string(bytes.size() - 1) +
                                           ": a run without its length (odd data size)");
    // First pass: the runs must cover exactly n voxels.
    std::size_t covered = 0;
    for (std::size_t q = 0; q < runs.size(); q += 2) {
        const auto value = static_cast<unsigned char>(runs[q]), count = static_cast<unsigned char>(runs[q + 1]);
        const auto at = name + ": byte offset " + std::to_string(start + q);
        if (value > 1)
            return fail(errc::parse_error, at + ": voxel value " + std::to_string(value) + ", expected 0 or 1");
        if (count == 0) return fail(errc::parse_error, at + ": a run of length 0");
        if (covered + count > n)
            return fail(errc::parse_error,
                        at + ": the runs cover more than the " + std::to_string(n) + " voxels of the header's dims");
        covered += count;
    }
    if (covered != n)
        return fail(errc::parse_error, name + ": the runs cover " + std::to_string(covered) + " of the " +
                                           std::to_string(n) + " voxels (truncated file?)");
    const double h = scale / static_cast<double>(d[0]);
    const grid_geometry g{
        {d[0], d[1], d[2]}, {translate[0] + 0.5 * h, translate[1] + 0.5 * h, translate[2] + 0.5 * h}, {h, h, h}};
    if (auto ok = check_grid_geometry(g, name); !ok) return fail(errc::parse_error, ok.error().message);
    bit_grid grid(g);
    // x slowest, then z, y fastest.
    std::size_t v = 0;
    for (std::size_t q = 0; q < runs.size(); q += 2) {
        const auto value = static_cast<unsigned char>(runs[q]), count = static_cast<unsigned char>(runs[q + 1]);
        for (unsigned c = 0; c < count; ++c, ++v)
            if (value) grid.set(v / (d[0] * d[0]), v % d[0], (v / d[0]) % d[0], 1);
    }
    return grid;
}

/// Reads a .binvox file (see parse_binvox). Errors: io_error when the file cannot be read
/// (or a non-regular file passes options.max_input_bytes); the parse errors.
inline result<bit_grid> read_binvox(const std::filesystem::path& path, const binvox_options& options = {}) {
    auto file = detail::input_file::open(path, options.max_input_bytes);
    if (!file) return file.error();
    return parse_binvox(file->text(), path.string());
}

}  // namespace hmira::io
