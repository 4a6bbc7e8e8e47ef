// hmira/algorithms/geometry/vertex_normals.hpp
// Per-vertex normals from the faces around each vertex, weighted by face area or by the
// corner angle, for shading, offsetting and smoothing. Written against face lists and
// positions only, so it runs on every model without adjacency (each face scatters to its
// corners instead of each vertex gathering its faces).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <string_view>
#include <utility>
#include <vector>

#include "../../concepts.hpp"
#include "face_normal.hpp"

namespace hmira {

/// How the faces around a vertex are weighted when their normals are summed.
enum class normal_weighting {
    area,   ///< by face area: large faces dominate (the unnormalised Newell normal)
    angle,  ///< by the face's interior angle at the vertex: independent of how faces are split
};

/// The weightings' names: "angle", "area" (see core/enum_names.hpp).
constexpr auto enum_names(normal_weighting) {
    return std::array{std::pair{normal_weighting::angle, std::string_view("angle")},
                      std::pair{normal_weighting::area, std::string_view("area")}};
}

/// Options of vertex_normals(): `vertex_normals(mesh, {.weighting = normal_weighting::area})`.
struct vertex_normal_options {
    normal_weighting weighting = normal_weighting::angle;  ///< see normal_weighting
    bool normalize = true;  ///< false keeps the weighted sum: sum of area x unit normal, or of angle x unit normal
};

/// What vertex_normals() needs: each face's vertices in winding order
/// (face_vertex_range_mesh), vertex positions (positioned_mesh) and a dense vertex index for
/// the output array (vertex_index_mesh).
template <class M, class T = default_traits<M>>
concept vertex_normals_mesh = face_vertex_range_mesh<M, T> && positioned_mesh<M, T> && vertex_index_mesh<M, T>;

namespace detail {

/// Interior angle at corner `at` between the sides to `prev` and `next`, in [0, 2 pi), seen
/// from the side `unit_normal` points to, so a reflex corner of a concave polygon counts > pi.
template <class S>
S corner_angle(const vec3<S>& prev, const vec3<S>& at, const vec3<S>& next, const vec3<S>& unit_normal) {
    const vec3<S> to_next = next - at, to_prev = prev - at;
    const S a = std::atan2(dot(cross(to_next, to_prev), unit_normal), dot(to_next, to_prev));
    return a < S(0) ? a + S(2) * std::numbers::pi_v<S> : a;
}

}  // namespace detail

/// Normal of every vertex: the sum of the normals of the faces around it, each weighted as
/// `options.weighting` says, then normalised (unless `options.normalize` is false).
///
/// Returns a std::vector indexed by `T::vertex_index(mesh, v)`, of size
/// `T::vertex_index_bound(mesh)`; read it with `normals[T::vertex_index(mesh, v)]`.
///
/// Complexity: O(V_bound + sum of face degrees) time, one pass over the faces;
/// O(V_bound) memory for the result plus O(largest face degree) scratch. No adjacency is
/// needed, so a face-vertex mesh pays no adapter. Angle weighting takes one atan2 per corner
/// and runs about four times slower than area weighting (bench/geometry/run.sh).
///
/// Preconditions: faces are wound consistently (counter-clockwise seen from outside) for the
/// normals to point outwards; a face's corners need not be coplanar (Newell's normal).
///
/// Errors: none; it never fails. A vertex with no face, a deleted vertex (a gap below the
/// index bound) and a vertex whose faces all have zero area get the zero vector, never NaN.
template <class M, class T = default_traits<M>>
    requires vertex_normals_mesh<M, T>
std::vector<vec3<typename T::scalar>> vertex_normals(const M& mesh, const vertex_normal_options& options = {}) {
    using S = typename T::scalar;
    using P = vec3<S>;
    std::vector<P> normals(T::vertex_index_bound(mesh), P{});
    std::vector<P> corner;          // positions of the current face, reused across faces
    std::vector<std::size_t> slot;  // their vertex indices
    for (auto f : T::faces(mesh)) {
        corner.clear();
        slot.clear();
        for (auto v : T::face_vertices(mesh, f)) {
            corner.push_back(static_cast<P>(T::position(mesh, v)));
            slot.push_back(static_cast<std::size_t>(T::vertex_index(mesh, v)));
        }
        const std::size_t k = corner.size();
        if (k < 3) continue;
        const P face_normal = newell_normal(corner);
        if (options.weighting == normal_weighting::area) {
            const P weighted = face_normal * S(0.5);  // |Newell normal| is twice the area
            for (std::size_t i = 0; i < k; ++i) normals[slot[i]] += weighted;
        } else {
            const S length = norm(face_normal);
            if (!(length > S(0))) continue;  // a zero-area face has no direction to give
            const P unit = face_normal / length;
            for (std::size_t i = 0; i < k; ++i)
                normals[slot[i]] +=
                    unit * detail::corner_angle(corner[(i + k - 1) % k], corner[i], corner[(i + 1) % k], unit);
        }
    }
    if (options.normalize)
        for (auto& n : normals) n = normalized(n);
    return normals;
}

}  // namespace hmira
