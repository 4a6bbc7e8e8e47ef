// hmira/algorithms/conversion/detail/marching_cubes_bits.hpp
// The word-level primitives of marching cubes: one bit per sample, packed 64 to a word, and the
// errors named from sample values. Part of marching_cubes.hpp.
#pragma once

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>

#include "../../../core/result.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace hmira::detail::mc {

/// Crossing points keep this fraction of an edge away from its samples, so that a sample equal
/// to the iso value never makes vertices on different edges coincide.
inline constexpr double edge_margin = 1.0 / 512;

// Bit count without a library call: the x86-64 baseline has no popcnt instruction, and most
// words here are zero anyway.
inline std::uint32_t count_bits(std::uint64_t x) noexcept {
#if defined(__POPCNT__)
    return static_cast<std::uint32_t>(std::popcount(x));
#else
    if (!x) return 0;
    x = x - ((x >> 1) & 0x5555555555555555ull);
    x = (x & 0x3333333333333333ull) + ((x >> 2) & 0x3333333333333333ull);
    x = (x + (x >> 4)) & 0x0f0f0f0f0f0f0f0full;
    return static_cast<std::uint32_t>((x * 0x0101010101010101ull) >> 56);
#endif
}

inline std::uint64_t shr1(const std::uint64_t* a, std::size_t w, std::size_t words) noexcept {
    return (a[w] >> 1) | (w + 1 < words ? a[w + 1] << 63 : 0);
}
inline unsigned bits2(const std::uint64_t* a, std::size_t i) noexcept {
    const std::size_t w = i >> 6, b = i & 63;
    if (b != 63) return static_cast<unsigned>((a[w] >> b) & 3u);
    return static_cast<unsigned>((a[w] >> 63) | ((a[w + 1] & 1u) << 1));
}

// Packs one row's classification (bit i set: sample i is inside) and reports non-finite
// samples (NaN or infinite: x - x is NaN exactly for those).
template <class V>
bool classify_row(const V* row, std::size_t nx, double iso, bool above, std::uint64_t* out) {
    bool bad_row = false;
    const std::size_t words = (nx + 63) / 64;
    if constexpr (std::is_same_v<V, float>) {
        // The float threshold that classifies every float exactly as the double iso would.
        float t = static_cast<float>(iso);
        if (above && double(t) < iso) t = std::nextafter(t, std::numeric_limits<float>::infinity());
        if (!above && double(t) > iso) t = std::nextafter(t, -std::numeric_limits<float>::infinity());
        for (std::size_t w = 0; w < words; ++w) {
            const float* p = row + w * 64;
            const std::size_t n = std::min<std::size_t>(64, nx - w * 64);
            std::uint64_t m = 0;
            unsigned bad = 0;
            if (n == 64) {
#if defined(__SSE2__)
                // Four compares and one movemask per four samples: this pass reads every
                // sample, so it sets the pace for sparse surfaces.
                const __m128 tt = _mm_set1_ps(t);
                unsigned unordered = 0;
                for (unsigned b = 0; b < 64; b += 4) {
                    const __m128 x = _mm_loadu_ps(p + b);
                    const __m128 c = above ? _mm_cmpge_ps(x, tt) : _mm_cmple_ps(x, tt);
                    m |= std::uint64_t(unsigned(_mm_movemask_ps(c))) << b;
                    const __m128 d = _mm_sub_ps(x, x);
                    unordered |= unsigned(_mm_movemask_ps(_mm_cmpunord_ps(d, d)));
                }
                bad |= unordered;
#else
                if (above)
                    for (unsigned b = 0; b < 64; ++b) m |= std::uint64_t(p[b] >= t) << b;
                else
                    for (unsigned b = 0; b < 64; ++b) m |= std::uint64_t(p[b] <= t) << b;
                for (unsigned b = 0; b < 64; ++b) bad |= unsigned(!(p[b] - p[b] == 0.0f));
#endif
            } else {
                for (unsigned b = 0; b < n; ++b) {
                    m |= std::uint64_t(above ? p[b] >= t : p[b] <= t) << b;
                    bad |= unsigned(!(p[b] - p[b] == 0.0f));
                }
            }
            out[w] = m;
            bad_row |= bad != 0;
        }
    } else {
        for (std::size_t w = 0; w < words; ++w) {
            const std::size_t n = std::min<std::size_t>(64, nx - w * 64);
            std::uint64_t m = 0;
            for (unsigned b = 0; b < n; ++b) {
                const double v = static_cast<double>(row[w * 64 + b]);
                m |= std::uint64_t(above ? v >= iso : v <= iso) << b;
                bad_row |= !(v - v == 0.0);
            }
            out[w] = m;
        }
    }
    return bad_row;
}

/// A number as the shortest text that reads back as the same double ("12", "0.5", "1e+30").
inline std::string shortest(double x) {
    char b[32];
    const auto r = std::to_chars(b, b + sizeof b, x);
    return std::string(b, r.ptr);
}

/// The error for an iso value outside the samples' range [lo, hi], which would give no surface.
inline hmira::error iso_outside_range(double iso, double lo, double hi) {
    return fail(errc::invalid_argument, "marching_cubes: iso " + shortest(iso) + " is outside the samples' range [" +
                                            shortest(lo) + ", " + shortest(hi) +
                                            "], so there is no surface; choose an iso between them");
}

}  // namespace hmira::detail::mc
