// hmira/algorithms/conversion/voxelize.hpp
// Turns a mesh into voxels (thesis 2.3.2, 8.4): the voxels its surface touches (conservative:
// triangle-box tests that lose no touching voxel to rounding), and for a closed mesh also the
// voxels inside it (parity of ray crossings over bit-packed rows). Generic over the mesh;
// parallel and deterministic.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/progress.hpp"
#include "../../core/result.hpp"
#include "../../core/vec3.hpp"
#include "../../grids/bit_grid.hpp"
#include "../../grids/voxel_grid.hpp"
#include "detail/parallel.hpp"
#include "detail/triangle_box.hpp"
#include "detail/voxel_crossings.hpp"

namespace hmira {

/// Which voxels voxelize() sets. Pick `centres` to measure volume or to match VTK's
/// vtkPolyDataToImageStencil and scikit-image (the count times pitch^3 is the enclosed volume
/// up to the sampling error); `solid` (the CLI's "conservative") for collision and for a grid
/// that covers the whole shape; `surface` for a shell.
enum class voxelize_mode {
    surface,  ///< the voxels the surface touches (their closed box meets a triangle)
    solid,    ///< surface voxels plus every voxel whose centre lies inside (conservative)
    centres,  ///< exactly the voxels whose centre lies inside the closed mesh
};

/// The modes' names, as the front ends accept them: "conservative" (solid), "centres",
/// "surface" (see core/enum_names.hpp).
constexpr auto enum_names(voxelize_mode) {
    return std::array{std::pair{voxelize_mode::solid, std::string_view("conservative")},
                      std::pair{voxelize_mode::centres, std::string_view("centres")},
                      std::pair{voxelize_mode::surface, std::string_view("surface")}};
}

/// What the solid and centres modes do with a mesh that is not closed (some edge has an odd number of faces).
enum class open_mesh_fill {
    surface_only,    ///< voxelize the surface only and say so in the result (the thesis's choice)
    winding_number,  ///< fill where the generalized winding number is at least 1/2
    fail,            ///< return an error
};

/// Options of voxelize() and voxelize_into().
struct voxelize_options {
    voxelize_mode mode = voxelize_mode::solid;                ///< which voxels to set
    open_mesh_fill open_mesh = open_mesh_fill::surface_only;  ///< what the filling modes do with a mesh that is not closed
    /// Accept zero-area triangles (all corners collinear) instead of reporting them; they add
    /// no surface voxels of their own. Faces with a repeated vertex are always an error.
    bool allow_degenerate = false;
    /// Worker threads (0: all available). The output does not depend on it.
    unsigned threads = 0;
    /// Called between blocks of triangles and of rows; returning false cancels the
    /// voxelization (error errc::cancelled, "voxelize: cancelled").
    progress_function progress = {};
};

/// The voxels, and how they were made.
struct voxelization {
    bit_grid voxels;  ///< the set voxels, on the requested grid
    /// True when the interior was filled (solid or centres mode on a closed mesh, or by winding number).
    bool filled = false;
    /// Empty, or why a filling mode did something else than asked (an open mesh).
    std::string note;
    std::size_t triangles = 0;             ///< triangles voxelized (polygons are fanned)
    std::size_t degenerate_triangles = 0;  ///< zero-area triangles met (allowed by the options)
};

template <class M, class T = default_traits<M>>
concept voxelize_mesh = face_vertex_range_mesh<M, T> && positioned_mesh<M, T> && vertex_index_mesh<M, T>;

/// A grid of cubic voxels around the mesh's bounding box: `resolution` voxels along its longest
/// side plus `padding` voxels on every side; sample (i, j, k) is voxel (i, j, k)'s centre.
/// Voxels whose closed box touches the surface are set, so a surface lying exactly on the
/// bounding box (a cube's faces) also sets the first padding layer: with padding >= 2 (the
/// default) at least one layer on every side stays empty, which marching cubes needs to close
/// the surface it extracts.
/// Errors: invalid_argument for resolution 0 or a mesh without vertices or with non-finite
/// positions. O(V).
template <class M, class T = default_traits<M>>
    requires positioned_mesh<M, T>
result<grid_geometry> voxel_grid_around(const M& mesh, std::size_t resolution, std::size_t padding = 2) {
    if (resolution == 0) return fail(errc::invalid_argument, "voxel_grid_around: resolution must be at least 1");
    vec3<double> lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
    vec3<double> hi = -lo;
    bool any = false;
    for (auto v : T::vertices(mesh)) {
        const vec3<typename T::scalar> p = T::position(mesh, v);
        for (std::size_t a = 0; a < 3; ++a) {
            if (!std::isfinite(double(p[a]))) return fail(errc::invalid_argument, "voxel_grid_around: a vertex position is not finite");
            lo[a] = std::min(lo[a], double(p[a]));
            hi[a] = std::max(hi[a], double(p[a]));
        }
        any = true;
    }
    if (!any) return fail(errc::invalid_argument, "voxel_grid_around: the mesh has no vertices");
    const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
    if (!std::isfinite(extent))
        return fail(errc::unsupported, "voxel_grid_around: the mesh spans more than the largest double along an axis; "
                                       "scale it down to voxelize it");
    const double h = extent > 0 ? extent / double(resolution) : 1.0;
    grid_geometry g;
    for (std::size_t a = 0; a < 3; ++a) {
        const auto n = static_cast<std::size_t>(std::ceil((hi[a] - lo[a]) / h - 1e-9));
        g.dims[a] = std::max<std::size_t>(n, 1) + 2 * padding;
        // Centre the box: the voxels span [lo - pad*h, ...] and samples sit at voxel centres.
        const double span = double(g.dims[a]) * h;
        g.origin[a] = 0.5 * (lo[a] + hi[a]) - 0.5 * span + 0.5 * h;
        g.spacing[a] = h;
    }
    return g;
}

/// About how many bytes voxelize() holds at its peak on `grid` for a mesh of `triangles`
/// triangles (polygons fanned): the grid's bits (whole 64-bit words per row, every voxel of
/// the grid, padding included) plus its copy of the triangles and their slab bins (at most
/// 96 bytes per triangle for the grids voxel_grid_around() makes). Callers compare it with
/// the memory they can spare before asking for a large grid: the bits are allocated
/// untouched (each slab clears its own), so an allocation the system cannot back may only
/// fail much later. O(1); saturates at the largest std::uint64_t.
inline std::uint64_t voxelize_memory_estimate(const grid_geometry& grid, std::size_t triangles) {
    const double words = std::ceil(double(grid.dims[0]) / 64.0) * double(grid.dims[1]) * double(grid.dims[2]);
    const double bytes = 8.0 * words + 96.0 * double(triangles);
    return bytes >= 0x1p64 ? std::numeric_limits<std::uint64_t>::max() : static_cast<std::uint64_t>(bytes);
}

namespace detail::vox {

// Triangle corners in voxel units: voxel (i, j, k)'s centre is (i, j, k), its box +-1/2.
struct tri {
    vec3<double> p[3];
    bool degenerate;
};

inline std::uint64_t mix(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

inline double solid_angle(vec3<double> a, vec3<double> b, vec3<double> c) {
    const double la = norm(a), lb = norm(b), lc = norm(c);
    const double num = dot(a, cross(b, c));
    const double den = la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb;
    return 2 * std::atan2(num, den);
}

}  // namespace detail::vox

namespace detail::vox {

// Voxel coordinates are clamped to +-2^60 (far outside any grid) and magnitudes below 2^-180
// are flushed to 0, so the exact predicates stay in their range.
inline double to_voxel_units(double p, double origin, double spacing) {
    const double q = std::clamp((p - origin) / spacing, -0x1p60, 0x1p60);
    return std::abs(q) < 0x1p-180 ? 0.0 : q;
}

/// The mesh's triangles in voxel units of `grid`, with the closedness check.
struct gathered {
    std::vector<tri> tris;
    bool closed = true;
    std::size_t degenerate = 0;
};

template <class M, class T>
result<gathered> gather(const M& mesh, const grid_geometry& grid, bool allow_degenerate) {
    gathered out;
    out.tris.reserve(T::face_count(mesh) * 2);
    std::uint64_t edge_parity = 0;
    std::vector<vec3<double>> loop;
    std::vector<std::size_t> ids;
    for (auto f : T::faces(mesh)) {
        loop.clear();
        ids.clear();
        for (auto v : T::face_vertices(mesh, f)) {
            const vec3<typename T::scalar> p = T::position(mesh, v);
            vec3<double> q;
            for (std::size_t a = 0; a < 3; ++a) {
                if (!std::isfinite(double(p[a])))
                    return fail(errc::invalid_argument, "voxelize: vertex " + std::to_string(T::vertex_index(mesh, v)) +
                                                            " has a non-finite position", static_cast<long long>(T::vertex_index(mesh, v)));
                q[a] = to_voxel_units(double(p[a]), grid.origin[a], grid.spacing[a]);
            }
            loop.push_back(q);
            ids.push_back(T::vertex_index(mesh, v));
        }
        const std::size_t n = loop.size();
        const long long fi = static_cast<long long>(out.tris.size());
        if (n < 3) return fail(errc::degenerate_face, "voxelize: a face has " + std::to_string(n) + " vertices", fi);
        for (std::size_t a = 0; a < n; ++a)
            for (std::size_t b = a + 1; b < n; ++b)
                if (ids[a] == ids[b])
                    return fail(errc::degenerate_face, "voxelize: a face uses vertex " + std::to_string(ids[a]) + " twice",
                                static_cast<long long>(ids[a]));
        for (std::size_t a = 0; a < n; ++a) {
            const std::uint64_t u = ids[a], w = ids[(a + 1) % n];
            edge_parity ^= mix((std::min(u, w) << 32) ^ std::max(u, w) ^ (std::min(u, w) >> 32));
        }
        for (std::size_t a = 1; a + 1 < n; ++a) {
            tri t{{loop[0], loop[a], loop[a + 1]}, false};
            const auto c = cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
            if (c.x == 0 && c.y == 0 && c.z == 0) {
                if (!allow_degenerate)
                    return fail(errc::degenerate_face, "voxelize: triangle " + std::to_string(out.tris.size()) +
                                                           " has zero area (set allow_degenerate to accept it)",
                                static_cast<long long>(out.tris.size()));
                t.degenerate = true;
                ++out.degenerate;
            }
            out.tris.push_back(t);
        }
    }
    out.closed = edge_parity == 0;
    return out;
}

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
        words[std::size_t(k - lo[2]) * layer_words + std::size_t(j - lo[1]) * row_words + (x >> 6)] |= std::uint64_t(on) << (x & 63);
    }
    /// The words of the plane u = iu of surface_columns<D>()'s walk (u is z for D = 0, 1 and
    /// y for D = 2), to give column() once per row.
    template <std::size_t D>
    std::uint64_t* plane(long long iu) const noexcept {
        if constexpr (D == 2) return words + std::size_t(iu - lo[1]) * row_words;
        else return words + std::size_t(iu - lo[2]) * layer_words;
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

/// The surface voxels of a triangle whose normal's dominant axis is D within the box [r0, r1]
/// (whole-grid voxel coordinates, already cut to the triangle's bounding box): walks the
/// columns along D row by row; in each column only the few voxels within the plane's range
/// over the column can touch the triangle. Calls set(i, j, k, on) for each candidate voxel,
/// with `on` true for those the triangle touches, and possibly for a few it misses by less
/// than the rounding margin below (a voxel may come more than once).
/// (flatten: GCC left the per-column lambdas as calls, 18% of sphere966's time at 512.)
template <std::size_t D>
[[gnu::flatten]] void surface_columns(const tri& tr, const vec3<double>& n, const vec3<double>& bl, const vec3<double>& bh,
                                      const long long (&r0)[3], const long long (&r1)[3], const bit_sink set) {
    // Columns are walked along v within a row: v is x where it can be (consecutive voxels share
    // a word), else y (the next row's word, 64 bytes on); never z (a layer, a page, away).
    constexpr std::size_t u = D == 2 ? 1 : 2, v = D == 0 ? 1 : 0;
    const vec3<double>* p = tr.p;
    const double c = dot(n, p[0]);
    const double slack = 0.5 * (std::abs(n[u]) + std::abs(n[v])) / std::abs(n[D]);
    // The reach widened by far more than the rounding of the height and slack: a voxel that
    // touches the plane exactly (at a corner or edge, common with corners on the half-voxel
    // lattice) must stay a candidate, and the exact tests below decide. The height is within
    // about the triangle's coordinates (|n[u]|, |n[v]| <= |n[D]|), which bounds the rounding.
    // For a sliver the rounded normal is known only to about eps |edge 0| |edge 1| (see the
    // widening below), which tilts the plane about corner 0 and moves the height over the
    // triangle by up to that over |n[D]| times the triangle's extent. Where that is large (a
    // triangle flat to rounding, nearly a segment) the shadow is thinner than a voxel, so every
    // column is an edge column, and edge_column() cuts the long reach to what the edge axes
    // allow: the cost stays that of the segment, not of its bounding box.
    double edge_size[3];  // |edge e|_1, edge e from corner e to corner e + 1
    for (int e = 0; e < 3; ++e) {
        const vec3<double> ed = p[(e + 1) % 3] - p[e];
        edge_size[e] = std::abs(ed.x) + std::abs(ed.y) + std::abs(ed.z);
    }
    const double extent = 2 + std::max({bh[0] - bl[0], bh[1] - bl[1], bh[2] - bl[2]});
    const double plane_doubt = 0x1p-44 * edge_size[0] * edge_size[1] * extent / std::abs(n[D]);
    const double reach_slack =
        slack + 0x1p-30 * (1 + slack + std::max({std::abs(bl[0]), std::abs(bl[1]), std::abs(bl[2]), std::abs(bh[0]), std::abs(bh[1]), std::abs(bh[2])})) +
        plane_doubt;
    const detail::triangle_box_tester tester(p[0], p[1], p[2], 0.5);
    // The tester's sums, with the terms of u and v computed once per column: an axis D' x e
    // (D' != D) is 0 along D', so its projection is the rounded sum of two terms in either
    // order; the normal's is ((x + y) + z) in the tester's order. Same roundings, same bits.
    const vec3<double>& o = tester.origin();
    const vec3<double>& normal = tester.axis(0);
    // Rounding. Each projection below is within a few ulps of |axis|_1 x (the triangle's extent
    // + 2) of the exact projection on the exact axis (of the exact edge vectors), at any voxel
    // centre within a voxel of the triangle's bounding box; the normal, a product of two edges,
    // within a few ulps of |edge 0|_1 |edge 1|_1 x that. Every interval is widened by 2^-44 of
    // that bound (some 25 times the rounding), so that a voxel the triangle touches, exactly at
    // a corner or an edge included, is never lost to rounding; the price is that a voxel
    // missing the triangle by less than the widening (about 1e-13 of the extent for a
    // well-shaped triangle, more for a sliver) may be set too.
    auto widening = [&](double axis_size) { return 0x1p-44 * axis_size * extent; };
    const double plane_widening = widening(edge_size[0] * edge_size[1]);
    const double plane_lo = tester.lo(0) - plane_widening, plane_hi = tester.hi(0) + plane_widening;
    double edge_d[6], edge_t[6], edge_lo[6], edge_hi[6];  // j = 2 e + (a == v): axis a x edge e
    for (int e = 0; e < 3; ++e)
        for (int k = 0; k < 2; ++k) {
            const int q = 1 + 3 * e + int(k == 0 ? u : v);
            edge_d[2 * e + k] = tester.axis(q)[D];
            edge_t[2 * e + k] = tester.axis(q)[k == 0 ? v : u];  // the other term: along v for a = u
            edge_lo[2 * e + k] = tester.lo(q) - widening(edge_size[e]);
            edge_hi[2 * e + k] = tester.hi(q) + widening(edge_size[e]);
        }
    // For the inner columns: the reach [w - reach_half, w + reach_half] within the window
    // and the bounding box widened by half a voxel (the voxels the box normal along D allows).
    const double inv_nd = 1 / n[D], nv_scaled = n[v] * inv_nd, reach_half = reach_slack + 0.5;
    long long reach_lo = 0, reach_hi = 0;
    if (!window_range(r0[D], r1[D], bl[D] - 0.5, bh[D] + 0.5, reach_lo, reach_hi)) return;
    // The separating axes D x edge (the shadow's edge normals in the (u, v) plane) give the
    // same answer for every voxel of a column: a column whose square is outside the shadow is
    // skipped; one whose square lies inside it needs only the plane test, since every point of
    // the plane over the square is then on the triangle.
    double axis_u[3], axis_v[3], inv_axis_v[3], lo2[3], hi2[3], inner_lo[3], inner_hi[3], bound_size[3];
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
        lo2[e] -= widening(edge_size[e]);  // (after the inner bounds: those stay as tight as they were)
        hi2[e] += widening(edge_size[e]);
        // For the doubt of the rows' estimates: the bounds' size in columns.
        bound_size[e] = (std::abs(lo2[e]) + std::abs(hi2[e]) + std::abs(inner_lo[e]) + std::abs(inner_hi[e])) * std::abs(inv_axis_v[e]);
    }
    // ... and a bound of |iv - p0[v]| over the window's columns, and of |p0[v]|.
    const double column_span = 1 + std::abs(double(r0[v])) + std::abs(double(r1[v])) + 2 * std::abs(p[0][v]);
    // Where the window cuts the triangle along D (a slab of the grid), many columns reach no
    // voxel of it. Column iv's plane height w is monotone in iv (so is its rounding), hence
    // the columns whose reach ends below the window form a prefix or a suffix of the row, and
    // those whose reach starts above it the other: cut both off [iv0, iv1] (false if nothing
    // is left), locating each end from the line's equation and settling it by the very
    // comparisons that make reach() empty there.
    auto live_columns = [&](long long& iv0, long long& iv1, double cu) {
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
        if (rising) settle(below, above, bottom, top);
        else settle(above, below, top, bottom);
        return iv0 <= iv1;
    };
    // Only a window that cuts the triangle along D leaves columns without a voxel to reach.
    const bool clipped = r0[D] > -fast_floor(-(bl[D] - 0.5)) || r1[D] < fast_floor(bh[D] + 0.5);
    for (long long iu = r0[u]; iu <= r1[u]; ++iu) {
        const double fu = double(iu);
        std::uint64_t* const plane_words = set.plane<D>(iu);
        // Each edge's projection of column iv, q_e(iv) = base_e + axis_v_e (iv - p0[v]) as kind()
        // computes it, is monotone in iv (so is its rounding): the columns not outside the
        // shadow by edge e's axis form an interval, and those inside e's side by the margin
        // another. Their ends follow from the line's equation, each known to within `doubt`
        // columns (a bound of the rounding of this estimate and of kind()'s q, with a factor
        // of some 1000 to spare). A column farther than that from every end is classified by
        // the ends alone; one nearer (rare) gets kind(). No column outside [near_lo, near_hi]
        // can meet the shadow.
        constexpr double infinity = std::numeric_limits<double>::infinity();
        double near_lo = double(r0[v]), near_hi = double(r1[v]), sure_lo = near_lo, sure_hi = near_hi;
        double base[3], in_lo[3], in_hi[3];
        bool row_outside = false;
        for (int e = 0; e < 3; ++e) {
            base[e] = axis_u[e] * (fu - p[0][u]);
            if (axis_v[e] == 0) {  // q_e is base_e along the whole row
                row_outside |= (base[e] < lo2[e]) | (base[e] > hi2[e]);
                const bool inside = (base[e] >= inner_lo[e]) & (base[e] <= inner_hi[e]);
                in_lo[e] = inside ? -infinity : infinity;
                in_hi[e] = inside ? infinity : -infinity;
                continue;
            }
            // Where q_e reaches each bound; q_e falls with iv where axis_v_e < 0. (The inner
            // band may be empty, its "lower" bound above the upper: so is the interval then.)
            const bool rising = axis_v[e] > 0;
            auto at = [&](double bound) { return (bound - base[e]) * inv_axis_v[e] + p[0][v]; };
            const double a = at(rising ? lo2[e] : hi2[e]), b = at(rising ? hi2[e] : lo2[e]);
            const double ia = at(rising ? inner_lo[e] : inner_hi[e]), ib = at(rising ? inner_hi[e] : inner_lo[e]);
            const double doubt = 0x1p-40 * (column_span + bound_size[e] + std::abs(base[e]) * std::abs(inv_axis_v[e]));
            near_lo = std::max(near_lo, a - doubt);
            near_hi = std::min(near_hi, b + doubt);
            sure_lo = std::max(sure_lo, a + doubt);
            sure_hi = std::min(sure_hi, b - doubt);
            in_lo[e] = ia + doubt;
            in_hi[e] = ib - doubt;
        }
        if (row_outside || !(near_lo <= near_hi)) continue;
        long long iv0 = std::max<long long>(r0[v], -fast_floor(-near_lo)), iv1 = std::min<long long>(r1[v], fast_floor(near_hi));
        const double cu = c - n[u] * fu;
        if (clipped && !live_columns(iv0, iv1, cu)) continue;
        // `outside` when the column's square is outside the shadow, else a mask of the edges
        // it lies across (bit e: not inside edge e's side by the margin); 0 inside the shadow.
        constexpr int outside = 8;
        auto kind = [&](long long iv) {
            const double fv = double(iv);
            bool out = false;
            int across = 0;
            for (int e = 0; e < 3; ++e) {
                const double q = base[e] + axis_v[e] * (fv - p[0][v]);
                out |= (q < lo2[e]) | (q > hi2[e]);
                across |= int((q < inner_lo[e]) | (q > inner_hi[e])) << e;
            }
            return out ? outside : across;
        };
        // The voxels of column iv within reach of the plane, [w0, w1], cut to the window and
        // the bounding box; false if none. The height by a multiplication: its rounding, a
        // few ulps of the triangle's coordinates, is far within reach_slack.
        const double cu_scaled = cu * inv_nd;
        auto reach = [&](long long iv, long long& w0, long long& w1) {
            const double w = cu_scaled - double(iv) * nv_scaled;
            w0 = std::max(reach_lo, -fast_floor(reach_half - w));
            w1 = std::min(reach_hi, fast_floor(w + reach_half));
            return w0 <= w1;
        };
        const double cu_rel = fu - o[u];
        // Whether the plane meets voxel (iu, iv, iw) given cw = iw - o[D], as meets_plane().
        auto meets_plane = [&](double tu, double tv, double cw) {
            double t[3];
            t[u] = tu;
            t[v] = tv;
            t[D] = normal[D] * cw;
            const double q = (t[0] + t[1]) + t[2];
            return (q >= plane_lo) & (q <= plane_hi);
        };
        const double tu = normal[u] * cu_rel;
        // overlaps_off<D>(): the plane and the axes u x edge, v x edge of the edges in
        // `across`. An edge whose side holds the whole square (by the margin) cannot separate
        // a voxel of the column that the other axes leave touching the triangle: clipping the
        // shadow by that edge's half-plane leaves the column's part of it unchanged.
        // (The edges are a template argument: a column is across one edge, now and then two,
        // and the tests of each set of edges compile to straight code.)
        auto edge_column_of = [&]<int across>(std::integral_constant<int, across>, long long iv) {
            long long w0, w1;
            if (!reach(iv, w0, w1)) return;
            const double cv_rel = double(iv) - o[v], tv = normal[v] * cv_rel;
            constexpr int axes = 2 * std::popcount(unsigned(across));
            double shared[axes], d[axes], lo[axes], hi[axes];
            for (int j = 0, a = 0; j < 6; ++j)
                if ((across >> (j / 2)) & 1) {
                    shared[a] = edge_t[j] * (j % 2 == 0 ? cv_rel : cu_rel);
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
                bool on = meets_plane(tu, tv, cw);
                for (int j = 0; j < axes; ++j) {
                    const double q = shared[j] + d[j] * cw;
                    on &= (q >= lo[j]) & (q <= hi[j]);
                }
                return on;
            };
            // Two voxels without a branch on how many, as inner_column().
            const auto put = set.column<D>(plane_words, iv);
            const long long second = w0 + (w1 > w0);
            put(w0, touches(w0));
            put(second, touches(second));
            for (long long iw = w0 + 2; iw <= w1; ++iw) put(iw, touches(iw));
        };
        auto edge_column = [&](long long iv, int across) {
            switch (across) {
                case 1: return edge_column_of(std::integral_constant<int, 1>{}, iv);
                case 2: return edge_column_of(std::integral_constant<int, 2>{}, iv);
                case 3: return edge_column_of(std::integral_constant<int, 3>{}, iv);
                case 4: return edge_column_of(std::integral_constant<int, 4>{}, iv);
                case 5: return edge_column_of(std::integral_constant<int, 5>{}, iv);
                case 6: return edge_column_of(std::integral_constant<int, 6>{}, iv);
                default: return edge_column_of(std::integral_constant<int, 7>{}, iv);
            }
        };
        // A column whose square lies inside the shadow: only the plane test.
        auto inner_column = [&](long long iv) {
            long long w0, w1;
            if (!reach(iv, w0, w1)) return;
            // Most columns reach one or two voxels: test two without a branch on how many
            // (the second is w0 again, set only if it passes, when the reach is one voxel).
            const long long second = w0 + (w1 > w0);
            const double tv = normal[v] * (double(iv) - o[v]);
            const auto put = set.column<D>(plane_words, iv);
            put(w0, meets_plane(tu, tv, double(w0) - o[D]));
            put(second, meets_plane(tu, tv, double(second) - o[D]));
            for (long long iw = w0 + 2; iw <= w1; ++iw) put(iw, meets_plane(tu, tv, double(iw) - o[D]));
        };
        // The inner run [ci, ce]: columns surely inside every edge's side. The rest of
        // [iv0, iv1] are edge columns, across the edges they are not surely inside, except
        // those within doubt of a shadow end, which kind() classifies.
        const long long sure0 = std::max(iv0, -fast_floor(-sure_lo)), sure1 = std::min(iv1, fast_floor(sure_hi));
        long long ci = std::max({sure0, -fast_floor(-in_lo[0]), -fast_floor(-in_lo[1]), -fast_floor(-in_lo[2])});
        long long ce = std::min({sure1, fast_floor(in_hi[0]), fast_floor(in_hi[1]), fast_floor(in_hi[2])});
        if (ci > ce) ci = iv1 + 1, ce = iv1;  // no inner run: all of [iv0, iv1] is edge columns
        auto outer_column = [&](long long iv) {
            if (iv < sure0 || iv > sure1) {
                const int k = kind(iv);
                if (k == 0) inner_column(iv);
                else if (k != outside) edge_column(iv, k);
                return;
            }
            const double fv = double(iv);
            int across = 0;
            for (int e = 0; e < 3; ++e) across |= int((fv < in_lo[e]) | (fv > in_hi[e])) << e;
            edge_column(iv, across);
        };
        for (long long iv = iv0; iv < ci; ++iv) outer_column(iv);
        for (long long iv = ce + 1; iv <= iv1; ++iv) outer_column(iv);
        for (long long iv = ci; iv <= ce; ++iv) inner_column(iv);
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
    const int d = std::abs(n.x) >= std::abs(n.y) ? (std::abs(n.x) >= std::abs(n.z) ? 0 : 2) : (std::abs(n.y) >= std::abs(n.z) ? 1 : 2);
    if (d == 0) surface_columns<0>(tr, n, bl, bh, r0, r1, set);
    else if (d == 1) surface_columns<1>(tr, n, bl, bh, r0, r1, set);
    else surface_columns<2>(tr, n, bl, bh, r0, r1, set);
}

/// What to compute in a window of the grid.
struct window_job {
    bool surface = false;    // voxels the surface touches
    bool crossings = false;  // the parity fill of voxel centres (closed mesh)
    bool winding = false;    // the winding-number fill between surface voxels (open mesh)
};

/// Triangles binned to slabs of whole z-layers of a window: slab s holds tri[start[s] ..
/// start[s + 1]), every triangle whose voxels or rays (z within one voxel of its own z range)
/// can meet the slab, in their original order.
struct slab_bins {
    std::vector<std::size_t> start;
    std::vector<std::uint32_t> tri;
};

/// Bins triangles `subset` (all where null) of `tris` to slabs of `layers` z-layers of the
/// window's `nz` layers starting at whole-grid layer `z0`. O(F + the slabs each spans).
inline slab_bins bin_to_slabs(const std::vector<tri>& tris, const std::vector<std::uint32_t>* subset, long long z0, long long nz,
                              long long layers) {
    const std::size_t count = subset ? subset->size() : tris.size();
    const long long slabs = (nz + layers - 1) / layers;
    auto slab_range = [&](const tri& t, long long& s0, long long& s1) {
        const double zl = std::min({t.p[0].z, t.p[1].z, t.p[2].z}), zh = std::max({t.p[0].z, t.p[1].z, t.p[2].z});
        const long long k0 = std::max<long long>(0, fast_floor(zl) - 1 - z0), k1 = std::min<long long>(nz - 1, fast_floor(zh) + 2 - z0);
        s0 = k0 / layers;
        s1 = k1 / layers;
        return k0 <= k1;
    };
    slab_bins b;
    b.start.assign(std::size_t(slabs) + 1, 0);
    for (std::size_t t = 0; t < count; ++t) {
        long long s0, s1;
        if (slab_range(tris[subset ? (*subset)[t] : t], s0, s1))
            for (long long s = s0; s <= s1; ++s) ++b.start[std::size_t(s) + 1];
    }
    for (std::size_t s = 0; s < std::size_t(slabs); ++s) b.start[s + 1] += b.start[s];
    b.tri.resize(b.start.back());
    std::vector<std::size_t> next(b.start.begin(), b.start.end() - 1);
    for (std::size_t t = 0; t < count; ++t) {
        const std::uint32_t id = subset ? (*subset)[t] : static_cast<std::uint32_t>(t);
        long long s0, s1;
        if (slab_range(tris[id], s0, s1))
            for (long long s = s0; s <= s1; ++s) b.tri[next[std::size_t(s)]++] = id;
    }
    return b;
}

/// Voxelizes `tris` into `out`, whose voxel (0, 0, 0) is voxel `lo` of the whole grid: the
/// surface voxels of triangles `surface_subset`, the crossings of triangles `crossing_subset`
/// (all triangles where a subset is null). The rays of the parity fill start at -infinity, so
/// a window gets the same bits as the whole grid has there when crossing_subset holds every
/// triangle whose shadow meets the window's rows. Writes every word of `out`, which may come
/// from bit_grid::unwritten(). Returns false when `progress` cancelled.
///
/// The window is cut into slabs of whole z-layers, each filled start to end by one thread:
/// crossings, prefix XOR, then surface voxels. A slab's words (up to 1 MiB) stay in that
/// core's cache through the three steps, and no two threads write one word, so no atomics.
/// Larger slabs than 512 KiB measured faster (fewer triangles cut in several slabs, each
/// prepared once per slab), while a 512^3 grid still has 19 slabs to share out.
inline bool fill_window(const std::vector<tri>& tris, const std::vector<std::uint32_t>* surface_subset,
                        const std::vector<std::uint32_t>* crossing_subset, const std::array<long long, 3>& lo, bit_grid& out,
                        const window_job& job, unsigned threads, const progress_function& progress) {
    const grid_dims dims = out.dims();
    const long long nx = static_cast<long long>(dims[0]), ny = static_cast<long long>(dims[1]), nz = static_cast<long long>(dims[2]);
    const std::size_t words = out.words_per_row();
    const long long layers = std::clamp<long long>(static_cast<long long>((std::size_t(1) << 17) / std::max<std::size_t>(1, words * dims[1])), 1, nz);
    const std::size_t slabs = std::size_t((nz + layers - 1) / layers);
    slab_bins surface_bins, own_crossing_bins;
    if (job.surface) surface_bins = bin_to_slabs(tris, surface_subset, lo[2], nz, layers);
    const bool shared = job.surface && surface_subset == crossing_subset;  // one set of bins serves both passes
    if (job.crossings && !shared) own_crossing_bins = bin_to_slabs(tris, crossing_subset, lo[2], nz, layers);
    const slab_bins& crossing_bins = shared ? surface_bins : own_crossing_bins;
    // Progress counts triangle visits and rows.
    const std::size_t rows = dims[1] * dims[2];
    progress_gate gate(progress, surface_bins.tri.size() + (job.crossings ? crossing_bins.tri.size() + rows : 0) + (job.winding ? rows : 0));

    const bit_sink set_voxel{out.words().data(), words, words * dims[1], {lo[0], lo[1], lo[2]}};

    // Window layers [k0, k1] of slab s. The slab's words are cleared here, not when the grid
    // was made: so they are in this core's cache for what follows.
    auto fill_slab = [&](std::size_t s) {
        const long long k0 = static_cast<long long>(s) * layers, k1 = std::min(nz, k0 + layers) - 1;
        const auto slab_words = out.words().subspan(std::size_t(k0) * dims[1] * words, std::size_t(k1 - k0 + 1) * dims[1] * words);
        std::fill(slab_words.begin(), slab_words.end(), std::uint64_t(0));
        if (job.crossings) {
            // Ray crossings: voxels beyond a crossing along x change side. Each row of the slab
            // notes the first and last word its marks fall in, [span_first, span_last], so that
            // the prefix pass below skips the words (and rows) that hold none.
            std::uint64_t* toggles = out.words().data();
            const std::size_t first_row = std::size_t(k0) * dims[1], slab_rows = std::size_t(k1 - k0 + 1) * dims[1];
            std::vector<std::uint32_t> span_first(slab_rows, std::numeric_limits<std::uint32_t>::max()), span_last(slab_rows, 0);
            for (std::size_t b = crossing_bins.start[s]; b < crossing_bins.start[s + 1]; ++b) {
                if ((b - crossing_bins.start[s]) % 1024 == 0 && !gate.advance(std::min<std::size_t>(1024, crossing_bins.start[s + 1] - b)))
                    return;
                const tri& tr = tris[crossing_bins.tri[b]];
                const crossing_triangle ct(tr.p[0], tr.p[1], tr.p[2]);
                if (ct.xmin - 1 >= double(lo[0] + nx)) continue;  // crosses no ray before the window's end
                ct.for_each_ray(lo[1], lo[1] + ny - 1, lo[2] + k0, lo[2] + k1, [&](long long j, long long k, const crossing_triangle::row_estimate& row) {
                    const long long first = ct.first_beyond(row, j, k) - lo[0];
                    if (first >= nx) return;
                    const std::size_t i = first <= 0 ? 0 : static_cast<std::size_t>(first);
                    const std::size_t r = std::size_t(k - lo[2]) * dims[1] + std::size_t(j - lo[1]) - first_row;
                    toggles[(first_row + r) * words + (i >> 6)] ^= std::uint64_t(1) << (i & 63);
                    const auto w = static_cast<std::uint32_t>(i >> 6);
                    span_first[r] = std::min(span_first[r], w);
                    span_last[r] = std::max(span_last[r], w);
                });
            }
            // Prefix XOR along each row turns crossing marks into inside bits. Words before a
            // row's first mark stay empty; those between its marks mostly hold none and take
            // only the carry; after its last mark the row is inside to its end only where a
            // window cut off crossings beyond it (a closed surface's row otherwise ends outside).
            const std::uint64_t last = (dims[0] & 63) ? (std::uint64_t(1) << (dims[0] & 63)) - 1 : ~std::uint64_t(0);
            auto prefix_xor = [](std::uint64_t x) {
                x ^= x << 1;
                x ^= x << 2;
                x ^= x << 4;
                x ^= x << 8;
                x ^= x << 16;
                return x ^ (x << 32);
            };
            for (std::size_t r = 0; r < slab_rows; ++r) {
                const std::size_t a = span_first[r], e = span_last[r];
                if (a > e) continue;  // no mark: the row stays empty
                std::uint64_t* row = toggles + (first_row + r) * words;
                std::uint64_t x = prefix_xor(row[a]);
                row[a] = x;
                std::uint64_t fill = std::uint64_t(0) - (x >> 63);  // all ones while inside
                for (std::size_t w = a + 1; w < e; ++w) {
                    x = row[w];
                    if (x) x = prefix_xor(x);
                    x ^= fill;
                    fill = std::uint64_t(0) - (x >> 63);
                    row[w] = x;
                }
                if (e > a) {
                    x = prefix_xor(row[e]) ^ fill;
                    fill = std::uint64_t(0) - (x >> 63);
                    row[e] = x;
                }
                if (fill)
                    for (std::size_t w = e + 1; w < words; ++w) row[w] = fill;
                row[words - 1] &= last;
            }
            const std::size_t r0 = first_row, r1 = first_row + slab_rows;
            if (!gate.advance(r1 - r0)) return;
        }
        // Surface voxels (most are found set already inside a solid).
        if (job.surface)
            for (std::size_t b = surface_bins.start[s]; b < surface_bins.start[s + 1]; ++b) {
                if ((b - surface_bins.start[s]) % 1024 == 0 && !gate.advance(std::min<std::size_t>(1024, surface_bins.start[s + 1] - b)))
                    return;
                const tri& tr = tris[surface_bins.tri[b]];
                const long long wlo[3] = {lo[0], lo[1], lo[2] + k0}, whi[3] = {lo[0] + nx - 1, lo[1] + ny - 1, lo[2] + k1};
                if (!tr.degenerate) surface_voxels(tr, wlo, whi, set_voxel);
            }
    };

    with_thread_count(threads, [&] {
        parallel_chunks(slabs, 1, [&](std::size_t s0, std::size_t s1) {
            for (std::size_t s = s0; s < s1 && !gate.cancelled(); ++s) fill_slab(s);
        });
        if (gate.cancelled()) return;
        if (job.winding) {
            // Between two surface voxels along a row the side cannot change without crossing
            // the surface, except through a hole: one winding number per run of empty voxels.
            const double four_pi = 4 * std::numbers::pi;
            parallel_chunks(dims[1] * dims[2], 16, [&](std::size_t q0, std::size_t q1) {
                for (std::size_t r = q0; r < q1 && gate.advance(); ++r) {
                    const std::size_t j = r % dims[1], k = r / dims[1];
                    std::uint64_t* row = out.row(j, k);
                    std::vector<std::size_t> starts;
                    for (std::size_t i = 0; i < dims[0]; ++i) {
                        const bool set = (row[i >> 6] >> (i & 63)) & 1;
                        const bool prev = i > 0 && ((row[(i - 1) >> 6] >> ((i - 1) & 63)) & 1);
                        if (!set && (i == 0 || prev)) starts.push_back(i);
                    }
                    for (std::size_t s0 : starts) {
                        const vec3<double> c{double(s0) + double(lo[0]), double(j) + double(lo[1]), double(k) + double(lo[2])};
                        double w = 0;
                        for (const auto& tr : tris) w += solid_angle(tr.p[0] - c, tr.p[1] - c, tr.p[2] - c);
                        if (w / four_pi < 0.5) continue;
                        std::size_t i = s0;
                        for (; i < dims[0] && !((row[i >> 6] >> (i & 63)) & 1); ++i) {}
                        for (std::size_t q = s0; q < i; ++q) row[q >> 6] |= std::uint64_t(1) << (q & 63);
                    }
                }
            });
        }
    });
    return !gate.cancelled();
}

/// What the options ask of a mesh that is closed or not; the note says what was done instead.
inline result<window_job> plan(const voxelize_options& options, bool closed, std::string& note, bool& filled) {
    window_job job;
    job.surface = options.mode != voxelize_mode::centres;
    const bool fill = options.mode != voxelize_mode::surface;
    filled = fill;
    if (fill && !closed) {
        const std::string why = "the mesh is not closed (an edge has an odd number of faces)";
        const std::string mode = options.mode == voxelize_mode::centres ? "centres" : "solid";
        if (options.open_mesh == open_mesh_fill::fail) return fail(errc::topology, "voxelize: " + mode + " mode: " + why);
        job.surface = true;
        if (options.open_mesh == open_mesh_fill::surface_only) {
            filled = false;
            note = mode + " fill skipped: " + why + "; surface voxels only";
        } else {
            job.winding = true;
            note = why + "; filled by generalized winding number" +
                   (options.mode == voxelize_mode::centres ? std::string(", with the surface voxels (conservative)") : std::string());
        }
        return job;
    }
    job.crossings = fill;
    return job;
}

}  // namespace detail::vox

/// Voxelizes `mesh` into a bit grid of geometry `grid` (sample (i, j, k) = centre of voxel
/// (i, j, k), voxel = the box of one spacing around it). Polygons are fanned into triangles.
///
/// - Surface voxels (modes surface and solid): every voxel whose closed box meets a triangle
///   (conservative voxelization), by a separating-axis test in floating point whose intervals
///   are widened past its rounding: no voxel the triangle touches is lost, a single touching
///   corner included; a voxel it misses by less than about 1e-13 of its size (more for a
///   sliver, whose plane is less well known) may be set too.
/// - Inside voxels (modes solid and centres) on a closed mesh (every edge used by an even
///   number of faces, checked by an XOR of edge hashes): every voxel whose centre lies inside,
///   by the parity of the crossings of a ray along x, decided by exact predicates (orient2d
///   for which triangles a ray crosses, orient3d for which side of the crossing a centre lies)
///   with a symbolic perturbation of the centre by (eps, eps^2, eps^3): rays through edges
///   and vertices count once, and a centre exactly on the surface is inside where the surface
///   faces -x. On a mesh that is not closed, see voxelize_options.
/// - Parallel over slabs of z-layers (about 1 MiB of bits each, one thread per slab, the
///   triangles binned to the slabs they reach): the output is the same for every thread count.
///
/// Complexity: O(F + sum over triangles of the slabs they reach + the voxels in their bounding
/// box) for the surface,
/// plus O(N/64 + sum over triangles of the rays their shadow covers and the rows it spans) for
/// the fill; the winding number fill costs O(F) per run of empty voxels along each row.
/// Errors (nothing is returned but the error): invalid_argument for an unusable grid (zero
/// dimension, spacing not positive) or a non-finite vertex position; degenerate_face for a face
/// with fewer than 3 vertices or a repeated vertex, and for a zero-area triangle unless
/// allow_degenerate; topology when a filling mode meets an open mesh with open_mesh = fail.
template <class M, class T = default_traits<M>>
    requires voxelize_mesh<M, T>
result<voxelization> voxelize(const M& mesh, const grid_geometry& grid, const voxelize_options& options = {}) {
    if (auto ok = check_grid_geometry(grid, "voxelize"); !ok) return ok.error();
    auto g = detail::vox::gather<M, T>(mesh, grid, options.allow_degenerate);
    if (!g) return g.error();
    voxelization out{bit_grid::unwritten(grid), false, {}, g->tris.size(), g->degenerate};
    auto job = detail::vox::plan(options, g->closed, out.note, out.filled);
    if (!job) return job.error();
    if (!detail::vox::fill_window(g->tris, nullptr, nullptr, {0, 0, 0}, out.voxels, *job, options.threads, options.progress))
        return fail(errc::cancelled, "voxelize: cancelled");
    return out;
}

/// Same voxels, written into any writable voxel grid of the wanted geometry (1 for a set
/// voxel, 0 elsewhere). Errors: those of voxelize(), before `grid` is touched.
template <class M, class T = default_traits<M>, writable_voxel_grid G>
    requires voxelize_mesh<M, T>
result<voxelization> voxelize_into(const M& mesh, G& grid, const voxelize_options& options = {}) {
    auto v = voxelize<M, T>(mesh, geometry_of(grid), options);
    if (!v) return v.error();
    const auto d = grid.dims();
    for (std::size_t k = 0; k < d[2]; ++k)
        for (std::size_t j = 0; j < d[1]; ++j)
            for (std::size_t i = 0; i < d[0]; ++i)
                grid.set(i, j, k, static_cast<typename G::value_type>(v->voxels.value(i, j, k)));
    return v;
}

}  // namespace hmira
