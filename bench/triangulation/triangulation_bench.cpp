// triangulate_faces beside the peers' own, in one run, on the same input for every case:
// - a torus of 1024^2 ~ 1.05M quads (what Catmull-Clark or a quad mesher gives);
// - one jagged 200,000-corner polygon (a star with random radii: half its corners reflex),
//   the face a cap or a cut section gives.
// hmira's triangulate_faces on halfedge_mesh and (generic, same code) on CGAL Surface_mesh and
// OpenMesh PolyMesh, beside CGAL's PMP::triangulate_faces and OpenMesh's triangulate() (a fan
// from each face's first corner: fast, but wrong for concave faces, so it is shown for the
// quads only). The mesh is copied outside the timed region; the face count is checked.
#include <random>

#include <hmira/algorithms/triangulation/triangulate_faces.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "support/peer_bench.hpp"

#ifdef HMIRA_BENCH_WITH_OPENMESH
#include <hmira/interop/openmesh.hpp>
#endif
#ifdef HMIRA_BENCH_WITH_CGAL
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Simple_cartesian.h>
#include <hmira/interop/cgal.hpp>
#endif

namespace {

using hmira_bench::soup;

const soup& quads() {
    static const soup s = hmira_bench::make_torus(1024, false);
    return s;
}

const soup& jagged() {
    static const soup s = [] {
        soup t;
        const std::size_t n = 200000;
        std::mt19937_64 rng(3);
        std::uniform_real_distribution<double> unit(0.7, 1.0);
        t.faces.emplace_back();
        for (std::size_t i = 0; i < n; ++i) {
            const double a = 2 * std::numbers::pi * double(i) / double(n), r = unit(rng);
            t.points.push_back({r * std::cos(a), r * std::sin(a), 0.0});
            t.faces[0].push_back(i);
        }
        return t;
    }();
    return s;
}

std::size_t triangles_of(const soup& s) {
    std::size_t n = 0;
    for (const auto& f : s.faces) n += f.size() - 2;
    return n;
}

template <class M, class T = hmira::default_traits<M>>
void hmira_triangulate(benchmark::State& state, const soup& (*input)()) {
    const M base = hmira_bench::build<M>(input());
    for (auto _ : state) {
        state.PauseTiming();
        M m = base;
        state.ResumeTiming();
        auto r = hmira::triangulate_faces(m);
        benchmark::DoNotOptimize(r);
        state.PauseTiming();
        if (!r || T::face_count(m) != triangles_of(input())) state.SkipWithError("wrong face count");
        state.ResumeTiming();
    }
}
template <class M>
void hmira_quads(benchmark::State& state) {
    hmira_triangulate<M>(state, quads);
}
template <class M>
void hmira_jagged(benchmark::State& state) {
    hmira_triangulate<M>(state, jagged);
}
BENCHMARK(hmira_quads<hmira::halfedge_mesh>)
    ->Name("quads/hmira/halfedge_mesh")
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(hmira_jagged<hmira::halfedge_mesh>)
    ->Name("jagged/hmira/halfedge_mesh")
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

#ifdef HMIRA_BENCH_WITH_OPENMESH
using om_poly = OpenMesh::PolyMesh_ArrayKernelT<>;
BENCHMARK(hmira_quads<om_poly>)->Name("quads/hmira/openmesh_poly")->Unit(benchmark::kMillisecond)->Iterations(1);
void openmesh_fan(benchmark::State& state) {
    const om_poly base = hmira_bench::build<om_poly>(quads());
    for (auto _ : state) {
        state.PauseTiming();
        om_poly m = base;
        state.ResumeTiming();
        m.triangulate();
        state.PauseTiming();
        if (m.n_faces() != triangles_of(quads())) state.SkipWithError("wrong face count");
        state.ResumeTiming();
    }
}
BENCHMARK(openmesh_fan)->Name("quads/openmesh/triangulate")->Unit(benchmark::kMillisecond)->Iterations(1);
#endif

#ifdef HMIRA_BENCH_WITH_CGAL
using cgal_mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;
BENCHMARK(hmira_quads<cgal_mesh>)->Name("quads/hmira/cgal_surface_mesh")->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(hmira_jagged<cgal_mesh>)
    ->Name("jagged/hmira/cgal_surface_mesh")
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
void cgal_triangulate(benchmark::State& state, const soup& (*input)()) {
    const cgal_mesh base = hmira_bench::build<cgal_mesh>(input());
    for (auto _ : state) {
        state.PauseTiming();
        cgal_mesh m = base;
        state.ResumeTiming();
        const bool ok = CGAL::Polygon_mesh_processing::triangulate_faces(m);
        state.PauseTiming();
        if (!ok || m.number_of_faces() != triangles_of(input())) state.SkipWithError("wrong face count");
        state.ResumeTiming();
    }
}
BENCHMARK_CAPTURE(cgal_triangulate, quads, quads)
    ->Name("quads/cgal/triangulate_faces")
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(cgal_triangulate, jagged, jagged)
    ->Name("jagged/cgal/triangulate_faces")
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
#endif

}  // namespace

int main(int argc, char** argv) {
    if (int rc = hmira_bench::run_benchmarks(argc, argv); rc != 0) return rc;
    using hmira_bench::print_ratio;
    std::printf("\nMedian CPU-time ratios (no target in the issue: reported against 1.0 and 1.1):\n");
    for (const std::string input : {"quads", "jagged"}) {
        print_ratio(input + ": hmira halfedge_mesh / CGAL triangulate_faces", input + "/hmira/halfedge_mesh",
                    input + "/cgal/triangulate_faces", 1.0);
        print_ratio(input + ": hmira on CGAL / hmira halfedge_mesh", input + "/hmira/cgal_surface_mesh",
                    input + "/hmira/halfedge_mesh", 1.1);
    }
    print_ratio("quads: hmira on OpenMesh / hmira halfedge_mesh", "quads/hmira/openmesh_poly",
                "quads/hmira/halfedge_mesh", 1.1);
    print_ratio("quads: hmira halfedge_mesh / OpenMesh fan (not exact)", "quads/hmira/halfedge_mesh",
                "quads/openmesh/triangulate", 1.0);
    benchmark::Shutdown();
    return 0;
}
