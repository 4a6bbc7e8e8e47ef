// Voxelization: conservative surface, parity fill against analytic counts, open meshes,
// determinism, and the voxelize -> marching cubes round trip on real closed meshes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <initializer_list>
#include <iomanip>
#include <random>
#include <utility>

#include <hmira/algorithms/conversion/marching_cubes.hpp>
#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/conversion/voxelize.hpp>
#include <hmira/algorithms/topology/mesh_topology.hpp>
#include <hmira/grids/dense_grid.hpp>
#include <hmira/grids/implicit_shapes.hpp>
#include <hmira/grids/sample.hpp>
#include <hmira/io/off.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "support/checks.hpp"
#include "support/exact_box_triangle.hpp"

#if defined(HMIRA_HAS_TBB)
#include <tbb/global_control.h>
#endif

namespace {

using hmira::vec3;

#if defined(HMIRA_SANITIZER_BUILD)
constexpr std::size_t real_res = 40;
#else
constexpr std::size_t real_res = 96;
#endif

// A closed triangulated sphere (marching cubes of its distance field; checked closed below).
hmira::face_vertex_mesh sphere_mesh(double r, std::size_t n = 48) {
    auto g = hmira::sample_function(hmira::cube_geometry(n, -1, 1), hmira::sphere_field{{0, 0, 0}, r});
    hmira::face_vertex_mesh m;
    (void)hmira::marching_cubes(m, *g).value();
    return m;
}

hmira::grid_geometry box_geometry(std::size_t n, double half) {
    const double h = 2 * half / double(n);
    return {{n, n, n}, {-half + 0.5 * h, -half + 0.5 * h, -half + 0.5 * h}, {h, h, h}};
}

double area(const hmira::face_vertex_mesh& m) {
    double a = 0;
    for (auto f : m.faces()) {
        auto fv = m.face_vertices(f);
        for (std::size_t i = 1; i + 1 < fv.size(); ++i)
            a += 0.5 * hmira::norm(hmira::cross(m.position(fv[i]) - m.position(fv[0]),
                                                m.position(fv[i + 1]) - m.position(fv[0])));
    }
    return a;
}

TEST(Voxelize, solid_sphere_matches_analytic_inside_test_outside_the_surface_band) {
    const double r = 0.7;
    const auto mesh = sphere_mesh(r, 64);
    ASSERT_TRUE(hmira::mesh_topology(mesh).closed());
    for (std::size_t n : {20u, 41u, 64u}) {
        const auto geo = box_geometry(n, 1.0);
        auto v = hmira::voxelize(mesh, geo, {.mode = hmira::voxelize_mode::solid});
        ASSERT_TRUE(v) << v.error().message;
        EXPECT_TRUE(v->filled);
        EXPECT_TRUE(v->note.empty());
        const double h = geo.spacing.x;
        // The mesh lies within ~h_mc^2 of the sphere; a voxel touching it has its centre within
        // half a diagonal of it.
        const double band = std::sqrt(3.0) / 2 * h + 0.01;
        std::size_t analytic = 0, mismatched = 0;
        for (std::size_t k = 0; k < n; ++k)
            for (std::size_t j = 0; j < n; ++j)
                for (std::size_t i = 0; i < n; ++i) {
                    const double d = hmira::norm(geo.position(i, j, k)) - r;
                    const bool set = v->voxels.value(i, j, k);
                    analytic += d < 0;
                    if (d < -band && !set) ++mismatched;
                    if (d > band && set) ++mismatched;
                }
        EXPECT_EQ(mismatched, 0u) << n;
        // And the count is the analytic one up to the band's voxels.
        const double band_voxels = 4 * std::numbers::pi * r * r * 2 * band / (h * h * h);
        EXPECT_NEAR(double(v->voxels.count()), double(analytic), band_voxels) << n;
    }
}

TEST(Voxelize, surface_mode_marks_a_thin_conservative_shell) {
    const double r = 0.7;
    const auto mesh = sphere_mesh(r);
    const auto geo = box_geometry(32, 1.0);
    auto v = hmira::voxelize(mesh, geo, {.mode = hmira::voxelize_mode::surface});
    ASSERT_TRUE(v);
    EXPECT_FALSE(v->filled);
    const double h = geo.spacing.x;
    for (std::size_t k = 0; k < 32; ++k)
        for (std::size_t j = 0; j < 32; ++j)
            for (std::size_t i = 0; i < 32; ++i) {
                const double d = std::abs(hmira::norm(geo.position(i, j, k)) - r);
                if (d > std::sqrt(3.0) / 2 * h + 0.01) {
                    EXPECT_EQ(v->voxels.value(i, j, k), 0);
                }
            }
    // Conservative: every vertex of the mesh lies in a set voxel.
    for (auto vh : mesh.vertices()) {
        const auto p = mesh.position(vh);
        const auto i = std::size_t(std::lround((p.x - geo.origin.x) / h)),
                   j = std::size_t(std::lround((p.y - geo.origin.y) / h)),
                   k = std::size_t(std::lround((p.z - geo.origin.z) / h));
        EXPECT_EQ(v->voxels.value(i, j, k), 1);
    }
}

TEST(Voxelize, single_triangle_marks_exactly_the_boxes_it_crosses) {
    // Compare the separating-axis test against dense point sampling of the triangle: every
    // voxel containing a sample point must be set, and a set voxel must lie near the triangle.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.5, 7.5);
    for (int trial = 0; trial < 20; ++trial) {
        hmira::face_vertex_mesh m;
        auto a = m.add_vertex({u(rng), u(rng), u(rng)}), b = m.add_vertex({u(rng), u(rng), u(rng)}),
             c = m.add_vertex({u(rng), u(rng), u(rng)});
        ASSERT_TRUE(m.add_face({a, b, c}));
        const hmira::grid_geometry geo{{9, 9, 9}, {0, 0, 0}, {1, 1, 1}};
        auto v = hmira::voxelize(m, geo, {.mode = hmira::voxelize_mode::surface});
        ASSERT_TRUE(v);
        const auto pa = m.position(a), pb = m.position(b), pc = m.position(c);
        for (int s = 0; s <= 200; ++s)
            for (int t = 0; s + t <= 200; ++t) {
                const auto p = pa + (pb - pa) * (s / 200.0) + (pc - pa) * (t / 200.0);
                EXPECT_EQ(v->voxels.value(std::size_t(std::lround(p.x)), std::size_t(std::lround(p.y)),
                                          std::size_t(std::lround(p.z))),
                          1);
            }
        // No voxel farther than half a diagonal from the triangle's plane is set.
        const auto n = hmira::normalized(hmira::cross(pb - pa, pc - pa));
        for (std::size_t k = 0; k < 9; ++k)
            for (std::size_t j = 0; j < 9; ++j)
                for (std::size_t i = 0; i < 9; ++i)
                    if (v->voxels.value(i, j, k)) {
                        EXPECT_LE(std::abs(hmira::dot(n, vec3<double>{double(i), double(j), double(k)} - pa)),
                                  std::sqrt(3.0) / 2 + 1e-9);
                    }
    }
}

TEST(Voxelize, open_mesh_in_solid_mode_says_so_and_keeps_the_surface) {
    auto mesh = sphere_mesh(0.7);
    ASSERT_TRUE(mesh.remove_face(hmira::face_handle(0)));
    mesh.collect_garbage();
    const auto geo = box_geometry(32, 1.0);
    auto v = hmira::voxelize(mesh, geo);
    ASSERT_TRUE(v);
    EXPECT_FALSE(v->filled);
    EXPECT_NE(v->note.find("not closed"), std::string::npos);
    auto surface = hmira::voxelize(mesh, geo, {.mode = hmira::voxelize_mode::surface});
    ASSERT_TRUE(surface);
    EXPECT_EQ(v->voxels.count(), surface->voxels.count());
    EXPECT_EQ(v->voxels.value(16, 16, 16), 0);

    auto refused = hmira::voxelize(mesh, geo, {.open_mesh = hmira::open_mesh_fill::fail});
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.error().code, hmira::errc::topology);

    // The winding number sees through the small hole: the ball is filled all the same.
    auto closed = hmira::voxelize(sphere_mesh(0.7), geo);
    auto wn = hmira::voxelize(mesh, geo, {.open_mesh = hmira::open_mesh_fill::winding_number});
    ASSERT_TRUE(wn && closed);
    EXPECT_TRUE(wn->filled);
    EXPECT_EQ(wn->voxels.value(16, 16, 16), 1);
    EXPECT_NEAR(double(wn->voxels.count()), double(closed->voxels.count()), 0.01 * double(closed->voxels.count()));
}

TEST(Voxelize, output_is_identical_for_1_2_and_8_threads) {
    const auto mesh = sphere_mesh(0.8, 40);
    const auto geo = box_geometry(57, 1.0);
    std::vector<std::vector<std::uint64_t>> runs;
    for (unsigned threads : {1u, 2u, 8u}) {
#if defined(HMIRA_HAS_TBB)
        tbb::global_control gc(tbb::global_control::max_allowed_parallelism, threads);
#endif
        auto v = hmira::voxelize(mesh, geo, {.threads = threads});
        ASSERT_TRUE(v);
        runs.emplace_back(v->voxels.words().begin(), v->voxels.words().end());
    }
    EXPECT_TRUE(runs[1] == runs[0]);
    EXPECT_TRUE(runs[2] == runs[0]);
}

TEST(Voxelize, works_on_halfedge_mesh_and_writable_grids) {
    auto g = hmira::sample_function(hmira::cube_geometry(24, -1, 1), hmira::torus_field{{0, 0, 0}, 0.6, 0.25});
    hmira::halfedge_mesh he;
    ASSERT_TRUE(hmira::marching_cubes(he, *g));
    const auto geo = box_geometry(30, 1.0);
    auto bits = hmira::voxelize(he, geo);
    ASSERT_TRUE(bits);
    EXPECT_TRUE(bits->filled);
    hmira::dense_grid<float> dense(geo, 7.0f);
    auto v = hmira::voxelize_into(he, dense);
    ASSERT_TRUE(v);
    std::size_t ones = 0;
    for (float x : dense.values()) {
        EXPECT_TRUE(x == 0.0f || x == 1.0f);
        ones += x == 1.0f;
    }
    EXPECT_EQ(ones, bits->voxels.count());
    EXPECT_EQ(bits->voxels.value(15, 15, 15), 0);  // the torus's hole
}

TEST(VoxelizeBadInput, nan_positions_degenerate_triangles_and_bad_grids_are_refused) {
    const hmira::grid_geometry geo{{8, 8, 8}, {0, 0, 0}, {1, 1, 1}};
    hmira::face_vertex_mesh m;
    auto a = m.add_vertex({1, 1, 1}), b = m.add_vertex({2, 1, 1}), c = m.add_vertex({3, 1, 1});
    ASSERT_TRUE(m.add_face({a, b, c}));  // collinear: zero area
    auto deg = hmira::voxelize(m, geo);
    ASSERT_FALSE(deg);
    EXPECT_EQ(deg.error().code, hmira::errc::degenerate_face);
    EXPECT_NE(deg.error().message.find("zero area"), std::string::npos);
    EXPECT_TRUE(hmira::voxelize(m, geo, {.allow_degenerate = true}));

    hmira::face_vertex_mesh n;
    auto p = n.add_vertex({1, 1, 1}), q = n.add_vertex({2, std::nan(""), 1}), r = n.add_vertex({1, 3, 1});
    ASSERT_TRUE(n.add_face({p, q, r}));
    auto bad = hmira::voxelize(n, geo);
    ASSERT_FALSE(bad);
    EXPECT_NE(bad.error().message.find("non-finite"), std::string::npos);

    const auto sphere = sphere_mesh(0.5, 16);
    EXPECT_FALSE(hmira::voxelize(sphere, hmira::grid_geometry{{8, 0, 8}, {0, 0, 0}, {1, 1, 1}}));
    auto zero = hmira::voxelize(sphere, hmira::grid_geometry{{8, 8, 8}, {0, 0, 0}, {0, 1, 1}});
    ASSERT_FALSE(zero);
    EXPECT_NE(zero.error().message.find("spacing"), std::string::npos);
    EXPECT_FALSE(hmira::voxel_grid_around(hmira::face_vertex_mesh{}, 32));
}

TEST(voxelize, the_default_grid_leaves_an_empty_layer_even_where_the_surface_lies_on_the_bounding_box) {
    hmira::face_vertex_mesh cube;
    ASSERT_TRUE(hmira::generate_cube(cube));  // every face lies on the bounding box
    for (std::size_t res : {4u, 7u, 16u}) {
        const auto geo = hmira::voxel_grid_around(cube, res);
        ASSERT_TRUE(geo);
        const auto vox = hmira::voxelize(cube, *geo);
        ASSERT_TRUE(vox) << vox.error().message;
        const auto d = vox->voxels.dims();
        std::size_t on_border = 0;
        for (std::size_t k = 0; k < d[2]; ++k)
            for (std::size_t j = 0; j < d[1]; ++j)
                for (std::size_t i = 0; i < d[0]; ++i)
                    if (i == 0 || j == 0 || k == 0 || i + 1 == d[0] || j + 1 == d[1] || k + 1 == d[2])
                        on_border += vox->voxels.value(i, j, k);
        EXPECT_EQ(on_border, 0u) << "resolution " << res;
        // The cube spans res voxels; those touching its faces from outside may be set too.
        EXPECT_GE(vox->voxels.count(), res * res * res) << "resolution " << res;
        EXPECT_LE(vox->voxels.count(), (res + 2) * (res + 2) * (res + 2)) << "resolution " << res;
        hmira::face_vertex_mesh back;
        ASSERT_TRUE(hmira::marching_cubes(back, vox->voxels, {.iso = 0.5, .inside = hmira::iso_inside::above}));
        EXPECT_TRUE(hmira::mesh_topology(back).closed()) << "resolution " << res;
    }
}

std::filesystem::path data_dir() {
    const char* d = std::getenv("HMIRA_TEST_DATA");
    return d ? std::filesystem::path(d) : std::filesystem::path();
}

class RealMesh : public ::testing::TestWithParam<const char*> {};

TEST_P(RealMesh, voxelize_then_marching_cubes_is_closed_with_volume_within_one_voxel_layer) {
    const auto path = data_dir() / "meshes" / GetParam();
    if (data_dir().empty() || !std::filesystem::exists(path)) GTEST_SKIP() << "test data not found: " << path;
    hmira::face_vertex_mesh mesh;
    ASSERT_TRUE(hmira::io::read_off(mesh, path));
    const auto topo = hmira::mesh_topology(mesh);
    ASSERT_TRUE(topo.closed()) << GetParam() << " is expected to be closed";
    const double volume = std::abs(hmira_test::signed_volume(mesh));
    auto geo = hmira::voxel_grid_around(mesh, real_res, 2);
    ASSERT_TRUE(geo);
    auto vox = hmira::voxelize(mesh, *geo, {.allow_degenerate = true});
    ASSERT_TRUE(vox) << vox.error().message;
    ASSERT_TRUE(vox->filled) << vox->note;
    hmira::face_vertex_mesh back;
    ASSERT_TRUE(hmira::marching_cubes(back, vox->voxels, {.iso = 0.5, .inside = hmira::iso_inside::above}));
    EXPECT_TRUE(hmira_test::is_valid(back));
    const auto t = hmira::mesh_topology(back);
    EXPECT_TRUE(t.closed());
    const double h = geo->spacing.x;
    const double got = hmira_test::signed_volume(back);
    EXPECT_GT(got, 0);
    EXPECT_NEAR(got, volume, area(mesh) * h) << "volume off by more than one voxel layer";
    // Every voxel of a conservative voxelization that holds a vertex is set.
    for (auto v : mesh.vertices()) {
        const auto p = mesh.position(v);
        const auto i = std::size_t(std::lround((p.x - geo->origin.x) / h)),
                   j = std::size_t(std::lround((p.y - geo->origin.y) / h)),
                   k = std::size_t(std::lround((p.z - geo->origin.z) / h));
        ASSERT_EQ(vox->voxels.value(i, j, k), 1);
    }
}

INSTANTIATE_TEST_SUITE_P(Closed, RealMesh, ::testing::Values("elephant.off", "fandisk.off"));

}  // namespace

namespace {

// The prepared per-triangle test must agree with the direct separating-axis test.
TEST(TriangleBox, prepared_test_agrees_with_direct_separating_axis_test) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-2, 2);
    int overlaps = 0, agree = 0, total = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const vec3<double> a{u(rng), u(rng), u(rng)}, b{u(rng), u(rng), u(rng)}, c{u(rng), u(rng), u(rng)};
        const hmira::detail::triangle_box_tester prepared(a, b, c, 0.5);
        for (int q = 0; q < 10; ++q) {
            const vec3<double> center{std::round(u(rng)), std::round(u(rng)), std::round(u(rng))};
            // Only boxes the bounding boxes allow: the caller checks the box normals.
            bool bbox = true;
            for (std::size_t k = 0; k < 3; ++k)
                bbox &=
                    std::min({a[k], b[k], c[k]}) <= center[k] + 0.5 && std::max({a[k], b[k], c[k]}) >= center[k] - 0.5;
            if (!bbox) continue;
            const bool direct = hmira::detail::triangle_box_overlap(center, 0.5, a, b, c);
            ++total;
            overlaps += direct;
            agree += direct == prepared.overlaps(center);
        }
    }
    EXPECT_EQ(agree, total);
    EXPECT_GT(overlaps, 0);
    EXPECT_LT(overlaps, total);  // both outcomes occur, so the comparison means something
}

}  // namespace

namespace {

// A random triangle of one of the kinds the surface walk treats specially: general position;
// corners on the half-voxel lattice (on voxel centres, faces, edges and corners, often axis-
// aligned or edge-on); flat in one axis (its normal along it); long slivers; corners on the
// quarter-voxel lattice; an axis-aligned edge on the lattice with the third corner anywhere
// (its ends touch voxels at a single corner); two lattice corners and one on a face plane.
std::array<vec3<double>, 3> random_triangle(std::mt19937& rng, int kind) {
    std::uniform_real_distribution<double> u(1.0, 13.0);
    std::uniform_int_distribution<int> half(2, 26), quarter(4, 52);
    auto lattice = [&] { return vec3<double>{half(rng) * 0.5, half(rng) * 0.5, half(rng) * 0.5}; };
    auto point = [&] { return vec3<double>{u(rng), u(rng), u(rng)}; };
    switch (kind) {
        case 0: return {point(), point(), point()};
        case 1: return {lattice(), lattice(), lattice()};
        case 2: {
            std::array<vec3<double>, 3> t{point(), point(), point()};
            const std::size_t axis = std::size_t(half(rng) % 3);
            const double level =
                half(rng) % 2 ? half(rng) * 0.5 : u(rng);  // on a voxel face or centre plane, or anywhere
            for (auto& p : t) p[axis] = level;
            return t;
        }
        case 3: {
            const vec3<double> a = point(), b = point();
            return {a, b, a + (b - a) * 0.5 + vec3<double>{0.05, -0.03, 0.02}};
        }
        case 4:
            return {vec3<double>{quarter(rng) * 0.25, quarter(rng) * 0.25, quarter(rng) * 0.25},
                    vec3<double>{quarter(rng) * 0.25, quarter(rng) * 0.25, quarter(rng) * 0.25},
                    vec3<double>{quarter(rng) * 0.25, quarter(rng) * 0.25, quarter(rng) * 0.25}};
        case 5: {
            const vec3<double> a = lattice();
            vec3<double> b = a;
            b[std::size_t(half(rng) % 3)] = half(rng) * 0.5;
            return {a, b, point()};
        }
        case 6: {
            vec3<double> c = lattice();
            c[std::size_t(half(rng) % 3)] = u(rng);
            return {lattice(), lattice(), c};
        }
        default: {
            const vec3<double> a = lattice(), b = lattice();
            return {a, b, a + (b - a) * 0.25 + vec3<double>{0, 0, 1e-9}};
        }
    }
}

// Voxelizes random triangles of the given kinds alone (surface mode, one thread) and compares
// every voxel of the grid with the exact per-voxel separating-axis test: each voxel the
// triangle touches must be set (exact ties included), and each voxel set must touch the
// triangle once its box is widened by `slack` on every side (the walk's rounding margin).
// Reports the first disagreements of each kind; returns the voxels compared and how many the
// triangle touches.
std::pair<long long, long long> compare_with_exact_test(std::initializer_list<int> kinds, int trials, unsigned seed,
                                                        double slack) {
    std::mt19937 rng(seed);
    const hmira::grid_geometry geo{{15, 15, 15}, {0, 0, 0}, {1, 1, 1}};
    long long touched = 0, tested = 0;
    for (int kind : kinds) {
        long long wrong[2] = {};  // voxels set that the triangle does not touch, touched ones left empty
        for (int trial = 0; trial < trials; ++trial) {
            const auto t = random_triangle(rng, kind);
            hmira::face_vertex_mesh m;
            auto a = m.add_vertex(t[0]), b = m.add_vertex(t[1]), c = m.add_vertex(t[2]);
            EXPECT_TRUE(m.add_face({a, b, c}));
            auto v = hmira::voxelize(m, geo,
                                     {.mode = hmira::voxelize_mode::surface, .allow_degenerate = true, .threads = 1});
            if (!v) {
                ADD_FAILURE() << v.error().message;
                continue;
            }
            const bool degenerate = v->degenerate_triangles == 1;  // adds no voxels of its own (allow_degenerate)
            // A voxel whose centre lies farther from the plane than its half-diagonal (by a wide
            // margin: the rounded plane of a well-shaped triangle is off by far less) can
            // neither touch the triangle nor be set; the exact test (slow) is kept for the rest.
            const vec3<double> normal = hmira::cross(t[1] - t[0], t[2] - t[1]);
            const double normal_length = hmira::norm(normal);
            const bool well_shaped = normal_length > 1e-6 * hmira::norm(t[1] - t[0]) * hmira::norm(t[2] - t[1]);
            for (std::size_t k = 0; k < 15; ++k)
                for (std::size_t j = 0; j < 15; ++j)
                    for (std::size_t i = 0; i < 15; ++i) {
                        const vec3<double> centre{double(i), double(j), double(k)};
                        const bool set = v->voxels.value(i, j, k) != 0;
                        ++tested;
                        if (well_shaped &&
                            std::abs(hmira::dot(normal, centre - t[0])) > (0.8661 + 1e-3) * normal_length) {
                            if (set && ++wrong[0] <= 2)
                                ADD_FAILURE() << "kind " << kind << " trial " << trial << ": voxel " << i << ' ' << j
                                              << ' ' << k << " set, far from the plane";
                            continue;
                        }
                        const bool touches =
                            !degenerate && hmira_test::exact_box_meets_triangle(centre, 0.5, t[0], t[1], t[2]);
                        touched += touches;
                        const bool wrongly_empty = touches && !set;
                        const bool wrongly_set =
                            set && !touches &&
                            !hmira_test::exact_box_meets_triangle(centre, 0.5 + slack, t[0], t[1], t[2]);
                        if (!wrongly_empty && !wrongly_set) continue;
                        if (++wrong[wrongly_empty] <= 2)
                            ADD_FAILURE()
                                << "kind " << kind << " trial " << trial << ": voxel " << i << ' ' << j << ' ' << k
                                << (wrongly_empty ? " touched but left empty" : " set but not touched") << "; triangle "
                                << std::setprecision(17) << t[0].x << ' ' << t[0].y << ' ' << t[0].z << ", " << t[1].x
                                << ' ' << t[1].y << ' ' << t[1].z << ", " << t[2].x << ' ' << t[2].y << ' ' << t[2].z;
                    }
        }
        EXPECT_EQ(wrong[0], 0) << "kind " << kind << ": voxels set that the triangle does not touch";
        EXPECT_EQ(wrong[1], 0) << "kind " << kind << ": voxels the triangle touches left empty";
    }
    return {tested, touched};
}

// The surface walk (rows of columns, the plane test alone where a column lies inside the
// triangle's shadow, the full test at the shadow's edge) sets every voxel the triangle touches
// and none that misses it by more than 1e-9 of a voxel: in general position, with corners on
// voxel centres, faces, edges and corners, in a voxel-face plane (touching the voxels on both
// sides), for slivers, and with a lattice edge whose ends touch voxels at one corner only.
// Before the walk's projections were taken relative to a corner and its reach widened, lattice
// triangles lost touched voxels at exact ties and face-plane ones lost a whole side; before
// its intervals were widened by a rounding margin, a lattice edge's end lost the voxel it
// touches at a corner (kind 5).
TEST(VoxelizeSurface, random_triangles_set_every_voxel_they_touch_and_none_they_miss) {
    const auto [tested, touched] = compare_with_exact_test({0, 1, 2, 3, 4, 5, 6}, 400, 20, 1e-9);
    EXPECT_GT(touched, 1000);         // the comparison met many touched voxels
    EXPECT_LT(touched, tested / 10);  // and many untouched ones
}

// Triangles a hair (1e-9 voxel) from degenerate: the normal is a difference of nearly equal
// products, known only to about 1e-7 of itself. The walk still sets every voxel the triangle
// touches; the voxels it sets beyond those lie within 1e-3 of a voxel of the triangle.
TEST(VoxelizeSurface, nearly_degenerate_triangles_lose_no_voxel) {
    const auto [tested, touched] = compare_with_exact_test({7}, 300, 21, 1e-3);
    EXPECT_GT(touched, 1000);
    EXPECT_LT(touched, tested / 10);
}

// A triangle whose normal is no larger than its rounding (its third corner 1e-15 off the line
// of the other two, across a 60-voxel grid): its plane is unknown, so the walk's reach along
// the columns spans the whole bounding box, and only the edge axes keep the voxels near the
// segment. Every voxel the segment passes through is set (the triangle holds the segment), and
// none far from it. With the doubt about the plane capped at two voxels, 34 of those voxels
// were left empty; uncapped without the edge axes cutting the reach, each column tested the
// whole bounding box.
TEST(VoxelizeSurface, a_triangle_flat_to_rounding_sets_its_segment_voxels_and_stays_near_it) {
    const vec3<double> a{1.3, 2.1, 1.7}, b{58.6, 41.2, 29.9};
    const vec3<double> c = a + (b - a) * 0.37 + vec3<double>{0, 1e-15, 1e-15};
    hmira::face_vertex_mesh m;
    auto va = m.add_vertex(a), vb = m.add_vertex(b), vc = m.add_vertex(c);
    ASSERT_TRUE(m.add_face({va, vb, vc}));
    const hmira::grid_geometry geo{{62, 62, 62}, {0, 0, 0}, {1, 1, 1}};
    auto v = hmira::voxelize(m, geo, {.mode = hmira::voxelize_mode::surface, .allow_degenerate = true, .threads = 1});
    ASSERT_TRUE(v) << v.error().message;
    ASSERT_EQ(v->degenerate_triangles, 0u);  // not exactly collinear: the walk does run
    const vec3<double> d = b - a;
    std::size_t far = 0, missed = 0;
    for (std::size_t k = 0; k < 62; ++k)
        for (std::size_t j = 0; j < 62; ++j)
            for (std::size_t i = 0; i < 62; ++i) {
                const vec3<double> p{double(i), double(j), double(k)};
                const double t = std::clamp(hmira::dot(p - a, d) / hmira::dot(d, d), 0.0, 1.0);
                const double distance = hmira::norm(p - (a + d * t));
                const bool set = v->voxels.value(i, j, k) != 0;
                far += set && distance > 4.5;
                missed += !set && distance < 0.4;  // the segment passes through its box
            }
    EXPECT_EQ(far, 0u);
    EXPECT_EQ(missed, 0u);
    EXPECT_GT(v->voxels.count(), 60u);
}

// The exact oracle itself, on cases decided by hand: a box touching a corner, an edge or a
// face of the triangle at one point or along a line counts; one a hair away does not.
TEST(VoxelizeSurface, the_exact_oracle_counts_touching_and_only_touching) {
    using hmira_test::exact_box_meets_triangle;
    const vec3<double> o{0, 0, 0};
    // Corner (0.5, 0.5, 0.5) of the box around the origin is a corner of the triangle.
    EXPECT_TRUE(exact_box_meets_triangle(o, 0.5, {0.5, 0.5, 0.5}, {3, 0.7, 0.9}, {0.6, 2, 4}));
    EXPECT_FALSE(exact_box_meets_triangle(o, 0.5, {0.5 + 1e-15, 0.5, 0.5}, {3, 0.7, 0.9}, {0.6, 2, 4}));
    // The triangle lies in the box's face plane z = 0.5: touching along a region.
    EXPECT_TRUE(exact_box_meets_triangle(o, 0.5, {-3, -3, 0.5}, {3, -3, 0.5}, {0, 3, 0.5}));
    EXPECT_FALSE(exact_box_meets_triangle(o, 0.5, {-3, -3, 0.5000000000000001}, {3, -3, 0.5000000000000001},
                                          {0, 3, 0.5000000000000001}));
    // An edge passes exactly through the box's edge x = 0.5, y = 0.5 (the plane x + y = 1 holds
    // the triangle), the rest of the triangle outside: touching along a line.
    EXPECT_TRUE(exact_box_meets_triangle(o, 0.5, {0.5, 0.5, -2}, {0.5, 0.5, 2}, {3, -2, 0}));
    // The same triangle moved by 2^-50 along y: its bounding box still touches the box, but
    // no point of it does.
    const double d = 0x1p-50;
    EXPECT_FALSE(exact_box_meets_triangle(o, 0.5, {0.5, 0.5 + d, -2}, {0.5, 0.5 + d, 2}, {3, -2 + d, 0}));
    // Bounding boxes overlap, the plane passes beside the box's corner or through it.
    EXPECT_FALSE(
        exact_box_meets_triangle(o, 0.5, {2, 0, 0}, {0, 2, 0}, {0, 0, 2}));  // x + y + z = 2 misses the box (max 1.5)
    EXPECT_TRUE(
        exact_box_meets_triangle(o, 0.5, {1.5, 0, 0}, {0, 1.5, 0}, {0, 0, 1.5}));  // x + y + z = 1.5 touches its corner
}

// Exactly collinear corners: refused by default, accepted with no voxels of their own.
TEST(VoxelizeSurface, a_zero_area_triangle_is_refused_or_adds_no_voxels) {
    hmira::face_vertex_mesh m;
    auto a = m.add_vertex({1, 1, 1}), b = m.add_vertex({5, 3, 7}), c = m.add_vertex({3, 2, 4});
    ASSERT_TRUE(m.add_face({a, b, c}));
    const hmira::grid_geometry geo{{9, 9, 9}, {0, 0, 0}, {1, 1, 1}};
    EXPECT_FALSE(hmira::voxelize(m, geo, {.mode = hmira::voxelize_mode::surface}));
    auto v = hmira::voxelize(m, geo, {.mode = hmira::voxelize_mode::surface, .allow_degenerate = true});
    ASSERT_TRUE(v);
    EXPECT_EQ(v->degenerate_triangles, 1u);
    EXPECT_EQ(v->voxels.count(), 0u);
}

}  // namespace
