// hmira/algorithms/orientation/flip_normals.hpp
// Reverses the orientation of every face, so every normal points the other way (thesis 5.2).
// A face-vertex model reverses each face's vertex list; a halfedge model reverses every loop
// and re-points targets, so that its connectivity stays consistent. Either way the winding
// really changes: flipping twice gives back the same mesh.
#pragma once

#include <cstddef>
#include <vector>

#include "../../concepts.hpp"

namespace hmira {

/// A halfedge model flips as a whole by re-linking its halfedges.
template <class M, class T = default_traits<M>>
concept halfedge_flip_mesh = halfedge_mutable_mesh<M, T> && halfedge_index_mesh<M, T> && vertex_index_mesh<M, T>;

/// A mesh whose faces can be flipped: face by face (face_reversible_mesh), or as a whole by
/// re-linking halfedges (halfedge_flip_mesh).
template <class M, class T = default_traits<M>>
concept flip_normals_mesh = face_reversible_mesh<M, T> || halfedge_flip_mesh<M, T>;

/// Reverses the winding of every face of a face-vertex model, each face's vertex order in
/// place. Returns the number of faces flipped. Complexity O(sum of face degrees).
template <class M, class T = default_traits<M>>
    requires face_reversible_mesh<M, T>
std::size_t flip_normals(M& mesh) {
    std::size_t n = 0;
    for (auto f : T::faces(mesh)) {
        T::reverse_face(mesh, f);
        ++n;
    }
    return n;
}

/// Reverses the winding of every face of a halfedge model: each halfedge's direction is
/// reversed (next <-> prev, target <-> source); faces keep their halfedges, each vertex gets an
/// outgoing halfedge again (a boundary one on the boundary), inner rings stay attached.
/// Returns the number of faces flipped. Complexity O(H_all + V_all), with O(H_all) scratch,
/// or less on a model whose traits offer reverse_orientation(mesh): halfedge_mesh (one pass
/// over its halfedge array, as the two halfedges of an edge lie side by side, no scratch),
/// CGAL::Surface_mesh and OpenMesh (one pass over their edges, O(H_all) scratch; the generic
/// pass cost Surface_mesh 1.6x its own loop, translating its incoming vertex halfedges to
/// outgoing and back).
template <class M, class T = default_traits<M>>
    requires halfedge_flip_mesh<M, T> && (!face_reversible_mesh<M, T>)
std::size_t flip_normals(M& mesh) {
    if constexpr (orientation_reversible_mesh<M, T>) {
        T::reverse_orientation(mesh);
        return T::face_count(mesh);
    }
    using H = typename T::halfedge_handle;
    const std::size_t nh = T::halfedge_index_bound(mesh);
    std::vector<H> old_prev(nh);
    std::vector<typename T::vertex_handle> source(nh);
    std::vector<H> all;
    all.reserve(nh);
    for (H h : T::halfedges(mesh)) {
        const auto i = T::halfedge_index(mesh, h);
        old_prev[i] = T::prev(mesh, h);
        source[i] = T::target(mesh, T::opposite(mesh, h));
        all.push_back(h);
    }
    // New outgoing halfedge per vertex, from the old connectivity.
    std::vector<std::pair<typename T::vertex_handle, H>> out;
    out.reserve(T::vertex_count(mesh));
    for (auto v : T::vertices(mesh)) {
        const H h = T::vertex_halfedge(mesh, v);
        if (h == T::null_halfedge()) continue;
        // A boundary vertex's outgoing halfedge must stay a boundary one: the boundary
        // halfedge that entered v now leaves it.
        const bool boundary = T::face(mesh, h) == T::null_face();
        out.emplace_back(v, boundary ? old_prev[T::halfedge_index(mesh, h)] : T::opposite(mesh, h));
    }
    for (H h : all) {
        const auto i = T::halfedge_index(mesh, h);
        T::set_target(mesh, h, source[i]);
        T::set_next(mesh, h, old_prev[i]);
    }
    for (const auto& [v, h] : out) T::set_vertex_halfedge(mesh, v, h);
    return T::face_count(mesh);
}

}  // namespace hmira
