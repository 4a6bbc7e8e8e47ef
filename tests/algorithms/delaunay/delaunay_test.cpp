// tests/algorithms/delaunay/delaunay_test.cpp
// delaunay_triangulation: properties on seeded uniform, clustered and lattice inputs, the
// degenerate and adversarial cases, the mapping, 2.5D lifting, the Voronoi dual, and output
// into both reference meshes checked by validate().
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#include <hmira/algorithms/delaunay/delaunay_triangulation.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "delaunay_checks.hpp"
#include "support/checks.hpp"

namespace {

using hmira::delaunay_status;
using hmira::delaunay_triangulation;
using hmira_test::is_delaunay_triangulation;
using hmira_test::point3;

#ifdef HMIRA_SANITIZER_BUILD
constexpr std::size_t big = 20000;
#else
constexpr std::size_t big = 200000;
#endif

TEST(delaunay, uniform_points_give_a_delaunay_triangulation_of_the_hull) {
    for (std::uint64_t seed : {1u, 2u, 3u}) {
        for (std::size_t n : {std::size_t(3), std::size_t(4), std::size_t(10), std::size_t(1000), big}) {
            const auto pts = hmira_test::uniform_points(n, seed);
            const auto d = delaunay_triangulation(pts);
            ASSERT_TRUE(d) << d.error().message;
            EXPECT_TRUE(is_delaunay_triangulation(pts, *d)) << "seed " << seed << " n " << n;
        }
    }
}

TEST(delaunay, clustered_points_give_a_delaunay_triangulation) {
    for (std::uint64_t seed : {4u, 5u}) {
        const auto pts = hmira_test::clustered_points(big / 2, seed);
        const auto d = delaunay_triangulation(pts);
        ASSERT_TRUE(d) << d.error().message;
        EXPECT_TRUE(is_delaunay_triangulation(pts, *d)) << "seed " << seed;
    }
}

TEST(delaunay, integer_lattice_is_triangulated_despite_cocircular_squares) {
    for (int side : {2, 3, 17, 200}) {
        const auto pts = hmira_test::lattice_points(side);
        const auto d = delaunay_triangulation(pts);
        ASSERT_TRUE(d) << d.error().message;
        EXPECT_TRUE(is_delaunay_triangulation(pts, *d)) << "side " << side;
        // Every lattice square is split into two triangles; the hull keeps its 4(side-1) points.
        EXPECT_EQ(d->triangles.size(), std::size_t(2 * (side - 1) * (side - 1)));
        EXPECT_EQ(d->hull.size(), std::size_t(4 * (side - 1)));
    }
}

TEST(delaunay, shuffled_lattice_gives_a_valid_triangulation_too) {
    auto pts = hmira_test::lattice_points(120);
    std::shuffle(pts.begin(), pts.end(), std::mt19937_64(9));
    const auto d = delaunay_triangulation(pts, {.brio = false});
    ASSERT_TRUE(d);
    EXPECT_TRUE(is_delaunay_triangulation(pts, *d));
}

TEST(delaunay, points_on_a_circle_are_triangulated) {
#ifdef HMIRA_SANITIZER_BUILD
    const std::size_t n = 10000;
#else
    const std::size_t n = 100000;
#endif
    const auto pts = hmira_test::circle_points(n);
    const auto d = delaunay_triangulation(pts);
    ASSERT_TRUE(d) << d.error().message;
    EXPECT_TRUE(is_delaunay_triangulation(pts, *d));
    EXPECT_EQ(d->triangles.size(), n - 2);  // all points on the hull
}

TEST(delaunay, exactly_cocircular_points_are_triangulated) {
    // The 12 integer points on the circle of radius 5, plus the centre, repeated on a grid of
    // centres 10 apart: many exactly cocircular quadruples.
    const int r5[][2] = {{5, 0},  {4, 3},   {3, 4},   {0, 5},  {-3, 4}, {-4, 3},
                         {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
    std::vector<point3> pts;
    for (int cx = 0; cx < 10; ++cx)
        for (int cy = 0; cy < 10; ++cy) {
            pts.push_back({10.0 * cx, 10.0 * cy, 0});
            for (const auto& q : r5) pts.push_back({10.0 * cx + q[0], 10.0 * cy + q[1], 0});
        }
    for (bool brio : {true, false}) {
        const auto d = delaunay_triangulation(pts, {.brio = brio});
        ASSERT_TRUE(d);
        EXPECT_TRUE(is_delaunay_triangulation(pts, *d));
    }
}

TEST(delaunay, nearly_collinear_points_are_triangulated) {
    // Points on the line y = x / 3, rounded, then nudged by an ulp or two either way.
    std::mt19937_64 rng(12);
    std::uniform_real_distribution<double> u(0.0, 1000.0);
    std::uniform_int_distribution<int> ulps(-2, 2);
    std::vector<point3> pts(20000);
    for (auto& p : pts) {
        p.x = u(rng);
        p.y = p.x / 3.0;
        for (int m = ulps(rng); m != 0; m += (m > 0 ? -1 : 1)) p.y = std::nextafter(p.y, m > 0 ? 1e9 : -1e9);
    }
    const auto d = delaunay_triangulation(pts);
    ASSERT_TRUE(d);
    ASSERT_EQ(d->status, delaunay_status::ok);
    EXPECT_TRUE(is_delaunay_triangulation(pts, *d));
}

TEST(delaunay, collinear_points_plus_one_off_the_line) {
    std::vector<point3> pts;
    for (int i = 0; i < 1000; ++i) pts.push_back({double(i), 2.0 * i, 0});
    pts.push_back({3.0, -1.0, 0});
    const auto d = delaunay_triangulation(pts);
    ASSERT_TRUE(d);
    EXPECT_TRUE(is_delaunay_triangulation(pts, *d));
    EXPECT_EQ(d->triangles.size(), std::size_t(999));
}

TEST(delaunay, duplicates_are_merged_and_mapped_to_their_first_occurrence) {
    auto base = hmira_test::uniform_points(5000, 21);
    std::vector<point3> pts = base;
    std::mt19937_64 rng(22);
    std::uniform_int_distribution<std::size_t> pick(0, base.size() - 1);
    for (int k = 0; k < 3000; ++k) {
        point3 q = base[pick(rng)];
        q.z = -1;  // same (x, y), other height: merged, z of the first occurrence kept
        pts.push_back(q);
    }
    std::shuffle(pts.begin() + 1000, pts.end(), rng);
    const auto d = delaunay_triangulation(pts);
    ASSERT_TRUE(d);
    EXPECT_EQ(d->points.size(), base.size());
    EXPECT_TRUE(is_delaunay_triangulation(pts, *d));
    for (std::size_t j = 0; j < pts.size(); ++j) {
        const auto v = d->input_to_vertex[j];
        const auto first = d->vertex_to_input[v];
        EXPECT_LE(first, j);
        for (std::size_t i = 0; i < first; ++i)
            if (pts[i].x == pts[j].x && pts[i].y == pts[j].y) FAIL() << "input " << i << " precedes first " << first;
        if (j > 2000) break;  // the quadratic check on a prefix is enough
    }
    // Every triangle's vertices keep the z of their first input.
    for (std::size_t v = 0; v < d->points.size(); ++v) EXPECT_EQ(d->points[v].z, pts[d->vertex_to_input[v]].z);
}

TEST(delaunay, all_points_repeated_many_times) {
    std::vector<point3> pts;
    for (int rep = 0; rep < 50; ++rep)
        for (int i = 0; i < 4; ++i) pts.push_back({double(i % 2), double(i / 2), double(rep)});
    const auto d = delaunay_triangulation(pts);
    ASSERT_TRUE(d);
    EXPECT_EQ(d->points.size(), 4u);
    EXPECT_EQ(d->triangles.size(), 2u);
    EXPECT_TRUE(is_delaunay_triangulation(pts, *d));
}

TEST(delaunay, all_collinear_input_gives_no_triangles_and_says_so) {
    std::vector<point3> pts;
    for (int i = 0; i < 100; ++i) pts.push_back({1.0 + i * 0.5, 2.0 - i * 0.25, double(i)});
    pts.push_back(pts[10]);
    const auto d = delaunay_triangulation(pts);
    ASSERT_TRUE(d) << d.error().message;
    EXPECT_EQ(d->status, delaunay_status::all_collinear);
    EXPECT_TRUE(d->triangles.empty());
    EXPECT_EQ(d->points.size(), 100u);
    EXPECT_EQ(d->input_to_vertex[100], d->input_to_vertex[10]);
    ASSERT_EQ(d->hull.size(), 2u);
    EXPECT_EQ(d->vertex_to_input[d->hull[0]], 0u);
    EXPECT_EQ(d->vertex_to_input[d->hull[1]], 99u);

    hmira::halfedge_mesh mesh;
    const auto r = delaunay_triangulation(mesh, pts);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, delaunay_status::all_collinear);
    EXPECT_EQ(hmira::default_traits<hmira::halfedge_mesh>::vertex_count(mesh), 0u);
}

TEST(delaunay, fewer_than_three_distinct_points_is_an_error) {
    const std::vector<std::vector<point3>> cases = {{},
                                                    {{1, 2, 3}},
                                                    {{1, 2, 3}, {4, 5, 6}},
                                                    {{1, 2, 3}, {1, 2, 4}, {1, 2, 5}},
                                                    {{0, 0, 0}, {1, 1, 0}, {0, 0, 0}, {1, 1, 1}}};
    for (const auto& pts : cases) {
        const auto d = delaunay_triangulation(pts);
        ASSERT_FALSE(d) << pts.size();
        EXPECT_EQ(d.error().code, hmira::errc::invalid_argument);
        EXPECT_NE(d.error().message.find("at least 3 distinct points"), std::string::npos) << d.error().message;
    }
}

TEST(delaunay, non_finite_and_out_of_range_coordinates_are_errors_naming_the_point) {
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    const point3 bad[] = {{nan, 0, 0},  {0, inf, 0},    {0, 0, nan},   {-inf, 1, 1},
                          {1e60, 0, 0}, {0, -1e300, 0}, {1e-60, 0, 0}, {0, 4.9e-324, 0}};
    for (const auto& b : bad) {
        auto pts = hmira_test::uniform_points(50, 31);
        pts[17] = b;
        const auto d = delaunay_triangulation(pts);
        ASSERT_FALSE(d);
        EXPECT_EQ(d.error().code, hmira::errc::invalid_argument);
        EXPECT_EQ(d.error().element, 17);
        EXPECT_NE(d.error().message.find("point 17"), std::string::npos) << d.error().message;

        hmira::face_vertex_mesh mesh;
        const auto r = delaunay_triangulation(mesh, pts);
        ASSERT_FALSE(r);
        EXPECT_EQ(hmira::default_traits<hmira::face_vertex_mesh>::vertex_count(mesh), 0u) << "mesh must stay unchanged";
    }
}

TEST(delaunay, coordinates_at_the_ends_of_the_range_are_accepted) {
    for (double s : {5e53, 1e-54, 1.0}) {
        auto pts = hmira_test::uniform_points(2000, 41);
        for (auto& p : pts) p.x = (1 + p.x) * s, p.y = (1 + p.y) * s;
        const auto d = delaunay_triangulation(pts);
        ASSERT_TRUE(d) << d.error().message;
        EXPECT_TRUE(is_delaunay_triangulation(pts, *d)) << s;
    }
}

TEST(delaunay, result_does_not_depend_on_input_order_in_general_position) {
    auto pts = hmira_test::uniform_points(20000, 51);
    const auto a = delaunay_triangulation(pts);
    std::vector<std::size_t> perm(pts.size());
    std::iota(perm.begin(), perm.end(), 0);
    std::shuffle(perm.begin(), perm.end(), std::mt19937_64(52));
    std::vector<point3> shuffled(pts.size());
    for (std::size_t i = 0; i < perm.size(); ++i) shuffled[i] = pts[perm[i]];
    const auto b = delaunay_triangulation(shuffled, {.brio = false});
    ASSERT_TRUE(a && b);
    auto tb = hmira_test::canonical_triangles(*b);
    for (auto& t : tb) {
        for (auto& v : t) v = static_cast<std::uint32_t>(perm[v]);
        std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    }
    std::sort(tb.begin(), tb.end());
    EXPECT_EQ(hmira_test::canonical_triangles(*a), tb);
}

TEST(delaunay, heights_are_kept_for_a_two_and_a_half_d_terrain) {
    std::vector<std::array<double, 3>> pts;
    for (int i = 0; i < 30; ++i)
        for (int j = 0; j < 30; ++j)
            pts.push_back({i * 0.1, j * 0.1 + 0.01 * ((i * j) % 3), std::sin(i * 0.3) * std::cos(j * 0.2)});
    const auto d = delaunay_triangulation(pts);
    ASSERT_TRUE(d);
    for (std::size_t v = 0; v < d->points.size(); ++v) EXPECT_EQ(d->points[v].z, pts[d->vertex_to_input[v]][2]);
    std::vector<std::array<double, 2>> flat;
    for (const auto& p : pts) flat.push_back({p[0], p[1]});
    const auto f = delaunay_triangulation(flat);
    ASSERT_TRUE(f);
    EXPECT_EQ(f->triangles, d->triangles) << "z must not influence the triangulation";
    for (const auto& q : f->points) EXPECT_EQ(q.z, 0.0);
}

TEST(delaunay, voronoi_vertices_are_circumcentres_and_edges_are_dual) {
    const auto pts = hmira_test::uniform_points(3000, 61);
    const auto d = delaunay_triangulation(pts, {.voronoi = true});
    ASSERT_TRUE(d);
    const auto& vd = d->voronoi;
    ASSERT_EQ(vd.vertices.size(), d->triangles.size());
    for (std::size_t t = 0; t < d->triangles.size(); ++t) {
        const auto& c = vd.vertices[t];
        double r[3];
        for (int i = 0; i < 3; ++i) {
            const auto& p = d->points[d->triangles[t][i]];
            r[i] = std::hypot(p.x - c.x, p.y - c.y);
        }
        EXPECT_NEAR(r[0], r[1], 1e-9 * (1 + r[0]));
        EXPECT_NEAR(r[0], r[2], 1e-9 * (1 + r[0]));
    }
    // Euler: E = 3n - 3 - h Delaunay edges, of which h on the hull (rays).
    const std::size_t n = d->points.size(), h = d->hull.size();
    EXPECT_EQ(vd.edges.size(), 3 * n - 3 - h);
    std::size_t rays = 0;
    for (const auto& e : vd.edges) {
        if (e.to == hmira::voronoi_edge::no_vertex) {
            ++rays;
            // The ray points away from the hull: the direction has the hull edge on its left.
            const auto& a = d->points[e.site0];
            const auto& b = d->points[e.site1];
            EXPECT_LT((b.x - a.x) * e.direction.y - (b.y - a.y) * e.direction.x, 0.0);
        } else {
            // A finite Voronoi edge is perpendicular to its Delaunay edge.
            const auto& a = d->points[e.site0];
            const auto& b = d->points[e.site1];
            const auto& p = vd.vertices[e.from];
            const auto& q = vd.vertices[e.to];
            const double dot = (b.x - a.x) * (q.x - p.x) + (b.y - a.y) * (q.y - p.y);
            EXPECT_NEAR(dot, 0.0, 1e-7 * std::hypot(b.x - a.x, b.y - a.y) * (1 + std::hypot(q.x - p.x, q.y - p.y)));
        }
    }
    EXPECT_EQ(rays, h);
}

TEST(delaunay, hilbert_keys_visit_every_cell_once_moving_to_a_neighbour_each_step) {
    // The spatial sort's curve: a wrong rotation would still sort, only slowly, so check it here.
    for (int bits : {1, 2, 5, 8}) {
        const std::uint32_t side = 1u << bits;
        std::vector<std::array<std::uint32_t, 2>> cell(side * side, {side, side});
        for (std::uint32_t x = 0; x < side; ++x)
            for (std::uint32_t y = 0; y < side; ++y) {
                const auto d = hmira::detail::delaunay::hilbert_index(x, y, bits);
                ASSERT_LT(d, side * side);
                ASSERT_EQ(cell[d][0], side) << "index " << d << " used twice";
                cell[d] = {x, y};
            }
        for (std::size_t d = 1; d < cell.size(); ++d) {
            const int dx = int(cell[d][0]) - int(cell[d - 1][0]), dy = int(cell[d][1]) - int(cell[d - 1][1]);
            ASSERT_EQ(std::abs(dx) + std::abs(dy), 1) << "bits " << bits << " step " << d;
        }
    }
}

template <class Mesh>
class delaunay_into_mesh : public ::testing::Test {};
using mesh_models = ::testing::Types<hmira::face_vertex_mesh, hmira::halfedge_mesh>;
TYPED_TEST_SUITE(delaunay_into_mesh, mesh_models);

TYPED_TEST(delaunay_into_mesh, output_mesh_validates_and_matches_the_triangle_list) {
    using T = hmira::default_traits<TypeParam>;
    const std::vector<std::vector<point3>> inputs = {hmira_test::uniform_points(20000, 71),
                                                     hmira_test::lattice_points(60), hmira_test::circle_points(2000),
                                                     hmira_test::clustered_points(10000, 72)};
    for (const auto& pts : inputs) {
        TypeParam mesh;
        const auto r = delaunay_triangulation(mesh, pts);
        ASSERT_TRUE(r) << r.error().message;
        const auto d = delaunay_triangulation(pts);
        EXPECT_TRUE(hmira_test::is_valid(mesh));
        EXPECT_EQ(T::vertex_count(mesh), d->points.size());
        EXPECT_EQ(T::face_count(mesh), d->triangles.size());
        ASSERT_EQ(r->faces.size(), d->triangles.size());
        for (std::size_t f = 0; f < r->faces.size(); f += 97) {
            std::vector<std::size_t> got, want;
            for (auto v : T::face_vertices(mesh, r->faces[f])) got.push_back(T::vertex_index(mesh, v));
            for (auto v : d->triangles[f]) want.push_back(T::vertex_index(mesh, r->vertices[v]));
            std::rotate(got.begin(), std::min_element(got.begin(), got.end()), got.end());
            std::rotate(want.begin(), std::min_element(want.begin(), want.end()), want.end());
            EXPECT_EQ(got, want);
        }
        for (std::size_t v = 0; v < r->vertices.size(); v += 31) {
            const auto p = T::position(mesh, r->vertices[v]);
            EXPECT_EQ(p, pts[r->vertex_to_input[v]]);
        }
        ASSERT_EQ(r->hull.size(), d->hull.size());
        for (std::size_t i = 0; i < r->hull.size(); ++i) EXPECT_EQ(r->hull[i], r->vertices[d->hull[i]]);
    }
}

}  // namespace
