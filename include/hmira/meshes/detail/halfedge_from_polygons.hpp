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

    // The connectivity of checked polygons (`out_begin[v]` where v's row of corners starts,
    // `stamp` scratch of one entry per vertex) into the empty mesh m, in one pass over the
    // faces: each corner a->b looks for its twin b->a among the corners already seen leaving
    // b, and becomes edge 2e (a new edge) or the twin's halfedge + 1, so edges come in order
    // of their first corner, as in link_polygons_checked. A corner's record gets its target at
    // once (the row search reads it), the rest when its face is done; a boundary halfedge gets
    // its target when its edge is made, its links at the end. False (m then half-built) on
    // anything wrong: an edge run twice the same way, a vertex with two boundary gaps or
    // several fans.
    template <class Offset>
    static bool link_polygons_fast(Mesh& m, std::span<const Offset> face_offsets,
                                   std::span<const std::uint32_t> corners, const std::vector<std::uint32_t>& out_begin,
                                   std::vector<std::uint32_t>& stamp) {
        using u32 = std::uint32_t;
        constexpr u32 none = UINT32_MAX;
        const std::size_t nv = out_begin.size() - 1, nf = face_offsets.empty() ? 0 : face_offsets.size() - 1,
                          nc = corners.size();
        std::copy(out_begin.begin(), out_begin.end() - 1, stamp.begin());  // stamp[v]: where v's row ends so far
        // Each vertex's row holds the halfedges of the corners seen leaving it; the vertex a
        // corner runs to is its halfedge's target, written as soon as the corner is seen.
        detail::trivial_array<u32> rows;
        rows.resize_for_overwrite(nc);  // written before read, row by row
        m.vertex_out_.assign(nv, halfedge_handle{});
        // A closed mesh has one edge per two corners; each boundary edge needs room for two more
        // halfedges, grown in steps as they appear (realloc: the written records move along).
        m.halfedges_.resize_for_overwrite(nc);
        m.faces_.resize_for_overwrite(nf);
        std::vector<u32> face_h;  // the halfedge of each corner of the face at hand
        u32 edges = 0;
        for (std::size_t f = 0; f < nf; ++f) {
            const u32 b = static_cast<u32>(face_offsets[f]), e = static_cast<u32>(face_offsets[f + 1]);
            const face_handle fh(static_cast<u32>(f));
            if (face_h.size() < e - b) face_h.resize(e - b);
            for (u32 k = b; k < e; ++k) {
                const u32 a = corners[k], t = corners[k + 1 == e ? b : k + 1];
                u32 h = none;
                for (u32 r = out_begin[t]; r < stamp[t]; ++r)
                    if (m.halfedges_[rows[r]].target.index == a) {
                        h = rows[r] ^ 1u;
                        break;
                    }
                // A directed edge met twice (an orientation conflict or a third face) shows, at
                // its first repeat, as a b->a that is itself a twin or already has one, or, with
                // no b->a yet, as the earlier a->b in a's row.
                if (h == none) {
                    for (u32 r = out_begin[a]; r < stamp[a]; ++r)
                        if (m.halfedges_[rows[r]].target.index == t) return false;
                    h = 2 * edges++;
                    if (h + 2 > m.halfedges_.size())
                        m.halfedges_.resize_for_overwrite(
                            std::min<std::size_t>(2 * nc, std::size_t{h} + 2 + (std::size_t{h} + 2) / 8 + 64));
                    m.halfedges_[h + 1] = {vertex_handle(a), {}, {}, {}};  // boundary until a twin turns up
                } else {
                    if ((h & 1u) == 0 || !m.halfedges_[h].face.is_null()) return false;
                    m.halfedges_[h].face = fh;  // taken: a second a->b must not pair with it
                }
                rows[stamp[a]++] = h;
                m.halfedges_[h].target = vertex_handle(t);
                face_h[k - b] = h;
                m.vertex_out_[a] = halfedge_handle(h);  // the last corner's, as add_face leaves it
            }
            const u32 n = e - b;
            for (u32 i = 0; i < n; ++i)
                m.halfedges_[face_h[i]] = {vertex_handle(corners[i + 1 == n ? b : b + i + 1]), fh,
                                           halfedge_handle(face_h[i + 1 == n ? 0 : i + 1]),
                                           halfedge_handle(face_h[i == 0 ? n - 1 : i - 1])};
            m.faces_[f] = halfedge_handle(face_h[n - 1]);
        }
        m.halfedges_.resize(2 * std::size_t{edges});
        // Boundary halfedges (the odd ones no face took) by the vertex they leave, then linked
        // into loops: the boundary halfedge entering a vertex continues with the one leaving it.
        std::fill(stamp.begin(), stamp.end(), none);
        if (2 * std::size_t{edges} > nc) {
            for (u32 h = 1; h < 2 * edges; h += 2)
                if (m.halfedges_[h].face.is_null()) {
                    const u32 from = m.halfedges_[h - 1].target.index;
                    if (stamp[from] != none) return false;
                    stamp[from] = h;
                }
            for (std::size_t v = 0; v < nv; ++v)
                if (const u32 hb = stamp[v]; hb != none) {
                    const u32 nb = stamp[m.halfedges_[hb].target.index];
                    if (nb == none) return false;
                    m.halfedges_[hb].next = halfedge_handle(nb);
                    m.halfedges_[nb].prev = halfedge_handle(hb);
                    m.vertex_out_[v] = halfedge_handle(hb);
                }
        }
        for (std::size_t v = 0; v < nv; ++v)
            if (!single_fan(m, static_cast<u32>(v), out_begin[v + 1] - out_begin[v] + (stamp[v] != none ? 1u : 0u)))
                return false;
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
