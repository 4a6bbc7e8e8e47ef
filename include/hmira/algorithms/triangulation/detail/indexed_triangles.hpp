// hmira/algorithms/triangulation/detail/indexed_triangles.hpp
// A mesh's faces as triangles over vertex indices, with the positions as doubles checked for the
// exact predicates: the common input of the exact 3D algorithms (self_intersections,
// inside_closed), which then work on plain arrays whatever the model.
#pragma once

#include <array>
#include <cstddef>
#include <ranges>
#include <string>
#include <vector>

#include "../../../concepts.hpp"
#include "../../../core/result.hpp"
#include "../../../core/vec3.hpp"
#include "../../../predicates/orient2d.hpp"
#include "../triangulate_faces.hpp"

namespace hmira::detail::triangulation {

/// One triangle of a face, by vertex index.
struct indexed_triangle {
    std::array<std::size_t, 3> v;
    std::size_t face;
};

/// Every vertex position as doubles, by vertex index; an error names the first vertex with a
/// coordinate the exact predicates cannot take.
template <class M, class T>
result<std::vector<vec3<double>>> predicate_positions(const M& mesh, const char* what) {
    std::vector<vec3<double>> pos(T::vertex_index_bound(mesh));
    for (auto v : T::vertices(mesh)) {
        const std::size_t i = T::vertex_index(mesh, v);
        const vec3<typename T::scalar> q = T::position(mesh, v);
        const vec3<double> p{double(q.x), double(q.y), double(q.z)};
        for (std::size_t k = 0; k < 3; ++k)
            if (!predicates::in_predicate_range(p[k]))
                return fail(errc::invalid_argument,
                            std::string(what) + ": vertex " + std::to_string(i) +
                                " has a coordinate that is not finite or outside the exact predicates' range",
                            (long long)i);
        pos[i] = p;
    }
    return pos;
}

/// The faces as triangles: a triangle as itself, a polygon as face_triangles cuts it, or fanned
/// from its first corner when it has no simple projection.
template <class M, class T>
std::vector<indexed_triangle> indexed_triangles(const M& mesh) {
    std::vector<indexed_triangle> out;
    out.reserve(T::face_count(mesh));
    std::vector<std::size_t> loop;
    for (auto f : T::faces(mesh)) {
        const std::size_t fi = T::face_index(mesh, f);
        loop.clear();
        for (auto v : T::face_vertices(mesh, f)) loop.push_back(T::vertex_index(mesh, v));
        if (loop.size() < 3) continue;
        bool rings = false;
        if constexpr (inner_ring_mesh<M, T>) rings = !std::ranges::empty(T::inner_rings(mesh, f));
        if (loop.size() == 3 && !rings) {
            out.push_back({{loop[0], loop[1], loop[2]}, fi});
            continue;
        }
        if (auto tris = face_triangles<M, T>(mesh, f)) {
            for (const auto& t : *tris)
                out.push_back(
                    {{T::vertex_index(mesh, t[0]), T::vertex_index(mesh, t[1]), T::vertex_index(mesh, t[2])}, fi});
            continue;
        }
        for (std::size_t i = 1; i + 1 < loop.size(); ++i) out.push_back({{loop[0], loop[i], loop[i + 1]}, fi});
    }
    return out;
}

}  // namespace hmira::detail::triangulation
