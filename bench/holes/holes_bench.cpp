// Hole filling on the same holes: 40 discs (3 face rings each) cut out of bunny00.off
// (HMIRA_TEST_DATA/meshes), filled by hmira's fill_hole on halfedge_mesh and on CGAL's
// Surface_mesh, and by CGAL::Polygon_mesh_processing::triangulate_hole with
// use_delaunay_triangulation(false) (the same Liepa weights). Counter `area`: total patch area.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <set>
#include <vector>

#include <hmira/algorithms/holes/fill_hole.hpp>
#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#ifdef HMIRA_BENCH_WITH_CGAL
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Simple_cartesian.h>
#include <hmira/interop/cgal.hpp>
#endif

namespace {

struct soup {
    std::vector<hmira::vec3<double>> points;
    std::vector<std::vector<std::size_t>> faces;
};

/// bunny00 with 40 three-ring discs removed (unused points dropped).
const soup& holed() {
    static const soup s = [] {
        soup in, out;
        const char* dir = std::getenv("HMIRA_TEST_DATA");
        hmira::face_vertex_mesh m;
        if (!hmira::io::read_mesh(m, std::filesystem::path(dir ? dir : "/work/test-data") / "meshes" / "bunny00.off")) return out;
        for (auto v : m.vertices()) in.points.push_back(m.position(v));
        for (auto f : m.faces()) {
            std::vector<std::size_t> face;
            for (auto v : m.face_vertices(f)) face.push_back(v.index);
            in.faces.push_back(face);
        }
        std::vector<std::vector<std::size_t>> faces_of(in.points.size());
        for (std::size_t f = 0; f < in.faces.size(); ++f)
            for (auto v : in.faces[f]) faces_of[v].push_back(f);
        std::vector<char> drop(in.faces.size(), 0);
        std::mt19937_64 rng(7);
        for (int h = 0; h < 40; ++h) {
            std::set<std::size_t> verts{std::uniform_int_distribution<std::size_t>(0, in.points.size() - 1)(rng)};
            for (int r = 0; r < 3; ++r) {
                auto next = verts;
                for (auto v : verts)
                    for (auto f : faces_of[v]) {
                        drop[f] = 1;
                        for (auto w : in.faces[f]) next.insert(w);
                    }
                verts = next;
            }
        }
        std::vector<std::size_t> map(in.points.size(), SIZE_MAX);
        for (std::size_t f = 0; f < in.faces.size(); ++f) {
            if (drop[f]) continue;
            std::vector<std::size_t> face;
            for (auto v : in.faces[f]) {
                if (map[v] == SIZE_MAX) {
                    map[v] = out.points.size();
                    out.points.push_back(in.points[v]);
                }
                face.push_back(map[v]);
            }
            out.faces.push_back(face);
        }
        return out;
    }();
    return s;
}

template <class M, class T = hmira::default_traits<M>>
M build() {
    M m;
    std::vector<typename T::vertex_handle> vs;
    for (const auto& p : holed().points) vs.push_back(T::add_vertex(m, {typename T::scalar(p.x), typename T::scalar(p.y), typename T::scalar(p.z)}));
    std::vector<typename T::vertex_handle> c;
    for (const auto& f : holed().faces) {
        c.clear();
        for (auto i : f) c.push_back(vs[i]);
        (void)T::add_face(m, std::span<const typename T::vertex_handle>(c));
    }
    return m;
}

template <class M, class T = hmira::default_traits<M>>
std::vector<typename T::halfedge_handle> loops(const M& m) {
    std::vector<typename T::halfedge_handle> out;
    std::vector<char> seen(T::halfedge_index_bound(m), 0);
    for (auto h : T::halfedges(m)) {
        if (T::face(m, h) != T::null_face() || seen[T::halfedge_index(m, h)]) continue;
        auto x = h;
        do {
            seen[T::halfedge_index(m, x)] = 1;
            x = T::next(m, x);
        } while (x != h);
        out.push_back(h);
    }
    return out;
}

template <class M, class T = hmira::default_traits<M>>
double face_area(const M& m, typename T::face_handle f) {
    std::vector<hmira::vec3<double>> p;
    for (auto v : T::face_vertices(m, f)) {
        const auto q = T::position(m, v);
        p.push_back({double(q[0]), double(q[1]), double(q[2])});
    }
    const auto n = hmira::cross(p[1] - p[0], p[2] - p[0]);
    return 0.5 * std::sqrt(hmira::dot(n, n));
}

template <class M, class T = hmira::default_traits<M>>
void hmira_fill(benchmark::State& state) {
    if (holed().points.empty()) {
        state.SkipWithError("bunny00.off not found (HMIRA_TEST_DATA)");
        return;
    }
    const M base = build<M>();
    double area = 0;
    std::size_t holes = 0;
    for (auto _ : state) {
        state.PauseTiming();
        M m = base;
        const auto hs = loops(m);
        holes = hs.size();
        std::vector<typename T::face_handle> added;
        state.ResumeTiming();
        for (auto h : hs) {
            auto r = hmira::fill_hole(m, h);
            if (r) added.insert(added.end(), r->faces.begin(), r->faces.end());
        }
        state.PauseTiming();
        area = 0;
        for (auto f : added) area += face_area(m, f);
        state.ResumeTiming();
    }
    state.counters["holes"] = double(holes);
    state.counters["area"] = area;
}
BENCHMARK(hmira_fill<hmira::halfedge_mesh>)->Name("fill_hole/hmira/halfedge_mesh")->Unit(benchmark::kMillisecond)->Iterations(3);

#ifdef HMIRA_BENCH_WITH_CGAL
using cgal_mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;
BENCHMARK(hmira_fill<cgal_mesh>)->Name("fill_hole/hmira/cgal_surface_mesh")->Unit(benchmark::kMillisecond)->Iterations(3);
void cgal_fill(benchmark::State& state) {
    if (holed().points.empty()) {
        state.SkipWithError("bunny00.off not found (HMIRA_TEST_DATA)");
        return;
    }
    const cgal_mesh base = build<cgal_mesh>();
    double area = 0;
    for (auto _ : state) {
        state.PauseTiming();
        cgal_mesh m = base;
        const auto hs = loops(m);
        std::vector<cgal_mesh::Face_index> added;
        state.ResumeTiming();
        for (auto h : hs)
            CGAL::Polygon_mesh_processing::triangulate_hole(m, h, std::back_inserter(added),
                                                            CGAL::parameters::use_delaunay_triangulation(false));
        state.PauseTiming();
        area = 0;
        for (auto f : added) area += face_area(m, f);
        state.ResumeTiming();
    }
    state.counters["area"] = area;
}
BENCHMARK(cgal_fill)->Name("fill_hole/cgal/triangulate_hole")->Unit(benchmark::kMillisecond)->Iterations(3);
#endif

}  // namespace

BENCHMARK_MAIN();
