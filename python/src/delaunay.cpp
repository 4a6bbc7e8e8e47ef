// python/src/delaunay.cpp
// delaunay_triangulation: points in the plane (or their x and y) to triangles indexing the
// caller's points, and optionally the Voronoi diagram.
#include "common.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <hmira/algorithms/delaunay/delaunay_triangulation.hpp>

namespace hmira_py {

namespace {

constexpr const char* DELAUNAY_DOC = R"doc(Delaunay triangulation of points in the plane.

Parameters
----------
points : ndarray of float64, shape (n, 2) or (n, 3)
    The points; a third column is a height, kept but ignored by the
    triangulation (2.5-D), unlike scipy's 3-D tetrahedra.
voronoi : bool, keyword-only
    Also return the Voronoi diagram.

Returns
-------
triangles : ndarray of int32, shape (m, 3)
    Counter-clockwise triangles indexing `points` (duplicates use their first
    occurrence).
voronoi_vertices : ndarray of float64, shape (m, 2)
    Only with ``voronoi=True``: the circumcentre of each triangle.
voronoi_edges : ndarray of int32, shape (e, 2)
    Only with ``voronoi=True``: pairs of Voronoi vertex indices, -1 marking the
    infinite end of a ray.

Examples
--------
>>> import numpy as np, hmira
>>> hmira.delaunay_triangulation(np.array([[0., 0.], [1., 0.], [0., 1.], [1., 1.1]])).shape
(2, 3)
)doc";

using point_array = nb::ndarray<const double, nb::ndim<2>, nb::c_contig, nb::device::cpu>;

nb::object delaunay(const point_array& points, bool voronoi) {
    const std::size_t n = points.shape(0), dim = points.shape(1);
    if (dim != 2 && dim != 3)
        value_error("delaunay_triangulation: points must have shape (n, 2) or (n, 3), got (" + std::to_string(n) +
                    ", " + std::to_string(dim) + ")");
    hmira::result<hmira::delaunay_triangles> r = hmira::fail(hmira::errc::invalid_argument, "");
    {
        nb::gil_scoped_release release;
        cpp_timer timer;
        const hmira::delaunay_options options{.voronoi = voronoi, .brio = true};
        if (dim == 2) {
            // (n, 2) doubles in C order are n std::array<double, 2>: read in place.
            const auto* p = reinterpret_cast<const std::array<double, 2>*>(points.data());
            r = hmira::delaunay_triangulation(std::span<const std::array<double, 2>>(p, n), options);
        } else {
            const auto* p = reinterpret_cast<const std::array<double, 3>*>(points.data());
            r = hmira::delaunay_triangulation(std::span<const std::array<double, 3>>(p, n), options);
        }
    }
    auto t = take(std::move(r));
    // Triangles index the caller's points (the first of each group of duplicates).
    std::vector<std::int32_t> tri(3 * t.triangles.size());
    for (std::size_t i = 0; i < t.triangles.size(); ++i)
        for (int c = 0; c < 3; ++c) tri[3 * i + c] = static_cast<std::int32_t>(t.vertex_to_input[t.triangles[i][c]]);
    const std::size_t m = t.triangles.size();
    auto triangles = adopt<std::int32_t>(std::move(tri), {m, 3});
    if (!voronoi) return nb::cast(triangles);
    std::vector<double> vv(2 * t.voronoi.vertices.size());
    for (std::size_t i = 0; i < t.voronoi.vertices.size(); ++i) {
        vv[2 * i] = t.voronoi.vertices[i].x;
        vv[2 * i + 1] = t.voronoi.vertices[i].y;
    }
    std::vector<std::int32_t> ve(2 * t.voronoi.edges.size());
    for (std::size_t i = 0; i < t.voronoi.edges.size(); ++i) {
        const auto& e = t.voronoi.edges[i];
        ve[2 * i] = static_cast<std::int32_t>(e.from);
        ve[2 * i + 1] = e.to == hmira::voronoi_edge::no_vertex ? -1 : static_cast<std::int32_t>(e.to);
    }
    const std::size_t k = t.voronoi.vertices.size(), ne = t.voronoi.edges.size();
    return nb::make_tuple(triangles, adopt<double>(std::move(vv), {k, 2}), adopt<std::int32_t>(std::move(ve), {ne, 2}));
}

}  // namespace

void bind_delaunay(nb::module_& m) {
    m.def("delaunay_triangulation", &delaunay, nb::arg("points"), nb::kw_only(),
          nb::arg("voronoi") = hmira::delaunay_options{}.voronoi, DELAUNAY_DOC);
}

}  // namespace hmira_py
