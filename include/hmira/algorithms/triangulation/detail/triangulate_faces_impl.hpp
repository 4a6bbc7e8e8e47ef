// hmira/algorithms/triangulation/detail/triangulate_faces_impl.hpp
// The machinery of face_triangles and triangulate_faces (see ../triangulate_faces.hpp for the
// interface): projecting a face to its plane, the fast path for convex quads, planning every
// face before the mesh is touched, and cutting each face along its diagonals.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "../../../concepts.hpp"
#include "../../../core/result.hpp"
#include "../../euler/euler_common.hpp"
#include "../../euler/make_edge_face.hpp"
#include "../../euler/make_edge_kill_ring.hpp"
#include "../../geometry/face_normal.hpp"
#include "../triangulate_faces.hpp"
#include "../triangulate_polygon.hpp"

namespace hmira {

namespace detail::triangulation {

/// Why a loop has no plane to be projected onto.
enum class projection_status { ok, not_finite, no_area };

/// The coordinates (u, v) of the plane a loop is projected onto: the coordinate plane its
/// Newell normal is closest to, ordered so that the loop is counter-clockwise there.
inline projection_status projection_axes(std::span<const vec3<double>> loop, int& u, int& v) {
    vec3<double> n{};
    for (std::size_t i = 0; i < loop.size(); ++i) n += newell_term(loop[i], loop[(i + 1) % loop.size()]);
    if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z)) return projection_status::not_finite;
    const double ax = std::fabs(n.x), ay = std::fabs(n.y), az = std::fabs(n.z);
    if (ax == 0 && ay == 0 && az == 0) return projection_status::no_area;
    const int k = ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2);
    u = (k + 1) % 3;
    v = (k + 2) % 3;
    if (n[std::size_t(k)] < 0) std::swap(u, v);
    return projection_status::ok;
}

/// One face's corners as plane points, projected along the dominant axis of the outer loop's
/// Newell normal (so the outer loop is counter-clockwise), and its loops as point indices.
template <class M, class T>
struct face_polygon {
    std::vector<typename T::vertex_handle> vertices;
    std::vector<point2> points;
    std::vector<std::vector<std::size_t>> loops;
};

template <class M, class T>
result<face_polygon<M, T>> project_face(const M& m, typename T::face_handle f) {
    face_polygon<M, T> out;
    std::vector<vec3<double>> p;
    auto add_loop = [&](auto&& range) {
        out.loops.emplace_back();
        for (auto v : range) {
            out.loops.back().push_back(out.vertices.size());
            out.vertices.push_back(v);
            const vec3<typename T::scalar> q = T::position(m, v);
            p.push_back({double(q.x), double(q.y), double(q.z)});
        }
    };
    add_loop(T::face_vertices(m, f));
    if constexpr (inner_ring_mesh<M, T>) {
        for (auto r : T::inner_rings(m, f)) {
            std::vector<typename T::vertex_handle> ring;
            auto h = typename T::halfedge_handle(r);
            do {
                ring.push_back(T::target(m, h));
                h = T::next(m, h);
            } while (h != typename T::halfedge_handle(r));
            add_loop(ring);
        }
    }
    auto name = [&] { return "face " + std::to_string(T::face_index(m, f)); };
    int u = 0, v = 0;
    // The outer loop's points come first in p.
    switch (projection_axes(std::span<const vec3<double>>(p.data(), out.loops[0].size()), u, v)) {
        case projection_status::not_finite:
            return fail(errc::invalid_argument, name() + " has a corner that is not finite",
                        (long long)T::face_index(m, f));
        case projection_status::no_area:
            return fail(errc::degenerate_face, name() + " has no area to project (its corners are collinear)",
                        (long long)T::face_index(m, f));
        case projection_status::ok: break;
    }
    out.points.reserve(p.size());
    for (const auto& q : p) out.points.push_back({q[std::size_t(u)], q[std::size_t(v)]});
    return out;
}

/// A ringless face of four corners, decided without building its polygon: its corners in
/// face_vertices order and the first corner of the diagonal to cut, to corner from + 2. Only
/// strictly convex quads (all four turns left in the projection project_face uses, exact) take
/// this path: they are cut along 1-3, or with the Delaunay option along 0-2 when corner 2 lies
/// inside the circle through 3, 0, 1. Anything else (more corners, concave,
/// degenerate, not finite) gives from = -1: the general path.
template <class M, class T>
struct quad_cut {
    std::array<typename T::vertex_handle, 4>
        corner;  // default-initialised: OpenMesh handles have an explicit default constructor
    int from = -1;
};

template <class M, class T>
quad_cut<M, T> convex_quad_cut(const M& m, typename T::face_handle f, bool delaunay) {
    quad_cut<M, T> out;
    std::size_t n = 0;
    for (auto v : T::face_vertices(m, f)) {
        if (n == 4) return out;
        out.corner[n++] = v;
    }
    if (n != 4) return out;
    std::array<vec3<double>, 4> p;
    for (std::size_t k = 0; k < 4; ++k) {
        const vec3<typename T::scalar> q = T::position(m, out.corner[k]);
        p[k] = {double(q.x), double(q.y), double(q.z)};
    }
    int u = 0, v = 0;  // the projection project_face uses
    if (projection_axes(p, u, v) != projection_status::ok) return out;
    std::array<point2, 4> q;
    for (std::size_t i = 0; i < 4; ++i) {
        q[i] = {p[i][std::size_t(u)], p[i][std::size_t(v)]};
        if (!predicates::in_predicate_range(q[i][0]) || !predicates::in_predicate_range(q[i][1])) return out;
    }
    for (std::size_t i = 0; i < 4; ++i)
        if (orient(q[(i + 3) % 4], q[i], q[(i + 1) % 4]) <= 0) return out;
    out.from =
        delaunay && predicates::incircle(q[3][0], q[3][1], q[0][0], q[0][1], q[1][0], q[1][1], q[2][0], q[2][1]) > 0
            ? 0
            : 1;
    return out;
}

/// A face triangulated on paper: its polygon and the triangles over its points.
template <class M, class T>
struct face_plan {
    typename T::face_handle face;
    face_polygon<M, T> polygon;
    std::vector<std::array<std::size_t, 3>> triangles;
};

/// A convex quad, the common case, planned compactly: the corners of its diagonal.
template <class M, class T>
struct quad_plan {
    typename T::face_handle face;
    typename T::vertex_handle a, b;
};

/// Every face of the mesh that needs cutting, triangulated on paper (the mesh is only read):
/// convex quads into `quads`, the others into `plans`. Errors: those of face_triangles.
template <class M, class T>
result<void> plan_faces(const M& mesh, const triangulate_polygon_options& options, std::vector<face_plan<M, T>>& plans,
                        std::vector<quad_plan<M, T>>& quads) {
    for (auto f : T::faces(mesh)) {
        if (!detail::euler::has_rings<M, T>(mesh, f)) {
            const auto h = T::face_halfedge(mesh, f);
            if (T::next(mesh, T::next(mesh, T::next(mesh, h))) == h) continue;
            if (auto q = convex_quad_cut<M, T>(mesh, f, options.delaunay); q.from >= 0) {
                quads.push_back({f, q.corner[std::size_t(q.from)], q.corner[std::size_t(q.from) + 2]});
                continue;
            }
        }
        auto poly = project_face<M, T>(mesh, f);
        if (!poly) return poly.error();
        auto tris = triangulate_polygon(poly->points, poly->loops, options);
        if (!tris) {
            auto e = tris.error();
            return fail(e.code, "triangulate_faces: face " + std::to_string(T::face_index(mesh, f)) + ": " + e.message,
                        (long long)T::face_index(mesh, f));
        }
        plans.push_back({f, std::move(*poly), std::move(*tris)});
    }
    return {};
}

/// Cuts a planned convex quad along its diagonal.
template <class M, class T>
result<void> cut_quad(M& mesh, const quad_plan<M, T>& q) {
    using H = typename T::halfedge_handle;
    // The face's halfedges into the diagonal's two corners.
    H into_a = T::null_halfedge(), into_b = T::null_halfedge();
    const H start = T::face_halfedge(mesh, q.face);
    H x = start;
    do {
        if (T::target(mesh, x) == q.a) into_a = x;
        if (T::target(mesh, x) == q.b) into_b = x;
        x = T::next(mesh, x);
    } while (x != start);
    auto r = make_edge_face<M, T>(mesh, into_a, into_b);
    if (!r)
        return fail(r.error().code,
                    "triangulate_faces: internal: " + r.error().message);  // unreachable on a valid mesh
    return {};
}

/// The diagonals of a planned face: the triangles' sides that are not sides of the face's
/// loops, each once, sorted.
inline std::vector<std::array<std::size_t, 2>> plan_diagonals(
    const std::vector<std::vector<std::size_t>>& loops, const std::vector<std::array<std::size_t, 3>>& triangles) {
    std::vector<std::array<std::size_t, 2>> sides;
    for (const auto& loop : loops)
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const auto a = loop[i], b = loop[(i + 1) % loop.size()];
            sides.push_back({std::min(a, b), std::max(a, b)});
        }
    std::sort(sides.begin(), sides.end());
    std::vector<std::array<std::size_t, 2>> diagonals;
    for (const auto& t : triangles)
        for (int s = 0; s < 3; ++s) {
            const std::array<std::size_t, 2> d{std::min(t[s], t[(s + 1) % 3]), std::max(t[s], t[(s + 1) % 3])};
            if (!std::binary_search(sides.begin(), sides.end(), d)) diagonals.push_back(d);
        }
    std::sort(diagonals.begin(), diagonals.end());
    diagonals.erase(std::unique(diagonals.begin(), diagonals.end()), diagonals.end());
    return diagonals;
}

/// Cuts one planned face along its diagonals. Keeps the point index of each vertex of the face
/// (a vertex appears once per face) and the pieces cut so far: scans on small faces, hash
/// lookups on big ones.
template <class M, class T>
class face_cutter {
    using V = typename T::vertex_handle;
    using H = typename T::halfedge_handle;
    using F = typename T::face_handle;

public:
    face_cutter(M& mesh, const face_plan<M, T>& plan)
        : mesh_(mesh),
          plan_(plan),
          pts_(plan.polygon.points),
          vs_(plan.polygon.vertices),
          big_(vs_.size() > 32),
          pieces_{plan.face} {
        if constexpr (vertex_index_mesh<M, T>)
            if (big_)
                for (std::size_t i = 0; i < vs_.size(); ++i)
                    point_by_vertex_.emplace(T::vertex_index(mesh_, vs_[i]), i);
        if (big_) piece_ids_.insert(T::face_index(mesh_, plan.face));
    }

    /// Adds every diagonal: a cut (makeEF) where both ends lie on one loop of the piece, else a
    /// bridge to a ring (makeEkillR). Counts the triangles added into `out`.
    result<void> run(triangulate_faces_result& out) {
        const std::size_t rings = plan_.polygon.loops.size() - 1;
        for (const auto& d : plan_diagonals(plan_.polygon.loops, plan_.triangles)) {
            const H ca = corner(d[0], d[1]), cb = corner(d[1], d[0]);
            if (const int side = shorter_side(ca, cb); side != 0) {
                // With inner rings the cut keeps its first corner's side as the old face (which
                // keeps the rings), as the bridges expect; without, the shorter part goes first.
                const bool swap = side < 0 && rings == 0;
                auto r = swap ? make_edge_face<M, T>(mesh_, cb, ca) : make_edge_face<M, T>(mesh_, ca, cb);
                if (!r)
                    return fail(r.error().code,
                                "triangulate_faces: internal: " + r.error().message);  // unreachable on a valid mesh
                add_piece(r->face);
                ++out.triangles_added;
            } else {
                if constexpr (euler_ring_mutable_mesh<M, T>) {
                    auto r = make_edge_kill_ring<M, T>(mesh_, ca, cb);
                    if (!r) return fail(r.error().code, "triangulate_faces: internal: " + r.error().message);
                }
            }
        }
        return {};
    }

private:
    std::size_t point_of(V v) const {
        if constexpr (vertex_index_mesh<M, T>) {
            if (big_) {
                const auto it = point_by_vertex_.find(T::vertex_index(mesh_, v));
                return it == point_by_vertex_.end() ? vs_.size() : it->second;
            }
        }
        for (std::size_t i = 0; i < vs_.size(); ++i)
            if (vs_[i] == v) return i;
        return vs_.size();
    }
    bool is_piece(F g) const {
        return big_ ? piece_ids_.count(T::face_index(mesh_, g)) > 0
                    : std::find(pieces_.begin(), pieces_.end(), g) != pieces_.end();
    }
    void add_piece(F g) {
        if (big_)
            piece_ids_.insert(T::face_index(mesh_, g));
        else
            pieces_.push_back(g);
    }

    /// The corner (halfedge into v) of a piece whose angle at v holds the direction to w.
    H corner(std::size_t v, std::size_t w) const {
        const auto start = T::vertex_halfedge(mesh_, vs_[v]);
        H fallback = T::null_halfedge();
        auto x = start;
        do {
            const H in = T::opposite(mesh_, x);
            if (T::face(mesh_, in) != T::null_face() && is_piece(T::face(mesh_, in))) {
                const auto a = point_of(T::target(mesh_, T::opposite(mesh_, in)));
                const auto b = point_of(T::target(mesh_, T::next(mesh_, in)));
                if (a < vs_.size() && b < vs_.size() && in_cone(pts_[a], pts_[v], pts_[b], pts_[w])) return in;
                if (fallback == T::null_halfedge()) fallback = in;
            }
            x = T::next(mesh_, in);
        } while (x != start);
        return fallback;
    }

    /// Whether b follows a on its loop, walking from both ends at once so that the cost is
    /// that of the shorter part: +1 when next(a) .. b is shorter, -1 when next(b) .. a is,
    /// 0 when they lie on different loops. make_edge_face re-points the part after its first
    /// corner, so passing the shorter part first makes every cut cost O(min part), and the
    /// whole face O(n log n) rather than O(n^2).
    int shorter_side(H a, H b) const {
        auto x = T::next(mesh_, a), y = T::next(mesh_, b);
        bool x_done = false, y_done = false;
        while (!x_done || !y_done) {
            if (!x_done) {
                if (x == b) return 1;
                x_done = x == a;
                x = T::next(mesh_, x);
            }
            if (!y_done) {
                if (y == a) return -1;
                y_done = y == b;
                y = T::next(mesh_, y);
            }
        }
        return 0;
    }

    M& mesh_;
    const face_plan<M, T>& plan_;
    const std::vector<point2>& pts_;
    const std::vector<V>& vs_;
    bool big_;
    std::unordered_map<std::size_t, std::size_t> point_by_vertex_;
    std::vector<F> pieces_;
    std::unordered_set<std::size_t> piece_ids_;
};

}  // namespace detail::triangulation

template <class M, class T>
    requires face_triangulable_mesh<M, T>
result<std::vector<std::array<typename T::vertex_handle, 3>>> face_triangles(
    const M& mesh, typename T::face_handle f, const triangulate_polygon_options& options) {
    namespace dt = detail::triangulation;
    using out_t = std::vector<std::array<typename T::vertex_handle, 3>>;
    if (!detail::euler::has_rings<M, T>(mesh, f)) {
        if (const auto q = dt::convex_quad_cut<M, T>(mesh, f, options.delaunay); q.from >= 0) {
            const auto c = [&](int k) { return q.corner[std::size_t((q.from + k) % 4)]; };
            return out_t{{c(2), c(3), c(0)}, {c(0), c(1), c(2)}};  // the diagonal c(0)-c(2)
        }
    }
    auto poly = dt::project_face<M, T>(mesh, f);
    if (!poly) return poly.error();
    if (poly->loops.size() == 1 && poly->loops[0].size() == 3)
        return out_t{{poly->vertices[0], poly->vertices[1], poly->vertices[2]}};
    auto tris = triangulate_polygon(poly->points, poly->loops, options);
    if (!tris) {
        auto e = tris.error();
        return fail(e.code, "face " + std::to_string(T::face_index(mesh, f)) + ": " + e.message,
                    (long long)T::face_index(mesh, f));
    }
    out_t out;
    out.reserve(tris->size());
    for (const auto& t : *tris) out.push_back({poly->vertices[t[0]], poly->vertices[t[1]], poly->vertices[t[2]]});
    return out;
}

template <class M, class T>
    requires triangulable_mesh<M, T>
result<triangulate_faces_result> triangulate_faces(M& mesh, const triangulate_polygon_options& options) {
    namespace dt = detail::triangulation;
    std::vector<dt::face_plan<M, T>> plans;
    std::vector<dt::quad_plan<M, T>> quads;
    if (auto planned = dt::plan_faces<M, T>(mesh, options, plans, quads); !planned) return planned.error();
    triangulate_faces_result out;
    std::size_t added = quads.size();
    for (const auto& pl : plans) added += pl.triangles.size() - 1;
    if constexpr (reservable_mesh<M, T> && edge_index_mesh<M, T>)
        T::reserve(mesh, T::vertex_index_bound(mesh), T::edge_index_bound(mesh) + added,
                   T::face_index_bound(mesh) + added);
    for (const auto& q : quads) {
        if (auto cut = dt::cut_quad<M, T>(mesh, q); !cut) return cut.error();
        ++out.triangles_added;
        ++out.faces_cut;
    }
    for (const auto& pl : plans) {
        if (auto cut = dt::face_cutter<M, T>(mesh, pl).run(out); !cut) return cut.error();
        ++out.faces_cut;
    }
    return out;
}

}  // namespace hmira
