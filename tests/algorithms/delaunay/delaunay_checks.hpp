// tests/algorithms/delaunay/delaunay_checks.hpp
// Independent checks of a Delaunay triangulation: a proper triangulation (ccw triangles,
// each directed edge once, boundary chain = the convex hull loop), every interior edge locally Delaunay
// under the exact in-circle test, 2n - 2 - h triangles, and a hull equal to a monotone-chain
// hull computed here. Inputs generators for the suites live here too.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <unordered_map>
#include <vector>

#include <hmira/algorithms/delaunay/delaunay_triangulation.hpp>
#include <hmira/predicates/incircle.hpp>
#include <hmira/predicates/orient2d.hpp>

namespace hmira_test {

using point3 = hmira::vec3<double>;

inline int orient(const point3& a, const point3& b, const point3& c) {
    return hmira::predicates::orient2d(a.x, a.y, b.x, b.y, c.x, c.y);
}

/// Strict convex hull (no collinear points), counter-clockwise, starting at the
/// lexicographically smallest point: Andrew's monotone chain with the exact orientation.
inline std::vector<point3> monotone_chain_hull(std::vector<point3> pts) {
    auto lex = [](const point3& a, const point3& b) { return a.x != b.x ? a.x < b.x : a.y < b.y; };
    std::sort(pts.begin(), pts.end(), lex);
    pts.erase(
        std::unique(pts.begin(), pts.end(), [](const point3& a, const point3& b) { return a.x == b.x && a.y == b.y; }),
        pts.end());
    if (pts.size() < 3) return pts;
    std::vector<point3> h(2 * pts.size());
    std::size_t k = 0;
    for (const auto& p : pts) {
        while (k >= 2 && orient(h[k - 2], h[k - 1], p) <= 0) --k;
        h[k++] = p;
    }
    for (std::size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
        while (k >= t && orient(h[k - 2], h[k - 1], pts[i]) <= 0) --k;
        h[k++] = pts[i];
    }
    h.resize(k - 1);
    return h;
}

/// Everything asked of a Delaunay triangulation of `input`, checked independently.
inline ::testing::AssertionResult is_delaunay_triangulation(const std::vector<point3>& input,
                                                            const hmira::delaunay_triangles& d) {
    using ::testing::AssertionFailure;
    const auto& P = d.points;
    const std::size_t n = P.size();
    if (d.status != hmira::delaunay_status::ok) return AssertionFailure() << "status is not ok";
    // Mapping: every input point maps to a distinct output point with the same x, y.
    if (d.input_to_vertex.size() != input.size() || d.vertex_to_input.size() != n)
        return AssertionFailure() << "mapping sizes";
    for (std::size_t j = 0; j < input.size(); ++j) {
        const auto v = d.input_to_vertex[j];
        if (v >= n || P[v].x != input[j].x || P[v].y != input[j].y)
            return AssertionFailure() << "input " << j << " maps to a vertex elsewhere";
    }
    for (std::size_t v = 0; v < n; ++v) {
        const auto j = d.vertex_to_input[v];
        if (j >= input.size() || d.input_to_vertex[j] != v || !(P[v] == input[j]))
            return AssertionFailure() << "vertex " << v << " is not input " << j;
    }
    // Distinctness of output points.
    {
        std::vector<std::uint32_t> idx(n);
        for (std::size_t i = 0; i < n; ++i) idx[i] = static_cast<std::uint32_t>(i);
        std::sort(idx.begin(), idx.end(),
                  [&](auto a, auto b) { return P[a].x != P[b].x ? P[a].x < P[b].x : P[a].y < P[b].y; });
        for (std::size_t i = 1; i < n; ++i)
            if (P[idx[i]].x == P[idx[i - 1]].x && P[idx[i]].y == P[idx[i - 1]].y)
                return AssertionFailure() << "output points " << idx[i - 1] << " and " << idx[i] << " coincide";
    }

    // Triangles: ccw, directed edges unique, twins found.
    std::unordered_map<std::uint64_t, std::uint32_t> edge_third;  // directed edge -> opposite corner
    edge_third.reserve(d.triangles.size() * 3);
    std::vector<std::uint8_t> used(n, 0);
    for (std::size_t t = 0; t < d.triangles.size(); ++t) {
        const auto& tr = d.triangles[t];
        for (int i = 0; i < 3; ++i) {
            if (tr[i] >= n) return AssertionFailure() << "triangle " << t << " has a bad index";
            used[tr[i]] = 1;
        }
        if (orient(P[tr[0]], P[tr[1]], P[tr[2]]) <= 0)
            return AssertionFailure() << "triangle " << t << " is not counter-clockwise (or degenerate)";
        for (int i = 0; i < 3; ++i) {
            const std::uint64_t key = (std::uint64_t(tr[i]) << 32) | tr[(i + 1) % 3];
            if (!edge_third.emplace(key, tr[(i + 2) % 3]).second)
                return AssertionFailure() << "directed edge " << tr[i] << "->" << tr[(i + 1) % 3] << " used twice";
        }
    }
    for (std::size_t v = 0; v < n; ++v)
        if (!used[v]) return AssertionFailure() << "vertex " << v << " is in no triangle";

    // Interior edges locally Delaunay; boundary edges collected.
    std::unordered_map<std::uint32_t, std::uint32_t> boundary_next;
    std::size_t interior_checked = 0;
    for (const auto& [key, c] : edge_third) {
        const auto a = static_cast<std::uint32_t>(key >> 32), b = static_cast<std::uint32_t>(key);
        const auto twin = edge_third.find((std::uint64_t(b) << 32) | a);
        if (twin == edge_third.end()) {
            if (!boundary_next.emplace(a, b).second) return AssertionFailure() << "boundary vertex " << a << " twice";
            continue;
        }
        if (a < b) {
            ++interior_checked;
            const auto dd = twin->second;
            if (hmira::predicates::incircle(P[a].x, P[a].y, P[b].x, P[b].y, P[c].x, P[c].y, P[dd].x, P[dd].y) > 0)
                return AssertionFailure() << "edge " << a << "-" << b << " is not locally Delaunay";
        }
    }
    // The boundary is one loop and it is the reported hull.
    const std::size_t h = d.hull.size();
    if (boundary_next.size() != h)
        return AssertionFailure() << "boundary has " << boundary_next.size() << " edges, hull " << h;
    for (std::size_t i = 0; i < h; ++i) {
        const auto it = boundary_next.find(d.hull[i]);
        if (it == boundary_next.end() || it->second != d.hull[(i + 1) % h])
            return AssertionFailure() << "hull step " << i << " is not a boundary edge";
    }
    // No overlap needs no area sum (which rounding spoils on slivers): the triangles are all
    // counter-clockwise and their boundary chain is exactly the convex hull loop, so every
    // point inside the hull has winding number 1 = the number of triangles covering it.
    // Count: 2n - 2 - h.
    if (d.triangles.size() != 2 * n - 2 - h)
        return AssertionFailure() << d.triangles.size() << " triangles, expected 2n-2-h = " << 2 * n - 2 - h;
    // Hull: convex, and its corners are the monotone-chain hull.
    std::vector<point3> corners;
    for (std::size_t i = 0; i < h; ++i) {
        const int o = orient(P[d.hull[(i + h - 1) % h]], P[d.hull[i]], P[d.hull[(i + 1) % h]]);
        if (o < 0) return AssertionFailure() << "hull turns right at " << d.hull[i];
        if (o > 0) corners.push_back(P[d.hull[i]]);
    }
    const auto ref = monotone_chain_hull(input);
    if (corners.size() != ref.size())
        return AssertionFailure() << "hull has " << corners.size() << " corners, monotone chain " << ref.size();
    const auto start = std::find_if(corners.begin(), corners.end(),
                                    [&](const point3& q) { return q.x == ref[0].x && q.y == ref[0].y; });
    if (start == corners.end()) return AssertionFailure() << "hull misses the leftmost point";
    std::rotate(corners.begin(), start, corners.end());
    for (std::size_t i = 0; i < ref.size(); ++i)
        if (corners[i].x != ref[i].x || corners[i].y != ref[i].y)
            return AssertionFailure() << "hull corner " << i << " differs";
    return ::testing::AssertionSuccess() << interior_checked << " interior edges checked";
}

// ---------------------------------------------------------------------------------------------
// Inputs

inline std::vector<point3> uniform_points(std::size_t n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<point3> p(n);
    for (auto& q : p) q = {u(rng), u(rng), u(rng)};
    return p;
}

inline std::vector<point3> clustered_points(std::size_t n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<point3> centres(std::max<std::size_t>(1, n / 5000));
    for (auto& c : centres) c = {u(rng) * 100, u(rng) * 100, 0};
    std::normal_distribution<double> g(0.0, 1.0);
    std::vector<point3> p(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto& c = centres[i % centres.size()];
        const double s = (i % 7 == 0) ? 3.0 : 0.05;  // tight cores with a looser halo
        p[i] = {c.x + s * g(rng), c.y + s * g(rng), g(rng)};
    }
    return p;
}

inline std::vector<point3> lattice_points(int side) {
    std::vector<point3> p;
    p.reserve(std::size_t(side) * side);
    for (int i = 0; i < side; ++i)
        for (int j = 0; j < side; ++j) p.push_back({double(i), double(j), double((i * 7 + j * 13) % 11)});
    return p;
}

inline std::vector<point3> circle_points(std::size_t n) {
    std::vector<point3> p(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double t = 6.283185307179586 * double(i) / double(n);
        p[i] = {std::cos(t), std::sin(t), 0.0};
    }
    return p;
}

/// Triangles as a canonical sorted set of vertex triples in input indices.
inline std::vector<std::array<std::uint32_t, 3>> canonical_triangles(const hmira::delaunay_triangles& d) {
    std::vector<std::array<std::uint32_t, 3>> out;
    out.reserve(d.triangles.size());
    for (auto t : d.triangles) {
        for (auto& v : t) v = d.vertex_to_input[v];
        std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
        out.push_back(t);
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace hmira_test
