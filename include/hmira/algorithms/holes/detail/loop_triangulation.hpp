// hmira/algorithms/holes/detail/loop_triangulation.hpp
// fill_hole's index-space work on a boundary loop: Liepa's dynamic programme, the projected
// fallback for long loops, and a flip pass that lowers the patch's area without more bend.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <unordered_map>
#include <vector>

#include "../../../core/progress.hpp"
#include "../../../core/result.hpp"
#include "../../../core/vec3.hpp"
#include "../../triangulation/triangulate_polygon.hpp"

namespace hmira::detail::holes {

inline vec3<double> unit_normal(const vec3<double>& a, const vec3<double>& b, const vec3<double>& c) {
    const auto n = cross(b - a, c - a);
    const double l = std::sqrt(dot(n, n));
    return l > 0 ? n / l : vec3<double>{};
}
inline double area(const vec3<double>& a, const vec3<double>& b, const vec3<double>& c) {
    const auto n = cross(b - a, c - a);
    return 0.5 * std::sqrt(dot(n, n));
}

/// A key that grows with the angle between two unit normals: sin(angle) up to a right angle,
/// 2 - sin(angle) beyond, so 0 is flat and 2 folded back. Unlike 1 - n.m it keeps its precision
/// for nearly flat pairs (1 - cos rounds to multiples of 1e-16 where cos ~ 1 - angle^2 / 2), so
/// nearly flat candidates are ranked by their real bend, as CGAL ranks them by an atan2 angle.
inline double bend(const vec3<double>& n, const vec3<double>& m) {
    if (dot(n, n) == 0 || dot(m, m) == 0) return 0;
    const auto c = cross(n, m);
    const double s = std::sqrt(dot(c, c));
    return dot(n, m) >= 0 ? s : 2 - s;
}

/// Liepa's weight: the largest bend first, then the area (the order CGAL's
/// Weight_min_max_dihedral_and_area uses, without tolerance).
struct weight {
    double bend = 0, area = 0;
    bool operator<(const weight& o) const { return bend != o.bend ? bend < o.bend : area < o.area; }
};

/// A boundary loop in index space: p[i] the position of loop vertex i (the loop runs i -> i + 1),
/// rim[i] the unit normal of the face across loop edge (i, i + 1), and the pairs the mesh joins
/// by an edge off the loop (they cannot become diagonals).
struct loop_data {
    std::vector<vec3<double>> p, rim;
    std::vector<std::vector<std::size_t>> joined;  ///< sorted, per loop vertex

    std::size_t size() const { return p.size(); }
    bool is_loop_edge(std::size_t i, std::size_t j) const {
        if (i > j) std::swap(i, j);
        return j == i + 1 || (i == 0 && j + 1 == size());
    }
    bool is_joined(std::size_t i, std::size_t j) const {
        return !is_loop_edge(i, j) && std::binary_search(joined[i].begin(), joined[i].end(), j);
    }
};

using triangle_list = std::vector<std::array<std::size_t, 3>>;  ///< corners ascending = the patch's winding

inline std::uint64_t pair_key(std::size_t i, std::size_t j) {
    if (i > j) std::swap(i, j);
    return (std::uint64_t(i) << 32) | std::uint64_t(j);
}

/// Inner steps of the dynamic programme between two progress reports (a few milliseconds).
inline constexpr std::size_t steps_per_block = std::size_t{1} << 16;

/// Progress blocks the dynamic programme on a loop of n edges reports: about n^3 / 6 inner
/// steps, one block per steps_per_block of them.
inline std::size_t dynamic_programming_blocks(std::size_t n) {
    const double steps = double(n) * double(n) * double(n) / 6;
    return std::size_t(steps / double(steps_per_block)) + 1;
}

/// Bytes the dynamic programme's tables take for a loop of n edges.
inline double dynamic_programming_bytes(std::size_t n) {
    return double(n) * double(n) * double(sizeof(weight) + sizeof(std::size_t));
}

/// Liepa's dynamic programme over all triangulations that add no edge the mesh has; empty when
/// there is none. As in Liepa (and CGAL), the bend across an inner edge (i, k) is taken against
/// the triangle the best solution of (i, k) puts there, so the result is optimal only up to that
/// greedy choice. Reports to `gate` once every steps_per_block inner steps; errc::cancelled
/// when it says stop. O(n^3) time, O(n^2) memory.
inline result<triangle_list> triangulate_by_dynamic_programming(const loop_data& loop, progress_gate& gate) {
    const std::size_t n = loop.size();
    std::size_t steps = 0;
    const auto& p = loop.p;
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<weight> W(n * n, weight{inf, inf});
    std::vector<std::size_t> K(n * n, n);
    for (std::size_t i = 0; i + 1 < n; ++i) W[i * n + i + 1] = {0, 0};
    auto inner_normal = [&](std::size_t i, std::size_t j) {
        if (j == i + 1) return loop.rim[i];
        const auto k = K[i * n + j];
        return unit_normal(p[i], p[k], p[j]);
    };
    for (std::size_t len = 2; len < n; ++len)
        for (std::size_t i = 0; i + len < n; ++i) {
            const std::size_t j = i + len;
            if (loop.is_joined(i, j)) continue;
            weight best{inf, inf};
            std::size_t best_k = n;
            steps += len;
            if (steps >= steps_per_block) {
                steps = 0;
                if (!gate.advance()) return fail(errc::cancelled, "fill_hole: cancelled");
            }
            for (std::size_t k = i + 1; k < j; ++k) {
                const auto& a = W[i * n + k];
                const auto& b = W[k * n + j];
                if (a.bend == inf || b.bend == inf) continue;
                const auto nk = unit_normal(p[i], p[k], p[j]);
                if (dot(nk, nk) == 0) continue;  // degenerate candidate, as CGAL refuses it
                double bd = std::max(a.bend, b.bend);
                bd = std::max(bd, bend(nk, inner_normal(i, k)));
                bd = std::max(bd, bend(nk, inner_normal(k, j)));
                if (i == 0 && j == n - 1) bd = std::max(bd, bend(nk, loop.rim[n - 1]));
                const weight w{bd, a.area + b.area + area(p[i], p[k], p[j])};
                if (w < best) {
                    best = w;
                    best_k = k;
                }
            }
            W[i * n + j] = best;
            K[i * n + j] = best_k;
        }
    triangle_list tris;
    if (K[n - 1] == n) return tris;
    std::vector<std::array<std::size_t, 2>> stack{{0, n - 1}};
    while (!stack.empty()) {
        const auto [i, j] = stack.back();
        stack.pop_back();
        const auto k = K[i * n + j];
        tris.push_back({i, k, j});
        if (k > i + 1) stack.push_back({i, k});
        if (j > k + 1) stack.push_back({k, j});
    }
    return tris;
}

/// The loop triangulated in the plane of its Newell normal (long loops). Errors:
/// errc::unsupported when the projection is not simple or a diagonal repeats a mesh edge.
/// O(n^2) typical, O(n) memory besides the polygon triangulation's.
inline result<triangle_list> triangulate_by_projection(const loop_data& loop) {
    const std::size_t n = loop.size();
    const auto& p = loop.p;
    vec3<double> nn{};
    for (std::size_t i = 0; i < n; ++i) nn += cross(p[i], p[(i + 1) % n]);
    const double ax = std::fabs(nn.x), ay = std::fabs(nn.y), az = std::fabs(nn.z);
    const int k = ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2);
    int u = (k + 1) % 3, w = (k + 2) % 3;
    if (nn[std::size_t(k)] < 0) std::swap(u, w);
    std::vector<point2> pts(n);
    for (std::size_t i = 0; i < n; ++i) pts[i] = {p[i][std::size_t(u)], p[i][std::size_t(w)]};
    std::vector<std::vector<std::size_t>> loops(1);
    for (std::size_t i = 0; i < n; ++i) loops[0].push_back(i);
    auto t = triangulate_polygon(pts, loops);
    if (!t)
        return fail(
            errc::unsupported,
            "fill_hole: a loop of " + std::to_string(n) +
                " edges is too long for the dynamic programme and its projection is not simple: " + t.error().message);
    triangle_list tris;
    for (auto tri : *t) {
        std::sort(tri.begin(), tri.end());
        if (loop.is_joined(tri[0], tri[1]) || loop.is_joined(tri[1], tri[2]) || loop.is_joined(tri[0], tri[2]))
            return fail(errc::unsupported,
                        "fill_hole: the projected triangulation of a long loop repeats an existing edge");
        tris.push_back(tri);
    }
    return tris;
}

/// Unit normal of a triangle of the list (corners ascending: the patch's winding).
inline vec3<double> normal_of(const loop_data& loop, const std::array<std::size_t, 3>& t) {
    return unit_normal(loop.p[t[0]], loop.p[t[1]], loop.p[t[2]]);
}

/// Flips diagonals of the patch while that lowers its area and bends no edge more than the
/// patch's largest bend: the lexicographic (largest bend, area) objective of the dynamic
/// programme can only improve, which undoes some of its greedy choices. Each flip lowers the
/// area, so the pass ends; it is also capped at 4 n rounds. O(rounds * n) time, O(n) memory.
inline void reduce_area_by_flips(const loop_data& loop, triangle_list& tris) {
    const std::size_t n = loop.size();
    if (tris.size() < 2) return;
    // Each edge's one or two triangles.
    std::unordered_map<std::uint64_t, std::array<std::size_t, 2>> on_edge;
    const std::size_t none = std::numeric_limits<std::size_t>::max();
    auto attach = [&](std::size_t t) {
        const auto& c = tris[t];
        for (int e = 0; e < 3; ++e) {
            auto [it, fresh] =
                on_edge.try_emplace(pair_key(c[e], c[(e + 1) % 3]), std::array<std::size_t, 2>{none, none});
            (void)fresh;
            (it->second[0] == none ? it->second[0] : it->second[1]) = t;
        }
    };
    auto detach = [&](std::size_t t) {
        const auto& c = tris[t];
        for (int e = 0; e < 3; ++e) {
            auto it = on_edge.find(pair_key(c[e], c[(e + 1) % 3]));
            if (it->second[0] == t) it->second[0] = it->second[1];
            it->second[1] = none;
            if (it->second[0] == none) on_edge.erase(it);
        }
    };
    for (std::size_t t = 0; t < tris.size(); ++t) attach(t);
    auto third = [](const std::array<std::size_t, 3>& t, std::size_t a, std::size_t b) {
        for (auto v : t)
            if (v != a && v != b) return v;
        return a;
    };
    // Bend across edge (a, b) when the triangle `skip` is replaced by one of normal `with`.
    auto edge_bend = [&](std::size_t a, std::size_t b, const vec3<double>& nrm, std::size_t skip_a,
                         std::size_t skip_b) {
        if (loop.is_loop_edge(a, b))
            return bend(nrm, loop.rim[std::min(a, b) + 1 == std::max(a, b) ? std::min(a, b) : n - 1]);
        const auto& ts = on_edge.at(pair_key(a, b));
        for (auto t : ts)
            if (t != none && t != skip_a && t != skip_b) return bend(nrm, normal_of(loop, tris[t]));
        return 0.0;
    };
    double max_bend = 0;
    for (const auto& [key, ts] : on_edge) {
        const std::size_t a = std::size_t(key >> 32), b = std::size_t(key & 0xffffffffu);
        const auto n0 = normal_of(loop, tris[ts[0]]);
        max_bend = std::max(max_bend,
                            ts[1] == none ? edge_bend(a, b, n0, ts[0], none) : bend(n0, normal_of(loop, tris[ts[1]])));
    }
    for (std::size_t round = 0; round < 4 * n; ++round) {
        bool flipped = false;
        std::vector<std::uint64_t> diagonals;
        for (const auto& [key, ts] : on_edge)
            if (ts[1] != none) diagonals.push_back(key);
        std::sort(diagonals.begin(), diagonals.end());  // a fixed order, whatever the hashing
        for (const auto key : diagonals) {
            auto it = on_edge.find(key);
            if (it == on_edge.end() || it->second[1] == none) continue;
            const std::size_t a = std::size_t(key >> 32), b = std::size_t(key & 0xffffffffu);
            const std::size_t t0 = it->second[0], t1 = it->second[1];
            const std::size_t c = third(tris[t0], a, b), d = third(tris[t1], a, b);
            if (loop.is_joined(c, d) || loop.is_loop_edge(c, d) || on_edge.count(pair_key(c, d))) continue;
            std::array<std::size_t, 3> u{a, c, d}, w{b, c, d};
            std::sort(u.begin(), u.end());
            std::sort(w.begin(), w.end());
            const double old_area = area(loop.p[tris[t0][0]], loop.p[tris[t0][1]], loop.p[tris[t0][2]]) +
                                    area(loop.p[tris[t1][0]], loop.p[tris[t1][1]], loop.p[tris[t1][2]]);
            const double new_area =
                area(loop.p[u[0]], loop.p[u[1]], loop.p[u[2]]) + area(loop.p[w[0]], loop.p[w[1]], loop.p[w[2]]);
            if (!(new_area < old_area * (1 - 1e-12))) continue;
            const auto nu = normal_of(loop, u), nw = normal_of(loop, w);
            if (dot(nu, nu) == 0 || dot(nw, nw) == 0) continue;
            if (bend(nu, nw) > max_bend) continue;
            if (edge_bend(a, c, nu, t0, t1) > max_bend || edge_bend(a, d, nu, t0, t1) > max_bend ||
                edge_bend(b, c, nw, t0, t1) > max_bend || edge_bend(b, d, nw, t0, t1) > max_bend)
                continue;
            detach(t0);
            detach(t1);
            tris[t0] = u;
            tris[t1] = w;
            attach(t0);
            attach(t1);
            flipped = true;
        }
        if (!flipped) break;
    }
}

/// The triangles in interval order: each (i, k, j) lies on the interval (i, j) of a parent,
/// starting with (0, n - 1), which is how fill_hole builds them. Any triangulation of the loop
/// has this order. O(n) expected.
inline result<triangle_list> in_interval_order(std::size_t n, const triangle_list& tris) {
    std::unordered_map<std::uint64_t, std::size_t> on;
    for (const auto& t : tris) on[pair_key(t[0], t[2])] = t[1];
    triangle_list out;
    std::vector<std::array<std::size_t, 2>> stack{{0, n - 1}};
    while (!stack.empty()) {
        const auto [i, j] = stack.back();
        stack.pop_back();
        const auto it = on.find(pair_key(i, j));
        if (it == on.end() || out.size() >= tris.size())
            return fail(errc::unsupported, "fill_hole: internal: the patch is not a triangulation of the loop");
        const auto m = it->second;
        out.push_back({i, m, j});
        if (m > i + 1) stack.push_back({i, m});
        if (j > m + 1) stack.push_back({m, j});
    }
    return out;
}

}  // namespace hmira::detail::holes
