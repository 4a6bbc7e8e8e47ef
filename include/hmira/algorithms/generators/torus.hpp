// hmira/algorithms/generators/torus.hpp
// A quad torus (genus 1, closed, wound outward) around the z axis: the smallest closed
// surface that is not a sphere, used to check genus-aware algorithms.
#pragma once

#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include "platonic_solids.hpp"  // generated_elements

namespace hmira {

/// Size and resolution of generate_torus().
struct torus_options {
    double major_radius = 1.0;        ///< distance from the z axis to the tube's centre
    double minor_radius = 0.25;       ///< tube radius; must be below major_radius
    std::size_t rings = 32;           ///< segments around the z axis (>= 3)
    std::size_t sides = 16;           ///< segments around the tube (>= 3)
    vec3<double> center = {0, 0, 0};  ///< where the torus's centre goes
};

/// Adds a torus of rings x sides quads. V = rings*sides, E = 2V, F = V. Complexity O(V).
/// Errors (mesh unchanged): fewer than 3 rings or sides, radii not 0 < minor < major.
template <class M, class T = default_traits<M>>
    requires polygon_mesh_builder<M, T>
result<generated_elements<M, T>> generate_torus(M& mesh, const torus_options& o = {}) {
    using S = typename T::scalar;
    if (o.rings < 3 || o.sides < 3)
        return fail(errc::invalid_argument, "generate_torus: rings and sides must be at least 3");
    if (!(o.minor_radius > 0 && o.minor_radius < o.major_radius))
        return fail(errc::invalid_argument, "generate_torus: need 0 < minor_radius < major_radius");
    generated_elements<M, T> out;
    for (std::size_t i = 0; i < o.rings; ++i)
        for (std::size_t j = 0; j < o.sides; ++j) {
            const double u = 2 * std::numbers::pi * double(i) / double(o.rings);
            const double v = 2 * std::numbers::pi * double(j) / double(o.sides);
            const double r = o.major_radius + o.minor_radius * std::cos(v);
            const auto p = vec3<double>{r * std::cos(u), r * std::sin(u), o.minor_radius * std::sin(v)} + o.center;
            out.vertices.push_back(T::add_vertex(mesh, vec3<S>{S(p.x), S(p.y), S(p.z)}));
        }
    auto id = [&](std::size_t i, std::size_t j) { return out.vertices[(i % o.rings) * o.sides + (j % o.sides)]; };
    for (std::size_t i = 0; i < o.rings; ++i)
        for (std::size_t j = 0; j < o.sides; ++j) {
            const std::array<typename T::vertex_handle, 4> quad{id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)};
            auto f = T::add_face(mesh, std::span<const typename T::vertex_handle>(quad));
            if (!f) return f.error();
            out.faces.push_back(*f);
        }
    return out;
}

}  // namespace hmira
