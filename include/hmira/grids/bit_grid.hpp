// hmira/grids/bit_grid.hpp
// An occupancy grid with one bit per voxel, packed along x in 64-bit words: what voxelize()
// produces, 32x smaller than a float grid and fast to fill, count and combine row by row.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <span>
#include <utility>
#include <vector>

#include "../core/vec3.hpp"
#include "voxel_grid.hpp"

namespace hmira {

namespace detail {

// An allocator that leaves new words unwritten when no value is given (vector(n) instead of
// vector(n, 0)): bit_grid::unwritten() hands its words to a producer that writes them all.
template <class T>
struct default_init_allocator : std::allocator<T> {
    template <class U>
    struct rebind {
        using other = default_init_allocator<U>;
    };
    default_init_allocator() = default;
    template <class U>
    default_init_allocator(const default_init_allocator<U>&) noexcept {}
    template <class U>
    void construct(U* p) noexcept {
        ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        std::allocator_traits<std::allocator<T>>::construct(*this, p, std::forward<Args>(args)...);
    }
};

}  // namespace detail

/// One bit per sample; value() is 0 or 1. Models voxel_grid and writable_voxel_grid (set()
/// stores v != 0). Row (j, k) is words_per_row() words, bits past dims[0] stay zero.
/// Concurrency: const access may run in parallel; set() must not race on one row word.
class bit_grid {
public:
    using value_type = std::uint8_t;  ///< what value() returns: 0 or 1

    /// An empty grid (all dimensions 0).
    bit_grid() = default;
    /// A grid of geometry `g` with every voxel clear.
    explicit bit_grid(const grid_geometry& g)
        : geometry_(g), words_((g.dims[0] + 63) / 64), bits_(words_ * g.dims[1] * g.dims[2], 0) {}

    /// A grid of geometry `g` whose words are not written yet: for a producer that writes
    /// every word itself (the bits past dims[0] as zero) before anything reads them, and so
    /// can write each part of the grid while it is in its core's cache. Reading a word before
    /// it is written is undefined behaviour.
    static bit_grid unwritten(const grid_geometry& g) { return bit_grid(g, nullptr); }

    grid_dims dims() const noexcept { return geometry_.dims; }            ///< voxels per axis
    vec3<double> origin() const noexcept { return geometry_.origin; }     ///< centre of voxel (0, 0, 0)
    vec3<double> spacing() const noexcept { return geometry_.spacing; }   ///< voxel size along each axis
    const grid_geometry& geometry() const noexcept { return geometry_; }  ///< dims, origin and spacing

    /// 1 if voxel (i, j, k) is set, else 0; no bounds check.
    value_type value(std::size_t i, std::size_t j, std::size_t k) const noexcept {
        return static_cast<value_type>((row(j, k)[i >> 6] >> (i & 63)) & 1u);
    }
    /// Sets voxel (i, j, k) when v != 0, clears it otherwise; no bounds check.
    void set(std::size_t i, std::size_t j, std::size_t k, value_type v) noexcept {
        const std::uint64_t bit = std::uint64_t(1) << (i & 63);
        auto& w = row(j, k)[i >> 6];
        w = v ? (w | bit) : (w & ~bit);
    }

    /// Number of set voxels. O(N / 64).
    std::size_t count() const noexcept {
        std::size_t n = 0;
        for (auto w : bits_) n += static_cast<std::size_t>(std::popcount(w));
        return n;
    }

    /// 64-bit words per row of voxels along x.
    std::size_t words_per_row() const noexcept { return words_; }
    /// The words of row (j, k): voxel i is bit i % 64 of word i / 64.
    std::uint64_t* row(std::size_t j, std::size_t k) noexcept {
        return bits_.data() + (k * geometry_.dims[1] + j) * words_;
    }
    /// The words of row (j, k), read-only.
    const std::uint64_t* row(std::size_t j, std::size_t k) const noexcept {
        return bits_.data() + (k * geometry_.dims[1] + j) * words_;
    }
    std::span<const std::uint64_t> words() const noexcept { return bits_; }  ///< all rows, (z, y) order
    std::span<std::uint64_t> words() noexcept { return bits_; }              ///< all rows, (z, y) order

private:
    bit_grid(const grid_geometry& g, std::nullptr_t)
        : geometry_(g), words_((g.dims[0] + 63) / 64), bits_(words_ * g.dims[1] * g.dims[2]) {}

    grid_geometry geometry_;
    std::size_t words_ = 0;
    std::vector<std::uint64_t, detail::default_init_allocator<std::uint64_t>> bits_;
};

}  // namespace hmira
