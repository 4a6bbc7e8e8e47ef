// hmira/algorithms/spatial/triangle_set.hpp
// A surface as plain triangles in double precision, each knowing the mesh face it came from:
// what the surface queries (winding number, signed distance, sampling, distances) run on.
// Polygon faces are cut by face_triangles (exact predicates), not fanned.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/result.hpp"
#include "../../core/vec3.hpp"
#include "../triangulation/triangulate_faces.hpp"

namespace hmira {

/// Triangles over a point array; triangle i lies on mesh face faces[i].
struct triangle_set {
    std::vector<vec3<double>> points;                     ///< indexed by T::vertex_index for a mesh
    std::vector<std::array<std::uint32_t, 3>> triangles;  ///< corners, wound like their face
    std::vector<std::size_t> faces;                       ///< T::face_index of each triangle's face
};

/// A mesh the surface queries read: face loops, positions, dense vertex and face indices.
template <class M, class T = default_traits<M>>
concept surface_query_mesh =
    face_vertex_range_mesh<M, T> && positioned_mesh<M, T> && vertex_index_mesh<M, T> && face_index_mesh<M, T>;

/// The triangles of every face of `mesh`: a triangle as itself, any other face (inner rings
/// included) by face_triangles. A polygon whose corners have no projected area (collinear)
/// bounds no area and gives no triangle.
/// \pre none. \post the mesh is only read.
/// Errors (`who` prefixes the message): errc::invalid_argument naming the vertex for a
/// non-finite position; face_triangles' errc::topology naming the face for a polygon that is
/// not simple in its plane; errc::unsupported past 2^32 - 1 vertices.
/// Complexity: O(V + F) for triangles, plus O(n log n) per polygon of n corners.
template <class M, class T = default_traits<M>>
    requires surface_query_mesh<M, T>
[[nodiscard]] result<triangle_set> triangles_of(const M& mesh, std::string_view who = "triangles_of") {
    triangle_set out;
    const std::size_t bound = T::vertex_index_bound(mesh);
    if (bound >= std::size_t(UINT32_MAX)) return fail(errc::unsupported, std::string(who) + ": too many vertices");
    out.points.resize(bound);
    for (auto v : T::vertices(mesh)) {
        const vec3<typename T::scalar> p = T::position(mesh, v);
        const vec3<double> q{double(p.x), double(p.y), double(p.z)};
        const auto i = T::vertex_index(mesh, v);
        if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z))
            return fail(errc::invalid_argument,
                        std::string(who) + ": vertex " + std::to_string(i) + " has a non-finite position",
                        (long long)i);
        out.points[i] = q;
    }
    out.triangles.reserve(T::face_count(mesh));
    out.faces.reserve(T::face_count(mesh));
    std::vector<std::uint32_t> loop;
    for (auto f : T::faces(mesh)) {
        loop.clear();
        for (auto v : T::face_vertices(mesh, f)) loop.push_back(std::uint32_t(T::vertex_index(mesh, v)));
        const bool ringless = !detail::euler::has_rings<M, T>(mesh, f);
        if (loop.size() == 3 && ringless) {
            out.triangles.push_back({loop[0], loop[1], loop[2]});
            out.faces.push_back(T::face_index(mesh, f));
            continue;
        }
        if (loop.size() < 3 && ringless) continue;  // no area
        auto cut = face_triangles<M, T>(mesh, f);
        if (!cut) {
            if (cut.error().code == errc::degenerate_face) continue;  // collinear corners: no area
            return fail(cut.error().code, std::string(who) + ": " + cut.error().message, cut.error().element);
        }
        for (const auto& t : *cut) {
            out.triangles.push_back({std::uint32_t(T::vertex_index(mesh, t[0])),
                                     std::uint32_t(T::vertex_index(mesh, t[1])),
                                     std::uint32_t(T::vertex_index(mesh, t[2]))});
            out.faces.push_back(T::face_index(mesh, f));
        }
    }
    return out;
}

/// A triangle_set over caller arrays (triangle i on face i), checked: every index below
/// points.size() and every point finite.
/// Errors: errc::invalid_argument naming the triangle or the point (`who` prefixes it).
/// Complexity: O(V + F).
[[nodiscard]] inline result<triangle_set> make_triangle_set(std::span<const vec3<double>> points,
                                                            std::span<const std::array<std::uint32_t, 3>> triangles,
                                                            std::string_view who = "make_triangle_set") {
    triangle_set out;
    out.points.assign(points.begin(), points.end());
    for (std::size_t i = 0; i < points.size(); ++i)
        if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y) || !std::isfinite(points[i].z))
            return fail(errc::invalid_argument,
                        std::string(who) + ": vertex " + std::to_string(i) + " has a non-finite position",
                        (long long)i);
    out.triangles.assign(triangles.begin(), triangles.end());
    out.faces.resize(triangles.size());
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        for (auto c : triangles[i])
            if (c >= points.size())
                return fail(errc::invalid_argument,
                            std::string(who) + ": triangle " + std::to_string(i) + " uses vertex " + std::to_string(c) +
                                ", but there are " + std::to_string(points.size()),
                            (long long)i);
        out.faces[i] = i;
    }
    return out;
}

}  // namespace hmira
