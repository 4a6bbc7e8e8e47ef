// Marching cubes: welded, closed, oriented, deterministic output on analytic fields, noise
// and 8-bit-like volumes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstring>
#include <memory>
#include <type_traits>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <string>

#include <hmira/algorithms/conversion/marching_cubes.hpp>
#include <hmira/algorithms/topology/mesh_topology.hpp>
#include <hmira/grids/dense_grid.hpp>
#include <hmira/grids/implicit_shapes.hpp>
#include <hmira/grids/sample.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "support/checks.hpp"

#if defined(HMIRA_HAS_TBB)
#include <tbb/global_control.h>
#endif

namespace {

using hmira::vec3;

#if defined(HMIRA_SANITIZER_BUILD)
constexpr std::size_t big_n = 40;
#else
constexpr std::size_t big_n = 96;
#endif

double mesh_area(const hmira::face_vertex_mesh& m) {
    double a = 0;
    for (auto f : m.faces()) {
        auto fv = m.face_vertices(f);
        const auto p = m.position(fv[0]), q = m.position(fv[1]), r = m.position(fv[2]);
        a += 0.5 * hmira::norm(hmira::cross(q - p, r - p));
    }
    return a;
}

void expect_closed_manifold(const hmira::face_vertex_mesh& m, long long genus, std::size_t components) {
    EXPECT_TRUE(hmira_test::is_valid(m));
    const auto t = hmira::mesh_topology(m);
    EXPECT_TRUE(t.closed()) << t.boundary_edges << " boundary edges, " << t.non_manifold_edges << " non-manifold edges";
    EXPECT_EQ(t.isolated_vertices, 0u);
    if (genus >= 0) {
        EXPECT_EQ(t.genus, genus);
    }
    if (components) {
        EXPECT_EQ(t.components, components);
    }
}

TEST(MarchingCubesTable, every_case_closes_and_triangulates) {
    // Building the table throws if any configuration leaves an open contour or a loop that
    // cannot be triangulated without a chord along a cube face.
    const auto& t = hmira::detail::mc::table();
    EXPECT_EQ(t.entries[t.first[0]].count, 0);
    EXPECT_EQ(t.entries[t.first[255]].count, 0);
    for (int c = 1; c < 255; ++c)
        for (unsigned d = 0; d < (1u << t.ambiguous_count[c]); ++d) EXPECT_GT(t.entries[t.first[c] + d].count, 0) << c;
}

TEST(MarchingCubes, sphere_is_closed_genus0_with_analytic_volume_and_area) {
    for (std::size_t n : {16u, 33u, unsigned(big_n)}) {
        const double r = 0.8;
        auto grid = hmira::sample_function(hmira::cube_geometry(n, -1, 1), hmira::sphere_field{{0.01, -0.02, 0.03}, r});
        ASSERT_TRUE(grid);
        hmira::face_vertex_mesh m;
        auto out = hmira::marching_cubes(m, *grid);
        ASSERT_TRUE(out) << out.error().message;
        expect_closed_manifold(m, 0, 1);
        const double h = grid->spacing().x;
        const double vol = hmira_test::signed_volume(m);
        const double exact_vol = 4.0 / 3.0 * std::numbers::pi * r * r * r;
        const double exact_area = 4 * std::numbers::pi * r * r;
        // Interpolated vertices lie within O(h^2) of the sphere; chords cut inside by h^2/(8r).
        EXPECT_GT(vol, 0) << "normals must point outward";
        EXPECT_NEAR(vol, exact_vol, exact_area * h * h) << n;
        EXPECT_NEAR(mesh_area(m), exact_area, exact_area * 2 * h) << n;
    }
}

TEST(MarchingCubes, torus_is_closed_genus1) {
    auto grid =
        hmira::sample_function(hmira::cube_geometry(big_n, -1.5, 1.5), hmira::torus_field{{0, 0, 0.05}, 1.0, 0.35});
    ASSERT_TRUE(grid);
    hmira::face_vertex_mesh m;
    ASSERT_TRUE(hmira::marching_cubes(m, *grid));
    expect_closed_manifold(m, 1, 1);
    const double h = grid->spacing().x;
    const double exact_vol = 2 * std::numbers::pi * std::numbers::pi * 1.0 * 0.35 * 0.35;
    const double exact_area = 4 * std::numbers::pi * std::numbers::pi * 1.0 * 0.35;
    EXPECT_NEAR(hmira_test::signed_volume(m), exact_vol, exact_area * h * h);
    EXPECT_NEAR(mesh_area(m), exact_area, exact_area * 2 * h);
}

TEST(MarchingCubes, inside_above_flips_orientation_not_shape) {
    auto grid =
        hmira::sample_function(hmira::cube_geometry(24, -1, 1), [](vec3<double> p) { return -(hmira::norm(p) - 0.7); });
    ASSERT_TRUE(grid);
    hmira::face_vertex_mesh m;
    ASSERT_TRUE(hmira::marching_cubes(m, *grid, {.inside = hmira::iso_inside::above}));
    expect_closed_manifold(m, 0, 1);
    EXPECT_GT(hmira_test::signed_volume(m), 0);
}

TEST(MarchingCubes, works_on_halfedge_mesh_builder) {
    auto grid = hmira::sample_function(hmira::cube_geometry(20, -1, 1), hmira::torus_field{{0, 0, 0}, 0.6, 0.25});
    ASSERT_TRUE(grid);
    hmira::halfedge_mesh m;
    auto out = hmira::marching_cubes(m, *grid);
    ASSERT_TRUE(out) << out.error().message;
    EXPECT_TRUE(hmira_test::is_valid(m));
    const auto t = hmira::mesh_topology(m);
    EXPECT_TRUE(t.closed());
    EXPECT_EQ(t.genus, 1);
}

// Random noise padded with an outside layer: every ambiguous configuration shows up, with
// every decision, and the surface must still close.
TEST(MarchingCubes, seeded_noise_fields_are_closed_manifolds) {
    for (unsigned seed = 1; seed <= 12; ++seed) {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<float> u(-1, 1);
        const std::size_t n = 12 + seed % 5;
        hmira::dense_grid<float> g({{n, n + 1, n + 2}, {0, 0, 0}, {1, 1, 1}}, 1.0f);
        for (std::size_t k = 1; k + 1 < n + 2; ++k)
            for (std::size_t j = 1; j + 1 < n + 1; ++j)
                for (std::size_t i = 1; i + 1 < n; ++i) g.set(i, j, k, u(rng));
        for (double iso : {0.0, 0.3, -0.4}) {
            hmira::face_vertex_mesh m;
            ASSERT_TRUE(hmira::marching_cubes(m, g, {.iso = iso}));
            SCOPED_TRACE("seed " + std::to_string(seed) + " iso " + std::to_string(iso));
            expect_closed_manifold(m, -1, 0);
            EXPECT_GT(hmira_test::signed_volume(m), 0);
        }
    }
}

// 8-bit-like data: values in {0, 1, 2}, iso 1, so a third of the samples equal the iso value.
TEST(MarchingCubes, samples_equal_to_iso_give_no_duplicate_vertices_or_zero_area_triangles) {
    for (unsigned seed = 1; seed <= 6; ++seed) {
        std::mt19937 rng(seed);
        const std::size_t n = 14;
        hmira::dense_grid<std::uint8_t> g({{n, n, n}, {0, 0, 0}, {1, 1, 1}}, 0);
        for (std::size_t k = 1; k + 1 < n; ++k)
            for (std::size_t j = 1; j + 1 < n; ++j)
                for (std::size_t i = 1; i + 1 < n; ++i) g.set(i, j, k, static_cast<std::uint8_t>(rng() % 3));
        for (auto inside : {hmira::iso_inside::above, hmira::iso_inside::below}) {
            auto tri = hmira::marching_cubes_indexed<double>(g, {.iso = 1.0, .inside = inside});
            ASSERT_TRUE(tri);
            std::set<std::array<double, 3>> seen;
            for (const auto& p : tri->positions)
                EXPECT_TRUE(seen.insert({p.x, p.y, p.z}).second) << "duplicate position";
            for (const auto& t : tri->triangles) {
                const auto a = tri->positions[t[0]], b = tri->positions[t[1]], c = tri->positions[t[2]];
                EXPECT_GT(hmira::norm(hmira::cross(b - a, c - a)), 0);
            }
            hmira::face_vertex_mesh m;
            ASSERT_TRUE(hmira::marching_cubes(m, g, {.iso = 1.0, .inside = inside}));
            expect_closed_manifold(m, -1, 0);  // validate also reports zero-area faces
            // Above: the solid {v >= 1} floats inside the layer of 0s, positive volume. Below:
            // the solid {v <= 1} fills the box around pockets of 2s, so the surface bounds
            // cavities, whose outward normals point into them: negative volume.
            if (inside == hmira::iso_inside::above) {
                EXPECT_GT(hmira_test::signed_volume(m), 0);
            } else {
                EXPECT_LT(hmira_test::signed_volume(m), 0);
            }
        }
    }
}

TEST(MarchingCubes, crossing_positions_interpolate_linearly_for_any_iso) {
    // f = x along a 4-sample axis: the surface f = iso is the plane x = iso exactly.
    hmira::dense_grid<double> g({{4, 3, 3}, {0, 0, 0}, {1, 1, 1}}, 0.0);
    for (std::size_t k = 0; k < 3; ++k)
        for (std::size_t j = 0; j < 3; ++j)
            for (std::size_t i = 0; i < 4; ++i) g.set(i, j, k, double(i));
    for (double iso : {0.25, 1.5, 2.9}) {
        auto tri = hmira::marching_cubes_indexed<double>(g, {.iso = iso});
        ASSERT_TRUE(tri);
        ASSERT_FALSE(tri->positions.empty());
        for (const auto& p : tri->positions) EXPECT_DOUBLE_EQ(p.x, iso);
    }
}

TEST(MarchingCubes, gradient_normals_point_outward_and_are_unit) {
    auto grid = hmira::sample_function(hmira::cube_geometry(32, -1, 1), hmira::sphere_field{{0, 0, 0}, 0.6});
    ASSERT_TRUE(grid);
    for (auto inside : {hmira::iso_inside::below, hmira::iso_inside::above}) {
        hmira::dense_grid<float> g = *grid;
        if (inside == hmira::iso_inside::above)
            for (auto& v : g.values()) v = -v;
        auto tri = hmira::marching_cubes_indexed<double>(g, {.inside = inside, .normals = true});
        ASSERT_TRUE(tri);
        ASSERT_EQ(tri->normals.size(), tri->positions.size());
        for (std::size_t v = 0; v < tri->positions.size(); ++v) {
            EXPECT_NEAR(hmira::norm(tri->normals[v]), 1.0, 1e-9);
            EXPECT_GT(hmira::dot(tri->normals[v], hmira::normalized(tri->positions[v])), 0.95);
        }
    }
}

TEST(MarchingCubes, output_is_identical_for_1_2_and_8_threads) {
    auto grid = hmira::sample_function(hmira::cube_geometry(big_n, -3, 3), hmira::gyroid_field{2.0});
    ASSERT_TRUE(grid);
    std::vector<hmira::indexed_triangles<float>> runs;
    for (unsigned threads : {1u, 2u, 8u}) {
#if defined(HMIRA_HAS_TBB)
        tbb::global_control gc(tbb::global_control::max_allowed_parallelism, threads);
#endif
        auto tri = hmira::marching_cubes_indexed(*grid, {.normals = true, .threads = threads});
        ASSERT_TRUE(tri);
        runs.push_back(std::move(*tri));
    }
    ASSERT_FALSE(runs[0].triangles.empty());
    for (std::size_t r = 1; r < runs.size(); ++r) {
        EXPECT_TRUE(runs[r].positions == runs[0].positions);
        EXPECT_TRUE(runs[r].triangles == runs[0].triangles);
        EXPECT_TRUE(runs[r].normals == runs[0].normals);
    }
}

// The output arrays are not zeroed before the writing pass, so every slot must be written:
// a slot left out would show what the memory held before, here a 0xA5 pattern.
TEST(MarchingCubes, output_does_not_depend_on_what_its_memory_held_before) {
    auto grid = hmira::sample_function(hmira::cube_geometry(40, -3, 3), hmira::gyroid_field{2.0});
    ASSERT_TRUE(grid);
    const auto first = hmira::marching_cubes_indexed<double>(*grid, {.normals = true, .threads = 2});
    ASSERT_TRUE(first);
    ASSERT_FALSE(first->triangles.empty());
    const std::size_t bytes[3] = {first->positions.size() * sizeof(vec3<double>),
                                  first->triangles.size() * sizeof(first->triangles[0]),
                                  first->normals.size() * sizeof(vec3<double>)};
    for (int round = 0; round < 3; ++round) {
        {
            // Freed just before the call, so that the allocator is likely to hand these back.
            std::vector<std::vector<unsigned char>> dirt;
            for (std::size_t b : bytes) dirt.emplace_back(b, 0xA5);
        }
        const unsigned threads = unsigned(round) + 1;
        const auto again = hmira::marching_cubes_indexed<double>(*grid, {.normals = true, .threads = threads});
        ASSERT_TRUE(again);
        ASSERT_EQ(again->positions.size(), first->positions.size());
        ASSERT_EQ(again->triangles.size(), first->triangles.size());
        ASSERT_EQ(again->normals.size(), first->normals.size());
        EXPECT_EQ(std::memcmp(again->positions.data(), first->positions.data(), bytes[0]), 0);
        EXPECT_EQ(std::memcmp(again->triangles.data(), first->triangles.data(), bytes[1]), 0);
        EXPECT_EQ(std::memcmp(again->normals.data(), first->normals.data(), bytes[2]), 0);
    }
    // Independent of the memory's history: every triangle names an existing vertex and every
    // normal is a unit vector.
    for (const auto& t : first->triangles)
        for (auto v : t) EXPECT_LT(v, first->positions.size());
    for (const auto& n : first->normals) EXPECT_NEAR(hmira::norm(n), 1.0, 1e-9);
}

TEST(UninitializedVector, behaves_as_std_vector_wherever_it_is_given_values) {
    hmira::uninitialized_vector<vec3<float>> v;
    v.push_back({1, 2, 3});
    v.resize(3, vec3<float>{4, 5, 6});
    v.emplace_back(vec3<float>{7, 8, 9});
    ASSERT_EQ(v.size(), 4u);
    EXPECT_EQ(v[0], (vec3<float>{1, 2, 3}));
    EXPECT_EQ(v[1], (vec3<float>{4, 5, 6}));
    EXPECT_EQ(v[2], (vec3<float>{4, 5, 6}));
    EXPECT_EQ(v[3], (vec3<float>{7, 8, 9}));
    v.resize(6);  // unwritten: written here before being read
    v[4] = {10, 11, 12};
    v[5] = {13, 14, 15};
    EXPECT_EQ(v[5], (vec3<float>{13, 14, 15}));
    const auto copy = v;
    EXPECT_TRUE(copy == v);
    // Stateless allocators compare equal, so a move hands the buffer over without copying.
    const auto* data = v.data();
    const auto moved = std::move(v);
    EXPECT_EQ(moved.data(), data);
    EXPECT_TRUE(moved == copy);
    static_assert(std::allocator_traits<hmira::uninitialized_allocator<int>>::is_always_equal::value);
    static_assert(std::is_same_v<std::allocator_traits<hmira::uninitialized_allocator<int>>::rebind_alloc<double>,
                                 hmira::uninitialized_allocator<double>>);
}

TEST(MarchingCubes, user_vector_is_read_in_place_and_matches_dense_grid) {
    const hmira::grid_geometry geo = hmira::cube_geometry(20, -1, 1);
    auto dense = hmira::sample_function(geo, hmira::torus_field{{0, 0, 0}, 0.6, 0.2});
    ASSERT_TRUE(dense);
    std::vector<float> mine(dense->values().begin(), dense->values().end());
    auto view = hmira::make_grid_view(mine, geo);
    ASSERT_TRUE(view);
    EXPECT_EQ(view->data(), mine.data());
    auto a = hmira::marching_cubes_indexed(*dense);
    auto b = hmira::marching_cubes_indexed(*view);
    ASSERT_TRUE(a && b);
    EXPECT_TRUE(a->positions == b->positions);
    EXPECT_TRUE(a->triangles == b->triangles);
}

// A grid that offers only value(i, j, k): the generic path must agree with the fast one.
struct function_grid {
    using value_type = double;
    hmira::grid_geometry g;
    hmira::grid_dims dims() const { return g.dims; }
    vec3<double> origin() const { return g.origin; }
    vec3<double> spacing() const { return g.spacing; }
    double value(std::size_t i, std::size_t j, std::size_t k) const {
        return hmira::sphere_field{{0, 0, 0}, 0.5}(g.position(i, j, k));
    }
};

TEST(MarchingCubes, generic_grid_without_storage_matches_dense_grid) {
    function_grid fg{hmira::cube_geometry(18, -1, 1)};
    auto dense = hmira::sample_function<double>(fg.g, hmira::sphere_field{{0, 0, 0}, 0.5});
    ASSERT_TRUE(dense);
    auto a = hmira::marching_cubes_indexed<double>(fg);
    auto b = hmira::marching_cubes_indexed<double>(*dense);
    ASSERT_TRUE(a && b);
    EXPECT_TRUE(a->positions == b->positions);
    EXPECT_TRUE(a->triangles == b->triangles);
}

template <class V>
class MarchingCubesNonFinite : public ::testing::Test {};
using non_finite_sample_types = ::testing::Types<float, double>;
TYPED_TEST_SUITE(MarchingCubesNonFinite, non_finite_sample_types);

// A sphere field (inside below 0) of 70 x 9 x 8 samples: rows of one whole 64-sample word
// and a tail, so that the vectorised and the scalar classification both meet the bad sample.
template <class V>
hmira::dense_grid<V> sphere_70() {
    hmira::dense_grid<V> g({{70, 9, 8}, {-1, -1, -1}, {2.0 / 69, 0.25, 2.0 / 7}});
    for (std::size_t k = 0; k < 8; ++k)
        for (std::size_t j = 0; j < 9; ++j)
            for (std::size_t i = 0; i < 70; ++i) {
                const auto p = g.geometry().position(i, j, k);
                g.set(i, j, k, static_cast<V>(p.x * p.x + p.y * p.y + p.z * p.z - 0.5));
            }
    return g;
}

TYPED_TEST(MarchingCubesNonFinite, infinite_and_nan_samples_are_refused_naming_the_sample) {
    using V = TypeParam;
    const V inf = std::numeric_limits<V>::infinity();
    struct where {
        std::size_t i, j, k;
    };
    // In a whole word, in the tail word, on the first and the last sample, on an inside and an
    // outside sample.
    for (const where w : {where{5, 4, 3}, where{66, 1, 6}, where{0, 0, 0}, where{69, 8, 7}, where{35, 4, 4}}) {
        for (const V bad : {inf, -inf, std::numeric_limits<V>::quiet_NaN()}) {
            auto g = sphere_70<V>();
            g.set(w.i, w.j, w.k, bad);
            const std::string name = "sample (" + std::to_string(w.i) + ", " + std::to_string(w.j) + ", " +
                                     std::to_string(w.k) + ") is " +
                                     (bad != bad ? "NaN"
                                      : bad > 0  ? "inf"
                                                 : "-inf");
            for (unsigned threads : {1u, 2u}) {
                auto r = hmira::marching_cubes_indexed<double>(g, {.threads = threads});
                ASSERT_FALSE(r) << name << ": " << r->positions.size() << " vertices";
                EXPECT_EQ(r.error().code, hmira::errc::invalid_argument);
                EXPECT_NE(r.error().message.find(name), std::string::npos) << r.error().message;
                EXPECT_EQ(r.error().element, static_cast<long long>(w.i + 70 * (w.j + 9 * w.k)));
                EXPECT_EQ(std::count(r.error().message.begin(), r.error().message.end(), '\n'), 0);
            }
            // Into a mesh: refused before the mesh is touched.
            hmira::halfedge_mesh m;
            auto into = hmira::marching_cubes(m, g);
            ASSERT_FALSE(into);
            EXPECT_EQ(m.vertex_count(), 0u);
            EXPECT_EQ(m.face_count(), 0u);
        }
    }
    // The same grid without the bad sample meshes, with finite positions only.
    auto r = hmira::marching_cubes_indexed<double>(sphere_70<V>());
    ASSERT_TRUE(r);
    EXPECT_GT(r->triangles.size(), 0u);
    for (const auto& p : r->positions) EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
}

// Samples read through value() only (no data()): the generic classification path.
struct infinite_at_grid {
    using value_type = double;
    hmira::grid_geometry g{{6, 5, 4}, {0, 0, 0}, {1, 1, 1}};
    hmira::grid_dims dims() const { return g.dims; }
    vec3<double> origin() const { return g.origin; }
    vec3<double> spacing() const { return g.spacing; }
    double value(std::size_t i, std::size_t j, std::size_t k) const {
        return (i == 4 && j == 1 && k == 2) ? std::numeric_limits<double>::infinity() : double(i) - 2.5;
    }
};

TEST(MarchingCubesBadInput, an_infinite_sample_of_a_grid_without_storage_is_refused) {
    auto r = hmira::marching_cubes_indexed<double>(infinite_at_grid{});
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().message.find("sample (4, 1, 2) is inf"), std::string::npos) << r.error().message;
}

template <class V>
class MarchingCubesIsoRange : public ::testing::Test {};
using iso_range_sample_types = ::testing::Types<std::uint8_t, std::int16_t, float, double>;
TYPED_TEST_SUITE(MarchingCubesIsoRange, iso_range_sample_types);

TYPED_TEST(MarchingCubesIsoRange, an_iso_outside_the_samples_range_is_refused_naming_the_range) {
    using V = TypeParam;
    // A ball of 40 in a background of 12, as a CT's bone in air: range [12, 40].
    hmira::dense_grid<V> g({{12, 11, 10}, {0, 0, 0}, {1, 1, 1}}, V(12));
    for (std::size_t k = 3; k < 7; ++k)
        for (std::size_t j = 3; j < 8; ++j)
            for (std::size_t i = 4; i < 8; ++i) g.set(i, j, k, V(40));
    for (auto inside : {hmira::iso_inside::below, hmira::iso_inside::above})
        for (double iso : {0.0, 11.5, 40.5, 300.0, -7.0}) {
            auto r = hmira::marching_cubes_indexed<double>(g, {.iso = iso, .inside = inside});
            ASSERT_FALSE(r) << "iso " << iso;
            EXPECT_EQ(r.error().code, hmira::errc::invalid_argument);
            EXPECT_NE(r.error().message.find("outside the samples' range [12, 40]"), std::string::npos)
                << r.error().message;
            hmira::face_vertex_mesh m;
            EXPECT_FALSE(hmira::marching_cubes(m, g, {.iso = iso, .inside = inside}));
            EXPECT_EQ(m.vertex_count(), 0u);
        }
    // Inside the range: the ball's surface, closed.
    auto ball = hmira::marching_cubes_indexed<double>(g, {.iso = 26, .inside = hmira::iso_inside::above});
    ASSERT_TRUE(ball);
    EXPECT_GT(ball->triangles.size(), 0u);
    // At either end of the range: accepted. The ends that put every sample on one side give
    // no triangles; the others still give the ball (samples equal to iso count as inside).
    auto at = [&](double iso, hmira::iso_inside inside) {
        return hmira::marching_cubes_indexed<double>(g, {.iso = iso, .inside = inside});
    };
    auto below_max = at(40, hmira::iso_inside::below), above_min = at(12, hmira::iso_inside::above);
    ASSERT_TRUE(below_max && above_min);
    EXPECT_EQ(below_max->triangles.size(), 0u);
    EXPECT_EQ(above_min->triangles.size(), 0u);
    auto below_min = at(12, hmira::iso_inside::below), above_max = at(40, hmira::iso_inside::above);
    ASSERT_TRUE(below_min && above_max);
    EXPECT_GT(below_min->triangles.size(), 0u);
    EXPECT_GT(above_max->triangles.size(), 0u);
    // A grid of equal samples: its one value is its range.
    hmira::dense_grid<V> flat({{5, 5, 5}, {0, 0, 0}, {1, 1, 1}}, V(7));
    EXPECT_TRUE(hmira::marching_cubes_indexed<double>(flat, {.iso = 7}));
    auto off = hmira::marching_cubes_indexed<double>(flat, {.iso = 8});
    ASSERT_FALSE(off);
    EXPECT_NE(off.error().message.find("iso 8 is outside the samples' range [7, 7]"), std::string::npos)
        << off.error().message;
}

TEST(MarchingCubesBadInput, nan_zero_spacing_and_empty_grids_are_refused_without_touching_the_mesh) {
    hmira::dense_grid<float> g({{4, 4, 4}, {0, 0, 0}, {1, 1, 1}}, 1.0f);
    g.set(1, 2, 3, std::numeric_limits<float>::quiet_NaN());
    hmira::face_vertex_mesh m;
    auto r = hmira::marching_cubes(m, g);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, hmira::errc::invalid_argument);
    EXPECT_NE(r.error().message.find("sample (1, 2, 3) is NaN"), std::string::npos) << r.error().message;
    EXPECT_EQ(m.vertex_count(), 0u);

    hmira::dense_grid<float> zero({{4, 4, 4}, {0, 0, 0}, {1, 0, 1}}, 1.0f);
    auto z = hmira::marching_cubes(m, zero);
    ASSERT_FALSE(z);
    EXPECT_NE(z.error().message.find("spacing"), std::string::npos);

    hmira::dense_grid<float> empty({{0, 4, 4}, {0, 0, 0}, {1, 1, 1}});
    EXPECT_FALSE(hmira::marching_cubes(m, empty));
    hmira::dense_grid<float> flat({{5, 1, 5}, {0, 0, 0}, {1, 1, 1}});
    EXPECT_FALSE(hmira::marching_cubes(m, flat));
    EXPECT_FALSE(hmira::marching_cubes(m, g, {.iso = std::numeric_limits<double>::infinity()}));
    EXPECT_EQ(m.vertex_count(), 0u);
    EXPECT_EQ(m.face_count(), 0u);
}

TEST(MarchingCubes, surface_with_no_crossing_is_empty_when_the_iso_is_in_the_range_and_refused_otherwise) {
    hmira::dense_grid<float> g({{5, 5, 5}, {0, 0, 0}, {1, 1, 1}}, 2.0f);
    auto tri = hmira::marching_cubes_indexed(g, {.iso = 2.0});
    ASSERT_TRUE(tri);
    EXPECT_TRUE(tri->positions.empty());
    EXPECT_TRUE(tri->triangles.empty());
    auto outside = hmira::marching_cubes_indexed(g);  // the default iso 0 lies below every sample
    ASSERT_FALSE(outside);
    EXPECT_EQ(outside.error().message,
              "marching_cubes: iso 0 is outside the samples' range [2, 2], so there is no surface; choose an iso "
              "between them");
}

}  // namespace
