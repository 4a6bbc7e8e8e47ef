// hmira/algorithms/triangulation/triangulate_faces.hpp
// Faces to triangles: face_triangles gives one face's triangles (inner rings included) as
// vertex triples, for writers such as STL; triangulate_faces cuts every face of a mesh.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "../../concepts.hpp"
#include "../geometry/face_normal.hpp"
#include "../../core/result.hpp"
#include "../euler/euler_common.hpp"
#include "../euler/make_edge_face.hpp"
#include "../euler/make_edge_kill_ring.hpp"
#include "triangulate_polygon.hpp"

namespace hmira {

/// A mesh whose faces face_triangles can read: the outer loop's vertices, positions, indices
/// (to name a refused face). Inner rings are read too where the model has them.
template <class M, class T = default_traits<M>>
concept face_triangulable_mesh = face_vertex_range_mesh<M, T> && positioned_mesh<M, T> && face_index_mesh<M, T>;

namespace detail::triangulation {

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
    vec3<double> n{};
    const auto& outer = out.loops[0];
    for (std::size_t i = 0; i < outer.size(); ++i) n += newell_term(p[outer[i]], p[outer[(i + 1) % outer.size()]]);
    if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z))
        return fail(errc::invalid_argument, name() + " has a corner that is not finite", (long long)T::face_index(m, f));
    const double ax = std::fabs(n.x), ay = std::fabs(n.y), az = std::fabs(n.z);
    if (ax == 0 && ay == 0 && az == 0)
        return fail(errc::degenerate_face, name() + " has no area to project (its corners are collinear)", (long long)T::face_index(m, f));
    const int k = ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2);
    int u = (k + 1) % 3, v = (k + 2) % 3;
    if (n[std::size_t(k)] < 0) std::swap(u, v);
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
    std::array<typename T::vertex_handle, 4> corner;  // default-initialised: OpenMesh handles have an explicit default constructor
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
    vec3<double> nn{};  // the Newell normal, as project_face computes it
    for (std::size_t i = 0; i < 4; ++i) nn += newell_term(p[i], p[(i + 1) % 4]);
    if (!std::isfinite(nn.x) || !std::isfinite(nn.y) || !std::isfinite(nn.z)) return out;
    const double ax = std::fabs(nn.x), ay = std::fabs(nn.y), az = std::fabs(nn.z);
    if (ax == 0 && ay == 0 && az == 0) return out;
    const int k = ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2);
    int u = (k + 1) % 3, v = (k + 2) % 3;
    if (nn[std::size_t(k)] < 0) std::swap(u, v);
    std::array<point2, 4> q;
    for (std::size_t i = 0; i < 4; ++i) {
        q[i] = {p[i][std::size_t(u)], p[i][std::size_t(v)]};
        if (!predicates::in_predicate_range(q[i][0]) || !predicates::in_predicate_range(q[i][1])) return out;
    }
    for (std::size_t i = 0; i < 4; ++i)
        if (orient(q[(i + 3) % 4], q[i], q[(i + 1) % 4]) <= 0) return out;
    out.from = delaunay && predicates::incircle(q[3][0], q[3][1], q[0][0], q[0][1], q[1][0], q[1][1], q[2][0], q[2][1]) > 0 ? 0 : 1;
    return out;
}

}  // namespace detail::triangulation

/// The triangles of face f as vertex triples, wound like the face: its outer loop and inner
/// rings projected onto the coordinate plane that the face's Newell normal is closest to, and
/// triangulated there with exact predicates (triangulate_polygon). A triangle without rings
/// comes back as itself.
///
/// Errors (naming the face): errc::degenerate_face for a loop of fewer than three corners or a
/// face without projected area; errc::topology when the projection is not a simple polygon
/// with holes (self-crossing, repeated corner, ring outside its face); errc::invalid_argument
/// for non-finite coordinates.
/// With options.delaunay the diagonals are flipped to the constrained Delaunay triangulation
/// in that plane (triangulate_polygon_options::delaunay).
/// Complexity: that of triangulate_polygon on the face's corners (O(n log n)).
template <class M, class T = default_traits<M>>
    requires face_triangulable_mesh<M, T>
[[nodiscard]] result<std::vector<std::array<typename T::vertex_handle, 3>>> face_triangles(const M& mesh, typename T::face_handle f,
                                                                                          const triangulate_polygon_options& options = {}) {
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
        return fail(e.code, "face " + std::to_string(T::face_index(mesh, f)) + ": " + e.message, (long long)T::face_index(mesh, f));
    }
    out_t out;
    out.reserve(tris->size());
    for (const auto& t : *tris) out.push_back({poly->vertices[t[0]], poly->vertices[t[1]], poly->vertices[t[2]]});
    return out;
}

/// A mesh triangulate_faces can cut: faces it can read (face_triangulable_mesh) and the Euler
/// operators to add the diagonals.
template <class M, class T = default_traits<M>>
concept triangulable_mesh = face_triangulable_mesh<M, T> && euler_mutable_mesh<M, T>;

/// What triangulate_faces did.
struct triangulate_faces_result {
    std::size_t faces_cut = 0;        ///< faces that were not triangles (or had rings)
    std::size_t triangles_added = 0;  ///< faces the mesh gained
};

/// Cuts every face that is not a triangle, or has inner rings, into triangles
/// (face_triangles), with the Euler operators: a bridge to a ring is makeEkillR, every other
/// diagonal makeEF. Every face is triangulated on paper first, so a refused face leaves the
/// mesh unchanged.
/// \post every face is a triangle without rings; V unchanged; the surface is the same point set.
/// With options.delaunay each face's diagonals are the constrained Delaunay ones in its plane.
/// Errors (mesh unchanged): those of face_triangles, naming the first refused face.
/// Complexity: O(sum over faces of n_f log n_f) typical, n_f the face's corners: each cut walks
/// the shorter part of its piece. Faces with inner rings: O(n_f) per cut and per bridge.
template <class M, class T = default_traits<M>>
    requires triangulable_mesh<M, T>
[[nodiscard]] result<triangulate_faces_result> triangulate_faces(M& mesh, const triangulate_polygon_options& options = {}) {
    namespace dt = detail::triangulation;
    using V = typename T::vertex_handle;
    using H = typename T::halfedge_handle;
    using F = typename T::face_handle;
    struct plan {
        F face;
        dt::face_polygon<M, T> polygon;
        std::vector<std::array<std::size_t, 3>> triangles;
    };
    std::vector<plan> plans;
    // Convex quads, the common case, are planned in a compact list of their own.
    struct quad_plan {
        F face;
        V a, b;  // the diagonal's corners
    };
    std::vector<quad_plan> quads;
    for (auto f : T::faces(mesh)) {
        if (!detail::euler::has_rings<M, T>(mesh, f)) {
            const auto h = T::face_halfedge(mesh, f);
            if (T::next(mesh, T::next(mesh, T::next(mesh, h))) == h) continue;
            if (auto q = dt::convex_quad_cut<M, T>(mesh, f, options.delaunay); q.from >= 0) {
                quads.push_back({f, q.corner[std::size_t(q.from)], q.corner[std::size_t(q.from) + 2]});
                continue;
            }
        }
        auto poly = dt::project_face<M, T>(mesh, f);
        if (!poly) return poly.error();
        auto tris = triangulate_polygon(poly->points, poly->loops, options);
        if (!tris) {
            auto e = tris.error();
            return fail(e.code, "triangulate_faces: face " + std::to_string(T::face_index(mesh, f)) + ": " + e.message,
                        (long long)T::face_index(mesh, f));
        }
        plans.push_back({f, std::move(*poly), std::move(*tris)});
    }
    triangulate_faces_result out;
    std::size_t added = quads.size();
    for (const auto& pl : plans) added += pl.triangles.size() - 1;
    if constexpr (reservable_mesh<M, T> && edge_index_mesh<M, T>)
        T::reserve(mesh, T::vertex_index_bound(mesh), T::edge_index_bound(mesh) + added, T::face_index_bound(mesh) + added);
    for (const auto& q : quads) {
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
        if (!r) return fail(r.error().code, "triangulate_faces: internal: " + r.error().message);  // unreachable on a valid mesh
        ++out.triangles_added;
        ++out.faces_cut;
    }
    for (auto& pl : plans) {
        const auto& pts = pl.polygon.points;
        const auto& vs = pl.polygon.vertices;
        // Point index of each vertex of this face (a vertex appears once per face), and the
        // pieces cut so far: scans on small faces, hash lookups on big ones.
        const bool big = vs.size() > 32;
        std::unordered_map<std::size_t, std::size_t> point_by_vertex;
        if constexpr (vertex_index_mesh<M, T>)
            if (big)
                for (std::size_t i = 0; i < vs.size(); ++i) point_by_vertex.emplace(T::vertex_index(mesh, vs[i]), i);
        auto point_of = [&](V v) {
            if constexpr (vertex_index_mesh<M, T>) {
                if (big) {
                    const auto it = point_by_vertex.find(T::vertex_index(mesh, v));
                    return it == point_by_vertex.end() ? vs.size() : it->second;
                }
            }
            for (std::size_t i = 0; i < vs.size(); ++i)
                if (vs[i] == v) return i;
            return vs.size();
        };
        // The diagonals: triangle sides that are not sides of the face's loops.
        std::vector<std::array<std::size_t, 2>> sides;
        for (const auto& loop : pl.polygon.loops)
            for (std::size_t i = 0; i < loop.size(); ++i) {
                const auto a = loop[i], b = loop[(i + 1) % loop.size()];
                sides.push_back({std::min(a, b), std::max(a, b)});
            }
        std::sort(sides.begin(), sides.end());
        std::vector<std::array<std::size_t, 2>> diagonals;
        for (const auto& t : pl.triangles)
            for (int s = 0; s < 3; ++s) {
                const std::array<std::size_t, 2> d{std::min(t[s], t[(s + 1) % 3]), std::max(t[s], t[(s + 1) % 3])};
                if (!std::binary_search(sides.begin(), sides.end(), d)) diagonals.push_back(d);
            }
        std::sort(diagonals.begin(), diagonals.end());
        diagonals.erase(std::unique(diagonals.begin(), diagonals.end()), diagonals.end());
        std::vector<F> pieces{pl.face};
        std::unordered_set<std::size_t> piece_ids;
        if (big) piece_ids.insert(T::face_index(mesh, pl.face));
        auto is_piece = [&](F g) {
            return big ? piece_ids.count(T::face_index(mesh, g)) > 0 : std::find(pieces.begin(), pieces.end(), g) != pieces.end();
        };
        auto add_piece = [&](F g) {
            if (big)
                piece_ids.insert(T::face_index(mesh, g));
            else
                pieces.push_back(g);
        };
        // The corner (halfedge into v) of a piece whose angle at v holds the direction to w.
        auto corner = [&](std::size_t v, std::size_t w) {
            const auto start = T::vertex_halfedge(mesh, vs[v]);
            H fallback = T::null_halfedge();
            auto x = start;
            do {
                const H in = T::opposite(mesh, x);
                if (T::face(mesh, in) != T::null_face() && is_piece(T::face(mesh, in))) {
                    const auto a = point_of(T::target(mesh, T::opposite(mesh, in)));
                    const auto b = point_of(T::target(mesh, T::next(mesh, in)));
                    if (a < vs.size() && b < vs.size() && dt::in_cone(pts[a], pts[v], pts[b], pts[w])) return in;
                    if (fallback == T::null_halfedge()) fallback = in;
                }
                x = T::next(mesh, in);
            } while (x != start);
            return fallback;
        };
        // Whether b follows a on its loop, walking from both ends at once so that the cost is
        // that of the shorter part: +1 when next(a) .. b is shorter, -1 when next(b) .. a is,
        // 0 when they lie on different loops. make_edge_face re-points the part after its first
        // corner, so passing the shorter part first makes every cut cost O(min part), and the
        // whole face O(n log n) rather than O(n^2).
        auto shorter_side = [&](H a, H b) {
            auto x = T::next(mesh, a), y = T::next(mesh, b);
            bool x_done = false, y_done = false;
            while (!x_done || !y_done) {
                if (!x_done) {
                    if (x == b) return 1;
                    x_done = x == a;
                    x = T::next(mesh, x);
                }
                if (!y_done) {
                    if (y == a) return -1;
                    y_done = y == b;
                    y = T::next(mesh, y);
                }
            }
            return 0;
        };
        const std::size_t rings = pl.polygon.loops.size() - 1;
        for (const auto& d : diagonals) {
            const H ca = corner(d[0], d[1]), cb = corner(d[1], d[0]);
            if (const int side = shorter_side(ca, cb); side != 0) {
                // With inner rings the cut keeps its first corner's side as the old face (which
                // keeps the rings), as the bridges expect; without, the shorter part goes first.
                const bool swap = side < 0 && rings == 0;
                auto r = swap ? make_edge_face<M, T>(mesh, cb, ca) : make_edge_face<M, T>(mesh, ca, cb);
                if (!r) return fail(r.error().code, "triangulate_faces: internal: " + r.error().message);  // unreachable on a valid mesh
                add_piece(r->face);
                ++out.triangles_added;
            } else {
                if constexpr (euler_ring_mutable_mesh<M, T>) {
                    auto r = make_edge_kill_ring<M, T>(mesh, ca, cb);
                    if (!r) return fail(r.error().code, "triangulate_faces: internal: " + r.error().message);
                }
            }
        }
        ++out.faces_cut;
    }
    return out;
}

}  // namespace hmira
