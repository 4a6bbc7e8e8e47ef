// Truncation: exact deltas, validity, orientation and positions on every model that
// supports editing; the truncated cube and the cuboctahedron; boundary corners; rejected input.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include <hmira/algorithms/generators/grid.hpp>
#include <hmira/algorithms/generators/torus.hpp>

#include "algorithms/editing/editing_support.hpp"

namespace {

using namespace hmira_test;

template <class M>
class truncate_test : public ::testing::Test {};
TYPED_TEST_SUITE(truncate_test, hmira_test::all_models);

#define SKIP_UNLESS_TRUNCATABLE()                                                        \
    if constexpr (!hmira::truncatable_mesh<TypeParam>) {                                 \
        GTEST_SKIP() << "model cannot be edited (no Euler operators or triangles only)"; \
    } else

TYPED_TEST(truncate_test, one_cube_corner_gives_a_triangle_at_a_third_of_each_edge) {
    SKIP_UNLESS_TRUNCATABLE() {
        using T = hmira::default_traits<TypeParam>;
        TypeParam m;
        auto cube = hmira::generate_cube(m).value();
        const auto v = cube.vertices[6];  // (1, 1, 1)
        const auto before = count(m);
        const double vol_before = signed_volume(m);
        auto r = hmira::truncate(m, v, {.fraction = 1.0 / 3});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_EQ(count(m), (counts{before.v + 2, before.e + 3, before.f + 1}));
        EXPECT_TRUE(valid_with_chi(m, 2));
        EXPECT_TRUE(faces_point_outward(m));
        ASSERT_NE(r->face, T::null_face());
        ASSERT_EQ(r->vertices.size(), 3u);
        // The cut points lie at 1/3 of the way from (1,1,1) towards each neighbour.
        for (auto p : {std::array<double, 3>{1.0 / 3, 1, 1}, {1, 1.0 / 3, 1}, {1, 1, 1.0 / 3}})
            EXPECT_TRUE(has_vertex_at(m, p));
        EXPECT_FALSE(has_vertex_at(m, {1, 1, 1}));
        // A corner tetrahedron with three legs of 2/3 is gone.
        EXPECT_NEAR(signed_volume(m), vol_before - std::pow(2.0 / 3, 3) / 6, tol<TypeParam>());
        // The new triangle faces away from the solid: along (1,1,1).
        const auto n = newell(m, r->face);
        EXPECT_GT(n[0] + n[1] + n[2], 0);
    }
}

TYPED_TEST(truncate_test, all_cube_vertices_at_a_third_give_the_truncated_cube) {
    SKIP_UNLESS_TRUNCATABLE() {
        TypeParam m;
        (void)hmira::generate_cube(m).value();
        auto r = hmira::truncate_all(m, {.fraction = 1.0 / 3});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_EQ(count(m), (counts{24, 36, 14}));
        EXPECT_TRUE(valid_with_chi(m, 2));
        EXPECT_EQ(face_sizes(m), (std::map<std::size_t, std::size_t>{{3, 8}, {8, 6}}));
        EXPECT_TRUE(faces_point_outward(m));
        EXPECT_NEAR(signed_volume(m), 8.0 - 8 * std::pow(2.0 / 3, 3) / 6, tol<TypeParam>());
        EXPECT_EQ(r->faces.size(), 8u);
        EXPECT_EQ(r->vertices.size(), 24u);
    }
}

TYPED_TEST(truncate_test, all_cube_vertices_at_half_share_the_meeting_points_giving_a_cuboctahedron) {
    SKIP_UNLESS_TRUNCATABLE() {
        TypeParam m;
        (void)hmira::generate_cube(m).value();
        auto r = hmira::truncate_all(m, {.fraction = 0.5});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_EQ(count(m), (counts{12, 24, 14}));
        EXPECT_TRUE(valid_with_chi(m, 2));
        EXPECT_EQ(face_sizes(m), (std::map<std::size_t, std::size_t>{{3, 8}, {4, 6}}));
        EXPECT_TRUE(faces_point_outward(m));
        EXPECT_NEAR(signed_volume(m), 8.0 - 8 * 1.0 / 6, tol<TypeParam>());
        for (auto p : {std::array<double, 3>{0, 1, 1}, {1, 0, -1}, {-1, -1, 0}}) EXPECT_TRUE(has_vertex_at(m, p));
    }
}

TYPED_TEST(truncate_test, a_distance_larger_than_half_an_edge_is_clamped_where_both_ends_are_cut) {
    SKIP_UNLESS_TRUNCATABLE() {
        TypeParam m;
        (void)hmira::generate_cube(m).value();
        auto r = hmira::truncate_all(m, {.distance = 5.0});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_EQ(count(m), (counts{12, 24, 14}));
        EXPECT_TRUE(valid_with_chi(m, 2));
    }
}

TYPED_TEST(truncate_test, distance_places_cuts_at_that_distance_from_the_vertex) {
    SKIP_UNLESS_TRUNCATABLE() {
        TypeParam m;
        auto cube = hmira::generate_cube(m).value();
        auto r = hmira::truncate(m, cube.vertices[0], {.distance = 0.25});  // (-1,-1,-1)
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(valid_with_chi(m, 2));
        for (auto p : {std::array<double, 3>{-0.75, -1, -1}, {-1, -0.75, -1}, {-1, -1, -0.75}})
            EXPECT_TRUE(has_vertex_at(m, p));
        EXPECT_TRUE(faces_point_outward(m));
    }
}

TYPED_TEST(truncate_test, vertices_of_every_degree_on_a_grid_follow_the_documented_deltas) {
    SKIP_UNLESS_TRUNCATABLE() {
        using T = hmira::default_traits<TypeParam>;
        // 3 x 3 quads: corner (degree 2), side (degree 3, boundary), centre (degree 4).
        for (auto [index, dv, de, df] : {std::array<long long, 4>{0, 1, 1, 0}, {1, 2, 3, 1}, {5, 3, 4, 1}}) {
            TypeParam m;
            auto g = hmira::generate_grid(m, {.columns = 3, .rows = 3}).value();
            const auto before = count(m);
            const auto loops_before = hmira::mesh_topology(m).boundary_loops;
            auto r = hmira::truncate(m, g.vertices[(std::size_t)index]);
            ASSERT_TRUE(r) << r.error().message;
            EXPECT_EQ(count(m), (counts{before.v + dv, before.e + de, before.f + df})) << "vertex " << index;
            EXPECT_TRUE(valid_with_chi(m, 1));
            EXPECT_EQ(hmira::mesh_topology(m).boundary_loops, loops_before);
            EXPECT_EQ(r->face == T::null_face(), df == 0);
            // Every face still faces +z.
            for (auto f : T::faces(m)) EXPECT_GT(newell(m, f)[2], 0);
        }
    }
}

TYPED_TEST(truncate_test, a_random_vertex_set_on_a_torus_keeps_it_a_valid_torus) {
    SKIP_UNLESS_TRUNCATABLE() {
        TypeParam m;
        auto t = hmira::generate_torus(m, {.rings = 12, .sides = 8}).value();
        std::vector<typename hmira::default_traits<TypeParam>::vertex_handle> pick;
        std::mt19937 rng(5);
        for (auto v : t.vertices)
            if (rng() % 3 == 0) pick.push_back(v);
        pick.push_back(pick.front());  // duplicates count once
        const auto before = count(m);
        auto r = hmira::truncate(m, pick, {.fraction = 0.5});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_EQ(r->faces.size(), pick.size() - 1);
        EXPECT_EQ(count(m).f, before.f + (long long)(pick.size() - 1));
        EXPECT_TRUE(valid_with_chi(m, 0));
        EXPECT_GT(signed_volume(m), 0);
    }
}

TYPED_TEST(truncate_test, bad_options_and_vertices_are_rejected_and_leave_the_mesh_unchanged) {
    SKIP_UNLESS_TRUNCATABLE() {
        using T = hmira::default_traits<TypeParam>;
        TypeParam m;
        auto cube = hmira::generate_cube(m).value();
        const auto lone = T::add_vertex(m, {5, 5, 5});
        const auto faces_before = canonical_faces(m);
        const auto before = count(m);
        const auto check = [&](auto r, hmira::errc code) {
            ASSERT_FALSE(r);
            EXPECT_EQ(r.error().code, code) << r.error().message;
            EXPECT_FALSE(r.error().message.empty());
            EXPECT_EQ(count(m), before);
            EXPECT_EQ(canonical_faces(m), faces_before);
        };
        for (double f : {0.0, 1.0, -0.2, std::numeric_limits<double>::quiet_NaN()})
            check(hmira::truncate(m, cube.vertices[0], {.fraction = f}), hmira::errc::invalid_argument);
        check(hmira::truncate(m, cube.vertices[0], {.distance = -1.0}), hmira::errc::invalid_argument);
        check(hmira::truncate(m, lone), hmira::errc::topology);
        // A set with one bad vertex changes nothing, even after good ones.
        std::vector<typename T::vertex_handle> set{cube.vertices[0], cube.vertices[1], lone};
        check(hmira::truncate(m, set), hmira::errc::topology);
        EXPECT_TRUE(has_vertex_at(m, {-1, -1, -1}));
    }
}

TYPED_TEST(truncate_test, a_pinched_vertex_is_rejected_as_non_manifold) {
    SKIP_UNLESS_TRUNCATABLE() {
        using T = hmira::default_traits<TypeParam>;
        TypeParam m;
        // Two triangles sharing only vertex c (a bowtie).
        const auto c = T::add_vertex(m, {0, 0, 0});
        const auto a = T::add_vertex(m, {1, 0, 0}), b = T::add_vertex(m, {1, 1, 0});
        const auto d = T::add_vertex(m, {-1, 0, 0}), e = T::add_vertex(m, {-1, -1, 0});
        const typename T::vertex_handle f1[] = {c, a, b}, f2[] = {c, d, e};
        if (!T::add_face(m, f1) || !T::add_face(m, f2)) GTEST_SKIP() << "model does not hold a pinched vertex";
        const auto before = count(m);
        auto r = hmira::truncate(m, c);
        ASSERT_FALSE(r);
        EXPECT_EQ(r.error().code, hmira::errc::non_manifold) << r.error().message;
        EXPECT_EQ(count(m), before);
    }
}

}  // namespace
