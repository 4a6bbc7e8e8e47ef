// Per-operation cost of truncate, bevel and extrude on a 1000 x 1000 quad torus (1M faces).
// Each iteration edits a fresh, untouched spot (every third ring and side), so every operation
// sees the same local configuration: the cost must not depend on the mesh size.
#include <benchmark/benchmark.h>

#include <cstddef>
#include <vector>

#include <hmira/algorithms/editing/editing.hpp>
#include <hmira/algorithms/generators/torus.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>
#ifdef HMIRA_BENCH_WITH_CGAL
#include <CGAL/Simple_cartesian.h>
#include <hmira/interop/cgal.hpp>
#endif
#ifdef HMIRA_BENCH_WITH_OPENMESH
#include <hmira/interop/openmesh.hpp>
#endif

namespace {

constexpr std::size_t n = 1000;  // rings = sides: n * n faces

template <class M>
struct fixture {
    M mesh;
    hmira::generated_elements<M> g;
    std::size_t next = 0;
    fixture() {
        g = hmira::generate_torus(mesh, {.major_radius = 4, .minor_radius = 1, .rings = n, .sides = n}).value();
    }
    // The k-th untouched spot: ring 3a, side 3b.
    std::size_t spot() {
        const std::size_t per = n / 3;
        const std::size_t k = next++ % (per * per);
        return (3 * (k / per)) * n + 3 * (k % per);
    }
};

template <class M>
void bm_truncate(benchmark::State& state) {
    fixture<M> f;
    for (auto _ : state) {
        auto r = hmira::truncate(f.mesh, f.g.vertices[f.spot()]);
        benchmark::DoNotOptimize(r);
    }
    state.counters["faces"] = double(hmira::default_traits<M>::face_count(f.mesh));
}

template <class M>
void bm_extrude(benchmark::State& state) {
    fixture<M> f;
    for (auto _ : state) {
        auto r = hmira::extrude(f.mesh, f.g.faces[f.spot()], {.distance = 0.001});
        benchmark::DoNotOptimize(r);
    }
    state.counters["faces"] = double(hmira::default_traits<M>::face_count(f.mesh));
}

template <class M>
void bm_bevel(benchmark::State& state) {
    using T = hmira::default_traits<M>;
    fixture<M> f;
    for (auto _ : state) {
        const auto v = f.g.vertices[f.spot()];
        auto r = hmira::bevel(f.mesh, T::edge(f.mesh, T::vertex_halfedge(f.mesh, v)), {.width = 0.0005});
        benchmark::DoNotOptimize(r);
    }
    state.counters["faces"] = double(T::face_count(f.mesh));
}

// The four edges around a face, rounded with 3 segments: arcs at both ends of every strip.
template <class M>
void bm_bevel_face_rim_rounded(benchmark::State& state) {
    using T = hmira::default_traits<M>;
    fixture<M> f;
    std::vector<typename T::edge_handle> rim;
    for (auto _ : state) {
        const auto face = f.g.faces[f.spot()];
        rim.clear();
        const auto first = T::face_halfedge(f.mesh, face);
        auto h = first;
        do {
            rim.push_back(T::edge(f.mesh, h));
            h = T::next(f.mesh, h);
        } while (h != first);
        auto r = hmira::bevel(f.mesh, rim, {.width = 0.0005, .segments = 3});
        benchmark::DoNotOptimize(r);
    }
    state.counters["faces"] = double(T::face_count(f.mesh));
}

// At most one op per spot: (n / 3)^2 = 111k spots.
constexpr benchmark::IterationCount iters = 100000;

BENCHMARK_TEMPLATE(bm_truncate, hmira::halfedge_mesh)->Iterations(iters)->Unit(benchmark::kNanosecond);
BENCHMARK_TEMPLATE(bm_extrude, hmira::halfedge_mesh)->Iterations(iters)->Unit(benchmark::kNanosecond);
BENCHMARK_TEMPLATE(bm_bevel, hmira::halfedge_mesh)->Iterations(iters)->Unit(benchmark::kNanosecond);
BENCHMARK_TEMPLATE(bm_bevel_face_rim_rounded, hmira::halfedge_mesh)->Iterations(iters)->Unit(benchmark::kNanosecond);
#ifdef HMIRA_BENCH_WITH_CGAL
using cgal_mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;
BENCHMARK_TEMPLATE(bm_truncate, cgal_mesh)->Iterations(iters)->Unit(benchmark::kNanosecond);
BENCHMARK_TEMPLATE(bm_extrude, cgal_mesh)->Iterations(iters)->Unit(benchmark::kNanosecond);
BENCHMARK_TEMPLATE(bm_bevel, cgal_mesh)->Iterations(iters)->Unit(benchmark::kNanosecond);
BENCHMARK_TEMPLATE(bm_bevel_face_rim_rounded, cgal_mesh)->Iterations(iters)->Unit(benchmark::kNanosecond);
#endif
#ifdef HMIRA_BENCH_WITH_OPENMESH
using openmesh_poly = OpenMesh::PolyMesh_ArrayKernelT<>;
BENCHMARK_TEMPLATE(bm_truncate, openmesh_poly)->Iterations(iters)->Unit(benchmark::kNanosecond);
BENCHMARK_TEMPLATE(bm_extrude, openmesh_poly)->Iterations(iters)->Unit(benchmark::kNanosecond);
BENCHMARK_TEMPLATE(bm_bevel, openmesh_poly)->Iterations(iters)->Unit(benchmark::kNanosecond);
BENCHMARK_TEMPLATE(bm_bevel_face_rim_rounded, openmesh_poly)->Iterations(iters)->Unit(benchmark::kNanosecond);
#endif

}  // namespace

BENCHMARK_MAIN();
