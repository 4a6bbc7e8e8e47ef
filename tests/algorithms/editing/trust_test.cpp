// Handles and links an edit cannot trust: a deleted vertex, edge or
// face is refused with errc::invalid_handle by the edits and the operators on every model
// that can tell (hmira's meshes, OpenMesh's status bits, CGAL's is_removed), and a vertex whose
// rotation is corrupt (a cycle that misses its start, a step that leaves the vertex) is
// refused with an error naming it, instead of being edited from a wrong rotation. The mesh is
// unchanged after every refusal.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <hmira/algorithms/editing/detail/editing_common.hpp>
#include <hmira/algorithms/primitives/primitives.hpp>

#include "algorithms/editing/editing_support.hpp"
#include "support/snapshot.hpp"

namespace {

template <class M>
struct trust_test : ::testing::Test {};
TYPED_TEST_SUITE(trust_test, hmira_test::all_models);

#define HMIRA_REQUIRE_EDITING(M)                                                        \
    if constexpr (!hmira::extrudable_mesh<M>) {                                         \
        GTEST_SKIP() << "not an editable model (no Euler operators or triangles only)"; \
        return;                                                                         \
    }

template <class R>
::testing::AssertionResult refused_as_invalid_handle(const R& r) {
    if (r) return ::testing::AssertionFailure() << "accepted";
    if (r.error().code != hmira::errc::invalid_handle)
        return ::testing::AssertionFailure() << "refused with another code: " << r.error().message;
    if (r.error().message.find("does not exist") == std::string::npos)
        return ::testing::AssertionFailure() << "the message does not say the element is gone: " << r.error().message;
    return ::testing::AssertionSuccess();
}

/// A 2x2x1 box with one vertex, one edge and one face deleted by Euler operators: a spike
/// grown and killed again (its vertex and edge go), and killEF on an edge between two faces
/// (the face on the other side of the halfedge goes; the halfedge's own face stays).
template <class M, class T = hmira::default_traits<M>>
struct box_with_dead_elements {
    M m;
    typename T::vertex_handle vertex{};
    typename T::halfedge_handle halfedge{};
    typename T::edge_handle edge{};
    typename T::face_handle face{}, survivor{};

    box_with_dead_elements() {
        EXPECT_TRUE(hmira_test::add_face_list(m, hmira_test::lattice_box(2, 2, 1)));
        const auto corner = T::face_halfedge(m, *T::faces(m).begin());
        const auto spike = hmira::make_edge_vertex<M, T>(m, corner, {0.5, 0.5, 3});
        EXPECT_TRUE(spike);
        vertex = spike.value().vertex;
        halfedge = spike.value().halfedge;
        edge = T::edge(m, halfedge);
        EXPECT_TRUE((hmira::kill_edge_vertex<M, T>(m, halfedge)));
        // An edge inside the bottom: both sides are faces of the 2x2 grid.
        for (auto h : T::halfedges(m))
            if (T::face(m, h) != T::null_face() && T::face(m, T::opposite(m, h)) != T::null_face()) {
                survivor = T::face(m, h);
                face = T::face(m, T::opposite(m, h));
                EXPECT_TRUE((hmira::kill_edge_face<M, T>(m, h)));
                break;
            }
        EXPECT_TRUE((hmira_test::is_valid<M, T>(m)));
    }
};

TYPED_TEST(trust_test, a_deleted_vertex_is_refused_by_every_edit_and_operator) {
    using M = TypeParam;
    HMIRA_REQUIRE_EDITING(M)
    else {
        using T = hmira::default_traits<M>;
        box_with_dead_elements<M> b;
        auto& m = b.m;
        ASSERT_TRUE((T::is_removed(m, b.vertex)));
        const auto before = hmira_test::snapshot<M, T>(m);
        const typename T::vertex_handle vs[] = {b.vertex};
        EXPECT_TRUE(refused_as_invalid_handle(hmira::truncate<M, T>(m, vs)));
        EXPECT_TRUE(refused_as_invalid_handle(hmira::truncate<M, T>(m, b.vertex)));
        EXPECT_TRUE(refused_as_invalid_handle(hmira::make_edge_vertex<M, T>(m, b.vertex, {0, 0, 0})));
        EXPECT_TRUE(refused_as_invalid_handle(hmira::remove_vertex<M, T>(m, b.vertex)));
        const auto alive = *T::vertices(m).begin();
        EXPECT_TRUE(refused_as_invalid_handle(hmira::add_edge<M, T>(m, b.vertex, alive)));
        EXPECT_TRUE(refused_as_invalid_handle(hmira::add_edge<M, T>(m, alive, b.vertex)));
        EXPECT_TRUE((hmira_test::snapshot<M, T>(m) == before));
        EXPECT_TRUE((hmira_test::is_valid<M, T>(m)));
    }
}

TYPED_TEST(trust_test, a_deleted_edge_is_refused_by_every_edit_and_operator) {
    using M = TypeParam;
    HMIRA_REQUIRE_EDITING(M)
    else {
        using T = hmira::default_traits<M>;
        box_with_dead_elements<M> b;
        auto& m = b.m;
        ASSERT_TRUE((T::is_removed(m, b.edge)));
        const auto before = hmira_test::snapshot<M, T>(m);
        const typename T::edge_handle es[] = {b.edge};
        EXPECT_TRUE(refused_as_invalid_handle(hmira::bevel<M, T>(m, es)));
        EXPECT_TRUE(refused_as_invalid_handle(hmira::bevel<M, T>(m, b.edge)));
        EXPECT_TRUE(refused_as_invalid_handle(hmira::kill_edge_vertex<M, T>(m, b.halfedge)));
        EXPECT_TRUE(refused_as_invalid_handle(hmira::make_edge_vertex<M, T>(m, b.halfedge, {0, 0, 0})));
        EXPECT_TRUE(refused_as_invalid_handle(hmira::kill_edge_face<M, T>(m, b.halfedge)));
        const auto alive = T::face_halfedge(m, b.survivor);
        EXPECT_TRUE(refused_as_invalid_handle(hmira::make_edge_face<M, T>(m, b.halfedge, alive)));
        EXPECT_TRUE(refused_as_invalid_handle(hmira::make_edge_face<M, T>(m, alive, b.halfedge)));
        EXPECT_TRUE(refused_as_invalid_handle(hmira::remove_edge<M, T>(m, b.halfedge)));
        EXPECT_TRUE((hmira_test::snapshot<M, T>(m) == before));
        EXPECT_TRUE((hmira_test::is_valid<M, T>(m)));
    }
}

TYPED_TEST(trust_test, a_deleted_face_is_refused_by_every_edit_and_operator) {
    using M = TypeParam;
    HMIRA_REQUIRE_EDITING(M)
    else {
        using T = hmira::default_traits<M>;
        box_with_dead_elements<M> b;
        auto& m = b.m;
        ASSERT_TRUE((T::is_removed(m, b.face)));
        ASSERT_FALSE((T::is_removed(m, b.survivor)));
        const auto before = hmira_test::snapshot<M, T>(m);
        EXPECT_TRUE(refused_as_invalid_handle(hmira::extrude<M, T>(m, b.face, {.distance = 1})));
        const typename T::face_handle fs[] = {b.survivor, b.face};
        EXPECT_TRUE(refused_as_invalid_handle(hmira::extrude<M, T>(m, fs, {.distance = 1})));
        EXPECT_TRUE(refused_as_invalid_handle(
            hmira::extrude<M, T>(m, fs, {.distance = 1, .mode = hmira::extrude_mode::individual})));
        EXPECT_TRUE(refused_as_invalid_handle(hmira::remove_face<M, T>(m, b.face)));
        if constexpr (hmira::euler_ring_mutable_mesh<M, T>) {
            EXPECT_TRUE(refused_as_invalid_handle(hmira::kill_face_make_ring<M, T>(m, b.face, b.survivor)));
            EXPECT_TRUE(refused_as_invalid_handle(hmira::kill_face_make_ring<M, T>(m, b.survivor, b.face)));
        }
        EXPECT_TRUE((hmira_test::snapshot<M, T>(m) == before));
        EXPECT_TRUE((hmira_test::is_valid<M, T>(m)));
        // The survivor is still editable: the refusal was about the handle, not the mesh.
        EXPECT_TRUE((hmira::extrude<M, T>(m, b.survivor, {.distance = 1})));
        EXPECT_TRUE((hmira_test::is_valid<M, T>(m)));
    }
}

TEST(trust_face_vertex, deleted_vertices_and_faces_are_refused_by_the_primitives) {
    using M = hmira::face_vertex_mesh;
    using T = hmira::default_traits<M>;
    M m;
    ASSERT_TRUE(hmira_test::add_face_list(m, hmira_test::grid(2, 2)));
    const auto f = *m.faces().begin();
    ASSERT_TRUE((hmira::remove_face<M, T>(m, f, {.remove_isolated_vertices = false})));
    const auto v = *m.vertices().begin();
    ASSERT_TRUE((hmira::remove_vertex<M, T>(m, v)));
    EXPECT_TRUE(T::is_removed(m, f));
    EXPECT_TRUE(T::is_removed(m, v));
    const auto before = hmira_test::snapshot<M, T>(m);
    EXPECT_TRUE(refused_as_invalid_handle(hmira::remove_face<M, T>(m, f)));
    EXPECT_TRUE(refused_as_invalid_handle(hmira::remove_vertex<M, T>(m, v)));
    EXPECT_TRUE((hmira_test::snapshot<M, T>(m) == before));
}

// ----- corrupt rotations ---------------------------------------------------------------------

/// A vertex of the bottom of a 2x2x1 box that is interior to the bottom grid (degree 4), and
/// its rotation, read before any corruption.
template <class M, class T = hmira::default_traits<M>>
std::vector<typename T::halfedge_handle> rotation_of(const M& m, typename T::vertex_handle v) {
    std::vector<typename T::halfedge_handle> out;
    auto h = T::vertex_halfedge(m, v);
    do {
        out.push_back(h);
        h = T::next(m, T::opposite(m, h));
    } while (h != T::vertex_halfedge(m, v) && out.size() < 64);
    return out;
}

template <class M, class T = hmira::default_traits<M>>
typename T::vertex_handle centre_of_bottom(const M& m) {
    for (auto v : T::vertices(m)) {
        const auto p = T::position(m, v);
        if (double(p[0]) == 1 && double(p[1]) == 1 && double(p[2]) == 0) return v;
    }
    ADD_FAILURE() << "no vertex at (1, 1, 0)";
    return *T::vertices(m).begin();
}

TYPED_TEST(trust_test, a_rotation_that_never_returns_to_its_start_is_an_error_not_a_wrong_answer) {
    using M = TypeParam;
    HMIRA_REQUIRE_EDITING(M)
    else {
        using T = hmira::default_traits<M>;
        M m;
        ASSERT_TRUE(hmira_test::add_face_list(m, hmira_test::lattice_box(2, 2, 1)));
        const auto v = centre_of_bottom<M, T>(m);
        const auto hs = rotation_of<M, T>(m, v);
        ASSERT_EQ(hs.size(), 4u);
        // next(opposite(h2)) := h1: the walk from h0 goes h0, h1, h2, h1, h2, ... and never
        // comes back to h0; every halfedge it meets still leaves v.
        T::set_next(m, T::opposite(m, hs[2]), hs[1]);
        const auto walk = hmira::detail::editing::checked_outgoing<M, T>(m, v, "test");
        ASSERT_FALSE(walk);
        EXPECT_EQ(walk.error().code, hmira::errc::topology);
        EXPECT_NE(walk.error().message.find("does not return"), std::string::npos) << walk.error().message;
        EXPECT_EQ(walk.error().element, (long long)T::vertex_index(m, v));

        const auto before = hmira_test::snapshot<M, T>(m, false);
        auto t = hmira::truncate<M, T>(m, v);
        ASSERT_FALSE(t);
        EXPECT_EQ(t.error().code, hmira::errc::topology);
        EXPECT_NE(t.error().message.find("truncate: the edges around vertex " + std::to_string(T::vertex_index(m, v)) +
                                         " are corrupt"),
                  std::string::npos)
            << t.error().message;
        auto b = hmira::bevel<M, T>(m, T::edge(m, hs[0]));
        ASSERT_FALSE(b);
        EXPECT_NE(b.error().message.find("corrupt"), std::string::npos) << b.error().message;
        EXPECT_TRUE((hmira_test::snapshot<M, T>(m, false) == before));
    }
}

TYPED_TEST(trust_test, a_rotation_step_that_leaves_the_vertex_is_an_error) {
    using M = TypeParam;
    HMIRA_REQUIRE_EDITING(M)
    else {
        using T = hmira::default_traits<M>;
        M m;
        ASSERT_TRUE(hmira_test::add_face_list(m, hmira_test::lattice_box(2, 2, 1)));
        const auto v = centre_of_bottom<M, T>(m);
        const auto hs = rotation_of<M, T>(m, v);
        ASSERT_EQ(hs.size(), 4u);
        // next(opposite(h0)) := opposite(h1), a halfedge into v rather than out of it.
        T::set_next(m, T::opposite(m, hs[0]), T::opposite(m, hs[1]));
        const auto walk = hmira::detail::editing::checked_outgoing<M, T>(m, v, "test");
        ASSERT_FALSE(walk);
        EXPECT_NE(walk.error().message.find("does not leave it"), std::string::npos) << walk.error().message;
        const auto before = hmira_test::snapshot<M, T>(m, false);
        const typename T::vertex_handle vs[] = {v};
        EXPECT_FALSE((hmira::truncate<M, T>(m, vs)));
        EXPECT_TRUE((hmira_test::snapshot<M, T>(m, false) == before));
    }
}

TYPED_TEST(trust_test, a_valid_rotation_of_any_degree_is_walked_whole) {
    using M = TypeParam;
    HMIRA_REQUIRE_EDITING(M)
    else {
        using T = hmira::default_traits<M>;
        // A fan of 300 triangles around one vertex: a degree far above any small guard.
        M m;
        hmira_test::face_list fan;
        fan.points.push_back({0, 0, 0});
        const int n = 300;
        for (int i = 0; i < n; ++i)
            fan.points.push_back({std::cos(2 * 3.14159265358979 * i / n), std::sin(2 * 3.14159265358979 * i / n), 0});
        for (int i = 0; i < n; ++i) fan.faces.push_back({0, std::size_t(1 + i), std::size_t(1 + (i + 1) % n)});
        ASSERT_TRUE(hmira_test::add_face_list(m, fan));
        const auto centre = *T::vertices(m).begin();
        const auto walk = hmira::detail::editing::checked_outgoing<M, T>(m, centre, "test");
        ASSERT_TRUE(walk) << walk.error().message;
        EXPECT_EQ(walk.value().size(), std::size_t(n));
        EXPECT_EQ((hmira::detail::editing::outgoing<M, T>(m, centre).size()), std::size_t(n));
        ASSERT_TRUE((hmira::truncate<M, T>(m, centre, {.fraction = 0.5})));
        EXPECT_TRUE((hmira_test::is_valid<M, T>(m)));
        EXPECT_EQ(T::face_count(m), std::size_t(n + 1));
    }
}

}  // namespace
