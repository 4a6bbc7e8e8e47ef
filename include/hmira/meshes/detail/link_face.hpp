// hmira/meshes/detail/link_face.hpp
// Adding a face to a half-edge structure, written once over the raw halfedge layer
// (halfedge_mutable_mesh), as CGAL's Euler::add_face is: halfedge_mesh and winged_edge_mesh
// both build their faces with it, and any model with that layer could.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/result.hpp"

namespace hmira::detail {

/// Buffers link_face reuses from call to call for faces too large for its stack arrays, so that
/// building a mesh face by face does not allocate per face. A mesh keeps one and passes it in.
template <class Halfedge>
struct face_link_scratch {
    std::vector<Halfedge> sides;                       ///< the halfedge of each side, once known
    std::vector<std::uint8_t> fresh;                   ///< whether that side's edge is new
    std::vector<std::pair<Halfedge, Halfedge>> links;  ///< next links to set, computed first
    std::vector<Halfedge> starts;                      ///< each corner's stored outgoing halfedge
};

namespace linking {

template <class M, class T>
std::string vertex_name(const M& m, typename T::vertex_handle v) {
    if constexpr (vertex_index_mesh<M, T>)
        return std::to_string(T::vertex_index(m, v));
    else {
        (void)m;
        (void)v;
        return "(unnumbered)";
    }
}
template <class M, class T>
long long vertex_number(const M& m, typename T::vertex_handle v) {
    if constexpr (vertex_index_mesh<M, T>)
        return static_cast<long long>(T::vertex_index(m, v));
    else {
        (void)m;
        (void)v;
        return -1;
    }
}

/// For re-linking at the vertex between `in` (incoming) and `out` (outgoing): the boundary
/// halfedge that closes out's fan on its far side, where the patch between them can move;
/// null if that is `in` itself (the new face would close the fan into a disk while other fans
/// still touch the vertex: non-manifold). O(V_adjacentV).
template <class M, class T>
typename T::halfedge_handle free_gap(const M& m, typename T::halfedge_handle in, typename T::halfedge_handle out) {
    auto h = T::opposite(m, out);
    const auto start = h;
    do {
        h = T::opposite(m, T::next(m, h));
        if (T::face(m, h) == T::null_face()) return h == in ? T::null_halfedge() : h;
    } while (h != start);
    return T::null_halfedge();
}

/// After v's stored outgoing halfedge `start` gained a face: stores another boundary halfedge
/// out of v, or keeps start if none is left (v is now interior). The fan is walked from start
/// both ways at once, forward by next(opposite) and backward by opposite(prev), until a
/// boundary halfedge turns up or the two walks meet: the two chains of dependent reads overlap,
/// which matters because a vertex that closes needs its whole fan walked (a sixth of building a
/// mesh face by face went into that walk when it went one way). O(V_adjacentV).
template <class M, class T>
void store_boundary_halfedge(M& m, typename T::vertex_handle v, typename T::halfedge_handle start) {
    const auto null_f = T::null_face();
    auto f = start, b = start;
    for (;;) {
        f = T::next(m, T::opposite(m, f));
        if (f == b) return;
        if (T::face(m, f) == null_f) break;
        b = T::opposite(m, T::prev(m, b));
        if (b == f) return;
        if (T::face(m, b) == null_f) {
            f = b;
            break;
        }
    }
    T::set_vertex_halfedge(m, v, f);
}

}  // namespace linking

/// Makes v's stored outgoing halfedge a boundary one if v has any. O(V_adjacentV).
template <class M, class T>
void prefer_boundary_halfedge(M& m, typename T::vertex_handle v) {
    const auto start = T::vertex_halfedge(m, v);
    if (start == T::null_halfedge()) return;
    auto h = start;
    do {
        if (T::face(m, h) == T::null_face()) {
            if (h != start) T::set_vertex_halfedge(m, v, h);
            return;
        }
        h = T::next(m, T::opposite(m, h));
    } while (h != start);
}

namespace linking {

/// The corner after corner i of a face of n corners.
constexpr std::size_t corner_after(std::size_t i, std::size_t n) { return i + 1 == n ? std::size_t{0} : i + 1; }

/// The first stage of link_face_sized: each corner's stored halfedge (starts), whether it is
/// interior (fresh[i] = 4, reported in order by check_corners), and the existing halfedge from
/// it to the next corner, or null (sides). The first reads of each corner (its stored halfedge,
/// then that halfedge's record) are likely cache misses that do not depend on the other
/// corners': each stage is done for all corners before the next, so that their misses overlap
/// instead of queueing behind each corner's fan walk.
template <std::size_t N, class M, class T>
void find_sides(M& m, const typename T::vertex_handle* vs, std::size_t n_run, typename T::halfedge_handle* starts,
                typename T::halfedge_handle* sides, std::uint8_t* fresh) {
    const std::size_t n = N != 0 ? N : n_run;
    const auto null_h = T::null_halfedge();
    for (std::size_t i = 0; i < n; ++i) starts[i] = T::vertex_halfedge(m, vs[i]);
    for (std::size_t i = 0; i < n; ++i) {
        fresh[i] = starts[i] != null_h && T::face(m, starts[i]) != T::null_face() ? 4 : 0;
        sides[i] = null_h;
    }
    for (std::size_t i = 0; i < n; ++i) {
        const auto start = starts[i];
        if (start == null_h) continue;
        const auto b = vs[corner_after(i, n)];
        auto h = start;
        do {
            if (T::target(m, h) == b) {
                sides[i] = h;
                break;
            }
            h = T::next(m, T::opposite(m, h));
        } while (h != start);
    }
}

/// Every check of link_face_sized, before anything changes, reporting the same first failure,
/// in corner order, as a corner-by-corner pass would: an interior corner, an edge that already
/// has two faces or runs the wrong way, a corner with no free boundary gap. On success
/// fresh[i] is 1 where the side from corner i is a new edge, else 0.
template <std::size_t N, class M, class T>
result<void> check_corners(M& m, const typename T::vertex_handle* vs, std::size_t n_run,
                           const typename T::halfedge_handle* sides, std::uint8_t* fresh) {
    const std::size_t n = N != 0 ? N : n_run;
    const auto null_h = T::null_halfedge();
    for (std::size_t i = 0; i < n; ++i) {
        if (fresh[i] & 4)
            return fail(errc::non_manifold,
                        "add_face: vertex " + linking::vertex_name<M, T>(m, vs[i]) +
                            " is interior (surrounded by faces); a face there would be non-manifold",
                        linking::vertex_number<M, T>(m, vs[i]));
        const auto h = sides[i];
        if (h != null_h && T::face(m, h) != T::null_face()) {
            const bool reversed = T::face(m, T::opposite(m, h)) == T::null_face();
            std::string edge =
                linking::vertex_name<M, T>(m, vs[i]) + "->" + linking::vertex_name<M, T>(m, vs[corner_after(i, n)]);
            std::string face = "face";
            if constexpr (face_index_mesh<M, T>) face += " " + std::to_string(T::face_index(m, T::face(m, h)));
            return fail(reversed ? errc::orientation_conflict : errc::non_manifold,
                        "add_face: edge " + edge +
                            (reversed ? " is already used in this direction by " + face +
                                            " (the new face is wound against its neighbour)"
                                      : " already has two faces"),
                        linking::vertex_number<M, T>(m, vs[i]));
        }
        fresh[i] = h == null_h;
    }
    // A corner between two existing edges must be able to move the boundary patch between them
    // to another gap of the vertex; check them all first so that a failure changes nothing.
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t ii = corner_after(i, n);
        if (fresh[i] || fresh[ii] || T::next(m, sides[i]) == sides[ii]) continue;
        if (linking::free_gap<M, T>(m, sides[i], sides[ii]) == null_h)
            return fail(errc::non_manifold,
                        "add_face: vertex " + linking::vertex_name<M, T>(m, vs[ii]) +
                            " has no free boundary gap to move its fans to",
                        linking::vertex_number<M, T>(m, vs[ii]));
    }
    return {};
}

/// Re-links each corner between two existing edges: the boundary patch between `in` and `out`
/// moves into the vertex's free gap, so the two become consecutive.
template <std::size_t N, class M, class T>
void relink_patches(M& m, std::size_t n_run, const typename T::halfedge_handle* sides, const std::uint8_t* fresh) {
    const std::size_t n = N != 0 ? N : n_run;
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t ii = corner_after(i, n);
        const auto in = sides[i], out = sides[ii];
        if (fresh[i] || fresh[ii] || T::next(m, in) == out) continue;
        const auto gap_prev = linking::free_gap<M, T>(m, in, out);
        const auto gap_next = T::next(m, gap_prev);
        const auto patch_first = T::next(m, in), patch_last = T::prev(m, out);
        T::set_next(m, gap_prev, patch_first);
        T::set_next(m, patch_last, gap_next);
        T::set_next(m, in, out);
    }
}

/// Puts face f on the sides (new edges already made) and links them: the new next links are
/// computed from the state before this face into `links` and applied afterwards; each corner
/// keeps a boundary outgoing halfedge if it has one.
template <std::size_t N, class M, class T>
void link_sides(M& m, const typename T::vertex_handle* vs, std::size_t n_run, const typename T::halfedge_handle* sides,
                std::uint8_t* fresh, std::pair<typename T::halfedge_handle, typename T::halfedge_handle>* links,
                typename T::face_handle f) {
    using H = typename T::halfedge_handle;
    const std::size_t n = N != 0 ? N : n_run;
    const auto null_h = T::null_halfedge();
    std::size_t link_count = 0;
    auto add_link = [&](H a, H b) { links[link_count++] = {a, b}; };
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t ii = corner_after(i, n);
        const auto v = vs[ii];
        const auto in = sides[i], out = sides[ii];
        const bool in_new = (fresh[i] & 1) != 0, out_new = (fresh[ii] & 1) != 0;
        if (!in_new && !out_new) {
            // The only halfedge out of v that gains a face is `out`: v needs another boundary
            // halfedge (or none, if it closes) only when it stored that one.
            if (T::vertex_halfedge(m, v) == out) fresh[ii] |= 2;
        } else {
            const auto outer_in = T::opposite(m, out), outer_out = T::opposite(m, in);
            if (in_new && !out_new) {
                add_link(T::prev(m, out), outer_out);
                T::set_vertex_halfedge(m, v, outer_out);
            } else if (!in_new && out_new) {
                const auto boundary_next = T::next(m, in);
                add_link(outer_in, boundary_next);
                T::set_vertex_halfedge(m, v, boundary_next);
            } else if (T::vertex_halfedge(m, v) == null_h) {
                T::set_vertex_halfedge(m, v, outer_out);
                add_link(outer_in, outer_out);
            } else {
                const auto boundary_next = T::vertex_halfedge(m, v);
                add_link(T::prev(m, boundary_next), outer_out);
                add_link(outer_in, boundary_next);
            }
            add_link(in, out);
        }
        T::set_face(m, in, f);
    }
    for (std::size_t k = 0; k < link_count; ++k) T::set_next(m, links[k].first, links[k].second);
    // Every other corner still stores a boundary halfedge: the one it had, or one set above.
    for (std::size_t i = 0; i < n; ++i)
        if (fresh[i] & 2) linking::store_boundary_halfedge<M, T>(m, vs[i], sides[i]);
}

/// link_face for faces of N corners (N = 0: any number, n given at run time). With N known,
/// every loop over the corners unrolls and the corner after i is a constant: the `(i + 1) % n`
/// of the run-time loops is a division, and the one that names the vertex a fan walk looks for
/// sits on that walk's chain of dependent reads.
template <std::size_t N, class M, class T>
result<typename T::face_handle> link_face_sized(M& m, const typename T::vertex_handle* vs, std::size_t n_run,
                                                face_link_scratch<typename T::halfedge_handle>& scratch) {
    const std::size_t n = N != 0 ? N : n_run;
    // Small faces (nearly all) keep their working state on the stack rather than in the
    // scratch vectors, which would be filled and grown for every face.
    using H = typename T::halfedge_handle;
    constexpr std::size_t small = 8;
    std::array<H, small> small_sides, small_starts;
    std::array<std::uint8_t, small> small_fresh;
    std::array<std::pair<H, H>, 3 * small> small_links;
    H* sides = small_sides.data();
    H* starts = small_starts.data();
    std::uint8_t* fresh = small_fresh.data();
    std::pair<H, H>* links = small_links.data();
    if (n > small) {
        scratch.sides.resize(n);
        scratch.starts.resize(n);
        scratch.fresh.resize(n);
        scratch.links.resize(3 * n);  // each corner sets at most three next links
        sides = scratch.sides.data();
        starts = scratch.starts.data();
        fresh = scratch.fresh.data();
        links = scratch.links.data();
    }
    find_sides<N, M, T>(m, vs, n, starts, sides, fresh);
    if (auto ok = check_corners<N, M, T>(m, vs, n, sides, fresh); !ok) return ok.error();
    relink_patches<N, M, T>(m, n, sides, fresh);
    for (std::size_t i = 0; i < n; ++i)
        if (fresh[i]) sides[i] = T::new_edge(m, vs[i], vs[corner_after(i, n)]);
    const auto f = T::new_face(m);
    T::set_face_halfedge(m, f, sides[n - 1]);
    link_sides<N, M, T>(m, vs, n, sides, fresh, links, f);
    return f;
}

}  // namespace linking

/// Adds the face with corners `vs` (counter-clockwise seen from outside), reusing the edges
/// that exist and re-linking the boundary fans around its corners, so that no non-manifold
/// vertex or edge can appear. Faces may arrive in any order: a face may touch a vertex in a fan
/// of its own, separated from the vertex's other fans by boundary gaps (a pinch that validate()
/// reports until the faces between the fans are added). `exists(v)` says whether a vertex
/// handle names a live vertex.
///
/// \pre none: every failure is found before the first change.
/// \post on success the face's halfedges form one loop with the face on their side, every
/// corner stores a boundary outgoing halfedge if it has one, and each edge has at most two faces.
///
/// Fails, with the mesh unchanged, when the face has fewer than 3 or repeated vertices, names
/// a vertex that does not exist, would give an edge a third face or a face on the wrong side
/// (orientation conflict), or would make a vertex non-manifold. O(sum of V_adjacentV over the
/// corners).
template <class M, class T, class Exists>
    requires halfedge_mutable_mesh<M, T>
result<typename T::face_handle> link_face(M& m, std::span<const typename T::vertex_handle> vs,
                                          face_link_scratch<typename T::halfedge_handle>& scratch, Exists&& exists) {
    const std::size_t n = vs.size();
    if (n < 3)
        return fail(errc::degenerate_face, "add_face: a face needs at least 3 vertices, got " + std::to_string(n));
    for (std::size_t i = 0; i < n; ++i) {
        if (!exists(vs[i]))
            return fail(errc::invalid_handle,
                        "add_face: corner " + std::to_string(i) + " names vertex " +
                            linking::vertex_name<M, T>(m, vs[i]) + ", which does not exist",
                        linking::vertex_number<M, T>(m, vs[i]));
        for (std::size_t j = 0; j < i; ++j)
            if (vs[j] == vs[i])
                return fail(errc::degenerate_face,
                            "add_face: vertex " + linking::vertex_name<M, T>(m, vs[i]) + " appears twice in the face",
                            linking::vertex_number<M, T>(m, vs[i]));
    }
    // Triangles and quads, nearly every face, take the unrolled code.
    if (n == 3) return linking::link_face_sized<3, M, T>(m, vs.data(), n, scratch);
    if (n == 4) return linking::link_face_sized<4, M, T>(m, vs.data(), n, scratch);
    return linking::link_face_sized<0, M, T>(m, vs.data(), n, scratch);
}

}  // namespace hmira::detail
