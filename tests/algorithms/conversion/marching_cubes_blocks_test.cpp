// Marching cubes by blocks: for random chunkings of analytic fields, noise, samples
// exactly at the iso value and real CT/MRI volumes, the welded blocks equal the whole-grid
// result element for element, positions bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <span>
#include <random>
#include <string>
#include <vector>

#include <hmira/algorithms/conversion/marching_cubes.hpp>
#include <hmira/algorithms/conversion/marching_cubes_blocks.hpp>
#include <hmira/grids/dense_grid.hpp>
#include <hmira/grids/sample.hpp>
#include <hmira/io/volume/inr.hpp>

namespace {

using hmira::grid_dims;

#if defined(HMIRA_SANITIZER_BUILD)
constexpr std::size_t n_side = 24;
constexpr int chunkings_per_field = 3;
#else
constexpr std::size_t n_side = 56;
constexpr int chunkings_per_field = 10;
#endif

/// Chunk sizes along one axis of n samples, each in [1, max_chunk], summing to n.
std::vector<std::size_t> random_chunks(std::size_t n, std::size_t max_chunk, std::mt19937& rng) {
    std::vector<std::size_t> c;
    for (std::size_t done = 0; done < n;) {
        const std::size_t s =
            std::min<std::size_t>(n - done, std::uniform_int_distribution<std::size_t>(1, max_chunk)(rng));
        c.push_back(s);
        done += s;
    }
    return c;
}

/// Cuts `grid` into the chunks given per axis, each plus one sample of overlap on its high
/// sides, runs marching_cubes_block on each, and returns the blocks in shuffled order.
std::vector<hmira::block_triangles<float>> blocks_of(const hmira::dense_grid<float>& grid,
                                                     const std::array<std::vector<std::size_t>, 3>& chunks,
                                                     const hmira::marching_cubes_block_options& o, std::mt19937& rng) {
    const grid_dims n = grid.dims();
    std::vector<hmira::block_triangles<float>> out;
    std::size_t z0 = 0;
    for (std::size_t cz : chunks[2]) {
        std::size_t y0 = 0;
        for (std::size_t cy : chunks[1]) {
            std::size_t x0 = 0;
            for (std::size_t cx : chunks[0]) {
                const grid_dims lo{x0, y0, z0};
                const grid_dims size{std::min(cx + 1, n[0] - x0), std::min(cy + 1, n[1] - y0),
                                     std::min(cz + 1, n[2] - z0)};
                std::vector<float> samples;
                samples.reserve(size[0] * size[1] * size[2]);
                for (std::size_t k = 0; k < size[2]; ++k)
                    for (std::size_t j = 0; j < size[1]; ++j)
                        for (std::size_t i = 0; i < size[0]; ++i)
                            samples.push_back(grid.value(lo[0] + i, lo[1] + j, lo[2] + k));
                auto view = hmira::make_grid_view(samples, {size, grid.origin(), grid.spacing()});
                EXPECT_TRUE(view);
                auto b = hmira::marching_cubes_block(*view, {.offset = lo, .whole = n}, o);
                EXPECT_TRUE(b) << b.error().message;
                if (b) {
                    EXPECT_TRUE(std::is_sorted(b->keys.begin(), b->keys.end()));
                    EXPECT_TRUE(std::is_sorted(b->cubes.begin(), b->cubes.end()));
                    out.push_back(std::move(*b));
                }
                x0 += cx;
            }
            y0 += cy;
        }
        z0 += cz;
    }
    std::shuffle(out.begin(), out.end(), rng);
    return out;
}

/// The samples of the block at `lo` with its one-sample overlap on the high sides.
std::vector<float> block_samples(const hmira::dense_grid<float>& grid, const grid_dims& lo, const grid_dims& size) {
    std::vector<float> samples;
    samples.reserve(size[0] * size[1] * size[2]);
    for (std::size_t k = 0; k < size[2]; ++k)
        for (std::size_t j = 0; j < size[1]; ++j)
            for (std::size_t i = 0; i < size[0]; ++i) samples.push_back(grid.value(lo[0] + i, lo[1] + j, lo[2] + k));
    return samples;
}

/// The direct path (detail::mc_direct): counts every block, lays out the whole result, then
/// lets every block write its share straight into it, the blocks in shuffled order. With
/// `swap`, positions come as (z, y, x) and triangles reversed, as for a C-ordered array.
hmira::indexed_triangles<double> direct_of(const hmira::dense_grid<float>& grid,
                                           const std::array<std::vector<std::size_t>, 3>& chunks,
                                           const hmira::marching_cubes_block_options& o, bool swap, std::mt19937& rng) {
    namespace direct = hmira::detail::mc_direct;
    const grid_dims n = grid.dims();
    std::vector<grid_dims> lo, size;
    std::vector<std::size_t> x_starts;
    for (std::size_t x0 = 0, c = 0; c < chunks[0].size(); x0 += chunks[0][c++]) x_starts.push_back(x0);
    for (std::size_t z0 = 0, cz = 0; cz < chunks[2].size(); z0 += chunks[2][cz++])
        for (std::size_t y0 = 0, cy = 0; cy < chunks[1].size(); y0 += chunks[1][cy++])
            for (std::size_t x0 = 0, cx = 0; cx < chunks[0].size(); x0 += chunks[0][cx++]) {
                lo.push_back({x0, y0, z0});
                size.push_back({std::min(chunks[0][cx] + 1, n[0] - x0), std::min(chunks[1][cy] + 1, n[1] - y0),
                                std::min(chunks[2][cz] + 1, n[2] - z0)});
            }
    std::vector<std::size_t> order(lo.size());
    for (std::size_t b = 0; b < order.size(); ++b) order[b] = b;
    std::shuffle(order.begin(), order.end(), rng);
    auto view_of_block = [&](std::size_t b, std::vector<float>& samples) {
        samples = block_samples(grid, lo[b], size[b]);
        return hmira::make_grid_view(samples, {size[b], grid.origin(), grid.spacing()});
    };
    std::vector<direct::block_counts> counts(lo.size());
    for (std::size_t b : order) {
        std::vector<float> samples;
        auto view = view_of_block(b, samples);
        EXPECT_TRUE(view);
        auto c = direct::count_block(*view, {.offset = lo[b], .whole = n}, o);
        EXPECT_TRUE(c) << c.error().message;
        if (c) counts[b] = std::move(*c);
    }
    auto tables = direct::make_layout(n, x_starts, lo, counts);
    EXPECT_TRUE(tables) << tables.error().message;
    hmira::indexed_triangles<double> out;
    if (!tables) return out;
    std::vector<double> positions(3 * tables->vertices, std::nan(""));
    std::vector<std::uint32_t> triangles(3 * tables->triangles, 0xffffffffu);
    const hmira::detail::mc::global_layout layout{.vertex_start = tables->vertex_start.data(),
                                                  .triangle_start = tables->triangle_start.data(),
                                                  .columns = tables->columns,
                                                  .positions = positions.data(),
                                                  .triangles = triangles.data(),
                                                  .swap_xz = swap};
    std::shuffle(order.begin(), order.end(), rng);
    auto column_of = [&](std::size_t b) {
        return std::size_t(std::find(x_starts.begin(), x_starts.end(), lo[b][0]) - x_starts.begin());
    };
    // Block by block (write_block_into), or several at once, row by row in turn
    // (write_blocks_into): the rows of chunks along x, or random groups of blocks.
    const unsigned mode = rng() % 3;
    std::vector<std::vector<std::size_t>> groups;
    if (mode == 0) {
        for (std::size_t b : order) {
            std::vector<float> samples;
            auto view = view_of_block(b, samples);
            auto where = layout;
            where.column = column_of(b);
            // Half the blocks reuse their counted rows, half count again.
            auto r = direct::write_block_into(*view, {.offset = lo[b], .whole = n}, where, o,
                                              (rng() & 1) ? &counts[b] : nullptr);
            EXPECT_TRUE(r) << r.error().message;
        }
    } else if (mode == 1) {
        const std::size_t mx = chunks[0].size();
        groups.resize(lo.size() / mx);
        for (std::size_t b : order) groups[b / mx].push_back(b);  // blocks are in C order, x fastest
    } else {
        for (std::size_t at = 0; at < order.size();) {
            const std::size_t size = std::min<std::size_t>(order.size() - at, 1 + rng() % 6);
            groups.emplace_back(order.begin() + std::ptrdiff_t(at), order.begin() + std::ptrdiff_t(at + size));
            at += size;
        }
    }
    for (const auto& group : groups) {
        std::vector<std::vector<float>> samples(group.size());
        using view_type = std::remove_cvref_t<decltype(*view_of_block(0, samples[0]))>;
        std::vector<view_type> views;
        std::vector<hmira::grid_block> wheres;
        std::vector<std::size_t> columns;
        std::vector<direct::block_counts*> counted;
        for (std::size_t g = 0; g < group.size(); ++g) {
            auto view = view_of_block(group[g], samples[g]);
            EXPECT_TRUE(view);
            views.push_back(*view);
            wheres.push_back({.offset = lo[group[g]], .whole = n});
            columns.push_back(column_of(group[g]));
            counted.push_back((rng() & 1) ? &counts[group[g]] : nullptr);
        }
        auto r = direct::write_blocks_into(
            std::span<const view_type>(views), std::span<const hmira::grid_block>(wheres),
            std::span<const std::size_t>(columns), layout, o, std::span<direct::block_counts* const>(counted));
        EXPECT_TRUE(r) << r.error().message;
    }
    for (std::size_t v = 0; v < tables->vertices; ++v)
        out.positions.push_back({positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]});
    for (std::size_t t = 0; t < tables->triangles; ++t)
        out.triangles.push_back({triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2]});
    return out;
}

/// Expects the merged blocks to equal the whole-grid marching cubes element for element.
void expect_identical(const hmira::indexed_triangles<float>& whole, const hmira::indexed_triangles<float>& merged,
                      const std::string& what) {
    ASSERT_EQ(merged.positions.size(), whole.positions.size()) << what;
    ASSERT_EQ(merged.triangles.size(), whole.triangles.size()) << what;
    EXPECT_EQ(std::memcmp(merged.positions.data(), whole.positions.data(),
                          whole.positions.size() * sizeof(whole.positions[0])),
              0)
        << what << ": positions differ";
    EXPECT_TRUE(merged.triangles == whole.triangles) << what << ": triangles differ";
}

/// Runs `chunkings_per_field` random chunkings (plus single-slab chunks along each axis) of
/// `grid` and checks each against the whole grid. Chunks stay within 1..64 samples and the
/// block count within 512.
void check_chunkings(const hmira::dense_grid<float>& grid, const hmira::marching_cubes_block_options& o, unsigned seed,
                     const std::string& name) {
    const hmira::marching_cubes_options whole_opt{.iso = o.iso, .inside = o.inside};
    auto whole = hmira::marching_cubes_indexed(grid, whole_opt);
    ASSERT_TRUE(whole) << whole.error().message;
    ASSERT_GT(whole->triangles.size(), 0u) << name << ": the test needs a surface";
    auto whole_double = hmira::marching_cubes_indexed<double>(grid, whole_opt);
    ASSERT_TRUE(whole_double) << whole_double.error().message;
    std::mt19937 rng(seed);
    const grid_dims n = grid.dims();
    auto run = [&](const std::array<std::vector<std::size_t>, 3>& chunks, const std::string& label) {
        ASSERT_LE(chunks[0].size() * chunks[1].size() * chunks[2].size(), 512u) << label;
        auto blocks = blocks_of(grid, chunks, o, rng);
        auto merged = hmira::merge_blocks(blocks);
        ASSERT_TRUE(merged) << merged.error().message;
        expect_identical(*whole, *merged, name + " " + label);
        // Written straight into the whole result: the same, in double and in array axes.
        const bool swap = (rng() & 1) != 0;
        const auto direct = direct_of(grid, chunks, o, swap, rng);
        auto expected = *whole_double;
        if (swap) {
            for (auto& p : expected.positions) std::swap(p.x, p.z);
            for (auto& t : expected.triangles) std::swap(t[1], t[2]);
        }
        ASSERT_EQ(direct.positions.size(), expected.positions.size()) << name << " " << label << " direct";
        ASSERT_EQ(direct.triangles.size(), expected.triangles.size()) << name << " " << label << " direct";
        const std::size_t bytes = expected.positions.size() * sizeof(expected.positions[0]);
        EXPECT_EQ(std::memcmp(direct.positions.data(), expected.positions.data(), bytes), 0)
            << name << " " << label << " direct: positions differ";
        EXPECT_TRUE(direct.triangles == expected.triangles) << name << " " << label << " direct: triangles differ";
    };
    for (int c = 0; c < chunkings_per_field; ++c) {
        // Small maxima would make thousands of blocks; keep the count under 512 (8^3).
        std::array<std::vector<std::size_t>, 3> chunks;
        for (int a = 0; a < 3; ++a) {
            const std::size_t min_max = (n[a] + 7) / 8;
            const std::size_t max_chunk =
                std::uniform_int_distribution<std::size_t>(std::max<std::size_t>(min_max, 1), 64)(rng);
            // Random sizes up to max_chunk can still give more than 8 chunks; retry until not.
            do chunks[a] = random_chunks(n[a], max_chunk, rng);
            while (chunks[a].size() > 8);
        }
        run(chunks, "chunking " + std::to_string(c));
    }
    // Single-slab chunks along each axis (one axis cut every sample, the others whole).
    for (int a = 0; a < 3; ++a) {
        std::array<std::vector<std::size_t>, 3> chunks{std::vector<std::size_t>{n[0]}, std::vector<std::size_t>{n[1]},
                                                       std::vector<std::size_t>{n[2]}};
        chunks[a].assign(std::min<std::size_t>(n[a], 512), 1);
        if (n[a] > 512) chunks[a].back() += n[a] - 512;
        run(chunks, "slabs along " + std::string(1, "xyz"[a]));
    }
}

hmira::grid_geometry box(std::size_t nx, std::size_t ny, std::size_t nz) {
    // Non-unit spacing and an offset origin, so positions exercise the full formula.
    return {{nx, ny, nz}, {-1.25, 0.5, 3.0}, {0.037, 0.041, 0.053}};
}

TEST(MarchingCubesBlocks, sphere_with_odd_sizes_equals_whole_grid) {
    const auto g = box(n_side + 1, n_side - 3, n_side + 5);
    const hmira::vec3<double> c = g.position(g.dims[0] / 2, g.dims[1] / 2, g.dims[2] / 2);
    auto grid = hmira::sample_function(g, [&](hmira::vec3<double> p) { return hmira::norm(p - c) - 0.6; });
    ASSERT_TRUE(grid);
    check_chunkings(*grid, {.iso = 0.0}, 1, "sphere");
}

TEST(MarchingCubesBlocks, gyroid_equals_whole_grid_both_insides) {
    const auto g = box(n_side, n_side + 2, n_side - 1);
    auto grid = hmira::sample_function(g, [](hmira::vec3<double> p) {
        const double s = 6.0;
        return std::sin(s * p.x) * std::cos(s * p.y) + std::sin(s * p.y) * std::cos(s * p.z) +
               std::sin(s * p.z) * std::cos(s * p.x);
    });
    ASSERT_TRUE(grid);
    check_chunkings(*grid, {.iso = 0.1, .inside = hmira::iso_inside::below}, 2, "gyroid below");
    check_chunkings(*grid, {.iso = 0.1, .inside = hmira::iso_inside::above}, 3, "gyroid above");
}

TEST(MarchingCubesBlocks, seeded_noise_with_ambiguous_cases_equals_whole_grid) {
    // White noise makes every ambiguous case, including the centre vertices of cases 10, 12, 13.
    hmira::dense_grid<float> grid(box(n_side / 2 + 3, n_side / 2, n_side / 2 + 1));
    std::mt19937 rng(42);
    for (auto& v : grid.values()) v = std::uniform_real_distribution<float>(-1, 1)(rng);
    auto whole = hmira::marching_cubes_indexed(grid, {});
    ASSERT_TRUE(whole);
    // The extra vertices are those no grid edge accounts for: the test must reach them.
    std::size_t crossings = 0;
    const grid_dims n = grid.dims();
    auto in = [&](std::size_t i, std::size_t j, std::size_t k) { return grid.value(i, j, k) <= 0.0f; };
    for (std::size_t k = 0; k < n[2]; ++k)
        for (std::size_t j = 0; j < n[1]; ++j)
            for (std::size_t i = 0; i < n[0]; ++i) {
                if (i + 1 < n[0]) crossings += in(i, j, k) != in(i + 1, j, k);
                if (j + 1 < n[1]) crossings += in(i, j, k) != in(i, j + 1, k);
                if (k + 1 < n[2]) crossings += in(i, j, k) != in(i, j, k + 1);
            }
    ASSERT_GT(whole->positions.size(), crossings) << "no centre vertices in the noise: pick another seed";
    check_chunkings(grid, {}, 4, "noise");
}

TEST(MarchingCubesBlocks, samples_exactly_at_iso_equal_whole_grid) {
    // Small integers, as in 8-bit data: a third of the samples equal the iso value.
    hmira::dense_grid<float> grid(box(n_side / 2, n_side / 2 + 5, n_side / 2 + 2));
    std::mt19937 rng(7);
    for (auto& v : grid.values()) v = float(std::uniform_int_distribution<int>(0, 2)(rng));
    check_chunkings(grid, {.iso = 1.0, .inside = hmira::iso_inside::above}, 5, "at iso");
}

std::filesystem::path data_dir() {
    const char* d = std::getenv("HMIRA_TEST_DATA");
    return d ? std::filesystem::path(d) : std::filesystem::path();
}

hmira::dense_grid<float> crop(const hmira::dense_grid<float>& g, grid_dims lo, grid_dims size) {
    hmira::grid_geometry geo = g.geometry();
    geo.dims = size;
    geo.origin = g.geometry().position(lo[0], lo[1], lo[2]);
    hmira::dense_grid<float> out(geo);
    for (std::size_t k = 0; k < size[2]; ++k)
        for (std::size_t j = 0; j < size[1]; ++j)
            for (std::size_t i = 0; i < size[0]; ++i) out.set(i, j, k, g.value(lo[0] + i, lo[1] + j, lo[2] + k));
    return out;
}

TEST(MarchingCubesBlocks, skull_and_liver_volumes_equal_whole_grid) {
    if (data_dir().empty()) GTEST_SKIP() << "HMIRA_TEST_DATA not set";
    struct volume {
        const char* file;
        double iso;
    };
    unsigned seed = 10;
    for (const volume v : {volume{"skull_2.9.inr", 2.9}, volume{"liver.inr.gz", 0.5}}) {
        const auto path = data_dir() / "images" / v.file;
        if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " missing";
        auto grid = hmira::io::read_inr(path);
        ASSERT_TRUE(grid) << grid.error().message;
        // The central part of the volume, where the surface is.
        const grid_dims n = grid->dims();
        grid_dims size, lo;
        for (int a = 0; a < 3; ++a) {
            size[a] = std::min<std::size_t>(n[a], n_side + 8);
            lo[a] = (n[a] - size[a]) / 2;
        }
        check_chunkings(crop(*grid, lo, size), {.iso = v.iso, .inside = hmira::iso_inside::above}, seed++, v.file);
    }
}

TEST(MarchingCubesBlocks, block_outside_the_grid_or_with_nan_names_the_block) {
    hmira::dense_grid<float> grid(box(4, 4, 4), 1.0f);
    auto b = hmira::marching_cubes_block(grid, {.offset = {2, 0, 0}, .whole = {5, 4, 4}});
    ASSERT_FALSE(b);
    EXPECT_NE(b.error().message.find("marching_cubes_block at (2, 0, 0)"), std::string::npos) << b.error().message;
    EXPECT_NE(b.error().message.find("along x"), std::string::npos) << b.error().message;
    grid.set(1, 2, 3, std::nanf(""));
    b = hmira::marching_cubes_block(grid, {.offset = {0, 0, 8}, .whole = {4, 4, 16}});
    ASSERT_FALSE(b);
    EXPECT_NE(b.error().message.find("marching_cubes_block at (0, 0, 8): marching_cubes: sample (1, 2, 11) is NaN"),
              std::string::npos)
        << b.error().message;
}

TEST(MarchingCubesBlocks,
     infinite_samples_are_refused_by_blocks_slabs_and_the_direct_path_naming_the_whole_grids_sample) {
    // A sphere field over 9 x 8 x 20 samples with one infinite sample at (6, 5, 13).
    const auto g = box(9, 8, 20);
    auto grid =
        hmira::sample_function(g, [](hmira::vec3<double> p) { return p.x * p.x + p.y * p.y + p.z * p.z - 0.3; });
    ASSERT_TRUE(grid);
    for (float bad : {std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity()}) {
        grid->set(6, 5, 13, bad);
        const std::string name = std::string("sample (6, 5, 13) is ") + (bad > 0 ? "inf" : "-inf");
        // One block holding it, seen in place: the index is the whole grid's.
        auto view = hmira::make_grid_view(std::span<const float>(grid->values().subspan(10 * 72, 6 * 72)),
                                          {{9, 8, 6}, g.origin, g.spacing});
        ASSERT_TRUE(view);
        auto b = hmira::marching_cubes_block(*view, {.offset = {0, 0, 10}, .whole = g.dims});
        ASSERT_FALSE(b);
        EXPECT_NE(b.error().message.find("marching_cubes_block at (0, 0, 10): marching_cubes: " + name),
                  std::string::npos)
            << b.error().message;
        // Slab by slab, whatever the slab size.
        for (std::size_t slab : {std::size_t(1), std::size_t(4), std::size_t(30)}) {
            auto fetch = [&](std::size_t k0, std::size_t count, std::vector<float>& out) -> hmira::result<void> {
                const auto begin = grid->values().begin() + std::ptrdiff_t(k0 * 72);
                out.assign(begin, begin + std::ptrdiff_t(count * 72));
                return {};
            };
            auto r = hmira::marching_cubes_by_slabs<double, float>(g, slab, fetch);
            ASSERT_FALSE(r) << "slab " << slab;
            EXPECT_NE(r.error().message.find(name), std::string::npos) << r.error().message;
        }
        // The direct path's counting step.
        auto c = hmira::detail::mc_direct::count_block(*view, {.offset = {0, 0, 10}, .whole = g.dims});
        ASSERT_FALSE(c);
        EXPECT_NE(c.error().message.find(name), std::string::npos) << c.error().message;
    }
}

TEST(MarchingCubesBlocks, slabs_refuse_an_iso_outside_the_whole_grids_range_and_accept_one_inside_without_surface) {
    // Samples 3 + k: the range is [3, 12], and each slab's own range is narrower.
    const auto g = box(5, 6, 10);
    auto fetch = [&](std::size_t k0, std::size_t count, std::vector<float>& out) -> hmira::result<void> {
        out.clear();
        for (std::size_t k = k0; k < k0 + count; ++k) out.insert(out.end(), 30, float(3 + k));
        return {};
    };
    for (std::size_t slab : {std::size_t(1), std::size_t(3), std::size_t(20)})
        for (double iso : {0.0, 2.5, 12.5, 100.0}) {
            auto r = hmira::marching_cubes_by_slabs<double, float>(g, slab, fetch, {.iso = iso});
            ASSERT_FALSE(r) << "slab " << slab << " iso " << iso;
            EXPECT_EQ(r.error().code, hmira::errc::invalid_argument);
            EXPECT_NE(r.error().message.find("outside the samples' range [3, 12]"), std::string::npos)
                << r.error().message;
        }
    // Every sample inside (iso = max, inside below): in the range, no surface, no error.
    auto all_inside = hmira::marching_cubes_by_slabs<double, float>(g, 3, fetch, {.iso = 12.0});
    ASSERT_TRUE(all_inside) << all_inside.error().message;
    EXPECT_EQ(all_inside->triangles.size(), 0u);
    // A surface in the last slab only.
    auto late = hmira::marching_cubes_by_slabs<double, float>(g, 3, fetch, {.iso = 11.5});
    ASSERT_TRUE(late) << late.error().message;
    EXPECT_GT(late->triangles.size(), 0u);
}

TEST(MarchingCubesBlocks, skull_at_the_default_iso_is_refused_whole_and_by_slabs) {
    if (data_dir().empty()) GTEST_SKIP() << "HMIRA_TEST_DATA not set";
    const auto path = data_dir() / "images" / "skull_2.9.inr";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " missing";
    auto grid = hmira::io::read_inr(path);
    ASSERT_TRUE(grid) << grid.error().message;
    const auto [lo, hi] = std::minmax_element(grid->values().begin(), grid->values().end());
    ASSERT_GT(*lo, 0.0f);  // the default iso 0 lies below every sample
    // As the shortest decimal text that reads back as the same double.
    auto text = [](double x) {
        char b[32];
        return std::string(b, std::to_chars(b, b + sizeof b, x).ptr);
    };
    const std::string range = "range [" + text(double(*lo)) + ", " + text(double(*hi)) + "]";
    auto whole = hmira::marching_cubes_indexed<double>(*grid);
    ASSERT_FALSE(whole);
    EXPECT_NE(whole.error().message.find("iso 0 is outside the samples' " + range), std::string::npos)
        << whole.error().message;
    const auto g = grid->geometry();
    auto fetch = [&](std::size_t k0, std::size_t count, std::vector<float>& out) -> hmira::result<void> {
        const auto begin = grid->values().begin() + std::ptrdiff_t(k0 * g.dims[0] * g.dims[1]);
        out.assign(begin, begin + std::ptrdiff_t(count * g.dims[0] * g.dims[1]));
        return {};
    };
    auto slabs = hmira::marching_cubes_by_slabs<double, float>(g, 16, fetch);
    ASSERT_FALSE(slabs);
    EXPECT_NE(slabs.error().message.find(range), std::string::npos) << slabs.error().message;
}

TEST(MarchingCubesBlocks, thin_blocks_are_empty_and_overlapping_blocks_are_refused) {
    hmira::dense_grid<float> grid(box(5, 5, 5));
    for (std::size_t i = 0; i < grid.size(); ++i) grid.values()[i] = (i % 3) ? 1.0f : -1.0f;
    // A block one sample thick has no cubes.
    auto view = hmira::make_grid_view(std::span<const float>(grid.values().subspan(0, 25)),
                                      {{5, 5, 1}, grid.origin(), grid.spacing()});
    ASSERT_TRUE(view);
    auto thin = hmira::marching_cubes_block(*view, {.offset = {0, 0, 4}, .whole = {5, 5, 5}});
    ASSERT_TRUE(thin);
    EXPECT_TRUE(thin->positions.empty() && thin->triangles.empty());
    // The same block twice holds every cube twice: merge refuses it.
    auto b = hmira::marching_cubes_block(grid, {.offset = {0, 0, 0}, .whole = {5, 5, 5}});
    ASSERT_TRUE(b);
    ASSERT_FALSE(b->triangles.empty());
    const std::vector<hmira::block_triangles<float>> twice{*b, *b};
    auto merged = hmira::merge_blocks(twice);
    ASSERT_FALSE(merged);
    EXPECT_NE(merged.error().message.find("the blocks overlap"), std::string::npos) << merged.error().message;
    // A triangle naming a vertex the block lacks.
    auto broken = *b;
    broken.triangles[0][1] = std::uint32_t(broken.positions.size());
    merged = hmira::merge_blocks(std::vector<hmira::block_triangles<float>>{broken});
    ASSERT_FALSE(merged);
    EXPECT_NE(merged.error().message.find("block 0 triangle 0 names vertex"), std::string::npos)
        << merged.error().message;
}

TEST(MarchingCubesBlocks, merge_into_caller_storage_on_any_thread_count_and_refused_tilings) {
    // Noise over a small grid, cut into uneven chunks with one-sample chunks at both ends.
    hmira::dense_grid<float> grid(box(13, 11, 9));
    std::mt19937 rng(99);
    for (auto& v : grid.values()) v = std::uniform_real_distribution<float>(-1, 1)(rng);
    auto whole = hmira::marching_cubes_indexed(grid, {});
    ASSERT_TRUE(whole);
    const std::array<std::vector<std::size_t>, 3> chunks{
        std::vector<std::size_t>{1, 5, 6, 1}, std::vector<std::size_t>{4, 6, 1}, std::vector<std::size_t>{1, 8}};
    auto blocks = blocks_of(grid, chunks, {}, rng);
    ASSERT_EQ(blocks.size(), 24u);
    // Storage from the caller, every element overwritten (filled with garbage first).
    for (unsigned threads : {1u, 2u, 3u}) {
        std::vector<hmira::block_triangles_view<float>> views;
        for (const auto& b : blocks) views.push_back(hmira::view_of(b));
        hmira::indexed_triangles<float> out;
        std::size_t calls = 0;
        auto allocate = [&](std::size_t nv, std::size_t nt) -> hmira::result<hmira::merged_storage<float>> {
            ++calls;
            out.positions.assign(nv, {-7.0f, -7.0f, -7.0f});
            out.triangles.assign(nt, {99u, 99u, 99u});
            return hmira::merged_storage<float>{out.positions, out.triangles};
        };
        auto ok = hmira::merge_blocks_into(std::span<const hmira::block_triangles_view<float>>(views), allocate,
                                           {.threads = threads});
        ASSERT_TRUE(ok) << ok.error().message;
        EXPECT_EQ(calls, 1u);
        expect_identical(*whole, out, "caller storage, " + std::to_string(threads) + " threads");
    }
    // An allocator's error comes back as is.
    {
        std::vector<hmira::block_triangles_view<float>> views;
        for (const auto& b : blocks) views.push_back(hmira::view_of(b));
        auto refuse = [](std::size_t, std::size_t) -> hmira::result<hmira::merged_storage<float>> {
            return hmira::fail(hmira::errc::io_error, "no room");
        };
        auto r = hmira::merge_blocks_into(std::span<const hmira::block_triangles_view<float>>(views), refuse);
        ASSERT_FALSE(r);
        EXPECT_EQ(r.error().message, "no room");
    }
    auto expect_refused = [&](std::vector<hmira::block_triangles<float>> bad, const std::string& says) {
        auto r = hmira::merge_blocks(bad);
        ASSERT_FALSE(r) << says;
        EXPECT_NE(r.error().message.find(says), std::string::npos) << r.error().message;
    };
    // A missing chunk, even an empty one.
    for (std::size_t drop = 0; drop < blocks.size(); drop += 5) {
        auto missing = blocks;
        missing.erase(missing.begin() + std::ptrdiff_t(drop));
        expect_refused(missing, "do not tile one grid");
    }
    // A block without its overlap.
    auto short_block = blocks;
    for (auto& b : short_block)
        if (b.offset == grid_dims{1, 4, 1}) b.size[0] -= 1;
    expect_refused(short_block, "where its chunk and overlap have");
    // A vertex on a chunk face that the owner gives another position.
    auto moved = blocks;
    bool done = false;
    for (auto& b : moved)
        for (std::size_t v = 0; v < b.keys.size() && !done; ++v) {
            const std::uint64_t i = b.keys[v] % 13, a = b.keys[v] / 13 % 4;
            if (a == 1 && i == b.offset[0] + b.size[0] - 1 && b.size[0] > 1 && b.offset[0] + b.size[0] < 13) {
                b.positions[v].y = std::nextafter(b.positions[v].y, 1e9f);
                done = true;
            }
        }
    ASSERT_TRUE(done) << "no vertex on an inner x face: pick another seed";
    expect_refused(moved, "different positions");
    // A vertex key outside its block.
    auto stray = blocks;
    for (auto& b : stray)
        if (!b.keys.empty()) {
            b.keys.back() += 13 * 4 * 11 * 9;
            break;
        }
    expect_refused(stray, "lies outside the block");
}

}  // namespace

namespace {

TEST(MarchingCubesBlocks, slab_by_slab_equals_whole_grid_for_every_slab_thickness) {
    const auto g = box(n_side - 5, n_side / 2 + 1, n_side / 2 + 3);
    auto grid = hmira::sample_function(g, [](hmira::vec3<double> p) {
        const double s = 7.0;
        return std::sin(s * p.x) * std::cos(s * p.y) + std::sin(s * p.y) * std::cos(s * p.z) +
               std::sin(s * p.z) * std::cos(s * p.x);
    });
    ASSERT_TRUE(grid);
    for (auto inside : {hmira::iso_inside::below, hmira::iso_inside::above}) {
        auto whole = hmira::marching_cubes_indexed<double>(*grid, {.iso = 0.05, .inside = inside});
        ASSERT_TRUE(whole);
        for (std::size_t slab :
             {std::size_t(1), std::size_t(2), std::size_t(5), std::size_t(13), g.dims[2] - 2, g.dims[2] + 4}) {
            std::size_t fetched = 0;
            auto fetch = [&](std::size_t k0, std::size_t count, std::vector<float>& out) -> hmira::result<void> {
                const auto begin = grid->values().begin() + std::ptrdiff_t(k0 * g.dims[0] * g.dims[1]);
                out.assign(begin, begin + std::ptrdiff_t(count * g.dims[0] * g.dims[1]));
                fetched += count;
                return {};
            };
            auto r = hmira::marching_cubes_by_slabs<double, float>(g, slab, fetch, {.iso = 0.05, .inside = inside});
            ASSERT_TRUE(r) << r.error().message;
            const std::string what = "slab " + std::to_string(slab);
            ASSERT_EQ(r->positions.size(), whole->positions.size()) << what;
            EXPECT_EQ(std::memcmp(r->positions.data(), whole->positions.data(),
                                  whole->positions.size() * sizeof(whole->positions[0])),
                      0)
                << what;
            EXPECT_TRUE(r->triangles == whole->triangles) << what;
            // Every slice is read once, plus one per slab border.
            const std::size_t slabs = (g.dims[2] - 1 + std::min(slab, g.dims[2]) - 1) / std::min(slab, g.dims[2]);
            EXPECT_EQ(fetched, g.dims[2] + slabs - 1) << what;
        }
    }
}

TEST(MarchingCubesBlocks, slab_fetch_error_is_returned) {
    const auto g = box(6, 6, 9);
    auto fetch = [&](std::size_t k0, std::size_t count, std::vector<float>& out) -> hmira::result<void> {
        if (k0 >= 4) return hmira::fail(hmira::errc::io_error, "disk on fire at slice " + std::to_string(k0));
        out.assign(count * 36, k0 ? 1.0f : -1.0f);
        return {};
    };
    auto r = hmira::marching_cubes_by_slabs<float, float>(g, 2, fetch);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, hmira::errc::io_error);
    EXPECT_EQ(r.error().message, "disk on fire at slice 4");
}

}  // namespace
