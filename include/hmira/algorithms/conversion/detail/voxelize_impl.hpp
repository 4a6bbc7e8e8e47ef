// hmira/algorithms/conversion/detail/voxelize_impl.hpp
// The machinery of voxelize() (see ../voxelize.hpp for the interface): the mesh's triangles in
// voxel units, the surface walk over columns of voxels, the parity fill by ray crossings over
// bit-packed rows, the winding-number fill of open meshes, and the slabs that run in parallel.
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
#include <type_traits>
#include <vector>

#include "../../../concepts.hpp"
#include "../../../core/progress.hpp"
#include "../../../core/result.hpp"
#include "../../../core/vec3.hpp"
#include "../../../grids/bit_grid.hpp"
#include "../../../grids/voxel_grid.hpp"
#include "../../spatial/detail/solid_angle.hpp"
#include "../voxelize.hpp"
#include "parallel.hpp"
#include "voxel_surface.hpp"
#include "voxel_crossings.hpp"

namespace hmira {

namespace detail::vox {

/// A 64-bit hash finaliser (splitmix64's): edge hashes XORed together cancel in pairs, so
/// their XOR is 0 when every edge is used by an even number of faces.
inline std::uint64_t mix(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

/// The signed solid angle of a triangle seen from the origin (spatial/detail/solid_angle.hpp).
using detail::spatial::solid_angle;

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
                    return fail(
                        errc::invalid_argument,
                        "voxelize: vertex " + std::to_string(T::vertex_index(mesh, v)) + " has a non-finite position",
                        static_cast<long long>(T::vertex_index(mesh, v)));
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
                    return fail(errc::degenerate_face,
                                "voxelize: a face uses vertex " + std::to_string(ids[a]) + " twice",
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
                    return fail(errc::degenerate_face,
                                "voxelize: triangle " + std::to_string(out.tris.size()) +
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
inline slab_bins bin_to_slabs(const std::vector<tri>& tris, const std::vector<std::uint32_t>* subset, long long z0,
                              long long nz, long long layers) {
    const std::size_t count = subset ? subset->size() : tris.size();
    const long long slabs = (nz + layers - 1) / layers;
    auto slab_range = [&](const tri& t, long long& s0, long long& s1) {
        const double zl = std::min({t.p[0].z, t.p[1].z, t.p[2].z}), zh = std::max({t.p[0].z, t.p[1].z, t.p[2].z});
        const long long k0 = std::max<long long>(0, fast_floor(zl) - 1 - z0),
                        k1 = std::min<long long>(nz - 1, fast_floor(zh) + 2 - z0);
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

/// Prefix XOR within a word: bit i becomes the XOR of bits 0 .. i.
inline std::uint64_t prefix_xor(std::uint64_t x) {
    x ^= x << 1;
    x ^= x << 2;
    x ^= x << 4;
    x ^= x << 8;
    x ^= x << 16;
    return x ^ (x << 32);
}

/// Turns the crossing marks of one row into inside bits by a prefix XOR along it. Words before
/// the row's first mark (word a) stay empty; those between its marks mostly hold none and take
/// only the carry; after its last mark (word e) the row is inside to its end only where a
/// window cut off crossings beyond it (a closed surface's row otherwise ends outside). `last`
/// masks the grid's bits of the row's last word.
inline void prefix_xor_row(std::uint64_t* row, std::size_t a, std::size_t e, std::size_t words, std::uint64_t last) {
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

/// One fill_window() call: the window, its slabs and the triangles binned to them.
struct window_fill {
    const std::vector<tri>& tris;
    const std::array<long long, 3>& lo;
    bit_grid& out;
    const window_job& job;
    grid_dims dims;
    long long nx, ny, nz;
    std::size_t words;
    long long layers;  // z-layers per slab
    std::size_t slabs;
    slab_bins surface_bins, own_crossing_bins;
    const slab_bins* crossing_bins;
    bit_sink set_voxel;

    window_fill(const std::vector<tri>& tris_, const std::vector<std::uint32_t>* surface_subset,
                const std::vector<std::uint32_t>* crossing_subset, const std::array<long long, 3>& lo_, bit_grid& out_,
                const window_job& job_)
        : tris(tris_), lo(lo_), out(out_), job(job_), dims(out_.dims()) {
        nx = static_cast<long long>(dims[0]);
        ny = static_cast<long long>(dims[1]);
        nz = static_cast<long long>(dims[2]);
        words = out.words_per_row();
        layers = std::clamp<long long>(
            static_cast<long long>((std::size_t(1) << 17) / std::max<std::size_t>(1, words * dims[1])), 1, nz);
        slabs = std::size_t((nz + layers - 1) / layers);
        if (job.surface) surface_bins = bin_to_slabs(tris, surface_subset, lo[2], nz, layers);
        const bool shared = job.surface && surface_subset == crossing_subset;  // one set of bins serves both passes
        if (job.crossings && !shared) own_crossing_bins = bin_to_slabs(tris, crossing_subset, lo[2], nz, layers);
        crossing_bins = shared ? &surface_bins : &own_crossing_bins;
        set_voxel = bit_sink{out.words().data(), words, words * dims[1], {lo[0], lo[1], lo[2]}};
    }

    /// Progress counts triangle visits and rows.
    std::size_t progress_total() const {
        const std::size_t rows = dims[1] * dims[2];
        return surface_bins.tri.size() + (job.crossings ? crossing_bins->tri.size() + rows : 0) +
               (job.winding ? rows : 0);
    }

    /// Window layers [k0, k1] of slab s: crossings, prefix XOR, then surface voxels. The slab's
    /// words are cleared here, not when the grid was made: so they are in this core's cache
    /// for what follows.
    void fill_slab(std::size_t s, progress_gate& gate) {
        const long long k0 = static_cast<long long>(s) * layers, k1 = std::min(nz, k0 + layers) - 1;
        const auto slab_words =
            out.words().subspan(std::size_t(k0) * dims[1] * words, std::size_t(k1 - k0 + 1) * dims[1] * words);
        std::fill(slab_words.begin(), slab_words.end(), std::uint64_t(0));
        if (job.crossings && !fill_crossings(s, k0, k1, gate)) return;
        if (job.surface) add_surface(s, k0, k1, gate);
    }

    /// Ray crossings: voxels beyond a crossing along x change side. Each row of the slab notes
    /// the first and last word its marks fall in, [span_first, span_last], so that the prefix
    /// pass skips the words (and rows) that hold none. False when cancelled.
    bool fill_crossings(std::size_t s, long long k0, long long k1, progress_gate& gate) {
        std::uint64_t* toggles = out.words().data();
        const std::size_t first_row = std::size_t(k0) * dims[1], slab_rows = std::size_t(k1 - k0 + 1) * dims[1];
        std::vector<std::uint32_t> span_first(slab_rows, std::numeric_limits<std::uint32_t>::max()),
            span_last(slab_rows, 0);
        const slab_bins& bins = *crossing_bins;
        for (std::size_t b = bins.start[s]; b < bins.start[s + 1]; ++b) {
            if ((b - bins.start[s]) % 1024 == 0 && !gate.advance(std::min<std::size_t>(1024, bins.start[s + 1] - b)))
                return false;
            const tri& tr = tris[bins.tri[b]];
            const crossing_triangle ct(tr.p[0], tr.p[1], tr.p[2]);
            if (ct.xmin - 1 >= double(lo[0] + nx)) continue;  // crosses no ray before the window's end
            ct.for_each_ray(lo[1], lo[1] + ny - 1, lo[2] + k0, lo[2] + k1,
                            [&](long long j, long long k, const crossing_triangle::row_estimate& row) {
                                const long long first = ct.first_beyond(row, j, k) - lo[0];
                                if (first >= nx) return;
                                const std::size_t i = first <= 0 ? 0 : static_cast<std::size_t>(first);
                                const std::size_t r =
                                    std::size_t(k - lo[2]) * dims[1] + std::size_t(j - lo[1]) - first_row;
                                toggles[(first_row + r) * words + (i >> 6)] ^= std::uint64_t(1) << (i & 63);
                                const auto w = static_cast<std::uint32_t>(i >> 6);
                                span_first[r] = std::min(span_first[r], w);
                                span_last[r] = std::max(span_last[r], w);
                            });
        }
        const std::uint64_t last = (dims[0] & 63) ? (std::uint64_t(1) << (dims[0] & 63)) - 1 : ~std::uint64_t(0);
        for (std::size_t r = 0; r < slab_rows; ++r) {
            const std::size_t a = span_first[r], e = span_last[r];
            if (a > e) continue;  // no mark: the row stays empty
            prefix_xor_row(toggles + (first_row + r) * words, a, e, words, last);
        }
        return gate.advance(slab_rows);
    }

    /// Surface voxels of slab s (most are found set already inside a solid).
    void add_surface(std::size_t s, long long k0, long long k1, progress_gate& gate) const {
        for (std::size_t b = surface_bins.start[s]; b < surface_bins.start[s + 1]; ++b) {
            if ((b - surface_bins.start[s]) % 1024 == 0 &&
                !gate.advance(std::min<std::size_t>(1024, surface_bins.start[s + 1] - b)))
                return;
            const tri& tr = tris[surface_bins.tri[b]];
            const long long wlo[3] = {lo[0], lo[1], lo[2] + k0}, whi[3] = {lo[0] + nx - 1, lo[1] + ny - 1, lo[2] + k1};
            if (!tr.degenerate) surface_voxels(tr, wlo, whi, set_voxel);
        }
    }

    /// The winding-number fill of an open mesh. Between two surface voxels along a row the side
    /// cannot change without crossing the surface, except through a hole: one winding number
    /// per run of empty voxels.
    void fill_by_winding(progress_gate& gate) {
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
                    const vec3<double> c{double(s0) + double(lo[0]), double(j) + double(lo[1]),
                                         double(k) + double(lo[2])};
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
};

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
/// Slabs of 1 MiB rather than less: fewer triangles are cut in several slabs (each prepared
/// once per slab), while a 512^3 grid still has 19 slabs to share out.
inline bool fill_window(const std::vector<tri>& tris, const std::vector<std::uint32_t>* surface_subset,
                        const std::vector<std::uint32_t>* crossing_subset, const std::array<long long, 3>& lo,
                        bit_grid& out, const window_job& job, unsigned threads, const progress_function& progress) {
    window_fill w(tris, surface_subset, crossing_subset, lo, out, job);
    progress_gate gate(progress, w.progress_total());
    with_thread_count(threads, [&] {
        parallel_chunks(w.slabs, 1, [&](std::size_t s0, std::size_t s1) {
            for (std::size_t s = s0; s < s1 && !gate.cancelled(); ++s) w.fill_slab(s, gate);
        });
        if (gate.cancelled()) return;
        if (job.winding) w.fill_by_winding(gate);
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
        if (options.open_mesh == open_mesh_fill::fail)
            return fail(errc::topology, "voxelize: " + mode + " mode: " + why);
        job.surface = true;
        if (options.open_mesh == open_mesh_fill::surface_only) {
            filled = false;
            note = mode + " fill skipped: " + why + "; surface voxels only";
        } else {
            job.winding = true;
            note = why + "; filled by generalized winding number" +
                   (options.mode == voxelize_mode::centres ? std::string(", with the surface voxels (conservative)")
                                                           : std::string());
        }
        return job;
    }
    job.crossings = fill;
    return job;
}

}  // namespace detail::vox

template <class M, class T>
    requires voxelize_mesh<M, T>
result<voxelization> voxelize(const M& mesh, const grid_geometry& grid, const voxelize_options& options) {
    if (auto ok = check_grid_geometry(grid, "voxelize"); !ok) return ok.error();
    auto g = detail::vox::gather<M, T>(mesh, grid, options.allow_degenerate);
    if (!g) return g.error();
    voxelization out{bit_grid::unwritten(grid), false, {}, g->tris.size(), g->degenerate};
    auto job = detail::vox::plan(options, g->closed, out.note, out.filled);
    if (!job) return job.error();
    if (!detail::vox::fill_window(g->tris, nullptr, nullptr, {0, 0, 0}, out.voxels, *job, options.threads,
                                  options.progress))
        return fail(errc::cancelled, "voxelize: cancelled");
    return out;
}

template <class M, class T, writable_voxel_grid G>
    requires voxelize_mesh<M, T>
result<voxelization> voxelize_into(const M& mesh, G& grid, const voxelize_options& options) {
    auto v = voxelize<M, T>(mesh, geometry_of(grid), options);
    if (!v) return v.error();
    const auto d = grid.dims();
    for (std::size_t k = 0; k < d[2]; ++k)
        for (std::size_t j = 0; j < d[1]; ++j)
            for (std::size_t i = 0; i < d[0]; ++i)
                grid.set(i, j, k, static_cast<typename G::value_type>(v->voxels.value(i, j, k)));
    return v;
}

template <class M, class T>
    requires positioned_mesh<M, T>
result<grid_geometry> voxel_grid_around(const M& mesh, std::size_t resolution, std::size_t padding) {
    if (resolution == 0) return fail(errc::invalid_argument, "voxel_grid_around: resolution must be at least 1");
    vec3<double> lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
                    std::numeric_limits<double>::max()};
    vec3<double> hi = -lo;
    bool any = false;
    for (auto v : T::vertices(mesh)) {
        const vec3<typename T::scalar> p = T::position(mesh, v);
        for (std::size_t a = 0; a < 3; ++a) {
            if (!std::isfinite(double(p[a])))
                return fail(errc::invalid_argument, "voxel_grid_around: a vertex position is not finite");
            lo[a] = std::min(lo[a], double(p[a]));
            hi[a] = std::max(hi[a], double(p[a]));
        }
        any = true;
    }
    if (!any) return fail(errc::invalid_argument, "voxel_grid_around: the mesh has no vertices");
    const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
    if (!std::isfinite(extent))
        return fail(errc::unsupported,
                    "voxel_grid_around: the mesh spans more than the largest double along an axis; "
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

inline std::uint64_t voxelize_memory_estimate(const grid_geometry& grid, std::size_t triangles) {
    const double words = std::ceil(double(grid.dims[0]) / 64.0) * double(grid.dims[1]) * double(grid.dims[2]);
    const double bytes = 8.0 * words + 96.0 * double(triangles);
    return bytes >= 0x1p64 ? std::numeric_limits<std::uint64_t>::max() : static_cast<std::uint64_t>(bytes);
}

}  // namespace hmira
