// hmira/algorithms/geometry/sharp_edges.hpp
// The edges where a surface bends by at least a given angle: what bevel --angle selects, and
// what feature-preserving algorithms keep. One definition for the library and every front end.
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

#include "../../concepts.hpp"
#include "face_normal.hpp"

namespace hmira {

/// What sharp_edges() needs: halfedge navigation (an edge's two faces) and positions.
template <class M, class T = default_traits<M>>
concept sharp_edges_mesh = halfedge_navigable_mesh<M, T> && face_normal_mesh<M, T>;

/// The edges between two faces whose normals (Newell's, face_area_vector) are at least
/// `angle_degrees` apart, in T::edges order: on a cube every edge at 90 or less, none above.
/// An angle of 0 or less selects every edge between two faces. Boundary edges, and edges at a
/// face of zero area (which has no normal), are never selected.
/// The angle in degrees is rounded when its cosine is taken, so an edge whose cosine lies
/// within 1e-12 of the limit's counts as sharp: a cube's edges are sharp at exactly 90.
/// Complexity O(E + sum of face degrees).
template <class M, class T = default_traits<M>>
    requires sharp_edges_mesh<M, T>
std::vector<typename T::edge_handle> sharp_edges(const M& mesh, double angle_degrees) {
    std::vector<typename T::edge_handle> out;
    const double cos_limit = std::cos(angle_degrees * std::numbers::pi / 180.0);
    for (auto e : T::edges(mesh)) {
        const auto h = T::edge_halfedge(mesh, e);
        const auto f0 = T::face(mesh, h), f1 = T::face(mesh, T::opposite(mesh, h));
        if (f0 == T::null_face() || f1 == T::null_face()) continue;
        if (angle_degrees > 0) {
            const auto n0 = face_area_vector<M, T>(mesh, f0);
            const auto n1 = face_area_vector<M, T>(mesh, f1);
            const double len = std::sqrt(dot(n0, n0) * dot(n1, n1));
            if (!(len > 0) || dot(n0, n1) / len > cos_limit + 1e-12) continue;
        }
        out.push_back(e);
    }
    return out;
}

}  // namespace hmira
