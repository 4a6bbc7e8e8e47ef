// Loop and Catmull-Clark take their new elements from CGAL's Surface_mesh in blocks, through the
// traits' resize, which sizes every property array at once. The user's own property maps must
// grow with the mesh (an entry per element, the map's default on new ones, old entries kept),
// the blocks' unused ends must be dropped, and a mesh holding garbage must come out valid.

#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

#include <hmira/algorithms/subdivision/catmull_clark.hpp>
#include <hmira/algorithms/subdivision/loop.hpp>

#include "support/shapes.hpp"
#include "algorithms/triangle/triangle_support.hpp"

#ifdef HMIRA_TEST_WITH_CGAL
#include <CGAL/boost/graph/Euler_operations.h>

namespace {

using namespace hmira_test;
using mesh = cgal_surface_mesh;
using traits = hmira::mesh_traits<mesh>;
using V = mesh::Vertex_index;
using E = mesh::Edge_index;
using F = mesh::Face_index;
using H = mesh::Halfedge_index;

static_assert(hmira::bulk_growable_mesh<mesh, traits>,
              "the subdivision schemes must take Surface_mesh's new elements in blocks");

/// The user's property maps of every kind, each old element tagged with its index + 1 (0 is
/// the maps' default), so that a new element, and an old one that lost its value, can be told.
struct user_maps {
    mesh::Property_map<V, int> v;
    mesh::Property_map<E, int> e;
    mesh::Property_map<F, int> f;
    mesh::Property_map<H, int> h;

    explicit user_maps(mesh& m)
        : v(m.add_property_map<V, int>("v:user", 0).first),
          e(m.add_property_map<E, int>("e:user", 0).first),
          f(m.add_property_map<F, int>("f:user", 0).first),
          h(m.add_property_map<H, int>("h:user", 0).first) {
        for (std::size_t i = 0; i < m.num_vertices(); ++i) v[V(mesh::size_type(i))] = int(i) + 1;
        for (std::size_t i = 0; i < m.num_edges(); ++i) e[E(mesh::size_type(i))] = int(i) + 1;
        for (std::size_t i = 0; i < m.num_faces(); ++i) f[F(mesh::size_type(i))] = int(i) + 1;
        for (std::size_t i = 0; i < m.num_halfedges(); ++i) h[H(mesh::size_type(i))] = int(i) + 1;
    }
};

/// Every map has one entry per index, the tags below the old bounds and the default above.
::testing::AssertionResult maps_follow(const mesh& m, const user_maps& u, std::size_t nv, std::size_t ne,
                                       std::size_t nf) {
    const auto check = [](const auto& map, std::size_t bound, std::size_t old_bound,
                          const char* kind) -> ::testing::AssertionResult {
        const auto size = std::size_t(map.end() - map.begin());
        if (size != bound)
            return ::testing::AssertionFailure()
                   << kind << " map has " << size << " entries for " << bound << " elements";
        for (std::size_t i = 0; i < bound; ++i) {
            const int expected = i < old_bound ? int(i) + 1 : 0;
            const int held = map.begin()[std::ptrdiff_t(i)];
            if (held != expected)
                return ::testing::AssertionFailure()
                       << kind << " " << i << " holds " << held << ", expected " << expected;
        }
        return ::testing::AssertionSuccess();
    };
    if (auto r = check(u.v, m.num_vertices(), nv, "vertex"); !r) return r;
    if (auto r = check(u.e, m.num_edges(), ne, "edge"); !r) return r;
    if (auto r = check(u.f, m.num_faces(), nf, "face"); !r) return r;
    return check(u.h, m.num_halfedges(), 2 * ne, "halfedge");
}

TEST(subdivision_cgal_bulk, traits_resize_appends_live_unlinked_elements_and_grows_user_maps) {
    mesh m = mesh_from<mesh>(grid(3, 2, true));
    const std::size_t nv = m.num_vertices(), ne = m.num_edges(), nf = m.num_faces();
    const user_maps u(m);
    m.reserve(mesh::size_type(nv + 5), mesh::size_type(ne + 7), mesh::size_type(nf + 3));
    traits::resize(m, nv + 5, ne + 7, nf + 3);
    EXPECT_EQ(m.number_of_vertices(), nv + 5);
    EXPECT_EQ(m.number_of_edges(), ne + 7);
    EXPECT_EQ(m.number_of_faces(), nf + 3);
    EXPECT_FALSE(m.has_garbage());
    EXPECT_TRUE(maps_follow(m, u, nv, ne, nf));
    for (std::size_t i = nv; i < nv + 5; ++i) {
        const V v = traits::vertex_at(m, i);
        EXPECT_EQ(v.idx(), i);
        EXPECT_FALSE(m.is_removed(v));
        EXPECT_EQ(m.halfedge(v), mesh::null_halfedge());
    }
    for (std::size_t i = ne; i < ne + 7; ++i) {
        const E e = traits::edge_at(m, i);
        EXPECT_EQ(e.idx(), i);
        EXPECT_FALSE(m.is_removed(e));
        EXPECT_EQ(m.face(m.halfedge(e)), mesh::null_face());
        EXPECT_EQ(m.face(m.opposite(m.halfedge(e))), mesh::null_face());
    }
    for (std::size_t i = nf; i < nf + 3; ++i) {
        const F f = traits::face_at(m, i);
        EXPECT_EQ(f.idx(), i);
        EXPECT_FALSE(m.is_removed(f));
        EXPECT_EQ(m.halfedge(f), mesh::null_halfedge());
    }
    // Shrinking back drops exactly the unlinked elements: the mesh is the one it was.
    traits::resize(m, nv, ne, nf);
    EXPECT_EQ(m.num_vertices(), nv);
    EXPECT_EQ(m.num_edges(), ne);
    EXPECT_EQ(m.num_faces(), nf);
    EXPECT_TRUE(maps_follow(m, u, nv, ne, nf));
    EXPECT_TRUE(valid_topology(m));
}

TEST(subdivision_cgal_bulk, loop_grows_every_user_property_map_with_the_mesh) {
    // An open grid, so that boundary edges (split without a cut) are made in blocks too.
    mesh m = mesh_from<mesh>(grid(9, 7, true));
    const std::size_t nv = m.num_vertices(), ne = m.num_edges(), nf = m.num_faces();
    ASSERT_EQ(nv, 80u);
    ASSERT_EQ(ne, 9u * 8 + 10u * 7 + 9u * 7);
    ASSERT_EQ(nf, 2u * 9 * 7);
    const user_maps u(m);
    const auto r = hmira::loop_subdivide(m);
    ASSERT_TRUE(r);
    EXPECT_TRUE(valid_topology(m));
    EXPECT_FALSE(m.has_garbage());
    EXPECT_EQ(m.number_of_vertices(), nv + ne);
    EXPECT_EQ(m.number_of_edges(), 2 * ne + 3 * nf);
    EXPECT_EQ(m.number_of_faces(), 4 * nf);
    EXPECT_TRUE(maps_follow(m, u, nv, ne, nf));
}

TEST(subdivision_cgal_bulk, catmull_clark_grows_every_user_property_map_with_the_mesh) {
    mesh m = mesh_from<mesh>(grid(8, 5));
    const std::size_t nv = m.num_vertices(), ne = m.num_edges(), nf = m.num_faces();
    ASSERT_EQ(nv, 54u);
    ASSERT_EQ(ne, 8u * 6 + 9u * 5);
    ASSERT_EQ(nf, 40u);
    const user_maps u(m);
    const auto r = hmira::catmull_clark_subdivide(m);
    ASSERT_TRUE(r);
    EXPECT_TRUE(valid_topology(m));
    EXPECT_FALSE(m.has_garbage());
    // Quads: a vertex per edge and per face, each quad into four.
    EXPECT_EQ(m.number_of_vertices(), nv + ne + nf);
    EXPECT_EQ(m.number_of_edges(), 2 * ne + 4 * nf);
    EXPECT_EQ(m.number_of_faces(), 4 * nf);
    EXPECT_TRUE(maps_follow(m, u, nv, ne, nf));
}

/// More elements per level than one block (4096) holds, over two levels, so that blocks end
/// inside a level and the last block's unused end is dropped at each level's end.
TEST(subdivision_cgal_bulk, several_blocks_over_two_levels_leave_exact_counts) {
    mesh tri = mesh_from<mesh>(triangulated(torus(40, 30)));
    mesh quad = mesh_from<mesh>(torus(40, 30));
    const std::size_t f0 = 40 * 30;
    ASSERT_TRUE(hmira::loop_subdivide(tri, {.levels = 2}));
    ASSERT_TRUE(hmira::catmull_clark_subdivide(quad, {.levels = 2}));
    for (const mesh* m : {&tri, &quad}) {
        EXPECT_TRUE(valid_topology(*m));
        // A closed torus: V - E + F = 0; no removed element, so the bounds are the counts.
        const long long chi =
            (long long)m->number_of_vertices() - (long long)m->number_of_edges() + (long long)m->number_of_faces();
        EXPECT_EQ(chi, 0);
        EXPECT_EQ(m->num_vertices(), m->number_of_vertices());
        EXPECT_EQ(m->num_edges(), m->number_of_edges());
        EXPECT_EQ(m->num_faces(), m->number_of_faces());
    }
    EXPECT_EQ(tri.number_of_faces(), 16 * 2 * f0);
    EXPECT_EQ(quad.number_of_faces(), 16 * f0);
}

/// With garbage, the blocks go past the removed elements' slots, which stay removed; the
/// user's maps still get an entry per slot.
TEST(subdivision_cgal_bulk, loop_on_a_mesh_with_garbage_keeps_it_removed_and_grows_user_maps) {
    mesh m;
    const auto a = m.add_vertex({9, 9, 9});
    const auto b = m.add_vertex({10, 9, 9});
    const auto c = m.add_vertex({9, 10, 9});
    const auto dead = m.add_face(a, b, c);
    const face_list shape = triangulated(torus(6, 5));
    std::vector<V> vs;
    for (const auto& p : shape.points) vs.push_back(m.add_vertex({p[0], p[1], p[2]}));
    for (const auto& face : shape.faces) {
        std::vector<V> loop;
        for (auto i : face) loop.push_back(vs[i]);
        ASSERT_NE(m.add_face(loop), mesh::null_face());
    }
    CGAL::Euler::remove_face(m.halfedge(dead), m);
    ASSERT_TRUE(m.has_garbage());
    const std::size_t nv = m.number_of_vertices(), ne = m.number_of_edges(), nf = m.number_of_faces();
    const std::size_t removed_v = m.number_of_removed_vertices(), removed_e = m.number_of_removed_edges(),
                      removed_f = m.number_of_removed_faces();
    auto user = m.add_property_map<V, int>("v:user", -1).first;
    ASSERT_TRUE(hmira::loop_subdivide(m));
    EXPECT_TRUE(valid_topology(m));
    EXPECT_EQ(m.number_of_vertices(), nv + ne);
    EXPECT_EQ(m.number_of_edges(), 2 * ne + 3 * nf);
    EXPECT_EQ(m.number_of_faces(), 4 * nf);
    EXPECT_EQ(m.number_of_removed_vertices(), removed_v);
    EXPECT_EQ(m.number_of_removed_edges(), removed_e);
    EXPECT_EQ(m.number_of_removed_faces(), removed_f);
    EXPECT_TRUE(m.is_removed(a) && m.is_removed(b) && m.is_removed(c) && m.is_removed(dead));
    EXPECT_EQ(std::size_t(user.end() - user.begin()), m.num_vertices());
    for (auto v : m.vertices()) EXPECT_EQ(user[v], -1);
    // Collecting the garbage must leave a valid mesh with the same counts.
    m.collect_garbage();
    EXPECT_TRUE(valid_topology(m));
    EXPECT_EQ(m.number_of_vertices(), nv + ne);
}

}  // namespace
#endif
