// hmira/meshes/halfedge_mesh.hpp
// The half-edge mesh of thesis 1.2.3: polygonal faces, open boundaries, and faces with inner
// rings (holes), so that Mantyla's ring operators have somewhere to live. Every local query of
// the thesis's table 4.3 runs at its efficient cost here.
#pragma once

#include <algorithm>
#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "../concepts.hpp"
#include "../core/huge_pages.hpp"
#include "../core/result.hpp"
#include "../core/vec3.hpp"
#include "../traits.hpp"
#include "detail/element_range.hpp"
#include "detail/halfedge_from_polygons.hpp"
#include "detail/halfedge_maintenance.hpp"
#include "detail/link_face.hpp"
#include "detail/native_traits.hpp"
#include "detail/slots.hpp"
#include "detail/trivial_array.hpp"
#include "face_vertex_mesh.hpp"  // index_remap
#include "handles.hpp"
#include "properties.hpp"

namespace hmira {

/// Halfedge mesh with inner rings.
///
/// Layout: the two halfedges of edge e are 2e and 2e+1, so opposite(h) is h ^ 1 and costs
/// nothing. Each halfedge stores target, face (null on the boundary), next and prev. A vertex
/// stores one outgoing halfedge, a boundary one whenever the vertex is on the boundary. A face
/// stores one halfedge of its outer loop and a list of inner rings (one halfedge per ring; the
/// ring's halfedges have the face as their face).
///
/// Native costs (thesis ch. 4): add vertex O(1); add face O(V_adjacentV) per corner (finds
/// existing edges and re-links boundary fans, so no non-manifold vertex or edge can appear);
/// next/prev/opposite/target/face O(1); face -> vertices O(V_consistF); vertex -> vertices,
/// edges, faces O(V_adjacentV); face -> faces O(F_adjacentF).
///
/// Deletion marks elements and puts their slots on a free list kept in the deleted slots' own
/// records (see erase_edge), so that deleting touches no new memory; creating an element of that
/// kind (add_vertex, new_edge, new_face, add_face) takes the most recently freed slot before it
/// appends, with its properties back at their defaults. So an operator followed by its inverse
/// (make_edge_face then kill_edge_face, ...) allocates nothing and leaves the index bounds as
/// they were. A handle to a deleted element stays invalid until its slot is reused; then it
/// names the new element. To detect that, keep versioned(h) instead of h: is_valid() of a
/// versioned handle is false once its element is gone, whether or not the slot was reused.
/// set_slot_reuse(false) makes every new element append (index order = creation order).
/// collect_garbage() compacts and reports the old -> new maps; it invalidates every handle,
/// versioned ones included. Const queries may run concurrently; mutations need exclusive access. Mutation at the raw
/// level (set_next, new_edge, erase_*) keeps nothing
/// consistent by itself: it is the layer the Euler operators are written on.
///
/// Per-vertex, -edge, -halfedge and -face user data by name: add/get/remove_*_property, from
/// the with_*_properties bases (properties.hpp); properties follow garbage collection.
template <class Scalar = double>
class basic_halfedge_mesh : public with_vertex_properties,
                            public with_edge_properties,
                            public with_halfedge_properties,
                            public with_face_properties {
public:
    using scalar = Scalar;       ///< coordinate type
    using point = vec3<Scalar>;  ///< position type

    // ----- counts and ranges -----------------------------------------------------------------
    /// Live element counts, and index bounds (deleted elements included until collected).
    ///@{
    std::size_t vertex_count() const noexcept { return positions_.size() - deleted_vertices_; }
    std::size_t edge_count() const noexcept { return halfedges_.size() / 2 - deleted_edges_; }
    std::size_t halfedge_count() const noexcept { return 2 * edge_count(); }
    std::size_t face_count() const noexcept { return faces_.size() - deleted_faces_; }
    std::size_t vertex_index_bound() const noexcept { return positions_.size(); }
    std::size_t edge_index_bound() const noexcept { return halfedges_.size() / 2; }
    std::size_t halfedge_index_bound() const noexcept { return halfedges_.size(); }
    std::size_t face_index_bound() const noexcept { return faces_.size(); }

    ///@}

    /// Ranges over the live elements, in index order. O(1) to make; iterating is O(bound).
    ///@{
    detail::element_range<vertex_handle> vertices() const {
        return {static_cast<std::uint32_t>(positions_.size()), deleted_vertices_ ? vertex_deleted_.data() : nullptr};
    }
    detail::element_range<edge_handle> edges() const {
        return {static_cast<std::uint32_t>(halfedges_.size() / 2), deleted_edges_ ? edge_deleted_.data() : nullptr};
    }
    detail::element_range<face_handle> faces() const {
        return {static_cast<std::uint32_t>(faces_.size()), deleted_faces_ ? face_deleted_.data() : nullptr};
    }
    ///@}
    /// All live halfedges (both of each live edge), in index order.
    detail::element_range<halfedge_handle, 1> halfedges() const {
        return {static_cast<std::uint32_t>(halfedges_.size()), deleted_edges_ ? edge_deleted_.data() : nullptr};
    }

    /// Whether the handle names a live element. O(1).
    ///@{
    // With nothing deleted no flag is read: add_face checks every corner, and a mesh built
    // without deletions keeps its flag arrays unwritten (their pages never mapped).
    bool is_valid(vertex_handle v) const noexcept {
        return v.index < positions_.size() && (deleted_vertices_ == 0 || !vertex_deleted_[v.index]);
    }
    bool is_valid(face_handle f) const noexcept {
        return f.index < faces_.size() && (deleted_faces_ == 0 || !face_deleted_[f.index]);
    }
    bool is_valid(edge_handle e) const noexcept {
        return e.index < halfedges_.size() / 2 && (deleted_edges_ == 0 || !edge_deleted_[e.index]);
    }
    bool is_valid(halfedge_handle h) const noexcept {
        return h.index < halfedges_.size() && (deleted_edges_ == 0 || !edge_deleted_[h.index >> 1]);
    }

    ///@}

    // ----- slot reuse and stale handles --------------------------------------------------------
    /// The generation of h's slot: 0 until the slot is first reused, one more at each reuse (a
    /// halfedge shares its edge's). O(1).
    ///@{
    std::uint32_t generation(vertex_handle v) const noexcept { return vertex_generations_[v.index]; }
    std::uint32_t generation(edge_handle e) const noexcept { return edge_generations_[e.index]; }
    std::uint32_t generation(halfedge_handle h) const noexcept { return edge_generations_[h.index >> 1]; }
    std::uint32_t generation(face_handle f) const noexcept { return face_generations_[f.index]; }
    ///@}
    /// h with its slot's current generation, for keeping across edits that delete. O(1).
    template <class Tag>
    versioned_handle<Tag> versioned(index_handle<Tag> h) const noexcept {
        return {h, generation(h)};
    }
    /// Whether the element h was taken from is still alive: the slot is live and has not been
    /// reused since. O(1). (Not across collect_garbage, which renumbers.)
    template <class Tag>
    bool is_valid(versioned_handle<Tag> h) const noexcept {
        return is_valid(h.handle) && generation(h.handle) == h.generation;
    }
    /// Whether new elements take freed slots (the default) or always append.
    bool slot_reuse() const noexcept { return reuse_slots_; }
    /// Turns slot reuse on or off. With it off, index order is creation order (what the CLI
    /// relies on to write new vertices after the input's); deleted slots still wait on the free
    /// lists and are taken again once reuse is back on. O(1).
    void set_slot_reuse(bool on) noexcept { reuse_slots_ = on; }
    /// Deleted slots waiting for reuse, of each kind. O(1).
    ///@{
    std::size_t free_vertex_slots() const noexcept { return free_vertices_.size(); }
    std::size_t free_edge_slots() const noexcept { return free_edges_.size(); }
    std::size_t free_face_slots() const noexcept { return free_faces_.size(); }
    ///@}

    // ----- navigation, all O(1) ---------------------------------------------------------------
    /// Halfedge navigation (thesis 1.2.3), all O(1): next and previous halfedge in the loop,
    /// the opposite halfedge (h ^ 1), end and start vertex, face (null on the boundary), edge,
    /// an edge's halfedge i (0 or 1), a vertex's outgoing halfedge (a boundary one on the
    /// boundary, null if isolated), a face's outer-loop halfedge, boundary tests, and an
    /// edge's two vertices.
    ///@{
    halfedge_handle next(halfedge_handle h) const { return halfedges_[h.index].next; }
    halfedge_handle prev(halfedge_handle h) const { return halfedges_[h.index].prev; }
    static constexpr halfedge_handle opposite(halfedge_handle h) noexcept { return halfedge_handle(h.index ^ 1u); }
    vertex_handle target(halfedge_handle h) const { return halfedges_[h.index].target; }
    vertex_handle source(halfedge_handle h) const { return halfedges_[h.index ^ 1u].target; }
    face_handle face(halfedge_handle h) const { return halfedges_[h.index].face; }
    static constexpr edge_handle edge(halfedge_handle h) noexcept { return edge_handle(h.index >> 1); }
    static constexpr halfedge_handle edge_halfedge(edge_handle e, unsigned i = 0) noexcept {
        return halfedge_handle(2 * e.index + i);
    }
    halfedge_handle vertex_halfedge(vertex_handle v) const { return vertex_out_[v.index]; }
    halfedge_handle face_halfedge(face_handle f) const { return faces_[f.index]; }
    bool is_boundary(halfedge_handle h) const { return face(h).is_null(); }
    bool is_boundary(edge_handle e) const {
        return is_boundary(edge_halfedge(e, 0)) || is_boundary(edge_halfedge(e, 1));
    }
    /// A vertex is on the boundary when its stored outgoing halfedge is (kept so by add_face),
    /// or when it is isolated.
    bool is_boundary(vertex_handle v) const {
        const auto h = vertex_out_[v.index];
        return h.is_null() || is_boundary(h);
    }
    bool is_isolated(vertex_handle v) const { return vertex_out_[v.index].is_null(); }
    std::array<vertex_handle, 2> edge_vertices(edge_handle e) const {
        return {target(edge_halfedge(e, 1)), target(edge_halfedge(e, 0))};
    }
    ///@}

    // ----- circulators ----------------------------------------------------------------------------
    /// \cond INTERNAL
    struct loop_step {
        static halfedge_handle step(const basic_halfedge_mesh& m, halfedge_handle h) { return m.next(h); }
        static halfedge_handle value(const basic_halfedge_mesh&, halfedge_handle h) { return h; }
    };
    struct loop_vertex_step : loop_step {
        static vertex_handle value(const basic_halfedge_mesh& m, halfedge_handle h) { return m.target(h); }
    };
    struct outgoing_step {
        static halfedge_handle step(const basic_halfedge_mesh& m, halfedge_handle h) { return m.next(opposite(h)); }
        static halfedge_handle value(const basic_halfedge_mesh&, halfedge_handle h) { return h; }
    };
    struct outgoing_target_step : outgoing_step {
        static vertex_handle value(const basic_halfedge_mesh& m, halfedge_handle h) { return m.target(h); }
    };
    struct outgoing_edge_step : outgoing_step {
        static edge_handle value(const basic_halfedge_mesh&, halfedge_handle h) { return edge(h); }
    };
    struct outgoing_face_step : outgoing_step {
        static bool keep(const basic_halfedge_mesh& m, halfedge_handle h) { return !m.is_boundary(h); }
        static face_handle value(const basic_halfedge_mesh& m, halfedge_handle h) { return m.face(h); }
    };
    template <class Policy>
    using loop = detail::loop_range<basic_halfedge_mesh, halfedge_handle, Policy>;
    /// \endcond

    /// Halfedges of the loop through h (a face's outer loop, an inner ring, or a boundary loop).
    loop<loop_step> loop_halfedges(halfedge_handle h) const { return {*this, h}; }
    /// The outer loop's vertices in winding order, starting at the first vertex given to add_face.
    loop<loop_vertex_step> face_vertices(face_handle f) const { return {*this, face_halfedge(f)}; }
    /// The outer loop's halfedges, starting at face_halfedge(f). O(V_consistF).
    loop<loop_step> face_halfedges(face_handle f) const { return {*this, face_halfedge(f)}; }
    /// Outgoing halfedges of v, O(V_adjacentV).
    loop<outgoing_step> outgoing_halfedges(vertex_handle v) const { return {*this, vertex_halfedge(v)}; }
    /// Neighbour vertices and incident edges of v, around its fan. O(V_adjacentV).
    ///@{
    loop<outgoing_target_step> adjacent_vertices(vertex_handle v) const { return {*this, vertex_halfedge(v)}; }
    ///@}
    /// \copydoc adjacent_vertices
    loop<outgoing_edge_step> vertex_edges(vertex_handle v) const { return {*this, vertex_halfedge(v)}; }
    /// Faces around v (boundary gaps skipped), O(F_adjacentV).
    loop<outgoing_face_step> vertex_faces(vertex_handle v) const { return {*this, vertex_halfedge(v)}; }
    /// Faces across the edges of f's outer loop and inner rings, O(F_adjacentF).
    std::vector<face_handle> adjacent_faces(face_handle f) const {
        std::vector<face_handle> out;
        auto collect = [&](halfedge_handle start) {
            for (auto h : loop_halfedges(start)) {
                const auto g = face(opposite(h));
                if (!g.is_null()) out.push_back(g);
            }
        };
        collect(face_halfedge(f));
        for (auto r : inner_rings(f)) collect(r);
        return out;
    }
    /// Number of edges at v. O(V_adjacentV).
    std::size_t valence(vertex_handle v) const {
        return static_cast<std::size_t>(std::ranges::distance(outgoing_halfedges(v)));
    }

    /// Finds the halfedge from a to b, or null. O(V_adjacentV).
    halfedge_handle find_halfedge(vertex_handle a, vertex_handle b) const {
        for (auto h : outgoing_halfedges(a))
            if (target(h) == b) return h;
        return {};
    }

    // ----- inner rings ---------------------------------------------------------------------------
    /// One halfedge of each inner ring of f.
    std::span<const halfedge_handle> inner_rings(face_handle f) const {
        const auto r = face_rings_[f.index];
        if (r == 0) return {};
        return ring_lists_[r - 1];
    }
    /// Whether f has holes. O(1).
    bool has_inner_rings(face_handle f) const {
        const auto r = face_rings_[f.index];
        return r != 0 && !ring_lists_[r - 1].empty();
    }
    /// Registers the loop through h as an inner ring of f (raw: does not set the loop's faces).
    void add_inner_ring(face_handle f, halfedge_handle h) {
        if (face_rings_[f.index] == 0) {
            ring_lists_.emplace_back();
            face_rings_.at(f.index, faces_.size()) = static_cast<std::uint32_t>(ring_lists_.size());
        }
        ring_lists_[face_rings_[f.index] - 1].push_back(h);
        ++changes_;
    }
    /// Unregisters the inner ring of f that contains h; returns whether one was found. O(ring size).
    bool remove_inner_ring(face_handle f, halfedge_handle h) {
        const auto r = face_rings_[f.index];
        if (r == 0) return false;
        auto& list = ring_lists_[r - 1];
        for (auto it = list.begin(); it != list.end(); ++it)
            for (auto g : loop_halfedges(*it))
                if (g == h) {
                    list.erase(it);
                    ++changes_;
                    return true;
                }
        return false;
    }
    /// Re-points the stored halfedge of the ring containing `old_h` to `new_h`.
    void set_inner_ring_halfedge(face_handle f, halfedge_handle old_h, halfedge_handle new_h) {
        const auto r = face_rings_[f.index];
        if (r == 0) return;
        for (auto& h : ring_lists_[r - 1])
            if (h == old_h) h = new_h;
    }

    // ----- geometry ------------------------------------------------------------------------------
    /// Read or move a vertex, O(1); all positions by vertex index.
    ///@{
    const point& position(vertex_handle v) const { return positions_[v.index]; }
    void set_position(vertex_handle v, const point& p) { positions_[v.index] = p; }
    std::span<const point> positions() const noexcept { return positions_; }
    ///@}

    // ----- building ------------------------------------------------------------------------------
    /// Adds an isolated vertex at p, in a freed slot if there is one. O(1) (amortised when it
    /// appends).
    vertex_handle add_vertex(const point& p) {
        if (reuse_slots_ && !free_vertices_.empty()) {
            const std::uint32_t v = free_vertices_.top();
            ++vertex_generations_.at(v, positions_.size());  // may throw: nothing changed yet
            vertex_props_.reset(v);
            free_vertices_.pop(vertex_out_[v].index);
            positions_[v] = p;
            vertex_out_[v] = {};
            vertex_deleted_.set(v, 0);
            --deleted_vertices_;
            ++changes_;
            return vertex_handle(v);
        }
        vertex_deleted_.ensure(positions_.size() + 1);
        vertex_out_.ensure_room(positions_.size() + 1);  // so that no push_back fails after the first
        positions_.push_back(p);
        vertex_out_.push_back({});
        vertex_props_.push_back();
        ++changes_;
        return vertex_handle(positions_.size() - 1);
    }

    /// add_face() for a braced list of vertices.
    result<face_handle> add_face(std::initializer_list<vertex_handle> vs) {
        return add_face(std::span<const vertex_handle>(vs.begin(), vs.size()));
    }

    /// Adds a polygon, linking it to the faces already present. Fails, with the mesh unchanged,
    /// when the face has fewer than 3 or repeated vertices, names a missing vertex, would give
    /// an edge a third face (or a face on the wrong side: orientation conflict), or would make a
    /// vertex non-manifold. O(sum of V_adjacentV over its corners).
    /// Faces may arrive in any order: a face may touch a vertex in a fan of its own, separated
    /// from the vertex's other fans by boundary gaps (a pinch that validate() reports as a
    /// non-manifold vertex until the faces between the fans are added).
    result<face_handle> add_face(std::span<const vertex_handle> vs) {
        return detail::link_face<basic_halfedge_mesh, mesh_traits<basic_halfedge_mesh>>(
            *this, vs, link_scratch_, [this](vertex_handle v) { return is_valid(v); });
    }

    /// Makes the stored outgoing halfedge of v a boundary one if v has any. O(V_adjacentV).
    void adjust_outgoing_halfedge(vertex_handle v) {
        detail::prefer_boundary_halfedge<basic_halfedge_mesh, mesh_traits<basic_halfedge_mesh>>(*this, v);
    }

    // ----- bulk building ---------------------------------------------------------------------------
    /// Builds a mesh from an indexed face list in one pass, with the checks add_face makes:
    /// face i has the vertices corners[face_offsets[i] .. face_offsets[i + 1]) (so
    /// face_offsets has one entry more than there are faces, starting at 0 and ending at
    /// corners.size()). Vertex i is at points[i]; unused points become isolated vertices.
    /// Vertex, face, edge and halfedge numbering: vertices and faces in input order, edges in
    /// order of their first corner, face_vertices(f) starting at the face's first corner.
    /// Errors (nothing is built): invalid_argument for inconsistent offsets; degenerate_face
    /// for fewer than 3 or repeated vertices; invalid_handle for an index >= points.size();
    /// orientation_conflict when two faces run an edge in the same direction; non_manifold for
    /// an edge with more than two faces or a vertex whose faces form more than one fan (a
    /// pinch, which add_face tolerates as an intermediate state but a finished mesh must not have).
    /// Complexity O(V + C x valence) for C corners, linear in practice; no per-face allocation.
    /// Scratch memory: 24 bytes per corner and 8 per vertex besides the mesh (an input it
    /// refuses after the per-face checks is gone over a second time, with 12 bytes per corner
    /// more, to name the same element whatever the face order).
    static result<basic_halfedge_mesh> from_polygons(std::span<const point> points,
                                                     std::span<const std::uint32_t> face_offsets,
                                                     std::span<const std::uint32_t> corners) {
        return detail::halfedge_from_polygons<basic_halfedge_mesh>::build(
            points.size(), [&](std::vector<point>& out) { out.assign(points.begin(), points.end()); }, face_offsets,
            corners);
    }

    /// Replaces this mesh's elements with the indexed polygons, as from_polygons builds them
    /// (the same checks, errors and numbering; position i is points[i] converted to Scalar),
    /// keeping what clear_elements keeps: the named properties (sized to the new elements, at
    /// their defaults) and the slot_reuse() setting. On error the mesh is unchanged. The result
    /// is the mesh that clear_elements() followed by add_face of every face in order would give,
    /// for every input both accept (vertex_halfedge included: the boundary one, else the one
    /// leaving the vertex's corner in its last face): what read_mesh uses for a file that needs
    /// no repair. Offsets may be 32- or 64-bit. Complexity as from_polygons.
    template <class Offset>
        requires(std::same_as<Offset, std::uint32_t> || std::same_as<Offset, std::uint64_t>)
    result<void> assign_polygons(std::span<const std::array<double, 3>> points, std::span<const Offset> face_offsets,
                                 std::span<const std::uint32_t> corners) {
        auto built = detail::halfedge_from_polygons<basic_halfedge_mesh>::build(
            points.size(),
            [&](std::vector<point>& out) {
                out.reserve(points.size());
                for (const auto& p : points)
                    out.push_back(
                        point{static_cast<Scalar>(p[0]), static_cast<Scalar>(p[1]), static_cast<Scalar>(p[2])});
            },
            face_offsets, corners);
        if (!built) return built.error();
        adopt_elements(std::move(*built));
        return {};
    }

    /// assign_polygons() taking the positions whole: on success they are moved into the mesh
    /// (no copy; `positions` is left empty), on error the mesh and `positions` are unchanged.
    template <class Offset>
        requires(std::same_as<Offset, std::uint32_t> || std::same_as<Offset, std::uint64_t>)
    result<void> assign_polygons(std::vector<point>& positions, std::span<const Offset> face_offsets,
                                 std::span<const std::uint32_t> corners) {
        auto built = detail::halfedge_from_polygons<basic_halfedge_mesh>::build(
            positions.size(), [&](std::vector<point>& out) { out = std::move(positions); }, face_offsets, corners);
        if (!built) return built.error();
        adopt_elements(std::move(*built));
        return {};
    }

private:
    // Building from indexed polygons (the checks, the one-pass link and the checked fallback) lives in
    // detail/halfedge_from_polygons.hpp; it reads and writes the records directly.
    friend struct detail::halfedge_from_polygons<basic_halfedge_mesh>;
    // Reversing the winding, garbage collection and bulk resize live in
    // detail/halfedge_maintenance.hpp, for the same reason.
    friend struct detail::halfedge_maintenance<basic_halfedge_mesh>;

    // Takes over a built mesh's elements, keeping this mesh's properties (emptied, then sized to
    // the new elements at their defaults) and slot-reuse setting, as clear_elements then add_*.
    void adopt_elements(basic_halfedge_mesh&& built) { replace_elements(std::move(built), 2); }

    // What clear_elements and adopt_elements share: `next`'s elements replace this mesh's; the
    // named properties are emptied (their defaults kept) and sized to the new elements; the
    // slot-reuse setting stays; the change count grows by `change_step`.
    void replace_elements(basic_halfedge_mesh&& next, std::uint64_t change_step) {
        auto vertex_props = std::move(vertex_props_);
        auto edge_props = std::move(edge_props_);
        auto halfedge_props = std::move(halfedge_props_);
        auto face_props = std::move(face_props_);
        const auto changes = changes_;
        const bool reuse = reuse_slots_;
        *this = std::move(next);
        reuse_slots_ = reuse;
        vertex_props_ = std::move(vertex_props);
        vertex_props_.resize(0);
        vertex_props_.resize(positions_.size());
        edge_props_ = std::move(edge_props);
        edge_props_.resize(0);
        edge_props_.resize(halfedges_.size() / 2);
        halfedge_props_ = std::move(halfedge_props);
        halfedge_props_.resize(0);
        halfedge_props_.resize(halfedges_.size());
        face_props_ = std::move(face_props);
        face_props_.resize(0);
        face_props_.resize(faces_.size());
        changes_ = changes + change_step;
    }

public:
    // ----- raw mutation (the layer Euler operators use; keeps nothing consistent) ------------------
    /// Raw setters, O(1): next (and the next's prev), target, face, a vertex's outgoing and a
    /// face's outer halfedge.
    ///@{
    void set_next(halfedge_handle h, halfedge_handle n) {
        link(h, n);
        ++changes_;
    }
    void set_target(halfedge_handle h, vertex_handle v) {
        halfedges_[h.index].target = v;
        ++changes_;
    }
    void set_face(halfedge_handle h, face_handle f) {
        halfedges_[h.index].face = f;
        ++changes_;
    }
    void set_vertex_halfedge(vertex_handle v, halfedge_handle h) {
        vertex_out_[v.index] = h;
        ++changes_;
    }
    void set_face_halfedge(face_handle f, halfedge_handle h) {
        faces_[f.index] = h;
        ++changes_;
    }
    ///@}

    /// A new edge from a to b, in a freed slot if there is one; returns the halfedge a->b.
    /// next/prev/face are unset (null face). O(1) (amortised when it appends).
    halfedge_handle new_edge(vertex_handle a, vertex_handle b) {
        if (reuse_slots_ && !free_edges_.empty()) {
            const std::uint32_t e = free_edges_.top();
            ++edge_generations_.at(e, halfedges_.size() / 2);  // may throw: nothing changed yet
            edge_props_.reset(e);
            halfedge_props_.reset(2 * std::size_t(e));
            halfedge_props_.reset(2 * std::size_t(e) + 1);
            free_edges_.pop(halfedges_[2 * std::size_t(e)].next.index);
            halfedges_[2 * std::size_t(e)] = {b, {}, {}, {}};
            halfedges_[2 * std::size_t(e) + 1] = {a, {}, {}, {}};
            edge_deleted_.set(e, 0);
            --deleted_edges_;
            ++changes_;
            return halfedge_handle(2 * e);
        }
        return append_edge(a, b);  // out of line, so that the reuse path above inlines into the operators
    }
    /// A new face with no halfedge and no rings, in a freed slot if there is one. O(1)
    /// (amortised when it appends).
    face_handle new_face() {
        if (reuse_slots_ && !free_faces_.empty()) {
            const std::uint32_t f = free_faces_.top();
            ++face_generations_.at(f, faces_.size());  // may throw: nothing changed yet
            face_props_.reset(f);
            free_faces_.pop(faces_[f].index);
            faces_[f] = {};  // an emptied ring list is kept for the next holes
            face_deleted_.set(f, 0);
            --deleted_faces_;
            ++changes_;
            return face_handle(f);
        }
        return append_face();
    }
    /// Marks an element deleted and frees its slot for reuse (raw: nothing is re-linked). The
    /// slot's records keep their values except one, which now holds the free list (as on CGAL's
    /// Surface_mesh): a vertex's outgoing halfedge, an edge's first halfedge's next, a face's
    /// halfedge. Read what you need before erasing. Erasing a deleted element does nothing.
    /// O(1); never allocates.
    ///@{
    void erase_edge(edge_handle e) noexcept {
        if (!edge_deleted_[e.index]) {
            edge_deleted_.set(e.index, 1);
            ++deleted_edges_;
            ++changes_;
            free_edges_.push(e.index, halfedges_[2 * std::size_t(e.index)].next.index);
        }
    }
    void erase_face(face_handle f) noexcept {
        if (!face_deleted_[f.index]) {
            face_deleted_.set(f.index, 1);
            ++deleted_faces_;
            ++changes_;
            if (const auto r = face_rings_[f.index]; r != 0) ring_lists_[r - 1].clear();
            free_faces_.push(f.index, faces_[f.index].index);
        }
    }
    void erase_vertex(vertex_handle v) noexcept {
        if (!vertex_deleted_[v.index]) {
            vertex_deleted_.set(v.index, 1);
            ++deleted_vertices_;
            ++changes_;
            free_vertices_.push(v.index, vertex_out_[v.index].index);
        }
    }

    ///@}

    /// Reverses the winding of every face in one pass over the halfedge array (what
    /// flip_normals uses): each edge's two halfedges swap targets and each halfedge swaps next
    /// and prev, all within the edge's pair of records; then each vertex takes the opposite of
    /// its outgoing halfedge, or on the boundary the boundary halfedge that entered it (now
    /// leaving it). Faces keep their outer halfedge and inner rings; handles stay valid.
    /// O(H_all + V_all), no scratch memory.
    void reverse_orientation() noexcept {
        detail::halfedge_maintenance<basic_halfedge_mesh>::reverse_orientation(*this);
    }

    /// Whether deleted elements wait for collect_garbage().
    bool has_garbage() const noexcept { return deleted_vertices_ + deleted_edges_ + deleted_faces_ > 0; }

    /// Drops deleted elements, renumbers the rest in their old order, rewrites every reference,
    /// and compacts the properties. Returns the old -> new maps. Invalidates handles and views.
    /// O(V_all + E_all + F_all).
    index_remap collect_garbage() { return detail::halfedge_maintenance<basic_halfedge_mesh>::collect_garbage(*this); }

    /// Reserves storage for that many vertices, edges and faces (index bounds).
    void reserve(std::size_t vertices, std::size_t edges, std::size_t faces) {
        detail::reserve_huge(positions_, vertices);
        vertex_out_.reserve(vertices);
        vertex_deleted_.ensure(vertices);
        halfedges_.reserve(2 * edges);
        edge_deleted_.ensure(edges);
        faces_.reserve(faces);
        face_deleted_.ensure(faces);
    }
    /// Sets the index bounds to `vertices`, `edges` and `faces` (raw, like new_edge): appends
    /// unlinked elements at their defaults (isolated vertices at the origin, edges whose
    /// halfedges have null target, next, prev and face, faces without a halfedge), always at the
    /// end whatever slot_reuse() says, with their properties at their defaults; or drops the last
    /// ones. What subdivision takes its new elements from, in blocks, through the traits'
    /// optional resize: one call per block instead of one add per element.
    /// \pre a dropped element is alive and nothing refers to it.
    /// May throw std::bad_alloc, with the mesh unchanged. O(change) (amortised when it grows).
    void resize(std::size_t vertices, std::size_t edges, std::size_t faces) {
        detail::halfedge_maintenance<basic_halfedge_mesh>::resize(*this, vertices, edges, faces);
    }
    /// Removes everything, properties included.
    void clear() { *this = basic_halfedge_mesh(); }
    /// Removes every element and keeps the named properties (emptied, their defaults kept), as
    /// OpenMesh's clear() does: what reading a file into a mesh uses. The slot_reuse() setting
    /// is kept too. The change count keeps
    /// growing, so an index built before sees that it is stale. Invalidates all handles. O(1)
    /// besides freeing the storage.
    void clear_elements() { replace_elements(basic_halfedge_mesh(), 1); }

    /// Grows on every change of connectivity or of the element set.
    std::uint64_t change_count() const noexcept { return changes_; }

private:
    struct halfedge_record {
        vertex_handle target;
        face_handle face;
        halfedge_handle next, prev;
    };

    halfedge_handle append_edge(vertex_handle a, vertex_handle b) {
        edge_deleted_.ensure(halfedges_.size() / 2 + 1);
        halfedges_.ensure_room(halfedges_.size() + 2);  // both halfedges or neither
        const auto h = halfedge_handle(halfedges_.size());
        halfedges_.push_back({b, {}, {}, {}});
        halfedges_.push_back({a, {}, {}, {}});
        edge_props_.push_back();
        halfedge_props_.push_back();
        halfedge_props_.push_back();
        ++changes_;
        return h;
    }
    face_handle append_face() {
        face_deleted_.ensure(faces_.size() + 1);
        faces_.push_back({});
        face_props_.push_back();
        ++changes_;
        return face_handle(faces_.size() - 1);
    }

    void link(halfedge_handle a, halfedge_handle b) {
        halfedges_[a.index].next = b;
        halfedges_[b.index].prev = a;
    }

    // A face stores its outer-loop halfedge only (4 bytes, as CGAL's does): the few faces with
    // holes find their ring list through face_rings_ (list index + 1; 0 for none). Deleted flags
    // read as zero until the first erasure writes one, and hold at least each index bound so
    // that erasing never allocates. The connectivity records grow by realloc (trivial_array):
    // reserve() before a subdivision moves them without a copy and keeps their pages. Positions
    // stay a std::vector so that assign_polygons can take the caller's vector whole.
    std::vector<point> positions_;
    detail::trivial_array<halfedge_handle> vertex_out_;
    detail::zeroed_array<std::uint8_t> vertex_deleted_;
    detail::trivial_array<halfedge_record> halfedges_;
    detail::zeroed_array<std::uint8_t> edge_deleted_;
    detail::trivial_array<halfedge_handle> faces_;
    detail::zeroed_array<std::uint8_t> face_deleted_;
    detail::zeroed_array<std::uint32_t> face_rings_;
    std::vector<std::vector<halfedge_handle>> ring_lists_;
    std::size_t deleted_vertices_ = 0, deleted_edges_ = 0, deleted_faces_ = 0;
    // Deleted slots waiting for reuse, and each slot's reuse count (see the class comment).
    detail::free_slots free_vertices_, free_edges_, free_faces_;
    detail::zeroed_array<std::uint32_t> vertex_generations_, edge_generations_, face_generations_;
    bool reuse_slots_ = true;
    std::uint64_t changes_ = 0;
    // Reused by add_face so that building a mesh does not allocate per face.
    detail::face_link_scratch<halfedge_handle> link_scratch_;
};

using halfedge_mesh = basic_halfedge_mesh<double>;

/// Native traits: halfedge navigation, inner rings and raw mutation, all at thesis cost.
template <class Scalar>
struct mesh_traits<basic_halfedge_mesh<Scalar>> : detail::native_halfedge_traits<basic_halfedge_mesh<Scalar>> {
    using mesh = basic_halfedge_mesh<Scalar>;

    static auto inner_rings(const mesh& m, face_handle f) { return m.inner_rings(f); }
    static void add_inner_ring(mesh& m, face_handle f, halfedge_handle h) { m.add_inner_ring(f, h); }
    static void remove_inner_ring(mesh& m, face_handle f, halfedge_handle h) { m.remove_inner_ring(f, h); }
    /// Optional (not a concept requirement): flip_normals in one pass over the halfedges.
    static void reverse_orientation(mesh& m) noexcept { m.reverse_orientation(); }
    /// Optional (not a concept requirement): room for this many elements (index bounds), which
    /// the edits and subdivision use before they grow the mesh.
    static void reserve(mesh& m, std::size_t vertices, std::size_t edges, std::size_t faces) {
        m.reserve(vertices, edges, faces);
    }
    /// Optional (not a concept requirement): unlinked elements appended or dropped in bulk,
    /// and the element of an index, so that subdivision takes its new elements in blocks
    /// (bulk_growable_mesh) instead of one add_vertex, new_edge or new_face each.
    static void resize(mesh& m, std::size_t vertices, std::size_t edges, std::size_t faces) {
        m.resize(vertices, edges, faces);
    }
    /// The element of index i (no check: i below the index bound). O(1).
    ///@{
    static vertex_handle vertex_at(const mesh&, std::size_t i) { return vertex_handle(static_cast<std::uint32_t>(i)); }
    static edge_handle edge_at(const mesh&, std::size_t i) { return edge_handle(static_cast<std::uint32_t>(i)); }
    static face_handle face_at(const mesh&, std::size_t i) { return face_handle(static_cast<std::uint32_t>(i)); }
    ///@}
};

}  // namespace hmira
