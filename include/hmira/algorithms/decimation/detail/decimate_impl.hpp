// hmira/algorithms/decimation/detail/decimate_impl.hpp
// The machinery of decimate (decimate.hpp holds the interface): the decimator, which keeps the
// quadrics, the flags and the queue and makes the collapses, and the definition of decimate,
// which checks the options, triangulates polygon input and runs the decimator.
//
// Cache: the collapses come in cost order, scattered over the mesh, so nearly every one misses the
// caches once the working set (about 100 bytes per input face on halfedge_mesh, mesh included)
// outgrows the last-level cache; the time per face then rises while the work per face (the queue's
// log E) stays flat. bench/sweep measures it. Hence the steps of a collapse request the lines
// they are about to read (the rings' positions, the neighbours' quadrics and places in the
// queue, the queue's next level) so that the misses overlap, and the large arrays ask for
// huge pages so that random reads do not also miss the TLB; neither changes a result.
#pragma once

#include <algorithm>
#include <utility>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "../../../core/huge_pages.hpp"
#include "../../../core/progress.hpp"
#include "../../../core/rollback.hpp"
#include "../../triangle/collapse_edge.hpp"
#include "../../triangulation/triangulate_faces.hpp"
#include "../decimate.hpp"
#include "indexed_heap.hpp"
#include "quadric.hpp"

namespace hmira {

namespace detail::decimation {

/// One collapse as the queue sees it: the halfedge whose source goes, and where its target
/// goes. An edge that may not collapse at all (constraints) has no candidate.
template <class H>
struct candidate {
    H halfedge;
    vec3<double> position;
    double cost;
};

template <class M, class T>
class decimator {
public:
    using V = typename T::vertex_handle;
    using H = typename T::halfedge_handle;
    using E = typename T::edge_handle;

    decimator(M& mesh, const decimate_options& options) : m_(mesh), o_(options), heap_(T::edge_index_bound(mesh)) {}

    /// Counts per vertex, quadrics, flags, the queue. O(V + E + F log E).
    void start(std::size_t faces) {
        faces_ = faces;
        const std::size_t vb = T::vertex_index_bound(m_), eb = T::edge_index_bound(m_);
        // The collapses read these arrays at random places: huge pages keep the address
        // translations of a large mesh in the TLB.
        filled(quadrics_, vb, quadric{});
        fixed_.assign(vb, 0);
        filled(edges_, eb, E{});
        refused_.assign(eb, 0);
        filled(mark_, vb, 0u);
        cos_limit_ = std::cos(o_.max_normal_angle * std::numbers::pi / 180);
        const double sin_min = std::sin(o_.min_angle * std::numbers::pi / 180);
        sin_min_sq_ = sin_min * sin_min;
        for (std::size_t i : o_.locked_vertices) fixed_[i] |= locked;
        // The weight of a face's plane: its area over the mean area (or 1), so that the errors
        // stay squared distances on the scale of the model.
        double mean_area = 0;
        if (seeded()) {
            // A run that goes on: its quadrics, the planes already summed in them.
            for (auto v : T::vertices(m_)) {
                const double* x = o_.start_quadrics.data() + 10 * index(v);
                quadrics_[index(v)] = {x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7], x[8], x[9]};
            }
        } else if (o_.area_weighted) {
            for (auto f : T::faces(m_)) mean_area += norm(twice_area_vector(T::face_halfedge(m_, f)));
            mean_area = faces > 0 ? mean_area / double(faces) : 0;
        }
        const auto weight = [&](double twice_area) { return mean_area > 0 ? twice_area / mean_area : 1.0; };
        for (auto f : T::faces(m_)) {
            if (seeded()) break;  // the starting quadrics hold these planes
            const H h = T::face_halfedge(m_, f);
            const V a = T::target(m_, h), b = T::target(m_, T::next(m_, h)), c = T::target(m_, T::prev(m_, h));
            const auto pa = position(a);
            const auto n = cross(position(b) - pa, position(c) - pa);
            const double len = norm(n);
            if (!(len > 0)) continue;  // a degenerate face pins no plane
            const quadric q = quadric::of_plane(n * (1 / len), pa, weight(len));
            quadrics_[index(a)] += q;
            quadrics_[index(b)] += q;
            quadrics_[index(c)] += q;
        }
        mark_features();
        for (auto e : T::edges(m_)) {
            const H h = T::edge_halfedge(m_, e), o = T::opposite(m_, h);
            const bool hb = T::face(m_, h) == T::null_face(), ob = T::face(m_, o) == T::null_face();
            if (!hb && !ob) {
                if (!feature_.empty() && feature_[T::edge_index(m_, e)])
                    for (const H side : {h, o}) add_edge_plane(side, weight);
                continue;
            }
            fixed_[index(T::target(m_, o))] |= boundary;
            fixed_[index(T::target(m_, h))] |= boundary;
            // A plane through the boundary edge, perpendicular to its face, keeps the
            // boundary from shrinking when boundary edges may collapse.
            if (!o_.keep_boundary && !(hb && ob)) add_edge_plane(hb ? o : h, weight);
        }
        if (o_.keep_features) {
            feature_count_.assign(vb, 0);
            for (auto v : T::vertices(m_)) count_features(v);
        }
        for (auto e : T::edges(m_)) {
            const std::size_t i = T::edge_index(m_, e);
            edges_[i] = e;
            if (const auto c = candidate_of(e)) heap_.append(std::uint32_t(i), c->cost);
        }
        heap_.heapify();
    }

    /// Collapses until a target is reached, the queue empties or the callback cancels
    /// (returns false then; the caller restores the mesh).
    bool run(std::size_t target_faces, progress_gate& gate, decimate_result& out) {
        constexpr std::size_t block = 1024;
        std::size_t since_report = 0;
        out.stopped_by = decimate_stop::constraints;
        const double max_cost = o_.max_error ? *o_.max_error * *o_.max_error : std::numeric_limits<double>::infinity();
        while (faces_ > target_faces) {
            if (heap_.empty()) break;
            if (heap_.top_cost() > max_cost) {
                out.stopped_by = decimate_stop::max_error;
                break;
            }
            const std::uint32_t key = heap_.top_key();
            heap_.erase(key);
            const auto c = candidate_of(edges_[key]);
            if (!c || !collapse(*c)) {
                refuse(key);
                continue;
            }
            out.error = std::max(out.error, c->cost);
            ++out.collapses;
            if (++since_report == block) {
                since_report = 0;
                if (!gate.advance()) return false;
            }
        }
        if (faces_ <= target_faces) out.stopped_by = decimate_stop::target_faces;
        out.error = std::sqrt(out.error);
        return true;
    }

    std::size_t faces() const noexcept { return faces_; }

    /// The quadrics of the remaining vertices, 10 numbers per vertex index (decimate_options::start_quadrics);
    /// zeros at indices without a vertex. O(V).
    std::vector<double> quadric_values() const {
        std::vector<double> out(10 * quadrics_.size(), 0.0);
        for (auto v : T::vertices(m_)) {
            const quadric& q = quadrics_[index(v)];
            const double x[10] = {q.xx, q.xy, q.xz, q.yy, q.yz, q.zz, q.bx, q.by, q.bz, q.c};
            std::copy(x, x + 10, out.begin() + std::ptrdiff_t(10 * index(v)));
        }
        return out;
    }

private:
    // refused_near: an edge at the vertex left the queue refused (refused_), to be retried when
    // a collapse next to the vertex changes its neighbourhood.
    static constexpr std::uint8_t locked = 1, boundary = 2, refused_near = 4;

    void refuse(std::uint32_t key) {
        refused_[key] = 1;
        const H h = T::edge_halfedge(m_, edges_[key]);
        fixed_[index(T::target(m_, h))] |= refused_near;
        fixed_[index(T::target(m_, T::opposite(m_, h)))] |= refused_near;
    }

    std::size_t index(V v) const { return T::vertex_index(m_, v); }

    /// The quadrics start from options.start_quadrics, which hold every plane already.
    bool seeded() const { return !o_.start_quadrics.empty(); }

    /// The cross product of the triangle of h's edges: twice its area, along its normal.
    vec3<double> twice_area_vector(H h) const {
        const auto p0 = position(T::target(m_, T::opposite(m_, h))), p1 = position(T::target(m_, h));
        return cross(p1 - p0, position(T::target(m_, T::next(m_, h))) - p0);
    }

    /// The plane through the edge of h perpendicular to h's triangle, weighted like that
    /// triangle, joins the quadrics of the edge's ends.
    template <class Weight>
    void add_edge_plane(H h, const Weight& weight) {
        if (seeded()) return;
        const V a = T::target(m_, T::opposite(m_, h)), b = T::target(m_, h);
        const auto face_n = twice_area_vector(h);
        const auto n = cross(face_n, position(b) - position(a));
        const double len = norm(n);
        if (!(len > 0)) return;
        const quadric q = quadric::of_plane(n * (1 / len), position(a), weight(norm(face_n)));
        quadrics_[index(a)] += q;
        quadrics_[index(b)] += q;
    }

    /// Feature edges by edge index, from the options' angle and list (none: feature_ stays empty).
    void mark_features() {
        if (!o_.feature_angle && o_.feature_edges.empty() && !o_.keep_features) return;
        feature_.assign(T::edge_index_bound(m_), 0);
        for (std::size_t i : o_.feature_edges) feature_[i] = 1;
        if (!o_.feature_angle) return;
        const double cos_limit = std::cos(*o_.feature_angle * std::numbers::pi / 180);
        for (auto e : T::edges(m_)) {
            const H h = T::edge_halfedge(m_, e), o = T::opposite(m_, h);
            if (T::face(m_, h) == T::null_face() || T::face(m_, o) == T::null_face()) continue;
            const auto n0 = twice_area_vector(h), n1 = twice_area_vector(o);
            const double len = std::sqrt(squared_norm(n0) * squared_norm(n1));
            if (len > 0 && dot(n0, n1) < cos_limit * len) feature_[T::edge_index(m_, e)] = 1;
        }
    }

    bool is_feature(E e) const { return !feature_.empty() && feature_[T::edge_index(m_, e)]; }

    /// The number of feature edges at v, up to 3 (keep_features).
    void count_features(V v) {
        std::uint8_t n = 0;
        const H s = T::vertex_halfedge(m_, v);
        if (s == T::null_halfedge()) return;
        H x = s;
        do {
            if (is_feature(T::edge(m_, x)) && n < 3) ++n;
            x = T::next(m_, T::opposite(m_, x));
        } while (x != s);
        feature_count_[index(v)] = n;
    }
    vec3<double> position(V v) const { return detail::triangle_ops::position_of<M, T>(m_, v); }
    bool pinned(V v) const {
        const std::uint8_t f = fixed_[index(v)];
        return (f & locked) || (o_.keep_boundary && (f & boundary));
    }

    /// The collapse this edge would make, or nothing when the constraints forbid it.
    std::optional<candidate<H>> candidate_of(E e) const {
        const H h = T::edge_halfedge(m_, e), o = T::opposite(m_, h);
        if (o_.keep_boundary && (T::face(m_, h) == T::null_face() || T::face(m_, o) == T::null_face()))
            return std::nullopt;
        const V a = T::target(m_, o), b = T::target(m_, h);
        bool pa = pinned(a), pb = pinned(b), on_line = false;
        if (o_.keep_features) {
            // Along a feature line only its inner vertices move; off it, a feature vertex stays.
            const std::uint8_t ca = feature_count_[index(a)], cb = feature_count_[index(b)];
            on_line = is_feature(e);
            pa = pa || (on_line ? ca != 2 : ca > 0);
            pb = pb || (on_line ? cb != 2 : cb > 0);
        }
        if (pa && pb) return std::nullopt;
        const quadric q = quadrics_[index(a)] + quadrics_[index(b)];
        // A pinned end survives where it is.
        if (pa) return candidate<H>{o, position(a), q(position(a))};
        if (pb) return candidate<H>{h, position(b), q(position(b))};
        if (on_line) {  // the survivor stays on the line: at the better end
            const double cb = q(position(b)), ca = q(position(a));
            return ca < cb ? candidate<H>{o, position(a), ca} : candidate<H>{h, position(b), cb};
        }
        if (const auto x = q.minimiser(); x && std::isfinite(x->x) && std::isfinite(x->y) && std::isfinite(x->z))
            return candidate<H>{h, *x, q(*x)};
        // No single best point: the best of the two ends and the midpoint.
        const vec3<double> ends[3] = {position(b), position(a), (position(a) + position(b)) * 0.5};
        std::size_t best = 0;
        double cost = q(ends[0]);
        for (std::size_t i = 1; i < 3; ++i)
            if (const double c = q(ends[i]); c < cost) cost = c, best = i;
        return candidate<H>{h, ends[best], cost};
    }

    /// Puts the edge in the queue at its current cost, or takes it out when it may not
    /// collapse.
    void update(E e, std::uint32_t key) {
        refused_[key] = 0;
        if (const auto c = candidate_of(e))
            heap_.set(key, c->cost);
        else
            heap_.erase(key);
    }

    /// The normal-angle and aspect-ratio limits on the faces that survive around the edge.
    bool geometry_ok(const candidate<H>& c) const {
        const H h = c.halfedge, o = T::opposite(m_, h);
        const V a = T::target(m_, o), b = T::target(m_, h);
        const auto f0 = T::face(m_, h), f1 = T::face(m_, o);
        const bool aspect = std::isfinite(o_.max_aspect_ratio);
        // A first walk over the two rings requests the neighbours' positions, so that their cache
        // misses overlap with the walk instead of each stalling the arithmetic below.
        if constexpr (std::is_lvalue_reference_v<decltype(T::position(m_, a))>) {
            for (const V v : {a, b}) {
                const H s = T::vertex_halfedge(m_, v);
                H x = s;
                do {
                    const V n = T::target(m_, x);
                    prefetch(&T::position(m_, n));
                    prefetch(&quadrics_[index(n)]);  // read by the updates after the collapse
                    x = T::next(m_, T::opposite(m_, x));
                } while (x != s);
            }
        }
        for (const V v : {a, b}) {
            const H s = T::vertex_halfedge(m_, v);
            H x = s;
            do {
                const auto g = T::face(m_, x);
                if (g != T::null_face() && g != f0 && g != f1) {
                    const V u = T::target(m_, x), w = T::target(m_, T::next(m_, x));
                    const auto pv = position(v), pu = position(u), pw = position(w);
                    const auto qu = (u == a || u == b) ? c.position : pu, qw = (w == a || w == b) ? c.position : pw;
                    const auto before = cross(pu - pv, pw - pv), after = cross(qu - c.position, qw - c.position);
                    const double lb = squared_norm(before), la = squared_norm(after);
                    if (!(la > 0)) return false;
                    const double d = dot(before, after);
                    // cos(angle) >= cos_limit, squared without a root; a zero-area face before
                    // has no normal to keep.
                    if (lb > 0 && (cos_limit_ >= 0 ? d < 0 || d * d < cos_limit_ * cos_limit_ * lb * la
                                                   : d < 0 && d * d > cos_limit_ * cos_limit_ * lb * la))
                        return false;
                    if (sin_min_sq_ > 0) {
                        const double after_sin = sin_min_angle_sq(c.position, qu, qw, la);
                        if (after_sin < sin_min_sq_ && after_sin < sin_min_angle_sq(pv, pu, pw, lb)) return false;
                    }
                    if (aspect) {
                        const double r_after = aspect_ratio(c.position, qu, qw, la);
                        if (r_after > o_.max_aspect_ratio && r_after > aspect_ratio(pv, pu, pw, lb)) return false;
                    }
                }
                x = T::next(m_, T::opposite(m_, x));
            } while (x != s);
        }
        return true;
    }

    /// The squared sine of the triangle's smallest angle (opposite its shortest side: twice the
    /// area over the two longer sides); `twice_area_sq` is the squared norm of the cross product.
    static double sin_min_angle_sq(const vec3<double>& p, const vec3<double>& q, const vec3<double>& r,
                                   double twice_area_sq) {
        double a = squared_norm(q - p), b = squared_norm(r - q), c = squared_norm(p - r);
        if (a > b) std::swap(a, b);
        if (b > c) std::swap(b, c);
        if (a > b) std::swap(a, b);
        const double d = b * c;
        return d > 0 ? twice_area_sq / d : 0;
    }

    /// Longest edge over the height onto it, 1 for an equilateral triangle; `twice_area_sq`
    /// is the squared norm of the cross product.
    static double aspect_ratio(const vec3<double>& p, const vec3<double>& q, const vec3<double>& r,
                               double twice_area_sq) {
        if (!(twice_area_sq > 0)) return std::numeric_limits<double>::infinity();
        const double l = std::max({squared_norm(q - p), squared_norm(r - q), squared_norm(p - r)});
        return l / std::sqrt(twice_area_sq) * (std::sqrt(3.0) / 2);
    }

    /// The topology rules of collapse_refusal for an edge with a triangle on each side in a
    /// mesh of triangles, in O(d): the ring of b is marked, then read from the ring of a. The
    /// rare edge whose ends both have three neighbours (it may belong to a tetrahedron) takes
    /// the general test.
    bool link_ok(H h) {
        const H o = T::opposite(m_, h), hn = T::next(m_, h), on = T::next(m_, o);
        const V a = T::target(m_, o), b = T::target(m_, h), c = T::target(m_, hn), d = T::target(m_, on);
        if (a == b || c == d) return false;
        const auto border = [&](H x) { return T::face(m_, T::opposite(m_, x)) == T::null_face(); };
        if ((border(hn) && border(T::prev(m_, h))) || (border(on) && border(T::prev(m_, o)))) return false;
        if (++mark_clock_ == 0) {  // the clock wrapped: clear the marks once
            std::fill(mark_.begin(), mark_.end(), 0u);
            mark_clock_ = 1;
        }
        std::size_t valence_b = 0, valence_a = 0;
        H s = T::vertex_halfedge(m_, b), x = s;
        do {
            mark_[index(T::target(m_, x))] = mark_clock_;
            ++valence_b;
            x = T::next(m_, T::opposite(m_, x));
        } while (x != s);
        bool a_on_boundary = false;
        s = T::vertex_halfedge(m_, a), x = s;
        do {
            if (T::face(m_, x) == T::null_face()) a_on_boundary = true;
            const V k = T::target(m_, x);
            if (x != h && k != c && k != d && mark_[index(k)] == mark_clock_) return false;
            ++valence_a;
            x = T::next(m_, T::opposite(m_, x));
        } while (x != s);
        if (a_on_boundary && T::face(m_, T::vertex_halfedge(m_, b)) == T::null_face()) return false;
        if (valence_a == 3 && valence_b == 3) return detail::triangle_ops::collapse_refusal<M, T>(m_, h, {})[0] == '\0';
        return true;
    }

    /// Makes the collapse if the geometry and the topology allow it; then the quadric of the
    /// survivor, the queue around it, and edges refused before near it. False: nothing changed.
    bool collapse(const candidate<H>& c) {
        namespace dt = detail::triangle_ops;
        if (!geometry_ok(c)) return false;
        const H h = c.halfedge, o = T::opposite(m_, h);
        const V a = T::target(m_, o), b = T::target(m_, h);
        const auto f0 = T::face(m_, h), f1 = T::face(m_, o);
        const std::uint32_t side0 = std::uint32_t(T::edge_index(m_, T::edge(m_, T::prev(m_, h))));
        const std::uint32_t side1 = std::uint32_t(T::edge_index(m_, T::edge(m_, T::next(m_, o))));
        // The side edges that stay take the place of those that go, feature flag included.
        const std::uint32_t kept0 = std::uint32_t(T::edge_index(m_, T::edge(m_, T::next(m_, h))));
        const std::uint32_t kept1 = std::uint32_t(T::edge_index(m_, T::edge(m_, T::prev(m_, o))));
        const V c0 = T::target(m_, T::next(m_, h)), c1 = T::target(m_, T::next(m_, o));
        // collapse_edge's steps without its error message, which a refusal would build for nothing:
        // the topology rules (the link condition), then the collapse itself.
        if (f0 != T::null_face() && f1 != T::null_face() ? !link_ok(h)
                                                         : dt::collapse_refusal<M, T>(m_, h, {})[0] != '\0')
            return false;
        auto links = dt::read_collapse_links<M, T>(m_, h);
        dt::apply_collapse<M, T>(m_, links, c.position);
        // The edges beside the edge went with their triangles.
        if (f0 != T::null_face()) heap_.erase(side0), --faces_;
        if (f1 != T::null_face()) heap_.erase(side1), --faces_;
        if (!feature_.empty()) {
            if (f0 != T::null_face()) feature_[kept0] |= feature_[side0];
            if (f1 != T::null_face()) feature_[kept1] |= feature_[side1];
        }
        if (o_.keep_features) {
            count_features(b);
            if (f0 != T::null_face()) count_features(c0);
            if (f1 != T::null_face()) count_features(c1);
        }
        quadrics_[index(b)] += quadrics_[index(a)];
        fixed_[index(b)] = std::uint8_t((fixed_[index(b)] | (fixed_[index(a)] & boundary)) & ~refused_near);
        // Every edge at the survivor has a new cost; an edge refused before at a neighbour may
        // pass now that the neighbourhood changed (only neighbours marked refused_near have one).
        const H s = T::vertex_halfedge(m_, b);
        H x = s;
        ring_.clear();
        do {
            ring_.push_back(x);
            x = T::next(m_, T::opposite(m_, x));
        } while (x != s);
        // The updates read, for each neighbour, its quadric and position and the edge's place in
        // the queue, scattered over memory: requested all at once, their cache misses overlap
        // instead of coming one after another.
        for (const H y : ring_) {
            const V n = T::target(m_, y);
            prefetch(&fixed_[index(n)]);
            prefetch(&quadrics_[index(n)]);
            prefetch(reinterpret_cast<const char*>(&quadrics_[index(n)]) + sizeof(quadric) - 1);
            if constexpr (std::is_lvalue_reference_v<decltype(T::position(m_, n))>) prefetch(&T::position(m_, n));
            heap_.prefetch_place(std::uint32_t(T::edge_index(m_, T::edge(m_, y))));
        }
        for (const H y : ring_) heap_.prefetch_entry(std::uint32_t(T::edge_index(m_, T::edge(m_, y))));
        for (const H y : ring_) {
            const E ey = T::edge(m_, y);
            update(ey, std::uint32_t(T::edge_index(m_, ey)));
        }
        do {
            const V n = T::target(m_, x);
            if (std::uint8_t& flags = fixed_[index(n)]; flags & refused_near) {
                flags = std::uint8_t(flags & ~refused_near);  // every refused edge at n is retried below
                const H t = T::vertex_halfedge(m_, n);
                H y = t;
                do {
                    const E ey = T::edge(m_, y);
                    const std::uint32_t k = std::uint32_t(T::edge_index(m_, ey));
                    if (refused_[k]) update(ey, k);
                    y = T::next(m_, T::opposite(m_, y));
                } while (y != t);
            }
            x = T::next(m_, T::opposite(m_, x));
        } while (x != s);
        return true;
    }

    template <class Vector, class Value>
    static void filled(Vector& v, std::size_t n, const Value& value) {
        hmira::detail::reserve_huge(v, n);
        v.assign(n, value);
    }

    static void prefetch([[maybe_unused]] const void* p) noexcept {
#if defined(__GNUC__) || defined(__clang__)
        __builtin_prefetch(p);
#endif
    }

    M& m_;
    const decimate_options& o_;
    std::vector<H> ring_;  // the survivor's outgoing halfedges (collapse)
    indexed_heap heap_;
    std::vector<quadric> quadrics_;            // by vertex index
    std::vector<std::uint8_t> fixed_;          // by vertex index: locked, boundary
    std::vector<E> edges_;                     // by edge index
    std::vector<std::uint8_t> refused_;        // by edge index: left the queue refused, retried nearby
    std::vector<std::uint8_t> feature_;        // by edge index (empty without features)
    std::vector<std::uint8_t> feature_count_;  // by vertex index: feature edges at it, up to 3 (keep_features)
    std::vector<std::uint32_t> mark_;          // by vertex index: == mark_clock_ for the link test's marked ring
    std::uint32_t mark_clock_ = 0;
    std::size_t faces_ = 0;
    double cos_limit_ = 0;
    double sin_min_sq_ = 0;
};

}  // namespace detail::decimation

template <class M, class T>
    requires decimatable_mesh<M, T>
result<decimate_result> decimate(M& mesh, const decimate_options& options) {
    namespace dt = detail::triangle_ops;
    const auto bad = [](const std::string& what) { return fail(errc::invalid_argument, "decimate: " + what); };
    if (!options.target_faces && !options.target_ratio && !options.max_error)
        return bad("set target_faces, target_ratio or max_error");
    if (options.target_ratio && !(*options.target_ratio >= 0 && *options.target_ratio <= 1))
        return bad("option target_ratio must be in [0, 1], got " + std::to_string(*options.target_ratio));
    if (options.max_error && !(*options.max_error >= 0 && std::isfinite(*options.max_error)))
        return bad("option max_error must be a finite distance >= 0, got " + std::to_string(*options.max_error));
    if (!(options.max_normal_angle >= 0 && options.max_normal_angle <= 180))
        return bad("option max_normal_angle must be in [0, 180] degrees, got " +
                   std::to_string(options.max_normal_angle));
    if (!(options.min_angle >= 0 && options.min_angle <= 60))
        return bad("option min_angle must be in [0, 60] degrees, got " + std::to_string(options.min_angle));
    if (!(options.max_aspect_ratio >= 1))
        return bad("option max_aspect_ratio must be at least 1, got " + std::to_string(options.max_aspect_ratio));
    if (options.feature_angle && !(*options.feature_angle >= 0 && *options.feature_angle <= 180))
        return bad("option feature_angle must be in [0, 180] degrees, got " + std::to_string(*options.feature_angle));
    if (!options.feature_edges.empty()) {
        std::vector<std::uint8_t> live(T::edge_index_bound(mesh), 0);
        for (auto e : T::edges(mesh)) live[T::edge_index(mesh, e)] = 1;
        for (std::size_t i : options.feature_edges)
            if (i >= live.size() || !live[i])
                return bad("option feature_edges names edge " + std::to_string(i) + ", which does not exist");
    }
    if (!options.start_quadrics.empty()) {
        const std::size_t need = 10 * T::vertex_index_bound(mesh);
        if (options.start_quadrics.size() != need)
            return bad("option start_quadrics needs 10 numbers per vertex index (" + std::to_string(need) + "), got " +
                       std::to_string(options.start_quadrics.size()));
        for (std::size_t i = 0; i < need; ++i)
            if (!std::isfinite(options.start_quadrics[i]))
                return bad("option start_quadrics has a non-finite number at vertex " + std::to_string(i / 10));
    }
    if (!options.locked_vertices.empty()) {
        std::vector<std::uint8_t> live(T::vertex_index_bound(mesh), 0);
        for (auto v : T::vertices(mesh)) live[T::vertex_index(mesh, v)] = 1;
        for (std::size_t i : options.locked_vertices)
            if (i >= live.size() || !live[i])
                return bad("option locked_vertices names vertex " + std::to_string(i) + ", which does not exist");
    }
    for (auto v : T::vertices(mesh))
        if (!dt::finite(dt::position_of<M, T>(mesh, v)))
            return fail(errc::invalid_argument,
                        "decimate: vertex " + std::to_string(T::vertex_index(mesh, v)) + " has a non-finite position",
                        (long long)T::vertex_index(mesh, v));

    decimate_result out;
    std::size_t faces = 0;
    bool triangles = true;
    for (auto f : T::faces(mesh)) {
        ++faces;
        if (triangles && !dt::in_triangle<M, T>(mesh, T::face_halfedge(mesh, f))) triangles = false;
    }
    // The copy a cancellation restores, taken before anything changes (triangulation included).
    // Without a callback nothing stops the collapses once they have begun (triangulate_faces
    // fails with the mesh unchanged), so there is nothing to copy.
    mesh_rollback<M> undo(mesh, bool(options.progress));
    if (!triangles) {
        if constexpr (triangulable_mesh<M, T>) {
            auto t = triangulate_faces<M, T>(mesh);
            if (!t) return t.error();
            faces = T::face_count(mesh);
            out.triangulated = true;
            out.note = "polygon faces were triangulated first; ";
        } else {
            return fail(errc::unsupported,
                        "decimate: the mesh has faces that are not triangles and the model cannot triangulate them");
        }
    }
    std::size_t target = 0;
    if (options.target_faces) target = *options.target_faces;
    if (options.target_ratio) target = std::max(target, std::size_t(std::ceil(*options.target_ratio * double(faces))));

    detail::decimation::decimator<M, T> d(mesh, options);
    d.start(faces);
    const std::size_t total = faces > target ? (faces - target) / 2048 : 0;
    detail::progress_gate gate(options.progress, total);
    if (!d.run(target, gate, out)) {
        undo.restore();
        return fail(errc::cancelled, "decimate: cancelled");
    }
    undo.commit();
    out.faces = d.faces();
    out.vertices = T::vertex_count(mesh);
    if (options.return_quadrics) out.quadrics = d.quadric_values();
    if (out.stopped_by == decimate_stop::constraints)
        out.note +=
            "stopped at " + std::to_string(out.faces) + " faces, above the target of " + std::to_string(target) +
            ": no remaining collapse satisfies the constraints (boundary, locked vertices, normal angle, aspect "
            "ratio) and the link condition";
    else if (out.stopped_by == decimate_stop::max_error && (options.target_faces || options.target_ratio))
        out.note += "stopped at " + std::to_string(out.faces) + " faces by max_error, before the face target";
    if (out.note.size() >= 2 && out.note.substr(out.note.size() - 2) == "; ") out.note.resize(out.note.size() - 2);
    return out;
}

}  // namespace hmira
