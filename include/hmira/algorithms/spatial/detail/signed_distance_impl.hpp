// hmira/algorithms/spatial/detail/signed_distance_impl.hpp
// The machinery of contains and signed_distance (see ../signed_distance.hpp): one engine that
// holds the closest-point tree, the winding-number tree and the pseudo-normals, and answers one
// point at a time; the batched loops over it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <unordered_map>
#include <vector>

#include "../../../core/result.hpp"
#include "../../../core/vec3.hpp"
#include "../../conversion/detail/parallel.hpp"
#include "../aabb_tree.hpp"
#include "../signed_distance.hpp"
#include "winding_number_impl.hpp"

namespace hmira {

namespace detail::spatial {

/// Which part of a triangle a closest point lies on: corner 0, 1, 2; edge 01, 02, 12; inside.
enum class triangle_region : std::uint8_t { v0, v1, v2, e01, e02, e12, face };

/// The Voronoi region of triangle (a, b, c) holding the point closest to p: the same tests, in
/// the same order, as closest_on_triangle, so region and point agree.
inline triangle_region closest_region(const vec3<double>& p, const vec3<double>& a, const vec3<double>& b,
                                      const vec3<double>& c) {
    const auto ab = b - a, ac = c - a, ap = p - a;
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return triangle_region::v0;
    const auto bp = p - b;
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return triangle_region::v1;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return triangle_region::e01;
    const auto cp = p - c;
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return triangle_region::v2;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return triangle_region::e02;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return triangle_region::e12;
    if (!(std::abs(va + vb + vc) > 0)) return triangle_region::v0;
    return triangle_region::face;
}

/// Everything a signed-distance query needs, built once per call.
class distance_engine {
public:
    distance_engine(const triangle_set& s, sign_mode sign) : s_(s), sign_(sign), tree_(s.points, s.triangles) {
        if (sign == sign_mode::winding_number) winding_.emplace(s);
        if (sign == sign_mode::pseudo_normal) build_pseudo_normals();
    }

    /// The signed distance at q (finite), with the closest point and its triangle; samples
    /// farther than `band` get +-band and no closest point.
    double at(const vec3<double>& q, double beta, double band, vec3<double>* closest, std::size_t* triangle) const {
        const auto c = tree_.closest_point(q, band);
        const bool found = std::isfinite(c.distance);
        if (closest) *closest = c.point;
        if (triangle) *triangle = c.face;
        const double d = found ? c.distance : band;
        return inside(q, c, found, beta) ? -d : d;
    }

private:
    bool inside(const vec3<double>& q, const closest_point_result& c, bool found, double beta) const {
        switch (sign_) {
            case sign_mode::winding_number: return winding_->query(q, beta).first >= 0.5;
            case sign_mode::parity: return odd_crossings(q);
            case sign_mode::pseudo_normal: {
                if (!found) return false;  // a far sample of the narrow band has no closest point
                const auto& t = s_.triangles[c.face];
                const auto& a = s_.points[t[0]];
                const auto& b = s_.points[t[1]];
                const auto& cc = s_.points[t[2]];
                vec3<double> n{};
                switch (closest_region(q, a, b, cc)) {
                    case triangle_region::v0: n = vertex_normal_[t[0]]; break;
                    case triangle_region::v1: n = vertex_normal_[t[1]]; break;
                    case triangle_region::v2: n = vertex_normal_[t[2]]; break;
                    case triangle_region::e01: n = edge_normal(t[0], t[1]); break;
                    case triangle_region::e02: n = edge_normal(t[0], t[2]); break;
                    case triangle_region::e12: n = edge_normal(t[1], t[2]); break;
                    case triangle_region::face: n = face_normal_[c.face]; break;
                }
                return dot(q - c.point, n) < 0;
            }
        }
        return false;
    }

    // Distinct hit parameters along one fixed, generic direction, each found by the tree's
    // first-hit query past the previous one.
    bool odd_crossings(const vec3<double>& q) const {
        static constexpr vec3<double> direction{0.5773502691896258, 0.5773502691896257, 0.5773502691896259};
        double t_min = 0;
        std::size_t hits = 0;
        for (std::size_t guard = 0; guard <= s_.triangles.size(); ++guard) {
            const auto h = tree_.ray_intersect({.origin = q, .direction = direction, .t_min = t_min});
            if (!h) break;
            ++hits;
            t_min = std::nextafter(h->t, std::numeric_limits<double>::infinity());
        }
        return hits % 2 == 1;
    }

    static std::uint64_t edge_key(std::uint32_t u, std::uint32_t v) {
        return (std::uint64_t(std::min(u, v)) << 32) | std::max(u, v);
    }
    vec3<double> edge_normal(std::uint32_t u, std::uint32_t v) const { return edge_normal_.at(edge_key(u, v)); }

    void build_pseudo_normals() {
        vertex_normal_.assign(s_.points.size(), {});
        face_normal_.resize(s_.triangles.size());
        for (std::size_t i = 0; i < s_.triangles.size(); ++i) {
            const auto& t = s_.triangles[i];
            const auto n = cross(s_.points[t[1]] - s_.points[t[0]], s_.points[t[2]] - s_.points[t[0]]);
            const double l = norm(n);
            face_normal_[i] = l > 0 ? n / l : vec3<double>{};
            for (std::size_t k = 0; k < 3; ++k) {
                const auto& p = s_.points[t[k]];
                const auto u = s_.points[t[(k + 1) % 3]] - p, w = s_.points[t[(k + 2) % 3]] - p;
                vertex_normal_[t[k]] += face_normal_[i] * std::atan2(norm(cross(u, w)), dot(u, w));
                edge_normal_[edge_key(t[k], t[(k + 1) % 3])] += face_normal_[i];
            }
        }
    }

    const triangle_set& s_;
    sign_mode sign_;
    aabb_tree tree_;
    std::optional<winding_tree> winding_;
    std::vector<vec3<double>> vertex_normal_, face_normal_;
    std::unordered_map<std::uint64_t, vec3<double>> edge_normal_;
};

}  // namespace detail::spatial

inline result<std::vector<std::uint8_t>> contains(const triangle_set& surface, std::span<const vec3<double>> points,
                                                  const winding_number_options& options) {
    if (auto ok = detail::spatial::check_query(surface, points, options.nan, "contains"); !ok) return ok.error();
    if (auto ok = detail::spatial::check_winding_options(options, "contains"); !ok) return ok.error();
    auto o = options;
    o.error_bounds = false;
    const auto w = detail::spatial::winding_numbers_of(surface, points, o);
    std::vector<std::uint8_t> out(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) out[i] = w.values[i] >= 0.5 ? 1 : 0;
    return out;
}

inline result<signed_distances> signed_distance(const triangle_set& surface, std::span<const vec3<double>> points,
                                                const signed_distance_options& options) {
    if (auto ok = detail::spatial::check_query(surface, points, options.nan, "signed_distance"); !ok) return ok.error();
    if (auto ok = detail::spatial::check_winding_options({.beta = options.beta}, "signed_distance"); !ok)
        return ok.error();
    const detail::spatial::distance_engine engine(surface, options.sign);
    signed_distances out;
    out.distances.assign(points.size(), std::numeric_limits<double>::quiet_NaN());
    out.closest.assign(points.size(), vec3<double>{});
    out.faces.assign(points.size(), 0);
    constexpr double inf = std::numeric_limits<double>::infinity();
    detail::with_thread_count(options.threads, [&] {
        detail::parallel_chunks(points.size(), 64, [&](std::size_t b, std::size_t e) {
            for (std::size_t i = b; i < e; ++i) {
                const auto& q = points[i];
                if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z)) continue;
                std::size_t t = 0;
                out.distances[i] = engine.at(q, options.beta, inf, &out.closest[i], &t);
                out.faces[i] = surface.faces[t];
            }
        });
    });
    return out;
}

template <class M, class T>
    requires surface_query_mesh<M, T>
result<std::vector<std::uint8_t>> contains(const M& mesh, std::span<const vec3<double>> points,
                                           const winding_number_options& options) {
    auto s = triangles_of<M, T>(mesh, "contains");
    if (!s) return s.error();
    return contains(*s, points, options);
}

template <class M, class T>
    requires surface_query_mesh<M, T>
result<signed_distances> signed_distance(const M& mesh, std::span<const vec3<double>> points,
                                         const signed_distance_options& options) {
    auto s = triangles_of<M, T>(mesh, "signed_distance");
    if (!s) return s.error();
    return signed_distance(*s, points, options);
}

}  // namespace hmira
