// The add/remove primitives of thesis 4.2 on every model with the raw halfedge layer: what
// each creates or removes (counted by hand for a 3 x 3 grid), validity afterwards, failed
// preconditions leaving the mesh unchanged, and add/remove pairs restoring the mesh.

#include <gtest/gtest.h>

#include <array>
#include <span>

#include <hmira/algorithms/primitives/primitives.hpp>

#include "euler/euler_support.hpp"
#include "support/models.hpp"

namespace {

using namespace hmira_test;

template <class M>
class primitives : public ::testing::Test {};
TYPED_TEST_SUITE(primitives, all_models);

template <class M, class T = hmira::default_traits<M>>
typename T::vertex_handle at(const M& m, double x, double y) {
    for (auto v : T::vertices(m))
        if (key_of<M, T>(m, v) == point_key{x, y, 0}) return v;
    ADD_FAILURE() << "no vertex at " << x << ", " << y;
    return typename T::vertex_handle();
}

template <class M>
::testing::AssertionResult same_mesh(M a, M b) {
    compact(a);
    compact(b);
    if (canonical<M>(a) == canonical<M>(b)) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "the canonical forms differ";
}

void expect_report(const hmira::removal_report& r, std::size_t faces, std::size_t edges, std::size_t vertices) {
    EXPECT_EQ(r.faces, faces);
    EXPECT_EQ(r.edges, edges);
    EXPECT_EQ(r.vertices, vertices);
}

TYPED_TEST(primitives, add_vertex_adds_one_isolated_vertex) {
    HMIRA_REQUIRE_EULER(TypeParam)
    else {
        using T = hmira::default_traits<TypeParam>;
        auto m = mesh_from<TypeParam>(grid(3, 3));
        const auto n = T::vertex_count(m);
        const auto v = hmira::add_vertex(m, {9, 9, 9});
        EXPECT_EQ(T::vertex_count(m), n + 1);
        EXPECT_EQ(T::vertex_halfedge(m, v), T::null_halfedge());
        EXPECT_TRUE(is_valid_relaxed(m));
    }
}

TYPED_TEST(primitives, remove_vertex_takes_its_faces_and_the_edges_and_vertices_they_leave_bare) {
    HMIRA_REQUIRE_EULER(TypeParam)
    else {
        using T = hmira::default_traits<TypeParam>;
        auto m = mesh_from<TypeParam>(grid(3, 3));
        // (1,1): its 4 faces go; its 4 edges; the 4 boundary edges of the corner faces at
        // (0,0)-(1,0)-(2,0) and (0,0)-(0,1)-(0,2); and (0,0), (1,0), (0,1) left with no edge.
        auto r = hmira::remove_vertex(m, at(m, 1, 1));
        ASSERT_TRUE(r) << r.error().message;
        expect_report(*r, 4, 8, 4);
        EXPECT_EQ(T::face_count(m), 5u);
        EXPECT_EQ(T::vertex_count(m), 12u);
        EXPECT_TRUE(hmira_test::is_valid(m));
        EXPECT_TRUE(euler_poincare_holds(m, 1));
    }
}

TYPED_TEST(primitives, remove_vertex_can_keep_what_the_faces_leave_bare) {
    HMIRA_REQUIRE_EULER(TypeParam)
    else {
        auto m = mesh_from<TypeParam>(grid(3, 3));
        auto r = hmira::remove_vertex(m, at(m, 1, 1), {.remove_wire_edges = false, .remove_isolated_vertices = false});
        ASSERT_TRUE(r) << r.error().message;
        expect_report(*r, 4, 4, 1);
        EXPECT_TRUE(is_valid_relaxed(m));
        EXPECT_TRUE(euler_poincare_holds(m, 1));
    }
}

TYPED_TEST(primitives, remove_edge_takes_its_two_faces) {
    HMIRA_REQUIRE_EULER(TypeParam)
    else {
        using T = hmira::default_traits<TypeParam>;
        auto m = mesh_from<TypeParam>(grid(3, 3));
        // The interior edge (1,1)-(2,1) between faces (1,0) and (1,1): both faces go, the edge
        // too, and the boundary side (1,0)-(2,0) of face (1,0), left with no face; every other
        // side still has a face and every vertex an edge.
        auto r = hmira::remove_edge(m, find_halfedge(m, at(m, 1, 1), at(m, 2, 1)));
        ASSERT_TRUE(r) << r.error().message;
        expect_report(*r, 2, 2, 0);
        EXPECT_EQ(T::face_count(m), 7u);
        EXPECT_TRUE(hmira_test::is_valid(m));
        EXPECT_TRUE(euler_poincare_holds(m, 1));
    }
}

TYPED_TEST(primitives, remove_face_then_add_face_restores_mesh) {
    HMIRA_REQUIRE_EULER(TypeParam)
    else {
        using T = hmira::default_traits<TypeParam>;
        auto m = mesh_from<TypeParam>(grid(3, 3));
        const auto start = m;
        const auto h = find_halfedge(m, at(m, 1, 1), at(m, 2, 1));
        auto r = hmira::remove_face(m, T::face(m, h));
        ASSERT_TRUE(r) << r.error().message;
        expect_report(*r, 1, 0, 0);  // an interior face: every side keeps its other face
        EXPECT_TRUE(hmira_test::is_valid(m));
        EXPECT_TRUE(euler_poincare_holds(m, 1));
        const std::array corners{at(m, 1, 1), at(m, 2, 1), at(m, 2, 2), at(m, 1, 2)};
        auto f = hmira::add_face(m, std::span<const typename T::vertex_handle>(corners));
        ASSERT_TRUE(f) << f.error().message;
        EXPECT_TRUE(hmira_test::is_valid(m));
        EXPECT_TRUE(same_mesh(m, start));
    }
}

TYPED_TEST(primitives, remove_corner_face_takes_its_bare_edges_and_vertex) {
    HMIRA_REQUIRE_EULER(TypeParam)
    else {
        using T = hmira::default_traits<TypeParam>;
        auto m = mesh_from<TypeParam>(grid(3, 3));
        const auto h = find_halfedge(m, at(m, 0, 0), at(m, 1, 0));
        auto r = hmira::remove_face(m, T::face(m, h));
        ASSERT_TRUE(r) << r.error().message;
        expect_report(*r, 1, 2, 1);
        EXPECT_TRUE(hmira_test::is_valid(m));
        EXPECT_TRUE(euler_poincare_holds(m, 1));
    }
}

TYPED_TEST(primitives, add_edge_then_remove_edge_restores_mesh) {
    HMIRA_REQUIRE_EULER(TypeParam)
    else {
        using T = hmira::default_traits<TypeParam>;
        auto m = mesh_from<TypeParam>(grid(3, 3));
        const auto start = m;
        // Two boundary vertices: the wire splits the boundary loop in two.
        auto e = hmira::add_edge(m, at(m, 0, 0), at(m, 3, 3));
        ASSERT_TRUE(e) << e.error().message;
        EXPECT_TRUE(is_valid_relaxed(m));
        EXPECT_TRUE(euler_poincare_holds(m, 1));
        EXPECT_EQ(count_euler(m).boundary_loops, 2);
        EXPECT_EQ(T::target(m, *e), at(m, 3, 3));
        auto r = hmira::remove_edge(m, *e);
        ASSERT_TRUE(r) << r.error().message;
        expect_report(*r, 0, 1, 0);
        EXPECT_TRUE(hmira_test::is_valid(m));
        EXPECT_TRUE(same_mesh(m, start));
        // Between a boundary vertex and a new isolated one, and between two isolated ones.
        const auto v = hmira::add_vertex(m, {5, 5, 0}), w = hmira::add_vertex(m, {6, 5, 0});
        ASSERT_TRUE(hmira::add_edge(m, at(m, 3, 0), v));
        ASSERT_TRUE(hmira::add_edge(m, w, hmira::add_vertex(m, {7, 5, 0})));
        EXPECT_TRUE(is_valid_relaxed(m));
        EXPECT_TRUE(euler_poincare_holds(m, 2));
    }
}

TYPED_TEST(primitives, add_edge_with_bad_ends_fails_and_changes_nothing) {
    HMIRA_REQUIRE_EULER(TypeParam)
    else {
        auto m = mesh_from<TypeParam>(grid(3, 3));
        const auto before = take_snapshot(m);
        auto interior = hmira::add_edge(m, at(m, 1, 1), at(m, 0, 0));
        ASSERT_FALSE(interior);
        EXPECT_NE(interior.error().message.find("interior"), std::string::npos);
        auto existing = hmira::add_edge(m, at(m, 0, 0), at(m, 1, 0));
        ASSERT_FALSE(existing);
        EXPECT_NE(existing.error().message.find("joined already"), std::string::npos);
        EXPECT_FALSE(hmira::add_edge(m, at(m, 0, 0), at(m, 0, 0)));
        EXPECT_TRUE(take_snapshot(m) == before);
    }
}

}  // namespace
