// hmira/algorithms/editing/detail/extrude_impl.hpp
// The machinery of extrude() (see extrude.hpp, which includes this file after its
// declarations): one face by makeEV and makeEF, a region by split_vertex along its outline,
// and the checks that pick the mode and find the outline. Not part of the public API.
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "editing_common.hpp"

namespace hmira::detail::editing {

template <class M, class T>
result<void> check_extrude_face(const M& m, typename T::face_handle f) {
    namespace de = detail::euler;
    if (!de::usable<M, T>(m, f))
        return fail(errc::invalid_handle, "extrude: " + de::name<M, T>("face", m, f) + " does not exist",
                    de::index_of<M, T>(m, f));
    return {};
}

/// One halfedge of every loop of f: the outer loop, then each inner ring (on models that have
/// rings). O(rings of f).
template <class M, class T>
std::vector<typename T::halfedge_handle> face_loops(const M& m, typename T::face_handle f) {
    std::vector<typename T::halfedge_handle> out{T::face_halfedge(m, f)};
    if constexpr (inner_ring_mesh<M, T>)
        for (auto r : T::inner_rings(m, f)) out.push_back(r);
    return out;
}

/// The halfedges of the loop through `start`, in order. O(loop size).
template <class M, class T>
std::vector<typename T::halfedge_handle> loop_of(const M& m, typename T::halfedge_handle start) {
    std::vector<typename T::halfedge_handle> out;
    auto h = start;
    do {
        out.push_back(h);
        h = T::next(m, h);
    } while (h != start);
    return out;
}

/// Newell vector of f over all its loops: inner rings are wound against the outer loop, so
/// they subtract their area. O(face degree + ring sizes).
template <class M, class T>
vec3<double> area_vector_with_rings(const M& m, typename T::face_handle f) {
    vec3<double> n{};
    for (auto start : face_loops<M, T>(m, f))
        for (auto h : loop_of<M, T>(m, start))
            n += newell_term(pos<M, T>(m, T::target(m, T::opposite(m, h))), pos<M, T>(m, T::target(m, h)));
    return n;
}

/// Extrudes one face by the displacement `d` from Euler operators, loop by loop (the outer
/// loop, then every inner ring): makeEV grows a new vertex out of every corner of the loop
/// into the face, then makeEF joins consecutive tips, each cutting a side quad off the face,
/// until the loop runs through the tips only. On a ring the quads face into the hole. For n
/// corners over all loops: V + n, E + 2n, F + n, rings unchanged. O(n + rings).
template <class M, class T, class Out>
result<void> extrude_one(M& m, typename T::face_handle f, const vec3<double>& d, Out& out) {
    using H = typename T::halfedge_handle;
    // Every loop is read before any change: makeEF re-registers the ring halfedges it cuts off.
    std::vector<std::vector<H>> loops;
    for (auto start : face_loops<M, T>(m, f)) loops.push_back(loop_of<M, T>(m, start));
    for (const auto& into : loops) {
        const std::size_t n = into.size();
        std::vector<H> up(n);
        for (std::size_t i = 0; i < n; ++i) {
            const auto r = mev<M, T>(m, into[i], pos<M, T>(m, T::target(m, into[i])) + d);
            if (!r) return r.error();
            up[i] = r.value().halfedge;
            out.vertices.push_back(r.value().vertex);
        }
        H h0 = up[0];
        for (std::size_t i = 0; i < n; ++i) {
            const auto r = mef<M, T>(m, h0, up[(i + 1) % n]);
            if (!r) return r.error();
            out.side_faces.push_back(r.value().face);
            h0 = r.value().halfedge;
        }
    }
    out.top_faces.push_back(f);
    return {};
}

/// Extrudes a connected region of several faces (already checked: `in_region` holds their
/// indices; `outline` the region-side halfedges g = u -> v of every loop, outer or ring, whose
/// other side is not in the region; no outline vertex pinched) by `d`, from Euler operators.
/// The region keeps its elements and moves; what stays behind is new:
///  1. split_vertex (the general makeEV) at every outline vertex v: a new vertex v' at v's place
///     takes over the edges outside the region, between the outline edge leaving v and the
///     one arriving; the new edge v -> v' lies in the outside faces on both sides of v (an
///     edge hanging into the one outside face when v has a single outside corner);
///  2. makeEF per outline edge, in the outside face across it: from u' to v', cutting off the
///     wall quad u -> u' -> v' -> v ... wound with the region;
///  3. the region's vertices (all of them, outline included) move by d.
/// V + b, E + 2b, F + b for b outline edges. O(R log R) for R corners of the region's faces,
/// plus the outline vertices' fans.
template <class M, class T, class Out>
result<void> extrude_region(M& m, const std::vector<typename T::face_handle>& faces, const index_set& in_region,
                            const std::vector<typename T::halfedge_handle>& outline, const vec3<double>& d, Out& out,
                            const progress_function& report) {
    using H = typename T::halfedge_handle;
    using F = typename T::face_handle;
    auto in_r = [&](F f) { return f != T::null_face() && in_region.contains(T::face_index(m, f)); };
    const std::size_t k = outline.size();
    reserve_growth<M, T>(m, k, 2 * k, k);  // V + b, E + 2b, F + b
    // Read phase. For g_i = u -> v: the corners of the split at v, and which outline halfedge
    // ends at u (its split makes the wall's other vertical edge).
    std::vector<H> h0(k), h1(k);
    std::vector<vec3<double>> place(k);
    index_map by_target;  // vertex index of v -> i
    for (std::size_t i = 0; i < k; ++i) {
        const auto g = outline[i];
        // Turn through the region's corners at v to the outline halfedge leaving v.
        auto x = g;
        H leaving = T::next(m, x);
        while (in_r(T::face(m, T::opposite(m, leaving)))) {
            x = T::opposite(m, leaving);
            leaving = T::next(m, x);
        }
        h0[i] = T::opposite(m, leaving);        // into v from outside, along the outline edge leaving v
        h1[i] = T::prev(m, T::opposite(m, g));  // the last outside corner before g
        place[i] = pos<M, T>(m, T::target(m, g));
        by_target.emplace(T::vertex_index(m, T::target(m, g)), i);
    }
    std::vector<std::size_t> left(k);  // the outline halfedge that ends at the source of g_i
    for (std::size_t i = 0; i < k; ++i)
        left[i] = by_target.find(T::vertex_index(m, T::target(m, T::opposite(m, outline[i]))));
    // 1. Split every outline vertex; `down[i]` runs from v_i to its copy.
    std::vector<H> down(k);
    progress_gate progress(report, 2 * k, "extrude");
    for (std::size_t i = 0; i < k; ++i) {
        if (auto ok = progress.step(); !ok) return ok.error();
        if (auto ok = inner_call_allowed<T>("split_vertex"); !ok) return ok.error();
        const auto r = split_vertex<M, T>(m, h0[i], h1[i], to_point<M, T>(place[i]));
        if (!r) return r.error();
        down[i] = r.value().halfedge;
        out.vertices.push_back(r.value().vertex);
    }
    // 2. One wall per outline edge: its face's loop reads ... -> v' -> v -> u -> u' -> ...
    for (std::size_t i = 0; i < k; ++i) {
        if (auto ok = progress.step(); !ok) return ok.error();
        const auto up_v = T::opposite(m, down[i]);  // v' -> v
        const auto r = mef<M, T>(m, T::prev(m, up_v), down[left[i]]);
        if (!r) return r.error();
        out.side_faces.push_back(r.value().face);
    }
    // 3. Move the region.
    index_set done;
    for (auto f : faces)
        for (auto start : face_loops<M, T>(m, f))
            for (auto h : loop_of<M, T>(m, start)) {
                const auto v = T::target(m, h);
                if (!done.insert(T::vertex_index(m, v))) continue;
                T::set_position(m, v, to_point<M, T>(pos<M, T>(m, v) + d));
            }
    out.top_faces = faces;
    return {};
}

/// Extrudes each face of `fs` on its own (individual mode, or a single face), along the given
/// direction or its own normal, in one transaction.
template <class M, class T>
result<extrude_result<M, T>> extrude_each(M& mesh, const std::vector<typename T::face_handle>& fs,
                                          const vec3<double>& dir, const extrude_options& options) {
    std::vector<vec3<double>> moves;
    std::size_t corners = 0;  // V + n, E + 2n, F + n for n corners over all loops
    for (auto f : fs) {
        for (auto start : face_loops<M, T>(mesh, f)) {
            auto h = start;
            do {
                ++corners;
                h = T::next(mesh, h);
            } while (h != start);
        }
        const auto n = area_vector_with_rings<M, T>(mesh, f);
        if (!options.direction && !(norm(n) > 0))
            return fail(errc::invalid_argument,
                        "extrude: " + detail::euler::name<M, T>("face", mesh, f) + " has zero area, so no normal",
                        static_cast<long long>(T::face_index(mesh, f)));
        moves.push_back((options.direction ? dir : normalized(n)) * options.distance);
    }
    return transact<M, T>(mesh, [&]<class JT>() -> result<extrude_result<M, T>> {
        extrude_result<M, T> out;
        reserve_growth<M, JT>(mesh, corners, 2 * corners, corners);
        progress_gate progress(options.progress, fs.size(), "extrude");
        for (std::size_t i = 0; i < fs.size(); ++i) {
            if (auto ok = progress.step(); !ok) return ok.error();
            if (auto ok = extrude_one<M, JT>(mesh, fs[i], moves[i], out); !ok) return ok.error();
        }
        return out;
    });
}

/// The outline of the region `fs` (the halfedges of its faces' loops whose other side is not
/// in the region), adding the faces' area vectors to `area`. errc::topology for a region that
/// is not connected through edges, has no outline, or is pinched at an outline vertex.
template <class M, class T>
result<std::vector<typename T::halfedge_handle>> extrude_outline(const M& mesh,
                                                                 const std::vector<typename T::face_handle>& fs,
                                                                 const index_set& in_region, vec3<double>& area) {
    using F = typename T::face_handle;
    auto in_r = [&](F f) { return f != T::null_face() && in_region.contains(T::face_index(mesh, f)); };
    std::vector<typename T::halfedge_handle> outline;
    {
        index_set reached;
        std::vector<F> stack{fs[0]};
        reached.insert(T::face_index(mesh, fs[0]));
        std::size_t count = 0;
        while (!stack.empty()) {
            const F f = stack.back();
            stack.pop_back();
            ++count;
            for (auto start : face_loops<M, T>(mesh, f))
                for (auto h : loop_of<M, T>(mesh, start)) {
                    const F g = T::face(mesh, T::opposite(mesh, h));
                    if (in_r(g) && !reached.contains(T::face_index(mesh, g))) {
                        reached.insert(T::face_index(mesh, g));
                        stack.push_back(g);
                    }
                }
        }
        if (count != fs.size())
            return fail(errc::topology,
                        "extrude: the faces are not connected through edges; use extrude_mode::individual or extrude "
                        "each part");
    }
    for (auto f : fs) {
        area += area_vector_with_rings<M, T>(mesh, f);
        for (auto start : face_loops<M, T>(mesh, f))
            for (auto h : loop_of<M, T>(mesh, start))
                if (!in_r(T::face(mesh, T::opposite(mesh, h)))) outline.push_back(h);
    }
    if (outline.empty())
        return fail(errc::topology,
                    "extrude: the region is a whole closed component; it has no outline to build walls on");
    std::vector<std::size_t> ends;
    for (auto g : outline) ends.push_back(T::vertex_index(mesh, T::target(mesh, g)));
    std::sort(ends.begin(), ends.end());
    const auto dup = std::adjacent_find(ends.begin(), ends.end());
    if (dup != ends.end())
        return fail(errc::topology,
                    "extrude: the region touches vertex " + std::to_string(*dup) +
                        " in two separate fans (pinched); extrude the parts separately",
                    static_cast<long long>(*dup));
    return outline;
}

}  // namespace hmira::detail::editing

namespace hmira {

template <class M, class T, class R>
    requires extrudable_mesh<M, T> && range_of_handles<R, typename T::face_handle>
result<extrude_result<M, T>> extrude(M& mesh, const R& faces, const extrude_options& options) {
    namespace de = detail::editing;
    using F = typename T::face_handle;
    if (!de::finite(options.distance) || options.distance == 0)
        return fail(errc::invalid_argument, "extrude: distance must be finite and non-zero");
    vec3<double> dir{};
    if (options.direction) {
        dir = *options.direction;
        if (!(norm(dir) > 0) || !de::finite(norm(dir)))
            return fail(errc::invalid_argument, "extrude: direction must be a finite non-zero vector");
        dir = normalized(dir);
    }
    std::vector<F> fs;
    de::index_set in_region;
    for (auto f0 : faces) {
        const F f = f0;
        if (auto ok = de::check_extrude_face<M, T>(mesh, f); !ok) return ok.error();
        const auto i = T::face_index(mesh, f);
        if (in_region.contains(i)) continue;
        in_region.insert(i);
        fs.push_back(f);
    }
    if (fs.empty()) return fail(errc::invalid_argument, "extrude: no face selected");
    if (options.mode == extrude_mode::individual || fs.size() == 1)
        return de::extrude_each<M, T>(mesh, fs, dir, options);
    // Region: connected, with an outline, not pinched.
    vec3<double> area{};
    const auto outline = de::extrude_outline<M, T>(mesh, fs, in_region, area);
    if (!outline) return outline.error();
    if (!options.direction) {
        if (!(norm(area) > 0))
            return fail(errc::invalid_argument, "extrude: the region's mean normal is zero; give a direction");
        dir = normalized(area);
    }
    return de::transact<M, T>(mesh, [&]<class JT>() -> result<extrude_result<M, T>> {
        extrude_result<M, T> out;
        if (auto ok = de::extrude_region<M, JT>(mesh, fs, in_region, outline.value(), dir * options.distance, out,
                                                options.progress);
            !ok)
            return ok.error();
        return out;
    });
}

template <class M, class T>
    requires extrudable_mesh<M, T>
result<extrude_result<M, T>> extrude(M& mesh, typename T::face_handle face, const extrude_options& options) {
    const typename T::face_handle one[1] = {face};
    return extrude<M, T>(mesh, one, options);
}

}  // namespace hmira
