// Times the spatial queries in C++ alone (no Python, no peer), on the inputs of bench.py:
// armadillo.off Loop-subdivided twice, 10^6 points uniform in its box enlarged by 10%, rays
// from them in random directions. For profiling; bench.py gives the comparison with the peers.
// Usage: profile_queries MESH [queries] [what...] (what: build cp ray any sd; default all)
// Build: g++ -std=c++20 -O3 -DNDEBUG -DHMIRA_HAS_TBB=1 -Iinclude bench/spatial/profile_queries.cpp -ltbb
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <random>
#include <string>
#include <vector>

#include "hmira/algorithms/spatial/bvh.hpp"
#include "hmira/algorithms/spatial/signed_distance.hpp"
#include "hmira/algorithms/subdivision/loop.hpp"
#include "hmira/io/off.hpp"
#include "hmira/meshes/halfedge_mesh.hpp"

int main(int argc, char** argv) {
    using clock = std::chrono::steady_clock;
    if (argc < 2) return 2;
    const std::size_t n = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 1000000;
    std::string what = "build cp ray any sd";
    if (argc > 3) {
        what.clear();
        for (int i = 3; i < argc; ++i) what += std::string(argv[i]) + " ";
    }
    const auto want = [&](const char* w) { return what.find(w) != std::string::npos; };
    hmira::halfedge_mesh m;
    if (!hmira::io::read_off(m, argv[1])) return 1;
    if (!hmira::loop_subdivide(m, {.levels = 2})) return 1;
    auto s = hmira::triangles_of(m);
    if (!s) return 1;
    hmira::vec3<double> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    for (const auto& p : s->points)
        for (std::size_t k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    std::mt19937_64 rng(0);
    std::vector<hmira::vec3<double>> pts(n);
    std::vector<hmira::ray> rays(n);
    std::normal_distribution<double> g;
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t k = 0; k < 3; ++k) {
            const double c = (lo[k] + hi[k]) / 2, h = (hi[k] - lo[k]) / 2 * 1.1;
            pts[i][k] = std::uniform_real_distribution<double>(c - h, c + h)(rng);
        }
        hmira::vec3<double> d{g(rng), g(rng), g(rng)};
        rays[i] = {.origin = pts[i], .direction = d / hmira::norm(d)};
    }
    std::printf("%zu triangles, %zu queries\n", s->triangles.size(), n);
    // Wall time; the CPU time of the process (all threads) is printed beside it, steadier on a
    // loaded machine.
    const auto time = [](auto&& f) {
        const auto t0 = clock::now();
        const std::clock_t c0 = std::clock();
        f();
        std::printf("[cpu %.3f s] ", double(std::clock() - c0) / CLOCKS_PER_SEC);
        return std::chrono::duration<double>(clock::now() - t0).count();
    };
    hmira::bvh tree;
    const double tb = time([&] { tree = *hmira::bvh::from_triangles(s->points, s->triangles, s->faces); });
    std::printf("build %.3f s (%zu nodes, depth %zu)\n", tb, tree.node_count(), tree.depth());
    double sum = 0;
    if (want("cp")) {
        std::vector<hmira::closest_surface_point> r;
        std::printf("closest %.3f s\n", time([&] { r = *tree.closest_points(pts); }));
        for (const auto& c : r) sum += c.distance;
    }
    if (want("ray")) {
        std::vector<hmira::ray_surface_hit> r;
        std::printf("first hit %.3f s\n", time([&] { r = *tree.first_hits(rays); }));
        std::size_t hits = 0;
        for (const auto& h : r) hits += h.found(), sum += h.found() ? h.t + double(h.face) : 0;
        std::printf("  %zu hits\n", hits);
    }
    if (want("any")) {
        std::vector<std::uint8_t> r;
        std::printf("any hit %.3f s\n", time([&] { r = *tree.any_hits(rays); }));
        for (auto h : r) sum += h;
    }
    if (want("sd")) {
        hmira::signed_distances r;
        std::printf("signed distance %.3f s\n", time([&] { r = *hmira::signed_distance(*s, pts); }));
        for (double d : r.distances) sum += d;
    }
    std::printf("checksum %.17g\n", sum);
}
