// hmira/algorithms/conversion/voxelize.hpp
// Turns a mesh into voxels (thesis 2.3.2, 8.4): the voxels its surface touches (conservative,
// exact triangle-box test), and for a closed mesh also the voxels inside it (parity of ray
// crossings over bit-packed rows). Generic over the mesh; parallel and deterministic.
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/progress.hpp"
#include "../../core/result.hpp"
#include "../../core/vec3.hpp"
#include "../../grids/bit_grid.hpp"
#include "../../grids/voxel_grid.hpp"
#include "detail/parallel.hpp"
#include "detail/triangle_box.hpp"

namespace hmira {

/// surface: the voxels the surface touches. solid: those plus every voxel whose centre lies
/// inside the mesh.
enum class voxelize_mode { surface, solid };

/// What solid mode does with a mesh that is not closed (some edge has an odd number of faces).
enum class open_mesh_fill {
    surface_only,    ///< voxelize the surface only and say so in the result (the thesis's choice)
    winding_number,  ///< fill where the generalized winding number is at least 1/2
    fail,            ///< return an error
};

/// Options of voxelize() and voxelize_into().
struct voxelize_options {
    voxelize_mode mode = voxelize_mode::solid;                ///< surface voxels only, or also the interior
    open_mesh_fill open_mesh = open_mesh_fill::surface_only;  ///< what solid mode does with a mesh that is not closed
    /// Accept zero-area triangles (all corners collinear) instead of reporting them; they add
    /// no surface voxels of their own. Faces with a repeated vertex are always an error.
    bool allow_degenerate = false;
    /// Worker threads (0: all available). The output does not depend on it.
    unsigned threads = 0;
    /// Called between blocks of triangles and of rows; returning false cancels the
    /// voxelization (error errc::unsupported, "voxelize: cancelled").
    progress_function progress = {};
};

/// The voxels, and how they were made.
struct voxelization {
    bit_grid voxels;  ///< the set voxels, on the requested grid
    /// True when the interior was filled (solid mode on a closed mesh, or by winding number).
    bool filled = false;
    /// Empty, or why solid mode did something else than asked (an open mesh).
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

// Fixed-point (1/1024 voxel) coordinates for the crossing test: the orientation predicates
// below are then exact in 64-bit integers, so a ray through a shared edge or vertex meets
// exactly one of the triangles around it.
constexpr double fixed_scale = 1024.0;
constexpr double fixed_limit = double(1 << 19);  // voxels; keeps products below 2^62

inline long long to_fixed(double v) {
    return std::llround(std::clamp(v, -fixed_limit, fixed_limit) * fixed_scale);
}

struct point2 {
    long long y, z;
};

// Orientation of p against the segment u -> v, exactly antisymmetric in (u, v) and broken
// for p on the line by a symbolic shift of p by (eps, eps^2) in (y, z).
inline int side(point2 u, point2 v, point2 p) {
    bool flip = false;
    if (v.y < u.y || (v.y == u.y && v.z < u.z)) {
        std::swap(u, v);
        flip = true;
    }
    const long long ey = v.y - u.y, ez = v.z - u.z;
    const long long w = ey * (p.z - u.z) - ez * (p.y - u.y);
    int s = w > 0 ? 1 : (w < 0 ? -1 : 0);
    if (s == 0) {
        // d/deps of ey * (eps^2) - ez * eps: the eps term dominates unless ez == 0.
        s = ez != 0 ? (ez > 0 ? -1 : 1) : (ey > 0 ? 1 : (ey < 0 ? -1 : 0));
    }
    return flip ? -s : s;
}

inline double solid_angle(vec3<double> a, vec3<double> b, vec3<double> c) {
    const double la = norm(a), lb = norm(b), lc = norm(c);
    const double num = dot(a, cross(b, c));
    const double den = la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb;
    return 2 * std::atan2(num, den);
}

}  // namespace detail::vox

/// Voxelizes `mesh` into a bit grid of geometry `grid` (sample (i, j, k) = centre of voxel
/// (i, j, k), voxel = the box of one spacing around it). Polygons are fanned into triangles.
///
/// - Surface voxels: every voxel whose closed box meets a triangle, by an exact separating-axis
///   test (conservative voxelization).
/// - Solid mode on a closed mesh (every edge used by an even number of faces, checked by an
///   XOR of edge hashes): also every voxel whose centre lies inside, by the parity of the
///   crossings of a ray along x, counted with exact fixed-point predicates so that rays through
///   edges and vertices count once. On a mesh that is not closed, see voxelize_options.
/// - Parallel over triangles (bits set by atomic OR / XOR, which commute) and rows: the output
///   is the same for every thread count.
///
/// Complexity: O(F + sum over triangles of the voxels in their bounding box) for the surface,
/// plus O(sum of the rays each triangle's shadow covers + N/64) for the fill; the winding
/// number fill costs O(F) per run of empty voxels along each row.
/// Errors (nothing is returned but the error): invalid_argument for an unusable grid (zero
/// dimension, spacing not positive) or a non-finite vertex position; degenerate_face for a face
/// with fewer than 3 vertices or a repeated vertex, and for a zero-area triangle unless
/// allow_degenerate; topology when solid mode meets an open mesh with open_mesh = fail.
template <class M, class T = default_traits<M>>
    requires voxelize_mesh<M, T>
result<voxelization> voxelize(const M& mesh, const grid_geometry& grid, const voxelize_options& options = {}) {
    using detail::vox::tri;
    if (auto ok = check_grid_geometry(grid, "voxelize"); !ok) return ok.error();
    const std::size_t nx = grid.dims[0], ny = grid.dims[1], nz = grid.dims[2];

    // Gather triangles in voxel units, and hash the edges for the closedness check.
    std::vector<tri> tris;
    tris.reserve(T::face_count(mesh) * 2);
    std::uint64_t edge_parity = 0;
    std::size_t degenerate = 0;
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
                q[a] = (double(p[a]) - grid.origin[a]) / grid.spacing[a];
            }
            loop.push_back(q);
            ids.push_back(T::vertex_index(mesh, v));
        }
        const std::size_t n = loop.size();
        const long long fi = static_cast<long long>(tris.size());
        if (n < 3) return fail(errc::degenerate_face, "voxelize: a face has " + std::to_string(n) + " vertices", fi);
        for (std::size_t a = 0; a < n; ++a)
            for (std::size_t b = a + 1; b < n; ++b)
                if (ids[a] == ids[b])
                    return fail(errc::degenerate_face, "voxelize: a face uses vertex " + std::to_string(ids[a]) + " twice",
                                static_cast<long long>(ids[a]));
        for (std::size_t a = 0; a < n; ++a) {
            const std::uint64_t u = ids[a], w = ids[(a + 1) % n];
            edge_parity ^= detail::vox::mix((std::min(u, w) << 32) ^ std::max(u, w) ^ (std::min(u, w) >> 32));
        }
        for (std::size_t a = 1; a + 1 < n; ++a) {
            tri t{{loop[0], loop[a], loop[a + 1]}, false};
            const auto c = cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
            if (c.x == 0 && c.y == 0 && c.z == 0) {
                if (!options.allow_degenerate)
                    return fail(errc::degenerate_face, "voxelize: triangle " + std::to_string(tris.size()) +
                                                           " has zero area (set allow_degenerate to accept it)",
                                static_cast<long long>(tris.size()));
                t.degenerate = true;
                ++degenerate;
            }
            tris.push_back(t);
        }
    }
    const bool closed = edge_parity == 0;
    bool fill = options.mode == voxelize_mode::solid;
    bool winding = false;
    voxelization out{bit_grid(grid), false, {}, tris.size(), degenerate};
    if (fill && !closed) {
        const std::string why = "the mesh is not closed (an edge has an odd number of faces)";
        if (options.open_mesh == open_mesh_fill::fail) return fail(errc::topology, "voxelize: solid mode: " + why);
        if (options.open_mesh == open_mesh_fill::surface_only) {
            fill = false;
            out.note = "solid fill skipped: " + why + "; surface voxels only";
        } else {
            winding = true;
            out.note = why + "; filled by generalized winding number";
        }
    }

    bit_grid& vox = out.voxels;
    const std::size_t words = vox.words_per_row();
    std::vector<std::uint64_t> toggles(fill && !winding ? words * ny * nz : 0, 0);
    // floor and ceil without a libm call (the x86-64 baseline has no roundsd); the clamp to
    // +-2^40 keeps the conversion defined for far-away geometry.
    auto fast_floor = [](double x) {
        x = std::clamp(x, -1099511627776.0, 1099511627776.0);
        const auto i = static_cast<long long>(x);
        return i - (double(i) > x);
    };
    auto clamp_index = [&](double lo, double hi, std::size_t n, long long& a, long long& b) {
        a = std::max<long long>(0, -fast_floor(-lo));
        b = std::min<long long>(static_cast<long long>(n) - 1, fast_floor(hi));
        return a <= b;
    };

    auto set_voxel = [&](long long i, long long j, long long k) {
        // Neighbouring triangles share most voxels: read first, and pay for the atomic OR only
        // when the bit is still clear.
        std::atomic_ref<std::uint64_t> word(vox.row(std::size_t(j), std::size_t(k))[std::size_t(i) >> 6]);
        const std::uint64_t bit = std::uint64_t(1) << (std::size_t(i) & 63);
        if (!(word.load(std::memory_order_relaxed) & bit)) word.fetch_or(bit, std::memory_order_relaxed);
    };
    // The voxels a triangle touches: walk the columns along the normal's dominant axis d; in
    // each column only the few voxels within the plane's range over the column can touch it.
    auto surface_voxels = [&](const tri& tr, const vec3<double>& lo, const vec3<double>& hi) {
        long long r0[3], r1[3];
        for (std::size_t a = 0; a < 3; ++a)
            if (!clamp_index(lo[a] - 0.5, hi[a] + 0.5, grid.dims[a], r0[a], r1[a])) return;
        if (r0[0] == r1[0] && r0[1] == r1[1] && r0[2] == r1[2]) {  // inside one voxel's box
            set_voxel(r0[0], r0[1], r0[2]);
            return;
        }
        const vec3<double> n = cross(tr.p[1] - tr.p[0], tr.p[2] - tr.p[0]);
        const std::size_t d = std::abs(n.x) >= std::abs(n.y) ? (std::abs(n.x) >= std::abs(n.z) ? 0 : 2) : (std::abs(n.y) >= std::abs(n.z) ? 1 : 2);
        const std::size_t u = (d + 1) % 3, v = (d + 2) % 3;
        const double c = dot(n, tr.p[0]);
        const double slack = 0.5 * (std::abs(n[u]) + std::abs(n[v])) / std::abs(n[d]);
        const detail::triangle_box_tester tester(tr.p[0], tr.p[1], tr.p[2], 0.5);
        long long idx[3];
        for (long long iu = r0[u]; iu <= r1[u]; ++iu)
            for (long long iv = r0[v]; iv <= r1[v]; ++iv) {
                const double w = (c - n[u] * double(iu) - n[v] * double(iv)) / n[d];
                long long w0, w1;
                if (!clamp_index(std::max(w - slack, lo[d]) - 0.5, std::min(w + slack, hi[d]) + 0.5, grid.dims[d], w0, w1)) continue;
                w0 = std::max(w0, r0[d]);
                w1 = std::min(w1, r1[d]);
                idx[u] = iu;
                idx[v] = iv;
                for (long long iw = w0; iw <= w1; ++iw) {
                    idx[d] = iw;
                    if (tester.overlaps({double(idx[0]), double(idx[1]), double(idx[2])}))
                        set_voxel(idx[0], idx[1], idx[2]);
                }
            }
    };

    const std::size_t row_blocks = fill ? ny * nz : 0;
    detail::progress_gate gate(options.progress, tris.size() + row_blocks);
    detail::with_thread_count(options.threads, [&] {
        // Surface voxels and ray crossings, one triangle at a time.
        detail::parallel_chunks(tris.size(), 1024, [&](std::size_t t0, std::size_t t1) {
            for (std::size_t t = t0; t < t1; ++t) {
                if ((t - t0) % 1024 == 0 && !gate.advance(std::min<std::size_t>(1024, t1 - t))) return;
                const auto& tr = tris[t];
                vec3<double> lo = tr.p[0], hi = tr.p[0];
                for (int c = 1; c < 3; ++c)
                    for (std::size_t a = 0; a < 3; ++a) {
                        lo[a] = std::min(lo[a], tr.p[c][a]);
                        hi[a] = std::max(hi[a], tr.p[c][a]);
                    }
                long long j0, j1, k0, k1;
                if (!tr.degenerate) surface_voxels(tr, lo, hi);
                if (toggles.empty()) continue;
                // Rays along x through voxel centres (j, k) inside the triangle's shadow.
                using detail::vox::point2;
                const point2 q[3] = {{detail::vox::to_fixed(tr.p[0].y), detail::vox::to_fixed(tr.p[0].z)},
                                     {detail::vox::to_fixed(tr.p[1].y), detail::vox::to_fixed(tr.p[1].z)},
                                     {detail::vox::to_fixed(tr.p[2].y), detail::vox::to_fixed(tr.p[2].z)}};
                const long long area = (q[1].y - q[0].y) * (q[2].z - q[0].z) - (q[1].z - q[0].z) * (q[2].y - q[0].y);
                if (area == 0) continue;  // seen edge-on: no ray crosses it (after the symbolic shift)
                const int orient = area > 0 ? 1 : -1;
                const double s = detail::vox::fixed_scale;
                if (!clamp_index(double(std::min({q[0].y, q[1].y, q[2].y})) / s, double(std::max({q[0].y, q[1].y, q[2].y})) / s, ny, j0, j1) ||
                    !clamp_index(double(std::min({q[0].z, q[1].z, q[2].z})) / s, double(std::max({q[0].z, q[1].z, q[2].z})) / s, nz, k0, k1))
                    continue;
                for (long long k = k0; k <= k1; ++k)
                    for (long long j = j0; j <= j1; ++j) {
                        const point2 p{j * 1024, k * 1024};
                        if (detail::vox::side(q[1], q[2], p) != orient || detail::vox::side(q[2], q[0], p) != orient ||
                            detail::vox::side(q[0], q[1], p) != orient)
                            continue;
                        // Where the ray meets the triangle's plane (barycentric in y, z).
                        const auto& a = tr.p[0];
                        const auto e1 = tr.p[1] - a, e2 = tr.p[2] - a;
                        const double det = e1.y * e2.z - e1.z * e2.y;
                        double x;
                        if (det != 0) {
                            const double dy = double(j) - a.y, dz = double(k) - a.z;
                            const double u = (dy * e2.z - dz * e2.y) / det, v = (e1.y * dz - e1.z * dy) / det;
                            x = a.x + u * e1.x + v * e2.x;
                        } else {
                            x = (a.x + tr.p[1].x + tr.p[2].x) / 3;  // edge-on in doubles, not in fixed point
                        }
                        // Voxels with centre beyond the crossing change side.
                        const double first = double(fast_floor(x)) + 1;
                        if (first >= double(nx)) continue;
                        const std::size_t i = first <= 0 ? 0 : static_cast<std::size_t>(first);
                        std::atomic_ref<std::uint64_t>(toggles[(std::size_t(k) * ny + std::size_t(j)) * words + (i >> 6)])
                            .fetch_xor(std::uint64_t(1) << (i & 63), std::memory_order_relaxed);
                    }
            }
        });

        if (gate.cancelled()) return;
        if (fill && !winding) {
            // Prefix XOR along each row turns crossing marks into inside bits.
            const std::uint64_t last = (nx & 63) ? (std::uint64_t(1) << (nx & 63)) - 1 : ~std::uint64_t(0);
            detail::parallel_chunks(ny * nz, 256, [&](std::size_t r0, std::size_t r1) {
                for (std::size_t r = r0; r < r1; ++r) {
                    if ((r - r0) % 256 == 0 && !gate.advance(std::min<std::size_t>(256, r1 - r))) return;
                    std::uint64_t carry = 0;
                    std::uint64_t* tg = &toggles[r * words];
                    std::uint64_t* row = vox.row(r % ny, r / ny);
                    for (std::size_t w = 0; w < words; ++w) {
                        std::uint64_t x = tg[w];
                        x ^= x << 1;
                        x ^= x << 2;
                        x ^= x << 4;
                        x ^= x << 8;
                        x ^= x << 16;
                        x ^= x << 32;
                        if (carry) x = ~x;
                        carry = x >> 63;
                        if (w + 1 == words) x &= last;
                        row[w] |= x;
                    }
                }
            });
        }
        if (winding) {
            // Between two surface voxels along a row the side cannot change without crossing
            // the surface, except through a hole: one winding number per run of empty voxels.
            const double four_pi = 4 * std::numbers::pi;
            detail::parallel_chunks(ny * nz, 16, [&](std::size_t r0, std::size_t r1) {
                for (std::size_t r = r0; r < r1 && gate.advance(); ++r) {
                    const std::size_t j = r % ny, k = r / ny;
                    std::uint64_t* row = vox.row(j, k);
                    std::vector<std::size_t> starts;
                    for (std::size_t i = 0; i < nx; ++i) {
                        const bool set = (row[i >> 6] >> (i & 63)) & 1;
                        const bool prev = i > 0 && ((row[(i - 1) >> 6] >> ((i - 1) & 63)) & 1);
                        if (!set && (i == 0 || prev)) starts.push_back(i);
                    }
                    for (std::size_t s0 : starts) {
                        const vec3<double> c{double(s0), double(j), double(k)};
                        double w = 0;
                        for (const auto& tr : tris) w += detail::vox::solid_angle(tr.p[0] - c, tr.p[1] - c, tr.p[2] - c);
                        if (w / four_pi < 0.5) continue;
                        std::size_t i = s0;
                        for (; i < nx && !((row[i >> 6] >> (i & 63)) & 1); ++i) {}
                        for (std::size_t q = s0; q < i; ++q) row[q >> 6] |= std::uint64_t(1) << (q & 63);
                    }
                }
            });
        }
    });
    if (gate.cancelled()) return fail(errc::unsupported, "voxelize: cancelled");
    out.filled = fill;
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
