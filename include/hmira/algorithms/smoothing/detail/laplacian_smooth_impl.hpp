// hmira/algorithms/smoothing/detail/laplacian_smooth_impl.hpp
// The machinery of laplacian_smooth and taubin_smooth (smoothing/laplacian_smooth.hpp): the
// weights, one step, the run of steps with its rollback, and the definitions.
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <limits>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include "../../../core/rollback.hpp"
#include "../../conversion/detail/parallel.hpp"
#include "../../triangle/triangle_common.hpp"

namespace hmira {

namespace detail::smoothing {

/// Vertices the smoothing loop visits between two calls of the progress callback.
inline constexpr std::size_t check_every = std::size_t(1) << 16;

/// Rows a worker thread takes at a time.
inline constexpr std::size_t rows_per_chunk = 2048;

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

/// How a step weights the neighbours: alike, by cotangents of the current positions, or by
/// weights computed once (neighbourhoods::weight).
enum class weighting { uniform, cotangent, frozen };

/// Every vertex's neighbourhood in compressed rows over dense vertex indices, gathered once per
/// call: row r is the r-th vertex in the mesh's vertex order, its entries the neighbours in the
/// order the halfedges around it circulate (the order the sums run in, so the result does not
/// depend on how the rows are stored). A vertex that does not move (fixed, or without edges)
/// has an empty row. `Index` holds a vertex index.
template <class Index>
struct neighbourhoods {
    static constexpr Index none = Index(-1);
    std::vector<Index> vertex;       ///< row r's vertex index
    std::vector<std::size_t> first;  ///< row r's entries are [first[r], first[r + 1])
    std::vector<Index> neighbour;    ///< an entry's neighbour
    /// Cotangent weights only: an entry's third corner in the face left of the edge from the
    /// vertex to the neighbour, and in the face right of it (none at a boundary).
    std::vector<Index> left, right;
    std::vector<double> weight;  ///< weighting::frozen only: an entry's weight

    std::size_t rows() const noexcept { return vertex.size(); }
    bool moves(std::size_t r) const noexcept { return first[r] != first[r + 1]; }
};

/// Rows one gathering task takes.
inline constexpr std::size_t rows_per_task = 8192;

/// The neighbourhoods (`fixed` by vertex index), with the third corners when `corners` is set:
/// the vertex order is listed first, then two parallel walks around the vertices, one to
/// count each row's entries and one to write them where the counts put them. O(V + E).
template <class Index, class M, class T>
neighbourhoods<Index> gather(const M& m, const std::vector<char>& fixed, bool corners) {
    using H = typename T::halfedge_handle;
    neighbourhoods<Index> n;
    std::vector<H> out_of;  // a halfedge out of row r's vertex, or null when it does not move
    n.vertex.reserve(T::vertex_count(m));
    out_of.reserve(T::vertex_count(m));
    for (auto v : T::vertices(m)) {
        const auto i = T::vertex_index(m, v);
        n.vertex.push_back(Index(i));
        out_of.push_back(fixed[i] ? T::null_halfedge() : T::vertex_halfedge(m, v));
    }
    const std::size_t rows = n.rows();
    n.first.assign(rows + 1, 0);
    const auto walk = [&](std::size_t r, auto&& visit) {
        const H s = out_of[r];
        if (s == T::null_halfedge()) return;
        H x = s;
        do {
            visit(x);
            x = T::next(m, T::opposite(m, x));
        } while (x != s);
    };
    detail::parallel_chunks(rows, rows_per_task, [&](std::size_t r0, std::size_t r1) {
        for (std::size_t r = r0; r < r1; ++r) walk(r, [&](H) { ++n.first[r + 1]; });
    });
    for (std::size_t r = 0; r < rows; ++r) n.first[r + 1] += n.first[r];
    n.neighbour.resize(n.first[rows]);
    if (corners) {
        n.left.resize(n.first[rows]);
        n.right.resize(n.first[rows]);
    }
    const auto corner = [&](H y) {
        if (T::face(m, y) == T::null_face()) return neighbourhoods<Index>::none;
        return Index(T::vertex_index(m, T::target(m, T::next(m, y))));
    };
    detail::parallel_chunks(rows, rows_per_task, [&](std::size_t r0, std::size_t r1) {
        for (std::size_t r = r0; r < r1; ++r) {
            std::size_t k = n.first[r];
            walk(r, [&](H x) {
                n.neighbour[k] = Index(T::vertex_index(m, T::target(m, x)));
                if (corners) {
                    n.left[k] = corner(x);
                    n.right[k] = corner(T::opposite(m, x));
                }
                ++k;
            });
        }
    });
    return n;
}

/// Row r's vertex's new position p_i + amount * (sum of w_j (p_j - p_i)) / (sum of w_j),
/// reading positions through `at` (by vertex index); p_i where it cannot move.
template <weighting W, class Index, class At>
vec3<double> moved(const neighbourhoods<Index>& n, std::size_t r, double amount, At&& at) {
    const std::size_t i = n.vertex[r];
    const vec3<double> pi = at(i);
    vec3<double> sum{};
    double total = 0;
    for (std::size_t k = n.first[r], end = n.first[r + 1]; k < end; ++k) {
        const std::size_t j = n.neighbour[k];
        double w = 1;
        if constexpr (W == weighting::cotangent) {
            w = 0;
            if (n.left[k] != n.none) w += 0.5 * cotangent(at(n.left[k]), at(i), at(j));
            if (n.right[k] != n.none) w += 0.5 * cotangent(at(n.right[k]), at(j), at(i));
        } else if constexpr (W == weighting::frozen) {
            w = n.weight[k];
        }
        sum += (at(j) - pi) * w;
        total += w;
    }
    if (total > 0) return pi + sum * (amount / total);
    if (total != total) return {total, total, total};  // the weights overflowed: NaN, so the caller rescales
    return pi;                                         // an obtuse fan whose cotangents cancel: leave it
}

/// Row r's vertex's new position, computed as moved() does on its neighbourhood scaled by a
/// power of two that brings the largest coordinate below 1 (exact but for subnormal results),
/// then scaled back: differences and products of coordinates near the largest double cannot
/// overflow there. Not finite when the true position lies beyond the range of double, or when
/// a coordinate of the neighbourhood is not finite (`not_finite_input` then set).
template <weighting W, class Index>
vec3<double> moved_rescaled(const neighbourhoods<Index>& n, std::size_t r, double amount,
                            const std::vector<vec3<double>>& p, bool& not_finite_input) {
    double largest = 0;
    const auto widen = [&](std::size_t k) {
        largest = std::max({largest, std::abs(p[k].x), std::abs(p[k].y), std::abs(p[k].z)});
    };
    widen(n.vertex[r]);
    for (std::size_t k = n.first[r]; k < n.first[r + 1]; ++k) widen(n.neighbour[k]);
    if (!(largest <= std::numeric_limits<double>::max())) {
        not_finite_input = true;
        return {largest, largest, largest};
    }
    const int e = largest > 0 ? std::ilogb(largest) + 1 : 0;
    const auto scaled = [&](std::size_t k) {
        return vec3<double>{std::ldexp(p[k].x, -e), std::ldexp(p[k].y, -e), std::ldexp(p[k].z, -e)};
    };
    const vec3<double> q = moved<W>(n, r, amount, scaled);
    return {std::ldexp(q.x, e), std::ldexp(q.y, e), std::ldexp(q.z, e)};
}

/// The cotangent weights of the starting positions, frozen for every step: each row's as
/// moved() weighs them, recomputed at a smaller scale for a row whose sums overflow.
template <class Index>
void freeze_weights(neighbourhoods<Index>& n, const std::vector<vec3<double>>& p) {
    n.weight.resize(n.neighbour.size());
    const auto fill = [&](std::size_t r, auto&& at) {
        double total = 0;
        const std::size_t i = n.vertex[r];
        for (std::size_t k = n.first[r]; k < n.first[r + 1]; ++k) {
            const std::size_t j = n.neighbour[k];
            double w = 0;
            if (n.left[k] != n.none) w += 0.5 * cotangent(at(n.left[k]), at(i), at(j));
            if (n.right[k] != n.none) w += 0.5 * cotangent(at(n.right[k]), at(j), at(i));
            n.weight[k] = w;
            total += w;
        }
        return total;
    };
    detail::parallel_chunks(n.rows(), rows_per_chunk, [&](std::size_t r0, std::size_t r1) {
        for (std::size_t r = r0; r < r1; ++r) {
            if (std::isfinite(fill(r, [&](std::size_t k) -> const vec3<double>& { return p[k]; }))) continue;
            double largest = 0;
            const auto widen = [&](const vec3<double>& q) {
                largest = std::max({largest, std::abs(q.x), std::abs(q.y), std::abs(q.z)});
            };
            widen(p[n.vertex[r]]);
            for (std::size_t k = n.first[r]; k < n.first[r + 1]; ++k) widen(p[n.neighbour[k]]);
            // A non-finite neighbourhood keeps its weights: the first step names the vertex.
            if (!(largest <= std::numeric_limits<double>::max())) continue;
            const int e = largest > 0 ? std::ilogb(largest) + 1 : 0;
            fill(r, [&](std::size_t k) {
                return vec3<double>{std::ldexp(p[k].x, -e), std::ldexp(p[k].y, -e), std::ldexp(p[k].z, -e)};
            });
        }
    });
}

/// One Jacobi step out = p + amount * L(p) over the rows, in parallel; `round` brings each new
/// position to what the mesh's scalar holds, so a model with float positions rounds between
/// steps as it would writing and reading back its positions. Every check_every vertices
/// visited in the mesh's vertex order (counted across steps in `visited`) it asks `gate`
/// whether to go on, between chunks of rows. A step whose new positions are all finite is
/// done; otherwise the rows that overflowed are recomputed at a smaller scale
/// (moved_rescaled), and one still not finite stops the step, named.
template <weighting W, class Index, class Round>
step_status step(const neighbourhoods<Index>& n, std::size_t vertex_count, double amount,
                 const std::vector<vec3<double>>& p, std::vector<vec3<double>>& out, const Round& round,
                 progress_gate& gate, std::size_t& visited) {
    const auto at = [&](std::size_t k) -> const vec3<double>& { return p[k]; };
    std::atomic<bool> overflow{false};
    const auto sweep = [&](std::size_t from, std::size_t to) {
        detail::parallel_chunks(to - from, rows_per_chunk, [&](std::size_t c0, std::size_t c1) {
            bool all_finite = true;
            for (std::size_t r = from + c0; r < from + c1; ++r) {
                if (!n.moves(r)) continue;
                const vec3<double> q = moved<W>(n, r, amount, at);
                all_finite &= finite(q);
                out[n.vertex[r]] = round(q);
            }
            if (!all_finite) overflow.store(true, std::memory_order_relaxed);
        });
    };
    // The gate is asked before the vertex that makes the count reach check_every, as a walk of
    // the vertices one by one would.
    std::size_t done = 0;
    for (std::size_t r = check_every - visited - 1; r < vertex_count; r += check_every) {
        sweep(done, r);
        done = r;
        if (!gate.advance(1)) return {true, -1, false};
    }
    sweep(done, n.rows());
    visited = (visited + vertex_count) % check_every;
    if (overflow.load(std::memory_order_relaxed)) {
        // Rare (coordinates near the largest double): redo the rows that overflowed, in order.
        for (std::size_t r = 0; r < n.rows(); ++r) {
            const std::size_t i = n.vertex[r];
            if (!n.moves(r) || finite(out[i])) continue;
            bool bad_input = false;
            const vec3<double> q = moved_rescaled<W>(n, r, amount, p, bad_input);
            if (!finite(q)) return {false, (long long)i, bad_input};
            out[i] = round(q);
        }
    }
    return {};
}

/// Runs `iterations` rounds of the steps `amounts` (one for Laplacian, lambda and mu for
/// Taubin) on the rows `n`, from the positions `p` (by vertex index), leaving the last in `p`.
template <weighting W, class Index, class Round>
step_status steps(const neighbourhoods<Index>& n, std::size_t vertex_count, std::size_t iterations,
                  std::initializer_list<double> amounts, std::vector<vec3<double>>& p, const Round& round,
                  progress_gate& gate, std::size_t& iteration) {
    std::vector<vec3<double>> out = p;  // a vertex without a row keeps its position in both
    std::size_t visited = 0;
    for (iteration = 0; iteration < iterations; ++iteration)
        for (const double amount : amounts) {
            const auto status = step<W>(n, vertex_count, amount, p, out, round, gate, visited);
            if (status.cancelled || status.beyond_range >= 0) return status;
            p.swap(out);
        }
    return {};
}

/// The options run() reads.
struct run_options {
    std::size_t iterations = 0;
    laplacian_weights weights = laplacian_weights::uniform;
    bool refresh_weights = true;
    unsigned threads = 0;
};

/// Gathers the rows, runs the steps and writes the positions once at the end, with vertex
/// indices held in `Index`. On cancellation or a position beyond the range of double, puts
/// every free vertex back where the call found it (position_rollback) and returns the error.
template <class Index, class M, class T>
result<void> run_on(M& m, const run_options& o, std::initializer_list<double> amounts, const std::vector<char>& fixed,
                    const progress_function& progress, const char* who) {
    using S = typename T::scalar;
    const std::size_t vertices = T::vertex_count(m);
    const double total_steps = double(o.iterations) * double(amounts.size());
    const double blocks = total_steps * double(vertices) / double(check_every);
    const std::size_t most = std::size_t(-1) / 2;
    detail::progress_gate gate(progress, blocks >= double(most) ? most : std::size_t(blocks));
    if (o.iterations == 0 || amounts.size() == 0) return {};
    // The positions are read once, into the rollback, and written once, at the end.
    position_rollback<M, T> undo(m);
    const auto round = [](const vec3<double>& q) {
        if constexpr (std::is_same_v<S, double>)
            return q;
        else
            return vec3<double>{double(S(q.x)), double(S(q.y)), double(S(q.z))};
    };
    const bool cotangent = o.weights == laplacian_weights::cotangent;
    step_status status;
    std::size_t iteration = 0;
    std::vector<vec3<double>> p;
    detail::with_thread_count(o.threads, [&] {
        auto n = gather<Index, M, T>(m, fixed, cotangent);
        p = undo.positions();
        if (!cotangent)
            status = steps<weighting::uniform>(n, vertices, o.iterations, amounts, p, round, gate, iteration);
        else if (o.refresh_weights)
            status = steps<weighting::cotangent>(n, vertices, o.iterations, amounts, p, round, gate, iteration);
        else {
            freeze_weights(n, p);
            status = steps<weighting::frozen>(n, vertices, o.iterations, amounts, p, round, gate, iteration);
        }
    });
    if (status.cancelled || status.beyond_range >= 0) {
        undo.restore_only([&](std::size_t i) { return !fixed[i]; });
        if (status.cancelled) return fail(errc::cancelled, std::string(who) + ": cancelled");
        const std::string vertex = "vertex " + std::to_string(status.beyond_range);
        if (status.not_finite_input)
            return fail(errc::unsupported,
                        std::string(who) + ": " + vertex + " or a neighbour has a non-finite coordinate",
                        status.beyond_range);
        return fail(errc::unsupported,
                    std::string(who) + ": " + vertex + " would move beyond the range of double (in iteration " +
                        std::to_string(iteration + 1) + ")",
                    status.beyond_range);
    }
    for (auto v : T::vertices(m)) {
        const auto i = T::vertex_index(m, v);
        if (!fixed[i]) detail::triangle_ops::set_position<M, T>(m, v, p[i]);
    }
    undo.commit();
    return {};
}

/// run_on with 32-bit vertex indices in the rows where they suffice.
template <class M, class T>
result<void> run(M& m, const run_options& o, std::initializer_list<double> amounts, const std::vector<char>& fixed,
                 const progress_function& progress, const char* who) {
    if (T::vertex_index_bound(m) < std::size_t(std::uint32_t(-1)))
        return run_on<std::uint32_t, M, T>(m, o, amounts, fixed, progress, who);
    return run_on<std::size_t, M, T>(m, o, amounts, fixed, progress, who);
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
    const detail::smoothing::run_options run{options.iterations, options.weights, options.refresh_weights,
                                             options.threads};
    if (auto r =
            detail::smoothing::run<M, T>(mesh, run, {options.lambda}, *fixed, options.progress, "laplacian_smooth");
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
    const detail::smoothing::run_options run{options.iterations, options.weights, options.refresh_weights,
                                             options.threads};
    if (auto r = detail::smoothing::run<M, T>(mesh, run, {options.lambda, options.mu}, *fixed, options.progress,
                                              "taubin_smooth");
        !r)
        return r.error();
    smooth_result out;
    for (auto v : T::vertices(mesh)) out.moved += !(*fixed)[T::vertex_index(mesh, v)];
    return out;
}

}  // namespace hmira
