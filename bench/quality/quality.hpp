// bench/quality/quality.hpp
// How good a decimated or remeshed surface is: the symmetric Hausdorff distance to the input
// (the library's hausdorff_distance), triangle-quality histograms and edge-length statistics.
// Used by the mesh_quality tool and by the decimation and remeshing benchmarks.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <hmira/algorithms/spatial/hausdorff_distance.hpp>
#include <hmira/concepts.hpp>

namespace hmira_bench::quality {

using hmira::vec3;

/// A mesh as plain triangles (polygons fanned from their first corner).
struct triangle_soup {
    std::vector<vec3<double>> points;
    std::vector<std::array<std::uint32_t, 3>> triangles;
};

/// Any mesh with positions and face loops as a triangle soup. O(V + C).
template <class M, class T = hmira::default_traits<M>>
triangle_soup soup_of(const M& mesh) {
    triangle_soup s;
    s.points.resize(T::vertex_index_bound(mesh));
    for (auto v : T::vertices(mesh)) {
        const auto p = T::position(mesh, v);
        s.points[T::vertex_index(mesh, v)] = {double(p[0]), double(p[1]), double(p[2])};
    }
    std::vector<std::uint32_t> loop;
    for (auto f : T::faces(mesh)) {
        loop.clear();
        for (auto v : T::face_vertices(mesh, f)) loop.push_back(std::uint32_t(T::vertex_index(mesh, v)));
        for (std::size_t i = 1; i + 1 < loop.size(); ++i) s.triangles.push_back({loop[0], loop[i], loop[i + 1]});
    }
    return s;
}

/// One direction of the sampled distance: from points on one surface to the other
/// (hmira::one_sided_distance: max, mean, rms, samples).
using one_sided = hmira::one_sided_distance;

/// The sampled Hausdorff distance between two surfaces, both ways.
struct hausdorff_result {
    one_sided a_to_b;  ///< samples on A, distances to B
    one_sided b_to_a;  ///< samples on B, distances to A
    /// max(a_to_b.max, b_to_a.max).
    double symmetric() const { return std::max(a_to_b.max, b_to_a.max); }
};

/// A soup as the library's triangle_set (triangle i on face i).
inline hmira::triangle_set set_of(const triangle_soup& s) {
    hmira::triangle_set t{s.points, s.triangles, std::vector<std::size_t>(s.triangles.size())};
    for (std::size_t i = 0; i < t.faces.size(); ++i) t.faces[i] = i;
    return t;
}

/// The symmetric sampled Hausdorff distance between A and B (hmira::hausdorff_distance: the
/// vertices plus max(per_triangle, ceil(min_samples / triangles)) random points per triangle,
/// a fixed seed); zeros when either soup is empty.
inline hausdorff_result hausdorff(const triangle_soup& a, const triangle_soup& b, std::size_t per_triangle = 10,
                                  std::size_t min_samples = 1000000) {
    const auto h =
        hmira::hausdorff_distance(set_of(a), set_of(b), {.per_triangle = per_triangle, .min_samples = min_samples});
    if (!h) return {};
    return {h->a_to_b, h->b_to_a};
}

/// Triangle shape: the minimum angle (degrees) and the aspect ratio (circumradius over twice
/// the inradius: 1 for an equilateral triangle, infinity for a degenerate one) of each.
struct triangle_quality {
    std::vector<double> min_angles;  ///< sorted ascending
    std::vector<double> aspects;     ///< sorted ascending
    /// The value at fraction q in [0, 1] of a sorted list (nearest rank).
    static double percentile(const std::vector<double>& sorted, double q) {
        if (sorted.empty()) return 0;
        const auto i = std::size_t(std::clamp(q, 0.0, 1.0) * double(sorted.size() - 1) + 0.5);
        return sorted[i];
    }
};

inline triangle_quality measure_triangles(const triangle_soup& s) {
    triangle_quality q;
    constexpr double pi = 3.14159265358979323846;
    for (const auto& t : s.triangles) {
        const auto a = s.points[t[0]], b = s.points[t[1]], c = s.points[t[2]];
        const double la = hmira::norm(b - c), lb = hmira::norm(c - a), lc = hmira::norm(a - b);
        auto angle = [](const vec3<double>& u, const vec3<double>& v) {
            return std::atan2(hmira::norm(hmira::cross(u, v)), hmira::dot(u, v));
        };
        const double m = std::min({angle(b - a, c - a), angle(c - b, a - b), angle(a - c, b - c)});
        q.min_angles.push_back(m * 180 / pi);
        const double area = 0.5 * hmira::norm(hmira::cross(b - a, c - a));
        const double s2 = 0.5 * (la + lb + lc);
        // R = abc / (4 area), r = area / s, aspect = R / (2 r) = abc s / (8 area^2).
        q.aspects.push_back(area > 0 ? la * lb * lc * s2 / (8 * area * area) : INFINITY);
    }
    std::sort(q.min_angles.begin(), q.min_angles.end());
    std::sort(q.aspects.begin(), q.aspects.end());
    return q;
}

/// Edge lengths over the unique edges of the soup.
struct edge_statistics {
    std::size_t count = 0;                          ///< number of edges
    double min = 0, max = 0, mean = 0, stddev = 0;  ///< of the lengths
    std::vector<double> lengths;                    ///< sorted ascending
    /// Fraction of the edges with length in [lo, hi].
    double fraction_within(double lo, double hi) const {
        if (lengths.empty()) return 0;
        const auto b = std::lower_bound(lengths.begin(), lengths.end(), lo);
        const auto e = std::upper_bound(lengths.begin(), lengths.end(), hi);
        return double(e - b) / double(lengths.size());
    }
};

inline edge_statistics measure_edges(const triangle_soup& s) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    edges.reserve(3 * s.triangles.size());
    for (const auto& t : s.triangles)
        for (int k = 0; k < 3; ++k) {
            const auto u = t[k], v = t[(k + 1) % 3];
            edges.emplace_back(std::min(u, v), std::max(u, v));
        }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    edge_statistics e;
    e.count = edges.size();
    if (edges.empty()) return e;
    double sum = 0, sum2 = 0;
    for (const auto& [u, v] : edges) {
        const double l = hmira::norm(s.points[u] - s.points[v]);
        e.lengths.push_back(l);
        sum += l;
        sum2 += l * l;
    }
    std::sort(e.lengths.begin(), e.lengths.end());
    e.min = e.lengths.front();
    e.max = e.lengths.back();
    e.mean = sum / double(e.count);
    e.stddev = std::sqrt(std::max(0.0, sum2 / double(e.count) - e.mean * e.mean));
    return e;
}

/// A compact multi-line report on one mesh: triangle quality and edge lengths; with a target
/// length > 0, also the fraction of edges within [4/5, 4/3] of it.
inline std::string describe(const char* label, const triangle_soup& s, double target_length = 0) {
    const auto q = measure_triangles(s);
    const auto e = measure_edges(s);
    std::string out;
    char line[512];
    std::vector<char> used(s.points.size(), 0);
    for (const auto& t : s.triangles) used[t[0]] = used[t[1]] = used[t[2]] = 1;
    const auto vertices = std::size_t(std::count(used.begin(), used.end(), 1));
    std::snprintf(line, sizeof line, "%s: %zu vertices, %zu triangles, %zu edges\n", label, vertices,
                  s.triangles.size(), e.count);
    out += line;
    std::snprintf(line, sizeof line, "  min angle (deg): min %.2f  p1 %.2f  p5 %.2f  median %.2f  max %.2f\n",
                  q.min_angles.empty() ? 0 : q.min_angles.front(), triangle_quality::percentile(q.min_angles, 0.01),
                  triangle_quality::percentile(q.min_angles, 0.05), triangle_quality::percentile(q.min_angles, 0.5),
                  q.min_angles.empty() ? 0 : q.min_angles.back());
    out += line;
    out += "  min angle histogram:";
    const double angle_edges[] = {0, 10, 20, 30, 40, 50, 60.0001};
    for (int b = 0; b < 6; ++b) {
        const auto n = std::lower_bound(q.min_angles.begin(), q.min_angles.end(), angle_edges[b + 1]) -
                       std::lower_bound(q.min_angles.begin(), q.min_angles.end(), angle_edges[b]);
        std::snprintf(line, sizeof line, " [%g,%g) %.1f%%", angle_edges[b], b == 5 ? 60.0 : angle_edges[b + 1],
                      q.min_angles.empty() ? 0.0 : 100.0 * double(n) / double(q.min_angles.size()));
        out += line;
    }
    out += "\n  aspect ratio: median ";
    std::snprintf(line, sizeof line,
                  "%.3f  p99 %.3f  max %.3g\n  aspect histogram:", triangle_quality::percentile(q.aspects, 0.5),
                  triangle_quality::percentile(q.aspects, 0.99), q.aspects.empty() ? 0 : q.aspects.back());
    out += line;
    const double aspect_edges[] = {0, 1.5, 2, 3, 5, 10, INFINITY};
    for (int b = 0; b < 6; ++b) {
        const auto n = std::lower_bound(q.aspects.begin(), q.aspects.end(), aspect_edges[b + 1]) -
                       std::lower_bound(q.aspects.begin(), q.aspects.end(), aspect_edges[b]);
        std::snprintf(line, sizeof line, " [%g,%g) %.1f%%", b == 0 ? 1.0 : aspect_edges[b], aspect_edges[b + 1],
                      q.aspects.empty() ? 0.0 : 100.0 * double(n) / double(q.aspects.size()));
        out += line;
    }
    std::snprintf(line, sizeof line, "\n  edge length: min %.4g  mean %.4g  max %.4g  stddev %.4g\n", e.min, e.mean,
                  e.max, e.stddev);
    out += line;
    if (target_length > 0) {
        std::snprintf(line, sizeof line, "  edges within [4/5, 4/3] of %.4g: %.2f%%\n", target_length,
                      100 * e.fraction_within(0.8 * target_length, 4.0 / 3.0 * target_length));
        out += line;
    }
    return out;
}

}  // namespace hmira_bench::quality
