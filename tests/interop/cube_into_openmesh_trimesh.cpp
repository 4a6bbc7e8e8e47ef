// OpenMesh's TriMesh declares triangles_only: generate_cube (quads) must not compile on it,
// and the message must name polygon_mesh_builder and triangles_only. With
// HMIRA_SNIPPET_OK the same call on a PolyMesh compiles.
#define _USE_MATH_DEFINES
#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/interop/openmesh.hpp>

int main() {
#ifdef HMIRA_SNIPPET_OK
    OpenMesh::PolyMesh_ArrayKernelT<> m;
#else
    OpenMesh::TriMesh_ArrayKernelT<> m;
#endif
    (void)hmira::generate_tetrahedron(m);  // triangles: fine on both
    (void)hmira::generate_cube(m);         // quads: rejected on the TriMesh
}
