// python/src/mesh_binding.hpp
// What the files binding hmira.Mesh's methods share: the mesh behind a MeshCore (py_mesh),
// running a read or a change with the GIL released, and checking element indices and points
// given from Python. mesh.cpp binds the class itself and calls each family's bind_mesh_<family>
// in the order the methods appear in the type stubs.
#pragma once

#include "common.hpp"

#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <hmira/meshes/halfedge_mesh.hpp>

namespace hmira_py {

using hmira::halfedge_mesh;
using hmira::vec3;

/// A mesh for Python: new elements always append (no reuse of deleted slots), so an int handle
/// held in Python stays invalid after its element is deleted, until collect_garbage(), as the
/// Euler operators' docstrings say; copies keep the setting.
inline std::shared_ptr<halfedge_mesh> appending_mesh(halfedge_mesh&& m = {}) {
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
        if (writing)
            throw std::runtime_error("Mesh: another thread is changing this mesh (a call on it is still running)");
    }
    void refuse_while_in_use() const {
        refuse_while_writing();
        if (readers > 0)
            throw std::runtime_error("Mesh: another thread is reading this mesh (a call on it is still running)");
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
inline void compact(halfedge_mesh& m) { (void)m.collect_garbage(); }

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

inline hmira::vertex_handle vertex_arg(const halfedge_mesh& m, long long i, const char* who) {
    if (i < 0 || std::size_t(i) >= m.vertex_index_bound() || !m.is_valid(hmira::vertex_handle(std::size_t(i))))
        value_error(std::string(who) + ": vertex " + std::to_string(i) + " does not exist");
    return hmira::vertex_handle(std::size_t(i));
}
inline hmira::face_handle face_arg(const halfedge_mesh& m, long long i, const char* who) {
    if (i < 0 || std::size_t(i) >= m.face_index_bound() || !m.is_valid(hmira::face_handle(std::size_t(i))))
        value_error(std::string(who) + ": face " + std::to_string(i) + " does not exist");
    return hmira::face_handle(std::size_t(i));
}
inline hmira::halfedge_handle halfedge_arg(const halfedge_mesh& m, long long i, const char* who) {
    if (i < 0 || std::size_t(i) >= m.halfedge_index_bound() || !m.is_valid(hmira::halfedge_handle(std::size_t(i))))
        value_error(std::string(who) + ": halfedge " + std::to_string(i) + " does not exist");
    return hmira::halfedge_handle(std::size_t(i));
}
inline vec3<double> point_arg(const std::vector<double>& p, const char* who) {
    if (p.size() != 3 || !std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
        value_error(std::string(who) + ": position must be 3 finite numbers");
    return {p[0], p[1], p[2]};
}
inline long long idx(auto h) { return h.index == UINT32_MAX ? -1 : static_cast<long long>(h.index); }
inline std::optional<vec3<double>> optional_point(const std::optional<std::vector<double>>& p, const char* who) {
    if (!p) return std::nullopt;
    return point_arg(*p, who);
}

/// change_without_gil for an operation that may delete elements: on success the mesh is
/// renumbered densely (compact), as the CLI writes it.
template <class Change>
auto change_compacted(py_mesh& self, Change&& change) {
    return change_without_gil(self, true, [&](halfedge_mesh& m, hmira::progress_function progress) {
        auto done = change(m, std::move(progress));
        if (done) compact(m);
        return done;
    });
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

/// Vertex indices (checked) as the options structs' fixed / locked vertex lists.
inline std::vector<std::size_t> fixed_arg(const halfedge_mesh& m, const std::optional<std::vector<long long>>& fixed,
                                          const char* who) {
    std::vector<std::size_t> out;
    if (fixed)
        for (long long i : *fixed) out.push_back(vertex_arg(m, i, who).index);
    return out;
}

/// The Mesh methods, one family a file, each adding its methods to the class.
void bind_mesh_triangle_operators(nb::class_<py_mesh>& c);  // flip, split, collapse (triangle_operators.cpp)
void bind_mesh_triangulation(nb::class_<py_mesh>& c);       // triangulate_faces (triangulation.cpp)
void bind_mesh_holes(nb::class_<py_mesh>& c);               // fill_hole, fill_holes (holes.cpp)
void bind_mesh_subdivision(nb::class_<py_mesh>& c);         // subdivide (subdivision.cpp)
void bind_mesh_smoothing(nb::class_<py_mesh>& c);           // laplacian_smooth, taubin_smooth (smoothing.cpp)
void bind_mesh_decimation(nb::class_<py_mesh>& c);          // decimate (decimation.cpp)
void bind_mesh_remeshing(nb::class_<py_mesh>& c);           // remesh (remeshing.cpp)
void bind_mesh_editing(nb::class_<py_mesh>& c);             // truncate, bevel, extrude (editing.cpp)
void bind_mesh_euler(nb::class_<py_mesh>& c);               // the Euler operators (euler.cpp)
void bind_mesh_intersections(nb::class_<py_mesh>& c);       // self_intersections (intersections.cpp)
void bind_mesh_spatial(nb::class_<py_mesh>& c);             // closest_point, ray_intersect (spatial.cpp)
void bind_mesh_queries(nb::class_<py_mesh>& c);             // contains, signed_distance, ... (queries.cpp)

}  // namespace hmira_py
