// A model with halfedges but no inner rings (its traits cannot add or remove them) cannot run
// a ring operator: the call must be rejected naming euler_ring_mutable_mesh.
#include <hmira/algorithms/euler/make_face_kill_ring.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

struct no_ring_traits : hmira::mesh_traits<hmira::halfedge_mesh> {
    static void add_inner_ring(hmira::halfedge_mesh&, hmira::face_handle, hmira::halfedge_handle) = delete;
    static void remove_inner_ring(hmira::halfedge_mesh&, hmira::face_handle, hmira::halfedge_handle) = delete;
};

int main() {
    hmira::halfedge_mesh m;
#ifdef HMIRA_CONTROL
    (void)hmira::make_face_kill_ring(m, hmira::halfedge_handle{});
#else
    (void)hmira::make_face_kill_ring<hmira::halfedge_mesh, no_ring_traits>(m, hmira::halfedge_handle{});
#endif
}
