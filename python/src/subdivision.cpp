// python/src/subdivision.cpp
// Mesh.subdivide: Loop, sqrt(3) or Catmull-Clark, `levels` times. The schemes leave the mesh
// unchanged on error and restore it when Ctrl-C cancels them through the progress hook.
#include "mesh_binding.hpp"
#include "results.hpp"

#include <hmira/algorithms/subdivision/subdivide.hpp>

namespace hmira_py {

void bind_mesh_subdivision(nb::class_<py_mesh>& c) {
    const hmira::subdivide_options defaults;
    c.def(
        "subdivide",
        [](py_mesh& s, const std::string& scheme, std::size_t levels) {
            const auto chosen = enum_arg<hmira::subdivision_scheme>(scheme, "subdivide", "scheme");
            const auto r = change_compacted(s, [&](halfedge_mesh& m, hmira::progress_function progress) {
                return hmira::subdivide(m, {.scheme = chosen, .levels = levels, .progress = std::move(progress)});
            });
            return subdivide_report{.vertices = r.vertices, .edges = r.edges, .faces = r.faces};
        },
        nb::kw_only(), nb::arg("scheme") = name_of(defaults.scheme), nb::arg("levels") = defaults.levels,
        "Subdivides `levels` times with `scheme`: 'loop' or 'sqrt3' (triangle meshes) or 'catmull-clark' (any\n"
        "polygon mesh), boundaries included; returns the counts after the last level\n(a SubdivideResult). 'sqrt3' "
        "refines the\n"
        "boundary on every second level of a call, so give it an even `levels` for a smooth boundary.\n\n"
        ">>> m = hmira.Mesh([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], [[0, 1, 2, 3]])\n"
        ">>> m.subdivide(scheme='catmull-clark')\n"
        "SubdivideResult(vertices=9, edges=12, faces=4)");
}

}  // namespace hmira_py
