// hmira/algorithms/spatial/detail/hausdorff_distance_impl.hpp
// The machinery of hausdorff_distance (see ../hausdorff_distance.hpp): per-triangle sampling
// into per-triangle partial sums, reduced in order so that the answer ignores the schedule.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "../../../core/result.hpp"
#include "../../conversion/detail/parallel.hpp"
#include "../aabb_tree.hpp"
#include "../hausdorff_distance.hpp"
#include "sample_surface_impl.hpp"

namespace hmira {

namespace detail::spatial {

struct distance_sums {
    double max = 0, sum = 0, sum2 = 0;
    std::size_t n = 0;
    void add(double d) {
        max = std::max(max, d);
        sum += d;
        sum2 += d * d;
        ++n;
    }
};

inline one_sided_distance sampled_distance(const triangle_set& from, const aabb_tree& to, const hausdorff_options& o) {
    const std::size_t f = from.triangles.size();
    const std::size_t k = std::max(o.per_triangle, (o.min_samples + f - 1) / f);
    // Only the vertices a triangle uses: a model may keep deleted vertices below its bound.
    std::vector<char> used(from.points.size(), 0);
    for (const auto& t : from.triangles) used[t[0]] = used[t[1]] = used[t[2]] = 1;
    std::vector<distance_sums> per_triangle(f), per_vertex(from.points.size());
    with_thread_count(o.threads, [&] {
        parallel_chunks(f, 16, [&](std::size_t b, std::size_t e) {
            for (std::size_t i = b; i < e; ++i) {
                const auto& t = from.triangles[i];
                const auto a = from.points[t[0]], ab = from.points[t[1]] - a, ac = from.points[t[2]] - a;
                uniform01 u(o.seed ^ std::uint64_t(i));
                for (std::size_t s = 0; s < k; ++s) {
                    const double r = std::sqrt(u()), v = u();
                    per_triangle[i].add(to.closest_point(a + ab * (r * (1 - v)) + ac * (r * v)).distance);
                }
            }
        });
        parallel_chunks(from.points.size(), 256, [&](std::size_t b, std::size_t e) {
            for (std::size_t i = b; i < e; ++i)
                if (used[i]) per_vertex[i].add(to.closest_point(from.points[i]).distance);
        });
    });
    distance_sums all;
    for (const auto* part : {&per_triangle, &per_vertex})
        for (const auto& p : *part) {
            all.max = std::max(all.max, p.max);
            all.sum += p.sum;
            all.sum2 += p.sum2;
            all.n += p.n;
        }
    one_sided_distance out;
    out.max = all.max;
    out.samples = all.n;
    out.mean = all.n ? all.sum / double(all.n) : 0.0;
    out.rms = all.n ? std::sqrt(all.sum2 / double(all.n)) : 0.0;
    return out;
}

}  // namespace detail::spatial

inline result<one_sided_distance> one_sided_hausdorff_distance(const triangle_set& from, const triangle_set& to,
                                                               const hausdorff_options& options) {
    if (from.triangles.empty() || to.triangles.empty())
        return fail(errc::invalid_argument, std::string("hausdorff_distance: the ") +
                                                (from.triangles.empty() ? "sampled" : "target") + " mesh has no faces");
    const aabb_tree tree(to.points, to.triangles);
    return detail::spatial::sampled_distance(from, tree, options);
}

inline result<hausdorff_result> hausdorff_distance(const triangle_set& a, const triangle_set& b,
                                                   const hausdorff_options& options) {
    if (a.triangles.empty() || b.triangles.empty())
        return fail(errc::invalid_argument,
                    std::string("hausdorff_distance: mesh ") + (a.triangles.empty() ? "A" : "B") + " has no faces");
    auto ab = one_sided_hausdorff_distance(a, b, options);
    if (!ab) return ab.error();
    auto ba = one_sided_hausdorff_distance(b, a, options);
    if (!ba) return ba.error();
    return hausdorff_result{*ab, *ba, std::max(ab->max, ba->max)};
}

template <class MA, class MB, class TA, class TB>
    requires surface_query_mesh<MA, TA> && surface_query_mesh<MB, TB>
result<hausdorff_result> hausdorff_distance(const MA& a, const MB& b, const hausdorff_options& options) {
    auto sa = triangles_of<MA, TA>(a, "hausdorff_distance");
    if (!sa) return sa.error();
    auto sb = triangles_of<MB, TB>(b, "hausdorff_distance");
    if (!sb) return sb.error();
    return hausdorff_distance(*sa, *sb, options);
}

}  // namespace hmira
