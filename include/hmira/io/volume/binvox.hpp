// hmira/io/volume/binvox.hpp
// Writes a voxel grid as .binvox, the run-length-encoded occupancy format most voxel tools
// read (binvox, viewvox, trimesh, binvox-rw-py).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <sstream>
#include <string>

#include "../../core/result.hpp"
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

}  // namespace hmira::io
