// Traits passed explicitly, as the thesis does (generate_cube<TMesh, TMesh_traits>): a mesh
// with no mesh_traits specialisation at all runs the algorithms through a traits class of the
// user's choosing, and two traits classes can give two views of one structure.
#include <gtest/gtest.h>

#include <ranges>
#include <span>

#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/topology/mesh_topology.hpp>
#include <hmira/algorithms/validation/validate.hpp>

namespace {

struct plain_mesh {  // deliberately no hmira::mesh_traits<plain_mesh>
    std::vector<hmira::vec3<double>> points;
    std::vector<std::vector<int>> faces;
};

struct plain_traits {
    using vertex_handle = int;
    using face_handle = int;
    using scalar = double;
    static auto vertices(const plain_mesh& m) { return std::views::iota(0, int(m.points.size())); }
    static auto faces(const plain_mesh& m) { return std::views::iota(0, int(m.faces.size())); }
    static std::size_t vertex_count(const plain_mesh& m) { return m.points.size(); }
    static std::size_t face_count(const plain_mesh& m) { return m.faces.size(); }
    static std::size_t vertex_index(const plain_mesh&, int v) { return std::size_t(v); }
    static std::size_t vertex_index_bound(const plain_mesh& m) { return m.points.size(); }
    static std::size_t face_index(const plain_mesh&, int f) { return std::size_t(f); }
    static std::size_t face_index_bound(const plain_mesh& m) { return m.faces.size(); }
    static std::span<const int> face_vertices(const plain_mesh& m, int f) { return m.faces[std::size_t(f)]; }
    static hmira::vec3<double> position(const plain_mesh& m, int v) { return m.points[std::size_t(v)]; }
    static int add_vertex(plain_mesh& m, hmira::vec3<double> p) {
        m.points.push_back(p);
        return int(m.points.size()) - 1;
    }
    static hmira::result<int> add_face(plain_mesh& m, std::span<const int> vs) {
        m.faces.emplace_back(vs.begin(), vs.end());
        return int(m.faces.size()) - 1;
    }
};

// A second view of the same structure that sees only the first `limit` faces.
struct first_two_faces_traits : plain_traits {
    static auto faces(const plain_mesh& m) { return std::views::iota(0, std::min(2, int(m.faces.size()))); }
    static std::size_t face_count(const plain_mesh& m) { return std::min<std::size_t>(2, m.faces.size()); }
};

TEST(explicit_traits, a_mesh_without_a_specialisation_runs_through_traits_given_explicitly) {
    static_assert(!hmira::mesh_builder<plain_mesh>, "no default traits exist for plain_mesh");
    static_assert(hmira::mesh_builder<plain_mesh, plain_traits>);
    plain_mesh m;
    auto made = hmira::generate_cube<plain_mesh, plain_traits>(m);
    ASSERT_TRUE(made);
    EXPECT_EQ(m.points.size(), 8u);
    EXPECT_EQ(m.faces.size(), 6u);
    EXPECT_TRUE((hmira::validate<plain_mesh, plain_traits>(m).empty()));
    const auto t = hmira::mesh_topology<plain_mesh, plain_traits>(m);
    EXPECT_EQ(t.euler_characteristic, 2);
    EXPECT_TRUE(t.closed());
}

TEST(explicit_traits, two_traits_classes_give_two_views_of_one_mesh) {
    plain_mesh m;
    ASSERT_TRUE((hmira::generate_cube<plain_mesh, plain_traits>(m)));
    const auto whole = hmira::mesh_topology<plain_mesh, plain_traits>(m);
    const auto part = hmira::mesh_topology<plain_mesh, first_two_faces_traits>(m);
    EXPECT_EQ(whole.faces, 6u);
    EXPECT_EQ(part.faces, 2u);
    EXPECT_EQ(part.edges, 7u);  // two quads sharing one edge
    EXPECT_EQ(part.boundary_loops, 1u);
    EXPECT_EQ(part.isolated_vertices, 2u);
}

}  // namespace
