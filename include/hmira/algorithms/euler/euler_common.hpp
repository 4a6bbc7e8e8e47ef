// hmira/algorithms/euler/euler_common.hpp
// What every Euler operator needs: the capability concepts they are written against, the
// Euler-Poincare bookkeeping they document, and small helpers on the raw halfedge layer.
// Include hmira/algorithms/euler/euler.hpp for all operators at once.
#pragma once

#include <concepts>
#include <cstddef>
#include <ranges>
#include <string>

#include "../../concepts.hpp"
#include "../../core/result.hpp"

namespace hmira {

/// A mesh the Euler operators can edit: halfedge navigation plus the raw halfedge mutation
/// layer (set_next/set_face/..., new_edge, new_face, add_vertex, erase_*). halfedge_mesh,
/// winged_edge_mesh and the OpenMesh and CGAL interop models qualify; face_vertex_mesh has no
/// edges and does not.
///
/// How hmira reads Mantyla's model on a surface mesh. Mantyla's solids have faces everywhere;
/// a surface mesh has open boundaries. hmira counts each boundary loop (a loop of halfedges
/// whose face is null) as one face of the Euler-Poincare formula, and each isolated vertex as
/// one face too (Mantyla's makeV/MVFS creates a vertex *and* a face; a surface model has no
/// face without edges, so its boundary loop of no halfedges stands in). With R the number of
/// inner rings, S the shells and H the holes (genus):
///
///     V - E + (F_faces + B_boundary_loops + I_isolated_vertices) - R = 2 (S - H)
///
/// Boundary loops cannot hold inner rings, so the ring operators need a real face.
///
/// A triangles-only model (traits declaring `triangles_only`, such as OpenMesh's TriMesh) is
/// rejected: the operators create faces of any degree.
template <class M, class T = default_traits<M>>
concept euler_mutable_mesh = halfedge_mutable_mesh<M, T> && !requires { requires T::triangles_only; };

/// A mesh whose faces can hold inner rings (Mantyla's holes) that can be attached and
/// detached: the ring operators (make_face_kill_ring, kill_face_make_ring,
/// make_edge_kill_ring, kill_edge_make_ring) need it. OpenMesh and CGAL have no inner rings.
template <class M, class T = default_traits<M>>
concept euler_ring_mutable_mesh = euler_mutable_mesh<M, T> && inner_ring_mutable_mesh<M, T>;

namespace detail::euler {

/// Builds an operator's error out of line: `return refuse([&] { return fail(...); });`. The
/// message strings then live in a cold function, not in the operator, which stays small enough
/// to inline into its caller (with the strings inline, makeEF/killEF were called out of line
/// and paid a large stack frame per call: 1.09x CGAL's split_face/join_face).
template <class Build>
[[gnu::cold, gnu::noinline]] hmira::error refuse(Build build) {
    return build();
}

/// Index of an element for error messages, or -1 where the model has no indices.
template <class M, class T>
long long index_of(const M& m, typename T::halfedge_handle h) {
    if constexpr (halfedge_index_mesh<M, T>) {
        if (h == T::null_halfedge()) return -1;
        return static_cast<long long>(T::halfedge_index(m, h));
    } else {
        return -1;
    }
}
template <class M, class T>
long long index_of(const M& m, typename T::vertex_handle v) {
    if constexpr (vertex_index_mesh<M, T>)
        return static_cast<long long>(T::vertex_index(m, v));
    else
        return -1;
}
template <class M, class T>
long long index_of(const M& m, typename T::face_handle f) {
    if constexpr (face_index_mesh<M, T>) {
        if (f == T::null_face()) return -1;
        return static_cast<long long>(T::face_index(m, f));
    } else {
        return -1;
    }
}
template <class M, class T, class Handle>
std::string name(const char* kind, const M& m, Handle h) {
    const auto i = index_of<M, T>(m, h);
    // Appending, not `" " + std::to_string(i)`: that form trips GCC 12's false -Wrestrict
    // (GCC bug 105329) when inlined at -O3.
    std::string out(kind);
    out += ' ';
    if (i < 0)
        out += "(null)";
    else
        out += std::to_string(i);
    return out;
}

/// Whether the traits can tell that x was erased (optional query `T::is_removed(m, x)`:
/// hmira's deleted flags, OpenMesh's status, CGAL's is_removed) and say it was. A model
/// without the query cannot tell; passing it a deleted element stays undefined there.
template <class M, class T, class Handle>
bool known_removed(const M& m, Handle x) {
    if constexpr (removal_queryable_mesh<M, T, Handle>)
        return T::is_removed(m, x);
    else {
        (void)m;
        (void)x;
        return false;
    }
}

/// A handle the operator can work with: not null, where the model has indices in range, and
/// not erased where the model can tell (known_removed).
template <class M, class T>
bool usable(const M& m, typename T::halfedge_handle h) {
    if (h == T::null_halfedge()) return false;
    if constexpr (halfedge_index_mesh<M, T>)
        if (T::halfedge_index(m, h) >= T::halfedge_index_bound(m)) return false;
    return !known_removed<M, T>(m, h);
}
template <class M, class T>
bool usable(const M& m, typename T::vertex_handle v) {
    if constexpr (vertex_index_mesh<M, T>)
        if (T::vertex_index(m, v) >= T::vertex_index_bound(m)) return false;
    return !known_removed<M, T>(m, v);
}
template <class M, class T>
bool usable(const M& m, typename T::face_handle f) {
    if (f == T::null_face()) return false;
    if constexpr (face_index_mesh<M, T>)
        if (T::face_index(m, f) >= T::face_index_bound(m)) return false;
    return !known_removed<M, T>(m, f);
}

template <class M, class T>
typename T::vertex_handle source(const M& m, typename T::halfedge_handle h) {
    return T::target(m, T::opposite(m, h));
}

/// Whether f has any inner ring (always false on a model without rings).
template <class M, class T>
bool has_rings(const M& m, typename T::face_handle f) {
    if constexpr (inner_ring_mesh<M, T>)
        return !std::ranges::empty(T::inner_rings(m, f));
    else {
        (void)m;
        (void)f;
        return false;
    }
}

/// If `old_h` is the halfedge registered for one of f's inner rings, registers `new_h` (on
/// the same loop) instead. O(rings of f), plus the model's remove_inner_ring cost when it hits.
template <class M, class T>
void replace_ring_halfedge(M& m, typename T::face_handle f, typename T::halfedge_handle old_h,
                           typename T::halfedge_handle new_h) {
    if constexpr (inner_ring_mutable_mesh<M, T>) {
        if (f == T::null_face()) return;
        bool hit = false;
        for (auto r : T::inner_rings(m, f))
            if (typename T::halfedge_handle(r) == old_h) {
                hit = true;
                break;
            }
        if (!hit) return;
        T::remove_inner_ring(m, f, old_h);
        T::add_inner_ring(m, f, new_h);
    } else {
        (void)m;
        (void)f;
        (void)old_h;
        (void)new_h;
    }
}

/// Re-points v's stored outgoing halfedge when the edge of `removed` (leaving v) is about to
/// be deleted: always when the replacement is a boundary halfedge (models that store an
/// incoming boundary halfedge, like CGAL's, may refer to the edge without reading back as
/// `removed`), otherwise when v stores `removed` itself. O(1).
template <class M, class T>
void replace_vertex_halfedge(M& m, typename T::vertex_handle v, typename T::halfedge_handle removed,
                             typename T::halfedge_handle replacement) {
    if (T::face(m, replacement) == T::null_face() || T::vertex_halfedge(m, v) == removed)
        T::set_vertex_halfedge(m, v, replacement);
}

/// A vertex on the boundary must store a boundary outgoing halfedge (the navigation concept
/// promises it). If v's stored halfedge is not a boundary one, looks for one around v and
/// stores it. O(V_adjacentV) when it has to look, O(1) otherwise.
template <class M, class T>
void prefer_boundary_halfedge(M& m, typename T::vertex_handle v) {
    const auto start = T::vertex_halfedge(m, v);
    if (start == T::null_halfedge() || T::face(m, start) == T::null_face()) return;
    auto h = start;
    do {
        if (T::face(m, h) == T::null_face()) {
            T::set_vertex_halfedge(m, v, h);
            return;
        }
        h = T::next(m, T::opposite(m, h));
    } while (h != start);
}

}  // namespace detail::euler
}  // namespace hmira
