// hmira/algorithms/generators/platonic_solids.hpp
// The five Platonic solids, centred at the origin and wound outward (counter-clockwise seen
// from outside), written into any mesh that can add vertices and faces (thesis appendix C).
// The cube is the thesis's [-1, 1]^3 cube, with its face (b, c, g, f) wound the right way.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/result.hpp"
#include "../../core/vec3.hpp"

namespace hmira {

/// Placement of a generated solid: every coordinate is multiplied by `scale`, then moved by `center`.
struct solid_options {
    double scale = 1.0;               ///< uniform scale of the canonical coordinates
    vec3<double> center = {0, 0, 0};  ///< where the solid's centre goes
};

/// What a generator created, in creation order.
template <class M, class T = default_traits<M>>
struct generated_elements {
    std::vector<typename T::vertex_handle> vertices;  ///< new vertices
    std::vector<typename T::face_handle> faces;       ///< new faces
};

namespace detail {

template <class M, class T, std::size_t N>
result<generated_elements<M, T>> add_solid(M& mesh, std::span<const std::array<double, 3>> points,
                                           std::span<const std::array<int, N>> faces, const solid_options& options) {
    using S = typename T::scalar;
    generated_elements<M, T> out;
    out.vertices.reserve(points.size());
    out.faces.reserve(faces.size());
    for (const auto& p : points) {
        const auto q = vec3<double>{p[0], p[1], p[2]} * options.scale + options.center;
        out.vertices.push_back(
            T::add_vertex(mesh, vec3<S>{static_cast<S>(q.x), static_cast<S>(q.y), static_cast<S>(q.z)}));
    }
    std::array<typename T::vertex_handle, N>
        corner;  // not `{}`: some handles (OpenMesh) have an explicit default constructor
    for (const auto& f : faces) {
        for (std::size_t i = 0; i < N; ++i) corner[i] = out.vertices[static_cast<std::size_t>(f[i])];
        auto added = T::add_face(mesh, std::span<const typename T::vertex_handle>(corner));
        if (!added) return added.error();
        out.faces.push_back(*added);
    }
    return out;
}

inline constexpr double golden = 1.6180339887498948482;

}  // namespace detail

/// Regular tetrahedron with vertices (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1). 4 V, 6 E, 4 F.
template <class M, class T = default_traits<M>>
    requires mesh_builder<M, T>
result<generated_elements<M, T>> generate_tetrahedron(M& mesh, const solid_options& options = {}) {
    static constexpr std::array<std::array<double, 3>, 4> p{{{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}}};
    static constexpr std::array<std::array<int, 3>, 4> f{{{2, 0, 1}, {1, 0, 3}, {3, 0, 2}, {2, 1, 3}}};
    return detail::add_solid<M, T, 3>(mesh, p, f, options);
}

/// The cube [-1, 1]^3 of thesis ch. 9, corners A..H in the thesis's order. 8 V, 12 E, 6 F (quads).
template <class M, class T = default_traits<M>>
    requires polygon_mesh_builder<M, T>
result<generated_elements<M, T>> generate_cube(M& mesh, const solid_options& options = {}) {
    // A B C D E F G H, as in the thesis.
    static constexpr std::array<std::array<double, 3>, 8> p{
        {{-1, -1, -1}, {1, -1, -1}, {1, -1, 1}, {-1, -1, 1}, {-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}}};
    // The thesis lists (b, c, g, f), which faces inward; (b, f, g, c) is the outward winding.
    static constexpr std::array<std::array<int, 4>, 6> f{
        {{0, 1, 2, 3}, {1, 5, 6, 2}, {2, 6, 7, 3}, {0, 3, 7, 4}, {4, 5, 1, 0}, {7, 6, 5, 4}}};
    return detail::add_solid<M, T, 4>(mesh, p, f, options);
}

/// Regular octahedron with vertices at the unit axis points. 6 V, 12 E, 8 F.
template <class M, class T = default_traits<M>>
    requires mesh_builder<M, T>
result<generated_elements<M, T>> generate_octahedron(M& mesh, const solid_options& options = {}) {
    static constexpr std::array<std::array<double, 3>, 6> p{
        {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}};
    static constexpr std::array<std::array<int, 3>, 8> f{
        {{4, 0, 2}, {2, 0, 5}, {3, 0, 4}, {5, 0, 3}, {2, 1, 4}, {5, 1, 2}, {4, 1, 3}, {3, 1, 5}}};
    return detail::add_solid<M, T, 3>(mesh, p, f, options);
}

/// Regular icosahedron with vertices at the cyclic permutations of (0, ±1, ±phi). 12 V, 30 E, 20 F.
template <class M, class T = default_traits<M>>
    requires mesh_builder<M, T>
result<generated_elements<M, T>> generate_icosahedron(M& mesh, const solid_options& options = {}) {
    constexpr double g = detail::golden;
    static constexpr std::array<std::array<double, 3>, 12> p{{{0, -1, -g},
                                                              {0, -1, g},
                                                              {0, 1, -g},
                                                              {0, 1, g},
                                                              {-1, -g, 0},
                                                              {-1, g, 0},
                                                              {1, -g, 0},
                                                              {1, g, 0},
                                                              {-g, 0, -1},
                                                              {g, 0, -1},
                                                              {-g, 0, 1},
                                                              {g, 0, 1}}};
    static constexpr std::array<std::array<int, 3>, 20> f{{{2, 0, 8},  {9, 0, 2},  {4, 0, 6},  {8, 0, 4},  {6, 0, 9},
                                                           {10, 1, 3}, {3, 1, 11}, {6, 1, 4},  {4, 1, 10}, {11, 1, 6},
                                                           {7, 2, 5},  {5, 2, 8},  {9, 2, 7},  {5, 3, 7},  {10, 3, 5},
                                                           {7, 3, 11}, {8, 4, 10}, {10, 5, 8}, {11, 6, 9}, {9, 7, 11}}};
    return detail::add_solid<M, T, 3>(mesh, p, f, options);
}

/// Regular dodecahedron with vertices (±1, ±1, ±1) and the cyclic permutations of
/// (0, ±1/phi, ±phi). 20 V, 30 E, 12 F (pentagons).
template <class M, class T = default_traits<M>>
    requires polygon_mesh_builder<M, T>
result<generated_elements<M, T>> generate_dodecahedron(M& mesh, const solid_options& options = {}) {
    constexpr double g = detail::golden, r = 1.0 / detail::golden;
    static constexpr std::array<std::array<double, 3>, 20> p{
        {{-1, -1, -1}, {-1, -1, 1}, {-1, 1, -1}, {-1, 1, 1}, {1, -1, -1}, {1, -1, 1},  {1, 1, -1},
         {1, 1, 1},    {0, -r, -g}, {0, -r, g},  {0, r, -g}, {0, r, g},   {-r, -g, 0}, {-r, g, 0},
         {r, -g, 0},   {r, g, 0},   {-g, 0, -r}, {g, 0, -r}, {-g, 0, r},  {g, 0, r}}};
    static constexpr std::array<std::array<int, 5>, 12> f{{{18, 16, 0, 12, 1},
                                                           {10, 8, 0, 16, 2},
                                                           {14, 12, 0, 8, 4},
                                                           {3, 18, 1, 9, 11},
                                                           {5, 9, 1, 12, 14},
                                                           {3, 13, 2, 16, 18},
                                                           {6, 10, 2, 13, 15},
                                                           {15, 13, 3, 11, 7},
                                                           {5, 14, 4, 17, 19},
                                                           {6, 17, 4, 8, 10},
                                                           {11, 9, 5, 19, 7},
                                                           {19, 17, 6, 15, 7}}};
    return detail::add_solid<M, T, 5>(mesh, p, f, options);
}

}  // namespace hmira
