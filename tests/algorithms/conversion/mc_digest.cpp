// Prints a digest of marching cubes' output (positions bit for bit, triangles, normals) on a
// gyroid and a seeded noise field. Built twice, with and without oneTBB; CTest checks that
// both builds print the same digest, i.e. the parallel build changes nothing in the output.
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>

#include <hmira/algorithms/conversion/marching_cubes.hpp>
#include <hmira/grids/dense_grid.hpp>
#include <hmira/grids/implicit_shapes.hpp>
#include <hmira/grids/sample.hpp>

namespace {

std::uint64_t fnv(std::uint64_t h, const void* data, std::size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 1099511628211ull;
    return h;
}

std::uint64_t digest(const hmira::indexed_triangles<double>& t, std::uint64_t h) {
    h = fnv(h, t.positions.data(), t.positions.size() * sizeof(t.positions[0]));
    h = fnv(h, t.triangles.data(), t.triangles.size() * sizeof(t.triangles[0]));
    return fnv(h, t.normals.data(), t.normals.size() * sizeof(t.normals[0]));
}

}  // namespace

int main() {
    std::uint64_t h = 1469598103934665603ull;
    auto gyroid = hmira::sample_function(hmira::cube_geometry(70, -3, 3), hmira::gyroid_field{2.0});
    for (unsigned threads : {1u, 2u, 8u}) {
        auto t = hmira::marching_cubes_indexed<double>(*gyroid, {.iso = 0.1, .normals = true, .threads = threads});
        if (!t) return 1;
        h = digest(*t, h);
    }
    std::mt19937 rng(42);
    std::uniform_real_distribution<float> u(-1, 1);
    hmira::dense_grid<float> noise({{30, 31, 29}, {0, 0, 0}, {1, 1, 1}});
    for (auto& v : noise.values()) v = u(rng);
    auto t = hmira::marching_cubes_indexed<double>(noise, {.normals = true, .threads = 2});
    if (!t) return 1;
    h = digest(*t, h);
    std::printf("%016llx\n", static_cast<unsigned long long>(h));
    return 0;
}
