// hmira/algorithms/primitives/add_remove_vertex.hpp
// Primitive add/remove of a vertex (thesis 4.2): add an unconnected vertex, or remove a
// vertex together with the faces and edges around it.
#pragma once

#include <vector>

#include "../../core/vec3.hpp"
#include "primitives_common.hpp"

namespace hmira {

/// Adds an isolated vertex at `position` and returns it. Any model that builds meshes can
/// (mesh_builder). Complexity O(1) (thesis: O(1)).
template <class M, class T = default_traits<M>>
    requires mesh_builder<M, T>
typename T::vertex_handle add_vertex(M& mesh, const vec3<typename T::scalar>& position) {
    return T::add_vertex(mesh, position);
}

/// Removes `vertex`, every face around it and every edge at it; then, as `options` ask, the
/// other edges of those faces that are left with no face, and the vertices left with no edge.
/// The faces' other vertices end up on the boundary. Returns what was removed. On a model
/// without edges (face_vertex_mesh) the traits' remove_vertex takes the vertex and its faces,
/// and `remove_isolated_vertices` removes the faces' other corners that no face uses any more.
///
/// \pre nothing: a vertex that does not exist is reported, not assumed away.
/// \post on success the vertex and its faces are gone, and nothing else changed but what the
/// report counts.
///
/// Complexity on a halfedge model O(sum of the degrees of the faces around the vertex), that
/// is O(V_adjacentV) for faces of bounded degree (thesis: O(V_adjacentV)). On a model that
/// removes vertices through its traits without vertex -> face links (face_vertex_mesh),
/// O(F_all x face degree): finding the vertex's faces scans them all, as does the model.
/// Errors: errc::invalid_handle for a vertex out of range (mesh unchanged).
template <class M, class T = default_traits<M>>
    requires vertex_erasable_mesh<M, T>
result<removal_report> remove_vertex(M& mesh, typename T::vertex_handle vertex, const remove_options& options = {}) {
    namespace de = detail::euler;
    namespace dp = detail::primitives;
    if (!de::usable<M, T>(mesh, vertex))
        return fail(errc::invalid_handle,
                    "remove_vertex: " + de::name<M, T>("vertex", mesh, vertex) + " does not exist",
                    de::index_of<M, T>(mesh, vertex));
    removal_report report;
    if constexpr (halfedge_mutable_mesh<M, T>) {
        const auto start = T::vertex_halfedge(mesh, vertex);
        if (start != T::null_halfedge()) {
            std::vector<typename T::face_handle> faces;
            std::vector<typename T::halfedge_handle> outgoing;
            auto h = start;
            do {
                outgoing.push_back(h);
                const auto f = T::face(mesh, h);
                if (f != T::null_face() && std::find(faces.begin(), faces.end(), f) == faces.end()) faces.push_back(f);
                h = T::next(mesh, T::opposite(mesh, h));
            } while (h != start);
            std::vector<typename T::halfedge_handle> touched;
            for (auto f : faces) dp::strip_face<M, T>(mesh, f, touched);
            report.faces = faces.size();
            // The edges at the vertex are wires now and must all go; the faces' other edges as asked.
            if (options.remove_wire_edges) outgoing.insert(outgoing.end(), touched.begin(), touched.end());
            dp::remove_wires<M, T>(mesh, outgoing, options, report, vertex);
        }
        T::erase_vertex(mesh, vertex);
    } else {
        // The faces that go, and their corners, before the model removes them.
        std::vector<typename T::vertex_handle> corners;
        if constexpr (vertex_face_adjacency_mesh<M, T>) {
            for (auto f : T::vertex_faces(mesh, vertex)) {
                ++report.faces;
                for (auto v : T::face_vertices(mesh, f)) corners.push_back(v);
            }
        } else {
            auto uses_vertex = [&](auto f) {
                for (auto v : T::face_vertices(mesh, f))
                    if (v == vertex) return true;
                return false;
            };
            for (auto f : T::faces(mesh))
                if (uses_vertex(f)) {
                    ++report.faces;
                    for (auto v : T::face_vertices(mesh, f)) corners.push_back(v);
                }
        }
        // The model checks the handle again (a deleted vertex, say) before changing anything.
        if (auto removed = T::remove_vertex(mesh, vertex); !removed) return removed.error();
        if (options.remove_isolated_vertices)
            if (auto r = dp::remove_unused_vertices<M, T>(mesh, std::move(corners), report, vertex); !r)
                return r.error();
    }
    ++report.vertices;
    return report;
}

}  // namespace hmira
