// hmira on OpenMesh objects, in place: what hmira algorithms do is visible through OpenMesh's
// own API, hmira's answers equal OpenMesh's circulators, and failures are errors, not
// invalid handles.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include <hmira/adapters/adapted_mesh.hpp>
#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/orientation/flip_normals.hpp>
#include <hmira/algorithms/topology/mesh_topology.hpp>
#include <hmira/interop/openmesh.hpp>

#include "support/checks.hpp"
#include "support/shapes.hpp"

namespace {

using poly = OpenMesh::PolyMesh_ArrayKernelT<>;
using tri = OpenMesh::TriMesh_ArrayKernelT<>;
using PT = hmira::mesh_traits<poly>;

static_assert(hmira::halfedge_mutable_mesh<poly> && hmira::halfedge_index_mesh<poly>);
static_assert(hmira::polygon_mesh_builder<poly>);
static_assert(hmira::mesh_builder<tri> && !hmira::polygon_mesh_builder<tri>, "TriMesh is triangles_only");
static_assert(hmira::halfedge_mutable_mesh<tri>);
static_assert(!hmira::change_counted_mesh<poly>, "OpenMesh keeps no change counter");
static_assert(!hmira::face_reversible_mesh<poly>);
static_assert(std::is_same_v<PT::vertex_handle, OpenMesh::VertexHandle>, "OpenMesh's own handles, no wrapper");

// Built through OpenMesh's API only: the test's own construction.
poly native_grid(int nx, int ny) {
    poly m;
    std::vector<OpenMesh::VertexHandle> v;
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) v.push_back(m.add_vertex(poly::Point(float(i), float(j), 0.f)));
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const int a = j * (nx + 1) + i;
            m.add_face(v[a], v[a + 1], v[a + nx + 2], v[a + nx + 1]);
        }
    return m;
}

// The traits without their one-pass reverse_orientation: flip_normals's generic pass.
struct traits_without_reverse_orientation : hmira::mesh_traits<poly> {
    static void reverse_orientation(poly&) = delete;
};

// Every link of every element, for comparing two meshes exactly.
std::vector<int> links(const poly& m) {
    std::vector<int> out;
    for (auto h : m.halfedges())
        for (int x : {m.next_halfedge_handle(h).idx(), m.prev_halfedge_handle(h).idx(), m.to_vertex_handle(h).idx(),
                      m.face_handle(h).idx()})
            out.push_back(x);
    for (auto v : m.vertices()) out.push_back(m.halfedge_handle(v).idx());
    for (auto f : m.faces()) out.push_back(m.halfedge_handle(f).idx());
    return out;
}

TEST(OpenMeshInterop, the_one_pass_flip_links_as_the_generic_pass_does_and_twice_restores_the_mesh) {
    poly m = native_grid(4, 3);
    // A hole in the middle, so that inner boundary vertices are flipped too; deleted elements
    // (OpenMesh's status) stay as they are.
    m.request_face_status();
    m.request_edge_status();
    m.request_halfedge_status();
    m.request_vertex_status();
    m.delete_face(poly::FaceHandle(6), false);
    const poly original = m;
    poly generic = m;
    EXPECT_EQ(hmira::flip_normals(m), 11u);
    EXPECT_EQ((hmira::flip_normals<poly, traits_without_reverse_orientation>(generic)), 11u);
    ASSERT_TRUE(hmira_test::is_valid(m));
    EXPECT_EQ(links(m), links(generic));
    EXPECT_NE(links(m), links(original));
    for (auto v : m.vertices()) EXPECT_TRUE(m.is_boundary(v) == m.is_boundary(m.halfedge_handle(v)));
    EXPECT_EQ(hmira::flip_normals(m), 11u);
    EXPECT_EQ(links(m), links(original));
}

TEST(OpenMeshInterop, flip_normals_runs_on_the_users_object_and_openmesh_sees_the_reversed_faces) {
    poly m = native_grid(4, 3);
    std::vector<std::vector<int>> before;
    for (auto f : m.faces()) {
        std::vector<int> loop;
        for (auto v : m.fv_range(f)) loop.push_back(v.idx());
        before.push_back(loop);
    }
    const poly* address = &m;
    EXPECT_EQ(hmira::flip_normals(m), 12u);
    EXPECT_EQ(address, &m);
    ASSERT_TRUE(hmira_test::is_valid(m));
    m.request_face_normals();
    m.update_face_normals();
    for (auto f : m.faces()) {
        EXPECT_NEAR(m.normal(f)[2], -1.f, 1e-6f) << "OpenMesh's own normal points down after the flip";
        std::vector<int> loop;
        for (auto v : m.fv_range(f)) loop.push_back(v.idx());
        auto expected = before[f.idx()];
        std::reverse(expected.begin(), expected.end());
        // Same cycle in reverse: compare as rotations.
        auto it = std::find(loop.begin(), loop.end(), expected[0]);
        ASSERT_NE(it, loop.end());
        std::rotate(loop.begin(), it, loop.end());
        EXPECT_EQ(loop, expected);
    }
    // OpenMesh's own boundary query still works: the outgoing halfedges were re-pointed.
    for (auto v : m.vertices()) EXPECT_TRUE(m.is_boundary(v) == m.is_boundary(m.halfedge_handle(v)));
}

TEST(OpenMeshInterop, hmira_adjacency_equals_openmesh_circulators_as_multisets) {
    poly m = native_grid(6, 5);
    m.add_vertex(poly::Point(9, 9, 9));  // isolated
    for (auto v : m.vertices()) {
        std::multiset<int> mine, theirs;
        for (auto w : PT::adjacent_vertices(m, v)) mine.insert(w.idx());
        for (auto w : m.vv_range(v)) theirs.insert(w.idx());
        EXPECT_EQ(mine, theirs);
        std::multiset<int> mf, tf;
        for (auto f : PT::vertex_faces(m, v)) mf.insert(f.idx());
        for (auto f : m.vf_range(v)) tf.insert(f.idx());
        EXPECT_EQ(mf, tf);
    }
    for (auto f : m.faces()) {
        std::multiset<int> mine, theirs;
        for (auto g : PT::adjacent_faces(m, f)) mine.insert(g.idx());
        for (auto g : m.ff_range(f)) theirs.insert(g.idx());
        EXPECT_EQ(mine, theirs);
    }
}

TEST(OpenMeshInterop, brute_force_adapters_work_on_openmesh_and_agree_with_it) {
    poly m = native_grid(3, 3);
    const auto a = hmira::adapt_brute_force(m);
    using A = hmira::default_traits<decltype(a)>;
    for (auto v : m.vertices()) {
        std::multiset<int> mine, theirs;
        for (auto w : A::adjacent_vertices(a, v)) mine.insert(w.idx());
        for (auto w : m.vv_range(v)) theirs.insert(w.idx());
        EXPECT_EQ(mine, theirs);
    }
}

TEST(OpenMeshInterop, a_refused_face_is_an_error_and_leaves_the_mesh_unchanged) {
    poly m;
    ASSERT_TRUE(hmira::generate_tetrahedron(m));
    std::vector<OpenMesh::VertexHandle> vs(m.vertices().begin(), m.vertices().end());
    const auto faces = m.n_faces();
    const std::array<OpenMesh::VertexHandle, 3> again{vs[0], vs[1], vs[2]};
    auto r = PT::add_face(m, again);
    ASSERT_FALSE(r);
    EXPECT_EQ(m.n_faces(), faces);
    const std::array<OpenMesh::VertexHandle, 3> repeated{vs[0], vs[0], vs[2]};
    EXPECT_EQ(PT::add_face(m, repeated).error().code, hmira::errc::degenerate_face);
    const std::array<OpenMesh::VertexHandle, 3> missing{vs[0], OpenMesh::VertexHandle(99), vs[2]};
    EXPECT_EQ(PT::add_face(m, missing).error().code, hmira::errc::invalid_handle);
    EXPECT_TRUE(hmira_test::is_valid(m));
}

// hmira's rings on OpenMesh step like OpenMesh's circulators, without a step guard, so a face
// loop whose next links never return to its start is endless: validate must stop and say so.
TEST(OpenMeshInterop, validate_reports_a_face_loop_that_never_closes_instead_of_following_it) {
    poly m = native_grid(2, 2);
    const auto f = *m.faces().begin();
    const auto h1 = m.next_halfedge_handle(m.halfedge_handle(f));
    m.set_next_halfedge_handle(h1, h1);  // the loop from f's halfedge now cycles at h1 for ever
    const auto problems = hmira::validate(m);
    const bool named = std::any_of(problems.begin(), problems.end(), [&](const hmira::mesh_problem& p) {
        return p.kind == hmira::problem_kind::broken_link &&
               p.message.find("face " + std::to_string(f.idx()) + ": its loop does not return") == 0;
    });
    EXPECT_TRUE(named) << "problems found: " << problems.size();
}

TEST(OpenMeshInterop, a_trimesh_refuses_a_quad_instead_of_triangulating_it) {
    tri m;
    using TT = hmira::mesh_traits<tri>;
    std::array<OpenMesh::VertexHandle, 4> q;
    for (int i = 0; i < 4; ++i) q[i] = TT::add_vertex(m, {float(i % 2), float(i / 2), 0});
    std::swap(q[2], q[3]);
    auto r = TT::add_face(m, q);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, hmira::errc::unsupported);
    EXPECT_EQ(m.n_faces(), 0u);
}

TEST(OpenMeshInterop, erasing_requests_openmesh_status_and_hides_the_element) {
    poly m = native_grid(2, 2);
    ASSERT_FALSE(m.has_face_status());
    const auto f = OpenMesh::FaceHandle(0);
    PT::erase_face(m, f);
    EXPECT_TRUE(m.has_face_status()) << "the interop switched on OpenMesh's face status";
    EXPECT_TRUE(m.status(f).deleted());
    EXPECT_EQ(PT::face_count(m), 3u);
    for (auto g : PT::faces(m)) EXPECT_NE(g, f);
    PT::erase_edge(m, OpenMesh::EdgeHandle(0));
    EXPECT_TRUE(m.has_edge_status() && m.has_halfedge_status());
    EXPECT_EQ(PT::edge_count(m), m.n_edges() - 1);
    for (auto h : PT::halfedges(m)) EXPECT_NE(PT::edge(m, h), OpenMesh::EdgeHandle(0));
    PT::erase_vertex(m, OpenMesh::VertexHandle(0));
    EXPECT_TRUE(m.has_vertex_status());
    EXPECT_EQ(PT::vertex_count(m), 8u);
}

TEST(OpenMeshInterop, generated_solids_have_the_euler_characteristic_of_a_sphere_in_both_models) {
    poly p;
    tri t;
    ASSERT_TRUE(hmira::generate_icosahedron(p));
    ASSERT_TRUE(hmira::generate_icosahedron(t));
    ASSERT_TRUE(hmira::generate_dodecahedron(p));
    EXPECT_EQ(hmira::mesh_topology(p).components, 2u);
    EXPECT_EQ(hmira::euler_characteristic(p), 4);
    EXPECT_EQ(hmira::euler_characteristic(t), 2);
    EXPECT_TRUE(hmira_test::is_valid(t));
}

TEST(OpenMeshInterop, positions_round_trip_through_float) {
    poly m;
    const auto v = PT::add_vertex(m, {1.5f, -2.25f, 3.0f});
    EXPECT_EQ(m.point(v), poly::Point(1.5f, -2.25f, 3.0f));
    PT::set_position(m, v, {0.5f, 0.25f, -1.0f});
    const auto p = PT::position(m, v);
    EXPECT_EQ(p.x, 0.5f);
    EXPECT_EQ(p.y, 0.25f);
    EXPECT_EQ(p.z, -1.0f);
}

}  // namespace
