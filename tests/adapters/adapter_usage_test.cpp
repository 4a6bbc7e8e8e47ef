// How adapters are used: an algorithm that needs vertex adjacency runs on face_vertex_mesh
// through either flavour; an indexed adapter refuses to answer once the mesh has changed;
// nothing returned dangles; the face-normal flip keeps winding and stored normal together.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <hmira/adapters/adapted_mesh.hpp>
#include <hmira/adapters/face_normal_flip.hpp>
#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/orientation/flip_normals.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

#include "adapters/random_meshes.hpp"
#include "support/checks.hpp"

namespace {

using fvm = hmira::face_vertex_mesh;

// A small algorithm written against vertex_adjacency_mesh only: the centroid of each
// vertex's neighbours (one Laplacian step's target).
template <class M, class T = hmira::default_traits<M>>
    requires hmira::vertex_adjacency_mesh<M, T> && hmira::positioned_mesh<M, T> && hmira::vertex_index_mesh<M, T>
std::vector<hmira::vec3<double>> neighbour_centroids(const M& m) {
    std::vector<hmira::vec3<double>> out(T::vertex_index_bound(m));
    for (auto v : T::vertices(m)) {
        hmira::vec3<double> sum{};
        double n = 0;
        for (auto w : T::adjacent_vertices(m, v)) {
            sum += T::position(m, w);
            n += 1;
        }
        out[T::vertex_index(m, v)] = n > 0 ? sum / n : T::position(m, v);
    }
    return out;
}

static_assert(!hmira::vertex_adjacency_mesh<fvm>, "face-vertex has no adjacency of its own");
static_assert(hmira::vertex_adjacency_mesh<hmira::with_indexed_adjacency<fvm>>);
static_assert(hmira::vertex_adjacency_mesh<hmira::with_brute_force_adjacency<fvm>>);
static_assert(hmira::vertex_face_adjacency_mesh<hmira::with_adjacency<fvm>>);
static_assert(hmira::vertex_edge_adjacency_mesh<hmira::with_adjacency<fvm>>);
static_assert(hmira::face_adjacency_mesh<hmira::with_adjacency<fvm>>);
static_assert(hmira::edge_list_mesh<hmira::with_brute_force_adjacency<fvm>>);
static_assert(hmira::face_vertex_range_mesh<hmira::with_adjacency<fvm>>);
static_assert(hmira::mesh_builder<hmira::with_adjacency<fvm>>);
static_assert(std::is_same_v<hmira::with_adjacency<fvm>, hmira::with_indexed_adjacency<fvm>>,
              "documented default: indexed");

// Asking a temporary adapted mesh would return views into an index about to be destroyed.
template <class W>
concept rvalue_query_compiles =
    requires(W&& w, hmira::vertex_handle v) { hmira::default_traits<W>::adjacent_vertices(std::move(w), v); };
static_assert(!rvalue_query_compiles<hmira::with_indexed_adjacency<fvm>>);
static_assert(!rvalue_query_compiles<hmira::with_brute_force_adjacency<fvm>>);

TEST(AdapterUsage, an_algorithm_needing_vertex_adjacency_runs_on_face_vertex_through_both_flavours) {
    fvm m;
    ASSERT_TRUE(hmira_test::add_face_list(m, hmira_test::random_mesh(3)));
    const auto brute = hmira::adapt_brute_force(m);
    const auto indexed = hmira::adapt_indexed(m);
    const auto a = neighbour_centroids(brute), b = neighbour_centroids(indexed);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_NEAR(a[i].x, b[i].x, 1e-12);
        EXPECT_NEAR(a[i].y, b[i].y, 1e-12);
        EXPECT_NEAR(a[i].z, b[i].z, 1e-12);
    }
}

TEST(AdapterUsage, an_indexed_adapter_used_after_the_mesh_changed_throws_instead_of_answering) {
    fvm m;
    ASSERT_TRUE(hmira::generate_cube(m));
    auto a = hmira::adapt_indexed(m);
    using A = hmira::default_traits<decltype(a)>;
    const auto v = hmira::vertex_handle(0u);
    EXPECT_EQ(std::ranges::distance(A::adjacent_vertices(a, v)), 3);
    const auto extra = m.add_vertex({5, 5, 5});
    ASSERT_TRUE(m.add_face({v, hmira::vertex_handle(2u), extra}));
    EXPECT_THROW((void)A::adjacent_vertices(a, v), hmira::hmira_error);
    EXPECT_THROW((void)A::vertex_faces(a, v), hmira::hmira_error);
    EXPECT_THROW((void)A::adjacent_faces(a, hmira::face_handle(0u)), hmira::hmira_error);
    EXPECT_THROW((void)A::edges(a), hmira::hmira_error);
    EXPECT_THROW((void)A::edge_count(a), hmira::hmira_error);
    try {
        (void)A::adjacent_vertices(a, v);
    } catch (const hmira::hmira_error& e) {
        EXPECT_NE(std::string(e.what()).find("changed"), std::string::npos) << e.what();
    }
    a.refresh();
    EXPECT_EQ(std::ranges::distance(A::adjacent_vertices(a, v)), 5);  // 1, 3, 4 and now 2 and the new vertex
}

TEST(AdapterUsage, a_brute_force_adapter_always_answers_for_the_mesh_as_it_is_now) {
    fvm m;
    ASSERT_TRUE(hmira::generate_cube(m));
    const auto a = hmira::adapt_brute_force(m);
    using A = hmira::default_traits<decltype(a)>;
    const auto v = hmira::vertex_handle(0u);
    EXPECT_EQ(A::adjacent_vertices(a, v).size(), 3u);
    const auto extra = m.add_vertex({5, 5, 5});
    ASSERT_TRUE(m.add_face({v, hmira::vertex_handle(2u), extra}));
    EXPECT_EQ(A::adjacent_vertices(a, v).size(), 5u);
}

TEST(AdapterUsage, an_indexed_adapter_refuses_a_mesh_it_was_not_built_from) {
    fvm m1, m2;
    ASSERT_TRUE(hmira::generate_cube(m1));
    ASSERT_TRUE(hmira::generate_cube(m2));
    const hmira::indexed_vertex_adjacency<fvm> index(m1);
    EXPECT_NO_THROW((void)index.adjacent_vertices(m1, hmira::vertex_handle(0u)));
    EXPECT_THROW((void)index.adjacent_vertices(m2, hmira::vertex_handle(0u)), hmira::hmira_error);
}

TEST(AdapterUsage, answers_outlive_the_query_and_a_moved_adapted_mesh_keeps_answering) {
    fvm m;
    ASSERT_TRUE(hmira_test::add_face_list(m, hmira_test::grid(4, 4)));
    auto a = hmira::adapt_indexed(m);
    using A = hmira::default_traits<decltype(a)>;
    auto ring = A::adjacent_vertices(a, hmira::vertex_handle(6u));  // a span into a's index
    auto moved = std::move(a);  // std::vector storage moves, so the span stays valid
    std::multiset<std::uint32_t> got;
    for (auto v : ring) got.insert(v.index);
    EXPECT_EQ(got, (std::multiset<std::uint32_t>{1, 5, 7, 11}));
    auto brute = hmira::adapt_brute_force(m);
    using B = hmira::default_traits<decltype(brute)>;
    auto owned = B::adjacent_vertices(brute, hmira::vertex_handle(6u));  // an owning vector
    EXPECT_EQ(owned.size(), 4u);
}

// Independent of the library: Newell's normal of a face, from its winding.
template <class M>
hmira::vec3<double> newell(const M& m, hmira::face_handle f) {
    hmira::vec3<double> n{};
    const auto fv = m.face_vertices(f);
    for (std::size_t i = 0; i < fv.size(); ++i) {
        const auto p = m.position(fv[i]), q = m.position(fv[(i + 1) % fv.size()]);
        n.x += (p.y - q.y) * (p.z + q.z);
        n.y += (p.z - q.z) * (p.x + q.x);
        n.z += (p.x - q.x) * (p.y + q.y);
    }
    const double len = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    return n / len;
}

TEST(AdapterUsage, face_normal_flip_reverses_the_winding_and_negates_the_stored_normal_together) {
    fvm m;
    ASSERT_TRUE(hmira::generate_dodecahedron(m));
    auto normals = m.add_face_property<hmira::vec3<double>>("normal");
    for (auto f : m.faces()) normals[f] = newell(m, f);
    const auto faces_before = hmira_test::canonical_faces(m);
    auto a = hmira::with_face_normal_flip(m, normals);
    EXPECT_EQ(hmira::flip_normals(a), m.face_count());
    ASSERT_TRUE(hmira_test::is_valid(m));
    EXPECT_NE(hmira_test::canonical_faces(m), faces_before) << "the winding must change, not only the normal";
    EXPECT_LT(hmira_test::signed_volume(m), 0);
    for (auto f : m.faces()) {
        const auto expected = newell(m, f);
        EXPECT_NEAR(normals[f].x, expected.x, 1e-12);
        EXPECT_NEAR(normals[f].y, expected.y, 1e-12);
        EXPECT_NEAR(normals[f].z, expected.z, 1e-12);
    }
    hmira::flip_normals(a);
    EXPECT_EQ(hmira_test::canonical_faces(m), faces_before);
}

}  // namespace
