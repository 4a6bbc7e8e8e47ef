// One Loop subdivision level of a triangulated torus of 2 * 724^2 ~ 1.05M triangles: hmira's
// loop_subdivide on halfedge_mesh and (generic, same code) on OpenMesh TriMesh and CGAL
// Surface_mesh, beside OpenMesh's LoopT subdivider and CGAL's Loop_subdivision, in one run.
// The mesh is copied outside the timed region. Each case runs one iteration (a level takes seconds).
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <vector>

#include <hmira/algorithms/subdivision/loop.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#ifdef HMIRA_BENCH_WITH_OPENMESH
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>
#include <hmira/interop/openmesh.hpp>
#endif
#ifdef HMIRA_BENCH_WITH_CGAL
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <hmira/interop/cgal.hpp>
#endif

namespace {

constexpr std::size_t n = 724;

/// The torus as points and triangles (each quad cut along a diagonal).
struct soup {
    std::vector<hmira::vec3<double>> points;
    std::vector<std::array<std::size_t, 3>> tris;
};
const soup& torus() {
    static const soup s = [] {
        soup t;
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j) {
                const double u = 2 * std::numbers::pi * double(i) / double(n), v = 2 * std::numbers::pi * double(j) / double(n);
                t.points.push_back({(2 + 0.7 * std::cos(v)) * std::cos(u), (2 + 0.7 * std::cos(v)) * std::sin(u), 0.7 * std::sin(v)});
            }
        auto id = [](std::size_t i, std::size_t j) { return (i % n) * n + (j % n); };
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j) {
                t.tris.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
                t.tris.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
            }
        return t;
    }();
    return s;
}

template <class M, class T = hmira::default_traits<M>>
M build() {
    M m;
    std::vector<typename T::vertex_handle> vs;
    for (const auto& p : torus().points) vs.push_back(T::add_vertex(m, {typename T::scalar(p.x), typename T::scalar(p.y), typename T::scalar(p.z)}));
    for (const auto& t : torus().tris) {
        const std::array<typename T::vertex_handle, 3> c{vs[t[0]], vs[t[1]], vs[t[2]]};
        (void)T::add_face(m, std::span<const typename T::vertex_handle>(c));
    }
    return m;
}

template <class M>
void hmira_loop(benchmark::State& state) {
    const M base = build<M>();
    for (auto _ : state) {
        state.PauseTiming();
        M m = base;
        state.ResumeTiming();
        auto r = hmira::loop_subdivide(m);
        benchmark::DoNotOptimize(r);
        state.PauseTiming();
        if (!r || r->faces != 4 * torus().tris.size()) state.SkipWithError("wrong face count");
        state.ResumeTiming();
    }
    state.counters["faces_in"] = double(torus().tris.size());
}
BENCHMARK(hmira_loop<hmira::halfedge_mesh>)->Name("loop/hmira/halfedge_mesh")->Unit(benchmark::kMillisecond)->Iterations(1);

#ifdef HMIRA_BENCH_WITH_OPENMESH
using om_tri = OpenMesh::TriMesh_ArrayKernelT<>;
BENCHMARK(hmira_loop<om_tri>)->Name("loop/hmira/openmesh_tri")->Unit(benchmark::kMillisecond)->Iterations(1);
void openmesh_loop(benchmark::State& state) {
    const om_tri base = build<om_tri>();
    for (auto _ : state) {
        state.PauseTiming();
        om_tri m = base;
        OpenMesh::Subdivider::Uniform::LoopT<om_tri> loop;
        loop.attach(m);
        state.ResumeTiming();
        loop(1);
        state.PauseTiming();
        loop.detach();
        if (m.n_faces() != 4 * torus().tris.size()) state.SkipWithError("wrong face count");
        state.ResumeTiming();
    }
}
BENCHMARK(openmesh_loop)->Name("loop/openmesh/LoopT")->Unit(benchmark::kMillisecond)->Iterations(1);
#endif

#ifdef HMIRA_BENCH_WITH_CGAL
using cgal_mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;
BENCHMARK(hmira_loop<cgal_mesh>)->Name("loop/hmira/cgal_surface_mesh")->Unit(benchmark::kMillisecond)->Iterations(1);
void cgal_loop(benchmark::State& state) {
    const cgal_mesh base = build<cgal_mesh>();
    for (auto _ : state) {
        state.PauseTiming();
        cgal_mesh m = base;
        state.ResumeTiming();
        CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(1));
        state.PauseTiming();
        if (m.number_of_faces() != 4 * torus().tris.size()) state.SkipWithError("wrong face count");
        state.ResumeTiming();
    }
}
BENCHMARK(cgal_loop)->Name("loop/cgal/Loop_subdivision")->Unit(benchmark::kMillisecond)->Iterations(1);
#endif

}  // namespace

BENCHMARK_MAIN();
