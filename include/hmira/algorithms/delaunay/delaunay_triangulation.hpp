// hmira/algorithms/delaunay/delaunay_triangulation.hpp
// Point set -> triangle mesh (thesis 2.3.1): the 2D Delaunay triangulation of (x, y), lifted
// by z into a 2.5D height field, written into any mesh model or returned as indexed triangles.
// Exact predicates, duplicates merged with a mapping, hull and optional Voronoi dual.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <ranges>
#include <span>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/result.hpp"
#include "../../core/vec3.hpp"
#include "../../traits.hpp"
#include "detail/delaunay_kernel.hpp"

namespace hmira {

/// A point delaunay_triangulation accepts: a `vec3`-like type with members x, y, z, or a
/// `std::array` of 2 or 3 scalars (z = 0 for two components).
template <class P>
concept delaunay_point =
    requires(const P& p) {
        { p.x } -> std::convertible_to<double>;
        { p.y } -> std::convertible_to<double>;
        { p.z } -> std::convertible_to<double>;
    } ||
    (requires { std::tuple_size<P>::value; } && (std::tuple_size<P>::value == 2 || std::tuple_size<P>::value == 3) &&
     requires(const P& p) {
         { p[0] } -> std::convertible_to<double>;
     });

/// A sized random-access range of delaunay_point.
template <class R>
concept delaunay_point_range = std::ranges::random_access_range<R> && std::ranges::sized_range<R> &&
    delaunay_point<std::ranges::range_value_t<R>>;

/// Whether the input spanned the plane.
enum class delaunay_status {
    ok,             ///< at least three non-collinear points: a triangulation
    all_collinear,  ///< all points on one line (at least 3 distinct): no triangles, hull = the 2 ends
};

/// What delaunay_triangulation computes besides the triangles.
struct delaunay_options {
    /// Also compute the Voronoi diagram (the dual: one vertex per triangle, one edge per
    /// Delaunay edge).
    bool voronoi = false;
    /// Insert in BRIO rounds (robust expected cost for any input order); false: one plain
    /// Hilbert order, a little faster on benign input.
    bool brio = true;
};

/// One Voronoi edge, dual to the Delaunay edge between sites site0 and site1 (output vertex
/// indices). It joins Voronoi vertices from and to (triangle indices), or, for a hull edge,
/// is the ray from `from` along `direction` (pointing out of the hull) and to == no_vertex.
struct voronoi_edge {
    static constexpr std::uint32_t no_vertex = 0xFFFFFFFFu;  ///< `to` of a ray
    /// The Delaunay edge's end vertices.
    ///@{
    std::uint32_t site0 = 0, site1 = 0;
    ///@}
    /// The Voronoi vertices joined (triangle indices).
    ///@{
    std::uint32_t from = 0, to = no_vertex;
    ///@}
    vec3<double> direction{};  ///< a ray's direction (hull edges only)
};

/// The Voronoi diagram: vertices[i] is the circumcentre of triangle i (z = 0).
struct voronoi_diagram {
    std::vector<vec3<double>> vertices;  ///< circumcentres, one per triangle
    std::vector<voronoi_edge> edges;     ///< one per Delaunay edge
};

/// The triangulation as plain data.
struct delaunay_triangles {
    delaunay_status status = delaunay_status::ok;  ///< ok, or all_collinear
    /// The distinct points (duplicates in x, y merged; z from the first input of each group).
    std::vector<vec3<double>> points;
    /// Counter-clockwise triangles (seen from +z) as indices into points.
    std::vector<std::array<std::uint32_t, 3>> triangles;
    /// The convex hull as a counter-clockwise loop of indices into points, starting at any
    /// vertex. Hull vertices on a straight stretch of the hull are included.
    std::vector<std::uint32_t> hull;
    /// points[i] is input point vertex_to_input[i] (the first of its duplicates, in input order).
    std::vector<std::uint32_t> vertex_to_input;
    /// Input point j became points[input_to_vertex[j]].
    std::vector<std::uint32_t> input_to_vertex;
    /// Empty unless options.voronoi.
    voronoi_diagram voronoi;
};

/// What delaunay_triangulation wrote into a mesh.
template <class Mesh, class Traits = default_traits<Mesh>>
struct delaunay_mesh_result {
    delaunay_status status = delaunay_status::ok;  ///< ok, or all_collinear
    /// The new vertices, one per distinct input point, in the order of delaunay_triangles::points.
    std::vector<vertex_handle_t<Mesh, Traits>> vertices;
    /// The new faces, in the order of delaunay_triangles::triangles.
    std::vector<face_handle_t<Mesh, Traits>> faces;
    /// The convex hull as a counter-clockwise loop of new vertices.
    std::vector<vertex_handle_t<Mesh, Traits>> hull;
    /// vertices[i] comes from input point vertex_to_input[i]; input j became vertices[input_to_vertex[j]].
    ///@{
    std::vector<std::uint32_t> vertex_to_input, input_to_vertex;
    ///@}
    /// Empty unless options.voronoi; vertex i is dual to faces[i], sites index `vertices`.
    voronoi_diagram voronoi;
};

namespace detail::delaunay {

template <delaunay_point P>
vec3<double> read_point(const P& p) {
    if constexpr (requires { p.x; }) {
        return {double(p.x), double(p.y), double(p.z)};
    } else if constexpr (std::tuple_size<P>::value == 2) {
        return {double(p[0]), double(p[1]), 0.0};
    } else {
        return {double(p[0]), double(p[1]), double(p[2])};
    }
}

inline std::string format_point(std::size_t i, const vec3<double>& q) {
    std::ostringstream s;
    s.precision(17);
    s << "point " << i << " (" << q.x << ", " << q.y << ", " << q.z << ")";
    return s.str();
}

/// Checks one input point: finite, and x, y inside the predicates' safe range.
inline result<void> check_point(std::size_t i, const vec3<double>& q) {
    if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z))
        return fail(errc::invalid_argument,
                    "delaunay_triangulation: " + format_point(i, q) + " has a NaN or infinite coordinate",
                    static_cast<long long>(i));
    if (!predicates::in_predicate_range(q.x) || !predicates::in_predicate_range(q.y))
        return fail(errc::invalid_argument,
                    "delaunay_triangulation: " + format_point(i, q) +
                        " has an x or y coordinate the exact predicates cannot handle without overflow or "
                        "underflow (allowed: 0, or magnitude in [2^-180, 2^180] ~ [6.5e-55, 1.5e54])",
                    static_cast<long long>(i));
    return {};
}

/// All points collinear: merge duplicates by sorting, report the two ends as the "hull".
template <class R>
result<delaunay_triangles> collinear_result(const R& points, const std::vector<xy>& in) {
    const std::size_t n = in.size();
    std::vector<std::uint32_t> idx(n);
    for (std::size_t i = 0; i < n; ++i) idx[i] = static_cast<std::uint32_t>(i);
    auto less = [&](std::uint32_t a, std::uint32_t b) {
        return in[a].x != in[b].x ? in[a].x < in[b].x : (in[a].y != in[b].y ? in[a].y < in[b].y : a < b);
    };
    std::sort(idx.begin(), idx.end(), less);
    // Group leader: the first input index of each run of equal points (runs are sorted by index).
    std::vector<std::uint32_t> leader(n);
    std::size_t groups = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const bool same = k > 0 && in[idx[k]].x == in[idx[k - 1]].x && in[idx[k]].y == in[idx[k - 1]].y;
        leader[idx[k]] = same ? leader[idx[k - 1]] : idx[k];
        groups += same ? 0 : 1;
    }
    if (groups < 3)
        return fail(errc::invalid_argument, "delaunay_triangulation: need at least 3 distinct points, got " +
                                                std::to_string(groups) + " (after merging duplicates)");
    delaunay_triangles out;
    out.status = delaunay_status::all_collinear;
    out.input_to_vertex.assign(n, 0);
    std::vector<std::uint32_t> id(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        if (leader[i] == i) {
            id[i] = static_cast<std::uint32_t>(out.points.size());
            out.vertex_to_input.push_back(static_cast<std::uint32_t>(i));
            out.points.push_back(read_point(std::ranges::begin(points)[i]));
        }
        out.input_to_vertex[i] = id[leader[i]];
    }
    out.hull = {out.input_to_vertex[idx.front()], out.input_to_vertex[idx.back()]};
    return out;
}

inline vec3<double> circumcenter(const xy& a, const xy& b, const xy& c) {
    // Relative to a, so that the result keeps its precision far from the origin.
    const double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
    const double d = 2.0 * (bx * cy - by * cx);
    const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    return {a.x + (cy * b2 - by * c2) / d, a.y + (bx * c2 - cx * b2) / d, 0.0};
}

}  // namespace detail::delaunay

/// The Delaunay triangulation of the points' (x, y), as indexed triangles; z rides along
/// (2.5D: a height field). Duplicates in (x, y) are merged and reported in the mapping.
/// Cocircular points are resolved consistently (a point on a circumcircle is not in conflict
/// with it), so the result is always a valid triangulation of the convex hull whose every
/// edge is locally Delaunay, even on lattices and circles.
///
/// Complexity: O(n log n) expected (n points): Hilbert/BRIO sort O(n), then incremental
/// insertion with short walks; predicates are exact and adaptive.
/// Preconditions: none (everything is checked).
/// Errors: errc::invalid_argument, naming the point, for a NaN or infinite coordinate or an x, y
/// outside the predicates' range (0 or magnitude in [2^-180, 2^180]); errc::invalid_argument
/// for fewer than 3 distinct points; errc::unsupported for 2^32 - 1 or more points.
/// All-collinear input is not an error: status all_collinear, no triangles.
template <delaunay_point_range R>
result<delaunay_triangles> delaunay_triangulation(const R& points, const delaunay_options& options = {}) {
    using namespace detail::delaunay;
    const std::size_t n = std::ranges::size(points);
    if (n >= 0xFFFFFFFFu)
        return fail(errc::unsupported, "delaunay_triangulation: " + std::to_string(n) + " points, at most 2^32 - 2 supported");
    std::vector<xy> in(n);
    for (std::size_t i = 0; i < n; ++i) {
        const vec3<double> q = read_point(std::ranges::begin(points)[i]);
        if (auto ok = check_point(i, q); !ok) return ok.error();
        in[i] = {q.x, q.y};
    }
    if (n < 3)
        return fail(errc::invalid_argument,
                    "delaunay_triangulation: need at least 3 distinct points, got " + std::to_string(n) + " points");

    // Points in insertion order: vertex id = rank, so that neighbours are near in memory too.
    const std::vector<std::uint32_t> order = insertion_order(in, options.brio);
    std::vector<xy> sorted(n);
    for (std::size_t r = 0; r < n; ++r) sorted[r] = in[order[r]];

    // The first triangle: the first point, the next distinct one, the next off their line.
    std::size_t r1 = 1;
    while (r1 < n && sorted[r1].x == sorted[0].x && sorted[r1].y == sorted[0].y) ++r1;
    std::size_t r2 = r1 + 1;
    while (r2 < n && predicates::orient2d(sorted[0].x, sorted[0].y, sorted[r1].x, sorted[r1].y, sorted[r2].x,
                                          sorted[r2].y) == 0)
        ++r2;
    if (r1 >= n || r2 >= n) return collinear_result(points, in);
    std::vector<xy>().swap(in);

    triangulation tri(std::move(sorted));
    tri.init(0, static_cast<std::uint32_t>(r1), static_cast<std::uint32_t>(r2));
    std::vector<std::uint32_t> canon(n);  // rank -> the rank of the vertex it merged into
    canon[0] = 0;
    canon[r1] = static_cast<std::uint32_t>(r1);
    canon[r2] = static_cast<std::uint32_t>(r2);
    for (std::size_t r = 1; r < n; ++r) {
        if (r == r1 || r == r2) continue;
        canon[r] = tri.insert(static_cast<std::uint32_t>(r));
    }

    // Number the distinct points by the first input index of each group.
    delaunay_triangles out;
    std::vector<std::uint32_t> out_id(n, 0xFFFFFFFFu);  // by canonical rank
    bool has_duplicates = false;
    for (std::size_t r = 0; r < n; ++r) has_duplicates |= canon[r] != r;
    if (!has_duplicates) {
        // The common case: output vertex i is input point i, and no scattered remapping.
        out_id = order;
        out.input_to_vertex.resize(n);
        out.vertex_to_input.resize(n);
        out.points.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            out.input_to_vertex[i] = out.vertex_to_input[i] = static_cast<std::uint32_t>(i);
            out.points[i] = read_point(std::ranges::begin(points)[i]);
        }
    } else {
        std::vector<std::uint32_t> first(n, 0xFFFFFFFFu);  // by canonical rank
        for (std::size_t r = 0; r < n; ++r) first[canon[r]] = std::min(first[canon[r]], order[r]);
        std::vector<std::uint32_t> rank_of(n);
        for (std::size_t r = 0; r < n; ++r) rank_of[order[r]] = static_cast<std::uint32_t>(r);
        out.input_to_vertex.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint32_t c = canon[rank_of[i]];
            if (first[c] == i) {
                out_id[c] = static_cast<std::uint32_t>(out.vertex_to_input.size());
                out.vertex_to_input.push_back(static_cast<std::uint32_t>(i));
            }
            out.input_to_vertex[i] = out_id[c];
        }
        out.points.resize(out.vertex_to_input.size());
        for (std::size_t v = 0; v < out.points.size(); ++v)
            out.points[v] = read_point(std::ranges::begin(points)[out.vertex_to_input[v]]);
    }

    // Finite triangles; remember each slot's output index for the Voronoi dual.
    const std::uint32_t slots = tri.triangle_count();
    std::vector<std::uint32_t> tri_id;
    if (options.voronoi) tri_id.assign(slots, voronoi_edge::no_vertex);
    out.triangles.reserve(slots);
    std::uint32_t some_ghost = 0;
    for (std::uint32_t t = 0; t < slots; ++t) {
        if (tri.is_ghost(t)) {
            some_ghost = t;
            continue;
        }
        if (options.voronoi) tri_id[t] = static_cast<std::uint32_t>(out.triangles.size());
        out.triangles.push_back({out_id[tri.tv[3 * t]], out_id[tri.tv[3 * t + 1]], out_id[tri.tv[3 * t + 2]]});
    }

    // The hull: ghost triangles chain around it clockwise (inside on the right of a -> b).
    for (std::uint32_t g = some_ghost;;) {
        out.hull.push_back(out_id[tri.tv[3 * g]]);
        g = tri.ta[3 * g] / 3;
        if (g == some_ghost) break;
    }
    std::reverse(out.hull.begin(), out.hull.end());

    if (options.voronoi) {
        auto& vd = out.voronoi;
        vd.vertices.resize(out.triangles.size());
        for (std::uint32_t t = 0; t < slots; ++t)
            if (!tri.is_ghost(t))
                vd.vertices[tri_id[t]] = circumcenter(tri.p[tri.tv[3 * t]], tri.p[tri.tv[3 * t + 1]], tri.p[tri.tv[3 * t + 2]]);
        for (std::uint32_t t = 0; t < slots; ++t) {
            if (tri.is_ghost(t)) continue;
            for (std::uint32_t i = 0; i < 3; ++i) {
                const std::uint32_t nb = tri.ta[3 * t + i] / 3;
                const std::uint32_t a = tri.tv[3 * t + (i + 1) % 3], b = tri.tv[3 * t + (i + 2) % 3];
                voronoi_edge e;
                e.site0 = out_id[a];
                e.site1 = out_id[b];
                e.from = tri_id[t];
                if (tri.is_ghost(nb)) {
                    // Outward normal of the hull edge a -> b (inside on its left).
                    e.direction = {tri.p[b].y - tri.p[a].y, tri.p[a].x - tri.p[b].x, 0.0};
                } else if (t < nb) {
                    e.to = tri_id[nb];
                } else {
                    continue;
                }
                vd.edges.push_back(e);
            }
        }
    }
    return out;
}

/// The Delaunay triangulation of the points' (x, y), written into `mesh`: one new vertex per
/// distinct point (at its x, y, z: a 2.5D height field) and one counter-clockwise triangle per
/// Delaunay triangle. Returns what it created, the hull, the duplicate mapping and, on request,
/// the Voronoi dual. See the indexed overload for the method and the degenerate cases.
///
/// Complexity: O(n log n) expected plus n add_vertex and ~2n add_face calls on the mesh.
/// Preconditions: none (everything is checked).
/// Errors: as the indexed overload, with the mesh unchanged. All-collinear input adds nothing
/// and returns status all_collinear (vertices, faces and hull empty; the mapping still numbers
/// the distinct points as the indexed overload does). If the mesh refuses a face (for example a mesh that
/// already holds a conflicting face cannot, since all vertices are new) its error is returned;
/// the vertices and faces added before it stay.
template <class M, class T = default_traits<M>, delaunay_point_range R>
    requires mesh_builder<M, T>
result<delaunay_mesh_result<M, T>> delaunay_triangulation(M& mesh, const R& points, const delaunay_options& options = {}) {
    auto tri = delaunay_triangulation(points, options);
    if (!tri) return tri.error();
    delaunay_mesh_result<M, T> out;
    out.status = tri->status;
    out.vertex_to_input = std::move(tri->vertex_to_input);
    out.input_to_vertex = std::move(tri->input_to_vertex);
    if (tri->status != delaunay_status::ok) return out;
    using S = typename T::scalar;
    out.vertices.reserve(tri->points.size());
    for (const auto& q : tri->points) out.vertices.push_back(T::add_vertex(mesh, vec3<S>{S(q.x), S(q.y), S(q.z)}));
    out.faces.reserve(tri->triangles.size());
    for (const auto& t : tri->triangles) {
        const std::array<vertex_handle_t<M, T>, 3> vs = {out.vertices[t[0]], out.vertices[t[1]], out.vertices[t[2]]};
        auto f = T::add_face(mesh, std::span<const vertex_handle_t<M, T>>(vs.data(), 3));
        if (!f) return f.error();
        out.faces.push_back(*f);
    }
    out.hull.reserve(tri->hull.size());
    for (std::uint32_t v : tri->hull) out.hull.push_back(out.vertices[v]);
    out.voronoi = std::move(tri->voronoi);
    return out;
}

}  // namespace hmira
