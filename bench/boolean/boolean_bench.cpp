// Booleans of OFF pairs in C++, for bench/boolean/run.sh: CGAL's corefinement with the Epick
// kernel on Surface_mesh, and hmira::mesh_boolean. Each case is timed two ways, the median of
// --reps runs: the operation alone (both inputs already in the tool's mesh, copied outside the
// timed region), and from arrays to arrays (building both meshes from vertex and triangle
// arrays, the operation, and reading the output back into arrays). hmira's operation alone is
// timed on its halfedge_mesh, and, the same generic code on other models, on CGAL's Surface_mesh
// and (where compiled in) OpenMesh's TriMesh with double points; its arrays route goes through
// face_vertex_mesh. A refusal (CGAL throws or returns false, hmira returns an error) is
// reported, not fatal. Each output is checked with CGAL's own is_valid_polygon_mesh, is_closed
// and does_self_intersect (hmira's output copied into a Surface_mesh for that), and its volume
// printed for the volume identity.
// Usage: boolean_bench --op union|intersection|difference --reps N [--threads N] A.off B.off
// (--threads: hmira's boolean_options::threads, 0 for all cores; CGAL runs on one thread)
// Prints two lines: "cgal op=<op> alone=<s> arrays=<s> faces=<n> volume=<v> valid=<0|1> closed=<0|1>
// self_intersecting=<0|1> refused=<0|1>", then "hmira" with the same keys and surface_mesh=<s>,
// openmesh=<s> (-1 where not compiled in), cut=<n> snapped=<n> rounding=<n> from the report.
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <hmira/algorithms/boolean/mesh_boolean.hpp>
#include <hmira/interop/cgal.hpp>
#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>
#ifdef HMIRA_BENCH_WITH_OPENMESH
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <hmira/interop/openmesh.hpp>
#endif

namespace {

using kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using surface = CGAL::Surface_mesh<kernel::Point_3>;
namespace pmp = CGAL::Polygon_mesh_processing;
using clock_type = std::chrono::steady_clock;

/// A triangle mesh as flat arrays, the form every tool is fed from.
struct arrays {
    std::vector<double> xyz;
    std::vector<std::array<std::size_t, 3>> tri;
};

arrays read_arrays(const char* path) {
    hmira::halfedge_mesh m;
    auto r = hmira::io::read_mesh(m, path);
    if (!r) {
        std::fprintf(stderr, "boolean_bench: %s: %s\n", path, r.error().message.c_str());
        std::exit(2);
    }
    using T = hmira::default_traits<hmira::halfedge_mesh>;
    arrays a;
    for (auto v : T::vertices(m)) {
        const auto p = T::position(m, v);
        a.xyz.insert(a.xyz.end(), {double(p[0]), double(p[1]), double(p[2])});
    }
    for (auto f : T::faces(m)) {
        std::array<std::size_t, 3> t{};
        int k = 0;
        for (auto v : T::face_vertices(m, f)) {
            if (k == 3) {
                std::fprintf(stderr, "boolean_bench: %s is not a triangle mesh\n", path);
                std::exit(2);
            }
            t[std::size_t(k++)] = T::vertex_index(m, v);
        }
        a.tri.push_back(t);
    }
    return a;
}

surface to_surface(const arrays& a) {
    surface s;
    std::vector<surface::Vertex_index> vs;
    vs.reserve(a.xyz.size() / 3);
    for (std::size_t i = 0; i < a.xyz.size(); i += 3)
        vs.push_back(s.add_vertex({a.xyz[i], a.xyz[i + 1], a.xyz[i + 2]}));
    for (const auto& t : a.tri) s.add_face(vs[t[0]], vs[t[1]], vs[t[2]]);
    return s;
}

arrays from_surface(const surface& s) {
    arrays a;
    std::vector<std::size_t> index(s.number_of_vertices() + s.number_of_removed_vertices());
    std::size_t n = 0;
    for (auto v : s.vertices()) {
        const auto& p = s.point(v);
        a.xyz.insert(a.xyz.end(), {p.x(), p.y(), p.z()});
        index[std::size_t(v)] = n++;
    }
    for (auto f : s.faces()) {
        std::array<std::size_t, 3> t{};
        int k = 0;
        for (auto v : s.vertices_around_face(s.halfedge(f))) t[std::size_t(std::min(k++, 2))] = index[std::size_t(v)];
        a.tri.push_back(t);
    }
    return a;
}

bool run_op(const std::string& op, surface& a, surface& b, surface& out) {
    if (op == "union") return pmp::corefine_and_compute_union(a, b, out);
    if (op == "intersection") return pmp::corefine_and_compute_intersection(a, b, out);
    return pmp::corefine_and_compute_difference(a, b, out);
}

double median(std::vector<double> t) {
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
}

/// The result of one tool on one case, as the output line reports it.
struct outcome {
    std::vector<double> alone, whole;
    surface result;
    bool refused = false;
};

void print_line(const char* tool, const std::string& op, const outcome& o, const std::string& extra = "") {
    const bool valid = !o.refused && CGAL::is_valid_polygon_mesh(o.result);
    const bool closed = !o.refused && CGAL::is_closed(o.result);
    const bool crossing = !o.refused && !o.result.is_empty() && pmp::does_self_intersect(o.result);
    const double volume = o.refused || !closed ? 0.0 : pmp::volume(o.result);
    std::printf(
        "%s op=%s alone=%.6f arrays=%.6f faces=%zu volume=%.17g valid=%d closed=%d self_intersecting=%d "
        "refused=%d%s\n",
        tool, op.c_str(), o.alone.empty() ? -1.0 : median(o.alone), o.whole.empty() ? -1.0 : median(o.whole),
        std::size_t(o.result.number_of_faces()), volume, int(valid), int(closed), int(crossing), int(o.refused),
        extra.c_str());
}

hmira::boolean_op hmira_op(const std::string& op) { return *hmira::from_string<hmira::boolean_op>(op); }

/// Any hmira model built from arrays (the polygon soup route every reader takes).
template <class M>
M to_model(const arrays& a) {
    hmira::io::polygon_soup s;
    for (std::size_t i = 0; i < a.xyz.size(); i += 3) s.points.push_back({a.xyz[i], a.xyz[i + 1], a.xyz[i + 2]});
    for (const auto& t : a.tri) {
        for (auto v : t) s.indices.push_back(std::uint32_t(v));
        s.face_offsets.push_back(s.indices.size());
    }
    M m;
    if (auto r = hmira::io::assign_from_soup(m, s, [](std::size_t) { return std::string("input"); }); !r) {
        std::fprintf(stderr, "boolean_bench: %s\n", r.error().message.c_str());
        std::exit(2);
    }
    return m;
}

/// A triangle mesh of any hmira model read back into arrays (vertex indices as the model numbers them).
template <class M>
arrays model_arrays(const M& m) {
    using T = hmira::default_traits<M>;
    arrays a;
    for (auto v : T::vertices(m)) {
        const auto p = T::position(m, v);
        a.xyz.insert(a.xyz.end(), {double(p[0]), double(p[1]), double(p[2])});
    }
    for (auto f : T::faces(m)) {
        std::array<std::size_t, 3> t{};
        int k = 0;
        for (auto v : T::face_vertices(m, f)) t[std::size_t(std::min(k++, 2))] = T::vertex_index(m, v);
        a.tri.push_back(t);
    }
    return a;
}

/// Seconds of hmira::mesh_boolean alone on inputs of model M (built outside the timed region).
template <class M>
double hmira_alone_on(const M& ma, const M& mb, const std::string& op, unsigned threads) {
    hmira::halfedge_mesh out;
    const auto t0 = clock_type::now();
    auto r = hmira::mesh_boolean(out, ma, mb, {.op = hmira_op(op), .threads = threads});
    const double s = std::chrono::duration<double>(clock_type::now() - t0).count();
    return r ? s : -1.0;
}

}  // namespace

int main(int argc, char** argv) {
    std::string op = "difference";
    int reps = 3;
    unsigned threads = 0;
    std::vector<const char*> files;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--op") && i + 1 < argc)
            op = argv[++i];
        else if (!std::strcmp(argv[i], "--reps") && i + 1 < argc)
            reps = std::max(1, std::atoi(argv[++i]));
        else if (!std::strcmp(argv[i], "--threads") && i + 1 < argc)
            threads = unsigned(std::max(0, std::atoi(argv[++i])));
        else
            files.push_back(argv[i]);
    }
    if (files.size() != 2 || (op != "union" && op != "intersection" && op != "difference")) {
        std::fprintf(stderr,
                     "usage: boolean_bench --op union|intersection|difference --reps N [--threads N] A.off B.off\n");
        return 2;
    }
    const arrays a = read_arrays(files[0]), b = read_arrays(files[1]);
    outcome cgal;
    for (int r = 0; r < reps && !cgal.refused; ++r) {
        try {
            surface sa = to_surface(a), sb = to_surface(b), out;
            const auto t0 = clock_type::now();
            const bool ok = run_op(op, sa, sb, out);
            cgal.alone.push_back(std::chrono::duration<double>(clock_type::now() - t0).count());
            if (!ok) cgal.refused = true;
            const auto t1 = clock_type::now();
            surface wa = to_surface(a), wb = to_surface(b), wout;
            run_op(op, wa, wb, wout);
            const arrays back = from_surface(wout);
            cgal.whole.push_back(std::chrono::duration<double>(clock_type::now() - t1).count());
            if (back.tri.empty() && !out.is_empty()) cgal.refused = true;
            cgal.result = std::move(out);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "cgal refused: %s\n", e.what());
            cgal.refused = true;
        }
    }
    print_line("cgal", op, cgal);
    std::fflush(stdout);

    outcome ours;
    std::vector<double> on_surface, on_openmesh;
    hmira::boolean_report report;
    const auto ha = to_model<hmira::halfedge_mesh>(a), hb = to_model<hmira::halfedge_mesh>(b);
    const surface sa = to_surface(a), sb = to_surface(b);
#ifdef HMIRA_BENCH_WITH_OPENMESH
    struct double_points : OpenMesh::DefaultTraits {
        using Point = OpenMesh::Vec3d;
    };
    using om_tri = OpenMesh::TriMesh_ArrayKernelT<double_points>;
    om_tri oa, ob;
    for (auto [src, dst] : {std::pair{&a, &oa}, std::pair{&b, &ob}}) {
        std::vector<om_tri::VertexHandle> vs;
        for (std::size_t i = 0; i < src->xyz.size(); i += 3)
            vs.push_back(dst->add_vertex({src->xyz[i], src->xyz[i + 1], src->xyz[i + 2]}));
        for (const auto& t : src->tri) dst->add_face(vs[t[0]], vs[t[1]], vs[t[2]]);
    }
#endif
    for (int r = 0; r < reps && !ours.refused; ++r) {
        hmira::halfedge_mesh out;
        const auto t0 = clock_type::now();
        auto done = hmira::mesh_boolean(out, ha, hb, {.op = hmira_op(op), .threads = threads});
        ours.alone.push_back(std::chrono::duration<double>(clock_type::now() - t0).count());
        if (!done) {
            std::fprintf(stderr, "hmira refused: %s\n", done.error().message.c_str());
            ours.refused = true;
            break;
        }
        report = std::move(*done);
        const auto t1 = clock_type::now();
        const auto fa = to_model<hmira::face_vertex_mesh>(a), fb = to_model<hmira::face_vertex_mesh>(b);
        hmira::face_vertex_mesh fout;
        const bool whole_ok = bool(hmira::mesh_boolean(fout, fa, fb, {.op = hmira_op(op), .threads = threads}));
        const arrays back = model_arrays(fout);
        ours.whole.push_back(std::chrono::duration<double>(clock_type::now() - t1).count());
        if (!whole_ok || back.tri.size() != out.face_count()) ours.refused = true;
        on_surface.push_back(hmira_alone_on(sa, sb, op, threads));
#ifdef HMIRA_BENCH_WITH_OPENMESH
        on_openmesh.push_back(hmira_alone_on(oa, ob, op, threads));
#endif
        if (r + 1 == reps) ours.result = to_surface(model_arrays(out));
    }
    char extra[256];
    std::snprintf(extra, sizeof extra, " surface_mesh=%.6f openmesh=%.6f cut=%zu snapped=%zu rounding=%zu",
                  on_surface.empty() ? -1.0 : median(on_surface), on_openmesh.empty() ? -1.0 : median(on_openmesh),
                  report.cut_triangles, report.snapped_vertices, report.rounding_intersections);
    print_line("hmira", op, ours, extra);
    return 0;
}
