// flip_normals really reverses every face on every model: the winding changes, the volume
// changes sign, the mesh stays valid, and flipping twice gives back the original.
#include <gtest/gtest.h>

#include <hmira/algorithms/euler/euler.hpp>
#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/orientation/flip_normals.hpp>
#include <hmira/algorithms/topology/mesh_topology.hpp>

#include "support/checks.hpp"
#include "support/models.hpp"
#include "support/shapes.hpp"

namespace {

using namespace hmira;

template <class M>
class flip_normals_suite : public ::testing::Test {};
TYPED_TEST_SUITE(flip_normals_suite, hmira_test::all_models);

template <class M>
std::vector<M> sample_meshes() {
    std::vector<M> out;
    {
        M m;
        EXPECT_TRUE(generate_icosahedron(m));
        out.push_back(std::move(m));
    }
    {
        M m;  // open patch with two holes and a second component
        auto g =
            hmira_test::without_faces(hmira_test::grid(8, 6, true), [](std::size_t f) { return f == 20 || f == 61; });
        EXPECT_TRUE(hmira_test::add_face_list(m, g));
        EXPECT_TRUE(generate_octahedron(m, {.center = {20, 0, 0}}));
        out.push_back(std::move(m));
    }
    if constexpr (polygon_mesh_builder<M>) {
        M m;
        EXPECT_TRUE(hmira_test::add_face_list(m, hmira_test::torus(9, 7)));
        out.push_back(std::move(m));
        M q;
        EXPECT_TRUE(hmira_test::add_face_list(
            q, hmira_test::without_faces(hmira_test::grid(5, 5), [](std::size_t f) { return f == 12; })));
        out.push_back(std::move(q));
    }
    return out;
}

std::multiset<std::vector<std::size_t>> reversed(const std::multiset<std::vector<std::size_t>>& faces) {
    std::multiset<std::vector<std::size_t>> out;
    for (auto loop : faces) {
        std::reverse(loop.begin(), loop.end());
        std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
        out.insert(loop);
    }
    return out;
}

TYPED_TEST(flip_normals_suite, flip_reverses_every_face_loop_and_keeps_the_mesh_valid) {
    using M = TypeParam;
    if constexpr (!flip_normals_mesh<M>) {
        GTEST_SKIP() << "model cannot flip";
    } else {
        for (auto& mesh : sample_meshes<M>()) {
            const auto before = hmira_test::canonical_faces(mesh);
            const double volume = hmira_test::signed_volume(mesh);
            const auto topo = mesh_topology(mesh);
            EXPECT_EQ(flip_normals(mesh), default_traits<M>::face_count(mesh));
            ASSERT_TRUE(hmira_test::is_valid(mesh));
            EXPECT_EQ(hmira_test::canonical_faces(mesh), reversed(before));
            EXPECT_NEAR(hmira_test::signed_volume(mesh), -volume, 1e-6 * (1 + std::abs(volume)));
            const auto after = mesh_topology(mesh);
            EXPECT_EQ(after.euler_characteristic, topo.euler_characteristic);
            EXPECT_EQ(after.boundary_loops, topo.boundary_loops);
            EXPECT_EQ(after.genus, topo.genus);
        }
    }
}

TYPED_TEST(flip_normals_suite, flipping_twice_is_the_identity) {
    using M = TypeParam;
    if constexpr (flip_normals_mesh<M>) {
        for (auto& mesh : sample_meshes<M>()) {
            const auto before = hmira_test::canonical_faces(mesh);
            flip_normals(mesh);
            flip_normals(mesh);
            ASSERT_TRUE(hmira_test::is_valid(mesh));
            EXPECT_EQ(hmira_test::canonical_faces(mesh), before);
        }
    }
}

// A flipped halfedge mesh must still accept faces in the flipped orientation: the boundary
// links really were reversed, not just the face lists.
TEST(flip_normals, flipped_halfedge_boundary_accepts_faces_of_the_new_orientation) {
    halfedge_mesh m;
    std::vector<vertex_handle> v;
    auto g = hmira_test::grid(3, 3);
    auto missing = g.faces[4];
    g = hmira_test::without_faces(g, [](std::size_t f) { return f == 4; });
    ASSERT_TRUE(hmira_test::add_face_list(m, g, &v));
    flip_normals(m);
    auto wrong = m.add_face({v[missing[0]], v[missing[1]], v[missing[2]], v[missing[3]]});
    EXPECT_FALSE(wrong);
    auto right = m.add_face({v[missing[3]], v[missing[2]], v[missing[1]], v[missing[0]]});
    ASSERT_TRUE(right) << right.error().message;
    EXPECT_TRUE(hmira_test::is_valid(m));
    EXPECT_EQ(mesh_topology(m).boundary_loops, 1u);
}

// halfedge_mesh flips in one pass over its halfedge array (traits' reverse_orientation); the
// generic algorithm (re-linking through set_next) must give exactly the same links, boundary
// vertices included, also with deleted elements waiting for collection.
struct generic_flip_traits : mesh_traits<halfedge_mesh> {
    static void reverse_orientation(halfedge_mesh&) = delete;  // forces the generic algorithm
};

TEST(flip_normals, one_pass_halfedge_flip_equals_the_generic_algorithm) {
    auto meshes = sample_meshes<halfedge_mesh>();
    {
        halfedge_mesh m;  // with garbage: a face and its edges deleted, not collected
        ASSERT_TRUE(hmira_test::add_face_list(m, hmira_test::grid(6, 5)));
        const face_handle f(7);
        for (auto h : m.face_halfedges(f))
            if (!m.is_boundary(m.opposite(h))) {
                ASSERT_TRUE(kill_edge_face(m, h));  // merges the neighbour in; edge and face deleted
                break;
            }
        ASSERT_TRUE(m.has_garbage());
        meshes.push_back(std::move(m));
    }
    for (auto& mesh : meshes) {
        halfedge_mesh fast = mesh, slow = mesh;
        EXPECT_EQ(flip_normals(fast), mesh.face_count());
        EXPECT_EQ((flip_normals<halfedge_mesh, generic_flip_traits>(slow)), mesh.face_count());
        ASSERT_TRUE(hmira_test::is_valid(fast));
        for (auto h : mesh.halfedges()) {
            EXPECT_EQ(fast.target(h), slow.target(h)) << h.index;
            EXPECT_EQ(fast.next(h), slow.next(h)) << h.index;
            EXPECT_EQ(fast.prev(h), slow.prev(h)) << h.index;
            EXPECT_EQ(fast.face(h), slow.face(h)) << h.index;
            EXPECT_EQ(fast.target(h), mesh.source(h)) << h.index;  // really reversed
        }
        for (auto v : mesh.vertices()) {
            EXPECT_EQ(fast.vertex_halfedge(v), slow.vertex_halfedge(v)) << v.index;
            EXPECT_EQ(fast.is_boundary(v), mesh.is_boundary(v)) << v.index;
        }
        EXPECT_GT(fast.change_count(), mesh.change_count());
    }
}

}  // namespace
