// Voxelization modes and blocks: the `centres` mode against lattice counts
// decided by hand (centres on faces, edges and vertices), an independent winding-number test,
// and the divergence-theorem volume of real closed meshes; solid == surface | centres; and
// voxelization by blocks equal to the whole grid, voxel for voxel, for every mode.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <random>
#include <vector>

#include <hmira/algorithms/conversion/voxelize.hpp>
#include <hmira/algorithms/conversion/voxelize_blocks.hpp>
#include <hmira/io/off.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

#if defined(HMIRA_HAS_TBB)
#include <tbb/global_control.h>
#endif

namespace {

using hmira::vec3;

std::filesystem::path data_dir() {
    const char* d = std::getenv("HMIRA_TEST_DATA");
    return d ? std::filesystem::path(d) : std::filesystem::path();
}

hmira::face_vertex_mesh read(const char* name) {
    hmira::face_vertex_mesh m;
    const auto path = data_dir() / "meshes" / name;
    if (data_dir().empty() || !std::filesystem::exists(path)) return m;
    if (!hmira::io::read_off(m, path)) return {};
    return m;
}

// The octahedron |x - c| + |y - c| + |z - c| <= r, outward faces, 8 triangles.
hmira::face_vertex_mesh octahedron(double c, double r) {
    hmira::face_vertex_mesh m;
    const vec3<double> p[6] = {{c + r, c, c}, {c - r, c, c}, {c, c + r, c},
                               {c, c - r, c}, {c, c, c + r}, {c, c, c - r}};
    std::vector<hmira::vertex_handle> v;
    for (const auto& q : p) v.push_back(m.add_vertex(q));
    for (int sx = 0; sx < 2; ++sx)
        for (int sy = 0; sy < 2; ++sy)
            for (int sz = 0; sz < 2; ++sz) {
                auto a = v[std::size_t(sx)], b = v[std::size_t(2 + sy)], d = v[std::size_t(4 + sz)];
                // Outward when the three signs' product is positive (+x, +y, +z is counter-clockwise).
                const bool ccw = ((sx + sy + sz) % 2) == 0;
                if (ccw)
                    (void)m.add_face({a, b, d}).value();
                else
                    (void)m.add_face({a, d, b}).value();
            }
    return m;
}

// The enclosed volume by the divergence theorem, computed here, not by the library.
double enclosed_volume(const hmira::face_vertex_mesh& m) {
    double v = 0;
    for (auto f : m.faces()) {
        auto fv = m.face_vertices(f);
        const auto a = m.position(fv[0]);
        for (std::size_t i = 1; i + 1 < fv.size(); ++i) {
            const auto b = m.position(fv[i]), c = m.position(fv[i + 1]);
            v += a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) + a.z * (b.x * c.y - b.y * c.x);
        }
    }
    return v / 6;
}

bool same_bits(const hmira::bit_grid& a, const hmira::bit_grid& b) {
    return a.dims() == b.dims() && std::ranges::equal(a.words(), b.words());
}

TEST(VoxelizeCentres, octahedron_with_vertices_edges_and_faces_on_voxel_centres_counts_by_the_stated_tie_rule) {
    // Lattice points on the boundary belong to the (eps, eps^2, eps^3)-shifted point's side:
    // inside iff every face through the point has a normal with negative x, i.e. x < c.
    for (int r : {1, 2, 5, 8}) {
        const int c = 10;
        const auto mesh = octahedron(c, r);
        const hmira::grid_geometry g{{21, 21, 21}, {0, 0, 0}, {1, 1, 1}};
        auto v = hmira::voxelize(mesh, g, {.mode = hmira::voxelize_mode::centres});
        ASSERT_TRUE(v) << v.error().message;
        EXPECT_TRUE(v->filled);
        std::size_t expected = 0;
        for (int k = 0; k < 21; ++k)
            for (int j = 0; j < 21; ++j)
                for (int i = 0; i < 21; ++i) {
                    const int d = std::abs(i - c) + std::abs(j - c) + std::abs(k - c);
                    const bool in = d < r || (d == r && i < c);
                    expected += in;
                    ASSERT_EQ(v->voxels.value(std::size_t(i), std::size_t(j), std::size_t(k)), in ? 1 : 0)
                        << "r " << r << " voxel " << i << ' ' << j << ' ' << k;
                }
        EXPECT_EQ(v->voxels.count(), expected);
    }
}

TEST(VoxelizeCentres, rotated_octahedra_agree_with_an_independent_winding_number_away_from_the_surface) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> angle(0, 2 * std::numbers::pi), shift(-0.5, 0.5);
    for (int trial = 0; trial < 6; ++trial) {
        auto mesh = octahedron(0, 1);
        const double a = angle(rng), b = angle(rng);
        const vec3<double> t{shift(rng), shift(rng), shift(rng)};
        for (auto vh : mesh.vertices()) {
            auto p = mesh.position(vh);
            p = {std::cos(a) * p.x - std::sin(a) * p.y, std::sin(a) * p.x + std::cos(a) * p.y, p.z};
            p = {p.x, std::cos(b) * p.y - std::sin(b) * p.z, std::sin(b) * p.y + std::cos(b) * p.z};
            mesh.set_position(vh, p + t);
        }
        const hmira::grid_geometry g{{24, 24, 24}, {-1.5, -1.5, -1.5}, {0.13, 0.13, 0.13}};
        auto v = hmira::voxelize(mesh, g, {.mode = hmira::voxelize_mode::centres});
        ASSERT_TRUE(v);
        std::size_t checked = 0;
        for (std::size_t k = 0; k < 24; ++k)
            for (std::size_t j = 0; j < 24; ++j)
                for (std::size_t i = 0; i < 24; ++i) {
                    const vec3<double> p{-1.5 + 0.13 * double(i), -1.5 + 0.13 * double(j), -1.5 + 0.13 * double(k)};
                    double w = 0, closest = 1e9;
                    for (auto f : mesh.faces()) {
                        auto fv = mesh.face_vertices(f);
                        const auto x = mesh.position(fv[0]) - p, y = mesh.position(fv[1]) - p,
                                   z = mesh.position(fv[2]) - p;
                        const double lx = hmira::norm(x), ly = hmira::norm(y), lz = hmira::norm(z);
                        w += 2 * std::atan2(hmira::dot(x, hmira::cross(y, z)), lx * ly * lz + hmira::dot(x, y) * lz +
                                                                                   hmira::dot(y, z) * lx +
                                                                                   hmira::dot(z, x) * ly);
                        const auto n = hmira::cross(y - x, z - x);
                        closest =
                            std::min(closest, std::abs(hmira::dot(n, x)) / hmira::norm(n));  // distance to the plane
                    }
                    if (closest < 1e-6) continue;
                    ++checked;
                    ASSERT_EQ(v->voxels.value(i, j, k), w / (4 * std::numbers::pi) > 0.5 ? 1 : 0) << "trial " << trial;
                }
        EXPECT_GT(checked, 13000u);
    }
}

class CentresOnRealMesh : public ::testing::TestWithParam<const char*> {};

TEST_P(CentresOnRealMesh, count_is_within_half_a_percent_of_the_volume_and_solid_is_surface_or_centres) {
    const auto mesh = read(GetParam());
    if (mesh.face_count() == 0) GTEST_SKIP() << "test data not found: " << GetParam();
    const double volume = std::abs(enclosed_volume(mesh));
    const auto g = hmira::voxel_grid_around(mesh, 256, 2);
    ASSERT_TRUE(g);
    auto centres = hmira::voxelize(mesh, *g, {.mode = hmira::voxelize_mode::centres, .allow_degenerate = true});
    ASSERT_TRUE(centres) << centres.error().message;
    ASSERT_TRUE(centres->filled) << centres->note;
    const double h = g->spacing.x;
    const double measured = double(centres->voxels.count()) * h * h * h;
    EXPECT_NEAR(measured / volume, 1.0, 0.005) << GetParam() << ": " << centres->voxels.count() << " voxels";
#if defined(HMIRA_SANITIZER_BUILD)
    // Keeps the sanitizer run short: the big meshes only check the count there.
    if (mesh.face_count() > 20000) return;
#endif
    // solid (conservative) is exactly surface | centres.
    auto solid = hmira::voxelize(mesh, *g, {.mode = hmira::voxelize_mode::solid, .allow_degenerate = true});
    auto surface = hmira::voxelize(mesh, *g, {.mode = hmira::voxelize_mode::surface, .allow_degenerate = true});
    ASSERT_TRUE(solid && surface);
    const auto ws = solid->voxels.words(), wf = surface->voxels.words(), wc = centres->voxels.words();
    for (std::size_t w = 0; w < ws.size(); ++w) ASSERT_EQ(ws[w], wf[w] | wc[w]) << "word " << w;
    // The same bits for one thread and for all.
    auto one =
        hmira::voxelize(mesh, *g, {.mode = hmira::voxelize_mode::centres, .allow_degenerate = true, .threads = 1});
    ASSERT_TRUE(one);
    EXPECT_TRUE(same_bits(one->voxels, centres->voxels));
}

INSTANTIATE_TEST_SUITE_P(Closed, CentresOnRealMesh,
                         ::testing::Values("elephant.off", "armadillo.off", "bunny00.off", "fandisk.off"));

TEST(VoxelizeCentres, an_open_mesh_is_refused_or_reported_as_the_options_say) {
    auto mesh = octahedron(10, 5);
    (void)mesh.remove_face(*mesh.faces().begin());
    const hmira::grid_geometry g{{21, 21, 21}, {0, 0, 0}, {1, 1, 1}};
    auto refused =
        hmira::voxelize(mesh, g, {.mode = hmira::voxelize_mode::centres, .open_mesh = hmira::open_mesh_fill::fail});
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.error().code, hmira::errc::topology);
    EXPECT_NE(refused.error().message.find("centres"), std::string::npos);
    auto surface = hmira::voxelize(mesh, g, {.mode = hmira::voxelize_mode::centres});
    ASSERT_TRUE(surface);
    EXPECT_FALSE(surface->filled);
    EXPECT_NE(surface->note.find("surface voxels only"), std::string::npos);
}

// Every voxel of `block` equals the whole grid's.
::testing::AssertionResult block_matches(const hmira::bit_grid& whole, const hmira::voxel_block& block,
                                         const hmira::bit_grid& got) {
    if (got.dims() != block.dims) return ::testing::AssertionFailure() << "block dims differ";
    for (std::size_t k = 0; k < block.dims[2]; ++k)
        for (std::size_t j = 0; j < block.dims[1]; ++j)
            for (std::size_t i = 0; i < block.dims[0]; ++i)
                if (got.value(i, j, k) != whole.value(block.lo[0] + i, block.lo[1] + j, block.lo[2] + k))
                    return ::testing::AssertionFailure()
                           << "voxel " << block.lo[0] + i << ' ' << block.lo[1] + j << ' ' << block.lo[2] + k
                           << " of block at " << block.lo[0] << ' ' << block.lo[1] << ' ' << block.lo[2];
    return ::testing::AssertionSuccess();
}

#if defined(HMIRA_SANITIZER_BUILD)
constexpr std::size_t block_res = 40;
constexpr int block_trials = 2;
#else
constexpr std::size_t block_res = 96;
constexpr int block_trials = 5;
#endif

class BlocksOnRealMesh : public ::testing::TestWithParam<const char*> {};

TEST_P(BlocksOnRealMesh, blocks_of_random_sizes_equal_the_whole_grid_in_every_mode) {
    const auto mesh = read(GetParam());
    if (mesh.face_count() == 0) GTEST_SKIP() << "test data not found: " << GetParam();
    const auto g = hmira::voxel_grid_around(mesh, block_res, 2);
    ASSERT_TRUE(g);
    std::mt19937_64 rng(42);
    std::uniform_int_distribution<std::size_t> size(1, 64);
    for (auto mode : {hmira::voxelize_mode::centres, hmira::voxelize_mode::solid, hmira::voxelize_mode::surface}) {
        const hmira::voxelize_options options{.mode = mode, .allow_degenerate = true};
        auto whole = hmira::voxelize(mesh, *g, options);
        ASSERT_TRUE(whole);
        for (int trial = 0; trial < block_trials; ++trial) {
            // Sizes that do not divide the grid, single slabs, and the whole grid in one block.
            hmira::grid_dims bs{size(rng), size(rng), size(rng)};
            if (trial == 0) bs = {g->dims[0], g->dims[1], 1};
            if (trial == 1) bs = g->dims;
            std::size_t blocks = 0, set = 0;
            auto r = hmira::voxelize_blocks(mesh, *g, bs, options,
                                            [&](const hmira::voxel_block& b, hmira::voxelization&& v) {
                                                ++blocks;
                                                set += v.voxels.count();
                                                EXPECT_EQ(v.filled, whole->filled);
                                                EXPECT_TRUE(block_matches(whole->voxels, b, v.voxels))
                                                    << GetParam() << " mode " << int(mode) << " block size " << bs[0]
                                                    << ' ' << bs[1] << ' ' << bs[2];
                                                return !HasFailure();
                                            });
            ASSERT_TRUE(r) << r.error().message;
            EXPECT_EQ(set, whole->voxels.count());
            std::size_t expected = 1;
            for (int a = 0; a < 3; ++a) expected *= (g->dims[a] + bs[a] - 1) / bs[a];
            EXPECT_EQ(blocks, expected);
        }
        // Single blocks computed alone, anywhere in the grid.
        for (int trial = 0; trial < 2 * block_trials; ++trial) {
            hmira::voxel_block b;
            for (int a = 0; a < 3; ++a) {
                b.lo[a] = std::uniform_int_distribution<std::size_t>(0, g->dims[a] - 1)(rng);
                b.dims[a] = std::uniform_int_distribution<std::size_t>(1, g->dims[a] - b.lo[a])(rng);
            }
            auto v = hmira::voxelize_block(mesh, *g, b, options);
            ASSERT_TRUE(v) << v.error().message;
            EXPECT_TRUE(block_matches(whole->voxels, b, v->voxels));
            EXPECT_EQ(v->voxels.origin().x, g->origin.x + double(b.lo[0]) * g->spacing.x);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Closed, BlocksOnRealMesh, ::testing::Values("elephant.off", "fandisk.off", "sphere966.off"));

// The rays a triangle's crossings visit, row by row from the rounded run ends, are exactly
// those its exact perturbed test counts as crossing it. Corners on lattices of 1/10, 1/3 and
// 1/7 voxel (whose edges pass within rounding of voxel centres: the run ends then lie within
// an ulp of an integer) and of whole and half voxels (edges through centres and corners).
TEST(VoxelizeCrossings, the_rays_visited_are_exactly_those_the_exact_test_counts) {
    using hmira::detail::vox::crossing_triangle;
    std::mt19937_64 rng(20261206);
    const double steps[] = {10, 3, 7, 1, 2};
    std::size_t visited_total = 0, near_integer_ends = 0;
    for (int t = 0; t < 6000; ++t) {
        const double step = steps[t % 5];
        std::uniform_int_distribution<int> coordinate(int(-3 * step), int(15 * step));
        vec3<double> p[3];
        for (auto& q : p) q = {coordinate(rng) / step, coordinate(rng) / step, coordinate(rng) / step};
        const crossing_triangle ct(p[0], p[1], p[2]);
        if (ct.orient == 0) continue;
        std::vector<int> seen(26 * 26, 0);
        ct.for_each_ray(-5, 20, -5, 20, [&](long long j, long long k, const crossing_triangle::row_estimate&) {
            ASSERT_TRUE(j >= -5 && j <= 20 && k >= -5 && k <= 20);
            ++seen[std::size_t((k + 5) * 26 + (j + 5))];
        });
        for (long long k = -5; k <= 20; ++k)
            for (long long j = -5; j <= 20; ++j) {
                const int expected = ct.crossed_by(double(j), double(k)) ? 1 : 0;
                const int got = seen[std::size_t((k + 5) * 26 + (j + 5))];
                ASSERT_EQ(got, expected) << "triangle " << t << " ray (" << j << ", " << k << "): (" << p[0].x << ", "
                                         << p[0].y << ", " << p[0].z << ") (" << p[1].x << ", " << p[1].y << ", "
                                         << p[1].z << ") (" << p[2].x << ", " << p[2].y << ", " << p[2].z << ")";
                visited_total += std::size_t(got);
            }
        // How often a run end lies within 1e-12 of an integer without being one (the cases
        // the rounded ends alone could get wrong): the test must meet some.
        for (long long k = -5; k <= 20; ++k)
            for (int e = 0; e < 3; ++e) {
                const auto& a = p[e];
                const auto& b = p[(e + 1) % 3];
                if (!(std::min(a.z, b.z) < double(k) && double(k) < std::max(a.z, b.z))) continue;
                const double y = a.y + (double(k) - a.z) / (b.z - a.z) * (b.y - a.y);
                const double off = std::abs(y - std::round(y));
                near_integer_ends += off > 0 && off < 1e-12;
            }
    }
    EXPECT_GT(visited_total, 100000u);
    EXPECT_GT(near_integer_ends, 100u);
}

// voxelize() fills the grid in slabs of z-layers (512 KiB of words each: here 59 layers of
// 1100 one-word rows, so the grid has two). Octahedra in random orientations, cut by the slab
// boundary at z = 59: surface voxels equal a direct separating-axis test of every voxel near
// the mesh, centres an independent winding number, solid their union, with 1 and 2 threads.
TEST(VoxelizeSlabs, octahedra_across_a_slab_boundary_match_independent_tests_voxel_for_voxel) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> angle(0, 2 * std::numbers::pi), shift(-0.5, 0.5);
    const hmira::grid_geometry g{{64, 1100, 100}, {0, 0, 0}, {1, 1, 1}};
    for (int trial = 0; trial < 3; ++trial) {
        auto mesh = octahedron(0, 20);
        const double a = angle(rng), b = angle(rng);
        const vec3<double> centre{32 + shift(rng), 550 + shift(rng), 59 + shift(rng)};
        for (auto vh : mesh.vertices()) {
            auto p = mesh.position(vh);
            p = {std::cos(a) * p.x - std::sin(a) * p.y, std::sin(a) * p.x + std::cos(a) * p.y, p.z};
            p = {p.x, std::cos(b) * p.y - std::sin(b) * p.z, std::sin(b) * p.y + std::cos(b) * p.z};
            mesh.set_position(vh, p + centre);
        }
        std::vector<std::array<vec3<double>, 3>> tris;
        for (auto f : mesh.faces()) {
            auto fv = mesh.face_vertices(f);
            tris.push_back({mesh.position(fv[0]), mesh.position(fv[1]), mesh.position(fv[2])});
        }
        hmira::voxelization v[3][2];
        const hmira::voxelize_mode modes[3] = {hmira::voxelize_mode::surface, hmira::voxelize_mode::centres,
                                               hmira::voxelize_mode::solid};
        for (int m = 0; m < 3; ++m)
            for (unsigned t : {1u, 2u}) {
                auto r = hmira::voxelize(mesh, g, {.mode = modes[m], .threads = t});
                ASSERT_TRUE(r);
                v[m][t - 1] = std::move(*r);
            }
        for (int m = 0; m < 3; ++m)
            EXPECT_TRUE(std::ranges::equal(v[m][0].voxels.words(), v[m][1].voxels.words())) << "mode " << m;
        // Every set voxel lies within [12, 52] x [530, 570] x [39, 79]: count there and compare.
        std::size_t surface = 0, centres = 0, solid = 0, checked = 0;
        for (std::size_t k = 36; k <= 82; ++k)
            for (std::size_t j = 527; j <= 573; ++j)
                for (std::size_t i = 9; i <= 55; ++i) {
                    const vec3<double> p{double(i), double(j), double(k)};
                    bool touches = false;
                    double w = 0, closest = 1e9;
                    for (const auto& t : tris) {
                        bool boxes = true;  // the box normals, which triangle_box_overlap leaves to its caller
                        for (std::size_t c = 0; c < 3; ++c)
                            boxes &= std::min({t[0][c], t[1][c], t[2][c]}) <= p[c] + 0.5 &&
                                     std::max({t[0][c], t[1][c], t[2][c]}) >= p[c] - 0.5;
                        touches |= boxes && hmira::detail::triangle_box_overlap(p, 0.5, t[0], t[1], t[2]);
                        const auto x = t[0] - p, y = t[1] - p, z = t[2] - p;
                        const double lx = hmira::norm(x), ly = hmira::norm(y), lz = hmira::norm(z);
                        w += 2 * std::atan2(hmira::dot(x, hmira::cross(y, z)), lx * ly * lz + hmira::dot(x, y) * lz +
                                                                                   hmira::dot(y, z) * lx +
                                                                                   hmira::dot(z, x) * ly);
                        const auto n = hmira::cross(y - x, z - x);
                        closest = std::min(closest, std::abs(hmira::dot(n, x)) / hmira::norm(n));
                    }
                    const bool inside = w / (4 * std::numbers::pi) > 0.5;
                    const auto s = v[0][0].voxels.value(i, j, k), c = v[1][0].voxels.value(i, j, k),
                               d = v[2][0].voxels.value(i, j, k);
                    ASSERT_EQ(s, touches ? 1 : 0)
                        << "trial " << trial << " surface voxel " << i << ' ' << j << ' ' << k;
                    if (closest > 1e-6) {
                        ++checked;
                        ASSERT_EQ(c, inside ? 1 : 0) << "trial " << trial << " centre " << i << ' ' << j << ' ' << k;
                    }
                    ASSERT_EQ(d, s | c) << "trial " << trial << " solid voxel " << i << ' ' << j << ' ' << k;
                    surface += s;
                    centres += c;
                    solid += d;
                }
        EXPECT_EQ(surface, v[0][0].voxels.count());
        EXPECT_EQ(centres, v[1][0].voxels.count());
        EXPECT_EQ(solid, v[2][0].voxels.count());
        EXPECT_GT(checked, 90000u);
        // Both slabs hold part of the shape.
        std::size_t low = 0;
        for (std::size_t k = 0; k < 59; ++k)
            for (std::size_t j = 527; j <= 573; ++j)
                low += static_cast<std::size_t>(std::popcount(v[2][0].voxels.row(j, k)[0]));
        EXPECT_GT(low, solid / 4);
        EXPECT_LT(low, solid - solid / 4);
    }
}

TEST(VoxelizeBlocks, octahedron_on_voxel_centres_in_one_voxel_blocks_and_bad_blocks_are_refused) {
    const auto mesh = octahedron(10, 5);
    const hmira::grid_geometry g{{21, 21, 21}, {0, 0, 0}, {1, 1, 1}};
    for (auto mode : {hmira::voxelize_mode::centres, hmira::voxelize_mode::solid}) {
        auto whole = hmira::voxelize(mesh, g, {.mode = mode});
        ASSERT_TRUE(whole);
        std::size_t set = 0;
        auto r = hmira::voxelize_blocks(
            mesh, g, {1, 1, 1}, {.mode = mode}, [&](const hmira::voxel_block& b, hmira::voxelization&& v) {
                set += v.voxels.count();
                EXPECT_EQ(v.voxels.value(0, 0, 0), whole->voxels.value(b.lo[0], b.lo[1], b.lo[2]))
                    << int(mode) << " at " << b.lo[0] << ' ' << b.lo[1] << ' ' << b.lo[2];
                return true;
            });
        ASSERT_TRUE(r);
        EXPECT_EQ(set, whole->voxels.count());
    }
    auto outside = hmira::voxelize_block(mesh, g, {{20, 0, 0}, {2, 1, 1}});
    ASSERT_FALSE(outside);
    EXPECT_EQ(outside.error().code, hmira::errc::invalid_argument);
    EXPECT_NE(outside.error().message.find("along x"), std::string::npos) << outside.error().message;
    auto empty = hmira::voxelize_block(mesh, g, {{0, 0, 0}, {1, 0, 1}});
    ASSERT_FALSE(empty);
    EXPECT_NE(empty.error().message.find("along y"), std::string::npos);
    auto zero = hmira::voxelize_blocks(mesh, g, {0, 4, 4}, {},
                                       [](const hmira::voxel_block&, hmira::voxelization&&) { return true; });
    ASSERT_FALSE(zero);
    // Stopping early hands over no more blocks.
    std::size_t seen = 0;
    ASSERT_TRUE(hmira::voxelize_blocks(mesh, g, {7, 7, 7}, {},
                                       [&](const hmira::voxel_block&, hmira::voxelization&&) { return ++seen < 3; }));
    EXPECT_EQ(seen, 3u);
}

}  // namespace
