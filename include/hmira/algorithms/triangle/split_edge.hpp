// hmira/algorithms/triangle/split_edge.hpp
// Edge split: a new vertex on an edge. Triangles on either side are split in two, so a
// triangle mesh stays one; on a polygon face or a boundary the vertex just joins the loop.
#pragma once

#include <optional>

#include "detail/split_links.hpp"
#include "triangle_common.hpp"

namespace hmira {

/// Where split_edge puts the new vertex.
struct split_edge_options {
    /// The new vertex's position; by default the edge's midpoint.
    std::optional<vec3<double>> position = std::nullopt;
    /// Split the triangles on either side of the edge (the default). When false, the vertex
    /// joins both loops and the neighbouring triangles become quadrilaterals (refused on a
    /// triangles-only model).
    bool split_triangles = true;
};

/// What split_edge created.
template <class M, class T = default_traits<M>>
struct split_edge_result {
    typename T::vertex_handle vertex;      ///< the new vertex
    typename T::halfedge_handle halfedge;  ///< new vertex -> target of the split halfedge; h now ends at `vertex`
};

/// Splits the edge of h = a->b at a new vertex w: h becomes a->w and a new edge runs w->b.
/// Each side whose face is a triangle without rings is cut by a new edge from w to its third
/// vertex; a polygon face or a boundary loop just gains w.
///
/// Inverse: collapse_edge(mesh, result.halfedge, {.placement = collapse_placement::target})
/// (the new vertex goes, b stays where it is).
/// \post V + 1; E + 1 + (triangles split); F + (triangles split).
/// Errors (mesh unchanged): errc::invalid_handle; errc::invalid_argument for a non-finite
/// position; errc::unsupported for `split_triangles = false` on a triangles-only model next
/// to a triangle.
/// Complexity O(1), plus O(rings of the two faces) where the model has inner rings.
template <class M, class T = default_traits<M>>
    requires triangle_operable_mesh<M, T>
[[nodiscard]] result<split_edge_result<M, T>> split_edge(M& mesh, typename T::halfedge_handle h,
                                                         const split_edge_options& options = {}) {
    namespace de = detail::euler;
    namespace dt = detail::triangle_ops;
    if (!de::usable<M, T>(mesh, h))
        return fail(errc::invalid_handle, "split_edge: " + de::name<M, T>("halfedge", mesh, h) + " does not exist",
                    de::index_of<M, T>(mesh, h));
    const auto o = T::opposite(mesh, h);
    const auto a = T::target(mesh, o), b = T::target(mesh, h);
    const vec3<double> p =
        options.position ? *options.position : (dt::position_of<M, T>(mesh, a) + dt::position_of<M, T>(mesh, b)) * 0.5;
    if (!dt::finite(p))
        return fail(errc::invalid_argument, "split_edge: option position is not finite", de::index_of<M, T>(mesh, h));
    const bool cut_h = options.split_triangles && dt::in_triangle<M, T>(mesh, h);
    const bool cut_o =
        options.split_triangles && dt::in_triangle<M, T>(mesh, o) && T::face(mesh, o) != T::face(mesh, h);
    if constexpr (triangle_only_mesh<M, T>) {
        const bool h_polygon = T::face(mesh, h) != T::null_face() && !cut_h;
        const bool o_polygon = T::face(mesh, o) != T::null_face() && !cut_o;
        if (h_polygon || o_polygon)
            return fail(errc::unsupported,
                        "split_edge: the edge of " + de::name<M, T>("halfedge", mesh, h) +
                            " would leave a quadrilateral, which a triangles-only mesh cannot hold",
                        de::index_of<M, T>(mesh, h));
    }

    const auto w = T::add_vertex(
        mesh, vec3<typename T::scalar>{typename T::scalar(p.x), typename T::scalar(p.y), typename T::scalar(p.z)});
    return split_edge_result<M, T>{w, dt::split_links<M, T>(mesh, h, w, cut_h, cut_o)};
}

}  // namespace hmira
