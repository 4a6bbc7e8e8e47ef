// Each local triangle operator on every model that supports it: counts and positions stated
// here, the inverse restores the mesh (connectivity up to relabelling, positions), and a
// refused operation names the reason and changes nothing.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <hmira/algorithms/generators/platonic_solids.hpp>

#include "algorithms/triangle/triangle_support.hpp"

namespace {

using namespace hmira_test;

template <class M>
class triangle_operators : public ::testing::Test {};
TYPED_TEST_SUITE(triangle_operators, all_models);

template <class M, class T = hmira::default_traits<M>>
typename T::vertex_handle vertex_at(const M& m, double x, double y, double z = 0) {
    for (auto v : T::vertices(m))
        if (key_of<M, T>(m, v) == point_key{x, y, z}) return v;
    ADD_FAILURE() << "no vertex at " << x << ", " << y << ", " << z;
    return typename T::vertex_handle();
}

template <class M, class T = hmira::default_traits<M>>
typename T::halfedge_handle halfedge_at(const M& m, std::pair<double, double> a, std::pair<double, double> b) {
    return find_halfedge<M, T>(m, vertex_at<M, T>(m, a.first, a.second), vertex_at<M, T>(m, b.first, b.second));
}

template <class M>
M tri_grid(std::size_t n) {
    return mesh_from<M>(grid(n, n, true));
}

/// Compacts both and compares their canonical forms.
template <class M>
::testing::AssertionResult same_mesh(M a, M b) {
    compact(a);
    compact(b);
    if (canonical(a) == canonical(b)) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "the meshes differ";
}

struct counts3 {
    long long v, e, f;
    bool operator==(const counts3&) const = default;
};
template <class M, class T = hmira::default_traits<M>>
counts3 counts_of(const M& m) {
    return {(long long)T::vertex_count(m), (long long)T::edge_count(m), (long long)T::face_count(m)};
}

TYPED_TEST(triangle_operators, flip_replaces_the_diagonal_and_flipping_again_restores_the_mesh) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        M m = tri_grid<M>(3);
        const M start = m;
        const auto c0 = counts_of(m);
        const auto h = halfedge_at(m, {1, 1}, {2, 2});
        ASSERT_TRUE(hmira::is_flip_ok(m, h));
        auto r = hmira::flip_edge(m, h);
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(valid_topology(m));
        EXPECT_EQ(counts_of(m), c0);
        EXPECT_EQ(halfedge_at(m, {1, 1}, {2, 2}), T::null_halfedge());
        // The other diagonal of the quad (1,1)-(2,1)-(2,2)-(1,2), from (2,1) to (1,2).
        EXPECT_EQ((key_of<M, T>(m, T::target(m, r->halfedge))), (point_key{1, 2, 0}));
        EXPECT_EQ((key_of<M, T>(m, T::target(m, T::opposite(m, r->halfedge)))), (point_key{2, 1, 0}));
        auto back = hmira::flip_edge(m, r->halfedge);
        ASSERT_TRUE(back) << back.error().message;
        EXPECT_TRUE(valid_topology(m));
        EXPECT_TRUE(same_mesh(m, start));
    }
}

TYPED_TEST(triangle_operators, flip_is_refused_on_a_boundary_edge_and_on_a_tetrahedron_and_changes_nothing) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        M m = tri_grid<M>(2);
        const auto h = halfedge_at(m, {0, 0}, {1, 0});
        EXPECT_FALSE(hmira::is_flip_ok(m, h));
        const auto before = take_snapshot(m);
        auto r = hmira::flip_edge(m, h);
        ASSERT_FALSE(r);
        EXPECT_EQ(r.error().code, hmira::errc::topology);
        EXPECT_EQ(take_snapshot(m), before);
        EXPECT_FALSE(hmira::flip_edge(m, T::null_halfedge()));

        // On a tetrahedron the two vertices opposite any edge are already joined.
        M t;
        ASSERT_TRUE(hmira::generate_tetrahedron(t));
        const auto tb = take_snapshot(t);
        for (auto x : T::halfedges(t)) {
            EXPECT_FALSE(hmira::is_flip_ok(t, x));
            EXPECT_FALSE(hmira::flip_edge(t, x));
        }
        EXPECT_EQ(take_snapshot(t), tb);
    }
}

TYPED_TEST(triangle_operators, split_of_an_interior_edge_splits_both_triangles_and_collapse_undoes_it) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        M m = tri_grid<M>(3);
        const M start = m;
        const auto c0 = counts_of(m);
        auto r = hmira::split_edge(m, halfedge_at(m, {1, 1}, {2, 2}));
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(valid_topology(m));
        EXPECT_EQ(counts_of(m), (counts3{c0.v + 1, c0.e + 3, c0.f + 2}));
        EXPECT_EQ((key_of<M, T>(m, r->vertex)), (point_key{1.5, 1.5, 0}));
        EXPECT_EQ((key_of<M, T>(m, T::target(m, r->halfedge))), (point_key{2, 2, 0}));
        // The new vertex joins the two ends and the two opposite corners.
        for (auto [x, y] : {std::pair{1.0, 1.0}, {2.0, 2.0}, {2.0, 1.0}, {1.0, 2.0}})
            EXPECT_NE(find_halfedge(m, r->vertex, vertex_at(m, x, y)), T::null_halfedge()) << x << ", " << y;
        auto back = hmira::collapse_edge(m, r->halfedge, {.placement = hmira::collapse_placement::target});
        ASSERT_TRUE(back) << back.error().message;
        EXPECT_TRUE(valid_topology(m));
        EXPECT_TRUE(same_mesh(m, start));
    }
}

TYPED_TEST(triangle_operators, split_of_a_boundary_edge_splits_one_triangle_and_collapse_undoes_it) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        M m = tri_grid<M>(3);
        const M start = m;
        const auto c0 = counts_of(m);
        // Both directions: the face side first, then the boundary side.
        for (auto [from, to] : {std::pair{std::pair{1.0, 0.0}, std::pair{2.0, 0.0}}, {{2.0, 0.0}, {1.0, 0.0}}}) {
            auto r = hmira::split_edge(m, halfedge_at(m, from, to), {.position = hmira::vec3<double>{1.25, 0, 0}});
            ASSERT_TRUE(r) << r.error().message;
            EXPECT_TRUE(valid_topology(m));
            EXPECT_EQ(counts_of(m), (counts3{c0.v + 1, c0.e + 2, c0.f + 1}));
            EXPECT_EQ((key_of<M, T>(m, r->vertex)), (point_key{1.25, 0, 0}));
            auto back = hmira::collapse_edge(m, r->halfedge, {.placement = hmira::collapse_placement::target});
            ASSERT_TRUE(back) << back.error().message;
            EXPECT_TRUE(valid_topology(m));
            EXPECT_TRUE(same_mesh(m, start));
        }
    }
}

TYPED_TEST(triangle_operators, split_next_to_polygons_joins_their_loops_and_collapse_undoes_it) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        if constexpr (requires { requires T::triangles_only; }) {
            // A triangles-only model cannot hold the quadrilaterals `split_triangles = false` makes.
            M m = tri_grid<M>(2);
            const auto before = take_snapshot(m);
            auto r = hmira::split_edge(m, halfedge_at(m, {0, 0}, {1, 1}), {.split_triangles = false});
            ASSERT_FALSE(r);
            EXPECT_EQ(r.error().code, hmira::errc::unsupported);
            EXPECT_EQ(take_snapshot(m), before);
        } else {
            M m = mesh_from<M>(grid(3, 3));
            const M start = m;
            const auto c0 = counts_of(m);
            auto r = hmira::split_edge(m, halfedge_at(m, {1, 1}, {2, 1}));
            ASSERT_TRUE(r) << r.error().message;
            EXPECT_TRUE(valid_topology(m));
            EXPECT_EQ(counts_of(m), (counts3{c0.v + 1, c0.e + 1, c0.f}));
            std::size_t pentagons = 0;
            for (auto f : T::faces(m)) pentagons += std::ranges::distance(T::face_vertices(m, f)) == 5;
            EXPECT_EQ(pentagons, 2u);
            auto back = hmira::collapse_edge(m, r->halfedge, {.placement = hmira::collapse_placement::target});
            ASSERT_TRUE(back) << back.error().message;
            EXPECT_TRUE(valid_topology(m));
            EXPECT_TRUE(same_mesh(m, start));
        }
    }
}

TYPED_TEST(triangle_operators, split_face_makes_three_triangles_and_collapse_undoes_it) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        M m = tri_grid<M>(2);
        const M start = m;
        const auto c0 = counts_of(m);
        const auto h = halfedge_at(m, {0, 0}, {1, 0});  // in triangle (0,0) (1,0) (1,1)
        auto r = hmira::split_face(m, T::face(m, h));
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(valid_topology(m));
        EXPECT_EQ(counts_of(m), (counts3{c0.v + 1, c0.e + 3, c0.f + 2}));
        const auto p = T::position(m, r->vertex);
        EXPECT_NEAR(double(p[0]), 2.0 / 3.0, 1e-6);
        EXPECT_NEAR(double(p[1]), 1.0 / 3.0, 1e-6);
        auto back = hmira::collapse_edge(m, r->halfedge, {.placement = hmira::collapse_placement::target});
        ASSERT_TRUE(back) << back.error().message;
        EXPECT_TRUE(valid_topology(m));
        EXPECT_TRUE(same_mesh(m, start));
    }
}

TYPED_TEST(triangle_operators, split_face_is_refused_on_a_quad) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        if constexpr (!requires { requires T::triangles_only; }) {
            M m = mesh_from<M>(grid(1, 1));
            const auto before = take_snapshot(m);
            auto r = hmira::split_face(m, *T::faces(m).begin());
            ASSERT_FALSE(r);
            EXPECT_EQ(r.error().code, hmira::errc::topology);
            EXPECT_EQ(take_snapshot(m), before);
        }
    }
}

TYPED_TEST(triangle_operators, collapse_removes_two_triangles_and_puts_the_survivor_at_the_midpoint) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        M m = tri_grid<M>(3);
        const auto c0 = counts_of(m);
        const auto b = vertex_at(m, 2, 2);
        auto r = hmira::collapse_edge(m, halfedge_at(m, {1, 1}, {2, 2}));
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(valid_topology(m));
        EXPECT_EQ(r->vertex, b);
        EXPECT_EQ(counts_of(m), (counts3{c0.v - 1, c0.e - 3, c0.f - 2}));
        EXPECT_EQ((key_of<M, T>(m, b)), (point_key{1.5, 1.5, 0}));
        // (1,1) had six neighbours, (2,2) six; they shared two: 6 + 6 - 2 - 2 (each other) = 8.
        EXPECT_EQ(std::ranges::distance(T::adjacent_vertices(m, b)), 8);
    }
}

TYPED_TEST(triangle_operators, collapse_refusals_name_the_rule_and_change_nothing) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        auto refused = [](M& m, typename T::halfedge_handle h, const char* rule, hmira::collapse_edge_options o = {}) {
            EXPECT_FALSE(hmira::is_collapse_ok(m, h, o)) << rule;
            const auto before = take_snapshot(m);
            auto r = hmira::collapse_edge(m, h, o);
            ASSERT_FALSE(r) << rule;
            EXPECT_NE(r.error().message.find(rule), std::string::npos) << r.error().message;
            EXPECT_EQ(take_snapshot(m), before) << rule;
        };
        {  // A strip of three squares: (1,0)-(1,1) joins two boundary vertices but is interior.
            M m = mesh_from<M>(grid(3, 1, true));
            refused(m, halfedge_at(m, {1, 0}, {1, 1}), "pinch");
            // The diagonal of the corner square hangs its corner triangle on it alone.
            refused(m, halfedge_at(m, {0, 0}, {1, 1}), "hangs on it alone");
            // A boundary edge is fine.
            EXPECT_TRUE(hmira::is_collapse_ok(m, halfedge_at(m, {0, 0}, {1, 0})));
        }
        {  // A single triangle hangs on each of its edges alone.
            M m = mesh_from<M>(face_list{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}});
            refused(m, halfedge_at(m, {0, 0}, {1, 0}), "boundary loop of three edges");
        }
        {  // Every edge of a tetrahedron.
            M m;
            ASSERT_TRUE(hmira::generate_tetrahedron(m));
            refused(m, *T::halfedges(m).begin(), "tetrahedron");
        }
        {  // Link condition: after a 1-to-3 split of triangle (1,1) (2,1) (2,2), the corner (2,2)
            // is adjacent to both ends of edge (1,1)-(2,1) but no longer in a triangle with it.
            M m = tri_grid<M>(3);
            const auto h = halfedge_at(m, {1, 1}, {2, 1});
            ASSERT_TRUE(hmira::is_collapse_ok(m, h));
            ASSERT_TRUE(hmira::split_face(m, T::face(m, h)));
            refused(m, h, "link condition");
        }
        {  // Geometric check: moving the survivor far away turns faces over.
            M m = tri_grid<M>(3);
            const auto h = halfedge_at(m, {1, 1}, {2, 2});
            const hmira::collapse_edge_options far{
                .placement = hmira::collapse_placement::given, .position = {10, 10, 0}, .check_geometry = true};
            EXPECT_TRUE(hmira::is_collapse_ok(m, h));
            refused(m, h, "fold", far);
            EXPECT_TRUE(hmira::is_collapse_ok(m, h, {.check_geometry = true}));
        }
        {  // A non-finite position.
            M m = tri_grid<M>(3);
            const auto before = take_snapshot(m);
            auto r = hmira::collapse_edge(m, halfedge_at(m, {1, 1}, {2, 2}),
                                          {.placement = hmira::collapse_placement::given,
                                           .position = {std::numeric_limits<double>::quiet_NaN(), 0, 0}});
            ASSERT_FALSE(r);
            EXPECT_EQ(r.error().code, hmira::errc::invalid_argument);
            EXPECT_EQ(take_snapshot(m), before);
        }
    }
}

}  // namespace
