// hmira/algorithms/subdivision/detail/range.hpp
// Keeps the subdivision schemes' sums from overflowing on coordinates near the largest double.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "../../triangle/triangle_common.hpp"

namespace hmira::detail::subdivision {

/// Every new position a scheme computes is a combination of old positions with non-negative
/// weights summing to 1, so it lies in their bounding box; but the sums it is computed from (a
/// vertex's neighbour sum, a + b, 19 p) can overflow when coordinates come near the largest
/// double. A mesh with a coordinate of magnitude 2^960 or more is therefore scaled by 2^-64
/// (a power of two: exact, except that magnitudes below 2^-958 lose bits) before the first
/// level, which leaves room for sums of up to 2^63 terms, and scaled back after the last; a
/// result that rounding pushes past the largest double is clamped to it (the true one is at
/// most the largest input). Other meshes, and models whose scalar cannot reach 2^960 (float),
/// are not touched: their results are the unscaled computation's, bit for bit.
template <class M, class T>
class range_guard {
public:
    static constexpr int shift = 64;

    /// Scales the mesh down if it needs it. O(V) to look.
    explicit range_guard(M& mesh) : mesh_(mesh) {
        using S = typename T::scalar;
        if constexpr (double(std::numeric_limits<S>::max()) >= 0x1p960) {
            namespace dt = detail::triangle_ops;
            double largest = 0;
            for (auto v : T::vertices(mesh)) {
                const auto p = dt::position_of<M, T>(mesh, v);
                largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
            }
            if (!(largest >= 0x1p960) || !(largest <= std::numeric_limits<double>::max())) return;
            scaled_ = true;
            for (auto v : T::vertices(mesh)) {
                const auto p = dt::position_of<M, T>(mesh, v);
                const vec3<double> q{std::ldexp(p.x, -shift), std::ldexp(p.y, -shift), std::ldexp(p.z, -shift)};
                dt::set_position<M, T>(mesh, v, q);
            }
        }
    }

    /// Whether the mesh was scaled down.
    bool scaled() const noexcept { return scaled_; }

    /// Scales the mesh back (after the last level), clamping to the largest double. O(V).
    void restore() {
        if (!scaled_) return;
        scaled_ = false;
        namespace dt = detail::triangle_ops;
        const auto back = [](double x) {
            constexpr double big = std::numeric_limits<double>::max();
            return std::clamp(std::ldexp(x, shift), -big, big);
        };
        for (auto v : T::vertices(mesh_)) {
            const auto p = dt::position_of<M, T>(mesh_, v);
            dt::set_position<M, T>(mesh_, v, {back(p.x), back(p.y), back(p.z)});
        }
    }

    /// The caller restored a copy taken before the scaling: nothing to scale back.
    void dismiss() noexcept { scaled_ = false; }

private:
    M& mesh_;
    bool scaled_ = false;
};

}  // namespace hmira::detail::subdivision
