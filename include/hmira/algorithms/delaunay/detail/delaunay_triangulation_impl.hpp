// hmira/algorithms/delaunay/detail/delaunay_triangulation_impl.hpp
// The steps of delaunay_triangulation (see ../delaunay_triangulation.hpp for the interface):
// reading and checking the points, the insertion by the kernel (delaunay_kernel.hpp), and
// numbering the result: distinct points, triangles, hull and the Voronoi dual.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <ranges>
#include <span>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "../../../core/result.hpp"
#include "../../../core/vec3.hpp"
#include "../delaunay_triangulation.hpp"
#include "delaunay_kernel.hpp"

namespace hmira {

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

/// The points' (x, y), each checked (check_point).
template <class R>
result<std::vector<xy>> read_plane_points(const R& points) {
    const std::size_t n = std::ranges::size(points);
    std::vector<xy> in(n);
    for (std::size_t i = 0; i < n; ++i) {
        const vec3<double> q = read_point(std::ranges::begin(points)[i]);
        if (auto ok = check_point(i, q); !ok) return ok.error();
        in[i] = {q.x, q.y};
    }
    return in;
}

/// The first triangle in insertion order: the first point, the next distinct one (rank r1), the
/// next off their line (rank r2). False when there is none: all points are collinear.
inline bool first_triangle(const std::vector<xy>& sorted, std::size_t& r1, std::size_t& r2) {
    const std::size_t n = sorted.size();
    r1 = 1;
    while (r1 < n && sorted[r1].x == sorted[0].x && sorted[r1].y == sorted[0].y) ++r1;
    r2 = r1 + 1;
    while (r2 < n &&
           predicates::orient2d(sorted[0].x, sorted[0].y, sorted[r1].x, sorted[r1].y, sorted[r2].x, sorted[r2].y) == 0)
        ++r2;
    return r1 < n && r2 < n;
}

/// Numbers the distinct points by the first input index of each group: fills out.points and
/// the mappings, and returns the output vertex of each canonical rank. `order` maps rank to
/// input index, `canon` rank to the rank of the vertex it merged into.
template <class R>
std::vector<std::uint32_t> number_vertices(const R& points, const std::vector<std::uint32_t>& order,
                                           const std::vector<std::uint32_t>& canon, delaunay_triangles& out) {
    const std::size_t n = order.size();
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
        return out_id;
    }
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
    return out_id;
}

/// The finite triangles into out.triangles; with `voronoi`, each slot's output index into
/// tri_id. Returns some ghost triangle's slot.
inline std::uint32_t collect_triangles(const triangulation& tri, const std::vector<std::uint32_t>& out_id, bool voronoi,
                                       delaunay_triangles& out, std::vector<std::uint32_t>& tri_id) {
    const std::uint32_t slots = tri.triangle_count();
    if (voronoi) tri_id.assign(slots, voronoi_edge::no_vertex);
    out.triangles.reserve(slots);
    std::uint32_t some_ghost = 0;
    for (std::uint32_t t = 0; t < slots; ++t) {
        if (tri.is_ghost(t)) {
            some_ghost = t;
            continue;
        }
        if (voronoi) tri_id[t] = static_cast<std::uint32_t>(out.triangles.size());
        out.triangles.push_back({out_id[tri.tv[3 * t]], out_id[tri.tv[3 * t + 1]], out_id[tri.tv[3 * t + 2]]});
    }
    return some_ghost;
}

/// The hull, counter-clockwise: ghost triangles chain around it clockwise (inside on the right
/// of a -> b), from any ghost.
inline std::vector<std::uint32_t> hull_loop(const triangulation& tri, const std::vector<std::uint32_t>& out_id,
                                            std::uint32_t some_ghost) {
    std::vector<std::uint32_t> hull;
    for (std::uint32_t g = some_ghost;;) {
        hull.push_back(out_id[tri.tv[3 * g]]);
        g = tri.ta[3 * g] / 3;
        if (g == some_ghost) break;
    }
    std::reverse(hull.begin(), hull.end());
    return hull;
}

/// The Voronoi dual: one circumcentre per finite triangle, one edge per Delaunay edge (a ray
/// out of the hull for a hull edge).
inline voronoi_diagram voronoi_dual(const triangulation& tri, const std::vector<std::uint32_t>& out_id,
                                    const std::vector<std::uint32_t>& tri_id, std::size_t triangles) {
    const std::uint32_t slots = tri.triangle_count();
    voronoi_diagram vd;
    vd.vertices.resize(triangles);
    for (std::uint32_t t = 0; t < slots; ++t)
        if (!tri.is_ghost(t))
            vd.vertices[tri_id[t]] =
                circumcenter(tri.p[tri.tv[3 * t]], tri.p[tri.tv[3 * t + 1]], tri.p[tri.tv[3 * t + 2]]);
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
    return vd;
}

}  // namespace detail::delaunay

template <delaunay_point_range R>
result<delaunay_triangles> delaunay_triangulation(const R& points, const delaunay_options& options) {
    using namespace detail::delaunay;
    const std::size_t n = std::ranges::size(points);
    if (n >= 0xFFFFFFFFu)
        return fail(errc::unsupported,
                    "delaunay_triangulation: " + std::to_string(n) + " points, at most 2^32 - 2 supported");
    auto in = read_plane_points(points);
    if (!in) return in.error();
    if (n < 3)
        return fail(errc::invalid_argument,
                    "delaunay_triangulation: need at least 3 distinct points, got " + std::to_string(n) + " points");

    // Points in insertion order: vertex id = rank, so that neighbours are near in memory too.
    const std::vector<std::uint32_t> order = insertion_order(*in, options.brio);
    std::vector<xy> sorted(n);
    for (std::size_t r = 0; r < n; ++r) sorted[r] = (*in)[order[r]];
    std::size_t r1 = 0, r2 = 0;
    if (!first_triangle(sorted, r1, r2)) return collinear_result(points, *in);
    std::vector<xy>().swap(*in);

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

    delaunay_triangles out;
    const std::vector<std::uint32_t> out_id = number_vertices(points, order, canon, out);
    std::vector<std::uint32_t> tri_id;
    const std::uint32_t some_ghost = collect_triangles(tri, out_id, options.voronoi, out, tri_id);
    out.hull = hull_loop(tri, out_id, some_ghost);
    if (options.voronoi) out.voronoi = voronoi_dual(tri, out_id, tri_id, out.triangles.size());
    return out;
}

template <class M, class T, delaunay_point_range R>
    requires mesh_builder<M, T>
result<delaunay_mesh_result<M, T>> delaunay_triangulation(M& mesh, const R& points, const delaunay_options& options) {
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
