// hmira/algorithms/subdivision/detail/sqrt3_impl.hpp
// The machinery of sqrt3_subdivide (subdivision/sqrt3.hpp): the per-level workspace, one
// level, and the entry point's definition.
#pragma once

#include <array>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "../../../core/rollback.hpp"
#include "../../triangle/flip_edge.hpp"
#include "../../triangle/split_edge.hpp"
#include "../../triangle/split_face.hpp"
#include "cancel_point.hpp"
#include "range.hpp"
#include "reserve.hpp"

namespace hmira {

namespace detail::subdivision {

/// Kobbelt's relaxation weight for an interior vertex of valence n: (4 - 2 cos(2 pi / n)) / 9.
inline double sqrt3_alpha(std::size_t n) { return (4 - 2 * std::cos(2 * std::numbers::pi / double(n))) / 9; }

/// One level's working arrays. Every new position is computed before the first change, from
/// the old positions; old vertices are then moved, and the new ones are made where they go.
template <class M, class T>
struct sqrt3_workspace {
    using H = typename T::halfedge_handle;
    std::vector<vec3<double>> vertex_point;  // by old vertex index: the neighbour sum, then the new position
    std::vector<std::uint32_t> valence;
    std::vector<std::uint8_t> boundary_edges;  // saturates at 3
    struct triangle {
        H h0;                 // a halfedge of the triangle
        H boundary_side;      // on a trisecting level: the triangle's boundary side, else null
        vec3<double> first;   // the centroid, or the trisection point nearer boundary_side's source
        vec3<double> second;  // the trisection point nearer boundary_side's target
    };
    std::vector<triangle> triangles;
    std::vector<H> old_interior;  // a halfedge of each old edge with a face on both sides
};

/// Fills `w.triangles` with one entry per face; returns the index of the first face that is
/// not a triangle without rings, -1, or -2 when `go_on` (if given) cancels. Changes nothing in
/// the mesh. O(F).
template <class M, class T>
long long gather_sqrt3_triangles(const M& mesh, sqrt3_workspace<M, T>& w, cancel_point* go_on = nullptr) {
    w.triangles.clear();
    for (auto f : T::faces(mesh)) {
        const auto h0 = T::face_halfedge(mesh, f);
        if (!detail::triangle_ops::in_triangle<M, T>(mesh, h0)) return (long long)T::face_index(mesh, f);
        w.triangles.push_back({h0, T::null_halfedge(), {}, {}});
        if (go_on && !(*go_on)()) return -2;
    }
    return -1;
}

/// One level on the triangles gathered in `w`; the mesh has room for it. With
/// `trisect_boundary`, a triangle with a boundary side has that side trisected instead of a
/// centroid (each such triangle has one boundary side: the level before split it). Returns
/// false when `go_on` cancels, which it does only between elements (the caller then restores
/// its copy).
template <class M, class T>
bool sqrt3_level(M& mesh, sqrt3_workspace<M, T>& w, bool trisect_boundary, cancel_point& go_on) {
    namespace dt = detail::triangle_ops;
    using H = typename T::halfedge_handle;
    using S = typename T::scalar;
    const auto null_face = T::null_face();
    const std::size_t vertex_bound = T::vertex_index_bound(mesh);
    w.vertex_point.assign(vertex_bound, {});
    w.valence.assign(vertex_bound, 0);
    w.boundary_edges.assign(vertex_bound, 0);
    w.old_interior.clear();
    auto& sum = w.vertex_point;
    const auto source_of = [&](H h) { return T::target(mesh, T::opposite(mesh, h)); };

    // Neighbour sums, valences and boundary edges per old vertex; the edges to flip.
    for (auto e : T::edges(mesh)) {
        const H h = T::edge_halfedge(mesh, e), o = T::opposite(mesh, h);
        const std::size_t ia = T::vertex_index(mesh, source_of(h)), ib = T::vertex_index(mesh, T::target(mesh, h));
        sum[ia] += dt::position_of<M, T>(mesh, T::target(mesh, h));
        sum[ib] += dt::position_of<M, T>(mesh, source_of(h));
        ++w.valence[ia];
        ++w.valence[ib];
        if (T::face(mesh, h) != null_face && T::face(mesh, o) != null_face) {
            w.old_interior.push_back(h);
        } else {
            w.boundary_edges[ia] = std::uint8_t(std::min(3, w.boundary_edges[ia] + 1));
            w.boundary_edges[ib] = std::uint8_t(std::min(3, w.boundary_edges[ib] + 1));
        }
        if (!go_on()) return false;
    }
    // New points, from the old positions: the centroid of each triangle; on a trisecting
    // level, the two points of the ternary cubic B-spline on each boundary side a -> b, with
    // u before a and z after b along the boundary: (u + 16 a + 10 b) / 27, (10 a + 16 b + z) / 27.
    for (auto& t : w.triangles) {
        const H h1 = T::next(mesh, t.h0), h2 = T::next(mesh, h1);
        if (trisect_boundary) {
            for (const H h : {t.h0, h1, h2}) {
                if (T::face(mesh, T::opposite(mesh, h)) != null_face) continue;
                assert(t.boundary_side == T::null_halfedge());
                t.boundary_side = h;
            }
        }
        if (t.boundary_side == T::null_halfedge()) {
            t.first =
                (dt::position_of<M, T>(mesh, T::target(mesh, t.h0)) + dt::position_of<M, T>(mesh, T::target(mesh, h1)) +
                 dt::position_of<M, T>(mesh, T::target(mesh, h2))) /
                3.0;
        } else {
            const H o = T::opposite(mesh, t.boundary_side);
            const auto a = dt::position_of<M, T>(mesh, source_of(t.boundary_side));
            const auto b = dt::position_of<M, T>(mesh, T::target(mesh, t.boundary_side));
            const auto u = dt::position_of<M, T>(mesh, T::target(mesh, T::next(mesh, o)));
            const auto z = dt::position_of<M, T>(mesh, source_of(T::prev(mesh, o)));
            t.first = (u + a * 16.0 + b * 10.0) / 27.0;
            t.second = (a * 10.0 + b * 16.0 + z) / 27.0;
        }
        if (!go_on()) return false;
    }
    // Old vertices: Kobbelt's rule inside; on a trisecting level a boundary vertex between
    // two boundary edges takes (4 u + 19 p + 4 z) / 27 of itself and its boundary neighbours;
    // otherwise (other levels, where boundary fans meet, isolated) it stays.
    for (auto v : T::vertices(mesh)) {
        const std::size_t i = T::vertex_index(mesh, v);
        const auto p = dt::position_of<M, T>(mesh, v);
        const std::size_t n = w.valence[i];
        if (w.boundary_edges[i] == 0 && n > 0) {
            const double alpha = sqrt3_alpha(n);
            sum[i] = p * (1 - alpha) + sum[i] * (alpha / double(n));
        } else if (trisect_boundary && w.boundary_edges[i] == 2) {
            const H s = T::vertex_halfedge(mesh, v);
            const auto a = dt::position_of<M, T>(mesh, T::target(mesh, s));
            const auto b = dt::position_of<M, T>(mesh, source_of(T::prev(mesh, s)));
            sum[i] = (p * 19.0 + (a + b) * 4.0) / 27.0;
        } else {
            sum[i] = p;
        }
        if (!go_on()) return false;
    }
    for (auto v : T::vertices(mesh)) {
        dt::set_position<M, T>(mesh, v, sum[T::vertex_index(mesh, v)]);
        if (!go_on()) return false;
    }

    const auto add = [&](const vec3<double>& q) { return T::add_vertex(mesh, vec3<S>{S(q.x), S(q.y), S(q.z)}); };
    for (const auto& t : w.triangles) {
        if (t.boundary_side == T::null_halfedge()) {
            [[maybe_unused]] const H centre_out = dt::split_face_links<M, T>(mesh, t.h0, add(t.first));
        } else {
            // (a, b, c) -> (a, x, c) + (x, b, c) -> (a, x, c) + (x, y, c) + (y, b, c).
            const H x_to_b = dt::split_links<M, T>(mesh, t.boundary_side, add(t.first), true, false);
            [[maybe_unused]] const H y_to_b = dt::split_links<M, T>(mesh, x_to_b, add(t.second), true, false);
        }
        if (!go_on()) return false;
    }
    // Each old interior edge now lies between two new triangles whose far corners are new
    // vertices that no edge joins yet, so every flip is allowed and its checks are skipped.
    for (const H h : w.old_interior) {
        assert((is_flip_ok<M, T>(mesh, h)));
        dt::flip_links<M, T>(mesh, h);
        if (!go_on()) return false;
    }
    return true;
}

}  // namespace detail::subdivision

template <class M, class T>
    requires sqrt3_subdividable_mesh<M, T>
result<sqrt3_result> sqrt3_subdivide(M& mesh, const sqrt3_options& options) {
    if (options.levels > 20)
        return fail(errc::invalid_argument,
                    "sqrt3_subdivide: option levels must be at most 20, got " + std::to_string(options.levels));
    namespace ds = detail::subdivision;
    ds::sqrt3_workspace<M, T> work;
    if (const long long bad = ds::gather_sqrt3_triangles<M, T>(mesh, work); bad >= 0)
        return fail(errc::topology,
                    "sqrt3_subdivide: face " + std::to_string(bad) + " is not a triangle (triangulate_faces first)",
                    bad);
    std::uint64_t boundary = 0;
    for (auto e : T::edges(mesh)) {
        const auto h = T::edge_halfedge(mesh, e);
        boundary += (T::face(mesh, h) == T::null_face()) != (T::face(mesh, T::opposite(mesh, h)) == T::null_face());
    }
    std::uint64_t v = T::vertex_count(mesh), e = T::edge_count(mesh), f = T::face_count(mesh);
    const std::uint64_t v0 = v, e0 = e, f0 = f;
    std::uint64_t elements = 0;  // what the levels count for the progress gate
    for (std::size_t l = 0; l < options.levels; ++l) {
        const std::uint64_t trisected = l % 2 == 1 ? boundary : 0;
        elements += 2 * v + e + 3 * f + e;
        v += f + trisected, e += 3 * f + trisected, f *= 3, boundary += 2 * trisected;
        if (2 * e >= (std::uint64_t(1) << 31))
            return fail(errc::invalid_argument,
                        "sqrt3_subdivide: " + std::to_string(options.levels) +
                            " levels would make more than 2^31 halfedges, more than a mesh index holds");
    }
    if (options.levels == 0) return sqrt3_result{T::vertex_count(mesh), T::edge_count(mesh), T::face_count(mesh)};
    ds::reserve_room<M, T>(mesh, T::vertex_index_bound(mesh) + std::size_t(v - v0),
                           T::edge_index_bound(mesh) + std::size_t(e - e0),
                           T::face_index_bound(mesh) + std::size_t(f - f0));
    work.triangles.reserve(std::size_t(f / 3));
    detail::progress_gate gate(options.progress, std::size_t(elements / ds::check_every));
    ds::cancel_point go_on{gate};
    // Without a callback nothing can stop a level half way, so there is nothing to copy. With
    // one, a copy taken before the first change is what a cancellation restores.
    mesh_rollback<M> undo(mesh, bool(options.progress));
    ds::range_guard<M, T> range(mesh);
    for (std::size_t l = 0; l < options.levels; ++l) {
        // Level 0's triangles were gathered above; later ones are triangles only (-1) unless cancelled (-2).
        const bool cancelled = (l > 0 && ds::gather_sqrt3_triangles<M, T>(mesh, work, &go_on) == -2) ||
                               !ds::sqrt3_level<M, T>(mesh, work, l % 2 == 1, go_on);
        if (cancelled) {
            range.dismiss();
            undo.restore();
            return fail(errc::cancelled, "sqrt3_subdivide: cancelled");
        }
    }
    range.restore();
    undo.commit();
    return sqrt3_result{T::vertex_count(mesh), T::edge_count(mesh), T::face_count(mesh)};
}

}  // namespace hmira
