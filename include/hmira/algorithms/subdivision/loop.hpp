// hmira/algorithms/subdivision/loop.hpp
// Loop subdivision of a triangle mesh, built from the local operators: every edge split at
// its Loop edge point, then the new edges that join an old and a new vertex flipped (1-to-4),
// and the old vertices moved by Loop's vertex rule. Boundaries follow the cubic B-spline.
#pragma once

#include <algorithm>
#include <array>
#include <cassert>
#include <cstdint>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <string>
#include <vector>

#include "../triangle/flip_edge.hpp"
#include "../triangle/split_edge.hpp"
#include "detail/reserve.hpp"

namespace hmira {

/// Options of loop_subdivide.
struct loop_options {
    /// Levels of subdivision (each multiplies the faces by 4).
    std::size_t levels = 1;
};

/// What loop_subdivide did.
struct loop_result {
    std::size_t vertices = 0;  ///< vertices after the last level
    std::size_t edges = 0;     ///< edges after the last level
    std::size_t faces = 0;     ///< faces after the last level
};

/// Whether every face of the mesh is a triangle without rings. O(F).
template <class M, class T = default_traits<M>>
    requires triangle_operable_mesh<M, T>
bool is_triangle_mesh(const M& mesh) {
    for (auto f : T::faces(mesh))
        if (!detail::triangle_ops::in_triangle<M, T>(mesh, T::face_halfedge(mesh, f))) return false;
    return true;
}

namespace detail::subdivision {

/// Loop's vertex weight beta for valence n: (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n.
inline double loop_beta(std::size_t n) {
    const double c = 0.375 + 0.25 * std::cos(2 * std::numbers::pi / double(n));
    return (0.625 - c * c) / double(n);
}

/// The per-level arrays, sized once for the largest level so that no level allocates after
/// the mesh starts changing (29 bytes a vertex, 36 an edge).
template <class M, class T>
struct loop_workspace {
    std::vector<vec3<double>> vertex_point;  // first the sums of neighbours, then the new positions
    std::vector<std::uint32_t> valence;
    std::vector<std::uint8_t> boundary_edges;  // saturates at 3
    std::vector<vec3<double>> edge_point;
    std::vector<typename T::halfedge_handle> edges, cuts;

    void reserve(std::size_t vertex_bound, std::size_t edge_count) {
        vertex_point.reserve(vertex_bound);
        valence.reserve(vertex_bound);
        boundary_edges.reserve(vertex_bound);
        edge_point.reserve(edge_count);
        edges.reserve(edge_count);
        cuts.reserve(2 * edge_count);
    }
};

/// One Loop level on a mesh of triangles without rings (established by the caller), with
/// room reserved in `w` and in the mesh.
template <class M, class T>
void loop_level(M& mesh, loop_workspace<M, T>& w) {
    namespace dt = detail::triangle_ops;
    using H = typename T::halfedge_handle;
    const std::size_t vertex_bound = T::vertex_index_bound(mesh);
    w.vertex_point.assign(vertex_bound, {});
    w.valence.assign(vertex_bound, 0);
    w.boundary_edges.assign(vertex_bound, 0);
    w.edge_point.clear();
    w.edges.clear();
    w.cuts.clear();
    auto& sum = w.vertex_point;

    // Edge points (3/8 of each end and 1/8 of each opposite corner; the midpoint on a
    // boundary), computed before any split changes the corners; each vertex sums its
    // neighbours and counts its edges and boundary edges.
    for (auto e : T::edges(mesh)) {
        const H h = T::edge_halfedge(mesh, e), o = T::opposite(mesh, h);
        const auto va = T::target(mesh, o), vb = T::target(mesh, h);
        const std::size_t ia = T::vertex_index(mesh, va), ib = T::vertex_index(mesh, vb);
        const auto a = dt::position_of<M, T>(mesh, va), b = dt::position_of<M, T>(mesh, vb);
        sum[ia] += b;
        sum[ib] += a;
        ++w.valence[ia];
        ++w.valence[ib];
        w.edges.push_back(h);
        if (T::face(mesh, h) != T::null_face() && T::face(mesh, o) != T::null_face()) {
            const auto c = dt::position_of<M, T>(mesh, T::target(mesh, T::next(mesh, h)));
            const auto d = dt::position_of<M, T>(mesh, T::target(mesh, T::next(mesh, o)));
            w.edge_point.push_back((a + b) * 0.375 + (c + d) * 0.125);
        } else {
            w.edge_point.push_back((a + b) * 0.5);
            w.boundary_edges[ia] = std::uint8_t(std::min(3, w.boundary_edges[ia] + 1));
            w.boundary_edges[ib] = std::uint8_t(std::min(3, w.boundary_edges[ib] + 1));
        }
    }
    // Old vertices: Loop's rule inside; on the boundary (two boundary edges, the stored
    // halfedge a boundary one) 3/4 of itself and 1/8 of each boundary neighbour; a vertex
    // where boundary fans meet, or an isolated one, stays.
    std::array<double, 16> betas{};
    for (std::size_t n = 3; n < betas.size(); ++n) betas[n] = loop_beta(n);
    for (auto v : T::vertices(mesh)) {
        const std::size_t i = T::vertex_index(mesh, v);
        const auto p = dt::position_of<M, T>(mesh, v);
        const std::size_t n = w.valence[i];
        if (w.boundary_edges[i] == 0 && n > 0) {
            const double beta = n < betas.size() && n >= 3 ? betas[n] : loop_beta(n);
            sum[i] = p * (1 - double(n) * beta) + sum[i] * beta;
        } else if (w.boundary_edges[i] == 2) {
            const H s = T::vertex_halfedge(mesh, v);
            const auto a = dt::position_of<M, T>(mesh, T::target(mesh, s));
            const auto b = dt::position_of<M, T>(mesh, T::target(mesh, T::opposite(mesh, T::prev(mesh, s))));
            sum[i] = p * 0.75 + (a + b) * 0.125;
        } else {
            sum[i] = p;
        }
    }
    // The splits: each cuts the triangles beside its edge from the new vertex to their third
    // corner; those cuts are next(h) on h's side and next(opposite(new halfedge)) on the other.
    for (std::size_t i = 0; i < w.edges.size(); ++i) {
        const H h = w.edges[i];
        const bool h_side = T::face(mesh, h) != T::null_face();
        const bool o_side = T::face(mesh, T::opposite(mesh, h)) != T::null_face();
        auto r = split_edge<M, T>(mesh, h, {.position = w.edge_point[i]});
        assert(r);
        const H h2 = r.value().halfedge;  // cannot fail: the halfedge is live and the position finite
        if (h_side) w.cuts.push_back(T::next(mesh, h));
        if (o_side) w.cuts.push_back(T::next(mesh, T::opposite(mesh, h2)));
    }
    // A cut that joins the new vertex to an old corner is flipped (1-to-4). Both its sides are
    // triangles whose far corners are new and not yet joined, so is_flip_ok holds for each,
    // and the flip's own checks are skipped.
    for (const H x : w.cuts) {
        if (T::vertex_index(mesh, T::target(mesh, x)) < vertex_bound) {
            assert((is_flip_ok<M, T>(mesh, x)));
            dt::flip_links<M, T>(mesh, x);
        }
    }
    for (auto v : T::vertices(mesh)) {
        const auto i = T::vertex_index(mesh, v);
        if (i < vertex_bound) dt::set_position<M, T>(mesh, v, sum[i]);
    }
}

}  // namespace detail::subdivision

/// A mesh loop_subdivide can run on: the triangle operators, and dense vertex and face indices
/// for its per-level arrays.
template <class M, class T = default_traits<M>>
concept loop_subdividable_mesh = triangle_operable_mesh<M, T> && vertex_index_mesh<M, T> && face_index_mesh<M, T>;

/// Loop subdivision, `options.levels` times. Each level splits every edge at its edge point
/// (3/8 of each end plus 1/8 of each opposite corner; the midpoint on a boundary), flips the
/// new edges that join an old vertex to a new one (so each triangle becomes four), and moves
/// each old vertex by Loop's rule (1 - n beta of itself plus beta of each of its n
/// neighbours, beta = (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n; on a boundary 3/4 of itself
/// and 1/8 of each boundary neighbour; a vertex where two boundary fans meet stays).
///
/// \pre every face is a triangle without rings.
/// \post per level: V + E, E * 2 + 3 F, F * 4; genus and boundary loops unchanged.
/// Errors (mesh unchanged): errc::topology when a face is not a triangle (naming it);
/// errc::invalid_argument for more than 10 levels (a million-fold growth), or when the result
/// would need more than 2^31 halfedges. The mesh and working arrays are sized for the last
/// level before the first change, so std::bad_alloc comes before any change (user property
/// arrays, which grow element by element, excepted).
/// Complexity O(F) per level (each operator is O(1) or O(valence)), so O(4^levels F).
template <class M, class T = default_traits<M>>
    requires loop_subdividable_mesh<M, T>
[[nodiscard]] result<loop_result> loop_subdivide(M& mesh, const loop_options& options = {}) {
    if (options.levels > 10)
        return fail(errc::invalid_argument, "loop_subdivide: option levels must be at most 10, got " + std::to_string(options.levels));
    for (auto f : T::faces(mesh))
        if (!detail::triangle_ops::in_triangle<M, T>(mesh, T::face_halfedge(mesh, f)))
            return fail(errc::topology,
                        "loop_subdivide: face " + std::to_string(T::face_index(mesh, f)) + " is not a triangle (triangulate_faces first)",
                        (long long)T::face_index(mesh, f));
    // Every level's counts are known: the mesh and the working arrays are sized for the last
    // level now, so nothing allocates once the mesh has started to change.
    std::uint64_t v = T::vertex_count(mesh), e = T::edge_count(mesh), f = T::face_count(mesh);
    const std::uint64_t v0 = v, e0 = e, f0 = f;
    std::uint64_t largest_v = v, largest_e = e;
    for (std::size_t l = 0; l < options.levels; ++l) {
        largest_v = v, largest_e = e;
        v = v + e, e = 2 * e + 3 * f, f = 4 * f;
        if (2 * e >= (std::uint64_t(1) << 31))
            return fail(errc::invalid_argument, "loop_subdivide: " + std::to_string(options.levels) +
                                                    " levels would make more than 2^31 halfedges, more than a mesh index holds");
    }
    if (options.levels == 0) return loop_result{T::vertex_count(mesh), T::edge_count(mesh), T::face_count(mesh)};
    const std::size_t vertex_bound = T::vertex_index_bound(mesh) + std::size_t(v - v0);
    if constexpr (edge_index_mesh<M, T>)
        detail::subdivision::reserve_room<M, T>(mesh, vertex_bound, T::edge_index_bound(mesh) + std::size_t(e - e0), T::face_index_bound(mesh) + std::size_t(f - f0));
    detail::subdivision::loop_workspace<M, T> work;
    work.reserve(vertex_bound - std::size_t(v - largest_v), std::size_t(largest_e));
    for (std::size_t l = 0; l < options.levels; ++l) detail::subdivision::loop_level<M, T>(mesh, work);
    return loop_result{T::vertex_count(mesh), T::edge_count(mesh), T::face_count(mesh)};
}

}  // namespace hmira
