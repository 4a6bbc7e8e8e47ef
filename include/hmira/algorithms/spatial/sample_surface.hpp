// hmira/algorithms/spatial/sample_surface.hpp
// Random points on a surface, uniform by area or spread as blue noise (Poisson disk), each with
// its face and barycentric coordinates, reproducible from a seed on every platform.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/result.hpp"
#include "../../core/vec3.hpp"
#include "triangle_set.hpp"

namespace hmira {

/// How sample_surface spreads its points.
enum class sampling_method {
    uniform,       ///< independent points, each triangle hit with probability proportional to its area
    poisson_disk,  ///< blue noise: Yuksel's weighted elimination of 5 * count uniform candidates
};
/// The methods' names, as the front ends accept them ("uniform", "poisson_disk").
constexpr auto enum_names(sampling_method) {
    return std::array{std::pair{sampling_method::uniform, std::string_view("uniform")},
                      std::pair{sampling_method::poisson_disk, std::string_view("poisson_disk")}};
}

/// Options of sample_surface.
struct sample_surface_options {
    sampling_method method = sampling_method::uniform;  ///< uniform or blue noise
    std::uint64_t seed = 0;                             ///< the same seed gives the same points
};

/// The samples: point i = sum over k of barycentrics[i][k] * position(corners[i][k]).
struct surface_samples {
    std::vector<vec3<double>> points;                 ///< on the surface
    std::vector<std::size_t> faces;                   ///< T::face_index of each point's face
    std::vector<std::array<double, 3>> barycentrics;  ///< non-negative, summing to 1
    std::vector<std::array<std::size_t, 3>> corners;  ///< the vertex indices they weigh (a polygon's
                                                      ///< triangle, as triangles_of cuts it)
};

/// `count` points on the surface of `mesh` (faces triangulated as triangles_of does).
///
/// Uniform: a triangle is chosen with probability area / total area by a binary search of the
/// cumulative areas, then a point in it by the square-root map of two uniform numbers. Poisson
/// disk: 5 * count uniform candidates, then the candidate of largest weight
/// sum (1 - d / 2 r_max)^8 over its neighbours closer than 2 r_max is removed until count
/// remain (Yuksel 2015), r_max = sqrt(A / (2 sqrt(3) count)); the points keep the candidates' order.
/// Random numbers: std::mt19937_64 seeded with options.seed, mapped to [0, 1) as the top 53
/// bits times 2^-53 (no std distribution, whose output differs between standard libraries).
/// \pre none. \post exactly `count` samples (none for count 0); the same mesh, count and
///   options give the same samples bit for bit.
/// Errors: errc::invalid_argument for a surface without area ("sample_surface: the mesh has
///   no area to sample"); those of triangles_of.
/// Complexity: uniform O(F + count log F); Poisson disk O(F + count (log F + k log count)), k the
///   candidates' neighbours (about 20 on a surface).
template <class M, class T = default_traits<M>>
    requires surface_query_mesh<M, T>
[[nodiscard]] result<surface_samples> sample_surface(const M& mesh, std::size_t count,
                                                     const sample_surface_options& options = {});

/// The same over a triangle_set: `faces` and `corners` come from it.
[[nodiscard]] inline result<surface_samples> sample_surface(const triangle_set& surface, std::size_t count,
                                                            const sample_surface_options& options = {});

}  // namespace hmira

#include "detail/sample_surface_impl.hpp"
