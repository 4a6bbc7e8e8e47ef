// python/src/results.hpp
// What the Mesh operations return to Python: small typed results (DecimateResult, ...) with the
// field names of the C++ report structs, counts where C++ returns element lists. Each is a bound
// class with read-only attributes; `r["faces"]`, `r.keys()`, `dict(r)` and `r == {...}` also work,
// as the plain dicts they replace did. results.cpp binds them.
#pragma once

#include "common.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace hmira_py {

/// Mesh.decimate (hmira::decimate_result; stopped_by as its name).
struct decimate_report {
    std::size_t faces = 0, vertices = 0, collapses = 0;
    bool triangulated = false;
    std::string stopped_by;
    double error = 0;
    std::string note;
};
/// A hole Mesh.fill_holes left open (hmira::open_hole; reason in words).
struct open_hole_report {
    std::size_t vertex = 0, edges = 0;
    std::string reason;
};
/// Mesh.fill_holes (hmira::fill_holes_result).
struct fill_holes_report {
    std::size_t filled = 0, skipped = 0, faces_added = 0, vertices_added = 0, unfaired = 0;
    std::vector<open_hole_report> open;
};
/// Mesh.truncate: counts of hmira::truncate_set_result's lists.
struct truncate_report {
    std::size_t faces = 0, vertices = 0;
};
/// Mesh.bevel: counts of hmira::bevel_result's lists, and the width used.
struct bevel_report {
    std::size_t strip_faces = 0, vertex_faces = 0, vertices = 0;
    double width = 0;
};
/// Mesh.extrude: counts of hmira::extrude_result's lists.
struct extrude_report {
    std::size_t top_faces = 0, side_faces = 0, vertices = 0;
};
/// Mesh.remesh (hmira::isotropic_remeshing_result).
struct remesh_report {
    std::size_t splits = 0, collapses = 0, flips = 0, feature_edges = 0;
};
/// Mesh.subdivide (hmira::subdivide_result).
struct subdivide_report {
    std::size_t vertices = 0, edges = 0, faces = 0;
};
/// Mesh.triangulate_faces (hmira::triangulate_faces_result).
struct triangulate_report {
    std::size_t faces_cut = 0, triangles_added = 0;
};

/// hmira.mesh_boolean (hmira::boolean_report; the face origins as arrays, the new Mesh).
struct boolean_result {
    nb::object mesh;
    nb::object origin_mesh;  ///< uint8 numpy array, one per output face
    nb::object origin_face;  ///< int64 numpy array, one per output face
    std::size_t intersecting_pairs = 0, cut_triangles = 0, snapped_vertices = 0, degenerate_faces = 0,
                rounding_intersections = 0;
};

/// Binds the result classes (results.cpp).
void bind_results(nb::module_& m);

}  // namespace hmira_py
