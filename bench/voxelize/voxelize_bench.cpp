// hmira voxelization (conservative solid and centres modes) of sphere966 (few large
// triangles), armadillo, elephant and a generated closed ~2M-triangle mesh at 256^3 and
// 512^3, with 1 and 2 threads. `--export DIR` writes the meshes (raw float64 vertices, int32
// triangles) and grids for peers.py, with hmira's solid, surface and centres counts and the
// centres bits (DIR/<mesh>_<res>.centres: the bit_grid's words, rows padded to 64 bits).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <string>
#include <utility>

#include <hmira/algorithms/conversion/marching_cubes.hpp>
#include <hmira/algorithms/conversion/voxelize.hpp>
#include <hmira/grids/sample.hpp>
#include <hmira/grids/implicit_shapes.hpp>
#include <hmira/io/off.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

#if defined(HMIRA_HAS_TBB)
#include <tbb/global_control.h>
#endif

namespace {

std::string data_dir() {
    if (const char* d = std::getenv("HMIRA_TEST_DATA")) return d;
    return "build/test-data";
}

// A closed mesh of about two million triangles: the gyroid's solid side cut by a ball, which
// has many handles, as marching cubes gives it.
hmira::face_vertex_mesh generated_mesh() {
    const auto geo = hmira::cube_geometry(360, -1, 1);
    auto g = hmira::sample_function(geo, [](hmira::vec3<double> p) {
        const double gy = hmira::gyroid_field{3 * std::numbers::pi}(p);
        return std::max(gy, hmira::norm(p) - 0.92);
    });
    hmira::face_vertex_mesh m;
    (void)hmira::marching_cubes(m, *g).value();
    return m;
}

const hmira::face_vertex_mesh& get(const std::string& name) {
    static std::map<std::string, hmira::face_vertex_mesh> cache;
    if (auto it = cache.find(name); it != cache.end()) return it->second;
    hmira::face_vertex_mesh m;
    if (name == "generated2M") {
        m = generated_mesh();
    } else if (auto r = hmira::io::read_off(m, data_dir() + "/meshes/" + name + ".off"); !r) {
        std::fprintf(stderr, "%s\n", r.error().message.c_str());
        std::exit(1);
    }
    return cache.emplace(name, std::move(m)).first->second;
}

const char* meshes[] = {"sphere966", "armadillo", "elephant", "generated2M"};
const std::size_t resolutions[] = {256, 512};

void bm_voxelize(benchmark::State& state, std::string name, std::size_t res, hmira::voxelize_mode mode) {
    const auto& m = get(name);
    const auto threads = static_cast<unsigned>(state.range(0));
#if defined(HMIRA_HAS_TBB)
    tbb::global_control gc(tbb::global_control::max_allowed_parallelism, threads);
#endif
    const auto geo = *hmira::voxel_grid_around(m, res, 1);
    for (auto _ : state) {
        auto v = hmira::voxelize(m, geo, {.mode = mode, .allow_degenerate = true, .threads = threads});
        if (!v || !v->filled)
            state.SkipWithError("not filled");
        else
            benchmark::DoNotOptimize(v->voxels.words().data());
    }
    // Counted outside the timed loop: the peers' times do not include counting either.
    auto v = hmira::voxelize(m, geo, {.mode = mode, .allow_degenerate = true, .threads = threads});
    state.counters["voxels"] = v ? double(v->voxels.count()) : 0.0;
    state.counters["triangles"] = double(m.face_count());
}

int export_meshes(const std::filesystem::path& dir) {
    std::filesystem::create_directories(dir);
    std::ofstream manifest(dir / "manifest.txt");
    manifest.precision(17);
    for (const char* name : meshes) {
        const auto& m = get(name);
        {
            std::ofstream v(dir / (std::string(name) + ".vertices"), std::ios::binary);
            for (auto p : m.positions()) v.write(reinterpret_cast<const char*>(&p), sizeof p);
            std::ofstream f(dir / (std::string(name) + ".faces"), std::ios::binary);
            for (auto fh : m.faces())
                for (auto vh : m.face_vertices(fh)) {
                    const std::int32_t i = static_cast<std::int32_t>(vh.index);
                    f.write(reinterpret_cast<const char*>(&i), sizeof i);
                }
        }
        for (std::size_t res : resolutions) {
            const auto geo = *hmira::voxel_grid_around(m, res, 1);
            auto solid = hmira::voxelize(m, geo, {.allow_degenerate = true});
            auto surface = hmira::voxelize(m, geo, {.mode = hmira::voxelize_mode::surface, .allow_degenerate = true});
            auto centres = hmira::voxelize(m, geo, {.mode = hmira::voxelize_mode::centres, .allow_degenerate = true});
            {
                std::ofstream bits(dir / (std::string(name) + "_" + std::to_string(res) + ".centres"),
                                   std::ios::binary);
                const auto w = centres->voxels.words();
                bits.write(reinterpret_cast<const char*>(w.data()), std::streamsize(w.size() * sizeof(std::uint64_t)));
            }
            manifest << name << ' ' << res << ' ' << m.vertex_count() << ' ' << m.face_count() << ' ' << geo.dims[0]
                     << ' ' << geo.dims[1] << ' ' << geo.dims[2] << ' ' << geo.origin.x << ' ' << geo.origin.y << ' '
                     << geo.origin.z << ' ' << geo.spacing.x << ' ' << solid->voxels.count() << ' '
                     << surface->voxels.count() << ' ' << centres->voxels.count() << '\n';
        }
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    for (int a = 1; a + 1 < argc; ++a)
        if (std::strcmp(argv[a], "--export") == 0) return export_meshes(argv[a + 1]);
    const std::pair<const char*, hmira::voxelize_mode> modes[] = {
        {"hmira_voxelize", hmira::voxelize_mode::solid}, {"hmira_voxelize_centres", hmira::voxelize_mode::centres}};
    for (const auto& [prefix, mode] : modes)
        for (const char* name : meshes)
            for (std::size_t res : resolutions)
                benchmark::RegisterBenchmark((std::string(prefix) + "/" + name + "/" + std::to_string(res)).c_str(),
                                             bm_voxelize, std::string(name), res, mode)
                    ->Arg(1)
                    ->Arg(2)
                    ->Unit(benchmark::kMillisecond)
                    ->MinTime(0.5)
                    ->UseRealTime()
                    ->MeasureProcessCPUTime();  // cpu_time: all threads, comparable with the peers' process time
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
