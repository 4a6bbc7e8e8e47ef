// Components, Euler characteristic, genus and boundary loops on every model, for shapes whose
// topology is known from their construction.
#include <gtest/gtest.h>

#include <random>

#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/topology/connected_components.hpp>
#include <hmira/algorithms/topology/mesh_topology.hpp>

#include "support/checks.hpp"
#include "support/models.hpp"
#include "support/shapes.hpp"

namespace {

using namespace hmira;

template <class M>
class topology : public ::testing::Test {};
TYPED_TEST_SUITE(topology, hmira_test::all_models);

TYPED_TEST(topology, components_of_a_disjoint_union_match_its_parts) {
    using M = TypeParam;
    using T = default_traits<M>;
    std::mt19937 rng(7);
    for (int trial = 0; trial < 5; ++trial) {
        M mesh;
        const int k = 1 + int(rng() % 6);
        std::vector<std::vector<typename T::vertex_handle>> parts;
        for (int i = 0; i < k; ++i) {
            auto made = (rng() % 2) ? generate_tetrahedron(mesh, {.center = {10.0 * i, 0, 0}})
                                    : generate_icosahedron(mesh, {.center = {10.0 * i, 0, 0}});
            ASSERT_TRUE(made);
            parts.push_back(made->vertices);
        }
        const auto isolated = T::add_vertex(mesh, {-5, -5, -5});
        const auto labels = connected_components(mesh);
        EXPECT_EQ(labels.count, std::size_t(k) + 1);
        std::set<std::uint32_t> seen;
        for (const auto& part : parts) {
            const auto label = labels.vertex_component[T::vertex_index(mesh, part.front())];
            for (auto v : part) EXPECT_EQ(labels.vertex_component[T::vertex_index(mesh, v)], label);
            EXPECT_TRUE(seen.insert(label).second) << "two parts share a label";
        }
        EXPECT_TRUE(seen.insert(labels.vertex_component[T::vertex_index(mesh, isolated)]).second);
        for (auto f : T::faces(mesh)) {
            auto loop = T::face_vertices(mesh, f);
            const auto first = *loop.begin();
            EXPECT_EQ(labels.face_component[T::face_index(mesh, f)],
                      labels.vertex_component[T::vertex_index(mesh, first)]);
        }
        const auto topo = mesh_topology(mesh);
        EXPECT_EQ(topo.isolated_vertices, 1u);
        EXPECT_EQ(topo.euler_characteristic, 2 * k + 1);
        EXPECT_EQ(topo.genus, 0);
    }
}

TYPED_TEST(topology, torus_has_genus_one_and_no_boundary) {
    using M = TypeParam;
    if constexpr (polygon_mesh_builder<M>) {
        M mesh;
        ASSERT_TRUE(hmira_test::add_face_list(mesh, hmira_test::torus(12, 8)));
        ASSERT_TRUE(hmira_test::is_valid(mesh));
        const auto topo = mesh_topology(mesh);
        EXPECT_EQ(topo.euler_characteristic, 0);
        EXPECT_EQ(topo.genus, 1);
        EXPECT_TRUE(topo.closed());
        EXPECT_EQ(euler_characteristic(mesh), 0);
    }
}

TYPED_TEST(topology, grid_with_holes_has_one_boundary_loop_per_hole_plus_the_rim) {
    using M = TypeParam;
    // Interior triangles far apart: each removed pair of triangles opens one hole.
    auto g = hmira_test::grid(12, 12, true);
    std::set<std::size_t> drop;
    const std::vector<std::pair<std::size_t, std::size_t>> holes{{2, 2}, {6, 3}, {9, 9}};
    for (auto [i, j] : holes) {
        drop.insert(2 * (j * 12 + i));
        drop.insert(2 * (j * 12 + i) + 1);
    }
    M mesh;
    ASSERT_TRUE(hmira_test::add_face_list(
        mesh, hmira_test::without_faces(g, [&](std::size_t f) { return drop.count(f) > 0; })));
    ASSERT_TRUE(hmira_test::is_valid(mesh));
    const auto topo = mesh_topology(mesh);
    EXPECT_EQ(topo.boundary_loops, holes.size() + 1);
    EXPECT_EQ(topo.genus, 0);
    EXPECT_EQ(topo.components, 1u);
    // A disk with h holes: chi = 1 - h.
    EXPECT_EQ(topo.euler_characteristic, 1 - static_cast<long long>(holes.size()));
    EXPECT_FALSE(topo.closed());
}

}  // namespace
