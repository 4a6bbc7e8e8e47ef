// halfedge_mesh::from_polygons builds the same mesh as adding the faces one by one, and
// refuses, with the element named, every input add_face would refuse or a finished
// manifold mesh must not have.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include <hmira/algorithms/topology/mesh_topology.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "adapters/random_meshes.hpp"
#include "support/checks.hpp"
#include "support/shapes.hpp"

namespace {

using hmira::halfedge_mesh;

struct flat {
    std::vector<hmira::vec3<double>> points;
    std::vector<std::uint32_t> offsets{0}, corners;
};

flat flatten(const hmira_test::face_list& g) {
    flat out;
    out.points = g.points;
    for (const auto& f : g.faces) {
        for (auto i : f) out.corners.push_back(static_cast<std::uint32_t>(i));
        out.offsets.push_back(static_cast<std::uint32_t>(out.corners.size()));
    }
    return out;
}

hmira::result<halfedge_mesh> build(const flat& f) {
    return halfedge_mesh::from_polygons(f.points, f.offsets, f.corners);
}

// Record by record: the same halfedge numbering, links, faces, outgoing halfedges and positions.
void expect_identical(const halfedge_mesh& a, const halfedge_mesh& b) {
    ASSERT_EQ(a.halfedge_count(), b.halfedge_count());
    ASSERT_EQ(a.vertex_count(), b.vertex_count());
    ASSERT_EQ(a.face_count(), b.face_count());
    for (std::uint32_t i = 0; i < a.halfedge_count(); ++i) {
        const hmira::halfedge_handle h(i);
        ASSERT_EQ(a.target(h), b.target(h)) << "halfedge " << i;
        ASSERT_EQ(a.face(h), b.face(h)) << "halfedge " << i;
        ASSERT_EQ(a.next(h), b.next(h)) << "halfedge " << i;
        ASSERT_EQ(a.prev(h), b.prev(h)) << "halfedge " << i;
    }
    for (std::uint32_t i = 0; i < a.vertex_count(); ++i) {
        const hmira::vertex_handle v(i);
        ASSERT_EQ(a.vertex_halfedge(v), b.vertex_halfedge(v)) << "vertex " << i;
        ASSERT_EQ(a.position(v), b.position(v)) << "vertex " << i;
    }
    for (std::uint32_t i = 0; i < a.face_count(); ++i)
        ASSERT_EQ(a.face_halfedge(hmira::face_handle(i)), b.face_halfedge(hmira::face_handle(i))) << "face " << i;
}

// Face by face with add_face, what from_polygons promises to equal.
halfedge_mesh one_by_one(const hmira_test::face_list& g) {
    halfedge_mesh one;
    EXPECT_TRUE(hmira_test::add_face_list(one, g));
    return one;
}

TEST(HalfedgeBulkBuild, builds_the_same_mesh_as_face_by_face_add_face_on_random_meshes) {
    for (unsigned seed = 1; seed <= 12; ++seed) {
        SCOPED_TRACE(seed);
        const auto g = hmira_test::random_mesh(seed);
        auto bulk = build(flatten(g));
        ASSERT_TRUE(bulk) << bulk.error().message;
        halfedge_mesh one;
        ASSERT_TRUE(hmira_test::add_face_list(one, g));
        ASSERT_TRUE(hmira_test::is_valid(*bulk, {.relaxed = true}));
        EXPECT_EQ(hmira_test::canonical_faces(*bulk), hmira_test::canonical_faces(one));
        EXPECT_EQ(bulk->edge_count(), one.edge_count());
        EXPECT_EQ(bulk->vertex_count(), one.vertex_count());
        const auto tb = hmira::mesh_topology(*bulk), to = hmira::mesh_topology(one);
        EXPECT_EQ(tb.boundary_loops, to.boundary_loops);
        EXPECT_EQ(tb.genus, to.genus);
        // face_vertices starts at the face's first corner, as add_face does.
        for (std::size_t f = 0; f < g.faces.size(); ++f)
            EXPECT_EQ(bulk->face_vertices(hmira::face_handle(f)).begin().cursor(),
                      bulk->face_halfedge(hmira::face_handle(f)));
        EXPECT_EQ((*bulk->face_vertices(hmira::face_handle(0u)).begin()).index, g.faces[0][0]);
    }
}

TEST(HalfedgeBulkBuild, numbers_and_links_every_record_as_face_by_face_add_face_does) {
    for (unsigned seed = 1; seed <= 12; ++seed) {
        SCOPED_TRACE(seed);
        const auto g = hmira_test::random_mesh(seed, 40, 30);
        auto bulk = build(flatten(g));
        ASSERT_TRUE(bulk) << bulk.error().message;
        expect_identical(*bulk, one_by_one(g));
    }
}

TEST(HalfedgeBulkBuild, disjoint_triangles_are_all_boundary_and_numbered_as_add_face_does) {
    // Every edge a boundary edge: twice as many halfedges as corners, the most the build makes.
    hmira_test::face_list g;
    for (std::size_t t = 0; t < 3000; ++t) {
        const double x = static_cast<double>(t);
        g.points.insert(g.points.end(), {{x, 0, 0}, {x + 1, 0, 0}, {x, 1, 0}});
        g.faces.push_back({3 * t, 3 * t + 1, 3 * t + 2});
    }
    auto bulk = build(flatten(g));
    ASSERT_TRUE(bulk) << bulk.error().message;
    EXPECT_EQ(bulk->halfedge_count(), 2 * 9000u);
    ASSERT_TRUE(hmira_test::is_valid(*bulk));
    EXPECT_EQ(hmira::mesh_topology(*bulk).boundary_loops, 3000u);
    expect_identical(*bulk, one_by_one(g));
}

TEST(HalfedgeBulkBuild, names_the_fault_by_the_lowest_source_vertex_whatever_the_face_order) {
    // Two edges run twice the same way: 2->3 (faces 0 and 1) and 0->1 (faces 2 and 3). Met
    // first in face order is 2->3, but the message names 0->1, the edge of the lower vertex.
    const std::vector<hmira::vec3<double>> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0},  {1, 1, 0},
                                             {2, 0, 0}, {2, 1, 0}, {-1, -1, 0}};
    const std::vector<std::uint32_t> offsets{0, 3, 6, 9, 12};
    const std::vector<std::uint32_t> corners{2, 3, 4, 2, 3, 5, 0, 1, 5, 0, 1, 6};
    auto r = halfedge_mesh::from_polygons(p, offsets, corners);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, hmira::errc::orientation_conflict);
    EXPECT_EQ(r.error().message,
              "from_polygons: edge 0->1 is run in the same direction by two faces (they are wound against each other)");
    EXPECT_EQ(r.error().element, 0);
    // A third face on edge 1->2 (faces 1 and 2 run it the same way, face 0 backwards).
    auto third = halfedge_mesh::from_polygons(p, std::vector<std::uint32_t>{0, 3, 6, 9},
                                              std::vector<std::uint32_t>{2, 1, 0, 1, 2, 3, 1, 2, 4});
    ASSERT_FALSE(third);
    EXPECT_EQ(third.error().code, hmira::errc::non_manifold);
    EXPECT_EQ(third.error().message, "from_polygons: edge 1->2 has more than two faces");
    EXPECT_EQ(third.error().element, 1);
    // The third face on 0-1 arrives after the edge is paired, from either side.
    for (const auto& corners : {std::vector<std::uint32_t>{1, 0, 2, 0, 1, 3, 0, 1, 4},
                                std::vector<std::uint32_t>{0, 1, 2, 1, 0, 3, 0, 1, 4}}) {
        auto paired = halfedge_mesh::from_polygons(p, std::vector<std::uint32_t>{0, 3, 6, 9}, corners);
        ASSERT_FALSE(paired);
        EXPECT_EQ(paired.error().message, "from_polygons: edge 0->1 has more than two faces");
        EXPECT_EQ(paired.error().element, 0);
    }
}

TEST(HalfedgeBulkBuild, a_closed_torus_has_no_boundary_and_every_vertex_a_full_fan) {
    auto m = build(flatten(hmira_test::torus(12, 8)));
    ASSERT_TRUE(m);
    ASSERT_TRUE(hmira_test::is_valid(*m));
    for (auto v : m->vertices()) EXPECT_EQ(m->valence(v), 4u);
    EXPECT_EQ(hmira::mesh_topology(*m).genus, 1);
}

TEST(HalfedgeBulkBuild, the_built_mesh_can_keep_growing_with_add_face) {
    auto g = hmira_test::grid(3, 3);
    auto m = build(flatten(g));
    ASSERT_TRUE(m);
    const auto a = hmira::vertex_handle(3u), b = hmira::vertex_handle(2u);
    const auto c = m->add_vertex({3, -1, 0});
    ASSERT_TRUE(m->add_face({a, b, c})) << "a face on the boundary, wound like its neighbour";
    EXPECT_TRUE(hmira_test::is_valid(*m));
}

TEST(HalfedgeBulkBuild, refuses_bad_input_and_names_the_element) {
    const std::vector<hmira::vec3<double>> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0},  {1, 1, 0},
                                             {2, 0, 0}, {2, 1, 0}, {-1, -1, 0}};
    auto code = [&](std::vector<std::uint32_t> offsets, std::vector<std::uint32_t> corners) {
        auto r = halfedge_mesh::from_polygons(p, offsets, corners);
        EXPECT_FALSE(r);
        return r ? hmira::errc::unsupported : r.error().code;
    };
    EXPECT_EQ(code({0, 2}, {0, 1}), hmira::errc::degenerate_face);
    EXPECT_EQ(code({0, 3}, {0, 1, 1}), hmira::errc::degenerate_face);
    EXPECT_EQ(code({0, 3}, {0, 1, 9}), hmira::errc::invalid_handle);
    EXPECT_EQ(code({0, 4}, {0, 1, 2}), hmira::errc::invalid_argument);
    // Two faces running 1->2 in the same direction.
    EXPECT_EQ(code({0, 3, 6}, {0, 1, 2, 1, 2, 3}), hmira::errc::orientation_conflict);
    // Three faces on edge 0-1.
    EXPECT_EQ(code({0, 3, 6, 9}, {0, 1, 2, 1, 0, 3, 0, 1, 6}), hmira::errc::non_manifold);
    // Two triangles touching only at vertex 1: a pinch.
    EXPECT_EQ(code({0, 3, 6}, {0, 1, 2, 1, 4, 5}), hmira::errc::non_manifold);
    auto r = halfedge_mesh::from_polygons(p, std::vector<std::uint32_t>{0, 3, 6},
                                          std::vector<std::uint32_t>{0, 1, 2, 1, 4, 5});
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().element, 1);
}

TEST(HalfedgeBulkBuild, two_closed_surfaces_sharing_one_vertex_are_refused) {
    // Two tetrahedra glued at vertex 0: no boundary anywhere, but vertex 0 has two fans.
    const std::vector<hmira::vec3<double>> p{{0, 0, 0},  {1, 0, 0},  {0, 1, 0}, {0, 0, 1},
                                             {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
    const std::vector<std::uint32_t> offsets{0, 3, 6, 9, 12, 15, 18, 21, 24};
    const std::vector<std::uint32_t> corners{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3, 0, 5, 4, 0, 4, 6, 0, 6, 5, 4, 5, 6};
    auto r = halfedge_mesh::from_polygons(p, offsets, corners);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, hmira::errc::non_manifold);
    EXPECT_EQ(r.error().element, 0);
}

TEST(HalfedgeBulkBuild, unused_points_become_isolated_vertices_and_no_faces_is_fine) {
    const std::vector<hmira::vec3<double>> p{{0, 0, 0}, {1, 0, 0}};
    auto r = halfedge_mesh::from_polygons(p, std::vector<std::uint32_t>{}, std::vector<std::uint32_t>{});
    ASSERT_TRUE(r);
    EXPECT_EQ(r->vertex_count(), 2u);
    EXPECT_TRUE(r->is_isolated(hmira::vertex_handle(0u)));
}

}  // namespace
