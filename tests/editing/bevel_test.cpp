// Bevel (issue 5): the cube-edge chamfer (volume removed computed here), rounded profiles on
// a circle, meeting bevels at a cube corner, kept end vertices on a grid, clamping, the
// vertex-only mode equal to truncate, and rejected input.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include <hmira/algorithms/generators/grid.hpp>

#include "editing/editing_support.hpp"

namespace {

using namespace hmira_test;

template <class M>
class bevel_test : public ::testing::Test {};
TYPED_TEST_SUITE(bevel_test, hmira_test::all_models);

#define SKIP_UNLESS_BEVELABLE()                                                     \
    if constexpr (!hmira::bevelable_mesh<TypeParam>) {                              \
        GTEST_SKIP() << "model cannot be edited (no Euler operators or triangles only)"; \
    } else

/// The cube edge from (1,1,-1) to (1,1,1) (corners F and G of generate_cube).
template <class M, class T = hmira::default_traits<M>>
typename T::edge_handle edge_between(const M& m, std::array<double, 3> a, std::array<double, 3> b) {
    for (auto e : T::edges(m)) {
        const auto ev = T::edge_vertices(m, e);
        const auto pa = p3<M, T>(m, ev[0]), pb = p3<M, T>(m, ev[1]);
        if ((dist(pa, a) < 1e-9 && dist(pb, b) < 1e-9) || (dist(pa, b) < 1e-9 && dist(pb, a) < 1e-9)) return e;
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
        std::vector<typename hmira::default_traits<TypeParam>::edge_handle> es{
            edge_between(m, {1, 1, 1}, {-1, 1, 1}), edge_between(m, {1, 1, 1}, {1, -1, 1}), edge_between(m, {1, 1, 1}, {1, 1, -1})};
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
        check(hmira::bevel(m, edge_between(m, {0, 0, 0}, {1, 0, 0})), hmira::errc::unsupported);  // boundary edge
        check(hmira::bevel(m, inner, {.segments = 3}), hmira::errc::unsupported);  // degree-4 ends stay
        // A good edge with a bad one changes nothing.
        std::vector<typename T::edge_handle> mixed{inner, edge_between(m, {3, 2, 0}, {3, 3, 0})};
        check(hmira::bevel(m, mixed), hmira::errc::unsupported);
    }
}

}  // namespace
