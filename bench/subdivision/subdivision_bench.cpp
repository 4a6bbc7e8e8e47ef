// One subdivision level of ~1M-face tori, in one run, on the same input for every case:
// - Loop, on a triangulated torus of 2 * 724^2 ~ 1.05M triangles: hmira's loop_subdivide on
//   halfedge_mesh and (generic, same code) on OpenMesh TriMesh and CGAL Surface_mesh, beside
//   OpenMesh's LoopT and CGAL's Loop_subdivision;
// - sqrt(3), on the same triangulated torus: sqrt3_subdivide on the same three models, beside
//   OpenMesh's Sqrt3T and CGAL's Sqrt3_subdivision (no target in the issue; shown for scale);
// - Catmull-Clark, on a torus of 1024^2 ~ 1.05M quads: catmull_clark_subdivide on
//   halfedge_mesh, OpenMesh PolyMesh and Surface_mesh, beside OpenMesh's CatmullClarkT and
//   CGAL's CatmullClark_subdivision.
// The mesh is copied outside the timed region; each case runs one iteration per repetition (a
// level takes a fraction of a second to seconds) and is repeated 3 times. After the run the
// medians are compared: hmira on halfedge_mesh / each peer (target <= 0.5), and hmira generic
// on OpenMesh and CGAL / hmira on halfedge_mesh (target <= 1.1). Run single-threaded.
// Each case also reports its user and system CPU time and the fresh memory it touched (minor
// page faults, in MB; a huge page counts as one fault): at a million faces the kernel's
// faulting and zeroing of the output's fresh pages (system time) is a large share of the CPU
// time and depends on the output's size alone, so the summary gives the ratios of user and of
// system time as well. bench/subdivision/run.sh runs it with and without transparent huge pages.
// The <scheme>/reserve/<model> cases time the traits' reserve alone, the same call to the same
// counts the algorithm makes before its first change (T::reserve(v + e, 2e + 3f, 4f) for Loop,
// T::reserve(v + e + f, 2e + corners, corners) for Catmull-Clark): on halfedge_mesh the
// connectivity moves by realloc (mremap keeps its pages) and only the positions' std::vector
// is copied; on OpenMesh and Surface_mesh std::vector::reserve copies every property array into
// fresh pages and frees the old ones. The <scheme>/grow/<model> cases add the traits' resize
// to the same counts (every new element appended at its defaults, which the algorithm does in
// blocks): the model's whole storage growth. The last two tables give, per model, the generic
// algorithm on it / on halfedge_mesh, whole and less each model's reserve (or growth): what
// the algorithm costs beyond the model's storage; and the fresh memory of the whole run and
// of that step alone.
// catmull_clark/hmira/openmesh_poly_double runs on a PolyMesh with double points (Vec3d),
// where the face points go straight into their vertices as on halfedge_mesh; with OpenMesh's
// default float points they need a double array of their own.
#include <benchmark/benchmark.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

#include <hmira/algorithms/subdivision/catmull_clark.hpp>
#include <hmira/algorithms/subdivision/loop.hpp>
#include <hmira/algorithms/subdivision/sqrt3.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "support/peer_bench.hpp"

#ifdef HMIRA_BENCH_WITH_OPENMESH
// The interop header first: CatmullClarkT.hh uses OpenMesh's property handles without including them.
#include <hmira/interop/openmesh.hpp>
#include <OpenMesh/Tools/Subdivider/Uniform/CatmullClarkT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/Sqrt3T.hh>
#endif
#ifdef HMIRA_BENCH_WITH_CGAL
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <hmira/interop/cgal.hpp>
#endif

namespace {

using hmira_bench::build;
using hmira_bench::soup;

/// Each case's single-run user and system CPU times, by name, for the summary.
std::map<std::string, std::vector<double>>& user_seconds_by_case() {
    static std::map<std::string, std::vector<double>> s;
    return s;
}
std::map<std::string, std::vector<double>>& sys_seconds_by_case() {
    static std::map<std::string, std::vector<double>> s;
    return s;
}
/// User plus system time of each single run (what the CPU-time ratios compare).
std::map<std::string, std::vector<double>>& cpu_seconds_by_case() {
    static std::map<std::string, std::vector<double>> s;
    return s;
}
/// Fresh memory each single run touched (minor page faults times the page size), in MB.
std::map<std::string, std::vector<double>>& fresh_mb_by_case() {
    static std::map<std::string, std::vector<double>> s;
    return s;
}

double seconds(const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); }

/// Runs f (the timed part) and records its user CPU time and fresh memory touched.
template <class F>
void measured(benchmark::State& state, const std::string& name, F&& f) {
    rusage before{}, after{};
    getrusage(RUSAGE_SELF, &before);
    f();
    getrusage(RUSAGE_SELF, &after);
    const double user = seconds(after.ru_utime) - seconds(before.ru_utime);
    const double sys = seconds(after.ru_stime) - seconds(before.ru_stime);
    user_seconds_by_case()[name].push_back(user);
    sys_seconds_by_case()[name].push_back(sys);
    // A minor fault maps one page, or a whole transparent huge page (counted as one base page
    // here, so with huge pages the figure is a lower bound).
    static const double page_bytes = double(sysconf(_SC_PAGESIZE));
    const double fresh_mb = double(after.ru_minflt - before.ru_minflt) * page_bytes / 1e6;
    cpu_seconds_by_case()[name].push_back(user + sys);
    fresh_mb_by_case()[name].push_back(fresh_mb);
    state.counters["cpu_ms"] = (user + sys) * 1e3;
    state.counters["user_ms"] = user * 1e3;
    state.counters["sys_ms"] = sys * 1e3;
    state.counters["fresh_MB"] = fresh_mb;
}

/// Registers a case under its name, which it also receives, one iteration per repetition.
int add_case(const char* name, void (*run)(benchmark::State&, const char*)) {
    benchmark::RegisterBenchmark(name, run, name)->Unit(benchmark::kMillisecond)->Iterations(1);
    return 0;
}

double median_in(std::map<std::string, std::vector<double>>& by_case, const std::string& name) {
    auto v = by_case[name];
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

const soup& triangle_torus() {
    static const soup s = hmira_bench::make_torus(724, true);
    return s;
}
const soup& quad_torus() {
    static const soup s = hmira_bench::make_torus(1024, false);
    return s;
}

template <class M>
void hmira_catmull_clark(benchmark::State& state, const char* name) {
    const M base = build<M>(quad_torus());
    for (auto _ : state) {
        state.PauseTiming();
        M m = base;
        state.ResumeTiming();
        hmira::result<hmira::catmull_clark_result> r = hmira::catmull_clark_result{};
        measured(state, name, [&] { r = hmira::catmull_clark_subdivide(m); });
        benchmark::DoNotOptimize(r);
        state.PauseTiming();
        if (!r || r->faces != 4 * quad_torus().faces.size()) state.SkipWithError("wrong face count");
        state.ResumeTiming();
    }
    state.counters["faces_in"] = double(quad_torus().faces.size());
}
const int registered_1 = add_case("catmull_clark/hmira/halfedge_mesh", &hmira_catmull_clark<hmira::halfedge_mesh>);

/// hmira's Loop (factor 4) or sqrt(3) (factor 3) on the triangle torus.
template <class M, int Factor>
void hmira_triangle_scheme(benchmark::State& state, const char* name) {
    const M base = build<M>(triangle_torus());
    for (auto _ : state) {
        state.PauseTiming();
        M m = base;
        state.ResumeTiming();
        std::size_t faces = 0;
        bool ok = false;
        measured(state, name, [&] {
            if constexpr (Factor == 4) {
                auto r = hmira::loop_subdivide(m);
                ok = bool(r), faces = r ? r->faces : 0;
            } else {
                auto r = hmira::sqrt3_subdivide(m);
                ok = bool(r), faces = r ? r->faces : 0;
            }
        });
        benchmark::DoNotOptimize(faces);
        state.PauseTiming();
        if (!ok || faces != Factor * triangle_torus().faces.size()) state.SkipWithError("wrong face count");
        state.ResumeTiming();
    }
    state.counters["faces_in"] = double(triangle_torus().faces.size());
}
template <class M>
void hmira_loop(benchmark::State& state, const char* name) {
    hmira_triangle_scheme<M, 4>(state, name);
}
template <class M>
void hmira_sqrt3(benchmark::State& state, const char* name) {
    hmira_triangle_scheme<M, 3>(state, name);
}
const int registered_2 = add_case("loop/hmira/halfedge_mesh", &hmira_loop<hmira::halfedge_mesh>);
const int registered_11 = add_case("sqrt3/hmira/halfedge_mesh", &hmira_sqrt3<hmira::halfedge_mesh>);

/// The traits' reserve alone, to the counts one Loop (Quad false, triangle torus) or
/// Catmull-Clark (Quad true, quad torus) level ends with: the share of a scheme's time that
/// is the model's storage growing, whatever algorithm runs. With Grow, also the traits'
/// resize to those counts: every new element appended at its defaults, as the algorithm's
/// blocks do (new_elements.hpp; here in one call, so the fill is not in cache when written).
template <class M, bool Quad, bool Grow = false>
void reserve_only(benchmark::State& state, const char* name) {
    using T = hmira::default_traits<M>;
    const soup& s = Quad ? quad_torus() : triangle_torus();
    const M base = build<M>(s);
    const std::size_t v = T::vertex_index_bound(base), e = T::edge_index_bound(base), f = T::face_index_bound(base);
    const std::size_t corners = (Quad ? 4 : 3) * f;
    for (auto _ : state) {
        state.PauseTiming();
        M m = base;
        state.ResumeTiming();
        measured(state, name, [&] {
            const std::size_t nv = Quad ? v + e + f : v + e, ne = Quad ? 2 * e + corners : 2 * e + 3 * f,
                              nf = Quad ? corners : 4 * f;
            T::reserve(m, nv, ne, nf);
            if constexpr (Grow) T::resize(m, nv, ne, nf);
        });
        benchmark::DoNotOptimize(m);
    }
}
const int registered_16 = add_case("loop/reserve/halfedge_mesh", &reserve_only<hmira::halfedge_mesh, false>);
const int registered_17 = add_case("catmull_clark/reserve/halfedge_mesh", &reserve_only<hmira::halfedge_mesh, true>);
const int registered_24 = add_case("loop/grow/halfedge_mesh", &reserve_only<hmira::halfedge_mesh, false, true>);
const int registered_25 = add_case("catmull_clark/grow/halfedge_mesh", &reserve_only<hmira::halfedge_mesh, true, true>);

#ifdef HMIRA_BENCH_WITH_OPENMESH
using om_tri = OpenMesh::TriMesh_ArrayKernelT<>;
const int registered_3 = add_case("loop/hmira/openmesh_tri", &hmira_loop<om_tri>);
/// OpenMesh's uniform subdivider S (LoopT, Sqrt3T), one level, on the triangle torus.
template <class S, int Factor>
void openmesh_triangle_scheme(benchmark::State& state, const char* name) {
    const om_tri base = build<om_tri>(triangle_torus());
    for (auto _ : state) {
        state.PauseTiming();
        om_tri m = base;
        S subdivider;
        subdivider.attach(m);
        state.ResumeTiming();
        measured(state, name, [&] { subdivider(1); });
        state.PauseTiming();
        subdivider.detach();
        if (m.n_faces() != Factor * triangle_torus().faces.size()) state.SkipWithError("wrong face count");
        state.ResumeTiming();
    }
}
void openmesh_loop(benchmark::State& state, const char* name) {
    openmesh_triangle_scheme<OpenMesh::Subdivider::Uniform::LoopT<om_tri>, 4>(state, name);
}
void openmesh_sqrt3(benchmark::State& state, const char* name) {
    openmesh_triangle_scheme<OpenMesh::Subdivider::Uniform::Sqrt3T<om_tri>, 3>(state, name);
}
const int registered_4 = add_case("loop/openmesh/LoopT", &openmesh_loop);
const int registered_12 = add_case("sqrt3/hmira/openmesh_tri", &hmira_sqrt3<om_tri>);
const int registered_13 = add_case("sqrt3/openmesh/Sqrt3T", &openmesh_sqrt3);

using om_poly = OpenMesh::PolyMesh_ArrayKernelT<>;
const int registered_5 = add_case("catmull_clark/hmira/openmesh_poly", &hmira_catmull_clark<om_poly>);
/// OpenMesh's PolyMesh with double points, as halfedge_mesh has.
struct om_double_traits : OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3d;
    using Normal = OpenMesh::Vec3d;
};
using om_poly_double = OpenMesh::PolyMesh_ArrayKernelT<om_double_traits>;
const int registered_18 = add_case("catmull_clark/hmira/openmesh_poly_double", &hmira_catmull_clark<om_poly_double>);
const int registered_19 = add_case("loop/reserve/openmesh_tri", &reserve_only<om_tri, false>);
const int registered_20 = add_case("catmull_clark/reserve/openmesh_poly", &reserve_only<om_poly, true>);
const int registered_21 = add_case("catmull_clark/reserve/openmesh_poly_double", &reserve_only<om_poly_double, true>);
const int registered_26 = add_case("loop/grow/openmesh_tri", &reserve_only<om_tri, false, true>);
const int registered_27 = add_case("catmull_clark/grow/openmesh_poly", &reserve_only<om_poly, true, true>);
const int registered_28 =
    add_case("catmull_clark/grow/openmesh_poly_double", &reserve_only<om_poly_double, true, true>);
void openmesh_catmull_clark(benchmark::State& state, const char* name) {
    const om_poly base = build<om_poly>(quad_torus());
    for (auto _ : state) {
        state.PauseTiming();
        om_poly m = base;
        OpenMesh::Subdivider::Uniform::CatmullClarkT<om_poly> cc;
        cc.attach(m);
        state.ResumeTiming();
        measured(state, name, [&] { cc(1); });
        state.PauseTiming();
        cc.detach();
        if (m.n_faces() != 4 * quad_torus().faces.size()) state.SkipWithError("wrong face count");
        state.ResumeTiming();
    }
}
const int registered_6 = add_case("catmull_clark/openmesh/CatmullClarkT", &openmesh_catmull_clark);
#endif

#ifdef HMIRA_BENCH_WITH_CGAL
using cgal_mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;
const int registered_7 = add_case("loop/hmira/cgal_surface_mesh", &hmira_loop<cgal_mesh>);
/// CGAL's Loop_subdivision or Sqrt3_subdivision, one level, on the triangle torus.
template <int Factor>
void cgal_triangle_scheme(benchmark::State& state, const char* name) {
    const cgal_mesh base = build<cgal_mesh>(triangle_torus());
    for (auto _ : state) {
        state.PauseTiming();
        cgal_mesh m = base;
        state.ResumeTiming();
        measured(state, name, [&] {
            if constexpr (Factor == 4)
                CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(1));
            else
                CGAL::Subdivision_method_3::Sqrt3_subdivision(m, CGAL::parameters::number_of_iterations(1));
        });
        state.PauseTiming();
        if (m.number_of_faces() != Factor * triangle_torus().faces.size()) state.SkipWithError("wrong face count");
        state.ResumeTiming();
    }
}
void cgal_loop(benchmark::State& state, const char* name) { cgal_triangle_scheme<4>(state, name); }
void cgal_sqrt3(benchmark::State& state, const char* name) { cgal_triangle_scheme<3>(state, name); }
const int registered_8 = add_case("loop/cgal/Loop_subdivision", &cgal_loop);
const int registered_14 = add_case("sqrt3/hmira/cgal_surface_mesh", &hmira_sqrt3<cgal_mesh>);
const int registered_15 = add_case("sqrt3/cgal/Sqrt3_subdivision", &cgal_sqrt3);

const int registered_9 = add_case("catmull_clark/hmira/cgal_surface_mesh", &hmira_catmull_clark<cgal_mesh>);
void cgal_catmull_clark(benchmark::State& state, const char* name) {
    const cgal_mesh base = build<cgal_mesh>(quad_torus());
    for (auto _ : state) {
        state.PauseTiming();
        cgal_mesh m = base;
        state.ResumeTiming();
        measured(state, name, [&] {
            CGAL::Subdivision_method_3::CatmullClark_subdivision(m, CGAL::parameters::number_of_iterations(1));
        });
        state.PauseTiming();
        if (m.number_of_faces() != 4 * quad_torus().faces.size()) state.SkipWithError("wrong face count");
        state.ResumeTiming();
    }
}
const int registered_10 = add_case("catmull_clark/cgal/CatmullClark_subdivision", &cgal_catmull_clark);
const int registered_22 = add_case("loop/reserve/cgal_surface_mesh", &reserve_only<cgal_mesh, false>);
const int registered_23 = add_case("catmull_clark/reserve/cgal_surface_mesh", &reserve_only<cgal_mesh, true>);
const int registered_29 = add_case("loop/grow/cgal_surface_mesh", &reserve_only<cgal_mesh, false, true>);
const int registered_30 = add_case("catmull_clark/grow/cgal_surface_mesh", &reserve_only<cgal_mesh, true, true>);
#endif

std::string openmesh_case(const std::string& scheme) {
    return scheme == "loop"    ? "loop/openmesh/LoopT"
           : scheme == "sqrt3" ? "sqrt3/openmesh/Sqrt3T"
                               : "catmull_clark/openmesh/CatmullClarkT";
}
std::string cgal_case(const std::string& scheme) {
    return scheme == "loop"    ? "loop/cgal/Loop_subdivision"
           : scheme == "sqrt3" ? "sqrt3/cgal/Sqrt3_subdivision"
                               : "catmull_clark/cgal/CatmullClark_subdivision";
}
std::string hmira_on_openmesh_case(const std::string& scheme) {
    return scheme + (scheme == "catmull_clark" ? "/hmira/openmesh_poly" : "/hmira/openmesh_tri");
}

}  // namespace

int main(int argc, char** argv) {
    if (int rc = hmira_bench::run_benchmarks(argc, argv); rc != 0) return rc;
    using hmira_bench::print_ratio;
    std::printf("\nMedian CPU-time ratios (one level, ~1M faces in):\n");
    for (const std::string scheme : {"loop", "catmull_clark", "sqrt3"}) {
        const std::string own = scheme + "/hmira/halfedge_mesh";
        const std::string om = openmesh_case(scheme), cg = cgal_case(scheme);
        // The 0.5 is for Loop and Catmull-Clark; sqrt(3) has no target of its own.
        const double peer_target = scheme == "sqrt3" ? 1.0 : 0.5;
        print_ratio(scheme + ": hmira halfedge_mesh / OpenMesh", own, om, peer_target);
        print_ratio(scheme + ": hmira halfedge_mesh / CGAL", own, cg, peer_target);
        print_ratio(scheme + ": hmira on OpenMesh / hmira halfedge_mesh", hmira_on_openmesh_case(scheme), own, 1.1);
        print_ratio(scheme + ": hmira on CGAL / hmira halfedge_mesh", scheme + "/hmira/cgal_surface_mesh", own, 1.1);
    }
    for (const bool user : {true, false}) {
        std::printf(user ? "\nMedian user-CPU-time ratios (without the kernel's zeroing of fresh pages):\n"
                         : "\nMedian system-CPU-time ratios (the kernel's faulting and zeroing of fresh pages):\n");
        auto& by_case = user ? user_seconds_by_case() : sys_seconds_by_case();
        for (const std::string scheme : {"loop", "catmull_clark", "sqrt3"}) {
            const std::string own = scheme + "/hmira/halfedge_mesh";
            const std::string om = openmesh_case(scheme), cg = cgal_case(scheme),
                              on_om = hmira_on_openmesh_case(scheme);
            const std::string on_cg = scheme + "/hmira/cgal_surface_mesh";
            for (const auto& [label, a, b] : {std::tuple{"hmira halfedge_mesh / OpenMesh", own, om},
                                              std::tuple{"hmira halfedge_mesh / CGAL", own, cg},
                                              std::tuple{"hmira on OpenMesh / hmira halfedge_mesh", on_om, own},
                                              std::tuple{"hmira on CGAL / hmira halfedge_mesh", on_cg, own}}) {
                const double ta = median_in(by_case, a), tb = median_in(by_case, b);
                if (ta > 0 && tb > 0)
                    std::printf("%-58s %7.1f ms / %7.1f ms = %5.2f\n", (scheme + ": " + label).c_str(), ta * 1e3,
                                tb * 1e3, ta / tb);
            }
        }
    }
    // The target, <= 1.1, for the generic algorithm on each model, whole and less that model's
    // reserve (the <scheme>/reserve/<model> case: the same T::reserve, to the same counts, the
    // algorithm makes before its first change), with the fresh memory each touched.
    auto& cpu = cpu_seconds_by_case();
    auto& fresh = fresh_mb_by_case();
    // step: "reserve" (the traits' reserve alone) or "grow" (reserve, then resize to the
    // final counts: the model's whole storage growth, default fill of every new element too).
    const auto storage_table = [&](const std::string& step, const char* what) {
        std::printf(
            "\nGeneric on a model / on halfedge_mesh, less each model's %s step (medians of the timed call alone):\n"
            "  ms = user + system CPU; fresh = MB of minor page faults; %s = %s;\n"
            "  less-%s = (model - its %s) / (hm - its %s); the peers' rows: peer / hm.\n",
            step.c_str(), step.c_str(), what, step.c_str(), step.c_str(), step.c_str());
        std::printf("%-44s %9s %9s %6s | %8s %8s %18s | %13s %13s\n", "scheme/model", "model ms", "hm ms", "ratio",
                    (step + " ms").c_str(), (step + " hm").c_str(), ("less-" + step).c_str(), "fresh MB",
                    (step + " MB").c_str());
        for (const std::string scheme : {"loop", "catmull_clark"}) {
            const std::string own = scheme + "/hmira/halfedge_mesh", own_step = scheme + "/" + step + "/halfedge_mesh";
            const double t_own = median_in(cpu, own), r_own = median_in(cpu, own_step);
            if (t_own <= 0) continue;
            const double m_own = median_in(fresh, own), rm_own = median_in(fresh, own_step);
            std::printf("%-44s %9.1f %9.1f %6s | %8.1f %8s %18s | %13.1f %13.1f\n", (scheme + "/halfedge_mesh").c_str(),
                        t_own * 1e3, t_own * 1e3, "1.00", r_own * 1e3, "", "", m_own, rm_own);
            const std::vector<std::string> models =
                scheme == "loop"
                    ? std::vector<std::string>{"openmesh_tri", "cgal_surface_mesh"}
                    : std::vector<std::string>{"openmesh_poly", "openmesh_poly_double", "cgal_surface_mesh"};
            for (const std::string& model : models) {
                const std::string on = scheme + "/hmira/" + model, res = scheme + "/" + step + "/" + model;
                const double t = median_in(cpu, on), r = median_in(cpu, res);
                if (t <= 0) continue;
                char less[40] = "";
                if (r > 0 && r_own > 0)
                    std::snprintf(less, sizeof less, "%.1f/%.1f=%.2f", (t - r) * 1e3, (t_own - r_own) * 1e3,
                                  (t - r) / (t_own - r_own));
                char fr[40], rfr[40] = "";
                std::snprintf(fr, sizeof fr, "%.1f/%.1f", median_in(fresh, on), m_own);
                if (r > 0) std::snprintf(rfr, sizeof rfr, "%.1f/%.1f", median_in(fresh, res), rm_own);
                std::printf("%-44s %9.1f %9.1f %6.2f | %8.1f %8.1f %18s | %13s %13s\n", (scheme + "/" + model).c_str(),
                            t * 1e3, t_own * 1e3, t / t_own, r * 1e3, r_own * 1e3, less, fr, rfr);
            }
            // The peers' own subdividers on the same input, for scale.
            for (const std::string& peer : {openmesh_case(scheme), cgal_case(scheme)})
                if (const double t = median_in(cpu, peer); t > 0) {
                    char fr[40];
                    std::snprintf(fr, sizeof fr, "%.1f/%.1f", median_in(fresh, peer), m_own);
                    std::printf("%-44s %9.1f %9.1f %6.2f | %8s %8s %18s | %13s\n", peer.c_str(), t * 1e3, t_own * 1e3,
                                t / t_own, "", "", "", fr);
                }
        }
    };
    storage_table("reserve", "the traits' reserve alone, to the level's final counts, as the algorithm calls it");
    storage_table("grow", "that reserve, then the traits' resize to those counts (every new element at its defaults)");
    benchmark::Shutdown();
    return 0;
}
