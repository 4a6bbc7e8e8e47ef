// hmira/algorithms/euler/make_edge_kill_ring.hpp
// Euler operators makeEkillR / killEmakeR (Mantyla's MEKR / KEMR): join an inner ring to
// another loop of its face with a new edge, and split a loop in two by deleting a bridge
// edge, the new part becoming an inner ring. With makeFkillR / killFmakeR they let the
// Euler operators build surfaces of any genus.
#pragma once

#include "euler_common.hpp"

namespace hmira {

/// What make_edge_kill_ring created: kill_edge_make_ring(mesh, halfedge) undoes it.
template <class M, class T = default_traits<M>>
struct make_edge_kill_ring_result {
    /// The new edge, oriented so that the loop following it (from next(halfedge)) is the
    /// former ring.
    typename T::halfedge_handle halfedge;
};

/// What kill_edge_make_ring left: make_edge_kill_ring(mesh, h0, h1) undoes it.
template <class M, class T = default_traits<M>>
struct kill_edge_make_ring_result {
    typename T::halfedge_handle ring;  ///< a halfedge of the new inner ring
    typename T::halfedge_handle h0;    ///< the corner on the loop that stayed
    typename T::halfedge_handle h1;    ///< the corner on the new ring
};

/// makeEkillR (MEKR): a new edge from target(h0) to target(h1), where h0 and h1 lie on two
/// different loops of one face (the outer loop and an inner ring, or two inner rings). The two
/// loops become one and one ring disappears: that of h1, unless h1 is on the outer loop, in
/// which case that of h0. E + 1, R - 1.
///
/// Errors (mesh unchanged): errc::invalid_handle; errc::topology when the corners lie on
/// different faces or on a boundary loop, on the same loop (that is make_edge_face), or at
/// the same vertex.
/// Complexity O(face degree + rings of the face).
template <class M, class T = default_traits<M>>
    requires euler_ring_mutable_mesh<M, T>
result<make_edge_kill_ring_result<M, T>> make_edge_kill_ring(M& mesh, typename T::halfedge_handle h0,
                                                             typename T::halfedge_handle h1) {
    namespace de = detail::euler;
    if (!de::usable<M, T>(mesh, h0) || !de::usable<M, T>(mesh, h1))
        return fail(errc::invalid_handle,
                    "make_edge_kill_ring: corner " +
                        de::name<M, T>("halfedge", mesh, de::usable<M, T>(mesh, h0) ? h1 : h0) + " does not exist",
                    de::index_of<M, T>(mesh, de::usable<M, T>(mesh, h0) ? h1 : h0));
    const auto f = T::face(mesh, h0);
    if (T::face(mesh, h1) != f)
        return fail(errc::topology,
                    "make_edge_kill_ring: the corners lie on different faces (" + de::name<M, T>("face", mesh, f) +
                        " and " + de::name<M, T>("face", mesh, T::face(mesh, h1)) + ")",
                    de::index_of<M, T>(mesh, h1));
    if (f == T::null_face())
        return fail(errc::topology, "make_edge_kill_ring: the corners lie on boundary loops, which hold no rings",
                    de::index_of<M, T>(mesh, h0));
    const auto s = T::target(mesh, h0), t = T::target(mesh, h1);
    if (s == t)
        return fail(errc::topology,
                    "make_edge_kill_ring: both corners are at " + de::name<M, T>("vertex", mesh, s) +
                        "; the new edge would be a loop",
                    de::index_of<M, T>(mesh, s));
    const auto fh = T::face_halfedge(mesh, f);
    bool h0_outer = false, h1_outer = false;
    auto x = h0;
    do {
        if (x == h1)
            return fail(errc::topology,
                        "make_edge_kill_ring: the corners lie on one loop of " + de::name<M, T>("face", mesh, f) +
                            "; an edge there splits the face: use make_edge_face",
                        de::index_of<M, T>(mesh, f));
        h0_outer |= x == fh;
        x = T::next(mesh, x);
    } while (x != h0);
    if (!h0_outer) {
        x = h1;
        do {
            h1_outer |= x == fh;
            x = T::next(mesh, x);
        } while (x != h1 && !h1_outer);
    }

    const auto killed = h1_outer ? h0 : h1;
    T::remove_inner_ring(mesh, f, killed);
    const auto n0 = T::next(mesh, h0), n1 = T::next(mesh, h1);
    const auto a = T::new_edge(mesh, s, t);
    const auto b = T::opposite(mesh, a);
    T::set_next(mesh, h0, a);
    T::set_next(mesh, a, n1);
    T::set_next(mesh, h1, b);
    T::set_next(mesh, b, n0);
    T::set_face(mesh, a, f);
    T::set_face(mesh, b, f);
    return make_edge_kill_ring_result<M, T>{h1_outer ? b : a};
}

/// killEmakeR (KEMR): deletes the edge of `halfedge`, whose two sides lie on one loop of a
/// face (a bridge); the loop falls in two and the part that followed `halfedge` (from
/// next(halfedge)) becomes a new inner ring of the face. The other part stays what the loop
/// was (the outer loop or a ring). E - 1, R + 1.
///
/// Errors (mesh unchanged): errc::invalid_handle; errc::topology when the edge is on a
/// boundary loop (a boundary cannot hold rings), when its sides lie on different faces (that
/// is kill_edge_face) or different loops, or when either part would have no edge (an end of
/// degree 1: that is kill_edge_vertex).
/// Complexity O(face degree + rings of the face).
template <class M, class T = default_traits<M>>
    requires euler_ring_mutable_mesh<M, T>
result<kill_edge_make_ring_result<M, T>> kill_edge_make_ring(M& mesh, typename T::halfedge_handle halfedge) {
    namespace de = detail::euler;
    const auto h = halfedge;
    if (!de::usable<M, T>(mesh, h))
        return fail(errc::invalid_handle,
                    "kill_edge_make_ring: " + de::name<M, T>("halfedge", mesh, h) + " does not exist",
                    de::index_of<M, T>(mesh, h));
    const auto o = T::opposite(mesh, h);
    const auto f = T::face(mesh, h);
    if (f == T::null_face())
        return fail(errc::topology,
                    "kill_edge_make_ring: " + de::name<M, T>("halfedge", mesh, h) +
                        " is on a boundary loop, which cannot hold rings",
                    de::index_of<M, T>(mesh, h));
    if (T::face(mesh, o) != f)
        return fail(errc::topology,
                    "kill_edge_make_ring: the edge separates two faces; removing it joins them: use kill_edge_face",
                    de::index_of<M, T>(mesh, h));
    const auto hn = T::next(mesh, h), on = T::next(mesh, o);
    if (hn == o || on == h)
        return fail(errc::topology,
                    "kill_edge_make_ring: an end of the edge has degree 1, so one part would have no edge: use "
                    "kill_edge_vertex",
                    de::index_of<M, T>(mesh, h));
    const auto fh = T::face_halfedge(mesh, f);
    bool fh_in_ring = fh == h || fh == o;
    auto x = hn;
    for (; x != o; x = T::next(mesh, x)) {
        if (x == h)
            return fail(errc::topology,
                        "kill_edge_make_ring: the two sides of the edge lie on different loops of " +
                            de::name<M, T>("face", mesh, f) + "; the edge is no bridge",
                        de::index_of<M, T>(mesh, h));
        fh_in_ring |= x == fh;
    }
    bool fh_in_rest = false;
    for (x = on; x != h && !fh_in_rest; x = T::next(mesh, x)) fh_in_rest = x == fh;
    const bool was_outer = fh_in_ring || fh_in_rest;

    const auto hp = T::prev(mesh, h), op = T::prev(mesh, o);
    const auto s = T::target(mesh, o), t = T::target(mesh, h);
    if (!was_outer) T::remove_inner_ring(mesh, f, h);
    T::set_next(mesh, op, hn);
    T::set_next(mesh, hp, on);
    de::replace_vertex_halfedge<M, T>(mesh, s, h, on);
    de::replace_vertex_halfedge<M, T>(mesh, t, o, hn);
    if (was_outer) {
        if (fh_in_ring) T::set_face_halfedge(mesh, f, on);
    } else {
        T::add_inner_ring(mesh, f, on);
    }
    T::add_inner_ring(mesh, f, hn);
    T::erase_edge(mesh, T::edge(mesh, h));
    return kill_edge_make_ring_result<M, T>{hn, hp, op};
}

}  // namespace hmira
