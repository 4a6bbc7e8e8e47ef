// python/src/boolean.cpp
// hmira.mesh_boolean: union, intersection, difference or xor of two closed meshes (each a Mesh
// or a (vertices, faces) pair) by hmira::mesh_boolean, into a new Mesh, with each output face's
// origin as numpy arrays; hmira.repair: the solid a closed, possibly self-intersecting mesh
// bounds, by hmira::make_solid, with the same report. The GIL is released while C++ runs; Ctrl-C
// cancels.
#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include <hmira/algorithms/boolean/make_solid.hpp>
#include <hmira/algorithms/boolean/mesh_boolean.hpp>
#include <hmira/algorithms/copy/copy_mesh.hpp>
#include <hmira/algorithms/repair/repair_polygon_soup.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

#include "mesh_binding.hpp"
#include "results.hpp"

namespace hmira_py {

namespace {

/// An operand: a Mesh's half-edge mesh (kept alive and marked as read), or a face-vertex mesh
/// built from a (vertices, faces) pair.
struct operand {
    const py_mesh* owner = nullptr;
    std::shared_ptr<const halfedge_mesh> mesh;
    hmira::face_vertex_mesh arrays;

    operand(nb::handle h, const char* which, const char* who = "mesh_boolean") {
        if (nb::isinstance<py_mesh>(h)) {
            owner = &nb::cast<const py_mesh&>(h);
            owner->refuse_while_writing();
            mesh = owner->mesh;
            ++owner->readers;
            return;
        }
        if (!nb::isinstance<nb::tuple>(h) || nb::len(h) != 2)
            value_error(std::string(who) + ": " + which + " must be a Mesh or a (vertices, faces) pair");
        const auto t = nb::cast<nb::tuple>(h);
        const auto soup = to_soup(nb::cast<vertex_array>(t[0]), t[1], who);
        const std::string name = std::string(who) + ": " + which;
        check(hmira::io::assign_from_soup(arrays, soup, [&](std::size_t) { return name; }));
    }
    operand(const operand&) = delete;
    operand& operator=(const operand&) = delete;
    ~operand() {
        if (owner) --owner->readers;
    }

    /// Calls run(m) on the mesh this operand holds.
    template <class Run>
    auto visit(Run&& run) const {
        using R = decltype(run(arrays));
        if (mesh) return R(run(*mesh));
        return R(run(arrays));
    }
};

/// The output of mesh_boolean as a half-edge mesh. A result that touches itself along edges (an
/// xor whose parts meet along the intersection curve) gets those edges' vertices split, by the
/// readers' repair; `faces` is remapped to the faces kept. Returns the repair summary.
std::string to_halfedge(const hmira::face_vertex_mesh& m, std::vector<hmira::boolean_face_origin>& faces,
                        halfedge_mesh& out) {
    using T = hmira::default_traits<hmira::face_vertex_mesh>;
    std::vector<std::array<double, 3>> points;
    std::vector<std::uint64_t> offsets{0};
    std::vector<std::uint32_t> corners;
    for (auto v : T::vertices(m)) {
        const auto p = T::position(m, v);
        points.push_back({double(p[0]), double(p[1]), double(p[2])});
    }
    for (auto f : T::faces(m)) {
        for (auto v : T::face_vertices(m, f)) corners.push_back(static_cast<std::uint32_t>(T::vertex_index(m, v)));
        offsets.push_back(corners.size());
    }
    if (out.assign_polygons(std::span<const std::array<double, 3>>(points), std::span<const std::uint64_t>(offsets),
                            std::span<const std::uint32_t>(corners)))
        return {};
    auto repaired = take(hmira::repair_polygon_soup(points.size(), offsets, corners));
    std::vector<std::array<double, 3>> copies(repaired.vertex_count);
    for (std::size_t v = 0; v < repaired.vertex_count; ++v) copies[v] = points[repaired.source_vertex(v)];
    out = halfedge_mesh{};
    check(out.assign_polygons(std::span<const std::array<double, 3>>(copies),
                              std::span<const std::uint64_t>(repaired.face_offsets),
                              std::span<const std::uint32_t>(repaired.corners)));
    std::vector<hmira::boolean_face_origin> kept;
    kept.reserve(repaired.face_count());
    for (std::size_t f = 0; f < repaired.face_count(); ++f) kept.push_back(faces[repaired.face_source[f]]);
    faces = std::move(kept);
    return repaired.report.summary();
}

/// The Python result of a run: the output as a new Mesh, the origins as numpy arrays, the counts.
boolean_result to_result(hmira::boolean_report report, halfedge_mesh&& out, const std::string& repairs) {
    const std::size_t n = report.faces.size();
    std::vector<std::uint8_t> origin_mesh(n);
    std::vector<std::int64_t> origin_face(n);
    for (std::size_t i = 0; i < n; ++i) {
        origin_mesh[i] = report.faces[i].mesh;
        origin_face[i] = static_cast<std::int64_t>(report.faces[i].face);
    }
    nb::object result_mesh = nb::module_::import_("hmira").attr("Mesh")();
    nb::cast<py_mesh&>(result_mesh).replace(std::move(out));
    result_mesh.attr("repairs") = repairs;
    return {.mesh = std::move(result_mesh),
            .origin_mesh = nb::cast(adopt<std::uint8_t>(std::move(origin_mesh), {n})),
            .origin_face = nb::cast(adopt<std::int64_t>(std::move(origin_face), {n})),
            .intersecting_pairs = report.intersecting_pairs,
            .cut_triangles = report.cut_triangles,
            .snapped_vertices = report.snapped_vertices,
            .degenerate_faces = report.degenerate_faces,
            .rounding_intersections = report.rounding_intersections};
}

boolean_result repair_free(nb::handle mesh, bool solid) {
    const operand om(mesh, "mesh", "repair");
    halfedge_mesh out;
    interrupt_watch watch;
    hmira::result<hmira::boolean_report> r = hmira::boolean_report{};
    std::string repairs;
    {
        nb::gil_scoped_release release;
        cpp_timer timer;
        hmira::face_vertex_mesh soup;
        r = om.visit([&](const auto& m) -> hmira::result<hmira::boolean_report> {
            if (solid) return hmira::make_solid(soup, m, {.progress = watch.callback()});
            if (auto c = hmira::copy_mesh(m, soup); !c) return c.error();
            hmira::boolean_report copied;
            for (std::size_t f = 0; f < soup.face_count(); ++f) copied.faces.push_back({0, f});
            return copied;
        });
        if (r) repairs = to_halfedge(soup, r->faces, out);
    }
    watch.rethrow();
    return to_result(take(std::move(r)), std::move(out), repairs);
}

boolean_result mesh_boolean_free(nb::handle a, nb::handle b, const std::string& op) {
    const auto o = enum_arg<hmira::boolean_op>(op, "mesh_boolean", "op");
    const operand oa(a, "a"), ob(b, "b");
    halfedge_mesh out;
    interrupt_watch watch;
    hmira::result<hmira::boolean_report> r = hmira::boolean_report{};
    std::string repairs;
    {
        nb::gil_scoped_release release;
        cpp_timer timer;
        const hmira::boolean_options options{.op = o, .progress = watch.callback()};
        hmira::face_vertex_mesh soup;
        r = oa.visit([&](const auto& ma) {
            return ob.visit([&](const auto& mb) { return hmira::mesh_boolean(soup, ma, mb, options); });
        });
        if (r) repairs = to_halfedge(soup, r->faces, out);
    }
    watch.rethrow();
    return to_result(take(std::move(r)), std::move(out), repairs);
}

}  // namespace

void bind_boolean(nb::module_& m) {
    m.def("mesh_boolean", &mesh_boolean_free, nb::arg("a"), nb::arg("b"), nb::kw_only(),
          nb::arg("op") = name_of(hmira::boolean_options{}.op),
          "Union, intersection, difference (a minus b) or symmetric difference of two closed meshes, computed "
          "exactly (hmira::mesh_boolean).\n\n"
          "Parameters\n----------\n"
          "a, b : Mesh or (vertices, faces)\n"
          "    Closed (self-intersecting, nested or overlapping shells allowed: a point is inside where the winding "
          "number is positive); polygons are cut into triangles.\n"
          "op : str, keyword-only\n"
          "    'union' (default), 'intersection', 'difference' or 'xor'.\n\n"
          "Returns\n-------\n"
          "BooleanResult\n"
          "    mesh (a new Mesh of triangles; empty for an empty result; where the result touches itself along edges, "
          "as an xor of overlapping meshes does along the intersection curve, those edges' vertices are split as "
          "read_mesh repairs, and mesh.repairs says so), origin_mesh (uint8 per output face: 0 for "
          "a, 1 for b), origin_face (int64 per output face: the face of that input it lies in), and the counts "
          "intersecting_pairs, cut_triangles, snapped_vertices, degenerate_faces, rounding_intersections.\n\n"
          "Raises\n------\n"
          "ValueError\n"
          "    An unknown op, a non-finite coordinate, a self-intersecting input that is not closed or has triangles "
          "overlapping in one plane.\n"
          "KeyboardInterrupt\n"
          "    Ctrl-C; nothing is returned.\n\n"
          "Examples\n--------\n"
          ">>> import hmira\n"
          ">>> V = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]\n"
          ">>> F = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]\n"
          ">>> r = hmira.mesh_boolean(hmira.Mesh(V, F), hmira.Mesh(V, F), op='difference')\n"
          ">>> r.mesh.face_count, len(r.origin_face)\n"
          "(0, 0)");
    m.def("repair", &repair_free, nb::arg("mesh"), nb::kw_only(), nb::arg("solid") = true,
          "The clean surface of the solid a closed mesh bounds (hmira::make_solid): self-intersections are cut "
          "exactly and only the boundary of the points the surface winds around (winding number > 0) is kept, so "
          "overlapping parts merge, a shell inside another disappears and an inward-turned shell stays a cavity.\n\n"
          "Parameters\n----------\n"
          "mesh : Mesh or (vertices, faces)\n"
          "    Closed (every edge used as often in one direction as in the other); polygons are cut into triangles.\n"
          "solid : bool, keyword-only\n"
          "    True (default): make_solid. False: the mesh as the readers' repair holds it (a copy).\n\n"
          "Returns\n-------\n"
          "BooleanResult\n"
          "    mesh (a new Mesh of triangles, closed and consistently oriented; empty when nothing is inside), "
          "origin_mesh (all 0), origin_face (int64 per output face: the input face it lies in), and the counts "
          "intersecting_pairs, cut_triangles, snapped_vertices, degenerate_faces, rounding_intersections.\n\n"
          "Raises\n------\n"
          "ValueError\n"
          "    A non-finite coordinate, an input that is not closed, triangles overlapping in one plane.\n"
          "KeyboardInterrupt\n"
          "    Ctrl-C; nothing is returned.\n\n"
          "Examples\n--------\n"
          ">>> import hmira\n"
          ">>> V = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]\n"
          ">>> F = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]\n"
          ">>> r = hmira.repair(hmira.Mesh(V, F))\n"
          ">>> r.mesh.face_count, r.cut_triangles\n"
          "(4, 0)");
}

}  // namespace hmira_py
