// hmira/algorithms/spatial/signed_distance.hpp
// Inside tests and signed distances at batches of points: the distance to the closest surface
// point, negative inside, the inside decided by the winding number (robust on open, non-manifold
// and self-intersecting input) or, for comparison, by pseudo-normals or ray parity.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/result.hpp"
#include "../../core/vec3.hpp"
#include "triangle_set.hpp"
#include "winding_number.hpp"

namespace hmira {

/// How signed_distance decides which side of the surface a point is on.
enum class sign_mode {
    winding_number,  ///< inside where the winding number is at least 1/2: right on open, soup and flipped input
    pseudo_normal,   ///< Baerentzen and Aanaes's angle-weighted pseudo-normal at the closest point: closed,
                     ///< consistently oriented manifolds only
    parity,          ///< an odd number of crossings along a fixed ray: closed surfaces only, ignores orientation
};
/// The modes' names, as the front ends accept them.
constexpr auto enum_names(sign_mode) {
    return std::array{std::pair{sign_mode::winding_number, std::string_view("winding_number")},
                      std::pair{sign_mode::pseudo_normal, std::string_view("pseudo_normal")},
                      std::pair{sign_mode::parity, std::string_view("parity")}};
}

/// Options of signed_distance.
struct signed_distance_options {
    sign_mode sign = sign_mode::winding_number;  ///< how the inside is decided
    double beta = 2.0;                           ///< the fast winding number's accuracy (winding_number_options)
    nan_policy nan = nan_policy::error;          ///< non-finite query points
    unsigned threads = 0;                        ///< worker threads (0: all); the answers do not depend on it
};

/// Per query point: the signed distance, the closest surface point and the face it lies on.
struct signed_distances {
    std::vector<double> distances;      ///< |p - closest|, negative inside; NaN for a propagated NaN point
    std::vector<vec3<double>> closest;  ///< the closest point on the surface
    std::vector<std::size_t> faces;     ///< T::face_index of the face holding it
};

/// Which points of `points` lie inside `mesh`: 1 where the winding number is at least 1/2.
/// \pre none. \post one answer per point, in order; a propagated non-finite point is outside.
/// Errors and complexity: those of winding_number.
template <class M, class T = default_traits<M>>
    requires surface_query_mesh<M, T>
[[nodiscard]] result<std::vector<std::uint8_t>> contains(const M& mesh, std::span<const vec3<double>> points,
                                                         const winding_number_options& options = {});

/// Signed distances from `points` to the surface of `mesh` (faces triangulated as triangles_of
/// does): the distance to the closest point of any triangle (aabb_tree), negative inside as
/// options.sign decides. A point on the surface has distance 0 whatever the sign.
/// \pre none. \post one answer per point, in order, the same for every thread count.
/// Errors: as winding_number ("signed_distance: ..."): a mesh without faces, a non-finite vertex
///   or (nan_policy::error) query point naming its index, beta not above 1.
/// Complexity: O(F log F) to build, then O(log F) expected per point for the closest point and
///   the fast winding number (parity: O(log F) per crossing); parallel over points.
template <class M, class T = default_traits<M>>
    requires surface_query_mesh<M, T>
[[nodiscard]] result<signed_distances> signed_distance(const M& mesh, std::span<const vec3<double>> points,
                                                       const signed_distance_options& options = {});

/// contains and signed_distance over a triangle_set (for example over caller arrays).
///@{
[[nodiscard]] inline result<std::vector<std::uint8_t>> contains(const triangle_set& surface,
                                                                std::span<const vec3<double>> points,
                                                                const winding_number_options& options = {});
[[nodiscard]] inline result<signed_distances> signed_distance(const triangle_set& surface,
                                                              std::span<const vec3<double>> points,
                                                              const signed_distance_options& options = {});
///@}

}  // namespace hmira

#include "detail/signed_distance_impl.hpp"
