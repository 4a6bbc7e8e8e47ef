// hmira/algorithms/subdivision/detail/reserve.hpp
// How the subdivision schemes size a mesh for its final element counts before their first
// change: through the traits' optional reserve, or the model's own member of that shape.
#pragma once

#include <cstddef>

#include "../../../concepts.hpp"
#include "../../../traits.hpp"

namespace hmira::detail::subdivision {

/// Room for this many vertices, edges and faces (index bounds), so that the levels never
/// reallocate the mesh: the traits' optional reserve (halfedge_mesh, winged_edge_mesh, OpenMesh, CGAL), else
/// the model's member reserve(vertices, edges, faces) (a model whose traits do not
/// forward it), else nothing. Only capacity changes.
template <class M, class T>
void reserve_room(M& mesh, std::size_t vertices, std::size_t edges, std::size_t faces) {
    if constexpr (reservable_mesh<M, T>)
        T::reserve(mesh, vertices, edges, faces);
    else if constexpr (
        requires { mesh.reserve(vertices, edges, faces); } && requires { mesh.edge_index_bound(); })
        mesh.reserve(vertices, edges, faces);
}

/// While it lives, a model that reuses deleted slots appends every new element instead:
/// halfedge_mesh through set_slot_reuse, CGAL's Surface_mesh (which refills removed elements'
/// slots while it holds garbage) through set_recycle_garbage. The schemes tell a level's new
/// vertices from its old ones by index (at or above the index bound the level began with),
/// which a vertex placed in a freed slot below that bound would break. Restores the setting.
template <class M>
class appending_guard {
public:
    explicit appending_guard(M& mesh) : mesh_(mesh) {
        if constexpr (requires { mesh.set_slot_reuse(false); }) {
            saved_ = mesh.slot_reuse();
            mesh.set_slot_reuse(false);
        } else if constexpr (requires { mesh.set_recycle_garbage(false); }) {
            saved_ = mesh.does_recycle_garbage();
            mesh.set_recycle_garbage(false);
        }
    }
    ~appending_guard() {
        if constexpr (requires { mesh_.set_slot_reuse(false); })
            mesh_.set_slot_reuse(saved_);
        else if constexpr (requires { mesh_.set_recycle_garbage(false); })
            mesh_.set_recycle_garbage(saved_);
    }
    appending_guard(const appending_guard&) = delete;
    appending_guard& operator=(const appending_guard&) = delete;

private:
    M& mesh_;
    bool saved_ = false;
};

}  // namespace hmira::detail::subdivision
