// hmira/algorithms/validation/detail/validate_impl.hpp
// The machinery of validate.hpp: one function per family of checks (positions, face loops,
// edges, vertex fans, isolated vertices, and for halfedge models the links, loops and fans of
// the halfedge records), each adding what it finds to a bounded problem list.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "../../../concepts.hpp"
#include "../../topology/connected_components.hpp"  // union_find
#include "../self_intersections.hpp"
#include "../../topology/edge_census.hpp"

namespace hmira::detail {

struct problem_sink {
    std::vector<mesh_problem>& out;
    std::size_t limit;
    bool full() const { return limit != 0 && out.size() >= limit; }
    void add(problem_kind k, std::size_t element, std::string msg) {
        if (!full()) out.push_back({k, element, std::move(msg)});
    }
};

/// Which halfedge, vertex and face indices name live elements, for the link checks.
template <class M, class T>
struct live_elements {
    using H = typename T::halfedge_handle;
    const M& mesh;
    std::size_t nh, nv, nf;
    std::vector<std::uint8_t> live_h, live_v, live_f;

    explicit live_elements(const M& m)
        : mesh(m),
          nh(T::halfedge_index_bound(m)),
          nv(T::vertex_index_bound(m)),
          nf(T::face_index_bound(m)),
          live_h(nh, 0),
          live_v(nv, 0),
          live_f(nf, 0) {
        for (auto v : T::vertices(mesh)) live_v[T::vertex_index(mesh, v)] = 1;
        for (auto f : T::faces(mesh)) live_f[T::face_index(mesh, f)] = 1;
        for (H h : T::halfedges(mesh)) live_h[T::halfedge_index(mesh, h)] = 1;
    }
    bool ok_h(H h) const {
        return h != T::null_halfedge() && T::halfedge_index(mesh, h) < nh && live_h[T::halfedge_index(mesh, h)];
    }
    bool ok_v(typename T::vertex_handle v) const {
        return T::vertex_index(mesh, v) < nv && live_v[T::vertex_index(mesh, v)];
    }
    bool ok_f(typename T::face_handle f) const { return T::face_index(mesh, f) < nf && live_f[T::face_index(mesh, f)]; }
    std::string hs(H h) const { return std::to_string(T::halfedge_index(mesh, h)); }
};

/// Every halfedge's own links: next/prev inverse, opposite an involution on one edge, target,
/// face and next consistent; wire edges (strict mode). Counts each face's halfedges and each
/// vertex's outgoing ones for the loop and fan checks. Returns whether every link can be
/// followed (the later checks walk them).
template <class M, class T>
bool validate_halfedge_links(const M& mesh, const validate_options& options, const live_elements<M, T>& live,
                             problem_sink& sink, std::vector<std::size_t>& face_sides,
                             std::vector<std::size_t>& outgoing) {
    using H = typename T::halfedge_handle;
    bool links_ok = true;
    for (H h : T::halfedges(mesh)) {
        if (sink.full()) return false;
        const auto n = T::next(mesh, h), p = T::prev(mesh, h), o = T::opposite(mesh, h);
        if (!live.ok_h(n) || !live.ok_h(p) || !live.ok_h(o)) {
            sink.add(problem_kind::invalid_reference, T::halfedge_index(mesh, h),
                     "halfedge " + live.hs(h) + " links to a missing halfedge");
            links_ok = false;
            continue;
        }
        if (T::prev(mesh, n) != h || T::next(mesh, p) != h) {
            sink.add(problem_kind::broken_link, T::halfedge_index(mesh, h),
                     "halfedge " + live.hs(h) + ": next/prev are not inverse");
            links_ok = false;
        }
        if (T::opposite(mesh, o) != h || o == h || T::edge(mesh, o) != T::edge(mesh, h)) {
            sink.add(problem_kind::broken_link, T::halfedge_index(mesh, h),
                     "halfedge " + live.hs(h) + ": opposite is not an involution on one edge");
            links_ok = false;
        }
        const auto t = T::target(mesh, h);
        if (!live.ok_v(t)) {
            sink.add(problem_kind::invalid_reference, T::halfedge_index(mesh, h),
                     "halfedge " + live.hs(h) + " points to a missing vertex");
            links_ok = false;
            continue;
        }
        if (T::target(mesh, T::opposite(mesh, n)) != t) {
            sink.add(problem_kind::broken_link, T::halfedge_index(mesh, h),
                     "halfedge " + live.hs(h) + ": next does not start where it ends");
            links_ok = false;
        }
        const auto f = T::face(mesh, h);
        if (f != T::null_face() && !live.ok_f(f)) {
            sink.add(problem_kind::invalid_reference, T::halfedge_index(mesh, h),
                     "halfedge " + live.hs(h) + " lies in a missing face");
            links_ok = false;
            continue;
        }
        if (T::face(mesh, n) != f) {
            sink.add(problem_kind::broken_link, T::halfedge_index(mesh, h),
                     "halfedge " + live.hs(h) + ": next lies in another face");
            links_ok = false;
        }
        if (f != T::null_face()) ++face_sides[T::face_index(mesh, f)];
        ++outgoing[T::vertex_index(mesh, T::target(mesh, o))];
        if (!options.relaxed && f == T::null_face() && T::face(mesh, o) == T::null_face() &&
            T::halfedge_index(mesh, h) < T::halfedge_index(mesh, o))
            sink.add(problem_kind::wire_edge, T::edge_index(mesh, T::edge(mesh, h)),
                     "edge " + std::to_string(T::edge_index(mesh, T::edge(mesh, h))) + " has no face on either side");
    }
    return links_ok;
}

/// Faces of a halfedge model: the outer loop and inner rings account for every halfedge of
/// the face, and stay in it.
template <class M, class T>
void validate_halfedge_loops(const M& mesh, const validate_options& options, const live_elements<M, T>& live,
                             problem_sink& sink, const std::vector<std::size_t>& face_sides) {
    using H = typename T::halfedge_handle;
    for (auto f : T::faces(mesh)) {
        if (sink.full()) return;
        const auto fi = T::face_index(mesh, f);
        const auto start = T::face_halfedge(mesh, f);
        if (!live.ok_h(start)) {
            sink.add(problem_kind::invalid_reference, fi, "face " + std::to_string(fi) + " has no valid halfedge");
            continue;
        }
        auto walk = [&](H s, const char* what) -> std::size_t {
            std::size_t len = 0;
            H h = s;
            do {
                if (T::face(mesh, h) != f) {
                    sink.add(problem_kind::broken_link, fi,
                             "face " + std::to_string(fi) + ": its " + what + " contains halfedge " + live.hs(h) +
                                 " of another face");
                    return len;
                }
                h = T::next(mesh, h);
                if (++len > live.nh) return len;
            } while (h != s);
            return len;
        };
        std::size_t sides = walk(start, "outer loop");
        if (!options.relaxed && sides < 3)
            sink.add(problem_kind::degenerate_face, fi,
                     "face " + std::to_string(fi) + " has " + std::to_string(sides) + " sides");
        if constexpr (inner_ring_mesh<M, T>)
            for (auto r : T::inner_rings(mesh, f)) {
                if (!live.ok_h(r)) {
                    sink.add(problem_kind::invalid_reference, fi,
                             "face " + std::to_string(fi) + " has an inner ring with an invalid halfedge");
                    continue;
                }
                sides += walk(r, "inner ring");
            }
        if (sides != face_sides[fi])
            sink.add(problem_kind::broken_link, fi,
                     "face " + std::to_string(fi) + " has " + std::to_string(face_sides[fi]) +
                         " halfedges but its loops hold " + std::to_string(sides));
    }
}

/// Vertices of a halfedge model: the stored halfedge leaves the vertex, the fan reaches every
/// outgoing halfedge (otherwise the vertex is non-manifold), and a boundary vertex stores a
/// boundary halfedge.
template <class M, class T>
void validate_halfedge_fans(const M& mesh, const validate_options& options, const live_elements<M, T>& live,
                            problem_sink& sink, const std::vector<std::size_t>& outgoing) {
    using H = typename T::halfedge_handle;
    for (auto v : T::vertices(mesh)) {
        if (sink.full()) return;
        const auto vi = T::vertex_index(mesh, v);
        const auto h0 = T::vertex_halfedge(mesh, v);
        if (h0 == T::null_halfedge()) {
            if (outgoing[vi] != 0)
                sink.add(
                    problem_kind::broken_link, vi,
                    "vertex " + std::to_string(vi) + " stores no halfedge but has " + std::to_string(outgoing[vi]));
            else if (!options.relaxed)
                sink.add(problem_kind::isolated_vertex, vi, "vertex " + std::to_string(vi) + " is isolated");
            continue;
        }
        if (!live.ok_h(h0) || T::target(mesh, T::opposite(mesh, h0)) != v) {
            sink.add(problem_kind::broken_link, vi,
                     "vertex " + std::to_string(vi) + " stores a halfedge that does not leave it");
            continue;
        }
        std::size_t around = 0;
        bool saw_boundary = false;
        H h = h0;
        do {
            saw_boundary |= T::face(mesh, h) == T::null_face();
            h = T::next(mesh, T::opposite(mesh, h));
            if (++around > live.nh) break;
        } while (h != h0);
        if (around != outgoing[vi])
            sink.add(problem_kind::non_manifold_vertex, vi,
                     "vertex " + std::to_string(vi) + ": its fan reaches " + std::to_string(around) + " of its " +
                         std::to_string(outgoing[vi]) + " edges");
        else if (saw_boundary && T::face(mesh, h0) != T::null_face())
            sink.add(problem_kind::broken_link, vi,
                     "vertex " + std::to_string(vi) + " is on the boundary but stores an interior halfedge");
    }
}

/// The halfedge records: links first; loops and fans only when every link can be followed
/// (walking loops over broken links could mislead, so what was found so far is reported).
template <class M, class T>
void validate_halfedges(const M& mesh, const validate_options& options, problem_sink& sink) {
    const live_elements<M, T> live(mesh);
    std::vector<std::size_t> face_sides(live.nf, 0);
    std::vector<std::size_t> outgoing(live.nv, 0);
    if (!validate_halfedge_links<M, T>(mesh, options, live, sink, face_sides, outgoing)) return;
    validate_halfedge_loops<M, T>(mesh, options, live, sink, face_sides);
    validate_halfedge_fans<M, T>(mesh, options, live, sink, outgoing);
}

/// Vertices with a NaN or infinite coordinate.
template <class M, class T>
void validate_positions(const M& mesh, problem_sink& sink) {
    for (auto v : T::vertices(mesh)) {
        if (sink.full()) return;
        const auto p = static_cast<vec3<typename T::scalar>>(T::position(mesh, v));
        if (!(std::isfinite(double(p.x)) && std::isfinite(double(p.y)) && std::isfinite(double(p.z)))) {
            const auto vi = T::vertex_index(mesh, v);
            sink.add(problem_kind::non_finite_position, vi,
                     "vertex " + std::to_string(vi) + " has a non-finite coordinate (NaN or infinity)");
        }
    }
}

/// Every face corner: its vertex and the vertices before and after it in its loop, for the
/// fan check; and which vertices some face uses.
struct face_corners {
    std::vector<std::uint32_t> vertex, prev, next;
    std::vector<std::uint8_t> used;

    void add_loop(const std::vector<std::uint32_t>& l) {
        for (std::size_t i = 0; i < l.size(); ++i) {
            used[l[i]] = 1;
            vertex.push_back(l[i]);
            prev.push_back(l[(i + l.size() - 1) % l.size()]);
            next.push_back(l[(i + 1) % l.size()]);
        }
    }
};

/// Whether face f's area vector (the sum of its edges' cross products) is exactly zero.
template <class M, class T>
bool has_zero_area(const M& mesh, typename T::face_handle f) {
    using S = typename T::scalar;
    vec3<S> area{}, first{}, prev{};
    bool started = false;
    // The edges' cross products summed in loop order, the closing edge last, without a copy of
    // the corners.
    for (auto v : T::face_vertices(mesh, f)) {
        const auto p = static_cast<vec3<S>>(T::position(mesh, v));
        if (started)
            area += cross(prev, p);
        else
            first = p;
        started = true;
        prev = p;
    }
    if (started) area += cross(prev, first);
    return area == vec3<S>{};
}

/// What the pass over the faces found that decides which checks can follow.
struct face_pass {
    bool references_ok = true;  ///< every face names live vertices only
    bool loops_close = true;    ///< every face loop returns to its start
};

/// The faces one by one: loops that do not close, missing vertices, fewer than 3 or repeated
/// vertices (strict mode), zero area (check_geometry); records the corners of the faces that
/// pass, inner rings included (a face's inner rings are part of its fan at their vertices:
/// without them a vertex on a ring would look like a pinch).
template <class M, class T>
face_pass validate_faces(const M& mesh, const validate_options& options, const std::vector<std::uint8_t>& live,
                         problem_sink& sink, face_corners& corners) {
    const std::size_t nv = live.size();
    face_pass pass;
    std::vector<std::uint32_t> loop, sorted;  // reused from face to face
    // A face loop with more corners than the mesh has halfedges never closes (corrupt next
    // links): stop there rather than follow it, since a model's rings need not guard.
    std::size_t longest_loop = std::numeric_limits<std::size_t>::max();
    if constexpr (halfedge_index_mesh<M, T>) longest_loop = T::halfedge_index_bound(mesh);
    for (auto f : T::faces(mesh)) {
        if (sink.full()) return pass;
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
            sink.add(problem_kind::broken_link, fi,
                     "face " + std::to_string(fi) + ": its loop does not return to its first halfedge");
            pass.loops_close = false;
            continue;
        }
        bool bad = false;
        for (auto i : loop)
            if (i >= nv || !live[i]) {
                sink.add(problem_kind::invalid_reference, fi,
                         "face " + std::to_string(fi) + " uses vertex " + std::to_string(i) + ", which does not exist");
                bad = true;
                pass.references_ok = false;
                break;
            }
        if (bad) continue;
        if (!options.relaxed) {
            if (loop.size() < 3) {
                sink.add(problem_kind::degenerate_face, fi,
                         "face " + std::to_string(fi) + " has only " + std::to_string(loop.size()) + " vertices");
                continue;
            }
            sorted.assign(loop.begin(), loop.end());
            std::sort(sorted.begin(), sorted.end());
            if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
                sink.add(problem_kind::degenerate_face, fi, "face " + std::to_string(fi) + " repeats a vertex");
                continue;
            }
        }
        if constexpr (positioned_mesh<M, T>) {
            if (options.check_geometry && loop.size() >= 3 && has_zero_area<M, T>(mesh, f))
                sink.add(problem_kind::zero_area_face, fi, "face " + std::to_string(fi) + " has zero area");
        }
        corners.add_loop(loop);
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
                corners.add_loop(loop);
            }
        }
    }
    return pass;
}

/// Edges with more than two sides, or with two sides in the same direction.
template <class M, class T>
void validate_edges(const M& mesh, problem_sink& sink) {
    for (const auto& e : edge_census<M, T>(mesh)) {
        if (sink.full()) return;
        if (e.uses() > 2)
            sink.add(problem_kind::non_manifold_edge, e.a,
                     "edge " + std::to_string(e.a) + "-" + std::to_string(e.b) + " has " + std::to_string(e.uses()) +
                         " faces");
        else if (e.forward == 2 || e.backward == 2)
            sink.add(problem_kind::inconsistent_orientation, e.a,
                     "edge " + std::to_string(e.a) + "-" + std::to_string(e.b) +
                         " is run in the same direction by both its faces");
    }
}

/// Corners around a vertex that share an edge belong to one fan; more than one fan means the
/// surface pinches at that vertex.
inline void validate_corner_fans(const face_corners& corners, std::size_t nv, problem_sink& sink) {
    const std::size_t nc = corners.vertex.size();
    union_find fans(nc);
    struct key {
        std::uint64_t vw;
        std::uint32_t corner;
    };
    std::vector<key> keys;
    keys.reserve(2 * nc);
    for (std::size_t c = 0; c < nc; ++c) {
        keys.push_back({(std::uint64_t(corners.vertex[c]) << 32) | corners.next[c], static_cast<std::uint32_t>(c)});
        keys.push_back({(std::uint64_t(corners.vertex[c]) << 32) | corners.prev[c], static_cast<std::uint32_t>(c)});
    }
    // Grouped by vertex with a counting sort, then each vertex's keys sorted: O(C log d).
    std::vector<std::size_t> start(nv + 1, 0);
    for (const auto& k : keys) ++start[(k.vw >> 32) + 1];
    for (std::size_t v = 1; v <= nv; ++v) start[v] += start[v - 1];
    {
        std::vector<key> grouped(keys.size());
        auto fill = start;
        for (const auto& k : keys) grouped[fill[k.vw >> 32]++] = k;
        keys.swap(grouped);
    }
    for (std::size_t v = 0; v < nv; ++v)
        std::sort(keys.begin() + std::ptrdiff_t(start[v]), keys.begin() + std::ptrdiff_t(start[v + 1]),
                  [](const key& a, const key& b) { return a.vw < b.vw; });
    for (std::size_t i = 1; i < keys.size(); ++i)
        if (keys[i].vw == keys[i - 1].vw) fans.unite(keys[i].corner, keys[i - 1].corner);
    std::vector<std::uint32_t> first_root(nv, UINT32_MAX);
    std::vector<std::uint8_t> reported(nv, 0);
    for (std::size_t c = 0; c < nc && !sink.full(); ++c) {
        const auto v = corners.vertex[c];
        const auto r = fans.find(static_cast<std::uint32_t>(c));
        if (first_root[v] == UINT32_MAX)
            first_root[v] = r;
        else if (first_root[v] != r && !reported[v]) {
            reported[v] = 1;
            sink.add(problem_kind::non_manifold_vertex, v,
                     "vertex " + std::to_string(v) + " joins two or more separate fans of faces");
        }
    }
}

}  // namespace hmira::detail

namespace hmira {

template <class M, class T>
    requires validate_mesh<M, T>
std::vector<mesh_problem> validate(const M& mesh, const validate_options& options) {
    constexpr bool halfedge_model = halfedge_index_mesh<M, T> && vertex_index_mesh<M, T> && edge_index_mesh<M, T>;
    std::vector<mesh_problem> out;
    detail::problem_sink sink{out, options.max_problems};
    const std::size_t nv = T::vertex_index_bound(mesh);
    std::vector<std::uint8_t> live(nv, 0);
    for (auto v : T::vertices(mesh)) live[T::vertex_index(mesh, v)] = 1;
    if constexpr (positioned_mesh<M, T>) detail::validate_positions<M, T>(mesh, sink);
    if (sink.full()) return out;

    detail::face_corners corners;
    corners.used.assign(nv, 0);
    const auto pass = detail::validate_faces<M, T>(mesh, options, live, sink, corners);
    if (sink.full() || !pass.references_ok) return out;
    if (!pass.loops_close) {
        // The face-based checks below walk every face loop; only the guarded link checks can
        // say more about the broken one.
        if constexpr (halfedge_model) detail::validate_halfedges<M, T>(mesh, options, sink);
        return out;
    }
    detail::validate_edges<M, T>(mesh, sink);
    if (sink.full()) return out;
    detail::validate_corner_fans(corners, nv, sink);

    if constexpr (halfedge_model) {
        detail::validate_halfedges<M, T>(mesh, options, sink);
    } else if (!options.relaxed) {
        for (auto v : T::vertices(mesh)) {
            if (sink.full()) break;
            const auto vi = T::vertex_index(mesh, v);
            if (!corners.used[vi])
                sink.add(problem_kind::isolated_vertex, vi, "vertex " + std::to_string(vi) + " is used by no face");
        }
    }
    if constexpr (self_intersection_mesh<M, T>) {
        // Positions outside the exact predicates' range (non-finite ones reported above) leave
        // the check undone rather than guessed.
        if (options.check_self_intersections && !sink.full())
            if (auto pairs = self_intersections<M, T>(mesh))
                for (const auto& p : *pairs)
                    sink.add(problem_kind::self_intersection, p[0],
                             "faces " + std::to_string(p[0]) + " and " + std::to_string(p[1]) + " intersect");
    }
    return out;
}

}  // namespace hmira
