// hmira/algorithms/primitives/primitives_common.hpp
// Shared pieces of the add/remove primitives (thesis 4.2): the concepts saying which models
// can honour each removal, the options and reports, and the routines the removals end in
// (taking out edges with no face left, and vertices with nothing left).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <ranges>
#include <vector>

#include "../euler/euler_common.hpp"

namespace hmira {

/// A mesh remove_face can honour. Either the raw halfedge layer (halfedge_mutable_mesh, the
/// face is unlinked and the edges and vertices it leaves bare go too), triangle-only models
/// included, since removing a face never makes a polygon; or a model whose traits remove faces
/// and vertices themselves (face_removal_mesh and vertex_removal_mesh, as face_vertex_mesh),
/// with face -> vertex ranges and vertex and face indices (to check the face exists and find
/// the vertices a removal leaves unused).
template <class M, class T = default_traits<M>>
concept face_erasable_mesh =
    halfedge_mutable_mesh<M, T> || (face_removal_mesh<M, T> && vertex_removal_mesh<M, T> &&
                                    face_vertex_range_mesh<M, T> && vertex_index_mesh<M, T> && face_index_mesh<M, T>);

/// A mesh remove_vertex can honour: the raw halfedge layer (triangle-only models included), or
/// traits that remove a vertex with its faces (vertex_removal_mesh, as face_vertex_mesh) plus
/// face -> vertex ranges and vertex indices.
template <class M, class T = default_traits<M>>
concept vertex_erasable_mesh = halfedge_mutable_mesh<M, T> ||
                               (vertex_removal_mesh<M, T> && face_vertex_range_mesh<M, T> && vertex_index_mesh<M, T>);

/// What a removal should also clean up. Removing faces can leave edges with no face on either
/// side (wire edges) and vertices with no edge; by default both go too, as a surface mesh
/// expects, so that a strict validate() still passes. On a model without edges
/// (face_vertex_mesh) there are no wire edges, and "no edge" means "used by no face".
struct remove_options {
    bool remove_wire_edges = true;         ///< also remove edges left with no face on either side
    bool remove_isolated_vertices = true;  ///< also remove vertices left with no edge
};

/// What a removal took out.
struct removal_report {
    /// How many faces, edges and vertices were removed.
    ///@{
    std::size_t faces = 0, edges = 0, vertices = 0;
    ///@}
};

namespace detail::primitives {

/// Makes f's loops (outer and inner rings) boundary, unregisters its rings, erases f, and
/// appends the loops' halfedges to `touched`. O(face degree).
template <class M, class T>
void strip_face(M& m, typename T::face_handle f, std::vector<typename T::halfedge_handle>& touched) {
    std::vector<typename T::halfedge_handle> starts{T::face_halfedge(m, f)};
    if constexpr (inner_ring_mutable_mesh<M, T>) {
        for (auto r : T::inner_rings(m, f)) starts.push_back(r);
        for (std::size_t i = 1; i < starts.size(); ++i) T::remove_inner_ring(m, f, starts[i]);
    }
    const std::size_t first = touched.size();
    for (auto s : starts) {
        auto x = s;
        do {
            T::set_face(m, x, T::null_face());
            touched.push_back(x);
            x = T::next(m, x);
        } while (x != s);
    }
    // Every vertex of the face is on the boundary now and must store a boundary halfedge.
    for (std::size_t i = first; i < touched.size(); ++i) {
        const auto v = detail::euler::source<M, T>(m, touched[i]);
        if (T::face(m, T::vertex_halfedge(m, v)) != T::null_face()) T::set_vertex_halfedge(m, v, touched[i]);
    }
    T::erase_face(m, f);
}

/// Removes the wire edge of x (no face on either side), re-linking the boundary loops
/// around it. Returns the ends left isolated (null where an end still has edges). O(1).
template <class M, class T>
std::pair<typename T::vertex_handle, typename T::vertex_handle> unlink_wire(M& m, typename T::halfedge_handle x) {
    using V = typename T::vertex_handle;
    const auto ox = T::opposite(m, x);
    const auto u = T::target(m, ox), w = T::target(m, x);
    const auto px = T::prev(m, x), nx = T::next(m, x), pox = T::prev(m, ox), nox = T::next(m, ox);
    const bool u_alone = px == ox, w_alone = nx == ox;
    if (!u_alone) T::set_next(m, px, nox);
    if (!w_alone) T::set_next(m, pox, nx);
    // Unconditionally: the replacements are boundary halfedges, and a model may refer to the
    // dying edge without reading back as x (CGAL stores an incoming halfedge).
    T::set_vertex_halfedge(m, u, u_alone ? T::null_halfedge() : nox);
    T::set_vertex_halfedge(m, w, w_alone ? T::null_halfedge() : nx);
    T::erase_edge(m, T::edge(m, x));
    return {u_alone ? u : V(), w_alone ? w : V()};
}

/// Removes the edges among `candidates` that have no face left on either side (each once),
/// and, if `options` ask, the vertices this leaves isolated (except `keep_vertex_out`).
/// O(candidates x removed edges); candidates are the sides of a few faces.
template <class M, class T>
void remove_wires(M& m, const std::vector<typename T::halfedge_handle>& candidates, const remove_options& options,
                  removal_report& report, typename T::vertex_handle keep_vertex_out = typename T::vertex_handle()) {
    std::vector<typename T::edge_handle> gone;
    for (auto x : candidates) {
        const auto e = T::edge(m, x);
        if (std::find(gone.begin(), gone.end(), e) != gone.end()) continue;
        if (T::face(m, x) != T::null_face() || T::face(m, T::opposite(m, x)) != T::null_face()) continue;
        const auto [a, b] = unlink_wire<M, T>(m, x);
        gone.push_back(e);
        ++report.edges;
        if (!options.remove_isolated_vertices) continue;
        for (auto v : {a, b})
            if (v != typename T::vertex_handle() && v != keep_vertex_out) {
                T::erase_vertex(m, v);
                ++report.vertices;
            }
    }
}

/// On a model whose traits remove elements (face_vertex_mesh): removes the vertices among
/// `candidates` that no face uses any more (each once), except `keep_vertex_out`. With
/// vertex -> face adjacency that is O(candidates x F_adjacentV); without it every face is
/// scanned once, O(F_all x face degree x log candidates); plus the model's remove_vertex for
/// each vertex removed (O(F_all) on face_vertex_mesh, which keeps no vertex -> face links).
template <class M, class T>
result<void> remove_unused_vertices(M& m, std::vector<typename T::vertex_handle> candidates, removal_report& report,
                                    typename T::vertex_handle keep_vertex_out = typename T::vertex_handle()) {
    auto by_index = [&m](auto a, auto b) { return T::vertex_index(m, a) < T::vertex_index(m, b); };
    std::sort(candidates.begin(), candidates.end(), by_index);
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    std::erase(candidates, keep_vertex_out);
    std::vector<std::uint8_t> used(candidates.size(), 0);
    if constexpr (vertex_face_adjacency_mesh<M, T>) {
        for (std::size_t i = 0; i < candidates.size(); ++i)
            used[i] = !std::ranges::empty(T::vertex_faces(m, candidates[i]));
    } else {
        for (auto f : T::faces(m))
            for (auto v : T::face_vertices(m, f)) {
                const auto at = std::lower_bound(candidates.begin(), candidates.end(), v, by_index);
                if (at != candidates.end() && *at == v) used[static_cast<std::size_t>(at - candidates.begin())] = 1;
            }
    }
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        if (used[i]) continue;
        // Cannot fail (a live vertex of a face just removed); passed on rather than dropped.
        if (auto r = T::remove_vertex(m, candidates[i]); !r) return r;
        ++report.vertices;
    }
    return {};
}

}  // namespace detail::primitives
}  // namespace hmira
