// hmira/algorithms/triangle/detail/collapse_edge_impl.hpp
// The machinery of collapse_edge (see collapse_edge.hpp, which includes this file after its
// declarations): why a collapse is refused, the links read before the collapse changes
// anything, and the relinking of each side. Not public API.
#pragma once

#include <vector>

#include "../triangle_common.hpp"

namespace hmira {

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
    if (f0 == T::null_face() && n0 == 3)
        return "the edge lies on a boundary loop of three edges (the hole would close to a double edge)";
    if (f1 == T::null_face() && n1 == 3)
        return "the edge lies on a boundary loop of three edges (the hole would close to a double edge)";
    const auto c = tri0 ? T::target(m, T::next(m, h)) : a;
    const auto d = tri1 ? T::target(m, T::next(m, o)) : a;
    if (tri0 && tri1 && c == d) return "the two triangles beside the edge share all three vertices";
    // A triangle whose two other edges are both on the boundary would leave a dangling edge.
    auto dangling = [&](typename T::halfedge_handle x) {
        return T::face(m, T::opposite(m, T::next(m, x))) == T::null_face() &&
               T::face(m, T::opposite(m, T::prev(m, x))) == T::null_face();
    };
    if ((tri0 && dangling(h)) || (tri1 && dangling(o)))
        return "a triangle beside the edge hangs on it alone (its other edges are boundary)";
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
                return T::face(m, y) != T::null_face() && loop_length<M, T>(m, y) == 3 ? T::target(m, T::next(m, y))
                                                                                       : c;
            };
            const auto x1 = third(cd), x2 = third(T::opposite(m, cd));
            if ((x1 == a && x2 == b) || (x1 == b && x2 == a))
                return "the edge belongs to a tetrahedron (it would flatten)";
        }
    }
    // A polygon (or inner ring) around a that also passes through b elsewhere would visit the
    // merged vertex twice.
    x = start;
    do {
        const auto g = T::face(m, x);
        if (g != T::null_face() && g != f0 && g != f1 &&
            (loop_length<M, T>(m, x) > 3 || detail::euler::has_rings<M, T>(m, g))) {
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

/// The links around the edge of h = a->b, read before a collapse changes anything.
template <class M, class T>
struct collapse_links {
    using H = typename T::halfedge_handle;
    using V = typename T::vertex_handle;
    using F = typename T::face_handle;
    H h, o, hn, hp, on, op;
    V a, b;
    F f0, f1;
    bool tri0 = false, tri1 = false;  // the face on each side is a triangle, which goes
    V c{}, d{};                       // the third corners of those triangles
    H c_out{}, d_out{};               // a surviving outgoing halfedge of c, d
    H b_any{};                        // a surviving outgoing halfedge of b (null: none yet)
    std::vector<H> into_a;            // the halfedges that end at a

    /// Whether x's edge goes: the collapsed edge, and one side of each triangle that goes.
    /// Read from the mesh at each call.
    bool removed_edge(const M& mesh, H x) const {
        const auto e = T::edge(mesh, x);
        return e == T::edge(mesh, h) || (tri0 && e == T::edge(mesh, hp)) || (tri1 && e == T::edge(mesh, on));
    }
};

template <class M, class T>
collapse_links<M, T> read_collapse_links(const M& mesh, typename T::halfedge_handle h) {
    collapse_links<M, T> l;
    l.h = h;
    l.o = T::opposite(mesh, h);
    l.a = T::target(mesh, l.o);
    l.b = T::target(mesh, h);
    l.f0 = T::face(mesh, h);
    l.f1 = T::face(mesh, l.o);
    l.tri0 = l.f0 != T::null_face() && loop_length<M, T>(mesh, h) == 3;
    l.tri1 = l.f1 != T::null_face() && loop_length<M, T>(mesh, l.o) == 3;
    // The halfedges that end at a (all but o's twin side) are re-targeted at b.
    {
        const auto s = T::vertex_halfedge(mesh, l.a);
        auto x = s;
        do {
            l.into_a.push_back(T::opposite(mesh, x));
            x = T::next(mesh, T::opposite(mesh, x));
        } while (x != s);
    }
    l.hn = T::next(mesh, h);
    l.hp = T::prev(mesh, h);
    l.on = T::next(mesh, l.o);
    l.op = T::prev(mesh, l.o);
    if (l.tri0) {
        l.c = T::target(mesh, l.hn);
        l.c_out = T::vertex_halfedge(mesh, l.c);
        if (l.c_out == l.hp) l.c_out = T::opposite(mesh, l.hn);
    }
    if (l.tri1) {
        l.d = T::target(mesh, l.on);
        l.d_out = T::vertex_halfedge(mesh, l.d);
        if (l.d_out == T::opposite(mesh, l.on)) l.d_out = l.op;
    }
    // Any surviving outgoing halfedge of b or a serves to find b's new stored halfedge.
    l.b_any = T::null_halfedge();
    {
        const auto s = T::vertex_halfedge(mesh, l.b);
        auto x = s;
        do {
            if (!l.removed_edge(mesh, x)) {
                l.b_any = x;
                break;
            }
            x = T::next(mesh, T::opposite(mesh, x));
        } while (x != s);
    }
    return l;
}

/// A triangle beside the collapsed edge goes: `keep`, one of its sides, takes the place of
/// `t`, the twin of its other side, in t's loop.
template <class M, class T>
void absorb_triangle(M& mesh, typename T::halfedge_handle t, typename T::halfedge_handle keep) {
    const auto g = T::face(mesh, t);
    T::set_next(mesh, T::prev(mesh, t), keep);
    T::set_next(mesh, keep, T::next(mesh, t));
    T::set_face(mesh, keep, g);
    if (g != T::null_face()) {
        if (T::face_halfedge(mesh, g) == t) T::set_face_halfedge(mesh, g, keep);
        detail::euler::replace_ring_halfedge<M, T>(mesh, g, t, keep);
    }
}

/// A polygon or boundary loop beside the collapsed edge loses it: `prev` now leads to `next`,
/// and face f (null for the boundary) no longer starts at `dead`.
template <class M, class T>
void skip_edge(M& mesh, typename T::halfedge_handle prev, typename T::halfedge_handle dead,
               typename T::halfedge_handle next, typename T::face_handle f) {
    T::set_next(mesh, prev, next);
    if (f != T::null_face()) {
        if (T::face_halfedge(mesh, f) == dead) T::set_face_halfedge(mesh, f, next);
    }
}

/// Collapses the edge read into `l`, putting b at p. Preconditions checked by the caller.
template <class M, class T>
void apply_collapse(M& mesh, collapse_links<M, T>& l, const vec3<double>& p) {
    // Side of h: triangle (a, b, c) goes, hn (b -> c) taking the place of hp's twin (a -> c).
    if (l.tri0)
        absorb_triangle<M, T>(mesh, T::opposite(mesh, l.hp), l.hn);
    else
        skip_edge<M, T>(mesh, l.hp, l.h, l.hn, l.f0);
    // Side of o: triangle (b, a, d) goes, op (d -> b) taking the place of on's twin (d -> a).
    if (l.tri1)
        absorb_triangle<M, T>(mesh, T::opposite(mesh, l.on), l.op);
    else
        skip_edge<M, T>(mesh, l.op, l.o, l.on, l.f1);
    for (const auto x : l.into_a)
        if (!l.removed_edge(mesh, x)) T::set_target(mesh, x, l.b);
    if (l.b_any == T::null_halfedge())
        for (const auto x : l.into_a)
            if (!l.removed_edge(mesh, x)) {
                l.b_any = T::opposite(mesh, x);
                break;
            }
    // Erase what went (read everything first: some models reuse links for their free lists).
    const auto eh = T::edge(mesh, l.h);
    const auto ehp = l.tri0 ? T::edge(mesh, l.hp) : eh;
    const auto eon = l.tri1 ? T::edge(mesh, l.on) : eh;
    T::erase_edge(mesh, eh);
    if (l.tri0) {
        T::erase_edge(mesh, ehp);
        T::erase_face(mesh, l.f0);
    }
    if (l.tri1) {
        T::erase_edge(mesh, eon);
        T::erase_face(mesh, l.f1);
    }
    T::erase_vertex(mesh, l.a);
    set_position<M, T>(mesh, l.b, p);
    refresh_vertex_halfedge<M, T>(mesh, l.b, l.b_any);
    if (l.tri0) refresh_vertex_halfedge<M, T>(mesh, l.c, l.c_out);
    if (l.tri1) refresh_vertex_halfedge<M, T>(mesh, l.d, l.d_out);
}

}  // namespace detail::triangle_ops

template <class M, class T>
    requires triangle_operable_mesh<M, T>
bool is_collapse_ok(const M& mesh, typename T::halfedge_handle h, const collapse_edge_options& options) {
    if (!detail::euler::usable<M, T>(mesh, h)) return false;
    const char* refusal = detail::triangle_ops::collapse_refusal<M, T>(mesh, h, options);
    return refusal[0] == '\0';
}

template <class M, class T>
    requires triangle_operable_mesh<M, T>
result<collapse_edge_result<M, T>> collapse_edge(M& mesh, typename T::halfedge_handle h,
                                                 const collapse_edge_options& options) {
    namespace de = detail::euler;
    namespace dt = detail::triangle_ops;
    if (!de::usable<M, T>(mesh, h))
        return fail(errc::invalid_handle, "collapse_edge: " + de::name<M, T>("halfedge", mesh, h) + " does not exist",
                    de::index_of<M, T>(mesh, h));
    if (options.placement == collapse_placement::given && !dt::finite(options.position))
        return fail(errc::invalid_argument, "collapse_edge: option position is not finite",
                    de::index_of<M, T>(mesh, h));
    if (const char* why = dt::collapse_refusal<M, T>(mesh, h, options); *why != '\0')
        return fail(errc::topology,
                    "collapse_edge: cannot collapse " + de::name<M, T>("halfedge", mesh, h) + ": " + why,
                    de::index_of<M, T>(mesh, h));
    auto l = dt::read_collapse_links<M, T>(mesh, h);
    const auto pa = dt::position_of<M, T>(mesh, l.a), pb = dt::position_of<M, T>(mesh, l.b);
    const vec3<double> p = options.placement == collapse_placement::midpoint ? (pa + pb) * 0.5
                           : options.placement == collapse_placement::target ? pb
                           : options.placement == collapse_placement::source ? pa
                                                                             : options.position;
    dt::apply_collapse<M, T>(mesh, l, p);
    return collapse_edge_result<M, T>{l.b};
}

}  // namespace hmira
