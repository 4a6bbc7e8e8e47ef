// hmira/algorithms/spatial/hausdorff_distance.hpp
// How far apart two surfaces are: the sampled one-sided Hausdorff distances both ways, their
// maximum (the symmetric distance), and the mean and RMS of the sampled distances.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "../../concepts.hpp"
#include "../../core/result.hpp"
#include "triangle_set.hpp"

namespace hmira {

/// Options of hausdorff_distance.
struct hausdorff_options {
    std::size_t per_triangle = 10;      ///< at least this many random points per triangle
    std::size_t min_samples = 1000000;  ///< and at least this many per surface, spread evenly over its triangles
    std::uint64_t seed = 0x9e3779b97f4a7c15ull;  ///< triangle i draws from std::mt19937_64(seed ^ i)
    unsigned threads = 0;                        ///< worker threads (0: all); the answers do not depend on it
};

/// One direction: from sample points on one surface to the other surface.
struct one_sided_distance {
    double max = 0;           ///< the largest sampled distance (the one-sided Hausdorff distance)
    double mean = 0;          ///< the mean sampled distance
    double rms = 0;           ///< the root mean square sampled distance
    std::size_t samples = 0;  ///< how many points were sampled
};

/// Both directions and the symmetric distance.
struct hausdorff_result {
    one_sided_distance a_to_b;  ///< samples on A, distances to B
    one_sided_distance b_to_a;  ///< samples on B, distances to A
    double symmetric = 0;       ///< max(a_to_b.max, b_to_a.max)
};

/// The sampled Hausdorff distance between the surfaces of `a` and `b` (faces triangulated as
/// triangles_of does). Each surface is sampled at its vertices (those a triangle uses) plus
/// max(per_triangle, ceil(min_samples / triangles)) uniform points per triangle (the
/// square-root map, random numbers as sample_surface draws them, per triangle, so the answer
/// does not depend on the thread count), and each sample's distance to the other surface is
/// its closest point in an aabb_tree. The sampled maximum never exceeds the true one-sided
/// distance; it reaches it when the farthest point is a vertex.
/// \pre none. \post symmetric == max(a_to_b.max, b_to_a.max); the same inputs give the same answer.
/// Errors: errc::invalid_argument when either mesh has no faces ("hausdorff_distance: mesh A has
///   no faces"); those of triangles_of.
/// Complexity: O(S log F) for S samples, parallel over triangles.
template <class MA, class MB, class TA = default_traits<MA>, class TB = default_traits<MB>>
    requires surface_query_mesh<MA, TA> && surface_query_mesh<MB, TB>
[[nodiscard]] result<hausdorff_result> hausdorff_distance(const MA& a, const MB& b,
                                                          const hausdorff_options& options = {});

/// The same over two triangle_sets.
[[nodiscard]] inline result<hausdorff_result> hausdorff_distance(const triangle_set& a, const triangle_set& b,
                                                                 const hausdorff_options& options = {});

/// One direction only: samples on `from` (as above), distances to `to`.
[[nodiscard]] inline result<one_sided_distance> one_sided_hausdorff_distance(const triangle_set& from,
                                                                             const triangle_set& to,
                                                                             const hausdorff_options& options = {});

}  // namespace hmira

#include "detail/hausdorff_distance_impl.hpp"
