// hmira/algorithms/spatial/detail/winding_number_impl.hpp
// The machinery of winding_number (see ../winding_number.hpp for the interface): the checks on
// the query points, the tree of far-field expansions and its query, the batched parallel loop.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "../../../core/result.hpp"
#include "../../../core/vec3.hpp"
#include "../../conversion/detail/parallel.hpp"
#include "../winding_number.hpp"
#include "solid_angle.hpp"

namespace hmira {

namespace detail::spatial {

/// The first non-finite point, or -1.
inline long long first_non_finite(std::span<const vec3<double>> points) {
    for (std::size_t i = 0; i < points.size(); ++i)
        if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y) || !std::isfinite(points[i].z))
            return (long long)i;
    return -1;
}

/// The common refusals of the point queries: no triangles, a non-finite point under
/// nan_policy::error.
inline result<void> check_query(const triangle_set& s, std::span<const vec3<double>> points, nan_policy nan,
                                const char* who) {
    if (s.triangles.empty()) return fail(errc::invalid_argument, std::string(who) + ": the mesh has no faces");
    if (nan == nan_policy::error)
        if (const long long i = first_non_finite(points); i >= 0)
            return fail(errc::invalid_argument,
                        std::string(who) + ": query point " + std::to_string(i) + " is not finite", i);
    return {};
}

/// Barill et al.'s tree: a node holds its triangles' far-field expansion about their
/// area-weighted centre c: N = sum of vector areas (the dipole) and
/// M = sum of vector_area (x) (centroid - c) (the first-order term), with the radius r of a ball
/// about c holding them and their total area A for the error bound. Median splits of the
/// centroids along the longest axis, so the same triangles give the same tree.
class winding_tree {
public:
    explicit winding_tree(const triangle_set& s) : s_(s) {
        const std::size_t n = s.triangles.size();
        order_.resize(n);
        centroid_.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            order_[i] = std::uint32_t(i);
            const auto& t = s.triangles[i];
            centroid_[i] = (s.points[t[0]] + s.points[t[1]] + s.points[t[2]]) / 3.0;
        }
        if (n == 0) return;
        // The shape depends on n alone (median splits, leaves of at most leaf_size): number
        // the nodes first, depth first with the left child first, then fill and split the
        // subtrees in parallel. Each node is filled just before its own split, as a serial
        // build would, so the sums and the tree do not depend on the schedule.
        nodes_.reserve(2 * (n / leaf_size + 1));
        nodes_.push_back({});
        struct task {
            std::uint32_t node, begin, end;
        };
        std::vector<task> todo{{0, 0, std::uint32_t(n)}};
        while (!todo.empty()) {
            const task t = todo.back();
            todo.pop_back();
            nodes_[t.node].first = t.begin;
            nodes_[t.node].count = t.end - t.begin;
            if (t.end - t.begin <= leaf_size) continue;
            const std::uint32_t mid = t.begin + (t.end - t.begin) / 2;
            const auto left = std::uint32_t(nodes_.size());
            nodes_[t.node].first = left;
            nodes_[t.node].count = 0;
            nodes_.push_back({});
            nodes_.push_back({});
            todo.push_back({left + 1, mid, t.end});
            todo.push_back({left, t.begin, mid});
        }
        build(0, 0, std::uint32_t(n));
    }

    /// The winding number at q (4 pi times it, summed), and the bound on its error.
    std::pair<double, double> query(const vec3<double>& q, double beta) const {
        double omega = 0, bound = 0;
        std::uint32_t stack[128];
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const node& nd = nodes_[stack[--top]];
            const vec3<double> e = nd.centre - q;
            const double d = norm(e);
            if (d > beta * nd.radius) {
                omega += expansion(nd, e, d);
                const double gap = d - nd.radius, g2 = gap * gap;
                bound += 4 * nd.area * nd.radius * nd.radius * nd.radius / (g2 * g2 * gap);
                continue;
            }
            if (nd.count > 0) {
                for (std::uint32_t i = nd.first; i < nd.first + nd.count; ++i) omega += direct(order_[i], q);
                continue;
            }
            stack[top++] = nd.first + 1;
            stack[top++] = nd.first;
        }
        constexpr double four_pi = 4 * std::numbers::pi;
        return {omega / four_pi, bound / four_pi};
    }

    /// The solid angle of triangle i seen from q.
    double direct(std::uint32_t i, const vec3<double>& q) const {
        const auto& t = s_.triangles[i];
        return solid_angle(s_.points[t[0]] - q, s_.points[t[1]] - q, s_.points[t[2]] - q);
    }

private:
    struct node {
        vec3<double> centre{};
        double radius = 0, area = 0;
        vec3<double> dipole{};
        std::array<double, 9> first_order{};    // M[3 i + j] = sum of vector_area_i * (centroid - centre)_j
        std::array<double, 27> second_order{};  // S[9 i + 3 j + k] = sum of vector_area_i * C_jk, C the
                                                // triangle's second moment about the centre over its area
        std::uint32_t first = 0;                // leaf: first slot of order_; inner: left child (right = first + 1)
        std::uint32_t count = 0;                // triangles in a leaf, 0 for an inner node
    };
    static constexpr std::uint32_t leaf_size = 8;

    vec3<double> vector_area(std::uint32_t i) const {
        const auto& t = s_.triangles[i];
        const auto& a = s_.points[t[0]];
        return cross(s_.points[t[1]] - a, s_.points[t[2]] - a) * 0.5;
    }

    // The expansion of nd's triangles' solid angle at q, with e = centre - q, d = |e|: the
    // integrand n.E(x), E(x) = (x - q)/|x - q|^3, expanded about the centre to second order:
    // E(c) = e/d^3, dE_i/dx_j = delta_ij/d^3 - 3 e_i e_j/d^5, and
    // d2E_i/dx_j dx_k = -3 (delta_ij e_k + delta_ik e_j + delta_jk e_i)/d^5 + 15 e_i e_j e_k/d^7.
    static double expansion(const node& nd, const vec3<double>& e, double d) {
        const double d2 = d * d, d3 = d2 * d, d5 = d3 * d2, d7 = d5 * d2;
        const auto& m = nd.first_order;
        const double trace = m[0] + m[4] + m[8];
        double eme = 0;
        for (std::size_t i = 0; i < 3; ++i)
            for (std::size_t j = 0; j < 3; ++j) eme += e[i] * m[3 * i + j] * e[j];
        const auto& t = nd.second_order;
        double contracted = 0, eee = 0;  // sum T_iik e_k + T_iji e_j + T_ijj e_i; sum T_ijk e_i e_j e_k
        for (std::size_t i = 0; i < 3; ++i)
            for (std::size_t j = 0; j < 3; ++j) {
                contracted += t[9 * i + 3 * i + j] * e[j] + t[9 * i + 3 * j + i] * e[j] + t[9 * i + 3 * j + j] * e[i];
                for (std::size_t k = 0; k < 3; ++k) eee += t[9 * i + 3 * j + k] * e[i] * e[j] * e[k];
            }
        return dot(nd.dipole, e) / d3 + (trace / d3 - 3 * eme / d5) + 0.5 * (15 * eee / d7 - 3 * contracted / d5);
    }

    void fill(node& nd, std::uint32_t begin, std::uint32_t end) const {
        nd.first = begin;
        nd.count = end - begin;
        vec3<double> weighted{}, plain{};
        double area = 0;
        nd.dipole = {};
        for (std::uint32_t k = begin; k < end; ++k) {
            const auto i = order_[k];
            const auto va = vector_area(i);
            const double a = norm(va);
            nd.dipole += va;
            area += a;
            weighted += centroid_[i] * a;
            plain += centroid_[i];
        }
        nd.area = area;
        nd.centre = area > 0 ? weighted / area : plain / double(end - begin);
        nd.first_order = {};
        nd.second_order = {};
        double r2 = 0;
        for (std::uint32_t k = begin; k < end; ++k) {
            const auto i = order_[k];
            const auto va = vector_area(i);
            const double a12 = norm(va) / 12;
            const auto g = centroid_[i] - nd.centre;
            std::array<vec3<double>, 3> c;
            for (std::size_t q = 0; q < 3; ++q) c[q] = s_.points[s_.triangles[i][q]] - nd.centre;
            const auto sum = c[0] + c[1] + c[2];
            for (std::size_t a = 0; a < 3; ++a)
                for (std::size_t b = 0; b < 3; ++b) {
                    nd.first_order[3 * a + b] += va[a] * g[b];
                    // The second moment of a triangle: area/12 (sum of c c^T + s s^T), s = sum of c.
                    const double moment =
                        a12 * (c[0][a] * c[0][b] + c[1][a] * c[1][b] + c[2][a] * c[2][b] + sum[a] * sum[b]);
                    for (std::size_t x = 0; x < 3; ++x) nd.second_order[9 * x + 3 * a + b] += va[x] * moment;
                }
            for (const auto& q : c) r2 = std::max(r2, squared_norm(q));
        }
        nd.radius = std::sqrt(r2);
    }

    /// Fills node `at` over order_[begin, end) and, for an inner node, splits the range and
    /// builds the children (in parallel past parallel_size triangles).
    void build(std::uint32_t at, std::uint32_t begin, std::uint32_t end) {
        const std::uint32_t left = nodes_[at].first;
        const bool leaf = nodes_[at].count > 0;
        fill(nodes_[at], begin, end);
        if (leaf) return;
        nodes_[at].first = left;
        nodes_[at].count = 0;
        const std::uint32_t mid = split(begin, end);
        if (end - begin > parallel_size)
            parallel_invoke([&] { build(left, begin, mid); }, [&] { build(left + 1, mid, end); });
        else
            build(left, begin, mid), build(left + 1, mid, end);
    }
    static constexpr std::uint32_t parallel_size = 8192;

    std::uint32_t split(std::uint32_t begin, std::uint32_t end) {
        vec3<double> lo = centroid_[order_[begin]], hi = lo;
        for (std::uint32_t k = begin; k < end; ++k)
            for (std::size_t a = 0; a < 3; ++a) {
                lo[a] = std::min(lo[a], centroid_[order_[k]][a]);
                hi[a] = std::max(hi[a], centroid_[order_[k]][a]);
            }
        std::size_t axis = 0;
        for (std::size_t a = 1; a < 3; ++a)
            if (hi[a] - lo[a] > hi[axis] - lo[axis]) axis = a;
        const std::uint32_t mid = begin + (end - begin) / 2;
        std::nth_element(
            order_.begin() + begin, order_.begin() + mid, order_.begin() + end, [&](std::uint32_t a, std::uint32_t b) {
                return centroid_[a][axis] < centroid_[b][axis] || (centroid_[a][axis] == centroid_[b][axis] && a < b);
            });
        return mid;
    }

    const triangle_set& s_;
    std::vector<std::uint32_t> order_;
    std::vector<vec3<double>> centroid_;
    std::vector<node> nodes_;
};

/// Winding numbers of checked input: values[i] for points[i], in parallel chunks.
inline winding_numbers winding_numbers_of(const triangle_set& s, std::span<const vec3<double>> points,
                                          const winding_number_options& options) {
    winding_numbers out;
    out.values.assign(points.size(), 0.0);
    if (options.error_bounds) out.error_bounds.assign(points.size(), 0.0);
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    constexpr double four_pi = 4 * std::numbers::pi;
    const bool fast = options.method == winding_method::fast;
    std::optional<winding_tree> tree;
    if (fast) tree.emplace(s);
    with_thread_count(options.threads, [&] {
        parallel_chunks(points.size(), 64, [&](std::size_t b, std::size_t e) {
            for (std::size_t i = b; i < e; ++i) {
                const auto& q = points[i];
                if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z)) {
                    out.values[i] = nan;
                    if (options.error_bounds) out.error_bounds[i] = nan;
                    continue;
                }
                if (fast) {
                    const auto [w, bound] = tree->query(q, options.beta);
                    out.values[i] = w;
                    if (options.error_bounds) out.error_bounds[i] = bound;
                } else {
                    double omega = 0;
                    for (const auto& t : s.triangles)
                        omega += solid_angle(s.points[t[0]] - q, s.points[t[1]] - q, s.points[t[2]] - q);
                    out.values[i] = omega / four_pi;
                }
            }
        });
    });
    return out;
}

inline result<void> check_winding_options(const winding_number_options& o, const char* who) {
    if (o.method == winding_method::fast && !(o.beta > 1))
        return fail(errc::invalid_argument, std::string(who) + ": beta must exceed 1, got " + std::to_string(o.beta));
    return {};
}

}  // namespace detail::spatial

inline result<winding_numbers> winding_number(const triangle_set& surface, std::span<const vec3<double>> points,
                                              const winding_number_options& options) {
    if (auto ok = detail::spatial::check_query(surface, points, options.nan, "winding_number"); !ok) return ok.error();
    if (auto ok = detail::spatial::check_winding_options(options, "winding_number"); !ok) return ok.error();
    return detail::spatial::winding_numbers_of(surface, points, options);
}

template <class M, class T>
    requires surface_query_mesh<M, T>
result<winding_numbers> winding_number(const M& mesh, std::span<const vec3<double>> points,
                                       const winding_number_options& options) {
    auto s = triangles_of<M, T>(mesh, "winding_number");
    if (!s) return s.error();
    return winding_number(*s, points, options);
}

}  // namespace hmira
