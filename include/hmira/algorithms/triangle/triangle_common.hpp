// hmira/algorithms/triangle/triangle_common.hpp
// What the local triangle operators (flip, split, collapse) share: the capability concept they
// are written against and small helpers on the raw halfedge layer.
#pragma once

#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/result.hpp"
#include "../../core/vec3.hpp"
#include "../euler/euler_common.hpp"

namespace hmira {

/// A mesh the local triangle operators can edit: halfedge navigation, the raw halfedge
/// mutation layer and movable positions. Unlike euler_mutable_mesh it admits triangles-only
/// models (OpenMesh's TriMesh): no operator leaves a face of another degree behind where it
/// found triangles. halfedge_mesh, winged_edge_mesh, OpenMesh PolyMesh and TriMesh, and CGAL's
/// Surface_mesh qualify.
template <class M, class T = default_traits<M>>
concept triangle_operable_mesh = halfedge_mutable_mesh<M, T> && position_mutable_mesh<M, T>;

namespace detail::triangle_ops {

/// Number of halfedges in the loop of h, counting no further than `limit`. O(min(loop, limit)).
template <class M, class T>
std::size_t loop_length(const M& m, typename T::halfedge_handle h, std::size_t limit = 4) {
    std::size_t n = 0;
    auto x = h;
    do {
        ++n;
        x = T::next(m, x);
    } while (x != h && n < limit);
    return n;
}

/// Whether h lies in a real face that is a triangle without inner rings. O(1).
template <class M, class T>
bool in_triangle(const M& m, typename T::halfedge_handle h) {
    const auto f = T::face(m, h);
    return f != T::null_face() && T::next(m, T::next(m, T::next(m, h))) == h && !detail::euler::has_rings<M, T>(m, f);
}

/// The halfedge from a to b, or null. O(valence of a).
template <class M, class T>
typename T::halfedge_handle find_halfedge(const M& m, typename T::vertex_handle a, typename T::vertex_handle b) {
    const auto start = T::vertex_halfedge(m, a);
    if (start == T::null_halfedge()) return start;
    auto h = start;
    do {
        if (T::target(m, h) == b) return h;
        h = T::next(m, T::opposite(m, h));
    } while (h != start);
    return T::null_halfedge();
}

/// Stores an outgoing halfedge of v again after its links changed, preferring a boundary one:
/// the navigation concept promises a boundary halfedge at a boundary vertex, and models that
/// keep an incoming halfedge (CGAL) must re-derive it from the new links. O(valence of v).
template <class M, class T>
void refresh_vertex_halfedge(M& m, typename T::vertex_handle v, typename T::halfedge_handle any_outgoing) {
    auto h = any_outgoing;
    do {
        if (T::face(m, h) == T::null_face()) break;
        h = T::next(m, T::opposite(m, h));
    } while (h != any_outgoing);
    T::set_vertex_halfedge(m, v, h);
}

template <class S>
bool finite(const vec3<S>& p) {
    return std::isfinite(double(p.x)) && std::isfinite(double(p.y)) && std::isfinite(double(p.z));
}

template <class M, class T>
vec3<double> position_of(const M& m, typename T::vertex_handle v) {
    const vec3<typename T::scalar> p = T::position(m, v);
    return {double(p.x), double(p.y), double(p.z)};
}

template <class M, class T>
void set_position(M& m, typename T::vertex_handle v, const vec3<double>& p) {
    using S = typename T::scalar;
    T::set_position(m, v, vec3<S>{S(p.x), S(p.y), S(p.z)});
}

}  // namespace detail::triangle_ops
}  // namespace hmira
