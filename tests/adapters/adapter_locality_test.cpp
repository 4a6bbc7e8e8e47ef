// Locality, counted rather than timed: an instrumented traits class counts every primitive
// operation, and a local query on halfedge_mesh or through an indexed adapter performs the
// same number of them on a small and on a 100x larger mesh. Brute force shows the contrast.
#include <gtest/gtest.h>

#include <cstddef>

#include <hmira/adapters/adapted_mesh.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "support/checks.hpp"
#include "support/shapes.hpp"

namespace {

inline std::size_t operations = 0;

// Every operation of the base traits, counted once per call.
template <class B>
struct counting_traits : B {
    using typename B::face_handle;
    using typename B::vertex_handle;
    template <class M>
    static auto vertices(const M& m) {
        ++operations;
        return B::vertices(m);
    }
    template <class M>
    static auto faces(const M& m) {
        ++operations;
        return B::faces(m);
    }
    template <class M, class F>
    static auto face_vertices(const M& m, F f) {
        ++operations;
        return B::face_vertices(m, f);
    }
    template <class M, class V>
    static auto vertex_index(const M& m, V v) {
        ++operations;
        return B::vertex_index(m, v);
    }
    template <class M, class F>
    static auto face_index(const M& m, F f) {
        ++operations;
        return B::face_index(m, f);
    }
    template <class M>
    static auto change_count(const M& m) {
        ++operations;
        return B::change_count(m);
    }
    template <class M, class H>
    static auto next(const M& m, H h) {
        ++operations;
        return B::next(m, h);
    }
    template <class M, class H>
    static auto opposite(const M& m, H h) {
        ++operations;
        return B::opposite(m, h);
    }
    template <class M, class H>
    static auto target(const M& m, H h) {
        ++operations;
        return B::target(m, h);
    }
    template <class M, class V>
    static auto vertex_halfedge(const M& m, V v) {
        ++operations;
        return B::vertex_halfedge(m, v);
    }
};

// One-ring through halfedge navigation only, written against the traits.
template <class M, class T>
std::size_t one_ring_size(const M& m, typename T::vertex_handle v) {
    const auto start = T::vertex_halfedge(m, v);
    auto h = start;
    std::size_t n = 0;
    do {
        (void)T::target(m, h);
        ++n;
        h = T::next(m, T::opposite(m, h));
    } while (h != start);
    return n;
}

// The interior vertex at grid cell (2, 2), whatever the grid size.
std::size_t interior_vertex(std::size_t nx) { return 2 * (nx + 1) + 2; }

template <class M>
M grid_mesh(std::size_t n) {
    M m;
    EXPECT_TRUE(hmira_test::add_face_list(m, hmira_test::grid(n, n, true)));
    return m;
}

TEST(Locality, halfedge_one_ring_costs_the_same_number_of_operations_on_small_and_large_meshes) {
    using CT = counting_traits<hmira::mesh_traits<hmira::halfedge_mesh>>;
    std::size_t counts[2];
    const std::size_t sizes[2] = {6, 60};
    for (int i = 0; i < 2; ++i) {
        const auto m = grid_mesh<hmira::halfedge_mesh>(sizes[i]);
        operations = 0;
        EXPECT_EQ((one_ring_size<hmira::halfedge_mesh, CT>(m, hmira::vertex_handle(interior_vertex(sizes[i])))), 6u);
        counts[i] = operations;
    }
    EXPECT_GT(counts[0], 0u) << "the instrumentation must see the query";
    EXPECT_EQ(counts[0], counts[1]);
}

TEST(Locality, indexed_adapter_queries_cost_the_same_number_of_operations_on_small_and_large_meshes) {
    using CT = counting_traits<hmira::mesh_traits<hmira::face_vertex_mesh>>;
    using W = hmira::with_indexed_adjacency<hmira::face_vertex_mesh, CT>;
    using A = hmira::default_traits<W>;
    std::size_t counts[2];
    const std::size_t sizes[2] = {6, 60};
    for (int i = 0; i < 2; ++i) {
        auto m = grid_mesh<hmira::face_vertex_mesh>(sizes[i]);
        const W w(m);  // the O(F) build is not part of the query
        const auto v = hmira::vertex_handle(interior_vertex(sizes[i]));
        operations = 0;
        EXPECT_EQ(std::ranges::distance(A::adjacent_vertices(w, v)), 6);
        EXPECT_EQ(std::ranges::distance(A::vertex_faces(w, v)), 6);
        EXPECT_EQ(std::ranges::distance(A::vertex_edges(w, v)), 6);
        EXPECT_EQ(std::ranges::distance(A::adjacent_faces(w, hmira::face_handle(7u))), 3);
        counts[i] = operations;
    }
    EXPECT_GT(counts[0], 0u) << "the instrumentation must see the queries (staleness checks at least)";
    EXPECT_EQ(counts[0], counts[1]);
}

TEST(Locality, brute_force_adapter_queries_grow_with_the_mesh_as_documented) {
    using CT = counting_traits<hmira::mesh_traits<hmira::face_vertex_mesh>>;
    using W = hmira::with_brute_force_adjacency<hmira::face_vertex_mesh, CT>;
    using A = hmira::default_traits<W>;
    std::size_t counts[2];
    const std::size_t sizes[2] = {6, 60};
    for (int i = 0; i < 2; ++i) {
        auto m = grid_mesh<hmira::face_vertex_mesh>(sizes[i]);
        const W w(m);
        operations = 0;
        EXPECT_EQ(A::adjacent_vertices(w, hmira::vertex_handle(interior_vertex(sizes[i]))).size(), 6u);
        counts[i] = operations;
    }
    // 100x the faces: at least 50x the operations (O(F_all) per query).
    EXPECT_GT(counts[1], 50 * counts[0]);
}

}  // namespace
