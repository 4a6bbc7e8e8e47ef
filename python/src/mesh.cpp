// python/src/mesh.cpp
// hmira.Mesh: a polygon mesh backed by hmira::halfedge_mesh, with its positions exported as a
// numpy view. The mesh lives behind a shared_ptr that every exported view also holds, and a
// topology change first moves the mesh away from storage a view still uses (copy on write), so
// a view can go stale but never points at freed memory; the Python wrapper (hmira.VertexView)
// compares the version it was made at and raises once it is stale. This file binds the class,
// its contents, I/O and queries; each algorithm family adds its methods from its own file.
#include "mesh_binding.hpp"

#include <cmath>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include <hmira/algorithms/geometry/vertex_normals.hpp>
#include <hmira/algorithms/orientation/flip_normals.hpp>
#include <hmira/algorithms/topology/mesh_topology.hpp>
#include <hmira/algorithms/validation/validate.hpp>
#include <hmira/io/mesh_io.hpp>

namespace hmira_py {

void bind_mesh_geometry(nb::class_<py_mesh>& c);

namespace {

/// Builds `fresh` in one pass (halfedge_mesh::assign_polygons) from an (n, 3) float64 array and
/// an (m, k) integer array, read in place with the GIL released; the positions are moved into
/// the mesh, not copied again. False, `fresh` untouched, for anything else (a sequence of
/// polygons, a non-finite coordinate, an index out of range, a soup the one-pass build refuses):
/// the caller then takes the readers' soup path, which reports the problem as it always has.
template <class Index>
bool assign_rows(halfedge_mesh& fresh, const vertex_array& vertices,
                 const nb::ndarray<const Index, nb::ndim<2>, nb::c_contig, nb::device::cpu>& faces) {
    const std::size_t nv = vertices.shape(0), m = faces.shape(0), k = faces.shape(1);
    if (vertices.shape(1) != 3 || nv > 0xffffffffu || m * k >= 0xffffffffu) return false;
    nb::gil_scoped_release release;
    cpp_timer timer;
    const double* v = vertices.data();
    std::vector<vec3<double>> points;
    points.reserve(nv);
    bool ok = true;
    for (std::size_t i = 0; i < nv; ++i) {
        points.push_back({v[3 * i], v[3 * i + 1], v[3 * i + 2]});
        ok &= std::isfinite(v[3 * i]) & std::isfinite(v[3 * i + 1]) & std::isfinite(v[3 * i + 2]);
    }
    if (!ok) return false;
    std::vector<std::uint32_t> offsets(m + 1);
    for (std::size_t i = 0; i <= m; ++i) offsets[i] = static_cast<std::uint32_t>(i * k);
    const Index* f = faces.data();
    if constexpr (std::is_same_v<Index, std::int32_t>) {
        // Read in place (int32 and uint32 may alias): with fewer than 2^31 vertices a negative
        // index reads as 2^31 or more, past every vertex, which the build refuses as out of range.
        if (nv <= 0x7fffffffu)
            return bool(fresh.assign_polygons(
                points, std::span<const std::uint32_t>(offsets),
                std::span<const std::uint32_t>(reinterpret_cast<const std::uint32_t*>(f), m * k)));
    }
    std::vector<std::uint32_t> corners(m * k);
    for (std::size_t c = 0; c < m * k; ++c) {
        ok &= f[c] >= 0 && std::uint64_t(f[c]) < nv;
        corners[c] = static_cast<std::uint32_t>(f[c]);
    }
    if (!ok) return false;
    return bool(fresh.assign_polygons(points, std::span<const std::uint32_t>(offsets),
                                      std::span<const std::uint32_t>(corners)));
}

}  // namespace

/// assign_rows when `faces` is an int32 or int64 (m, k) array (not a list or a tuple).
bool assign_arrays(halfedge_mesh& fresh, const vertex_array& vertices, nb::handle faces) {
    if (nb::isinstance<nb::list>(faces) || nb::isinstance<nb::tuple>(faces)) return false;
    nb::ndarray<const std::int32_t, nb::ndim<2>, nb::c_contig, nb::device::cpu> narrow;
    if (nb::try_cast(faces, narrow, false)) return assign_rows(fresh, vertices, narrow);
    nb::ndarray<const std::int64_t, nb::ndim<2>, nb::c_contig, nb::device::cpu> wide;
    if (nb::try_cast(faces, wide, false)) return assign_rows(fresh, vertices, wide);
    return false;
}

namespace {

void set_polygons(py_mesh& self, const vertex_array& vertices, nb::handle faces) {
    halfedge_mesh fresh;
    // A clean (m, k) array builds in one pass; the one-pass build gives the very mesh the soup
    // path's add_face calls give for every soup it takes (io/detail/polygon_soup.hpp).
    if (assign_arrays(fresh, vertices, faces)) {
        self.replace(std::move(fresh));
        return;
    }
    const auto soup = to_soup(vertices, faces, "Mesh");
    hmira::result<void> built;
    {
        // The readers' own soup-to-mesh path, so construction gets whatever repair they do.
        nb::gil_scoped_release release;
        built = hmira::io::assign_from_soup(fresh, soup, [](std::size_t) { return std::string("Mesh"); });
    }
    check(built);
    self.replace(std::move(fresh));
}

void read(py_mesh& self, const std::string& path, bool weld_stl) {
    halfedge_mesh fresh;
    hmira::result<hmira::io::read_report> r = hmira::fail(hmira::errc::invalid_argument, "");
    {
        nb::gil_scoped_release release;
        cpp_timer timer;
        hmira::io::read_options options;
        options.weld_stl = weld_stl;
        r = hmira::io::read_mesh(fresh, path, options);
    }
    check(r);
    self.replace(std::move(fresh));
}

void write(const py_mesh& self, const std::string& path, bool ascii, bool big_endian, bool float32, bool attributes) {
    const auto options = write_options_from(ascii, big_endian, float32, attributes);
    check(read_without_gil(self, [&](const halfedge_mesh& m) { return hmira::io::write_mesh(m, path, options); }));
}

nb::ndarray<nb::numpy, double, nb::ndim<2>> positions(py_mesh& self) {
    auto* keep = new std::shared_ptr<halfedge_mesh>(self.mesh);
    nb::capsule owner(keep, [](void* p) noexcept { delete static_cast<std::shared_ptr<halfedge_mesh>*>(p); });
    const auto span = self.get().positions();
    static_assert(sizeof(vec3<double>) == 3 * sizeof(double));
    // The mesh is not const (only the accessor is): writing through the view moves vertices.
    auto* data = const_cast<double*>(reinterpret_cast<const double*>(span.data()));
    return nb::ndarray<nb::numpy, double, nb::ndim<2>>(data, {span.size(), 3}, owner);
}

nb::list polygons(const py_mesh& self) {
    const auto& m = self.get();
    // Lists made at their final size and filled in place: one pass, no appends.
    nb::list out = nb::steal<nb::list>(PyList_New(Py_ssize_t(m.face_count())));
    std::vector<long long> corners;
    Py_ssize_t k = 0;
    for (auto f : m.faces()) {
        corners.clear();
        for (auto v : m.face_vertices(f)) corners.push_back(static_cast<long long>(v.index));
        PyObject* poly = PyList_New(Py_ssize_t(corners.size()));
        if (!poly) throw nb::python_error();
        for (std::size_t c = 0; c < corners.size(); ++c) {
            PyObject* i = PyLong_FromLongLong(corners[c]);
            if (!i) {
                Py_DECREF(poly);
                throw nb::python_error();
            }
            PyList_SET_ITEM(poly, Py_ssize_t(c), i);
        }
        PyList_SET_ITEM(out.ptr(), k++, poly);
    }
    return out;
}

nb::ndarray<nb::numpy, std::int32_t, nb::ndim<2>> faces(const py_mesh& self) {
    const auto& m = self.get();
    std::vector<std::int32_t> out;
    std::size_t k = 0, count = 0;
    for (auto f : m.faces()) {
        std::size_t n = 0;
        for (auto v : m.face_vertices(f)) {
            out.push_back(static_cast<std::int32_t>(v.index));
            ++n;
        }
        if (count == 0)
            k = n;
        else if (n != k)
            value_error("Mesh.faces: face " + std::to_string(f.index) + " has " + std::to_string(n) +
                        " corners, face 0 has " + std::to_string(k) + "; use Mesh.polygons for mixed polygons");
        ++count;
    }
    auto* owned = new std::vector<std::int32_t>(std::move(out));
    nb::capsule owner(owned, [](void* p) noexcept { delete static_cast<std::vector<std::int32_t>*>(p); });
    return nb::ndarray<nb::numpy, std::int32_t, nb::ndim<2>>(owned->data(), {count, k}, owner);
}

struct topology {
    std::size_t vertices, edges, faces, components, boundary_loops, boundary_edges, isolated_vertices,
        non_manifold_edges;
    long long genus, euler_characteristic;
    bool closed;
};

topology topology_of(const py_mesh& self) {
    const auto s = read_without_gil(self, [](const halfedge_mesh& m) { return hmira::mesh_topology(m); });
    return {s.vertices,
            s.edges,
            s.faces,
            s.components,
            s.boundary_loops,
            s.boundary_edges,
            s.isolated_vertices,
            s.non_manifold_edges,
            s.genus,
            s.euler_characteristic,
            s.closed()};
}

std::vector<std::string> validate(const py_mesh& self, bool relaxed) {
    std::vector<std::string> out;
    auto problems = read_without_gil(self, [&](const halfedge_mesh& m) {
        hmira::validate_options o;
        o.relaxed = relaxed;
        return hmira::validate(m, o);
    });
    for (auto& p : problems) out.push_back(std::move(p.message));
    return out;
}

nb::ndarray<nb::numpy, double, nb::ndim<2>> normals(const py_mesh& self, const std::string& weighting) {
    hmira::vertex_normal_options o;
    o.weighting = choice_arg<hmira::normal_weighting>(weighting, "vertex_normals", "weighting");
    auto n = read_without_gil(self, [&](const halfedge_mesh& m) { return hmira::vertex_normals(m, o); });
    const std::size_t count = n.size();
    auto* owned = new std::vector<vec3<double>>(std::move(n));
    nb::capsule owner(owned, [](void* p) noexcept { delete static_cast<std::vector<vec3<double>>*>(p); });
    return nb::ndarray<nb::numpy, double, nb::ndim<2>>(reinterpret_cast<double*>(owned->data()), {count, 3}, owner);
}

constexpr const char* MESH_DOC = R"doc(A polygon mesh backed by hmira's half-edge mesh (the compiled part of
hmira.Mesh; use hmira.Mesh, which adds the checked `vertices` view).)doc";

void bind_topology(nb::module_& m) {
    nb::class_<topology>(m, "Topology", "Counts of a mesh's elements and its topological invariants.")
        .def_ro("vertices", &topology::vertices, "live vertices")
        .def_ro("edges", &topology::edges, "edges")
        .def_ro("faces", &topology::faces, "faces")
        .def_ro("genus", &topology::genus, "total genus of the surface components")
        .def_ro("components", &topology::components, "connected components, isolated vertices included")
        .def_ro("boundary_loops", &topology::boundary_loops, "closed chains of boundary edges")
        .def_ro("boundary_edges", &topology::boundary_edges, "edges with one face")
        .def_ro("isolated_vertices", &topology::isolated_vertices, "vertices used by no face")
        .def_ro("non_manifold_edges", &topology::non_manifold_edges, "edges with more than two faces")
        .def_ro("euler_characteristic", &topology::euler_characteristic, "V - E + F")
        .def_ro("closed", &topology::closed, "no boundary and no non-manifold edge")
        .def("__repr__", [](const topology& t) {
            return "Topology(vertices=" + std::to_string(t.vertices) + ", edges=" + std::to_string(t.edges) +
                   ", faces=" + std::to_string(t.faces) + ", genus=" + std::to_string(t.genus) +
                   ", components=" + std::to_string(t.components) +
                   ", boundary_loops=" + std::to_string(t.boundary_loops) + ")";
        });
}

/// The class's own methods: construction, contents, I/O and the queries.
void bind_contents(nb::class_<py_mesh>& core) {
    const hmira::validate_options validate_defaults;
    const hmira::vertex_normal_options normal_defaults;
    core.def(nb::init<>(), "An empty mesh.")
        .def("_set_polygons", &set_polygons, nb::arg("vertices"), nb::arg("faces"),
             "Replaces the content by (vertices, faces); faces an (m, k) integer array or a sequence of polygons.")
        .def("_read", &read, nb::arg("path"), nb::kw_only(), nb::arg("weld_stl") = hmira::io::read_options{}.weld_stl,
             "Replaces the content by a mesh file's.")
        .def(
            "_assign",
            [](py_mesh& self, const py_mesh& other) {
                self.replace(read_without_gil(other, [](const halfedge_mesh& m) { return halfedge_mesh(m); }));
            },
            nb::arg("other"), "Replaces the content by a copy of `other`'s.")
        .def("_positions", &positions,
             "The positions as a writable (n, 3) float64 view (unchecked; see Mesh.vertices).")
        .def_prop_ro(
            "_topology_version", [](const py_mesh& s) { return s.version; }, "Bumped by every topology change.")
        .def("write", &write, nb::arg("path"), nb::kw_only(), nb::arg("ascii") = false, nb::arg("big_endian") = false,
             nb::arg("float32") = false, nb::arg("attributes") = hmira::io::write_options{}.write_attributes,
             R"doc(Write the mesh to a file (OBJ, OFF, PLY, STL, glTF .glb or .gltf by extension), atomically.

Parameters
----------
path : str
ascii : bool, keyword-only
    PLY/STL: text instead of binary.
big_endian : bool, keyword-only
    PLY: binary big endian.
float32 : bool, keyword-only
    PLY: 32-bit coordinates (default 64-bit).
attributes : bool, keyword-only
    Write per-vertex normals and colours read from a file.)doc")
        .def_prop_ro(
            "vertex_count", [](const py_mesh& s) { return s.get().vertex_count(); }, "Live vertices.")
        .def_prop_ro(
            "edge_count", [](const py_mesh& s) { return s.get().edge_count(); }, "Live edges.")
        .def_prop_ro(
            "face_count", [](const py_mesh& s) { return s.get().face_count(); }, "Live faces.")
        .def_prop_ro("faces", &faces, nb::rv_policy::automatic,
                     "Faces as an (m, k) int32 array (ValueError when faces differ in size).")
        .def_prop_ro("polygons", &polygons, nb::rv_policy::automatic, "Faces as a list of vertex-index lists.")
        .def("topology", &topology_of, "V, E, F, genus, components and boundary loops (a Topology).")
        .def("validate", &validate, nb::kw_only(), nb::arg("relaxed") = validate_defaults.relaxed,
             "The mesh's problems, one message each; an empty list for a valid mesh.")
        .def(
            "flip",
            [](py_mesh& s) {
                // The positions do not move: views stay valid (no topology change for them).
                return change_without_gil(s, false, [](halfedge_mesh& m, const hmira::progress_function&) {
                    return hmira::result<std::size_t>(hmira::flip_normals(m));
                });
            },
            "Reverse every face's winding; returns the faces flipped.")
        .def("vertex_normals", &normals, nb::kw_only(), nb::arg("weighting") = name_of(normal_defaults.weighting),
             "Unit vertex normals (n, 3), faces weighted by corner angle ('angle') or area ('area').")
        .def(
            "collect_garbage",
            [](py_mesh& s) {
                change_without_gil(s, true, [](halfedge_mesh& m, const hmira::progress_function&) {
                    compact(m);
                    return hmira::result<bool>(true);
                });
            },
            "Drop deleted elements and renumber densely (after kill operators).");
}

}  // namespace

void bind_mesh(nb::module_& m) {
    bind_topology(m);
    // The order of the calls is the order of the methods in the type stubs.
    auto core = nb::class_<py_mesh>(m, "MeshCore", MESH_DOC, nb::is_weak_referenceable());
    bind_mesh_triangle_operators(core);
    bind_mesh_triangulation(core);
    bind_mesh_holes(core);
    bind_mesh_subdivision(core);
    bind_mesh_smoothing(core);
    bind_mesh_decimation(core);
    bind_mesh_remeshing(core);
    bind_contents(core);
    bind_mesh_editing(core);
    bind_mesh_euler(core);
    bind_mesh_intersections(core);
    bind_mesh_spatial(core);
    bind_mesh_geometry(core);  // bounds, area, volume, edges, split (mesh_geometry.cpp)
    bind_mesh_queries(core);
}

}  // namespace hmira_py
