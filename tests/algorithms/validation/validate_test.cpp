// validate() finds each kind of problem it promises, names the element, and stays quiet on
// good meshes. The broken meshes are built with a deliberately permissive user mesh type,
// so that nothing upstream refuses them first.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <span>

#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/validation/validate.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "support/checks.hpp"

namespace {

// A user's in-house "anything goes" polygon list.
struct soup_mesh {
    std::vector<hmira::vec3<double>> points;
    std::vector<std::vector<int>> faces;
};

}  // namespace

template <>
struct hmira::mesh_traits<soup_mesh> {
    using vertex_handle = int;
    using face_handle = int;
    using scalar = double;
    static auto vertices(const soup_mesh& m) { return std::views::iota(0, int(m.points.size())); }
    static auto faces(const soup_mesh& m) { return std::views::iota(0, int(m.faces.size())); }
    static std::size_t vertex_count(const soup_mesh& m) { return m.points.size(); }
    static std::size_t face_count(const soup_mesh& m) { return m.faces.size(); }
    static std::size_t vertex_index(const soup_mesh&, int v) { return std::size_t(v); }
    static std::size_t vertex_index_bound(const soup_mesh& m) { return m.points.size(); }
    static std::size_t face_index(const soup_mesh&, int f) { return std::size_t(f); }
    static std::size_t face_index_bound(const soup_mesh& m) { return m.faces.size(); }
    static std::span<const int> face_vertices(const soup_mesh& m, int f) { return m.faces[std::size_t(f)]; }
    static hmira::vec3<double> position(const soup_mesh& m, int v) { return m.points[std::size_t(v)]; }
};

namespace {

using namespace hmira;

soup_mesh tetra() {
    return {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
}

bool has(const std::vector<mesh_problem>& ps, problem_kind k, std::size_t element) {
    return std::any_of(ps.begin(), ps.end(),
                       [&](const mesh_problem& p) { return p.kind == k && p.element == element; });
}

TEST(validate, a_closed_tetrahedron_has_no_problems) {
    EXPECT_TRUE(validate(tetra()).empty()) << hmira_test::describe(validate(tetra()));
}

TEST(validate, reports_a_face_with_a_repeated_vertex) {
    auto m = tetra();
    m.faces.push_back({0, 1, 1});
    EXPECT_TRUE(has(validate(m), problem_kind::degenerate_face, 4));
}

TEST(validate, reports_a_face_with_two_vertices_except_in_relaxed_mode) {
    auto m = tetra();
    m.faces.push_back({0, 1});
    EXPECT_TRUE(has(validate(m), problem_kind::degenerate_face, 4));
    EXPECT_FALSE(has(validate(m, {.relaxed = true}), problem_kind::degenerate_face, 4));
}

TEST(validate, reports_a_dangling_vertex_reference) {
    auto m = tetra();
    m.faces.push_back({0, 1, 9});
    EXPECT_TRUE(has(validate(m), problem_kind::invalid_reference, 4));
}

TEST(validate, reports_an_edge_with_three_faces) {
    auto m = tetra();
    m.points.push_back({1, 1, 1});
    m.faces.push_back({1, 2, 4});  // third face on edge 1-2
    EXPECT_TRUE(has(validate(m), problem_kind::non_manifold_edge, 1));
}

TEST(validate, reports_inconsistent_orientation) {
    auto m = tetra();
    std::reverse(m.faces[3].begin(), m.faces[3].end());
    const auto ps = validate(m);
    EXPECT_TRUE(std::any_of(ps.begin(), ps.end(),
                            [](const mesh_problem& p) { return p.kind == problem_kind::inconsistent_orientation; }));
}

TEST(validate, reports_two_solids_touching_at_one_vertex) {
    auto m = tetra();
    // A second tetrahedron sharing only vertex 3: a pinch (bow-tie) vertex.
    m.points.push_back({0, 0, 2});
    m.points.push_back({1, 0, 2});
    m.points.push_back({0, 1, 2});
    m.faces.push_back({3, 6, 5});
    m.faces.push_back({3, 5, 4});
    m.faces.push_back({3, 4, 6});
    m.faces.push_back({4, 5, 6});
    const auto ps = validate(m);
    EXPECT_TRUE(has(ps, problem_kind::non_manifold_vertex, 3)) << hmira_test::describe(ps);
    EXPECT_EQ(ps.size(), 1u) << hmira_test::describe(ps);
}

TEST(validate, reports_isolated_vertices_only_in_strict_mode) {
    auto m = tetra();
    m.points.push_back({5, 5, 5});
    EXPECT_TRUE(has(validate(m), problem_kind::isolated_vertex, 4));
    EXPECT_TRUE(validate(m, {.relaxed = true}).empty());
}

TEST(validate, reports_zero_area_faces_when_checking_geometry) {
    auto m = tetra();
    m.points[3] = {0.5, 0.5, 0};  // face 3 (1, 2, 3) becomes collinear
    EXPECT_TRUE(has(validate(m), problem_kind::zero_area_face, 3));
    EXPECT_FALSE(has(validate(m, {.check_geometry = false}), problem_kind::zero_area_face, 3));
}

TEST(validate, reports_non_finite_positions_naming_the_vertex_even_without_the_geometry_check) {
    for (double bad :
         {std::nan(""), std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()}) {
        auto m = tetra();
        m.points[2].y = bad;
        for (bool geometry : {true, false}) {
            const auto ps = validate(m, {.check_geometry = geometry});
            EXPECT_TRUE(has(ps, problem_kind::non_finite_position, 2)) << hmira_test::describe(ps);
            EXPECT_EQ(std::count_if(ps.begin(), ps.end(),
                                    [](const mesh_problem& p) { return p.kind == problem_kind::non_finite_position; }),
                      1);
        }
    }
    EXPECT_STREQ(to_string(problem_kind::non_finite_position), "non-finite position");
}

TEST(validate, stops_after_max_problems) {
    soup_mesh m;
    m.points.assign(3, {});
    for (int i = 0; i < 50; ++i) m.faces.push_back({0, 1, 7});
    EXPECT_EQ(validate(m, {.max_problems = 5}).size(), 5u);
}

TEST(validate, finds_broken_halfedge_links) {
    halfedge_mesh m;
    ASSERT_TRUE(generate_cube(m));
    ASSERT_TRUE(hmira_test::is_valid(m));
    // Corrupt one next pointer: the face loops no longer close properly.
    const auto h = m.face_halfedge(face_handle(0u));
    m.set_next(h, m.next(m.next(h)));
    const auto ps = validate(m);
    EXPECT_FALSE(ps.empty());
    EXPECT_TRUE(std::any_of(ps.begin(), ps.end(), [](const mesh_problem& p) {
        return p.kind == problem_kind::broken_link;
    })) << hmira_test::describe(ps);
}

TEST(validate, finds_a_vertex_storing_an_interior_halfedge_on_the_boundary) {
    halfedge_mesh m;
    const auto a = m.add_vertex({0, 0, 0}), b = m.add_vertex({1, 0, 0}), c = m.add_vertex({0, 1, 0}),
               d = m.add_vertex({1, 1, 0});
    ASSERT_TRUE(m.add_face({a, b, c}));
    ASSERT_TRUE(m.add_face({b, d, c}));
    ASSERT_TRUE(hmira_test::is_valid(m));
    const auto inner = m.find_halfedge(b, c);
    m.set_vertex_halfedge(b, inner);
    EXPECT_TRUE(has(validate(m), problem_kind::broken_link, b.index));
}

TEST(validate, finds_a_wire_edge_except_in_relaxed_mode) {
    halfedge_mesh m;
    const auto a = m.add_vertex({0, 0, 0}), b = m.add_vertex({1, 0, 0});
    const auto h = m.new_edge(a, b);
    m.set_next(h, halfedge_mesh::opposite(h));
    m.set_next(halfedge_mesh::opposite(h), h);
    m.set_vertex_halfedge(a, h);
    m.set_vertex_halfedge(b, halfedge_mesh::opposite(h));
    const auto strict = validate(m);
    EXPECT_TRUE(std::any_of(strict.begin(), strict.end(),
                            [](const mesh_problem& p) { return p.kind == problem_kind::wire_edge; }));
    EXPECT_TRUE(validate(m, {.relaxed = true}).empty()) << hmira_test::describe(validate(m, {.relaxed = true}));
}

}  // namespace

#include <hmira/algorithms/euler/make_face_kill_ring.hpp>
#include <hmira/algorithms/generators/grid.hpp>

namespace {

// A vertex whose faces are joined only through an inner ring (a face turned into a hole of
// another face by killFmakeR) is manifold: validate must count ring corners in its fans.
TEST(validate, inner_ring_corners_join_the_fans_of_their_vertices) {
    hmira::halfedge_mesh m;
    auto g = hmira::generate_grid(m, {.columns = 2, .rows = 1, .triangles = true});
    ASSERT_TRUE(g);
    // Around boundary vertex (1, 0) the fan is faces[0] - faces[3] - faces[2]; the middle one
    // becomes a ring of faces[0].
    auto ring = hmira::kill_face_make_ring(m, g->faces[3], g->faces[0]);
    ASSERT_TRUE(ring) << ring.error().message;
    EXPECT_TRUE(m.has_inner_rings(g->faces[0]));
    const auto problems = hmira::validate(m, {.relaxed = true});
    EXPECT_TRUE(problems.empty()) << hmira_test::describe(problems);
}

}  // namespace
