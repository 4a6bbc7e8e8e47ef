// halfedge_mesh's bulk element layer (resize, vertex_at, edge_at, face_at through its traits),
// which Loop and Catmull-Clark take their new elements from in blocks: resize appends unlinked
// elements at their defaults and drops them again, and subdividing in blocks gives the very
// mesh (indices, links and positions, bit for bit) that one traits add per element gives.

#include <gtest/gtest.h>

#include <hmira/algorithms/subdivision/catmull_clark.hpp>
#include <hmira/algorithms/subdivision/loop.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "algorithms/triangle/triangle_support.hpp"

namespace {

using namespace hmira_test;
using hm = hmira::halfedge_mesh;

/// halfedge_mesh's traits without the optional bulk layer: every new element is one
/// add_vertex, new_edge or new_face, as on a model that offers no resize.
struct one_at_a_time_traits : hmira::mesh_traits<hm> {
    static void resize() = delete;  // hides the bulk resize (bulk_growable_mesh needs resize(m, v, e, f))
};

static_assert(hmira::bulk_growable_mesh<hm, hmira::default_traits<hm>>);
static_assert(hmira::change_counted_mesh<hm, hmira::default_traits<hm>>);
static_assert(!hmira::bulk_growable_mesh<hm, one_at_a_time_traits>);

/// Every index bound, link, position and face halfedge (take_snapshot), without the change
/// count it ends with: one resize per block counts fewer changes than one add per element.
snapshot links_and_positions(const hm& m) {
    snapshot s = take_snapshot(m);
    s.data.pop_back();
    return s;
}

/// A grid with an inner hole and a user vertex property: an outer and an inner boundary, and a
/// property array that must follow every new element.
hm open_mesh(bool triangles) {
    const auto g = triangles ? triangulated(grid(6, 5)) : grid(6, 5);
    return mesh_from<hm>(without_faces(g, [](std::size_t f) { return f == 17; }));
}

TEST(halfedge_mesh_bulk, resize_appends_unlinked_defaults_and_dropping_them_restores_the_mesh) {
    hm m = open_mesh(true);
    auto weight = m.add_vertex_property<int>("weight", 7);
    const auto before = links_and_positions(m);
    const std::size_t v = m.vertex_index_bound(), e = m.edge_index_bound(), f = m.face_index_bound();
    const auto changes = m.change_count();
    m.resize(v + 3, e + 2, f + 1);
    EXPECT_GT(m.change_count(), changes);
    ASSERT_EQ(m.vertex_count(), v + 3);
    ASSERT_EQ(m.edge_count(), e + 2);
    ASSERT_EQ(m.face_count(), f + 1);
    using T = hmira::default_traits<hm>;
    for (std::size_t i = v; i < v + 3; ++i) {
        const auto x = T::vertex_at(m, i);
        EXPECT_EQ(x.index, i);
        EXPECT_TRUE(m.is_isolated(x));
        EXPECT_EQ(m.position(x), (hmira::vec3<double>{0, 0, 0}));
        EXPECT_EQ(weight[x], 7);
    }
    for (std::size_t i = e; i < e + 2; ++i)
        for (unsigned k = 0; k < 2; ++k) {
            const auto h = m.edge_halfedge(T::edge_at(m, i), k);
            EXPECT_TRUE(m.target(h).is_null());
            EXPECT_TRUE(m.next(h).is_null());
            EXPECT_TRUE(m.prev(h).is_null());
            EXPECT_TRUE(m.face(h).is_null());
        }
    EXPECT_TRUE(m.face_halfedge(T::face_at(m, f)).is_null());
    m.resize(v, e, f);
    EXPECT_EQ(links_and_positions(m), before);
    EXPECT_TRUE(valid_topology(m));
}

TEST(halfedge_mesh_bulk, loop_in_blocks_equals_loop_one_element_at_a_time) {
    for (std::size_t levels : {1u, 2u}) {
        hm bulk = open_mesh(true), single = bulk;
        auto a = hmira::loop_subdivide(bulk, {.levels = levels});
        auto b = hmira::loop_subdivide<hm, one_at_a_time_traits>(single, {.levels = levels});
        ASSERT_TRUE(a) << a.error().message;
        ASSERT_TRUE(b) << b.error().message;
        EXPECT_TRUE(valid_topology(bulk));
        EXPECT_EQ(links_and_positions(bulk), links_and_positions(single)) << levels << " level(s)";
        EXPECT_EQ(bulk.vertex_index_bound(), single.vertex_index_bound());
        EXPECT_EQ(bulk.edge_index_bound(), single.edge_index_bound());
        EXPECT_EQ(bulk.face_index_bound(), single.face_index_bound());
    }
}

TEST(halfedge_mesh_bulk, catmull_clark_in_blocks_equals_catmull_clark_one_element_at_a_time) {
    for (bool triangles : {false, true})
        for (std::size_t levels : {1u, 2u}) {
            hm bulk = open_mesh(triangles), single = bulk;
            auto a = hmira::catmull_clark_subdivide(bulk, {.levels = levels});
            auto b = hmira::catmull_clark_subdivide<hm, one_at_a_time_traits>(single, {.levels = levels});
            ASSERT_TRUE(a) << a.error().message;
            ASSERT_TRUE(b) << b.error().message;
            EXPECT_TRUE(valid_topology(bulk));
            EXPECT_EQ(links_and_positions(bulk), links_and_positions(single))
                << levels << " level(s), triangles " << triangles;
            EXPECT_EQ(bulk.vertex_index_bound(), single.vertex_index_bound());
            EXPECT_EQ(bulk.edge_index_bound(), single.edge_index_bound());
            EXPECT_EQ(bulk.face_index_bound(), single.face_index_bound());
        }
}

TEST(halfedge_mesh_bulk, new_elements_follow_a_user_property_at_its_default) {
    hm m = open_mesh(false);
    auto tag = m.add_vertex_property<int>("tag", -1);
    for (auto v : m.vertices()) tag[v] = int(v.index);
    const std::size_t old = m.vertex_index_bound();
    auto r = hmira::catmull_clark_subdivide(m);
    ASSERT_TRUE(r) << r.error().message;
    for (auto v : m.vertices()) EXPECT_EQ(tag[v], v.index < old ? int(v.index) : -1);
}

}  // namespace
