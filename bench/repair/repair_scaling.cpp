// bench/repair/repair_scaling.cpp
// repair_polygon_soup against soup size: a triangulated torus from 10k to 1M faces, its face
// order shuffled, a quarter of its faces flipped and some vertices pinched together, so every
// stage does work. Time per corner should stay flat (O(C log d)).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <hmira/algorithms/repair/repair_polygon_soup.hpp>

namespace {

struct soup {
    std::size_t vertices = 0;
    std::vector<std::uint64_t> offsets{0};
    std::vector<std::uint32_t> corners;
};

soup damaged_torus(std::uint32_t n) {
    const std::uint32_t m = n / 2;
    soup s;
    s.vertices = std::size_t{n} * m;
    std::vector<std::array<std::uint32_t, 3>> tris;
    auto id = [&](std::uint32_t i, std::uint32_t j) { return (i % n) * m + (j % m); };
    for (std::uint32_t i = 0; i < n; ++i)
        for (std::uint32_t j = 0; j < m; ++j) {
            tris.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            tris.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    std::mt19937 rng(1);
    std::shuffle(tris.begin(), tris.end(), rng);
    for (std::size_t f = 0; f < tris.size(); f += 4) std::swap(tris[f][0], tris[f][1]);
    // Pinch: vertex (i, 0) also stands for (i + n/2, 0) on every 16th ring (non-manifold vertices).
    for (auto& t : tris)
        for (auto& v : t)
            if (v % m == 0 && (v / m) % 16 == 0 && v / m >= n / 2) v = (v / m - n / 2) * m;
    for (const auto& t : tris) {
        s.corners.insert(s.corners.end(), t.begin(), t.end());
        s.offsets.push_back(s.corners.size());
    }
    return s;
}

void repair_damaged_torus(benchmark::State& state) {
    const auto s = damaged_torus(static_cast<std::uint32_t>(state.range(0)));
    for (auto _ : state) {
        auto r = hmira::repair_polygon_soup(s.vertices, s.offsets, s.corners);
        benchmark::DoNotOptimize(r);
    }
    state.counters["faces"] = static_cast<double>(s.offsets.size() - 1);
    state.counters["ns_per_corner"] =
        benchmark::Counter(static_cast<double>(s.corners.size()),
                           benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
// n x n/2 quads, two triangles each: 10k, 40k, 160k, 640k, ~1M faces.
BENCHMARK(repair_damaged_torus)->Arg(100)->Arg(200)->Arg(400)->Arg(800)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
