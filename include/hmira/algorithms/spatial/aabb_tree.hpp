// hmira/algorithms/spatial/aabb_tree.hpp
// A bounding-volume hierarchy (axis-aligned boxes) over triangles: the closest point on a
// surface and the first hit of a ray in O(log n) per query. Remeshing projects onto it.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/result.hpp"
#include "../../core/vec3.hpp"
#include "../conversion/detail/parallel.hpp"
#include "ray.hpp"

namespace hmira {

/// The closest point on the tree's triangles to a query point.
struct closest_point_result {
    vec3<double> point{};                                       ///< the closest point on the surface
    std::size_t face = 0;                                       ///< the id of the triangle it lies on (see aabb_tree)
    double distance = std::numeric_limits<double>::infinity();  ///< |point - query|; infinity for an empty tree
};

/// The first triangle a ray hits.
struct ray_hit {
    double t = 0;          ///< the ray parameter: point = origin + t * direction
    vec3<double> point{};  ///< where the ray hits
    std::size_t face = 0;  ///< the id of the triangle hit (see aabb_tree)
};

namespace detail::spatial {

/// The point of triangle (a, b, c) closest to p, by the Voronoi regions of its vertices,
/// edges and interior (barycentric tests on dot products). O(1).
inline vec3<double> closest_on_triangle(const vec3<double>& p, const vec3<double>& a, const vec3<double>& b,
                                        const vec3<double>& c) {
    const auto ab = b - a, ac = c - a, ap = p - a;
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const auto bp = p - b;
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
    const auto cp = p - c;
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const double denom = va + vb + vc;
    if (!(std::abs(denom) > 0)) return a;  // degenerate triangle: its vertex regions covered the rest
    return a + ab * (vb / denom) + ac * (vc / denom);
}

/// Ray parameter of the hit of (o, d) with triangle (a, b, c), or a negative number for none
/// (Moeller-Trumbore; hits on edges count). O(1).
inline double ray_triangle(const vec3<double>& o, const vec3<double>& d, const vec3<double>& a, const vec3<double>& b,
                           const vec3<double>& c) {
    const auto e1 = b - a, e2 = c - a;
    const auto pv = cross(d, e2);
    const double det = dot(e1, pv);
    if (!(std::abs(det) > 0)) return -1;
    const double inv = 1.0 / det;
    const auto tv = o - a;
    const double u = dot(tv, pv) * inv;
    if (u < 0 || u > 1) return -1;
    const auto qv = cross(tv, e1);
    const double v = dot(d, qv) * inv;
    if (v < 0 || u + v > 1) return -1;
    return dot(e2, qv) * inv;
}

}  // namespace detail::spatial

/// An axis-aligned bounding-box tree over a fixed set of triangles, each carrying an id (for a
/// tree built from a mesh, the index T::face_index of the face it came from). It keeps its own
/// copy of the triangles, so the mesh may change afterwards. Built by median splits along the
/// longest axis: the same triangles in the same order give the same tree and the same answers.
class aabb_tree {
public:
    /// An empty tree: every query misses.
    aabb_tree() = default;

    /// A tree over triangles[i] = (points[t[0]], points[t[1]], points[t[2]]) with id ids[i]
    /// (or i when ids is empty).
    /// \pre every index < points.size(); ids empty or ids.size() == triangles.size(); points
    /// finite (aabb_tree_from_mesh checks this for meshes).
    /// Complexity O(n log n) time, O(n) memory.
    aabb_tree(std::span<const vec3<double>> points, std::span<const std::array<std::uint32_t, 3>> triangles,
              std::span<const std::size_t> ids = {}) {
        corners_.reserve(triangles.size());
        ids_.reserve(triangles.size());
        for (std::size_t i = 0; i < triangles.size(); ++i) {
            const auto& t = triangles[i];
            corners_.push_back({points[t[0]], points[t[1]], points[t[2]]});
            ids_.push_back(ids.empty() ? i : ids[i]);
        }
        build();
    }

    /// Number of triangles. O(1).
    std::size_t size() const noexcept { return corners_.size(); }
    /// Whether the tree holds no triangle. O(1).
    bool empty() const noexcept { return corners_.empty(); }
    /// The corners of the i-th triangle (in the tree's own order) and its id. O(1).
    ///@{
    const std::array<vec3<double>, 3>& triangle(std::size_t i) const { return corners_[i]; }
    std::size_t id(std::size_t i) const { return ids_[i]; }
    ///@}

    /// The point of the triangles closest to p, the id of its triangle and the distance. Ties
    /// go to the triangle met first in the tree's fixed order. An empty tree returns
    /// distance infinity.
    /// Complexity O(log n) expected for a well-spread surface, O(n) worst case.
    closest_point_result closest_point(const vec3<double>& p) const {
        return closest_point(p, std::numeric_limits<double>::infinity());
    }

    /// As closest_point(p), but only looks for points closer than `bound` (a known upper bound
    /// speeds the search up, for example the distance to the previous answer). Returns
    /// distance infinity when none is closer than bound.
    closest_point_result closest_point(const vec3<double>& p, double bound) const {
        closest_point_result best;
        if (nodes_.empty()) return best;
        double best_d2 = bound * bound;
        std::uint32_t stack[64];
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const node& n = nodes_[stack[--top]];
            if (box_distance2(n, p) >= best_d2) continue;
            if (n.count > 0) {
                for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
                    const auto& c = corners_[i];
                    const auto q = detail::spatial::closest_on_triangle(p, c[0], c[1], c[2]);
                    const double d2 = squared_norm(q - p);
                    if (d2 < best_d2) {
                        best_d2 = d2;
                        best.point = q;
                        best.face = ids_[i];
                        best.distance = d2;
                    }
                }
                continue;
            }
            // Visit the nearer child first: it usually tightens the bound for the other.
            const double dl = box_distance2(nodes_[n.first], p), dr = box_distance2(nodes_[n.first + 1], p);
            const bool left_first = dl <= dr;
            stack[top++] = left_first ? n.first + 1 : n.first;
            stack[top++] = left_first ? n.first : n.first + 1;
        }
        if (best.distance != std::numeric_limits<double>::infinity()) best.distance = std::sqrt(best.distance);
        return best;
    }

    /// The first hit of r with the triangles (smallest t in [r.t_min, r.t_max]), or none.
    /// Ties go to the triangle met first in the tree's fixed order.
    /// Complexity O(log n) expected, O(n) worst case.
    std::optional<ray_hit> ray_intersect(const ray& r) const {
        if (nodes_.empty()) return std::nullopt;
        const vec3<double> inv{1.0 / r.direction.x, 1.0 / r.direction.y, 1.0 / r.direction.z};
        double best_t = r.t_max;
        std::optional<ray_hit> best;
        std::uint32_t stack[64];
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const node& n = nodes_[stack[--top]];
            if (!(box_entry(n, r.origin, inv, r.t_min, best_t) <= best_t)) continue;
            if (n.count > 0) {
                for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
                    const auto& c = corners_[i];
                    const double t = detail::spatial::ray_triangle(r.origin, r.direction, c[0], c[1], c[2]);
                    if (t >= r.t_min && (t < best_t || (!best && t == best_t))) {
                        best_t = t;
                        best = ray_hit{t, r.origin + r.direction * t, ids_[i]};
                    }
                }
                continue;
            }
            const double tl = box_entry(nodes_[n.first], r.origin, inv, r.t_min, best_t);
            const double tr = box_entry(nodes_[n.first + 1], r.origin, inv, r.t_min, best_t);
            const bool left_first = tl <= tr;
            stack[top++] = left_first ? n.first + 1 : n.first;
            stack[top++] = left_first ? n.first : n.first + 1;
        }
        return best;
    }

private:
    struct node {
        vec3<double> lo, hi;
        std::uint32_t first = 0;  // leaf: first triangle; inner: left child (right = first + 1)
        std::uint32_t count = 0;  // triangles in a leaf, 0 for an inner node
    };
    static constexpr std::uint32_t leaf_size = 4;

    static double box_distance2(const node& n, const vec3<double>& p) {
        double d2 = 0;
        for (std::size_t k = 0; k < 3; ++k) {
            const double e = std::max({n.lo[k] - p[k], 0.0, p[k] - n.hi[k]});
            d2 += e * e;
        }
        return d2;
    }

    // The parameter where the ray enters the box, or infinity when it misses it within
    // [t0, t1] (slab test; NaN from 0 * inf compares false and counts as a miss only where safe).
    static double box_entry(const node& n, const vec3<double>& o, const vec3<double>& inv, double t0, double t1) {
        for (std::size_t k = 0; k < 3; ++k) {
            double a = (n.lo[k] - o[k]) * inv[k], b = (n.hi[k] - o[k]) * inv[k];
            if (a > b) std::swap(a, b);
            // A ray parallel to a slab it starts in gives NaN (0 * inf): no constraint.
            if (a == a) t0 = std::max(t0, a);
            if (b == b) t1 = std::min(t1, b);
            if (t0 > t1) return std::numeric_limits<double>::infinity();
        }
        return t0;
    }

    /// Boxes node `at` over order[begin, end) and, for an inner node, splits the range at its
    /// median along the centres' longest axis and builds the children (in parallel when big).
    void build_subtree(std::uint32_t at, std::uint32_t begin, std::uint32_t end, std::vector<std::uint32_t>& order,
                       const std::vector<vec3<double>>& centre) {
        node& nd = nodes_[at];
        constexpr double inf = std::numeric_limits<double>::infinity();
        nd.lo = {inf, inf, inf};
        nd.hi = -nd.lo;
        vec3<double> clo = nd.lo, chi = nd.hi;
        for (std::uint32_t i = begin; i < end; ++i) {
            for (const auto& q : corners_[order[i]])
                for (std::size_t k = 0; k < 3; ++k) {
                    nd.lo[k] = std::min(nd.lo[k], q[k]);
                    nd.hi[k] = std::max(nd.hi[k], q[k]);
                }
            for (std::size_t k = 0; k < 3; ++k) {
                clo[k] = std::min(clo[k], centre[order[i]][k]);
                chi[k] = std::max(chi[k], centre[order[i]][k]);
            }
        }
        if (nd.count > 0) return;
        std::size_t axis = 0;
        for (std::size_t k = 1; k < 3; ++k)
            if (chi[k] - clo[k] > chi[axis] - clo[axis]) axis = k;
        const std::uint32_t mid = begin + (end - begin) / 2;
        // Ties broken by index keep the split (and so the tree) independent of the sort.
        std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end,
                         [&](std::uint32_t a, std::uint32_t b) {
                             return centre[a][axis] < centre[b][axis] || (centre[a][axis] == centre[b][axis] && a < b);
                         });
        const std::uint32_t left = nd.first;
        if (end - begin > 8192)
            detail::parallel_invoke([&] { build_subtree(left, begin, mid, order, centre); },
                                    [&] { build_subtree(left + 1, mid, end, order, centre); });
        else
            build_subtree(left, begin, mid, order, centre), build_subtree(left + 1, mid, end, order, centre);
    }

    void build() {
        nodes_.clear();
        if (corners_.empty()) return;
        const std::size_t n = corners_.size();
        std::vector<std::uint32_t> order(n);
        std::vector<vec3<double>> centre(n);
        for (std::size_t i = 0; i < n; ++i) {
            order[i] = std::uint32_t(i);
            centre[i] = (corners_[i][0] + corners_[i][1] + corners_[i][2]) / 3.0;
        }
        // The shape depends on n alone (median splits): number the nodes first, depth first
        // with the left child first; then box and split the subtrees in parallel, each range
        // split in the order a serial build would leave it, so the tree does not depend on the
        // schedule.
        nodes_.reserve(2 * (n / leaf_size + 1));
        nodes_.push_back({});
        struct task {
            std::uint32_t node, begin, end;
        };
        std::vector<task> todo{{0, 0, std::uint32_t(n)}};
        while (!todo.empty()) {
            const task t = todo.back();
            todo.pop_back();
            if (t.end - t.begin <= leaf_size) {
                nodes_[t.node].first = t.begin;
                nodes_[t.node].count = t.end - t.begin;
                continue;
            }
            const auto left = std::uint32_t(nodes_.size());
            nodes_[t.node].first = left;
            nodes_[t.node].count = 0;
            nodes_.push_back({});
            nodes_.push_back({});
            const std::uint32_t mid = t.begin + (t.end - t.begin) / 2;
            todo.push_back({left + 1, mid, t.end});
            todo.push_back({left, t.begin, mid});
        }
        build_subtree(0, 0, std::uint32_t(n), order, centre);
        // Store the triangles in leaf order, so a leaf's triangles are contiguous.
        std::vector<std::array<vec3<double>, 3>> corners(n);
        std::vector<std::size_t> ids(n);
        for (std::size_t i = 0; i < n; ++i) {
            corners[i] = corners_[order[i]];
            ids[i] = ids_[order[i]];
        }
        corners_ = std::move(corners);
        ids_ = std::move(ids);
    }

    std::vector<std::array<vec3<double>, 3>> corners_;
    std::vector<std::size_t> ids_;
    std::vector<node> nodes_;
};

/// A mesh an aabb_tree can be built from: face loops, positions, dense vertex and face indices.
template <class M, class T = default_traits<M>>
concept aabb_tree_source_mesh =
    face_vertex_range_mesh<M, T> && positioned_mesh<M, T> && vertex_index_mesh<M, T> && face_index_mesh<M, T>;

/// An aabb_tree over the faces of a mesh; a polygon face is cut into a fan from its first
/// vertex, every piece carrying the face's index T::face_index(mesh, f).
/// Errors: errc::invalid_argument naming the vertex for a non-finite position.
/// Complexity O(n log n) for n triangles.
template <class M, class T = default_traits<M>>
    requires aabb_tree_source_mesh<M, T>
[[nodiscard]] result<aabb_tree> aabb_tree_from_mesh(const M& mesh) {
    std::vector<vec3<double>> points(T::vertex_index_bound(mesh));
    for (auto v : T::vertices(mesh)) {
        const vec3<typename T::scalar> p = T::position(mesh, v);
        const vec3<double> q{double(p.x), double(p.y), double(p.z)};
        if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z))
            return fail(errc::invalid_argument,
                        "aabb_tree_from_mesh: vertex " + std::to_string(T::vertex_index(mesh, v)) +
                            " has a non-finite position",
                        (long long)T::vertex_index(mesh, v));
        points[T::vertex_index(mesh, v)] = q;
    }
    std::vector<std::array<std::uint32_t, 3>> triangles;
    std::vector<std::size_t> ids;
    triangles.reserve(T::face_count(mesh));
    ids.reserve(T::face_count(mesh));
    std::vector<std::uint32_t> loop;
    for (auto f : T::faces(mesh)) {
        loop.clear();
        for (auto v : T::face_vertices(mesh, f)) loop.push_back(std::uint32_t(T::vertex_index(mesh, v)));
        for (std::size_t i = 1; i + 1 < loop.size(); ++i) {
            triangles.push_back({loop[0], loop[i], loop[i + 1]});
            ids.push_back(T::face_index(mesh, f));
        }
    }
    return aabb_tree(points, triangles, ids);
}

}  // namespace hmira
