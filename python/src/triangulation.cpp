// python/src/triangulation.cpp
// Mesh.triangulate_faces: every polygon cut into triangles, on a copy that replaces the mesh
// only on success.
#include "mesh_binding.hpp"
#include "results.hpp"

#include <hmira/algorithms/triangulation/triangulate_faces.hpp>

namespace hmira_py {

void bind_mesh_triangulation(nb::class_<py_mesh>& c) {
    c.def(
        "triangulate_faces",
        [](py_mesh& s, bool delaunay) {
            const auto r =
                on_copy(s, [&](halfedge_mesh& m) { return hmira::triangulate_faces(m, {.delaunay = delaunay}); });
            return triangulate_report{.faces_cut = r.faces_cut, .triangles_added = r.triangles_added};
        },
        nb::kw_only(), nb::arg("delaunay") = hmira::triangulate_polygon_options{}.delaunay,
        "Triangulates every polygon (inner rings included, robust on concave faces); with delaunay=True each face's "
        "diagonals "
        "are its constrained Delaunay ones (largest smallest angle). Returns a TriangulateResult (faces_cut, "
        "triangles_added).");
}

}  // namespace hmira_py
