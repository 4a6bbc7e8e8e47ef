// hmira/predicates/exact_point.hpp
// Predicates on points that are given (explicit) or constructed (implicit: a line meeting a plane,
// three planes meeting), mixed freely: orientation in a coordinate plane, orientation against a
// plane of given points, coordinate comparison and exact equality. Built for the per-triangle
// triangulations of mesh arrangements, where every intersection point must be compared exactly.
//
// Every point is held as homogeneous coordinates (X, Y, Z, W), each a polynomial in the input
// doubles: the point is (X / W, Y / W, Z / W), W > 0 after normalisation. A predicate is the sign
// of a determinant in those coordinates. It is evaluated first in interval arithmetic (each
// operation rounded to nearest, then widened outward by one ulp with std::nextafter, so the
// interval always holds the exact value); where the interval excludes zero, or is exactly {0},
// its sign is the answer. Otherwise the same determinant is evaluated in exact expansion
// arithmetic. No tolerance enters a decision. The intervals are computed once per point, at
// construction; the exact coordinates are computed on demand and not cached, since only
// degenerate configurations reach them.
//
// Range: the polynomials are of high degree (up to 11 for line-plane points, 20 for three-plane
// points), so the exact stage holds only while no product overflows and no expansion component
// underflows. in_implicit_range() is the range for line-plane points; three-plane points are exact
// for coordinates that are small integers times one power of two, as arrangements of meshes on a
// fixed-precision grid have. Callers check their input against it.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "implicit_point.hpp"

namespace hmira::predicates {

/// The exponents of v = m 2^low with m odd, and |v| < 2^high: the finest and the coarsest bit
/// of a finite nonzero double.
inline void bit_span(double v, int& low, int& high) noexcept {
    const double f = std::frexp(v < 0 ? -v : v, &high);  // |v| = f 2^high, f in [0.5, 1)
    auto m = static_cast<std::uint64_t>(std::ldexp(f, 53));
    low = high - 53;
    while ((m & 1u) == 0) m >>= 1, ++low;
}

/// Coordinates accepted by the line-plane predicates: 0, or a finite value below 2^85 in magnitude
/// whose lowest set bit is at least 2^-92. Products of up to 11 such numbers (the degree of the
/// predicates on line-plane points) neither overflow nor lose bits below the smallest subnormal,
/// so the expansion arithmetic stays exact. Every double in [2^-39, 2^85] qualifies, as do
/// coarser values below that, such as 2^-52. A caller whose input spans at most 177 bits (from
/// its coarsest to its finest bit) can scale it by a power of two into this range, exactly.
inline bool in_implicit_range(double v) noexcept {
    if (v == 0.0) return true;
    if (!std::isfinite(v)) return false;
    int low = 0, high = 0;
    bit_span(v, low, high);
    return high <= 85 && low >= -92;
}

/// The point where three planes meet, each plane given by three points.
/// \pre the planes' normals are linearly independent and no plane's points are collinear.
struct three_plane_point {
    std::array<point3, 3> a;  ///< three points of the first plane
    std::array<point3, 3> b;  ///< three points of the second plane
    std::array<point3, 3> c;  ///< three points of the third plane
};

/// An explicit or implicit point, with a precomputed floating-point enclosure for the filter.
class exact_point;

/// Orientation of the projections of a, b, c onto the coordinate plane that drops axis `drop`
/// (the other two axes in cyclic order, (drop + 1) % 3 then (drop + 2) % 3): +1 counter-clockwise,
/// -1 clockwise, 0 collinear. Exact. Complexity O(1).
inline int orient2d(int drop, const exact_point& a, const exact_point& b, const exact_point& c);

/// Orientation of d against the plane through the explicit points a, b, c, with orient3d's
/// convention: +1 if d is on the side (b - a) x (c - a) points to, -1 opposite, 0 on the plane.
inline int orient3d(const point3& a, const point3& b, const point3& c, const exact_point& d);

/// sign(a[axis] - b[axis]), exactly.
inline int compare_coordinate(int axis, const exact_point& a, const exact_point& b);

/// Lexicographic order of (x, y, z): -1, 0 or +1. Exact; 0 means the points coincide.
inline int compare_xyz(const exact_point& a, const exact_point& b);

/// True when a and b are the same point, exactly.
inline bool same_point(const exact_point& a, const exact_point& b) { return compare_xyz(a, b) == 0; }

namespace detail {

/// A closed interval holding an exact real value; an empty or NaN interval never decides.
struct interval {
    double lo = 0, hi = 0;

    interval() = default;
    /// The exact value v.
    interval(double v) noexcept : lo(v), hi(v) {}
    interval(double l, double h) noexcept : lo(l), hi(h) {}
    static interval exact(double v) noexcept { return {v, v}; }
    /// +1 / -1 when the whole interval is on one side of zero, 0 when it is exactly {0}, 2 when
    /// undecided (it straddles zero, or a bound overflowed to infinity or NaN).
    int sign() const noexcept {
        if (lo > 0) return 1;
        if (hi < 0) return -1;
        if (lo == 0 && hi == 0) return 0;
        return 2;
    }
};

/// Exact homogeneous coordinates: X, Y, Z, W as expansions, W > 0.
using exact_homogeneous = std::array<dynamic_expansion, 4>;

}  // namespace detail

/// A point that is either given (explicit) or constructed (a line-plane or three-plane
/// intersection), kept as its definition: predicates on it are exact, filtered by interval
/// arithmetic first, and its coordinates are rounded only when approximate() is asked.
class exact_point {
public:
    /// What defines the point.
    enum class kind : std::uint8_t { explicit_point, line_plane, three_planes };

    /// An explicit point. Every coordinate must satisfy in_predicate_range().
    exact_point(const point3& p = {}) : kind_(kind::explicit_point), p_(p) {
        filter_ = {detail::interval::exact(p.x), detail::interval::exact(p.y), detail::interval::exact(p.z),
                   detail::interval::exact(1.0)};
    }
    /// A line-plane intersection (see line_plane_point for its precondition).
    exact_point(const line_plane_point& l) : kind_(kind::line_plane), l_(l) { filter_ = lpi_filter(l); }
    /// A three-plane intersection (see three_plane_point for its precondition).
    exact_point(const three_plane_point& t) : kind_(kind::three_planes), t_(t) { filter_ = tpi_filter(t); }

    /// What defines the point.
    kind what() const noexcept { return kind_; }
    /// The explicit coordinates. \pre what() == kind::explicit_point.
    const point3& explicit_coordinates() const noexcept { return p_; }
    /// The definition. \pre what() == kind::line_plane.
    const line_plane_point& line_plane() const noexcept { return l_; }
    /// The point rounded to double, for output only. Explicit points are returned as given. A
    /// constructed one is evaluated in floating point where the filter's intervals vouch for the
    /// result (inside their enclosure, which is narrower than 2^-40 of the point's size), and
    /// rounded from its exact homogeneous coordinates otherwise: it is finite and accurate however
    /// nearly parallel the line and plane, or the three planes, that define it. NaN only when the
    /// definition breaks its precondition (W exactly zero).
    point3 approximate() const;
    /// Interval enclosures of X, Y, Z, W (W may straddle zero: then every predicate goes exact).
    const std::array<detail::interval, 4>& filter() const noexcept { return filter_; }
    /// Exact homogeneous coordinates with W > 0.
    detail::exact_homogeneous exact() const;

private:
    static std::array<detail::interval, 4> lpi_filter(const line_plane_point& l);
    static std::array<detail::interval, 4> tpi_filter(const three_plane_point& t);

    kind kind_;
    union {  // the definition, by kind_ (arrangements hold one of these per input vertex)
        point3 p_;
        line_plane_point l_;
        three_plane_point t_;
    };
    std::array<detail::interval, 4> filter_{};
};

}  // namespace hmira::predicates

#include "detail/exact_point_impl.hpp"
