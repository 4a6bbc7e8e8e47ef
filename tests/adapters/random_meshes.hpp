// Seeded random meshes for the adapter tests: triangle or quad grids and tori with holes
// punched in them, faces shuffled, and isolated vertices sprinkled in, so every adjacency
// query meets boundaries, interior vertices and vertices with nothing around them.
#pragma once

#include <algorithm>
#include <cstddef>
#include <random>
#include <vector>

#include "support/shapes.hpp"

namespace hmira_test {

/// A random manifold face list: holes of one cell on a lattice with a random offset (so no
/// vertex is pinched), faces shuffled, and `isolated` extra vertices used by no face.
inline face_list random_mesh(unsigned seed, std::size_t nx = 14, std::size_t ny = 11, std::size_t isolated = 5) {
    std::mt19937 rng(seed);
    const bool tri = rng() % 2 == 0;
    const bool closed = rng() % 3 == 0;
    face_list g = closed ? torus(nx, ny) : grid(nx, ny, tri);
    const std::size_t per_cell = (!closed && tri) ? 2 : 1;
    const std::size_t stride = 3 + rng() % 2, ox = rng() % stride, oy = rng() % stride;
    const std::size_t row = closed ? ny : nx;
    g = without_faces(std::move(g), [&](std::size_t f) {
        const std::size_t cell = f / per_cell;
        return (cell % row) % stride == ox && (cell / row) % stride == oy && (cell / row) > 0;
    });
    std::shuffle(g.faces.begin(), g.faces.end(), rng);
    // Rotate each face's start vertex: the adapters must not depend on it.
    for (auto& f : g.faces) std::rotate(f.begin(), f.begin() + static_cast<std::ptrdiff_t>(rng() % f.size()), f.end());
    std::uniform_real_distribution<double> u(-5, 5);
    for (std::size_t i = 0; i < isolated; ++i) g.points.push_back({u(rng), u(rng), u(rng)});
    return g;
}

}  // namespace hmira_test
