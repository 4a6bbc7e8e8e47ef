// tests/support/shapes.hpp
// Meshes the suites build from first principles (grids, tori, disjoint unions), written
// through mesh_traits so they work on every model. Face lists here are the test's own data.
#pragma once

#include <cmath>
#include <cstddef>
#include <numbers>
#include <random>
#include <span>
#include <vector>

#include <hmira/concepts.hpp>

namespace hmira_test {

struct face_list {
    std::vector<hmira::vec3<double>> points;
    std::vector<std::vector<std::size_t>> faces;
};

/// An nx x ny grid of quads (or triangles when `triangles`) in the z = 0 plane, wound +z.
inline face_list grid(std::size_t nx, std::size_t ny, bool triangles = false) {
    face_list g;
    for (std::size_t j = 0; j <= ny; ++j)
        for (std::size_t i = 0; i <= nx; ++i) g.points.push_back({double(i), double(j), 0.0});
    auto id = [&](std::size_t i, std::size_t j) { return j * (nx + 1) + i; };
    for (std::size_t j = 0; j < ny; ++j)
        for (std::size_t i = 0; i < nx; ++i) {
            const auto a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
            if (triangles) {
                g.faces.push_back({a, b, c});
                g.faces.push_back({a, c, d});
            } else {
                g.faces.push_back({a, b, c, d});
            }
        }
    return g;
}

/// A torus of n x m quads (genus 1, closed), wound outward.
inline face_list torus(std::size_t n, std::size_t m, double R = 2.0, double r = 0.7) {
    face_list t;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < m; ++j) {
            const double u = 2 * std::numbers::pi * double(i) / double(n),
                         v = 2 * std::numbers::pi * double(j) / double(m);
            t.points.push_back(
                {(R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)});
        }
    auto id = [&](std::size_t i, std::size_t j) { return (i % n) * m + (j % m); };
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < m; ++j) t.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    return t;
}

/// Removes the faces for which `drop(face index)` is true (makes holes and boundaries).
template <class Pred>
face_list without_faces(face_list g, Pred drop) {
    std::vector<std::vector<std::size_t>> kept;
    for (std::size_t f = 0; f < g.faces.size(); ++f)
        if (!drop(f)) kept.push_back(g.faces[f]);
    g.faces = std::move(kept);
    return g;
}

/// Adds the face list to the mesh through its traits; returns whether every face was accepted.
template <class M, class T = hmira::default_traits<M>>
bool add_face_list(M& mesh, const face_list& g, std::vector<typename T::vertex_handle>* vertices_out = nullptr) {
    using S = typename T::scalar;
    std::vector<typename T::vertex_handle> vs;
    for (const auto& p : g.points) vs.push_back(T::add_vertex(mesh, hmira::vec3<S>{S(p.x), S(p.y), S(p.z)}));
    bool ok = true;
    std::vector<typename T::vertex_handle> corners;
    for (const auto& f : g.faces) {
        corners.clear();
        for (auto i : f) corners.push_back(vs[i]);
        ok &= static_cast<bool>(T::add_face(mesh, std::span<const typename T::vertex_handle>(corners)));
    }
    if (vertices_out) *vertices_out = vs;
    return ok;
}

}  // namespace hmira_test
