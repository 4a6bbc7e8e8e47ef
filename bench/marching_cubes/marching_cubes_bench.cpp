// hmira marching cubes on the volumes (gyroid at 128^3; sphere, torus, gyroid at 256^3 and 384^3 and
// the real skull) with 1 and 2 threads. `--export DIR` writes the same volumes as raw float32
// for the peers in peers.py, and reports whether hmira's output is welded and closed.
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <set>
#include <string>

#include <hmira/algorithms/conversion/marching_cubes.hpp>
#include <hmira/algorithms/topology/mesh_topology.hpp>
#include <hmira/grids/dense_grid.hpp>
#include <hmira/grids/implicit_shapes.hpp>
#include <hmira/grids/sample.hpp>
#include <hmira/io/volume/inr.hpp>
#include <hmira/io/volume/raw.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

#if defined(HMIRA_HAS_TBB)
#include <tbb/global_control.h>
#endif

namespace {

struct volume {
    hmira::dense_grid<float> grid;
    double iso = 0;
    hmira::iso_inside inside = hmira::iso_inside::below;
};

std::string skull_path() {
    if (const char* p = std::getenv("HMIRA_SKULL")) return p;
    if (const char* d = std::getenv("HMIRA_TEST_DATA")) return std::string(d) + "/images/skull_2.9.inr";
    return "build/test-data/images/skull_2.9.inr";
}

// Name -> volume, built on first use.
const volume& get(const std::string& name) {
    static std::map<std::string, volume> cache;
    if (auto it = cache.find(name); it != cache.end()) return it->second;
    volume v;
    if (name == "skull") {
        auto g = hmira::io::read_inr(skull_path());
        if (!g) {
            std::fprintf(stderr, "%s\n", g.error().message.c_str());
            std::exit(1);
        }
        v.grid = std::move(*g);
        v.iso = 2.9;
        v.inside = hmira::iso_inside::above;
    } else {
        const auto us = name.find('_');
        const std::string shape = name.substr(0, us);
        const std::size_t n = std::stoul(name.substr(us + 1));
        const auto geo = hmira::cube_geometry(n, -1, 1);
        if (shape == "sphere")
            v.grid = *hmira::sample_function(geo, hmira::sphere_field{{0, 0, 0}, 0.8});
        else if (shape == "torus")
            v.grid = *hmira::sample_function(geo, hmira::torus_field{{0, 0, 0}, 0.6, 0.25});
        else
            v.grid = *hmira::sample_function(geo, hmira::gyroid_field{4 * std::numbers::pi});
    }
    return cache.emplace(name, std::move(v)).first->second;
}

const char* volumes[] = {"gyroid_128", "sphere_256", "torus_256",  "gyroid_256",
                         "sphere_384", "torus_384",  "gyroid_384", "skull"};

void bm_marching_cubes(benchmark::State& state, std::string name) {
    const auto& v = get(name);
    const auto threads = static_cast<unsigned>(state.range(0));
#if defined(HMIRA_HAS_TBB)
    tbb::global_control gc(tbb::global_control::max_allowed_parallelism, threads);
#endif
    std::size_t tris = 0;
    // Kernel time and page faults per call (all threads): the first touch of the fresh output
    // pages is kernel time, which bandwidth_probe measures on its own.
    rusage before{}, after{};
    getrusage(RUSAGE_SELF, &before);
    for (auto _ : state) {
        auto out = hmira::marching_cubes_indexed(v.grid, {.iso = v.iso, .inside = v.inside, .threads = threads});
        tris = out->triangles.size();
        benchmark::DoNotOptimize(out->positions.data());
    }
    getrusage(RUSAGE_SELF, &after);
    const auto ms = [](const timeval& t) { return double(t.tv_sec) * 1e3 + double(t.tv_usec) / 1e3; };
    const double calls = double(state.iterations());
    state.counters["triangles"] = double(tris);
    state.counters["sys_ms"] = (ms(after.ru_stime) - ms(before.ru_stime)) / calls;
    state.counters["faults"] = double(after.ru_minflt - before.ru_minflt) / calls;
}

int export_volumes(const std::filesystem::path& dir) {
    std::filesystem::create_directories(dir);
    std::ofstream manifest(dir / "manifest.txt");
    for (const char* name : volumes) {
        const auto& v = get(name);
        const auto d = v.grid.dims();
        if (auto ok = hmira::io::write_raw(v.grid, dir / (std::string(name) + ".raw")); !ok) {
            std::fprintf(stderr, "%s\n", ok.error().message.c_str());
            return 1;
        }
        auto tri = hmira::marching_cubes_indexed<double>(v.grid, {.iso = v.iso, .inside = v.inside});
        hmira::face_vertex_mesh m;
        for (const auto& p : tri->positions) m.add_vertex(p);
        for (const auto& t : tri->triangles)
            (void)m.add_face({hmira::vertex_handle(t[0]), hmira::vertex_handle(t[1]), hmira::vertex_handle(t[2])});
        const auto topo = hmira::mesh_topology(m);
        std::set<std::array<double, 3>> unique;
        for (const auto& p : tri->positions) unique.insert({p.x, p.y, p.z});
        manifest << name << ' ' << d[0] << ' ' << d[1] << ' ' << d[2] << ' ' << v.iso << ' '
                 << (v.inside == hmira::iso_inside::above ? "above" : "below") << ' ' << tri->triangles.size() << ' '
                 << (unique.size() == tri->positions.size() ? "welded" : "unwelded") << ' '
                 << (topo.closed() ? "closed" : "open") << '\n';
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    for (int a = 1; a + 1 < argc; ++a)
        if (std::strcmp(argv[a], "--export") == 0) return export_volumes(argv[a + 1]);
    for (const char* name : volumes)
        benchmark::RegisterBenchmark((std::string("hmira_mc/") + name).c_str(), bm_marching_cubes, std::string(name))
            ->Arg(1)
            ->Arg(2)
            ->Unit(benchmark::kMillisecond)
            ->MinTime(0.5)
            ->MeasureProcessCPUTime()  // CPU time of all threads: the steady figure on a shared machine
            ->UseRealTime();
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
