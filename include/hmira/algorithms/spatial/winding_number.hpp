// hmira/algorithms/spatial/winding_number.hpp
// The generalised winding number of a surface at query points (Jacobson et al. 2013): 1 inside
// a closed outward-oriented surface, 0 outside, and a smooth, robust inside measure on open,
// non-manifold and self-intersecting input. Direct sum, or Barill et al. 2018's fast tree.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/result.hpp"
#include "../../core/vec3.hpp"
#include "triangle_set.hpp"

namespace hmira {

/// How winding_number sums the triangles' solid angles.
enum class winding_method {
    direct,  ///< every triangle, for every point: exact up to rounding, O(F) per point
    fast,    ///< Barill et al.'s tree of far-field expansions: O(log F) per point, error bounded below
};
/// The methods' names, as the front ends accept them.
constexpr auto enum_names(winding_method) {
    return std::array{std::pair{winding_method::direct, std::string_view("direct")},
                      std::pair{winding_method::fast, std::string_view("fast")}};
}

/// What a query point that is not finite (NaN or infinite) does.
enum class nan_policy {
    error,      ///< the call fails with errc::invalid_argument naming the point's index
    propagate,  ///< the point's answer is NaN (contains: outside)
};
/// The policies' names, as the front ends accept them ("error", "propagate").
constexpr auto enum_names(nan_policy) {
    return std::array{std::pair{nan_policy::error, std::string_view("error")},
                      std::pair{nan_policy::propagate, std::string_view("propagate")}};
}

/// Options of winding_number (and of the sign of signed_distance, and of contains).
struct winding_number_options {
    winding_method method = winding_method::fast;  ///< direct sum or the fast tree
    /// The fast method's accuracy: a tree node of radius r (a ball about its area-weighted
    /// centre holding its triangles) is replaced by its expansion when the point lies farther
    /// than beta * r from the centre. Larger is slower and more accurate; must exceed 1.
    double beta = 2.0;
    bool error_bounds = false;           ///< also return each point's guaranteed error bound
    nan_policy nan = nan_policy::error;  ///< non-finite query points
    unsigned threads = 0;                ///< worker threads (0: all); the answers do not depend on it
};

/// The winding numbers, one per query point, and (when asked for) the bound on each one's error.
struct winding_numbers {
    std::vector<double> values;        ///< w(p), in the points' order
    std::vector<double> error_bounds;  ///< empty unless options.error_bounds; 0 for the direct method
};

/// Winding numbers of `mesh` (its faces triangulated as triangles_of does) at `points`.
///
/// w(p) = sum over triangles of the signed solid angle (Van Oosterom and Strackee) / 4 pi.
/// The fast method expands each far node's triangles about their centre c to second order
/// (the dipole N.(c - p) / |c - p|^3 plus the first- and second-order terms of the field), as
/// Barill et al. Its error is bounded: the integrand's Taylor remainder, by Legendre's bound
/// |D^k (1/|x|)| <= k! / |x|^(k+1), is for a node of radius r, total triangle area A and
/// distance d from p at most 4 A r^3 / (4 pi (d - r)^5); the sum over the nodes a point
/// accepted is returned as its error bound. The bound holds for every input but is loose;
/// measured errors are far below it: on soups of spheres crossed by large random triangles,
/// worst 0.05 and mean 0.003 at beta = 2, worst 0.002 at beta = 4; off closed models, within
/// 0.02 of 0 or 1 at beta = 2, 0.1 from the surface (the tests check these).
///
/// \pre none: points and positions are checked.
/// \post values[i] is w(points[i]) (direct), or within error_bounds[i] of it (fast), up to
///   rounding; the same answers for every thread count.
/// Errors: errc::invalid_argument for a mesh without faces ("winding_number: the mesh has no
///   faces"), a non-finite vertex, beta not above 1, or (nan_policy::error) a non-finite point
///   ("winding_number: query point 7 is not finite", element 7); those of triangles_of.
/// Complexity: direct O(P F); fast O(F log F) to build plus O(log F) per point for a point
///   away from the surface (O(F) worst case); parallel over points.
template <class M, class T = default_traits<M>>
    requires surface_query_mesh<M, T>
[[nodiscard]] result<winding_numbers> winding_number(const M& mesh, std::span<const vec3<double>> points,
                                                     const winding_number_options& options = {});

/// The same over a triangle_set (for example one from make_triangle_set over caller arrays).
[[nodiscard]] inline result<winding_numbers> winding_number(const triangle_set& surface,
                                                            std::span<const vec3<double>> points,
                                                            const winding_number_options& options = {});

}  // namespace hmira

#include "detail/winding_number_impl.hpp"
