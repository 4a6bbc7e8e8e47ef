// Locality of the triangle operators: a traits class that forwards to halfedge_mesh's traits
// and counts every primitive call shows that each operator's count does not grow with the
// size of the mesh (it depends on the valences around the edge only).

#include <gtest/gtest.h>

#include <cstddef>

#include <hmira/algorithms/triangle/triangle.hpp>
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
    static void set_position(halfedge_mesh& m, V v, const hmira::vec3<double>& p) {
        ++calls;
        base::set_position(m, v, p);
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
};
using CT = counting_traits;
static_assert(hmira::triangle_operable_mesh<halfedge_mesh, CT>);

template <class Op>
std::size_t count(Op op) {
    CT::calls = 0;
    op();
    return CT::calls;
}

struct op_counts {
    std::size_t flip_check, flip, split, split_face, collapse_check, collapse, collapse_geometric;
    bool operator==(const op_counts&) const = default;
};

/// Every operator on the centre of an n x n triangulated grid.
op_counts measure(std::size_t n) {
    halfedge_mesh m = hmira_test::mesh_from<halfedge_mesh>(hmira_test::grid(n, n, true));
    const double c = double(n / 2);
    hmira::vertex_handle a, b;
    for (auto v : m.vertices()) {
        if (m.position(v) == hmira::vec3<double>{c, c, 0}) a = v;
        if (m.position(v) == hmira::vec3<double>{c + 1, c + 1, 0}) b = v;
    }
    const auto h = m.find_halfedge(a, b);
    op_counts k{};
    k.flip_check = count([&] { EXPECT_TRUE((hmira::is_flip_ok<halfedge_mesh, CT>(m, h))); });
    hmira::result<hmira::flip_edge_result<halfedge_mesh, CT>> f = hmira::error{};
    k.flip = count([&] { f = hmira::flip_edge<halfedge_mesh, CT>(m, h); });
    EXPECT_TRUE(f);
    EXPECT_TRUE((hmira::flip_edge<halfedge_mesh, CT>(m, f->halfedge)));
    hmira::result<hmira::split_edge_result<halfedge_mesh, CT>> s = hmira::error{};
    k.split = count([&] { s = hmira::split_edge<halfedge_mesh, CT>(m, h); });
    EXPECT_TRUE(s);
    k.collapse_check = count([&] { EXPECT_TRUE((hmira::is_collapse_ok<halfedge_mesh, CT>(m, s->halfedge))); });
    k.collapse_geometric = count(
        [&] { EXPECT_TRUE((hmira::is_collapse_ok<halfedge_mesh, CT>(m, s->halfedge, {.check_geometry = true}))); });
    k.collapse = count([&] {
        EXPECT_TRUE((
            hmira::collapse_edge<halfedge_mesh, CT>(m, s->halfedge, {.placement = hmira::collapse_placement::target})));
    });
    hmira::result<hmira::split_face_result<halfedge_mesh, CT>> sf = hmira::error{};
    k.split_face = count([&] { sf = hmira::split_face<halfedge_mesh, CT>(m, m.face(h)); });
    EXPECT_TRUE(sf);
    EXPECT_TRUE(hmira_test::is_valid(m));
    return k;
}

TEST(triangle_locality, primitive_counts_do_not_grow_with_mesh_size) {
    const auto small = measure(4), large = measure(200);  // 32 triangles against 80 000
    EXPECT_EQ(small, large);
    // And they are small: a flip is a fixed handful of links; a collapse walks the two
    // valence-6 neighbourhoods of its ends.
    EXPECT_LT(large.flip, 80u);
    EXPECT_LT(large.split, 80u);
    EXPECT_LT(large.split_face, 60u);
    EXPECT_LT(large.collapse_check + large.collapse, 600u);
}

}  // namespace
