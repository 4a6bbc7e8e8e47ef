// hmira/algorithms/spatial/ray.hpp
// A ray with its parameter interval: what the spatial queries (aabb_tree, bvh) intersect.
#pragma once

#include <limits>

#include "../../core/vec3.hpp"

namespace hmira {

/// A ray: origin + t * direction, for t in [t_min, t_max].
struct ray {
    vec3<double> origin{};                                   ///< where the ray starts
    vec3<double> direction{};                                ///< not necessarily unit length; must be non-zero
    double t_min = 0;                                        ///< the smallest parameter that counts as a hit
    double t_max = std::numeric_limits<double>::infinity();  ///< the largest one
};

}  // namespace hmira
