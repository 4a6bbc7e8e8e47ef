// python/src/decimation.cpp
// Mesh.decimate: quadric error decimation. Ctrl-C cancels through the progress hook, and
// decimate then restores the mesh.
#include "mesh_binding.hpp"
#include "results.hpp"

#include <hmira/algorithms/decimation/decimate.hpp>

namespace hmira_py {

namespace {

decimate_report decimate(py_mesh& s, std::optional<std::size_t> target_faces, std::optional<double> target_ratio,
                         std::optional<double> max_error, bool fix_boundary, double max_normal_angle,
                         double max_aspect_ratio, std::optional<std::vector<long long>> fixed_vertices,
                         double min_angle, bool area_weighted, std::optional<double> feature_angle,
                         std::optional<std::vector<std::size_t>> feature_edges, bool keep_features) {
    hmira::decimate_options o{.target_faces = target_faces,
                              .target_ratio = target_ratio,
                              .max_error = max_error,
                              .keep_boundary = fix_boundary,
                              .max_normal_angle = max_normal_angle,
                              .max_aspect_ratio = max_aspect_ratio,
                              .min_angle = min_angle,
                              .locked_vertices = fixed_arg(s.get(), fixed_vertices, "decimate"),
                              .area_weighted = area_weighted,
                              .feature_angle = feature_angle,
                              .feature_edges = feature_edges ? *feature_edges : std::vector<std::size_t>{},
                              .keep_features = keep_features};
    const auto r = change_compacted(s, [&](halfedge_mesh& m, hmira::progress_function progress) {
        o.progress = std::move(progress);
        return hmira::decimate(m, o);
    });
    return {.faces = r.faces,
            .vertices = r.vertices,
            .collapses = r.collapses,
            .triangulated = r.triangulated,
            .stopped_by = r.stopped_by == hmira::decimate_stop::target_faces ? "target_faces"
                          : r.stopped_by == hmira::decimate_stop::max_error  ? "max_error"
                                                                             : "constraints",
            .error = r.error,
            .note = r.note};
}

}  // namespace

void bind_mesh_decimation(nb::class_<py_mesh>& c) {
    const hmira::decimate_options defaults;
    c.def("decimate", &decimate, nb::kw_only(), nb::arg("target_faces") = nb::none(),
          nb::arg("target_ratio") = nb::none(), nb::arg("max_error") = nb::none(),
          nb::arg("fix_boundary") = defaults.keep_boundary, nb::arg("max_normal_angle") = defaults.max_normal_angle,
          nb::arg("max_aspect_ratio") = defaults.max_aspect_ratio, nb::arg("fixed_vertices") = nb::none(),
          nb::arg("min_angle") = defaults.min_angle, nb::arg("area_weighted") = defaults.area_weighted,
          nb::arg("feature_angle") = nb::none(), nb::arg("feature_edges") = nb::none(),
          nb::arg("keep_features") = defaults.keep_features,
          "Quadric error decimation (Garland-Heckbert) until the first target reached: target_faces, target_ratio\n"
          "(of the faces) or max_error (a distance). Polygons are triangulated first. Boundary vertices stay\n"
          "unless fix_boundary=False; fixed_vertices never move (the names smoothing uses; hmira.Mesh.decimate\n"
          "still takes keep_boundary and locked_vertices, deprecated). feature_angle (degrees) and feature_edges\n"
          "add planes through creases; keep_features keeps feature lines on their input vertices.\n"
          "Returns a DecimateResult (faces, vertices, collapses,\n"
          "triangulated, stopped_by, error, note); vertices are renumbered densely afterwards.\n\n"
          ">>> m = hmira.Mesh([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0.5, 0.5, 0]],\n"
          "...                [[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]])\n"
          ">>> m.decimate(target_faces=2).faces\n"
          "2");
}

}  // namespace hmira_py
