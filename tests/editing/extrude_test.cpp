// Extrusion (issue 5): one face, a region, individual faces; exact deltas, validity, walls
// of quads, outward orientation, the volume added; rejected input leaves the mesh unchanged.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include <hmira/algorithms/generators/grid.hpp>

#include "editing/editing_support.hpp"

namespace {

using namespace hmira_test;

template <class M>
class extrude_test : public ::testing::Test {};
TYPED_TEST_SUITE(extrude_test, hmira_test::all_models);

#define SKIP_UNLESS_EXTRUDABLE()                                                    \
    if constexpr (!hmira::extrudable_mesh<TypeParam>) {                             \
        GTEST_SKIP() << "model cannot be edited (no Euler operators or triangles only)"; \
    } else

template <class M>
M box(int nx, int ny, int nz) {
    M m;
    EXPECT_TRUE(add_face_list(m, lattice_box(nx, ny, nz)));
    return m;
}

TYPED_TEST(extrude_test, one_cube_face_moved_out_by_d_adds_area_times_d) {
    SKIP_UNLESS_EXTRUDABLE() {
        using T = hmira::default_traits<TypeParam>;
        for (double d : {0.5, 2.0}) {
            TypeParam m;
            auto cube = hmira::generate_cube(m).value();
            const auto top = cube.faces[5];  // y = +1, area 4
            const auto before = count(m);
            const double vol = signed_volume(m);
            auto r = hmira::extrude(m, top, {.distance = d});
            ASSERT_TRUE(r) << r.error().message;
            EXPECT_EQ(count(m), (counts{before.v + 4, before.e + 8, before.f + 4}));
            EXPECT_TRUE(valid_with_chi(m, 2));
            EXPECT_NEAR(signed_volume(m), vol + 4 * d, tol<TypeParam>());
            EXPECT_TRUE(faces_point_outward(m, {0, d / 2, 0}));
            ASSERT_EQ(r->top_faces.size(), 1u);
            EXPECT_EQ(r->top_faces[0], top);
            EXPECT_EQ(r->side_faces.size(), 4u);
            EXPECT_EQ(r->vertices.size(), 4u);
            for (auto v : T::face_vertices(m, top)) EXPECT_NEAR(p3(m, v)[1], 1 + d, tol<TypeParam>());
            for (auto f : r->side_faces) EXPECT_EQ(std::ranges::distance(T::face_vertices(m, f)), 4);
            EXPECT_EQ(face_sizes(m), (std::map<std::size_t, std::size_t>{{4, 10}}));
        }
    }
}

TYPED_TEST(extrude_test, a_negative_distance_digs_a_pocket_that_removes_area_times_d) {
    SKIP_UNLESS_EXTRUDABLE() {
        using T = hmira::default_traits<TypeParam>;
        TypeParam m;
        auto cube = hmira::generate_cube(m).value();
        const double vol = signed_volume(m);
        auto r = hmira::extrude(m, cube.faces[5], {.distance = -0.75});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(valid_with_chi(m, 2));
        EXPECT_NEAR(signed_volume(m), vol - 4 * 0.75, tol<TypeParam>());
        // The pocket floor still faces +y, out of the solid; each wall faces into the pocket.
        EXPECT_GT(newell(m, cube.faces[5])[1], 0);
        for (auto f : r->side_faces) {
            const auto n = newell(m, f);
            const auto c = centroid(m, f);
            EXPECT_LT(n[0] * c[0] + n[2] * c[2], 0) << "wall faces away from the pocket";
            EXPECT_NEAR(n[1], 0, tol<TypeParam>());
        }
        (void)sizeof(T);
    }
}

TYPED_TEST(extrude_test, an_oblique_direction_adds_the_projected_volume) {
    SKIP_UNLESS_EXTRUDABLE() {
        TypeParam m;
        auto cube = hmira::generate_cube(m).value();
        const double vol = signed_volume(m);
        auto r = hmira::extrude(m, cube.faces[5], {.distance = 1.0, .direction = hmira::vec3<double>{0, 1, 1}});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(valid_with_chi(m, 2));
        EXPECT_NEAR(signed_volume(m), vol + 4 * std::sqrt(0.5), tol<TypeParam>());
    }
}

TYPED_TEST(extrude_test, a_region_moves_as_one_piece_with_walls_only_on_its_outline) {
    SKIP_UNLESS_EXTRUDABLE() {
        using T = hmira::default_traits<TypeParam>;
        auto m = box<TypeParam>(3, 3, 1);
        const auto region = faces_on_plane(m, 2, 1.0);  // the 9 top quads
        ASSERT_EQ(region.size(), 9u);
        const auto before = count(m);
        const double vol = signed_volume(m);
        auto r = hmira::extrude(m, region, {.distance = 0.5});
        ASSERT_TRUE(r) << r.error().message;
        // Outline of 12 edges: 12 new vertices, 24 new edges, 12 walls; 4 inner vertices move.
        EXPECT_EQ(count(m), (counts{before.v + 12, before.e + 24, before.f + 12}));
        EXPECT_TRUE(valid_with_chi(m, 2));
        EXPECT_NEAR(signed_volume(m), vol + 9 * 0.5, tol<TypeParam>());
        EXPECT_TRUE(faces_point_outward(m, {1.5, 1.5, 0.75}));
        EXPECT_EQ(r->side_faces.size(), 12u);
        for (auto f : region)
            for (auto v : T::face_vertices(m, f)) EXPECT_NEAR(p3(m, v)[2], 1.5, tol<TypeParam>());
        EXPECT_EQ(face_sizes(m).size(), 1u);  // quads only
        EXPECT_FALSE(has_vertex_at(m, {1, 1, 1}));
        EXPECT_TRUE(has_vertex_at(m, {1, 1, 1.5}));
        EXPECT_TRUE(has_vertex_at(m, {0, 1, 1}));  // the outline stays, with its copy above
        EXPECT_TRUE(has_vertex_at(m, {0, 1, 1.5}));
    }
}

TYPED_TEST(extrude_test, a_region_reaching_the_boundary_keeps_the_boundary_valid) {
    SKIP_UNLESS_EXTRUDABLE() {
        TypeParam m;
        auto g = hmira::generate_grid(m, {.columns = 4, .rows = 3}).value();
        // The first row of cells: its outline runs along the grid's boundary on three sides.
        std::vector<typename hmira::default_traits<TypeParam>::face_handle> region(g.faces.begin(), g.faces.begin() + 4);
        const auto before = count(m);
        auto r = hmira::extrude(m, region, {.distance = 1.0});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_EQ(count(m), (counts{before.v + 10, before.e + 20, before.f + 10}));
        EXPECT_TRUE(valid_with_chi(m, 1));
        EXPECT_EQ(hmira::mesh_topology(m).boundary_loops, 1u);
    }
}

TYPED_TEST(extrude_test, individual_mode_extrudes_each_face_along_its_own_normal) {
    SKIP_UNLESS_EXTRUDABLE() {
        auto m = box<TypeParam>(2, 1, 1);
        std::vector<typename hmira::default_traits<TypeParam>::face_handle> sel = faces_on_plane(m, 2, 1.0);
        const auto side = faces_on_plane(m, 0, 2.0);  // the +x end
        sel.insert(sel.end(), side.begin(), side.end());
        ASSERT_EQ(sel.size(), 3u);
        const auto before = count(m);
        const double vol = signed_volume(m);
        auto r = hmira::extrude(m, sel, {.distance = 0.25, .mode = hmira::extrude_mode::individual});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_EQ(count(m), (counts{before.v + 12, before.e + 24, before.f + 12}));
        EXPECT_TRUE(valid_with_chi(m, 2));
        EXPECT_NEAR(signed_volume(m), vol + 3 * 0.25, tol<TypeParam>());
        EXPECT_TRUE(has_vertex_at(m, {2.25, 0, 0}));
        EXPECT_TRUE(has_vertex_at(m, {2, 0, 1.25}));
    }
}

TYPED_TEST(extrude_test, a_single_face_region_equals_individual_mode) {
    SKIP_UNLESS_EXTRUDABLE() {
        TypeParam a, b;
        auto ca = hmira::generate_cube(a).value();
        auto cb = hmira::generate_cube(b).value();
        ASSERT_TRUE(hmira::extrude(a, ca.faces[2], {.distance = 0.3}));
        ASSERT_TRUE(hmira::extrude(b, cb.faces[2], {.distance = 0.3, .mode = hmira::extrude_mode::individual}));
        EXPECT_EQ(canonical_faces(a), canonical_faces(b));
    }
}

TYPED_TEST(extrude_test, bad_input_is_rejected_and_leaves_the_mesh_unchanged) {
    SKIP_UNLESS_EXTRUDABLE() {
        using F = typename hmira::default_traits<TypeParam>::face_handle;
        auto m = box<TypeParam>(3, 3, 1);
        const auto top = faces_on_plane(m, 2, 1.0);
        const auto faces_before = canonical_faces(m);
        const auto before = count(m);
        const auto check = [&](auto r, hmira::errc code) {
            ASSERT_FALSE(r);
            EXPECT_EQ(r.error().code, code) << r.error().message;
            EXPECT_EQ(count(m), before);
            EXPECT_EQ(canonical_faces(m), faces_before);
        };
        for (double d : {0.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
            check(hmira::extrude(m, top[0], {.distance = d}), hmira::errc::invalid_argument);
        check(hmira::extrude(m, top[0], {.direction = hmira::vec3<double>{0, 0, 0}}), hmira::errc::invalid_argument);
        check(hmira::extrude(m, std::vector<F>{}), hmira::errc::invalid_argument);
        // Two faces that share no edge: not a region.
        const auto bottom = faces_on_plane(m, 2, 0.0);
        check(hmira::extrude(m, std::vector<F>{top[0], bottom[0]}), hmira::errc::topology);
        // Every face: no outline.
        std::vector<F> all;
        for (auto f : hmira::default_traits<TypeParam>::faces(m)) all.push_back(f);
        check(hmira::extrude(m, all), hmira::errc::topology);
        // Diagonal neighbours joined by an edge-neighbour on one side only: pinched at a vertex.
        std::vector<F> pinched;
        for (auto f : top) {
            const auto c = centroid(m, f);
            if ((std::abs(c[0] - 0.5) < 1e-9 && std::abs(c[1] - 0.5) < 1e-9) || (std::abs(c[0] - 1.5) < 1e-9 && std::abs(c[1] - 1.5) < 1e-9))
                pinched.push_back(f);
        }
        ASSERT_EQ(pinched.size(), 2u);
        check(hmira::extrude(m, pinched), hmira::errc::topology);
    }
}

}  // namespace
