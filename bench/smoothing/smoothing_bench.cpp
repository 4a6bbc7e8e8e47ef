// Smoothing beside the peers, in one run, on a torus of 2 * 724^2 ~ 1.05M triangles whose
// vertices are jittered along their normals (seeded), ten steps each:
// - hmira's laplacian_smooth (uniform weights, lambda 0.5) on halfedge_mesh and (generic, same
//   code) on OpenMesh TriMesh, beside OpenMesh's JacobiLaplaceSmootherT (Tangential_and_Normal,
//   C0: the same uniform umbrella operator with the same 0.5 step, Jacobi updates);
// - hmira's taubin_smooth (ten lambda/mu pairs, so twenty steps) on halfedge_mesh;
// - CGAL's PMP::angle_and_area_smoothing with angle smoothing only, ten iterations: a different
//   method (it moves vertices to even out angles, tangentially), shown for scale only.
// The mesh is copied outside the timed region. After the run: hmira / OpenMesh (target <= 1.0,
// none in the issue) and hmira on OpenMesh / on halfedge_mesh (target <= 1.1).
#include <random>

#include <hmira/algorithms/smoothing/laplacian_smooth.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "support/peer_bench.hpp"

#ifdef HMIRA_BENCH_WITH_OPENMESH
#include <hmira/interop/openmesh.hpp>
#include <OpenMesh/Tools/Smoother/JacobiLaplaceSmootherT.hh>
#endif
#ifdef HMIRA_BENCH_WITH_CGAL
#include <CGAL/Polygon_mesh_processing/angle_and_area_smoothing.h>
#include <CGAL/Simple_cartesian.h>
#include <hmira/interop/cgal.hpp>
#endif

namespace {

using hmira_bench::soup;

constexpr std::size_t steps = 10;

const soup& noisy_torus() {
    static const soup s = [] {
        soup t = hmira_bench::make_torus(724, true);
        std::mt19937_64 rng(5);
        std::uniform_real_distribution<double> jitter(0.99, 1.01);
        for (auto& p : t.points) p = p * jitter(rng);  // radial noise of 1%
        return t;
    }();
    return s;
}

template <class M>
void hmira_laplacian(benchmark::State& state) {
    const M base = hmira_bench::build<M>(noisy_torus());
    for (auto _ : state) {
        state.PauseTiming();
        M m = base;
        state.ResumeTiming();
        auto r = hmira::laplacian_smooth(m, {.iterations = steps, .lambda = 0.5});
        benchmark::DoNotOptimize(r);
        state.PauseTiming();
        if (!r) state.SkipWithError("laplacian_smooth failed");
        state.ResumeTiming();
    }
}
BENCHMARK(hmira_laplacian<hmira::halfedge_mesh>)
    ->Name("laplacian/hmira/halfedge_mesh")
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

void hmira_taubin(benchmark::State& state) {
    const hmira::halfedge_mesh base = hmira_bench::build<hmira::halfedge_mesh>(noisy_torus());
    for (auto _ : state) {
        state.PauseTiming();
        hmira::halfedge_mesh m = base;
        state.ResumeTiming();
        auto r = hmira::taubin_smooth(m, {.iterations = steps});
        benchmark::DoNotOptimize(r);
        state.PauseTiming();
        if (!r) state.SkipWithError("taubin_smooth failed");
        state.ResumeTiming();
    }
}
BENCHMARK(hmira_taubin)->Name("taubin/hmira/halfedge_mesh")->Unit(benchmark::kMillisecond)->Iterations(1);

#ifdef HMIRA_BENCH_WITH_OPENMESH
using om_tri = OpenMesh::TriMesh_ArrayKernelT<>;
BENCHMARK(hmira_laplacian<om_tri>)->Name("laplacian/hmira/openmesh_tri")->Unit(benchmark::kMillisecond)->Iterations(1);
void openmesh_jacobi(benchmark::State& state) {
    const om_tri base = hmira_bench::build<om_tri>(noisy_torus());
    for (auto _ : state) {
        state.PauseTiming();
        om_tri m = base;
        OpenMesh::Smoother::JacobiLaplaceSmootherT<om_tri> smoother(m);
        state.ResumeTiming();
        smoother.initialize(OpenMesh::Smoother::JacobiLaplaceSmootherT<om_tri>::Tangential_and_Normal,
                            OpenMesh::Smoother::JacobiLaplaceSmootherT<om_tri>::C0);
        smoother.smooth(unsigned(steps));
        benchmark::ClobberMemory();
    }
}
BENCHMARK(openmesh_jacobi)
    ->Name("laplacian/openmesh/JacobiLaplaceSmootherT")
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
#endif

#ifdef HMIRA_BENCH_WITH_CGAL
using cgal_mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;
void cgal_angle_smoothing(benchmark::State& state) {
    const cgal_mesh base = hmira_bench::build<cgal_mesh>(noisy_torus());
    for (auto _ : state) {
        state.PauseTiming();
        cgal_mesh m = base;
        state.ResumeTiming();
        CGAL::Polygon_mesh_processing::angle_and_area_smoothing(m,
                                                                CGAL::parameters::number_of_iterations(unsigned(steps))
                                                                    .use_angle_smoothing(true)
                                                                    .use_area_smoothing(false));
        benchmark::ClobberMemory();
    }
}
BENCHMARK(cgal_angle_smoothing)
    ->Name("angle/cgal/angle_and_area_smoothing")
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
#endif

}  // namespace

int main(int argc, char** argv) {
    if (int rc = hmira_bench::run_benchmarks(argc, argv); rc != 0) return rc;
    using hmira_bench::print_ratio;
    std::printf("\nMedian CPU-time ratios (ten steps, ~1M triangles):\n");
    print_ratio("laplacian: hmira halfedge_mesh / OpenMesh Jacobi", "laplacian/hmira/halfedge_mesh",
                "laplacian/openmesh/JacobiLaplaceSmootherT", 1.0);
    print_ratio("laplacian: hmira on OpenMesh / hmira halfedge_mesh", "laplacian/hmira/openmesh_tri",
                "laplacian/hmira/halfedge_mesh", 1.1);
    print_ratio("taubin (20 steps) hmira / CGAL angle smoothing (10)", "taubin/hmira/halfedge_mesh",
                "angle/cgal/angle_and_area_smoothing", 1.0);
    benchmark::Shutdown();
    return 0;
}
