// hmira/algorithms/euler/detail/split_vertex_impl.hpp
// The machinery of split_vertex and join_vertices (see split_vertex.hpp): walking a vertex's
// rotation, and the checks that refuse a join which would break the mesh. Not public API.
#pragma once

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "../euler_common.hpp"

namespace hmira::detail::euler {

/// The halfedges into target(from) met when turning from `from` (x -> opposite(next(x))) up
/// to and including `to`; empty if `to` is not met before coming back to `from` (then the
/// two are not in one rotation). O(halfedges turned over).
template <class M, class T>
std::vector<typename T::halfedge_handle> turn_between(const M& m, typename T::halfedge_handle from,
                                                      typename T::halfedge_handle to) {
    std::vector<typename T::halfedge_handle> out;
    auto x = from;
    do {
        x = T::opposite(m, T::next(m, x));
        out.push_back(x);
        if (x == to) return out;
    } while (x != from && out.size() <= (std::size_t{1} << 24));
    out.clear();
    return out;
}

/// Why joining the ends of h (v -> w) would break the mesh, as an error, given that the edge is
/// no loop and w has degree 2 or more: see join_vertices' precondition. Mesh unchanged.
/// O((d_v + d_w) log(d_v + d_w)) (O(d_v d_w) without vertex indices) plus O(d_v d_w).
template <class M, class T>
result<void> join_vertices_refusal(const M& mesh, typename T::halfedge_handle h) {
    namespace de = detail::euler;
    using V = typename T::vertex_handle;
    using F = typename T::face_handle;
    const auto o = T::opposite(mesh, h);
    const auto v = T::target(mesh, o), w = T::target(mesh, h);
    const auto n = T::next(mesh, h), r = T::next(mesh, o);
    if (r == h)
        return fail(errc::topology,
                    "join_vertices: " + de::name<M, T>("vertex", mesh, v) +
                        " (the survivor) has degree 1; join from the other end (the opposite halfedge)",
                    de::index_of<M, T>(mesh, v));
    const auto fh = T::face(mesh, h), fo = T::face(mesh, o);
    if (fh == fo && fh != T::null_face())
        return fail(errc::topology,
                    "join_vertices: both sides of the edge lie on " + de::name<M, T>("face", mesh, fh) +
                        "; joining its ends would make the face touch one vertex twice",
                    de::index_of<M, T>(mesh, fh));
    for (auto [loop_start, f] : {std::pair{h, fh}, std::pair{o, fo}}) {
        const auto a = T::next(mesh, loop_start);
        if (T::next(mesh, T::next(mesh, a)) == loop_start)
            return fail(errc::topology,
                        "join_vertices: the edge is a side of the triangle " + de::name<M, T>("face", mesh, f) +
                            "; joining its ends would collapse it",
                        de::index_of<M, T>(mesh, f));
    }
    // Neighbours and boundary gaps of both ends.
    std::vector<V> nv, nw;
    std::vector<F> fv, fw;  // faces around each end, other than the edge's own two
    std::size_t gaps = 0, to_w = 0;
    for (auto x = r;; x = T::next(mesh, T::opposite(mesh, x))) {  // outgoing of v, after h
        if (x == h) break;
        nv.push_back(T::target(mesh, x));
        to_w += T::target(mesh, x) == w ? 1 : 0;
        const auto f = T::face(mesh, x);
        gaps += f == T::null_face() ? 1 : 0;
        if (f != T::null_face() && f != fh && f != fo) fv.push_back(f);
    }
    for (auto x = n;; x = T::next(mesh, T::opposite(mesh, x))) {  // outgoing of w, after o
        if (x == o) break;
        nw.push_back(T::target(mesh, x));
        const auto f = T::face(mesh, x);
        gaps += f == T::null_face() ? 1 : 0;
        if (f != T::null_face() && f != fh && f != fo) fw.push_back(f);
    }
    // h's and o's own corners merge with their neighbours' (counted above through n and r).
    if (to_w > 0)
        return fail(errc::topology,
                    "join_vertices: " + de::name<M, T>("vertex", mesh, v) + " and " +
                        de::name<M, T>("vertex", mesh, w) +
                        " are joined by more than one edge; joining them would leave a loop edge",
                    de::index_of<M, T>(mesh, w));
    const auto common = [&]() -> long long {
        if constexpr (vertex_index_mesh<M, T>) {
            std::vector<std::size_t> a, b;
            for (auto x : nv) a.push_back(T::vertex_index(mesh, x));
            for (auto x : nw) b.push_back(T::vertex_index(mesh, x));
            std::sort(a.begin(), a.end());
            std::sort(b.begin(), b.end());
            std::vector<std::size_t> both;
            std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(both));
            return both.empty() ? -2 : static_cast<long long>(both.front());
        } else {
            for (auto x : nv)
                for (auto y : nw)
                    if (x == y) return -1;
            return -2;
        }
    }();
    if (common != -2)
        return fail(errc::non_manifold,
                    "join_vertices: " + de::name<M, T>("vertex", mesh, v) + " and " +
                        de::name<M, T>("vertex", mesh, w) + " have a common neighbour (vertex " +
                        (common >= 0 ? std::to_string(common) : std::string("(no index)")) +
                        "); joining them would make a double edge",
                    common);
    for (auto a : fv)
        for (auto b : fw)
            if (a == b)
                return fail(errc::non_manifold,
                            "join_vertices: " + de::name<M, T>("face", mesh, a) +
                                " touches both ends of the edge without containing it; joining them would make it "
                                "touch one vertex twice",
                            de::index_of<M, T>(mesh, a));
    if (gaps > 1)
        return fail(errc::non_manifold,
                    "join_vertices: the joined vertex would have " + std::to_string(gaps) + " boundary gaps (" +
                        de::name<M, T>("vertex", mesh, v) + " and " + de::name<M, T>("vertex", mesh, w) +
                        " are on the boundary and the edge is not), which pinches the surface",
                    de::index_of<M, T>(mesh, w));

    return {};
}

}  // namespace hmira::detail::euler
