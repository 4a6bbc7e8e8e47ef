// python/src/triangle_operators.cpp
// Mesh's local triangle operators: flip, split and collapse an edge, split a face. They change
// the mesh in place and keep deleted slots until collect_garbage(), as the Euler operators do.
#include "mesh_binding.hpp"

#include <hmira/algorithms/triangle/triangle.hpp>

namespace hmira_py {

namespace {

hmira::collapse_edge_options collapse_options(const std::string& placement,
                                              const std::optional<std::vector<double>>& position, bool check_geometry,
                                              const char* who) {
    hmira::collapse_edge_options o;
    o.check_geometry = check_geometry;
    o.placement = choice_arg<hmira::collapse_placement>(placement, who, "placement");
    if ((o.placement == hmira::collapse_placement::given) != position.has_value())
        value_error(std::string(who) + ": give position exactly when placement='given'");
    if (position) o.position = point_arg(*position, who);
    return o;
}

void bind_flip_and_split(nb::class_<py_mesh>& c) {
    c.def(
         "is_flip_ok",
         [](const py_mesh& s, long long h) {
             const auto hh = halfedge_arg(s.get(), h, "is_flip_ok");
             return read_without_gil(s, [&](const halfedge_mesh& m) { return hmira::is_flip_ok(m, hh); });
         },
         nb::arg("halfedge"),
         "Whether flip_edge(halfedge) is allowed: two triangles on either side, no edge between the two opposite "
         "vertices yet.")
        .def(
            "flip_edge",
            [](py_mesh& s, long long h) {
                const auto hh = halfedge_arg(s.get(), h, "flip_edge");
                const auto r = change_without_gil(s, true, [&](halfedge_mesh& m, const hmira::progress_function&) {
                    return hmira::flip_edge(m, hh);
                });
                return idx(r.halfedge);
            },
            nb::arg("halfedge"),
            "Turns the edge between two triangles to join their opposite vertices; returns the flipped halfedge. Its "
            "own inverse.")
        .def(
            "split_edge",
            [](py_mesh& s, long long h, std::optional<std::vector<double>> position, bool split_triangles) {
                const auto hh = halfedge_arg(s.get(), h, "split_edge");
                const hmira::split_edge_options o{.position = optional_point(position, "split_edge"),
                                                  .split_triangles = split_triangles};
                const auto r = change_without_gil(s, true, [&](halfedge_mesh& m, const hmira::progress_function&) {
                    return hmira::split_edge(m, hh, o);
                });
                return std::pair{idx(r.vertex), idx(r.halfedge)};
            },
            nb::arg("halfedge"), nb::kw_only(), nb::arg("position") = nb::none(),
            nb::arg("split_triangles") = hmira::split_edge_options{}.split_triangles,
            "A new vertex on the edge (at its midpoint by default), the triangles beside it split; returns (vertex, "
            "halfedge from the new "
            "vertex to the old target). collapse_edge(halfedge, placement='target') undoes it.")
        .def(
            "split_face",
            [](py_mesh& s, long long f, std::optional<std::vector<double>> position) {
                const auto ff = face_arg(s.get(), f, "split_face");
                const hmira::split_face_options o{.position = optional_point(position, "split_face")};
                const auto r = change_without_gil(s, true, [&](halfedge_mesh& m, const hmira::progress_function&) {
                    return hmira::split_face(m, ff, o);
                });
                return std::pair{idx(r.vertex), idx(r.halfedge)};
            },
            nb::arg("face"), nb::kw_only(), nb::arg("position") = nb::none(),
            "Splits a triangle into three at a new vertex (its centroid by default); returns (vertex, halfedge).");
}

void bind_collapse(nb::class_<py_mesh>& c) {
    const hmira::collapse_edge_options defaults;
    c.def(
         "is_collapse_ok",
         [](const py_mesh& s, long long h, const std::string& placement, std::optional<std::vector<double>> position,
            bool check_geometry) {
             const auto hh = halfedge_arg(s.get(), h, "is_collapse_ok");
             const auto o = collapse_options(placement, position, check_geometry, "is_collapse_ok");
             return read_without_gil(s, [&](const halfedge_mesh& m) { return hmira::is_collapse_ok(m, hh, o); });
         },
         nb::arg("halfedge"), nb::kw_only(), nb::arg("placement") = name_of(defaults.placement),
         nb::arg("position") = nb::none(), nb::arg("check_geometry") = defaults.check_geometry,
         "Whether collapse_edge(halfedge) is allowed: the link condition and the boundary rules, and with "
         "check_geometry no face turned over.")
        .def(
            "collapse_edge",
            [](py_mesh& s, long long h, const std::string& placement, std::optional<std::vector<double>> position,
               bool check_geometry) {
                const auto hh = halfedge_arg(s.get(), h, "collapse_edge");
                const auto o = collapse_options(placement, position, check_geometry, "collapse_edge");
                const auto r = change_without_gil(s, true, [&](halfedge_mesh& m, const hmira::progress_function&) {
                    return hmira::collapse_edge(m, hh, o);
                });
                return idx(r.vertex);
            },
            nb::arg("halfedge"), nb::kw_only(), nb::arg("placement") = name_of(defaults.placement),
            nb::arg("position") = nb::none(), nb::arg("check_geometry") = defaults.check_geometry,
            "Merges the halfedge's source into its target, which survives at `placement` ('midpoint', 'target', "
            "'source' or 'given' "
            "with position); returns the surviving vertex. Deleted slots stay until collect_garbage().");
}

}  // namespace

void bind_mesh_triangle_operators(nb::class_<py_mesh>& c) {
    bind_flip_and_split(c);
    bind_collapse(c);
}

}  // namespace hmira_py
