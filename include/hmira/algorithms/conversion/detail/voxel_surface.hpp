// hmira/algorithms/conversion/detail/voxel_surface.hpp
// The surface voxels of one triangle for voxelize(): every voxel of a window of the grid whose
// closed box the triangle touches, found by walking the columns of voxels along the axis the
// triangle faces most, row by row, with the separating-axis tests of triangle_box.hpp.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "../../../core/vec3.hpp"
#include "triangle_box.hpp"

namespace hmira::detail::vox {

// Triangle corners in voxel units: voxel (i, j, k)'s centre is (i, j, k), its box +-1/2.
struct tri {
    vec3<double> p[3];
    bool degenerate;
};

// floor without a libm call (the x86-64 baseline has no roundsd); the clamp to +-2^40 keeps
// the conversion defined for far-away geometry.
inline long long fast_floor(double x) {
    // (ternaries rather than std::clamp, which returns a reference: GCC makes maxsd/minsd of them)
    x = x < -0x1p40 ? -0x1p40 : x;
    x = x > 0x1p40 ? 0x1p40 : x;
    const auto i = static_cast<long long>(x);
    return i - (double(i) > x);
}

// The integer range [r0, r1] of [from, to] within [lo, hi], false if empty. Rounds the same
// way wherever the window lies, so that a window gets the whole grid's bits.
inline bool window_range(long long lo, long long hi, double from, double to, long long& r0, long long& r1) {
    r0 = std::max<long long>(lo, -fast_floor(-from));
    r1 = std::min<long long>(hi, fast_floor(to));
    return r0 <= r1;
}

/// The voxels of one column along axis D of a window. D = 0: the column lies in one row,
/// whose words start at `words`; D = 1, 2: it crosses rows or layers at one bit of x, its voxel
/// w being `bit` of word words[(w - lo) * stride].
template <std::size_t D>
struct column_sink {
    std::uint64_t* words;
    std::uint64_t bit;
    std::size_t stride;
    long long lo;  // the window's first voxel along D (whole-grid coordinates)
    /// Sets voxel w of the column when `on`, without a branch on it.
    void operator()(long long w, bool on) const noexcept {
        if constexpr (D == 0) {
            const std::size_t x = std::size_t(w - lo);
            words[x >> 6] |= std::uint64_t(on) << (x & 63);
        } else {
            words[std::size_t(w - lo) * stride] |= bit & (std::uint64_t(0) - std::uint64_t(on));
        }
    }
};

/// Where surface voxels go: the words of a window of the grid whose voxel (0, 0, 0) is voxel
/// `lo` of the whole grid. Passed by value, so that its fields stay in registers while the
/// walk stores words (which could alias them through a reference).
struct bit_sink {
    std::uint64_t* words;
    std::size_t row_words, layer_words;
    long long lo[3];
    /// Sets voxel (i, j, k) (whole-grid coordinates) when `on`, without a branch on it.
    void operator()(long long i, long long j, long long k, bool on) const noexcept {
        const std::size_t x = std::size_t(i - lo[0]);
        words[std::size_t(k - lo[2]) * layer_words + std::size_t(j - lo[1]) * row_words + (x >> 6)] |= std::uint64_t(on)
                                                                                                       << (x & 63);
    }
    /// The words of the plane u = iu of surface_columns<D>()'s walk (u is z for D = 0, 1 and
    /// y for D = 2), to give column() once per row.
    template <std::size_t D>
    std::uint64_t* plane(long long iu) const noexcept {
        if constexpr (D == 2)
            return words + std::size_t(iu - lo[1]) * row_words;
        else
            return words + std::size_t(iu - lo[2]) * layer_words;
    }
    /// Column iv of `plane` (v is y for D = 0, else x).
    template <std::size_t D>
    column_sink<D> column(std::uint64_t* plane_words, long long iv) const noexcept {
        if constexpr (D == 0) {
            return {plane_words + std::size_t(iv - lo[1]) * row_words, 0, 0, lo[0]};
        } else {
            const std::size_t x = std::size_t(iv - lo[0]);
            return {plane_words + (x >> 6), std::uint64_t(1) << (x & 63), D == 1 ? row_words : layer_words, lo[D]};
        }
    }
};

/// One triangle's walk over the columns along D (its normal's dominant axis) of the box
/// [r0, r1] (whole-grid voxel coordinates, already cut to the triangle's bounding box).
/// Columns are walked along v within a row: v is x where it can be (consecutive voxels share
/// a word), else y (the next row's word, 64 bytes on); never z (a layer, a page, away).
///
/// Reach. The voxels of a column that can touch the triangle are those within reach of its
/// plane: the height over the column widened by far more than the rounding of the height and
/// slack. A voxel that touches the plane exactly (at a corner or edge, common with corners on
/// the half-voxel lattice) must stay a candidate, and the exact tests decide. The height is
/// within about the triangle's coordinates (|n[u]|, |n[v]| <= |n[D]|), which bounds the
/// rounding. For a sliver the rounded normal is known only to about eps |edge 0| |edge 1|,
/// which tilts the plane about corner 0 and moves the height over the triangle by up to that
/// over |n[D]| times the triangle's extent. Where that is large (a triangle flat to rounding,
/// nearly a segment) the shadow is thinner than a voxel, so every column is an edge column,
/// and edge_column() cuts the long reach to what the edge axes allow: the cost stays that of
/// the segment, not of its bounding box.
///
/// Rounding. The voxel tests use triangle_box_tester's sums, with the terms of u and v
/// computed once per column: an axis D' x e (D' != D) is 0 along D', so its projection is the
/// rounded sum of two terms in either order; the normal's is ((x + y) + z) in the tester's
/// order. Same roundings, same bits. Each projection is within a few ulps of |axis|_1 x (the
/// triangle's extent + 2) of the exact projection on the exact axis (of the exact edge
/// vectors), at any voxel centre within a voxel of the triangle's bounding box; the normal, a
/// product of two edges, within a few ulps of |edge 0|_1 |edge 1|_1 x that. Every interval is
/// widened by 2^-44 of that bound (some 25 times the rounding), so that a voxel the triangle
/// touches, exactly at a corner or an edge included, is never lost to rounding; the price is
/// that a voxel missing the triangle by less than the widening (about 1e-13 of the extent for
/// a well-shaped triangle, more for a sliver) may be set too.
template <std::size_t D>
struct column_walk {
    static constexpr std::size_t u = D == 2 ? 1 : 2, v = D == 0 ? 1 : 0;
    /// `outside` when a column's square is outside the shadow, else a mask of the edges it
    /// lies across (bit e: not inside edge e's side by the margin); 0 inside the shadow.
    static constexpr int outside = 8;

    const vec3<double>* p;
    vec3<double> n;
    const long long* r0;
    const long long* r1;
    bit_sink set;
    double c, reach_slack;
    vec3<double> o, normal;  // the tester's origin and plane normal
    double plane_lo, plane_hi;
    double edge_d[6], edge_t[6], edge_lo[6], edge_hi[6];  // j = 2 e + (a == v): axis a x edge e
    double inv_nd, nv_scaled, reach_half;
    // The separating axes D x edge (the shadow's edge normals in the (u, v) plane), their
    // bounds widened for rounding (lo2, hi2) and the inner band of columns surely inside.
    double axis_u[3], axis_v[3], inv_axis_v[3], lo2[3], hi2[3], inner_lo[3], inner_hi[3], bound_size[3];
    double column_span;  // a bound of |iv - p0[v]| over the window's columns, and of |p0[v]|
    bool clipped;        // the window cuts the triangle along D

    /// What one row (u = iu) of the walk shares between its columns.
    struct row {
        double fu;
        std::uint64_t* plane_words;
        double near_lo, near_hi, sure_lo, sure_hi;
        double base[3], in_lo[3], in_hi[3];
        long long iv0, iv1;
        double cu, cu_scaled, cu_rel, tu;
    };

    column_walk(const tri& tr, const vec3<double>& normal_, const vec3<double>& bl, const vec3<double>& bh,
                const long long (&r0_)[3], const long long (&r1_)[3], const bit_sink set_)
        : p(tr.p), n(normal_), r0(r0_), r1(r1_), set(set_) {
        c = dot(n, p[0]);
        const double slack = 0.5 * (std::abs(n[u]) + std::abs(n[v])) / std::abs(n[D]);
        double edge_size[3];  // |edge e|_1, edge e from corner e to corner e + 1
        for (int e = 0; e < 3; ++e) {
            const vec3<double> ed = p[(e + 1) % 3] - p[e];
            edge_size[e] = std::abs(ed.x) + std::abs(ed.y) + std::abs(ed.z);
        }
        const double extent = 2 + std::max({bh[0] - bl[0], bh[1] - bl[1], bh[2] - bl[2]});
        const double plane_doubt = 0x1p-44 * edge_size[0] * edge_size[1] * extent / std::abs(n[D]);
        reach_slack = slack +
                      0x1p-30 * (1 + slack +
                                 std::max({std::abs(bl[0]), std::abs(bl[1]), std::abs(bl[2]), std::abs(bh[0]),
                                           std::abs(bh[1]), std::abs(bh[2])})) +
                      plane_doubt;
        const detail::triangle_box_tester tester(p[0], p[1], p[2], 0.5);
        o = tester.origin();
        normal = tester.axis(0);
        auto widening = [&](double axis_size) { return 0x1p-44 * axis_size * extent; };
        const double plane_widening = widening(edge_size[0] * edge_size[1]);
        plane_lo = tester.lo(0) - plane_widening;
        plane_hi = tester.hi(0) + plane_widening;
        for (int e = 0; e < 3; ++e)
            for (int k = 0; k < 2; ++k) {
                const int q = 1 + 3 * e + int(k == 0 ? u : v);
                edge_d[2 * e + k] = tester.axis(q)[D];
                edge_t[2 * e + k] = tester.axis(q)[k == 0 ? v : u];  // the other term: along v for a = u
                edge_lo[2 * e + k] = tester.lo(q) - widening(edge_size[e]);
                edge_hi[2 * e + k] = tester.hi(q) + widening(edge_size[e]);
            }
        inv_nd = 1 / n[D];
        nv_scaled = n[v] * inv_nd;
        reach_half = reach_slack + 0.5;
        shadow_axes(edge_size, extent);
        column_span = 1 + std::abs(double(r0[v])) + std::abs(double(r1[v])) + 2 * std::abs(p[0][v]);
        clipped = r0[D] > -fast_floor(-(bl[D] - 0.5)) || r1[D] < fast_floor(bh[D] + 0.5);
    }

    /// The axes D x edge give the same answer for every voxel of a column: a column whose
    /// square is outside the shadow is skipped; one whose square lies inside it needs only the
    /// plane test, since every point of the plane over the square is then on the triangle.
    void shadow_axes(const double (&edge_size)[3], double extent) {
        for (int e = 0; e < 3; ++e) {
            const vec3<double> ed = p[(e + 1) % 3] - p[e];
            axis_u[e] = -ed[v];
            axis_v[e] = ed[u];
            inv_axis_v[e] = axis_v[e] != 0 ? 1 / axis_v[e] : 0;
            // Relative to corner 0, as the tester's axes (a column side on an edge's line ties exactly).
            const double pa = 0, pb = axis_u[e] * (p[1][u] - p[0][u]) + axis_v[e] * (p[1][v] - p[0][v]),
                         pc = axis_u[e] * (p[2][u] - p[0][u]) + axis_v[e] * (p[2][v] - p[0][v]);
            const double r = 0.5 * (std::abs(axis_u[e]) + std::abs(axis_v[e]));
            lo2[e] = std::min({pa, pb, pc}) - r;
            hi2[e] = std::max({pa, pb, pc}) + r;
            const double width = std::abs(axis_u[e]) + std::abs(axis_v[e]);
            const double margin = 1e-9 * (std::abs(lo2[e]) + std::abs(hi2[e]) + width);
            inner_lo[e] = lo2[e] + width + margin;
            inner_hi[e] = hi2[e] - width - margin;
            // Widened after the inner bounds are taken, which stay tight.
            lo2[e] -= 0x1p-44 * edge_size[e] * extent;
            hi2[e] += 0x1p-44 * edge_size[e] * extent;
            // For the doubt of the rows' estimates: the bounds' size in columns.
            bound_size[e] = (std::abs(lo2[e]) + std::abs(hi2[e]) + std::abs(inner_lo[e]) + std::abs(inner_hi[e])) *
                            std::abs(inv_axis_v[e]);
        }
    }

    /// Row iu's columns that can meet the shadow, [near_lo, near_hi], with the bounds of the
    /// columns surely inside each edge's side; false when none can. Each edge's projection of
    /// column iv, q_e(iv) = base_e + axis_v_e (iv - p0[v]) as kind() computes it, is monotone
    /// in iv (so is its rounding): the columns not outside the shadow by edge e's axis form an
    /// interval, and those inside e's side by the margin another. Their ends follow from the
    /// line's equation, each known to within `doubt` columns (a bound of the rounding of this
    /// estimate and of kind()'s q, with a factor of some 1000 to spare). A column farther than
    /// that from every end is classified by the ends alone; one nearer (rare) gets kind().
    bool row_bounds(long long iu, row& r) const {
        constexpr double infinity = std::numeric_limits<double>::infinity();
        r.fu = double(iu);
        r.near_lo = double(r0[v]);
        r.near_hi = double(r1[v]);
        r.sure_lo = r.near_lo;
        r.sure_hi = r.near_hi;
        bool row_outside = false;
        for (int e = 0; e < 3; ++e) {
            r.base[e] = axis_u[e] * (r.fu - p[0][u]);
            if (axis_v[e] == 0) {  // q_e is base_e along the whole row
                row_outside |= (r.base[e] < lo2[e]) | (r.base[e] > hi2[e]);
                const bool inside = (r.base[e] >= inner_lo[e]) & (r.base[e] <= inner_hi[e]);
                r.in_lo[e] = inside ? -infinity : infinity;
                r.in_hi[e] = inside ? infinity : -infinity;
                continue;
            }
            // Where q_e reaches each bound; q_e falls with iv where axis_v_e < 0. (The inner
            // band may be empty, its "lower" bound above the upper: so is the interval then.)
            const bool rising = axis_v[e] > 0;
            auto at = [&](double bound) { return (bound - r.base[e]) * inv_axis_v[e] + p[0][v]; };
            const double a = at(rising ? lo2[e] : hi2[e]), b = at(rising ? hi2[e] : lo2[e]);
            const double ia = at(rising ? inner_lo[e] : inner_hi[e]), ib = at(rising ? inner_hi[e] : inner_lo[e]);
            const double doubt =
                0x1p-40 * (column_span + bound_size[e] + std::abs(r.base[e]) * std::abs(inv_axis_v[e]));
            r.near_lo = std::max(r.near_lo, a - doubt);
            r.near_hi = std::min(r.near_hi, b + doubt);
            r.sure_lo = std::max(r.sure_lo, a + doubt);
            r.sure_hi = std::min(r.sure_hi, b - doubt);
            r.in_lo[e] = ia + doubt;
            r.in_hi[e] = ib - doubt;
        }
        if (row_outside || !(r.near_lo <= r.near_hi)) return false;
        r.iv0 = std::max<long long>(r0[v], -fast_floor(-r.near_lo));
        r.iv1 = std::min<long long>(r1[v], fast_floor(r.near_hi));
        r.cu = c - n[u] * r.fu;
        return true;
    }

    /// Where the window cuts the triangle along D (a slab of the grid), many columns reach no
    /// voxel of it. Column iv's plane height w is monotone in iv (so is its rounding), hence
    /// the columns whose reach ends below the window form a prefix or a suffix of the row, and
    /// those whose reach starts above it the other: cuts both off [iv0, iv1] (false if nothing
    /// is left), locating each end from the line's equation and settling it by the very
    /// comparisons that make reach() empty there.
    bool live_columns(long long& iv0, long long& iv1, double cu) const {
        auto height = [&](long long iv) { return (cu - n[v] * double(iv)) / n[D]; };
        auto below = [&](long long iv) { return (height(iv) + reach_slack) + 0.5 < double(r0[D]); };
        auto above = [&](long long iv) { return (height(iv) - reach_slack) - 0.5 > double(r1[D]); };
        if (n[v] == 0) return !below(iv0) && !above(iv0);
        // The column where the height crosses `level`, clamped to [iv0 - 1, iv1 + 1].
        auto crossing = [&](double level) {
            const double t = (cu - n[D] * level) / n[v];
            if (!(t > double(iv0 - 1))) return iv0 - 1;
            if (!(t < double(iv1 + 1))) return iv1 + 1;
            return fast_floor(t);
        };
        const double top = double(r1[D]) + 0.5 + reach_slack, bottom = double(r0[D]) - 0.5 - reach_slack;
        const bool rising = (n[v] > 0) != (n[D] > 0);  // the height grows with iv
        // First column not in the prefix where `pre` holds, and last not in the suffix where `post` holds.
        auto settle = [&](auto&& pre, auto&& post, double pre_level, double post_level) {
            long long x = std::clamp(crossing(pre_level), iv0, iv1 + 1);
            while (x > iv0 && !pre(x - 1)) --x;
            while (x <= iv1 && pre(x)) ++x;
            long long y = std::clamp(crossing(post_level), iv0 - 1, iv1);
            while (y < iv1 && !post(y + 1)) ++y;
            while (y >= iv0 && post(y)) --y;
            iv0 = x;
            iv1 = y;
        };
        if (rising)
            settle(below, above, bottom, top);
        else
            settle(above, below, top, bottom);
        return iv0 <= iv1;
    }

    /// `outside`, or the mask of the edges column iv lies across.
    int kind(const row& r, long long iv) const {
        const double fv = double(iv);
        bool out = false;
        int across = 0;
        for (int e = 0; e < 3; ++e) {
            const double q = r.base[e] + axis_v[e] * (fv - p[0][v]);
            out |= (q < lo2[e]) | (q > hi2[e]);
            across |= int((q < inner_lo[e]) | (q > inner_hi[e])) << e;
        }
        return out ? outside : across;
    }

    /// The voxels of column iv within reach of the plane, [w0, w1], cut to the window and the
    /// bounding box; false if none. The height by a multiplication: its rounding, a few ulps
    /// of the triangle's coordinates, is far within reach_slack.
    bool reach(const row& r, long long iv, long long& w0, long long& w1) const {
        const double w = r.cu_scaled - double(iv) * nv_scaled;
        w0 = std::max(reach_lo, -fast_floor(reach_half - w));
        w1 = std::min(reach_hi, fast_floor(w + reach_half));
        return w0 <= w1;
    }
    long long reach_lo = 0, reach_hi = 0;  // the reach's bounds: the window, and the box widened by half a voxel

    /// Whether the plane meets voxel (iu, iv, iw) given cw = iw - o[D], as triangle_box_tester::meets_plane().
    bool meets_plane(double tu, double tv, double cw) const {
        double t[3];
        t[u] = tu;
        t[v] = tv;
        t[D] = normal[D] * cw;
        const double q = (t[0] + t[1]) + t[2];
        return (q >= plane_lo) & (q <= plane_hi);
    }

    /// A column across the edges in `across`: the plane and the axes u x edge, v x edge of those
    /// edges, as triangle_box_tester::overlaps_off<D>(). An edge whose side holds the whole
    /// square (by the margin) cannot separate a voxel of the column that the other axes leave
    /// touching the triangle: clipping the shadow by that edge's half-plane leaves the column's
    /// part of it unchanged. (The edges are a template argument: a column is across one edge,
    /// at times two, and the tests of each set of edges compile to straight code.)
    template <int across>
    void edge_column(const row& r, long long iv) const {
        long long w0, w1;
        if (!reach(r, iv, w0, w1)) return;
        const double cv_rel = double(iv) - o[v], tv = normal[v] * cv_rel;
        constexpr int axes = 2 * std::popcount(unsigned(across));
        double shared[axes], d[axes], lo[axes], hi[axes];
        for (int j = 0, a = 0; j < 6; ++j)
            if ((across >> (j / 2)) & 1) {
                shared[a] = edge_t[j] * (j % 2 == 0 ? cv_rel : r.cu_rel);
                d[a] = edge_d[j];
                lo[a] = edge_lo[j];
                hi[a++] = edge_hi[j];
            }
        if (w1 - w0 > 3) {
            // A long reach (a plane known only roughly): each edge axis bounds cw to an
            // interval; cut the reach to it, widened by a voxel (far more than the rounding
            // of the quotient; the tests below decide).
            for (int j = 0; j < axes; ++j) {
                if (d[j] == 0) continue;
                const double first = (lo[j] - shared[j]) / d[j], second = (hi[j] - shared[j]) / d[j];
                const double from = std::min(first, second) + o[D] - 1, to = std::max(first, second) + o[D] + 1;
                if (!window_range(w0, w1, from, to, w0, w1)) return;
            }
        }
        auto touches = [&](long long iw) {
            const double cw = double(iw) - o[D];
            bool on = meets_plane(r.tu, tv, cw);
            for (int j = 0; j < axes; ++j) {
                const double q = shared[j] + d[j] * cw;
                on &= (q >= lo[j]) & (q <= hi[j]);
            }
            return on;
        };
        // Two voxels without a branch on how many, as inner_column().
        const auto put = set.column<D>(r.plane_words, iv);
        const long long second = w0 + (w1 > w0);
        put(w0, touches(w0));
        put(second, touches(second));
        for (long long iw = w0 + 2; iw <= w1; ++iw) put(iw, touches(iw));
    }

    void edge_column(const row& r, long long iv, int across) const {
        switch (across) {
            case 1: return edge_column<1>(r, iv);
            case 2: return edge_column<2>(r, iv);
            case 3: return edge_column<3>(r, iv);
            case 4: return edge_column<4>(r, iv);
            case 5: return edge_column<5>(r, iv);
            case 6: return edge_column<6>(r, iv);
            default: return edge_column<7>(r, iv);
        }
    }

    /// A column whose square lies inside the shadow: only the plane test.
    void inner_column(const row& r, long long iv) const {
        long long w0, w1;
        if (!reach(r, iv, w0, w1)) return;
        // Most columns reach one or two voxels: test two without a branch on how many
        // (the second is w0 again, set only if it passes, when the reach is one voxel).
        const long long second = w0 + (w1 > w0);
        const double tv = normal[v] * (double(iv) - o[v]);
        const auto put = set.column<D>(r.plane_words, iv);
        put(w0, meets_plane(r.tu, tv, double(w0) - o[D]));
        put(second, meets_plane(r.tu, tv, double(second) - o[D]));
        for (long long iw = w0 + 2; iw <= w1; ++iw) put(iw, meets_plane(r.tu, tv, double(iw) - o[D]));
    }

    /// A column outside the inner run: across the edges it is not surely inside, except within
    /// doubt of a shadow end [sure0, sure1], where kind() classifies it.
    void outer_column(const row& r, long long iv, long long sure0, long long sure1) const {
        if (iv < sure0 || iv > sure1) {
            const int k = kind(r, iv);
            if (k == 0)
                inner_column(r, iv);
            else if (k != outside)
                edge_column(r, iv, k);
            return;
        }
        const double fv = double(iv);
        int across = 0;
        for (int e = 0; e < 3; ++e) across |= int((fv < r.in_lo[e]) | (fv > r.in_hi[e])) << e;
        edge_column(r, iv, across);
    }

    /// The columns [iv0, iv1] of a row: the inner run [ci, ce] (columns surely inside every
    /// edge's side) by the plane test alone, the rest as edge columns.
    void walk_row(row& r) const {
        r.cu_scaled = r.cu * inv_nd;
        r.cu_rel = r.fu - o[u];
        r.tu = normal[u] * r.cu_rel;
        const long long iv0 = r.iv0, iv1 = r.iv1;
        const long long sure0 = std::max(iv0, -fast_floor(-r.sure_lo)), sure1 = std::min(iv1, fast_floor(r.sure_hi));
        long long ci = std::max({sure0, -fast_floor(-r.in_lo[0]), -fast_floor(-r.in_lo[1]), -fast_floor(-r.in_lo[2])});
        long long ce = std::min({sure1, fast_floor(r.in_hi[0]), fast_floor(r.in_hi[1]), fast_floor(r.in_hi[2])});
        if (ci > ce) ci = iv1 + 1, ce = iv1;  // no inner run: all of [iv0, iv1] is edge columns
        for (long long iv = iv0; iv < ci; ++iv) outer_column(r, iv, sure0, sure1);
        for (long long iv = ce + 1; iv <= iv1; ++iv) outer_column(r, iv, sure0, sure1);
        for (long long iv = ci; iv <= ce; ++iv) inner_column(r, iv);
    }
};

/// The surface voxels of a triangle whose normal's dominant axis is D within the box [r0, r1]
/// (whole-grid voxel coordinates, already cut to the triangle's bounding box): walks the
/// columns along D row by row (column_walk); in each column only the few voxels within the
/// plane's range over the column can touch the triangle. Calls set(i, j, k, on) for each
/// candidate voxel, with `on` true for those the triangle touches, and possibly for a few it
/// misses by less than the rounding margin (a voxel may come more than once). Flattened, so
/// that the walk's per-column functions are inlined into it rather than called.
template <std::size_t D>
[[gnu::flatten]] void surface_columns(const tri& tr, const vec3<double>& n, const vec3<double>& bl,
                                      const vec3<double>& bh, const long long (&r0)[3], const long long (&r1)[3],
                                      const bit_sink set) {
    using walk_t = column_walk<D>;
    walk_t walk(tr, n, bl, bh, r0, r1, set);
    // The reach within the window and the bounding box widened by half a voxel (the voxels
    // the box normal along D allows).
    if (!window_range(r0[D], r1[D], bl[D] - 0.5, bh[D] + 0.5, walk.reach_lo, walk.reach_hi)) return;
    typename walk_t::row r{};
    for (long long iu = r0[walk_t::u]; iu <= r1[walk_t::u]; ++iu) {
        r.plane_words = set.plane<D>(iu);
        if (!walk.row_bounds(iu, r)) continue;
        if (walk.clipped && !walk.live_columns(r.iv0, r.iv1, r.cu)) continue;
        walk.walk_row(r);
    }
}

/// Sets the voxels of the whole-grid box [wlo, whi] that triangle `tr` touches.
inline void surface_voxels(const tri& tr, const long long (&wlo)[3], const long long (&whi)[3], const bit_sink set) {
    const vec3<double>* p = tr.p;
    vec3<double> bl = p[0], bh = p[0];
    for (int c = 1; c < 3; ++c)
        for (std::size_t a = 0; a < 3; ++a) {
            bl[a] = std::min(bl[a], p[c][a]);
            bh[a] = std::max(bh[a], p[c][a]);
        }
    long long r0[3], r1[3];
    for (std::size_t a = 0; a < 3; ++a)
        if (!window_range(wlo[a], whi[a], bl[a] - 0.5, bh[a] + 0.5, r0[a], r1[a])) return;
    bool one_box = true;  // the triangle lies in one voxel's box (not merely clamped to one by the window)
    for (std::size_t a = 0; a < 3; ++a)
        one_box &= r0[a] == r1[a] && bl[a] >= double(r0[a]) - 0.5 && bh[a] <= double(r0[a]) + 0.5;
    if (one_box) {
        set(r0[0], r0[1], r0[2], true);
        return;
    }
    const vec3<double> n = cross(p[1] - p[0], p[2] - p[0]);
    const int d = std::abs(n.x) >= std::abs(n.y) ? (std::abs(n.x) >= std::abs(n.z) ? 0 : 2)
                                                 : (std::abs(n.y) >= std::abs(n.z) ? 1 : 2);
    if (d == 0)
        surface_columns<0>(tr, n, bl, bh, r0, r1, set);
    else if (d == 1)
        surface_columns<1>(tr, n, bl, bh, r0, r1, set);
    else
        surface_columns<2>(tr, n, bl, bh, r0, r1, set);
}

}  // namespace hmira::detail::vox
