// python/src/euler.cpp
// Mesh's Euler operators, with handles as ints: the make operators add elements, the kill
// operators leave deleted slots until collect_garbage(), so a handle held in Python stays
// invalid rather than naming another element.
#include "mesh_binding.hpp"

#include <nanobind/stl/tuple.h>

#include <tuple>
#include <utility>

#include <hmira/algorithms/euler/euler.hpp>

namespace hmira_py {

void bind_mesh_euler(nb::class_<py_mesh>& c) {
    c.def(
         "find_halfedge",
         [](const py_mesh& s, long long a, long long b) {
             const auto& m = s.get();
             return idx(m.find_halfedge(vertex_arg(m, a, "find_halfedge"), vertex_arg(m, b, "find_halfedge")));
         },
         nb::arg("a"), nb::arg("b"), "The halfedge from vertex a to vertex b, or -1.")
        .def(
            "make_vertex",
            [](py_mesh& s, const std::vector<double>& p) {
                const auto q = point_arg(p, "make_vertex");
                return idx(hmira::make_vertex(s.for_topology_change(), q).vertex);
            },
            nb::arg("position"), "makeV: a new isolated vertex; returns its index.")
        .def(
            "make_edge_vertex",
            [](py_mesh& s, long long corner, const std::vector<double>& p) {
                const auto q = point_arg(p, "make_edge_vertex");
                const auto h = halfedge_arg(s.get(), corner, "make_edge_vertex");
                auto r = take(hmira::make_edge_vertex(s.for_topology_change(), h, q));
                return std::pair{idx(r.vertex), idx(r.halfedge)};
            },
            nb::arg("corner"), nb::arg("position"),
            "makeEV: a new vertex joined to target(corner); returns (vertex, halfedge from the old vertex to the new).")
        .def(
            "kill_edge_vertex",
            [](py_mesh& s, long long h) {
                const auto hh = halfedge_arg(s.get(), h, "kill_edge_vertex");
                auto r = take(hmira::kill_edge_vertex(s.for_topology_change(), hh));
                return std::tuple{idx(r.vertex), idx(r.corner), std::tuple{r.position.x, r.position.y, r.position.z}};
            },
            nb::arg("halfedge"),
            "killEV: removes the edge and its degree-1 target; returns (vertex, corner, position) for the redo.")
        .def(
            "make_edge_face",
            [](py_mesh& s, long long h0, long long h1) {
                const auto a = halfedge_arg(s.get(), h0, "make_edge_face"),
                           b = halfedge_arg(s.get(), h1, "make_edge_face");
                auto r = take(hmira::make_edge_face(s.for_topology_change(), a, b));
                return std::pair{idx(r.halfedge), idx(r.face)};
            },
            nb::arg("h0"), nb::arg("h1"),
            "makeEF: splits a face by an edge from target(h0) to target(h1); returns (halfedge, face).")
        .def(
            "kill_edge_face",
            [](py_mesh& s, long long h) {
                const auto hh = halfedge_arg(s.get(), h, "kill_edge_face");
                auto r = take(hmira::kill_edge_face(s.for_topology_change(), hh));
                return std::tuple{idx(r.face), idx(r.h0), idx(r.h1)};
            },
            nb::arg("halfedge"),
            "killEF: removes the edge, merging its two faces; returns (face, h0, h1) for make_edge_face.");
}

}  // namespace hmira_py
