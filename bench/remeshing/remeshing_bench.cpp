// remeshing_bench MESH [--factor F] [-k K] [--features DEG] [--repeat R]
// Remeshes MESH to target length L = F x its mean edge length (default F = 1) with K iterations
// (default 5): hmira's isotropic_remeshing on halfedge_mesh and (the same generic code) on
// OpenMesh TriMesh and CGAL Surface_mesh, and CGAL's PMP::isotropic_remeshing on Surface_mesh
// with the same L and K (and, with --features, sharp edges detected at the same angle and given
// as constraints). Each case runs R times (default 3) on a fresh copy, copied outside the
// timer; the median CPU time is reported. Then the ratios against the targets (hmira / CGAL <= 0.7;
// generic / halfedge_mesh <= 1.15) and the quality of hmira's and CGAL's outputs: minimum-angle
// percentiles, edges within [4/5, 4/3] L, and the sampled Hausdorff distance to the input.
#include <algorithm>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <hmira/algorithms/remeshing/isotropic_remeshing.hpp>
#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "quality/quality.hpp"

#ifdef HMIRA_BENCH_WITH_OPENMESH
#include <hmira/interop/openmesh.hpp>
#endif
#ifdef HMIRA_BENCH_WITH_CGAL
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Simple_cartesian.h>
#include <hmira/interop/cgal.hpp>
#endif

namespace {

namespace q = hmira_bench::quality;

struct options {
    std::string path;
    double factor = 1;
    std::size_t iterations = 5;
    std::optional<double> features;
    int repeat = 3;
};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

/// CPU seconds used by the process so far: the machine may be loaded, and CPU time is what
/// the comparison is about (every case runs on one thread).
double cpu_seconds() { return double(std::clock()) / CLOCKS_PER_SEC; }

/// Times `run` on fresh copies of `input`; returns the median CPU seconds and the last output.
template <class M>
std::pair<double, M> time_case(const M& input, int repeat, const std::function<void(M&)>& run) {
    std::vector<double> t;
    M out;
    for (int i = 0; i < repeat; ++i) {
        M m = input;
        const double t0 = cpu_seconds();
        run(m);
        t.push_back(cpu_seconds() - t0);
        out = std::move(m);
    }
    return {median(t), std::move(out)};
}

template <class M>
void hmira_remesh(M& m, double L, const options& o) {
    auto r = hmira::isotropic_remeshing(
        m, {.target_edge_length = L, .iterations = o.iterations, .feature_angle = o.features});
    if (!r) {
        std::fprintf(stderr, "remeshing_bench: %s\n", r.error().message.c_str());
        std::exit(1);
    }
}

void report_quality(const char* label, const q::triangle_soup& input, const q::triangle_soup& out, double L) {
    const auto t = q::measure_triangles(out);
    const auto e = q::measure_edges(out);
    const auto h = q::hausdorff(input, out, 10, 1000000);
    std::printf(
        "  %-26s %8zu faces  min angle p1 %6.2f median %6.2f min %6.2f  in [4/5,4/3]L %6.2f%%  Hausdorff %.4g\n", label,
        out.triangles.size(), q::triangle_quality::percentile(t.min_angles, 0.01),
        q::triangle_quality::percentile(t.min_angles, 0.5), t.min_angles.empty() ? 0.0 : t.min_angles.front(),
        100 * e.fraction_within(0.8 * L, 4.0 / 3.0 * L), h.symmetric());
}

}  // namespace

int main(int argc, char** argv) {
    options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto number = [&]() {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "remeshing_bench: option %s needs a value\n", a.c_str());
                std::exit(2);
            }
            return std::atof(argv[++i]);
        };
        if (a == "--factor")
            o.factor = number();
        else if (a == "-k")
            o.iterations = std::size_t(number());
        else if (a == "--features")
            o.features = number();
        else if (a == "--repeat")
            o.repeat = std::max(1, int(number()));
        else
            o.path = a;
    }
    if (o.path.empty()) {
        std::fprintf(stderr, "usage: remeshing_bench MESH [--factor F] [-k K] [--features DEG] [--repeat R]\n");
        return 2;
    }
    hmira::halfedge_mesh he;
    if (auto r = hmira::io::read_mesh(he, o.path); !r) {
        std::fprintf(stderr, "remeshing_bench: %s\n", r.error().message.c_str());
        return 1;
    }
    const auto input = q::soup_of(he);
    const double L = o.factor * q::measure_edges(input).mean;
    std::printf("%s: %zu triangles, L = %.5g (%.2f x mean edge), %zu iterations%s\n", o.path.c_str(),
                input.triangles.size(), L, o.factor, o.iterations, o.features ? ", features kept" : "");

    const auto [t_he, out_he] = time_case<hmira::halfedge_mesh>(he, o.repeat, [&](auto& m) { hmira_remesh(m, L, o); });
    std::printf("  hmira halfedge_mesh          %8.3f s\n", t_he);
#ifdef HMIRA_BENCH_WITH_OPENMESH
    OpenMesh::TriMesh_ArrayKernelT<> om;
    if (!hmira::io::read_mesh(om, o.path)) return 1;
    const auto [t_om, out_om] =
        time_case<OpenMesh::TriMesh_ArrayKernelT<>>(om, o.repeat, [&](auto& m) { hmira_remesh(m, L, o); });
    std::printf("  hmira OpenMesh TriMesh       %8.3f s  (%.2fx halfedge_mesh, target <= 1.15)\n", t_om, t_om / t_he);
#endif
#ifdef HMIRA_BENCH_WITH_CGAL
    using surface_mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;
    surface_mesh sm;
    if (!hmira::io::read_mesh(sm, o.path)) return 1;
    const auto [t_sm, out_sm] = time_case<surface_mesh>(sm, o.repeat, [&](auto& m) { hmira_remesh(m, L, o); });
    std::printf("  hmira CGAL Surface_mesh      %8.3f s  (%.2fx halfedge_mesh, target <= 1.15)\n", t_sm, t_sm / t_he);
    namespace PMP = CGAL::Polygon_mesh_processing;
    const auto [t_cgal, out_cgal] = time_case<surface_mesh>(sm, o.repeat, [&](surface_mesh& m) {
        auto ecm = m.add_property_map<surface_mesh::Edge_index, bool>("e:constrained", false).first;
        if (o.features) PMP::detect_sharp_edges(m, *o.features, ecm);
        PMP::isotropic_remeshing(
            faces(m), L, m,
            CGAL::parameters::number_of_iterations(unsigned(o.iterations)).edge_is_constrained_map(ecm));
    });
    std::printf("  CGAL PMP::isotropic_remeshing %7.3f s\n", t_cgal);
    std::printf("  ratio hmira halfedge_mesh / CGAL: %.2f (target <= 0.7)\n", t_he / t_cgal);
#endif
    std::printf("quality (sampled Hausdorff to the input, >= 10^6 samples each way):\n");
    report_quality("hmira halfedge_mesh", input, q::soup_of(out_he), L);
#ifdef HMIRA_BENCH_WITH_OPENMESH
    report_quality("hmira OpenMesh TriMesh", input, q::soup_of(out_om), L);
#endif
#ifdef HMIRA_BENCH_WITH_CGAL
    report_quality("hmira CGAL Surface_mesh", input, q::soup_of(out_sm), L);
    report_quality("CGAL", input, q::soup_of(out_cgal), L);
#endif
    return 0;
}
