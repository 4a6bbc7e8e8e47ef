// hmira/algorithms/conversion/iso_level.hpp
// The iso value every front end uses when the caller gives none: the midpoint of the samples'
// range, as scikit-image's marching_cubes, so that a default never lies outside the data (an
// iso given outside it is refused by marching_cubes_indexed, with the range in the message).
#pragma once

#include <cmath>
#include <cstddef>
#include <string>
#include <utility>

#include "../../core/result.hpp"
#include "../../grids/voxel_grid.hpp"

namespace hmira {

/// The smallest and largest sample of a grid.
struct sample_range {
    double min = 0;  ///< smallest sample
    double max = 0;  ///< largest sample
    /// The iso value used when none is given: (min + max) / 2, computed without overflow.
    double midpoint() const noexcept { return min / 2 + max / 2; }
    /// True when `iso` lies in [min, max] (the ends included: an iso equal to min or max is accepted).
    bool contains(double iso) const noexcept { return min <= iso && iso <= max; }
};

/// The range of the samples of `grid`.
/// \pre none.
/// Complexity: O(N) for N samples, one serial pass.
/// Errors (invalid_argument): an empty grid; a NaN or infinite sample, named by its (i, j, k).
template <voxel_grid G>
[[nodiscard]] result<sample_range> samples_range(const G& grid);

/// The iso value marching cubes uses over `grid` when the caller gives none: the midpoint of the
/// samples' range, so that a surface exists whenever the samples are not all equal. (A given iso
/// needs no check here: marching_cubes_indexed refuses one outside the range.)
/// \pre none.
/// Complexity: O(N), one pass (see samples_range).
/// Errors: those of samples_range.
template <voxel_grid G>
[[nodiscard]] result<double> default_iso(const G& grid);

template <voxel_grid G>
result<sample_range> samples_range(const G& grid) {
    const auto d = grid.dims();
    if (d[0] == 0 || d[1] == 0 || d[2] == 0) return fail(errc::invalid_argument, "the volume has no samples");
    sample_range r{static_cast<double>(grid.value(0, 0, 0)), static_cast<double>(grid.value(0, 0, 0))};
    for (std::size_t k = 0; k < d[2]; ++k)
        for (std::size_t j = 0; j < d[1]; ++j)
            for (std::size_t i = 0; i < d[0]; ++i) {
                const double v = static_cast<double>(grid.value(i, j, k));
                if (!std::isfinite(v))
                    return fail(errc::invalid_argument, "sample (" + std::to_string(i) + ", " + std::to_string(j) +
                                                            ", " + std::to_string(k) + ") is " +
                                                            (std::isnan(v) ? "nan"
                                                             : v > 0       ? "inf"
                                                                           : "-inf") +
                                                            "; every sample must be finite");
                if (v < r.min) r.min = v;
                if (v > r.max) r.max = v;
            }
    return r;
}

template <voxel_grid G>
result<double> default_iso(const G& grid) {
    auto range = samples_range(grid);
    if (!range) return range.error();
    return range->midpoint();
}

}  // namespace hmira
