// Booleans of OFF pairs in C++, for bench/boolean/run.sh: CGAL's corefinement with the Epick
// kernel on Surface_mesh. Each case is timed two ways, the median of --reps runs: the operation
// alone (both inputs already in Surface_mesh, copied outside the timed region), and from arrays
// to arrays (building both Surface_mesh from vertex and triangle arrays, the operation, and
// reading the output back into arrays). A refusal (CGAL throws or returns false) is reported,
// not fatal. Each output is checked with CGAL's own is_valid_polygon_mesh, is_closed and
// does_self_intersect, and its volume printed for the volume identity.
// Usage: boolean_bench --op union|intersection|difference --reps N A.off B.off
// Prints one line: "cgal op=<op> alone=<s> arrays=<s> faces=<n> volume=<v> valid=<0|1> closed=<0|1>
// self_intersecting=<0|1> refused=<0|1>".
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
#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

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

}  // namespace

int main(int argc, char** argv) {
    std::string op = "difference";
    int reps = 3;
    std::vector<const char*> files;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--op") && i + 1 < argc)
            op = argv[++i];
        else if (!std::strcmp(argv[i], "--reps") && i + 1 < argc)
            reps = std::max(1, std::atoi(argv[++i]));
        else
            files.push_back(argv[i]);
    }
    if (files.size() != 2 || (op != "union" && op != "intersection" && op != "difference")) {
        std::fprintf(stderr, "usage: boolean_bench --op union|intersection|difference --reps N A.off B.off\n");
        return 2;
    }
    const arrays a = read_arrays(files[0]), b = read_arrays(files[1]);
    std::vector<double> alone, whole;
    surface result;
    bool refused = false;
    for (int r = 0; r < reps && !refused; ++r) {
        try {
            surface sa = to_surface(a), sb = to_surface(b), out;
            const auto t0 = clock_type::now();
            const bool ok = run_op(op, sa, sb, out);
            alone.push_back(std::chrono::duration<double>(clock_type::now() - t0).count());
            if (!ok) refused = true;
            const auto t1 = clock_type::now();
            surface wa = to_surface(a), wb = to_surface(b), wout;
            run_op(op, wa, wb, wout);
            const arrays back = from_surface(wout);
            whole.push_back(std::chrono::duration<double>(clock_type::now() - t1).count());
            if (back.tri.empty() && !out.is_empty()) refused = true;
            result = std::move(out);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "cgal refused: %s\n", e.what());
            refused = true;
        }
    }
    const bool valid = !refused && CGAL::is_valid_polygon_mesh(result);
    const bool closed = !refused && CGAL::is_closed(result);
    const bool crossing = !refused && !result.is_empty() && pmp::does_self_intersect(result);
    const double volume = refused || !closed ? 0.0 : pmp::volume(result);
    std::printf(
        "cgal op=%s alone=%.6f arrays=%.6f faces=%zu volume=%.17g valid=%d closed=%d self_intersecting=%d "
        "refused=%d\n",
        op.c_str(), alone.empty() ? -1.0 : median(alone), whole.empty() ? -1.0 : median(whole),
        std::size_t(result.number_of_faces()), volume, int(valid), int(closed), int(crossing), int(refused));
    return 0;
}
