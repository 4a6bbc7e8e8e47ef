// hmira/algorithms/conversion/detail/marching_cubes_extractor.hpp
// The marching cubes extractor: classifies samples into bit rows, counts each row's vertices and
// triangles, then writes them in place, each pass parallel over z-slices. Part of marching_cubes.hpp,
// which it follows (it reads marching_cubes_options and writes indexed_triangles).
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "../../../core/progress.hpp"
#include "../../../core/result.hpp"
#include "../../../core/uninitialized_vector.hpp"
#include "../../../core/vec3.hpp"
#include "../../../grids/voxel_grid.hpp"
#include "marching_cubes_bits.hpp"
#include "marching_cubes_table.hpp"
#include "parallel.hpp"

namespace hmira::detail::mc {

/// Where a block writes straight into the whole grid's result (marching_cubes_blocks.hpp,
/// write_block_into): the global index of the first vertex of every run of one sample row,
/// axis and chunk column, and of the first triangle of every cube row and chunk column, in the
/// whole grid's order. A block writes the vertices it owns and its triangles; the vertices on
/// its high faces are written by their owners, and their ids read from the same tables.
struct global_layout {
    const std::uint32_t* vertex_start = nullptr;    ///< at ((gk * ny + gj) * 4 + axis) * columns + column
    const std::uint32_t* triangle_start = nullptr;  ///< at (gk * ny + gj) * columns + column
    std::size_t columns = 1;                        ///< chunks along x
    std::size_t column = 0;                         ///< this block's chunk along x
    std::size_t own_x = 0, own_y = 0, own_z = 0;    ///< the block's owned samples per axis, [0, own)
    double* positions = nullptr;                    ///< 3 per vertex of the whole result
    std::uint32_t* triangles = nullptr;             ///< 3 per triangle of the whole result
    bool swap_xz = false;                           ///< write (z, y, x) and reverse triangles (C-ordered arrays)
};

/// What the counting passes of the extractor leave for the writing pass: the bit rows, the
/// crossings per row and axis, and the rows' first vertices and triangles.
struct counted_state {
    uninitialized_vector<std::uint64_t> bits;                    ///< one bit per sample, rows of whole words
    uninitialized_vector<std::uint32_t> xcount, ycount, zcount;  ///< crossed edges per row and axis
    uninitialized_vector<std::uint64_t> vbase, tbase;            ///< first vertex and triangle per row (prefix sums)
};

/// Where a block lies in a larger grid, and where the extractor records the global keys of
/// what it writes (marching_cubes_blocks.hpp), or, with `layout`, the global places it writes
/// to. Positions then use global sample indices, so they are bit for bit those of the whole grid.
struct block_tags {
    std::array<std::size_t, 3> offset{0, 0, 0};            ///< global index of the block's sample (0, 0, 0)
    std::array<std::size_t, 3> whole{0, 0, 0};             ///< dimensions of the whole grid
    std::vector<std::uint64_t>* vertex_keys = nullptr;     ///< one per output vertex
    std::vector<std::uint64_t>* triangle_cubes = nullptr;  ///< one per output triangle
    const global_layout* layout = nullptr;                 ///< write into the whole result instead
    bool count_only = false;                               ///< stop after counting (see owned_counts())
    /// The global row index of local row (j, k).
    std::size_t global_row(std::size_t j, std::size_t k) const noexcept {
        return (k + offset[2]) * whole[1] + (j + offset[1]);
    }
    /// Vertices sort by key exactly as the whole grid orders them: rows (z, y), then x-, y-,
    /// z-edges and cube centres (axis 3), each by increasing x.
    std::uint64_t vertex_key(std::size_t i, std::size_t j, std::size_t k, int axis) const noexcept {
        return ((std::uint64_t(k + offset[2]) * whole[1] + (j + offset[1])) * 4 + std::uint64_t(axis)) * whole[0] +
               (i + offset[0]);
    }
    std::uint64_t cube_key(std::size_t i, std::size_t j, std::size_t k) const noexcept {
        return (std::uint64_t(k + offset[2]) * whole[1] + (j + offset[1])) * whole[0] + (i + offset[0]);
    }
};

template <class G>
class extractor {
public:
    extractor(const G& grid, const marching_cubes_options& o) : grid_(grid), opt_(o) {
        const auto d = grid.dims();
        nx_ = d[0];
        ny_ = d[1];
        nz_ = d[2];
        words_ = (nx_ + 63) / 64;
        above_ = o.inside == iso_inside::above;
        if constexpr (contiguous_voxel_grid<G>) data_ = grid.data();
        sy_ = nx_;
        sz_ = nx_ * ny_;
        // A block seen in place inside a larger array: rows and slices farther apart.
        if constexpr (requires { grid.strides(); }) {
            const auto st = grid.strides();
            sy_ = st[0];
            sz_ = st[1];
        }
    }
    /// Makes the extractor work as one block of a larger grid; `tags` outlives run().
    void set_block(const block_tags* tags) noexcept { tags_ = tags; }

    template <class S>
    result<indexed_triangles<S>> run() {
        const std::size_t rows = ny_ * nz_;
        const auto& table = mc::table();
        progress_gate gate(opt_.progress, 3 * nz_);
        // Counted before (count_only, then keep_counts()): only the writing pass is left.
        if (!reuse_)
            if (auto counted = count(gate); !counted) return counted.error();

        indexed_triangles<S> out;
        // No surface: an iso value outside the samples' range is refused rather than returning
        // nothing (a surface needs a sample on each side, so only an empty result can have
        // such an iso, and only then is the range read: one more pass, never on the hot path).
        if (!tags_ && vbase_[rows] == 0) {
            const auto [lo, hi] = sample_range();
            if (!(lo <= opt_.iso && opt_.iso <= hi)) return iso_outside_range(opt_.iso, lo, hi);
        }
        if (tags_ && tags_->count_only) return out;
        layout_ = tags_ ? tags_->layout : nullptr;
        // Unwritten until pass 3 writes every slot: zeroing them here would be a serial pass
        // over the whole output, which caps the parallel speed-up; left unwritten, each thread
        // takes the page faults of its own slice.
        if (!layout_) {
            out.positions.resize(vbase_[rows]);
            out.triangles.resize(tbase_[rows]);
        }
        if (opt_.normals) out.normals.resize(vbase_[rows]);
        if (tags_ && !layout_) {
            tags_->vertex_keys->resize(vbase_[rows]);
            tags_->triangle_cubes->resize(tbase_[rows]);
        }

        // Pass 3: every row writes its vertices and its cubes' triangles into the slots
        // counted above, so the output order is the same whatever the schedule.
        parallel_chunks(nz_, 1, [&](std::size_t k0, std::size_t k1) {
            scratch s(words_);
            for (std::size_t k = k0; k < k1 && gate.advance(); ++k)
                for (std::size_t j = 0; j < ny_; ++j) {
                    if (j + prefetch_distance < ny_) prefetch_row(j + prefetch_distance, k);
                    write_row_vertices(j, k, out);
                    if (j + 1 < ny_ && k + 1 < nz_) write_cube_row(j, k, s, table, out);
                }
        });
        if (gate.cancelled()) return cancelled();
        return out;
    }

    /// After run() with count_only: hands the counted rows over, so that an extractor of the
    /// same samples can write without counting again (reuse_counts()).
    void keep_counts(counted_state& state) {
        state = {std::move(bits_),   std::move(xcount_), std::move(ycount_),
                 std::move(zcount_), std::move(vbase_),  std::move(tbase_)};
    }
    /// Takes the counts keep_counts() handed over from an extractor of the same samples and
    /// options; run() then only writes.
    void reuse_counts(counted_state&& state) {
        bits_ = std::move(state.bits);
        xcount_ = std::move(state.xcount);
        ycount_ = std::move(state.ycount);
        zcount_ = std::move(state.zcount);
        vbase_ = std::move(state.vbase);
        tbase_ = std::move(state.tbase);
        reuse_ = true;
    }

    /// After run() with count_only: calls f(j, k, vertices[4], triangles) for every row (j, k)
    /// the block owns (j < own_y, k < own_z), with its owned vertices per axis (x-, y-, z-edges
    /// with i < own_x, centres) and its cube row's triangles.
    template <class F>
    void owned_counts(std::size_t own_x, std::size_t own_y, std::size_t own_z, const F& f) const {
        for (std::size_t k = 0; k < own_z && k < nz_; ++k)
            for (std::size_t j = 0; j < own_y && j < ny_; ++j) {
                const std::size_t r = k * ny_ + j;
                std::uint64_t yc = ycount_[r], zc = zcount_[r];
                // The edges at the last sample of the block lie on the next chunk along x.
                if (own_x < nx_) {
                    const std::size_t i = own_x, w = i >> 6, b = i & 63;
                    const std::uint64_t* a = row(j, k);
                    if (j + 1 < ny_) yc -= ((a[w] ^ row(j + 1, k)[w]) >> b) & 1;
                    if (k + 1 < nz_) zc -= ((a[w] ^ row(j, k + 1)[w]) >> b) & 1;
                }
                const std::uint64_t all = vbase_[r + 1] - vbase_[r];
                const std::uint64_t counts[4] = {xcount_[r], yc, zc, all - xcount_[r] - ycount_[r] - zcount_[r]};
                f(j, k, counts, tbase_[r + 1] - tbase_[r]);
            }
    }

    /// For writing several blocks row by row in turn (mc_direct::write_blocks_into): counts,
    /// unless reuse_counts() gave the counts, and prepares to write into the tags' layout;
    /// then write_layout_row(j, k) for every row writes what run() would, row by row.
    result<void> begin_layout_write() {
        if (!tags_ || !tags_->layout) return fail(errc::invalid_argument, "marching_cubes: no layout to write into");
        progress_gate gate(opt_.progress, 3 * nz_);
        if (!reuse_)
            if (auto counted = count(gate); !counted) return counted.error();
        layout_ = tags_->layout;
        row_scratch_ = std::make_unique<scratch>(words_);
        return {};
    }
    /// After begin_layout_write(): the owned vertices of row (j, k) and its cube row's
    /// triangles, into the layout (j < ny, k < nz of this block).
    void write_layout_row(std::size_t j, std::size_t k) {
        if (j + prefetch_distance < ny_) prefetch_row(j + prefetch_distance, k);
        write_row_vertices(j, k, no_output_);
        if (j + 1 < ny_ && k + 1 < nz_) write_cube_row(j, k, *row_scratch_, mc::table(), no_output_);
    }

private:
    static hmira::error cancelled() { return fail(errc::cancelled, "marching_cubes: cancelled"); }

    // The smallest and largest sample (all finite: pass 1 refused any other). O(N), parallel.
    std::pair<double, double> sample_range() const {
        constexpr double inf = std::numeric_limits<double>::infinity();
        std::vector<double> lo(nz_, inf), hi(nz_, -inf);
        parallel_chunks(nz_, 1, [&](std::size_t k0, std::size_t k1) {
            for (std::size_t k = k0; k < k1; ++k) {
                double l = lo[k], h = hi[k];
                for (std::size_t j = 0; j < ny_; ++j)
                    for (std::size_t i = 0; i < nx_; ++i) {
                        const double v = value(i, j, k);
                        l = v < l ? v : l;
                        h = v > h ? v : h;
                    }
                lo[k] = l;
                hi[k] = h;
            }
        });
        return {*std::min_element(lo.begin(), lo.end()), *std::max_element(hi.begin(), hi.end())};
    }

    // The error for the first sample in (z, y, x) order of slice k that is not finite, named by
    // its index in the whole grid, or as the grid names that index if it can
    // (sample_name(i, j, k), e.g. "volume[k, j, i]" for a view of a C-ordered array).
    // Only on this error path: a second read of one slice.
    hmira::error non_finite_sample(std::size_t k) const {
        for (std::size_t j = 0; j < ny_; ++j)
            for (std::size_t i = 0; i < nx_; ++i) {
                const double v = value(i, j, k);
                if (v - v == 0.0) continue;
                const std::size_t gi = tags_ ? i + tags_->offset[0] : i, gj = tags_ ? j + tags_->offset[1] : j,
                                  gk = tags_ ? k + tags_->offset[2] : k;
                const std::size_t wx = tags_ ? tags_->whole[0] : nx_, wy = tags_ ? tags_->whole[1] : ny_;
                std::string name;
                if constexpr (requires {
                                  { grid_.sample_name(gi, gj, gk) } -> std::convertible_to<std::string>;
                              })
                    name = grid_.sample_name(gi, gj, gk);
                else
                    name =
                        "sample (" + std::to_string(gi) + ", " + std::to_string(gj) + ", " + std::to_string(gk) + ")";
                const char* what = v != v ? "NaN" : v > 0 ? "inf" : "-inf";
                return fail(errc::invalid_argument,
                            "marching_cubes: " + name + " is " + what + "; every sample must be finite",
                            static_cast<long long>(gi + wx * (gj + wy * gk)));
            }
        return fail(errc::invalid_argument,
                    "marching_cubes: z-slice " + std::to_string(k) + " holds a sample that is not finite");
    }

    // Passes 1 and 2 of run(): classify, count, and lay out the rows' vertices and triangles.
    result<void> count(progress_gate& gate) {
        const std::size_t rows = ny_ * nz_;
        const auto& table = mc::table();
        // Unwritten here: passes 1 and 2 write every word and every row's counts, so zeroing
        // them first would only add a serial pass (N/8 bytes of bits, 28 bytes per row).
        for (auto* v : {&xcount_, &ycount_, &zcount_}) {
            v->clear();
            v->resize(rows);
        }
        bits_.clear();
        bits_.resize(rows * words_);
        vbase_.clear();
        vbase_.resize(rows + 1);
        tbase_.clear();
        tbase_.resize(rows + 1);
        vbase_[0] = tbase_[0] = 0;

        // Pass 1: classify every sample into bit rows, noting the slices holding a sample
        // that is not finite (the classification reads every sample anyway).
        std::vector<std::uint8_t> bad_in_slab(nz_, 0);
        parallel_chunks(nz_, 1, [&](std::size_t k0, std::size_t k1) {
            std::vector<double> buffer;
            for (std::size_t k = k0; k < k1 && gate.advance(); ++k)
                for (std::size_t j = 0; j < ny_; ++j) {
                    std::uint64_t* out = &bits_[(k * ny_ + j) * words_];
                    bool bad;
                    if constexpr (contiguous_voxel_grid<G>) {
                        bad = classify_row(data_ + j * sy_ + k * sz_, nx_, opt_.iso, above_, out);
                    } else {
                        buffer.resize(nx_);
                        for (std::size_t i = 0; i < nx_; ++i) buffer[i] = static_cast<double>(grid_.value(i, j, k));
                        bad = classify_row(buffer.data(), nx_, opt_.iso, above_, out);
                    }
                    if (bad) bad_in_slab[k] = 1;
                }
        });
        if (gate.cancelled()) return cancelled();
        for (std::size_t k = 0; k < nz_; ++k)
            if (bad_in_slab[k]) return non_finite_sample(k);

        // Pass 2: count crossed edges per row (the vertices it owns) and triangles per cube row.
        parallel_chunks(nz_, 1, [&](std::size_t k0, std::size_t k1) {
            scratch s(words_);
            for (std::size_t k = k0; k < k1 && gate.advance(); ++k)
                for (std::size_t j = 0; j < ny_; ++j) {
                    const std::size_t r = k * ny_ + j;
                    const std::uint64_t* a = row(j, k);
                    std::uint32_t xc = 0, yc = 0, zc = 0;
                    for (std::size_t w = 0; w < words_; ++w) {
                        xc += count_bits((a[w] ^ shr1(a, w, words_)) & x_valid(w));
                        if (j + 1 < ny_) yc += count_bits(a[w] ^ row(j + 1, k)[w]);
                        if (k + 1 < nz_) zc += count_bits(a[w] ^ row(j, k + 1)[w]);
                    }
                    xcount_[r] = xc;
                    ycount_[r] = yc;
                    zcount_[r] = zc;
                    std::uint64_t centers = 0;
                    tbase_[r + 1] = 0;  // no cube row past the last sample row
                    if (j + 1 < ny_ && k + 1 < nz_) {
                        std::uint64_t tris = 0;
                        for_each_active_cube(j, k, s, [&](std::size_t i, unsigned config) {
                            const auto& e = table.entries[table.first[config] + decide(i, j, k, config)];
                            tris += e.count;
                            centers += e.center_loop != 0;
                        });
                        tbase_[r + 1] = tris;
                    }
                    vbase_[r + 1] = std::uint64_t(xc) + yc + zc + centers;
                }
        });
        if (gate.cancelled()) return cancelled();
        for (std::size_t r = 0; r < rows; ++r) {
            vbase_[r + 1] += vbase_[r];
            tbase_[r + 1] += tbase_[r];
        }
        if (vbase_[rows] > std::numeric_limits<std::uint32_t>::max())
            return fail(errc::unsupported, "marching_cubes: more than 2^32 - 1 vertices");

        return {};
    }

    struct scratch {
        explicit scratch(std::size_t words) : active(words), cubes(words), masks(8 * words), ids(8 * 64 * words + 1) {}
        std::vector<std::uint64_t> active, cubes, masks;
        // Per crossing mask q and edge position i, at q * 64 * words + i: the edge's vertex id
        // (written only where the mask has a bit).
        std::vector<std::uint32_t> ids;
    };

    const std::uint64_t* row(std::size_t j, std::size_t k) const noexcept { return &bits_[(k * ny_ + j) * words_]; }

    // The samples a row's vertices interpolate are scattered over three sample rows; asking
    // for them a few rows ahead hides most of the memory latency of the writing pass.
    static constexpr std::size_t prefetch_distance = 16;
    void prefetch_row(std::size_t j, std::size_t k) const noexcept {
        if constexpr (contiguous_voxel_grid<G>) {
            const std::uint64_t* a = row(j, k);
            const std::uint64_t* b = j + 1 < ny_ ? row(j + 1, k) : a;
            const std::uint64_t* c = k + 1 < nz_ ? row(j, k + 1) : a;
            for (std::size_t w = 0; w < words_; ++w) {
                std::uint64_t m = (a[w] ^ shr1(a, w, words_)) | (a[w] ^ b[w]) | (a[w] ^ c[w]);
                // One request per 16 samples (a 64-byte line of floats) is enough.
                std::uint64_t lines = 0;
                for (unsigned q = 0; q < 64; q += 16) lines |= ((m >> q) & 0xffff) ? (std::uint64_t(1) << q) : 0;
                while (lines) {
                    const std::size_t i = w * 64 + static_cast<std::size_t>(std::countr_zero(lines));
                    lines &= lines - 1;
                    const auto* p = data_ + i + j * sy_ + k * sz_;
                    __builtin_prefetch(p);
                    if (b != a) __builtin_prefetch(p + sy_);
                    if (c != a) __builtin_prefetch(p + sz_);
                }
            }
        }
    }
    std::uint64_t x_valid(std::size_t w) const noexcept {
        // Bits i < nx - 1: x-edges and cubes exist only there.
        const std::size_t lo = w * 64, n = nx_ - 1;
        if (n >= lo + 64) return ~std::uint64_t(0);
        if (n <= lo) return 0;
        return (std::uint64_t(1) << (n - lo)) - 1;
    }

    double value(std::size_t i, std::size_t j, std::size_t k) const {
        if constexpr (contiguous_voxel_grid<G>)
            return static_cast<double>(data_[i + j * sy_ + k * sz_]);
        else
            return static_cast<double>(grid_.value(i, j, k));
    }
    // Positive inside, negative outside (0 counts as inside).
    double inside_value(std::size_t i, std::size_t j, std::size_t k) const {
        const double v = value(i, j, k);
        return above_ ? v - opt_.iso : opt_.iso - v;
    }

    // Calls f(i, config) for every cube of row (j, k) with corners on both sides, in i order.
    template <class F>
    void for_each_active_cube(std::size_t j, std::size_t k, scratch& s, const F& f) const {
        if (!find_active_cubes(j, k, s)) return;
        const std::uint64_t *a = row(j, k), *b = row(j + 1, k), *c = row(j, k + 1), *d = row(j + 1, k + 1);
        for (std::size_t w = 0; w < words_; ++w) {
            std::uint64_t act = s.cubes[w];
            while (act) {
                const std::size_t i = w * 64 + static_cast<std::size_t>(std::countr_zero(act));
                act &= act - 1;
                const unsigned config = bits2(a, i) | (bits2(b, i) << 2) | (bits2(c, i) << 4) | (bits2(d, i) << 6);
                f(i, config);
            }
        }
    }

    // Marks in s.cubes the cubes of row (j, k) with corners on both sides; false if none.
    bool find_active_cubes(std::size_t j, std::size_t k, scratch& s) const {
        const std::uint64_t *a = row(j, k), *b = row(j + 1, k), *c = row(j, k + 1), *d = row(j + 1, k + 1);
        std::uint64_t any = 0;
        for (std::size_t w = 0; w < words_; ++w) {
            s.active[w] = (a[w] ^ b[w]) | (a[w] ^ c[w]) | (a[w] ^ d[w]);
            any |= s.active[w] | (a[w] ^ (a[w] >> 1));
        }
        if (!any) {
            // Nothing differs within words; a flip across a word boundary may remain.
            bool boundary = false;
            for (std::size_t w = 0; w + 1 < words_; ++w) boundary |= ((a[w] >> 63) ^ (a[w + 1] & 1)) != 0;
            if (!boundary) return false;
        }
        std::uint64_t found = 0;
        for (std::size_t w = 0; w < words_; ++w) {
            s.cubes[w] = (s.active[w] | shr1(s.active.data(), w, words_) | (a[w] ^ shr1(a, w, words_))) & x_valid(w);
            found |= s.cubes[w];
        }
        return found != 0;
    }

    // The asymptotic decider on each ambiguous face: its inside corners are joined when the
    // bilinear saddle lies inside, i.e. when in0 * in1 >= out0 * out1 (values signed inside
    // positive). It reads only the face's four samples, so both cubes sharing it agree.
    unsigned decide(std::size_t i, std::size_t j, std::size_t k, unsigned config) const {
        const auto& table = mc::table();
        const unsigned n = table.ambiguous_count[config];
        unsigned bits = 0;
        for (unsigned q = 0; q < n; ++q) {
            const auto& fc = face_corners[table.ambiguous_faces[config][q]];
            double in = 1, out = 1;
            for (int m = 0; m < 4; ++m) {
                const int c = fc[m];
                const double v = inside_value(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1));
                if ((config >> c) & 1)
                    in *= v;
                else
                    out *= v;
            }
            if (in >= out) bits |= 1u << q;
        }
        return bits;
    }

    vec3<double> gradient(std::size_t i, std::size_t j, std::size_t k) const {
        const auto sp = grid_.spacing();
        auto diff = [&](std::size_t lo_i, std::size_t lo_j, std::size_t lo_k, std::size_t hi_i, std::size_t hi_j,
                        std::size_t hi_k, double h) { return (value(hi_i, hi_j, hi_k) - value(lo_i, lo_j, lo_k)) / h; };
        const std::size_t i0 = i ? i - 1 : i, i1 = i + 1 < nx_ ? i + 1 : i;
        const std::size_t j0 = j ? j - 1 : j, j1 = j + 1 < ny_ ? j + 1 : j;
        const std::size_t k0 = k ? k - 1 : k, k1 = k + 1 < nz_ ? k + 1 : k;
        return {diff(i0, j, k, i1, j, k, sp.x * double(i1 - i0)), diff(i, j0, k, i, j1, k, sp.y * double(j1 - j0)),
                diff(i, j, k0, i, j, k1, sp.z * double(k1 - k0))};
    }

    // The crossing on the edge from sample (i, j, k) along `axis`, and the outward gradient
    // direction there (unnormalised; only computed when asked for).
    void edge_point(std::size_t i, std::size_t j, std::size_t k, int axis, vec3<double>& pos,
                    vec3<double>* normal) const {
        std::size_t i1 = i, j1 = j, k1 = k;
        (axis == 0 ? i1 : axis == 1 ? j1 : k1) += 1;
        const double v0 = value(i, j, k), v1 = value(i1, j1, k1);
        double t = (opt_.iso - v0) / (v1 - v0);
        t = std::clamp(t, edge_margin, 1.0 - edge_margin);
        const auto o = grid_.origin();
        const auto sp = grid_.spacing();
        const std::size_t gi = tags_ ? i + tags_->offset[0] : i, gj = tags_ ? j + tags_->offset[1] : j,
                          gk = tags_ ? k + tags_->offset[2] : k;
        vec3<double> p{double(gi), double(gj), double(gk)};
        p[static_cast<std::size_t>(axis)] += t;
        pos = {o.x + p.x * sp.x, o.y + p.y * sp.y, o.z + p.z * sp.z};
        if (normal) {
            vec3<double> g = gradient(i, j, k) * (1 - t) + gradient(i1, j1, k1) * t;
            *normal = above_ ? -g : g;  // the field grows inward when inside is above: outward is down
        }
    }

    template <class S>
    void store(std::size_t id, const vec3<double>& p, const vec3<double>* n, indexed_triangles<S>& out) const {
        if (layout_) {
            double* dst = layout_->positions + 3 * id;
            dst[0] = layout_->swap_xz ? p.z : p.x;
            dst[1] = p.y;
            dst[2] = layout_->swap_xz ? p.x : p.z;
            return;
        }
        out.positions[id] = {static_cast<S>(p.x), static_cast<S>(p.y), static_cast<S>(p.z)};
        if (n) {
            const auto u = normalized(*n);
            out.normals[id] = {static_cast<S>(u.x), static_cast<S>(u.y), static_cast<S>(u.z)};
        }
    }

    template <class S>
    void write_vertex(std::size_t id, std::size_t i, std::size_t j, std::size_t k, int axis,
                      indexed_triangles<S>& out) const {
        vec3<double> p, n;
        const bool normals = !out.normals.empty();
        edge_point(i, j, k, axis, p, normals ? &n : nullptr);
        store(id, p, normals ? &n : nullptr, out);
        if (tags_ && !layout_) (*tags_->vertex_keys)[id] = tags_->vertex_key(i, j, k, axis);
    }

    // The extra vertex of a loop that needs one: the mean of the loop's crossings.
    template <class S>
    void write_center(std::size_t id, std::size_t i, std::size_t j, std::size_t k, unsigned loop,
                      indexed_triangles<S>& out) const {
        const bool normals = !out.normals.empty();
        vec3<double> sum_p{}, sum_n{};
        double count = 0;
        for (; loop; loop &= loop - 1) {
            const int e = std::countr_zero(loop);
            const int c = edge_corners[e][0];
            vec3<double> p, n;
            edge_point(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1), e / 4, p, normals ? &n : nullptr);
            sum_p += p;
            if (normals) sum_n += normalized(n);
            count += 1;
        }
        sum_p /= count;
        store(id, sum_p, normals ? &sum_n : nullptr, out);
        if (tags_ && !layout_) (*tags_->vertex_keys)[id] = tags_->vertex_key(i, j, k, 3);
    }

    template <class S>
    void write_row_vertices(std::size_t j, std::size_t k, indexed_triangles<S>& out) const {
        const std::size_t r = k * ny_ + j;
        std::size_t id = vbase_[r];
        const std::uint64_t* a = row(j, k);
        // Writing into the whole result: only the rows and samples the block owns, at the
        // global start of their run.
        if (layout_ && (j >= layout_->own_y || k >= layout_->own_z)) return;
        const std::size_t own_x = layout_ ? layout_->own_x : nx_;
        auto emit = [&](auto mask_of, int axis) {
            if (layout_) id = layout_start(j, k, axis, layout_->column);
            for (std::size_t w = 0; w < words_; ++w) {
                std::uint64_t m = mask_of(w);
                while (m) {
                    const std::size_t i = w * 64 + static_cast<std::size_t>(std::countr_zero(m));
                    m &= m - 1;
                    if (i >= own_x) return;
                    write_vertex(id++, i, j, k, axis, out);
                }
            }
        };
        emit([&](std::size_t w) { return (a[w] ^ shr1(a, w, words_)) & x_valid(w); }, 0);
        if (j + 1 < ny_) emit([&](std::size_t w) { return a[w] ^ row(j + 1, k)[w]; }, 1);
        if (k + 1 < nz_) emit([&](std::size_t w) { return a[w] ^ row(j, k + 1)[w]; }, 2);
    }

    template <class S>
    void write_cube_row(std::size_t j, std::size_t k, scratch& s, const case_table& table,
                        indexed_triangles<S>& out) const {
        // The crossing masks of the rows around this cube row. A vertex's id is its row's base
        // plus its rank in its mask; numbering each mask's bits in one sweep costs a store per
        // vertex, where ranking every cube corner would cost a bit count (no popcnt
        // instruction in the x86-64 baseline) per triangle corner.
        if (tbase_[k * ny_ + j + 1] == tbase_[k * ny_ + j]) return;  // no triangles in this cube row
        const std::size_t ra = k * ny_ + j, rb = ra + 1, rc = ra + ny_, rd = rc + 1;
        const std::uint64_t *a = row(j, k), *b = row(j + 1, k), *c = row(j, k + 1), *d = row(j + 1, k + 1);
        std::uint64_t* m = s.masks.data();
        const std::size_t W = words_, stride = 64 * W;
        for (std::size_t w = 0; w < W; ++w) {
            m[0 * W + w] = (a[w] ^ shr1(a, w, W)) & x_valid(w);
            m[1 * W + w] = (b[w] ^ shr1(b, w, W)) & x_valid(w);
            m[2 * W + w] = (c[w] ^ shr1(c, w, W)) & x_valid(w);
            m[3 * W + w] = (d[w] ^ shr1(d, w, W)) & x_valid(w);
            m[4 * W + w] = a[w] ^ b[w];  // y-edges of row a
            m[5 * W + w] = c[w] ^ d[w];  // y-edges of row c
            m[6 * W + w] = a[w] ^ c[w];  // z-edges of row a
            m[7 * W + w] = b[w] ^ d[w];  // z-edges of row b
        }
        const std::uint64_t base[8] = {vbase_[ra],
                                       vbase_[rb],
                                       vbase_[rc],
                                       vbase_[rd],
                                       vbase_[ra] + xcount_[ra],
                                       vbase_[rc] + xcount_[rc],
                                       vbase_[ra] + xcount_[ra] + ycount_[ra],
                                       vbase_[rb] + xcount_[rb] + ycount_[rb]};
        std::uint32_t* ids = s.ids.data();
        if (layout_) {
            // Ids in the whole result: the global start of each mask's run in this chunk
            // column; an edge at the block's last sample along x is the first of the next's.
            static constexpr int mask_row[8][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {0, 0}, {0, 1}, {0, 0}, {1, 0}};
            static constexpr int mask_axis[8] = {0, 0, 0, 0, 1, 1, 2, 2};
            for (int q = 0; q < 8; ++q) {
                const std::size_t qj = j + std::size_t(mask_row[q][0]), qk = k + std::size_t(mask_row[q][1]);
                auto id = layout_start(qj, qk, mask_axis[q], layout_->column);
                std::uint32_t* slot = ids + std::size_t(q) * stride;
                for (std::size_t w = 0; w < W; ++w)
                    for (std::uint64_t bits = m[std::size_t(q) * W + w]; bits; bits &= bits - 1) {
                        const std::size_t i = w * 64 + static_cast<std::size_t>(std::countr_zero(bits));
                        slot[i] = i < layout_->own_x ? id++ : layout_start(qj, qk, mask_axis[q], layout_->column + 1);
                    }
            }
        } else {
            for (int q = 0; q < 8; ++q) {
                auto id = static_cast<std::uint32_t>(base[q]);
                std::uint32_t* slot = ids + std::size_t(q) * stride;
                for (std::size_t w = 0; w < W; ++w)
                    for (std::uint64_t bits = m[std::size_t(q) * W + w]; bits; bits &= bits - 1)
                        slot[w * 64 + static_cast<std::size_t>(std::countr_zero(bits))] = id++;
            }
        }
        // Edge e of the cube at i reads mask edge_mask[e] at i + edge_step[e].
        static constexpr int edge_mask[12] = {0, 1, 2, 3, 4, 4, 5, 5, 6, 6, 7, 7};
        static constexpr int edge_step[12] = {0, 0, 0, 0, 0, 1, 0, 1, 0, 1, 0, 1};
        std::size_t edge_at[12];
        for (int e = 0; e < 12; ++e) edge_at[e] = std::size_t(edge_mask[e]) * stride + std::size_t(edge_step[e]);
        std::size_t t = tbase_[ra];
        std::size_t center = vbase_[ra] + xcount_[ra] + ycount_[ra] + zcount_[ra];
        if (layout_) {
            t = layout_->triangle_start[tags_->global_row(j, k) * layout_->columns + layout_->column];
            center = layout_start(j, k, 3, layout_->column);
        }
        for_each_active_cube(j, k, s, [&](std::size_t i, unsigned config) {
            const auto& entry = table.entries[table.first[config] + decide(i, j, k, config)];
            std::uint32_t id[13];
            if (entry.center_loop) {
                id[center_vertex] = static_cast<std::uint32_t>(center);
                write_center(center++, i, j, k, entry.center_loop, out);
            }
            const std::uint32_t* at = ids + i;
            for (unsigned crossed = table.crossed_edges[config]; crossed; crossed &= crossed - 1) {
                const int e = std::countr_zero(crossed);
                id[e] = at[edge_at[e]];
            }
            if (layout_) {
                // Reversed with swap_xz: swapping two axes mirrors the surface.
                const int second = layout_->swap_xz ? 2 : 1, third = 3 - second;
                std::uint32_t* dst = layout_->triangles + 3 * t;
                for (unsigned n = 0; n < entry.count; ++n) {
                    dst[3 * n] = id[entry.edges[3 * n]];
                    dst[3 * n + 1] = id[entry.edges[3 * n + std::size_t(second)]];
                    dst[3 * n + 2] = id[entry.edges[3 * n + std::size_t(third)]];
                }
                t += entry.count;
                return;
            }
            auto* dst = out.triangles.data() + t;
            for (unsigned n = 0; n < entry.count; ++n)
                dst[n] = {id[entry.edges[3 * n]], id[entry.edges[3 * n + 1]], id[entry.edges[3 * n + 2]]};
            if (tags_)
                for (unsigned n = 0; n < entry.count; ++n) (*tags_->triangle_cubes)[t + n] = tags_->cube_key(i, j, k);
            t += entry.count;
        });
    }

    const G& grid_;
    marching_cubes_options opt_;
    const typename G::value_type* data_ = nullptr;
    std::size_t nx_ = 0, ny_ = 0, nz_ = 0, words_ = 0;
    std::size_t sy_ = 0, sz_ = 0;  // samples from one row to the next, and from one slice to the next
    bool above_ = false;
    const block_tags* tags_ = nullptr;
    const global_layout* layout_ = nullptr;
    bool reuse_ = false;
    std::uint32_t layout_start(std::size_t j, std::size_t k, int axis, std::size_t column) const noexcept {
        return layout_->vertex_start[(tags_->global_row(j, k) * 4 + std::size_t(axis)) * layout_->columns + column];
    }
    uninitialized_vector<std::uint64_t> bits_;
    uninitialized_vector<std::uint32_t> xcount_, ycount_, zcount_;
    uninitialized_vector<std::uint64_t> vbase_, tbase_;
    std::unique_ptr<scratch> row_scratch_;  // write_layout_row()'s
    indexed_triangles<double> no_output_;   // write_layout_row() writes into the layout only
};

}  // namespace hmira::detail::mc
