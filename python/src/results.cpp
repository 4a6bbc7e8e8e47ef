// python/src/results.cpp
// Binds the typed results of results.hpp: read-only attributes, plus the mapping protocol
// (r["faces"], keys(), dict(r), == with a dict) the plain dicts they replace offered.
#include "results.hpp"

#include <nanobind/stl/vector.h>

#include <string>
#include <utility>

namespace hmira_py {
namespace {

nb::dict as_dict(nb::handle self) {
    nb::dict d;
    for (nb::handle name : nb::borrow<nb::tuple>(self.type().attr("_fields"))) d[name] = self.attr(name);
    return d;
}

/// A result class named `name` over the members `fields` (name, member pointer, docstring).
template <class T, class... Members>
void bind_result(nb::module_& m, const char* name, const char* doc, std::pair<const char*, Members T::*>... fields) {
    nb::class_<T> c(m, name, doc);
    (c.def_ro(fields.first, fields.second), ...);
    c.attr("_fields") = nb::make_tuple(fields.first...);
    c.def(
         "__getitem__",
         [](nb::handle self, const std::string& key) -> nb::object {
             for (nb::handle f : nb::borrow<nb::tuple>(self.type().attr("_fields")))
                 if (nb::cast<std::string>(f) == key) return self.attr(key.c_str());
             throw nb::key_error(key.c_str());
         },
         nb::arg("key"), "The field `key`, as the dict results of earlier versions offered it.")
        .def(
            "keys", [](nb::handle self) { return nb::list(self.type().attr("_fields")); },
            "The field names, in order (with __getitem__, dict(result) works).")
        .def("_asdict", &as_dict, "The fields as a dict.")
        .def(
            "__eq__",
            [](nb::handle self, nb::handle other) {
                if (nb::isinstance<nb::dict>(other) || other.type().is(self.type()))
                    return as_dict(self).equal(nb::isinstance<nb::dict>(other) ? nb::borrow(other) : as_dict(other));
                return false;
            },
            nb::arg("other").none())
        .def("__repr__", [name](nb::handle self) {
            std::string out = name;
            out += "(";
            bool first = true;
            for (auto [k, v] : as_dict(self)) {
                out +=
                    (first ? "" : ", ") + nb::cast<std::string>(nb::str(k)) + "=" + nb::cast<std::string>(nb::repr(v));
                first = false;
            }
            return out + ")";
        });
    c.attr("__hash__") = nb::none();
}

template <class T, class M>
std::pair<const char*, M T::*> f(const char* name, M T::*member) {
    return {name, member};
}

}  // namespace

void bind_results(nb::module_& m) {
    bind_result<open_hole_report>(m, "OpenHole", "A hole fill_holes left open: its first vertex, length and why.",
                                  f("vertex", &open_hole_report::vertex), f("edges", &open_hole_report::edges),
                                  f("reason", &open_hole_report::reason));
    bind_result<fill_holes_report>(
        m, "FillHolesResult", "What Mesh.fill_holes did: loops filled and skipped, faces and vertices added.",
        f("filled", &fill_holes_report::filled), f("skipped", &fill_holes_report::skipped),
        f("faces_added", &fill_holes_report::faces_added), f("vertices_added", &fill_holes_report::vertices_added),
        f("unfaired", &fill_holes_report::unfaired), f("open", &fill_holes_report::open));
    bind_result<decimate_report>(
        m, "DecimateResult",
        "What Mesh.decimate did: faces and vertices after, collapses, why it stopped ('target_faces', 'max_error' "
        "or 'constraints'), the largest error of a collapse made.",
        f("faces", &decimate_report::faces), f("vertices", &decimate_report::vertices),
        f("collapses", &decimate_report::collapses), f("triangulated", &decimate_report::triangulated),
        f("stopped_by", &decimate_report::stopped_by), f("error", &decimate_report::error),
        f("note", &decimate_report::note));
    bind_result<truncate_report>(m, "TruncateResult", "What Mesh.truncate made: new faces and vertices (counts).",
                                 f("faces", &truncate_report::faces), f("vertices", &truncate_report::vertices));
    bind_result<bevel_report>(m, "BevelResult",
                              "What Mesh.bevel made: strip faces, vertex faces, vertices (counts), and the smallest "
                              "width used.",
                              f("strip_faces", &bevel_report::strip_faces),
                              f("vertex_faces", &bevel_report::vertex_faces), f("vertices", &bevel_report::vertices),
                              f("width", &bevel_report::width));
    bind_result<extrude_report>(m, "ExtrudeResult", "What Mesh.extrude made: top faces, side faces, vertices (counts).",
                                f("top_faces", &extrude_report::top_faces),
                                f("side_faces", &extrude_report::side_faces), f("vertices", &extrude_report::vertices));
    bind_result<remesh_report>(m, "RemeshResult", "What Mesh.remesh did: splits, collapses, flips, feature edges kept.",
                               f("splits", &remesh_report::splits), f("collapses", &remesh_report::collapses),
                               f("flips", &remesh_report::flips), f("feature_edges", &remesh_report::feature_edges));
    bind_result<subdivide_report>(m, "SubdivideResult", "Vertex, edge and face counts after Mesh.subdivide.",
                                  f("vertices", &subdivide_report::vertices), f("edges", &subdivide_report::edges),
                                  f("faces", &subdivide_report::faces));
    bind_result<triangulate_report>(
        m, "TriangulateResult", "What Mesh.triangulate_faces did: faces cut, triangles added.",
        f("faces_cut", &triangulate_report::faces_cut), f("triangles_added", &triangulate_report::triangles_added));
    bind_result<boolean_result>(
        m, "BooleanResult",
        "What mesh_boolean made: the new Mesh, per output face its origin (origin_mesh 0 for a, 1 for b; "
        "origin_face the face there), candidate pairs tested, input triangles cut, snapped vertices, degenerate "
        "faces and face pairs that rounding made intersect.",
        f("mesh", &boolean_result::mesh), f("origin_mesh", &boolean_result::origin_mesh),
        f("origin_face", &boolean_result::origin_face), f("intersecting_pairs", &boolean_result::intersecting_pairs),
        f("cut_triangles", &boolean_result::cut_triangles), f("snapped_vertices", &boolean_result::snapped_vertices),
        f("degenerate_faces", &boolean_result::degenerate_faces),
        f("rounding_intersections", &boolean_result::rounding_intersections));
}

}  // namespace hmira_py
