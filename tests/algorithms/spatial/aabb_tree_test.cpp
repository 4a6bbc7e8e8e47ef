// aabb_tree: closest_point and ray_intersect agree with a brute-force scan (written here with
// other formulas: plane projection plus segment clamping, plane hit plus same-side tests) on
// random triangle soups and on real meshes; an empty tree misses; bad positions are refused.
// The quality tool (bench/quality): Hausdorff 0 to itself, the shift to a translated copy.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <limits>
#include <random>

#include <hmira/algorithms/spatial/aabb_tree.hpp>
#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "quality/quality.hpp"

namespace {

using hmira::vec3;
using v3 = vec3<double>;

struct soup {
    std::vector<v3> points;
    std::vector<std::array<std::uint32_t, 3>> triangles;
};

v3 closest_on_segment(const v3& p, const v3& a, const v3& b) {
    const v3 d = b - a;
    const double l2 = hmira::dot(d, d);
    if (l2 == 0) return a;
    const double t = std::clamp(hmira::dot(p - a, d) / l2, 0.0, 1.0);
    return a + d * t;
}

// Independent of the library: projection onto the plane if it falls inside, else the best of
// the three edges.
double brute_distance_to_triangle(const v3& p, const v3& a, const v3& b, const v3& c) {
    const v3 n = hmira::cross(b - a, c - a);
    const double n2 = hmira::dot(n, n);
    if (n2 > 0) {
        const v3 q = p - n * (hmira::dot(p - a, n) / n2);
        const bool inside = hmira::dot(hmira::cross(b - a, q - a), n) >= 0 &&
                            hmira::dot(hmira::cross(c - b, q - b), n) >= 0 &&
                            hmira::dot(hmira::cross(a - c, q - c), n) >= 0;
        if (inside) return hmira::norm(q - p);
    }
    return std::min({hmira::norm(closest_on_segment(p, a, b) - p), hmira::norm(closest_on_segment(p, b, c) - p),
                     hmira::norm(closest_on_segment(p, c, a) - p)});
}

double brute_closest(const soup& s, const v3& p) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& t : s.triangles)
        best = std::min(best, brute_distance_to_triangle(p, s.points[t[0]], s.points[t[1]], s.points[t[2]]));
    return best;
}

// Plane hit, then the point must be on the inner side of all three edges.
double brute_ray(const soup& s, const hmira::ray& r) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& t : s.triangles) {
        const v3 a = s.points[t[0]], b = s.points[t[1]], c = s.points[t[2]];
        const v3 n = hmira::cross(b - a, c - a);
        const double den = hmira::dot(n, r.direction);
        if (den == 0) continue;
        const double u = hmira::dot(a - r.origin, n) / den;
        if (u < r.t_min || u > r.t_max) continue;
        const v3 q = r.origin + r.direction * u;
        const double e = 1e-12 * hmira::dot(n, n);
        if (hmira::dot(hmira::cross(b - a, q - a), n) >= -e && hmira::dot(hmira::cross(c - b, q - b), n) >= -e &&
            hmira::dot(hmira::cross(a - c, q - c), n) >= -e)
            best = std::min(best, u);
    }
    return best;
}

soup random_soup(std::size_t n, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> pos(-1, 1), off(-0.1, 0.1);
    soup s;
    for (std::size_t i = 0; i < n; ++i) {
        const v3 c{pos(rng), pos(rng), pos(rng)};
        for (int k = 0; k < 3; ++k) s.points.push_back(c + v3{off(rng), off(rng), off(rng)});
        s.triangles.push_back({std::uint32_t(3 * i), std::uint32_t(3 * i + 1), std::uint32_t(3 * i + 2)});
    }
    return s;
}

std::filesystem::path data_dir() {
    const char* d = std::getenv("HMIRA_TEST_DATA");
    return d ? std::filesystem::path(d) / "meshes" : std::filesystem::path();
}

#ifdef HMIRA_SANITIZER_BUILD
constexpr int queries = 60;
constexpr std::size_t real_mesh_samples = 20000, real_mesh_per_triangle = 1;
#else
constexpr int queries = 400;
constexpr std::size_t real_mesh_samples = 200000, real_mesh_per_triangle = 10;
#endif

void check_against_brute_force(const soup& s, const hmira::aabb_tree& tree, unsigned seed, double spread) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> pos(-spread, spread), dir(-1, 1);
    for (int i = 0; i < queries; ++i) {
        const v3 p{pos(rng), pos(rng), pos(rng)};
        const auto r = tree.closest_point(p);
        const double expected = brute_closest(s, p);
        ASSERT_NEAR(r.distance, expected, 1e-9 * (1 + expected)) << "query " << i;
        EXPECT_NEAR(hmira::norm(r.point - p), r.distance, 1e-9 * (1 + expected));
        // The point lies on the triangle it names.
        ASSERT_LT(r.face, s.triangles.size());
        const auto& t = s.triangles[r.face];
        EXPECT_LT(brute_distance_to_triangle(r.point, s.points[t[0]], s.points[t[1]], s.points[t[2]]),
                  1e-9 * (1 + expected));

        const hmira::ray ray{.origin = p, .direction = {dir(rng), dir(rng), dir(rng)}};
        const auto hit = tree.ray_intersect(ray);
        const double t_expected = brute_ray(s, ray);
        if (std::isinf(t_expected)) {
            // A graze the brute force misses by its tolerance may still be a hit; never a far one.
            if (hit) {
                const auto& t = s.triangles[hit->face];
                EXPECT_LT(brute_distance_to_triangle(hit->point, s.points[t[0]], s.points[t[1]], s.points[t[2]]), 1e-9);
            }
        } else {
            ASSERT_TRUE(hit) << "query " << i;
            EXPECT_NEAR(hit->t, t_expected, 1e-9 * (1 + t_expected));
            EXPECT_NEAR(hmira::norm(hit->point - (ray.origin + ray.direction * hit->t)), 0, 1e-12 * (1 + hit->t));
        }
    }
}

TEST(aabb_tree, closest_point_and_ray_match_brute_force_on_random_soups) {
    for (std::size_t n : {1u, 2u, 5u, 17u, 300u}) {
        SCOPED_TRACE(n);
        const soup s = random_soup(n, unsigned(n));
        const hmira::aabb_tree tree(s.points, s.triangles);
        EXPECT_EQ(tree.size(), n);
        check_against_brute_force(s, tree, 7u + unsigned(n), 1.5);
    }
}

TEST(aabb_tree, closest_point_and_ray_match_brute_force_on_real_meshes) {
    const auto dir = data_dir();
    if (dir.empty() || !std::filesystem::exists(dir / "elephant.off")) GTEST_SKIP() << "run scripts/test-data.sh first";
    for (const char* name : {"elephant.off", "fandisk.off"}) {
        SCOPED_TRACE(name);
        hmira::halfedge_mesh m;
        ASSERT_TRUE(hmira::io::read_mesh(m, dir / name));
        auto tree = hmira::aabb_tree_from_mesh(m);
        ASSERT_TRUE(tree) << tree.error().message;
        using T = hmira::default_traits<hmira::halfedge_mesh>;
        soup s;
        s.points.resize(T::vertex_index_bound(m));
        for (auto v : T::vertices(m)) {
            const auto p = T::position(m, v);
            s.points[T::vertex_index(m, v)] = {double(p.x), double(p.y), double(p.z)};
        }
        s.triangles.resize(T::face_index_bound(m));
        for (auto f : T::faces(m)) {
            std::vector<std::uint32_t> loop;
            for (auto v : T::face_vertices(m, f)) loop.push_back(std::uint32_t(T::vertex_index(m, v)));
            ASSERT_EQ(loop.size(), 3u);
            s.triangles[T::face_index(m, f)] = {loop[0], loop[1], loop[2]};
        }
        EXPECT_EQ(tree->size(), T::face_count(m));
        // Queries around the mesh's own extent (both meshes fit in a few units).
        v3 lo{1e300, 1e300, 1e300}, hi = -lo;
        for (const auto& p : s.points)
            for (std::size_t k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
        const double spread = 0.75 * std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
        // Shift the soup so the random queries centred on 0 cover the mesh.
        const v3 centre = (lo + hi) * 0.5;
        for (auto& p : s.points) p = p - centre;
        const hmira::aabb_tree centred(s.points, s.triangles);
        check_against_brute_force(s, centred, 11, spread);
        // Vertices are on the surface: distance 0.
        for (std::size_t i = 0; i < s.points.size(); i += 97)
            EXPECT_EQ(centred.closest_point(s.points[i]).distance, 0.0);
    }
}

TEST(aabb_tree, known_answers_on_one_triangle) {
    const std::vector<v3> pts{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const std::vector<std::array<std::uint32_t, 3>> tri{{0, 1, 2}};
    const std::vector<std::size_t> ids{42};
    const hmira::aabb_tree tree(pts, tri, ids);
    auto r = tree.closest_point({0.25, 0.25, 2});
    EXPECT_EQ(r.face, 42u);
    EXPECT_DOUBLE_EQ(r.distance, 2);
    EXPECT_EQ(r.point, (v3{0.25, 0.25, 0}));
    r = tree.closest_point({-1, -1, 0});  // vertex region
    EXPECT_EQ(r.point, (v3{0, 0, 0}));
    EXPECT_DOUBLE_EQ(r.distance, std::sqrt(2.0));
    r = tree.closest_point({1, 1, 0});  // hypotenuse region
    EXPECT_NEAR(r.point.x, 0.5, 1e-15);
    EXPECT_NEAR(r.point.y, 0.5, 1e-15);
    // Bounded search: nothing closer than 1 -> infinity.
    EXPECT_TRUE(std::isinf(tree.closest_point({0.25, 0.25, 2}, 1.0).distance));

    auto h = tree.ray_intersect({.origin = {0.2, 0.2, 1}, .direction = {0, 0, -2}});
    ASSERT_TRUE(h);
    EXPECT_DOUBLE_EQ(h->t, 0.5);
    EXPECT_EQ(h->face, 42u);
    EXPECT_FALSE(tree.ray_intersect({.origin = {0.2, 0.2, 1}, .direction = {0, 0, 1}}));  // points away
    EXPECT_FALSE(tree.ray_intersect({.origin = {0.2, 0.2, 1}, .direction = {0, 0, -1}, .t_max = 0.5}));
    EXPECT_FALSE(tree.ray_intersect({.origin = {0.8, 0.8, 1}, .direction = {0, 0, -1}}));  // beside it
    // An axis-parallel ray starting on the box's face (0 * inf in the slab test) hits the edge.
    h = tree.ray_intersect({.origin = {0, 0.2, 1}, .direction = {0, 0, -1}});
    ASSERT_TRUE(h);
    EXPECT_DOUBLE_EQ(h->t, 1.0);
}

TEST(aabb_tree, empty_tree_misses_everything) {
    const hmira::aabb_tree tree;
    EXPECT_TRUE(tree.empty());
    EXPECT_TRUE(std::isinf(tree.closest_point({0, 0, 0}).distance));
    EXPECT_FALSE(tree.ray_intersect({.origin = {0, 0, 0}, .direction = {1, 0, 0}}));
    hmira::halfedge_mesh m;
    auto built = hmira::aabb_tree_from_mesh(m);
    ASSERT_TRUE(built);
    EXPECT_TRUE(built->empty());
}

TEST(aabb_tree, same_input_gives_the_same_answers) {
    const soup s = random_soup(500, 3);
    const hmira::aabb_tree a(s.points, s.triangles), b(s.points, s.triangles);
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> pos(-1, 1);
    for (int i = 0; i < 50; ++i) {
        const v3 p{pos(rng), pos(rng), pos(rng)};
        const auto x = a.closest_point(p), y = b.closest_point(p);
        EXPECT_EQ(x.face, y.face);
        EXPECT_EQ(x.point, y.point);
    }
}

TEST(aabb_tree, non_finite_positions_are_refused_by_name) {
    hmira::halfedge_mesh m;
    using T = hmira::default_traits<hmira::halfedge_mesh>;
    const auto a = T::add_vertex(m, {0, 0, 0}), b = T::add_vertex(m, {1, 0, 0}),
               c = T::add_vertex(m, {0, std::numeric_limits<double>::quiet_NaN(), 0});
    const std::array<decltype(a), 3> f{a, b, c};
    ASSERT_TRUE(T::add_face(m, f));
    auto r = hmira::aabb_tree_from_mesh(m);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, hmira::errc::invalid_argument);
    EXPECT_NE(r.error().message.find("vertex 2"), std::string::npos) << r.error().message;
}

// A unit square in two triangles, lifted by z; a second copy shifted far enough along z that
// every sample's nearest point is straight across.
hmira_bench::quality::triangle_soup square(double z) {
    return {{{0, 0, z}, {1, 0, z}, {1, 1, z}, {0, 1, z}}, {{0, 1, 2}, {0, 2, 3}}};
}

TEST(mesh_quality, hausdorff_of_a_surface_with_itself_is_zero) {
    const soup s = random_soup(50, 9);
    const hmira_bench::quality::triangle_soup q{s.points, s.triangles};
    const auto h = hmira_bench::quality::hausdorff(q, q, 10, 20000);
    EXPECT_LT(h.symmetric(), 1e-12);  // zero up to the rounding of the sample positions
    EXPECT_GE(h.a_to_b.samples, 20000u);
    EXPECT_GE(h.b_to_a.samples, 20000u);
}

TEST(mesh_quality, hausdorff_of_a_translated_copy_is_the_translation_length) {
    const auto a = square(0), b = square(0.3);
    const auto h = hmira_bench::quality::hausdorff(a, b, 10, 5000);
    EXPECT_NEAR(h.symmetric(), 0.3, 1e-12);
    EXPECT_NEAR(h.a_to_b.mean, 0.3, 1e-12);
    EXPECT_NEAR(h.b_to_a.max, 0.3, 1e-12);
    // Real mesh: each sample's distance to the shifted copy is at most the shift, and the
    // vertices (on flat parts) reach almost all of it.
    const auto dir = data_dir();
    if (dir.empty() || !std::filesystem::exists(dir / "fandisk.off")) GTEST_SKIP() << "run scripts/test-data.sh first";
    hmira::halfedge_mesh m;
    ASSERT_TRUE(hmira::io::read_mesh(m, dir / "fandisk.off"));
    const auto s = hmira_bench::quality::soup_of(m);
    auto t = s;
    const v3 shift{0.01, -0.02, 0.02};  // length 0.03 on a model about 5 units across
    for (auto& p : t.points) p = p + shift;
    const auto g = hmira_bench::quality::hausdorff(s, t, real_mesh_per_triangle, real_mesh_samples);
    EXPECT_LE(g.symmetric(), 0.03 + 1e-12);
    EXPECT_GT(g.symmetric(), 0.029);
}

TEST(mesh_quality, triangle_and_edge_statistics_have_the_known_values) {
    // An equilateral triangle and a right isosceles one.
    const hmira_bench::quality::triangle_soup s{
        {{0, 0, 0}, {1, 0, 0}, {0.5, std::sqrt(3.0) / 2, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}}, {{0, 1, 2}, {3, 4, 5}}};
    const auto q = hmira_bench::quality::measure_triangles(s);
    ASSERT_EQ(q.min_angles.size(), 2u);
    EXPECT_NEAR(q.min_angles[0], 45, 1e-9);
    EXPECT_NEAR(q.min_angles[1], 60, 1e-9);
    EXPECT_NEAR(q.aspects[0], 1, 1e-9);
    // Right isosceles with legs 1: R = sqrt(2)/2, r = (2 - sqrt(2))/2.
    EXPECT_NEAR(q.aspects[1], (std::sqrt(2.0) / 2) / (2 - std::sqrt(2.0)), 1e-9);
    const auto e = hmira_bench::quality::measure_edges(s);
    EXPECT_EQ(e.count, 6u);
    EXPECT_NEAR(e.max, std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(e.fraction_within(0.99, 1.01), 5.0 / 6.0, 1e-12);
    const auto text = hmira_bench::quality::describe("two", s, 1.0);
    EXPECT_NE(text.find("2 triangles"), std::string::npos) << text;
}

}  // namespace
