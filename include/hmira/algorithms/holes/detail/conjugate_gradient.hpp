// hmira/algorithms/holes/detail/conjugate_gradient.hpp
// A small sparse symmetric positive definite solver for hole fairing: compressed rows and
// Jacobi-preconditioned conjugate gradients, standard library only (no Eigen in the core).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "../../../core/progress.hpp"

namespace hmira::detail::holes {

/// A square sparse matrix in compressed rows.
struct sparse_matrix {
    std::size_t size = 0;
    std::vector<std::size_t> row_start{0};  ///< row r's entries are [row_start[r], row_start[r + 1])
    std::vector<std::size_t> column;
    std::vector<double> value;

    /// Appends row `size` from (column, value) pairs; repeated columns are summed. O(k log k).
    void add_row(std::vector<std::pair<std::size_t, double>>& entries) {
        std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        for (std::size_t e = 0; e < entries.size(); ++e) {
            if (e > 0 && entries[e].first == entries[e - 1].first)
                value.back() += entries[e].second;
            else {
                column.push_back(entries[e].first);
                value.push_back(entries[e].second);
            }
        }
        row_start.push_back(column.size());
        ++size;
    }
    /// y = A x. O(non-zeros).
    void multiply(const std::vector<double>& x, std::vector<double>& y) const {
        y.assign(size, 0.0);
        for (std::size_t r = 0; r < size; ++r) {
            double s = 0;
            for (std::size_t e = row_start[r]; e < row_start[r + 1]; ++e) s += value[e] * x[column[e]];
            y[r] = s;
        }
    }
    double diagonal(std::size_t r) const {
        for (std::size_t e = row_start[r]; e < row_start[r + 1]; ++e)
            if (column[e] == r) return value[e];
        return 0;
    }
};

/// How a solve ended.
struct solve_outcome {
    bool converged = false;
    std::size_t iterations = 0;
    double relative_residual = 0;  ///< |b - A x| / |b| at the end
    bool cancelled = false;        ///< the progress gate said stop (x is then the last iterate)
};

/// Solves A x = b for a symmetric positive definite A by conjugate gradients with the Jacobi
/// preconditioner, starting from x (resized to A's size if it is not). Stops when
/// the recurrence's residual is at most tolerance |b|, or after max_iterations; x is then the
/// last iterate, and `converged` says whether the true residual |b - A x| is within 10 x
/// tolerance |b|. A non-positive diagonal or a non-finite value stops it unconverged.
/// With a `gate`, reports to it after about every 2^20 multiply-adds and once at the end,
/// counting `blocks` blocks over max_iterations iterations (the rest at the end), and stops
/// (`cancelled`, not converged) when it says stop.
/// Complexity O(iterations * non-zeros), O(size) extra memory.
inline solve_outcome conjugate_gradient(const sparse_matrix& a, const std::vector<double>& b, std::vector<double>& x,
                                        double tolerance, std::size_t max_iterations, progress_gate* gate = nullptr,
                                        std::size_t blocks = 0) {
    std::size_t reported = 0;
    auto report = [&](std::size_t iterations) {
        const double share = max_iterations > 0 ? double(iterations) / double(max_iterations) : 1.0;
        const std::size_t due = std::min(blocks, std::size_t(share * double(blocks)));
        const std::size_t now = due > reported ? due - reported : 0;
        reported += now;
        return gate->advance(now);
    };
    auto outcome = [&](solve_outcome o) {
        if (gate && !o.cancelled && !gate->advance(blocks > reported ? blocks - reported : 0)) o.cancelled = true;
        return o;
    };
    const auto solved = [&]() -> solve_outcome {
        const std::size_t n = a.size;
        solve_outcome out;
        x.resize(n, 0.0);
        double b_norm = 0;
        for (double v : b) b_norm += v * v;
        b_norm = std::sqrt(b_norm);
        if (!std::isfinite(b_norm)) return out;
        std::vector<double> inverse_diagonal(n), r(n), z(n), p(n), q;
        for (std::size_t i = 0; i < n; ++i) {
            const double d = a.diagonal(i);
            if (!(d > 0)) return out;
            inverse_diagonal[i] = 1 / d;
        }
        a.multiply(x, q);
        double r_norm = 0;
        for (std::size_t i = 0; i < n; ++i) {
            r[i] = b[i] - q[i];
            r_norm += r[i] * r[i];
        }
        const double goal = tolerance * (b_norm > 0 ? b_norm : 1);
        // The recurrence's residual drifts from the true one; the verdict uses the true one.
        auto finish = [&](double) {
            a.multiply(x, q);
            double rn = 0;
            for (std::size_t i = 0; i < n; ++i) rn += (b[i] - q[i]) * (b[i] - q[i]);
            rn = std::sqrt(rn);
            out.relative_residual = b_norm > 0 ? rn / b_norm : rn;
            out.converged = std::isfinite(rn) && rn <= 10 * goal;
            return out;
        };
        if (std::sqrt(r_norm) <= goal) return finish(std::sqrt(r_norm));
        double rz = 0;
        for (std::size_t i = 0; i < n; ++i) {
            z[i] = inverse_diagonal[i] * r[i];
            p[i] = z[i];
            rz += r[i] * z[i];
        }
        std::size_t work = 0;
        for (out.iterations = 1; out.iterations <= max_iterations; ++out.iterations) {
            work += a.value.size() + 4 * n;
            if (gate && work >= (std::size_t{1} << 20)) {
                work = 0;
                if (!report(out.iterations)) {
                    out.cancelled = true;
                    return out;
                }
            }
            a.multiply(p, q);
            double pq = 0;
            for (std::size_t i = 0; i < n; ++i) pq += p[i] * q[i];
            if (!(pq > 0) || !std::isfinite(pq)) return finish(std::sqrt(r_norm));
            const double alpha = rz / pq;
            r_norm = 0;
            for (std::size_t i = 0; i < n; ++i) {
                x[i] += alpha * p[i];
                r[i] -= alpha * q[i];
                r_norm += r[i] * r[i];
            }
            if (!std::isfinite(r_norm)) return finish(r_norm);
            if (std::sqrt(r_norm) <= goal) return finish(std::sqrt(r_norm));
            double rz_next = 0;
            for (std::size_t i = 0; i < n; ++i) {
                z[i] = inverse_diagonal[i] * r[i];
                rz_next += r[i] * z[i];
            }
            const double beta = rz_next / rz;
            rz = rz_next;
            for (std::size_t i = 0; i < n; ++i) p[i] = z[i] + beta * p[i];
        }
        out.iterations = max_iterations;
        return finish(std::sqrt(r_norm));
    }();
    return outcome(solved);
}

}  // namespace hmira::detail::holes
