// hmira/algorithms/geometry/face_normal.hpp
// A polygon's normal by Newell's method, the one definition every algorithm and front end uses:
// exact for planar polygons of any degree (its length is twice the area), and a stable average
// for slightly non-planar ones.
#pragma once

#include <cstddef>
#include <ranges>

#include "../../concepts.hpp"
#include "../../core/vec3.hpp"

namespace hmira {

/// One side's term of Newell's sum, for the side from `a` to `b`. Summing it over a loop's
/// sides gives the loop's area vector; summing over several loops (inner rings wound against
/// the outer loop) gives the area vector of a face with holes.
inline vec3<double> newell_term(const vec3<double>& a, const vec3<double>& b) {
    return {(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
}

/// Newell's normal of the closed polygon through `points` (a random-access range of vec3<S>),
/// unnormalised, in S: its length is twice the area. O(n).
template <std::ranges::random_access_range R>
std::ranges::range_value_t<R> newell_normal(const R& points) {
    std::ranges::range_value_t<R> n{};
    const std::size_t k = std::ranges::size(points);
    for (std::size_t i = 0; i < k; ++i) {
        const auto& a = points[i];
        const auto& b = points[(i + 1) % k];
        n.x += (a.y - b.y) * (a.z + b.z);
        n.y += (a.z - b.z) * (a.x + b.x);
        n.z += (a.x - b.x) * (a.y + b.y);
    }
    return n;
}

/// What face_area_vector() needs: a face's vertices in order and their positions.
template <class M, class T = default_traits<M>>
concept face_normal_mesh = face_vertex_range_mesh<M, T> && positioned_mesh<M, T>;

/// The Newell normal of face f's outer loop, unnormalised (length twice the area): the area
/// vector. O(face degree).
template <class M, class T = default_traits<M>>
    requires face_normal_mesh<M, T>
vec3<double> face_area_vector(const M& mesh, typename T::face_handle f) {
    vec3<double> n{}, first{}, previous{};
    bool started = false;
    for (auto v : T::face_vertices(mesh, f)) {
        const auto q = T::position(mesh, v);
        const vec3<double> p{double(q.x), double(q.y), double(q.z)};
        if (started)
            n += newell_term(previous, p);
        else
            first = p, started = true;
        previous = p;
    }
    if (started) n += newell_term(previous, first);
    return n;
}

}  // namespace hmira
