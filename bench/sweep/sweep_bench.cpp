// bench/sweep/sweep_bench.cpp
// Size sweeps: each performance-critical algorithm at sizes from 10^4 elements up
// (10^7 for the linear ones that fit in time and memory), the exponent of CPU time against
// size fitted on log-log axes and compared with the complexity its doc block states, and the
// spread of the time per element, and each size's working set (the input and what the call
// allocates), which the verdict uses to tell a cache level's step from the complexity (see
// print_sweep_summary in bench/support/sweep.hpp). Not run in CI: `bash scripts/bench.sh sweep`
// or bench/sweep/run.sh (see there). Every time is the median CPU time (all threads) of
// `repeats` calls on fresh copies of the input, after one untimed warm-up call.
//   sweep_bench [--quick] [--only SUBSTRING] [--max ELEMENTS] [--repeats N]
#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <new>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <malloc.h>
#include <unistd.h>

#include <hmira/algorithms/delaunay/delaunay_triangulation.hpp>
#include <hmira/algorithms/conversion/marching_cubes.hpp>
#include <hmira/algorithms/conversion/voxelize.hpp>
#include <hmira/algorithms/decimation/decimate.hpp>
#include <hmira/algorithms/holes/fill_hole.hpp>
#include <hmira/algorithms/remeshing/isotropic_remeshing.hpp>
#include <hmira/algorithms/smoothing/laplacian_smooth.hpp>
#include <hmira/algorithms/subdivision/catmull_clark.hpp>
#include <hmira/algorithms/subdivision/loop.hpp>
#include <hmira/algorithms/triangulation/triangulate_faces.hpp>
#include <hmira/grids/implicit_shapes.hpp>
#include <hmira/grids/sample.hpp>
#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "support/sweep.hpp"

// The heap in use and its peak, counted by the replaced operator new and delete below: the
// bytes a call allocates, for its working set (the verdict fits sizes beyond the cache).
namespace {
std::atomic<std::size_t> heap_in_use{0}, heap_peak{0};
void* counted(void* p) {
    if (!p) throw std::bad_alloc();
    const std::size_t n = malloc_usable_size(p);
    const std::size_t now = heap_in_use.fetch_add(n, std::memory_order_relaxed) + n;
    std::size_t peak = heap_peak.load(std::memory_order_relaxed);
    while (now > peak && !heap_peak.compare_exchange_weak(peak, now, std::memory_order_relaxed)) {}
    return p;
}
void uncounted(void* p) noexcept {
    if (!p) return;
    heap_in_use.fetch_sub(malloc_usable_size(p), std::memory_order_relaxed);
    std::free(p);
}
}  // namespace
void* operator new(std::size_t n) { return counted(std::malloc(n ? n : 1)); }
void* operator new(std::size_t n, std::align_val_t a) {
    const std::size_t al = std::size_t(a);
    return counted(std::aligned_alloc(al, (std::max<std::size_t>(n, 1) + al - 1) / al * al));
}
void operator delete(void* p) noexcept { uncounted(p); }
void operator delete(void* p, std::size_t) noexcept { uncounted(p); }
void operator delete(void* p, std::align_val_t) noexcept { uncounted(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { uncounted(p); }

namespace {

using M = hmira::halfedge_mesh;
using T = hmira::default_traits<M>;
namespace hb = hmira_bench;

struct config {
    bool quick = false;
    std::string only;
    double max_elements = 1e7;
    int repeats = 3;
};

/// 10^4, 10^4.5, ... up to `hi`: three sizes in the largest decade, whose exponent decides (two,
/// one on each side of a cache level, measured the cache, not the algorithm).
std::vector<double> sizes(const config& c, double hi) {
    std::vector<double> out;
    for (double e = 4; std::pow(10.0, e) <= std::min(hi, c.max_elements) * 1.001; e += 0.5)
        out.push_back(std::pow(10.0, e));
    return out;
}

[[noreturn]] void die(const std::string& what) {
    std::fprintf(stderr, "sweep_bench: %s\n", what.c_str());
    std::exit(1);
}

/// The median CPU time of `run` on fresh copies of `input` (copies made outside the timing),
/// and the working set: the copy and the heap's peak growth during the warm-up call, plus
/// `shared_bytes` of input the call reads in place (captured, not copied).
template <class Input, class Run>
hb::sweep_point timed(const std::string& name, const Input& input, double elements, int repeats, Run run,
                      double shared_bytes = 0) {
    double bytes = shared_bytes;
    {
        const std::size_t before = heap_in_use.load();
        Input warm = input;
        heap_peak.store(heap_in_use.load());
        run(warm);
        bytes += double(heap_peak.load() - before);
    }
    std::vector<double> ts;
    for (int r = 0; r < repeats; ++r) {
        Input copy = input;
        const double t0 = hb::process_cpu_seconds();
        run(copy);
        ts.push_back(hb::process_cpu_seconds() - t0);
    }
    const double t = hb::median(ts);
    std::printf("  %-42s n %10.0f  median cpu %9.4f s  %8.1f ns/element  working set %8.1f MiB\n", name.c_str(),
                elements, t, t / elements * 1e9, bytes / (1024 * 1024));
    std::fflush(stdout);
    return {elements, t, bytes};
}

/// A torus as indexed polygons: rings x sides quads, or each quad cut into two triangles.
struct polygons {
    std::vector<M::point> points;
    std::vector<std::uint32_t> offsets{0}, corners;
};
polygons torus_polygons(std::size_t rings, std::size_t sides, bool triangles) {
    polygons p;
    p.points.reserve(rings * sides);
    for (std::size_t i = 0; i < rings; ++i)
        for (std::size_t j = 0; j < sides; ++j) {
            const double u = 2 * std::numbers::pi * double(i) / double(rings),
                         v = 2 * std::numbers::pi * double(j) / double(sides);
            p.points.push_back({(4 + std::cos(v)) * std::cos(u), (4 + std::cos(v)) * std::sin(u), std::sin(v)});
        }
    auto id = [&](std::size_t i, std::size_t j) { return std::uint32_t((i % rings) * sides + j % sides); };
    for (std::size_t i = 0; i < rings; ++i)
        for (std::size_t j = 0; j < sides; ++j) {
            const auto a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
            if (triangles) {
                for (auto x : {a, b, c, a, c, d}) p.corners.push_back(x);
                p.offsets.push_back(std::uint32_t(p.corners.size() - 3));
            } else {
                for (auto x : {a, b, c, d}) p.corners.push_back(x);
            }
            p.offsets.push_back(std::uint32_t(p.corners.size()));
        }
    return p;
}
/// A torus of about `faces` faces (quads or triangles).
polygons torus_of(double faces, bool triangles) {
    const auto side = std::max<std::size_t>(3, std::size_t(std::lround(std::sqrt(faces / (triangles ? 2 : 1)))));
    return torus_polygons(side, side, triangles);
}
M mesh_of(const polygons& p) {
    auto m = M::from_polygons(p.points, p.offsets, p.corners);
    if (!m) die(m.error().message);
    return std::move(*m);
}

struct sweep_case {
    std::string name;
    hb::complexity_claim claim;
    double full_max, quick_max;  ///< the largest size, in elements, of a full and of a --quick sweep
    std::function<hb::sweep_point(double n, const config&)> point;
};

template <class R>
void check(const R& r, const char* what) {
    if (!r) die(std::string(what) + ": " + r.error().message);
}

std::vector<sweep_case> cases() {
    std::vector<sweep_case> cs;
    cs.push_back({"marching_cubes_indexed (samples, 1 thread)",
                  {"O(N) for N samples", 1},
                  1e7,
                  1e6,
                  [](double n, const config& c) {
                      const auto side = std::size_t(std::lround(std::cbrt(n)));
                      const auto grid =
                          hmira::sample_function(hmira::cube_geometry(side, -6.0, 6.0), hmira::gyroid_field{});
                      check(grid, "sample_function");
                      const auto& g = *grid;
                      return timed(
                          "marching_cubes_indexed", 0, double(side * side * side), c.repeats,
                          [&](int) {
                              auto r = hmira::marching_cubes_indexed(g, {.threads = 1});
                              check(r, "marching_cubes_indexed");
                          },
                          double(g.size() * sizeof(*g.data())));
                  }});
    cs.push_back({"voxelize solid (voxels, 2k-triangle torus, 1 thread)",
                  {"O(F + voxels in the triangles' boxes + N/64 + ...), <= O(N)", 1},
                  1e7,
                  1e6,
                  [](double n, const config& c) {
                      // Few triangles, so that the voxels' terms dominate from small grids on.
                      static const M torus = mesh_of(torus_of(2e3, true));
                      // The torus is flat: a resolution along its longest side of cbrt(n) gives
                      // fewer than n voxels; scale it once by what the first try gave.
                      auto res = std::size_t(std::lround(std::cbrt(n)));
                      if (auto first = hmira::voxel_grid_around(torus, res, 1))
                          res = std::size_t(std::lround(double(res) * std::cbrt(n / double(first->size()))));
                      const auto geo = hmira::voxel_grid_around(torus, res, 1);
                      check(geo, "voxel_grid_around");
                      const double voxels = double(geo->dims[0]) * double(geo->dims[1]) * double(geo->dims[2]);
                      return timed("voxelize", 0, voxels, c.repeats, [&](int) {
                          auto v = hmira::voxelize(torus, *geo, {.threads = 1});
                          check(v, "voxelize");
                      });
                  }});
    cs.push_back(
        {"delaunay_triangulation (points)", {"O(n log n) expected", 1, 0.2}, 3.2e6, 1e6, [](double n, const config& c) {
             std::vector<std::array<double, 2>> pts(static_cast<std::size_t>(n));
             std::mt19937_64 rng(42);
             std::uniform_real_distribution<double> u(0.0, 1.0);
             for (auto& p : pts) p = {u(rng), u(rng)};
             return timed(
                 "delaunay_triangulation", 0, n, c.repeats,
                 [&](int) {
                     auto d = hmira::delaunay_triangulation(pts);
                     check(d, "delaunay_triangulation");
                 },
                 double(pts.size() * sizeof(pts[0])));
         }});
    cs.push_back({"halfedge_mesh::from_polygons (quads)",
                  {"O(V + C x valence), linear in practice", 1},
                  1e7,
                  1e6,
                  [](double n, const config& c) {
                      const auto p = torus_of(n, false);
                      const double shared =
                          double(p.points.size() * sizeof(p.points[0]) + (p.offsets.size() + p.corners.size()) * 4);
                      const double faces = double(p.offsets.size() - 1);
                      return timed(
                          "from_polygons", 0, faces, c.repeats, [&](int) { mesh_of(p); }, shared);
                  }});
    const auto dir = std::filesystem::temp_directory_path() / ("hmira-sweep-" + std::to_string(::getpid()));
    for (const bool halfedge : {false, true}) {
        const double full_max = halfedge ? 3.2e6 : 1e7;
        cs.push_back({std::string("read_mesh binary PLY -> ") + (halfedge ? "halfedge_mesh" : "face_vertex_mesh") +
                          " (triangles)",
                      {halfedge ? "O(bytes + C log d + insertions)" : "O(bytes)", 1},
                      full_max,
                      1e6,
                      [dir, halfedge](double n, const config& c) {
                          std::filesystem::create_directories(dir);
                          const auto path = dir / "torus.ply";
                          const auto p = torus_of(n, true);
                          const double faces = double(p.offsets.size() - 1);
                          {
                              auto r = hmira::io::write_mesh(mesh_of(p), path);
                              check(r, "write_mesh");
                          }
                          auto pt = timed(
                              "read_mesh", 0, faces, c.repeats,
                              [&](int) {
                                  if (halfedge) {
                                      M m;
                                      check(hmira::io::read_mesh(m, path), "read_mesh");
                                  } else {
                                      hmira::face_vertex_mesh m;
                                      check(hmira::io::read_mesh(m, path), "read_mesh");
                                  }
                              },
                              double(std::filesystem::file_size(path)));
                          std::filesystem::remove_all(dir);
                          return pt;
                      }});
    }
    cs.push_back(
        {"loop_subdivide, 1 level (input triangles)", {"O(F) per level", 1}, 1e6, 1e6, [](double n, const config& c) {
             const M m = mesh_of(torus_of(n, true));
             return timed("loop_subdivide", m, double(T::face_count(m)), c.repeats,
                          [](M& x) { check(hmira::loop_subdivide(x), "loop"); });
         }});
    cs.push_back({"catmull_clark_subdivide, 1 level (input quads)",
                  {"O(C) per level", 1},
                  1e6,
                  1e6,
                  [](double n, const config& c) {
                      const M m = mesh_of(torus_of(n, false));
                      return timed("catmull_clark_subdivide", m, double(T::face_count(m)), c.repeats,
                                   [](M& x) { check(hmira::catmull_clark_subdivide(x), "catmull_clark"); });
                  }});
    cs.push_back({"laplacian_smooth, 10 iterations (vertices)",
                  {"O(iterations (V + E))", 1},
                  1e7,
                  1e6,
                  [](double n, const config& c) {
                      const M m = mesh_of(torus_of(n, false));
                      return timed("laplacian_smooth", m, double(T::vertex_count(m)), c.repeats, [](M& x) {
                          check(hmira::laplacian_smooth(x, {.iterations = 10}), "laplacian_smooth");
                      });
                  }});
    cs.push_back({"triangulate_faces (quads)",
                  {"O(sum n_f log n_f) = O(F) for quads", 1},
                  3.2e6,
                  1e6,
                  [](double n, const config& c) {
                      const M m = mesh_of(torus_of(n, false));
                      return timed("triangulate_faces", m, double(T::face_count(m)), c.repeats,
                                   [](M& x) { check(hmira::triangulate_faces(x), "triangulate_faces"); });
                  }});
    cs.push_back({"decimate to half (triangles)",
                  {"O(E log E) + O(d log E) per collapse", 1, 0.2},
                  1e7,
                  1e6,
                  [](double n, const config& c) {
                      const M m = mesh_of(torus_of(n, true));
                      const auto f = T::face_count(m);
                      return timed("decimate", m, double(f), c.repeats,
                                   [f](M& x) { check(hmira::decimate(x, {.target_faces = f / 2}), "decimate"); });
                  }});
    cs.push_back({"isotropic_remeshing, 1 iteration (triangles)",
                  {"O(iterations F log F_in)", 1, 0.2},
                  1e6,
                  1e5,
                  [](double n, const config& c) {
                      const auto p = torus_of(n, true);
                      const M m = mesh_of(p);
                      // The torus's own mean edge length: each round does a bounded amount of work per face.
                      const double side = std::sqrt(n / 2), L = 2 * std::numbers::pi * 4.5 / side;
                      return timed("isotropic_remeshing", m, double(T::face_count(m)), c.repeats, [L](M& x) {
                          check(hmira::isotropic_remeshing(x, {.target_edge_length = L, .iterations = 1}),
                                "isotropic_remeshing");
                      });
                  }});
    return cs;
}

/// A flat annulus of 2k triangles, k vertices on each circle; its inner loop (k edges) is the hole.
M annulus(std::size_t k) {
    polygons p;
    for (double r : {1.0, 2.0})
        for (std::size_t i = 0; i < k; ++i) {
            const double a = 2 * std::numbers::pi * double(i) / double(k);
            p.points.push_back({r * std::cos(a), r * std::sin(a), 0});
        }
    for (std::uint32_t i = 0; i < k; ++i) {
        const std::uint32_t j = std::uint32_t((i + 1) % k), K = std::uint32_t(k);
        for (auto x : {i, K + i, K + j, i, K + j, j}) p.corners.push_back(x);
        p.offsets.push_back(std::uint32_t(p.corners.size() - 3));
        p.offsets.push_back(std::uint32_t(p.corners.size()));
    }
    return mesh_of(p);
}

/// fill_hole's two methods, by loop length n (not 10^4..10^7: the dynamic programme is O(n^3)
/// and used up to 200 edges; the projected triangulation above).
std::vector<sweep_case> hole_cases() {
    auto fill = [](double n, const config& c) {
        const M m = annulus(std::size_t(n));
        T::halfedge_handle h = T::null_halfedge();
        for (auto x : T::halfedges(m))
            if (T::face(m, x) == T::null_face() && T::vertex_index(m, T::target(m, x)) < std::size_t(n)) h = x;
        return timed("fill_hole", m, n, c.repeats, [h](M& x) { check(hmira::fill_hole(x, h), "fill_hole"); });
    };
    return {{"fill_hole, dynamic programme (loop edges <= 200)", {"O(n^3)", 3}, 200, 200, fill},
            {"fill_hole, projected (loop edges > 200)", {"O(n^2) typical", 2}, 6400, 3200, fill}};
}

}  // namespace

int main(int argc, char** argv) {
    config c;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--quick")
            c.quick = true;
        else if (a == "--only" && i + 1 < argc)
            c.only = argv[++i];
        else if (a == "--max" && i + 1 < argc)
            c.max_elements = std::atof(argv[++i]);
        else if (a == "--repeats" && i + 1 < argc)
            c.repeats = std::max(1, std::atoi(argv[++i]));
        else {
            std::fprintf(stderr, "usage: sweep_bench [--quick] [--only SUBSTRING] [--max ELEMENTS] [--repeats N]\n");
            return 2;
        }
    }
    std::setvbuf(stdout, nullptr, _IOLBF, 0);
    hb::keep_freed_memory();
    std::vector<std::string> summary;
    int failed = 0, unsure = 0;
    auto run = [&](const sweep_case& s, const std::vector<double>& ns) {
        if (s.name.find(c.only) == std::string::npos) return;
        std::printf("%s\n", s.name.c_str());
        std::vector<hb::sweep_point> pts;
        for (double n : ns) pts.push_back(s.point(n, c));
        const std::string v = hb::print_sweep_summary("  => " + s.name.substr(0, 40), pts, s.claim);
        failed += v == "FAIL";
        unsure += v == "UNSURE";
        std::printf("\n");
    };
    for (const auto& s : cases()) run(s, sizes(c, c.quick ? s.quick_max : s.full_max));
    const auto holes = hole_cases();
    run(holes[0], c.quick ? std::vector<double>{25, 50, 100, 200} : std::vector<double>{25, 50, 100, 141, 200});
    run(holes[1],
        c.quick ? std::vector<double>{400, 800, 1600, 3200} : std::vector<double>{400, 800, 1600, 3200, 6400});
    std::printf("sweep: %d claim(s) contradicted", failed);
    if (unsure) std::printf(", %d undecided (largest decade across the last-level cache: run the full sweep)", unsure);
    std::printf("\n");
    return 0;
}
