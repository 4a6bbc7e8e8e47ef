// hmira/algorithms/triangle/split_edge.hpp
// Edge split: a new vertex on an edge. Triangles on either side are split in two, so a
// triangle mesh stays one; on a polygon face or a boundary the vertex just joins the loop.
#pragma once

#include <optional>

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

namespace detail::triangle_ops {

/// Makes new edges and faces through the traits (what split_links uses unless told otherwise).
template <class M, class T>
struct traits_new_elements {
    M& mesh;
    typename T::halfedge_handle edge(typename T::vertex_handle a, typename T::vertex_handle b) { return T::new_edge(mesh, a, b); }
    typename T::face_handle face() { return T::new_face(mesh); }
};

/// The link changes of split_edge, without its checks, at an isolated vertex w the caller
/// made: for callers that established the preconditions for a whole batch of edges up front
/// (Loop subdivision). `cut_h` / `cut_o`: split the triangle on that side. New edges and
/// faces come from `make.edge(a, b)` (as T::new_edge) and `make.face()` (as T::new_face),
/// which lets a batch take them from elements it made in bulk. Returns the new halfedge
/// w -> b. O(1).
template <class M, class T, class Make>
typename T::halfedge_handle split_links(M& mesh, typename T::halfedge_handle h, typename T::vertex_handle w, bool cut_h, bool cut_o,
                                        Make& make) {
    const auto o = T::opposite(mesh, h);
    const auto a = T::target(mesh, o), b = T::target(mesh, h);
    const auto f0 = T::face(mesh, h), f1 = T::face(mesh, o);
    const auto hn = T::next(mesh, h), op = T::prev(mesh, o);
    const auto a_out = T::vertex_halfedge(mesh, a);
    const auto b_out = T::vertex_halfedge(mesh, b);

    const auto h2 = make.edge(w, b);  // w -> b
    const auto o2 = T::opposite(mesh, h2);    // b -> w
    // h: a -> w, o: w -> a; the new edge takes h's place in front of hn and o's behind op.
    T::set_target(mesh, h, w);
    T::set_next(mesh, h, h2);
    T::set_next(mesh, h2, hn);
    T::set_face(mesh, h2, f0);
    T::set_next(mesh, op, o2);
    T::set_next(mesh, o2, o);
    T::set_face(mesh, o2, f1);

    if (cut_h) {  // (a, w, b, c) -> (a, w, c) + (w, b, c)
        const auto c = T::target(mesh, hn);
        const auto hp = T::prev(mesh, h);
        const auto wc = make.edge(w, c);
        const auto cw = T::opposite(mesh, wc);
        const auto g = make.face();
        T::set_next(mesh, h, wc);
        T::set_next(mesh, wc, hp);
        T::set_face(mesh, wc, f0);
        T::set_next(mesh, hn, cw);
        T::set_next(mesh, cw, h2);
        T::set_face(mesh, cw, g);
        T::set_face(mesh, h2, g);
        T::set_face(mesh, hn, g);
        T::set_face_halfedge(mesh, f0, h);
        T::set_face_halfedge(mesh, g, h2);
    }
    if (cut_o) {  // (w, a, d, b) -> (w, a, d) + (b, w, d)
        const auto on = T::next(mesh, o);
        const auto d = T::target(mesh, on);
        const auto dw = make.edge(d, w);
        const auto wd = T::opposite(mesh, dw);
        const auto g = make.face();
        T::set_next(mesh, on, dw);
        T::set_next(mesh, dw, o);
        T::set_face(mesh, dw, f1);
        T::set_next(mesh, o2, wd);
        T::set_next(mesh, wd, op);
        T::set_face(mesh, wd, g);
        T::set_face(mesh, o2, g);
        T::set_face(mesh, op, g);
        T::set_face_halfedge(mesh, f1, o);
        T::set_face_halfedge(mesh, g, o2);
    }
    // w sits on the boundary exactly when the edge did; b's stored o (b -> a) now leaves w.
    T::set_vertex_halfedge(mesh, w, f0 == T::null_face() ? h2 : o);
    T::set_vertex_halfedge(mesh, b, b_out == o ? o2 : b_out);
    T::set_vertex_halfedge(mesh, a, a_out);
    return h2;
}

/// split_links with new edges and faces from the traits.
template <class M, class T>
typename T::halfedge_handle split_links(M& mesh, typename T::halfedge_handle h, typename T::vertex_handle w, bool cut_h, bool cut_o) {
    traits_new_elements<M, T> make{mesh};
    return split_links<M, T>(mesh, h, w, cut_h, cut_o, make);
}

}  // namespace detail::triangle_ops

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
    const vec3<double> p = options.position ? *options.position
                                            : (dt::position_of<M, T>(mesh, a) + dt::position_of<M, T>(mesh, b)) * 0.5;
    if (!dt::finite(p))
        return fail(errc::invalid_argument, "split_edge: option position is not finite", de::index_of<M, T>(mesh, h));
    const bool cut_h = options.split_triangles && dt::in_triangle<M, T>(mesh, h);
    const bool cut_o = options.split_triangles && dt::in_triangle<M, T>(mesh, o) && T::face(mesh, o) != T::face(mesh, h);
    if constexpr (triangle_only_mesh<M, T>) {
        const bool h_polygon = T::face(mesh, h) != T::null_face() && !cut_h;
        const bool o_polygon = T::face(mesh, o) != T::null_face() && !cut_o;
        if (h_polygon || o_polygon)
            return fail(errc::unsupported,
                        "split_edge: the edge of " + de::name<M, T>("halfedge", mesh, h) +
                            " would leave a quadrilateral, which a triangles-only mesh cannot hold",
                        de::index_of<M, T>(mesh, h));
    }

    const auto w = T::add_vertex(mesh, vec3<typename T::scalar>{typename T::scalar(p.x), typename T::scalar(p.y),
                                                                typename T::scalar(p.z)});
    return split_edge_result<M, T>{w, dt::split_links<M, T>(mesh, h, w, cut_h, cut_o)};
}

}  // namespace hmira
