// python/src/decimation.cpp
// Mesh.decimate: quadric error decimation. Ctrl-C cancels through the progress hook, and
// decimate then restores the mesh.
#include "mesh_binding.hpp"

#include <hmira/algorithms/decimation/decimate.hpp>

namespace hmira_py {

namespace {

nb::dict decimate(py_mesh& s, std::optional<std::size_t> target_faces, std::optional<double> target_ratio,
                  std::optional<double> max_error, bool fix_boundary, double max_normal_angle, double max_aspect_ratio,
                  std::optional<std::vector<long long>> fixed_vertices) {
    hmira::decimate_options o{.target_faces = target_faces,
                              .target_ratio = target_ratio,
                              .max_error = max_error,
                              .keep_boundary = fix_boundary,
                              .max_normal_angle = max_normal_angle,
                              .max_aspect_ratio = max_aspect_ratio,
                              .locked_vertices = fixed_arg(s.get(), fixed_vertices, "decimate")};
    const auto r = change_compacted(s, [&](halfedge_mesh& m, hmira::progress_function progress) {
        o.progress = std::move(progress);
        return hmira::decimate(m, o);
    });
    nb::dict d;
    d["faces"] = r.faces;
    d["vertices"] = r.vertices;
    d["collapses"] = r.collapses;
    d["triangulated"] = r.triangulated;
    d["stopped_by"] = r.stopped_by == hmira::decimate_stop::target_faces ? "target_faces"
                      : r.stopped_by == hmira::decimate_stop::max_error  ? "max_error"
                                                                         : "constraints";
    d["error"] = r.error;
    d["note"] = r.note;
    return d;
}

}  // namespace

void bind_mesh_decimation(nb::class_<py_mesh>& c) {
    const hmira::decimate_options defaults;
    c.def("decimate", &decimate, nb::kw_only(), nb::arg("target_faces") = nb::none(),
          nb::arg("target_ratio") = nb::none(), nb::arg("max_error") = nb::none(),
          nb::arg("fix_boundary") = defaults.keep_boundary, nb::arg("max_normal_angle") = defaults.max_normal_angle,
          nb::arg("max_aspect_ratio") = defaults.max_aspect_ratio, nb::arg("fixed_vertices") = nb::none(),
          "Quadric error decimation (Garland-Heckbert) until the first target reached: target_faces, target_ratio\n"
          "(of the faces) or max_error (a distance). Polygons are triangulated first. Boundary vertices stay\n"
          "unless fix_boundary=False; fixed_vertices never move (the names smoothing uses; hmira.Mesh.decimate\n"
          "still takes keep_boundary and locked_vertices, deprecated). Returns {'faces', 'vertices', 'collapses',\n"
          "'triangulated', 'stopped_by', 'error', 'note'}; vertices are renumbered densely afterwards.\n\n"
          ">>> m = hmira.Mesh([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0.5, 0.5, 0]],\n"
          "...                [[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]])\n"
          ">>> m.decimate(target_faces=2)['faces']\n"
          "2");
}

}  // namespace hmira_py
