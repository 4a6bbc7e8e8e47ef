// hmira/grids/implicit_shapes.hpp
// Implicit functions for tests, benchmarks and the demo: sphere and torus as signed distances
// (negative inside) and the gyroid, a triply periodic surface with many handles.
#pragma once

#include <cmath>

#include "../core/vec3.hpp"

namespace hmira {

/// Signed distance to a sphere: |p - center| - radius. Inside is below 0.
struct sphere_field {
    vec3<double> center{0, 0, 0};  ///< centre of the sphere
    double radius = 1.0;           ///< its radius
    /// The signed distance at p.
    double operator()(const vec3<double>& p) const noexcept { return norm(p - center) - radius; }
};

/// Signed distance to a torus around the z axis through `center`, tube radius `minor` at
/// distance `major` from the axis. Inside is below 0; genus 1.
struct torus_field {
    vec3<double> center{0, 0, 0};  ///< centre of the torus
    double major = 1.0;            ///< distance from the axis to the tube's centre line
    double minor = 0.25;           ///< radius of the tube
    /// The signed distance at p.
    double operator()(const vec3<double>& p) const noexcept {
        const vec3<double> q = p - center;
        const double ring = std::sqrt(q.x * q.x + q.y * q.y) - major;
        return std::sqrt(ring * ring + q.z * q.z) - minor;
    }
};

/// The gyroid sin(x')cos(y') + sin(y')cos(z') + sin(z')cos(x') with x' = x * frequency.
/// Its zero set is connected with many handles; it is not a distance.
struct gyroid_field {
    double frequency = 1.0;  ///< angular frequency: one period every 2 pi / frequency
    /// The field's value at p.
    double operator()(const vec3<double>& p) const noexcept {
        const double x = p.x * frequency, y = p.y * frequency, z = p.z * frequency;
        return std::sin(x) * std::cos(y) + std::sin(y) * std::cos(z) + std::sin(z) * std::cos(x);
    }
};

}  // namespace hmira
