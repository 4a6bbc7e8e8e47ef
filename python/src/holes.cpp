// python/src/holes.cpp
// Mesh.fill_hole and Mesh.fill_holes: boundary loops closed with triangles, optionally refined
// and faired. Both roll a cancelled (Ctrl-C) or failed fill back themselves.
#include "mesh_binding.hpp"
#include "results.hpp"

#include <hmira/algorithms/holes/fill_hole.hpp>

namespace hmira_py {

namespace {

hmira::fill_hole_options fill_options(std::size_t max_dynamic_programming_edges, bool refine, const std::string& fair,
                                      const char* who) {
    hmira::fill_hole_options o;
    o.max_dynamic_programming_edges = max_dynamic_programming_edges;
    o.fair = choice_arg<hmira::fairing>(fair, who, "fair");
    o.refine = refine || o.fair != hmira::fairing::none;  // fairing moves the vertices refinement adds
    return o;
}

std::vector<open_hole_report> open_holes(const hmira::fill_holes_result& r, std::size_t max_edges) {
    std::vector<open_hole_report> open;
    for (const auto& h : r.open)
        open.push_back(
            {.vertex = h.vertex,
             .edges = h.edges,
             .reason = h.reason == hmira::open_hole_reason::too_long
                           ? "a loop of " + std::to_string(h.edges) + " edges > max_edges " + std::to_string(max_edges)
                           : h.message});
    return open;
}

fill_holes_report fill_holes(py_mesh& s, std::size_t max_edges, std::size_t max_dynamic_programming_edges, bool refine,
                             const std::string& fair) {
    const auto o = fill_options(max_dynamic_programming_edges, refine, fair, "fill_holes");
    if (max_edges < 3) value_error("fill_holes: max_edges must be at least 3, got " + std::to_string(max_edges));
    const auto r = change_compacted(s, [&](halfedge_mesh& m, hmira::progress_function progress) {
        auto with_progress = o;
        with_progress.progress = std::move(progress);
        return hmira::fill_holes(m, max_edges, with_progress);
    });
    return {.filled = r.filled,
            .skipped = r.skipped,
            .faces_added = r.faces_added,
            .vertices_added = r.vertices_added,
            .unfaired = r.unfaired,
            .open = open_holes(r, max_edges)};
}

}  // namespace

void bind_mesh_holes(nb::class_<py_mesh>& c) {
    const hmira::fill_hole_options defaults;
    c.def(
         "fill_hole",
         [](py_mesh& s, long long h, std::size_t max_dynamic_programming_edges, bool refine, const std::string& fair) {
             const auto hh = halfedge_arg(s.get(), h, "fill_hole");
             const auto o = fill_options(max_dynamic_programming_edges, refine, fair, "fill_hole");
             const auto r =
                 change_without_gil(s, true, [&](halfedge_mesh& m, const hmira::progress_function& progress) {
                     auto with_progress = o;
                     with_progress.progress = progress;
                     return hmira::fill_hole(m, hh, with_progress);
                 });
             std::vector<long long> faces;
             for (auto f : r.faces) faces.push_back(idx(f));
             return faces;
         },
         nb::arg("boundary_halfedge"), nb::kw_only(),
         nb::arg("max_dynamic_programming_edges") = defaults.max_dynamic_programming_edges,
         nb::arg("refine") = defaults.refine, nb::arg("fair") = name_of(defaults.fair),
         "Closes the boundary loop of a boundary halfedge with triangles (minimal area, maximal dihedral, Liepa 2003); "
         "with refine=True "
         "the patch is refined to the edge length around the hole, and fair='membrane' or 'thin-plate' (implies "
         "refine) smooths it. "
         "Returns the new faces.")
        .def("fill_holes", &fill_holes, nb::arg("max_edges") = hmira::fill_holes_default_max_edges, nb::kw_only(),
             nb::arg("max_dynamic_programming_edges") = defaults.max_dynamic_programming_edges,
             nb::arg("refine") = defaults.refine, nb::arg("fair") = name_of(defaults.fair),
             "Fills every hole of at most max_edges boundary edges (the CLI's --max-edges and default) (refine and "
             "fair as for fill_hole); returns "
             "a FillHolesResult (filled, skipped, faces_added, vertices_added, unfaired, open), 'open' listing each "
             "hole left open as an OpenHole (vertex, edges, reason). Ctrl-C stops it with the mesh unchanged.");
}

}  // namespace hmira_py
