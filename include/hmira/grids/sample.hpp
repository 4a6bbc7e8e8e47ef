// hmira/grids/sample.hpp
// Turns an implicit function f(x, y, z) (thesis 1.1.2) into a voxel map by evaluating it at
// every sample position, in parallel over z-slices when oneTBB is available.
#pragma once

#include <concepts>
#include <cstddef>

#include "../algorithms/conversion/detail/parallel.hpp"
#include "../core/result.hpp"
#include "../core/vec3.hpp"
#include "dense_grid.hpp"
#include "voxel_grid.hpp"

namespace hmira {

/// Writes f(position(i, j, k)) into every sample of `grid`. f takes a vec3<double> and
/// returns something convertible to G::value_type; it must be safe to call concurrently.
/// O(N) evaluations of f for N samples; parallel over z-slices; every sample is written by
/// exactly one call, so the result is the same for any thread count.
template <writable_voxel_grid G, class F>
    requires std::invocable<const F&, vec3<double>>
void sample_into(G& grid, const F& f) {
    const auto g = geometry_of(grid);
    detail::parallel_chunks(g.dims[2], 1, [&](std::size_t k0, std::size_t k1) {
        for (std::size_t k = k0; k < k1; ++k)
            for (std::size_t j = 0; j < g.dims[1]; ++j)
                for (std::size_t i = 0; i < g.dims[0]; ++i)
                    grid.set(i, j, k, static_cast<typename G::value_type>(f(g.position(i, j, k))));
    });
}

/// A new dense_grid<T> of geometry `g` holding f at every sample.
/// Errors: invalid_argument for an unusable geometry (zero dimension, spacing not positive).
template <class T = float, class F>
    requires std::invocable<const F&, vec3<double>>
result<dense_grid<T>> sample_function(const grid_geometry& g, const F& f) {
    if (auto ok = check_grid_geometry(g, "sample_function"); !ok) return ok.error();
    dense_grid<T> grid(g);
    sample_into(grid, f);
    return grid;
}

/// The geometry of an n x n x n grid whose samples span the box [lo, hi] on every axis
/// (the same bounds on x, y and z), a convenience for sampling the shapes below.
inline grid_geometry cube_geometry(std::size_t n, double lo, double hi) {
    const double h = n > 1 ? (hi - lo) / double(n - 1) : 1.0;
    return {{n, n, n}, {lo, lo, lo}, {h, h, h}};
}

}  // namespace hmira
