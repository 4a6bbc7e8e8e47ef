// hmira/algorithms/spatial/detail/bvh_impl.hpp
// The machinery of the bvh (see ../bvh.hpp for the interface): building, refitting and
// traversing its arrays, the batched queries, and the mesh-taking entry points with their
// staleness check. The build's geometry is in bvh_build.hpp.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "../../../concepts.hpp"
#include "../../../core/result.hpp"
#include "../../conversion/detail/parallel.hpp"
#include "../../euler/euler_common.hpp"
#include "../../triangulation/triangulate_faces.hpp"
#include "../bvh.hpp"
#include "bvh_build.hpp"

namespace hmira {

namespace detail {

/// Builds, refits and traverses a bvh's private arrays.
struct bvh_access {
    using node = bvh::node;

    static result<bvh> build(std::span<const vec3<double>> points,
                             std::span<const std::array<std::uint32_t, 3>> triangles,
                             std::span<const std::size_t> faces, const bvh_options& options) {
        namespace bb = detail::bvh_build;
        constexpr std::size_t limit = std::numeric_limits<std::uint32_t>::max();
        if (points.size() > limit || triangles.size() > limit)
            return fail(errc::unsupported, "bvh: more than 2^32 - 1 points or triangles");
        if (!faces.empty() && faces.size() != triangles.size())
            return fail(errc::invalid_argument, "bvh: " + std::to_string(faces.size()) + " face indices for " +
                                                    std::to_string(triangles.size()) + " triangles");
        if (options.max_leaf_size < 1 || options.max_leaf_size > 64)
            return fail(errc::invalid_argument, "bvh: max_leaf_size must be 1 to 64");
        for (std::size_t i = 0; i < points.size(); ++i)
            if (!bb::finite(points[i]))
                return fail(errc::invalid_argument, "bvh: point " + std::to_string(i) + " is not finite", (long long)i);
        for (std::size_t i = 0; i < triangles.size(); ++i)
            for (auto v : triangles[i])
                if (v >= points.size())
                    return fail(errc::invalid_argument,
                                "bvh: triangle " + std::to_string(i) + " has vertex " + std::to_string(v) +
                                    ", past the " + std::to_string(points.size()) + " points",
                                (long long)i);
        bvh t;
        t.point_count_ = points.size();
        const std::size_t n = triangles.size();
        if (n == 0) return t;
        std::vector<bb::prim> prims(n);
        detail::with_thread_count(options.threads, [&] {
            detail::parallel_chunks(n, 4096, [&](std::size_t lo, std::size_t hi) {
                for (std::size_t i = lo; i < hi; ++i) {
                    for (auto v : triangles[i]) prims[i].b.grow(points[v]);
                    prims[i].c = (prims[i].b.lo + prims[i].b.hi) * 0.5;
                    prims[i].id = static_cast<std::uint32_t>(i);
                }
            });
            const bb::builder b{prims, options.max_leaf_size};
            t.nodes_.reserve(2 * n);
            t.depth_ = b.build(t.nodes_, 0, static_cast<std::uint32_t>(n), 0);
            t.reach_ = reach_of(t.nodes_[0]);
            bb::collapse_wide(t.nodes_, t.wide_);
            t.corners_.resize(n);
            t.vertices_.resize(n);
            t.faces_.resize(n);
            t.degenerate_.resize(n);
            detail::parallel_chunks(n, 4096, [&](std::size_t lo, std::size_t hi) {
                for (std::size_t i = lo; i < hi; ++i) {
                    const std::uint32_t k = prims[i].id;
                    t.vertices_[i] = triangles[k];
                    t.faces_[i] = faces.empty() ? k : faces[k];
                }
            });
            place_corners(t, points);
        });
        return t;
    }

    /// The largest |coordinate| of a box: every box lies within the root's.
    static double reach_of(const node& root) {
        double r = 0;
        for (std::size_t k = 0; k < 3; ++k)
            r = std::max({r, std::abs(double(root.lo[k])), std::abs(double(root.hi[k]))});
        return r;
    }

    /// Corners and degeneracy flags of every triangle from `points`.
    static void place_corners(bvh& t, std::span<const vec3<double>> points) {
        detail::parallel_chunks(t.size(), 4096, [&](std::size_t lo, std::size_t hi) {
            for (std::size_t i = lo; i < hi; ++i) {
                const auto& v = t.vertices_[i];
                t.corners_[i] = {points[v[0]], points[v[1]], points[v[2]]};
                t.degenerate_[i] = detail::bvh_build::collinear(points[v[0]], points[v[1]], points[v[2]]);
            }
        });
    }

    static result<void> refit(bvh& t, std::span<const vec3<double>> points) {
        namespace bb = detail::bvh_build;
        if (points.size() < t.point_count_)
            return fail(errc::invalid_argument, "bvh::refit: " + std::to_string(points.size()) +
                                                    " points, the tree was built on " + std::to_string(t.point_count_));
        for (std::size_t i = 0; i < t.point_count_; ++i)
            if (!bb::finite(points[i]))
                return fail(errc::invalid_argument, "bvh::refit: point " + std::to_string(i) + " is not finite",
                            (long long)i);
        place_corners(t, points);
        // Children follow their parent in preorder, so a backward sweep sees them first. The
        // rounding is monotone, so an inner box (the union of its children's rounded boxes)
        // equals the rounded union the build stores.
        for (std::size_t i = t.nodes_.size(); i-- > 0;) {
            node& n = t.nodes_[i];
            if (n.count > 0) {
                bb::box b;
                for (std::uint32_t k = n.index; k < n.index + n.count; ++k) {
                    b.grow(t.corners_[k].a);
                    b.grow(t.corners_[k].b);
                    b.grow(t.corners_[k].c);
                }
                bb::store(n, b);
            } else {
                const node &l = t.nodes_[i + 1], &r = t.nodes_[n.index];
                for (std::size_t k = 0; k < 3; ++k)
                    n.lo[k] = std::min(l.lo[k], r.lo[k]), n.hi[k] = std::max(l.hi[k], r.hi[k]);
            }
        }
        if (!t.nodes_.empty()) t.reach_ = reach_of(t.nodes_[0]);
        bb::collapse_wide(t.nodes_, t.wide_);
        return {};
    }

    static closest_surface_point closest(const bvh& t, const vec3<double>& p, double max_distance) {
        namespace bb = detail::bvh_build;
        closest_surface_point best;
        if (!bb::finite(p)) {
            best.point = {bb::nan, bb::nan, bb::nan};
            best.distance = bb::nan;
            return best;
        }
        if (t.nodes_.empty() || !(max_distance >= 0)) return best;
        double best_d2 = max_distance * max_distance;
        bool found = false;
        // Visit a box nearer than the best so far (or as near, while nothing is found: the
        // maximum distance is inclusive).
        const auto visit = [&](double d2) { return d2 < best_d2 || (!found && d2 <= best_d2); };
        std::size_t best_i = 0;
        bb::weighted_point best_q{};
        struct entry {
            std::uint32_t node;
            double d2;
        };
        entry stack[bb::stack_size];
        int top = 0;
        stack[top++] = {0, bb::box_distance2(t.nodes_[0], p)};
        while (top > 0) {
            const entry e = stack[--top];
            if (!visit(e.d2)) continue;
            const node& n = t.nodes_[e.node];
            if (n.count > 0) {
                for (std::uint32_t i = n.index; i < n.index + n.count; ++i) {
                    const auto& c = t.corners_[i];
                    const auto q = bb::closest_on_triangle(p, c.a, c.b, c.c, t.degenerate_[i] != 0);
                    const double d2 = squared_norm(q.q - p);
                    if (visit(d2)) best_d2 = d2, found = true, best_i = i, best_q = q;
                }
                continue;
            }
            // The nearer child goes on top: it usually tightens the bound for the other.
            const std::uint32_t l = e.node + 1, r = n.index;
            const double dl = bb::box_distance2(t.nodes_[l], p), dr = bb::box_distance2(t.nodes_[r], p);
            const bool left_first = dl <= dr;
            const entry near{left_first ? l : r, left_first ? dl : dr}, far{left_first ? r : l, left_first ? dr : dl};
            if (visit(far.d2)) stack[top++] = far;
            if (visit(near.d2)) stack[top++] = near;
        }
        if (!found) return best;
        best.point = best_q.q;
        best.barycentric = best_q.w;
        best.face = t.faces_[best_i];
        best.vertices = t.vertices_[best_i];
        best.distance = std::sqrt(best_d2);
        return best;
    }

    static ray_surface_hit make_hit(const bvh& t, const ray& r, std::size_t i, double s, double u, double v) {
        ray_surface_hit h;
        h.t = s;
        h.point = r.origin + r.direction * s;
        h.face = t.faces_[i];
        h.vertices = t.vertices_[i];
        h.barycentric = {1 - u - v, u, v};
        return h;
    }

    static bool finite_ray(const ray& r) {
        return detail::bvh_build::finite(r.origin) && detail::bvh_build::finite(r.direction);
    }

    static ray_surface_hit nan_hit() {
        namespace bb = detail::bvh_build;
        ray_surface_hit h;
        h.t = bb::nan;
        h.point = {bb::nan, bb::nan, bb::nan};
        return h;
    }

    /// The traversal the three ray queries share: calls leaf(i, t, u, v) on every hit of a
    /// non-degenerate triangle with t in [t_min, bound()], nearer boxes first; stops when
    /// leaf returns false. It walks the four-wide nodes, testing a node's boxes together, in
    /// float (box_entry_float4) unless the ray cannot be bounded in float or `boxes` asks for
    /// double; both keep every box the ray meets, and the triangles are always tested in
    /// double, so the hits are the same.
    template <class Bound, class Leaf>
    static void traverse(const bvh& t, const ray& r, bvh_box_test boxes, const Bound& bound, const Leaf& leaf) {
        namespace bb = detail::bvh_build;
        if (t.wide_.empty()) return;
        if (boxes == bvh_box_test::float32) {
            const bb::float_ray f = bb::prepare_float_ray(r.origin, r.direction, t.reach_);
            if (f.exact) {
                const float t_min = bb::round_down(r.t_min);
                descend<float>(t, r, bound, leaf, [&](const bvh::wide_node& w, std::array<float, 4>& e) {
                    bb::box_entry_float4(w, f, t_min, bb::round_up(bound()), e);
                });
                return;
            }
        }
        const vec3<double> inv{1.0 / r.direction.x, 1.0 / r.direction.y, 1.0 / r.direction.z};
        descend<double>(t, r, bound, leaf, [&](const bvh::wide_node& w, std::array<double, 4>& e) {
            bb::box_entry4(w, r.origin, inv, r.t_min, bound(), e);
        });
    }

    /// Asks for the memory a stack item will read, while the nearer items are processed.
    template <class Item>
    static void prefetch([[maybe_unused]] const bvh& t, [[maybe_unused]] const Item& x) {
#if defined(__GNUC__)
        if (x.count == 0) {
            __builtin_prefetch(&t.wide_[x.index]);
            __builtin_prefetch(reinterpret_cast<const char*>(&t.wide_[x.index]) + 64);
        } else {
            __builtin_prefetch(&t.corners_[x.index]);
        }
#endif
    }

    /// traverse's loop, with entry(node, e) giving where the ray enters each of a wide node's
    /// boxes (NaN: it misses). A stack entry is a child: a wide node (count 0) or a leaf range.
    template <class F, class Bound, class Leaf, class Entry>
    static void descend(const bvh& t, const ray& r, const Bound& bound, const Leaf& leaf, const Entry& entry) {
        namespace bb = detail::bvh_build;
        struct item {
            std::uint32_t index, count;
            F t;
        };
        // Each wide level pushes at most three items past the one it pops.
        item stack[4 * bb::stack_size];
        int top = 0;
        stack[top++] = {0, 0, F(r.t_min)};
        std::array<F, 4> e;
        while (top > 0) {
            const item it = stack[--top];
            if (!(it.t <= bound())) continue;
            if (it.count > 0) {
                for (std::uint32_t i = it.index; i < it.index + it.count; ++i) {
                    if (t.degenerate_[i]) continue;
                    const auto& c = t.corners_[i];
                    double u = 0, v = 0;
                    const double s = bb::ray_triangle(r.origin, r.direction, c.a, c.b, c.c, u, v);
                    if (s >= r.t_min && s <= bound() && !leaf(i, s, u, v)) return;
                }
                continue;
            }
            const bvh::wide_node& w = t.wide_[it.index];
            entry(w, e);
            // The children hit, farthest first, so that the nearest is popped next.
            item hit[4];
            int n = 0;
            for (std::uint32_t j = 0; j < 4; ++j) {
                if (!(e[j] <= bound()) || (w.index[j] == 0 && w.count[j] == 0)) continue;
                item x{w.index[j], w.count[j], e[j]};
                prefetch(t, x);
                int at = n++;
                for (; at > 0 && hit[at - 1].t < x.t; --at) hit[at] = hit[at - 1];
                hit[at] = x;
            }
            for (int j = 0; j < n; ++j) stack[top++] = hit[j];
        }
    }

    static ray_surface_hit first(const bvh& t, const ray& r, bvh_box_test boxes) {
        if (!finite_ray(r)) return nan_hit();
        double best = r.t_max;
        bool found = false;
        std::size_t best_i = 0;
        double bu = 0, bv = 0;
        // Among equal parameters the triangle first in the tree's order wins, whatever order
        // the traversal meets them in.
        traverse(
            t, r, boxes, [&] { return best; },
            [&](std::size_t i, double s, double u, double v) {
                if (s < best || !found || (s == best && i < best_i)) best = s, found = true, best_i = i, bu = u, bv = v;
                return true;
            });
        return found ? make_hit(t, r, best_i, best, bu, bv) : ray_surface_hit{};
    }

    static bool any(const bvh& t, const ray& r, bvh_box_test boxes) {
        if (!finite_ray(r)) return false;
        bool hit = false;
        traverse(
            t, r, boxes, [&] { return r.t_max; },
            [&](std::size_t, double, double, double) {
                hit = true;
                return false;
            });
        return hit;
    }

    static std::vector<ray_surface_hit> all(const bvh& t, const ray& r) {
        std::vector<ray_surface_hit> out;
        if (!finite_ray(r)) return out;
        traverse(
            t, r, bvh_box_test::float32, [&] { return r.t_max; },
            [&](std::size_t i, double s, double u, double v) {
                out.push_back(make_hit(t, r, i, s, u, v));
                return true;
            });
        std::sort(out.begin(), out.end(), [](const ray_surface_hit& a, const ray_surface_hit& b) {
            return a.t < b.t || (a.t == b.t && (a.face < b.face || (a.face == b.face && a.vertices < b.vertices)));
        });
        out.erase(std::unique(out.begin(), out.end(),
                              [](const ray_surface_hit& a, const ray_surface_hit& b) {
                                  return a.t == b.t && a.face == b.face;
                              }),
                  out.end());
        return out;
    }

    /// Runs query(i) for every i < n into out[i], in parallel; first refuses a non-finite
    /// query when asked to.
    template <class Out, class Finite, class Query>
    static result<std::vector<Out>> batch(std::size_t n, unsigned threads, bvh_nan_policy nan, const char* who,
                                          const Finite& is_finite, const Query& query) {
        if (nan == bvh_nan_policy::refuse)
            for (std::size_t i = 0; i < n; ++i)
                if (!is_finite(i))
                    return fail(errc::invalid_argument,
                                std::string(who) + ": query " + std::to_string(i) + " is not finite", (long long)i);
        std::vector<Out> out(n);
        detail::with_thread_count(threads, [&] {
            detail::parallel_chunks(n, 512, [&](std::size_t lo, std::size_t hi) {
                for (std::size_t i = lo; i < hi; ++i) out[i] = query(i);
            });
        });
        return out;
    }
};

}  // namespace detail

inline result<bvh> bvh::from_triangles(std::span<const vec3<double>> points,
                                       std::span<const std::array<std::uint32_t, 3>> triangles,
                                       std::span<const std::size_t> faces, const bvh_options& options) {
    return detail::bvh_access::build(points, triangles, faces, options);
}

inline closest_surface_point bvh::closest_point(const vec3<double>& p, const closest_point_options& options) const {
    return detail::bvh_access::closest(*this, p, options.max_distance);
}

inline ray_surface_hit bvh::first_hit(const ray& r) const {
    return detail::bvh_access::first(*this, r, bvh_box_test::float32);
}

inline bool bvh::any_hit(const ray& r) const { return detail::bvh_access::any(*this, r, bvh_box_test::float32); }

inline std::vector<ray_surface_hit> bvh::all_hits(const ray& r) const { return detail::bvh_access::all(*this, r); }

inline result<std::vector<closest_surface_point>> bvh::closest_points(std::span<const vec3<double>> points,
                                                                      const closest_point_options& options) const {
    return detail::bvh_access::batch<closest_surface_point>(
        points.size(), options.threads, options.nan, "closest_points",
        [&](std::size_t i) { return detail::bvh_build::finite(points[i]); },
        [&](std::size_t i) { return detail::bvh_access::closest(*this, points[i], options.max_distance); });
}

inline result<std::vector<ray_surface_hit>> bvh::first_hits(std::span<const ray> rays,
                                                            const ray_query_options& options) const {
    return detail::bvh_access::batch<ray_surface_hit>(
        rays.size(), options.threads, options.nan, "first_hits",
        [&](std::size_t i) { return detail::bvh_access::finite_ray(rays[i]); },
        [&](std::size_t i) { return detail::bvh_access::first(*this, rays[i], options.boxes); });
}

inline result<std::vector<std::uint8_t>> bvh::any_hits(std::span<const ray> rays,
                                                       const ray_query_options& options) const {
    return detail::bvh_access::batch<std::uint8_t>(
        rays.size(), options.threads, options.nan, "any_hits",
        [&](std::size_t i) { return detail::bvh_access::finite_ray(rays[i]); },
        [&](std::size_t i) { return std::uint8_t(detail::bvh_access::any(*this, rays[i], options.boxes)); });
}

inline result<void> bvh::refit(std::span<const vec3<double>> points) {
    return detail::bvh_access::refit(*this, points);
}

namespace detail::bvh_build {

/// The counts a tree records of its mesh.
template <class M, class T>
bvh::source source_of(const M& mesh) {
    bvh::source s;
    s.vertices = T::vertex_count(mesh);
    s.faces = T::face_count(mesh);
    s.vertex_bound = T::vertex_index_bound(mesh);
    if constexpr (change_counted_mesh<M, T>) {
        s.change_count = static_cast<std::uint64_t>(T::change_count(mesh));
        s.counted = true;
    }
    return s;
}

/// Refuses a mesh whose counts differ from those the tree was built from.
template <class M, class T>
result<void> check_fresh(const M& mesh, const bvh& tree, const char* who) {
    const bvh::source now = source_of<M, T>(mesh), then = tree.built_from();
    if (now == then) return {};
    const auto counts = [](const bvh::source& s) {
        std::string c = std::to_string(s.vertices) + " vertices, " + std::to_string(s.faces) + " faces, index bound " +
                        std::to_string(s.vertex_bound);
        if (s.counted) c += ", change count " + std::to_string(s.change_count);
        return c;
    };
    return fail(errc::invalid_argument, std::string(who) + ": the mesh changed since its bvh was built (now " +
                                            counts(now) + "; built on " + counts(then) + "): rebuild the tree");
}

/// The positions by vertex index (zero at unused indices); refuses a non-finite one.
template <class M, class T>
result<std::vector<vec3<double>>> positions(const M& mesh, const char* who) {
    std::vector<vec3<double>> points(T::vertex_index_bound(mesh));
    for (auto v : T::vertices(mesh)) {
        const vec3<typename T::scalar> p = T::position(mesh, v);
        const vec3<double> q{double(p.x), double(p.y), double(p.z)};
        const auto i = T::vertex_index(mesh, v);
        if (!finite(q))
            return fail(errc::invalid_argument,
                        std::string(who) + ": vertex " + std::to_string(i) + " has a non-finite position",
                        (long long)i);
        points[i] = q;
    }
    return points;
}

}  // namespace detail::bvh_build

template <class M, class T>
    requires bvh_source_mesh<M, T>
result<bvh> build_bvh(const M& mesh, const bvh_options& options) {
    namespace bb = detail::bvh_build;
    if (T::vertex_index_bound(mesh) > std::numeric_limits<std::uint32_t>::max())
        return fail(errc::unsupported, "build_bvh: more than 2^32 - 1 vertices");
    auto points = bb::positions<M, T>(mesh, "build_bvh");
    if (!points) return points.error();
    std::vector<std::array<std::uint32_t, 3>> triangles;
    std::vector<std::size_t> faces;
    triangles.reserve(T::face_count(mesh));
    faces.reserve(T::face_count(mesh));
    std::vector<std::uint32_t> loop;
    const auto index = [&](typename T::vertex_handle v) {
        return static_cast<std::uint32_t>(T::vertex_index(mesh, v));
    };
    for (auto f : T::faces(mesh)) {
        loop.clear();
        for (auto v : T::face_vertices(mesh, f)) loop.push_back(index(v));
        const std::size_t fi = T::face_index(mesh, f);
        if (loop.size() == 3 && !detail::euler::has_rings<M, T>(mesh, f)) {
            triangles.push_back({loop[0], loop[1], loop[2]});
            faces.push_back(fi);
            continue;
        }
        auto cut = face_triangles<M, T>(mesh, f);
        if (cut) {
            for (const auto& t : *cut)
                triangles.push_back({index(t[0]), index(t[1]), index(t[2])}), faces.push_back(fi);
        } else if (cut.error().code == errc::degenerate_face) {
            for (std::size_t i = 1; i + 1 < loop.size(); ++i)
                triangles.push_back({loop[0], loop[i], loop[i + 1]}), faces.push_back(fi);
        } else {
            return fail(cut.error().code, "build_bvh: " + cut.error().message, cut.error().element);
        }
    }
    auto tree = bvh::from_triangles(*points, triangles, faces, options);
    if (!tree) return tree.error();
    tree->set_built_from(bb::source_of<M, T>(mesh));
    return tree;
}

template <class M, class T>
    requires bvh_source_mesh<M, T>
result<void> refit_bvh(const M& mesh, bvh& tree) {
    namespace bb = detail::bvh_build;
    if (auto fresh = bb::check_fresh<M, T>(mesh, tree, "refit_bvh"); !fresh) return fresh.error();
    auto points = bb::positions<M, T>(mesh, "refit_bvh");
    if (!points) return points.error();
    return tree.refit(*points);
}

template <class M, class T>
    requires bvh_source_mesh<M, T>
result<closest_surface_point> closest_point(const M& mesh, const bvh& tree, const vec3<double>& p,
                                            const closest_point_options& options) {
    if (auto fresh = detail::bvh_build::check_fresh<M, T>(mesh, tree, "closest_point"); !fresh) return fresh.error();
    return tree.closest_point(p, options);
}

template <class M, class T>
    requires bvh_source_mesh<M, T>
result<std::vector<closest_surface_point>> closest_points(const M& mesh, const bvh& tree,
                                                          std::span<const vec3<double>> points,
                                                          const closest_point_options& options) {
    if (auto fresh = detail::bvh_build::check_fresh<M, T>(mesh, tree, "closest_points"); !fresh) return fresh.error();
    return tree.closest_points(points, options);
}

template <class M, class T>
    requires bvh_source_mesh<M, T>
result<ray_surface_hit> ray_first_hit(const M& mesh, const bvh& tree, const ray& r) {
    if (auto fresh = detail::bvh_build::check_fresh<M, T>(mesh, tree, "ray_first_hit"); !fresh) return fresh.error();
    return tree.first_hit(r);
}

template <class M, class T>
    requires bvh_source_mesh<M, T>
result<std::vector<ray_surface_hit>> ray_first_hits(const M& mesh, const bvh& tree, std::span<const ray> rays,
                                                    const ray_query_options& options) {
    if (auto fresh = detail::bvh_build::check_fresh<M, T>(mesh, tree, "ray_first_hits"); !fresh) return fresh.error();
    return tree.first_hits(rays, options);
}

template <class M, class T>
    requires bvh_source_mesh<M, T>
result<bool> ray_any_hit(const M& mesh, const bvh& tree, const ray& r) {
    if (auto fresh = detail::bvh_build::check_fresh<M, T>(mesh, tree, "ray_any_hit"); !fresh) return fresh.error();
    return tree.any_hit(r);
}

template <class M, class T>
    requires bvh_source_mesh<M, T>
result<std::vector<std::uint8_t>> ray_any_hits(const M& mesh, const bvh& tree, std::span<const ray> rays,
                                               const ray_query_options& options) {
    if (auto fresh = detail::bvh_build::check_fresh<M, T>(mesh, tree, "ray_any_hits"); !fresh) return fresh.error();
    return tree.any_hits(rays, options);
}

template <class M, class T>
    requires bvh_source_mesh<M, T>
result<std::vector<ray_surface_hit>> ray_all_hits(const M& mesh, const bvh& tree, const ray& r) {
    if (auto fresh = detail::bvh_build::check_fresh<M, T>(mesh, tree, "ray_all_hits"); !fresh) return fresh.error();
    return tree.all_hits(r);
}

}  // namespace hmira
