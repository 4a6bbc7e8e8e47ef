// hmira/algorithms/geometry/mesh_measures.hpp
// A mesh's bounding box, surface area and enclosed volume: the measures every front end shows,
// computed once here from the same Newell area vectors as the face normals.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "../../concepts.hpp"
#include "../../core/vec3.hpp"
#include "face_normal.hpp"

namespace hmira {

/// An axis-aligned box: the smallest and the largest coordinate along each axis.
struct bounding_box {
    vec3<double> min;  ///< smallest x, y and z
    vec3<double> max;  ///< largest x, y and z
};

/// The box around the live vertices (isolated ones included); nullopt for a mesh without vertices.
/// Complexity O(V).
template <class M, class T = default_traits<M>>
    requires positioned_mesh<M, T>
std::optional<bounding_box> mesh_bounds(const M& mesh);

/// The total area of the faces: half the length of each face's Newell area vector, summed
/// (exact for planar polygons). Complexity O(sum of face degrees).
template <class M, class T = default_traits<M>>
    requires face_normal_mesh<M, T>
double surface_area(const M& mesh);

/// The signed volume the faces enclose, by the divergence theorem: the sum over faces of
/// p0 . A / 6, with p0 a face's first corner and A its area vector (the fan of tetrahedra from
/// the origin over the face's triangle fan, for any polygon, planar or not). Positive for a
/// closed mesh whose faces wind counter-clockwise seen from outside, negative when inside-out;
/// for a mesh with holes the value depends on where the origin is.
/// Complexity O(sum of face degrees).
template <class M, class T = default_traits<M>>
    requires face_normal_mesh<M, T>
double signed_volume(const M& mesh);

template <class M, class T>
    requires positioned_mesh<M, T>
std::optional<bounding_box> mesh_bounds(const M& mesh) {
    std::optional<bounding_box> box;
    for (auto v : T::vertices(mesh)) {
        const auto q = T::position(mesh, v);
        const vec3<double> p{double(q.x), double(q.y), double(q.z)};
        if (!box) {
            box = bounding_box{p, p};
            continue;
        }
        box->min = {std::min(box->min.x, p.x), std::min(box->min.y, p.y), std::min(box->min.z, p.z)};
        box->max = {std::max(box->max.x, p.x), std::max(box->max.y, p.y), std::max(box->max.z, p.z)};
    }
    return box;
}

template <class M, class T>
    requires face_normal_mesh<M, T>
double surface_area(const M& mesh) {
    double area = 0;
    for (auto f : T::faces(mesh)) {
        const auto a = face_area_vector<M, T>(mesh, f);
        area += std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z) / 2;
    }
    return area;
}

template <class M, class T>
    requires face_normal_mesh<M, T>
double signed_volume(const M& mesh) {
    double six_volume = 0;
    for (auto f : T::faces(mesh)) {
        const auto a = face_area_vector<M, T>(mesh, f);
        for (auto v : T::face_vertices(mesh, f)) {
            const auto q = T::position(mesh, v);
            six_volume += double(q.x) * a.x + double(q.y) * a.y + double(q.z) * a.z;
            break;
        }
    }
    return six_volume / 6;
}

}  // namespace hmira
