// hmira/algorithms/spatial/detail/sample_surface_impl.hpp
// The machinery of sample_surface (see ../sample_surface.hpp): the portable uniform numbers,
// area-weighted triangle choice, and Yuksel's sample elimination over a hash grid.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <queue>
#include <random>
#include <unordered_map>
#include <utility>
#include <vector>

#include "../../../core/result.hpp"
#include "../../../core/vec3.hpp"
#include "../sample_surface.hpp"

namespace hmira {

namespace detail::spatial {

/// Uniform doubles in [0, 1) from std::mt19937_64, whose output the standard fixes: the top
/// 53 bits times 2^-53, the same on every platform.
class uniform01 {
public:
    explicit uniform01(std::uint64_t seed) : engine_(seed) {}
    double operator()() { return double(engine_() >> 11) * 0x1p-53; }

private:
    std::mt19937_64 engine_;
};

/// The triangles' areas summed in order, and a point chooser over them.
struct area_table {
    std::vector<double> cumulative;  // cumulative[i] = area of triangles 0..i
    double total() const { return cumulative.empty() ? 0.0 : cumulative.back(); }
};

inline area_table areas_of(const triangle_set& s) {
    area_table t;
    t.cumulative.reserve(s.triangles.size());
    double sum = 0;
    for (const auto& tri : s.triangles) {
        const auto& a = s.points[tri[0]];
        sum += 0.5 * norm(cross(s.points[tri[1]] - a, s.points[tri[2]] - a));
        t.cumulative.push_back(sum);
    }
    return t;
}

/// Appends one uniform sample: a triangle by area (zero-area ones are never chosen), then a
/// point by the square-root map.
inline void add_uniform_sample(const triangle_set& s, const area_table& areas, uniform01& u, surface_samples& out) {
    const double x = u() * areas.total();
    auto it = std::upper_bound(areas.cumulative.begin(), areas.cumulative.end(), x);
    if (it == areas.cumulative.end()) --it;
    const auto i = std::size_t(it - areas.cumulative.begin());
    const double r = std::sqrt(u()), v = u();
    const std::array<double, 3> b{1 - r, r * (1 - v), r * v};
    const auto& t = s.triangles[i];
    out.points.push_back(s.points[t[0]] * b[0] + s.points[t[1]] * b[1] + s.points[t[2]] * b[2]);
    out.faces.push_back(s.faces[i]);
    out.barycentrics.push_back(b);
    out.corners.push_back({t[0], t[1], t[2]});
}

/// Keeps `count` of the candidates by Yuksel's weighted sample elimination.
inline surface_samples eliminate(const surface_samples& c, std::size_t count, double area) {
    const std::size_t n = c.points.size();
    const double r_max = std::sqrt(area / (2 * std::sqrt(3.0) * double(count)));
    const double reach = 2 * r_max, cell = reach;
    auto key = [&](const vec3<double>& p, long long dx, long long dy, long long dz) {
        const auto ix = std::uint64_t(std::llround(std::floor(p.x / cell)) + dx) & 0x1fffff;
        const auto iy = std::uint64_t(std::llround(std::floor(p.y / cell)) + dy) & 0x1fffff;
        const auto iz = std::uint64_t(std::llround(std::floor(p.z / cell)) + dz) & 0x1fffff;
        return ix | (iy << 21) | (iz << 42);
    };
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> grid;
    for (std::size_t i = 0; i < n; ++i) grid[key(c.points[i], 0, 0, 0)].push_back(std::uint32_t(i));
    std::vector<std::vector<std::pair<std::uint32_t, double>>> near(n);
    std::vector<double> weight(n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
        for (long long dz = -1; dz <= 1; ++dz)
            for (long long dy = -1; dy <= 1; ++dy)
                for (long long dx = -1; dx <= 1; ++dx) {
                    const auto it = grid.find(key(c.points[i], dx, dy, dz));
                    if (it == grid.end()) continue;
                    for (auto j : it->second) {
                        if (j == i) continue;
                        const double d = norm(c.points[i] - c.points[j]);
                        if (d >= reach) continue;
                        const double x = 1 - d / reach, x2 = x * x, x4 = x2 * x2;
                        const double w = x4 * x4;
                        near[i].push_back({j, w});
                        weight[i] += w;
                    }
                }
    std::priority_queue<std::pair<double, std::uint32_t>> heap;
    for (std::size_t i = 0; i < n; ++i) heap.push({weight[i], std::uint32_t(i)});
    std::vector<char> removed(n, 0);
    for (std::size_t left = n; left > count && !heap.empty();) {
        const auto [w, i] = heap.top();
        heap.pop();
        if (removed[i] || w != weight[i]) continue;
        removed[i] = 1;
        --left;
        for (const auto& [j, wj] : near[i])
            if (!removed[j]) {
                weight[j] -= wj;
                heap.push({weight[j], j});
            }
    }
    surface_samples out;
    for (std::size_t i = 0; i < n; ++i)
        if (!removed[i]) {
            out.points.push_back(c.points[i]);
            out.faces.push_back(c.faces[i]);
            out.barycentrics.push_back(c.barycentrics[i]);
            out.corners.push_back(c.corners[i]);
        }
    return out;
}

}  // namespace detail::spatial

inline result<surface_samples> sample_surface(const triangle_set& surface, std::size_t count,
                                              const sample_surface_options& options) {
    namespace ds = detail::spatial;
    const auto areas = ds::areas_of(surface);
    if (!(areas.total() > 0)) return fail(errc::invalid_argument, "sample_surface: the mesh has no area to sample");
    ds::uniform01 u(options.seed);
    const std::size_t candidates = options.method == sampling_method::poisson_disk ? 5 * count : count;
    surface_samples out;
    out.points.reserve(candidates);
    for (std::size_t i = 0; i < candidates; ++i) ds::add_uniform_sample(surface, areas, u, out);
    if (options.method == sampling_method::poisson_disk && count > 0) return ds::eliminate(out, count, areas.total());
    return out;
}

template <class M, class T>
    requires surface_query_mesh<M, T>
result<surface_samples> sample_surface(const M& mesh, std::size_t count, const sample_surface_options& options) {
    auto s = triangles_of<M, T>(mesh, "sample_surface");
    if (!s) return s.error();
    return sample_surface(*s, count, options);
}

}  // namespace hmira
