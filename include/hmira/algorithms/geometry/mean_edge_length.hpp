// hmira/algorithms/geometry/mean_edge_length.hpp
// The mean length of a mesh's edges, at any scale a double holds: each length is taken
// hypot-style (the difference scaled by its largest component before squaring), and the sum
// is scaled by the longest edge, so neither coordinates near 1e300 nor near 1e-300 overflow
// or underflow on the way.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "../../concepts.hpp"

namespace hmira {

namespace detail::geometry {

/// |b - a| without overflow or underflow in the intermediate squares: +inf only when the
/// length itself exceeds the largest double; NaN when a coordinate is not finite.
inline double distance(const vec3<double>& a, const vec3<double>& b) noexcept {
    vec3<double> d = b - a;
    double twice = 1;
    if (!(std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z))) {
        // The difference overflowed (coordinates of opposite sign near the largest double), or
        // a coordinate is not finite: halve first. Non-finite input stays non-finite.
        d = b * 0.5 - a * 0.5;
        twice = 2;
    }
    const double s = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
    if (!(s > 0)) return s == 0 ? 0.0 : s;  // 0, or NaN
    if (std::isinf(s)) return s;
    const vec3<double> u = d / s;
    return twice * s * std::sqrt(dot(u, u));
}

}  // namespace detail::geometry

/// What mean_edge_length() needs: the edges with their end vertices, and positions.
template <class M, class T = default_traits<M>>
concept mean_edge_length_mesh = edge_list_mesh<M, T> && positioned_mesh<M, T>;

/// The mean length of the mesh's edges, in double precision whatever T::scalar is.
/// 0 when the mesh has no edge or every edge has length 0; +inf only when the mean itself
/// exceeds the largest double; NaN when an edge's end has a non-finite coordinate.
/// Accurate to a few units in the last place at every scale: lengths are computed hypot-style
/// and summed relative to the longest edge, so coordinates near 1e300 or 1e-300 give the
/// right answer where squaring them would overflow or underflow.
/// Complexity O(E), O(1) extra memory (two passes over the edges).
template <class M, class T = default_traits<M>>
    requires mean_edge_length_mesh<M, T>
[[nodiscard]] double mean_edge_length(const M& mesh) {
    auto at = [&](typename T::vertex_handle v) {
        const vec3<typename T::scalar> p = T::position(mesh, v);
        return vec3<double>{double(p.x), double(p.y), double(p.z)};
    };
    auto length = [&](typename T::edge_handle e) {
        const auto ends = T::edge_vertices(mesh, e);
        return detail::geometry::distance(at(ends[0]), at(ends[1]));
    };
    std::size_t count = 0;
    double longest = 0;
    for (auto e : T::edges(mesh)) {
        const double l = length(e);
        if (std::isnan(l)) return l;
        longest = std::max(longest, l);
        ++count;
    }
    if (count == 0 || longest == 0 || std::isinf(longest)) return count == 0 ? 0.0 : longest;
    double sum = 0;  // of lengths / longest: each in [0, 1], so no overflow
    for (auto e : T::edges(mesh)) sum += length(e) / longest;
    return longest * (sum / double(count));
}

}  // namespace hmira
