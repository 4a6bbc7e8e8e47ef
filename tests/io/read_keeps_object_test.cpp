// Reading into a mesh keeps the user's object: the mesh is emptied, not
// replaced, so the properties a user added before reading are still there afterwards, sized
// to the new elements with their default values; on a failed read nothing changes at all.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>
#include <hmira/meshes/winged_edge_mesh.hpp>

#include "support/shapes.hpp"

#ifdef HMIRA_TEST_WITH_OPENMESH
#include <hmira/interop/openmesh.hpp>
#endif

namespace {

std::filesystem::path write_file(const std::string& name, const std::string& text) {
    const auto path =
        std::filesystem::temp_directory_path() / ("hmira_keeps_object_" + std::to_string(::getpid()) + "_" + name);
    std::ofstream(path) << text;
    return path;
}

// A square pyramid without its base: 5 vertices, 4 triangles.
const char* pyramid_off = "OFF\n5 4 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 1\n3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n";

template <class M>
struct read_keeps_object : ::testing::Test {};
using hmira_models = ::testing::Types<hmira::face_vertex_mesh, hmira::halfedge_mesh, hmira::winged_edge_mesh>;
TYPED_TEST_SUITE(read_keeps_object, hmira_models);

TYPED_TEST(read_keeps_object, named_properties_survive_a_read_sized_to_the_new_elements) {
    using M = TypeParam;
    M m;
    ASSERT_TRUE(hmira_test::add_face_list(m, hmira_test::grid(3, 3)));  // 16 vertices, 9 faces
    auto weight = m.template add_vertex_property<double>("weight", 7.5);
    auto label = m.template add_face_property<int>("label", -1);
    for (auto v : m.vertices()) weight[v] = 100.0;
    for (auto f : m.faces()) label[f] = 3;
    const auto changes = m.change_count();

    const auto path = write_file("pyramid.off", pyramid_off);
    auto r = hmira::io::read_mesh(m, path);
    std::filesystem::remove(path);
    ASSERT_TRUE(r) << r.error().message;
    ASSERT_EQ(m.vertex_count(), 5u);
    ASSERT_EQ(m.face_count(), 4u);
    EXPECT_GT(m.change_count(), changes) << "an index built before the read must see it is stale";

    auto w = m.template get_vertex_property<double>("weight");
    ASSERT_TRUE(w) << "the vertex property was dropped by the read";
    EXPECT_EQ(w->values().size(), m.vertex_index_bound());
    for (auto v : m.vertices()) EXPECT_EQ((*w)[v], 7.5) << "new vertices get the property's default";
    auto l = m.template get_face_property<int>("label");
    ASSERT_TRUE(l) << "the face property was dropped by the read";
    EXPECT_EQ(l->values().size(), m.face_index_bound());
    for (auto f : m.faces()) EXPECT_EQ((*l)[f], -1);
    // The handle taken before the read still refers to the mesh's array.
    EXPECT_EQ(&weight.values(), &w->values());
}

TYPED_TEST(read_keeps_object, a_failed_read_changes_neither_elements_nor_properties) {
    using M = TypeParam;
    M m;
    ASSERT_TRUE(hmira_test::add_face_list(m, hmira_test::grid(2, 2)));
    auto weight = m.template add_vertex_property<double>("weight", 0.0);
    for (auto v : m.vertices()) weight[v] = 1.0 + v.index;
    const auto path = write_file("bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n");  // vertex 9 does not exist
    auto r = hmira::io::read_mesh(m, path);
    std::filesystem::remove(path);
    ASSERT_FALSE(r);
    EXPECT_EQ(m.vertex_count(), 9u);
    EXPECT_EQ(m.face_count(), 4u);
    auto w = m.template get_vertex_property<double>("weight");
    ASSERT_TRUE(w);
    for (auto v : m.vertices()) EXPECT_EQ((*w)[v], 1.0 + v.index);
}

TYPED_TEST(read_keeps_object, clear_elements_keeps_properties_and_clear_drops_them) {
    using M = TypeParam;
    M m;
    ASSERT_TRUE(hmira_test::add_face_list(m, hmira_test::grid(1, 1)));
    (void)m.template add_vertex_property<float>("kept", 2.0f);
    m.clear_elements();
    EXPECT_EQ(m.vertex_count(), 0u);
    EXPECT_EQ(m.face_count(), 0u);
    auto kept = m.template get_vertex_property<float>("kept");
    ASSERT_TRUE(kept);
    EXPECT_TRUE(kept->values().empty());
    const auto v = m.add_vertex({0, 0, 0});
    EXPECT_EQ((*kept)[v], 2.0f);
    m.clear();
    EXPECT_FALSE(m.template get_vertex_property<float>("kept"));
}

#ifdef HMIRA_TEST_WITH_OPENMESH
TEST(read_keeps_object_openmesh, requested_and_added_properties_survive_a_read) {
    OpenMesh::PolyMesh_ArrayKernelT<> m;
    m.request_vertex_colors();
    OpenMesh::VPropHandleT<double> weight;
    m.add_property(weight, "weight");
    ASSERT_TRUE(hmira_test::add_face_list(m, hmira_test::grid(2, 2)));
    const auto path = write_file("pyramid_om.off", pyramid_off);
    auto r = hmira::io::read_mesh(m, path);
    std::filesystem::remove(path);
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_EQ(m.n_vertices(), 5u);
    EXPECT_EQ(m.n_faces(), 4u);
    EXPECT_TRUE(m.has_vertex_colors());
    OpenMesh::VPropHandleT<double> again;
    ASSERT_TRUE(m.get_property_handle(again, "weight"));
    EXPECT_EQ(m.property(again).n_elements(), m.n_vertices());
}
#endif

}  // namespace
