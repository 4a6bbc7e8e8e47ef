// hmira/algorithms/triangle/split_face.hpp
// Face split (1-to-3): a new vertex inside a triangle joined to its three corners, as in
// incremental point insertion and sqrt(3) subdivision.
#pragma once

#include <optional>

#include "triangle_common.hpp"

namespace hmira {

namespace detail::triangle_ops {

/// split_face's link changes: joins the isolated vertex w to the three corners of the
/// triangle of h0 (checked by the caller) and returns w -> target(h0). The triangle keeps
/// h0; the two new faces take the other two sides. O(1).
template <class M, class T>
typename T::halfedge_handle split_face_links(M& mesh, typename T::halfedge_handle h0, typename T::vertex_handle w) {
    const auto f = T::face(mesh, h0);
    const auto h1 = T::next(mesh, h0), h2 = T::next(mesh, h1);
    const auto a = T::target(mesh, h2), b = T::target(mesh, h0), c = T::target(mesh, h1);
    const auto bw = T::new_edge(mesh, b, w), wb = T::opposite(mesh, bw);
    const auto cw = T::new_edge(mesh, c, w), wc = T::opposite(mesh, cw);
    const auto aw = T::new_edge(mesh, a, w), wa = T::opposite(mesh, aw);
    const auto f1 = T::new_face(mesh), f2 = T::new_face(mesh);
    auto link = [&](auto x, auto y, auto z, auto face) {
        T::set_next(mesh, x, y);
        T::set_next(mesh, y, z);
        T::set_next(mesh, z, x);
        T::set_face(mesh, x, face);
        T::set_face(mesh, y, face);
        T::set_face(mesh, z, face);
        T::set_face_halfedge(mesh, face, x);
    };
    link(h0, bw, wa, f);
    link(h1, cw, wb, f1);
    link(h2, aw, wc, f2);
    T::set_vertex_halfedge(mesh, w, wb);
    return wb;
}

}  // namespace detail::triangle_ops

/// Where split_face puts the new vertex.
struct split_face_options {
    /// The new vertex's position; by default the triangle's centroid.
    std::optional<vec3<double>> position = std::nullopt;
};

/// What split_face created.
template <class M, class T = default_traits<M>>
struct split_face_result {
    typename T::vertex_handle vertex;      ///< the new vertex, of degree 3
    typename T::halfedge_handle halfedge;  ///< new vertex -> the target of the face's stored halfedge
};

/// Splits triangle f into three around a new vertex w: corners (a, b, c) give (a, b, w),
/// (b, c, w) and (c, a, w); f keeps the first.
///
/// Inverse: collapse_edge(mesh, result.halfedge, {.placement = collapse_placement::target}).
/// \post V + 1, E + 3, F + 2.
/// Errors (mesh unchanged): errc::invalid_handle; errc::topology when f is not a triangle or
/// has inner rings; errc::invalid_argument for a non-finite position.
/// Complexity O(1).
template <class M, class T = default_traits<M>>
    requires triangle_operable_mesh<M, T>
[[nodiscard]] result<split_face_result<M, T>> split_face(M& mesh, typename T::face_handle f,
                                                         const split_face_options& options = {}) {
    namespace de = detail::euler;
    namespace dt = detail::triangle_ops;
    if (!de::usable<M, T>(mesh, f))
        return fail(errc::invalid_handle, "split_face: " + de::name<M, T>("face", mesh, f) + " does not exist",
                    de::index_of<M, T>(mesh, f));
    const auto h0 = T::face_halfedge(mesh, f);
    if (!dt::in_triangle<M, T>(mesh, h0))
        return fail(errc::topology,
                    "split_face: " + de::name<M, T>("face", mesh, f) + " is not a triangle without inner rings",
                    de::index_of<M, T>(mesh, f));
    const auto h1 = T::next(mesh, h0), h2 = T::next(mesh, h1);
    const auto a = T::target(mesh, h2), b = T::target(mesh, h0), c = T::target(mesh, h1);
    const vec3<double> p =
        options.position
            ? *options.position
            : (dt::position_of<M, T>(mesh, a) + dt::position_of<M, T>(mesh, b) + dt::position_of<M, T>(mesh, c)) / 3.0;
    if (!dt::finite(p))
        return fail(errc::invalid_argument, "split_face: option position is not finite", de::index_of<M, T>(mesh, f));

    using S = typename T::scalar;
    const auto w = T::add_vertex(mesh, vec3<S>{S(p.x), S(p.y), S(p.z)});
    return split_face_result<M, T>{w, dt::split_face_links<M, T>(mesh, h0, w)};
}

}  // namespace hmira
