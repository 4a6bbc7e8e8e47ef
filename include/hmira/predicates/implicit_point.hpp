// hmira/predicates/implicit_point.hpp
// Points that are not given but constructed, kept exact by never constructing them: an implicit
// point is stored as the input that defines it, and a predicate on it is the sign of a polynomial
// in that input, evaluated in exact expansion arithmetic (indirect predicates: Attene 2020,
// "Indirect predicates for geometric constructions"; Cherchi et al. 2022).
//
// Design choice: implicit points with indirect predicates, not rational coordinates (GMP). The
// core stays on the standard library; the sizes of the polynomials are bounded statically by
// the kind of point, so no allocation beyond a few vectors. The implicit point here is the
// intersection of a segment's line with a plane through three points (LPI). Its coordinates are
// rounded to double only where a caller asks for them (approximate()), never inside a predicate.
// The predicates take the exact path on every call; a floating-point filter in front of it
// (Attene's semi-static bounds) is not there yet.
#pragma once

#include <cstddef>
#include <vector>

#include "detail/expansion.hpp"
#include "intersect3d.hpp"

namespace hmira::predicates {

/// The point where the line through p and q meets the plane through r, s, t.
/// \pre the line is not parallel to the plane (orient3d(r, s, t, p) != orient3d(r, s, t, q), or
///   more precisely (s - r) x (t - r) . (q - p) != 0) and r, s, t are not collinear.
struct line_plane_point {
    point3 p;  ///< a point of the line
    point3 q;  ///< another point of the line
    point3 r;  ///< a point of the plane
    point3 s;  ///< a second point of the plane
    point3 t;  ///< a third point of the plane
};

/// orient3d(x, b, c, d) for the implicit point x, exactly: +1 if d is on the side of the plane
/// through x, b, c that (b - x) x (c - x) points to, -1 on the other, 0 if coplanar.
/// Complexity: O(1), a fixed polynomial of degree 6 in the input evaluated exactly.
/// Preconditions: those of line_plane_point; every coordinate in in_predicate_range().
inline int orient3d(const line_plane_point& x, const point3& b, const point3& c, const point3& d);

/// The implicit point evaluated in floating point (no error bound: nearly parallel input loses
/// digits): for output only, never for a decision.
inline point3 approximate(const line_plane_point& x) noexcept;

namespace detail {

/// An expansion of any length, for the indirect predicates (their sizes are bounded but large).
using dynamic_expansion = std::vector<double>;

inline dynamic_expansion dyn_diff(double a, double b) {
    const expansion<2> e = exact_diff(a, b);
    return dynamic_expansion(e.c, e.c + e.n);
}
inline dynamic_expansion dyn_sum(const dynamic_expansion& a, const dynamic_expansion& b) {
    dynamic_expansion h(a.size() + b.size());
    h.resize(sum_components(a.data(), a.size(), b.data(), b.size(), h.data()));
    return h;
}
inline dynamic_expansion dyn_negate(dynamic_expansion a) {
    for (double& x : a) x = -x;
    return a;
}
inline dynamic_expansion dyn_product(const dynamic_expansion& a, const dynamic_expansion& b) {
    dynamic_expansion h, part(2 * a.size());
    for (double x : b) {
        part.resize(2 * a.size());
        part.resize(scale_components(a.data(), a.size(), x, part.data()));
        h = dyn_sum(h, part);
    }
    return h;
}
inline int dyn_sign(const dynamic_expansion& e) noexcept { return e.empty() ? 0 : (e.back() > 0) - (e.back() < 0); }

using dyn_vec = std::array<dynamic_expansion, 3>;

inline dyn_vec dyn_vdiff(const point3& a, const point3& b) {
    return {dyn_diff(a.x, b.x), dyn_diff(a.y, b.y), dyn_diff(a.z, b.z)};
}
inline dyn_vec dyn_cross(const dyn_vec& u, const dyn_vec& v) {
    auto term = [](const dynamic_expansion& a, const dynamic_expansion& b, const dynamic_expansion& c,
                   const dynamic_expansion& d) { return dyn_sum(dyn_product(a, b), dyn_negate(dyn_product(c, d))); };
    return {term(u[1], v[2], u[2], v[1]), term(u[2], v[0], u[0], v[2]), term(u[0], v[1], u[1], v[0])};
}
inline dynamic_expansion dyn_dot(const dyn_vec& u, const dyn_vec& v) {
    return dyn_sum(dyn_sum(dyn_product(u[0], v[0]), dyn_product(u[1], v[1])), dyn_product(u[2], v[2]));
}

}  // namespace detail

inline int orient3d(const line_plane_point& x, const point3& b, const point3& c, const point3& d) {
    namespace dt = detail;
    // x = p + (ln / ld) (q - p), ln = n.(r - p), ld = n.(q - p), n = (s - r) x (t - r).
    const dt::dyn_vec n = dt::dyn_cross(dt::dyn_vdiff(x.s, x.r), dt::dyn_vdiff(x.t, x.r));
    const dt::dyn_vec qp = dt::dyn_vdiff(x.q, x.p);
    const dt::dynamic_expansion ln = dt::dyn_dot(n, dt::dyn_vdiff(x.r, x.p));
    const dt::dynamic_expansion ld = dt::dyn_dot(n, qp);
    // ld (x - d) = ld (p - d) + ln (q - p); orient3d(x, b, c, d) = -sign((x - d) . (b - d) x (c - d)).
    const dt::dyn_vec pd = dt::dyn_vdiff(x.p, d);
    dt::dyn_vec xd;
    for (std::size_t k = 0; k < 3; ++k) xd[k] = dt::dyn_sum(dt::dyn_product(ld, pd[k]), dt::dyn_product(ln, qp[k]));
    const dt::dynamic_expansion det = dt::dyn_dot(xd, dt::dyn_cross(dt::dyn_vdiff(b, d), dt::dyn_vdiff(c, d)));
    return -dt::dyn_sign(det) * dt::dyn_sign(ld);
}

inline point3 approximate(const line_plane_point& x) noexcept {
    const point3 n = {(x.s.y - x.r.y) * (x.t.z - x.r.z) - (x.s.z - x.r.z) * (x.t.y - x.r.y),
                      (x.s.z - x.r.z) * (x.t.x - x.r.x) - (x.s.x - x.r.x) * (x.t.z - x.r.z),
                      (x.s.x - x.r.x) * (x.t.y - x.r.y) - (x.s.y - x.r.y) * (x.t.x - x.r.x)};
    const point3 qp = {x.q.x - x.p.x, x.q.y - x.p.y, x.q.z - x.p.z};
    const double ln = n.x * (x.r.x - x.p.x) + n.y * (x.r.y - x.p.y) + n.z * (x.r.z - x.p.z);
    const double ld = n.x * qp.x + n.y * qp.y + n.z * qp.z;
    const double l = ln / ld;
    return {x.p.x + l * qp.x, x.p.y + l * qp.y, x.p.z + l * qp.z};
}

}  // namespace hmira::predicates
