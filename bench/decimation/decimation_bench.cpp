// Decimation to 1% of bunny00.off Loop-subdivided twice (1,206,528 triangles), in one run on
// the same input: hmira's decimate on halfedge_mesh and (generic, same code) on OpenMesh TriMesh
// and CGAL Surface_mesh, beside CGAL's Surface_mesh_simplification::edge_collapse with
// GarlandHeckbert_plane_policies and OpenMesh's Decimater with ModQuadricT. Open3D runs from
// peers.py on the input this program writes. Copies are made outside the timed region; each
// case runs `--reps` times (default 3) and reports the median.
// Usage: decimation_bench [--bunny FILE] [--out DIR] [--reps N] [--ratio R]
// With --out, writes input.off and each case's output (<case>.off) there for the quality tool,
// and prints "case seconds faces" lines that run.sh turns into ratios.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <ctime>
#include <map>
#include <string>
#include <vector>

#include <hmira/algorithms/decimation/decimate.hpp>
#include <hmira/algorithms/subdivision/loop.hpp>
#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#ifdef HMIRA_BENCH_WITH_OPENMESH
#include <hmira/interop/openmesh.hpp>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>
#endif
#ifdef HMIRA_BENCH_WITH_CGAL
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <hmira/interop/cgal.hpp>
#ifdef HMIRA_BENCH_WITH_EIGEN
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#endif
#endif

namespace {

using clock_type = std::chrono::steady_clock;

/// A copy of `from` in another model, face by face through the traits.
template <class M, class F, class TM = hmira::default_traits<M>, class TF = hmira::default_traits<F>>
M convert(const F& from) {
    M m;
    std::vector<typename TM::vertex_handle> vs(TF::vertex_index_bound(from));
    for (auto v : TF::vertices(from)) {
        const auto p = TF::position(from, v);
        vs[TF::vertex_index(from, v)] =
            TM::add_vertex(m, {typename TM::scalar(p[0]), typename TM::scalar(p[1]), typename TM::scalar(p[2])});
    }
    std::vector<typename TM::vertex_handle> c;
    for (auto f : TF::faces(from)) {
        c.clear();
        for (auto v : TF::face_vertices(from, f)) c.push_back(vs[TF::vertex_index(from, v)]);
        if (!TM::add_face(m, std::span<const typename TM::vertex_handle>(c))) {
            std::fprintf(stderr, "convert: a face was refused\n");
            std::exit(1);
        }
    }
    return m;
}

struct outcome {
    double seconds;      // wall, median
    double cpu_seconds;  // process CPU time, median: the honest figure on a shared machine
    std::size_t faces;
};

double cpu_now() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

/// Times `run` on fresh copies of `base`; the first copy's result is written to out/<name>.off.
template <class M, class Run>
outcome measure(const std::string& name, const M& base, int reps, const std::filesystem::path& out, Run run) {
    std::vector<double> s, cpu;
    std::size_t faces = 0;
    for (int i = 0; i < reps; ++i) {
        M m = base;
        const auto t0 = clock_type::now();
        const double c0 = cpu_now();
        faces = run(m);
        cpu.push_back(cpu_now() - c0);
        s.push_back(std::chrono::duration<double>(clock_type::now() - t0).count());
        if (i == 0 && !out.empty()) {
            if constexpr (requires { hmira::io::write_mesh(m, out / (name + ".off")); }) {
                if (!hmira::io::write_mesh(m, out / (name + ".off")))
                    std::fprintf(stderr, "cannot write %s.off\n", name.c_str());
            }
        }
    }
    std::sort(s.begin(), s.end());
    std::sort(cpu.begin(), cpu.end());
    std::printf("%-28s %8.3f s wall %8.3f s cpu  %8zu faces\n", name.c_str(), s[s.size() / 2], cpu[cpu.size() / 2],
                faces);
    std::fflush(stdout);
    return {s[s.size() / 2], cpu[cpu.size() / 2], faces};
}

}  // namespace

int main(int argc, char** argv) {
    std::filesystem::path bunny, out;
    int reps = 3;
    double ratio = 0.01;
    if (const char* d = std::getenv("HMIRA_TEST_DATA")) bunny = std::filesystem::path(d) / "meshes" / "bunny00.off";
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string a = argv[i];
        if (a == "--bunny")
            bunny = argv[i + 1];
        else if (a == "--out")
            out = argv[i + 1];
        else if (a == "--reps")
            reps = std::max(1, std::atoi(argv[i + 1]));
        else if (a == "--ratio")
            ratio = std::atof(argv[i + 1]);
        else {
            std::fprintf(stderr, "unknown option %s\n", a.c_str());
            return 2;
        }
    }
    hmira::halfedge_mesh base;
    if (auto r = hmira::io::read_mesh(base, bunny); !r) {
        std::fprintf(stderr, "%s\n", r.error().message.c_str());
        return 1;
    }
    if (auto r = hmira::loop_subdivide(base, {.levels = 2}); !r) {
        std::fprintf(stderr, "%s\n", r.error().message.c_str());
        return 1;
    }
    base = convert<hmira::halfedge_mesh>(base);  // compact, as a freshly read mesh
    const std::size_t faces = hmira::default_traits<hmira::halfedge_mesh>::face_count(base);
    const std::size_t target = std::size_t(double(faces) * ratio + 0.5);
    std::printf("input %zu triangles, target %zu\n", faces, target);
    if (!out.empty()) {
        std::filesystem::create_directories(out);
        if (!hmira::io::write_mesh(base, out / "input.off")) return 1;
    }
    std::map<std::string, outcome> results;
    auto ours = [&](auto& m) {
        auto r = hmira::decimate(m, {.target_faces = target});
        if (!r) {
            std::fprintf(stderr, "%s\n", r.error().message.c_str());
            std::exit(1);
        }
        return r->faces;
    };
    results["hmira/halfedge_mesh"] = measure("hmira_halfedge_mesh", base, reps, out, ours);
#ifdef HMIRA_BENCH_WITH_OPENMESH
    using om_tri = OpenMesh::TriMesh_ArrayKernelT<>;
    const om_tri om = convert<om_tri>(base);
    results["hmira/openmesh_tri"] = measure("hmira_openmesh_tri", om, reps, out, ours);
    results["openmesh/decimater"] = measure("openmesh_decimater", om, reps, out, [&](om_tri& m) {
        OpenMesh::Decimater::DecimaterT<om_tri> decimater(m);
        OpenMesh::Decimater::ModQuadricT<om_tri>::Handle quadric;
        decimater.add(quadric);
        decimater.initialize();
        decimater.decimate_to_faces(0, target);
        m.garbage_collection();
        return std::size_t(m.n_faces());
    });
#endif
#ifdef HMIRA_BENCH_WITH_CGAL
    using sm = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;
    const sm cm = convert<sm>(base);
    results["hmira/cgal_surface_mesh"] = measure("hmira_cgal_surface_mesh", cm, reps, out, ours);
#ifdef HMIRA_BENCH_WITH_EIGEN
    results["cgal/edge_collapse_gh"] = measure("cgal_edge_collapse_gh", cm, reps, out, [&](sm& m) {
        namespace SMS = CGAL::Surface_mesh_simplification;
        SMS::GarlandHeckbert_plane_policies<sm, CGAL::Simple_cartesian<double>> policies(m);
        auto stop = [&](const auto&, const auto&, std::size_t, std::size_t) { return m.number_of_faces() <= target; };
        SMS::edge_collapse(m, stop,
                           CGAL::parameters::get_cost(policies.get_cost()).get_placement(policies.get_placement()));
        return std::size_t(m.number_of_faces());
    });
#endif
#endif
    const outcome h = results["hmira/halfedge_mesh"];
    std::printf("\nratios of medians, one run (wall, cpu):\n");
    for (const auto& [name, o] : results)
        if (name.rfind("hmira/", 0) != 0)
            std::printf("  hmira halfedge_mesh / %-24s %.3f  %.3f\n", name.c_str(), h.seconds / o.seconds,
                        h.cpu_seconds / o.cpu_seconds);
    for (const auto& [name, o] : results)
        if (name.rfind("hmira/", 0) == 0 && name != "hmira/halfedge_mesh")
            std::printf("  %-24s / hmira halfedge_mesh %.3f  %.3f\n", name.c_str(), o.seconds / h.seconds,
                        o.cpu_seconds / h.cpu_seconds);
    std::printf("hmira_halfedge_seconds %.6f %.6f\n", h.seconds, h.cpu_seconds);
    return 0;
}
