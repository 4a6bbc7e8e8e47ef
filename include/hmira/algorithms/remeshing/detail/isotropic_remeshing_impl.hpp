// hmira/algorithms/remeshing/detail/isotropic_remeshing_impl.hpp
// The machinery of isotropic_remeshing (remeshing/isotropic_remeshing.hpp): the checks of scale
// and range, and the definitions of the entry points; the passes are in remesher.hpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <cstddef>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "../../../core/rollback.hpp"
#include "../../geometry/mean_edge_length.hpp"
#include "../../spatial/aabb_tree.hpp"
#include "../../subdivision/detail/reserve.hpp"
#include "remesher.hpp"

namespace hmira {

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

template <class M, class T>
    requires remeshable_mesh<M, T>
result<double> default_target_edge_length(const M& mesh) {
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

template <class M, class T>
    requires remeshable_mesh<M, T>
result<isotropic_remeshing_estimate> estimate_isotropic_remeshing(const M& mesh, double L) {
    if (auto ok = detail::remeshing::check_length(L); !ok) return ok.error();
    if (auto ok = detail::remeshing::check_finite<M, T>(mesh); !ok) return ok.error();
    if (auto ok = detail::remeshing::check_scale<M, T>(mesh); !ok) return ok.error();
    const double triangles = detail::remeshing::area_over_squared_length<M, T>(mesh, L) / (std::sqrt(3.0) / 4);
    return isotropic_remeshing_estimate{triangles,
                                        (triangles + double(T::face_count(mesh))) * remeshing_bytes_per_triangle};
}

template <class M, class T>
    requires remeshable_mesh<M, T>
result<isotropic_remeshing_result> isotropic_remeshing(M& mesh, const isotropic_remeshing_options& options) {
    const double L = options.target_edge_length;
    if (auto ok = detail::remeshing::check_length(L); !ok) return ok.error();
    if (options.feature_angle && !(*options.feature_angle >= 0 && *options.feature_angle <= 180))
        return fail(errc::invalid_argument,
                    "isotropic_remeshing: option feature_angle must lie in [0, 180] degrees, got " +
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
                        "isotropic_remeshing: option feature_edges names edge " + std::to_string(i) +
                            ", but edge indices end at " + std::to_string(feature.size()),
                        (long long)i);
        feature[i] = 1;
    }

    detail::progress_gate gate(options.progress, 4 * options.iterations + 1);
    auto cancelled = [] { return fail(errc::cancelled, "isotropic_remeshing: cancelled"); };
    // The remesher works on the mesh itself; a copy taken before the first change is what a
    // failure or a cancellation restores (mesh_rollback). It is taken even without a callback:
    // the scaling below comes before the last check (the aabb_tree of the input).
    mesh_rollback<M> undo(mesh, true);
    M& work = mesh;
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
    undo.commit();
    out.splits = r.splits;
    out.collapses = r.collapses;
    out.flips = r.flips;
    out.feature_edges = r.initial_features;
    return out;
}

}  // namespace hmira
