// Each Euler operator against its inverse on every model that supports it: the pair restores
// the mesh (same connectivity up to relabelling, same positions), every state in between is
// valid and satisfies Euler-Poincare, and an operator whose precondition fails names the
// reason and leaves the mesh exactly as it was.

#include <gtest/gtest.h>

#include <string>

#include <hmira/algorithms/euler/euler.hpp>

#include "algorithms/euler/euler_support.hpp"
#include "support/models.hpp"

namespace {

using namespace hmira_test;

template <class M>
class euler_operators : public ::testing::Test {};
TYPED_TEST_SUITE(euler_operators, all_models);

/// A 3 x 3 grid of quads (S = 1, H = 0, one boundary loop).
template <class M>
M grid_mesh() {
    return mesh_from<M>(grid(3, 3));
}

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

/// Compacts both and compares their canonical forms.
template <class M>
::testing::AssertionResult same_mesh(M a, M b) {
    compact(a);
    compact(b);
    if (canonical<M>(a) == canonical<M>(b)) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "the canonical forms differ";
}

/// The result failed with `code` and a message containing `words`.
template <class R>
::testing::AssertionResult failed_with(const R& r, hmira::errc code, const std::string& words) {
    if (r) return ::testing::AssertionFailure() << "the operator succeeded";
    if (r.error().code != code) return ::testing::AssertionFailure() << "wrong code; message: " << r.error().message;
    if (r.error().message.find(words) == std::string::npos)
        return ::testing::AssertionFailure()
               << "message \"" << r.error().message << "\" does not say \"" << words << "\"";
    return ::testing::AssertionSuccess();
}

TYPED_TEST(euler_operators, make_vertex_then_kill_restores_mesh) {
    HMIRA_REQUIRE_EULER(TypeParam)
    else {
        auto m = grid_mesh<TypeParam>();
        const auto start = m;
        const auto r = hmira::make_vertex(m, {7, 7, 7});
        EXPECT_TRUE(is_valid_relaxed(m));
        EXPECT_TRUE(euler_poincare_holds(m, 2));  // a second shell
        ASSERT_TRUE(hmira::kill_vertex(m, r.vertex));
        EXPECT_TRUE(euler_poincare_holds(m, 1));
        EXPECT_TRUE(hmira_test::is_valid(m));
        EXPECT_TRUE(same_mesh(m, start));
    }
}

TYPED_TEST(euler_operators, kill_vertex_with_edges_fails_and_changes_nothing) {
    HMIRA_REQUIRE_EULER(TypeParam)
    else {
        auto m = grid_mesh<TypeParam>();
        const auto before = take_snapshot(m);
        EXPECT_TRUE(failed_with(hmira::kill_vertex(m, vertex_at(m, 1, 1)), hmira::errc::topology, "still has edges"));
        EXPECT_TRUE(take_snapshot(m) == before);
    }
}

TYPED_TEST(euler_operators, make_edge_vertex_then_kill_restores_mesh_in_a_face_and_on_the_boundary) {
    HMIRA_REQUIRE_EULER(TypeParam)
    else {
        using T = hmira::default_traits<TypeParam>;
        auto m = grid_mesh<TypeParam>();
        const auto start = m;
        // Into the corner of the face at (1,1)-(2,2) at vertex (1,1), and into the boundary at (0,0).
        for (auto corner : {halfedge_at(m, {1, 2}, {1, 1}), halfedge_at(m, {1, 0}, {0, 0})}) {
            const auto face = T::face(m, corner);
            auto r = hmira::make_edge_vertex(m, corner, {0.25, 0.5, 1});
            ASSERT_TRUE(r) << r.error().message;
            EXPECT_TRUE(is_valid_relaxed(m));
            EXPECT_TRUE(euler_poincare_holds(m, 1));
            EXPECT_EQ(T::face(m, r->halfedge), face);
            EXPECT_EQ(T::next(m, r->halfedge), T::opposite(m, r->halfedge));
            EXPECT_EQ(T::next(m, corner), r->halfedge);
            auto k = hmira::kill_edge_vertex(m, r->halfedge);
            ASSERT_TRUE(k) << k.error().message;
            EXPECT_EQ(k->corner, corner);
            EXPECT_TRUE(hmira_test::is_valid(m));
            EXPECT_TRUE(same_mesh(m, start));
        }
    }
}

TYPED_TEST(euler_operators, make_edge_vertex_grows_a_wire_from_an_isolated_vertex_and_kill_returns_it) {
    HMIRA_REQUIRE_EULER(TypeParam)
    else {
        using T = hmira::default_traits<TypeParam>;
        TypeParam m;
        const auto v = hmira::make_vertex(m, {0, 0, 0}).vertex;
        auto r = hmira::make_edge_vertex(m, v, {1, 0, 0});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(is_valid_relaxed(m));
        EXPECT_TRUE(euler_poincare_holds(m, 1));
        EXPECT_TRUE(failed_with(hmira::make_edge_vertex(m, v, {2, 0, 0}), hmira::errc::topology, "pass the corner"));
        auto k = hmira::kill_edge_vertex(m, r->halfedge);
        ASSERT_TRUE(k) << k.error().message;
        EXPECT_EQ(k->corner, T::null_halfedge());
        EXPECT_EQ(T::vertex_halfedge(m, v), T::null_halfedge());
        EXPECT_TRUE(euler_poincare_holds(m, 1));
        EXPECT_EQ(T::vertex_count(m), 1u);
    }
}

TYPED_TEST(euler_operators, kill_edge_vertex_on_a_vertex_of_degree_two_fails_and_changes_nothing) {
    HMIRA_REQUIRE_EULER(TypeParam)
    else {
        auto m = grid_mesh<TypeParam>();
        const auto before = take_snapshot(m);
        // (0,0) is a corner of the grid: degree 2.
        EXPECT_TRUE(failed_with(hmira::kill_edge_vertex(m, halfedge_at(m, {1, 0}, {0, 0})), hmira::errc::topology,
                                "degree 2 or more"));
        EXPECT_TRUE(
            failed_with(hmira::kill_edge_vertex(m, typename hmira::default_traits<TypeParam>::halfedge_handle{}),
                        hmira::errc::invalid_handle, "does not exist"));
        EXPECT_TRUE(take_snapshot(m) == before);
    }
}

TYPED_TEST(euler_operators, make_edge_face_then_kill_restores_mesh) {
    HMIRA_REQUIRE_EULER(TypeParam)
    else {
        using T = hmira::default_traits<TypeParam>;
        auto m = grid_mesh<TypeParam>();
        const auto start = m;
        // Split the quad (1,1) (2,1) (2,2) (1,2) along (1,1)-(2,2).
        const auto h0 = halfedge_at(m, {1, 2}, {1, 1}), h1 = halfedge_at(m, {2, 1}, {2, 2});
        const auto old_face = T::face(m, h0);
        auto r = hmira::make_edge_face(m, h0, h1);
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(hmira_test::is_valid(m));
        EXPECT_TRUE(euler_poincare_holds(m, 1));
        EXPECT_EQ(T::face_count(m), 10u);
        EXPECT_EQ(T::face(m, r->halfedge), old_face);
        EXPECT_EQ(T::face(m, h1), r->face);
        EXPECT_EQ(T::face(m, T::opposite(m, r->halfedge)), r->face);
        EXPECT_EQ(std::ranges::distance(T::face_vertices(m, r->face)), 3);
        EXPECT_EQ(std::ranges::distance(T::face_vertices(m, old_face)), 3);
        auto k = hmira::kill_edge_face(m, r->halfedge);
        ASSERT_TRUE(k) << k.error().message;
        EXPECT_EQ(k->face, old_face);
        EXPECT_TRUE(hmira_test::is_valid(m));
        EXPECT_TRUE(same_mesh(m, start));
        // And the corners it returns make the same split again.
        auto again = hmira::make_edge_face(m, k->h0, k->h1);
        ASSERT_TRUE(again) << again.error().message;
        EXPECT_TRUE(same_mesh(m, [&] {
            auto s = start;
            (void)hmira::make_edge_face(s, halfedge_at(s, {1, 2}, {1, 1}), halfedge_at(s, {2, 1}, {2, 2}));
            return s;
        }()));
    }
}

TYPED_TEST(euler_operators, kill_edge_face_then_make_restores_mesh_on_a_closed_surface) {
    HMIRA_REQUIRE_EULER(TypeParam)
    else {
        auto m = mesh_from<TypeParam>(torus(6, 4));
        const auto start = m;
        using T = hmira::default_traits<TypeParam>;
        for (auto h : T::halfedges(start)) {
            auto k = hmira::kill_edge_face(m, h);
            ASSERT_TRUE(k) << k.error().message;
            EXPECT_TRUE(hmira_test::is_valid(m));
            EXPECT_TRUE(euler_poincare_holds(m, 0));  // S - H = 1 - 1
            auto r = hmira::make_edge_face(m, k->h0, k->h1);
            ASSERT_TRUE(r) << r.error().message;
            EXPECT_TRUE(same_mesh(m, start));
            break;
        }
    }
}

TYPED_TEST(euler_operators, make_edge_face_closes_a_boundary_loop_and_kill_reopens_it) {
    HMIRA_REQUIRE_EULER(TypeParam)
    else {
        using T = hmira::default_traits<TypeParam>;
        auto m = grid_mesh<TypeParam>();
        const auto start = m;
        // Fold a triangle over the boundary corner at (0,0): the boundary runs
        // (2,0)->(1,0)->(0,0)->(0,1); the new face (1,0) (0,0) (0,1) contains h1.
        const auto h0 = halfedge_at(m, {2, 0}, {1, 0}), h1 = halfedge_at(m, {0, 0}, {0, 1});
        ASSERT_EQ(T::face(m, h0), T::null_face());
        ASSERT_EQ(T::face(m, h1), T::null_face());
        auto r = hmira::make_edge_face(m, h0, h1);
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(hmira_test::is_valid(m));
        EXPECT_TRUE(euler_poincare_holds(m, 1));
        EXPECT_EQ(T::face(m, r->halfedge), T::null_face());
        EXPECT_EQ(std::ranges::distance(T::face_vertices(m, r->face)), 3);
        auto k = hmira::kill_edge_face(m, r->halfedge);
        ASSERT_TRUE(k) << k.error().message;
        EXPECT_EQ(k->face, T::null_face());
        EXPECT_TRUE(hmira_test::is_valid(m));
        EXPECT_TRUE(same_mesh(m, start));
    }
}

TYPED_TEST(euler_operators, make_edge_face_with_bad_corners_fails_and_changes_nothing) {
    HMIRA_REQUIRE_EULER(TypeParam)
    else {
        auto m = grid_mesh<TypeParam>();
        const auto before = take_snapshot(m);
        // Corners of two different faces.
        EXPECT_TRUE(
            failed_with(hmira::make_edge_face(m, halfedge_at(m, {1, 2}, {1, 1}), halfedge_at(m, {3, 2}, {3, 3})),
                        hmira::errc::topology, "different faces"));
        // Both corners at one vertex: a loop edge.
        const auto h = halfedge_at(m, {1, 2}, {1, 1});
        EXPECT_TRUE(failed_with(hmira::make_edge_face(m, h, h), hmira::errc::topology, "would be a loop"));
        EXPECT_TRUE(take_snapshot(m) == before);
    }
}

TYPED_TEST(euler_operators, kill_edge_face_on_a_boundary_or_bridge_edge_fails_and_changes_nothing) {
    HMIRA_REQUIRE_EULER(TypeParam)
    else {
        using T = hmira::default_traits<TypeParam>;
        auto m = grid_mesh<TypeParam>();
        // A bridge: a wire from (1,1) into the face (1,1)-(2,2), then a second edge back would
        // make a face; a strut's edge has the same face on both sides.
        auto strut = hmira::make_edge_vertex(m, halfedge_at(m, {1, 2}, {1, 1}), {1.5, 1.5, 0});
        ASSERT_TRUE(strut);
        const auto before = take_snapshot(m);
        EXPECT_TRUE(failed_with(hmira::kill_edge_face(m, strut->halfedge), hmira::errc::topology, "bridge"));
        // The boundary side of a boundary edge has no face to kill.
        const auto inner = halfedge_at(m, {0, 0}, {1, 0});
        const auto outer = T::face(m, inner) == T::null_face() ? T::opposite(m, inner) : inner;
        EXPECT_TRUE(failed_with(hmira::kill_edge_face(m, outer), hmira::errc::topology, "no face on its other side"));
        EXPECT_TRUE(take_snapshot(m) == before);
    }
}

TYPED_TEST(euler_operators, fill_boundary_loop_then_open_restores_mesh) {
    HMIRA_REQUIRE_EULER(TypeParam)
    else {
        using T = hmira::default_traits<TypeParam>;
        auto m = grid_mesh<TypeParam>();
        const auto start = m;
        auto h = halfedge_at(m, {0, 0}, {1, 0});
        if (T::face(m, h) != T::null_face()) h = T::opposite(m, h);
        auto r = hmira::fill_boundary_loop(m, h);
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(hmira_test::is_valid(m));  // a closed disc-plus-disc: a sphere
        EXPECT_TRUE(euler_poincare_holds(m, 1));
        EXPECT_EQ(std::ranges::distance(T::face_vertices(m, r->face)), 12);
        const auto before = take_snapshot(m);
        EXPECT_TRUE(failed_with(hmira::fill_boundary_loop(m, h), hmira::errc::topology, "not on a boundary loop"));
        EXPECT_TRUE(take_snapshot(m) == before);
        ASSERT_TRUE(hmira::open_face(m, r->face));
        EXPECT_TRUE(hmira_test::is_valid(m));
        EXPECT_TRUE(same_mesh(m, start));
    }
}

// ----- ring operators: only where faces hold inner rings ----------------------------------------

template <class M>
class euler_ring_operators : public ::testing::Test {};
TYPED_TEST_SUITE(euler_ring_operators, all_models);

#define HMIRA_REQUIRE_RINGS(M)                                                        \
    if constexpr (!hmira::euler_ring_mutable_mesh<M> || !indexed_halfedge_model<M>) { \
        GTEST_SKIP() << "not an euler_ring_mutable_mesh (no inner rings)";            \
        return;                                                                       \
    }

TYPED_TEST(euler_ring_operators, kill_face_make_ring_then_make_face_restores_mesh) {
    HMIRA_REQUIRE_RINGS(TypeParam)
    else {
        using T = hmira::default_traits<TypeParam>;
        auto m = mesh_from<TypeParam>(torus(6, 4));
        const auto start = m;
        const auto h = *T::halfedges(m).begin();
        const auto f = T::face(m, h), host = T::face(m, T::opposite(m, h));
        auto r = hmira::kill_face_make_ring(m, f, host);
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(is_valid_relaxed(m));
        EXPECT_TRUE(euler_poincare_holds(m, -1));  // S - H drops by one
        EXPECT_EQ(std::ranges::distance(T::inner_rings(m, host)), 1);
        const auto before = take_snapshot(m);
        EXPECT_TRUE(failed_with(hmira::kill_face_make_ring(m, host, host), hmira::errc::topology, "ring of itself"));
        EXPECT_TRUE(
            failed_with(hmira::make_face_kill_ring(m, T::face_halfedge(m, host)), hmira::errc::topology, "outer loop"));
        EXPECT_TRUE(take_snapshot(m) == before);
        auto back = hmira::make_face_kill_ring(m, r->ring);
        ASSERT_TRUE(back) << back.error().message;
        EXPECT_EQ(back->host, host);
        EXPECT_TRUE(hmira_test::is_valid(m));
        EXPECT_TRUE(same_mesh(m, start));
    }
}

TYPED_TEST(euler_ring_operators, make_edge_kill_ring_then_kill_restores_mesh) {
    HMIRA_REQUIRE_RINGS(TypeParam)
    else {
        using T = hmira::default_traits<TypeParam>;
        // A 5 x 5 grid whose middle face becomes a ring of the face below it... of a distant face
        // would be odd geometry; topology does not care: use the face left of it.
        auto m = mesh_from<TypeParam>(grid(5, 5));
        const auto mid = T::face(m, halfedge_at(m, {2, 2}, {3, 2}));
        const auto host = T::face(m, halfedge_at(m, {2, 2}, {2, 3}));
        ASSERT_NE(mid, host);
        auto ring = hmira::kill_face_make_ring(m, mid, host);
        ASSERT_TRUE(ring) << ring.error().message;
        const auto start = m;
        // Join the ring corner at (3,3) to the host's outer corner at (1,3).
        const auto h0 = halfedge_at(m, {2, 3}, {1, 3});
        const auto h1 = halfedge_at(m, {3, 2}, {3, 3});
        ASSERT_EQ(T::face(m, h0), host);
        ASSERT_EQ(T::face(m, h1), host);
        const auto before = take_snapshot(m);
        EXPECT_TRUE(failed_with(hmira::make_edge_face(m, h0, h1), hmira::errc::topology, "different loops"));
        EXPECT_TRUE(failed_with(hmira::make_edge_kill_ring(m, h0, T::prev(m, h0)), hmira::errc::topology, "one loop"));
        EXPECT_TRUE(take_snapshot(m) == before);
        auto r = hmira::make_edge_kill_ring(m, h0, h1);
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(is_valid_relaxed(m));
        EXPECT_TRUE(euler_poincare_holds(m, 0));
        EXPECT_EQ(std::ranges::distance(T::inner_rings(m, host)), 0);
        const auto merged = take_snapshot(m);
        EXPECT_TRUE(failed_with(hmira::kill_edge_make_ring(m, halfedge_at(m, {1, 3}, {2, 3})), hmira::errc::topology,
                                "use kill_edge_face"));
        EXPECT_TRUE(take_snapshot(m) == merged);
        auto k = hmira::kill_edge_make_ring(m, r->halfedge);
        ASSERT_TRUE(k) << k.error().message;
        EXPECT_TRUE(is_valid_relaxed(m));
        EXPECT_TRUE(same_mesh(m, start));
        // The reverse direction makes the outer part the ring: the outer loop must stay outer.
        auto r2 = hmira::make_edge_kill_ring(m, k->h0, k->h1);
        ASSERT_TRUE(r2);
        auto k2 = hmira::kill_edge_make_ring(m, T::opposite(m, r2->halfedge));
        ASSERT_TRUE(k2) << k2.error().message;
        EXPECT_TRUE(is_valid_relaxed(m));
        EXPECT_EQ(std::ranges::distance(T::inner_rings(m, host)), 1);
        EXPECT_EQ(std::ranges::distance(T::face_vertices(m, host)), 4);  // the ring's square is outer now
    }
}

TYPED_TEST(euler_ring_operators, kill_edge_make_ring_on_a_strut_fails_and_changes_nothing) {
    HMIRA_REQUIRE_RINGS(TypeParam)
    else {
        auto m = grid_mesh<TypeParam>();
        auto strut = hmira::make_edge_vertex(m, halfedge_at(m, {1, 2}, {1, 1}), {1.5, 1.5, 0});
        ASSERT_TRUE(strut);
        const auto before = take_snapshot(m);
        EXPECT_TRUE(failed_with(hmira::kill_edge_make_ring(m, strut->halfedge), hmira::errc::topology, "degree 1"));
        EXPECT_TRUE(take_snapshot(m) == before);
    }
}

}  // namespace
