// hmira/algorithms/euler/make_edge_face.hpp
// Euler operators makeEF / killEF (Mantyla's MEF / KEF, thesis 2.1.5-2.1.6): split a face (or
// close a boundary loop into a face) with a new edge, and join two faces by deleting the edge
// between them. They are what editing functions (truncate, bevel, extrude) are built from.
#pragma once

#include "euler_common.hpp"

namespace hmira {

/// What make_edge_face created.
template <class M, class T = default_traits<M>>
struct make_edge_face_result {
    /// The new edge, running from target(h0) to target(h1) on the side of the old face;
    /// kill_edge_face(mesh, halfedge) undoes the operator.
    typename T::halfedge_handle halfedge;
    typename T::face_handle face;  ///< the new face, on the side of h1 (it contains h1)
};

/// What kill_edge_face left, enough to redo: make_edge_face(mesh, h0, h1) recreates the edge
/// and a face with the killed face's loop.
template <class M, class T = default_traits<M>>
struct kill_edge_face_result {
    typename T::face_handle face;  ///< the surviving face (null if the killed face joined the boundary)
    /// The corner halfedges to pass back to make_edge_face.
    ///@{
    typename T::halfedge_handle h0, h1;
    ///@}
};

/// makeEF (MEF): a new edge from target(h0) to target(h1) that splits the loop holding both
/// halfedges in two, and a new face for the part that contains h1.
///
/// h0 and h1 are corners of one loop: the outer loop of a face, one of its inner rings, or a
/// boundary loop (null face; then the new face closes part of the boundary, and the other
/// part stays boundary). Afterwards the old face's loop is `h0 -> new edge -> old next(h1)`
/// and the new face's loop is `h1 -> opposite -> old next(h0)`. Inner rings stay with the old
/// face. E + 1, F + 1.
///
/// Errors (mesh unchanged): errc::invalid_handle; errc::topology when h0 and h1 lie on
/// different faces, on different loops of one face (that is make_edge_kill_ring), or end at
/// the same vertex (the edge would be a loop).
/// Complexity O(face degree): the new face's halfedges are re-pointed; plus, on a boundary
/// loop, O(V_adjacentV) for the vertices that must keep storing a boundary halfedge, and
/// O(rings of the face) where the model has rings.
template <class M, class T = default_traits<M>>
    requires euler_mutable_mesh<M, T>
result<make_edge_face_result<M, T>> make_edge_face(M& mesh, typename T::halfedge_handle h0,
                                                   typename T::halfedge_handle h1) {
    namespace de = detail::euler;
    if (!de::usable<M, T>(mesh, h0) || !de::usable<M, T>(mesh, h1)) [[unlikely]]
        return de::refuse([&] {
            const auto bad = de::usable<M, T>(mesh, h0) ? h1 : h0;
            return fail(errc::invalid_handle,
                        "make_edge_face: corner " + de::name<M, T>("halfedge", mesh, bad) + " does not exist",
                        de::index_of<M, T>(mesh, bad));
        });
    const auto f = T::face(mesh, h0);
    if (T::face(mesh, h1) != f) [[unlikely]]
        return de::refuse([&] {
            return fail(errc::topology,
                        "make_edge_face: the corners lie on different faces (" + de::name<M, T>("face", mesh, f) +
                            " and " + de::name<M, T>("face", mesh, T::face(mesh, h1)) +
                            "); a new edge and face need two corners of one face",
                        de::index_of<M, T>(mesh, h1));
        });
    const auto s = T::target(mesh, h0), t = T::target(mesh, h1);
    if (s == t) [[unlikely]]
        return de::refuse([&] {
            return fail(errc::topology,
                        "make_edge_face: both corners are at " + de::name<M, T>("vertex", mesh, s) +
                            "; the new edge would be a loop",
                        de::index_of<M, T>(mesh, s));
        });
    const auto n0 = T::next(mesh, h0), n1 = T::next(mesh, h1);
    // A face without inner rings has one loop, so two corners on it are on one loop. Only a
    // boundary (one null face, many loops) or a face with rings needs the walk: the part that
    // becomes the new face runs from next(h0) to h1, and finding h1 there proves both corners
    // are on one loop.
    if (f == T::null_face() || de::has_rings<M, T>(mesh, f)) {
        for (auto x = n0;; x = T::next(mesh, x)) {
            if (x == h1) break;
            if (x == h0) [[unlikely]]
                return de::refuse([&] {
                    return fail(errc::topology,
                                "make_edge_face: the corners lie on different loops of " +
                                    de::name<M, T>("face", mesh, f) +
                                    " (an inner ring and another loop); joining two loops is make_edge_kill_ring",
                                de::index_of<M, T>(mesh, f));
                });
        }
    }

    const auto a = T::new_edge(mesh, s, t);
    const auto b = T::opposite(mesh, a);
    const auto g = T::new_face(mesh);
    T::set_next(mesh, h0, a);
    T::set_next(mesh, a, n1);
    T::set_next(mesh, h1, b);
    T::set_next(mesh, b, n0);
    T::set_face(mesh, a, f);
    T::set_face(mesh, b, g);
    T::set_face_halfedge(mesh, g, b);

    if (f != T::null_face()) {
        // Whatever the old face stored on the part that left must move back onto its side:
        // compared while the part is re-pointed, which costs no extra read of the loop.
        const auto stored = T::face_halfedge(mesh, f);
        bool moved = false;
        for (auto x = n0; x != b; x = T::next(mesh, x)) {
            T::set_face(mesh, x, g);
            moved |= x == stored;
        }
        if (moved) T::set_face_halfedge(mesh, f, a);
        if constexpr (inner_ring_mutable_mesh<M, T>) {
            if (de::has_rings<M, T>(mesh, f)) {
                typename T::halfedge_handle ring = T::null_halfedge();
                for (auto r : T::inner_rings(mesh, f))
                    if (T::face(mesh, r) == g) {
                        ring = r;
                        break;
                    }
                if (ring != T::null_halfedge()) de::replace_ring_halfedge<M, T>(mesh, f, ring, a);
            }
        }
    } else {
        for (auto x = n0; x != b; x = T::next(mesh, x)) T::set_face(mesh, x, g);
        // Closing part of a boundary loop: vertices there may have stored a halfedge that is
        // no longer boundary, yet still be on the boundary (through the other part).
        auto x = b;
        do {
            de::prefer_boundary_halfedge<M, T>(mesh, T::target(mesh, x));
            x = T::next(mesh, x);
        } while (x != b);
    }
    return make_edge_face_result<M, T>{a, g};
}

/// killEF (KEF): deletes the edge of `halfedge` and the face on its other side, whose loop
/// joins the loop of `halfedge` (the inverse of make_edge_face: pass its result's halfedge).
///
/// The face of `halfedge` survives; it may be null (the boundary), and then the killed face
/// becomes part of the boundary. E - 1, F - 1.
///
/// Errors (mesh unchanged): errc::invalid_handle; errc::topology when there is no face on
/// the other side (a boundary or wire edge: nothing to kill), when both sides lie on the
/// same face (a bridge: removing it splits a loop, which is kill_edge_make_ring), or when the
/// face to kill has inner rings (moving them would make the operator irreversible).
/// Complexity O(face degree) (the killed face's halfedges are re-pointed), plus
/// O(V_adjacentV) when the face joins the boundary.
template <class M, class T = default_traits<M>>
    requires euler_mutable_mesh<M, T>
result<kill_edge_face_result<M, T>> kill_edge_face(M& mesh, typename T::halfedge_handle halfedge) {
    namespace de = detail::euler;
    const auto h = halfedge;
    if (!de::usable<M, T>(mesh, h)) [[unlikely]]
        return de::refuse([&] {
            return fail(errc::invalid_handle,
                        "kill_edge_face: " + de::name<M, T>("halfedge", mesh, h) + " does not exist",
                        de::index_of<M, T>(mesh, h));
        });
    const auto o = T::opposite(mesh, h);
    const auto f = T::face(mesh, h), g = T::face(mesh, o);
    if (g == T::null_face()) [[unlikely]]
        return de::refuse([&] {
            return fail(errc::topology,
                        "kill_edge_face: " + de::name<M, T>("halfedge", mesh, h) +
                            " has no face on its other side (a boundary or wire edge), so there is no face to kill",
                        de::index_of<M, T>(mesh, h));
        });
    if (f == g) [[unlikely]]
        return de::refuse([&] {
            return fail(errc::topology,
                        "kill_edge_face: both sides of the edge lie on " + de::name<M, T>("face", mesh, f) +
                            " (a bridge); removing it would split a loop: use kill_edge_make_ring",
                        de::index_of<M, T>(mesh, h));
        });
    // Moving the rings to the surviving face would not be undone by make_edge_face (which
    // leaves rings with the old face), so the operator refuses instead: kill_edge_face is then
    // exactly inverted by make_edge_face.
    if (de::has_rings<M, T>(mesh, g)) [[unlikely]]
        return de::refuse([&] {
            return fail(
                errc::topology,
                "kill_edge_face: " + de::name<M, T>("face", mesh, g) +
                    " has inner rings; make them faces (make_face_kill_ring) or join them (make_edge_kill_ring) first",
                de::index_of<M, T>(mesh, g));
        });

    const auto hp = T::prev(mesh, h), hn = T::next(mesh, h);
    const auto op = T::prev(mesh, o), on = T::next(mesh, o);
    const auto s = T::target(mesh, o), t = T::target(mesh, h);
    for (auto x = on; x != o; x = T::next(mesh, x)) T::set_face(mesh, x, f);
    T::set_next(mesh, hp, on);
    T::set_next(mesh, op, hn);
    de::replace_vertex_halfedge<M, T>(mesh, s, h, on);
    de::replace_vertex_halfedge<M, T>(mesh, t, o, hn);
    if (f != T::null_face()) {
        if (T::face_halfedge(mesh, f) == h) T::set_face_halfedge(mesh, f, hp);
        if (de::has_rings<M, T>(mesh, f))
            de::replace_ring_halfedge<M, T>(mesh, f, h, hp);  // (tested inline: the call was not inlined)
    } else {
        // The killed face's vertices are on the boundary now.
        for (auto x = on; x != hn; x = T::next(mesh, x)) {
            const auto v = T::target(mesh, T::opposite(mesh, x));
            if (T::face(mesh, T::vertex_halfedge(mesh, v)) != T::null_face()) T::set_vertex_halfedge(mesh, v, x);
        }
    }
    T::erase_edge(mesh, T::edge(mesh, h));
    T::erase_face(mesh, g);
    return kill_edge_face_result<M, T>{f, hp, op};
}

}  // namespace hmira
