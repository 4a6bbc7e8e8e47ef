// hmira/algorithms/spatial/detail/signed_distance_grid_impl.hpp
// The machinery of signed_distance_grid and offset (see ../signed_distance_grid.hpp): rows of
// samples through one distance engine, and the grid placed about an offset surface.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

#include "../../../core/result.hpp"
#include "../../conversion/detail/parallel.hpp"
#include "../../conversion/marching_cubes.hpp"
#include "../signed_distance_grid.hpp"
#include "signed_distance_impl.hpp"

namespace hmira {

template <class V>
result<dense_grid<V>> signed_distance_grid(const triangle_set& surface, const grid_geometry& g,
                                           const signed_distance_grid_options& options) {
    if (auto ok = check_grid_geometry(g, "signed_distance_grid"); !ok) return ok.error();
    if (!(options.band > 0))
        return fail(errc::invalid_argument,
                    "signed_distance_grid: band must be positive, got " + std::to_string(options.band));
    if (surface.triangles.empty()) return fail(errc::invalid_argument, "signed_distance_grid: the mesh has no faces");
    if (auto ok = detail::spatial::check_winding_options({.beta = options.beta}, "signed_distance_grid"); !ok)
        return ok.error();
    const detail::spatial::distance_engine engine(surface, options.sign);
    dense_grid<V> grid(g);
    detail::with_thread_count(options.threads, [&] {
        detail::parallel_chunks(g.dims[1] * g.dims[2], 1, [&](std::size_t r0, std::size_t r1) {
            for (std::size_t r = r0; r < r1; ++r) {
                const std::size_t j = r % g.dims[1], k = r / g.dims[1];
                for (std::size_t i = 0; i < g.dims[0]; ++i)
                    grid.set(i, j, k, V(engine.at(g.position(i, j, k), options.beta, options.band, nullptr, nullptr)));
            }
        });
    });
    return grid;
}

inline result<indexed_triangles<double>> offset(const triangle_set& surface, double d, const offset_options& options) {
    if (!std::isfinite(d)) return fail(errc::invalid_argument, "offset: the distance must be finite");
    if (options.resolution < 8)
        return fail(errc::invalid_argument,
                    "offset: resolution must be at least 8, got " + std::to_string(options.resolution));
    if (surface.triangles.empty()) return fail(errc::invalid_argument, "offset: the mesh has no faces");
    vec3<double> lo{}, hi{};
    bool first = true;
    for (const auto& t : surface.triangles)
        for (auto c : t) {
            const auto& p = surface.points[c];
            if (first) lo = hi = p, first = false;
            for (std::size_t a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
        }
    const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z}) + 2 * std::abs(d);
    // Three samples of margin beyond |d| on each side, within `resolution` samples in all.
    const double h = extent > 0 ? extent / double(options.resolution - 7) : 1.0;
    const double margin = std::abs(d) + 3 * h;
    const auto overflow = [] {
        return fail(errc::invalid_argument,
                    "offset: the mesh's extent plus the distance overflows double; scale the mesh down first");
    };
    if (!std::isfinite(extent) || !std::isfinite(margin) || !(h > 0)) return overflow();
    grid_geometry g;
    g.spacing = {h, h, h};
    for (std::size_t a = 0; a < 3; ++a) {
        g.origin[a] = lo[a] - margin;
        const double samples = std::ceil((hi[a] - lo[a] + 2 * margin) / h);
        if (!std::isfinite(g.origin[a]) || !(samples >= 0 && samples <= double(options.resolution) + 8))
            return overflow();
        g.dims[a] = std::size_t(samples) + 1;
    }
    auto field = signed_distance_grid<double>(
        surface, g, {.band = std::abs(d) + 3 * h, .beta = options.beta, .threads = options.threads});
    if (!field) return fail(field.error().code, "offset: " + field.error().message, field.error().element);
    auto mesh = marching_cubes_indexed<double>(*field, {.iso = d, .threads = options.threads});
    if (!mesh) return fail(mesh.error().code, "offset: " + mesh.error().message, mesh.error().element);
    return mesh;
}

template <class V, class M, class T>
    requires surface_query_mesh<M, T>
result<dense_grid<V>> signed_distance_grid(const M& mesh, const grid_geometry& g,
                                           const signed_distance_grid_options& options) {
    auto s = triangles_of<M, T>(mesh, "signed_distance_grid");
    if (!s) return s.error();
    return signed_distance_grid<V>(*s, g, options);
}

template <class M, class T>
    requires surface_query_mesh<M, T>
result<indexed_triangles<double>> offset(const M& mesh, double d, const offset_options& options) {
    auto s = triangles_of<M, T>(mesh, "offset");
    if (!s) return s.error();
    return offset(*s, d, options);
}

}  // namespace hmira
