// hmira/algorithms/remeshing/detail/remesher.hpp
// The working parts of isotropic_remeshing: the per-element flags it keeps beside the mesh and
// the four passes of one iteration (split, collapse, flip, relax and project).
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <cstddef>
#include <vector>

#include "../../spatial/aabb_tree.hpp"
#include "../../triangle/collapse_edge.hpp"
#include "../../triangle/flip_edge.hpp"
#include "../../triangle/split_edge.hpp"

namespace hmira::detail::remeshing {

/// One remeshing run on one mesh. Feature edges (and boundary edges) are never collapsed or
/// flipped; their vertices ("locked") never move and are never removed, so a feature polyline
/// only gains vertices on its own segments.
template <class M, class T>
class remesher {
public:
    using V = typename T::vertex_handle;
    using H = typename T::halfedge_handle;
    using E = typename T::edge_handle;

    remesher(M& m, double target, const aabb_tree* surface) : m_(m), surface_(surface) {
        high2_ = (4.0 / 3.0 * target) * (4.0 / 3.0 * target);
        low2_ = (4.0 / 5.0 * target) * (4.0 / 5.0 * target);
    }

    /// Marks the edges with feature[edge index] (and the boundary) and locks their vertices.
    void set_features(const std::vector<char>& feature) {
        feature_ = feature;
        feature_.resize(T::edge_index_bound(m_), 0);
        locked_.assign(T::vertex_index_bound(m_), 0);
        for (auto e : T::edges(m_)) {
            const auto h = T::edge_halfedge(m_, e);
            auto& f = feature_[T::edge_index(m_, e)];
            if (T::face(m_, h) == T::null_face() || T::face(m_, T::opposite(m_, h)) == T::null_face()) f = 1;
            if (f) {
                ++initial_features;
                locked_[T::vertex_index(m_, T::target(m_, h))] = 1;
                locked_[T::vertex_index(m_, T::target(m_, T::opposite(m_, h)))] = 1;
            }
        }
        for (auto v : T::vertices(m_))
            if (T::vertex_halfedge(m_, v) == T::null_halfedge()) locked_[T::vertex_index(m_, v)] = 1;
    }

    /// What the passes did so far, and the feature edges (boundary included) at the start.
    std::size_t splits = 0, collapses = 0, flips = 0, initial_features = 0;

    /// Splits every edge longer than 4/3 target at its midpoint, until none is.
    void split_long_edges() {
        std::vector<H> work;
        work.reserve(T::edge_count(m_));
        for (auto e : T::edges(m_)) work.push_back(T::edge_halfedge(m_, e));
        // First in, first out: every edge of a round is looked at before the edges its splits
        // made. Last in, first out can chase a needle forever: the cuts of a thin triangle
        // stay long while the long edge that causes them waits at the bottom of the stack.
        for (std::size_t next = 0; next < work.size(); ++next) {
            const H h = work[next];
            if (!(squared_norm(pos(T::target(m_, h)) - pos(source(h))) > high2_)) continue;
            const bool on_feature = feature_[T::edge_index(m_, T::edge(m_, h))];
            auto r = split_edge<M, T>(m_, h);
            if (!r) continue;  // cannot happen on a triangle mesh; the edge then just stays long
            ++splits;
            grow();
            const V w = r->vertex;
            locked_[T::vertex_index(m_, w)] = on_feature;
            // Around w: the two halves keep the split edge's flag, the cuts are not features.
            const H s = T::vertex_halfedge(m_, w);
            H x = s;
            do {
                const auto e = T::edge(m_, x);
                feature_[T::edge_index(m_, e)] = on_feature && (e == T::edge(m_, h) || e == T::edge(m_, r->halfedge));
                work.push_back(x);
                x = T::next(m_, T::opposite(m_, x));
            } while (x != s);
        }
    }

    /// Collapses every edge shorter than 4/5 target whose collapse keeps every edge around it
    /// shorter than 4/3 target and turns no triangle over. A free end goes into a locked one;
    /// two free ends meet at the midpoint.
    void collapse_short_edges() {
        dead_.assign(T::edge_index_bound(m_), 0);
        std::vector<E> work;
        work.reserve(T::edge_count(m_));
        for (auto e : T::edges(m_)) work.push_back(e);
        while (!work.empty()) {
            const E e = work.back();
            work.pop_back();
            const auto ei = T::edge_index(m_, e);
            if (dead_[ei] || feature_[ei]) continue;
            const H h = T::edge_halfedge(m_, e);
            const V a = source(h), b = T::target(m_, h);
            const auto pa = pos(a), pb = pos(b);
            if (squared_norm(pb - pa) >= low2_) continue;
            const bool la = locked_[T::vertex_index(m_, a)], lb = locked_[T::vertex_index(m_, b)];
            if (la && lb) continue;
            // A locked end stays where it is; two free ends meet at the midpoint (Botsch-Kobbelt).
            const vec3<double> p = la ? pa : lb ? pb : (pa + pb) * 0.5;
            const H x = la ? T::opposite(m_, h) : h;  // x's source is removed
            if (!short_enough_after(source(x), T::target(m_, x), p)) continue;
            const collapse_edge_options options{
                .placement = collapse_placement::given, .position = p, .check_geometry = true};
            if (const char* refusal = triangle_ops::collapse_refusal<M, T>(m_, x, options); refusal[0] != '\0')
                continue;
            // The edges that go: x's own and, per triangle beside it, the one at the removed end.
            const H o = T::opposite(m_, x);
            dead_[ei] = 1;
            if (T::face(m_, x) != T::null_face()) dead_[T::edge_index(m_, T::edge(m_, T::prev(m_, x)))] = 1;
            if (T::face(m_, o) != T::null_face()) dead_[T::edge_index(m_, T::edge(m_, T::next(m_, o)))] = 1;
            auto r = collapse_edge<M, T>(m_, x, options);
            if (!r) continue;  // refused above already; kept for safety
            ++collapses;
            const V keep = r->vertex;
            const H s = T::vertex_halfedge(m_, keep);
            H y = s;
            do {
                work.push_back(T::edge(m_, y));
                y = T::next(m_, T::opposite(m_, y));
            } while (y != s);
        }
    }

    /// Flips interior non-feature edges where that brings the four vertices' valences closer
    /// to 6 (4 on the boundary) and turns no triangle over.
    /// An interior non-feature edge as the quad its flip would re-cut: halfedge h runs a -> b,
    /// c is opposite it in h's triangle and d in the other. Empty for feature and boundary edges.
    struct flip_quad {
        H h;
        V a, b, c, d;
    };
    std::optional<flip_quad> flip_candidate(E e) const {
        if (feature_[T::edge_index(m_, e)]) return std::nullopt;
        const H h = T::edge_halfedge(m_, e), o = T::opposite(m_, h);
        if (T::face(m_, h) == T::null_face() || T::face(m_, o) == T::null_face()) return std::nullopt;
        return flip_quad{h, T::target(m_, o), T::target(m_, h), T::target(m_, T::next(m_, h)),
                         T::target(m_, T::next(m_, o))};
    }

    void equalize_valences() {
        valence_.assign(T::vertex_index_bound(m_), 0);
        std::vector<char> boundary(T::vertex_index_bound(m_), 0);
        for (auto v : T::vertices(m_)) {
            const H s = T::vertex_halfedge(m_, v);
            if (s == T::null_halfedge()) continue;
            const auto i = T::vertex_index(m_, v);
            boundary[i] = T::face(m_, s) == T::null_face();
            H x = s;
            do {
                ++valence_[i];
                x = T::next(m_, T::opposite(m_, x));
            } while (x != s);
        }
        auto deviation = [&](std::size_t i, int change) {
            const int d = valence_[i] + change - (boundary[i] ? 4 : 6);
            return d < 0 ? -d : d;
        };
        std::vector<E> edges;
        edges.reserve(T::edge_count(m_));
        for (auto e : T::edges(m_)) edges.push_back(e);
        for (const E e : edges) {
            const auto q = flip_candidate(e);
            if (!q) continue;
            const auto [h, a, b, c, d] = *q;
            const auto ia = T::vertex_index(m_, a), ib = T::vertex_index(m_, b);
            const auto ic = T::vertex_index(m_, c), id = T::vertex_index(m_, d);
            const int before = deviation(ia, 0) + deviation(ib, 0) + deviation(ic, 0) + deviation(id, 0);
            const int after = deviation(ia, -1) + deviation(ib, -1) + deviation(ic, 1) + deviation(id, 1);
            if (after >= before) continue;
            if (!flip_keeps_orientation(pos(a), pos(b), pos(c), pos(d))) continue;
            if (!is_flip_ok<M, T>(m_, h)) continue;
            triangle_ops::flip_links<M, T>(m_, h);
            ++flips;
            --valence_[ia];
            --valence_[ib];
            ++valence_[ic];
            ++valence_[id];
        }
        improve_thin_triangles();
    }

    /// Flips interior non-feature edges beside a thin triangle that touches a locked vertex when
    /// that makes the smaller angle of the two triangles larger. Next to a feature line the
    /// locked vertices keep their spacing, so valence flips and relaxation alone leave thin
    /// triangles (and slivers between nearly collinear feature vertices) there; this local
    /// Delaunay step removes them. Far from locked vertices valence flips are left alone.
    void improve_thin_triangles() {
        // The candidates: per locked vertex, the edges from it and the edges facing it.
        std::vector<E> edges;
        for (auto v : T::vertices(m_)) {
            if (!locked_[T::vertex_index(m_, v)]) continue;
            const H s = T::vertex_halfedge(m_, v);
            if (s == T::null_halfedge()) continue;
            H x = s;
            do {
                edges.push_back(T::edge(m_, x));
                if (T::face(m_, x) != T::null_face()) edges.push_back(T::edge(m_, T::next(m_, x)));
                x = T::next(m_, T::opposite(m_, x));
            } while (x != s);
        }
        for (const E e : edges) {
            const auto q = flip_candidate(e);
            if (!q) continue;
            const auto [h, a, b, c, d] = *q;
            const auto pa = pos(a), pb = pos(b), pc = pos(c), pd = pos(d);
            const double before = std::max(largest_cosine(pa, pb, pc), largest_cosine(pb, pa, pd));
            if (before < thin_cosine) continue;
            const double after = std::max(largest_cosine(pc, pa, pd), largest_cosine(pd, pb, pc));
            if (!(after < before - 1e-3)) continue;
            // Only across a nearly flat pair: a flip over a crease would cut into the surface. A
            // cap (an angle over 160 degrees at c or d) is the exception: its normal says nothing,
            // and its apex lies near ab, so the flip moves the surface by little. On a feature
            // line (a, c, b locked in a row) the flip puts the edges back on the line.
            const bool cap = dot(normalized(pa - pc), normalized(pb - pc)) < cap_cosine ||
                             dot(normalized(pa - pd), normalized(pb - pd)) < cap_cosine;
            if (!cap && dot(normalized(cross(pb - pa, pc - pa)), normalized(cross(pa - pb, pd - pb))) < flat_cosine)
                continue;
            if (!flip_keeps_orientation(pa, pb, pc, pd)) continue;
            if (!is_flip_ok<M, T>(m_, h)) continue;
            triangle_ops::flip_links<M, T>(m_, h);
            ++flips;
        }
    }

    /// Moves every free vertex to the centroid of its neighbours within its tangent plane, then
    /// onto the input surface (all vertices read before any moves). Beside a locked vertex the
    /// centroid is that of the fan's triangles weighted by their areas: the plain centroid of
    /// the neighbours pulls such a vertex towards the feature line's uneven vertices and leaves
    /// thin triangles on it (fandisk: 1st-percentile minimum angle 33.4 -> 35.5 degrees).
    void relax_and_project() {
        const std::size_t n = T::vertex_index_bound(m_);
        std::vector<vec3<double>> moved(n);
        std::vector<char> moves(n, 0);
        for (auto v : T::vertices(m_)) {
            const auto i = T::vertex_index(m_, v);
            if (locked_[i]) continue;
            const H s = T::vertex_halfedge(m_, v);
            const vec3<double> p = pos(v);
            vec3<double> centroid{}, normal{};
            bool near_locked = false;
            int k = 0;
            H x = s;
            // The neighbour before target(s) in the fan: the third corner of s's triangle.
            vec3<double> prev = pos(T::target(m_, T::next(m_, s)));
            do {
                const vec3<double> q = pos(T::target(m_, x));
                // Face normal of (p, q, prev) summed with its area weight; the vertex is interior.
                normal += cross(q - p, prev - p);
                centroid += q;
                near_locked |= locked_[T::vertex_index(m_, T::target(m_, x))] != 0;
                prev = q;
                ++k;
                x = T::next(m_, T::opposite(m_, x));
            } while (x != s);
            centroid = centroid / double(k);
            if (near_locked) {
                // The fan's triangle centroids (p + q + prev) / 3, weighted by twice their areas.
                vec3<double> weighted{};
                double area = 0;
                prev = pos(T::target(m_, T::next(m_, s)));
                x = s;
                do {
                    const vec3<double> q = pos(T::target(m_, x));
                    const double twice_area = norm(cross(q - p, prev - p));
                    weighted += (p + q + prev) * (twice_area / 3);
                    area += twice_area;
                    prev = q;
                    x = T::next(m_, T::opposite(m_, x));
                } while (x != s);
                if (area > 0) centroid = weighted / area;
            }
            const vec3<double> nn = normalized(normal);
            vec3<double> d = centroid - p;
            d -= nn * dot(nn, d);
            vec3<double> q = p + d;
            if (surface_) {
                const auto c = surface_->closest_point(q);
                if (c.distance != INFINITY) q = c.point;
            }
            moved[i] = q;
            moves[i] = 1;
        }
        for (auto v : T::vertices(m_)) {
            const auto i = T::vertex_index(m_, v);
            if (moves[i]) triangle_ops::set_position<M, T>(m_, v, moved[i]);
        }
    }

private:
    static constexpr double thin_cosine = 0.8191520442889918;  // cos 35 degrees
    static constexpr double flat_cosine = 0.9396926207859084;  // cos 20 degrees
    static constexpr double cap_cosine = -0.9396926207859084;  // cos 160 degrees

    // The cosine of the smallest angle of triangle (a, b, c).
    static double largest_cosine(const vec3<double>& a, const vec3<double>& b, const vec3<double>& c) {
        const vec3<double> ab = normalized(b - a), bc = normalized(c - b), ca = normalized(a - c);
        return std::max({-dot(ab, ca), -dot(bc, ab), -dot(ca, bc)});
    }

    vec3<double> pos(V v) const { return triangle_ops::position_of<M, T>(m_, v); }
    V source(H h) const { return T::target(m_, T::opposite(m_, h)); }

    void grow() {
        if (locked_.size() < T::vertex_index_bound(m_)) locked_.resize(2 * T::vertex_index_bound(m_), 0);
        if (feature_.size() < T::edge_index_bound(m_)) feature_.resize(2 * T::edge_index_bound(m_), 0);
    }

    // Whether every neighbour of a and b (other than a and b) lies within 4/3 target of p.
    bool short_enough_after(V a, V b, const vec3<double>& p) const {
        for (const V v : {a, b}) {
            const H s = T::vertex_halfedge(m_, v);
            H x = s;
            do {
                const V u = T::target(m_, x);
                if (u != a && u != b && squared_norm(pos(u) - p) > high2_) return false;
                x = T::next(m_, T::opposite(m_, x));
            } while (x != s);
        }
        return true;
    }

    // Triangles (a, b, c) and (b, a, d) become (c, a, d) and (d, b, c): both must face the
    // way the pair did, and neither may be degenerate.
    static bool flip_keeps_orientation(const vec3<double>& a, const vec3<double>& b, const vec3<double>& c,
                                       const vec3<double>& d) {
        const vec3<double> before = cross(b - a, c - a) + cross(a - b, d - b);
        const vec3<double> n0 = cross(a - c, d - c), n1 = cross(b - d, c - d);
        return dot(n0, before) > 0 && dot(n1, before) > 0 && dot(n0, n1) > 0;
    }

    M& m_;
    const aabb_tree* surface_;
    double high2_ = 0, low2_ = 0;
    std::vector<char> feature_, locked_, dead_;
    std::vector<int> valence_;
};

}  // namespace hmira::detail::remeshing
