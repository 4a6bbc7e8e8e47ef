// Bevel: the cube-edge chamfer (volume removed computed here), rounded profiles on
// a circle, meeting bevels at a cube corner, kept end vertices on a grid, clamping, the
// vertex-only mode equal to truncate, and rejected input. Rounded bevels where edges meet
// (segments > 1): the rounded cube (counts, spheres, cylinders, volume convergence), mitres,
// pass-through vertices, pointed ends, a degree-5 apex, and random selections.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <set>
#include <vector>

#include <hmira/algorithms/generators/grid.hpp>
#include <hmira/algorithms/generators/torus.hpp>

#include "algorithms/editing/editing_support.hpp"

namespace {

using namespace hmira_test;

template <class M>
class bevel_test : public ::testing::Test {};
TYPED_TEST_SUITE(bevel_test, hmira_test::all_models);

#define SKIP_UNLESS_BEVELABLE()                                                          \
    if constexpr (!hmira::bevelable_mesh<TypeParam>) {                                   \
        GTEST_SKIP() << "model cannot be edited (no Euler operators or triangles only)"; \
    } else

/// The edge between the vertices at a and b (e.g. the cube edge (1,1,-1)-(1,1,1)).
template <class M, class T = hmira::default_traits<M>>
typename T::edge_handle edge_between(const M& m, std::array<double, 3> a, std::array<double, 3> b) {
    for (auto e : T::edges(m)) {
        const auto ev = T::edge_vertices(m, e);
        const auto pa = p3<M, T>(m, ev[0]), pb = p3<M, T>(m, ev[1]);
        const double eps = 10 * tol<M, T>();  // float models store cos / sin rounded
        if ((dist(pa, a) < eps && dist(pb, b) < eps) || (dist(pa, b) < eps && dist(pb, a) < eps)) return e;
    }
    ADD_FAILURE() << "no such edge";
    return typename T::edge_handle();
}

TYPED_TEST(bevel_test, one_cube_edge_with_one_segment_is_the_expected_chamfer) {
    SKIP_UNLESS_BEVELABLE() {
        using T = hmira::default_traits<TypeParam>;
        for (double w : {0.2, 0.5}) {
            TypeParam m;
            (void)hmira::generate_cube(m).value();
            const auto e = edge_between(m, {1, 1, -1}, {1, 1, 1});
            auto r = hmira::bevel(m, e, {.width = w});
            ASSERT_TRUE(r) << r.error().message;
            EXPECT_EQ(count(m), (counts{10, 15, 7}));
            EXPECT_TRUE(valid_with_chi(m, 2));
            EXPECT_TRUE(faces_point_outward(m));
            // A prism with a right-angled cross-section of legs w, 2 long, is cut away.
            EXPECT_NEAR(signed_volume(m), 8.0 - w * w, tol<TypeParam>());
            EXPECT_EQ(face_sizes(m), (std::map<std::size_t, std::size_t>{{4, 5}, {5, 2}}));
            ASSERT_EQ(r->strip_faces.size(), 1u);
            EXPECT_EQ(r->vertices.size(), 4u);
            EXPECT_DOUBLE_EQ(r->width, w);
            for (auto z : {-1.0, 1.0}) {
                EXPECT_TRUE(has_vertex_at(m, {1 - w, 1, z}));
                EXPECT_TRUE(has_vertex_at(m, {1, 1 - w, z}));
                EXPECT_FALSE(has_vertex_at(m, {1, 1, z}));
            }
            // The chamfer faces along (1, 1, 0).
            const auto n = newell(m, r->strip_faces[0]);
            EXPECT_GT(n[0], 0);
            EXPECT_NEAR(n[0], n[1], tol<TypeParam>());
            EXPECT_NEAR(n[2], 0, tol<TypeParam>());
            (void)sizeof(T);
        }
    }
}

TYPED_TEST(bevel_test, more_segments_follow_a_circular_arc_tangent_to_both_faces) {
    SKIP_UNLESS_BEVELABLE() {
        using T = hmira::default_traits<TypeParam>;
        const double w = 0.4;
        const int n = 4;
        TypeParam m;
        (void)hmira::generate_cube(m).value();
        auto r = hmira::bevel(m, edge_between(m, {1, 1, -1}, {1, 1, 1}), {.width = w, .segments = n});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_EQ(count(m), (counts{8 - 2 + 4 + 2 * (n - 1), 15 + 3 * (n - 1), 7 + (n - 1)}));
        EXPECT_TRUE(valid_with_chi(m, 2));
        EXPECT_TRUE(faces_point_outward(m));
        EXPECT_EQ(r->strip_faces.size(), std::size_t(n));
        // Every new vertex lies on the circle of radius w around the line x = y = 1 - w.
        for (auto v : r->vertices) {
            const auto p = p3(m, v);
            EXPECT_NEAR(std::hypot(p[0] - (1 - w), p[1] - (1 - w)), w, tol<TypeParam>());
        }
        // Between the flat chamfer and the exact quarter-round.
        const double vol = signed_volume(m);
        EXPECT_LT(vol, 8.0 - 2 * w * w * (1 - std::numbers::pi / 4));
        EXPECT_GT(vol, 8.0 - w * w);
        for (auto f : r->strip_faces) EXPECT_EQ(std::ranges::distance(T::face_vertices(m, f)), 4);
    }
}

TYPED_TEST(bevel_test, three_edges_meeting_at_a_cube_corner_close_it_with_a_triangle) {
    SKIP_UNLESS_BEVELABLE() {
        TypeParam m;
        (void)hmira::generate_cube(m).value();
        std::vector<typename hmira::default_traits<TypeParam>::edge_handle> es{edge_between(m, {1, 1, 1}, {-1, 1, 1}),
                                                                               edge_between(m, {1, 1, 1}, {1, -1, 1}),
                                                                               edge_between(m, {1, 1, 1}, {1, 1, -1})};
        auto r = hmira::bevel(m, es, {.width = 0.25});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_EQ(count(m), (counts{13, 21, 10}));
        EXPECT_TRUE(valid_with_chi(m, 2));
        EXPECT_TRUE(faces_point_outward(m));
        ASSERT_EQ(r->vertex_faces.size(), 1u);
        EXPECT_EQ(face_sizes(m)[3], 1u);
        // The corner triangle's vertices are at w from both edges in each face.
        EXPECT_TRUE(has_vertex_at(m, {0.75, 0.75, 1}));
        EXPECT_TRUE(has_vertex_at(m, {1, 0.75, 0.75}));
        EXPECT_TRUE(has_vertex_at(m, {0.75, 1, 0.75}));
        const auto n = newell(m, r->vertex_faces[0]);
        EXPECT_GT(n[0] + n[1] + n[2], 0);
    }
}

TYPED_TEST(bevel_test, all_cube_edges_give_the_chamfered_cube) {
    SKIP_UNLESS_BEVELABLE() {
        using T = hmira::default_traits<TypeParam>;
        TypeParam m;
        (void)hmira::generate_cube(m).value();
        std::vector<typename T::edge_handle> es;
        for (auto e : T::edges(m)) es.push_back(e);
        const double w = 0.3;
        auto r = hmira::bevel(m, es, {.width = w});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_EQ(count(m), (counts{24, 48, 26}));
        EXPECT_TRUE(valid_with_chi(m, 2));
        EXPECT_TRUE(faces_point_outward(m));
        EXPECT_EQ(face_sizes(m), (std::map<std::size_t, std::size_t>{{3, 8}, {4, 18}}));
        // In corner-local coordinates (a, b, c) = distances to the three faces at a corner,
        // the solid keeps a + b >= w on every edge and a + b + c >= 2w at every corner (the
        // triangle's plane). Removed: along each edge a right triangle of legs w over the
        // length 2 - 2w between the corner cubes; in each corner cube of side w, the part
        // a + b + c < 2w, which is the cube minus the tetrahedron a + b + c >= 2w (w^3 / 6).
        const double edges_cut = 12 * (w * w / 2) * (2 - 2 * w);
        const double expected = 8.0 - edges_cut - 8 * (w * w * w - w * w * w / 6);
        EXPECT_NEAR(signed_volume(m), expected, tol<TypeParam>());
    }
}

TYPED_TEST(bevel_test, end_vertices_with_edges_away_from_the_bevel_stay_in_place) {
    SKIP_UNLESS_BEVELABLE() {
        using T = hmira::default_traits<TypeParam>;
        TypeParam m;
        (void)hmira::generate_grid(m, {.columns = 4, .rows = 4}).value();
        const auto e = edge_between(m, {2, 1, 0}, {2, 2, 0});
        const auto before = count(m);
        auto r = hmira::bevel(m, e, {.width = 0.25});
        ASSERT_TRUE(r) << r.error().message;
        // 4 slid vertices; the strip is one new face; the edge becomes two.
        EXPECT_EQ(count(m), (counts{before.v + 4, before.e + 5, before.f + 1}));
        EXPECT_TRUE(valid_with_chi(m, 1));
        EXPECT_TRUE(has_vertex_at(m, {2, 1, 0}));
        EXPECT_TRUE(has_vertex_at(m, {2, 2, 0}));
        EXPECT_TRUE(has_vertex_at(m, {1.75, 1, 0}));
        EXPECT_TRUE(has_vertex_at(m, {2.25, 2, 0}));
        for (auto f : T::faces(m)) EXPECT_GT(newell(m, f)[2], 0);
        EXPECT_EQ(std::ranges::distance(T::face_vertices(m, r->strip_faces[0])), 6);
    }
}

TYPED_TEST(bevel_test, an_edge_ending_on_the_boundary_closes_the_corner_there) {
    SKIP_UNLESS_BEVELABLE() {
        using T = hmira::default_traits<TypeParam>;
        TypeParam m;
        (void)hmira::generate_grid(m, {.columns = 2, .rows = 1}).value();
        const auto e = edge_between(m, {1, 0, 0}, {1, 1, 0});  // both ends on the boundary, degree 3
        auto r = hmira::bevel(m, e, {.width = 0.25});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_EQ(count(m), (counts{8, 10, 3}));
        EXPECT_TRUE(valid_with_chi(m, 1));
        EXPECT_EQ(hmira::mesh_topology(m).boundary_loops, 1u);
        for (auto f : T::faces(m)) EXPECT_GT(newell(m, f)[2], 0);
    }
}

TYPED_TEST(bevel_test, clamp_overlap_keeps_new_vertices_within_half_an_edge) {
    SKIP_UNLESS_BEVELABLE() {
        TypeParam m;
        (void)hmira::generate_cube(m).value();
        auto r = hmira::bevel(m, edge_between(m, {1, 1, -1}, {1, 1, 1}), {.width = 5.0});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_DOUBLE_EQ(r->width, 1.0);
        EXPECT_TRUE(valid_with_chi(m, 2));
        EXPECT_NEAR(signed_volume(m), 7.0, tol<TypeParam>());
        TypeParam u;
        (void)hmira::generate_cube(u).value();
        auto ru = hmira::bevel(u, edge_between(u, {1, 1, -1}, {1, 1, 1}), {.width = 1.5, .clamp_overlap = false});
        ASSERT_TRUE(ru) << ru.error().message;
        EXPECT_DOUBLE_EQ(ru->width, 1.5);
    }
}

TYPED_TEST(bevel_test, vertex_only_mode_equals_truncate) {
    SKIP_UNLESS_BEVELABLE() {
        using T = hmira::default_traits<TypeParam>;
        TypeParam a, b;
        auto ca = hmira::generate_cube(a).value();
        auto cb = hmira::generate_cube(b).value();
        std::vector<typename T::vertex_handle> va{ca.vertices[0], ca.vertices[6]}, vb{cb.vertices[0], cb.vertices[6]};
        auto ra = hmira::bevel_vertices(a, va, {.width = 0.3});
        auto rb = hmira::truncate(b, vb, {.distance = 0.3});
        ASSERT_TRUE(ra && rb);
        EXPECT_EQ(canonical_faces(a), canonical_faces(b));
        EXPECT_NEAR(signed_volume(a), signed_volume(b), 1e-12);
        EXPECT_EQ(ra->vertex_faces.size(), 2u);
        EXPECT_TRUE(valid_with_chi(a, 2));
    }
}

TYPED_TEST(bevel_test, bad_input_is_rejected_and_leaves_the_mesh_unchanged) {
    SKIP_UNLESS_BEVELABLE() {
        using T = hmira::default_traits<TypeParam>;
        TypeParam m;
        (void)hmira::generate_grid(m, {.columns = 3, .rows = 3}).value();
        const auto faces_before = canonical_faces(m);
        const auto before = count(m);
        const auto check = [&](auto r, hmira::errc code) {
            ASSERT_FALSE(r);
            EXPECT_EQ(r.error().code, code) << r.error().message;
            EXPECT_EQ(count(m), before);
            EXPECT_EQ(canonical_faces(m), faces_before);
        };
        const auto inner = edge_between(m, {1, 1, 0}, {2, 1, 0});
        for (double w : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN()})
            check(hmira::bevel(m, inner, {.width = w}), hmira::errc::invalid_argument);
        check(hmira::bevel(m, inner, {.segments = 0}), hmira::errc::invalid_argument);
        check(hmira::bevel(m, std::vector<typename T::edge_handle>{}), hmira::errc::invalid_argument);
        check(hmira::bevel(m, inner, {.segments = 65}), hmira::errc::invalid_argument);
        // Boundary edges bevel (bevel_boundary_test.cpp), but not with bad options.
        const auto boundary = edge_between(m, {0, 0, 0}, {1, 0, 0});
        check(hmira::bevel(m, boundary, {.width = -1}), hmira::errc::invalid_argument);
        check(hmira::bevel(m, std::vector<typename T::edge_handle>{inner, boundary}, {.segments = 0}),
              hmira::errc::invalid_argument);
    }
}

// ---- segments > 1 where bevelled edges meet ----

/// Interior vertices, interior edges and faces of a vertex patch of k arcs of n segments
/// filled as documented, counted element by element: n = 2m: a centre, k spokes of m
/// segments, k m x m grids; n = 2m + 1: k inner corners, 2k paths of m segments, the inner
/// k-gon, k strips of m quads, k m x m grids. (An m x m grid has (m-1)^2 interior vertices and
/// 2 m (m-1) interior edges.)
struct patch_counts {
    long long v = 0, e = 0, f = 0;
};
inline patch_counts grid_patch(long long k, long long n) {
    const long long m = n / 2;
    if (n % 2 == 0) return {1 + k * (m - 1) + k * (m - 1) * (m - 1), k * m + k * 2 * m * (m - 1), k * m * m};
    return {k + 2 * k * (m - 1) + k * (m - 1) * (m - 1), 2 * k * m + k + k * (m - 1) + k * 2 * m * (m - 1),
            k * m * m + k * m + 1};
}

template <class M, class T = hmira::default_traits<M>>
std::vector<typename T::edge_handle> all_edges(const M& m) {
    std::vector<typename T::edge_handle> es;
    for (auto e : T::edges(m)) es.push_back(e);
    return es;
}

/// The rounded cube's counts: 8 corner patches of 3 arcs (3n boundary vertices each, which
/// are all the vertices outside the patches), 12 strips of n faces (n + 1 lengthwise edges
/// each), 24 arcs of n edges, the 6 shrunk faces.
inline counts rounded_cube_counts(long long n) {
    const auto p = grid_patch(3, n);
    return {8 * (3 * n + p.v), 12 * (n + 1) + 24 * n + 8 * p.e, 6 + 12 * n + 8 * p.f};
}

TYPED_TEST(bevel_test, all_cube_edges_with_segments_give_a_rounded_cube_with_spherical_corners) {
    SKIP_UNLESS_BEVELABLE() {
        using T = hmira::default_traits<TypeParam>;
        const double w = 0.3;
        for (int n : {2, 3, 4}) {
            SCOPED_TRACE(::testing::Message() << "segments " << n);
            TypeParam m;
            (void)hmira::generate_cube(m).value();
            auto r = hmira::bevel(m, all_edges(m), {.width = w, .segments = n});
            ASSERT_TRUE(r) << r.error().message;
            const auto expected = rounded_cube_counts(n);
            EXPECT_EQ(count(m), expected);
            EXPECT_TRUE(valid_with_chi(m, 2));
            EXPECT_TRUE(faces_point_outward(m));
            // Quads everywhere, except the middle triangle of each corner for odd n.
            const std::size_t triangles = n % 2 ? 8 : 0;
            std::map<std::size_t, std::size_t> sizes{{4, std::size_t(expected.f) - triangles}};
            if (triangles) sizes[3] = triangles;
            EXPECT_EQ(face_sizes(m), sizes);
            EXPECT_EQ(r->strip_faces.size(), std::size_t(12 * n));
            EXPECT_EQ(r->vertex_faces.size(), std::size_t(8 * grid_patch(3, n).f));
            EXPECT_EQ(r->vertices.size(), std::size_t(expected.v));  // all old vertices went
            // Every vertex belongs to a corner patch: it lies on the sphere of radius w around
            // the corner moved inward by w on each axis.
            for (auto v : T::vertices(m)) {
                const auto p = p3(m, v);
                std::array<double, 3> c{};
                for (int a = 0; a < 3; ++a) c[a] = std::copysign(1 - w, p[a]);
                EXPECT_NEAR(dist(p, c), w, tol<TypeParam>()) << p[0] << " " << p[1] << " " << p[2];
            }
            // Every strip vertex lies on its edge's cylinder of radius w.
            for (std::size_t s = 0; s < r->strip_faces.size(); ++s) {
                const auto f = r->strip_faces[s];
                const auto c = centroid(m, f);
                int axis = 0;  // the strip runs along the axis where its centroid is 0
                for (int a = 1; a < 3; ++a)
                    if (std::abs(c[a]) < std::abs(c[axis])) axis = a;
                ASSERT_NEAR(c[axis], 0, tol<TypeParam>());
                for (auto v : T::face_vertices(m, f)) {
                    const auto p = p3(m, v);
                    double d2 = 0;
                    for (int a = 0; a < 3; ++a)
                        if (a != axis) d2 += (p[a] - std::copysign(1 - w, c[a])) * (p[a] - std::copysign(1 - w, c[a]));
                    EXPECT_NEAR(std::sqrt(d2), w, tol<TypeParam>());
                }
            }
            // The result lists are exactly the new faces.
            std::set<std::size_t> listed;
            for (auto f : r->strip_faces) listed.insert(T::face_index(m, f));
            for (auto f : r->vertex_faces) listed.insert(T::face_index(m, f));
            EXPECT_EQ(listed.size(), std::size_t(expected.f - 6));
        }
    }
}

TYPED_TEST(bevel_test, rounded_cube_volume_converges_to_the_exact_rounded_cube) {
    SKIP_UNLESS_BEVELABLE() {
        const double w = 0.4, l = 2 - 2 * w, pi = std::numbers::pi;
        // The exact solid: the inner box grown by w: box, 6 slabs, 12 quarter cylinders, 8
        // sphere octants (one ball).
        const double exact = l * l * l + 6 * l * l * w + 12 * (pi * w * w / 4) * l + 4.0 / 3.0 * pi * w * w * w;
        double previous_error = std::numeric_limits<double>::infinity();
        for (int n = 1; n <= 8; ++n) {
            SCOPED_TRACE(::testing::Message() << "segments " << n);
            TypeParam m;
            (void)hmira::generate_cube(m).value();
            ASSERT_TRUE(hmira::bevel(m, all_edges(m), {.width = w, .segments = n}));
            const double error = exact - signed_volume(m);
            // Inscribed (every vertex on the exact surface): never more volume than the solid,
            // at least what the edges' inscribed polygons lose (n chords of a quarter circle,
            // each cutting a circular segment of area w^2/2 (t - sin t), t = pi / 2n), and
            // less with every segment.
            const double t = pi / (2 * n);
            const double edges_lost = 12 * l * n * w * w / 2 * (t - std::sin(t));
            EXPECT_GT(error, edges_lost - 100 * tol<TypeParam>());
            EXPECT_LT(error, previous_error);
            // Bound: the corners lose what the chamfer's corners lose (of each corner cube of
            // side w the octant keeps pi w^3 / 6, the flat cut w^3 / 6), shrunk like the edges'
            // loss (their chords span the same angles), with a factor 2 for the grid's cells,
            // which span up to twice an arc segment's angle.
            const double corners_lost_flat = 8 * (pi - 1) * w * w * w / 6;
            const double edges_lost_flat = 12 * l * w * w / 2 * (pi / 2 - 1);
            EXPECT_LT(error,
                      edges_lost + 2 * corners_lost_flat * edges_lost / edges_lost_flat + 100 * tol<TypeParam>());
            previous_error = error;
        }
        EXPECT_LT(previous_error, 0.01 * exact);
    }
}

TYPED_TEST(bevel_test, a_loop_around_a_cube_face_meets_in_mitres_on_both_cylinders) {
    SKIP_UNLESS_BEVELABLE() {
        using T = hmira::default_traits<TypeParam>;
        const double w = 0.3;
        const int n = 3;
        TypeParam m;
        (void)hmira::generate_cube(m).value();
        std::vector<typename T::edge_handle> loop{
            edge_between(m, {1, 1, 1}, {-1, 1, 1}), edge_between(m, {-1, 1, 1}, {-1, -1, 1}),
            edge_between(m, {-1, -1, 1}, {1, -1, 1}), edge_between(m, {1, -1, 1}, {1, 1, 1})};
        auto r = hmira::bevel(m, loop, {.width = w, .segments = n});
        ASSERT_TRUE(r) << r.error().message;
        // Each top corner (degree 3, two bevelled edges) becomes a point inside the top face
        // and one on the vertical edge, joined by one end edge that both strips share: 4 + 8
        // vertices, 4 strips (segments = 1: 12/20/10). Each shared end edge is split once
        // (n - 1 vertices), each strip cut n - 1 times.
        EXPECT_EQ(count(m), (counts{12 + 4 * (n - 1), 20 + 4 * (n - 1) + 4 * (n - 1), 10 + 4 * (n - 1)}));
        EXPECT_TRUE(valid_with_chi(m, 2));
        EXPECT_TRUE(faces_point_outward(m));
        EXPECT_EQ(face_sizes(m), (std::map<std::size_t, std::size_t>{{4, std::size_t(10 + 4 * (n - 1))}}));
        EXPECT_EQ(r->strip_faces.size(), std::size_t(4 * n));
        EXPECT_TRUE(r->vertex_faces.empty());
        // Every vertex of the top half is a mitre point: in a diagonal plane |x| = |y|, and on
        // both strips' cylinders of radius w (the mitre is their intersection).
        std::size_t top = 0;
        for (auto v : T::vertices(m)) {
            const auto p = p3(m, v);
            if (p[2] < 0) continue;
            ++top;
            EXPECT_NEAR(std::abs(p[0]), std::abs(p[1]), tol<TypeParam>());
            EXPECT_NEAR(std::hypot(std::abs(p[0]) - (1 - w), p[2] - (1 - w)), w, tol<TypeParam>());
            EXPECT_NEAR(std::hypot(std::abs(p[1]) - (1 - w), p[2] - (1 - w)), w, tol<TypeParam>());
        }
        EXPECT_EQ(top, std::size_t(4 * (n + 1)));
    }
}

TYPED_TEST(bevel_test, a_pass_through_vertex_shares_one_circular_end_edge_between_two_strips) {
    SKIP_UNLESS_BEVELABLE() {
        using T = hmira::default_traits<TypeParam>;
        const double w = 0.25;
        const int n = 4;
        TypeParam m;
        ASSERT_TRUE(add_face_list(m, lattice_box(2, 1, 1)));  // 12/20/10
        // Two collinear edges along the top front line; (1, 0, 1) has degree 4 and stays
        // nowhere: each of its corners slides, the two slides on one edge meet, and it becomes
        // one end edge shared by both strips. The box corners at the ends, degree 3, become one
        // end edge each. segments = 1: 12 - 3 + 6 vertices, 10 + 2 faces.
        std::vector<typename T::edge_handle> es{edge_between(m, {0, 0, 1}, {1, 0, 1}),
                                                edge_between(m, {1, 0, 1}, {2, 0, 1})};
        auto r = hmira::bevel(m, es, {.width = w, .segments = n});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_EQ(count(m), (counts{15 + 3 * (n - 1), 25 + 3 * (n - 1) + 2 * (n - 1), 12 + 2 * (n - 1)}));
        EXPECT_TRUE(valid_with_chi(m, 2));
        EXPECT_TRUE(faces_point_outward(m, {1, 0.5, 0.5}));
        // The two end faces x = 0 and x = 2 gain the corner's end edge with its arc points.
        EXPECT_EQ(face_sizes(m), (std::map<std::size_t, std::size_t>{{4, std::size_t(16)}, {std::size_t(4 + n), 2}}));
        EXPECT_EQ(r->strip_faces.size(), std::size_t(2 * n));
        // Every new vertex lies on the quarter circles of the strips' common cylinder.
        for (auto v : r->vertices) {
            const auto p = p3(m, v);
            EXPECT_NEAR(std::hypot(p[1] - w, p[2] - (1 - w)), w, tol<TypeParam>());
        }
        EXPECT_EQ(r->vertices.size(), std::size_t(6 + 3 * (n - 1)));
    }
}

TYPED_TEST(bevel_test, two_edges_meeting_on_a_grid_fan_out_from_the_vertices_that_stay) {
    SKIP_UNLESS_BEVELABLE() {
        using T = hmira::default_traits<TypeParam>;
        const int n = 3;
        TypeParam m;
        (void)hmira::generate_grid(m, {.columns = 4, .rows = 4}).value();  // 25/40/16
        std::vector<typename T::edge_handle> es{edge_between(m, {2, 2, 0}, {3, 2, 0}),
                                                edge_between(m, {2, 2, 0}, {2, 1, 0})};
        auto r = hmira::bevel(m, es, {.width = 0.25, .segments = n});
        ASSERT_TRUE(r) << r.error().message;
        // (2, 2) has degree 4 and every edge next to a bevelled one: it goes, replaced by a
        // triangle (a point between the two edges, slides on the other two edges). The far ends,
        // (3, 2) and (2, 1), keep unbevelled edges and stay: the strips end in them.
        // segments = 1: +7 - 1 vertices, +9 edges, +3 faces. Then two end edges split into n
        // segments and each strip fanned n - 1 times.
        EXPECT_EQ(count(m), (counts{31 + 2 * (n - 1), 49 + 2 * (n - 1) + 2 * (n - 1), 19 + 2 * (n - 1)}));
        EXPECT_TRUE(valid_with_chi(m, 1));
        for (auto f : T::faces(m)) EXPECT_GT(newell(m, f)[2], 1e-6);  // flat, +z, no zero area
        EXPECT_TRUE(has_vertex_at(m, {3, 2, 0}));
        EXPECT_TRUE(has_vertex_at(m, {2, 1, 0}));
        EXPECT_FALSE(has_vertex_at(m, {2, 2, 0}));
        EXPECT_TRUE(has_vertex_at(m, {2.25, 1.75, 0}));
        // The patch has a straight side: it stays one face with its arcs' points.
        ASSERT_EQ(r->vertex_faces.size(), 1u);
        EXPECT_EQ(std::ranges::distance(T::face_vertices(m, r->vertex_faces[0])), 3 + 2 * (n - 1));
        // Every face of a strip has the kept end vertex as a corner.
        ASSERT_EQ(r->strip_faces.size(), std::size_t(2 * n));
        for (std::size_t s = 0; s < 2; ++s)
            for (std::size_t j = 0; j < std::size_t(n); ++j) {
                const std::array<double, 3> tip =
                    s == 0 ? std::array<double, 3>{3, 2, 0} : std::array<double, 3>{2, 1, 0};
                bool has_tip = false;
                for (auto v : T::face_vertices(m, r->strip_faces[s * n + j])) has_tip |= dist(p3(m, v), tip) < 1e-9;
                EXPECT_TRUE(has_tip) << "strip " << s << " face " << j;
            }
    }
}

/// A pyramid over a regular pentagon (radius 1, z = 0) with apex (0, 0, 1): the test's data.
inline face_list pentagonal_pyramid() {
    face_list p;
    for (int i = 0; i < 5; ++i) {
        const double a = 2 * std::numbers::pi * i / 5;
        p.points.push_back({std::cos(a), std::sin(a), 0});
    }
    p.points.push_back({0, 0, 1});
    for (std::size_t i = 0; i < 5; ++i) p.faces.push_back({i, (i + 1) % 5, 5});
    p.faces.push_back({4, 3, 2, 1, 0});
    return p;
}

TYPED_TEST(bevel_test, a_degree_five_apex_is_filled_with_a_pentagonal_grid) {
    SKIP_UNLESS_BEVELABLE() {
        using T = hmira::default_traits<TypeParam>;
        for (int n : {2, 3}) {
            SCOPED_TRACE(::testing::Message() << "segments " << n);
            TypeParam m;
            ASSERT_TRUE(add_face_list(m, pentagonal_pyramid()));  // 6/10/6
            std::vector<typename T::edge_handle> es;
            for (int i = 0; i < 5; ++i) {
                const double a = 2 * std::numbers::pi * i / 5;
                es.push_back(edge_between(m, {0, 0, 1}, {std::cos(a), std::sin(a), 0}));
            }
            auto r = hmira::bevel(m, es, {.width = 0.15, .segments = n});
            ASSERT_TRUE(r) << r.error().message;
            // segments = 1: the apex becomes a pentagon of 5 inner points, each base vertex
            // (degree 3) one end edge between two slides: 15/25/12. Then 10 end edges split,
            // 5 strips cut, and the pentagon grid-filled.
            const auto p = grid_patch(5, n);
            EXPECT_EQ(count(m), (counts{15 + 10 * (n - 1) + p.v, 25 + 10 * (n - 1) + 5 * (n - 1) + p.e,
                                        12 + 5 * (n - 1) + p.f - 1}));
            EXPECT_TRUE(valid_with_chi(m, 2));
            EXPECT_TRUE(faces_point_outward(m, {0, 0, 0.25}));
            for (auto f : T::faces(m)) {
                const auto a = newell(m, f);
                EXPECT_GT(std::hypot(a[0], a[1], a[2]), 1e-6) << "face " << T::face_index(m, f);
            }
            EXPECT_EQ(r->vertex_faces.size(), std::size_t(p.f));
            EXPECT_EQ(r->strip_faces.size(), std::size_t(5 * n));
            // The grid fill's middle pentagon (odd n only); the base gains its 5 end arcs.
            auto sizes = face_sizes(m);
            EXPECT_EQ(sizes[5], n % 2 ? 1u : 0u);
            EXPECT_EQ(sizes[std::size_t(10 + 5 * (n - 1))], 1u);
            EXPECT_EQ(sizes[3], 5u);  // the lateral faces, cut back to triangles
            EXPECT_EQ(sizes[4], std::size_t(count(m).f) - 6 - (n % 2 ? 1 : 0));
        }
    }
}

TYPED_TEST(bevel_test, at_the_clamp_limit_a_rounded_cube_stays_valid) {
    SKIP_UNLESS_BEVELABLE() {
        using T = hmira::default_traits<TypeParam>;
        for (int n : {2, 3}) {
            TypeParam m;
            (void)hmira::generate_cube(m).value();
            const auto before = count(m);
            auto r = hmira::bevel(m, all_edges(m), {.width = 5.0, .segments = n});
            // Every edge at its limit would shrink the flat faces to points: the edges that would
            // leave a face of zero area are skipped instead, and the rest bevel to a valid mesh.
            // In float coordinates (OpenMesh's PolyMesh) rounding can leave every edge with a
            // face of zero area: then nothing applies, and the mesh is unchanged.
            if (!r && std::is_same_v<typename T::scalar, float>) {
                EXPECT_EQ(r.error().code, hmira::errc::unsupported) << r.error().message;
                EXPECT_EQ(count(m), before);
                EXPECT_TRUE(valid_with_chi(m, 2));
                continue;
            }
            ASSERT_TRUE(r) << r.error().message;
            EXPECT_GT(r->skipped_edges, 0u);
            EXPECT_GT(r->bevelled_edges, 0u);
            EXPECT_EQ(r->bevelled_edges + r->skipped_edges, 12u);
            EXPECT_TRUE(valid_with_chi(m, 2));
            for (auto v : T::vertices(m)) {
                const auto p = p3(m, v);
                EXPECT_TRUE(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]));
            }
        }
    }
}

TYPED_TEST(bevel_test, edges_whose_clamped_strips_would_leave_zero_area_faces_are_skipped_and_counted) {
    SKIP_UNLESS_BEVELABLE() {
        // Every edge of a cube (the four corner points of each face meet at its centre) and of
        // an octahedron (the three corner points of each triangle meet at its centre), with a
        // width the clamp cuts to the limit: bevelled in full, faces of zero area remain.
        for (int shape = 0; shape < 2; ++shape) {
            SCOPED_TRACE(shape == 0 ? "cube" : "octahedron");
            TypeParam m;
            if (shape == 0)
                (void)hmira::generate_cube(m).value();
            else
                (void)hmira::generate_octahedron(m).value();
            const auto edges = all_edges(m);
            const auto before = count(m);
            auto r = hmira::bevel(m, edges, {.width = 5.0});
            ASSERT_TRUE(r) << r.error().message;
            EXPECT_TRUE(valid_with_chi(m, 2));  // with the geometry: no face of zero area
            EXPECT_GT(r->skipped_edges, 0u);
            EXPECT_GT(r->bevelled_edges, 0u);
            EXPECT_EQ(r->bevelled_edges + r->skipped_edges, edges.size());
            EXPECT_EQ(r->strip_faces.size(), r->bevelled_edges);  // one flat strip per bevelled edge
            EXPECT_EQ(count(m).f, before.f + (long long)(r->strip_faces.size() + r->vertex_faces.size()));
        }
        // Below the limit nothing is skipped.
        TypeParam c;
        (void)hmira::generate_cube(c).value();
        auto r = hmira::bevel(c, all_edges(c), {.width = 0.3});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_EQ(r->skipped_edges, 0u);
        EXPECT_EQ(r->bevelled_edges, 12u);
        EXPECT_TRUE(valid_with_chi(c, 2));
    }
}

TYPED_TEST(bevel_test, random_selections_with_random_segments_keep_closed_meshes_valid) {
    SKIP_UNLESS_BEVELABLE() {
        using T = hmira::default_traits<TypeParam>;
#ifdef HMIRA_SANITIZER_BUILD
        const unsigned trials = 30;
#else
        const unsigned trials = 120;
#endif
        std::mt19937 rng(20261123);
        std::size_t applied = 0;
        for (unsigned trial = 0; trial < trials; ++trial) {
            TypeParam m;
            const unsigned shape = trial % 7;
            if (shape == 0)
                (void)hmira::generate_torus(m,
                                            {.major_radius = 3, .minor_radius = 1, .rings = 6 + rng() % 4, .sides = 5})
                    .value();
            else if (shape == 1)
                (void)hmira::generate_cube(m).value();
            else if (shape == 2)
                (void)hmira::generate_octahedron(m).value();
            else if (shape == 3)
                (void)hmira::generate_dodecahedron(m).value();
            else if (shape == 4)
                (void)hmira::generate_icosahedron(m).value();
            else if (shape == 5)
                ASSERT_TRUE(add_face_list(m, lattice_box(1 + int(rng() % 3), 2, 1)));
            else
                (void)hmira::generate_grid(m, {.columns = 3 + rng() % 3, .rows = 3 + rng() % 3}).value();
            const long long chi = shape == 0 ? 0 : (shape == 6 ? 1 : 2);
            const int n = 1 + int(rng() % 6);
            const double width = 0.02 + 0.5 * double(rng() % 1000) / 1000.0;
            const double keep = 0.1 + 0.6 * double(rng() % 100) / 100.0;
            std::vector<typename T::edge_handle> es;
            for (auto e : T::edges(m)) {
                const auto h = T::edge_halfedge(m, e);
                const bool inner = T::face(m, h) != T::null_face() && T::face(m, T::opposite(m, h)) != T::null_face();
                // Boundary edges are refused (tested above); on the grid, bevel inner ones only.
                if (double(rng() % 1000) / 1000.0 < keep && (inner || shape != 6)) es.push_back(e);
            }
            if (es.empty()) continue;
            SCOPED_TRACE(::testing::Message() << "trial " << trial << " shape " << shape << " segments " << n
                                              << " width " << width << " edges " << es.size());
            const auto before = count(m);
            const auto faces_before = canonical_faces(m);
            auto r = hmira::bevel(m, es, {.width = width, .segments = n});
            if (!r) {
                EXPECT_EQ(count(m), before);
                EXPECT_EQ(canonical_faces(m), faces_before);
                continue;
            }
            ++applied;
            // Edges that would leave a face of zero area are skipped: geometry holds too.
            ASSERT_TRUE(valid_with_chi(m, chi));
            EXPECT_EQ(r->bevelled_edges + r->skipped_edges, es.size());
            // No old face goes; every listed face is new and listed once.
            EXPECT_EQ(count(m).f, before.f + (long long)(r->strip_faces.size() + r->vertex_faces.size()));
            std::set<std::size_t> listed;
            for (auto f : r->strip_faces) listed.insert(T::face_index(m, f));
            for (auto f : r->vertex_faces) listed.insert(T::face_index(m, f));
            EXPECT_EQ(listed.size(), r->strip_faces.size() + r->vertex_faces.size());
            std::set<std::size_t> made;
            for (auto v : r->vertices) {
                made.insert(T::vertex_index(m, v));
                const auto p = p3(m, v);
                EXPECT_TRUE(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]));
            }
            EXPECT_EQ(made.size(), r->vertices.size());
            EXPECT_LE((long long)r->vertices.size(), count(m).v);
        }
        EXPECT_GT(applied, std::size_t(trials / 2));
    }
}

}  // namespace
