// python/src/intersections.cpp
// Mesh.self_intersections: the pairs of faces that intersect other than along what they share,
// decided exactly in C++ with the GIL released (Ctrl-C stops it).
#include "mesh_binding.hpp"

#include <cstdint>

#include <hmira/algorithms/validation/self_intersections.hpp>

namespace hmira_py {

void bind_mesh_intersections(nb::class_<py_mesh>& c) {
    c.def(
        "self_intersections",
        [](const py_mesh& s) {
            interrupt_watch watch;
            auto r = read_without_gil(s, [&](const halfedge_mesh& m) {
                return hmira::self_intersections(m, {.progress = watch.callback()});
            });
            watch.rethrow();
            const auto pairs = take(std::move(r));
            std::vector<std::int64_t> flat;
            flat.reserve(2 * pairs.size());
            for (const auto& p : pairs) {
                flat.push_back(std::int64_t(p[0]));
                flat.push_back(std::int64_t(p[1]));
            }
            return adopt<std::int64_t>(std::move(flat), {pairs.size(), 2});
        },
        "The pairs of faces that intersect other than along a shared edge or vertex (touching, crossing, folded or "
        "overlapping in one plane), decided exactly: a (k, 2) int64 array of face indices, each row (f, g) with "
        "f < g, rows sorted. Polygon faces are tested by their triangles.\n\n"
        "Examples\n--------\n"
        ">>> import numpy as np, hmira\n"
        ">>> v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [.2, .2, -1], [.3, .2, 1], [.2, .3, 1]], float)\n"
        ">>> hmira.Mesh(v, [[0, 1, 2], [3, 4, 5]]).self_intersections().tolist()\n"
        "[[0, 1]]");
}

}  // namespace hmira_py
