// hmira/meshes/winged_edge_mesh.hpp
// The winged-edge mesh of thesis 1.2.2 (Baumgart): one record per edge holding its two
// vertices, its two faces and its four wing edges; a vertex and a face each keep one edge.
// Its traits also present halfedge navigation, a halfedge being an (edge, side) pair, so the
// Euler operators and every halfedge algorithm run on it unchanged.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <ranges>
#include <span>
#include <string>
#include <vector>

#include "../concepts.hpp"
#include "../core/result.hpp"
#include "../core/vec3.hpp"
#include "../traits.hpp"
#include "detail/element_range.hpp"
#include "detail/link_face.hpp"
#include "detail/native_traits.hpp"
#include "face_vertex_mesh.hpp"  // index_remap
#include "handles.hpp"
#include "properties.hpp"

namespace hmira {

/// Winged-edge mesh (thesis 1.2.2).
///
/// Layout: edge e runs from `vertex[0]` to `vertex[1]`. Side 0 of the edge is the face
/// `face[0]` that runs it forwards (vertex[0] -> vertex[1]), side 1 the face `face[1]` that runs
/// it backwards; a null face is the boundary. The four wings are the edges that come before and
/// after e in the loop of each side: `prev_wing[s]`, `next_wing[s]`. The thesis asks which face
/// is "first" and which vertex is "first" (1.2.2); here the edge's direction answers both, and
/// each wing reference also records, in its lowest bit, which side of the wing edge continues
/// the loop. Baumgart's original recovers that bit by comparing vertices at every step; storing
/// it costs no memory (the index has room) and keeps navigation O(1) and unambiguous even in
/// the middle of raw mutation, while the vertices are being rewritten.
///
/// A halfedge is the pair (edge e, side s) with index 2e + s: it runs vertex[s] -> vertex[1-s]
/// and lies in face[s]. A vertex keeps one edge it touches (as an outgoing (edge, side), a
/// boundary one when the vertex is on the boundary); a face keeps one edge of its loop.
///
/// Native costs (thesis ch. 4): add vertex O(1); add face O(V_adjacentV) per corner (checks
/// manifoldness and orientation like halfedge_mesh); edge -> vertices, edge -> faces, wing
/// edges O(1); face -> vertices/edges O(V_consistF); vertex -> vertices/edges/faces
/// O(V_adjacentV); face -> faces O(F_adjacentF). No inner rings: faces are simple loops.
///
/// Deletion marks elements; collect_garbage() compacts them. Handles stay valid until then.
/// Const queries may run concurrently; mutations need exclusive access. The raw mutation
/// (set_next, new_edge, erase_*) keeps nothing consistent by itself, as in halfedge_mesh.
///
/// Per-vertex, -edge and -face user data by name: add/get/remove_*_property, from the
/// with_*_properties bases (properties.hpp); properties follow garbage collection.
template <class Scalar = double>
class basic_winged_edge_mesh : public with_vertex_properties, public with_edge_properties, public with_face_properties {
public:
    /// The coordinate type.
    using scalar = Scalar;
    /// A vertex position.
    using point = vec3<Scalar>;

    /// One winged edge. Wing references are halfedge indices 2e' + s' (edge e', side s').
    struct edge_record {
        std::array<vertex_handle, 2> vertex;       ///< from, to
        std::array<face_handle, 2> face;           ///< forward side, backward side (null: boundary)
        std::array<halfedge_handle, 2> next_wing;  ///< the wing after e in face[s]'s loop
        std::array<halfedge_handle, 2> prev_wing;  ///< the wing before e in face[s]'s loop
    };

    // ----- counts and ranges -----------------------------------------------------------------
    /// Live element counts (deleted elements not counted; halfedges: two per edge). O(1).
    ///@{
    std::size_t vertex_count() const noexcept { return positions_.size() - deleted_vertices_; }
    std::size_t edge_count() const noexcept { return edges_.size() - deleted_edges_; }
    std::size_t halfedge_count() const noexcept { return 2 * edge_count(); }
    std::size_t face_count() const noexcept { return face_edge_.size() - deleted_faces_; }
    ///@}
    /// Index bounds: one past the largest index, deleted elements included (until
    /// collect_garbage()). O(1).
    ///@{
    std::size_t vertex_index_bound() const noexcept { return positions_.size(); }
    std::size_t edge_index_bound() const noexcept { return edges_.size(); }
    std::size_t halfedge_index_bound() const noexcept { return 2 * edges_.size(); }
    std::size_t face_index_bound() const noexcept { return face_edge_.size(); }
    ///@}

    /// The live vertices, edges and faces in index order, skipping deleted ones. Lazy views;
    /// iteration O(V_all), O(E_all), O(F_all).
    ///@{
    detail::element_range<vertex_handle> vertices() const {
        return {static_cast<std::uint32_t>(positions_.size()), deleted_vertices_ ? vertex_deleted_.data() : nullptr};
    }
    detail::element_range<edge_handle> edges() const {
        return {static_cast<std::uint32_t>(edges_.size()), deleted_edges_ ? edge_deleted_.data() : nullptr};
    }
    detail::element_range<face_handle> faces() const {
        return {static_cast<std::uint32_t>(face_edge_.size()), deleted_faces_ ? face_deleted_.data() : nullptr};
    }
    ///@}
    /// Both sides of every live edge, in index order.
    detail::element_range<halfedge_handle, 1> halfedges() const {
        return {static_cast<std::uint32_t>(2 * edges_.size()), deleted_edges_ ? edge_deleted_.data() : nullptr};
    }

    /// Whether the handle names an element that exists and is not deleted. O(1).
    ///@{
    bool is_valid(vertex_handle v) const noexcept { return v.index < positions_.size() && !vertex_deleted_[v.index]; }
    bool is_valid(face_handle f) const noexcept { return f.index < face_edge_.size() && !face_deleted_[f.index]; }
    bool is_valid(edge_handle e) const noexcept { return e.index < edges_.size() && !edge_deleted_[e.index]; }
    bool is_valid(halfedge_handle h) const noexcept {
        return (h.index >> 1) < edges_.size() && !edge_deleted_[h.index >> 1];
    }
    ///@}

    // ----- the winged-edge records, O(1) -----------------------------------------------------
    /// The raw winged-edge record of e. O(1). Precondition (unchecked): e is valid.
    const edge_record& record(edge_handle e) const { return edges_[e.index]; }
    /// The two faces the edge separates (its wings' faces): forward side, backward side.
    std::array<face_handle, 2> edge_faces(edge_handle e) const { return edges_[e.index].face; }
    /// The edge's two vertices: from (`vertex[0]`), to (`vertex[1]`). O(1).
    std::array<vertex_handle, 2> edge_vertices(edge_handle e) const { return edges_[e.index].vertex; }
    /// The edge this vertex keeps (null if isolated), and the one this face keeps. O(1).
    ///@{
    edge_handle vertex_edge(vertex_handle v) const {
        return vertex_out_[v.index].is_null() ? edge_handle{} : edge(vertex_out_[v.index]);
    }
    edge_handle face_edge(face_handle f) const { return edge(face_edge_[f.index]); }
    ///@}

    // ----- halfedge view of the records, all O(1) ---------------------------------------------
    // Preconditions (unchecked) for all of these: the handles are valid.
    /// The edge of halfedge (e, s): e. Pure index arithmetic.
    static constexpr edge_handle edge(halfedge_handle h) noexcept { return edge_handle(h.index >> 1); }
    /// The side s of halfedge (e, s): 0 runs the edge forwards, 1 backwards.
    static constexpr unsigned side(halfedge_handle h) noexcept { return h.index & 1u; }
    /// The other side of the same edge: (e, 1 - s).
    static constexpr halfedge_handle opposite(halfedge_handle h) noexcept { return halfedge_handle(h.index ^ 1u); }
    /// The halfedge (e, s); side 0 (the default) runs vertex[0] -> vertex[1].
    static constexpr halfedge_handle edge_halfedge(edge_handle e, unsigned s = 0) noexcept {
        return halfedge_handle(2 * e.index + s);
    }
    /// The next halfedge in h's loop (the next wing of its side). O(1).
    halfedge_handle next(halfedge_handle h) const { return edges_[h.index >> 1].next_wing[h.index & 1u]; }
    /// The previous halfedge in h's loop (the previous wing of its side). O(1).
    halfedge_handle prev(halfedge_handle h) const { return edges_[h.index >> 1].prev_wing[h.index & 1u]; }
    /// The vertex h points to: vertex[1 - s]. O(1).
    vertex_handle target(halfedge_handle h) const { return edges_[h.index >> 1].vertex[1u - (h.index & 1u)]; }
    /// The vertex h starts from: vertex[s]. O(1).
    vertex_handle source(halfedge_handle h) const { return edges_[h.index >> 1].vertex[h.index & 1u]; }
    /// The face on h's side, face[s]; null on the boundary. O(1).
    face_handle face(halfedge_handle h) const { return edges_[h.index >> 1].face[h.index & 1u]; }
    /// The outgoing side of the edge v keeps (a boundary one if v is on the boundary); null
    /// for an isolated vertex. O(1).
    halfedge_handle vertex_halfedge(vertex_handle v) const { return vertex_out_[v.index]; }
    /// The side of the edge f keeps that lies in f. O(1).
    halfedge_handle face_halfedge(face_handle f) const { return face_edge_[f.index]; }
    /// Boundary tests, O(1): a halfedge with no face; an edge with a null face on either
    /// side; a vertex whose kept edge is a boundary one, or that is isolated.
    ///@{
    bool is_boundary(halfedge_handle h) const { return face(h).is_null(); }
    bool is_boundary(edge_handle e) const {
        return edges_[e.index].face[0].is_null() || edges_[e.index].face[1].is_null();
    }
    bool is_boundary(vertex_handle v) const {
        const auto h = vertex_out_[v.index];
        return h.is_null() || is_boundary(h);
    }
    ///@}
    /// Whether v has no edge. O(1).
    bool is_isolated(vertex_handle v) const { return vertex_out_[v.index].is_null(); }

    // ----- circulators -----------------------------------------------------------------------
    /// \cond INTERNAL
    struct loop_step {
        static halfedge_handle step(const basic_winged_edge_mesh& m, halfedge_handle h) { return m.next(h); }
        static halfedge_handle value(const basic_winged_edge_mesh&, halfedge_handle h) { return h; }
    };
    struct loop_vertex_step : loop_step {
        static vertex_handle value(const basic_winged_edge_mesh& m, halfedge_handle h) { return m.target(h); }
    };
    struct loop_edge_step : loop_step {
        static edge_handle value(const basic_winged_edge_mesh&, halfedge_handle h) { return edge(h); }
    };
    struct outgoing_step {
        static halfedge_handle step(const basic_winged_edge_mesh& m, halfedge_handle h) { return m.next(opposite(h)); }
        static halfedge_handle value(const basic_winged_edge_mesh&, halfedge_handle h) { return h; }
    };
    struct outgoing_target_step : outgoing_step {
        static vertex_handle value(const basic_winged_edge_mesh& m, halfedge_handle h) { return m.target(h); }
    };
    struct outgoing_edge_step : outgoing_step {
        static edge_handle value(const basic_winged_edge_mesh&, halfedge_handle h) { return edge(h); }
    };
    struct outgoing_face_step : outgoing_step {
        static bool keep(const basic_winged_edge_mesh& m, halfedge_handle h) { return !m.is_boundary(h); }
        static face_handle value(const basic_winged_edge_mesh& m, halfedge_handle h) { return m.face(h); }
    };
    struct loop_across_step : loop_step {
        static bool keep(const basic_winged_edge_mesh& m, halfedge_handle h) { return !m.is_boundary(opposite(h)); }
        static face_handle value(const basic_winged_edge_mesh& m, halfedge_handle h) { return m.face(opposite(h)); }
    };
    /// \endcond
    /// A circulator range: from a start halfedge, steps with Policy until it is back at the
    /// start, yielding Policy's value of each halfedge; empty for a null start.
    template <class Policy>
    using loop = detail::loop_range<basic_winged_edge_mesh, halfedge_handle, Policy>;

    /// The halfedges of h's loop, from h, following next(). O(length of the loop).
    loop<loop_step> loop_halfedges(halfedge_handle h) const { return {*this, h}; }
    /// The face's vertices in winding order, starting at the first vertex given to add_face.
    loop<loop_vertex_step> face_vertices(face_handle f) const { return {*this, face_halfedge(f)}; }
    /// The face's edges in winding order. O(E_consistF).
    loop<loop_edge_step> face_edges(face_handle f) const { return {*this, face_halfedge(f)}; }
    /// The halfedges of f's loop, from face_halfedge(f). O(V_consistF).
    loop<loop_step> face_halfedges(face_handle f) const { return {*this, face_halfedge(f)}; }
    /// The halfedges leaving v, from vertex_halfedge(v); empty for an isolated vertex.
    /// O(V_adjacentV).
    loop<outgoing_step> outgoing_halfedges(vertex_handle v) const { return {*this, vertex_halfedge(v)}; }
    /// The vertices sharing an edge with v (targets of its outgoing halfedges). O(V_adjacentV).
    loop<outgoing_target_step> adjacent_vertices(vertex_handle v) const { return {*this, vertex_halfedge(v)}; }
    /// The edges at v, one per outgoing halfedge. O(E_adjacentV).
    loop<outgoing_edge_step> vertex_edges(vertex_handle v) const { return {*this, vertex_halfedge(v)}; }
    /// Faces around v (boundary gaps skipped), O(F_adjacentV).
    loop<outgoing_face_step> vertex_faces(vertex_handle v) const { return {*this, vertex_halfedge(v)}; }
    /// Faces across f's edges (the other wing of each edge), O(F_adjacentF).
    loop<loop_across_step> adjacent_faces(face_handle f) const { return {*this, face_halfedge(f)}; }
    /// Number of edges at v (0 if isolated). O(V_adjacentV).
    std::size_t valence(vertex_handle v) const {
        return static_cast<std::size_t>(std::ranges::distance(outgoing_halfedges(v)));
    }

    /// The side of an edge running from a to b, or null. O(V_adjacentV).
    halfedge_handle find_halfedge(vertex_handle a, vertex_handle b) const {
        for (auto h : outgoing_halfedges(a))
            if (target(h) == b) return h;
        return {};
    }

    // ----- geometry --------------------------------------------------------------------------
    /// The position of v. O(1). Precondition (unchecked): v is valid.
    const point& position(vertex_handle v) const { return positions_[v.index]; }
    /// Moves v to p; connectivity and change_count() are unaffected. O(1).
    void set_position(vertex_handle v, const point& p) { positions_[v.index] = p; }
    /// All positions by vertex index, deleted vertices included. O(1).
    std::span<const point> positions() const noexcept { return positions_; }

    // ----- building --------------------------------------------------------------------------
    /// Adds an isolated vertex at p and returns it. O(1) amortised.
    vertex_handle add_vertex(const point& p) {
        positions_.push_back(p);
        vertex_out_.push_back({});
        vertex_deleted_.push_back(0);
        vertex_props_.push_back();
        ++changes_;
        return vertex_handle(positions_.size() - 1);
    }

    /// add_face(std::span) for a braced list of vertices, e.g. `m.add_face({a, b, c})`.
    result<face_handle> add_face(std::initializer_list<vertex_handle> vs) {
        return add_face(std::span<const vertex_handle>(vs.begin(), vs.size()));
    }

    /// Adds a polygon, sharing the edges it has with faces already present. Fails, with the
    /// mesh unchanged, when the face has fewer than 3 or repeated vertices, names a missing
    /// vertex, would give an edge a third face or a face on the wrong side (orientation
    /// conflict), or would make a vertex non-manifold. O(sum of V_adjacentV over its corners).
    /// Faces may arrive in any order: a face may touch a vertex in a fan of its own (a pinch
    /// that validate() reports until the faces between the fans are added).
    result<face_handle> add_face(std::span<const vertex_handle> vs) {
        return detail::link_face<basic_winged_edge_mesh, mesh_traits<basic_winged_edge_mesh>>(
            *this, vs, link_scratch_, [this](vertex_handle v) { return is_valid(v); });
    }

    /// Makes the edge a vertex keeps a boundary one if the vertex has any. O(V_adjacentV).
    void adjust_outgoing_halfedge(vertex_handle v) {
        detail::prefer_boundary_halfedge<basic_winged_edge_mesh, mesh_traits<basic_winged_edge_mesh>>(*this, v);
    }

    // ----- raw mutation on the records (the halfedge layer; keeps nothing consistent) ---------
    /// Makes n follow h in its loop: sets h's next wing and n's previous wing. O(1).
    void set_next(halfedge_handle h, halfedge_handle n) {
        link(h, n);
        ++changes_;
    }
    /// Sets the vertex h points to (vertex[1 - s] of its edge). O(1).
    void set_target(halfedge_handle h, vertex_handle v) {
        edges_[h.index >> 1].vertex[1u - (h.index & 1u)] = v;
        ++changes_;
    }
    /// Sets the face on h's side (null: boundary). O(1).
    void set_face(halfedge_handle h, face_handle f) {
        edges_[h.index >> 1].face[h.index & 1u] = f;
        ++changes_;
    }
    /// Sets the outgoing halfedge v keeps. O(1).
    void set_vertex_halfedge(vertex_handle v, halfedge_handle h) {
        vertex_out_[v.index] = h;
        ++changes_;
    }
    /// Sets the halfedge f keeps (one of its loop). O(1).
    void set_face_halfedge(face_handle f, halfedge_handle h) {
        face_edge_[f.index] = h;
        ++changes_;
    }

    /// A new edge from a to b; returns its forward side (a -> b). Wings unset, faces null.
    halfedge_handle new_edge(vertex_handle a, vertex_handle b) {
        edges_.push_back({{a, b}, {}, {}, {}});
        edge_deleted_.push_back(0);
        edge_props_.push_back();
        ++changes_;
        return halfedge_handle(2 * (edges_.size() - 1));
    }
    /// A new face with no halfedge yet. O(1) amortised.
    face_handle new_face() {
        face_edge_.push_back({});
        face_deleted_.push_back(0);
        face_props_.push_back();
        ++changes_;
        return face_handle(face_edge_.size() - 1);
    }
    /// Marks the element deleted (both sides, for an edge); no-op if already deleted. Does not
    /// touch the references to it. O(1).
    ///@{
    void erase_edge(edge_handle e) {
        if (!edge_deleted_[e.index]) {
            edge_deleted_[e.index] = 1;
            ++deleted_edges_;
            ++changes_;
        }
    }
    void erase_face(face_handle f) {
        if (!face_deleted_[f.index]) {
            face_deleted_[f.index] = 1;
            ++deleted_faces_;
            ++changes_;
        }
    }
    void erase_vertex(vertex_handle v) {
        if (!vertex_deleted_[v.index]) {
            vertex_deleted_[v.index] = 1;
            ++deleted_vertices_;
            ++changes_;
        }
    }
    ///@}

    /// Whether some element is marked deleted (collect_garbage() would compact). O(1).
    bool has_garbage() const noexcept { return deleted_vertices_ + deleted_edges_ + deleted_faces_ > 0; }

    /// Drops deleted elements, renumbers the rest in their old order, rewrites every reference
    /// and compacts the properties. Returns the old -> new maps (halfedges: 2e + s). Invalidates
    /// handles and views. O(V_all + E_all + F_all).
    index_remap collect_garbage() {
        index_remap map;
        auto make_map = [](const std::vector<std::uint8_t>& deleted, std::vector<std::uint32_t>& out) {
            out.assign(deleted.size(), UINT32_MAX);
            std::uint32_t k = 0;
            for (std::size_t i = 0; i < deleted.size(); ++i)
                if (!deleted[i]) out[i] = k++;
            return k;
        };
        const auto nv = make_map(vertex_deleted_, map.vertices);
        const auto ne = make_map(edge_deleted_, map.edges);
        const auto nf = make_map(face_deleted_, map.faces);
        map.halfedges.assign(2 * edges_.size(), UINT32_MAX);
        for (std::size_t h = 0; h < map.halfedges.size(); ++h)
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
        for (std::size_t v = 0; v < positions_.size(); ++v)
            if (map.vertices[v] != UINT32_MAX) {
                positions_[map.vertices[v]] = positions_[v];
                vertex_out_[map.vertices[v]] = mh(vertex_out_[v]);
            }
        positions_.resize(nv);
        vertex_out_.resize(nv);
        vertex_deleted_.assign(nv, 0);
        for (std::size_t e = 0; e < edges_.size(); ++e)
            if (map.edges[e] != UINT32_MAX) {
                const auto r = edges_[e];
                edges_[map.edges[e]] = {{mv(r.vertex[0]), mv(r.vertex[1])},
                                        {mf(r.face[0]), mf(r.face[1])},
                                        {mh(r.next_wing[0]), mh(r.next_wing[1])},
                                        {mh(r.prev_wing[0]), mh(r.prev_wing[1])}};
            }
        edges_.resize(ne);
        edge_deleted_.assign(ne, 0);
        for (std::size_t f = 0; f < face_edge_.size(); ++f)
            if (map.faces[f] != UINT32_MAX) face_edge_[map.faces[f]] = mh(face_edge_[f]);
        face_edge_.resize(nf);
        face_deleted_.assign(nf, 0);
        vertex_props_.compact(map.vertices, nv);
        edge_props_.compact(map.edges, ne);
        face_props_.compact(map.faces, nf);
        deleted_vertices_ = deleted_edges_ = deleted_faces_ = 0;
        ++changes_;
        return map;
    }

    /// Room for this many vertices, edges and faces, so that building does not reallocate.
    void reserve(std::size_t vertices, std::size_t edges, std::size_t faces) {
        positions_.reserve(vertices);
        vertex_out_.reserve(vertices);
        vertex_deleted_.reserve(vertices);
        edges_.reserve(edges);
        edge_deleted_.reserve(edges);
        face_edge_.reserve(faces);
        face_deleted_.reserve(faces);
    }
    /// Removes every element and property. Invalidates all handles.
    void clear() { *this = basic_winged_edge_mesh(); }
    /// Removes every element and keeps the named properties (emptied, their defaults kept), as
    /// OpenMesh's clear() does: what reading a file into a mesh uses. The change count keeps
    /// growing, so an index built before sees that it is stale. Invalidates all handles. O(1)
    /// besides freeing the storage.
    void clear_elements() {
        auto vertex_props = std::move(vertex_props_);
        auto edge_props = std::move(edge_props_);
        auto face_props = std::move(face_props_);
        const auto changes = changes_;
        *this = basic_winged_edge_mesh();
        vertex_props_ = std::move(vertex_props);
        vertex_props_.resize(0);
        edge_props_ = std::move(edge_props);
        edge_props_.resize(0);
        face_props_ = std::move(face_props);
        face_props_.resize(0);
        changes_ = changes + 1;
    }

    /// Grows on every change of connectivity or of the element set.
    std::uint64_t change_count() const noexcept { return changes_; }

private:
    // Setting a wing on one side sets the matching back-wing, so next and prev stay inverse.
    void link(halfedge_handle a, halfedge_handle b) {
        edges_[a.index >> 1].next_wing[a.index & 1u] = b;
        edges_[b.index >> 1].prev_wing[b.index & 1u] = a;
    }

    std::vector<point> positions_;
    std::vector<halfedge_handle> vertex_out_;  // the edge each vertex keeps, as its outgoing side
    std::vector<std::uint8_t> vertex_deleted_;
    std::vector<edge_record> edges_;
    std::vector<std::uint8_t> edge_deleted_;
    std::vector<halfedge_handle> face_edge_;  // the edge each face keeps, as the side in the face
    std::vector<std::uint8_t> face_deleted_;
    std::size_t deleted_vertices_ = 0, deleted_edges_ = 0, deleted_faces_ = 0;
    std::uint64_t changes_ = 0;
    // Reused by add_face so that building does not allocate per face.
    detail::face_link_scratch<halfedge_handle> link_scratch_;
};

using winged_edge_mesh = basic_winged_edge_mesh<double>;

/// Native traits: the winged-edge queries at their thesis cost, and the halfedge view
/// ((edge, side) pairs) with raw mutation, so Euler operators and flip_normals run on it.
template <class Scalar>
struct mesh_traits<basic_winged_edge_mesh<Scalar>> : detail::native_halfedge_traits<basic_winged_edge_mesh<Scalar>> {
    using mesh = basic_winged_edge_mesh<Scalar>;

    static auto edge_faces(const mesh& m, edge_handle e) { return m.edge_faces(e); }
    /// Optional (not a concept requirement): room for this many elements.
    static void reserve(mesh& m, std::size_t vertices, std::size_t edges, std::size_t faces) {
        m.reserve(vertices, edges, faces);
    }
};

}  // namespace hmira
