// hmira/algorithms/editing/truncate.hpp
// Vertex truncation (thesis 2.2): cut the corner at a vertex with a plane through new points on
// its edges, replacing the vertex by a new face. Works on one vertex, a set, or all vertices
// (cube -> truncated cube), on every Euler-capable model, built from the Euler operators.
#pragma once

#include <cstddef>
#include <ranges>
#include <string>
#include <vector>

#include "detail/editing_common.hpp"

namespace hmira {

/// A mesh truncate() can edit: see editable_mesh (Euler operators, positions, indices).
template <class M, class T = default_traits<M>>
concept truncatable_mesh = editable_mesh<M, T>;

/// Where the cuts go. Each cut point lies on an edge at `fraction` of the edge's length from
/// the truncated vertex or, when `distance` > 0, at that absolute distance instead.
/// On an edge whose other end is truncated by the same call the cut is clamped to half the
/// edge, so cuts from both ends never cross; at exactly half they meet and share one vertex
/// (cube at 1/2 -> cuboctahedron). Otherwise it is clamped to the whole edge (at 1 the cut
/// point lies on the neighbour, joined to it by an edge of length zero).
struct truncate_options {
    double fraction = 1.0 / 3.0;  ///< in (0, 1); used when distance is 0
    double distance = 0.0;        ///< > 0: absolute distance along each edge, overrides fraction
    /// Called every 1024 cut points and new faces, from the calling thread; returning false
    /// cancels: the mesh is rolled back and the error is errc::cancelled.
    progress_function progress = {};
};

/// What truncating one vertex created.
template <class M, class T = default_traits<M>>
struct truncate_result {
    /// The new face, wound like the faces around it; null for a vertex of degree 2 (the corner
    /// of a single face at the boundary, or between two faces), which is cut by one edge only.
    typename T::face_handle face;
    std::vector<typename T::vertex_handle> vertices;  ///< the cut points, in the new face's order
};

/// What truncating a set of vertices created.
template <class M, class T = default_traits<M>>
struct truncate_set_result {
    std::vector<typename T::face_handle> faces;       ///< one per vertex, in input order (null: degree 2)
    std::vector<typename T::vertex_handle> vertices;  ///< every cut point made (a shared one once)
};

namespace detail::editing {

template <class M, class T>
result<void> check_truncate_options(const truncate_options& o, const char* what) {
    if (!(o.distance >= 0) || !finite(o.distance))
        return fail(errc::invalid_argument, std::string(what) + ": distance must be finite and >= 0 (0 selects fraction)");
    if (o.distance == 0 && !(o.fraction > 0 && o.fraction < 1))
        return fail(errc::invalid_argument, std::string(what) + ": fraction must lie in (0, 1), got " + std::to_string(o.fraction));
    return {};
}

/// Cut parameter along h (from its source), clamped as truncate_options says.
template <class M, class T>
double cut_parameter(const M& m, typename T::halfedge_handle h, const truncate_options& o, bool other_end_cut) {
    const double len = norm(pos<M, T>(m, T::target(m, h)) - pos<M, T>(m, detail::euler::source<M, T>(m, h)));
    double t = o.distance > 0 ? (len > 0 ? o.distance / len : 1.0) : o.fraction;
    const double limit = other_end_cut ? 0.5 : 1.0;
    return t < limit ? t : limit;
}

/// Truncates the vertices whose indices are in `selected` (already checked): splits every
/// edge at their cuts, then replaces each vertex by a polygon through its cut points. Run
/// inside a transaction (T journaled); an inner failure is passed on.
template <class M, class T, class Out>
result<void> truncate_checked(M& m, const std::vector<typename T::vertex_handle>& vs, const index_set& selected,
                              const truncate_options& o, Out& out) {
    using H = typename T::halfedge_handle;
    // Plan every split before changing anything, from the original geometry.
    struct cut { H h; double t_from, t_to; bool both; };
    std::vector<cut> cuts;
    for (auto v : vs)
        for (auto h : outgoing<M, T>(m, v)) {
            const auto w = T::target(m, h);
            const bool both = selected.contains(T::vertex_index(m, w));
            if (both && T::vertex_index(m, w) < T::vertex_index(m, v)) continue;  // planned from w
            const double tv = cut_parameter<M, T>(m, h, o, both);
            const double tw = both ? cut_parameter<M, T>(m, T::opposite(m, h), o, true) : 0.0;
            cuts.push_back({h, tv, tw, both});
        }
    // Each cut makes one or two points, each by split_edge (slots: V + 1, E + 2, F + 1); each
    // vertex of degree d then makes d edges and d faces (mef), one more on the boundary,
    // before merging them (kef).
    std::size_t points = 0, degrees = 0;
    for (const auto& c : cuts) {
        points += (c.both && c.t_from + c.t_to < 1.0) ? 2 : 1;
        degrees += c.both ? 2 : 1;
    }
    reserve_growth<M, T>(m, points, 2 * points + degrees, points + degrees + vs.size());
    edit_progress progress(o.progress, cuts.size() + vs.size(), "truncate");
    for (const auto& c : cuts) {
        if (auto ok = progress.step(); !ok) return ok.error();
        const auto a = pos<M, T>(m, detail::euler::source<M, T>(m, c.h));
        const auto b = pos<M, T>(m, T::target(m, c.h));
        const auto s = split_edge<M, T>(m, c.h, lerp(a, b, c.t_from));
        if (!s) return s.error();
        out.vertices.push_back(s.value().vertex);
        if (!c.both || c.t_from + c.t_to >= 1.0) continue;  // meeting cuts share one point
        const auto s2 = split_edge<M, T>(m, s.value().second, lerp(a, b, 1.0 - c.t_to));
        if (!s2) return s2.error();
        out.vertices.push_back(s2.value().vertex);
    }
    for (auto v : vs) {
        if (auto ok = progress.step(); !ok) return ok.error();
        const auto f = replace_vertex_by_polygon<M, T>(m, v);
        if (!f) return f.error();
        out.faces.push_back(f.value());
    }
    return {};
}

}  // namespace detail::editing

/// Truncates the vertices in `vertices` (a range of vertex handles; duplicates count once):
/// each is replaced by a new face through cut points on its edges (see truncate_options for
/// where they go and what happens where two cuts meet). A vertex of degree d gives a d-gon;
/// the faces around it gain one vertex each. Per vertex: V + d - 1, E + d, F + 1; a point
/// shared by two meeting cuts saves one vertex and one edge.
///
/// Boundary vertices: the new face closes the corner, with one new boundary edge between the
/// two cut points on the boundary edges. A vertex of degree 2 has no room for a face: its
/// corner is cut off by a single new edge (V + 1, E + 1, F + 0).
///
/// Complexity O(sum of the degrees of the vertices) = O(V_adjacentV) per vertex, plus
/// O(k) expected for the selection of k vertices (hashing). Atomic: on any error, when an
/// allocation throws, or when options.progress cancels, the mesh is unchanged (see detail/transaction.hpp). Errors (mesh unchanged): errc::invalid_argument for options out
/// of range; errc::invalid_handle for a missing vertex; errc::topology for an isolated vertex
/// or a vertex of degree 1; errc::non_manifold for a vertex with several boundary gaps.
template <class M, class T = default_traits<M>, class R>
    requires truncatable_mesh<M, T> && range_of_handles<R, typename T::vertex_handle>
result<truncate_set_result<M, T>> truncate(M& mesh, const R& vertices, const truncate_options& options = {}) {
    namespace de = detail::editing;
    if (auto ok = de::check_truncate_options<M, T>(options, "truncate"); !ok) return ok.error();
    std::vector<typename T::vertex_handle> vs;
    de::index_set selected;
    for (auto v0 : vertices) {
        const typename T::vertex_handle v = v0;
        if (auto ok = de::check_corner_vertex<M, T>(mesh, v, "truncate"); !ok) return ok.error();
        const auto i = T::vertex_index(mesh, v);
        if (selected.contains(i)) continue;
        selected.insert(i);
        vs.push_back(v);
    }
    return de::transact<M, T>(mesh, [&]<class JT>() -> result<truncate_set_result<M, T>> {
        truncate_set_result<M, T> out;
        if (auto ok = de::truncate_checked<M, JT>(mesh, vs, selected, options, out); !ok) return ok.error();
        return out;
    });
}

/// Truncates one vertex of degree d (see the set overload): V + d - 1, E + d, F + 1.
/// Complexity O(V_adjacentV). Errors as for the set overload; the mesh is unchanged on error.
template <class M, class T = default_traits<M>>
    requires truncatable_mesh<M, T>
result<truncate_result<M, T>> truncate(M& mesh, typename T::vertex_handle vertex, const truncate_options& options = {}) {
    namespace de = detail::editing;
    if (auto ok = de::check_truncate_options<M, T>(options, "truncate"); !ok) return ok.error();
    if (auto ok = de::check_corner_vertex<M, T>(mesh, vertex, "truncate"); !ok) return ok.error();
    de::index_set selected;
    selected.insert(T::vertex_index(mesh, vertex));
    auto r = de::transact<M, T>(mesh, [&]<class JT>() -> result<truncate_set_result<M, T>> {
        truncate_set_result<M, T> set;
        if (auto ok = de::truncate_checked<M, JT>(mesh, std::vector<typename T::vertex_handle>{vertex}, selected, options, set); !ok)
            return ok.error();
        return set;
    });
    if (!r) return r.error();
    truncate_result<M, T> out{r.value().faces[0], {}};
    if (out.face != T::null_face()) {
        for (auto v : T::face_vertices(mesh, out.face)) out.vertices.push_back(v);
    } else {
        out.vertices = std::move(r.value().vertices);
    }
    return out;
}

/// Truncates every vertex of the mesh (cube -> truncated cube: 24 V, 36 E, 14 F with 8
/// triangles and 6 octagons at fraction 1/3; cuboctahedron at 1/2). Isolated vertices are
/// errors, as in the set overload. Complexity O(V + E) = O(E_all).
template <class M, class T = default_traits<M>>
    requires truncatable_mesh<M, T>
result<truncate_set_result<M, T>> truncate_all(M& mesh, const truncate_options& options = {}) {
    std::vector<typename T::vertex_handle> vs;
    for (auto v : T::vertices(mesh)) vs.push_back(v);
    return truncate<M, T>(mesh, vs, options);
}

}  // namespace hmira
