// hmira/traits.hpp
// The single customisation point (thesis ch. 9): mesh_traits<Mesh> tells the library a mesh's
// element types and the static operations on them. Specialise it for your mesh, or write a
// traits class of your own and pass it explicitly: `hmira::flip_normals<my_mesh, my_traits>(m)`.
#pragma once

#include <cstddef>
#include <type_traits>

#include "core/vec3.hpp"

namespace hmira {

/// Specialise this for your mesh type. The primary template is empty on purpose: a mesh
/// without traits satisfies no concept, and the compiler says which capability is missing.
///
/// A specialisation provides the types
///   vertex_handle, face_handle, scalar            (every mesh)
///   edge_handle, halfedge_handle                  (meshes with edges / halfedges)
/// and any of the static operations listed in hmira/concepts.hpp. Each operation takes the
/// mesh first. Only what an algorithm's concept asks for needs to be there.
template <class Mesh>
struct mesh_traits {
    /// Marks the empty primary template; a specialisation has no such member.
    static constexpr bool is_unspecialised_primary_template = true;
};

/// The default traits for a mesh type: mesh_traits with cv-ref removed.
template <class Mesh>
using default_traits = mesh_traits<std::remove_cvref_t<Mesh>>;

template <class Mesh, class Traits = default_traits<Mesh>>
using vertex_handle_t = typename Traits::vertex_handle;
template <class Mesh, class Traits = default_traits<Mesh>>
using face_handle_t = typename Traits::face_handle;
template <class Mesh, class Traits = default_traits<Mesh>>
using edge_handle_t = typename Traits::edge_handle;
template <class Mesh, class Traits = default_traits<Mesh>>
using halfedge_handle_t = typename Traits::halfedge_handle;
template <class Mesh, class Traits = default_traits<Mesh>>
using scalar_t = typename Traits::scalar;
template <class Mesh, class Traits = default_traits<Mesh>>
using point_t = vec3<typename Traits::scalar>;

}  // namespace hmira
