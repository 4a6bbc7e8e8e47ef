// Locality of the Euler operators: a traits class that forwards to halfedge_mesh's traits and
// counts every primitive call (navigation and raw mutation) shows that each operator's count
// stays within its thesis bound, O(1) or O(face degree) / O(ring size), and does not grow
// with the size of the mesh.

#include <gtest/gtest.h>

#include <cstddef>

#include <hmira/algorithms/euler/euler.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "algorithms/euler/euler_support.hpp"

namespace {

using hmira::halfedge_mesh;
using base = hmira::mesh_traits<halfedge_mesh>;

/// mesh_traits<halfedge_mesh>, counting each primitive operation the operators call.
struct counting_traits : base {
    static inline std::size_t calls = 0;
    using H = base::halfedge_handle;
    using V = base::vertex_handle;
    using F = base::face_handle;
    using E = base::edge_handle;

    static H next(const halfedge_mesh& m, H h) {
        ++calls;
        return base::next(m, h);
    }
    static H prev(const halfedge_mesh& m, H h) {
        ++calls;
        return base::prev(m, h);
    }
    static H opposite(const halfedge_mesh& m, H h) {
        ++calls;
        return base::opposite(m, h);
    }
    static V target(const halfedge_mesh& m, H h) {
        ++calls;
        return base::target(m, h);
    }
    static F face(const halfedge_mesh& m, H h) {
        ++calls;
        return base::face(m, h);
    }
    static E edge(const halfedge_mesh& m, H h) {
        ++calls;
        return base::edge(m, h);
    }
    static H vertex_halfedge(const halfedge_mesh& m, V v) {
        ++calls;
        return base::vertex_halfedge(m, v);
    }
    static H face_halfedge(const halfedge_mesh& m, F f) {
        ++calls;
        return base::face_halfedge(m, f);
    }
    static auto inner_rings(const halfedge_mesh& m, F f) {
        ++calls;
        return base::inner_rings(m, f);
    }
    static auto position(const halfedge_mesh& m, V v) {
        ++calls;
        return base::position(m, v);
    }

    static void set_next(halfedge_mesh& m, H h, H n) {
        ++calls;
        base::set_next(m, h, n);
    }
    static void set_target(halfedge_mesh& m, H h, V v) {
        ++calls;
        base::set_target(m, h, v);
    }
    static void set_face(halfedge_mesh& m, H h, F f) {
        ++calls;
        base::set_face(m, h, f);
    }
    static void set_vertex_halfedge(halfedge_mesh& m, V v, H h) {
        ++calls;
        base::set_vertex_halfedge(m, v, h);
    }
    static void set_face_halfedge(halfedge_mesh& m, F f, H h) {
        ++calls;
        base::set_face_halfedge(m, f, h);
    }
    static H new_edge(halfedge_mesh& m, V a, V b) {
        ++calls;
        return base::new_edge(m, a, b);
    }
    static F new_face(halfedge_mesh& m) {
        ++calls;
        return base::new_face(m);
    }
    static V add_vertex(halfedge_mesh& m, const hmira::vec3<double>& p) {
        ++calls;
        return base::add_vertex(m, p);
    }
    static void erase_edge(halfedge_mesh& m, E e) {
        ++calls;
        base::erase_edge(m, e);
    }
    static void erase_face(halfedge_mesh& m, F f) {
        ++calls;
        base::erase_face(m, f);
    }
    static void erase_vertex(halfedge_mesh& m, V v) {
        ++calls;
        base::erase_vertex(m, v);
    }
    static void add_inner_ring(halfedge_mesh& m, F f, H h) {
        ++calls;
        base::add_inner_ring(m, f, h);
    }
    static void remove_inner_ring(halfedge_mesh& m, F f, H h) {
        ++calls;
        base::remove_inner_ring(m, f, h);
    }
};
using CT = counting_traits;
static_assert(hmira::euler_ring_mutable_mesh<halfedge_mesh, CT>);

/// Counts the primitive calls `op` makes.
template <class Op>
std::size_t count(Op op) {
    CT::calls = 0;
    op();
    return CT::calls;
}

/// An n x n quad grid; the halfedge entering the corner (c, c) of the face at (c, c).
struct grid_case {
    halfedge_mesh m;
    hmira::halfedge_handle corner;  // (c, c+1) -> (c, c): in face (c, c), next runs to (c+1, c)
    explicit grid_case(std::size_t n) : m(hmira_test::mesh_from<halfedge_mesh>(hmira_test::grid(n, n))) {
        const double c = double(n / 2);
        hmira::vertex_handle a, b;
        for (auto v : m.vertices()) {
            if (m.position(v) == hmira::vec3<double>{c, c + 1, 0}) a = v;
            if (m.position(v) == hmira::vec3<double>{c, c, 0}) b = v;
        }
        corner = m.find_halfedge(a, b);
    }
};

/// The counts of every operator on the interior face of an n x n grid.
struct op_counts {
    std::size_t mev, kev, mef, kef, kfmr, mfkr, mekr, kemr;
    bool operator==(const op_counts&) const = default;
};

op_counts measure(std::size_t n) {
    grid_case g(n);
    auto& m = g.m;
    op_counts c{};
    hmira::result<hmira::make_edge_vertex_result<halfedge_mesh, CT>> ev = hmira::error{};
    c.mev = count([&] { ev = hmira::make_edge_vertex<halfedge_mesh, CT>(m, g.corner, {0.3, 0.3, 0}); });
    EXPECT_TRUE(ev);
    c.kev = count([&] { EXPECT_TRUE((hmira::kill_edge_vertex<halfedge_mesh, CT>(m, ev->halfedge))); });
    const auto h1 = m.next(m.next(g.corner));
    hmira::result<hmira::make_edge_face_result<halfedge_mesh, CT>> ef = hmira::error{};
    c.mef = count([&] { ef = hmira::make_edge_face<halfedge_mesh, CT>(m, g.corner, h1); });
    EXPECT_TRUE(ef);
    c.kef = count([&] { EXPECT_TRUE((hmira::kill_edge_face<halfedge_mesh, CT>(m, ef->halfedge))); });
    // The face becomes a ring of its neighbour across the corner's edge, and back.
    const auto f = m.face(g.corner), host = m.face(m.opposite(g.corner));
    hmira::result<hmira::kill_face_make_ring_result<halfedge_mesh, CT>> fr = hmira::error{};
    c.kfmr = count([&] { fr = hmira::kill_face_make_ring<halfedge_mesh, CT>(m, f, host); });
    EXPECT_TRUE(fr);
    // Join the ring to the host's outer loop (its far corner) and split it off again.
    const auto outer = m.prev(m.prev(m.face_halfedge(host)));
    hmira::result<hmira::make_edge_kill_ring_result<halfedge_mesh, CT>> ek = hmira::error{};
    const auto ring_corner = m.next(fr->ring);
    c.mekr = count([&] { ek = hmira::make_edge_kill_ring<halfedge_mesh, CT>(m, outer, ring_corner); });
    EXPECT_TRUE(ek) << ek.error().message;
    c.kemr = count([&] { EXPECT_TRUE((hmira::kill_edge_make_ring<halfedge_mesh, CT>(m, ek->halfedge))); });
    c.mfkr = count([&] { EXPECT_TRUE((hmira::make_face_kill_ring<halfedge_mesh, CT>(m, fr->ring))); });
    EXPECT_TRUE(hmira_test::is_valid(m));
    return c;
}

TEST(euler_locality, primitive_counts_do_not_grow_with_mesh_size) {
    const auto small = measure(4), large = measure(200);  // 16 faces against 40 000
    EXPECT_EQ(small.mev, large.mev);
    EXPECT_EQ(small.kev, large.kev);
    EXPECT_EQ(small.mef, large.mef);
    EXPECT_EQ(small.kef, large.kef);
    EXPECT_EQ(small.kfmr, large.kfmr);
    EXPECT_EQ(small.mfkr, large.mfkr);
    EXPECT_EQ(small.mekr, large.mekr);
    EXPECT_EQ(small.kemr, large.kemr);
}

TEST(euler_locality, make_and_kill_edge_vertex_are_constant_time) {
    // O(1): a small constant (its independence of the mesh size is checked above).
    const auto c = measure(4);
    EXPECT_LE(c.mev, 12u);
    EXPECT_LE(c.kev, 20u);
}

TEST(euler_locality, face_and_ring_operators_are_linear_in_the_face_degree) {
    // On quads (degree 4, ring size 4) the bounds below are a few calls per side plus a
    // constant; the next test checks that they scale with the degree, not with the mesh.
    const auto c = measure(4);
    const std::size_t degree = 4, per_side = 6, constant = 30;
    EXPECT_LE(c.mef, per_side * degree + constant);
    EXPECT_LE(c.kef, per_side * degree + constant);
    EXPECT_LE(c.kfmr, per_side * degree + constant);
    EXPECT_LE(c.mfkr, per_side * degree + constant);
    EXPECT_LE(c.mekr, per_side * 2 * degree + constant);
    EXPECT_LE(c.kemr, per_side * 2 * degree + constant);
}

TEST(euler_locality, make_edge_face_grows_with_the_face_degree_only) {
    // Split an n-gon (a fan of struts closed into a polygon would be involved; a ring of n
    // edges made by make_edge_vertex along a wire and closed by make_edge_face is simpler).
    auto polygon_split_count = [](std::size_t n, std::size_t far_faces) {
        halfedge_mesh m = hmira_test::mesh_from<halfedge_mesh>(hmira_test::grid(far_faces, 1));
        auto v = hmira::make_vertex(m, {-5, -5, 0}).vertex;
        auto first = hmira::make_edge_vertex(m, v, {-5, -4, 0});
        auto last = first->halfedge;
        for (std::size_t i = 2; i < n; ++i)
            last = hmira::make_edge_vertex(m, last, {-5.0 + 0.01 * double(i), -3.0 - double(i), 0})->halfedge;
        auto poly = hmira::make_edge_face(m, last, m.opposite(first->halfedge));  // closes an n-gon
        EXPECT_TRUE(poly) << poly.error().message;
        // Split it between its first and middle corners.
        auto h0 = m.face_halfedge(poly->face), h1 = h0;
        for (std::size_t i = 0; i < n / 2; ++i) h1 = m.next(h1);
        return count([&] { EXPECT_TRUE((hmira::make_edge_face<halfedge_mesh, CT>(m, h0, h1))); });
    };
    const auto c10 = polygon_split_count(10, 2), c40 = polygon_split_count(40, 2),
               c40_big = polygon_split_count(40, 500);
    EXPECT_EQ(c40, c40_big) << "the count depends on the rest of the mesh";
    EXPECT_GT(c40, c10) << "a bigger face should cost more";
    EXPECT_LE(c40, 4 * 40 + 30u) << "more than a few calls per side";
}

}  // namespace
