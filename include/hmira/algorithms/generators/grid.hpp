// hmira/algorithms/generators/grid.hpp
// A flat rectangular grid of quads or triangles: an open surface with one boundary loop, the
// standard input for benchmarks at any size.
#pragma once

#include <cstddef>
#include <vector>

#include "platonic_solids.hpp"  // generated_elements

namespace hmira {

/// Size and resolution of generate_grid().
struct grid_options {
    std::size_t columns = 10;         ///< cells along x (>= 1)
    std::size_t rows = 10;            ///< cells along y (>= 1)
    double cell_size = 1.0;           ///< edge length of a cell
    bool triangles = false;           ///< split each cell into two triangles
    vec3<double> origin = {0, 0, 0};  ///< position of the corner vertex (0, 0)
};

/// Adds a grid in the z = origin.z plane, wound towards +z. V = (columns+1)(rows+1),
/// F = columns*rows (twice that with triangles). Complexity O(V).
/// Errors (mesh unchanged): zero columns or rows; quads asked of a triangle-only mesh
/// (errc::unsupported: use `.triangles = true` there).
template <class M, class T = default_traits<M>>
    requires mesh_builder<M, T>
result<generated_elements<M, T>> generate_grid(M& mesh, const grid_options& o = {}) {
    using S = typename T::scalar;
    if (o.columns == 0 || o.rows == 0)
        return fail(errc::invalid_argument, "generate_grid: columns and rows must be at least 1");
    if constexpr (!polygon_mesh_builder<M, T>)
        if (!o.triangles)
            return fail(errc::unsupported, "generate_grid: this mesh holds triangles only; set .triangles = true");
    generated_elements<M, T> out;
    out.vertices.reserve((o.columns + 1) * (o.rows + 1));
    for (std::size_t j = 0; j <= o.rows; ++j)
        for (std::size_t i = 0; i <= o.columns; ++i) {
            const auto p = o.origin + vec3<double>{double(i) * o.cell_size, double(j) * o.cell_size, 0};
            out.vertices.push_back(T::add_vertex(mesh, vec3<S>{S(p.x), S(p.y), S(p.z)}));
        }
    auto id = [&](std::size_t i, std::size_t j) { return out.vertices[j * (o.columns + 1) + i]; };
    auto add = [&](std::initializer_list<typename T::vertex_handle> vs) -> bool {
        auto f = T::add_face(mesh, std::span<const typename T::vertex_handle>(vs.begin(), vs.size()));
        if (f) out.faces.push_back(*f);
        return static_cast<bool>(f);
    };
    for (std::size_t j = 0; j < o.rows; ++j)
        for (std::size_t i = 0; i < o.columns; ++i) {
            const auto a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
            const bool ok = o.triangles ? (add({a, b, c}) && add({a, c, d})) : add({a, b, c, d});
            if (!ok) return fail(errc::unsupported, "generate_grid: the mesh refused a face");
        }
    return out;
}

}  // namespace hmira
