// hmira/meshes/detail/halfedge_maintenance.hpp
// The whole-mesh operations of basic_halfedge_mesh that rewrite its arrays in one pass:
// reversing every face's winding, dropping deleted elements (collect_garbage) and setting the
// index bounds in bulk (resize). A friend of the mesh, writing its records directly; the
// documented members of the mesh forward here.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "../face_vertex_mesh.hpp"  // index_remap
#include "../handles.hpp"
#include "slots.hpp"
#include "trivial_array.hpp"

namespace hmira::detail {

/// The one-pass rewrites of basic_halfedge_mesh (Mesh), kept out of the class body.
template <class Mesh>
struct halfedge_maintenance {
    /// See basic_halfedge_mesh::reverse_orientation.
    static void reverse_orientation(Mesh& m) noexcept {
        for (std::size_t h = 0; h + 1 < m.halfedges_.size(); h += 2) {
            auto& a = m.halfedges_[h];
            auto& b = m.halfedges_[h + 1];
            std::swap(a.target, b.target);
            std::swap(a.next, a.prev);
            std::swap(b.next, b.prev);
        }
        // That also moved the free list's links (a freed edge's first next) into prev: walk
        // the list and put them back. O(free edges), no branch in the loop above.
        std::uint32_t e = m.free_edges_.empty() ? detail::free_slots::none : m.free_edges_.top();
        for (std::size_t k = 0; k < m.free_edges_.size() && e != detail::free_slots::none; ++k) {
            auto& a = m.halfedges_[2 * std::size_t(e)];
            std::swap(a.next, a.prev);
            e = a.next.index;
        }
        for (std::size_t v = 0; v < m.vertex_out_.size(); ++v) {
            const auto h = m.vertex_out_[v];
            if (h.is_null() || (m.deleted_vertices_ && m.vertex_deleted_[v])) continue;
            const auto& rec = m.halfedges_[h.index];
            m.vertex_out_[v] = rec.face.is_null() ? rec.next : m.opposite(h);
        }
        ++m.changes_;
    }

    /// See basic_halfedge_mesh::collect_garbage.
    static index_remap collect_garbage(Mesh& m) {
        index_remap map;
        auto make_map = [](const detail::zeroed_array<std::uint8_t>& deleted, std::size_t bound,
                           std::vector<std::uint32_t>& out) {
            out.assign(bound, UINT32_MAX);
            std::uint32_t k = 0;
            for (std::size_t i = 0; i < bound; ++i)
                if (!deleted[i]) out[i] = k++;
            return k;
        };
        const auto nv = make_map(m.vertex_deleted_, m.positions_.size(), map.vertices);
        const auto ne = make_map(m.edge_deleted_, m.halfedges_.size() / 2, map.edges);
        const auto nf = make_map(m.face_deleted_, m.faces_.size(), map.faces);
        map.halfedges.assign(m.halfedges_.size(), UINT32_MAX);
        for (std::size_t h = 0; h < m.halfedges_.size(); ++h)
            if (map.edges[h >> 1] != UINT32_MAX) map.halfedges[h] = 2 * map.edges[h >> 1] + (h & 1u);
        auto mv = [&](vertex_handle v) {
            return v.is_null() || v.index >= map.vertices.size() ? vertex_handle{}
                                                                 : vertex_handle(map.vertices[v.index]);
        };
        auto mh = [&](halfedge_handle h) {
            return h.is_null() || h.index >= map.halfedges.size() ? halfedge_handle{}
                                                                  : halfedge_handle(map.halfedges[h.index]);
        };
        auto mf = [&](face_handle f) {
            return f.is_null() || f.index >= map.faces.size() ? face_handle{} : face_handle(map.faces[f.index]);
        };

        for (std::size_t v = 0; v < m.positions_.size(); ++v)
            if (map.vertices[v] != UINT32_MAX) {
                m.positions_[map.vertices[v]] = m.positions_[v];
                m.vertex_out_[map.vertices[v]] = mh(m.vertex_out_[v]);
            }
        m.positions_.resize(nv);
        m.vertex_out_.resize(nv);
        for (std::size_t h = 0; h < m.halfedges_.size(); ++h)
            if (map.halfedges[h] != UINT32_MAX) {
                const auto rec = m.halfedges_[h];
                m.halfedges_[map.halfedges[h]] = {mv(rec.target), mf(rec.face), mh(rec.next), mh(rec.prev)};
            }
        m.halfedges_.resize(2 * static_cast<std::size_t>(ne));
        std::vector<std::vector<halfedge_handle>> rings;
        detail::zeroed_array<std::uint32_t> face_rings;
        for (std::size_t f = 0; f < m.faces_.size(); ++f)
            if (map.faces[f] != UINT32_MAX) {
                m.faces_[map.faces[f]] = mh(m.faces_[f]);
                if (const auto r = m.face_rings_[f]; r != 0 && !m.ring_lists_[r - 1].empty()) {
                    auto list = std::move(m.ring_lists_[r - 1]);
                    for (auto& h : list) h = mh(h);
                    rings.push_back(std::move(list));
                    face_rings.at(map.faces[f], nf) = static_cast<std::uint32_t>(rings.size());
                }
            }
        m.faces_.resize(nf);
        m.ring_lists_ = std::move(rings);
        m.face_rings_ = std::move(face_rings);
        m.vertex_deleted_.zero();
        m.edge_deleted_.zero();
        m.face_deleted_.zero();
        m.vertex_props_.compact(map.vertices, nv);
        m.edge_props_.compact(map.edges, ne);
        m.halfedge_props_.compact(map.halfedges, 2 * static_cast<std::size_t>(ne));
        m.face_props_.compact(map.faces, nf);
        m.deleted_vertices_ = m.deleted_edges_ = m.deleted_faces_ = 0;
        m.free_vertices_.clear();
        m.free_edges_.clear();
        m.free_faces_.clear();
        m.vertex_generations_.clear();
        m.edge_generations_.clear();
        m.face_generations_.clear();
        ++m.changes_;
        return map;
    }

    /// See basic_halfedge_mesh::resize.
    static void resize(Mesh& m, std::size_t vertices, std::size_t edges, std::size_t faces) {
        // Every allocation first, so that nothing changes unless all of them succeed.
        m.vertex_deleted_.ensure(vertices);
        m.edge_deleted_.ensure(edges);
        m.face_deleted_.ensure(faces);
        if (vertices > m.positions_.capacity()) m.positions_.reserve(std::max(vertices, 2 * m.positions_.capacity()));
        m.vertex_out_.ensure_room(vertices);
        m.halfedges_.ensure_room(2 * edges);
        m.faces_.ensure_room(faces);
        const std::size_t old_v = m.positions_.size(), old_e = m.halfedges_.size() / 2, old_f = m.faces_.size();
        try {
            m.vertex_props_.resize(vertices);
            m.edge_props_.resize(edges);
            m.halfedge_props_.resize(2 * edges);
            m.face_props_.resize(faces);
        } catch (...) {  // a user property array could not grow: shrink them all back (never throws)
            m.vertex_props_.resize(old_v);
            m.edge_props_.resize(old_e);
            m.halfedge_props_.resize(2 * old_e);
            m.face_props_.resize(old_f);
            throw;
        }
        m.positions_.resize(vertices);
        m.vertex_out_.resize(vertices, halfedge_handle{});
        m.halfedges_.resize(2 * edges, typename Mesh::halfedge_record{});
        m.faces_.resize(faces, halfedge_handle{});
        ++m.changes_;
    }
};

}  // namespace hmira::detail
