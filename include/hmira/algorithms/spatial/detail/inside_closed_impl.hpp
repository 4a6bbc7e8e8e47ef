// hmira/algorithms/spatial/detail/inside_closed_impl.hpp
// The machinery of inside_closed (see ../inside_closed.hpp for the interface): the perturbed
// orientation of the query point against one edge in the yz plane, the signed crossing of one
// triangle, and the loop over points in parallel blocks.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "../../../core/progress.hpp"
#include "../../../core/result.hpp"
#include "../../../predicates/intersect3d.hpp"
#include "../../conversion/detail/parallel.hpp"
#include "../../triangulation/detail/indexed_triangles.hpp"
#include "../inside_closed.hpp"

namespace hmira::detail::inside {

using predicates::point3;

/// Sign of orient2d(a, b, q') in the yz plane for q' = q + (0, e, e^2), e > 0 infinitesimal:
/// the exact sign when it is not 0, else the sign of the coefficient of e, (a.z - b.z), else of
/// e^2, (b.y - a.y). Only a == b in yz gives 0. Swapping a and b negates every term, so the two
/// faces on an edge see it alike.
inline int perturbed_side(const point3& a, const point3& b, const point3& q) noexcept {
    if (const int o = predicates::orient2d(a.y, a.z, b.y, b.z, q.y, q.z); o != 0) return o;
    if (a.z != b.z) return a.z > b.z ? 1 : -1;
    if (a.y != b.y) return b.y > a.y ? 1 : -1;
    return 0;
}

/// What one triangle contributes for point q: on_surface, or its signed crossing (-1, 0, +1)
/// of the perturbed ray from q along +x.
struct crossing {
    bool on_surface = false;
    int sign = 0;
};

inline crossing cross(const point3& a, const point3& b, const point3& c, const point3& q) noexcept {
    const double xmax = std::max({a.x, b.x, c.x});
    const double ylo = std::min({a.y, b.y, c.y}), yhi = std::max({a.y, b.y, c.y});
    const double zlo = std::min({a.z, b.z, c.z}), zhi = std::max({a.z, b.z, c.z});
    // Outside the closed box in y or z, or wholly behind: neither on the face nor crossed.
    if (q.y < ylo || q.y > yhi || q.z < zlo || q.z > zhi || q.x > xmax) return {};
    if (q.x >= std::min({a.x, b.x, c.x}) && predicates::point_in_triangle(q, a, b, c)) return {true, 0};
    // Not on the face: the moved point q' leaves a box it touches only at its upper y or z end.
    if (q.y == yhi || q.z == zhi || q.x == xmax) return {};
    const int s = predicates::orient2d(a.y, a.z, b.y, b.z, c.y, c.z);  // sign of the normal's x
    if (s == 0) return {};                                             // parallel to the ray
    if (perturbed_side(a, b, q) != s || perturbed_side(b, c, q) != s || perturbed_side(c, a, q) != s) return {};
    // q' projects inside; the face is ahead along +x when q is on its back side. q is off the
    // face's plane here: on it, projecting inside the closed triangle, it would lie on the face.
    return {false, predicates::orient3d(a, b, c, q) == -s ? s : 0};
}

/// Winding number of q, or on_surface.
struct winding {
    bool on_surface = false;
    long long number = 0;
};

inline winding wind(const std::vector<triangulation::indexed_triangle>& tris, const std::vector<point3>& pos,
                    const point3& q) noexcept {
    winding w;
    for (const auto& t : tris) {
        const crossing c = cross(pos[t.v[0]], pos[t.v[1]], pos[t.v[2]], q);
        if (c.on_surface) return {true, 0};
        w.number += c.sign;
    }
    return w;
}

inline result<void> check_point(const vec3<double>& p, std::size_t i) {
    for (std::size_t k = 0; k < 3; ++k)
        if (!predicates::in_predicate_range(p[k]))
            return fail(errc::invalid_argument,
                        "inside_closed: point " + std::to_string(i) +
                            " has a coordinate that is not finite or outside the exact predicates' range",
                        (long long)i);
    return {};
}

/// Points per block of the parallel loop: each block is one progress step.
inline constexpr std::size_t block_size = 64;

}  // namespace hmira::detail::inside

namespace hmira {

template <class M, class T>
    requires inside_closed_mesh<M, T>
result<std::vector<point_location>> inside_closed(const M& mesh, std::span<const vec3<double>> points,
                                                  const inside_closed_options& options) {
    namespace di = detail::inside;
    auto pos = detail::triangulation::predicate_positions<M, T>(mesh, "inside_closed");
    if (!pos) return pos.error();
    for (std::size_t i = 0; i < points.size(); ++i)
        if (auto ok = di::check_point(points[i], i); !ok) return ok.error();
    const auto tris = detail::triangulation::indexed_triangles<M, T>(mesh);
    std::vector<point_location> out(points.size(), point_location::outside);
    const std::size_t blocks = (points.size() + di::block_size - 1) / di::block_size;
    detail::progress_gate gate(options.progress, blocks, "inside_closed");
    detail::with_thread_count(options.threads, [&] {
        detail::parallel_chunks(blocks, 1, [&](std::size_t b0, std::size_t b1) {
            for (std::size_t b = b0; b < b1; ++b) {
                if (gate.cancelled()) return;
                const std::size_t end = std::min(points.size(), (b + 1) * di::block_size);
                for (std::size_t i = b * di::block_size; i < end; ++i) {
                    const di::winding w = di::wind(tris, *pos, points[i]);
                    out[i] = w.on_surface    ? point_location::on_surface
                             : w.number != 0 ? point_location::inside
                                             : point_location::outside;
                }
                gate.advance();
            }
        });
    });
    if (gate.cancelled()) return fail(errc::cancelled, "inside_closed: cancelled");
    return out;
}

template <class M, class T>
    requires inside_closed_mesh<M, T>
result<point_location> inside_closed(const M& mesh, const vec3<double>& point) {
    auto r = inside_closed<M, T>(mesh, std::span<const vec3<double>>(&point, 1));
    if (!r) return r.error();
    return (*r)[0];
}

template <class M, class T>
    requires inside_closed_mesh<M, T>
result<long long> closed_winding_number(const M& mesh, const vec3<double>& point) {
    auto pos = detail::triangulation::predicate_positions<M, T>(mesh, "closed_winding_number");
    if (!pos) return pos.error();
    if (auto ok = detail::inside::check_point(point, 0); !ok) return ok.error();
    const auto w = detail::inside::wind(detail::triangulation::indexed_triangles<M, T>(mesh), *pos, point);
    if (w.on_surface)
        return fail(errc::invalid_argument, "closed_winding_number: the point lies on the surface, which has none");
    return w.number;
}

}  // namespace hmira
