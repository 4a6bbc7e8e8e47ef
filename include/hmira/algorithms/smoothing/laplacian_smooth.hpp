// hmira/algorithms/smoothing/laplacian_smooth.hpp
// Laplacian smoothing (uniform or cotangent weights) and Taubin's lambda/mu smoothing, which
// alternates a shrinking and an inflating step so the surface smooths without shrinking.
#pragma once

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/result.hpp"
#include "../triangle/triangle_common.hpp"

namespace hmira {

/// How a vertex's neighbours are weighted.
enum class laplacian_weights {
    uniform,    ///< each neighbour alike (umbrella operator): also evens out the sampling
    cotangent,  ///< (cot alpha + cot beta) / 2 per edge: moves along the normal only (triangles only)
};

/// Options of laplacian_smooth.
struct laplacian_smooth_options {
    std::size_t iterations = 1;                           ///< smoothing steps
    double lambda = 0.5;                                  ///< step size, in (0, 1]
    laplacian_weights weights = laplacian_weights::uniform;  ///< neighbour weights
    bool fix_boundary = true;                             ///< keep boundary vertices where they are
    std::vector<std::size_t> fixed_vertices{};            ///< vertex indices (feature vertices) that stay exactly
};

/// Options of taubin_smooth.
struct taubin_smooth_options {
    std::size_t iterations = 10;                          ///< lambda/mu pairs
    double lambda = 0.5;                                  ///< shrinking step, > 0
    double mu = -0.53;                                    ///< inflating step, < -lambda
    laplacian_weights weights = laplacian_weights::uniform;  ///< neighbour weights
    bool fix_boundary = true;                             ///< keep boundary vertices where they are
    std::vector<std::size_t> fixed_vertices{};            ///< vertex indices that stay exactly
};

/// What a smoothing did.
struct smooth_result {
    std::size_t moved = 0;  ///< vertices free to move
};

/// A mesh the smoothers can run on: halfedge navigation (neighbours, boundary), movable
/// positions, dense vertex indices. Every halfedge model qualifies, TriMesh included.
template <class M, class T = default_traits<M>>
concept smoothable_mesh = halfedge_navigable_mesh<M, T> && position_mutable_mesh<M, T> && vertex_index_mesh<M, T>;

namespace detail::smoothing {

/// The positions a step reads and the ones it writes, by vertex index: allocated once per
/// call, not once per step (two fresh V-sized buffers a step cost as much as the step's
/// arithmetic on a large mesh).
struct buffers {
    std::vector<vec3<double>> p, out;
};

/// One Jacobi step p += step * L(p) on the free vertices. Positions are read back from the
/// mesh every step, so a model with float positions rounds between steps as it always did.
template <class M, class T>
void step(M& m, double amount, laplacian_weights weights, const std::vector<char>& fixed, buffers& b) {
    namespace dt = detail::triangle_ops;
    auto& p = b.p;
    auto& out = b.out;
    p.resize(T::vertex_index_bound(m));
    out.resize(p.size());
    for (auto v : T::vertices(m)) p[T::vertex_index(m, v)] = dt::position_of<M, T>(m, v);
    auto cot = [](const vec3<double>& a, const vec3<double>& b, const vec3<double>& c) {  // at a
        const auto u = b - a, w = c - a;
        const double s = std::sqrt(squared_norm(cross(u, w)));
        return s > 0 ? dot(u, w) / s : 0.0;
    };
    for (auto v : T::vertices(m)) {
        const auto i = T::vertex_index(m, v);
        if (fixed[i]) continue;
        out[i] = p[i];  // what a vertex keeps when it cannot move (no edges, or a cancelling fan)
        const auto s = T::vertex_halfedge(m, v);
        if (s == T::null_halfedge()) continue;
        vec3<double> sum{};
        double total = 0;
        auto x = s;
        do {
            const auto j = T::vertex_index(m, T::target(m, x));
            double w = 1;
            if (weights == laplacian_weights::cotangent) {
                w = 0;
                for (const auto y : {x, T::opposite(m, x)}) {
                    if (T::face(m, y) == T::null_face()) continue;
                    const auto c = T::vertex_index(m, T::target(m, T::next(m, y)));
                    const auto a = T::vertex_index(m, T::target(m, T::opposite(m, y))), b = T::vertex_index(m, T::target(m, y));
                    w += 0.5 * cot(p[c], p[a], p[b]);
                }
            }
            sum += (p[j] - p[i]) * w;
            total += w;
            x = T::next(m, T::opposite(m, x));
        } while (x != s);
        if (!(total > 0)) continue;  // an obtuse fan whose cotangents cancel: leave it
        out[i] = p[i] + sum * (amount / total);
    }
    for (auto v : T::vertices(m)) {
        const auto i = T::vertex_index(m, v);
        if (!fixed[i]) dt::set_position<M, T>(m, v, out[i]);
    }
}

template <class M, class T>
result<std::vector<char>> fixed_set(const M& m, bool fix_boundary, const std::vector<std::size_t>& listed, laplacian_weights weights,
                                    const char* who) {
    std::vector<char> fixed(T::vertex_index_bound(m), 0);
    for (auto i : listed) {
        if (i >= fixed.size())
            return fail(errc::invalid_argument, std::string(who) + ": option fixed_vertices names vertex " + std::to_string(i) + " of " +
                                                    std::to_string(fixed.size()), (long long)i);
        fixed[i] = 1;
    }
    for (auto v : T::vertices(m)) {
        const auto s = T::vertex_halfedge(m, v);
        if (fix_boundary && s != T::null_halfedge() && T::face(m, s) == T::null_face()) fixed[T::vertex_index(m, v)] = 1;
    }
    if (weights == laplacian_weights::cotangent)
        for (auto f : T::faces(m))
            if (!detail::triangle_ops::in_triangle<M, T>(m, T::face_halfedge(m, f)))
                return fail(errc::topology, std::string(who) + ": cotangent weights need triangles; a face is not one (triangulate_faces first)");
    return fixed;
}

}  // namespace detail::smoothing

/// Laplacian smoothing: `iterations` times, every free vertex moves by `lambda` times the
/// weighted mean of its neighbours minus itself (all vertices read before any moves).
/// Boundary vertices (with `fix_boundary`) and `fixed_vertices` stay exactly where they are.
/// Uniform weights shrink a closed surface noticeably; see taubin_smooth.
/// Errors (mesh unchanged): errc::invalid_argument for a lambda outside (0, 1] or a fixed
/// vertex index out of range; errc::topology for cotangent weights on a non-triangle.
/// Complexity O(iterations * (V + E)), and 48 bytes per vertex besides the mesh. Each step
/// streams the vertices in index order and reads their neighbours, so the time per vertex
/// steps up (about 1.5x) once mesh and buffers (about 90 bytes per vertex on a quad
/// halfedge_mesh) outgrow the last-level cache, and is flat beyond it (bench/sweep: exponent
/// 0.99 over 10^6..10^7 vertices; instructions per vertex constant).
template <class M, class T = default_traits<M>>
    requires smoothable_mesh<M, T>
[[nodiscard]] result<smooth_result> laplacian_smooth(M& mesh, const laplacian_smooth_options& options = {}) {
    if (!(options.lambda > 0 && options.lambda <= 1))
        return fail(errc::invalid_argument, "laplacian_smooth: option lambda must lie in (0, 1], got " + std::to_string(options.lambda));
    auto fixed = detail::smoothing::fixed_set<M, T>(mesh, options.fix_boundary, options.fixed_vertices, options.weights, "laplacian_smooth");
    if (!fixed) return fixed.error();
    detail::smoothing::buffers b;
    for (std::size_t k = 0; k < options.iterations; ++k) detail::smoothing::step<M, T>(mesh, options.lambda, options.weights, *fixed, b);
    smooth_result out;
    for (auto v : T::vertices(mesh)) out.moved += !(*fixed)[T::vertex_index(mesh, v)];
    return out;
}

/// Taubin's lambda/mu smoothing: each iteration a Laplacian step of `lambda` (shrinks) then
/// one of `mu` (inflates), a low-pass filter that keeps the volume nearly constant.
/// Errors (mesh unchanged): errc::invalid_argument unless 0 < lambda <= 1 and
/// -1 <= mu < -lambda, or for a fixed vertex out of range; errc::topology as laplacian_smooth.
/// Complexity O(iterations * (V + E)).
template <class M, class T = default_traits<M>>
    requires smoothable_mesh<M, T>
[[nodiscard]] result<smooth_result> taubin_smooth(M& mesh, const taubin_smooth_options& options = {}) {
    if (!(options.lambda > 0 && options.lambda <= 1 && options.mu < -options.lambda && options.mu >= -1))
        return fail(errc::invalid_argument, "taubin_smooth: options must satisfy 0 < lambda <= 1 and -1 <= mu < -lambda, got lambda " +
                                                std::to_string(options.lambda) + ", mu " + std::to_string(options.mu));
    auto fixed = detail::smoothing::fixed_set<M, T>(mesh, options.fix_boundary, options.fixed_vertices, options.weights, "taubin_smooth");
    if (!fixed) return fixed.error();
    detail::smoothing::buffers b;
    for (std::size_t k = 0; k < options.iterations; ++k) {
        detail::smoothing::step<M, T>(mesh, options.lambda, options.weights, *fixed, b);
        detail::smoothing::step<M, T>(mesh, options.mu, options.weights, *fixed, b);
    }
    smooth_result out;
    for (auto v : T::vertices(mesh)) out.moved += !(*fixed)[T::vertex_index(mesh, v)];
    return out;
}

}  // namespace hmira
