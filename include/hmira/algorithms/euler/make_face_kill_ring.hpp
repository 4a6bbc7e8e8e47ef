// hmira/algorithms/euler/make_face_kill_ring.hpp
// Euler operators makeFkillR / killFmakeR (Mantyla's MFKRH / KFMRH, thesis 2.1.7-2.1.8): an
// inner ring becomes a face of its own, and a face becomes an inner ring of another face.
// killFmakeR is how a through-hole (genus) or the gluing of two shells is made.
#pragma once

#include "euler_common.hpp"

namespace hmira {

/// What make_face_kill_ring created.
template <class M, class T = default_traits<M>>
struct make_face_kill_ring_result {
    typename T::face_handle face;  ///< the new face, whose outer loop is the former ring
    typename T::face_handle host;  ///< the face that held the ring
};

/// What kill_face_make_ring made: make_face_kill_ring(mesh, ring) undoes it.
template <class M, class T = default_traits<M>>
struct kill_face_make_ring_result {
    typename T::halfedge_handle ring;  ///< a halfedge of the new inner ring
    typename T::face_handle host;      ///< the face that now holds it
};

/// makeFkillR (MFKRH): the inner ring through `ring` stops being a ring of its face and
/// becomes the outer loop of a new face (which faces the other way from the old host, as
/// the ring was wound as a hole). F + 1, R - 1, and S - H grows by one: a hole closes
/// (H - 1) or a shell splits off (S + 1).
///
/// Errors (mesh unchanged): errc::invalid_handle; errc::topology when `ring` lies on a
/// boundary loop or on the outer loop of its face.
/// Complexity O(ring size + rings of the host).
template <class M, class T = default_traits<M>>
    requires euler_ring_mutable_mesh<M, T>
result<make_face_kill_ring_result<M, T>> make_face_kill_ring(M& mesh, typename T::halfedge_handle ring) {
    namespace de = detail::euler;
    if (!de::usable<M, T>(mesh, ring))
        return fail(errc::invalid_handle,
                    "make_face_kill_ring: " + de::name<M, T>("halfedge", mesh, ring) + " does not exist",
                    de::index_of<M, T>(mesh, ring));
    const auto f = T::face(mesh, ring);
    if (f == T::null_face())
        return fail(errc::topology,
                    "make_face_kill_ring: " + de::name<M, T>("halfedge", mesh, ring) +
                        " is on a boundary loop, not on an inner ring",
                    de::index_of<M, T>(mesh, ring));
    const auto fh = T::face_halfedge(mesh, f);
    auto x = ring;
    do {
        if (x == fh)
            return fail(errc::topology,
                        "make_face_kill_ring: " + de::name<M, T>("halfedge", mesh, ring) + " is on the outer loop of " +
                            de::name<M, T>("face", mesh, f) + ", not on an inner ring",
                        de::index_of<M, T>(mesh, ring));
        x = T::next(mesh, x);
    } while (x != ring);

    T::remove_inner_ring(mesh, f, ring);
    const auto g = T::new_face(mesh);
    x = ring;
    do {
        T::set_face(mesh, x, g);
        x = T::next(mesh, x);
    } while (x != ring);
    T::set_face_halfedge(mesh, g, ring);
    return make_face_kill_ring_result<M, T>{g, f};
}

/// killFmakeR (KFMRH): deletes `face` and makes its outer loop an inner ring of `host`.
/// F - 1, R + 1, and S - H drops by one: if the two faces are on one shell a hole opens
/// (H + 1, as in a torus); if not, the two shells become one (S - 1). The caller places
/// the geometry: the loop should lie inside the host and be wound against it.
///
/// Errors (mesh unchanged): errc::invalid_handle; errc::topology when `face` is `host`, or
/// when `face` has inner rings of its own (make them faces first).
/// Complexity O(face degree).
template <class M, class T = default_traits<M>>
    requires euler_ring_mutable_mesh<M, T>
result<kill_face_make_ring_result<M, T>> kill_face_make_ring(M& mesh, typename T::face_handle face,
                                                             typename T::face_handle host) {
    namespace de = detail::euler;
    if (!de::usable<M, T>(mesh, face) || !de::usable<M, T>(mesh, host))
        return fail(errc::invalid_handle,
                    "kill_face_make_ring: " + de::name<M, T>("face", mesh, de::usable<M, T>(mesh, face) ? host : face) +
                        " does not exist",
                    de::index_of<M, T>(mesh, de::usable<M, T>(mesh, face) ? host : face));
    if (face == host)
        return fail(errc::topology,
                    "kill_face_make_ring: " + de::name<M, T>("face", mesh, face) + " cannot become a ring of itself",
                    de::index_of<M, T>(mesh, face));
    if (de::has_rings<M, T>(mesh, face))
        return fail(errc::topology,
                    "kill_face_make_ring: " + de::name<M, T>("face", mesh, face) +
                        " has inner rings of its own; make them faces first",
                    de::index_of<M, T>(mesh, face));
    const auto ring = T::face_halfedge(mesh, face);
    auto x = ring;
    do {
        T::set_face(mesh, x, host);
        x = T::next(mesh, x);
    } while (x != ring);
    T::add_inner_ring(mesh, host, ring);
    T::erase_face(mesh, face);
    return kill_face_make_ring_result<M, T>{ring, host};
}

}  // namespace hmira
