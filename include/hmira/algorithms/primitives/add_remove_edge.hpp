// hmira/algorithms/primitives/add_remove_edge.hpp
// Primitive add/remove of an edge (thesis 4.2): connect two vertices by a wire edge (no face
// on either side yet), or remove an edge together with the faces on its sides.
#pragma once

#include <vector>

#include "primitives_common.hpp"

namespace hmira {

/// Adds an edge between `from` and `to` with no face on either side, and returns its halfedge
/// from -> to. Each end must be isolated or on the boundary; the edge goes into the boundary
/// gap the vertex stores (vertex_halfedge), so at a vertex with several gaps name the corner
/// with make_edge_vertex / make_edge_face instead. If both ends are on one boundary loop, that
/// loop falls in two. A wire edge makes no face, so triangle-only models (OpenMesh's TriMesh)
/// can take it: only the raw halfedge layer is needed.
///
/// Complexity O(V_adjacentV) (thesis: O(V_adjacentV)): the ends are searched for an existing
/// edge. Errors (mesh unchanged): errc::invalid_handle; errc::topology when from == to, when
/// the edge exists already, or when an end is an interior vertex (no boundary gap to put it in).
template <class M, class T = default_traits<M>>
    requires halfedge_mutable_mesh<M, T>
result<typename T::halfedge_handle> add_edge(M& mesh, typename T::vertex_handle from, typename T::vertex_handle to) {
    namespace de = detail::euler;
    for (auto v : {from, to})
        if (!de::usable<M, T>(mesh, v))
            return fail(errc::invalid_handle, "add_edge: " + de::name<M, T>("vertex", mesh, v) + " does not exist",
                        de::index_of<M, T>(mesh, v));
    if (from == to)
        return fail(errc::topology,
                    "add_edge: an edge from " + de::name<M, T>("vertex", mesh, from) + " to itself would be a loop",
                    de::index_of<M, T>(mesh, from));
    const auto gf = T::vertex_halfedge(mesh, from), gt = T::vertex_halfedge(mesh, to);
    for (auto [v, g] : {std::pair{from, gf}, std::pair{to, gt}})
        if (g != T::null_halfedge() && T::face(mesh, g) != T::null_face())
            return fail(errc::topology,
                        "add_edge: " + de::name<M, T>("vertex", mesh, v) +
                            " is interior (surrounded by faces); an edge there would be non-manifold",
                        de::index_of<M, T>(mesh, v));
    if (gf != T::null_halfedge()) {
        auto h = gf;
        do {
            if (T::target(mesh, h) == to)
                return fail(errc::topology,
                            "add_edge: " + de::name<M, T>("vertex", mesh, from) + " and " +
                                de::name<M, T>("vertex", mesh, to) + " are joined already",
                            de::index_of<M, T>(mesh, from));
            h = T::next(mesh, T::opposite(mesh, h));
        } while (h != gf);
    }
    const auto x = T::new_edge(mesh, from, to);
    const auto ox = T::opposite(mesh, x);
    T::set_face(mesh, x, T::null_face());
    T::set_face(mesh, ox, T::null_face());
    // Work out both ends' boundary neighbours before linking, as linking one end moves them.
    const auto pf = gf == T::null_halfedge() ? ox : T::prev(mesh, gf);
    const auto pt = gt == T::null_halfedge() ? x : T::prev(mesh, gt);
    T::set_next(mesh, pf, x);
    T::set_next(mesh, ox, gf == T::null_halfedge() ? x : gf);
    T::set_next(mesh, pt, ox);
    T::set_next(mesh, x, gt == T::null_halfedge() ? ox : gt);
    if (gf == T::null_halfedge()) T::set_vertex_halfedge(mesh, from, x);
    if (gt == T::null_halfedge()) T::set_vertex_halfedge(mesh, to, ox);
    return x;
}

/// Removes the edge of `halfedge` and the faces on its sides; then, as `options` ask, the
/// other edges of those faces left with no face, and the vertices left with no edge (the
/// edge's own ends included). Returns what was removed.
///
/// Removing never makes a polygon, so triangle-only models can too.
///
/// Complexity O(1) for an edge without faces (thesis: O(1)), plus O(face degree) for each
/// face on its sides. Errors: errc::invalid_handle (mesh unchanged).
template <class M, class T = default_traits<M>>
    requires halfedge_mutable_mesh<M, T>
result<removal_report> remove_edge(M& mesh, typename T::halfedge_handle halfedge, const remove_options& options = {}) {
    namespace de = detail::euler;
    namespace dp = detail::primitives;
    if (!de::usable<M, T>(mesh, halfedge))
        return fail(errc::invalid_handle,
                    "remove_edge: " + de::name<M, T>("halfedge", mesh, halfedge) + " does not exist",
                    de::index_of<M, T>(mesh, halfedge));
    removal_report report;
    std::vector<typename T::halfedge_handle> touched{halfedge};
    const auto f = T::face(mesh, halfedge), g = T::face(mesh, T::opposite(mesh, halfedge));
    if (f != T::null_face()) {
        dp::strip_face<M, T>(mesh, f, touched);
        ++report.faces;
    }
    if (g != T::null_face() && g != f) {
        dp::strip_face<M, T>(mesh, g, touched);
        ++report.faces;
    }
    if (!options.remove_wire_edges) touched.resize(1);
    dp::remove_wires<M, T>(mesh, touched, options, report);
    return report;
}

}  // namespace hmira
