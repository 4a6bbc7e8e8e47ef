// inside_closed decides inside, outside and on-surface exactly: on lattice points whose rays
// along +x run through edges and vertices of a cube and an octahedron (the answer known from
// the coordinates), and against a solid-angle winding-number sum on random points.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>

#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/spatial/inside_closed.hpp>
#include <hmira/io/mesh_io.hpp>

#include "support/models.hpp"
#include "support/shapes.hpp"

namespace {

using hmira::point_location;
using hmira::vec3;

/// The generalised winding number by the solid angles of the triangles (van Oosterom and
/// Strackee), in floating point: an independent reference away from the surface.
template <class M, class T = hmira::default_traits<M>>
double solid_angle_winding(const M& m, const vec3<double>& q) {
    double sum = 0;
    for (auto f : T::faces(m)) {
        std::vector<vec3<double>> p;
        for (auto v : T::face_vertices(m, f)) {
            const auto x = T::position(m, v);
            p.push_back({double(x.x) - q.x, double(x.y) - q.y, double(x.z) - q.z});
        }
        for (std::size_t i = 1; i + 1 < p.size(); ++i) {  // a fan: exact for the convex faces used here
            const vec3<double> a = p[0], b = p[i], c = p[i + 1];
            const double la = std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
            const double lb = std::sqrt(b.x * b.x + b.y * b.y + b.z * b.z);
            const double lc = std::sqrt(c.x * c.x + c.y * c.y + c.z * c.z);
            const double det =
                a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) + a.z * (b.x * c.y - b.y * c.x);
            const double dot = la * lb * lc + (a.x * b.x + a.y * b.y + a.z * b.z) * lc +
                               (b.x * c.x + b.y * c.y + b.z * c.z) * la + (c.x * a.x + c.y * a.y + c.z * a.z) * lb;
            sum += 2 * std::atan2(det, dot);
        }
    }
    return sum / (4 * std::numbers::pi);
}

template <class M>
void expect_matches_winding_sum(const M& m, const vec3<double>& lo, const vec3<double>& hi, int n, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> ux(lo.x, hi.x), uy(lo.y, hi.y), uz(lo.z, hi.z);
    std::vector<vec3<double>> pts;
    for (int i = 0; i < n; ++i) pts.push_back({ux(rng), uy(rng), uz(rng)});
    const auto got = hmira::inside_closed(m, pts);
    ASSERT_TRUE(got) << got.error().message;
    int inside = 0, checked = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const double w = solid_angle_winding(m, pts[i]);
        const double r = std::round(w);
        if (std::fabs(w - r) > 0.05) continue;  // too near the surface for the float reference
        ++checked;
        inside += r != 0;
        ASSERT_EQ((*got)[i], r != 0 ? point_location::inside : point_location::outside) << i << " w=" << w;
        const auto exact = hmira::closed_winding_number(m, pts[i]);
        ASSERT_TRUE(exact);
        EXPECT_EQ(*exact, (long long)r) << i;
    }
    EXPECT_GT(inside, 0);
    EXPECT_GT(checked, n * 3 / 4);
}

template <class M>
class inside_closed_typed : public ::testing::Test {};
TYPED_TEST_SUITE(inside_closed_typed, hmira_test::all_models);

TYPED_TEST(inside_closed_typed, octahedron_lattice_points_through_edges_and_vertices) {
    TypeParam m;
    ASSERT_TRUE(hmira::generate_octahedron(m, {.scale = 2}));
    std::vector<vec3<double>> pts;
    std::vector<point_location> want;
    for (int i = -6; i <= 6; ++i)
        for (int j = -6; j <= 6; ++j)
            for (int k = -6; k <= 6; ++k) {
                const vec3<double> p{i * 0.5, j * 0.5, k * 0.5};
                const double l1 = std::fabs(p.x) + std::fabs(p.y) + std::fabs(p.z);
                pts.push_back(p);
                want.push_back(l1 < 2 ? point_location::inside
                                      : (l1 == 2 ? point_location::on_surface : point_location::outside));
            }
    const auto got = hmira::inside_closed(m, pts);
    ASSERT_TRUE(got) << got.error().message;
    for (std::size_t i = 0; i < pts.size(); ++i)
        ASSERT_EQ((*got)[i], want[i]) << pts[i].x << ' ' << pts[i].y << ' ' << pts[i].z;
}

TYPED_TEST(inside_closed_typed, agrees_with_the_winding_sum_on_random_points) {
    TypeParam m;
    ASSERT_TRUE(hmira::generate_icosahedron(m));
    expect_matches_winding_sum(m, {-2, -2, -2}, {2, 2, 2}, 150, 31);
}

TEST(inside_closed, cube_lattice_points_through_edges_and_vertices) {
    hmira::halfedge_mesh m;  // quads: cut by face_triangles, the diagonals cancel
    ASSERT_TRUE(hmira::generate_cube(m));
    std::vector<vec3<double>> pts;
    std::vector<point_location> want;
    for (int i = -3; i <= 3; ++i)
        for (int j = -3; j <= 3; ++j)
            for (int k = -3; k <= 3; ++k) {
                const vec3<double> p{i * 0.5, j * 0.5, k * 0.5};
                const double mx = std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
                pts.push_back(p);
                want.push_back(mx < 1 ? point_location::inside
                                      : (mx == 1 ? point_location::on_surface : point_location::outside));
            }
    const auto got = hmira::inside_closed(m, pts, {.threads = 1});
    ASSERT_TRUE(got) << got.error().message;
    for (std::size_t i = 0; i < pts.size(); ++i)
        ASSERT_EQ((*got)[i], want[i]) << pts[i].x << ' ' << pts[i].y << ' ' << pts[i].z;
}

TEST(inside_closed, overlapping_shells_wind_twice_and_an_inverted_one_negatively) {
    hmira::face_vertex_mesh m;
    ASSERT_TRUE(hmira::generate_cube(m));
    ASSERT_TRUE(hmira::generate_cube(m, {.center = {1, 0, 0}}));
    EXPECT_EQ(*hmira::closed_winding_number(m, {0.5, 0.25, 0.25}), 2);
    EXPECT_EQ(*hmira::closed_winding_number(m, {-0.5, 0, 0}), 1);
    EXPECT_EQ(*hmira::closed_winding_number(m, {3, 0, 0}), 0);
    EXPECT_EQ(*hmira::inside_closed(m, {0.5, 0.25, 0.25}), point_location::inside);
    EXPECT_EQ(*hmira::inside_closed(m, {0, 0, 0}), point_location::on_surface);  // the second cube's face
    hmira_test::face_list inverted = hmira_test::torus(10, 6);
    for (auto& f : inverted.faces) std::reverse(f.begin(), f.end());
    hmira::face_vertex_mesh t;
    ASSERT_TRUE(hmira_test::add_face_list(t, inverted));
    EXPECT_EQ(*hmira::closed_winding_number(t, {2, 0, 0}), -1);  // on the tube's core circle
    EXPECT_EQ(*hmira::closed_winding_number(t, {0, 0, 0}), 0);   // in the hole
}

TEST(inside_closed, agrees_with_the_winding_sum_on_a_torus_and_the_sphere_file) {
    hmira::face_vertex_mesh t;
    ASSERT_TRUE(hmira_test::add_face_list(t, hmira_test::torus(16, 10)));
    expect_matches_winding_sum(t, {-3, -3, -1}, {3, 3, 1}, 150, 32);
    const char* dir = std::getenv("HMIRA_TEST_DATA");
    if (!dir || !*dir) GTEST_SKIP() << "HMIRA_TEST_DATA not set";
    hmira::face_vertex_mesh s;
    ASSERT_TRUE(hmira::io::read_mesh(s, std::filesystem::path(dir) / "meshes/sphere.off"));
    expect_matches_winding_sum(s, {-1.2, -1.2, -1.2}, {1.2, 1.2, 1.2}, 150, 33);
}

TEST(inside_closed, refuses_a_point_that_is_not_finite_and_can_be_cancelled) {
    hmira::face_vertex_mesh m;
    ASSERT_TRUE(hmira::generate_cube(m));
    const auto bad = hmira::inside_closed(m, {0, std::nan(""), 0});
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().code, hmira::errc::invalid_argument);
    std::vector<vec3<double>> many(1000, vec3<double>{0.1, 0.2, 0.3});
    const auto stopped = hmira::inside_closed(m, many, {.progress = [](double) { return false; }});
    ASSERT_FALSE(stopped);
    EXPECT_EQ(stopped.error().code, hmira::errc::cancelled);
}

}  // namespace
