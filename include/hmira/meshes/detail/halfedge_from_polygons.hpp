// hmira/meshes/detail/halfedge_from_polygons.hpp
// basic_halfedge_mesh built from indexed polygons (from_polygons, assign_polygons): the per-face
// checks, the one-pass link over the corners, and the slower checked link that runs only on a
// refused input, to name the same faulty element whatever the face order. A friend of the mesh,
// writing its records directly; everything is an inline template.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "../../core/huge_pages.hpp"
#include "../../core/result.hpp"
#include "../handles.hpp"
#include "trivial_array.hpp"

namespace hmira::detail {

/// The polygon building of basic_halfedge_mesh (Mesh), kept out of the class body.
template <class Mesh>
struct halfedge_from_polygons {
    // from_polygons' work, over any offset width; fill_positions(positions_) runs only once
    // every check has passed, so that a refused input is never consumed. The per-face checks
    // come first, in face order; then link_polygons_fast builds the mesh in one pass over the
    // corners and, if it meets anything wrong, link_polygons_checked builds it again in the
    // order that names the same element every time (what the error messages promise).
    template <class Offset, class FillPositions>
    static result<Mesh> build(std::size_t nv, FillPositions&& fill_positions, std::span<const Offset> face_offsets,
                              std::span<const std::uint32_t> corners) {
        using u32 = std::uint32_t;
        constexpr u32 none = UINT32_MAX;
        const std::size_t nf = face_offsets.empty() ? 0 : face_offsets.size() - 1;
        const std::size_t nc = corners.size();
        if ((nf == 0 && nc != 0) || (nf > 0 && (face_offsets[0] != 0 || face_offsets[nf] != nc)))
            return fail(errc::invalid_argument,
                        "from_polygons: face_offsets must start at 0 and end at corners.size()");
        if (nc >= none / 2 || nv >= none)
            return fail(errc::invalid_argument, "from_polygons: too many elements for 32-bit indices");
        if (nf >= none) return fail(errc::invalid_argument, "from_polygons: too many elements for 32-bit indices");

        // Corners counted by source vertex; a corner's target is the next corner's vertex, read
        // from the face when needed rather than stored (less memory to fault in).
        std::vector<u32> stamp, out_begin;
        detail::reserve_huge(stamp, nv);
        detail::reserve_huge(out_begin, nv + 1);
        stamp.assign(nv, none);
        out_begin.assign(nv + 1, 0);
        for (std::size_t f = 0; f < nf; ++f) {
            // An offset past the end is refused before any corner is read (a decrease is caught
            // one face later, too late for a face that runs past the end).
            if (face_offsets[f + 1] < face_offsets[f] || face_offsets[f + 1] > nc)
                return fail(errc::invalid_argument, "from_polygons: face_offsets decrease at face " + std::to_string(f),
                            static_cast<long long>(f));
            const u32 b = static_cast<u32>(face_offsets[f]), e = static_cast<u32>(face_offsets[f + 1]);
            if (e - b < 3)
                return fail(errc::degenerate_face,
                            "from_polygons: face " + std::to_string(f) + " has fewer than 3 vertices",
                            static_cast<long long>(f));
            for (u32 k = b; k < e; ++k) {
                const u32 v = corners[k];
                if (v >= nv)
                    return fail(errc::invalid_handle,
                                "from_polygons: face " + std::to_string(f) + " names vertex " + std::to_string(v) +
                                    ", which does not exist",
                                static_cast<long long>(f));
                if (stamp[v] == f)
                    return fail(errc::degenerate_face,
                                "from_polygons: face " + std::to_string(f) + " repeats vertex " + std::to_string(v),
                                static_cast<long long>(f));
                stamp[v] = static_cast<u32>(f);
                ++out_begin[v + 1];
            }
        }
        for (std::size_t v = 0; v < nv; ++v) out_begin[v + 1] += out_begin[v];  // out_begin[v]: where v's row starts
        Mesh m;
        if (!link_polygons_fast(m, face_offsets, corners, out_begin, stamp)) {
            m = Mesh();
            if (auto linked = link_polygons_checked(m, face_offsets, corners, out_begin, stamp); !linked)
                return linked.error();
        }
        const std::size_t edges = m.halfedges_.size() / 2;
        fill_positions(m.positions_);
        m.vertex_deleted_.ensure(nv);
        m.edge_deleted_.ensure(edges);
        m.face_deleted_.ensure(nf);
        m.vertex_props_.resize(nv);
        m.edge_props_.resize(edges);
        m.halfedge_props_.resize(2 * edges);
        m.face_props_.resize(nf);
        m.changes_ = 1;
        return m;
    }

    // Whether the halfedges leaving v, `degree` of them, all lie in the one fan around it:
    // the walk from m.vertex_out_[v] comes back after exactly `degree` steps. O(degree).
    static bool single_fan(const Mesh& m, std::uint32_t v, std::uint32_t degree) {
        const auto start = m.vertex_out_[v];
        if (start.is_null()) return true;
        std::uint32_t around = 0;
        auto h = start;
        do {
            h = m.halfedges_[h.index ^ 1u].next;
            ++around;
        } while (h != start && around <= degree);
        return around == degree;
    }

    // One corner as seen from its vertex v: the vertices before (p) and after (x) it in its
    // face, the corner's own index k (its halfedge runs v -> x) and the index kp of the
    // corner before it (whose halfedge runs p -> v).
    struct corner_at_vertex {
        std::uint32_t p, x, k, kp;
    };

    // The connectivity of checked polygons (`out_begin[v]` where v's row of corners starts,
    // `stamp` scratch of one entry per vertex) into the empty mesh m. Every question the link
    // asks is about one vertex at a time, so the corners are first grouped by vertex (rows,
    // filled in corner order) and each row is then read on its own, in contiguous memory:
    // - the twin of the halfedge v -> x of a corner is the halfedge x -> v coming into v in
    //   the row's corner whose p is x (none: a boundary edge);
    // - next(twin(h)) is that corner's outgoing halfedge, so the walk around v that add_face
    //   and validate take is a walk along the row, and v has one fan when that walk covers
    //   the row (from the corner no halfedge comes into, when v is on the boundary).
    // Edges are then numbered in order of their first corner, as in link_polygons_checked:
    // a corner whose twin comes later (or has none) makes edge e, halfedge 2e, its twin (or the
    // boundary halfedge) 2e + 1. False (m then half-built) on anything wrong: an edge run
    // twice the same way, a vertex with two boundary gaps or several fans.
    template <class Offset>
    static bool link_polygons_fast(Mesh& m, std::span<const Offset> face_offsets,
                                   std::span<const std::uint32_t> corners, const std::vector<std::uint32_t>& out_begin,
                                   std::vector<std::uint32_t>& stamp) {
        using u32 = std::uint32_t;
        constexpr u32 none = UINT32_MAX;
        const std::size_t nv = out_begin.size() - 1, nf = face_offsets.empty() ? 0 : face_offsets.size() - 1,
                          nc = corners.size();
        std::copy(out_begin.begin(), out_begin.end() - 1, stamp.begin());  // stamp[v]: where v's row ends so far
        detail::trivial_array<corner_at_vertex> rows;
        rows.resize_for_overwrite(nc);  // every entry written here, row by row
        for (std::size_t f = 0; f < nf; ++f) {
            const u32 b = static_cast<u32>(face_offsets[f]), e = static_cast<u32>(face_offsets[f + 1]);
            for (u32 k = b; k < e; ++k) {
                const u32 kp = k == b ? e - 1 : k - 1, kn = k + 1 == e ? b : k + 1;
                rows[stamp[corners[k]]++] = {corners[kp], corners[kn], k, kp};
            }
        }
        // Twins, one row at a time: twin[k] the corner whose halfedge is the twin of corner k's,
        // none on the boundary. The boundary halfedges around a vertex v are the twins of the
        // halfedge leaving v that has no twin (entering v) and of the one entering v that has
        // none (leaving v): one pair of corners per boundary vertex, kept in `gaps`.
        detail::trivial_array<u32> twin;
        twin.resize_for_overwrite(nc);
        struct gap {
            u32 v, k_in, k_out;  // twin(halfedge of k_in) enters v, twin(halfedge of k_out) leaves it
        };
        std::vector<gap> gaps;
        std::vector<u32> after;  // after[i]: the row entry that the walk around the vertex visits after entry i
        std::vector<unsigned char> entered;
        for (std::size_t v = 0; v < nv; ++v) {
            const corner_at_vertex* row = rows.data() + out_begin[v];
            const u32 d = out_begin[v + 1] - out_begin[v];
            if (d == 0) continue;
            if (after.size() < d) {
                after.resize(d);
                entered.resize(d);
            }
            std::fill(entered.begin(), entered.begin() + d, 0);
            // Entry i's halfedge v -> x pairs with the first entry whose p is x. An edge run
            // twice the same way shows in the row of its source: both its entries pair with the
            // same entry (caught by `entered`), or neither pairs (two gaps).
            u32 k_in = none, start = 0, open = 0;
            for (u32 i = 0; i < d; ++i) {
                const u32 x = row[i].x;
                u32 j = 0;
                while (j < d && row[j].p != x) ++j;
                if (j == d) {
                    after[i] = none;
                    twin[row[i].k] = none;
                    k_in = row[i].k;
                    ++open;
                    continue;
                }
                if (entered[j]) return false;  // x -> v paired twice: v -> x is run twice
                entered[j] = 1;
                after[i] = j;
                twin[row[i].k] = row[j].kp;
            }
            if (open > 1) return false;  // two boundary gaps: two fans
            if (open == 1) {
                while (entered[start]) ++start;  // the corner no halfedge comes into
                gaps.push_back({static_cast<u32>(v), k_in, row[start].kp});
            }
            u32 steps = 0, i = start;
            do {
                i = after[i];
                ++steps;
            } while (i != none && i != start && steps <= d);
            if (steps != d) return false;
        }
        // Halfedges of the corners: the first corner of an edge (by corner index) gets 2e.
        detail::trivial_array<u32> corner_h;
        corner_h.resize_for_overwrite(nc);
        u32 edges = 0;
        for (u32 k = 0; k < nc; ++k) {
            const u32 t = twin[k];
            if (t != none && t < k) continue;  // corner_h[k] was written with its twin
            corner_h[k] = 2 * edges;
            if (t != none) corner_h[t] = 2 * edges + 1;
            ++edges;
        }
        m.vertex_out_.assign(nv, halfedge_handle{});
        m.halfedges_.resize_for_overwrite(2 * std::size_t{edges});
        m.faces_.resize_for_overwrite(nf);
        for (std::size_t f = 0; f < nf; ++f) {
            const u32 b = static_cast<u32>(face_offsets[f]), e = static_cast<u32>(face_offsets[f + 1]);
            const face_handle fh(static_cast<u32>(f));
            u32 h_prev = corner_h[e - 1], h = corner_h[b];
            for (u32 k = b; k < e; ++k) {
                const u32 k_next = k + 1 == e ? b : k + 1, h_next = corner_h[k_next], a = corners[k];
                m.halfedges_[h] = {vertex_handle(corners[k_next]), fh, halfedge_handle(h_next),
                                   halfedge_handle(h_prev)};
                if (twin[k] == none) m.halfedges_[h ^ 1u] = {vertex_handle(a), {}, {}, {}};  // linked below
                m.vertex_out_[a] = halfedge_handle(h);  // the last corner's, as add_face leaves it
                h_prev = h;
                h = h_next;
            }
            m.faces_[f] = halfedge_handle(corner_h[e - 1]);
        }
        // Boundary loops: the boundary halfedge entering a vertex continues with the one leaving it.
        for (const gap& g : gaps) {
            const u32 h_in = corner_h[g.k_in] ^ 1u, h_out = corner_h[g.k_out] ^ 1u;
            m.halfedges_[h_in].next = halfedge_handle(h_out);
            m.halfedges_[h_out].prev = halfedge_handle(h_in);
            m.vertex_out_[g.v] = halfedge_handle(h_out);
        }
        return true;
    }

    // link_polygons_fast's mesh, or the first fault in a fixed order: an edge run twice by
    // its source vertex, then boundary gaps in corner order, then fans by vertex. Slower (more
    // passes, 24 bytes of scratch per corner); run only when the fast pass found a fault.
    template <class Offset>
    static result<void> link_polygons_checked(Mesh& m, std::span<const Offset> face_offsets,
                                              std::span<const std::uint32_t> corners,
                                              const std::vector<std::uint32_t>& out_begin,
                                              std::vector<std::uint32_t>& stamp) {
        using u32 = std::uint32_t;
        constexpr u32 none = UINT32_MAX;
        const std::size_t nv = out_begin.size() - 1, nf = face_offsets.empty() ? 0 : face_offsets.size() - 1,
                          nc = corners.size();
        // Corners grouped by source vertex, with their targets beside them so that the twin
        // search below scans contiguous memory.
        std::vector<u32> out(nc), out_target(nc);
        std::copy(out_begin.begin(), out_begin.end() - 1, stamp.begin());  // stamp[v]: where v's row ends so far
        for (std::size_t f = 0; f < nf; ++f) {
            const u32 b = static_cast<u32>(face_offsets[f]), e = static_cast<u32>(face_offsets[f + 1]);
            for (u32 k = b; k < e; ++k) {
                const u32 i = stamp[corners[k]]++;
                out[i] = k;
                out_target[i] = corners[k + 1 == e ? b : k + 1];
            }
        }
        // Twins: the corner running the same edge backwards; the same direction twice is an error.
        std::vector<u32> twin(nc, none);
        for (std::size_t a = 0; a < nv; ++a) {
            const u32 rb = out_begin[a], re = out_begin[a + 1];
            for (u32 i = rb; i < re; ++i) {
                const u32 b = out_target[i];
                for (u32 j = i + 1; j < re; ++j)
                    if (out_target[j] == b) {
                        bool reverse = false;
                        for (u32 r = out_begin[b]; r < out_begin[b + 1]; ++r) reverse |= out_target[r] == a;
                        return fail(reverse ? errc::non_manifold : errc::orientation_conflict,
                                    "from_polygons: edge " + std::to_string(a) + "->" + std::to_string(b) +
                                        (reverse ? " has more than two faces"
                                                 : " is run in the same direction by two faces (they are wound against "
                                                   "each other)"),
                                    static_cast<long long>(a));
                    }
                for (u32 r = out_begin[b]; r < out_begin[b + 1]; ++r)
                    if (out_target[r] == a) {
                        twin[out[i]] = out[r];
                        break;
                    }
            }
        }
        std::size_t edges = 0;
        for (u32 k = 0; k < nc; ++k) edges += (twin[k] == none || twin[k] > k);
        // Halfedge of each corner: 2e for the first corner of an edge, 2e + 1 for its twin or
        // for the boundary halfedge opposite an unpaired corner.
        std::vector<u32>& corner_h = out_target;  // reuse: the grouping is no longer needed after this
        {
            u32 e = 0;
            for (u32 k = 0; k < nc; ++k) {
                if (twin[k] != none && twin[k] < k) continue;
                corner_h[k] = 2 * e;
                if (twin[k] != none) corner_h[twin[k]] = 2 * e + 1;
                ++e;
            }
        }
        m.vertex_out_.assign(nv, halfedge_handle{});
        m.halfedges_.resize_for_overwrite(2 * edges);  // every record is written below, first touched there
        m.faces_.resize_for_overwrite(nf);
        std::fill(stamp.begin(), stamp.end(), none);  // now: the boundary halfedge leaving each vertex
        for (std::size_t f = 0; f < nf; ++f) {
            const u32 b = static_cast<u32>(face_offsets[f]), e = static_cast<u32>(face_offsets[f + 1]);
            const face_handle fh(static_cast<u32>(f));
            for (u32 k = b; k < e; ++k) {
                const u32 h = corner_h[k];
                const u32 to = corners[k + 1 == e ? b : k + 1];
                m.halfedges_[h] = {vertex_handle(to), fh, halfedge_handle(corner_h[k + 1 == e ? b : k + 1]),
                                   halfedge_handle(corner_h[k == b ? e - 1 : k - 1])};
                if (twin[k] == none) {
                    const u32 from = to;  // the boundary halfedge runs target -> source
                    if (stamp[from] != none)
                        return fail(errc::non_manifold,
                                    "from_polygons: vertex " + std::to_string(from) +
                                        " joins two or more separate fans of faces",
                                    static_cast<long long>(from));
                    stamp[from] = h ^ 1u;
                    // next and prev: the boundary loops below
                    m.halfedges_[h ^ 1u] = {vertex_handle(corners[k]), {}, {}, {}};
                }
            }
            m.faces_[f] = halfedge_handle(corner_h[e - 1]);
        }
        // Boundary loops: the boundary halfedge entering a vertex continues with the one leaving it.
        for (std::size_t v = 0; v < nv; ++v)
            if (stamp[v] != none) {
                const u32 hb = stamp[v];
                const u32 to = m.halfedges_[hb].target.index;
                const u32 nb = stamp[to];
                if (nb == none)  // cannot happen: boundary halfedges enter and leave a vertex equally often
                    return fail(errc::non_manifold,
                                "from_polygons: boundary breaks off at vertex " + std::to_string(to),
                                static_cast<long long>(to));
                m.halfedges_[hb].next = halfedge_handle(nb);
                m.halfedges_[nb].prev = halfedge_handle(hb);
                m.vertex_out_[v] = halfedge_handle(hb);
            }
        // A vertex with no boundary keeps the halfedge of one of its corners.
        for (u32 k = 0; k < nc; ++k) {
            const u32 v = corners[k];
            if (stamp[v] == none) m.vertex_out_[v] = halfedge_handle(corner_h[k]);
        }
        // Every outgoing halfedge of a vertex must lie in the one fan around it.
        for (std::size_t v = 0; v < nv; ++v)
            if (!single_fan(m, static_cast<u32>(v), out_begin[v + 1] - out_begin[v] + (stamp[v] != none ? 1u : 0u)))
                return fail(errc::non_manifold,
                            "from_polygons: vertex " + std::to_string(v) + " joins two or more separate fans of faces",
                            static_cast<long long>(v));
        return {};
    }
};

}  // namespace hmira::detail
