// hmira/grids/dense_grid.hpp
// A grid that owns its samples in one array (x fastest), and a non-owning view that adapts a
// user's own array (std::vector<float>, a span, a mapped file) without copying it.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "../core/result.hpp"
#include "../core/vec3.hpp"
#include "voxel_grid.hpp"

namespace hmira {

/// Owns dims[0] * dims[1] * dims[2] samples of type T, x fastest. Models voxel_grid,
/// writable_voxel_grid and contiguous_voxel_grid. Concurrency: const access may run in
/// parallel; set() on distinct samples may too.
template <class T>
class dense_grid {
public:
    using value_type = T;  ///< the sample type

    /// An empty grid (all dimensions 0).
    dense_grid() = default;
    /// A grid of the given geometry with every sample set to `fill`.
    explicit dense_grid(const grid_geometry& g, T fill = T{}) : geometry_(g), values_(g.size(), fill) {}

    grid_dims dims() const noexcept { return geometry_.dims; }            ///< samples per axis
    vec3<double> origin() const noexcept { return geometry_.origin; }     ///< position of sample (0, 0, 0)
    vec3<double> spacing() const noexcept { return geometry_.spacing; }   ///< distance between samples
    const grid_geometry& geometry() const noexcept { return geometry_; }  ///< dims, origin and spacing
    std::size_t size() const noexcept { return values_.size(); }          ///< number of samples

    /// Offset of sample (i, j, k) in data().
    std::size_t index(std::size_t i, std::size_t j, std::size_t k) const noexcept {
        return i + geometry_.dims[0] * (j + geometry_.dims[1] * k);
    }
    /// Sample (i, j, k); no bounds check.
    T value(std::size_t i, std::size_t j, std::size_t k) const noexcept { return values_[index(i, j, k)]; }
    /// Overwrites sample (i, j, k); no bounds check.
    void set(std::size_t i, std::size_t j, std::size_t k, T v) noexcept { values_[index(i, j, k)] = v; }

    const T* data() const noexcept { return values_.data(); }       ///< sample (0, 0, 0); x fastest
    T* data() noexcept { return values_.data(); }                   ///< sample (0, 0, 0); x fastest
    std::span<const T> values() const noexcept { return values_; }  ///< all samples, x fastest
    std::span<T> values() noexcept { return values_; }              ///< all samples, x fastest

private:
    grid_geometry geometry_;
    std::vector<T> values_;
};

/// A voxel_grid over samples the caller owns (T may be const). Copying the view copies no
/// samples; the caller keeps the array alive and unmoved while the view is used.
template <class T>
class grid_view {
public:
    using value_type = std::remove_const_t<T>;  ///< the sample type, without const

    /// A view of nothing (all dimensions 0).
    grid_view() = default;
    /// Views `samples` as a grid of geometry `g`; make_grid_view() checks the sizes first.
    grid_view(std::span<T> samples, const grid_geometry& g) : geometry_(g), samples_(samples) {}

    grid_dims dims() const noexcept { return geometry_.dims; }            ///< samples per axis
    vec3<double> origin() const noexcept { return geometry_.origin; }     ///< position of sample (0, 0, 0)
    vec3<double> spacing() const noexcept { return geometry_.spacing; }   ///< distance between samples
    const grid_geometry& geometry() const noexcept { return geometry_; }  ///< dims, origin and spacing

    /// Offset of sample (i, j, k) in data().
    std::size_t index(std::size_t i, std::size_t j, std::size_t k) const noexcept {
        return i + geometry_.dims[0] * (j + geometry_.dims[1] * k);
    }
    /// Sample (i, j, k); no bounds check.
    value_type value(std::size_t i, std::size_t j, std::size_t k) const noexcept { return samples_[index(i, j, k)]; }
    /// Overwrites sample (i, j, k) in the caller's array (views of non-const T only).
    void set(std::size_t i, std::size_t j, std::size_t k, value_type v) noexcept
        requires(!std::is_const_v<T>)
    {
        samples_[index(i, j, k)] = v;
    }
    /// The caller's array: sample (0, 0, 0), x fastest.
    const value_type* data() const noexcept { return samples_.data(); }

private:
    grid_geometry geometry_;
    std::span<T> samples_;
};

/// Wraps `samples` (x fastest, then y, then z) as a grid of geometry `g` without copying.
/// Errors: invalid_argument if the sample count is not dims[0] * dims[1] * dims[2], or the
/// geometry is unusable (zero dimension, spacing not positive). O(1).
template <class T>
result<grid_view<T>> make_grid_view(std::span<T> samples, const grid_geometry& g) {
    if (auto ok = check_grid_geometry(g, "make_grid_view"); !ok) return ok.error();
    if (samples.size() != g.size())
        return fail(errc::invalid_argument, "make_grid_view: " + std::to_string(samples.size()) +
                                                " samples given, dimensions " + std::to_string(g.dims[0]) + " x " +
                                                std::to_string(g.dims[1]) + " x " + std::to_string(g.dims[2]) +
                                                " need " + std::to_string(g.size()));
    return grid_view<T>(samples, g);
}

/// Same for a std::vector; the view sees later writes to the vector but not a reallocation.
template <class T, class A>
result<grid_view<const T>> make_grid_view(const std::vector<T, A>& samples, const grid_geometry& g) {
    return make_grid_view(std::span<const T>(samples), g);
}
template <class T, class A>
result<grid_view<T>> make_grid_view(std::vector<T, A>& samples, const grid_geometry& g) {
    return make_grid_view(std::span<T>(samples), g);
}

}  // namespace hmira
