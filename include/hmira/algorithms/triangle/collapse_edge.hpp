// hmira/algorithms/triangle/collapse_edge.hpp
// Edge collapse: an edge shrinks to a point, its source merging into its target; the
// triangles on either side disappear. The basis of decimation and of the inverse of a split.
#pragma once

#include <array>
#include <string_view>
#include <utility>
#include <vector>

#include "triangle_common.hpp"

namespace hmira {

/// Where the surviving vertex of a collapse goes.
enum class collapse_placement {
    midpoint,  ///< halfway along the edge
    target,    ///< where the surviving vertex (the halfedge's target) already is
    source,    ///< where the removed vertex (the halfedge's source) was
    given,     ///< at collapse_edge_options::position
};

/// The placements' names: "midpoint", "target", "source", "given" (see core/enum_names.hpp).
constexpr auto enum_names(collapse_placement) {
    return std::array{std::pair{collapse_placement::midpoint, std::string_view("midpoint")},
                      std::pair{collapse_placement::target, std::string_view("target")},
                      std::pair{collapse_placement::source, std::string_view("source")},
                      std::pair{collapse_placement::given, std::string_view("given")}};
}

/// Options of is_collapse_ok and collapse_edge.
struct collapse_edge_options {
    /// Where the surviving vertex goes.
    collapse_placement placement = collapse_placement::midpoint;
    /// The position used with collapse_placement::given.
    vec3<double> position{};
    /// Also refuse a collapse that turns a remaining face around (its normal after the move
    /// points against its normal before) or makes it degenerate.
    bool check_geometry = false;
};

/// What collapse_edge left.
template <class M, class T = default_traits<M>>
struct collapse_edge_result {
    typename T::vertex_handle vertex;  ///< the surviving vertex (the halfedge's target), at its new position
};

namespace detail::triangle_ops {

/// Why the collapse of h is refused, or an empty string. See is_collapse_ok.
template <class M, class T>
const char* collapse_refusal(const M& m, typename T::halfedge_handle h, const collapse_edge_options& options) {
    const auto o = T::opposite(m, h);
    const auto a = T::target(m, o), b = T::target(m, h);
    if (a == b) return "the edge is a loop";
    const auto f0 = T::face(m, h), f1 = T::face(m, o);
    if (f0 == T::null_face() && f1 == T::null_face()) return "the edge is a wire edge (no face on either side)";
    if (f0 == f1) return "the edge has the same face on both sides";
    // Each side: a boundary or a polygon loses one edge; a triangle disappears, and its two
    // other edges merge. A side loop of fewer than three edges cannot shrink further.
    const std::size_t n0 = loop_length<M, T>(m, h), n1 = loop_length<M, T>(m, o);
    if (n0 < 3 || n1 < 3) return "a loop beside the edge has fewer than three edges";
    const bool tri0 = f0 != T::null_face() && n0 == 3, tri1 = f1 != T::null_face() && n1 == 3;
    if ((tri0 && detail::euler::has_rings<M, T>(m, f0)) || (tri1 && detail::euler::has_rings<M, T>(m, f1)))
        return "a triangle beside the edge has inner rings";
    if (f0 == T::null_face() && n0 == 3) return "the edge lies on a boundary loop of three edges (the hole would close to a double edge)";
    if (f1 == T::null_face() && n1 == 3) return "the edge lies on a boundary loop of three edges (the hole would close to a double edge)";
    const auto c = tri0 ? T::target(m, T::next(m, h)) : a;
    const auto d = tri1 ? T::target(m, T::next(m, o)) : a;
    if (tri0 && tri1 && c == d) return "the two triangles beside the edge share all three vertices";
    // A triangle whose two other edges are both on the boundary would leave a dangling edge.
    auto dangling = [&](typename T::halfedge_handle x) {
        return T::face(m, T::opposite(m, T::next(m, x))) == T::null_face() &&
               T::face(m, T::opposite(m, T::prev(m, x))) == T::null_face();
    };
    if ((tri0 && dangling(h)) || (tri1 && dangling(o))) return "a triangle beside the edge hangs on it alone (its other edges are boundary)";
    // Link condition: the only vertices adjacent to both ends are the third corners of the
    // triangles beside the edge.
    const auto start = T::vertex_halfedge(m, a);
    bool a_on_boundary = false;
    auto x = start;
    do {
        if (T::face(m, x) == T::null_face()) a_on_boundary = true;
        const auto k = T::target(m, x);
        if (x != h && !(tri0 && k == c) && !(tri1 && k == d) && find_halfedge<M, T>(m, k, b) != T::null_halfedge())
            return "the link condition fails: the edge's ends share a neighbour outside the triangles beside it";
        x = T::next(m, T::opposite(m, x));
    } while (x != start);
    if (f0 != T::null_face() && f1 != T::null_face() && a_on_boundary) {
        const auto vb = T::vertex_halfedge(m, b);
        if (vb != T::null_halfedge() && T::face(m, vb) == T::null_face())
            return "both ends are on the boundary but the edge is not (the boundary would pinch)";
    }
    // A closed tetrahedron: the edge between the third corners lies in triangles with a and b.
    if (tri0 && tri1) {
        const auto cd = find_halfedge<M, T>(m, c, d);
        if (cd != T::null_halfedge()) {
            auto third = [&](typename T::halfedge_handle y) {
                return T::face(m, y) != T::null_face() && loop_length<M, T>(m, y) == 3 ? T::target(m, T::next(m, y)) : c;
            };
            const auto x1 = third(cd), x2 = third(T::opposite(m, cd));
            if ((x1 == a && x2 == b) || (x1 == b && x2 == a)) return "the edge belongs to a tetrahedron (it would flatten)";
        }
    }
    // A polygon (or inner ring) around a that also passes through b elsewhere would visit the
    // merged vertex twice.
    x = start;
    do {
        const auto g = T::face(m, x);
        if (g != T::null_face() && g != f0 && g != f1 && (loop_length<M, T>(m, x) > 3 || detail::euler::has_rings<M, T>(m, g))) {
            auto visits_b = [&](typename T::halfedge_handle s) {
                auto y = s;
                do {
                    if (T::target(m, y) == b) return true;
                    y = T::next(m, y);
                } while (y != s);
                return false;
            };
            if (visits_b(T::face_halfedge(m, g))) return "a face around the source also passes through the target";
            if constexpr (inner_ring_mesh<M, T>)
                for (auto r : T::inner_rings(m, g))
                    if (visits_b(r)) return "a face around the source also passes through the target";
        }
        x = T::next(m, T::opposite(m, x));
    } while (x != start);

    if (options.check_geometry) {
        const auto pa = position_of<M, T>(m, a), pb = position_of<M, T>(m, b);
        const vec3<double> target = options.placement == collapse_placement::midpoint ? (pa + pb) * 0.5
                                    : options.placement == collapse_placement::target ? pb
                                    : options.placement == collapse_placement::source ? pa
                                                                                      : options.position;
        // Every face around a or b that survives, with both ends moved to the target.
        for (const auto v : {a, b}) {
            const auto s = T::vertex_halfedge(m, v);
            auto y = s;
            do {
                const auto g = T::face(m, y);
                if (g != T::null_face() && !(g == f0 && tri0) && !(g == f1 && tri1)) {
                    vec3<double> before{}, after{};
                    auto z = T::face_halfedge(m, g);
                    const auto zs = z;
                    do {
                        const auto u = T::target(m, T::opposite(m, z)), w = T::target(m, z);
                        const auto p0 = position_of<M, T>(m, u), p1 = position_of<M, T>(m, w);
                        const auto q0 = (u == a || u == b) ? target : p0, q1 = (w == a || w == b) ? target : p1;
                        before += cross(p0, p1);
                        after += cross(q0, q1);
                        z = T::next(m, z);
                    } while (z != zs);
                    if (!(dot(before, after) > 0)) return "a face around the edge would fold over or degenerate";
                }
                y = T::next(m, T::opposite(m, y));
            } while (y != s);
        }
    }
    return "";
}

}  // namespace detail::triangle_ops

/// Whether collapse_edge(mesh, h, options) may run, checked without changing anything:
/// - the link condition: every vertex adjacent to both ends is the third corner of a
///   triangle beside the edge (otherwise the collapse makes a double edge);
/// - boundary rules: an interior edge between two boundary vertices is refused (the boundary
///   would pinch), as is an edge on a boundary loop of three edges, a triangle hanging on the
///   edge alone, and a closed tetrahedron or two-triangle pillow;
/// - beside the edge, polygons lose one corner (they must keep three) and triangles
///   disappear (they must have no inner rings); no polygon around the source may also pass
///   through the target;
/// - with `options.check_geometry`, no remaining face around the edge turns over.
/// On a triangle mesh the topological part is CGAL's `Euler::does_satisfy_link_condition`.
/// Complexity O(sum over neighbours k of the source of valence(k)), plus the degrees of the
/// polygons around the source.
template <class M, class T = default_traits<M>>
    requires triangle_operable_mesh<M, T>
bool is_collapse_ok(const M& mesh, typename T::halfedge_handle h, const collapse_edge_options& options = {}) {
    if (!detail::euler::usable<M, T>(mesh, h)) return false;
    const char* refusal = detail::triangle_ops::collapse_refusal<M, T>(mesh, h, options);
    return refusal[0] == '\0';
}

/// Collapses the edge of h = a->b: a is removed, b survives at the position the options give
/// (the midpoint by default). A triangle beside the edge disappears and its two other edges
/// become one; a polygon or boundary loop beside it loses the edge.
///
/// Inverse of split_edge and split_face with `placement = collapse_placement::target` (see
/// those operators).
/// \post V - 1; E - 1 - (triangles removed); F - (triangles removed); every halfedge that
/// ended at a now ends at b.
/// Errors (mesh unchanged): errc::invalid_handle; errc::topology naming the rule when
/// is_collapse_ok fails; errc::invalid_argument for a non-finite `position`.
/// Complexity: that of is_collapse_ok, plus O(valence of a) for the collapse itself.
template <class M, class T = default_traits<M>>
    requires triangle_operable_mesh<M, T>
[[nodiscard]] result<collapse_edge_result<M, T>> collapse_edge(M& mesh, typename T::halfedge_handle h,
                                                               const collapse_edge_options& options = {}) {
    namespace de = detail::euler;
    namespace dt = detail::triangle_ops;
    if (!de::usable<M, T>(mesh, h))
        return fail(errc::invalid_handle, "collapse_edge: " + de::name<M, T>("halfedge", mesh, h) + " does not exist",
                    de::index_of<M, T>(mesh, h));
    if (options.placement == collapse_placement::given && !dt::finite(options.position))
        return fail(errc::invalid_argument, "collapse_edge: option position is not finite", de::index_of<M, T>(mesh, h));
    if (const char* why = dt::collapse_refusal<M, T>(mesh, h, options); *why != '\0')
        return fail(errc::topology, "collapse_edge: cannot collapse " + de::name<M, T>("halfedge", mesh, h) + ": " + why,
                    de::index_of<M, T>(mesh, h));

    const auto o = T::opposite(mesh, h);
    const auto a = T::target(mesh, o), b = T::target(mesh, h);
    const auto f0 = T::face(mesh, h), f1 = T::face(mesh, o);
    const bool tri0 = f0 != T::null_face() && dt::loop_length<M, T>(mesh, h) == 3;
    const bool tri1 = f1 != T::null_face() && dt::loop_length<M, T>(mesh, o) == 3;
    const auto pa = dt::position_of<M, T>(mesh, a), pb = dt::position_of<M, T>(mesh, b);
    const vec3<double> p = options.placement == collapse_placement::midpoint ? (pa + pb) * 0.5
                           : options.placement == collapse_placement::target ? pb
                           : options.placement == collapse_placement::source ? pa
                                                                             : options.position;

    // The halfedges that end at a (all but o's twin side) are re-targeted at b.
    std::vector<typename T::halfedge_handle> into_a;
    {
        const auto s = T::vertex_halfedge(mesh, a);
        auto x = s;
        do {
            into_a.push_back(T::opposite(mesh, x));
            x = T::next(mesh, T::opposite(mesh, x));
        } while (x != s);
    }
    const auto hn = T::next(mesh, h), hp = T::prev(mesh, h);
    const auto on = T::next(mesh, o), op = T::prev(mesh, o);
    auto removed_edge = [&](typename T::halfedge_handle x) {
        const auto e = T::edge(mesh, x);
        return e == T::edge(mesh, h) || (tri0 && e == T::edge(mesh, hp)) || (tri1 && e == T::edge(mesh, on));
    };
    typename T::vertex_handle c{}, d{};
    typename T::halfedge_handle c_out{}, d_out{};
    if (tri0) {
        c = T::target(mesh, hn);
        c_out = T::vertex_halfedge(mesh, c);
        if (c_out == hp) c_out = T::opposite(mesh, hn);
    }
    if (tri1) {
        d = T::target(mesh, on);
        d_out = T::vertex_halfedge(mesh, d);
        if (d_out == T::opposite(mesh, on)) d_out = op;
    }
    // Any surviving outgoing halfedge of b or a serves to find b's new stored halfedge.
    typename T::halfedge_handle b_any = T::null_halfedge();
    {
        const auto s = T::vertex_halfedge(mesh, b);
        auto x = s;
        do {
            if (!removed_edge(x)) { b_any = x; break; }
            x = T::next(mesh, T::opposite(mesh, x));
        } while (x != s);
    }

    // Side of h.
    if (tri0) {
        // Triangle (a, b, c) goes; hn (b -> c) takes the place of hp's twin (a -> c).
        const auto t = T::opposite(mesh, hp);
        const auto g = T::face(mesh, t);
        T::set_next(mesh, T::prev(mesh, t), hn);
        T::set_next(mesh, hn, T::next(mesh, t));
        T::set_face(mesh, hn, g);
        if (g != T::null_face()) {
            if (T::face_halfedge(mesh, g) == t) T::set_face_halfedge(mesh, g, hn);
            de::replace_ring_halfedge<M, T>(mesh, g, t, hn);
        }
    } else {
        T::set_next(mesh, hp, hn);
        if (f0 != T::null_face()) {
            if (T::face_halfedge(mesh, f0) == h) T::set_face_halfedge(mesh, f0, hn);
        }
    }
    // Side of o.
    if (tri1) {
        // Triangle (b, a, d) goes; op (d -> b) takes the place of on's twin (d -> a).
        const auto t = T::opposite(mesh, on);
        const auto g = T::face(mesh, t);
        T::set_next(mesh, T::prev(mesh, t), op);
        T::set_next(mesh, op, T::next(mesh, t));
        T::set_face(mesh, op, g);
        if (g != T::null_face()) {
            if (T::face_halfedge(mesh, g) == t) T::set_face_halfedge(mesh, g, op);
            de::replace_ring_halfedge<M, T>(mesh, g, t, op);
        }
    } else {
        T::set_next(mesh, op, on);
        if (f1 != T::null_face()) {
            if (T::face_halfedge(mesh, f1) == o) T::set_face_halfedge(mesh, f1, on);
        }
    }
    for (const auto x : into_a)
        if (!removed_edge(x)) T::set_target(mesh, x, b);
    if (b_any == T::null_halfedge())
        for (const auto x : into_a)
            if (!removed_edge(x)) { b_any = T::opposite(mesh, x); break; }

    // Erase what went (read everything first: some models reuse links for their free lists).
    const auto eh = T::edge(mesh, h);
    const auto ehp = tri0 ? T::edge(mesh, hp) : eh;
    const auto eon = tri1 ? T::edge(mesh, on) : eh;
    T::erase_edge(mesh, eh);
    if (tri0) {
        T::erase_edge(mesh, ehp);
        T::erase_face(mesh, f0);
    }
    if (tri1) {
        T::erase_edge(mesh, eon);
        T::erase_face(mesh, f1);
    }
    T::erase_vertex(mesh, a);
    dt::set_position<M, T>(mesh, b, p);
    dt::refresh_vertex_halfedge<M, T>(mesh, b, b_any);
    if (tri0) dt::refresh_vertex_halfedge<M, T>(mesh, c, c_out);
    if (tri1) dt::refresh_vertex_halfedge<M, T>(mesh, d, d_out);
    return collapse_edge_result<M, T>{b};
}

}  // namespace hmira
