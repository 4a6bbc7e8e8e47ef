// The face-vertex mesh: faces refuse bad input unchanged, removal and garbage collection keep
// the surviving faces and their properties.
#include <gtest/gtest.h>

#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

#include "support/checks.hpp"

namespace {

using namespace hmira;

TEST(face_vertex_mesh, bad_faces_are_refused_and_change_nothing) {
    face_vertex_mesh m;
    const auto a = m.add_vertex({0, 0, 0}), b = m.add_vertex({1, 0, 0}), c = m.add_vertex({0, 1, 0});
    const auto changes = m.change_count();
    EXPECT_EQ(m.add_face({a, b}).error().code, errc::degenerate_face);
    EXPECT_EQ(m.add_face({a, b, a}).error().code, errc::degenerate_face);
    auto missing = m.add_face({a, b, vertex_handle(17u)});
    EXPECT_EQ(missing.error().code, errc::invalid_handle);
    EXPECT_NE(missing.error().message.find("17"), std::string::npos) << "the message must name the vertex";
    EXPECT_EQ(m.face_count(), 0u);
    EXPECT_EQ(m.change_count(), changes);
    EXPECT_TRUE(m.add_face({a, b, c}));
}

TEST(face_vertex_mesh, removing_a_vertex_removes_exactly_the_faces_that_use_it) {
    face_vertex_mesh m;
    ASSERT_TRUE(generate_icosahedron(m));
    const auto v = vertex_handle(3u);
    std::size_t using_v = 0;
    for (auto f : m.faces()) {
        auto fv = m.face_vertices(f);
        using_v += std::find(fv.begin(), fv.end(), v) != fv.end();
    }
    ASSERT_TRUE(m.remove_vertex(v));
    EXPECT_EQ(m.face_count(), 20 - using_v);
    EXPECT_EQ(m.vertex_count(), 11u);
    for (auto f : m.faces()) {
        auto fv = m.face_vertices(f);
        EXPECT_EQ(std::find(fv.begin(), fv.end(), v), fv.end());
    }
    EXPECT_FALSE(m.remove_vertex(v)) << "removing twice must fail";
    EXPECT_TRUE(hmira_test::is_valid(m));
}

TEST(face_vertex_mesh, collect_garbage_compacts_faces_vertices_and_properties) {
    face_vertex_mesh m;
    ASSERT_TRUE(generate_cube(m));
    auto colour = m.add_face_property<int>("colour");
    auto weight = m.add_vertex_property<double>("weight");
    for (auto f : m.faces()) colour[f] = int(f.index) + 100;
    for (auto v : m.vertices()) weight[v] = double(v.index) / 8;
    std::vector<std::vector<vec3<double>>> kept_faces;
    ASSERT_TRUE(m.remove_face(face_handle(2u)));
    ASSERT_TRUE(m.remove_vertex(vertex_handle(4u)));
    for (auto f : m.faces()) {
        std::vector<vec3<double>> loop;
        for (auto v : m.face_vertices(f)) loop.push_back(m.position(v));
        kept_faces.push_back(loop);
    }
    const auto map = m.collect_garbage();
    EXPECT_FALSE(m.has_garbage());
    EXPECT_EQ(m.vertex_count(), 7u);
    EXPECT_EQ(map.vertices[4], UINT32_MAX);
    std::size_t k = 0;
    for (auto f : m.faces()) {
        std::vector<vec3<double>> loop;
        for (auto v : m.face_vertices(f)) loop.push_back(m.position(v));
        EXPECT_EQ(loop, kept_faces[k++]);
    }
    for (std::uint32_t old = 0; old < map.faces.size(); ++old)
        if (map.faces[old] != UINT32_MAX) {
            EXPECT_EQ(colour[face_handle(map.faces[old])], int(old) + 100);
        }
    for (std::uint32_t old = 0; old < map.vertices.size(); ++old)
        if (map.vertices[old] != UINT32_MAX) {
            EXPECT_EQ(weight[vertex_handle(map.vertices[old])], double(old) / 8);
        }
}

TEST(face_vertex_mesh, reverse_face_reverses_the_vertex_order) {
    face_vertex_mesh m;
    const auto a = m.add_vertex({0, 0, 0}), b = m.add_vertex({1, 0, 0}), c = m.add_vertex({0, 1, 0}),
               d = m.add_vertex({1, 1, 0});
    auto f = m.add_face({a, b, d, c});
    ASSERT_TRUE(f);
    m.reverse_face(*f);
    auto fv = m.face_vertices(*f);
    EXPECT_EQ(std::vector<vertex_handle>(fv.begin(), fv.end()), (std::vector<vertex_handle>{c, d, b, a}));
}

}  // namespace

namespace {

using hmira::errc;
using hmira::face_vertex_mesh;
using point3 = std::array<double, 3>;

// A mesh with one triangle, a named vertex property holding 7 on it, and its change count.
face_vertex_mesh one_triangle_with_property() {
    face_vertex_mesh m;
    const auto a = m.add_vertex({0, 0, 0}), b = m.add_vertex({1, 0, 0}), c = m.add_vertex({0, 1, 0});
    EXPECT_TRUE(m.add_face({a, b, c}));
    auto p = m.add_vertex_property<int>("v:tag", 7);
    EXPECT_TRUE(p.valid());
    return m;
}

TEST(face_vertex_mesh_assign, indexed_polygons_become_the_faces_in_order) {
    auto m = one_triangle_with_property();
    const std::vector<point3> points{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}};
    const std::vector<std::uint32_t> corners{0, 1, 2, 3, 1, 4, 2};
    ASSERT_TRUE(m.assign(std::span<const point3>(points), std::vector<std::size_t>{0, 4, 7}, corners));
    ASSERT_EQ(m.vertex_count(), 5u);
    ASSERT_EQ(m.face_count(), 2u);
    EXPECT_EQ(m.position(hmira::vertex_handle(4u)), (hmira::vec3<double>{2, 0, 0}));
    const std::vector<std::uint32_t> quad{0, 1, 2, 3}, tri{1, 4, 2};
    std::vector<std::uint32_t> got;
    for (auto v : m.face_vertices(hmira::face_handle(0u))) got.push_back(v.index);
    EXPECT_EQ(got, quad);
    got.clear();
    for (auto v : m.face_vertices(hmira::face_handle(1u))) got.push_back(v.index);
    EXPECT_EQ(got, tri);
    // The named property stays, sized to the new vertices with its default.
    auto p = m.get_vertex_property<int>("v:tag");
    ASSERT_TRUE(p.has_value());
    EXPECT_EQ((*p)[hmira::vertex_handle(4u)], 7);
    // The same as building face by face.
    face_vertex_mesh built;
    for (const auto& q : points) built.add_vertex({q[0], q[1], q[2]});
    ASSERT_TRUE(built.add_face(
        {hmira::vertex_handle(0u), hmira::vertex_handle(1u), hmira::vertex_handle(2u), hmira::vertex_handle(3u)}));
    ASSERT_TRUE(built.add_face({hmira::vertex_handle(1u), hmira::vertex_handle(4u), hmira::vertex_handle(2u)}));
    for (auto f : built.faces()) {
        auto a = built.face_vertices(f), b = m.face_vertices(f);
        EXPECT_TRUE(std::equal(a.begin(), a.end(), b.begin(), b.end()));
    }
}

TEST(face_vertex_mesh_assign, a_bad_face_or_offset_names_the_face_and_changes_nothing) {
    const std::vector<point3> points{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    struct bad_case {
        std::vector<std::size_t> offsets;
        std::vector<std::uint32_t> corners;
        errc code;
        long long face;
        std::string says;
    };
    const std::vector<bad_case> cases{
        {{0, 3, 5}, {0, 1, 2, 2, 3}, errc::degenerate_face, 1, "at least 3 vertices, got 2"},
        {{0, 3, 6}, {0, 1, 2, 0, 2, 9}, errc::invalid_handle, 1, "names vertex 9, which does not exist"},
        {{0, 3, 6}, {0, 1, 2, 3, 0, 3}, errc::degenerate_face, 1, "vertex 3 appears twice"},
        {{0, 4}, {0, 1, 2}, errc::invalid_argument, -1, "end at the corner count 3"},
        {{1, 3}, {0, 1, 2}, errc::invalid_argument, -1, "start at 0"},
        {{0, 3, 2, 3}, {0, 1, 2}, errc::invalid_argument, 1, "out of order"},
    };
    for (const auto& c : cases) {
        auto m = one_triangle_with_property();
        const auto changes = m.change_count();
        auto r = m.assign(std::span<const point3>(points), std::vector<std::size_t>(c.offsets), c.corners);
        ASSERT_FALSE(r) << c.says;
        EXPECT_EQ(r.error().code, c.code) << r.error().message;
        EXPECT_EQ(r.error().element, c.face) << r.error().message;
        EXPECT_NE(r.error().message.find(c.says), std::string::npos) << r.error().message;
        EXPECT_EQ(m.change_count(), changes);
        EXPECT_EQ(m.vertex_count(), 3u);
        EXPECT_EQ(m.face_count(), 1u);
        EXPECT_EQ(m.position(hmira::vertex_handle(1u)), (hmira::vec3<double>{1, 0, 0}));
        EXPECT_TRUE(m.get_vertex_property<int>("v:tag").has_value());
    }
}

TEST(face_vertex_mesh_assign, arrays_taken_by_move_become_the_mesh_without_a_copy) {
    auto m = one_triangle_with_property();
    std::vector<hmira::vec3<double>> positions{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}};
    std::vector<hmira::vertex_handle> corners;
    for (std::uint32_t i : {0u, 1u, 2u, 3u, 1u, 4u, 2u}) corners.push_back(hmira::vertex_handle(i));
    const auto* position_data = positions.data();
    const auto* corner_data = corners.data();
    ASSERT_TRUE(m.assign(std::move(positions), std::vector<std::size_t>{0, 4, 7}, std::move(corners)));
    ASSERT_EQ(m.vertex_count(), 5u);
    ASSERT_EQ(m.face_count(), 2u);
    // The very arrays: nothing was copied.
    EXPECT_EQ(m.positions().data(), position_data);
    EXPECT_EQ(m.face_vertices(hmira::face_handle(0u)).data(), corner_data);
    EXPECT_EQ(m.position(hmira::vertex_handle(4u)), (hmira::vec3<double>{2, 0, 0}));
    std::vector<std::uint32_t> got;
    for (auto v : m.face_vertices(hmira::face_handle(1u))) got.push_back(v.index);
    EXPECT_EQ(got, (std::vector<std::uint32_t>{1, 4, 2}));
    auto p = m.get_vertex_property<int>("v:tag");
    ASSERT_TRUE(p.has_value());
    EXPECT_EQ((*p)[hmira::vertex_handle(4u)], 7);
    EXPECT_TRUE(hmira_test::is_valid(m));
}

TEST(face_vertex_mesh_assign, arrays_taken_by_move_are_refused_whole_and_left_as_they_were) {
    struct bad_case {
        std::vector<std::size_t> offsets;
        std::vector<std::uint32_t> corners;
        errc code;
        long long face;
        std::string says;
    };
    // Triangles take a shortcut through the checks; their refusals must say the same.
    const std::vector<bad_case> cases{
        {{0, 3, 6}, {0, 1, 2, 0, 2, 9}, errc::invalid_handle, 1, "names vertex 9, which does not exist"},
        {{0, 3, 6}, {0, 1, 2, 3, 3, 0}, errc::degenerate_face, 1, "vertex 3 appears twice"},
        {{0, 3, 6}, {1, 1, 2, 0, 2, 3}, errc::degenerate_face, 0, "vertex 1 appears twice"},
        {{0, 4, 7}, {0, 1, 2, 0, 1, 4, 2}, errc::degenerate_face, 0, "vertex 0 appears twice"},
        {{0, 3, 5}, {0, 1, 2, 2, 3}, errc::degenerate_face, 1, "at least 3 vertices, got 2"},
        {{0, 4}, {0, 1, 2}, errc::invalid_argument, -1, "end at the corner count 3"},
        {{0, 3, 2, 3}, {0, 1, 2}, errc::invalid_argument, 1, "out of order"},
    };
    for (const auto& c : cases) {
        auto m = one_triangle_with_property();
        const auto changes = m.change_count();
        std::vector<hmira::vec3<double>> positions{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}};
        std::vector<hmira::vertex_handle> corners;
        for (auto i : c.corners) corners.push_back(hmira::vertex_handle(i));
        const auto corners_before = corners;
        std::vector<std::size_t> offsets = c.offsets;
        auto r = m.assign(std::move(positions), std::move(offsets), std::move(corners));
        ASSERT_FALSE(r) << c.says;
        EXPECT_EQ(r.error().code, c.code) << r.error().message;
        EXPECT_EQ(r.error().element, c.face) << r.error().message;
        EXPECT_NE(r.error().message.find(c.says), std::string::npos) << r.error().message;
        EXPECT_EQ(m.change_count(), changes);
        EXPECT_EQ(m.vertex_count(), 3u);
        EXPECT_EQ(m.face_count(), 1u);
        EXPECT_EQ(m.position(hmira::vertex_handle(1u)), (hmira::vec3<double>{1, 0, 0}));
        EXPECT_TRUE(m.get_vertex_property<int>("v:tag").has_value());
        // A refused call leaves the caller's arrays as they were.
        EXPECT_EQ(positions.size(), 5u);
        EXPECT_EQ(offsets, c.offsets);
        EXPECT_EQ(corners, corners_before);
        EXPECT_TRUE(hmira_test::is_valid(m));
    }
}

}  // namespace
