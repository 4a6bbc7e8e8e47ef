// hmira/grids/voxel_grid.hpp
// What a voxel map is to the algorithms (thesis 2.3.2): dimensions, origin, spacing and a value
// at (i, j, k). Marching cubes reads any voxel_grid; voxelization writes any writable one.
#pragma once

#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <limits>
#include <string>

#include "../core/result.hpp"
#include "../core/vec3.hpp"

namespace hmira {

/// Sample (i, j, k) of a grid lies at origin + (i, j, k) * spacing (component-wise); i runs
/// fastest in memory for the grids that have memory.
using grid_dims = std::array<std::size_t, 3>;

/// A readable voxel map: `g.dims()`, `g.origin()`, `g.spacing()` and `g.value(i, j, k)`
/// (convertible to double), with `G::value_type` naming the stored type.
template <class G>
concept voxel_grid = requires(const G& g, std::size_t i) {
    typename G::value_type;
    { g.dims() } -> std::convertible_to<grid_dims>;
    { g.origin() } -> std::convertible_to<vec3<double>>;
    { g.spacing() } -> std::convertible_to<vec3<double>>;
    { g.value(i, i, i) } -> std::convertible_to<double>;
};

/// A voxel map that can also be written: `g.set(i, j, k, v)` with v a `G::value_type`.
template <class G>
concept writable_voxel_grid =
    voxel_grid<G> && requires(G& g, std::size_t i, typename G::value_type v) { g.set(i, i, i, v); };

/// A voxel map whose samples lie in one array, x fastest then y then z: `g.data()` points at
/// sample (0, 0, 0). Algorithms read such grids row by row instead of sample by sample.
template <class G>
concept contiguous_voxel_grid = voxel_grid<G> && requires(const G& g) {
    { g.data() } -> std::convertible_to<const typename G::value_type*>;
};

/// The shape of a grid without its values: what voxelize() is asked to fill, and what a
/// reader reports.
struct grid_geometry {
    grid_dims dims{0, 0, 0};        ///< samples along x, y and z
    vec3<double> origin{0, 0, 0};   ///< position of sample (0, 0, 0)
    vec3<double> spacing{1, 1, 1};  ///< distance between neighbouring samples along each axis

    /// Number of samples, dims[0] * dims[1] * dims[2].
    std::size_t size() const noexcept { return dims[0] * dims[1] * dims[2]; }
    /// Position of sample (i, j, k).
    vec3<double> position(std::size_t i, std::size_t j, std::size_t k) const noexcept {
        return {origin.x + double(i) * spacing.x, origin.y + double(j) * spacing.y, origin.z + double(k) * spacing.z};
    }
};

/// The geometry of any grid.
template <voxel_grid G>
grid_geometry geometry_of(const G& g) {
    return {g.dims(), g.origin(), g.spacing()};
}

/// Checks that a geometry describes a usable grid: every dimension at least `min_dim`, the
/// sample count representable, spacing finite and positive, origin finite. `who` prefixes the
/// message ("marching_cubes: ...").
inline result<void> check_grid_geometry(const grid_geometry& g, const std::string& who, std::size_t min_dim = 1) {
    static constexpr const char* axis = "xyz";
    for (int a = 0; a < 3; ++a) {
        if (g.dims[a] < min_dim)
            return fail(errc::invalid_argument, who + ": grid dimension " + std::string(1, axis[a]) + " is " +
                                                    std::to_string(g.dims[a]) + ", needs at least " +
                                                    std::to_string(min_dim));
        if (!(g.spacing[a] > 0) || !std::isfinite(g.spacing[a]))
            return fail(errc::invalid_argument, who + ": grid spacing along " + std::string(1, axis[a]) +
                                                    " must be finite and positive, got " +
                                                    std::to_string(g.spacing[a]));
        if (!std::isfinite(g.origin[a])) return fail(errc::invalid_argument, who + ": grid origin is not finite");
    }
    // Indices are 32-bit inside the algorithms; a larger grid would not fit in memory anyway.
    if (g.dims[0] >= (1u << 30) || g.dims[1] >= (1u << 30) || g.dims[2] >= (1u << 30) ||
        double(g.dims[0]) * double(g.dims[1]) * double(g.dims[2]) >
            double(std::numeric_limits<std::uint32_t>::max()) * 16.0)
        return fail(errc::invalid_argument, who + ": grid too large");
    return {};
}

}  // namespace hmira
