// python/src/editing.cpp
// Mesh._truncate, _bevel and _extrude (hmira.Mesh wraps them): the editing operations, each
// atomic (on error or Ctrl-C the mesh is unchanged), the mesh renumbered densely afterwards.
#include "mesh_binding.hpp"
#include "results.hpp"

#include <hmira/algorithms/editing/editing.hpp>
#include <hmira/algorithms/geometry/sharp_edges.hpp>

namespace hmira_py {

namespace {

truncate_report truncate(py_mesh& self, std::optional<std::vector<long long>> vertices, bool all,
                         std::optional<double> fraction, std::optional<double> distance) {
    auto& m0 = self.get();
    if (all == vertices.has_value()) value_error("truncate: give vertices or all=True (one of them)");
    std::vector<hmira::vertex_handle> vs;
    if (all)
        for (auto v : m0.vertices()) vs.push_back(v);
    else
        for (long long i : *vertices) vs.push_back(vertex_arg(m0, i, "truncate"));
    const auto r = change_compacted(self, [&](halfedge_mesh& m, hmira::progress_function progress) {
        const hmira::truncate_options defaults;
        const hmira::truncate_options o{.fraction = fraction.value_or(defaults.fraction),
                                        .distance = distance.value_or(defaults.distance),
                                        .progress = std::move(progress)};
        return hmira::truncate(m, vs, o);
    });
    return {.faces = r.faces.size(), .vertices = r.vertices.size()};
}

bevel_report bevel(py_mesh& self, std::optional<std::vector<std::pair<long long, long long>>> edges, bool all,
                   std::optional<double> angle, double width, int segments, bool no_clamp,
                   std::optional<std::vector<long long>> vertices, bool vertices_all) {
    auto& m0 = self.get();
    const int ways =
        int(edges.has_value()) + int(all) + int(angle.has_value()) + int(vertices.has_value()) + int(vertices_all);
    if (ways != 1)
        value_error("bevel: choose edges, all=True or angle=DEG, or vertices / vertices_all=True (exactly one)");
    std::vector<hmira::vertex_handle> vs;
    std::vector<hmira::edge_handle> es;
    const bool vertex_mode = vertices || vertices_all;
    if (vertex_mode) {
        if (vertices_all)
            for (auto v : m0.vertices()) vs.push_back(v);
        else
            for (long long i : *vertices) vs.push_back(vertex_arg(m0, i, "bevel"));
    } else {
        if (edges) {
            for (auto [a, b] : *edges) {
                const auto h = m0.find_halfedge(vertex_arg(m0, a, "bevel"), vertex_arg(m0, b, "bevel"));
                if (!m0.is_valid(h))
                    value_error("bevel: no edge between vertices " + std::to_string(a) + " and " + std::to_string(b));
                es.push_back(m0.edge(h));
            }
        } else {
            es = hmira::sharp_edges(m0, angle ? *angle : 0.0);
            if (es.empty())
                value_error(angle ? "bevel: no edge has a dihedral angle of at least " + std::to_string(*angle) +
                                        " degrees"
                                  : std::string("bevel: the mesh has no edge between two faces"));
        }
    }
    const auto b = change_compacted(self, [&](halfedge_mesh& m, hmira::progress_function progress) {
        const hmira::bevel_options o{.width = width,
                                     .segments = segments,
                                     .clamp_overlap = !no_clamp,
                                     .clamp_globally = false,
                                     .progress = std::move(progress)};
        return vertex_mode ? hmira::bevel_vertices(m, vs, o) : hmira::bevel(m, es, o);
    });
    return {.strip_faces = b.strip_faces.size(),
            .vertex_faces = b.vertex_faces.size(),
            .vertices = b.vertices.size(),
            .width = b.width};
}

extrude_report extrude(py_mesh& self, std::optional<std::vector<long long>> faces, bool all, double distance,
                       std::optional<std::vector<double>> direction, const std::string& mode) {
    auto& m0 = self.get();
    if (all == faces.has_value()) value_error("extrude: give faces or all=True (one of them)");
    const auto chosen = choice_arg<hmira::extrude_mode>(mode, "extrude", "mode");
    std::vector<hmira::face_handle> fs;
    if (all)
        for (auto f : m0.faces()) fs.push_back(f);
    else
        for (long long i : *faces) fs.push_back(face_arg(m0, i, "extrude"));
    std::optional<vec3<double>> towards;
    if (direction) towards = point_arg(*direction, "extrude: direction");
    const auto r = change_compacted(self, [&](halfedge_mesh& m, hmira::progress_function progress) {
        const hmira::extrude_options o{
            .distance = distance, .direction = towards, .mode = chosen, .progress = std::move(progress)};
        return hmira::extrude(m, fs, o);
    });
    return {.top_faces = r.top_faces.size(), .side_faces = r.side_faces.size(), .vertices = r.vertices.size()};
}

}  // namespace

void bind_mesh_editing(nb::class_<py_mesh>& c) {
    const hmira::bevel_options bevel_defaults;
    const hmira::extrude_options extrude_defaults;
    c.def("_truncate", &truncate, nb::arg("vertices") = nb::none(), nb::kw_only(), nb::arg("all") = false,
          nb::arg("fraction") = nb::none(), nb::arg("distance") = nb::none())
        .def("_bevel", &bevel, nb::arg("edges") = nb::none(), nb::kw_only(), nb::arg("all") = false,
             nb::arg("angle") = nb::none(), nb::arg("width") = bevel_defaults.width,
             nb::arg("segments") = bevel_defaults.segments, nb::arg("no_clamp") = !bevel_defaults.clamp_overlap,
             nb::arg("vertices") = nb::none(), nb::arg("vertices_all") = false)
        .def("_extrude", &extrude, nb::arg("faces") = nb::none(), nb::kw_only(), nb::arg("all") = false,
             nb::arg("distance") = extrude_defaults.distance, nb::arg("direction") = nb::none(),
             nb::arg("mode") = name_of(extrude_defaults.mode));
}

}  // namespace hmira_py
