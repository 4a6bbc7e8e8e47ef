// hmira/algorithms/remeshing/isotropic_remeshing.hpp
// Isotropic remeshing (Botsch and Kobbelt 2004): turns a triangle mesh into one whose edges
// all have about the same length and whose triangles are nearly equilateral, on the same surface.
#pragma once

#include <cmath>
#include <concepts>
#include <cstddef>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/progress.hpp"
#include "../../core/result.hpp"
#include "../spatial/aabb_tree.hpp"
#include "../triangle/triangle_common.hpp"
#include "../subdivision/detail/reserve.hpp"
#include "detail/remesher.hpp"

namespace hmira {

namespace detail::remeshing {
/// A number as a message shows it: 6 significant digits, exponent when needed ("1e-07").
inline std::string number(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
}
}  // namespace detail::remeshing

/// Options of isotropic_remeshing.
struct isotropic_remeshing_options {
    /// The edge length L to reach: edges end up within [4/5 L, 4/3 L]. Required (> 0).
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
    /// Refuses a target length that would make more triangles than this (the estimate is the
    /// surface area over the area of an equilateral triangle of side L).
    std::size_t max_faces = std::size_t{1} << 28;
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
/// Errors (mesh unchanged): errc::invalid_argument for a target length that is not a finite
/// positive number or too small (options.max_faces), a feature angle outside [0, 180], a
/// feature edge index out of range, or a vertex with a non-finite position (named);
/// errc::unsupported for a face that is not a triangle (named); errc::invalid_argument ending
/// in "cancelled" when options.progress returns false.
/// Complexity O(iterations * (F log F_in)) for F faces at the end, F_in at the start (each
/// projection is a closest-point query, O(log F_in)); O(F + F_in) extra memory.
template <class M, class T = default_traits<M>>
    requires remeshable_mesh<M, T>
[[nodiscard]] result<isotropic_remeshing_result> isotropic_remeshing(M& mesh,
                                                                     const isotropic_remeshing_options& options) {
    const double L = options.target_edge_length;
    if (!(std::isfinite(L) && L > 0))
        return fail(errc::invalid_argument, "isotropic_remeshing: option target_edge_length must be a finite number > 0, got " +
                                                detail::remeshing::number(L));
    if (options.feature_angle && !(*options.feature_angle >= 0 && *options.feature_angle <= 180))
        return fail(errc::invalid_argument, "isotropic_remeshing: option feature_angle must lie in [0, 180] degrees, got " +
                                                detail::remeshing::number(*options.feature_angle));
    for (auto v : T::vertices(mesh))
        if (!detail::triangle_ops::finite(detail::triangle_ops::position_of<M, T>(mesh, v)))
            return fail(errc::invalid_argument,
                        "isotropic_remeshing: vertex " + std::to_string(T::vertex_index(mesh, v)) + " has a non-finite position",
                        (long long)T::vertex_index(mesh, v));
    double area = 0;
    for (auto f : T::faces(mesh)) {
        const auto h = T::face_halfedge(mesh, f);
        if (!detail::triangle_ops::in_triangle<M, T>(mesh, h))
            return fail(errc::unsupported,
                        "isotropic_remeshing: face " + std::to_string(T::face_index(mesh, f)) +
                            " is not a triangle (triangulate_faces first)",
                        (long long)T::face_index(mesh, f));
        const auto a = detail::triangle_ops::position_of<M, T>(mesh, T::target(mesh, T::opposite(mesh, h)));
        const auto b = detail::triangle_ops::position_of<M, T>(mesh, T::target(mesh, h));
        const auto c = detail::triangle_ops::position_of<M, T>(mesh, T::target(mesh, T::next(mesh, h)));
        area += 0.5 * norm(cross(b - a, c - a));
    }
    const double expected_faces = area / (std::sqrt(3.0) / 4 * L * L);
    if (!(expected_faces <= double(options.max_faces)))
        return fail(errc::invalid_argument, "isotropic_remeshing: option target_edge_length " + detail::remeshing::number(L) +
                                                " would make about " + detail::remeshing::number(expected_faces) +
                                                " triangles, more than max_faces " + std::to_string(options.max_faces));
    std::vector<char> feature(T::edge_index_bound(mesh), 0);
    for (const auto i : options.feature_edges) {
        if (i >= feature.size())
            return fail(errc::invalid_argument,
                        "isotropic_remeshing: option feature_edges names edge " + std::to_string(i) + ", but edge indices end at " +
                            std::to_string(feature.size()),
                        (long long)i);
        feature[i] = 1;
    }
    if (options.feature_angle) {
        const double cos_limit = std::cos(*options.feature_angle * 3.14159265358979323846 / 180);
        auto normal = [&](typename T::halfedge_handle h) {
            const auto a = detail::triangle_ops::position_of<M, T>(mesh, T::target(mesh, T::opposite(mesh, h)));
            const auto b = detail::triangle_ops::position_of<M, T>(mesh, T::target(mesh, h));
            const auto c = detail::triangle_ops::position_of<M, T>(mesh, T::target(mesh, T::next(mesh, h)));
            return normalized(cross(b - a, c - a));
        };
        for (auto e : T::edges(mesh)) {
            const auto h = T::edge_halfedge(mesh, e), o = T::opposite(mesh, h);
            if (T::face(mesh, h) == T::null_face() || T::face(mesh, o) == T::null_face()) continue;
            if (dot(normal(h), normal(o)) < cos_limit) feature[T::edge_index(mesh, e)] = 1;
        }
    }

    detail::progress_gate gate(options.progress, 4 * options.iterations + 1);
    auto cancelled = [] { return fail(errc::cancelled, "isotropic_remeshing: cancelled"); };
    std::optional<aabb_tree> surface;
    if (options.project) {
        auto tree = aabb_tree_from_mesh<M, T>(mesh);
        if (!tree) return tree.error();
        surface.emplace(std::move(*tree));
    }
    if (!gate.advance()) return cancelled();

    M work = mesh;
    // The remesher keeps its feature and lock flags by index and only grows them, so a new
    // element in a freed slot would inherit a deleted one's flags: work appends instead.
    std::optional<detail::subdivision::appending_guard<M>> appending(std::in_place, work);
    detail::remeshing::remesher<M, T> r(work, L, surface ? &*surface : nullptr);
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
    mesh = std::move(work);
    out.splits = r.splits;
    out.collapses = r.collapses;
    out.flips = r.flips;
    out.feature_edges = r.initial_features;
    return out;
}

}  // namespace hmira
