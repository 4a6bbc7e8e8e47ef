// python/src/viewer.cpp
// The viewer page for Python (hmira.view, Mesh._repr_html_, hmira.render): the same page as
// `hmira view`, made by viewer/viewer_page.hpp with the bundle that hmira_viewer_embed(_core)
// compiled in (python/CMakeLists.txt). hmira/viewer.py turns meshes into the plain arrays taken here.
#include "common.hpp"

#include <nanobind/stl/tuple.h>

#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <viewer_bundle.hpp>
#include <viewer_page.hpp>

namespace hmira_py {

namespace {

using point_array = nb::ndarray<const double, nb::ndim<2>, nb::c_contig, nb::device::cpu>;
using index_array = nb::ndarray<const std::uint32_t, nb::ndim<1>, nb::c_contig, nb::device::cpu>;
/// vertices, edges, faces, genus, closed: what the page's info corner shows.
using info_tuple = std::tuple<std::size_t, std::size_t, std::size_t, long long, bool>;
using page_input = std::tuple<std::string, point_array, index_array, index_array, info_tuple>;

constexpr const char* NO_BUNDLE =
    "hmira: this hmira was built without the viewer bundle: run viewer/build.sh (needs node and npm), "
    "then reinstall (pip install .)";

/// Checks one mesh's arrays (the \pre of make_page_mesh) and returns them as spans; `who` names it.
hmira_viewer::mesh_arrays arrays_of(const page_input& in, const std::string& who) {
    const auto& [name, points, offsets, corners, info] = in;
    if (points.shape(1) != 3)
        value_error(who + ": vertices must have shape (n, 3), got (n, " + std::to_string(points.shape(1)) + ")");
    const std::size_t n = points.shape(0);
    if (n == 0) value_error(who + ": no vertices to show");
    if (n > std::numeric_limits<std::uint32_t>::max() / 2)
        value_error(who + ": " + std::to_string(n) + " vertices are more than a page can index (32-bit)");
    const double* p = points.data();
    for (std::size_t i = 0; i < 3 * n; ++i)
        if (!std::isfinite(p[i]))
            value_error(who + ": vertex " + std::to_string(i / 3) + " has a non-finite coordinate");
    const std::uint32_t* o = offsets.data();
    const std::uint32_t* c = corners.data();
    const std::size_t faces = offsets.shape(0) == 0 ? 0 : offsets.shape(0) - 1;
    if (offsets.shape(0) == 0 || o[0] != 0 || o[faces] != corners.shape(0))
        value_error(who + ": face offsets must start at 0 and end at the number of corners");
    for (std::size_t f = 0; f < faces; ++f)
        if (o[f + 1] < o[f]) value_error(who + ": face offsets decrease at face " + std::to_string(f));
    for (std::size_t k = 0; k < corners.shape(0); ++k)
        if (c[k] >= n)
            value_error(who + ": corner " + std::to_string(k) + " names vertex " + std::to_string(c[k]) + " of " +
                        std::to_string(n));
    return {.points = {p, 3 * n}, .offsets = {o, offsets.shape(0)}, .corners = {c, corners.shape(0)}};
}

/// The whole page for one mesh or two side by side (sharing the first one's origin, as the CLI).
nb::str viewer_page(const std::vector<page_input>& meshes) {
    const std::string_view bundle = hmira_viewer::bundle();
    if (bundle.empty()) throw std::runtime_error(NO_BUNDLE);
    if (meshes.empty() || meshes.size() > 2)
        value_error("view: one mesh, or two to compare, got " + std::to_string(meshes.size()));
    std::vector<hmira_viewer::mesh_arrays> arrays;
    for (std::size_t i = 0; i < meshes.size(); ++i)
        arrays.push_back(arrays_of(meshes[i], i == 0 ? "view" : "view: compare"));
    std::string page;
    {
        nb::gil_scoped_release release;  // the arrays stay alive: `meshes` holds them
        const auto origin = hmira_viewer::bounding_box_centre(arrays.front().points);
        std::vector<hmira_viewer::page_mesh> pages;
        for (std::size_t i = 0; i < meshes.size(); ++i) {
            const auto& [v, e, f, genus, closed] = std::get<4>(meshes[i]);
            pages.push_back(hmira_viewer::make_page_mesh(
                std::get<0>(meshes[i]), {.vertices = v, .edges = e, .faces = f, .genus = genus, .closed = closed},
                arrays[i], origin));
        }
        std::ostringstream os;
        hmira_viewer::write_page(os, pages, bundle);
        page = std::move(os).str();
    }
    return nb::str(page.data(), page.size());
}

}  // namespace

void bind_viewer(nb::module_& m) {
    m.def("_viewer_page", &viewer_page, nb::arg("meshes"),
          "The self-contained viewer page (HTML) for one or two meshes, each (name, vertices (n, 3) float64, "
          "face offsets uint32 (F + 1), corners uint32, (V, E, F, genus, closed)). RuntimeError without the bundle.");
    m.def(
        "_viewer_bundle_available", [] { return !hmira_viewer::bundle().empty(); },
        "Whether the viewer bundle (viewer/build.sh) was compiled into this extension.");
}

}  // namespace hmira_py
