// python/src/spatial.cpp
// hmira.BVH (a bvh over a Mesh, for repeated batched queries) and Mesh.closest_point /
// Mesh.ray_intersect (one tree per call). Queries take (n, 3) float64 or float32 arrays and
// run with the GIL released; answers come back as numpy arrays.
#include "mesh_binding.hpp"

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <hmira/algorithms/spatial/bvh.hpp>

namespace hmira_py {

namespace {

using any_array = nb::ndarray<nb::ro, nb::ndim<2>, nb::device::cpu>;
using b8 = nb::ndarray<nb::numpy, bool>;

/// Rows of an (n, 3) float64 or float32 array as points (any strides). Called with the GIL held
/// for the checks; the copy itself runs in the caller's GIL-free section.
struct rows {
    const void* data = nullptr;
    bool single = false;
    std::size_t n = 0;
    std::int64_t s0 = 0, s1 = 0;

    rows(const any_array& a, const char* who, const char* name) {
        if (a.shape(1) != 3)
            value_error(std::string(who) + ": " + name + " must have shape (n, 3), got (" + std::to_string(a.shape(0)) +
                        ", " + std::to_string(a.shape(1)) + ")");
        if (a.dtype() == nb::dtype<double>())
            single = false;
        else if (a.dtype() == nb::dtype<float>())
            single = true;
        else
            value_error(std::string(who) + ": " + name + " must be float64 or float32");
        data = a.data();
        n = a.shape(0);
        s0 = a.stride(0);
        s1 = a.stride(1);
    }
    std::vector<vec3<double>> read() const {
        std::vector<vec3<double>> out(n);
        for (std::size_t i = 0; i < n; ++i) {
            const auto at = [&](std::size_t k) {
                const std::int64_t e = std::int64_t(i) * s0 + std::int64_t(k) * s1;
                return single ? double(static_cast<const float*>(data)[e]) : static_cast<const double*>(data)[e];
            };
            out[i] = {at(0), at(1), at(2)};
        }
        return out;
    }
};

hmira::bvh_nan_policy nan_arg(const std::string& nan, const char* who) {
    if (nan == "raise") return hmira::bvh_nan_policy::refuse;
    if (nan == "propagate") return hmira::bvh_nan_policy::propagate;
    value_error(std::string(who) + ": nan must be 'raise' or 'propagate', got '" + nan + "'");
}

/// A bvh over a Mesh, with what it was built from: the mesh (kept alive) and its version.
struct py_bvh {
    nb::object owner;
    const py_mesh* mesh = nullptr;
    std::uint64_t version = 0;
    hmira::bvh tree;

    /// Refuses a mesh changed since the build: the binding's version (bumped by every change of
    /// connectivity made through Mesh methods), then the library's own check.
    void check_fresh(const char* who) const {
        if (mesh->version != version)
            throw hmira_failure(hmira::errc::invalid_argument,
                                std::string(who) + ": the mesh changed since its BVH was built: rebuild the BVH");
        mesh->refuse_while_writing();
        check(hmira::detail::bvh_build::check_fresh<halfedge_mesh, hmira::default_traits<halfedge_mesh>>(*mesh->mesh,
                                                                                                         tree, who));
    }
};

hmira::bvh build(const py_mesh& m, const char* who) {
    if (m.get().face_count() == 0) value_error(std::string(who) + ": the mesh has no faces");
    return take(read_without_gil(m, [](const halfedge_mesh& mesh) { return hmira::build_bvh(mesh); }));
}

nb::tuple closest(const hmira::bvh& tree, const any_array& points, double max_distance, unsigned threads,
                  const std::string& nan, const char* who) {
    const rows in(points, who, "points");
    const hmira::closest_point_options o{.max_distance = max_distance, .threads = threads, .nan = nan_arg(nan, who)};
    std::vector<double> p, b, d;
    std::vector<std::int64_t> f;
    auto r = [&] {
        nb::gil_scoped_release release;
        cpp_timer timer;
        const auto q = in.read();
        auto found = tree.closest_points(q, o);
        if (!found) return hmira::result<void>(found.error());
        const std::size_t n = q.size();
        p.resize(3 * n), b.resize(3 * n), d.resize(n), f.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            const auto& c = (*found)[i];
            for (std::size_t k = 0; k < 3; ++k) p[3 * i + k] = c.point[k], b[3 * i + k] = c.barycentric[k];
            d[i] = c.distance;
            f[i] = c.found() ? std::int64_t(c.face) : -1;
        }
        return hmira::result<void>();
    }();
    check(r);
    const std::size_t n = d.size();
    return nb::make_tuple(adopt<double>(std::move(p), {n, 3}), adopt<std::int64_t>(std::move(f), {n}),
                          adopt<double>(std::move(b), {n, 3}), adopt<double>(std::move(d), {n}));
}

/// mode "first": (t, faces, barycentrics, points); mode "any": a bool array.
nb::object intersect(const hmira::bvh& tree, const any_array& origins, const any_array& directions,
                     const std::string& mode, unsigned threads, const std::string& nan, const char* who) {
    if (mode != "first" && mode != "any")
        value_error(std::string(who) + ": mode must be 'first' or 'any', got '" + mode + "'");
    const rows o(origins, who, "origins"), d(directions, who, "directions");
    if (o.n != d.n)
        value_error(std::string(who) + ": " + std::to_string(o.n) + " origins but " + std::to_string(d.n) +
                    " directions");
    const hmira::ray_query_options opt{.threads = threads, .nan = nan_arg(nan, who)};
    const std::size_t n = o.n;
    std::vector<double> t, b, p;
    std::vector<std::int64_t> f;
    std::vector<std::uint8_t> any;
    auto r = [&] {
        nb::gil_scoped_release release;
        cpp_timer timer;
        const auto a = o.read(), dd = d.read();
        std::vector<hmira::ray> rays(n);
        for (std::size_t i = 0; i < n; ++i) rays[i] = {.origin = a[i], .direction = dd[i]};
        if (mode == "any") {
            auto h = tree.any_hits(rays, opt);
            if (!h) return hmira::result<void>(h.error());
            any = std::move(*h);
            return hmira::result<void>();
        }
        auto h = tree.first_hits(rays, opt);
        if (!h) return hmira::result<void>(h.error());
        t.resize(n), f.resize(n), b.resize(3 * n), p.resize(3 * n);
        for (std::size_t i = 0; i < n; ++i) {
            const auto& x = (*h)[i];
            t[i] = x.t;
            f[i] = x.found() ? std::int64_t(x.face) : -1;
            for (std::size_t k = 0; k < 3; ++k) b[3 * i + k] = x.barycentric[k], p[3 * i + k] = x.point[k];
        }
        return hmira::result<void>();
    }();
    check(r);
    if (mode == "any") {
        auto* owned = new std::vector<std::uint8_t>(std::move(any));
        nb::capsule holder(owned, [](void* q) noexcept { delete static_cast<std::vector<std::uint8_t>*>(q); });
        return nb::cast(b8(reinterpret_cast<bool*>(owned->data()), {n}, holder));
    }
    return nb::make_tuple(adopt<double>(std::move(t), {n}), adopt<std::int64_t>(std::move(f), {n}),
                          adopt<double>(std::move(b), {n, 3}), adopt<double>(std::move(p), {n, 3}));
}

constexpr const char* closest_doc = R"(The closest surface point to each query point.

Parameters
----------
points : ndarray, shape (n, 3), float64 or float32
max_distance : float
    Look no farther; a point with nothing that close gets face -1 and distance inf.
threads : int
    Worker threads (0: all). The answers do not depend on it.
nan : {'raise', 'propagate'}
    A query with a NaN or infinite coordinate raises ValueError naming its index, or gets NaN
    point and distance and face -1.

Returns
-------
points : ndarray (n, 3) float64
faces : ndarray (n,) int64
    The face each point lies on (-1 if none).
barycentrics : ndarray (n, 3) float64
    Weights on the corners of the triangle of that face's triangulation the point lies on.
distances : ndarray (n,) float64
)";

constexpr const char* ray_doc = R"(Intersects rays origin + t * direction (t >= 0) with the surface.

Parameters
----------
origins, directions : ndarray, shape (n, 3), float64 or float32
mode : {'first', 'any'}
    'first': the nearest hit of each ray; 'any': whether it hits at all (occlusion, faster).
threads : int
    Worker threads (0: all).
nan : {'raise', 'propagate'}
    A ray with a non-finite coordinate raises ValueError naming its index, or gets a NaN t.

Returns
-------
mode 'first': (t, faces, barycentrics, points): t (n,) (inf for a miss), faces (n,) int64
(-1 for a miss), barycentrics (n, 3), points (n, 3). mode 'any': a bool array (n,).
Degenerate (zero-area) triangles are never hit.
)";

std::string with_example(const char* doc, const char* example) {
    return std::string(doc) + "\nBuilds a BVH on every call: keep an hmira.BVH to query the same mesh again.\n\n" +
           "Examples\n--------\n>>> import hmira, numpy as np\n" +
           ">>> m = hmira.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])\n" + example;
}

}  // namespace

void bind_mesh_spatial(nb::class_<py_mesh>& c) {
    const hmira::closest_point_options defaults;
    // Docstrings live as long as the module.
    static const std::string closest_mesh_doc =
        with_example(closest_doc,
                     ">>> points, faces, bary, dist = m.closest_point(np.array([[0.2, 0.2, 1.0]]))\n"
                     ">>> faces.tolist(), dist.tolist()\n([0], [1.0])\n");
    static const std::string ray_mesh_doc = with_example(
        ray_doc,
        ">>> t, faces, bary, points = m.ray_intersect(np.array([[0.2, 0.2, 1.0]]), np.array([[0.0, 0.0, -1.0]]))\n"
        ">>> t.tolist(), faces.tolist()\n([1.0], [0])\n");
    c.def(
         "closest_point",
         [](const py_mesh& s, const any_array& points, double max_distance, unsigned threads, const std::string& nan) {
             const auto tree = build(s, "closest_point");
             return closest(tree, points, max_distance, threads, nan, "closest_point");
         },
         nb::arg("points"), nb::kw_only(), nb::arg("max_distance") = defaults.max_distance,
         nb::arg("threads") = defaults.threads, nb::arg("nan") = "raise", closest_mesh_doc.c_str())
        .def(
            "ray_intersect",
            [](const py_mesh& s, const any_array& origins, const any_array& directions, const std::string& mode,
               unsigned threads, const std::string& nan) {
                const auto tree = build(s, "ray_intersect");
                return intersect(tree, origins, directions, mode, threads, nan, "ray_intersect");
            },
            nb::arg("origins"), nb::arg("directions"), nb::kw_only(), nb::arg("mode") = "first",
            nb::arg("threads") = 0u, nb::arg("nan") = "raise", ray_mesh_doc.c_str());
}

void bind_spatial(nb::module_& m) {
    nb::class_<py_bvh>(
        m, "BVH",
        "A bounding-volume hierarchy over a Mesh's faces (polygons triangulated in their plane), for\n"
        "repeated batched closest-point and ray queries.\n\n"
        "The tree copies the triangles; a query after the mesh's connectivity changed raises\n"
        "ValueError. Positions moved in place (through Mesh.vertices) are not detected: call refit().\n\n"
        "Parameters\n----------\nmesh : Mesh\n    A mesh with at least one face.\n\n"
        "Examples\n--------\n>>> import hmira, numpy as np\n"
        ">>> m = hmira.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])\n"
        ">>> bvh = hmira.BVH(m)\n"
        ">>> bvh.closest_point(np.array([[0.2, 0.2, 1.0]]))[3].tolist()\n[1.0]\n")
        .def(
            "__init__",
            [](py_bvh* self, nb::handle mesh) {
                const auto& m = nb::cast<const py_mesh&>(mesh);
                new (self) py_bvh{nb::borrow(mesh), &m, m.version, build(m, "BVH")};
            },
            nb::arg("mesh"))
        .def_prop_ro(
            "triangle_count", [](const py_bvh& b) { return b.tree.size(); }, "Number of triangles in the tree.")
        .def(
            "refit",
            [](py_bvh& b) {
                b.check_fresh("BVH.refit");
                check(read_without_gil(*b.mesh,
                                       [&](const halfedge_mesh& mesh) { return hmira::refit_bvh(mesh, b.tree); }));
            },
            "Recomputes the boxes from the mesh's current positions (after moving vertices), keeping the tree.")
        .def(
            "closest_point",
            [](const py_bvh& b, const any_array& points, double max_distance, unsigned threads,
               const std::string& nan) {
                b.check_fresh("BVH.closest_point");
                return closest(b.tree, points, max_distance, threads, nan, "BVH.closest_point");
            },
            nb::arg("points"), nb::kw_only(), nb::arg("max_distance") = std::numeric_limits<double>::infinity(),
            nb::arg("threads") = 0u, nb::arg("nan") = "raise", closest_doc)
        .def(
            "ray_intersect",
            [](const py_bvh& b, const any_array& origins, const any_array& directions, const std::string& mode,
               unsigned threads, const std::string& nan) {
                b.check_fresh("BVH.ray_intersect");
                return intersect(b.tree, origins, directions, mode, threads, nan, "BVH.ray_intersect");
            },
            nb::arg("origins"), nb::arg("directions"), nb::kw_only(), nb::arg("mode") = "first",
            nb::arg("threads") = 0u, nb::arg("nan") = "raise", ray_doc);
}

}  // namespace hmira_py
