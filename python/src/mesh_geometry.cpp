// python/src/mesh_geometry.cpp
// hmira.Mesh's geometry basics (bounds, area, volume, face normals and areas, unique edges,
// component labels and sub-meshes, vertex colours) and the construction paths that say what they
// repaired or refuse instead: reading a file with its repair report, and building from arrays
// without any repair. The measures are the library's (algorithms/geometry, algorithms/topology);
// this file only turns them into numpy arrays.
#include "mesh_binding.hpp"

#include <algorithm>
#include <array>
#include <initializer_list>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <optional>
#include <utility>
#include <vector>

#include <hmira/algorithms/geometry/face_normal.hpp>
#include <hmira/algorithms/geometry/mesh_measures.hpp>
#include <hmira/algorithms/topology/connected_components.hpp>
#include <hmira/io/mesh_io.hpp>

namespace hmira_py {

/// Builds `fresh` in one pass from an (m, k) int32/int64 face array (mesh.cpp); false for anything else.
bool assign_arrays(halfedge_mesh& fresh, const vertex_array& vertices, nb::handle faces);

namespace {

using color4 = std::array<std::uint8_t, 4>;  // the readers' "v:color" property (RGBA)
using f64_rows = nb::ndarray<nb::numpy, double, nb::ndim<2>>;

/// A numpy array of N dimensions that owns a C++ container (moved in, freed with the array).
template <class Scalar, std::size_t N, class Container>
nb::ndarray<nb::numpy, Scalar, nb::ndim<N>> owned(Container&& c, std::initializer_list<std::size_t> shape) {
    auto* held = new Container(std::move(c));
    nb::capsule owner(held, [](void* p) noexcept { delete static_cast<Container*>(p); });
    return nb::ndarray<nb::numpy, Scalar, nb::ndim<N>>(reinterpret_cast<Scalar*>(held->data()), shape, owner);
}

/// The bounding box as a (2, 3) array [min, max]; (0, 3) for a mesh without vertices.
f64_rows bounds(const py_mesh& self) {
    const auto box = read_without_gil(self, [](const halfedge_mesh& m) { return hmira::mesh_bounds(m); });
    std::vector<double> out;
    if (box) out = {box->min.x, box->min.y, box->min.z, box->max.x, box->max.y, box->max.z};
    const std::size_t rows = box ? 2 : 0;
    return owned<double, 2>(std::move(out), {rows, 3});
}

/// Per face (in face order, as Mesh.faces): the unit normal and the area, from the library's
/// Newell area vector; a face of zero area gets the zero normal.
std::pair<std::vector<vec3<double>>, std::vector<double>> face_measures(const halfedge_mesh& m) {
    std::vector<vec3<double>> normals;
    std::vector<double> areas;
    normals.reserve(m.face_count());
    areas.reserve(m.face_count());
    for (auto f : m.faces()) {
        const auto a = hmira::face_area_vector(m, f);
        const double twice = std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
        areas.push_back(twice / 2);
        normals.push_back(twice > 0 ? vec3<double>{a.x / twice, a.y / twice, a.z / twice} : vec3<double>{});
    }
    return {std::move(normals), std::move(areas)};
}

f64_rows face_normals(const py_mesh& self) {
    auto n = read_without_gil(self, [](const halfedge_mesh& m) { return face_measures(m).first; });
    const std::size_t count = n.size();
    return owned<double, 2>(std::move(n), {count, 3});
}

nb::ndarray<nb::numpy, double, nb::ndim<1>> face_areas(const py_mesh& self) {
    auto a = read_without_gil(self, [](const halfedge_mesh& m) { return face_measures(m).second; });
    const std::size_t count = a.size();
    return owned<double, 1>(std::move(a), {count});
}

/// Each edge once, as (k, 2) int32 vertex indices, the smaller first, in edge order.
nb::ndarray<nb::numpy, std::int32_t, nb::ndim<2>> edges(const py_mesh& self) {
    auto e = read_without_gil(self, [](const halfedge_mesh& m) {
        std::vector<std::array<std::int32_t, 2>> out;
        out.reserve(m.edge_count());
        for (auto edge : m.edges()) {
            const auto [a, b] = m.edge_vertices(edge);
            const auto i = static_cast<std::int32_t>(a.index), j = static_cast<std::int32_t>(b.index);
            out.push_back(i < j ? std::array{i, j} : std::array{j, i});
        }
        return out;
    });
    const std::size_t count = e.size();
    return owned<std::int32_t, 2>(std::move(e), {count, 2});
}

/// The library's component labels, per face (in face order) and the count of components that have faces,
/// renumbered 0 .. count-1 in order of their lowest vertex index.
std::pair<nb::ndarray<nb::numpy, std::int32_t, nb::ndim<1>>, std::size_t> face_components(const py_mesh& self) {
    auto labels = read_without_gil(self, [](const halfedge_mesh& m) {
        const auto c = hmira::connected_components(m);
        std::vector<std::int32_t> renumber(c.count, -1), out;
        out.reserve(m.face_count());
        std::int32_t next = 0;
        // Components in order of their lowest vertex index: the library numbers them so.
        for (auto f : m.faces()) {
            const auto l = c.face_component[f.index];
            out.push_back(static_cast<std::int32_t>(l));
        }
        std::vector<char> used(c.count, 0);
        for (auto l : out) used[std::size_t(l)] = 1;
        for (std::size_t l = 0; l < c.count; ++l)
            if (used[l]) renumber[l] = next++;
        for (auto& l : out) l = renumber[std::size_t(l)];
        return std::pair{std::move(out), std::size_t(next)};
    });
    const std::size_t count = labels.first.size();
    return {owned<std::int32_t, 1>(std::move(labels.first), {count}), labels.second};
}

/// Replaces self by the faces of `other` listed in `chosen` (face order indices, increasing), with only
/// the vertices they use, renumbered in index order; vertex colours and normals read from a file follow.
void assign_faces(py_mesh& self, const py_mesh& other, const std::vector<long long>& chosen) {
    auto fresh = read_without_gil(other, [&](const halfedge_mesh& m) {
        std::vector<hmira::face_handle> order;
        order.reserve(m.face_count());
        for (auto f : m.faces()) order.push_back(f);
        hmira::io::polygon_soup soup;
        std::vector<std::int64_t> new_index(m.vertex_index_bound(), -1);
        std::vector<hmira::vertex_handle> kept;
        for (long long i : chosen) {
            if (i < 0 || std::size_t(i) >= order.size()) return std::optional<halfedge_mesh>();
            for (auto v : m.face_vertices(order[std::size_t(i)])) {
                if (new_index[v.index] < 0) {
                    new_index[v.index] = std::int64_t(kept.size());
                    kept.push_back(v);
                }
                soup.indices.push_back(static_cast<std::uint32_t>(new_index[v.index]));
            }
            soup.face_offsets.push_back(soup.indices.size());
        }
        // Renumber in index order (the order Mesh.vertices lists them in).
        std::vector<hmira::vertex_handle> sorted = kept;
        std::ranges::sort(sorted, {}, [](hmira::vertex_handle v) { return v.index; });
        std::vector<std::uint32_t> final_index(kept.size());
        for (std::size_t k = 0; k < sorted.size(); ++k)
            final_index[std::size_t(new_index[sorted[k].index])] = static_cast<std::uint32_t>(k);
        for (auto& c : soup.indices) c = final_index[c];
        const auto colors = m.get_vertex_property<color4>("v:color");
        const auto normals = m.get_vertex_property<vec3<float>>("v:normal");
        for (auto v : sorted) {
            const auto p = m.position(v);
            soup.points.push_back({double(p.x), double(p.y), double(p.z)});
            if (colors) soup.attributes.colors.push_back((*colors)[v]);
            if (normals) soup.attributes.normals.push_back((*normals)[v]);
        }
        halfedge_mesh out;
        auto built = hmira::io::assign_from_soup(out, soup, [](std::size_t) { return std::string("Mesh.split"); });
        if (!built) return std::optional<halfedge_mesh>();
        return std::optional<halfedge_mesh>(std::move(out));
    });
    if (!fresh) value_error("Mesh._assign_faces: a face index is out of range or the faces do not form a mesh");
    self.replace(std::move(*fresh));
}

/// Vertex colours read from a file (or set), as an (n, 4) uint8 RGBA array indexed like Mesh.vertices;
/// None when the mesh has none.
nb::object vertex_colors(const py_mesh& self) {
    const auto& m = self.get();
    const auto p = m.get_vertex_property<color4>("v:color");
    if (!p) return nb::none();
    std::vector<color4> out(m.vertex_index_bound(), color4{0, 0, 0, 0});
    for (auto v : m.vertices()) out[v.index] = (*p)[v];
    const std::size_t n = out.size();
    return nb::cast(owned<std::uint8_t, 2>(std::move(out), {n, 4}));
}

using color_array = nb::ndarray<const std::uint8_t, nb::ndim<2>, nb::c_contig, nb::device::cpu>;

void set_vertex_colors(py_mesh& self, const std::optional<color_array>& colors) {
    auto& m = self.get();
    self.refuse_while_in_use();
    if (!colors) {
        (void)m.remove_vertex_property("v:color");
        return;
    }
    const auto& c = *colors;
    if (c.shape(0) != m.vertex_index_bound() || (c.shape(1) != 3 && c.shape(1) != 4))
        value_error("Mesh.vertex_colors: expected an (" + std::to_string(m.vertex_index_bound()) +
                    ", 3) or (n, 4) uint8 array, got (" + std::to_string(c.shape(0)) + ", " +
                    std::to_string(c.shape(1)) + ")");
    auto p = m.get_vertex_property<color4>("v:color");
    auto prop = p ? *p : m.add_vertex_property<color4>("v:color", color4{255, 255, 255, 255});
    const std::size_t k = c.shape(1);
    for (auto v : m.vertices()) {
        const std::uint8_t* row = c.data() + v.index * k;
        prop[v] = {row[0], row[1], row[2], k == 4 ? row[3] : std::uint8_t{255}};
    }
}

/// Reads a file with the library's reader, repairing (as the CLI's editing commands do) or refusing what
/// a half-edge mesh cannot hold; returns the one-line summary of the repair ("" when nothing was repaired).
std::string read_reported(py_mesh& self, const std::string& path, bool weld_stl, bool repair) {
    halfedge_mesh fresh;
    hmira::result<hmira::io::read_report> r = hmira::fail(hmira::errc::invalid_argument, "");
    {
        nb::gil_scoped_release release;
        cpp_timer timer;
        hmira::io::read_options options;
        options.weld_stl = weld_stl;
        options.repair = repair;
        r = hmira::io::read_mesh(fresh, path, options);
    }
    check(r);
    self.replace(std::move(fresh));
    return r->repair.clean() ? std::string() : r->repair.summary();
}

/// Replaces the content by (vertices, faces). Without `repair`, exactly as given, so a non-manifold
/// (pinched vertex included) or inconsistently oriented input is refused with the element named; with
/// it, through the readers' repair. Returns the repair's one-line summary ("" when nothing was repaired).
std::string set_polygons_checked(py_mesh& self, const vertex_array& vertices, nb::handle faces, bool repair,
                                 const char* who) {
    {
        // A clean (m, k) array builds in one pass, in place: nothing to refuse or repair.
        halfedge_mesh fresh;
        if (assign_arrays(fresh, vertices, faces)) {
            self.replace(std::move(fresh));
            return {};
        }
    }
    auto soup = to_soup(vertices, faces, who);
    halfedge_mesh fresh;
    std::string summary;
    hmira::error failure{};
    bool ok = true;
    {
        nb::gil_scoped_release release;
        if (repair) {
            hmira::io::read_options options;
            options.repair = true;
            auto built = hmira::io::build_from_soup(fresh, std::move(soup), who, options);
            if (built && !built->repair.clean()) summary = built->repair.summary();
            if (!built) ok = false, failure = built.error();
        } else {
            auto built = fresh.assign_polygons(std::span<const std::array<double, 3>>(soup.points),
                                               std::span<const std::uint64_t>(soup.face_offsets),
                                               std::span<const std::uint32_t>(soup.indices));
            if (!built) ok = false, failure = built.error();
        }
    }
    if (!ok) value_error(repair ? failure.message : std::string(who) + ": " + failure.message);
    self.replace(std::move(fresh));
    return summary;
}

}  // namespace

void bind_mesh_geometry(nb::class_<py_mesh>& c) {
    c.def("bounds", &bounds, "The bounding box as a (2, 3) float64 array [min, max]; (0, 3) without vertices.")
        .def(
            "area",
            [](const py_mesh& s) {
                return read_without_gil(s, [](const halfedge_mesh& m) { return hmira::surface_area(m); });
            },
            "The total area of the faces.")
        .def(
            "volume",
            [](const py_mesh& s) {
                return read_without_gil(s, [](const halfedge_mesh& m) { return hmira::signed_volume(m); });
            },
            "The signed enclosed volume (divergence theorem): positive for a closed mesh wound counter-clockwise "
            "seen from outside, negative when inside-out.")
        .def("face_normals", &face_normals, "Unit face normals (m, 3) in face order; zero for a face of zero area.")
        .def("face_areas", &face_areas, "Face areas (m,) in face order.")
        .def("edges", &edges, "Each edge once as (k, 2) int32 vertex indices, the smaller index first.")
        .def("_face_components", &face_components,
             "(labels per face, count): connected components that have faces, numbered by lowest vertex index.")
        .def("_assign_faces", &assign_faces, nb::arg("other"), nb::arg("faces"),
             "Replaces the content by the listed faces of `other` and the vertices they use.")
        .def_prop_ro("_vertex_colors", &vertex_colors, "Vertex colours (n, 4) uint8, or None.")
        .def("_set_vertex_colors", &set_vertex_colors, nb::arg("colors").none(),
             "Sets (n, 3) or (n, 4) uint8 vertex colours; None removes them.")
        .def("_read_reported", &read_reported, nb::arg("path"), nb::kw_only(), nb::arg("weld_stl"), nb::arg("repair"),
             "Replaces the content by a file's; returns the repair summary ('' when nothing was repaired).")
        .def(
            "_set_polygons_checked",
            [](py_mesh& s, const vertex_array& v, nb::handle f, bool repair) {
                return set_polygons_checked(s, v, f, repair, "Mesh");
            },
            nb::arg("vertices"), nb::arg("faces"), nb::kw_only(), nb::arg("repair"),
            "Replaces the content by (vertices, faces): refused with the element named unless repair, which "
            "returns the repair summary.");
}

}  // namespace hmira_py
