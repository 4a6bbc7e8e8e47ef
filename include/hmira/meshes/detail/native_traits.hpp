// hmira/meshes/detail/native_traits.hpp
// The part of mesh_traits that hmira's own meshes share: each operation forwards to the
// mesh's member of the same name, so the three specialisations list only what is theirs.
// Static inline forwarding, no state and no virtual call: algorithms see the same code as if
// each specialisation spelt the functions out.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "../../core/result.hpp"
#include "../../core/vec3.hpp"
#include "../handles.hpp"

namespace hmira::detail {

/// Elements, positions, face corners and building: what every hmira mesh has.
template <class Mesh>
struct native_element_traits {
    using mesh = Mesh;
    using vertex_handle = hmira::vertex_handle;
    using face_handle = hmira::face_handle;
    using scalar = typename Mesh::scalar;

    static auto vertices(const mesh& m) { return m.vertices(); }
    static auto faces(const mesh& m) { return m.faces(); }
    static std::size_t vertex_count(const mesh& m) { return m.vertex_count(); }
    static std::size_t face_count(const mesh& m) { return m.face_count(); }
    static std::size_t vertex_index(const mesh&, vertex_handle v) { return v.index; }
    static std::size_t vertex_index_bound(const mesh& m) { return m.vertex_index_bound(); }
    static std::size_t face_index(const mesh&, face_handle f) { return f.index; }
    static std::size_t face_index_bound(const mesh& m) { return m.face_index_bound(); }
    static auto face_vertices(const mesh& m, face_handle f) { return m.face_vertices(f); }
    static const vec3<scalar>& position(const mesh& m, vertex_handle v) { return m.position(v); }
    static void set_position(mesh& m, vertex_handle v, const vec3<scalar>& p) { m.set_position(v, p); }
    static vertex_handle add_vertex(mesh& m, const vec3<scalar>& p) { return m.add_vertex(p); }
    static result<face_handle> add_face(mesh& m, std::span<const vertex_handle> vs) { return m.add_face(vs); }
    static std::uint64_t change_count(const mesh& m) { return m.change_count(); }
};

/// Adds edges, halfedge navigation, adjacency and the raw mutation layer the Euler operators
/// are written on: what halfedge_mesh and winged_edge_mesh both have.
template <class Mesh>
struct native_halfedge_traits : native_element_traits<Mesh> {
    using mesh = Mesh;
    using vertex_handle = hmira::vertex_handle;
    using face_handle = hmira::face_handle;
    using edge_handle = hmira::edge_handle;
    using halfedge_handle = hmira::halfedge_handle;

    static auto edges(const mesh& m) { return m.edges(); }
    static auto halfedges(const mesh& m) { return m.halfedges(); }
    static std::size_t edge_count(const mesh& m) { return m.edge_count(); }
    static std::size_t edge_index(const mesh&, edge_handle e) { return e.index; }
    static std::size_t edge_index_bound(const mesh& m) { return m.edge_index_bound(); }
    static std::size_t halfedge_index(const mesh&, halfedge_handle h) { return h.index; }
    static std::size_t halfedge_index_bound(const mesh& m) { return m.halfedge_index_bound(); }

    static auto adjacent_vertices(const mesh& m, vertex_handle v) { return m.adjacent_vertices(v); }
    static auto vertex_faces(const mesh& m, vertex_handle v) { return m.vertex_faces(v); }
    static auto vertex_edges(const mesh& m, vertex_handle v) { return m.vertex_edges(v); }
    static auto adjacent_faces(const mesh& m, face_handle f) { return m.adjacent_faces(f); }
    static auto edge_vertices(const mesh& m, edge_handle e) { return m.edge_vertices(e); }

    static halfedge_handle next(const mesh& m, halfedge_handle h) { return m.next(h); }
    static halfedge_handle prev(const mesh& m, halfedge_handle h) { return m.prev(h); }
    static halfedge_handle opposite(const mesh&, halfedge_handle h) { return mesh::opposite(h); }
    static vertex_handle target(const mesh& m, halfedge_handle h) { return m.target(h); }
    static face_handle face(const mesh& m, halfedge_handle h) { return m.face(h); }
    static edge_handle edge(const mesh&, halfedge_handle h) { return mesh::edge(h); }
    static halfedge_handle edge_halfedge(const mesh&, edge_handle e) { return mesh::edge_halfedge(e); }
    static halfedge_handle vertex_halfedge(const mesh& m, vertex_handle v) { return m.vertex_halfedge(v); }
    static halfedge_handle face_halfedge(const mesh& m, face_handle f) { return m.face_halfedge(f); }
    static constexpr face_handle null_face() { return {}; }
    static constexpr halfedge_handle null_halfedge() { return {}; }

    static void set_next(mesh& m, halfedge_handle h, halfedge_handle n) { m.set_next(h, n); }
    static void set_target(mesh& m, halfedge_handle h, vertex_handle v) { m.set_target(h, v); }
    static void set_face(mesh& m, halfedge_handle h, face_handle f) { m.set_face(h, f); }
    static void set_vertex_halfedge(mesh& m, vertex_handle v, halfedge_handle h) { m.set_vertex_halfedge(v, h); }
    static void set_face_halfedge(mesh& m, face_handle f, halfedge_handle h) { m.set_face_halfedge(f, h); }
    static halfedge_handle new_edge(mesh& m, vertex_handle a, vertex_handle b) { return m.new_edge(a, b); }
    static face_handle new_face(mesh& m) { return m.new_face(); }
    static void erase_edge(mesh& m, edge_handle e) { m.erase_edge(e); }
    static void erase_face(mesh& m, face_handle f) { m.erase_face(f); }
    static void erase_vertex(mesh& m, vertex_handle v) { m.erase_vertex(v); }

    /// Whether the element was erased (optional traits query: operators refuse such handles
    /// with errc::invalid_handle). Meaningful for an index below the bound. O(1).
    static bool is_removed(const mesh& m, vertex_handle v) { return !m.is_valid(v); }
    static bool is_removed(const mesh& m, face_handle f) { return !m.is_valid(f); }
    static bool is_removed(const mesh& m, edge_handle e) { return !m.is_valid(e); }
    static bool is_removed(const mesh& m, halfedge_handle h) { return !m.is_valid(h); }
};

}  // namespace hmira::detail
