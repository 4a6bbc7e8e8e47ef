// hmira/predicates/detail/exact_point_impl.hpp
// The machinery of exact_point.hpp: outward-rounded interval arithmetic, an expansion number type,
// the homogeneous coordinates of each kind of point written once for both, and the predicates.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace hmira::predicates {
namespace detail {

inline constexpr double interval_inf = std::numeric_limits<double>::infinity();

/// The interval that decides nothing.
inline interval interval_all() noexcept { return {-interval_inf, interval_inf}; }

inline interval operator+(interval a, interval b) noexcept {
    // two_sum gives the exact rounding error of each bound: a bound is kept where rounding moved
    // it the safe way, and moved by one ulp otherwise.
    double l, el, h, eh;
    two_sum(a.lo, b.lo, l, el);
    two_sum(a.hi, b.hi, h, eh);
    if (!std::isfinite(l) || !std::isfinite(h) || el != el || eh != eh) return interval_all();
    return {el < 0 ? std::nextafter(l, -interval_inf) : l, eh > 0 ? std::nextafter(h, interval_inf) : h};
}
inline interval operator-(interval a) noexcept { return {-a.hi, -a.lo}; }
inline interval operator-(interval a, interval b) noexcept { return a + (-b); }
inline interval operator*(interval a, interval b) noexcept {
    const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    double l = p[0], h = p[0];
    for (double v : p) {
        if (!std::isfinite(v)) return interval_all();
        l = std::min(l, v);
        h = std::max(h, v);
    }
    if (a.lo == a.hi && b.lo == b.hi) {  // one exact product: its rounding error is known exactly
        double x, e;
        two_product(a.lo, b.lo, x, e);
        return {e < 0 ? std::nextafter(x, -interval_inf) : x, e > 0 ? std::nextafter(x, interval_inf) : x};
    }
    // A product that underflowed may be off by a subnormal ulp, which nextafter also covers.
    return {std::nextafter(l, -interval_inf), std::nextafter(h, interval_inf)};
}

/// An exact real as an expansion, with the operators the shared formulas below need.
struct exact_number {
    dynamic_expansion e;

    exact_number() = default;
    exact_number(double v) {
        if (v != 0) e.push_back(v);
    }
    explicit exact_number(dynamic_expansion x) : e(std::move(x)) {}
    int sign() const noexcept { return dyn_sign(e); }
};
inline exact_number operator+(const exact_number& a, const exact_number& b) { return exact_number(dyn_sum(a.e, b.e)); }
inline exact_number operator-(const exact_number& a) { return exact_number(dyn_negate(a.e)); }
inline exact_number operator-(const exact_number& a, const exact_number& b) { return a + (-b); }
inline exact_number operator*(const exact_number& a, const exact_number& b) {
    return exact_number(dyn_product(a.e, b.e));
}

template <class N>
using nvec = std::array<N, 3>;

template <class N>
nvec<N> nsub(const point3& a, const point3& b) {
    return {N(a.x) - N(b.x), N(a.y) - N(b.y), N(a.z) - N(b.z)};
}
template <class N>
nvec<N> ncross(const nvec<N>& u, const nvec<N>& v) {
    return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}
template <class N>
N ndot(const nvec<N>& u, const nvec<N>& v) {
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}
template <class N>
nvec<N> npoint(const point3& p) {
    return {N(p.x), N(p.y), N(p.z)};
}

/// Homogeneous coordinates of a line-plane point: x = p + (ln / ld) (q - p), so
/// (X, W) = (ld p + ln (q - p), ld) with n = (s - r) x (t - r), ln = n.(r - p), ld = n.(q - p).
template <class N>
std::array<N, 4> lpi_coordinates(const line_plane_point& l) {
    const nvec<N> n = ncross(nsub<N>(l.s, l.r), nsub<N>(l.t, l.r));
    const nvec<N> qp = nsub<N>(l.q, l.p);
    const N ln = ndot(n, nsub<N>(l.r, l.p)), ld = ndot(n, qp);
    const nvec<N> p = npoint<N>(l.p);
    return {ld * p[0] + ln * qp[0], ld * p[1] + ln * qp[1], ld * p[2] + ln * qp[2], ld};
}

/// Homogeneous coordinates of a three-plane point, by Cramer's rule: with n_i the normals and
/// d_i = n_i . (a point of plane i), x = (d_a n_b x n_c + d_b n_c x n_a + d_c n_a x n_b) / (n_a . n_b x n_c).
template <class N>
std::array<N, 4> tpi_coordinates(const three_plane_point& t) {
    auto normal = [](const std::array<point3, 3>& p) { return ncross(nsub<N>(p[1], p[0]), nsub<N>(p[2], p[0])); };
    const nvec<N> na = normal(t.a), nb = normal(t.b), nc = normal(t.c);
    const N da = ndot(na, npoint<N>(t.a[0])), db = ndot(nb, npoint<N>(t.b[0])), dc = ndot(nc, npoint<N>(t.c[0]));
    const nvec<N> bc = ncross(nb, nc), ca = ncross(nc, na), ab = ncross(na, nb);
    std::array<N, 4> h;
    for (std::size_t k = 0; k < 3; ++k) h[k] = da * bc[k] + db * ca[k] + dc * ab[k];
    h[3] = ndot(na, bc);
    return h;
}

/// Make W positive (a homogeneous point is unchanged when every coordinate changes sign).
inline void normalise(std::array<interval, 4>& h) noexcept {
    if (h[3].hi < 0)
        for (interval& v : h) v = -v;
}
inline exact_homogeneous normalise(std::array<exact_number, 4> h) {
    const bool flip = h[3].sign() < 0;
    exact_homogeneous out;
    for (std::size_t k = 0; k < 4; ++k) out[k] = flip ? dyn_negate(std::move(h[k].e)) : std::move(h[k].e);
    return out;
}

/// x / w, w nonzero, rounded to double from the exact expansions. Both are first scaled by the
/// power of two that brings w's leading component into [0.5, 1), so neither overflows however high
/// the degree, and each is summed from its smallest component up: for nonoverlapping expansions
/// that sum is within an ulp or so of the exact value, and so is the quotient.
inline double expansion_quotient(const dynamic_expansion& x, const dynamic_expansion& w) {
    if (x.empty()) return 0.0;
    int e = 0;
    std::frexp(w.back(), &e);
    double xs = 0, ws = 0;
    for (double c : x) xs += std::ldexp(c, -e);
    for (double c : w) ws += std::ldexp(c, -e);
    return xs / ws;
}

/// True when every coordinate of f lies in the enclosure of X / W that the filter h gives (W > 0
/// there), and each enclosure is narrower than 2^-40 of the point's largest coordinate: f is then
/// within that distance of the exact point. This only chooses how a point is rounded for output
/// (the double formula, or the exact coordinates when f is not vouched for); no decision uses it.
inline bool vouched(const point3& f, const std::array<interval, 4>& h) noexcept {
    double lo[3], hi[3], m = 0;
    for (std::size_t k = 0; k < 3; ++k) {
        const double a = h[k].lo / h[3].lo, b = h[k].lo / h[3].hi, c = h[k].hi / h[3].lo, d = h[k].hi / h[3].hi;
        lo[k] = std::nextafter(std::min(a, b), -interval_inf);
        hi[k] = std::nextafter(std::max(c, d), interval_inf);
        m = std::max({m, std::fabs(lo[k]), std::fabs(hi[k])});
    }
    if (!std::isfinite(m)) return false;
    for (std::size_t k = 0; k < 3; ++k)
        if (!(lo[k] <= f[k] && f[k] <= hi[k] && hi[k] - lo[k] <= std::ldexp(m, -40))) return false;
    return true;
}

/// True when the filter may be used: W certainly positive.
inline bool filter_usable(const exact_point& p) noexcept { return p.filter()[3].lo > 0; }

template <class N>
std::array<N, 4> as_numbers(const exact_point& p) {
    if constexpr (std::is_same_v<N, interval>) {
        return p.filter();
    } else {
        exact_homogeneous h = p.exact();
        return {N(std::move(h[0])), N(std::move(h[1])), N(std::move(h[2])), N(std::move(h[3]))};
    }
}

template <class N>
N orient2d_homogeneous(int drop, const exact_point& a, const exact_point& b, const exact_point& c) {
    const std::size_t u = std::size_t((drop + 1) % 3), v = std::size_t((drop + 2) % 3);
    const std::array<N, 4> A = as_numbers<N>(a), B = as_numbers<N>(b), C = as_numbers<N>(c);
    return A[u] * (B[v] * C[3] - B[3] * C[v]) - A[v] * (B[u] * C[3] - B[3] * C[u]) + A[3] * (B[u] * C[v] - B[v] * C[u]);
}

template <class N>
N orient3d_homogeneous(const point3& a, const point3& b, const point3& c, const exact_point& d) {
    const nvec<N> n = ncross(nsub<N>(b, a), nsub<N>(c, a));
    const std::array<N, 4> D = as_numbers<N>(d);
    const nvec<N> pa = npoint<N>(a);
    return ndot(n, nvec<N>{D[0] - pa[0] * D[3], D[1] - pa[1] * D[3], D[2] - pa[2] * D[3]});
}

template <class N>
N compare_homogeneous(std::size_t axis, const exact_point& a, const exact_point& b) {
    const std::array<N, 4> A = as_numbers<N>(a), B = as_numbers<N>(b);
    return A[axis] * B[3] - B[axis] * A[3];
}

/// Shortcuts by definition, before any arithmetic: the degeneracies an arrangement creates on
/// purpose (a crossing point on the edge that made it, the same crossing found twice) are
/// recognised from the points that define them.
inline bool same_coordinates(const point3& a, const point3& b) noexcept {
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

/// a, b and c all lie on the line of one of them that is a line-plane point, by definition: each
/// is that point, an end of its defining segment, or a line-plane point on the same line.
inline bool on_one_defining_line(const exact_point& a, const exact_point& b, const exact_point& c) noexcept {
    using K = exact_point::kind;
    const exact_point* pts[3] = {&a, &b, &c};
    for (const exact_point* x : pts) {
        if (x->what() != K::line_plane) continue;
        const line_plane_point& l = x->line_plane();
        bool all = true;
        for (const exact_point* y : pts) {
            if (y == x) continue;
            if (y->what() == K::explicit_point)
                all = same_coordinates(y->explicit_coordinates(), l.p) ||
                      same_coordinates(y->explicit_coordinates(), l.q);
            else if (y->what() == K::line_plane)
                all = (same_coordinates(y->line_plane().p, l.p) && same_coordinates(y->line_plane().q, l.q)) ||
                      (same_coordinates(y->line_plane().p, l.q) && same_coordinates(y->line_plane().q, l.p));
            else
                all = false;
            if (!all) break;
        }
        if (all) return true;
    }
    return false;
}

/// a and b are line-plane points with the same line (either way round) and the same plane (its
/// three points in any order): the same point by definition.
inline bool same_definition(const exact_point& a, const exact_point& b) noexcept {
    using K = exact_point::kind;
    if (a.what() != K::line_plane || b.what() != K::line_plane) return false;
    const line_plane_point &x = a.line_plane(), &y = b.line_plane();
    const bool line = (same_coordinates(x.p, y.p) && same_coordinates(x.q, y.q)) ||
                      (same_coordinates(x.p, y.q) && same_coordinates(x.q, y.p));
    if (!line) return false;
    auto in_plane = [&](const point3& v) {
        return same_coordinates(v, y.r) || same_coordinates(v, y.s) || same_coordinates(v, y.t);
    };
    return in_plane(x.r) && in_plane(x.s) && in_plane(x.t) && !same_coordinates(x.r, x.s) &&
           !same_coordinates(x.s, x.t) && !same_coordinates(x.r, x.t);
}

}  // namespace detail

inline std::array<detail::interval, 4> exact_point::lpi_filter(const line_plane_point& l) {
    std::array<detail::interval, 4> h = detail::lpi_coordinates<detail::interval>(l);
    detail::normalise(h);
    return h;
}

inline std::array<detail::interval, 4> exact_point::tpi_filter(const three_plane_point& t) {
    std::array<detail::interval, 4> h = detail::tpi_coordinates<detail::interval>(t);
    detail::normalise(h);
    return h;
}

inline detail::exact_homogeneous exact_point::exact() const {
    switch (kind_) {
        case kind::line_plane: return detail::normalise(detail::lpi_coordinates<detail::exact_number>(l_));
        case kind::three_planes: return detail::normalise(detail::tpi_coordinates<detail::exact_number>(t_));
        case kind::explicit_point: break;
    }
    return {detail::dynamic_expansion(p_.x != 0 ? 1 : 0, p_.x), detail::dynamic_expansion(p_.y != 0 ? 1 : 0, p_.y),
            detail::dynamic_expansion(p_.z != 0 ? 1 : 0, p_.z), detail::dynamic_expansion(1, 1.0)};
}

inline point3 exact_point::approximate() const {
    if (kind_ == kind::explicit_point) return p_;
    if (filter_[3].lo > 0) {  // W certainly positive: the double formula, kept where the filter vouches for it
        point3 f{};
        if (kind_ == kind::line_plane) {
            f = predicates::approximate(l_);
        } else {
            const std::array<double, 4> h = detail::tpi_coordinates<double>(t_);
            f = {h[0] / h[3], h[1] / h[3], h[2] / h[3]};
        }
        if (detail::vouched(f, filter_)) return f;
    }
    const detail::exact_homogeneous h = exact();
    if (h[3].empty()) {  // a definition outside its precondition has no point: NaN says so
        const double nan = std::numeric_limits<double>::quiet_NaN();
        return {nan, nan, nan};
    }
    return {detail::expansion_quotient(h[0], h[3]), detail::expansion_quotient(h[1], h[3]),
            detail::expansion_quotient(h[2], h[3])};
}

inline int orient2d(int drop, const exact_point& a, const exact_point& b, const exact_point& c) {
    using K = exact_point::kind;
    if (a.what() == K::explicit_point && b.what() == K::explicit_point && c.what() == K::explicit_point)
        return detail::orient2d_drop(drop, a.explicit_coordinates(), b.explicit_coordinates(),
                                     c.explicit_coordinates());
    if (detail::on_one_defining_line(a, b, c)) return 0;
    if (detail::filter_usable(a) && detail::filter_usable(b) && detail::filter_usable(c)) {
        const int s = detail::orient2d_homogeneous<detail::interval>(drop, a, b, c).sign();
        if (s != 2) return s;
    }
    return detail::orient2d_homogeneous<detail::exact_number>(drop, a, b, c).sign();
}

inline int orient3d(const point3& a, const point3& b, const point3& c, const exact_point& d) {
    if (d.what() == exact_point::kind::explicit_point) return orient3d(a, b, c, d.explicit_coordinates());
    if (detail::filter_usable(d)) {
        const int s = detail::orient3d_homogeneous<detail::interval>(a, b, c, d).sign();
        if (s != 2) return s;
    }
    return detail::orient3d_homogeneous<detail::exact_number>(a, b, c, d).sign();
}

inline int compare_coordinate(int axis, const exact_point& a, const exact_point& b) {
    using K = exact_point::kind;
    const std::size_t k = std::size_t(axis);
    if (a.what() == K::explicit_point && b.what() == K::explicit_point) {
        const double x = a.explicit_coordinates()[k], y = b.explicit_coordinates()[k];
        return (x > y) - (x < y);
    }
    if (detail::filter_usable(a) && detail::filter_usable(b)) {
        const int s = detail::compare_homogeneous<detail::interval>(k, a, b).sign();
        if (s != 2) return s;
    }
    return detail::compare_homogeneous<detail::exact_number>(k, a, b).sign();
}

inline int compare_xyz(const exact_point& a, const exact_point& b) {
    if (detail::same_definition(a, b)) return 0;
    for (int k = 0; k < 3; ++k)
        if (const int s = compare_coordinate(k, a, b); s != 0) return s;
    return 0;
}

}  // namespace hmira::predicates
