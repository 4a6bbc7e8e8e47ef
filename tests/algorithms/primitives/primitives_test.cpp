// The add/remove primitives of thesis 4.2 on every model that can honour each: what each
// creates or removes (counted by hand for 3 x 3 grids of quads and of triangles), validity
// afterwards, failed preconditions leaving the mesh unchanged, and add/remove pairs restoring
// the mesh. The triangle-grid suite also runs on face_vertex_mesh (removal through its traits)
// and OpenMesh's TriMesh (removing never makes a polygon).

#include <gtest/gtest.h>

#include <array>
#include <span>
#include <type_traits>
#include <utility>

#include <hmira/algorithms/primitives/primitives.hpp>

#include "algorithms/euler/euler_support.hpp"
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

// ---------------------------------------------------------------------------------------------
// The removals on every model that can honour them, on a 3 x 3 grid of triangles (each quad
// (i, j) split into (i,j)-(i+1,j)-(i+1,j+1) and (i,j)-(i+1,j+1)-(i,j+1)), so that OpenMesh's
// TriMesh and face_vertex_mesh take part.

static_assert(hmira::face_erasable_mesh<hmira::face_vertex_mesh> &&
              hmira::vertex_erasable_mesh<hmira::face_vertex_mesh>);
static_assert(!hmira::halfedge_mutable_mesh<hmira::face_vertex_mesh>, "face_vertex_mesh has no edges to add or remove");
#ifdef HMIRA_TEST_WITH_OPENMESH
static_assert(hmira::face_erasable_mesh<openmesh_tri> && hmira::vertex_erasable_mesh<openmesh_tri> &&
              hmira::halfedge_mutable_mesh<openmesh_tri>);
static_assert(!hmira::euler_mutable_mesh<openmesh_tri>, "TriMesh still cannot take the Euler operators");
#endif

/// Every live vertex (index, position) and face (index, corners by vertex index), with the
/// counts: equal snapshots mean the same live elements, connectivity and positions, on any
/// model with face -> vertex ranges (face_vertex_mesh included).
struct face_snapshot {
    std::vector<std::pair<std::size_t, std::array<double, 3>>> vertices;
    std::vector<std::pair<std::size_t, std::vector<std::size_t>>> faces;
    std::size_t vertex_count = 0, face_count = 0;
    bool operator==(const face_snapshot&) const = default;
};

template <class M, class T = hmira::default_traits<M>>
face_snapshot take_face_snapshot(const M& m) {
    face_snapshot s{{}, {}, T::vertex_count(m), T::face_count(m)};
    for (auto v : T::vertices(m)) {
        const auto p = T::position(m, v);
        s.vertices.push_back({T::vertex_index(m, v), {double(p[0]), double(p[1]), double(p[2])}});
    }
    for (auto f : T::faces(m)) {
        std::vector<std::size_t> loop;
        for (auto v : T::face_vertices(m, f)) loop.push_back(T::vertex_index(m, v));
        s.faces.push_back({T::face_index(m, f), loop});
    }
    return s;
}

/// A handle with index i (out of range when i >= the bound), for each model's handle type.
template <class H>
H handle_at(std::size_t i) {
    if constexpr (std::is_constructible_v<H, std::uint32_t>)
        return H(static_cast<std::uint32_t>(i));
    else
        return H(static_cast<int>(i));
}

/// Edges removed, as the model counts them: a model without edges removes none.
template <class M>
constexpr std::size_t edges_if_any(std::size_t n) {
    return hmira::halfedge_mutable_mesh<M> ? n : 0;
}

template <class M>
class erasable_primitives : public ::testing::Test {};
TYPED_TEST_SUITE(erasable_primitives, all_models);

#define HMIRA_REQUIRE_FACE_ERASABLE(M)                                                  \
    if constexpr (!hmira::face_erasable_mesh<M> || !hmira::vertex_erasable_mesh<M>) {   \
        GTEST_SKIP() << "neither halfedge_mutable_mesh nor removal through the traits"; \
        return;                                                                         \
    }

template <class M, class T = hmira::default_traits<M>>
typename T::face_handle face_with(const M& m, std::array<point_key, 3> corners) {
    for (auto f : T::faces(m)) {
        std::size_t hits = 0, n = 0;
        for (auto v : T::face_vertices(m, f)) {
            ++n;
            hits += std::find(corners.begin(), corners.end(), key_of<M, T>(m, v)) != corners.end();
        }
        if (n == 3 && hits == 3) return f;
    }
    ADD_FAILURE() << "no such face";
    return typename T::face_handle();
}

point_key xy(double x, double y) { return {x, y, 0}; }

TYPED_TEST(erasable_primitives, remove_interior_triangle_then_add_face_restores_mesh) {
    HMIRA_REQUIRE_FACE_ERASABLE(TypeParam)
    else {
        using T = hmira::default_traits<TypeParam>;
        auto m = mesh_from<TypeParam>(grid(3, 3, true));
        const auto start = canonical_faces(m);
        // (1,1)-(2,1)-(2,2): every side has another face, every corner other faces.
        auto r = hmira::remove_face(m, face_with(m, {xy(1, 1), xy(2, 1), xy(2, 2)}));
        ASSERT_TRUE(r) << r.error().message;
        expect_report(*r, 1, 0, 0);
        EXPECT_EQ(T::face_count(m), 17u);
        EXPECT_EQ(T::vertex_count(m), 16u);
        EXPECT_TRUE(hmira_test::is_valid(m));
        const std::array corners{at(m, 1, 1), at(m, 2, 1), at(m, 2, 2)};
        auto f = hmira::add_face(m, std::span<const typename T::vertex_handle>(corners));
        ASSERT_TRUE(f) << f.error().message;
        EXPECT_TRUE(hmira_test::is_valid(m));
        EXPECT_EQ(canonical_faces(m), start);
    }
}

TYPED_TEST(erasable_primitives, remove_corner_triangle_takes_its_bare_edges_and_vertex) {
    HMIRA_REQUIRE_FACE_ERASABLE(TypeParam)
    else {
        using T = hmira::default_traits<TypeParam>;
        auto m = mesh_from<TypeParam>(grid(3, 3, true));
        // (2,0)-(3,0)-(3,1) is the only face at (3,0): its two boundary sides and (3,0) go;
        // the diagonal (3,1)-(2,0) keeps the face (2,0)-(3,1)-(2,1).
        auto r = hmira::remove_face(m, face_with(m, {xy(2, 0), xy(3, 0), xy(3, 1)}));
        ASSERT_TRUE(r) << r.error().message;
        expect_report(*r, 1, edges_if_any<TypeParam>(2), 1);
        EXPECT_EQ(T::face_count(m), 17u);
        EXPECT_EQ(T::vertex_count(m), 15u);
        EXPECT_TRUE(hmira_test::is_valid(m));
    }
}

TYPED_TEST(erasable_primitives, remove_corner_triangle_can_keep_what_it_leaves_bare) {
    HMIRA_REQUIRE_FACE_ERASABLE(TypeParam)
    else {
        using T = hmira::default_traits<TypeParam>;
        auto m = mesh_from<TypeParam>(grid(3, 3, true));
        auto r = hmira::remove_face(m, face_with(m, {xy(2, 0), xy(3, 0), xy(3, 1)}),
                                    {.remove_wire_edges = false, .remove_isolated_vertices = false});
        ASSERT_TRUE(r) << r.error().message;
        expect_report(*r, 1, 0, 0);
        EXPECT_EQ(T::vertex_count(m), 16u);
        EXPECT_TRUE(is_valid_relaxed(m));
    }
}

TYPED_TEST(erasable_primitives, remove_vertex_takes_its_six_triangles_and_what_they_leave_bare) {
    HMIRA_REQUIRE_FACE_ERASABLE(TypeParam)
    else {
        using T = hmira::default_traits<TypeParam>;
        auto m = mesh_from<TypeParam>(grid(3, 3, true));
        // (1,1) has six triangles (neighbours (0,0), (1,0), (2,1), (2,2), (1,2), (0,1)). They go
        // with its six edges, the boundary sides (0,0)-(1,0) and (0,1)-(0,0), and (0,0), whose
        // faces were all among them. The hexagon's other sides keep a face.
        auto r = hmira::remove_vertex(m, at(m, 1, 1));
        ASSERT_TRUE(r) << r.error().message;
        expect_report(*r, 6, edges_if_any<TypeParam>(8), 2);
        EXPECT_EQ(T::face_count(m), 12u);
        EXPECT_EQ(T::vertex_count(m), 14u);
        EXPECT_TRUE(hmira_test::is_valid(m));
        for (auto v : T::vertices(m)) EXPECT_TRUE((key_of<TypeParam, T>(m, v) != xy(0, 0)));
    }
}

TYPED_TEST(erasable_primitives, remove_vertex_can_keep_the_corners_it_leaves_bare) {
    HMIRA_REQUIRE_FACE_ERASABLE(TypeParam)
    else {
        using T = hmira::default_traits<TypeParam>;
        auto m = mesh_from<TypeParam>(grid(3, 3, true));
        auto r = hmira::remove_vertex(m, at(m, 1, 1), {.remove_wire_edges = false, .remove_isolated_vertices = false});
        ASSERT_TRUE(r) << r.error().message;
        // The edges at the vertex always go (they cannot outlive it); nothing else.
        expect_report(*r, 6, edges_if_any<TypeParam>(6), 1);
        EXPECT_EQ(T::vertex_count(m), 15u);
        EXPECT_TRUE(is_valid_relaxed(m));
    }
}

TYPED_TEST(erasable_primitives, removals_of_missing_elements_fail_and_change_nothing) {
    HMIRA_REQUIRE_FACE_ERASABLE(TypeParam)
    else {
        using T = hmira::default_traits<TypeParam>;
        auto m = mesh_from<TypeParam>(grid(3, 3, true));
        const auto before = take_face_snapshot(m);
        auto f = hmira::remove_face(m, handle_at<typename T::face_handle>(T::face_index_bound(m) + 5));
        ASSERT_FALSE(f);
        EXPECT_EQ(f.error().code, hmira::errc::invalid_handle);
        EXPECT_NE(f.error().message.find("does not exist"), std::string::npos) << f.error().message;
        auto v = hmira::remove_vertex(m, handle_at<typename T::vertex_handle>(T::vertex_index_bound(m) + 5));
        ASSERT_FALSE(v);
        EXPECT_EQ(v.error().code, hmira::errc::invalid_handle);
        EXPECT_TRUE(take_face_snapshot(m) == before);
        EXPECT_TRUE(hmira_test::is_valid(m));
    }
}

TYPED_TEST(erasable_primitives, removing_a_removed_element_again_fails_and_changes_nothing_where_the_traits_can_tell) {
    HMIRA_REQUIRE_FACE_ERASABLE(TypeParam)
    else if constexpr (!hmira::face_removal_mesh<TypeParam>) {
        GTEST_SKIP() << "a deleted handle cannot be told apart through these traits";
    }
    else {
        auto m = mesh_from<TypeParam>(grid(3, 3, true));
        const auto f = face_with(m, {xy(1, 1), xy(2, 1), xy(2, 2)});
        const auto v = at(m, 1, 1);
        ASSERT_TRUE(hmira::remove_vertex(m, v));  // takes f too
        const auto before = take_face_snapshot(m);
        EXPECT_FALSE(hmira::remove_face(m, f));
        EXPECT_FALSE(hmira::remove_vertex(m, v));
        EXPECT_TRUE(take_face_snapshot(m) == before);
        EXPECT_TRUE(hmira_test::is_valid(m));
    }
}

TYPED_TEST(erasable_primitives, remove_interior_diagonal_takes_its_two_triangles) {
    if constexpr (!hmira::halfedge_mutable_mesh<TypeParam> || !indexed_halfedge_model<TypeParam>) {
        GTEST_SKIP() << "no edges";
    } else {
        using T = hmira::default_traits<TypeParam>;
        auto m = mesh_from<TypeParam>(grid(3, 3, true));
        // The diagonal (1,1)-(2,2): both triangles of quad (1,1) go; their other sides keep a face.
        auto r = hmira::remove_edge(m, find_halfedge(m, at(m, 1, 1), at(m, 2, 2)));
        ASSERT_TRUE(r) << r.error().message;
        expect_report(*r, 2, 1, 0);
        EXPECT_EQ(T::face_count(m), 16u);
        EXPECT_TRUE(hmira_test::is_valid(m));
        EXPECT_TRUE(euler_poincare_holds(m, 1));  // boundary loops count as faces: still one shell, no handle
    }
}

TYPED_TEST(erasable_primitives, add_wire_edge_then_remove_it_restores_mesh) {
    if constexpr (!hmira::halfedge_mutable_mesh<TypeParam> || !indexed_halfedge_model<TypeParam>) {
        GTEST_SKIP() << "no edges";
    } else {
        auto m = mesh_from<TypeParam>(grid(3, 3, true));
        const auto start = m;
        const auto before = take_snapshot(m);
        // A wire edge is no face, so triangle-only models take it too.
        auto e = hmira::add_edge(m, at(m, 0, 0), at(m, 3, 3));
        ASSERT_TRUE(e) << e.error().message;
        EXPECT_TRUE(is_valid_relaxed(m));
        EXPECT_EQ(count_euler(m).boundary_loops, 2);
        auto r = hmira::remove_edge(m, *e);
        ASSERT_TRUE(r) << r.error().message;
        expect_report(*r, 0, 1, 0);
        EXPECT_TRUE(hmira_test::is_valid(m));
        EXPECT_TRUE(same_mesh(m, start));
        // A bad end fails and changes nothing.
        auto copy = start;
        auto bad = hmira::add_edge(copy, at(copy, 1, 1), at(copy, 0, 0));
        ASSERT_FALSE(bad);
        EXPECT_TRUE(take_snapshot(copy) == before);
    }
}

}  // namespace
