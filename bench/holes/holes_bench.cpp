// Hole filling on the same holes: 40 discs (3 face rings each) cut out of bunny00.off
// (HMIRA_TEST_DATA/meshes), filled by hmira's fill_hole on halfedge_mesh and on CGAL's
// Surface_mesh, and by CGAL::Polygon_mesh_processing::triangulate_hole with
// use_delaunay_triangulation(false) (the same Liepa weights). Counter `area`: total patch area;
// fill_hole/area_per_hole counts the holes whose hmira patch is larger than CGAL's.
// refine_fair/*: the same holes triangulated, refined (Liepa, density sqrt 2) and faired as a
// thin plate, by hmira (uniform Laplacian, conjugate gradients) and by CGAL's
// triangulate_refine_and_fair_hole (cotangent weights, fairing_continuity 1, Eigen SparseLU).
// Counters: vertices added, mean patch edge (edges with both faces in a patch) beside the mean
// loop edge, unfaired patches.
#include <benchmark/benchmark.h>

#include <algorithm>
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
#ifdef HMIRA_BENCH_WITH_EIGEN
#include <CGAL/Polygon_mesh_processing/fair.h>
#endif
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
        if (!hmira::io::read_mesh(m, std::filesystem::path(dir ? dir : "/work/test-data") / "meshes" / "bunny00.off"))
            return out;
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
    for (const auto& p : holed().points)
        vs.push_back(T::add_vertex(m, {typename T::scalar(p.x), typename T::scalar(p.y), typename T::scalar(p.z)}));
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
double edge_length(const M& m, typename T::halfedge_handle h) {
    const auto a = T::position(m, T::target(m, h)), b = T::position(m, T::target(m, T::opposite(m, h)));
    const hmira::vec3<double> d{double(a[0] - b[0]), double(a[1] - b[1]), double(a[2] - b[2])};
    return std::sqrt(hmira::dot(d, d));
}

/// Mean length of the edges with both faces among `faces` (each counted from both sides).
template <class M, class T = hmira::default_traits<M>>
double patch_mean_edge(const M& m, const std::vector<typename T::face_handle>& faces) {
    std::vector<char> in(T::face_index_bound(m), 0);
    for (auto f : faces) in[T::face_index(m, f)] = 1;
    double sum = 0;
    std::size_t n = 0;
    for (auto f : faces) {
        const auto h0 = T::face_halfedge(m, f);
        auto x = h0;
        do {
            const auto o = T::face(m, T::opposite(m, x));
            if (o != T::null_face() && in[T::face_index(m, o)]) {
                sum += edge_length(m, x);
                ++n;
            }
            x = T::next(m, x);
        } while (x != h0);
    }
    return n ? sum / double(n) : 0;
}

/// Mean length of the loops' edges.
template <class M, class T = hmira::default_traits<M>>
double loops_mean_edge(const M& m, const std::vector<typename T::halfedge_handle>& hs) {
    double sum = 0;
    std::size_t n = 0;
    for (auto h : hs) {
        auto x = h;
        do {
            sum += edge_length(m, x);
            ++n;
            x = T::next(m, x);
        } while (x != h);
    }
    return n ? sum / double(n) : 0;
}

template <class M, class T = hmira::default_traits<M>>
void hmira_refine_fair(benchmark::State& state) {
    if (holed().points.empty()) {
        state.SkipWithError("bunny00.off not found (HMIRA_TEST_DATA)");
        return;
    }
    const M base = build<M>();
    std::size_t vertices = 0, unfaired = 0;
    double mean_edge = 0, loop_edge = 0;
    for (auto _ : state) {
        state.PauseTiming();
        M m = base;
        const auto hs = loops(m);
        loop_edge = loops_mean_edge(m, hs);
        std::vector<typename T::face_handle> added;
        vertices = unfaired = 0;
        state.ResumeTiming();
        for (auto h : hs) {
            auto r = hmira::fill_hole(m, h, {.refine = true, .fair = hmira::fairing::thin_plate});
            if (!r) continue;
            added.insert(added.end(), r->faces.begin(), r->faces.end());
            vertices += r->vertices.size();
            unfaired += r->faired ? 0 : 1;
        }
        state.PauseTiming();
        mean_edge = patch_mean_edge(m, added);
        state.ResumeTiming();
    }
    state.counters["vertices"] = double(vertices);
    state.counters["mean_edge"] = mean_edge;
    state.counters["loop_edge"] = loop_edge;
    state.counters["unfaired"] = double(unfaired);
}
BENCHMARK(hmira_refine_fair<hmira::halfedge_mesh>)
    ->Name("refine_fair/hmira/halfedge_mesh")
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

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
BENCHMARK(hmira_fill<hmira::halfedge_mesh>)
    ->Name("fill_hole/hmira/halfedge_mesh")
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

#ifdef HMIRA_BENCH_WITH_CGAL
using cgal_mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;
BENCHMARK(hmira_fill<cgal_mesh>)
    ->Name("fill_hole/hmira/cgal_surface_mesh")
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);
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
BENCHMARK(hmira_refine_fair<cgal_mesh>)
    ->Name("refine_fair/hmira/cgal_surface_mesh")
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

/// Hole by hole, on copies of the same mesh: how many hmira patches are larger than CGAL's.
void area_per_hole(benchmark::State& state) {
    if (holed().points.empty()) {
        state.SkipWithError("bunny00.off not found (HMIRA_TEST_DATA)");
        return;
    }
    const cgal_mesh base = build<cgal_mesh>();
    std::size_t larger = 0;
    double worst = 0;
    for (auto _ : state) {
        larger = 0;
        worst = 0;
        for (auto h : loops(base)) {
            cgal_mesh a = base, b = base;
            std::vector<cgal_mesh::Face_index> fa;
            CGAL::Polygon_mesh_processing::triangulate_hole(a, h, std::back_inserter(fa),
                                                            CGAL::parameters::use_delaunay_triangulation(false));
            auto r = hmira::fill_hole(b, h);
            double sa = 0, sb = 0;
            for (auto f : fa) sa += face_area(a, f);
            if (r)
                for (auto f : r->faces) sb += face_area(b, f);
            // The same triangles summed in another order differ by ~1e-16 relative: not larger.
            if (sb > sa * (1 + 1e-12)) ++larger;
            worst = std::max(worst, (sb - sa) / sa);
        }
    }
    state.counters["holes_larger"] = double(larger);
    state.counters["max_relative_excess"] = worst;
}
BENCHMARK(area_per_hole)->Name("fill_hole/area_per_hole")->Unit(benchmark::kMillisecond)->Iterations(1);

#ifdef HMIRA_BENCH_WITH_EIGEN
void cgal_refine_fair(benchmark::State& state) {
    if (holed().points.empty()) {
        state.SkipWithError("bunny00.off not found (HMIRA_TEST_DATA)");
        return;
    }
    const cgal_mesh base = build<cgal_mesh>();
    std::size_t vertices = 0, unfaired = 0;
    double mean_edge = 0, loop_edge = 0;
    for (auto _ : state) {
        state.PauseTiming();
        cgal_mesh m = base;
        const auto hs = loops(m);
        loop_edge = loops_mean_edge(m, hs);
        std::vector<cgal_mesh::Face_index> added;
        std::vector<cgal_mesh::Vertex_index> new_vertices;
        unfaired = 0;
        state.ResumeTiming();
        for (auto h : hs) {
            const auto r = CGAL::Polygon_mesh_processing::triangulate_refine_and_fair_hole(
                m, h, std::back_inserter(added), std::back_inserter(new_vertices),
                CGAL::parameters::use_delaunay_triangulation(false));
            if (!std::get<0>(r)) ++unfaired;
        }
        state.PauseTiming();
        vertices = new_vertices.size();
        mean_edge = patch_mean_edge(m, added);
        state.ResumeTiming();
    }
    state.counters["vertices"] = double(vertices);
    state.counters["mean_edge"] = mean_edge;
    state.counters["loop_edge"] = loop_edge;
    state.counters["unfaired"] = double(unfaired);
}
BENCHMARK(cgal_refine_fair)
    ->Name("refine_fair/cgal/triangulate_refine_and_fair_hole")
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);
#endif
#endif

}  // namespace

BENCHMARK_MAIN();
