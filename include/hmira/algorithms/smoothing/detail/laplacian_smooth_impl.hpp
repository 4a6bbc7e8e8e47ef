// hmira/algorithms/smoothing/detail/laplacian_smooth_impl.hpp
// The machinery of laplacian_smooth and taubin_smooth (smoothing/laplacian_smooth.hpp): the
// weights, one step, the run of steps with its rollback, and the definitions.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <limits>
#include <string>
#include <vector>

#include "../../../core/rollback.hpp"
#include "../../triangle/triangle_common.hpp"

namespace hmira {

namespace detail::smoothing {

/// Vertices the smoothing loop visits between two calls of the progress callback.
inline constexpr std::size_t check_every = std::size_t(1) << 16;

/// The positions a step reads and the ones it writes, by vertex index: allocated once per
/// call, not once per step (fresh V-sized buffers every step cost as much as the step's
/// arithmetic on a large mesh). The first step reads the positions the call started from,
/// which the call's position_rollback holds.
struct buffers {
    std::vector<vec3<double>> p, out;
};

/// What a step ran into.
struct step_status {
    bool cancelled = false;
    long long beyond_range = -1;    ///< a vertex whose new position is not a finite double, or -1
    bool not_finite_input = false;  ///< that vertex's neighbourhood holds a non-finite coordinate
};

/// Whether all three coordinates are finite.
inline bool finite(const vec3<double>& q) {
    constexpr double big = std::numeric_limits<double>::max();
    return std::abs(q.x) <= big && std::abs(q.y) <= big && std::abs(q.z) <= big;
}

/// The cotangent of the angle at a in triangle (a, b, c); 0 for a degenerate triangle, NaN
/// when the products overflow (the caller then recomputes the vertex at a smaller scale).
inline double cotangent(const vec3<double>& a, const vec3<double>& b, const vec3<double>& c) {
    const auto u = b - a, w = c - a;
    const double s = std::sqrt(squared_norm(cross(u, w)));
    if (s > 0 && s <= std::numeric_limits<double>::max()) return dot(u, w) / s;
    return s == 0 ? 0.0 : std::numeric_limits<double>::quiet_NaN();
}

/// Vertex i's new position p_i + amount * (sum of w_j (p_j - p_i)) / (sum of w_j), reading
/// positions through `at` (by vertex index); p_i where it cannot move. `s` is a halfedge out
/// of the vertex.
template <class M, class T, class At>
vec3<double> moved(const M& m, std::size_t i, typename T::halfedge_handle s, double amount, laplacian_weights weights,
                   At&& at) {
    const vec3<double> pi = at(i);
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
                const auto a = T::vertex_index(m, T::target(m, T::opposite(m, y)));
                const auto b = T::vertex_index(m, T::target(m, y));
                w += 0.5 * cotangent(at(c), at(a), at(b));
            }
        }
        sum += (at(j) - pi) * w;
        total += w;
        x = T::next(m, T::opposite(m, x));
    } while (x != s);
    if (total > 0) return pi + sum * (amount / total);
    if (total != total) return {total, total, total};  // the weights overflowed: NaN, so the caller rescales
    return pi;                                         // an obtuse fan whose cotangents cancel: leave it
}

/// Vertex i's new position, computed as moved() does on its neighbourhood scaled by a power of
/// two that brings the largest coordinate below 1 (exact but for subnormal results), then
/// scaled back: differences and products of coordinates near the largest double cannot
/// overflow there. Not finite when the true position lies beyond the range of double, or
/// when a coordinate of the neighbourhood is not finite (`not_finite_input` then set).
template <class M, class T>
vec3<double> moved_rescaled(const M& m, std::size_t i, typename T::halfedge_handle s, double amount,
                            laplacian_weights weights, const std::vector<vec3<double>>& p, bool& not_finite_input) {
    double largest = 0;
    const auto widen = [&](std::size_t k) {
        largest = std::max({largest, std::abs(p[k].x), std::abs(p[k].y), std::abs(p[k].z)});
    };
    widen(i);
    auto x = s;
    do {
        widen(T::vertex_index(m, T::target(m, x)));
        x = T::next(m, T::opposite(m, x));
    } while (x != s);
    if (!(largest <= std::numeric_limits<double>::max())) {
        not_finite_input = true;
        return {largest, largest, largest};
    }
    const int e = largest > 0 ? std::ilogb(largest) + 1 : 0;
    const auto scaled = [&](std::size_t k) {
        return vec3<double>{std::ldexp(p[k].x, -e), std::ldexp(p[k].y, -e), std::ldexp(p[k].z, -e)};
    };
    const vec3<double> q = moved<M, T>(m, i, s, amount, weights, scaled);
    return {std::ldexp(q.x, e), std::ldexp(q.y, e), std::ldexp(q.z, e)};
}

/// One Jacobi step p += step * L(p) on the free vertices. Positions are read back from the
/// mesh every step (into `into`), so a model with float positions rounds between steps as it
/// always did. Every check_every vertices visited (counted across steps in `visited`) it asks
/// `gate` whether to go on. A step whose new positions are all finite writes them; otherwise
/// the vertices that overflowed are recomputed at a smaller scale (moved_rescaled), and if one
/// is still not finite the step writes nothing and names it. Returns what stopped it, if
/// anything. The finiteness check is one flag per sweep, folded into the loop.
template <class M, class T>
step_status step(M& m, double amount, laplacian_weights weights, const std::vector<char>& fixed,
                 const std::vector<vec3<double>>* start, std::vector<vec3<double>>& into,
                 std::vector<vec3<double>>& out, progress_gate& gate, std::size_t& visited) {
    namespace dt = detail::triangle_ops;
    if (!start) {
        into.resize(T::vertex_index_bound(m));
        for (auto v : T::vertices(m)) into[T::vertex_index(m, v)] = dt::position_of<M, T>(m, v);
    }
    const auto& p = start ? *start : into;
    out.resize(p.size());
    const auto at = [&](std::size_t k) -> const vec3<double>& { return p[k]; };
    bool all_finite = true;
    for (auto v : T::vertices(m)) {
        if (++visited == check_every) {
            visited = 0;
            if (!gate.advance(1)) return {true, -1, false};
        }
        const auto i = T::vertex_index(m, v);
        if (fixed[i]) continue;
        const auto s = T::vertex_halfedge(m, v);
        if (s == T::null_halfedge()) {
            out[i] = p[i];  // no edges: it stays
            continue;
        }
        out[i] = moved<M, T>(m, i, s, amount, weights, at);
        all_finite &= finite(out[i]);
    }
    if (!all_finite) {
        // Rare (coordinates near the largest double): redo the vertices that overflowed.
        for (auto v : T::vertices(m)) {
            const auto i = T::vertex_index(m, v);
            if (fixed[i] || finite(out[i])) continue;
            bool bad_input = false;
            out[i] = moved_rescaled<M, T>(m, i, T::vertex_halfedge(m, v), amount, weights, p, bad_input);
            if (!finite(out[i])) return {false, (long long)i, bad_input};
        }
    }
    for (auto v : T::vertices(m)) {
        const auto i = T::vertex_index(m, v);
        if (!fixed[i]) dt::set_position<M, T>(m, v, out[i]);
    }
    return {};
}

/// Runs `iterations` rounds of the steps `amounts` (one for Laplacian, lambda and mu for
/// Taubin). On cancellation or a position beyond the range of double, puts every free vertex
/// back where the call found it (position_rollback) and returns the error.
template <class M, class T>
result<void> run(M& m, std::size_t iterations, std::initializer_list<double> amounts, laplacian_weights weights,
                 const std::vector<char>& fixed, const progress_function& progress, const char* who) {
    const std::size_t vertices = T::vertex_count(m);
    const double steps = double(iterations) * double(amounts.size());
    const double blocks = steps * double(vertices) / double(check_every);
    const std::size_t most = std::size_t(-1) / 2;
    detail::progress_gate gate(progress, blocks >= double(most) ? most : std::size_t(blocks));
    // Smoothing moves vertices only: the rollback keeps the starting positions, which the first
    // step reads anyway, so it costs no pass of its own.
    if (iterations == 0 || amounts.size() == 0) return {};
    position_rollback<M, T> undo(m);
    buffers b;
    std::size_t visited = 0;
    bool first = true;
    for (std::size_t k = 0; k < iterations; ++k)
        for (const double amount : amounts) {
            const auto status =
                step<M, T>(m, amount, weights, fixed, first ? &undo.positions() : nullptr, b.p, b.out, gate, visited);
            first = false;
            if (!status.cancelled && status.beyond_range < 0) continue;
            undo.restore_only([&](std::size_t i) { return !fixed[i]; });
            if (status.cancelled) return fail(errc::cancelled, std::string(who) + ": cancelled");
            const std::string vertex = "vertex " + std::to_string(status.beyond_range);
            if (status.not_finite_input)
                return fail(errc::unsupported,
                            std::string(who) + ": " + vertex + " or a neighbour has a non-finite coordinate",
                            status.beyond_range);
            return fail(errc::unsupported,
                        std::string(who) + ": " + vertex + " would move beyond the range of double (in iteration " +
                            std::to_string(k + 1) + ")",
                        status.beyond_range);
        }
    undo.commit();
    return {};
}

template <class M, class T>
result<std::vector<char>> fixed_set(const M& m, bool fix_boundary, const std::vector<std::size_t>& listed,
                                    laplacian_weights weights, const char* who) {
    std::vector<char> fixed(T::vertex_index_bound(m), 0);
    for (auto i : listed) {
        if (i >= fixed.size())
            return fail(errc::invalid_argument,
                        std::string(who) + ": option fixed_vertices names vertex " + std::to_string(i) + " of " +
                            std::to_string(fixed.size()),
                        (long long)i);
        fixed[i] = 1;
    }
    for (auto v : T::vertices(m)) {
        const auto s = T::vertex_halfedge(m, v);
        if (fix_boundary && s != T::null_halfedge() && T::face(m, s) == T::null_face())
            fixed[T::vertex_index(m, v)] = 1;
    }
    if (weights == laplacian_weights::cotangent)
        for (auto f : T::faces(m))
            if (!detail::triangle_ops::in_triangle<M, T>(m, T::face_halfedge(m, f)))
                return fail(errc::topology,
                            std::string(who) +
                                ": cotangent weights need triangles; a face is not one (triangulate_faces first)");
    return fixed;
}

}  // namespace detail::smoothing

template <class M, class T>
    requires smoothable_mesh<M, T>
result<smooth_result> laplacian_smooth(M& mesh, const laplacian_smooth_options& options) {
    if (!(options.lambda > 0 && options.lambda <= 1))
        return fail(errc::invalid_argument,
                    "laplacian_smooth: option lambda must lie in (0, 1], got " + std::to_string(options.lambda));
    auto fixed = detail::smoothing::fixed_set<M, T>(mesh, options.fix_boundary, options.fixed_vertices, options.weights,
                                                    "laplacian_smooth");
    if (!fixed) return fixed.error();
    if (auto r = detail::smoothing::run<M, T>(mesh, options.iterations, {options.lambda}, options.weights, *fixed,
                                              options.progress, "laplacian_smooth");
        !r)
        return r.error();
    smooth_result out;
    for (auto v : T::vertices(mesh)) out.moved += !(*fixed)[T::vertex_index(mesh, v)];
    return out;
}

template <class M, class T>
    requires smoothable_mesh<M, T>
result<smooth_result> taubin_smooth(M& mesh, const taubin_smooth_options& options) {
    if (!(options.lambda > 0 && options.lambda <= 1 && options.mu < -options.lambda && options.mu >= -1))
        return fail(errc::invalid_argument,
                    "taubin_smooth: options must satisfy 0 < lambda <= 1 and -1 <= mu < -lambda, got lambda " +
                        std::to_string(options.lambda) + ", mu " + std::to_string(options.mu));
    auto fixed = detail::smoothing::fixed_set<M, T>(mesh, options.fix_boundary, options.fixed_vertices, options.weights,
                                                    "taubin_smooth");
    if (!fixed) return fixed.error();
    if (auto r = detail::smoothing::run<M, T>(mesh, options.iterations, {options.lambda, options.mu}, options.weights,
                                              *fixed, options.progress, "taubin_smooth");
        !r)
        return r.error();
    smooth_result out;
    for (auto v : T::vertices(mesh)) out.moved += !(*fixed)[T::vertex_index(mesh, v)];
    return out;
}

}  // namespace hmira
