// hmira/algorithms/subdivision/detail/reserve.hpp
// How the subdivision schemes size a mesh for its final element counts before their first
// change: through the traits' optional reserve, or the model's own member of that shape.
#pragma once

#include <cstddef>

#include "../../../traits.hpp"

namespace hmira::detail::subdivision {

/// Room for this many vertices, edges and faces (index bounds), so that the levels never
/// reallocate the mesh: the traits' optional reserve (halfedge_mesh, winged_edge_mesh, OpenMesh, CGAL), else
/// the model's member reserve(vertices, edges, faces) (a model whose traits do not
/// forward it), else nothing. Only capacity changes.
template <class M, class T>
void reserve_room(M& mesh, std::size_t vertices, std::size_t edges, std::size_t faces) {
    if constexpr (requires { T::reserve(mesh, vertices, edges, faces); })
        T::reserve(mesh, vertices, edges, faces);
    else if constexpr (requires { mesh.reserve(vertices, edges, faces); } && requires { mesh.edge_index_bound(); })
        mesh.reserve(vertices, edges, faces);
}

}  // namespace hmira::detail::subdivision
