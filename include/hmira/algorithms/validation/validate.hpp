// hmira/algorithms/validation/validate.hpp
// Checks a mesh and returns the problems it finds instead of asserting: tests run it after
// every mutation, tools report it, and a user can decide what to do about each problem.
// The relaxed mode accepts the legal intermediate states of Euler construction.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "../../concepts.hpp"
#include "../topology/connected_components.hpp"  // union_find
#include "../topology/edge_census.hpp"

namespace hmira {

enum class problem_kind {
    invalid_reference,         ///< a handle that points to no live element
    degenerate_face,           ///< fewer than 3 vertices, or a vertex repeated in a face
    zero_area_face,            ///< all corners collinear or coincident (geometry check)
    non_manifold_edge,         ///< an edge with more than two face sides
    non_manifold_vertex,       ///< the faces around a vertex form more than one fan
    inconsistent_orientation,  ///< two faces run an edge in the same direction
    isolated_vertex,           ///< a vertex used by no edge or face (legal in relaxed mode)
    wire_edge,                 ///< an edge with no face on either side (legal in relaxed mode)
    broken_link,               ///< halfedge invariants violated (next/prev/opposite/target/face)
    non_finite_position,       ///< a vertex coordinate is NaN or infinite
};

/// Readable name of a problem kind, for reports.
inline const char* to_string(problem_kind k) {
    switch (k) {
        case problem_kind::invalid_reference: return "invalid reference";
        case problem_kind::degenerate_face: return "degenerate face";
        case problem_kind::zero_area_face: return "zero-area face";
        case problem_kind::non_manifold_edge: return "non-manifold edge";
        case problem_kind::non_manifold_vertex: return "non-manifold vertex";
        case problem_kind::inconsistent_orientation: return "inconsistent orientation";
        case problem_kind::isolated_vertex: return "isolated vertex";
        case problem_kind::wire_edge: return "wire edge";
        case problem_kind::broken_link: return "broken link";
        case problem_kind::non_finite_position: return "non-finite position";
    }
    return "unknown";
}

/// One problem: its kind, the index of the element concerned (vertex, face or halfedge index
/// as the message says), and a one-line message naming it.
struct mesh_problem {
    problem_kind kind;        ///< what is wrong
    std::size_t element = 0;  ///< index of the element concerned
    std::string message;      ///< one line naming it
};

/// What validate() checks.
struct validate_options {
    /// Accept isolated vertices, wire edges, faces of fewer than 3 sides and repeated vertices
    /// in a face loop: the legal intermediate states of Euler construction.
    bool relaxed = false;
    /// Also report faces whose area is exactly zero (needs positions).
    bool check_geometry = true;
    /// Stop after this many problems (0: no limit), so a badly broken mesh reports quickly.
    std::size_t max_problems = 1000;
};

template <class M, class T = default_traits<M>>
concept validate_mesh = face_vertex_range_mesh<M, T> && vertex_index_mesh<M, T> && face_index_mesh<M, T>;

namespace detail {

struct problem_sink {
    std::vector<mesh_problem>& out;
    std::size_t limit;
    bool full() const { return limit != 0 && out.size() >= limit; }
    void add(problem_kind k, std::size_t element, std::string msg) {
        if (!full()) out.push_back({k, element, std::move(msg)});
    }
};

template <class M, class T>
void validate_halfedges(const M& mesh, const validate_options& options, problem_sink& sink) {
    using H = typename T::halfedge_handle;
    const std::size_t nh = T::halfedge_index_bound(mesh);
    const std::size_t nv = T::vertex_index_bound(mesh);
    const std::size_t nf = T::face_index_bound(mesh);
    std::vector<std::uint8_t> live_h(nh, 0), live_v(nv, 0), live_f(nf, 0);
    for (auto v : T::vertices(mesh)) live_v[T::vertex_index(mesh, v)] = 1;
    for (auto f : T::faces(mesh)) live_f[T::face_index(mesh, f)] = 1;
    for (H h : T::halfedges(mesh)) live_h[T::halfedge_index(mesh, h)] = 1;
    auto ok_h = [&](H h) { return h != T::null_halfedge() && T::halfedge_index(mesh, h) < nh && live_h[T::halfedge_index(mesh, h)]; };
    auto ok_v = [&](auto v) { return T::vertex_index(mesh, v) < nv && live_v[T::vertex_index(mesh, v)]; };
    auto ok_f = [&](auto f) { return T::face_index(mesh, f) < nf && live_f[T::face_index(mesh, f)]; };
    auto hs = [&](H h) { return std::to_string(T::halfedge_index(mesh, h)); };

    std::vector<std::size_t> face_sides(nf, 0);
    std::vector<std::size_t> outgoing(nv, 0);
    bool links_ok = true;
    for (H h : T::halfedges(mesh)) {
        if (sink.full()) return;
        const auto n = T::next(mesh, h), p = T::prev(mesh, h), o = T::opposite(mesh, h);
        if (!ok_h(n) || !ok_h(p) || !ok_h(o)) {
            sink.add(problem_kind::invalid_reference, T::halfedge_index(mesh, h), "halfedge " + hs(h) + " links to a missing halfedge");
            links_ok = false;
            continue;
        }
        if (T::prev(mesh, n) != h || T::next(mesh, p) != h) {
            sink.add(problem_kind::broken_link, T::halfedge_index(mesh, h), "halfedge " + hs(h) + ": next/prev are not inverse");
            links_ok = false;
        }
        if (T::opposite(mesh, o) != h || o == h || T::edge(mesh, o) != T::edge(mesh, h)) {
            sink.add(problem_kind::broken_link, T::halfedge_index(mesh, h), "halfedge " + hs(h) + ": opposite is not an involution on one edge");
            links_ok = false;
        }
        const auto t = T::target(mesh, h);
        if (!ok_v(t)) {
            sink.add(problem_kind::invalid_reference, T::halfedge_index(mesh, h), "halfedge " + hs(h) + " points to a missing vertex");
            links_ok = false;
            continue;
        }
        if (T::target(mesh, T::opposite(mesh, n)) != t) {
            sink.add(problem_kind::broken_link, T::halfedge_index(mesh, h), "halfedge " + hs(h) + ": next does not start where it ends");
            links_ok = false;
        }
        const auto f = T::face(mesh, h);
        if (f != T::null_face() && !ok_f(f)) {
            sink.add(problem_kind::invalid_reference, T::halfedge_index(mesh, h), "halfedge " + hs(h) + " lies in a missing face");
            links_ok = false;
            continue;
        }
        if (T::face(mesh, n) != f) {
            sink.add(problem_kind::broken_link, T::halfedge_index(mesh, h), "halfedge " + hs(h) + ": next lies in another face");
            links_ok = false;
        }
        if (f != T::null_face()) ++face_sides[T::face_index(mesh, f)];
        ++outgoing[T::vertex_index(mesh, T::target(mesh, o))];
        if (!options.relaxed && f == T::null_face() && T::face(mesh, o) == T::null_face() &&
            T::halfedge_index(mesh, h) < T::halfedge_index(mesh, o))
            sink.add(problem_kind::wire_edge, T::edge_index(mesh, T::edge(mesh, h)),
                     "edge " + std::to_string(T::edge_index(mesh, T::edge(mesh, h))) + " has no face on either side");
    }
    if (!links_ok) return;  // walking loops over broken links could mislead; report what we have

    // Faces: the outer loop and inner rings account for every halfedge of the face.
    for (auto f : T::faces(mesh)) {
        if (sink.full()) return;
        const auto fi = T::face_index(mesh, f);
        const auto start = T::face_halfedge(mesh, f);
        if (!ok_h(start)) {
            sink.add(problem_kind::invalid_reference, fi, "face " + std::to_string(fi) + " has no valid halfedge");
            continue;
        }
        auto walk = [&](H s, const char* what) -> std::size_t {
            std::size_t len = 0;
            H h = s;
            do {
                if (T::face(mesh, h) != f) {
                    sink.add(problem_kind::broken_link, fi, "face " + std::to_string(fi) + ": its " + what + " contains halfedge " + hs(h) + " of another face");
                    return len;
                }
                h = T::next(mesh, h);
                if (++len > nh) return len;
            } while (h != s);
            return len;
        };
        std::size_t sides = walk(start, "outer loop");
        if (!options.relaxed && sides < 3)
            sink.add(problem_kind::degenerate_face, fi, "face " + std::to_string(fi) + " has " + std::to_string(sides) + " sides");
        if constexpr (inner_ring_mesh<M, T>)
            for (auto r : T::inner_rings(mesh, f)) {
                if (!ok_h(r)) {
                    sink.add(problem_kind::invalid_reference, fi, "face " + std::to_string(fi) + " has an inner ring with an invalid halfedge");
                    continue;
                }
                sides += walk(r, "inner ring");
            }
        if (sides != face_sides[fi])
            sink.add(problem_kind::broken_link, fi, "face " + std::to_string(fi) + " has " + std::to_string(face_sides[fi]) +
                                                        " halfedges but its loops hold " + std::to_string(sides));
    }
    // Vertices: the stored halfedge leaves the vertex, the fan reaches every outgoing halfedge
    // (otherwise the vertex is non-manifold), and a boundary vertex stores a boundary halfedge.
    for (auto v : T::vertices(mesh)) {
        if (sink.full()) return;
        const auto vi = T::vertex_index(mesh, v);
        const auto h0 = T::vertex_halfedge(mesh, v);
        if (h0 == T::null_halfedge()) {
            if (outgoing[vi] != 0)
                sink.add(problem_kind::broken_link, vi, "vertex " + std::to_string(vi) + " stores no halfedge but has " + std::to_string(outgoing[vi]));
            else if (!options.relaxed)
                sink.add(problem_kind::isolated_vertex, vi, "vertex " + std::to_string(vi) + " is isolated");
            continue;
        }
        if (!ok_h(h0) || T::target(mesh, T::opposite(mesh, h0)) != v) {
            sink.add(problem_kind::broken_link, vi, "vertex " + std::to_string(vi) + " stores a halfedge that does not leave it");
            continue;
        }
        std::size_t around = 0;
        bool saw_boundary = false;
        H h = h0;
        do {
            saw_boundary |= T::face(mesh, h) == T::null_face();
            h = T::next(mesh, T::opposite(mesh, h));
            if (++around > nh) break;
        } while (h != h0);
        if (around != outgoing[vi])
            sink.add(problem_kind::non_manifold_vertex, vi, "vertex " + std::to_string(vi) + ": its fan reaches " + std::to_string(around) +
                                                                " of its " + std::to_string(outgoing[vi]) + " edges");
        else if (saw_boundary && T::face(mesh, h0) != T::null_face())
            sink.add(problem_kind::broken_link, vi, "vertex " + std::to_string(vi) + " is on the boundary but stores an interior halfedge");
    }
}

}  // namespace detail

/// Checks the mesh; an empty result means valid. Cost O(V + C log C) for V vertices and C face
/// corners, plus O(H_all) for halfedge models.
///
/// Meshes with positions: vertices with a NaN or infinite coordinate (always checked: no
/// geometric operation can use them). Every model: faces of fewer than 3 or repeated vertices (strict mode), faces naming
/// missing vertices, exactly-zero-area faces (check_geometry), edges with more than two face
/// sides, edges run twice in one direction (inconsistent orientation), vertices whose faces
/// form several fans, isolated vertices (strict mode).
/// Halfedge models also: every next/prev/opposite/target/face link, loops of faces and inner
/// rings, vertex fans, boundary halfedges stored at boundary vertices, wire edges (strict).
template <class M, class T = default_traits<M>>
    requires validate_mesh<M, T>
std::vector<mesh_problem> validate(const M& mesh, const validate_options& options = {}) {
    std::vector<mesh_problem> out;
    detail::problem_sink sink{out, options.max_problems};
    const std::size_t nv = T::vertex_index_bound(mesh);
    std::vector<std::uint8_t> live(nv, 0), used(nv, 0);
    for (auto v : T::vertices(mesh)) live[T::vertex_index(mesh, v)] = 1;

    if constexpr (positioned_mesh<M, T>) {
        for (auto v : T::vertices(mesh)) {
            if (sink.full()) return out;
            const auto p = static_cast<vec3<typename T::scalar>>(T::position(mesh, v));
            if (!(std::isfinite(double(p.x)) && std::isfinite(double(p.y)) && std::isfinite(double(p.z)))) {
                const auto vi = T::vertex_index(mesh, v);
                sink.add(problem_kind::non_finite_position, vi, "vertex " + std::to_string(vi) + " has a non-finite coordinate (NaN or infinity)");
            }
        }
    }

    // Faces one by one.
    std::vector<std::uint32_t> corner_vertex;  // per corner: vertex index
    std::vector<std::uint32_t> corner_prev, corner_next;
    std::vector<std::uint32_t> loop;
    bool references_ok = true;
    // A face loop with more corners than the mesh has halfedges never closes (corrupt next
    // links): stop there rather than follow it, since a model's rings need not guard.
    std::size_t longest_loop = std::numeric_limits<std::size_t>::max();
    bool loops_close = true;
    if constexpr (halfedge_index_mesh<M, T>) longest_loop = T::halfedge_index_bound(mesh);
    for (auto f : T::faces(mesh)) {
        if (sink.full()) return out;
        const auto fi = T::face_index(mesh, f);
        loop.clear();
        bool closes = true;
        for (auto v : T::face_vertices(mesh, f)) {
            if (loop.size() == longest_loop) {
                closes = false;
                break;
            }
            loop.push_back(static_cast<std::uint32_t>(T::vertex_index(mesh, v)));
        }
        if (!closes) {
            sink.add(problem_kind::broken_link, fi, "face " + std::to_string(fi) + ": its loop does not return to its first halfedge");
            loops_close = false;
            continue;
        }
        bool bad = false;
        for (auto i : loop)
            if (i >= nv || !live[i]) {
                sink.add(problem_kind::invalid_reference, fi, "face " + std::to_string(fi) + " uses vertex " + std::to_string(i) + ", which does not exist");
                bad = true;
                references_ok = false;
                break;
            }
        if (bad) continue;
        if (!options.relaxed) {
            if (loop.size() < 3) {
                sink.add(problem_kind::degenerate_face, fi, "face " + std::to_string(fi) + " has only " + std::to_string(loop.size()) + " vertices");
                continue;
            }
            auto sorted = loop;
            std::sort(sorted.begin(), sorted.end());
            if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
                sink.add(problem_kind::degenerate_face, fi, "face " + std::to_string(fi) + " repeats a vertex");
                continue;
            }
        }
        if constexpr (positioned_mesh<M, T>) {
            if (options.check_geometry && loop.size() >= 3) {
                using S = typename T::scalar;
                vec3<S> area{};
                std::vector<vec3<S>> ps;
                for (auto v : T::face_vertices(mesh, f)) ps.push_back(static_cast<vec3<S>>(T::position(mesh, v)));
                for (std::size_t i = 0; i < ps.size(); ++i) area += cross(ps[i], ps[(i + 1) % ps.size()]);
                if (area == vec3<S>{})
                    sink.add(problem_kind::zero_area_face, fi, "face " + std::to_string(fi) + " has zero area");
            }
        }
        auto add_corners = [&](const std::vector<std::uint32_t>& l) {
            for (std::size_t i = 0; i < l.size(); ++i) {
                used[l[i]] = 1;
                corner_vertex.push_back(l[i]);
                corner_prev.push_back(l[(i + l.size() - 1) % l.size()]);
                corner_next.push_back(l[(i + 1) % l.size()]);
            }
        };
        add_corners(loop);
        // A face's inner rings are part of its fan at their vertices: without them a vertex on
        // a ring would look like a pinch.
        if constexpr (inner_ring_mesh<M, T>) {
            for (auto r : T::inner_rings(mesh, f)) {
                loop.clear();
                auto h = r;
                std::size_t guard = 0;
                do {
                    const auto vi = static_cast<std::uint32_t>(T::vertex_index(mesh, T::target(mesh, h)));
                    if (vi >= nv) break;
                    loop.push_back(vi);
                    h = T::next(mesh, h);
                } while (h != r && ++guard <= T::halfedge_index_bound(mesh));
                add_corners(loop);
            }
        }
    }
    if (!references_ok) return out;
    if (!loops_close) {
        // The face-based checks below walk every face loop; only the guarded link checks can
        // say more about the broken one.
        if constexpr (halfedge_index_mesh<M, T> && vertex_index_mesh<M, T> && edge_index_mesh<M, T>)
            detail::validate_halfedges<M, T>(mesh, options, sink);
        return out;
    }

    // Edges: more than two sides, or two sides in the same direction.
    for (const auto& e : edge_census<M, T>(mesh)) {
        if (sink.full()) return out;
        if (e.uses() > 2)
            sink.add(problem_kind::non_manifold_edge, e.a, "edge " + std::to_string(e.a) + "-" + std::to_string(e.b) + " has " + std::to_string(e.uses()) + " faces");
        else if (e.forward == 2 || e.backward == 2)
            sink.add(problem_kind::inconsistent_orientation, e.a, "edge " + std::to_string(e.a) + "-" + std::to_string(e.b) +
                                                                       " is run in the same direction by both its faces");
    }

    // Vertices: corners around a vertex that share an edge belong to one fan; more than one
    // fan means the surface pinches at that vertex.
    {
        const std::size_t nc = corner_vertex.size();
        union_find fans(nc);
        struct key { std::uint64_t vw; std::uint32_t corner; };
        std::vector<key> keys;
        keys.reserve(2 * nc);
        for (std::size_t c = 0; c < nc; ++c) {
            keys.push_back({(std::uint64_t(corner_vertex[c]) << 32) | corner_next[c], static_cast<std::uint32_t>(c)});
            keys.push_back({(std::uint64_t(corner_vertex[c]) << 32) | corner_prev[c], static_cast<std::uint32_t>(c)});
        }
        std::sort(keys.begin(), keys.end(), [](const key& a, const key& b) { return a.vw < b.vw; });
        for (std::size_t i = 1; i < keys.size(); ++i)
            if (keys[i].vw == keys[i - 1].vw) fans.unite(keys[i].corner, keys[i - 1].corner);
        std::vector<std::uint32_t> first_root(nv, UINT32_MAX);
        std::vector<std::uint8_t> reported(nv, 0);
        for (std::size_t c = 0; c < nc && !sink.full(); ++c) {
            const auto v = corner_vertex[c];
            const auto r = fans.find(static_cast<std::uint32_t>(c));
            if (first_root[v] == UINT32_MAX) first_root[v] = r;
            else if (first_root[v] != r && !reported[v]) {
                reported[v] = 1;
                sink.add(problem_kind::non_manifold_vertex, v, "vertex " + std::to_string(v) + " joins two or more separate fans of faces");
            }
        }
    }

    if constexpr (halfedge_index_mesh<M, T> && vertex_index_mesh<M, T> && edge_index_mesh<M, T>) {
        detail::validate_halfedges<M, T>(mesh, options, sink);
    } else if (!options.relaxed) {
        for (auto v : T::vertices(mesh)) {
            if (sink.full()) break;
            const auto vi = T::vertex_index(mesh, v);
            if (!used[vi]) sink.add(problem_kind::isolated_vertex, vi, "vertex " + std::to_string(vi) + " is used by no face");
        }
    }
    return out;
}

}  // namespace hmira
