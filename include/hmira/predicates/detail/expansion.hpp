// hmira/predicates/detail/expansion.hpp
// Error-free transformations and floating-point expansion arithmetic (Priest; Shewchuk,
// "Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric Predicates", 1997):
// the exact arithmetic the adaptive predicates fall back on. Written for hmira from the paper.
#pragma once

#include <cfloat>
#include <cmath>
#include <cstddef>

// The error-free transformations below are exact only under IEEE round-to-nearest double
// arithmetic evaluated as written. Refuse the flags that break that, instead of returning
// wrong signs at run time.
#if defined(__FAST_MATH__)
#error \
    "hmira predicates: -ffast-math (or -Ofast) breaks the exact orient2d/incircle predicates; compile this translation unit without it"
#endif
#if defined(__ASSOCIATIVE_MATH__)
#error \
    "hmira predicates: -fassociative-math lets the compiler re-associate the error-free sums of the exact predicates; compile without it"
#endif
#if defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__
#error \
    "hmira predicates: -ffinite-math-only removes the NaN/infinity checks the predicates' callers rely on; compile without it"
#endif
#if defined(FLT_EVAL_METHOD) && FLT_EVAL_METHOD != 0 && FLT_EVAL_METHOD != -1
#error \
    "hmira predicates: need double expressions evaluated in double precision (FLT_EVAL_METHOD == 0, e.g. -mfpmath=sse on x86)"
#endif

namespace hmira::predicates::detail {

// FMA contraction (-ffp-contract=fast with an FMA-capable -march) would fuse a*b+c in Dekker's
// splitting and make two_product inexact. Where the target has a fused multiply-add we use it
// explicitly: fma(a, b, -a*b) is the exact rounding error of a*b whatever the contraction mode.
// Where it has none, the compiler cannot contract either, and Dekker's product is exact.
#if defined(__FP_FAST_FMA) || defined(__FMA__) || defined(__ARM_FEATURE_FMA)
#define HMIRA_PREDICATES_USE_FMA 1
#endif

/// 2^-53: half an ulp of 1, the relative rounding error of one operation.
inline constexpr double epsilon = 0x1p-53;
#ifndef HMIRA_PREDICATES_USE_FMA
/// 2^27 + 1: splits a double into two halves of 26 bits each.
inline constexpr double splitter = 0x1p27 + 1.0;
#endif

/// x + y == a + b exactly, x = fl(a + b). No precondition on magnitudes.
inline void two_sum(double a, double b, double& x, double& y) noexcept {
    x = a + b;
    const double bv = x - a;
    const double av = x - bv;
    y = (a - av) + (b - bv);
}

/// x + y == a - b exactly, x = fl(a - b).
inline void two_diff(double a, double b, double& x, double& y) noexcept {
    x = a - b;
    const double bv = a - x;
    const double av = x + bv;
    y = (a - av) + (bv - b);
}

/// The rounding error of x = fl(a - b): (a - b) - x exactly.
inline double two_diff_tail(double a, double b, double x) noexcept {
    const double bv = a - x;
    const double av = x + bv;
    return (a - av) + (bv - b);
}

/// x + y == a * b exactly, x = fl(a * b) (no overflow or underflow assumed).
inline void two_product(double a, double b, double& x, double& y) noexcept {
    x = a * b;
#ifdef HMIRA_PREDICATES_USE_FMA
    y = __builtin_fma(a, b, -x);
#else
    const double ca = splitter * a;
    const double ahi = ca - (ca - a);
    const double alo = a - ahi;
    const double cb = splitter * b;
    const double bhi = cb - (cb - b);
    const double blo = b - bhi;
    y = alo * blo - (((x - ahi * bhi) - alo * bhi) - ahi * blo);
#endif
}

/// An expansion: a sum of non-overlapping doubles in increasing magnitude, zeros removed.
/// Fixed capacity N, on the stack; the sizes in the predicates are bounded statically.
template <std::size_t N>
struct expansion {
    double c[N];
    std::size_t n = 0;

    /// The component of largest magnitude: its sign is the sign of the whole sum.
    double top() const noexcept { return n ? c[n - 1] : 0.0; }
    /// An approximation of the value (the sum of components).
    double estimate() const noexcept {
        double s = 0;
        for (std::size_t i = 0; i < n; ++i) s += c[i];
        return s;
    }
};

/// The exact a*b - c*d as an expansion of up to 4 components.
inline expansion<4> two_two_diff_products(double a, double b, double c, double d) noexcept {
    double p1, p0, q1, q0;
    two_product(a, b, p1, p0);
    two_product(c, d, q1, q0);
    // (p1 + p0) - (q1 + q0), Shewchuk's Two-Two-Diff.
    double i, x0, j, k, x1, x2, x3;
    two_diff(p0, q0, i, x0);
    two_sum(p1, i, j, k);
    two_diff(k, q1, i, x1);
    two_sum(j, i, x3, x2);
    expansion<4> r;
    for (double v : {x0, x1, x2, x3})
        if (v != 0.0) r.c[r.n++] = v;
    return r;
}

/// h = e + f, exactly, on raw component arrays; returns the length of h (at most ne + nf).
/// Merges the components by magnitude, then sweeps them with two_sum (Shewchuk's
/// Fast-Expansion-Sum with zero elimination; two_sum yields the same values as fast_two_sum
/// wherever the latter is valid, and needs no magnitude precondition). h may not alias e or f.
inline std::size_t sum_components(const double* e, std::size_t ne, const double* f, std::size_t nf,
                                  double* h) noexcept {
    std::size_t hn = 0;
    if (ne == 0 || nf == 0) {
        const double* s = ne ? e : f;
        const std::size_t sn = ne ? ne : nf;
        for (std::size_t i = 0; i < sn; ++i) h[i] = s[i];
        return sn;
    }
    std::size_t ei = 0, fi = 0;
    auto next = [&]() {
        if (fi >= nf || (ei < ne && std::fabs(e[ei]) < std::fabs(f[fi]))) return e[ei++];
        return f[fi++];
    };
    double q = next();
    while (ei < ne || fi < nf) {
        const double g = next();
        double s, err;
        two_sum(q, g, s, err);
        if (err != 0.0) h[hn++] = err;
        q = s;
    }
    if (q != 0.0) h[hn++] = q;
    return hn;
}

/// h = e * b, exactly (Shewchuk's Scale-Expansion with zero elimination); returns the length
/// of h (at most 2 ne). h may not alias e.
inline std::size_t scale_components(const double* e, std::size_t ne, double b, double* h) noexcept {
    std::size_t hn = 0;
    if (ne == 0 || b == 0.0) return 0;
    double q, err;
    two_product(e[0], b, q, err);
    if (err != 0.0) h[hn++] = err;
    for (std::size_t i = 1; i < ne; ++i) {
        double p1, p0, s;
        two_product(e[i], b, p1, p0);
        two_sum(q, p0, s, err);
        if (err != 0.0) h[hn++] = err;
        two_sum(p1, s, q, err);
        if (err != 0.0) h[hn++] = err;
    }
    if (q != 0.0) h[hn++] = q;
    return hn;
}

/// h = e + f, exactly.
template <std::size_t NH, std::size_t NE, std::size_t NF>
void expansion_sum(const expansion<NE>& e, const expansion<NF>& f, expansion<NH>& h) noexcept {
    static_assert(NH >= NE + NF, "expansion_sum: output too small");
    h.n = sum_components(e.c, e.n, f.c, f.n, h.c);
}

/// h = e - f, exactly.
template <std::size_t NH, std::size_t NE, std::size_t NF>
void expansion_diff(const expansion<NE>& e, const expansion<NF>& f, expansion<NH>& h) noexcept {
    static_assert(NH >= NE + NF, "expansion_diff: output too small");
    double neg[NF];
    for (std::size_t i = 0; i < f.n; ++i) neg[i] = -f.c[i];
    h.n = sum_components(e.c, e.n, neg, f.n, h.c);
}

/// h = e * b, exactly.
template <std::size_t NH, std::size_t NE>
void scale_expansion(const expansion<NE>& e, double b, expansion<NH>& h) noexcept {
    static_assert(NH >= 2 * NE, "scale_expansion: output too small");
    h.n = scale_components(e.c, e.n, b, h.c);
}

/// h = e * f, exactly: the sum of e scaled by each component of f.
template <std::size_t NH, std::size_t NE, std::size_t NF>
void expansion_product(const expansion<NE>& e, const expansion<NF>& f, expansion<NH>& h) noexcept {
    static_assert(NH >= 2 * NE * NF, "expansion_product: output too small");
    double part[2 * NE];
    double tmp[NH];
    h.n = 0;
    for (std::size_t j = 0; j < f.n; ++j) {
        const std::size_t pn = scale_components(e.c, e.n, f.c[j], part);
        if (h.n == 0) {  // (not through tmp: GCC cannot see that an empty tmp is never read)
            for (std::size_t i = 0; i < pn; ++i) h.c[i] = part[i];
            h.n = pn;
            continue;
        }
        for (std::size_t i = 0; i < h.n; ++i) tmp[i] = h.c[i];
        h.n = sum_components(tmp, h.n, part, pn, h.c);
    }
}

/// The exact value of a difference a - b as a two-component expansion.
inline expansion<2> exact_diff(double a, double b) noexcept {
    double x, y;
    two_diff(a, b, x, y);
    expansion<2> r;
    if (y != 0.0) r.c[r.n++] = y;
    if (x != 0.0) r.c[r.n++] = x;
    return r;
}

/// Sign of an expansion: the sign of its largest component.
template <std::size_t N>
int sign(const expansion<N>& e) noexcept {
    const double t = e.top();
    return (t > 0.0) - (t < 0.0);
}

}  // namespace hmira::predicates::detail
