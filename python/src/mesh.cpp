// python/src/mesh.cpp
// hmira.Mesh: a polygon mesh backed by hmira::halfedge_mesh, with its positions exported as a
// numpy view. The mesh lives behind a shared_ptr that every exported view also holds, and a
// topology change first moves the mesh away from storage a view still uses (copy on write), so
// a view can go stale but never points at freed memory; the Python wrapper (hmira.VertexView)
// compares the version it was made at and raises once it is stale.
#include "common.hpp"

#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <hmira/algorithms/decimation/decimate.hpp>
#include <hmira/algorithms/editing/editing.hpp>
#include <hmira/algorithms/euler/euler.hpp>
#include <hmira/algorithms/geometry/vertex_normals.hpp>
#include <hmira/algorithms/holes/fill_hole.hpp>
#include <hmira/algorithms/remeshing/isotropic_remeshing.hpp>
#include <hmira/algorithms/smoothing/laplacian_smooth.hpp>
#include <hmira/algorithms/geometry/sharp_edges.hpp>
#include <hmira/algorithms/subdivision/subdivide.hpp>
#include <hmira/algorithms/triangle/triangle.hpp>
#include <hmira/algorithms/triangulation/triangulate_faces.hpp>
#include <hmira/algorithms/orientation/flip_normals.hpp>
#include <hmira/algorithms/topology/mesh_topology.hpp>
#include <hmira/algorithms/validation/validate.hpp>
#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

namespace hmira_py {

hmira::io::polygon_soup to_soup(const nb::ndarray<const double, nb::ndim<2>, nb::c_contig, nb::device::cpu>& vertices,
                                nb::handle faces, const char* who);
hmira::io::write_options write_options_from(bool ascii, bool big_endian, bool float32, bool attributes);

namespace {

using hmira::halfedge_mesh;
using hmira::vec3;

/// A mesh for Python: new elements always append (no reuse of deleted slots), so an int handle
/// held in Python stays invalid after its element is deleted, until collect_garbage(), as the
/// Euler operators' docstrings say; copies keep the setting.
std::shared_ptr<halfedge_mesh> appending_mesh(halfedge_mesh&& m = {}) {
    m.set_slot_reuse(false);
    return std::make_shared<halfedge_mesh>(std::move(m));
}

struct py_mesh {
    std::shared_ptr<halfedge_mesh> mesh = appending_mesh();
    /// Bumped by every change that may move or renumber the positions.
    std::uint64_t version = 0;
    /// Calls running with the GIL released: readers of the mesh, and at most one writer (then
    /// no reader). Read and changed only with the GIL held, so plain counters suffice; another
    /// thread's call on a mesh in use raises instead of racing with it.
    mutable int readers = 0;
    bool writing = false;

    halfedge_mesh& get() {
        refuse_while_writing();
        return *mesh;
    }
    const halfedge_mesh& get() const {
        refuse_while_writing();
        return *mesh;
    }
    void refuse_while_writing() const {
        if (writing) throw std::runtime_error("Mesh: another thread is changing this mesh (a call on it is still running)");
    }
    void refuse_while_in_use() const {
        refuse_while_writing();
        if (readers > 0) throw std::runtime_error("Mesh: another thread is reading this mesh (a call on it is still running)");
    }

    /// Call before a topology change: a view exported earlier keeps the old storage.
    halfedge_mesh& for_topology_change() {
        refuse_while_in_use();
        if (mesh.use_count() > 1) mesh = std::make_shared<halfedge_mesh>(*mesh);
        ++version;
        return *mesh;
    }
    void replace(halfedge_mesh&& fresh) {
        refuse_while_in_use();
        mesh = appending_mesh(std::move(fresh));
        ++version;
    }
};

/// Compacts after an edit so that vertex and face indices stay dense (0 .. n-1), as the CLI
/// writes them; returns nothing the caller needs.
void compact(halfedge_mesh& m) { (void)m.collect_garbage(); }

/// Runs `read(mesh)` with the GIL released (the mesh is marked as being read meanwhile).
template <class Read>
auto read_without_gil(const py_mesh& self, Read&& read) {
    const auto keep = std::shared_ptr<const halfedge_mesh>(self.mesh);
    self.refuse_while_writing();
    struct reading {
        const py_mesh& s;
        explicit reading(const py_mesh& m) : s(m) { ++s.readers; }
        ~reading() { --s.readers; }
    } mark(self);
    nb::gil_scoped_release release;
    return read(*keep);
}

/// Runs `change(mesh, progress)` with the GIL released, Ctrl-C watched through `progress`
/// (the change must pass it to the C++ options) and the mesh marked as being written. The
/// storage is first moved away from exported views when `topology` is set. A Ctrl-C raises
/// KeyboardInterrupt (the change, cancelled, has rolled back); an error raises ValueError.
template <class Change>
auto change_without_gil(py_mesh& self, bool topology, Change&& change) {
    halfedge_mesh& m = topology ? self.for_topology_change() : (self.refuse_while_in_use(), *self.mesh);
    interrupt_watch watch;
    struct writing {
        py_mesh& s;
        explicit writing(py_mesh& m) : s(m) { s.writing = true; }
        ~writing() { s.writing = false; }
    } mark(self);
    auto r = [&] {
        nb::gil_scoped_release release;
        cpp_timer timer;
        const bool had_garbage = m.has_garbage();
        auto done = change(m, watch.callback());
        // A rolled-back edit leaves what it made as garbage after the live elements: dropping
        // it gives back the same dense indices (unless the mesh had garbage of its own).
        if (!done && !had_garbage) compact(m);
        return done;
    }();
    watch.rethrow();
    return take(std::move(r));
}

using vertex_array = nb::ndarray<const double, nb::ndim<2>, nb::c_contig, nb::device::cpu>;

hmira::vertex_handle vertex_arg(const halfedge_mesh& m, long long i, const char* who) {
    if (i < 0 || std::size_t(i) >= m.vertex_index_bound() || !m.is_valid(hmira::vertex_handle(std::size_t(i))))
        value_error(std::string(who) + ": vertex " + std::to_string(i) + " does not exist");
    return hmira::vertex_handle(std::size_t(i));
}
hmira::face_handle face_arg(const halfedge_mesh& m, long long i, const char* who) {
    if (i < 0 || std::size_t(i) >= m.face_index_bound() || !m.is_valid(hmira::face_handle(std::size_t(i))))
        value_error(std::string(who) + ": face " + std::to_string(i) + " does not exist");
    return hmira::face_handle(std::size_t(i));
}
hmira::halfedge_handle halfedge_arg(const halfedge_mesh& m, long long i, const char* who) {
    if (i < 0 || std::size_t(i) >= m.halfedge_index_bound() || !m.is_valid(hmira::halfedge_handle(std::size_t(i))))
        value_error(std::string(who) + ": halfedge " + std::to_string(i) + " does not exist");
    return hmira::halfedge_handle(std::size_t(i));
}
vec3<double> point_arg(const std::vector<double>& p, const char* who) {
    if (p.size() != 3 || !std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
        value_error(std::string(who) + ": position must be 3 finite numbers");
    return {p[0], p[1], p[2]};
}
long long idx(auto h) { return h.index == UINT32_MAX ? -1 : static_cast<long long>(h.index); }

void set_polygons(py_mesh& self, const vertex_array& vertices, nb::handle faces) {
    const auto soup = to_soup(vertices, faces, "Mesh");
    halfedge_mesh fresh;
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
    nb::list out;
    const auto& m = self.get();
    for (auto f : m.faces()) {
        nb::list poly;
        for (auto v : m.face_vertices(f)) poly.append(static_cast<long long>(v.index));
        out.append(poly);
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
        if (count == 0) k = n;
        else if (n != k)
            value_error("Mesh.faces: face " + std::to_string(f.index) + " has " + std::to_string(n) + " corners, face 0 has " +
                        std::to_string(k) + "; use Mesh.polygons for mixed polygons");
        ++count;
    }
    auto* owned = new std::vector<std::int32_t>(std::move(out));
    nb::capsule owner(owned, [](void* p) noexcept { delete static_cast<std::vector<std::int32_t>*>(p); });
    return nb::ndarray<nb::numpy, std::int32_t, nb::ndim<2>>(owned->data(), {count, k}, owner);
}

struct topology {
    std::size_t vertices, edges, faces, components, boundary_loops, boundary_edges, isolated_vertices, non_manifold_edges;
    long long genus, euler_characteristic;
    bool closed;
};

topology topology_of(const py_mesh& self) {
    const auto s = read_without_gil(self, [](const halfedge_mesh& m) { return hmira::mesh_topology(m); });
    return {s.vertices, s.edges, s.faces, s.components, s.boundary_loops, s.boundary_edges, s.isolated_vertices,
            s.non_manifold_edges, s.genus, s.euler_characteristic, s.closed()};
}

std::vector<std::string> validate(const py_mesh& self, bool relaxed) {
    std::vector<std::string> out;
    auto problems = read_without_gil(self, [&](const halfedge_mesh& m) {
        return hmira::validate(m, {.relaxed = relaxed, .check_geometry = true, .max_problems = 1000});
    });
    for (auto& p : problems)
        out.push_back(std::move(p.message));
    return out;
}

nb::ndarray<nb::numpy, double, nb::ndim<2>> normals(const py_mesh& self, const std::string& weighting) {
    hmira::vertex_normal_options o;
    if (weighting == "angle") o.weighting = hmira::normal_weighting::angle;
    else if (weighting == "area") o.weighting = hmira::normal_weighting::area;
    else value_error("vertex_normals: weighting must be 'angle' or 'area', got '" + weighting + "'");
    auto n = read_without_gil(self, [&](const halfedge_mesh& m) { return hmira::vertex_normals(m, o); });
    const std::size_t count = n.size();
    auto* owned = new std::vector<vec3<double>>(std::move(n));
    nb::capsule owner(owned, [](void* p) noexcept { delete static_cast<std::vector<vec3<double>>*>(p); });
    return nb::ndarray<nb::numpy, double, nb::ndim<2>>(reinterpret_cast<double*>(owned->data()), {count, 3}, owner);
}


nb::dict truncate(py_mesh& self, std::optional<std::vector<long long>> vertices, bool all, std::optional<double> fraction,
                  std::optional<double> distance) {
    auto& m0 = self.get();
    if (all == vertices.has_value()) value_error("truncate: give vertices or all=True (one of them)");
    std::vector<hmira::vertex_handle> vs;
    if (all) for (auto v : m0.vertices()) vs.push_back(v);
    else for (long long i : *vertices) vs.push_back(vertex_arg(m0, i, "truncate"));
    // truncate() is atomic: on error or Ctrl-C the mesh is unchanged.
    const auto r = change_without_gil(self, true, [&](halfedge_mesh& m, hmira::progress_function progress) {
        const hmira::truncate_options o{.fraction = fraction.value_or(1.0 / 3.0), .distance = distance.value_or(0.0),
                                        .progress = std::move(progress)};
        auto made = hmira::truncate(m, vs, o);
        if (made) compact(m);
        return made;
    });
    nb::dict d;
    d["faces"] = r.faces.size();
    d["vertices"] = r.vertices.size();
    return d;
}

nb::dict bevel(py_mesh& self, std::optional<std::vector<std::pair<long long, long long>>> edges, bool all, std::optional<double> angle,
               double width, int segments, bool no_clamp, std::optional<std::vector<long long>> vertices, bool vertices_all) {
    auto& m0 = self.get();
    const int ways = int(edges.has_value()) + int(all) + int(angle.has_value()) + int(vertices.has_value()) + int(vertices_all);
    if (ways != 1) value_error("bevel: choose edges, all=True or angle=DEG, or vertices / vertices_all=True (exactly one)");
    std::vector<hmira::vertex_handle> vs;
    std::vector<hmira::edge_handle> es;
    const bool vertex_mode = vertices || vertices_all;
    if (vertex_mode) {
        if (vertices_all) for (auto v : m0.vertices()) vs.push_back(v);
        else for (long long i : *vertices) vs.push_back(vertex_arg(m0, i, "bevel"));
    } else {
        if (edges) {
            for (auto [a, b] : *edges) {
                const auto h = m0.find_halfedge(vertex_arg(m0, a, "bevel"), vertex_arg(m0, b, "bevel"));
                if (!m0.is_valid(h)) value_error("bevel: no edge between vertices " + std::to_string(a) + " and " + std::to_string(b));
                es.push_back(m0.edge(h));
            }
        } else {
            es = hmira::sharp_edges(m0, angle ? *angle : 0.0);
            if (es.empty()) value_error(angle ? "bevel: no edge has a dihedral angle of at least " + std::to_string(*angle) + " degrees"
                                              : std::string("bevel: the mesh has no edge between two faces"));
        }
    }
    const auto b = change_without_gil(self, true, [&](halfedge_mesh& m, hmira::progress_function progress) {
        const hmira::bevel_options o{.width = width, .segments = segments, .clamp_overlap = !no_clamp, .clamp_globally = false,
                                     .progress = std::move(progress)};
        auto made = vertex_mode ? hmira::bevel_vertices(m, vs, o) : hmira::bevel(m, es, o);
        if (made) compact(m);
        return made;
    });
    nb::dict d;
    d["strip_faces"] = b.strip_faces.size();
    d["vertex_faces"] = b.vertex_faces.size();
    d["vertices"] = b.vertices.size();
    d["width"] = b.width;
    return d;
}

nb::dict extrude(py_mesh& self, std::optional<std::vector<long long>> faces, bool all, double distance,
                 std::optional<std::vector<double>> direction, const std::string& mode) {
    auto& m0 = self.get();
    if (all == faces.has_value()) value_error("extrude: give faces or all=True (one of them)");
    if (mode != "region" && mode != "individual") value_error("extrude: mode must be 'region' or 'individual', got '" + mode + "'");
    std::vector<hmira::face_handle> fs;
    if (all) for (auto f : m0.faces()) fs.push_back(f);
    else for (long long i : *faces) fs.push_back(face_arg(m0, i, "extrude"));
    std::optional<vec3<double>> towards;
    if (direction) towards = point_arg(*direction, "extrude: direction");
    const auto r = change_without_gil(self, true, [&](halfedge_mesh& m, hmira::progress_function progress) {
        const hmira::extrude_options o{.distance = distance, .direction = towards,
                                       .mode = mode == "individual" ? hmira::extrude_mode::individual : hmira::extrude_mode::region,
                                       .progress = std::move(progress)};
        auto made = hmira::extrude(m, fs, o);
        if (made) compact(m);
        return made;
    });
    nb::dict d;
    d["top_faces"] = r.top_faces.size();
    d["side_faces"] = r.side_faces.size();
    d["vertices"] = r.vertices.size();
    return d;
}

// ---- The everyday operations (issue 18): local triangle operators, triangulation, hole
// filling, subdivision, smoothing. Local operators change the mesh in place and keep deleted
// slots until collect_garbage(), as the Euler operators do; the whole-mesh operations run on a
// copy that replaces the mesh only on success, so an error leaves it unchanged.

std::optional<vec3<double>> optional_point(const std::optional<std::vector<double>>& p, const char* who) {
    if (!p) return std::nullopt;
    return point_arg(*p, who);
}

hmira::collapse_edge_options collapse_options(const std::string& placement, const std::optional<std::vector<double>>& position,
                                              bool check_geometry, const char* who) {
    hmira::collapse_edge_options o;
    o.check_geometry = check_geometry;
    if (placement == "midpoint") o.placement = hmira::collapse_placement::midpoint;
    else if (placement == "target") o.placement = hmira::collapse_placement::target;
    else if (placement == "source") o.placement = hmira::collapse_placement::source;
    else if (placement == "given") o.placement = hmira::collapse_placement::given;
    else value_error(std::string(who) + ": placement must be 'midpoint', 'target', 'source' or 'given', got '" + placement + "'");
    if ((o.placement == hmira::collapse_placement::given) != position.has_value())
        value_error(std::string(who) + ": give position exactly when placement='given'");
    if (position) o.position = point_arg(*position, who);
    return o;
}

hmira::fill_hole_options fill_options(std::size_t max_dynamic_programming_edges, bool refine, const std::string& fair, const char* who) {
    hmira::fill_hole_options o;
    o.max_dynamic_programming_edges = max_dynamic_programming_edges;
    if (fair == "none") o.fair = hmira::fairing::none;
    else if (fair == "membrane") o.fair = hmira::fairing::membrane;
    else if (fair == "thin-plate") o.fair = hmira::fairing::thin_plate;
    else value_error(std::string(who) + ": fair must be 'none', 'membrane' or 'thin-plate', got '" + fair + "'");
    o.refine = refine || o.fair != hmira::fairing::none;  // fairing moves the vertices refinement adds
    return o;
}

/// Runs a whole-mesh operation on a copy that replaces the mesh on success.
template <class Op>
auto on_copy(py_mesh& self, Op&& op) {
    return change_without_gil(self, true, [&](halfedge_mesh& m, const hmira::progress_function&) {
        halfedge_mesh work = m;
        auto r = op(work);
        if (r) {
            m = std::move(work);
            compact(m);
        }
        return r;
    });
}

/// The value of an option enum named by `name` (core/enum_names.hpp), or ValueError listing
/// the names.
template <hmira::named_enum E>
E enum_arg(const std::string& name, const char* who, const char* option) {
    if (const auto e = hmira::from_string<E>(name)) return *e;
    value_error(std::string(who) + ": unknown " + option + " '" + name + "' (supported: " + hmira::quoted_names<E>() + ")");
}

hmira::laplacian_weights weights_arg(const std::string& w, const char* who) {
    return enum_arg<hmira::laplacian_weights>(w, who, "weights");
}

std::vector<std::size_t> fixed_arg(const halfedge_mesh& m, const std::optional<std::vector<long long>>& fixed, const char* who) {
    std::vector<std::size_t> out;
    if (fixed)
        for (long long i : *fixed) out.push_back(vertex_arg(m, i, who).index);
    return out;
}

void bind_everyday(nb::class_<py_mesh>& c) {
    c.def("is_flip_ok", [](const py_mesh& s, long long h) {
             const auto hh = halfedge_arg(s.get(), h, "is_flip_ok");
             return read_without_gil(s, [&](const halfedge_mesh& m) { return hmira::is_flip_ok(m, hh); });
         }, nb::arg("halfedge"), "Whether flip_edge(halfedge) is allowed: two triangles on either side, no edge between the two opposite vertices yet.")
     .def("flip_edge", [](py_mesh& s, long long h) {
             const auto hh = halfedge_arg(s.get(), h, "flip_edge");
             const auto r = change_without_gil(s, true, [&](halfedge_mesh& m, const hmira::progress_function&) { return hmira::flip_edge(m, hh); });
             return idx(r.halfedge);
         }, nb::arg("halfedge"),
         "Turns the edge between two triangles to join their opposite vertices; returns the flipped halfedge. Its own inverse.")
     .def("split_edge", [](py_mesh& s, long long h, std::optional<std::vector<double>> position, bool split_triangles) {
             const auto hh = halfedge_arg(s.get(), h, "split_edge");
             const hmira::split_edge_options o{.position = optional_point(position, "split_edge"), .split_triangles = split_triangles};
             const auto r = change_without_gil(s, true, [&](halfedge_mesh& m, const hmira::progress_function&) { return hmira::split_edge(m, hh, o); });
             return nb::make_tuple(idx(r.vertex), idx(r.halfedge));
         }, nb::arg("halfedge"), nb::kw_only(), nb::arg("position") = nb::none(), nb::arg("split_triangles") = true,
         "A new vertex on the edge (at its midpoint by default), the triangles beside it split; returns (vertex, halfedge from the new "
         "vertex to the old target). collapse_edge(halfedge, placement='target') undoes it.")
     .def("split_face", [](py_mesh& s, long long f, std::optional<std::vector<double>> position) {
             const auto ff = face_arg(s.get(), f, "split_face");
             const hmira::split_face_options o{.position = optional_point(position, "split_face")};
             const auto r = change_without_gil(s, true, [&](halfedge_mesh& m, const hmira::progress_function&) { return hmira::split_face(m, ff, o); });
             return nb::make_tuple(idx(r.vertex), idx(r.halfedge));
         }, nb::arg("face"), nb::kw_only(), nb::arg("position") = nb::none(),
         "Splits a triangle into three at a new vertex (its centroid by default); returns (vertex, halfedge).")
     .def("is_collapse_ok", [](const py_mesh& s, long long h, const std::string& placement, std::optional<std::vector<double>> position,
                               bool check_geometry) {
             const auto hh = halfedge_arg(s.get(), h, "is_collapse_ok");
             const auto o = collapse_options(placement, position, check_geometry, "is_collapse_ok");
             return read_without_gil(s, [&](const halfedge_mesh& m) { return hmira::is_collapse_ok(m, hh, o); });
         }, nb::arg("halfedge"), nb::kw_only(), nb::arg("placement") = "midpoint", nb::arg("position") = nb::none(),
         nb::arg("check_geometry") = false,
         "Whether collapse_edge(halfedge) is allowed: the link condition and the boundary rules, and with check_geometry no face turned over.")
     .def("collapse_edge", [](py_mesh& s, long long h, const std::string& placement, std::optional<std::vector<double>> position,
                              bool check_geometry) {
             const auto hh = halfedge_arg(s.get(), h, "collapse_edge");
             const auto o = collapse_options(placement, position, check_geometry, "collapse_edge");
             const auto r = change_without_gil(s, true, [&](halfedge_mesh& m, const hmira::progress_function&) { return hmira::collapse_edge(m, hh, o); });
             return idx(r.vertex);
         }, nb::arg("halfedge"), nb::kw_only(), nb::arg("placement") = "midpoint", nb::arg("position") = nb::none(),
         nb::arg("check_geometry") = false,
         "Merges the halfedge's source into its target, which survives at `placement` ('midpoint', 'target', 'source' or 'given' "
         "with position); returns the surviving vertex. Deleted slots stay until collect_garbage().")
     .def("triangulate_faces", [](py_mesh& s, bool delaunay) {
             const auto r = on_copy(s, [&](halfedge_mesh& m) { return hmira::triangulate_faces(m, {.delaunay = delaunay}); });
             nb::dict d;
             d["faces_cut"] = r.faces_cut;
             d["triangles_added"] = r.triangles_added;
             return d;
         }, nb::kw_only(), nb::arg("delaunay") = false,
         "Triangulates every polygon (inner rings included, robust on concave faces); with delaunay=True each face's diagonals "
         "are its constrained Delaunay ones (largest smallest angle). Returns {'faces_cut', 'triangles_added'}.")
     .def("fill_hole", [](py_mesh& s, long long h, std::size_t max_dynamic_programming_edges, bool refine, const std::string& fair) {
             const auto hh = halfedge_arg(s.get(), h, "fill_hole");
             const auto o = fill_options(max_dynamic_programming_edges, refine, fair, "fill_hole");
             // A cancelled fill (Ctrl-C) is rolled back by fill_hole itself.
             const auto r = change_without_gil(s, true, [&](halfedge_mesh& m, const hmira::progress_function& progress) {
                 auto with_progress = o;
                 with_progress.progress = progress;
                 return hmira::fill_hole(m, hh, with_progress);
             });
             std::vector<long long> faces;
             for (auto f : r.faces) faces.push_back(idx(f));
             return faces;
         }, nb::arg("boundary_halfedge"), nb::kw_only(), nb::arg("max_dynamic_programming_edges") = 200, nb::arg("refine") = false,
         nb::arg("fair") = "none",
         "Closes the boundary loop of a boundary halfedge with triangles (minimal area, maximal dihedral, Liepa 2003); with refine=True "
         "the patch is refined to the edge length around the hole, and fair='membrane' or 'thin-plate' (implies refine) smooths it. "
         "Returns the new faces.")
     .def("fill_holes", [](py_mesh& s, std::size_t max_size, std::size_t max_dynamic_programming_edges, bool refine, const std::string& fair) {
             const auto o = fill_options(max_dynamic_programming_edges, refine, fair, "fill_holes");
             // fill_holes rolls a cancelled run (Ctrl-C) back itself: the mesh is left as it was.
             const auto r = change_without_gil(s, true, [&](halfedge_mesh& m, const hmira::progress_function& progress) {
                 auto with_progress = o;
                 with_progress.progress = progress;
                 auto done = hmira::fill_holes(m, max_size, with_progress);
                 if (done) compact(m);
                 return done;
             });
             nb::dict d;
             d["filled"] = r.filled;
             d["skipped"] = r.skipped;
             d["faces_added"] = r.faces_added;
             d["vertices_added"] = r.vertices_added;
             d["unfaired"] = r.unfaired;
             nb::list open;
             for (const auto& h : r.open) {
                 nb::dict e;
                 e["vertex"] = h.vertex;
                 e["edges"] = h.edges;
                 e["reason"] = h.reason == hmira::open_hole_reason::too_long
                                   ? "a loop of " + std::to_string(h.edges) + " edges > max_size " + std::to_string(max_size)
                                   : h.message;
                 open.append(e);
             }
             d["open"] = open;
             return d;
         }, nb::arg("max_size"), nb::kw_only(), nb::arg("max_dynamic_programming_edges") = 200, nb::arg("refine") = false,
         nb::arg("fair") = "none",
         "Fills every hole of at most max_size boundary edges (refine and fair as for fill_hole); returns {'filled', 'skipped', "
         "'faces_added', 'vertices_added', 'unfaired', 'open'}, 'open' listing each hole left open as {'vertex', 'edges', "
         "'reason'}. Ctrl-C stops it with the mesh unchanged.")
     .def("subdivide", [](py_mesh& s, const std::string& scheme, std::size_t levels) {
             const auto chosen = enum_arg<hmira::subdivision_scheme>(scheme, "subdivide", "scheme");
             // The schemes leave the mesh unchanged on error and restore it on Ctrl-C (progress).
             const auto r = change_without_gil(s, true, [&](halfedge_mesh& m, hmira::progress_function progress) {
                 auto done = hmira::subdivide(m, {.scheme = chosen, .levels = levels, .progress = std::move(progress)});
                 if (done) compact(m);
                 return done;
             });
             nb::dict d;
             d["vertices"] = r.vertices;
             d["edges"] = r.edges;
             d["faces"] = r.faces;
             return d;
         }, nb::kw_only(), nb::arg("scheme") = std::string(hmira::to_string(hmira::subdivide_options{}.scheme)),
         nb::arg("levels") = hmira::subdivide_options{}.levels,
         "Subdivides `levels` times with `scheme`: 'loop' or 'sqrt3' (triangle meshes) or 'catmull-clark' (any\n"
         "polygon mesh), boundaries included; returns the counts after the last level. 'sqrt3' refines the\n"
         "boundary on every second level of a call, so give it an even `levels` for a smooth boundary.\n\n"
         ">>> m = hmira.Mesh([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], [[0, 1, 2, 3]])\n"
         ">>> m.subdivide(scheme='catmull-clark')\n"
         "{'vertices': 9, 'edges': 12, 'faces': 4}")
     .def("laplacian_smooth", [](py_mesh& s, std::size_t iterations, double lambda, const std::string& weights, bool fix_boundary,
                                 std::optional<std::vector<long long>> fixed_vertices) {
             hmira::laplacian_smooth_options o{.iterations = iterations, .lambda = lambda,
                                               .weights = weights_arg(weights, "laplacian_smooth"),
                                                     .fix_boundary = fix_boundary, .fixed_vertices = fixed_arg(s.get(), fixed_vertices, "laplacian_smooth")};
             // Positions move in place: the vertices view stays valid and sees them move.
             // Ctrl-C cancels through the progress hook; the smoother then restores every position.
             return change_without_gil(s, false, [&](halfedge_mesh& m, hmira::progress_function progress) {
                        o.progress = std::move(progress);
                        return hmira::laplacian_smooth(m, o);
                    }).moved;
         }, nb::kw_only(), nb::arg("iterations") = 1, nb::arg("lambda_") = 0.5, nb::arg("weights") = "uniform", nb::arg("fix_boundary") = true,
         nb::arg("fixed_vertices") = nb::none(),
         "Laplacian smoothing (uniform or cotangent weights, step lambda_ in (0, 1]); returns the number of vertices free to move.")
     .def("taubin_smooth", [](py_mesh& s, std::size_t iterations, double lambda, double mu, const std::string& weights, bool fix_boundary,
                              std::optional<std::vector<long long>> fixed_vertices) {
             hmira::taubin_smooth_options o{.iterations = iterations, .lambda = lambda, .mu = mu,
                                            .weights = weights_arg(weights, "taubin_smooth"),
                                                  .fix_boundary = fix_boundary, .fixed_vertices = fixed_arg(s.get(), fixed_vertices, "taubin_smooth")};
             return change_without_gil(s, false, [&](halfedge_mesh& m, hmira::progress_function progress) {
                        o.progress = std::move(progress);
                        return hmira::taubin_smooth(m, o);
                    }).moved;
         }, nb::kw_only(), nb::arg("iterations") = 10, nb::arg("lambda_") = 0.5, nb::arg("mu") = -0.53, nb::arg("weights") = "uniform",
         nb::arg("fix_boundary") = true, nb::arg("fixed_vertices") = nb::none(),
         "Taubin lambda/mu smoothing (keeps the volume); returns the number of vertices free to move.");
}

// ---- decimate (issue 19): one self-contained block --------------------------------------------
void bind_decimate(nb::class_<py_mesh>& c) {
    c.def("decimate", [](py_mesh& s, std::optional<std::size_t> target_faces, std::optional<double> target_ratio,
                         std::optional<double> max_error, bool keep_boundary, double max_normal_angle, double max_aspect_ratio,
                         std::optional<std::vector<long long>> locked_vertices) {
            hmira::decimate_options o{.target_faces = target_faces, .target_ratio = target_ratio, .max_error = max_error,
                                      .keep_boundary = keep_boundary, .max_normal_angle = max_normal_angle,
                                      .max_aspect_ratio = max_aspect_ratio, .locked_vertices = fixed_arg(s.get(), locked_vertices, "decimate")};
            const auto r = change_without_gil(s, true, [&](halfedge_mesh& m, hmira::progress_function progress) {
                o.progress = std::move(progress);  // Ctrl-C cancels; decimate then restores the mesh
                auto done = hmira::decimate(m, o);
                if (done) compact(m);
                return done;
            });
            nb::dict d;
            d["faces"] = r.faces;
            d["vertices"] = r.vertices;
            d["collapses"] = r.collapses;
            d["triangulated"] = r.triangulated;
            d["stopped_by"] = r.stopped_by == hmira::decimate_stop::target_faces ? "target_faces"
                              : r.stopped_by == hmira::decimate_stop::max_error ? "max_error"
                                                                                 : "constraints";
            d["error"] = r.error;
            d["note"] = r.note;
            return d;
        }, nb::kw_only(), nb::arg("target_faces") = nb::none(), nb::arg("target_ratio") = nb::none(), nb::arg("max_error") = nb::none(),
        nb::arg("keep_boundary") = true, nb::arg("max_normal_angle") = 90.0,
        nb::arg("max_aspect_ratio") = std::numeric_limits<double>::infinity(), nb::arg("locked_vertices") = nb::none(),
        "Quadric error decimation (Garland-Heckbert) until the first target reached: target_faces, target_ratio\n"
        "(of the faces) or max_error (a distance). Polygons are triangulated first. Boundary vertices stay\n"
        "unless keep_boundary=False; locked_vertices never move. Returns {'faces', 'vertices', 'collapses',\n"
        "'triangulated', 'stopped_by', 'error', 'note'}; vertices are renumbered densely afterwards.\n\n"
        ">>> m = hmira.Mesh([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0.5, 0.5, 0]],\n"
        "...                [[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]])\n"
        ">>> m.decimate(target_faces=2)['faces']\n"
        "2");
}

// ---- Isotropic remeshing (issue 19): Mesh.remesh, on a copy (the library works on one) that
// replaces the mesh on success; Ctrl-C cancels through the progress hook.
void bind_remesh(nb::class_<py_mesh>& c) {
    c.def("remesh", [](py_mesh& s, std::optional<double> target_edge_length, std::size_t iterations, std::optional<double> feature_angle,
                       std::optional<std::vector<long long>> feature_edges) {
             std::vector<std::size_t> features;
             if (feature_edges)
                 for (long long e : *feature_edges) {
                     if (e < 0) value_error("remesh: feature_edges names edge " + std::to_string(e) + ", which does not exist");
                     features.push_back(std::size_t(e));
                 }
             const auto r = change_without_gil(s, true, [&](halfedge_mesh& m, hmira::progress_function progress) {
                 double length = target_edge_length.value_or(0.0);
                 if (!target_edge_length) {  // the mean edge length, or why the mesh has none to use
                     const auto mean = hmira::default_target_edge_length(m);
                     if (!mean) return hmira::result<hmira::isotropic_remeshing_result>(mean.error());
                     length = *mean;
                 }
                 auto done = hmira::isotropic_remeshing(m, {.target_edge_length = length, .iterations = iterations,
                                                            .feature_angle = feature_angle, .feature_edges = features,
                                                            .progress = std::move(progress)});
                 if (done) compact(m);
                 return done;
             });
             nb::dict d;
             d["splits"] = r.splits;
             d["collapses"] = r.collapses;
             d["flips"] = r.flips;
             d["feature_edges"] = r.feature_edges;
             return d;
         }, nb::kw_only(), nb::arg("target_edge_length") = nb::none(),
         nb::arg("iterations") = hmira::isotropic_remeshing_options{}.iterations, nb::arg("feature_angle") = nb::none(),
         nb::arg("feature_edges") = nb::none(),
         "Isotropic remeshing of a triangle mesh towards target_edge_length (default: the mean edge length):\n"
         "`iterations` rounds of split, collapse, flip and tangential relaxation with projection onto the input.\n"
         "The boundary is kept, and so are edges sharper than feature_angle degrees and the edges listed in\n"
         "feature_edges (edge indices). Returns {'splits', 'collapses', 'flips', 'feature_edges'}.\n\n"
         ">>> m = hmira.Mesh([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], [[0, 1, 2], [0, 2, 3]])\n"
         ">>> m.remesh(target_edge_length=0.25)['feature_edges']\n"
         "4");
}

constexpr const char* MESH_DOC = R"doc(A polygon mesh backed by hmira's half-edge mesh (the compiled part of
hmira.Mesh; use hmira.Mesh, which adds the checked `vertices` view).)doc";

}  // namespace

void bind_mesh(nb::module_& m) {
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
                   ", components=" + std::to_string(t.components) + ", boundary_loops=" + std::to_string(t.boundary_loops) + ")";
        });

    auto core = nb::class_<py_mesh>(m, "MeshCore", MESH_DOC, nb::is_weak_referenceable());
    bind_everyday(core);
    bind_decimate(core);
    bind_remesh(core);
    core
        .def(nb::init<>(), "An empty mesh.")
        .def("_set_polygons", &set_polygons, nb::arg("vertices"), nb::arg("faces"),
             "Replaces the content by (vertices, faces); faces an (m, k) integer array or a sequence of polygons.")
        .def("_read", &read, nb::arg("path"), nb::kw_only(), nb::arg("weld_stl") = true, "Replaces the content by a mesh file's.")
        .def("_assign", [](py_mesh& self, const py_mesh& other) {
                 self.replace(read_without_gil(other, [](const halfedge_mesh& m) { return halfedge_mesh(m); }));
             }, nb::arg("other"),
             "Replaces the content by a copy of `other`'s.")
        .def("_positions", &positions, "The positions as a writable (n, 3) float64 view (unchecked; see Mesh.vertices).")
        .def_prop_ro("_topology_version", [](const py_mesh& s) { return s.version; }, "Bumped by every topology change.")
        .def("write", &write, nb::arg("path"), nb::kw_only(), nb::arg("ascii") = false, nb::arg("big_endian") = false,
             nb::arg("float32") = false, nb::arg("attributes") = true,
             R"doc(Write the mesh to a file (OBJ, OFF, PLY or STL by extension), atomically.

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
        .def_prop_ro("vertex_count", [](const py_mesh& s) { return s.get().vertex_count(); }, "Live vertices.")
        .def_prop_ro("edge_count", [](const py_mesh& s) { return s.get().edge_count(); }, "Live edges.")
        .def_prop_ro("face_count", [](const py_mesh& s) { return s.get().face_count(); }, "Live faces.")
        .def_prop_ro("faces", &faces, nb::rv_policy::automatic, "Faces as an (m, k) int32 array (ValueError when faces differ in size).")
        .def_prop_ro("polygons", &polygons, nb::rv_policy::automatic, "Faces as a list of vertex-index lists.")
        .def("topology", &topology_of, "V, E, F, genus, components and boundary loops (a Topology).")
        .def("validate", &validate, nb::kw_only(), nb::arg("relaxed") = false,
             "The mesh's problems, one message each; an empty list for a valid mesh.")
        .def("flip", [](py_mesh& s) {
                 // The positions do not move: views stay valid (no topology change for them).
                 return change_without_gil(s, false, [](halfedge_mesh& m, const hmira::progress_function&) {
                     return hmira::result<std::size_t>(hmira::flip_normals(m));
                 });
             }, "Reverse every face's winding; returns the faces flipped.")
        .def("vertex_normals", &normals, nb::kw_only(), nb::arg("weighting") = "angle",
             "Unit vertex normals (n, 3), faces weighted by corner angle ('angle') or area ('area').")
        .def("collect_garbage", [](py_mesh& s) {
                 change_without_gil(s, true, [](halfedge_mesh& m, const hmira::progress_function&) {
                     compact(m);
                     return hmira::result<bool>(true);
                 });
             },
             "Drop deleted elements and renumber densely (after kill operators).")
        .def("_truncate", &truncate, nb::arg("vertices") = nb::none(), nb::kw_only(), nb::arg("all") = false,
             nb::arg("fraction") = nb::none(), nb::arg("distance") = nb::none())
        .def("_bevel", &bevel, nb::arg("edges") = nb::none(), nb::kw_only(), nb::arg("all") = false, nb::arg("angle") = nb::none(),
             nb::arg("width") = 0.1, nb::arg("segments") = 1, nb::arg("no_clamp") = false, nb::arg("vertices") = nb::none(),
             nb::arg("vertices_all") = false)
        .def("_extrude", &extrude, nb::arg("faces") = nb::none(), nb::kw_only(), nb::arg("all") = false, nb::arg("distance") = 1.0,
             nb::arg("direction") = nb::none(), nb::arg("mode") = "region")
        // ---- Euler operators: handles as ints; kill operators leave deleted slots until collect_garbage()
        .def("find_halfedge", [](const py_mesh& s, long long a, long long b) {
                 const auto& m = s.get();
                 return idx(m.find_halfedge(vertex_arg(m, a, "find_halfedge"), vertex_arg(m, b, "find_halfedge")));
             }, nb::arg("a"), nb::arg("b"), "The halfedge from vertex a to vertex b, or -1.")
        .def("make_vertex", [](py_mesh& s, const std::vector<double>& p) {
                 const auto q = point_arg(p, "make_vertex");
                 return idx(hmira::make_vertex(s.for_topology_change(), q).vertex);
             }, nb::arg("position"), "makeV: a new isolated vertex; returns its index.")
        .def("make_edge_vertex", [](py_mesh& s, long long corner, const std::vector<double>& p) {
                 const auto q = point_arg(p, "make_edge_vertex");
                 const auto h = halfedge_arg(s.get(), corner, "make_edge_vertex");
                 auto r = take(hmira::make_edge_vertex(s.for_topology_change(), h, q));
                 return nb::make_tuple(idx(r.vertex), idx(r.halfedge));
             }, nb::arg("corner"), nb::arg("position"),
             "makeEV: a new vertex joined to target(corner); returns (vertex, halfedge from the old vertex to the new).")
        .def("kill_edge_vertex", [](py_mesh& s, long long h) {
                 const auto hh = halfedge_arg(s.get(), h, "kill_edge_vertex");
                 auto r = take(hmira::kill_edge_vertex(s.for_topology_change(), hh));
                 return nb::make_tuple(idx(r.vertex), idx(r.corner), nb::make_tuple(r.position.x, r.position.y, r.position.z));
             }, nb::arg("halfedge"), "killEV: removes the edge and its degree-1 target; returns (vertex, corner, position) for the redo.")
        .def("make_edge_face", [](py_mesh& s, long long h0, long long h1) {
                 const auto a = halfedge_arg(s.get(), h0, "make_edge_face"), b = halfedge_arg(s.get(), h1, "make_edge_face");
                 auto r = take(hmira::make_edge_face(s.for_topology_change(), a, b));
                 return nb::make_tuple(idx(r.halfedge), idx(r.face));
             }, nb::arg("h0"), nb::arg("h1"), "makeEF: splits a face by an edge from target(h0) to target(h1); returns (halfedge, face).")
        .def("kill_edge_face", [](py_mesh& s, long long h) {
                 const auto hh = halfedge_arg(s.get(), h, "kill_edge_face");
                 auto r = take(hmira::kill_edge_face(s.for_topology_change(), hh));
                 return nb::make_tuple(idx(r.face), idx(r.h0), idx(r.h1));
             }, nb::arg("halfedge"), "killEF: removes the edge, merging its two faces; returns (face, h0, h1) for make_edge_face.");
}

}  // namespace hmira_py
