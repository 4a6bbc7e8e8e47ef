// Both adapter flavours give the native answer: on random meshes with boundaries and
// isolated vertices, every adjacency of a face_vertex_mesh seen through brute_force_* and
// indexed_* adapters equals, as a multiset, the halfedge_mesh's own answer for the same faces.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <utility>
#include <vector>

#include <hmira/adapters/adapted_mesh.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>
#include <hmira/meshes/winged_edge_mesh.hpp>

#include "adapters/random_meshes.hpp"
#include "support/checks.hpp"

namespace {

using fvm = hmira::face_vertex_mesh;
using hem = hmira::halfedge_mesh;

template <class M, class R>
std::multiset<std::size_t> vertex_set(const M& m, R&& range) {
    using T = hmira::default_traits<M>;
    std::multiset<std::size_t> out;
    for (auto v : range) out.insert(T::vertex_index(m, v));
    return out;
}
template <class M, class R>
std::multiset<std::size_t> face_set(const M& m, R&& range) {
    using T = hmira::default_traits<M>;
    std::multiset<std::size_t> out;
    for (auto f : range) out.insert(T::face_index(m, f));
    return out;
}
template <class M, class R>
std::multiset<std::pair<std::size_t, std::size_t>> edge_set(const M& m, R&& range) {
    using T = hmira::default_traits<M>;
    std::multiset<std::pair<std::size_t, std::size_t>> out;
    for (auto e : range) {
        const auto ends = T::edge_vertices(m, e);
        auto a = T::vertex_index(m, ends[0]), b = T::vertex_index(m, ends[1]);
        out.insert({std::min(a, b), std::max(a, b)});
    }
    return out;
}

struct pair_of_models {
    fvm face_vertex;
    hem halfedge;
};

// Same faces in the same order: face i of one is face i of the other.
pair_of_models build(unsigned seed) {
    pair_of_models p;
    const auto g = hmira_test::random_mesh(seed);
    EXPECT_TRUE(hmira_test::add_face_list(p.face_vertex, g));
    EXPECT_TRUE(hmira_test::add_face_list(p.halfedge, g));
    EXPECT_TRUE(hmira_test::is_valid(p.halfedge, {.relaxed = true}));
    return p;
}

template <class Adapted>
void expect_same_as_native(const Adapted& a, const hem& native) {
    using A = hmira::default_traits<Adapted>;
    using N = hmira::default_traits<hem>;
    const auto& m = a.base();
    std::size_t isolated = 0, boundary = 0;
    for (auto v : A::vertices(a)) {
        const auto nv = hmira::vertex_handle(static_cast<std::uint32_t>(A::vertex_index(a, v)));
        const auto native_ring = vertex_set(native, N::adjacent_vertices(native, nv));
        isolated += native_ring.empty();
        boundary += native.is_boundary(nv) && !native_ring.empty();
        ASSERT_EQ(vertex_set(m, A::adjacent_vertices(a, v)), native_ring) << "vertex " << A::vertex_index(a, v);
        ASSERT_EQ(face_set(m, A::vertex_faces(a, v)), face_set(native, N::vertex_faces(native, nv)));
        ASSERT_EQ(edge_set(a, A::vertex_edges(a, v)), edge_set(native, N::vertex_edges(native, nv)));
    }
    EXPECT_GT(isolated, 0u) << "the random mesh must contain isolated vertices";
    EXPECT_GT(boundary, 0u) << "the random mesh must have a boundary";
    for (auto f : A::faces(a)) {
        const auto nf = hmira::face_handle(static_cast<std::uint32_t>(A::face_index(a, f)));
        ASSERT_EQ(face_set(m, A::adjacent_faces(a, f)), face_set(native, N::adjacent_faces(native, nf)));
    }
    EXPECT_EQ(A::edge_count(a), N::edge_count(native));
    EXPECT_EQ(edge_set(a, A::edges(a)), edge_set(native, N::edges(native)));
}

TEST(AdapterEquivalence, brute_force_adapters_give_the_native_halfedge_answers_as_multisets) {
    for (unsigned seed = 1; seed <= 6; ++seed) {
        SCOPED_TRACE(seed);
        auto p = build(seed);
        const hmira::with_brute_force_adjacency<fvm> a(p.face_vertex);
        expect_same_as_native(a, p.halfedge);
    }
}

TEST(AdapterEquivalence, indexed_adapters_give_the_native_halfedge_answers_as_multisets) {
    for (unsigned seed = 1; seed <= 12; ++seed) {
        SCOPED_TRACE(seed);
        auto p = build(seed);
        const hmira::with_indexed_adjacency<fvm> a(p.face_vertex);
        expect_same_as_native(a, p.halfedge);
    }
}

TEST(AdapterEquivalence, adapters_forced_onto_a_halfedge_mesh_agree_with_its_own_operations) {
    for (unsigned seed = 20; seed <= 23; ++seed) {
        SCOPED_TRACE(seed);
        auto p = build(seed);
        const hmira::with_indexed_adjacency<hem> indexed(p.halfedge);
        expect_same_as_native(indexed, p.halfedge);
        const hmira::with_brute_force_adjacency<hem> brute(p.halfedge);
        expect_same_as_native(brute, p.halfedge);
    }
}

TEST(AdapterEquivalence, adapters_on_a_winged_edge_mesh_agree_with_its_native_records) {
    const auto g = hmira_test::random_mesh(31);
    hmira::winged_edge_mesh w;
    ASSERT_TRUE(hmira_test::add_face_list(w, g));
    const hmira::with_indexed_adjacency<hmira::winged_edge_mesh> a(w);
    using A = hmira::default_traits<decltype(a)>;
    using N = hmira::default_traits<hmira::winged_edge_mesh>;
    for (auto v : w.vertices()) {
        EXPECT_EQ(vertex_set(w, A::adjacent_vertices(a, v)), vertex_set(w, N::adjacent_vertices(w, v)));
        EXPECT_EQ(face_set(w, A::vertex_faces(a, v)), face_set(w, N::vertex_faces(w, v)));
    }
    for (auto f : w.faces()) EXPECT_EQ(face_set(w, A::adjacent_faces(a, f)), face_set(w, N::adjacent_faces(w, f)));
}

}  // namespace
