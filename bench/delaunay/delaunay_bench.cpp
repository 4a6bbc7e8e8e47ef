// bench/delaunay/delaunay_bench.cpp
// 2D Delaunay triangulation of uniform random points: hmira (the full indexed result, with
// duplicate mapping and hull) against CGAL's Delaunay_triangulation_2 with the exact-predicates
// inexact-constructions kernel (range insertion, which spatially sorts). Points come from
// $HMIRA_DELAUNAY_POINTS/points_<n>.bin (float64 x, y pairs, written by peers.py so that every
// library sees the same points), or are generated here if that file is missing.
#include <benchmark/benchmark.h>

#include <sys/resource.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include <hmira/algorithms/delaunay/delaunay_triangulation.hpp>

#ifdef HMIRA_BENCH_WITH_CGAL
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#endif

namespace {

std::vector<std::array<double, 2>> load_points(std::size_t n) {
    std::vector<std::array<double, 2>> pts(n);
    if (const char* dir = std::getenv("HMIRA_DELAUNAY_POINTS")) {
        const std::string path = std::string(dir) + "/points_" + std::to_string(n) + ".bin";
        if (std::FILE* f = std::fopen(path.c_str(), "rb")) {
            const std::size_t got = std::fread(pts.data(), sizeof(double) * 2, n, f);
            std::fclose(f);
            if (got == n) return pts;
        }
    }
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (auto& p : pts) p = {u(rng), u(rng)};
    return pts;
}

void report_peak_memory(benchmark::State& state) {
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);
    state.counters["peak_rss_MB"] = double(ru.ru_maxrss) / 1024.0;  // kilobytes on Linux
}

void hmira_delaunay(benchmark::State& state) {
    const auto pts = load_points(static_cast<std::size_t>(state.range(0)));
    std::size_t triangles = 0;
    for (auto _ : state) {
        auto d = hmira::delaunay_triangulation(pts);
        triangles = d->triangles.size();
        benchmark::DoNotOptimize(d->triangles.data());
    }
    state.counters["triangles"] = double(triangles);
    report_peak_memory(state);
}

#ifdef HMIRA_BENCH_WITH_CGAL
void cgal_delaunay(benchmark::State& state) {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    const auto raw = load_points(static_cast<std::size_t>(state.range(0)));
    std::vector<K::Point_2> pts;
    pts.reserve(raw.size());
    for (const auto& p : raw) pts.emplace_back(p[0], p[1]);
    std::size_t triangles = 0;
    for (auto _ : state) {
        CGAL::Delaunay_triangulation_2<K> dt;
        dt.insert(pts.begin(), pts.end());
        triangles = dt.number_of_faces();
        benchmark::DoNotOptimize(triangles);
    }
    state.counters["triangles"] = double(triangles);
    report_peak_memory(state);
}
BENCHMARK(cgal_delaunay)->Arg(100000)->Arg(1000000)->Arg(4000000)->Unit(benchmark::kMillisecond)->UseRealTime();
#endif

BENCHMARK(hmira_delaunay)->Arg(100000)->Arg(1000000)->Arg(4000000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
