// hmira/algorithms/editing/detail/grid_fill.hpp
// Grid fill of a bevel's vertex patch: a face bounded by k arcs of n segments each becomes a
// grid of quads (Blender-like "grid fill"), built from the Euler operators only and placed on
// a sphere fitted to its boundary when the boundary is (nearly) spherical. Not public API.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "editing_common.hpp"

namespace hmira::detail::editing {

/// The halfedge of f's loop whose target is v (null when v is not on the loop). Callers only
/// ask for vertices that occur once on the loop. O(face degree).
template <class M, class T>
typename T::halfedge_handle into_vertex(const M& m, typename T::face_handle f, typename T::vertex_handle v) {
    const auto start = T::face_halfedge(m, f);
    auto h = start;
    do {
        if (T::target(m, h) == v) return h;
        h = T::next(m, h);
    } while (h != start);
    return T::null_halfedge();
}

/// What grid_fill added to the mesh.
template <class M, class T>
struct grid_fill_result {
    std::vector<typename T::face_handle> faces;       ///< the new faces (the filled face is not repeated)
    std::vector<typename T::vertex_handle> vertices;  ///< the new vertices
};

/// The sphere |p - centre| = radius through `pts` by linear least squares (|p|^2 = 2 c.p + d),
/// accepted only when it fits: rms distance from the sphere < 1% of the radius, and radius
/// < 10 x the points' diameter (a nearly flat boundary would give a huge, useless sphere).
struct fitted_sphere {
    bool ok = false;
    vec3<double> centre{};
    double radius = 0;
};

inline fitted_sphere fit_sphere(const std::vector<vec3<double>>& pts) {
    fitted_sphere out;
    if (pts.size() < 4) return out;
    // Centre the points first so the normal equations are well conditioned.
    vec3<double> mean{};
    for (const auto& p : pts) mean += p;
    mean = mean / double(pts.size());
    double diameter = 0;
    for (const auto& p : pts)
        for (const auto& q : pts) diameter = std::max(diameter, norm(p - q));
    if (!(diameter > 0)) return out;
    // Scaled by the diameter as well: unknowns (cx, cy, cz, d) of 2 c.p + d = |p|^2.
    std::array<std::array<double, 5>, 4> a{};  // augmented normal equations
    for (const auto& p0 : pts) {
        const auto p = (p0 - mean) / diameter;
        const double row[4] = {2 * p.x, 2 * p.y, 2 * p.z, 1};
        const double rhs = dot(p, p);
        for (int i = 0; i < 4; ++i) {
            for (int j = 0; j < 4; ++j) a[i][j] += row[i] * row[j];
            a[i][4] += row[i] * rhs;
        }
    }
    // Gaussian elimination with partial pivoting; a (near) singular system means the points
    // are (nearly) coplanar: no sphere.
    for (int c = 0; c < 4; ++c) {
        int piv = c;
        for (int r = c + 1; r < 4; ++r)
            if (std::abs(a[r][c]) > std::abs(a[piv][c])) piv = r;
        if (!(std::abs(a[piv][c]) > 1e-12 * double(pts.size()))) return out;
        std::swap(a[c], a[piv]);
        for (int r = 0; r < 4; ++r) {
            if (r == c) continue;
            const double f = a[r][c] / a[c][c];
            for (int j = c; j < 5; ++j) a[r][j] -= f * a[c][j];
        }
    }
    const vec3<double> c{a[0][4] / a[0][0], a[1][4] / a[1][1], a[2][4] / a[2][2]};
    const double d = a[3][4] / a[3][3];
    const double r2 = d + dot(c, c);
    if (!(r2 > 0) || !std::isfinite(r2)) return out;
    const double r = std::sqrt(r2);
    double ss = 0;
    for (const auto& p0 : pts) {
        const double e = norm((p0 - mean) / diameter - c) - r;
        ss += e * e;
    }
    const double rms = std::sqrt(ss / double(pts.size()));
    if (!(rms < 0.01 * r) || !(r < 10.0)) return out;
    out.ok = true;
    out.centre = mean + c * diameter;
    out.radius = r * diameter;
    return out;
}

/// Where a grid fill puts its points, from the boundary alone. With m = floor(n / 2) (`h`
/// here), patch i is a grid G[r][s], r, s in [0, h]: G[0][s] = A_i[a0 + s] (to the corner),
/// G[r][h] = A_{i+1}[r], G[r][0] = L_i[r], G[h][s] = R_i[h - s]; its loop runs G[0][0] ->
/// G[0][h] -> G[h][h] -> G[h][0] -> G[0][0], as f's does. L_i runs from A_i[a0] to Q_i, R_i
/// from A_{i+1}[h] to Q_i, where Q_i is where patch i's two inner paths meet (the centre for
/// even n, where R_i = L_{i+1}).
struct grid_fill_layout {
    using P = vec3<double>;
    std::size_t k = 0;                            ///< arcs
    std::size_t n = 0;                            ///< segments per arc
    std::size_t h = 0;                            ///< m of the description: patch size
    bool odd = false;                             ///< n is odd: strips between the patches, a k-gon in the middle
    std::size_t a0 = 0;                           ///< where patch i starts on arc i (h for even n, h + 1 for odd)
    std::vector<std::vector<P>> ap;               ///< the arcs' positions
    std::vector<std::vector<P>> lp, rp;           ///< the inner paths L_i, R_i
    std::vector<std::vector<std::vector<P>>> gp;  ///< each patch's grid G
    fitted_sphere sphere;                         ///< fit_sphere of the boundary

    std::size_t nx(std::size_t i) const { return (i + 1) % k; }
    /// p projected onto the fitted sphere, when the fit was accepted.
    P place(const P& p) const {
        if (!sphere.ok) return p;
        const auto d = p - sphere.centre;
        const double len = norm(d);
        return len > 0 ? sphere.centre + d * (sphere.radius / len) : p;
    }
};

/// The positions of the grid fill of the loop `arcs` (see grid_fill): inner paths straight
/// (centre = centroid of the boundary, I_i = 1/n of the way from it to corner i + 1), patch
/// interiors by a Coons patch of their four sides.
template <class M, class T>
grid_fill_layout grid_fill_positions(const M& m, const std::vector<std::vector<typename T::vertex_handle>>& arcs) {
    using P = vec3<double>;
    grid_fill_layout g;
    const std::size_t k = g.k = arcs.size();
    const std::size_t n = g.n = arcs[0].size() - 1;
    const std::size_t h = g.h = n / 2;
    g.odd = n % 2 == 1;
    const std::size_t a0 = g.a0 = n - h;
    auto& ap = g.ap;
    ap.resize(k);
    std::vector<P> boundary;
    for (std::size_t i = 0; i < k; ++i) {
        for (auto v : arcs[i]) ap[i].push_back(pos<M, T>(m, v));
        for (std::size_t j = 0; j < n; ++j) boundary.push_back(ap[i][j]);
    }
    P centre{};
    for (const auto& p : boundary) centre += p;
    centre = centre / double(boundary.size());
    std::vector<P> q(k, centre);
    if (g.odd)
        for (std::size_t i = 0; i < k; ++i) q[i] = lerp(centre, ap[i][n], 1.0 / double(n));
    g.lp.resize(k);
    g.rp.resize(k);
    for (std::size_t i = 0; i < k; ++i)
        for (std::size_t r = 0; r <= h; ++r) {
            g.lp[i].push_back(lerp(ap[i][a0], q[i], double(r) / double(h)));
            g.rp[i].push_back(lerp(ap[g.nx(i)][h], q[i], double(r) / double(h)));
        }
    g.gp.assign(k, std::vector<std::vector<P>>(h + 1, std::vector<P>(h + 1)));
    for (std::size_t i = 0; i < k; ++i) {
        auto& gi = g.gp[i];
        for (std::size_t s = 0; s <= h; ++s) {
            gi[0][s] = ap[i][a0 + s];
            gi[h][s] = g.rp[i][h - s];
        }
        for (std::size_t r = 0; r <= h; ++r) {
            gi[r][h] = ap[g.nx(i)][r];
            gi[r][0] = g.lp[i][r];
        }
        for (std::size_t r = 1; r < h; ++r)
            for (std::size_t s = 1; s < h; ++s) {
                const double u = double(r) / double(h), t = double(s) / double(h);
                gi[r][s] = gi[0][s] * (1 - u) + gi[h][s] * u + gi[r][0] * (1 - t) + gi[r][h] * t -
                           (gi[0][0] * ((1 - u) * (1 - t)) + gi[0][h] * ((1 - u) * t) + gi[h][0] * (u * (1 - t)) +
                            gi[h][h] * (u * t));
            }
    }
    g.sphere = fit_sphere(boundary);
    return g;
}

/// v[from, to).
inline std::vector<vec3<double>> slice(const std::vector<vec3<double>>& v, std::size_t from, std::size_t to) {
    return std::vector<vec3<double>>(v.begin() + std::ptrdiff_t(from), v.begin() + std::ptrdiff_t(to));
}

/// The topology of a grid fill under construction: the mesh, the layout, what was added, and
/// the vertex handles of the inner paths (same layout as lp / rp) and the faces split off.
template <class M, class T>
struct grid_fill_builder {
    using V = typename T::vertex_handle;
    using F = typename T::face_handle;
    M& m;
    const grid_fill_layout& g;
    grid_fill_result<M, T>& out;
    std::vector<std::vector<V>> lv, rv;
    std::vector<F> patch, strip;
    F rest;  // the part of f not yet split off

    /// Chain from x through new vertices at `pts`, closed at y when y is given. makeEF's new
    /// face is the part of the loop running forward from x to y; returns it (null if open).
    result<F> chain(F face, V x, const std::vector<vec3<double>>& pts, const V* y, std::vector<V>& made) {
        auto corner = into_vertex<M, T>(m, face, x);
        const auto cy = y ? into_vertex<M, T>(m, face, *y) : T::null_halfedge();
        for (const auto& p : pts) {
            const auto r = mev<M, T>(m, corner, g.place(p));
            if (!r) return r.error();
            made.push_back(r.value().vertex);
            out.vertices.push_back(r.value().vertex);
            corner = r.value().halfedge;
        }
        if (!y) return T::null_face();
        const auto nf = mef<M, T>(m, corner, cy);
        if (!nf) return nf.error();
        out.faces.push_back(nf.value().face);
        return nf.value().face;
    }
};

/// Even n: the inner paths are spokes to one centre vertex. Spoke 0 is an antenna ending in
/// the centre; each further spoke closes patch i - 1.
template <class M, class T>
result<void> grid_fill_spokes(grid_fill_builder<M, T>& b,
                              const std::vector<std::vector<typename T::vertex_handle>>& arcs) {
    const auto& g = b.g;
    const std::size_t k = g.k, h = g.h;
    b.lv[0].push_back(arcs[0][h]);
    if (auto r = b.chain(b.rest, arcs[0][h], slice(g.lp[0], 1, h + 1), nullptr, b.lv[0]); !r) return r.error();
    const auto o = b.lv[0][h];
    for (std::size_t i = 1; i < k; ++i) {
        b.lv[i].push_back(arcs[i][h]);
        const auto nf = b.chain(b.rest, arcs[i][h], slice(g.lp[i], 1, h), &o, b.lv[i]);
        if (!nf) return nf.error();
        b.lv[i].push_back(o);
        b.patch[i - 1] = b.rest;
        b.rest = nf.value();
    }
    b.patch[k - 1] = b.rest;
    for (std::size_t i = 0; i < k; ++i) b.rv[i] = b.lv[g.nx(i)];
    return {};
}

/// Odd n: L_0 is an antenna ending at I_0; then, around: R_i closes patch i, and L_{i+1} with
/// the inner edge I_{i+1} -> I_i closes strip i + 1. What is left is strip 0 and the middle
/// k-gon, split by the edge I_{k-1} -> I_0. Each strip is then cut by its rungs.
template <class M, class T>
result<void> grid_fill_strips(grid_fill_builder<M, T>& b,
                              const std::vector<std::vector<typename T::vertex_handle>>& arcs) {
    using V = typename T::vertex_handle;
    using F = typename T::face_handle;
    const auto& g = b.g;
    const std::size_t k = g.k, h = g.h, a0 = g.a0;
    auto& lv = b.lv;
    auto& rv = b.rv;
    lv[0].push_back(arcs[0][a0]);
    if (auto r = b.chain(b.rest, arcs[0][a0], slice(g.lp[0], 1, h + 1), nullptr, lv[0]); !r) return r.error();
    for (std::size_t i = 0; i < k; ++i) {
        rv[i].push_back(arcs[g.nx(i)][h]);
        auto nf = b.chain(b.rest, arcs[g.nx(i)][h], slice(g.rp[i], 1, h), &lv[i][h], rv[i]);
        if (!nf) return nf.error();
        rv[i].push_back(lv[i][h]);
        b.patch[i] = b.rest;
        b.rest = nf.value();
        if (i + 1 == k) break;
        lv[i + 1].push_back(arcs[i + 1][a0]);
        nf = b.chain(b.rest, arcs[i + 1][a0], slice(g.lp[i + 1], 1, h + 1), &lv[i][h], lv[i + 1]);
        if (!nf) return nf.error();
        b.strip[i + 1] = b.rest;
        b.rest = nf.value();
    }
    std::vector<V> none;
    const auto s0 = b.chain(b.rest, lv[k - 1][h], {}, &lv[0][h], none);
    if (!s0) return s0.error();
    b.strip[0] = s0.value();
    // Each strip between patches i - 1 and i: rungs R_{i-1}[r] - L_i[r].
    for (std::size_t i = 0; i < k; ++i) {
        F c = b.strip[i];
        const auto& rr = rv[(i + k - 1) % k];
        for (std::size_t r = 1; r < h; ++r) {
            // Forward from L_i[r]: up L_i, across the inner edge, down R_{i-1}: the rest.
            const auto nc = b.chain(c, lv[i][r], {}, &rr[r], none);
            if (!nc) return nc.error();
            c = nc.value();
        }
    }
    return {};
}

/// Cuts patch i into quads: rows r = 1 .. h-1 from G[r][0] to G[r][h], then each row strip
/// into cells.
template <class M, class T>
result<void> grid_fill_cells(grid_fill_builder<M, T>& b,
                             const std::vector<std::vector<typename T::vertex_handle>>& arcs, std::size_t i) {
    using V = typename T::vertex_handle;
    using F = typename T::face_handle;
    const auto& gl = b.g;
    const std::size_t h = gl.h, a0 = gl.a0;
    std::vector<std::vector<V>> g(h + 1, std::vector<V>(h + 1));
    for (std::size_t s = 0; s <= h; ++s) {
        g[0][s] = arcs[i][a0 + s];
        g[h][s] = b.rv[i][h - s];
    }
    for (std::size_t r = 0; r <= h; ++r) {
        g[r][h] = arcs[gl.nx(i)][r];
        g[r][0] = b.lv[i][r];
    }
    F c = b.patch[i];
    std::vector<F> rows(h);  // rows[r]: between grid rows r and r + 1
    for (std::size_t r = 1; r < h; ++r) {
        std::vector<V> made{g[r][0]};
        // Forward from G[r][0] runs back up to row 0: the new face is the row strip r - 1.
        const auto row = b.chain(c, g[r][0], slice(gl.gp[i][r], 1, h), &g[r][h], made);
        if (!row) return row.error();
        rows[r - 1] = row.value();
        for (std::size_t s = 1; s < h; ++s) g[r][s] = made[s];
    }
    rows[h - 1] = c;
    std::vector<V> none;
    for (std::size_t r = 0; r < h; ++r) {
        F cell = rows[r];
        // Forward from G[r][s] runs to the row's far end and back: the new face is the rest.
        for (std::size_t s = 1; s < h; ++s) {
            const auto next_cell = b.chain(cell, g[r][s], {}, &g[r + 1][s], none);
            if (!next_cell) return next_cell.error();
            cell = next_cell.value();
        }
    }
    return {};
}

/// Fills face f, whose loop is k >= 3 arcs of n >= 2 segments, with quads (and, for odd n,
/// one k-gon in the middle). arcs[i] holds arc i's vertices A_i[0..n] in f's loop order, with
/// A_i[n] = A_{i+1}[0] (the corners). With m = floor(n / 2), each corner A_i[n] gets an m x m
/// patch of quads, bounded by the arcs' halves and two inner paths of m segments:
/// - n even: the paths are spokes from the arc midpoints A_i[m] to one centre vertex;
/// - n odd: patch i's paths end at an inner vertex I_i; between patches, along each arc's
///   middle segment, lies a strip of m quads, and the I_i bound the middle k-gon.
/// Positions: see grid_fill_positions; everything is projected onto fit_sphere(boundary) when
/// that fit is accepted.
/// Built from makeEV chains (antennas into the face) closed by makeEF; every halfedge is found
/// by walking the current face: O(k n^3) at worst (O(k n^2) new elements). Run inside a
/// transaction (T journaled); an inner failure is passed on.
template <class M, class T>
result<grid_fill_result<M, T>> grid_fill(M& m, typename T::face_handle f,
                                         const std::vector<std::vector<typename T::vertex_handle>>& arcs) {
    grid_fill_result<M, T> out;
    const auto layout = grid_fill_positions<M, T>(m, arcs);
    const std::size_t k = layout.k;
    grid_fill_builder<M, T> b{m, layout, out, {}, {}, {}, {}, f};
    b.lv.resize(k);
    b.rv.resize(k);
    b.patch.resize(k);
    b.strip.resize(k);
    if (auto ok = layout.odd ? grid_fill_strips<M, T>(b, arcs) : grid_fill_spokes<M, T>(b, arcs); !ok)
        return ok.error();
    for (std::size_t i = 0; i < k; ++i)
        if (auto ok = grid_fill_cells<M, T>(b, arcs, i); !ok) return ok.error();
    return out;
}

}  // namespace hmira::detail::editing
