// What the decimation suites share: jittered tori, with or without holes.
#pragma once

#include <cmath>
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

namespace hmira_test {

/// A closed cylinder of radius 1 and height 1 (axis z): `around` segments, `rows` rows of
/// triangles on the side and a fan on each cap. Its two rims are creases of 90 degrees.
inline face_list capped_cylinder(std::size_t around, std::size_t rows) {
    face_list t;
    const double pi = 3.14159265358979323846;
    for (std::size_t i = 0; i <= rows; ++i)
        for (std::size_t j = 0; j < around; ++j) {
            const double a = 2 * pi * double(j) / double(around);
            t.points.push_back({std::cos(a), std::sin(a), double(i) / double(rows)});
        }
    const std::size_t bottom = t.points.size(), top = bottom + 1;
    t.points.push_back({0, 0, 0});
    t.points.push_back({0, 0, 1});
    auto at = [&](std::size_t i, std::size_t j) { return i * around + j % around; };
    for (std::size_t i = 0; i < rows; ++i)
        for (std::size_t j = 0; j < around; ++j) {
            t.faces.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
            t.faces.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
        }
    for (std::size_t j = 0; j < around; ++j) {
        t.faces.push_back({bottom, at(0, j + 1), at(0, j)});
        t.faces.push_back({top, at(rows, j), at(rows, j + 1)});
    }
    return t;
}

}  // namespace hmira_test
