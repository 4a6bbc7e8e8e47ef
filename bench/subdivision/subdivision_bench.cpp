// One subdivision level of ~1M-face tori, in one run, on the same input for every case:
// - Loop, on a triangulated torus of 2 * 724^2 ~ 1.05M triangles: hmira's loop_subdivide on
//   halfedge_mesh and (generic, same code) on OpenMesh TriMesh and CGAL Surface_mesh, beside
//   OpenMesh's LoopT and CGAL's Loop_subdivision;
// - Catmull-Clark, on a torus of 1024^2 ~ 1.05M quads: catmull_clark_subdivide on
//   halfedge_mesh, OpenMesh PolyMesh and Surface_mesh, beside OpenMesh's CatmullClarkT and
//   CGAL's CatmullClark_subdivision.
// The mesh is copied outside the timed region; each case runs one iteration per repetition (a
// level takes a fraction of a second to seconds) and is repeated 3 times. After the run the
// medians are compared: hmira on halfedge_mesh / each peer (target <= 0.5), and hmira generic
// on OpenMesh and CGAL / hmira on halfedge_mesh (target <= 1.1). Run single-threaded.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include <hmira/algorithms/subdivision/catmull_clark.hpp>
#include <hmira/algorithms/subdivision/loop.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "support/peer_bench.hpp"

#ifdef HMIRA_BENCH_WITH_OPENMESH
// The interop header first: CatmullClarkT.hh uses OpenMesh's property handles without including them.
#include <hmira/interop/openmesh.hpp>
#include <OpenMesh/Tools/Subdivider/Uniform/CatmullClarkT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>
#endif
#ifdef HMIRA_BENCH_WITH_CGAL
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <hmira/interop/cgal.hpp>
#endif

namespace {

using hmira_bench::build;
using hmira_bench::soup;

const soup& triangle_torus() {
    static const soup s = hmira_bench::make_torus(724, true);
    return s;
}
const soup& quad_torus() {
    static const soup s = hmira_bench::make_torus(1024, false);
    return s;
}

template <class M>
void hmira_catmull_clark(benchmark::State& state) {
    const M base = build<M>(quad_torus());
    for (auto _ : state) {
        state.PauseTiming();
        M m = base;
        state.ResumeTiming();
        auto r = hmira::catmull_clark_subdivide(m);
        benchmark::DoNotOptimize(r);
        state.PauseTiming();
        if (!r || r->faces != 4 * quad_torus().faces.size()) state.SkipWithError("wrong face count");
        state.ResumeTiming();
    }
    state.counters["faces_in"] = double(quad_torus().faces.size());
}
BENCHMARK(hmira_catmull_clark<hmira::halfedge_mesh>)->Name("catmull_clark/hmira/halfedge_mesh")->Unit(benchmark::kMillisecond)->Iterations(1);

template <class M>
void hmira_loop(benchmark::State& state) {
    const M base = build<M>(triangle_torus());
    for (auto _ : state) {
        state.PauseTiming();
        M m = base;
        state.ResumeTiming();
        auto r = hmira::loop_subdivide(m);
        benchmark::DoNotOptimize(r);
        state.PauseTiming();
        if (!r || r->faces != 4 * triangle_torus().faces.size()) state.SkipWithError("wrong face count");
        state.ResumeTiming();
    }
    state.counters["faces_in"] = double(triangle_torus().faces.size());
}
BENCHMARK(hmira_loop<hmira::halfedge_mesh>)->Name("loop/hmira/halfedge_mesh")->Unit(benchmark::kMillisecond)->Iterations(1);

#ifdef HMIRA_BENCH_WITH_OPENMESH
using om_tri = OpenMesh::TriMesh_ArrayKernelT<>;
BENCHMARK(hmira_loop<om_tri>)->Name("loop/hmira/openmesh_tri")->Unit(benchmark::kMillisecond)->Iterations(1);
void openmesh_loop(benchmark::State& state) {
    const om_tri base = build<om_tri>(triangle_torus());
    for (auto _ : state) {
        state.PauseTiming();
        om_tri m = base;
        OpenMesh::Subdivider::Uniform::LoopT<om_tri> loop;
        loop.attach(m);
        state.ResumeTiming();
        loop(1);
        state.PauseTiming();
        loop.detach();
        if (m.n_faces() != 4 * triangle_torus().faces.size()) state.SkipWithError("wrong face count");
        state.ResumeTiming();
    }
}
BENCHMARK(openmesh_loop)->Name("loop/openmesh/LoopT")->Unit(benchmark::kMillisecond)->Iterations(1);

using om_poly = OpenMesh::PolyMesh_ArrayKernelT<>;
BENCHMARK(hmira_catmull_clark<om_poly>)->Name("catmull_clark/hmira/openmesh_poly")->Unit(benchmark::kMillisecond)->Iterations(1);
void openmesh_catmull_clark(benchmark::State& state) {
    const om_poly base = build<om_poly>(quad_torus());
    for (auto _ : state) {
        state.PauseTiming();
        om_poly m = base;
        OpenMesh::Subdivider::Uniform::CatmullClarkT<om_poly> cc;
        cc.attach(m);
        state.ResumeTiming();
        cc(1);
        state.PauseTiming();
        cc.detach();
        if (m.n_faces() != 4 * quad_torus().faces.size()) state.SkipWithError("wrong face count");
        state.ResumeTiming();
    }
}
BENCHMARK(openmesh_catmull_clark)->Name("catmull_clark/openmesh/CatmullClarkT")->Unit(benchmark::kMillisecond)->Iterations(1);
#endif

#ifdef HMIRA_BENCH_WITH_CGAL
using cgal_mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;
BENCHMARK(hmira_loop<cgal_mesh>)->Name("loop/hmira/cgal_surface_mesh")->Unit(benchmark::kMillisecond)->Iterations(1);
void cgal_loop(benchmark::State& state) {
    const cgal_mesh base = build<cgal_mesh>(triangle_torus());
    for (auto _ : state) {
        state.PauseTiming();
        cgal_mesh m = base;
        state.ResumeTiming();
        CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(1));
        state.PauseTiming();
        if (m.number_of_faces() != 4 * triangle_torus().faces.size()) state.SkipWithError("wrong face count");
        state.ResumeTiming();
    }
}
BENCHMARK(cgal_loop)->Name("loop/cgal/Loop_subdivision")->Unit(benchmark::kMillisecond)->Iterations(1);

BENCHMARK(hmira_catmull_clark<cgal_mesh>)->Name("catmull_clark/hmira/cgal_surface_mesh")->Unit(benchmark::kMillisecond)->Iterations(1);
void cgal_catmull_clark(benchmark::State& state) {
    const cgal_mesh base = build<cgal_mesh>(quad_torus());
    for (auto _ : state) {
        state.PauseTiming();
        cgal_mesh m = base;
        state.ResumeTiming();
        CGAL::Subdivision_method_3::CatmullClark_subdivision(m, CGAL::parameters::number_of_iterations(1));
        state.PauseTiming();
        if (m.number_of_faces() != 4 * quad_torus().faces.size()) state.SkipWithError("wrong face count");
        state.ResumeTiming();
    }
}
BENCHMARK(cgal_catmull_clark)->Name("catmull_clark/cgal/CatmullClark_subdivision")->Unit(benchmark::kMillisecond)->Iterations(1);
#endif

}  // namespace

int main(int argc, char** argv) {
    if (int rc = hmira_bench::run_benchmarks(argc, argv); rc != 0) return rc;
    using hmira_bench::print_ratio;
    std::printf("\nMedian CPU-time ratios (one level, ~1M faces in):\n");
    for (const std::string scheme : {"loop", "catmull_clark"}) {
        const std::string own = scheme + "/hmira/halfedge_mesh";
        const std::string om = scheme == "loop" ? "loop/openmesh/LoopT" : "catmull_clark/openmesh/CatmullClarkT";
        const std::string cg = scheme == "loop" ? "loop/cgal/Loop_subdivision" : "catmull_clark/cgal/CatmullClark_subdivision";
        print_ratio(scheme + ": hmira halfedge_mesh / OpenMesh", own, om, 0.5);
        print_ratio(scheme + ": hmira halfedge_mesh / CGAL", own, cg, 0.5);
        print_ratio(scheme + ": hmira on OpenMesh / hmira halfedge_mesh",
                    scheme + (scheme == "loop" ? "/hmira/openmesh_tri" : "/hmira/openmesh_poly"), own, 1.1);
        print_ratio(scheme + ": hmira on CGAL / hmira halfedge_mesh", scheme + "/hmira/cgal_surface_mesh", own, 1.1);
    }
    benchmark::Shutdown();
    return 0;
}
