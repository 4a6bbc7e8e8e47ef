// hmira/algorithms/primitives/add_remove_face.hpp
// Primitive add/remove of a face (thesis 4.2): create a face from its vertices, linking it to
// the faces around it, or remove a face, leaving a hole in the surface.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "primitives_common.hpp"

namespace hmira {

/// Creates a face with the given corners (counter-clockwise seen from outside), reusing the
/// edges that exist and linking it to its neighbours, and returns it. This is the model's own
/// face construction (mesh_traits::add_face): for halfedge_mesh and winged_edge_mesh it costs
/// O(V_adjacentV) per corner (thesis: O(V_adjacentV)) and fails, with the mesh unchanged, on
/// fewer than 3 or repeated corners, missing vertices, an edge that would get a third face or
/// run against its neighbour's winding, or a vertex that would become non-manifold.
template <class M, class T = default_traits<M>>
    requires mesh_builder<M, T>
result<typename T::face_handle> add_face(M& mesh, std::span<const typename T::vertex_handle> corners) {
    return T::add_face(mesh, corners);
}

/// Removes `face`, leaving a hole (its sides become boundary); then, as `options` ask, the
/// edges left with no face on either side and the vertices left with no edge. Inner rings of
/// the face go with it. Returns what was removed. Removing a face between two others around a
/// vertex pinches the surface there (the vertex gets two boundary gaps), as in any halfedge
/// model. On a model without edges (face_vertex_mesh) the face goes through the traits'
/// remove_face and `remove_isolated_vertices` removes its corners that no other face uses.
///
/// \pre nothing: a face that does not exist is reported, not assumed away.
/// \post on success the face is gone and nothing else changed but what the report counts.
///
/// Complexity on a halfedge model O(face degree) (thesis: O(V_adjacentV)). On a model that
/// removes faces through its traits, the model's remove_face (O(1) on face_vertex_mesh), plus,
/// when vertices are cleaned up, the scan of remove_unused_vertices: O(F_all x face degree)
/// on face_vertex_mesh, which keeps no vertex -> face links (pass
/// `.remove_isolated_vertices = false` to avoid it).
/// Errors: errc::invalid_handle (mesh unchanged).
template <class M, class T = default_traits<M>>
    requires face_erasable_mesh<M, T>
result<removal_report> remove_face(M& mesh, typename T::face_handle face, const remove_options& options = {}) {
    namespace de = detail::euler;
    namespace dp = detail::primitives;
    removal_report report{1, 0, 0};
    if constexpr (halfedge_mutable_mesh<M, T>) {
        if (!de::usable<M, T>(mesh, face))
            return fail(errc::invalid_handle, "remove_face: " + de::name<M, T>("face", mesh, face) + " does not exist",
                        de::index_of<M, T>(mesh, face));
        std::vector<typename T::halfedge_handle> touched;
        dp::strip_face<M, T>(mesh, face, touched);
        if (options.remove_wire_edges) dp::remove_wires<M, T>(mesh, touched, options, report);
    } else {
        const auto index = T::face_index(mesh, face);
        if (index >= T::face_index_bound(mesh))
            return fail(errc::invalid_handle, "remove_face: face " + std::to_string(index) + " does not exist",
                        static_cast<long long>(index));
        std::vector<typename T::vertex_handle> corners;
        if (options.remove_isolated_vertices)
            for (auto v : T::face_vertices(mesh, face)) corners.push_back(v);
        // The model checks the handle again (a deleted face, say) before changing anything.
        if (auto removed = T::remove_face(mesh, face); !removed) return removed.error();
        if (options.remove_isolated_vertices)
            if (auto r = dp::remove_unused_vertices<M, T>(mesh, std::move(corners), report); !r) return r.error();
    }
    return report;
}

}  // namespace hmira
