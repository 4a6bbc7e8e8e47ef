// python/src/remeshing.cpp
// Mesh.remesh: isotropic remeshing, on a copy (the library works on one) that replaces the
// mesh on success; Ctrl-C cancels through the progress hook.
#include "mesh_binding.hpp"
#include "results.hpp"

#include <hmira/algorithms/remeshing/isotropic_remeshing.hpp>

namespace hmira_py {

namespace {

remesh_report remesh(py_mesh& s, std::optional<double> target_edge_length, std::size_t iterations,
                     std::optional<double> feature_angle, std::optional<std::vector<long long>> feature_edges) {
    std::vector<std::size_t> features;
    if (feature_edges)
        for (long long e : *feature_edges) {
            if (e < 0) value_error("remesh: feature_edges names edge " + std::to_string(e) + ", which does not exist");
            features.push_back(std::size_t(e));
        }
    const auto r = change_compacted(s, [&](halfedge_mesh& m, hmira::progress_function progress) {
        double length = target_edge_length.value_or(0.0);
        if (!target_edge_length) {  // the mean edge length, or why the mesh has none to use
            const auto mean = hmira::default_target_edge_length(m);
            if (!mean) return hmira::result<hmira::isotropic_remeshing_result>(mean.error());
            length = *mean;
        }
        return hmira::isotropic_remeshing(m, {.target_edge_length = length,
                                              .iterations = iterations,
                                              .feature_angle = feature_angle,
                                              .feature_edges = features,
                                              .progress = std::move(progress)});
    });
    return {.splits = r.splits, .collapses = r.collapses, .flips = r.flips, .feature_edges = r.feature_edges};
}

}  // namespace

void bind_mesh_remeshing(nb::class_<py_mesh>& c) {
    c.def("remesh", &remesh, nb::kw_only(), nb::arg("target_edge_length") = nb::none(),
          nb::arg("iterations") = hmira::isotropic_remeshing_options{}.iterations,
          nb::arg("feature_angle") = nb::none(), nb::arg("feature_edges") = nb::none(),
          "Isotropic remeshing of a triangle mesh towards target_edge_length (default: the mean edge length):\n"
          "`iterations` rounds of split, collapse, flip and tangential relaxation with projection onto the input.\n"
          "The boundary is kept, and so are edges sharper than feature_angle degrees and the edges listed in\n"
          "feature_edges (edge indices). Returns a RemeshResult (splits, collapses, flips, feature_edges).\n\n"
          ">>> m = hmira.Mesh([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], [[0, 1, 2], [0, 2, 3]])\n"
          ">>> m.remesh(target_edge_length=0.25).feature_edges\n"
          "4");
}

}  // namespace hmira_py
