// Specification of winged_edge_mesh: its records, its halfedge view and its building checks.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <vector>

#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/orientation/flip_normals.hpp>
#include <hmira/algorithms/topology/mesh_topology.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>
#include <hmira/meshes/winged_edge_mesh.hpp>

#include "support/checks.hpp"
#include "support/shapes.hpp"

namespace {

using hmira::winged_edge_mesh;
using T = hmira::mesh_traits<winged_edge_mesh>;

static_assert(hmira::halfedge_navigable_mesh<winged_edge_mesh>);
static_assert(hmira::halfedge_mutable_mesh<winged_edge_mesh>);
static_assert(hmira::halfedge_index_mesh<winged_edge_mesh>);
static_assert(hmira::polygon_mesh_builder<winged_edge_mesh>);
static_assert(hmira::vertex_adjacency_mesh<winged_edge_mesh>);
static_assert(hmira::vertex_face_adjacency_mesh<winged_edge_mesh>);
static_assert(hmira::vertex_edge_adjacency_mesh<winged_edge_mesh>);
static_assert(hmira::face_adjacency_mesh<winged_edge_mesh>);
static_assert(hmira::change_counted_mesh<winged_edge_mesh>);
static_assert(hmira::flip_normals_mesh<winged_edge_mesh>);
static_assert(!hmira::inner_ring_mesh<winged_edge_mesh>, "winged edges have simple face loops only");

TEST(WingedEdge, every_edge_record_names_its_two_faces_and_four_wings_consistently) {
    winged_edge_mesh m;
    ASSERT_TRUE(hmira::generate_cube(m));
    ASSERT_TRUE(hmira_test::is_valid(m));
    EXPECT_EQ(m.edge_count(), 12u);
    for (auto e : m.edges()) {
        const auto& r = m.record(e);
        for (unsigned s = 0; s < 2; ++s) {
            ASSERT_FALSE(r.face[s].is_null()) << "a closed cube has no boundary";
            // The wing after e on side s starts where side s of e ends, in the same face.
            const auto n = r.next_wing[s];
            EXPECT_EQ(m.source(n), r.vertex[1 - s]);
            EXPECT_EQ(m.face(n), r.face[s]);
            const auto p = r.prev_wing[s];
            EXPECT_EQ(m.target(p), r.vertex[s]);
            EXPECT_EQ(m.face(p), r.face[s]);
        }
        EXPECT_NE(r.face[0], r.face[1]);
    }
}

TEST(WingedEdge, face_and_vertex_keep_one_of_their_edges) {
    winged_edge_mesh m;
    ASSERT_TRUE(hmira::generate_icosahedron(m));
    for (auto f : m.faces()) {
        const auto e = m.face_edge(f);
        const auto faces = m.edge_faces(e);
        EXPECT_TRUE(faces[0] == f || faces[1] == f);
    }
    for (auto v : m.vertices()) {
        const auto ends = m.edge_vertices(m.vertex_edge(v));
        EXPECT_TRUE(ends[0] == v || ends[1] == v);
        EXPECT_EQ(m.valence(v), 5u);
    }
}

TEST(WingedEdge, grid_with_holes_has_the_same_topology_as_the_halfedge_mesh_built_from_the_same_faces) {
    std::mt19937 rng(7);
    for (int round = 0; round < 5; ++round) {
        // Holes of one cell on a 3x3 lattice with a random offset: boundaries, no pinched vertex.
        const bool tri = round % 2 == 0;
        const std::size_t ox = rng() % 3, oy = rng() % 3, per_cell = tri ? 2 : 1;
        auto g = hmira_test::without_faces(hmira_test::grid(12, 9, tri), [&](std::size_t f) {
            const std::size_t cell = f / per_cell;
            return (cell % 12) % 3 == ox && (cell / 12) % 3 == oy;
        });
        winged_edge_mesh w;
        hmira::halfedge_mesh h;
        ASSERT_TRUE(hmira_test::add_face_list(w, g) == hmira_test::add_face_list(h, g));
        // A removed corner cell leaves its corner vertex isolated: legal in relaxed mode.
        ASSERT_TRUE(hmira_test::is_valid(w, {.relaxed = true}));
        EXPECT_EQ(hmira_test::canonical_faces(w), hmira_test::canonical_faces(h));
        const auto tw = hmira::mesh_topology(w), th = hmira::mesh_topology(h);
        EXPECT_EQ(tw.edges, th.edges);
        EXPECT_EQ(tw.boundary_loops, th.boundary_loops);
        EXPECT_EQ(w.edge_count(), h.edge_count());
    }
}

TEST(WingedEdge, a_rejected_face_leaves_the_mesh_unchanged) {
    winged_edge_mesh m;
    ASSERT_TRUE(hmira::generate_tetrahedron(m));
    const auto before = hmira_test::canonical_faces(m);
    const auto edges = m.edge_count();
    std::vector<hmira::vertex_handle> vs(m.vertices().begin(), m.vertices().end());
    // A closed surface has no room for another face on any edge.
    auto r = m.add_face({vs[0], vs[1], vs[2]});
    EXPECT_FALSE(r);
    auto r2 = m.add_face({vs[0], vs[0], vs[2]});
    ASSERT_FALSE(r2);
    EXPECT_EQ(r2.error().code, hmira::errc::degenerate_face);
    EXPECT_EQ(hmira_test::canonical_faces(m), before);
    EXPECT_EQ(m.edge_count(), edges);
    EXPECT_TRUE(hmira_test::is_valid(m));
}

TEST(WingedEdge, opposite_orientation_is_reported_as_a_conflict) {
    winged_edge_mesh m;
    auto a = m.add_vertex({0, 0, 0}), b = m.add_vertex({1, 0, 0}), c = m.add_vertex({0, 1, 0}),
         d = m.add_vertex({1, 1, 0});
    ASSERT_TRUE(m.add_face({a, b, c}));
    auto bad = m.add_face({b, c, d});  // runs b->c like the first face
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().code, hmira::errc::orientation_conflict);
    ASSERT_TRUE(m.add_face({c, b, d}));
    EXPECT_TRUE(hmira_test::is_valid(m));
}

TEST(WingedEdge, flip_normals_negates_volume_and_twice_restores_the_faces) {
    winged_edge_mesh m;
    ASSERT_TRUE(hmira::generate_dodecahedron(m));
    const auto faces = hmira_test::canonical_faces(m);
    const double vol = hmira_test::signed_volume(m);
    ASSERT_GT(vol, 0);
    EXPECT_EQ(hmira::flip_normals(m), m.face_count());
    ASSERT_TRUE(hmira_test::is_valid(m));
    EXPECT_NEAR(hmira_test::signed_volume(m), -vol, 1e-9);
    hmira::flip_normals(m);
    ASSERT_TRUE(hmira_test::is_valid(m));
    EXPECT_EQ(hmira_test::canonical_faces(m), faces);
}

TEST(WingedEdge, flip_normals_keeps_boundary_vertices_on_boundary_halfedges) {
    winged_edge_mesh m;
    ASSERT_TRUE(hmira_test::add_face_list(m, hmira_test::grid(5, 4)));
    hmira::flip_normals(m);
    EXPECT_TRUE(hmira_test::is_valid(m));
}

TEST(WingedEdge, collect_garbage_compacts_and_keeps_the_rest_valid) {
    winged_edge_mesh m;
    ASSERT_TRUE(hmira_test::add_face_list(m, hmira_test::grid(3, 3)));
    // Remove corner face 0 = (0, 1, 5, 4), vertex 0 and its two outer edges by raw mutation.
    const auto f0 = hmira::face_handle(0u);
    const auto v0 = hmira::vertex_handle(0u);
    const auto h = m.vertex_halfedge(v0);  // boundary 0 -> 4
    const auto g = m.prev(h);              // boundary 1 -> 0
    ASSERT_EQ(m.target(h), hmira::vertex_handle(4u));
    ASSERT_EQ(m.source(g), hmira::vertex_handle(1u));
    const auto inner_a = m.next(m.opposite(g));  // 1 -> 5, becomes boundary
    const auto inner_b = m.prev(m.opposite(h));  // 5 -> 4, becomes boundary
    const auto bprev = m.prev(g), bnext = m.next(h);
    m.erase_face(f0);
    m.erase_edge(m.edge(h));
    m.erase_edge(m.edge(g));
    m.erase_vertex(v0);
    m.set_face(inner_a, {});
    m.set_face(inner_b, {});
    m.set_next(bprev, inner_a);
    m.set_next(inner_a, inner_b);
    m.set_next(inner_b, bnext);
    m.set_vertex_halfedge(m.source(inner_a), inner_a);
    m.set_vertex_halfedge(m.source(inner_b), inner_b);
    m.set_vertex_halfedge(m.source(bnext), bnext);
    ASSERT_TRUE(hmira_test::is_valid(m)) << "hand-made removal of a corner face";
    const auto faces = m.face_count();
    m.collect_garbage();
    EXPECT_FALSE(m.has_garbage());
    EXPECT_EQ(m.face_count(), faces);
    EXPECT_EQ(m.vertex_count(), 15u);
    EXPECT_TRUE(hmira_test::is_valid(m));
}

TEST(WingedEdge, change_count_grows_with_every_mutation) {
    winged_edge_mesh m;
    auto c = m.change_count();
    auto a = m.add_vertex({0, 0, 0});
    EXPECT_GT(m.change_count(), c);
    c = m.change_count();
    auto b = m.add_vertex({1, 0, 0}), d = m.add_vertex({0, 1, 0});
    ASSERT_TRUE(m.add_face({a, b, d}));
    EXPECT_GT(m.change_count(), c);
}

}  // namespace
