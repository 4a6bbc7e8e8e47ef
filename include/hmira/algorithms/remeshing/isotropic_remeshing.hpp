// hmira/algorithms/remeshing/isotropic_remeshing.hpp
// Isotropic remeshing (Botsch and Kobbelt 2004): turns a triangle mesh into one whose edges
// all have about the same length and whose triangles are nearly equilateral, on the same surface.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <concepts>
#include <cstddef>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/progress.hpp"
#include "../../core/result.hpp"
#include "../geometry/mean_edge_length.hpp"
#include "../spatial/aabb_tree.hpp"
#include "../triangle/triangle_common.hpp"
#include "../subdivision/detail/reserve.hpp"
#include "detail/remesher.hpp"

namespace hmira {

/// The scales isotropic_remeshing works at. Its tests compare squared lengths, and its
/// closest-point projection multiplies four lengths together, which stays a normal double for
/// lengths in about [2^-240, 2^240]; a mesh whose extent (largest side of the bounding box of
/// its edges' ends) lies outside is remeshed as a copy scaled by a power of two (exact) into
/// that range and scaled back. What no scaling can help is refused: a mesh smaller than
/// remeshing_min_extent, about 1e-292, whose coordinates have too few bits left to place new
/// vertices between them (doubles below 2^-1022 lose precision), and a mesh with a coordinate
/// above remeshing_max_coordinate, about 1.1e307, where the points computed between and
/// around its vertices could exceed the largest double.
inline constexpr double remeshing_min_extent = 0x1p-970;
inline constexpr double remeshing_max_coordinate = 0x1p1020;

/// Roughly how many bytes a remeshing run needs per triangle, of the result and of the input
/// (its working copy and its aabb_tree): measured on halfedge_mesh through `hmira remesh`,
/// whose peak also holds the output's face-vertex copy while writing (the elephant at 0.002:
/// 694k triangles, 133 MB peak, 190 bytes each), then rounded up.
inline constexpr double remeshing_bytes_per_triangle = 256;

namespace detail::remeshing {
/// A number as a message shows it: 6 significant digits, exponent when needed ("1e-07").
inline std::string number(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
}

/// A byte count as a message shows it: "512 bytes", "3.2 MiB", "1.5 TiB"; "more than 1e308
/// bytes" past the largest double.
inline std::string bytes(double b) {
    if (std::isinf(b)) return "more than 1e308 bytes";
    const char* units[] = {"bytes", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
    std::size_t u = 0;
    while (b >= 1024 && u + 1 < std::size(units)) {
        b /= 1024;
        ++u;
    }
    std::ostringstream s;
    s.precision(u == 0 ? 6 : 3);
    s << b << ' ' << units[u];
    return s.str();
}

/// Refuses a target length that is not a finite positive number (errc::invalid_argument).
inline result<void> check_length(double L) {
    if (!(std::isfinite(L) && L > 0))
        return fail(errc::invalid_argument,
                    "isotropic_remeshing: option target_edge_length must be a finite number > 0, got " + number(L));
    return {};
}

/// An estimated count as a message shows it: "about 1.2e+07", or "more than 1e308" past the largest double.
inline std::string count_text(double n) {
    return std::isinf(n) ? std::string("more than 1e308") : "about " + number(n);
}

/// Refuses a mesh at a scale remeshing cannot work at (errc::unsupported, naming it): all the
/// edges' ends at one point, an extent below remeshing_min_extent, or a coordinate above
/// remeshing_max_coordinate. Returns the power of two 2^k closest to the extent (1 for a mesh
/// without edges): the mesh divided by it spans between 1/2 and 2.
template <class M, class T>
result<double> check_scale(const M& mesh) {
    vec3<double> lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
    bool any = false;
    for (auto e : T::edges(mesh))
        for (int k = 0; k < 2; ++k) {
            const auto p = triangle_ops::position_of<M, T>(mesh, T::edge_vertices(mesh, e)[k]);
            lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
            hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
            any = true;
        }
    if (!any) return 1.0;
    const double largest = std::max({-lo.x, -lo.y, -lo.z, hi.x, hi.y, hi.z});
    if (largest > remeshing_max_coordinate)
        return fail(errc::unsupported, "isotropic_remeshing: a coordinate reaches " + number(largest) +
                                           ", too large to remesh (above ~" + number(remeshing_max_coordinate) +
                                           " the points computed between vertices could overflow)");
    const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
    if (extent == 0)
        return fail(errc::unsupported, "isotropic_remeshing: all vertices coincide, so there is nothing to remesh");
    if (extent < remeshing_min_extent)
        return fail(errc::unsupported, "isotropic_remeshing: the mesh spans only " + number(extent) +
                                           ", too small to remesh (below ~" + number(remeshing_min_extent) +
                                           " doubles have too few bits to place new vertices)");
    return std::ldexp(1.0, std::ilogb(extent));
}

/// Refuses a vertex with a NaN or infinite coordinate (errc::unsupported, naming it).
template <class M, class T>
result<void> check_finite(const M& mesh) {
    for (auto v : T::vertices(mesh))
        if (!triangle_ops::finite(triangle_ops::position_of<M, T>(mesh, v)))
            return fail(errc::unsupported,
                        "isotropic_remeshing: vertex " + std::to_string(T::vertex_index(mesh, v)) +
                            " has a non-finite position",
                        (long long)T::vertex_index(mesh, v));
    return {};
}

/// The sum of the faces' areas over L^2 (polygons fanned from their first corner), with each
/// triangle's edge vectors scaled by their largest component before the cross product, so
/// that it neither underflows nor turns NaN: +inf when it exceeds the largest double.
template <class M, class T>
double area_over_squared_length(const M& mesh, double L) {
    double sum = 0;
    std::vector<vec3<double>> corners;
    for (auto f : T::faces(mesh)) {
        corners.clear();
        for (auto v : T::face_vertices(mesh, f)) corners.push_back(triangle_ops::position_of<M, T>(mesh, v));
        for (std::size_t i = 1; i + 1 < corners.size(); ++i) {
            const vec3<double> u = corners[i] - corners[0], w = corners[i + 1] - corners[0];
            const double s =
                std::max({std::abs(u.x), std::abs(u.y), std::abs(u.z), std::abs(w.x), std::abs(w.y), std::abs(w.z)});
            if (!(s > 0)) continue;
            const double unit_area = 0.5 * norm(cross(u / s, w / s));  // in [0, 1]
            if (!(unit_area > 0)) continue;
            const double r = s / L;
            sum += unit_area * r * r;
        }
    }
    return sum;
}
}  // namespace detail::remeshing

/// Options of isotropic_remeshing.
struct isotropic_remeshing_options {
    /// The edge length L to reach: edges end up within [4/5 L, 4/3 L]. Required (finite, > 0;
    /// default_target_edge_length() gives the usual choice).
    double target_edge_length = 0;
    /// Rounds of split, collapse, flip and relax-and-project.
    std::size_t iterations = 5;
    /// When set, an interior edge whose two faces' normals differ by more than this angle (in
    /// degrees, in [0, 180]) is a feature edge: kept where it is, like a boundary.
    std::optional<double> feature_angle = std::nullopt;
    /// More feature edges, by edge index (T::edge_index), kept as well.
    std::vector<std::size_t> feature_edges{};
    /// Project every moved vertex back onto the input surface (through an aabb_tree of it).
    bool project = true;
    /// Refuses a target length that would make more triangles than this (the estimate of
    /// estimate_isotropic_remeshing(): the surface area over the area of an equilateral
    /// triangle of side L).
    std::size_t max_faces = std::size_t{1} << 28;
    /// Refuses, before allocating, a target length whose estimated peak memory
    /// (estimate_isotropic_remeshing().bytes) exceeds this many bytes. Front ends pass the
    /// free memory; the default sets no limit.
    std::uint64_t max_bytes = UINT64_MAX;
    /// Called between passes with the fraction done; returning false cancels.
    progress_function progress{};
};

/// What isotropic_remeshing did.
struct isotropic_remeshing_result {
    std::size_t splits = 0;         ///< edge splits
    std::size_t collapses = 0;      ///< edge collapses
    std::size_t flips = 0;          ///< edge flips
    std::size_t feature_edges = 0;  ///< edges kept as features at the start (boundary included)
};

/// A mesh isotropic_remeshing can run on: the triangle operators, dense vertex, edge and face
/// indices for its side tables, and copies (it works on a copy so that a failure or a
/// cancellation leaves the input untouched). halfedge_mesh, winged_edge_mesh, OpenMesh's
/// TriMesh and PolyMesh, and CGAL's Surface_mesh qualify.
template <class M, class T = default_traits<M>>
concept remeshable_mesh = triangle_operable_mesh<M, T> && vertex_index_mesh<M, T> && edge_index_mesh<M, T> &&
                          face_index_mesh<M, T> && face_vertex_range_mesh<M, T> && std::copyable<M>;

/// The edge length isotropic_remeshing aims at when the caller names none: the mean edge
/// length of the mesh (mean_edge_length(), computed without overflow or underflow at any
/// scale). A mesh without edges gives 1 (any length leaves it as it is).
/// Errors: errc::unsupported for a vertex with a non-finite position (named), for a mesh at a
/// scale isotropic_remeshing refuses (all vertices at one point, or beyond
/// remeshing_min_extent and remeshing_max_coordinate, named), and when every edge has length 0.
/// Complexity O(V + E).
template <class M, class T = default_traits<M>>
    requires remeshable_mesh<M, T>
[[nodiscard]] result<double> default_target_edge_length(const M& mesh) {
    if (auto ok = detail::remeshing::check_finite<M, T>(mesh); !ok) return ok.error();
    if (auto ok = detail::remeshing::check_scale<M, T>(mesh); !ok) return ok.error();
    if (T::edge_count(mesh) == 0) return 1.0;
    const double mean = mean_edge_length<M, T>(mesh);
    if (!(mean > 0))
        return fail(errc::unsupported,
                    "isotropic_remeshing: every edge has length 0 (the vertices of each face coincide), "
                    "so there is no edge length to remesh at");
    return mean;
}

/// What remeshing a mesh at one target length is expected to make and need.
struct isotropic_remeshing_estimate {
    double triangles = 0;  ///< about how many triangles the result has: surface area over (sqrt(3)/4) L^2
    double bytes = 0;      ///< about the peak memory of the run (remeshing_bytes_per_triangle per triangle)
};

/// Estimates the result of isotropic_remeshing(mesh, {.target_edge_length = L}) before any
/// allocation: the triangle count from the surface area (computed without underflow, never
/// NaN; +inf when out of range) and the bytes from the result's and the input's triangles.
/// Errors: errc::invalid_argument for a length that is not finite and positive;
/// errc::unsupported for a vertex with a non-finite position (named) and for a mesh at a scale
/// isotropic_remeshing refuses (all vertices at one point, or beyond remeshing_min_extent and
/// remeshing_max_coordinate, named).
/// Complexity O(F) for F faces; O(1) extra memory besides one face's corners.
template <class M, class T = default_traits<M>>
    requires remeshable_mesh<M, T>
[[nodiscard]] result<isotropic_remeshing_estimate> estimate_isotropic_remeshing(const M& mesh, double L) {
    if (auto ok = detail::remeshing::check_length(L); !ok) return ok.error();
    if (auto ok = detail::remeshing::check_finite<M, T>(mesh); !ok) return ok.error();
    if (auto ok = detail::remeshing::check_scale<M, T>(mesh); !ok) return ok.error();
    const double triangles = detail::remeshing::area_over_squared_length<M, T>(mesh, L) / (std::sqrt(3.0) / 4);
    return isotropic_remeshing_estimate{triangles,
                                        (triangles + double(T::face_count(mesh))) * remeshing_bytes_per_triangle};
}

/// Remeshes a triangle mesh towards edge length L = options.target_edge_length. Each iteration:
/// 1. splits every edge longer than 4/3 L at its midpoint;
/// 2. collapses every edge shorter than 4/5 L unless that makes an edge longer than 4/3 L or
///    turns a triangle over;
/// 3. flips edges that bring vertex valences closer to 6 (4 on the boundary), then, beside
///    boundary and feature vertices, edges whose flip makes the smaller angle of a thin pair of
///    nearly coplanar triangles (below 35 degrees) larger;
/// 4. moves each vertex to the centroid of its neighbours (beside a boundary or feature vertex:
///    of its triangles, weighted by area) within its tangent plane and projects it onto the
///    input surface (closest point in an aabb_tree of the input).
///
/// Boundary edges and feature edges (by options.feature_angle and options.feature_edges) are
/// never collapsed or flipped, and their vertices never move: they are only split at their
/// midpoints, so every boundary and feature polyline keeps its shape and its vertices.
/// Deleted elements stay in models that keep them (halfedge_mesh: collect_garbage()).
/// \pre a triangle mesh (triangulate_faces first otherwise).
/// \post every face is a triangle; boundary and feature vertices of the input are still there,
/// at the same positions.
/// Works at any scale a double holds (see remeshing_min_extent): a mesh far from unit size is
/// remeshed as a copy scaled by a power of two, exactly, and scaled back; vertices that did not
/// move get their input positions back bit for bit.
/// Errors (mesh unchanged), all before any allocation but the last: errc::invalid_argument
/// for a target length that is not a finite positive number or would make more triangles than
/// options.max_faces or need more bytes than options.max_bytes (estimate_isotropic_remeshing,
/// named in the message), a feature angle outside [0, 180], a feature edge index out of
/// range; errc::unsupported for a vertex with a non-finite position or a face that is not a
/// triangle (named), and for a mesh at a scale it refuses (all vertices at one point, or beyond
/// remeshing_min_extent and remeshing_max_coordinate, named); errc::cancelled when
/// options.progress returns false.
/// Complexity O(iterations * (F log F_in)) for F faces at the end, F_in at the start (each
/// projection is a closest-point query, O(log F_in)); O(F + F_in) extra memory.
template <class M, class T = default_traits<M>>
    requires remeshable_mesh<M, T>
[[nodiscard]] result<isotropic_remeshing_result> isotropic_remeshing(M& mesh,
                                                                     const isotropic_remeshing_options& options) {
    const double L = options.target_edge_length;
    if (auto ok = detail::remeshing::check_length(L); !ok) return ok.error();
    if (options.feature_angle && !(*options.feature_angle >= 0 && *options.feature_angle <= 180))
        return fail(errc::invalid_argument, "isotropic_remeshing: option feature_angle must lie in [0, 180] degrees, got " +
                                                detail::remeshing::number(*options.feature_angle));
    if (auto ok = detail::remeshing::check_finite<M, T>(mesh); !ok) return ok.error();
    for (auto f : T::faces(mesh)) {
        const auto h = T::face_halfedge(mesh, f);
        if (!detail::triangle_ops::in_triangle<M, T>(mesh, h))
            return fail(errc::unsupported,
                        "isotropic_remeshing: face " + std::to_string(T::face_index(mesh, f)) +
                            " is not a triangle (triangulate_faces first)",
                        (long long)T::face_index(mesh, f));
    }
    const auto estimate = estimate_isotropic_remeshing<M, T>(mesh, L);
    if (!estimate) return estimate.error();
    if (!(estimate->triangles <= double(options.max_faces)))
        return fail(errc::invalid_argument, "isotropic_remeshing: option target_edge_length " +
                                                detail::remeshing::number(L) + " would make " +
                                                detail::remeshing::count_text(estimate->triangles) +
                                                " triangles, more than max_faces " + std::to_string(options.max_faces));
    if (!(estimate->bytes <= double(options.max_bytes)))
        return fail(errc::invalid_argument,
                    "isotropic_remeshing: option target_edge_length " + detail::remeshing::number(L) + " would make " +
                        detail::remeshing::count_text(estimate->triangles) + " triangles needing about " +
                        detail::remeshing::bytes(estimate->bytes) + ", more than max_bytes " +
                        detail::remeshing::bytes(double(options.max_bytes)));
    std::vector<char> feature(T::edge_index_bound(mesh), 0);
    for (const auto i : options.feature_edges) {
        if (i >= feature.size())
            return fail(errc::invalid_argument,
                        "isotropic_remeshing: option feature_edges names edge " + std::to_string(i) + ", but edge indices end at " +
                            std::to_string(feature.size()),
                        (long long)i);
        feature[i] = 1;
    }

    detail::progress_gate gate(options.progress, 4 * options.iterations + 1);
    auto cancelled = [] { return fail(errc::cancelled, "isotropic_remeshing: cancelled"); };
    M work = mesh;
    // Far from unit size, work is the mesh scaled by a power of two (exact) to an extent in
    // [1, 2): products of four lengths in the projection stay normal doubles. `input` keeps
    // the positions to give back to the vertices that do not move.
    const double extent = detail::remeshing::check_scale<M, T>(mesh).value();
    const bool rescale = extent < 0x1p-200 || extent > 0x1p200;
    const double unit = rescale ? extent : 1.0;
    std::vector<vec3<double>> input;
    if (rescale) {
        input.resize(T::vertex_index_bound(work));
        for (auto v : T::vertices(work)) {
            const auto p = detail::triangle_ops::position_of<M, T>(work, v);
            input[T::vertex_index(work, v)] = p;
            detail::triangle_ops::set_position<M, T>(work, v, p / unit);
        }
    }
    if (options.feature_angle) {
        const double cos_limit = std::cos(*options.feature_angle * 3.14159265358979323846 / 180);
        auto normal = [&](typename T::halfedge_handle h) {
            const auto a = detail::triangle_ops::position_of<M, T>(work, T::target(work, T::opposite(work, h)));
            const auto b = detail::triangle_ops::position_of<M, T>(work, T::target(work, h));
            const auto c = detail::triangle_ops::position_of<M, T>(work, T::target(work, T::next(work, h)));
            return normalized(cross(b - a, c - a));
        };
        for (auto e : T::edges(work)) {
            const auto h = T::edge_halfedge(work, e), o = T::opposite(work, h);
            if (T::face(work, h) == T::null_face() || T::face(work, o) == T::null_face()) continue;
            if (dot(normal(h), normal(o)) < cos_limit) feature[T::edge_index(work, e)] = 1;
        }
    }
    std::optional<aabb_tree> surface;
    if (options.project) {
        auto tree = aabb_tree_from_mesh<M, T>(work);
        if (!tree) return tree.error();
        surface.emplace(std::move(*tree));
    }
    if (!gate.advance()) return cancelled();

    // The remesher keeps its feature and lock flags by index and only grows them, so a new
    // element in a freed slot would inherit a deleted one's flags: work appends instead.
    std::optional<detail::subdivision::appending_guard<M>> appending(std::in_place, work);
    detail::remeshing::remesher<M, T> r(work, L / unit, surface ? &*surface : nullptr);
    r.set_features(feature);
    isotropic_remeshing_result out;
    for (std::size_t k = 0; k < options.iterations; ++k) {
        r.split_long_edges();
        if (!gate.advance()) return cancelled();
        r.collapse_short_edges();
        if (!gate.advance()) return cancelled();
        r.equalize_valences();
        if (!gate.advance()) return cancelled();
        r.relax_and_project();
        if (!gate.advance()) return cancelled();
    }
    appending.reset();  // the caller's mesh keeps its own slot_reuse setting
    if (rescale)
        for (auto v : T::vertices(work)) {
            const auto i = T::vertex_index(work, v);
            const auto p = detail::triangle_ops::position_of<M, T>(work, v);
            const bool kept = i < input.size() && p == input[i] / unit;  // an input vertex that did not move
            detail::triangle_ops::set_position<M, T>(work, v, kept ? input[i] : p * unit);
        }
    mesh = std::move(work);
    out.splits = r.splits;
    out.collapses = r.collapses;
    out.flips = r.flips;
    out.feature_edges = r.initial_features;
    return out;
}

}  // namespace hmira
