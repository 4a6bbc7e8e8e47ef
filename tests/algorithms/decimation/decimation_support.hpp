// What the decimation suites share: jittered tori, with or without holes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <random>

#include "algorithms/triangle/triangle_support.hpp"

namespace hmira_test {

/// A torus with its vertices jittered (so no two collapses tie by symmetry alone), and
/// optionally with separated quads removed to make boundary loops.
inline face_list bumpy_torus(std::size_t n, std::size_t m, bool holes, std::uint64_t seed) {
    face_list t = triangulated(torus(n, m));
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> jitter(-0.01, 0.01);
    for (auto& p : t.points) p = p + hmira::vec3<double>{jitter(rng), jitter(rng), jitter(rng)};
    if (!holes) return t;
    return without_faces(t, [&](std::size_t f) {
        const std::size_t q = f / 2, i = q / m, j = q % m;
        return i % 5 == 2 && j % 4 == 1;
    });
}

}  // namespace hmira_test
