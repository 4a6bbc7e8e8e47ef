// hmira/algorithms/editing/bevel.hpp
// Edge bevel (thesis 2.2): replace edges by strips of faces (a flat chamfer, or a rounded
// profile of several segments), cutting back the faces on either side, as 3D editors do.
// Built from the Euler operators; bevel_vertices is the vertex-only mode (= truncate).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <ranges>
#include <string>
#include <utility>
#include <vector>

#include "detail/editing_common.hpp"
#include "truncate.hpp"

namespace hmira {

/// A mesh bevel() can edit: see editable_mesh (Euler operators, positions, indices).
template <class M, class T = default_traits<M>>
concept bevelable_mesh = editable_mesh<M, T>;

/// How wide and how round the bevel is.
struct bevel_options {
    /// Distance, inside each face next to a bevelled edge, from the old edge to the new one
    /// (the "offset" of 3D editors). Finite, > 0.
    double width = 0.1;
    /// Faces across each strip: 1 is a flat chamfer (one quad per edge); more follow a circular
    /// arc tangent to both neighbouring faces. In [1, 64].
    int segments = 1;
    /// Shrink the width (uniformly, for the whole call) so that no new vertex passes an
    /// existing one or one placed from the edge's other end: new vertices reach at most half
    /// way along any edge (at exactly half, points from both ends coincide, as when all four
    /// edges of a square face are bevelled to its centre). Off: the width is used as given.
    bool clamp_overlap = true;
};

/// What a bevel created.
template <class M, class T = default_traits<M>>
struct bevel_result {
    /// The strip faces, `segments` per bevelled edge, edge by edge in input order.
    std::vector<typename T::face_handle> strip_faces;
    /// The patches closing vertices where three or more bevelled edges meet (a triangle at a
    /// cube corner), and vertex-only mode's faces.
    std::vector<typename T::face_handle> vertex_faces;
    std::vector<typename T::vertex_handle> vertices;  ///< every new vertex
    double width = 0;                                 ///< the width used (after clamping)
};

namespace detail::editing {

/// Point t in [0, 1] of the circular arc from a to b tangent to a-c and c-b (a rational
/// quadratic Bezier with control point c; exact circle when |a - c| = |b - c|).
inline vec3<double> arc_point(const vec3<double>& a, const vec3<double>& c, const vec3<double>& b, double t) {
    const double cosb = dot(normalized(a - c), normalized(b - c));
    const double beta = std::acos(std::clamp(cosb, -1.0, 1.0));
    const double w = std::sin(beta / 2);
    const double b0 = (1 - t) * (1 - t), b1 = 2 * t * (1 - t) * w, b2 = t * t;
    return (a * b0 + c * b1 + b * b2) / (b0 + b1 + b2);
}

}  // namespace detail::editing

/// Bevels the edges in `edges` (a range of edge handles; duplicates count once).
///
/// What happens, edge by edge and vertex by vertex (the behaviour of 3D editors' bevel with
/// the "offset" width):
/// - Each bevelled edge is replaced by a strip: `segments` quads whose long sides lie at
///   `width` from the old edge inside the two faces next to it; those faces shrink.
/// - At an end vertex, every face corner next to a bevelled edge gets a new vertex: on the
///   corner's other edge when that one is not bevelled (slid along it so that its offset from
///   the bevelled edge is `width`; an edge slid from two corners takes the mean), or inside the
///   face at `width` from both edges when both are bevelled.
/// - If every edge of the vertex is bevelled or next to a bevelled edge around it, the vertex
///   goes: its new vertices are joined into one face (a triangle at a cube corner with three
///   bevelled edges), or, with only two of them (a corner of degree 3 with one bevelled edge,
///   as on a cube), into one edge that the remaining face gains, exactly the chamfer of a cube
///   edge. At the boundary, that face or edge closes the corner with one boundary edge.
/// - Otherwise (the vertex also has edges away from the bevel, e.g. a degree-4 vertex of a
///   grid with one bevelled edge) the vertex stays where it is, with those edges, and the
///   strip ends in it: the strip face then has the vertex as a pointed end.
/// V/E/F: a cube edge with segments = 1 gives V + 2, E + 3, F + 1 (8/12/6 -> 10/15/7).
///
/// segments > 1 needs every end vertex to be removed with a single bevelled edge (degree 3,
/// as on a cube edge); rounded patches where bevels meet are not built (errc::unsupported).
///
/// Complexity O(sum of the end vertices' degrees and the touched faces' degrees) per edge =
/// O(V_adjacentV), plus O(k log k) for k edges. Errors (mesh unchanged): errc::invalid_argument
/// for options out of range or an empty selection; errc::invalid_handle for a missing edge;
/// errc::unsupported for a boundary edge, a degenerate corner (collinear edges) or segments > 1
/// where not supported; errc::topology / errc::non_manifold for end vertices truncate() would
/// reject.
template <class M, class T = default_traits<M>, class R>
    requires bevelable_mesh<M, T> && range_of_handles<R, typename T::edge_handle>
result<bevel_result<M, T>> bevel(M& mesh, const R& edges, const bevel_options& options = {}) {
    namespace de = detail::editing;
    namespace du = detail::euler;
    using H = typename T::halfedge_handle;
    using V = typename T::vertex_handle;
    if (!(options.width > 0) || !de::finite(options.width))
        return fail(errc::invalid_argument, "bevel: width must be finite and > 0");
    if (options.segments < 1 || options.segments > 64)
        return fail(errc::invalid_argument, "bevel: segments must lie in [1, 64], got " + std::to_string(options.segments));
    // Selection.
    std::vector<H> sel;
    de::index_set bevelled;
    for (auto e0 : edges) {
        const typename T::edge_handle e = e0;
        if (T::edge_index(mesh, e) >= T::edge_index_bound(mesh))
            return fail(errc::invalid_handle, "bevel: edge " + std::to_string(T::edge_index(mesh, e)) + " does not exist",
                        static_cast<long long>(T::edge_index(mesh, e)));
        const auto h = T::edge_halfedge(mesh, e);
        if (T::face(mesh, h) == T::null_face() || T::face(mesh, T::opposite(mesh, h)) == T::null_face())
            return fail(errc::unsupported, "bevel: edge " + std::to_string(T::edge_index(mesh, e)) +
                                               " is on the boundary; only edges between two faces are bevelled",
                        static_cast<long long>(T::edge_index(mesh, e)));
        if (bevelled.insert(T::edge_index(mesh, e))) sel.push_back(h);
    }
    if (sel.empty()) return fail(errc::invalid_argument, "bevel: no edge selected");
    auto is_bev = [&](H h) { return bevelled.contains(T::edge_index(mesh, T::edge(mesh, h))); };
    std::vector<V> touched;
    de::index_set touched_set;
    for (auto h : sel)
        for (auto v : {du::source<M, T>(mesh, h), T::target(mesh, h)}) {
            if (auto ok = de::check_corner_vertex<M, T>(mesh, v, "bevel"); !ok) return ok.error();
            if (touched_set.insert(T::vertex_index(mesh, v))) touched.push_back(v);
        }

    // Plan, from the original geometry: slides on unbevelled edges, points inside corners
    // between two bevelled edges, which vertices go. Distances scale with the width.
    struct slide { H h; double sum = 0; int n = 0; };
    struct inner { H corner; V v; vec3<double> dir; };  // point = pos(v) + dir * width
    std::vector<slide> slides;
    std::vector<inner> inners;
    std::vector<bool> removed(touched.size(), true);
    std::vector<int> bevel_count(touched.size(), 0);
    double limit_ratio = 1e300;  // max width / requested width allowed by clamp_overlap
    auto add_slide = [&](H h, double per_width) {
        for (auto& s : slides)
            if (s.h == h) { s.sum += per_width; ++s.n; return; }
        slides.push_back({h, per_width, 1});
    };
    for (std::size_t k = 0; k < touched.size(); ++k) {
        const auto v = touched[k];
        const auto pv = de::pos<M, T>(mesh, v);
        const auto hs = de::outgoing<M, T>(mesh, v);
        const std::size_t d = hs.size();
        std::vector<bool> near(d, false);
        for (std::size_t i = 0; i < d; ++i) {
            const auto a = hs[i], b = hs[(i + 1) % d];
            if (is_bev(a)) ++bevel_count[k];
            if (T::face(mesh, b) == T::null_face()) continue;  // the boundary gap is no corner
            const bool ba = is_bev(a), bb = is_bev(b);
            if (!ba && !bb) continue;
            near[i] = near[(i + 1) % d] = true;
            const auto ua = normalized(de::pos<M, T>(mesh, T::target(mesh, a)) - pv);
            const auto ub = normalized(de::pos<M, T>(mesh, T::target(mesh, b)) - pv);
            const double s = norm(cross(ua, ub));
            if (!(s > 1e-9))
                return fail(errc::unsupported, "bevel: the edges of a face corner at " + du::name<M, T>("vertex", mesh, v) +
                                                   " are collinear; the offset there is undefined",
                            du::index_of<M, T>(mesh, v));
            if (ba && bb) inners.push_back({T::opposite(mesh, a), v, (ua + ub) / s});
            else add_slide(ba ? b : a, 1.0 / s);
        }
        for (std::size_t i = 0; i < d; ++i)
            if (!near[i]) removed[k] = false;
    }
    // Clamp: new vertices reach at most half way along any edge (a slid vertex at the far end
    // would collapse the face beside the strip).
    for (const auto& s : slides) {
        const double len = norm(de::pos<M, T>(mesh, T::target(mesh, s.h)) - de::pos<M, T>(mesh, du::source<M, T>(mesh, s.h)));
        limit_ratio = std::min(limit_ratio, len / 2 / (s.sum / s.n));
    }
    for (const auto& in : inners) {
        // The inner point projects onto both bevelled edges at |dir|-scaled distances.
        const auto a = T::opposite(mesh, in.corner);
        const auto b = T::next(mesh, in.corner);
        for (auto h : {a, b}) {
            const auto e = de::pos<M, T>(mesh, T::target(mesh, h)) - de::pos<M, T>(mesh, in.v);
            const double along = dot(in.dir, normalized(e));
            if (along > 0) limit_ratio = std::min(limit_ratio, norm(e) / 2 / along);
        }
    }
    const double width = options.clamp_overlap ? std::min(options.width, limit_ratio) : options.width;
    if (options.segments > 1)
        for (std::size_t k = 0; k < touched.size(); ++k)
            if (!removed[k] || bevel_count[k] != 1)
                return fail(errc::unsupported,
                            "bevel: segments > 1 needs each end vertex to have one bevelled edge and no edges away from the bevel "
                            "(degree 3, as on a cube edge); " + du::name<M, T>("vertex", mesh, touched[k]) + " has not",
                            du::index_of<M, T>(mesh, touched[k]));

    // ---- change the mesh (nothing below fails) ----
    bevel_result<M, T> out;
    out.width = width;
    // The ends' positions are the rounded profiles' control points (the ends may be gone and
    // their handles reused by the time the profiles are built).
    std::vector<std::pair<vec3<double>, vec3<double>>> ends(sel.size());
    for (std::size_t i = 0; i < sel.size(); ++i)
        ends[i] = {de::pos<M, T>(mesh, du::source<M, T>(mesh, sel[i])), de::pos<M, T>(mesh, T::target(mesh, sel[i]))};
    // 1. Split the slid edges (once where slides from both ends meet exactly).
    std::vector<bool> done(slides.size(), false);
    for (std::size_t i = 0; i < slides.size(); ++i) {
        if (done[i]) continue;
        done[i] = true;
        const auto h = slides[i].h;
        const auto a = de::pos<M, T>(mesh, du::source<M, T>(mesh, h)), b = de::pos<M, T>(mesh, T::target(mesh, h));
        const double len = norm(b - a);
        const double t = width * slides[i].sum / slides[i].n / len;
        double t_back = -1;
        for (std::size_t j = i + 1; j < slides.size(); ++j)
            if (slides[j].h == T::opposite(mesh, h)) {
                done[j] = true;
                t_back = width * slides[j].sum / slides[j].n / len;
            }
        if (t_back >= 0 && t + t_back == 1.0) {
            out.vertices.push_back(de::split_edge<M, T>(mesh, h, lerp(a, b, t)).vertex);
            continue;
        }
        const auto s = de::split_edge<M, T>(mesh, h, lerp(a, b, t));
        out.vertices.push_back(s.vertex);
        if (t_back >= 0) out.vertices.push_back(de::split_edge<M, T>(mesh, s.second, lerp(a, b, 1 - t_back)).vertex);
    }
    // 2. Points inside corners between two bevelled edges, hung from the vertex by makeEV.
    for (const auto& in : inners)
        out.vertices.push_back(make_edge_vertex<M, T>(mesh, in.corner, de::to_point<M, T>(de::pos<M, T>(mesh, in.v) + in.dir * width))->vertex);
    // 3. Each bevelled edge: cut the quad (p, v, w, q) off each side, then join the two quads.
    std::vector<H> strip_side(sel.size());  // a halfedge of each strip, on its F_L long side
    for (std::size_t i = 0; i < sel.size(); ++i) {
        const auto h = sel[i], o = T::opposite(mesh, h);
        const auto left = make_edge_face<M, T>(mesh, T::prev(mesh, T::prev(mesh, h)), T::next(mesh, h));
        (void)make_edge_face<M, T>(mesh, T::prev(mesh, T::prev(mesh, o)), T::next(mesh, o));
        strip_side[i] = T::opposite(mesh, left->halfedge);  // q -> p, inside the strip
        (void)kill_edge_face<M, T>(mesh, h);
    }
    // 4. Vertices with nothing left but new neighbours go.
    for (std::size_t k = 0; k < touched.size(); ++k)
        if (removed[k]) {
            const auto f = de::replace_vertex_by_polygon<M, T>(mesh, touched[k]);
            if (f != T::null_face()) out.vertex_faces.push_back(f);
        }
    // 5. Rounded profile: split both end edges along arcs and cut the strip across.
    for (std::size_t i = 0; i < sel.size(); ++i) {
        const auto qp = strip_side[i];
        out.strip_faces.push_back(T::face(mesh, qp));
        if (options.segments == 1) continue;
        const auto n = static_cast<std::size_t>(options.segments);
        const auto v_end = T::next(mesh, qp);                    // p -> p'
        const auto w_end = T::prev(mesh, qp);                    // q' -> q
        const auto p = T::target(mesh, qp), pp = T::target(mesh, v_end);
        const auto q = T::target(mesh, w_end), qq = du::source<M, T>(mesh, w_end);
        const auto [cv, cw] = ends[i];
        std::vector<H> into_p(n), into_q(n);
        auto x = v_end;
        const auto P0 = de::pos<M, T>(mesh, p), P1 = de::pos<M, T>(mesh, pp);
        const auto Q0 = de::pos<M, T>(mesh, q), Q1 = de::pos<M, T>(mesh, qq);
        for (std::size_t j = 1; j < n; ++j) {
            const auto s = de::split_edge<M, T>(mesh, x, de::arc_point(P0, cv, P1, double(j) / double(n)));
            out.vertices.push_back(s.vertex);
            into_p[j] = s.first;
            x = s.second;
        }
        x = w_end;
        for (std::size_t j = n - 1; j >= 1; --j) {
            const auto s = de::split_edge<M, T>(mesh, x, de::arc_point(Q0, cw, Q1, double(j) / double(n)));
            out.vertices.push_back(s.vertex);
            into_q[j] = s.first;
            x = s.second;
        }
        for (std::size_t j = 1; j < n; ++j)
            out.strip_faces.push_back(make_edge_face<M, T>(mesh, into_p[j], into_q[j])->face);
    }
    return out;
}

/// Bevels one edge (see the range overload). A cube edge with segments = 1 gives the chamfer:
/// V + 2, E + 3, F + 1, removing a prism of volume width^2 / 2 x the edge length.
template <class M, class T = default_traits<M>>
    requires bevelable_mesh<M, T>
result<bevel_result<M, T>> bevel(M& mesh, typename T::edge_handle edge, const bevel_options& options = {}) {
    const typename T::edge_handle one[1] = {edge};
    return bevel<M, T>(mesh, one, options);
}

/// Vertex-only bevel, as 3D editors call it: exactly truncate(mesh, vertices, {.distance =
/// options.width}) (cut points at `width` along each edge, clamped at half an edge where both
/// ends are bevelled). Only segments = 1 is supported (errc::unsupported otherwise);
/// clamp_overlap is always on. Returns the new faces in vertex_faces. Errors as truncate().
template <class M, class T = default_traits<M>, class R>
    requires bevelable_mesh<M, T> && range_of_handles<R, typename T::vertex_handle>
result<bevel_result<M, T>> bevel_vertices(M& mesh, const R& vertices, const bevel_options& options = {}) {
    if (options.segments != 1)
        return fail(errc::unsupported, "bevel_vertices: only segments = 1 (a flat cut) is supported in vertex-only mode");
    if (!(options.width > 0) || !detail::editing::finite(options.width))
        return fail(errc::invalid_argument, "bevel_vertices: width must be finite and > 0");
    auto r = truncate<M, T>(mesh, vertices, {.fraction = 1.0 / 3.0, .distance = options.width});
    if (!r) return r.error();
    bevel_result<M, T> out;
    for (auto f : r->faces)
        if (f != T::null_face()) out.vertex_faces.push_back(f);
    out.vertices = std::move(r->vertices);
    out.width = options.width;
    return out;
}

}  // namespace hmira
