// hmira/algorithms/spatial/detail/bvh_build.hpp
// The bvh's geometry (see ../bvh.hpp): the binned-SAH build and its flattening into preorder,
// boxes rounded outward to float, and the exact, nearly-exact and conservative tests its
// traversals run (collinear corners, closest point on a triangle, ray-triangle, ray-box).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "../../../concepts.hpp"
#include "../../../core/result.hpp"
#include "../../../predicates/orient2d.hpp"
#include "../../conversion/detail/parallel.hpp"
#include "../bvh.hpp"

namespace hmira {

namespace detail::bvh_build {

inline constexpr double inf = std::numeric_limits<double>::infinity();
inline constexpr double nan = std::numeric_limits<double>::quiet_NaN();
inline constexpr int bins = 16;
/// Past this depth the build splits at the median, so no path exceeds 64 + 32 nodes and the
/// traversal stacks below cannot overflow.
inline constexpr std::size_t sah_depth = 64, stack_size = 128;
/// The four-wide nodes make a leaf of any subtree of at most this many triangles.
inline constexpr std::uint32_t wide_leaf = 6;
/// Subtrees over more triangles than this build their two children in parallel.
inline constexpr std::uint32_t parallel_threshold = 4096;

/// The largest float <= x and the smallest float >= x: boxes are rounded outward.
inline float round_down(double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    return f;
}
inline float round_up(double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    return f;
}

struct box {
    vec3<double> lo{inf, inf, inf}, hi{-inf, -inf, -inf};
    void grow(const vec3<double>& p) {
        for (std::size_t k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    }
    void grow(const box& b) {
        for (std::size_t k = 0; k < 3; ++k) lo[k] = std::min(lo[k], b.lo[k]), hi[k] = std::max(hi[k], b.hi[k]);
    }
    double half_area() const {
        const vec3<double> d = hi - lo;
        return d.x * d.y + d.y * d.z + d.z * d.x;
    }
};

inline void store(bvh::node& n, const box& b) {
    for (std::size_t k = 0; k < 3; ++k) n.lo[k] = round_down(b.lo[k]), n.hi[k] = round_up(b.hi[k]);
}

inline bool finite(const vec3<double>& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

/// Whether a, b, c are collinear (or coincide), decided exactly: all three coordinate-plane
/// projections have orientation zero. Coordinates outside the predicates' range count as not
/// collinear; the ray test then meets its zero determinant instead.
inline bool collinear(const vec3<double>& a, const vec3<double>& b, const vec3<double>& c) {
    for (const auto& p : {a, b, c})
        for (std::size_t k = 0; k < 3; ++k)
            if (!predicates::in_predicate_range(p[k])) return false;
    using predicates::orient2d;
    return orient2d(a.x, a.y, b.x, b.y, c.x, c.y) == 0 && orient2d(a.y, a.z, b.y, b.z, c.y, c.z) == 0 &&
           orient2d(a.z, a.x, b.z, b.x, c.z, c.x) == 0;
}

/// A triangle while the tree is built: its box, the box's centre and its index. The build
/// partitions these records themselves, so every pass over a node's range reads memory in order.
struct prim {
    box b;
    vec3<double> c;
    std::uint32_t id = 0;
};

/// The binned-SAH build over prims[begin, end), written in preorder: an inner node's left child
/// follows it, its `index` is the right child. The two halves of a split are disjoint ranges of
/// `prims`, so big subtrees build in parallel into their own vectors, appended in the same order
/// afterwards: the tree does not depend on the schedule.
struct builder {
    std::vector<prim>& prims;
    std::uint32_t max_leaf;

    /// Depth of the subtree built.
    std::size_t build(std::vector<bvh::node>& out, std::uint32_t begin, std::uint32_t end, std::size_t depth) const {
        const std::size_t at = out.size();
        out.push_back({});
        box b, cb;
        for (std::uint32_t i = begin; i < end; ++i) b.grow(prims[i].b), cb.grow(prims[i].c);
        store(out[at], b);
        const std::uint32_t mid = split(begin, end, b, cb, depth);
        if (mid == begin) {
            out[at].index = begin;
            out[at].count = end - begin;
            return 1;
        }
        std::size_t dl = 0, dr = 0;
        if (end - begin > parallel_threshold) {
            std::vector<bvh::node> left, right;
            parallel_invoke([&] { dl = build(left, begin, mid, depth + 1); },
                            [&] { dr = build(right, mid, end, depth + 1); });
            append(out, left);
            out[at].index = static_cast<std::uint32_t>(out.size());
            append(out, right);
        } else {
            dl = build(out, begin, mid, depth + 1);
            out[at].index = static_cast<std::uint32_t>(out.size());
            dr = build(out, mid, end, depth + 1);
        }
        return 1 + std::max(dl, dr);
    }

    static void append(std::vector<bvh::node>& out, const std::vector<bvh::node>& sub) {
        const auto base = static_cast<std::uint32_t>(out.size());
        for (bvh::node n : sub) {
            if (n.count == 0) n.index += base;
            out.push_back(n);
        }
    }

    static int bin_of(double c, double lo, double scale) {
        return std::min(bins - 1, static_cast<int>((c - lo) * scale));
    }

    /// Partitions prims[begin, end) and returns where the right child starts, or begin for a
    /// leaf. Cost model: a box test costs as much as a triangle test.
    std::uint32_t split(std::uint32_t begin, std::uint32_t end, const box& b, const box& cb, std::size_t depth) const {
        const std::uint32_t n = end - begin;
        if (n <= 1) return begin;
        if (depth >= sah_depth) return n <= max_leaf ? begin : median(begin, end, cb);
        std::array<double, 3> scale{};
        for (std::size_t axis = 0; axis < 3; ++axis) {
            const double extent = cb.hi[axis] - cb.lo[axis];
            scale[axis] = extent > 0 ? bins / extent : 0;
        }
        // One pass bins the triangles along all three axes.
        std::array<std::array<box, bins>, 3> bb;
        std::array<std::array<std::uint32_t, bins>, 3> count{};
        for (std::uint32_t i = begin; i < end; ++i)
            for (std::size_t axis = 0; axis < 3; ++axis) {
                if (scale[axis] == 0) continue;
                const auto k = std::size_t(bin_of(prims[i].c[axis], cb.lo[axis], scale[axis]));
                bb[axis][k].grow(prims[i].b);
                ++count[axis][k];
            }
        double best = inf;
        int best_axis = -1, best_bin = 0;
        for (std::size_t axis = 0; axis < 3; ++axis) {
            if (scale[axis] == 0) continue;
            // right_cost[k]: the cost of the bins k.. on the right side.
            std::array<double, bins> right_cost{};
            box r;
            std::uint32_t nr = 0;
            for (int k = bins - 1; k > 0; --k) {
                r.grow(bb[axis][std::size_t(k)]);
                nr += count[axis][std::size_t(k)];
                right_cost[std::size_t(k)] = nr ? nr * r.half_area() : 0;
            }
            box l;
            std::uint32_t nl = 0;
            for (int k = 0; k + 1 < bins; ++k) {
                l.grow(bb[axis][std::size_t(k)]);
                nl += count[axis][std::size_t(k)];
                if (nl == 0 || nl == n) continue;
                const double cost = nl * l.half_area() + right_cost[std::size_t(k) + 1];
                if (cost < best) best = cost, best_axis = int(axis), best_bin = k;
            }
        }
        if (best_axis < 0) return n <= max_leaf ? begin : begin + n / 2;  // all centroids coincide
        const double area = b.half_area();
        if (n <= max_leaf && n * area <= area + best) return begin;
        const auto axis = std::size_t(best_axis);
        const auto it = std::partition(prims.begin() + begin, prims.begin() + end, [&](const prim& t) {
            return bin_of(t.c[axis], cb.lo[axis], scale[axis]) <= best_bin;
        });
        return static_cast<std::uint32_t>(it - prims.begin());
    }

    /// The median along the centroids' longest axis, ties broken by index.
    std::uint32_t median(std::uint32_t begin, std::uint32_t end, const box& cb) const {
        std::size_t axis = 0;
        for (std::size_t k = 6; k < 3; ++k)
            if (cb.hi[k] - cb.lo[k] > cb.hi[axis] - cb.lo[axis]) axis = k;
        const std::uint32_t mid = begin + (end - begin) / 2;
        std::nth_element(prims.begin() + begin, prims.begin() + mid, prims.begin() + end,
                         [&](const prim& a, const prim& b) {
                             return a.c[axis] < b.c[axis] || (a.c[axis] == b.c[axis] && a.id < b.id);
                         });
        return mid;
    }
};

/// A point on a triangle and its weights on the corners.
struct weighted_point {
    vec3<double> q;
    std::array<double, 3> w;
};

/// The closest point to p on the three edges (for collinear corners).
inline weighted_point closest_on_edges(const vec3<double>& p, const std::array<vec3<double>, 3>& c) {
    weighted_point best{c[0], {1, 0, 0}};
    double best_d2 = inf;
    for (std::size_t i = 0; i < 3; ++i) {
        const std::size_t j = (i + 1) % 3;
        const vec3<double> d = c[j] - c[i];
        const double l2 = dot(d, d);
        const double s = l2 > 0 ? std::clamp(dot(p - c[i], d) / l2, 0.0, 1.0) : 0.0;
        const vec3<double> q = c[i] + d * s;
        const double d2 = squared_norm(q - p);
        if (d2 < best_d2) {
            best_d2 = d2;
            best.q = q;
            best.w = {0, 0, 0};
            best.w[i] = 1 - s;
            best.w[j] += s;
        }
    }
    return best;
}

/// The closest point of triangle (a, b, c) to p, by the Voronoi regions of its corners, edges
/// and interior (Ericson's tests on dot products). A division that comes out non-finite (a
/// nearly collinear triangle) falls back to the edges. O(1).
inline weighted_point closest_on_triangle(const vec3<double>& p, const vec3<double>& a, const vec3<double>& b,
                                          const vec3<double>& c, bool degenerate) {
    if (degenerate) return closest_on_edges(p, {a, b, c});
    const auto ab = b - a, ac = c - a, ap = p - a;
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return {a, {1, 0, 0}};
    const auto bp = p - b;
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return {b, {0, 1, 0}};
    const auto cp = p - c;
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return {c, {0, 0, 1}};
    weighted_point out;
    const double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        const double v = d1 / (d1 - d3);
        out = {a + ab * v, {1 - v, v, 0}};
    } else if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        const double w = d2 / (d2 - d6);
        out = {a + ac * w, {1 - w, 0, w}};
    } else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
        const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        out = {b + (c - b) * w, {0, 1 - w, w}};
    } else {
        const double inv = 1 / (va + vb + vc);
        const double v = vb * inv, w = vc * inv;
        out = {a + ab * v + ac * w, {1 - v - w, v, w}};
    }
    return finite(out.q) ? out : closest_on_edges(p, {a, b, c});
}

/// The parameter where ray (o, d) meets triangle (a, b, c), with its weights u, v on b and c
/// (Moeller-Trumbore; hits on edges count), or NaN for none. O(1).
inline double ray_triangle(const vec3<double>& o, const vec3<double>& d, const vec3<double>& a, const vec3<double>& b,
                           const vec3<double>& c, double& u, double& v) {
    const auto e1 = b - a, e2 = c - a;
    const auto pv = cross(d, e2);
    const double det = dot(e1, pv);
    if (!(det != 0)) return nan;
    const double inv = 1.0 / det;
    const auto tv = o - a;
    u = dot(tv, pv) * inv;
    if (!(u >= 0 && u <= 1)) return nan;
    const auto qv = cross(tv, e1);
    v = dot(d, qv) * inv;
    if (!(v >= 0 && u + v <= 1)) return nan;
    return dot(e2, qv) * inv;
}

/// Squared distance from p to a node's box.
inline double box_distance2(const bvh::node& n, const vec3<double>& p) {
    double d2 = 0;
    for (std::size_t k = 0; k < 3; ++k) {
        const double e = std::max({double(n.lo[k]) - p[k], 0.0, p[k] - double(n.hi[k])});
        d2 += e * e;
    }
    return d2;
}

/// Where the ray (o, 1 / inv) enters a node's box within [t0, t1], or NaN when it misses it
/// (slab test). The far slab is widened by a few ulps so that the rounding of the slab
/// products never drops a box the ray touches (Ize, "Robust BVH ray traversal"); a ray
/// parallel to a slab it starts in gives NaN (0 * inf), which constrains nothing.
inline double box_entry(const bvh::node& n, const vec3<double>& o, const vec3<double>& inv, double t0, double t1) {
    constexpr double slack = 4 * std::numeric_limits<double>::epsilon();
    for (std::size_t k = 0; k < 3; ++k) {
        double a = (double(n.lo[k]) - o[k]) * inv[k], b = (double(n.hi[k]) - o[k]) * inv[k];
        if (a > b) std::swap(a, b);
        if (a == a) t0 = std::max(t0, a);
        if (b == b) t1 = std::min(t1, b + std::abs(b) * slack);
        if (t0 > t1) return nan;
    }
    return t0;
}

/// A ray prepared for the float slab test: its origin and inverse direction rounded to float,
/// and per axis the absolute part of the margin that covers that rounding. `exact` is false
/// when float cannot bound the slabs (a direction component that is zero or nearly so, or
/// products past float's range): the ray then runs the double test.
struct float_ray {
    std::array<float, 3> o{}, inv{}, err{};
    bool exact = false;
};

/// The relative margin of the float slab test: the rounding of the origin, the inverse and the
/// two slab operations is below 4 * 2^-24 of the result plus 2^-24 * |o| * |inv|; the margin
/// takes 2^-20 of each, at least four times that, so the float interval contains the double one.
inline constexpr float float_slack = 1.0f / (1 << 20);

/// Prepares r for box_entry_float; `reach` bounds |coordinate| over the whole tree.
inline float_ray prepare_float_ray(const vec3<double>& o, const vec3<double>& d, double reach) {
    float_ray f;
    f.exact = true;
    for (std::size_t k = 0; k < 3; ++k) {
        const double inv = 1.0 / d[k];
        if (!(std::abs(inv) * (std::abs(o[k]) + reach) < 1e30)) f.exact = false;
        f.o[k] = static_cast<float>(o[k]);
        f.inv[k] = static_cast<float>(inv);
        f.err[k] = float_slack * std::abs(f.o[k]) * std::abs(f.inv[k]) + 4 * std::numeric_limits<float>::min();
    }
    return f;
}

/// The float counterpart of box_entry: where the ray enters the box within [t0, t1], widened on
/// both sides by the margins above so that it never drops a box the double test keeps (the
/// value returned is at most the double test's entry), or NaN when it misses. Only for a ray
/// with `exact` set. O(1), branch-free per axis.
inline double box_entry_float(const bvh::node& n, const float_ray& r, float t0, float t1) {
    for (std::size_t k = 0; k < 3; ++k) {
        const float a = (n.lo[k] - r.o[k]) * r.inv[k], b = (n.hi[k] - r.o[k]) * r.inv[k];
        const float near = std::min(a, b), far = std::max(a, b);
        t0 = std::max(t0, near - (float_slack * std::abs(near) + r.err[k]));
        t1 = std::min(t1, far + (float_slack * std::abs(far) + r.err[k]));
    }
    return t0 <= t1 ? double(t0) : nan;
}

/// The four-wide form of a binary tree in preorder: each wide node takes an inner node's two
/// children and keeps opening its largest inner child (by box area) until it has four children
/// or only leaves; the leaves keep their triangle ranges, so every query finds the same
/// triangles. Written root first, children after their parent. O(n).
template <class WideNode>
void collapse_wide(const std::vector<bvh::node>& nodes, std::vector<WideNode>& wide) {
    wide.clear();
    if (nodes.empty()) return;
    wide.reserve(nodes.size() / 2 + 1);
    // A subtree's triangles are a contiguous range (preorder); one of at most wide_leaf
    // triangles becomes one leaf: fewer, fuller nodes for the same triangles.
    std::vector<std::uint32_t> first(nodes.size()), end(nodes.size());
    for (std::size_t i = nodes.size(); i-- > 0;) {
        const auto& n = nodes[i];
        if (n.count > 0)
            first[i] = n.index, end[i] = n.index + n.count;
        else
            first[i] = first[i + 1], end[i] = end[n.index];
    }
    const auto leaf = [&](std::uint32_t i) { return nodes[i].count > 0 || end[i] - first[i] <= wide_leaf; };
    const auto area = [&](std::uint32_t i) {
        const auto& n = nodes[i];
        const float dx = n.hi[0] - n.lo[0], dy = n.hi[1] - n.lo[1], dz = n.hi[2] - n.lo[2];
        return dx * dy + dy * dz + dz * dx;
    };
    // pending: (binary node, wide node to fill).
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pending{{0, 0}};
    wide.emplace_back();
    while (!pending.empty()) {
        const auto [bin, at] = pending.back();
        pending.pop_back();
        std::array<std::uint32_t, 4> kids{};
        std::uint32_t k = 0;
        if (leaf(bin)) {
            kids[k++] = bin;  // a root leaf: one child
        } else {
            kids[k++] = bin + 1, kids[k++] = nodes[bin].index;
            while (k < 4) {
                int open = -1;
                for (std::uint32_t j = 0; j < k; ++j)
                    if (!leaf(kids[j]) && (open < 0 || area(kids[j]) > area(kids[std::size_t(open)]))) open = int(j);
                if (open < 0) break;
                const std::uint32_t c = kids[std::size_t(open)];
                kids[std::size_t(open)] = c + 1, kids[k++] = nodes[c].index;
            }
        }
        WideNode w;
        for (std::uint32_t j = 0; j < k; ++j) {
            const auto& n = nodes[kids[j]];
            for (std::size_t a = 0; a < 3; ++a) w.lo[a][j] = n.lo[a], w.hi[a][j] = n.hi[a];
            if (leaf(kids[j])) {
                w.index[j] = first[kids[j]], w.count[j] = end[kids[j]] - first[kids[j]];
            } else {
                w.index[j] = static_cast<std::uint32_t>(wide.size());
                wide.emplace_back();
                pending.push_back({kids[j], w.index[j]});
            }
        }
        wide[at] = w;
    }
}

/// box_entry_float on the four boxes of a wide node at once: entry[j] is where the ray enters
/// box j within [t0, t1], widened as there, or NaN for a miss (an unused lane's is meaningless).
template <class WideNode>
inline void box_entry_float4(const WideNode& w, const float_ray& r, float t0, float t1, std::array<float, 4>& entry) {
    std::array<float, 4> lo, hi;
    lo.fill(t0), hi.fill(t1);
    for (std::size_t k = 0; k < 3; ++k) {
        for (std::size_t j = 0; j < 4; ++j) {
            const float a = (w.lo[k][j] - r.o[k]) * r.inv[k], b = (w.hi[k][j] - r.o[k]) * r.inv[k];
            const float near = a < b ? a : b, far = a < b ? b : a;
            const float wn = near - (float_slack * std::abs(near) + r.err[k]);
            const float wf = far + (float_slack * std::abs(far) + r.err[k]);
            lo[j] = lo[j] < wn ? wn : lo[j];
            hi[j] = hi[j] < wf ? hi[j] : wf;
        }
    }
    for (std::size_t j = 0; j < 4; ++j) entry[j] = lo[j] <= hi[j] ? lo[j] : std::numeric_limits<float>::quiet_NaN();
}

/// box_entry (double slabs) on the four boxes of a wide node.
template <class WideNode>
inline void box_entry4(const WideNode& w, const vec3<double>& o, const vec3<double>& inv, double t0, double t1,
                       std::array<double, 4>& entry) {
    constexpr double slack = 4 * std::numeric_limits<double>::epsilon();
    for (std::size_t j = 0; j < 4; ++j) {
        double s0 = t0, s1 = t1;
        for (std::size_t k = 0; k < 3; ++k) {
            double a = (double(w.lo[k][j]) - o[k]) * inv[k], b = (double(w.hi[k][j]) - o[k]) * inv[k];
            if (a > b) std::swap(a, b);
            if (a == a) s0 = std::max(s0, a);
            if (b == b) s1 = std::min(s1, b + std::abs(b) * slack);
        }
        entry[j] = s0 <= s1 ? s0 : nan;
    }
}

}  // namespace detail::bvh_build

}  // namespace hmira
