// face_vertex_mesh has no edges or halfedges: an Euler operator must be rejected naming
// euler_mutable_mesh.
#include <hmira/algorithms/euler/make_edge_face.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

int main() {
#ifdef HMIRA_CONTROL
    hmira::halfedge_mesh m;
    (void)hmira::make_edge_face(m, hmira::halfedge_handle{}, hmira::halfedge_handle{});
#else
    hmira::face_vertex_mesh m;
    (void)hmira::kill_edge_face(m, 0);
#endif
}
