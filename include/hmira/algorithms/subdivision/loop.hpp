// hmira/algorithms/subdivision/loop.hpp
// Loop subdivision of a triangle mesh, built from the local operators: every edge split at
// its Loop edge point, then the new edges that join an old and a new vertex flipped (1-to-4),
// and the old vertices moved by Loop's vertex rule. Boundaries follow the cubic B-spline.
#pragma once

#include <cassert>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <string>
#include <vector>

#include "../triangle/flip_edge.hpp"
#include "../triangle/split_edge.hpp"

namespace hmira {

/// Options of loop_subdivide.
struct loop_options {
    /// Levels of subdivision (each multiplies the faces by 4).
    std::size_t levels = 1;
};

/// What loop_subdivide did.
struct loop_result {
    std::size_t vertices = 0;  ///< vertices after the last level
    std::size_t edges = 0;     ///< edges after the last level
    std::size_t faces = 0;     ///< faces after the last level
};

/// Whether every face of the mesh is a triangle without rings. O(F).
template <class M, class T = default_traits<M>>
    requires triangle_operable_mesh<M, T>
bool is_triangle_mesh(const M& mesh) {
    for (auto f : T::faces(mesh))
        if (!detail::triangle_ops::in_triangle<M, T>(mesh, T::face_halfedge(mesh, f))) return false;
    return true;
}

namespace detail::subdivision {

template <class M, class T>
void loop_level(M& mesh) {
    namespace dt = detail::triangle_ops;
    using H = typename T::halfedge_handle;
    // Old vertices: Loop's vertex rule (interior: Warren-free beta; boundary: 1/8, 3/4, 1/8).
    std::vector<vec3<double>> moved(T::vertex_index_bound(mesh));
    std::vector<char> is_old(T::vertex_index_bound(mesh), 0);
    for (auto v : T::vertices(mesh)) {
        const auto i = T::vertex_index(mesh, v);
        is_old[i] = 1;
        const auto p = dt::position_of<M, T>(mesh, v);
        const auto s = T::vertex_halfedge(mesh, v);
        if (s == T::null_halfedge()) {
            moved[i] = p;
            continue;
        }
        if (T::face(mesh, s) == T::null_face()) {  // boundary: its two boundary neighbours
            const auto a = dt::position_of<M, T>(mesh, T::target(mesh, s));
            const auto b = dt::position_of<M, T>(mesh, T::target(mesh, T::opposite(mesh, T::prev(mesh, s))));
            moved[i] = p * 0.75 + (a + b) * 0.125;
            continue;
        }
        vec3<double> sum{};
        std::size_t n = 0;
        auto x = s;
        do {
            sum += dt::position_of<M, T>(mesh, T::target(mesh, x));
            ++n;
            x = T::next(mesh, T::opposite(mesh, x));
        } while (x != s);
        const double c = 0.375 + 0.25 * std::cos(2 * std::numbers::pi / double(n));
        const double beta = (0.625 - c * c) / double(n);
        moved[i] = p * (1 - double(n) * beta) + sum * beta;
    }
    // Edge points, then the splits (edge handles and halfedge handles stay valid: the
    // operators only add elements here).
    std::vector<std::pair<H, vec3<double>>> splits;
    for (auto e : T::edges(mesh)) {
        const H h = T::edge_halfedge(mesh, e), o = T::opposite(mesh, h);
        const auto a = dt::position_of<M, T>(mesh, T::target(mesh, o)), b = dt::position_of<M, T>(mesh, T::target(mesh, h));
        vec3<double> q = (a + b) * 0.5;
        if (T::face(mesh, h) != T::null_face() && T::face(mesh, o) != T::null_face()) {
            const auto c = dt::position_of<M, T>(mesh, T::target(mesh, T::next(mesh, h)));
            const auto d = dt::position_of<M, T>(mesh, T::target(mesh, T::next(mesh, o)));
            q = (a + b) * 0.375 + (c + d) * 0.125;
        }
        splits.push_back({h, q});
    }
    std::vector<H> cuts;
    cuts.reserve(splits.size() * 2);
    for (const auto& [h, q] : splits) {
        const auto a = T::target(mesh, T::opposite(mesh, h)), b = T::target(mesh, h);
        auto r = split_edge<M, T>(mesh, h, {.position = q});
        // A triangle mesh always splits: the edge's ends differ and its sides are triangles.
        if (!r) continue;
        const auto s = T::vertex_halfedge(mesh, r->vertex);
        auto x = s;
        do {
            const auto t = T::target(mesh, x);
            if (t != a && t != b) cuts.push_back(x);
            x = T::next(mesh, T::opposite(mesh, x));
        } while (x != s);
    }
    const auto old_bound = is_old.size();
    auto old = [&](typename T::vertex_handle v) {
        const auto i = T::vertex_index(mesh, v);
        return i < old_bound && is_old[i];
    };
    for (const auto x : cuts) {
        const bool a_old = old(T::target(mesh, T::opposite(mesh, x))), b_old = old(T::target(mesh, x));
        if (a_old != b_old) {
            // Cannot fail after the splits: both sides are triangles, the far corners new and unjoined.
            [[maybe_unused]] const bool flipped = static_cast<bool>(flip_edge<M, T>(mesh, x));
            assert(flipped);
        }
    }
    for (auto v : T::vertices(mesh)) {
        const auto i = T::vertex_index(mesh, v);
        if (i < old_bound && is_old[i]) dt::set_position<M, T>(mesh, v, moved[i]);
    }
}

}  // namespace detail::subdivision

/// A mesh loop_subdivide can run on: the triangle operators, and dense vertex and face indices
/// for its per-level arrays.
template <class M, class T = default_traits<M>>
concept loop_subdividable_mesh = triangle_operable_mesh<M, T> && vertex_index_mesh<M, T> && face_index_mesh<M, T>;

/// Loop subdivision, `options.levels` times. Each level splits every edge at its edge point
/// (3/8 of each end plus 1/8 of each opposite corner; the midpoint on a boundary), flips the
/// new edges that join an old vertex to a new one (so each triangle becomes four), and moves
/// each old vertex by Loop's rule (1 - n beta of itself plus beta of each of its n
/// neighbours, beta = (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n; on a boundary 3/4 of itself
/// and 1/8 of each boundary neighbour).
///
/// \pre every face is a triangle without rings.
/// \post per level: V + E, E * 2 + 3 F, F * 4; genus and boundary loops unchanged.
/// Errors (mesh unchanged): errc::topology when a face is not a triangle (naming it);
/// errc::invalid_argument for more than 10 levels (a million-fold growth).
/// Complexity O(F) per level (each operator is O(1) or O(valence)), so O(4^levels F).
template <class M, class T = default_traits<M>>
    requires loop_subdividable_mesh<M, T>
[[nodiscard]] result<loop_result> loop_subdivide(M& mesh, const loop_options& options = {}) {
    if (options.levels > 10)
        return fail(errc::invalid_argument, "loop_subdivide: option levels must be at most 10, got " + std::to_string(options.levels));
    for (auto f : T::faces(mesh))
        if (!detail::triangle_ops::in_triangle<M, T>(mesh, T::face_halfedge(mesh, f)))
            return fail(errc::topology,
                        "loop_subdivide: face " + std::to_string(T::face_index(mesh, f)) + " is not a triangle (triangulate_faces first)",
                        (long long)T::face_index(mesh, f));
    for (std::size_t l = 0; l < options.levels; ++l) detail::subdivision::loop_level<M, T>(mesh);
    return loop_result{T::vertex_count(mesh), T::edge_count(mesh), T::face_count(mesh)};
}

}  // namespace hmira
