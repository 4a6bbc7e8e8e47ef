// hmira/concepts.hpp
// One small concept per capability a mesh can have (thesis ch. 10). Algorithms state the
// capabilities they need in a requires clause, so a mesh that lacks one is rejected at compile
// time by a message naming that capability (for example `vertex_adjacency_mesh`) and the
// missing traits operation (for example `T::adjacent_vertices(m, v)`).
//
// Every concept takes the mesh type M and a traits type T, which defaults to mesh_traits<M>.
// In the operation lists below, `m` is an `M&` (or `const M&` for queries), `v`, `f`, `e`, `h`
// are vertex, face, edge and halfedge handles, and `p` is a `vec3<T::scalar>`.
#pragma once

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <ranges>
#include <span>

#include "core/result.hpp"
#include "core/vec3.hpp"
#include "traits.hpp"

namespace hmira {

/// A forward range whose elements convert to Handle. Views returned by traits must own or
/// reference the mesh, never a temporary, so they stay valid while the mesh is unchanged.
template <class R, class Handle>
concept range_of_handles = std::ranges::forward_range<R> && std::convertible_to<std::ranges::range_value_t<R>, Handle>;

// ---------------------------------------------------------------------------------------------
// Types

/// T names the element types: `vertex_handle`, `face_handle` (both regular: copyable,
/// default-constructible, equality-comparable) and the coordinate type `scalar`.
template <class M, class T = default_traits<M>>
concept mesh_element_types =
    requires {
        typename T::vertex_handle;
        typename T::face_handle;
        typename T::scalar;
    } && std::regular<typename T::vertex_handle> && std::regular<typename T::face_handle> &&
    std::floating_point<typename T::scalar>;

// ---------------------------------------------------------------------------------------------
// Whole-structure getters (thesis table 4.4: O(V_all), O(F_all), O(E_all))

/// `T::vertices(m)` ranges over the live vertices; `T::vertex_count(m)` counts them.
template <class M, class T = default_traits<M>>
concept vertex_list_mesh = mesh_element_types<M, T> && requires(const M& m) {
    { T::vertices(m) } -> range_of_handles<typename T::vertex_handle>;
    { T::vertex_count(m) } -> std::convertible_to<std::size_t>;
};

/// `T::faces(m)` ranges over the live faces; `T::face_count(m)` counts them.
template <class M, class T = default_traits<M>>
concept face_list_mesh = mesh_element_types<M, T> && requires(const M& m) {
    { T::faces(m) } -> range_of_handles<typename T::face_handle>;
    { T::face_count(m) } -> std::convertible_to<std::size_t>;
};

/// `T::edge_handle` exists (regular); `T::edges(m)` ranges over the edges, `T::edge_count(m)`
/// counts them, and `T::edge_vertices(m, e)` gives the two end vertices as something with
/// `[0]` and `[1]` (for example std::array).
template <class M, class T = default_traits<M>>
concept edge_list_mesh = mesh_element_types<M, T> && requires { typename T::edge_handle; } &&
                         std::regular<typename T::edge_handle> && requires(const M& m, typename T::edge_handle e) {
                             { T::edges(m) } -> range_of_handles<typename T::edge_handle>;
                             { T::edge_count(m) } -> std::convertible_to<std::size_t>;
                             { T::edge_vertices(m, e)[0] } -> std::convertible_to<typename T::vertex_handle>;
                             { T::edge_vertices(m, e)[1] } -> std::convertible_to<typename T::vertex_handle>;
                         };

// ---------------------------------------------------------------------------------------------
// Dense indices: algorithms keep per-element scratch data in plain arrays. An index lies in
// [0, bound); deleted elements may leave gaps below the bound.

/// `T::vertex_index(m, v)` and `T::vertex_index_bound(m)`.
template <class M, class T = default_traits<M>>
concept vertex_index_mesh = vertex_list_mesh<M, T> && requires(const M& m, typename T::vertex_handle v) {
    { T::vertex_index(m, v) } -> std::convertible_to<std::size_t>;
    { T::vertex_index_bound(m) } -> std::convertible_to<std::size_t>;
};

/// `T::face_index(m, f)` and `T::face_index_bound(m)`.
template <class M, class T = default_traits<M>>
concept face_index_mesh = face_list_mesh<M, T> && requires(const M& m, typename T::face_handle f) {
    { T::face_index(m, f) } -> std::convertible_to<std::size_t>;
    { T::face_index_bound(m) } -> std::convertible_to<std::size_t>;
};

/// `T::edge_index(m, e)` and `T::edge_index_bound(m)`.
template <class M, class T = default_traits<M>>
concept edge_index_mesh = edge_list_mesh<M, T> && requires(const M& m, typename T::edge_handle e) {
    { T::edge_index(m, e) } -> std::convertible_to<std::size_t>;
    { T::edge_index_bound(m) } -> std::convertible_to<std::size_t>;
};

// ---------------------------------------------------------------------------------------------
// Local getters (thesis table 4.3)

/// `T::face_vertices(m, f)` ranges over the vertices of f's outer loop in winding order
/// (counter-clockwise seen from outside). Cost: O(V_consistF) natively.
template <class M, class T = default_traits<M>>
concept face_vertex_range_mesh = face_list_mesh<M, T> && requires(const M& m, typename T::face_handle f) {
    { T::face_vertices(m, f) } -> range_of_handles<typename T::vertex_handle>;
};

/// `T::position(m, v)` returns the position, convertible to vec3<T::scalar>.
template <class M, class T = default_traits<M>>
concept positioned_mesh = vertex_list_mesh<M, T> && requires(const M& m, typename T::vertex_handle v) {
    { T::position(m, v) } -> std::convertible_to<vec3<typename T::scalar>>;
};

/// `T::set_position(m, v, p)` moves a vertex.
template <class M, class T = default_traits<M>>
concept position_mutable_mesh =
    positioned_mesh<M, T> &&
    requires(M& m, typename T::vertex_handle v, vec3<typename T::scalar> p) { T::set_position(m, v, p); };

/// `T::adjacent_vertices(m, v)`: the vertices sharing an edge with v. Allowed: O(V_adjacentV).
template <class M, class T = default_traits<M>>
concept vertex_adjacency_mesh = vertex_list_mesh<M, T> && requires(const M& m, typename T::vertex_handle v) {
    { T::adjacent_vertices(m, v) } -> range_of_handles<typename T::vertex_handle>;
};

/// `T::vertex_faces(m, v)`: the faces around v. Allowed: O(F_adjacentV).
template <class M, class T = default_traits<M>>
concept vertex_face_adjacency_mesh =
    vertex_list_mesh<M, T> && face_list_mesh<M, T> && requires(const M& m, typename T::vertex_handle v) {
        { T::vertex_faces(m, v) } -> range_of_handles<typename T::face_handle>;
    };

/// `T::vertex_edges(m, v)`: the edges incident to v. Allowed: O(E_adjacentV).
template <class M, class T = default_traits<M>>
concept vertex_edge_adjacency_mesh = edge_list_mesh<M, T> && requires(const M& m, typename T::vertex_handle v) {
    { T::vertex_edges(m, v) } -> range_of_handles<typename T::edge_handle>;
};

/// `T::adjacent_faces(m, f)`: the faces sharing an edge with f. Allowed: O(F_adjacentF).
template <class M, class T = default_traits<M>>
concept face_adjacency_mesh = face_list_mesh<M, T> && requires(const M& m, typename T::face_handle f) {
    { T::adjacent_faces(m, f) } -> range_of_handles<typename T::face_handle>;
};

/// Halfedge navigation (thesis 1.2.3). T names `halfedge_handle`, and provides, all O(1):
///   next(m,h), prev(m,h), opposite(m,h), target(m,h) -> vertex, face(m,h) -> face or
///   T::null_face() on a boundary halfedge, edge(m,h), edge_halfedge(m,e),
///   vertex_halfedge(m,v) -> an outgoing halfedge (a boundary one if v is on the boundary,
///   T::null_halfedge() if v is isolated), face_halfedge(m,f) -> a halfedge of f's outer loop,
///   T::halfedges(m) over all halfedges.
template <class M, class T = default_traits<M>>
concept halfedge_navigable_mesh =
    vertex_list_mesh<M, T> && face_list_mesh<M, T> && edge_list_mesh<M, T> &&
    requires { typename T::halfedge_handle; } && std::regular<typename T::halfedge_handle> &&
    requires(const M& m, typename T::halfedge_handle h, typename T::vertex_handle v, typename T::face_handle f,
             typename T::edge_handle e) {
        { T::next(m, h) } -> std::convertible_to<typename T::halfedge_handle>;
        { T::prev(m, h) } -> std::convertible_to<typename T::halfedge_handle>;
        { T::opposite(m, h) } -> std::convertible_to<typename T::halfedge_handle>;
        { T::target(m, h) } -> std::convertible_to<typename T::vertex_handle>;
        { T::face(m, h) } -> std::convertible_to<typename T::face_handle>;
        { T::edge(m, h) } -> std::convertible_to<typename T::edge_handle>;
        { T::edge_halfedge(m, e) } -> std::convertible_to<typename T::halfedge_handle>;
        { T::vertex_halfedge(m, v) } -> std::convertible_to<typename T::halfedge_handle>;
        { T::face_halfedge(m, f) } -> std::convertible_to<typename T::halfedge_handle>;
        { T::halfedges(m) } -> range_of_handles<typename T::halfedge_handle>;
        { T::null_face() } -> std::convertible_to<typename T::face_handle>;
        { T::null_halfedge() } -> std::convertible_to<typename T::halfedge_handle>;
    };

/// `T::halfedge_index(m, h)` and `T::halfedge_index_bound(m)`.
template <class M, class T = default_traits<M>>
concept halfedge_index_mesh = halfedge_navigable_mesh<M, T> && requires(const M& m, typename T::halfedge_handle h) {
    { T::halfedge_index(m, h) } -> std::convertible_to<std::size_t>;
    { T::halfedge_index_bound(m) } -> std::convertible_to<std::size_t>;
};

/// Faces with holes (Mantyla's inner rings, thesis 1.1.5): `T::inner_rings(m, f)` ranges over
/// one halfedge of each inner ring of f. Face -> vertices (face_vertex_range_mesh) still gives
/// only the outer loop.
template <class M, class T = default_traits<M>>
concept inner_ring_mesh = halfedge_navigable_mesh<M, T> && requires(const M& m, typename T::face_handle f) {
    { T::inner_rings(m, f) } -> range_of_handles<typename T::halfedge_handle>;
};

// ---------------------------------------------------------------------------------------------
// Mutation

/// Building a mesh face by face: `T::add_vertex(m, p)` returns the new vertex, and
/// `T::add_face(m, vs)` with `vs` a std::span<const vertex_handle> returns result<face_handle>
/// (an error, and the mesh unchanged, when the face cannot be added).
template <class M, class T = default_traits<M>>
concept mesh_builder = mesh_element_types<M, T> &&
                       requires(M& m, vec3<typename T::scalar> p, std::span<const typename T::vertex_handle> vs) {
                           { T::add_vertex(m, p) } -> std::convertible_to<typename T::vertex_handle>;
                           { T::add_face(m, vs) } -> std::same_as<result<typename T::face_handle>>;
                       };

/// A mesh that may hold faces of any degree. A triangle-only model declares
/// `static constexpr bool triangles_only = true;` in its traits and is rejected by the
/// algorithms that create polygons.
template <class M, class T = default_traits<M>>
concept polygon_mesh_builder = mesh_builder<M, T> && !requires { requires T::triangles_only; };

/// `T::reverse_face(m, f)` reverses one face's vertex order in place. Only a model without
/// shared connectivity (face-vertex) can do this face by face.
template <class M, class T = default_traits<M>>
concept face_reversible_mesh =
    face_list_mesh<M, T> && requires(M& m, typename T::face_handle f) { T::reverse_face(m, f); };

/// The low-level halfedge mutation that Euler operators and orientation changes are written
/// against; none of them keeps the mesh consistent by itself:
///   set_next(m,h,n) (and prev(n) = h), set_target(m,h,v), set_face(m,h,f),
///   set_vertex_halfedge(m,v,h), set_face_halfedge(m,f,h),
///   new_edge(m, from, to) -> halfedge from->to (its opposite runs to->from, links unset),
///   new_face(m) -> face, add_vertex(m, p) -> vertex,
///   erase_edge(m,e), erase_face(m,f), erase_vertex(m,v) (mark deleted, no re-linking; a
///   model may reuse one of the element's links for its free list, as halfedge_mesh and CGAL
///   do, so read an element's links before erasing it).
template <class M, class T = default_traits<M>>
concept halfedge_mutable_mesh =
    halfedge_navigable_mesh<M, T> &&
    requires(M& m, typename T::halfedge_handle h, typename T::vertex_handle v, typename T::face_handle f,
             typename T::edge_handle e, vec3<typename T::scalar> p) {
        T::set_next(m, h, h);
        T::set_target(m, h, v);
        T::set_face(m, h, f);
        T::set_vertex_halfedge(m, v, h);
        T::set_face_halfedge(m, f, h);
        { T::new_edge(m, v, v) } -> std::convertible_to<typename T::halfedge_handle>;
        { T::new_face(m) } -> std::convertible_to<typename T::face_handle>;
        { T::add_vertex(m, p) } -> std::convertible_to<typename T::vertex_handle>;
        T::erase_edge(m, e);
        T::erase_face(m, f);
        T::erase_vertex(m, v);
    };

/// Inner rings that can be attached and detached: `T::add_inner_ring(m, f, h)` and
/// `T::remove_inner_ring(m, f, h)`.
template <class M, class T = default_traits<M>>
concept inner_ring_mutable_mesh = inner_ring_mesh<M, T> && halfedge_mutable_mesh<M, T> &&
                                  requires(M& m, typename T::face_handle f, typename T::halfedge_handle h) {
                                      T::add_inner_ring(m, f, h);
                                      T::remove_inner_ring(m, f, h);
                                  };

/// `T::remove_face(m, f)` removes one face and keeps its vertices, returning result<void>
/// (an error, and the mesh unchanged, for a face that does not exist). The way a model
/// without edges (face-vertex) removes faces; halfedge models unlink them through
/// halfedge_mutable_mesh instead.
template <class M, class T = default_traits<M>>
concept face_removal_mesh = face_list_mesh<M, T> && requires(M& m, typename T::face_handle f) {
    { T::remove_face(m, f) } -> std::same_as<result<void>>;
};

/// `T::remove_vertex(m, v)` removes a vertex and every face that uses it, returning
/// result<void> (an error, and the mesh unchanged, for a vertex that does not exist).
template <class M, class T = default_traits<M>>
concept vertex_removal_mesh =
    vertex_list_mesh<M, T> && face_list_mesh<M, T> && requires(M& m, typename T::vertex_handle v) {
        { T::remove_vertex(m, v) } -> std::same_as<result<void>>;
    };

/// `T::change_count(m)` grows on every change of connectivity, so that a cache built from
/// the mesh (an indexed adapter) can tell it has gone stale.
template <class M, class T = default_traits<M>>
concept change_counted_mesh = requires(const M& m) {
    { T::change_count(m) } -> std::convertible_to<std::uint64_t>;
};

// ---------------------------------------------------------------------------------------------
// Optional hooks: operations a model's traits may offer so that an algorithm can take a faster
// or cheaper path. No algorithm requires one; each tests the hook's concept and otherwise takes
// its general path, with the same result.

/// The optional hooks, for a traits class to list the ones it means to provide:
///
///     static constexpr hmira::hook hooks[] = {hmira::hook::reserve, hmira::hook::reverse_orientation};
///
/// Every listed hook is then checked wherever an algorithm looks for it: a hook whose name or
/// parameters do not match (`reserv` for `reserve`) stops the build with a static_assert that
/// names it. Without the list, such a hook is simply not found and the general path runs.
enum class hook {
    reserve,                  ///< reservable_mesh
    bulk_growth,              ///< bulk_growable_mesh
    reverse_orientation,      ///< orientation_reversible_mesh
    prepare_erase,            ///< erase_preparing_mesh
    remove_vertices,          ///< bulk_vertex_removal_mesh
    restore_vertex_halfedge,  ///< vertex_halfedge_restorable_mesh
    is_removed,               ///< removal_queryable_mesh
};

namespace detail {

/// Whether T lists `h` in its `hooks` array.
template <class T>
consteval bool declares_hook(hook h) {
    if constexpr (requires { T::hooks; }) {
        for (hook listed : T::hooks)
            if (listed == h) return true;
    }
    return false;
}

/// `found`, after stopping the build when T lists hook H but its operation was not found.
template <class T, hook H, bool found>
consteval bool checked_hook() {
    constexpr bool ok = found || !declares_hook<T>(H);
    if constexpr (H == hook::reserve)
        static_assert(ok, "the traits list hook::reserve, but T::reserve(m, vertices, edges, faces) does not match");
    else if constexpr (H == hook::bulk_growth)
        static_assert(ok,
                      "the traits list hook::bulk_growth, but T::resize(m, vertices, edges, faces), "
                      "T::vertex_at(m, i), T::edge_at(m, i) or T::face_at(m, i) does not match");
    else if constexpr (H == hook::reverse_orientation)
        static_assert(ok, "the traits list hook::reverse_orientation, but T::reverse_orientation(m) does not match");
    else if constexpr (H == hook::prepare_erase)
        static_assert(ok, "the traits list hook::prepare_erase, but T::prepare_erase(m) does not match");
    else if constexpr (H == hook::remove_vertices)
        static_assert(ok, "the traits list hook::remove_vertices, but T::remove_vertices(m, vertices) does not match");
    else if constexpr (H == hook::restore_vertex_halfedge)
        static_assert(ok,
                      "the traits list hook::restore_vertex_halfedge, but T::stored_vertex_halfedge(m, v) or "
                      "T::restore_vertex_halfedge(m, v, h) does not match");
    else if constexpr (H == hook::is_removed)
        static_assert(ok, "the traits list hook::is_removed, but T::is_removed(m, x) does not match");
    return found;
}

}  // namespace detail

/// `T::reserve(m, vertices, edges, faces)` makes room for those index bounds, so that a
/// growing algorithm never reallocates half way. Only capacity changes.
template <class M, class T = default_traits<M>>
concept reservable_mesh =
    detail::checked_hook<T, hook::reserve, (requires(M& m, std::size_t n) { T::reserve(m, n, n, n); })>();

/// `T::resize(m, vertices, edges, faces)` appends unlinked elements up to those index bounds,
/// and `T::vertex_at(m, i)`, `T::edge_at(m, i)`, `T::face_at(m, i)` name an element by its
/// index: new elements in blocks instead of one traits add at a time (OpenMesh, Surface_mesh).
template <class M, class T = default_traits<M>>
concept bulk_growable_mesh = detail::checked_hook<T, hook::bulk_growth, (requires(M& m, const M& cm, std::size_t n) {
                                                      T::resize(m, n, n, n);
                                                      {
                                                          T::vertex_at(cm, n)
                                                      } -> std::same_as<typename T::vertex_handle>;
                                                      { T::edge_at(cm, n) } -> std::same_as<typename T::edge_handle>;
                                                      { T::face_at(cm, n) } -> std::same_as<typename T::face_handle>;
                                                  })>();

/// `T::reverse_orientation(m)` reverses every face in one pass over the model's own storage.
template <class M, class T = default_traits<M>>
concept orientation_reversible_mesh =
    detail::checked_hook<T, hook::reverse_orientation, (requires(M& m) { T::reverse_orientation(m); })>();

/// `T::prepare_erase(m)` readies the model for erasures that a rollback may undo (OpenMesh
/// requests its status flags once, before the first change, instead of inside the edit).
template <class M, class T = default_traits<M>>
concept erase_preparing_mesh =
    detail::checked_hook<T, hook::prepare_erase, (requires(M& m) { T::prepare_erase(m); })>();

/// `T::remove_vertices(m, vertices)`, with `vertices` a std::span<const vertex_handle>,
/// removes them all in one pass, returning result<void>.
template <class M, class T = default_traits<M>>
concept bulk_vertex_removal_mesh =
    detail::checked_hook<T, hook::remove_vertices, (requires(M& m, std::span<const typename T::vertex_handle> vs) {
                             { T::remove_vertices(m, vs) } -> std::same_as<result<void>>;
                         })>();

/// `T::stored_vertex_halfedge(m, v)` reads the halfedge the model stores for v (which may
/// differ from vertex_halfedge: CGAL keeps an incoming one) and
/// `T::restore_vertex_halfedge(m, v, h)` writes such a value back, so a rollback restores the
/// model's storage exactly.
template <class M, class T = default_traits<M>>
concept vertex_halfedge_restorable_mesh =
    detail::checked_hook<T, hook::restore_vertex_halfedge,
                         (requires(M& m, typename T::vertex_handle v, typename T::halfedge_handle h) {
                             { T::stored_vertex_halfedge(m, v) } -> std::convertible_to<typename T::halfedge_handle>;
                             T::restore_vertex_halfedge(m, v, h);
                         })>();

/// `T::is_removed(m, x)` tells whether the element x (a handle of type Handle) was erased.
template <class M, class T, class Handle>
concept removal_queryable_mesh = detail::checked_hook<T, hook::is_removed, (requires(const M& m, Handle x) {
                                                          { T::is_removed(m, x) } -> std::convertible_to<bool>;
                                                      })>();

/// A triangle-only model: its traits declare `static constexpr bool triangles_only = true;`.
template <class M, class T = default_traits<M>>
concept triangle_only_mesh = requires { requires T::triangles_only; };

/// Test hook of the fault-injection suites: `T::fail_inner_call()` returns true to make the
/// next inner operator call of an edit fail as if its precondition had not held. No real
/// model has it.
template <class T>
concept fault_injecting_traits = requires {
    { T::fail_inner_call() } -> std::convertible_to<bool>;
};

}  // namespace hmira
