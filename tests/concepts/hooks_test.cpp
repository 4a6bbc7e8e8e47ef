// The optional hooks of concepts.hpp: which model offers which (so that a hook renamed in a
// model, and silently no longer found, fails here), and that a traits class listing its hooks
// runs the same algorithms with the same results as one that does not.
#include <gtest/gtest.h>

#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/orientation/flip_normals.hpp>
#include <hmira/algorithms/validation/validate.hpp>
#include <hmira/concepts.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>
#include <hmira/meshes/winged_edge_mesh.hpp>

#include "support/models.hpp"

namespace {

using hmira::face_vertex_mesh;
using hmira::halfedge_mesh;
using hmira::winged_edge_mesh;

// Growing edits reserve through the hook where the model also has edge indices.
static_assert(hmira::reservable_mesh<halfedge_mesh> && hmira::edge_index_mesh<halfedge_mesh>);
static_assert(hmira::bulk_growable_mesh<halfedge_mesh>);
static_assert(hmira::orientation_reversible_mesh<halfedge_mesh>);
static_assert(!hmira::erase_preparing_mesh<halfedge_mesh>);
static_assert(!hmira::vertex_halfedge_restorable_mesh<halfedge_mesh>);
static_assert(hmira::reservable_mesh<winged_edge_mesh> && hmira::edge_index_mesh<winged_edge_mesh>);
static_assert(!hmira::bulk_growable_mesh<winged_edge_mesh>);
static_assert(hmira::bulk_vertex_removal_mesh<face_vertex_mesh>);
static_assert(
    hmira::removal_queryable_mesh<face_vertex_mesh, hmira::mesh_traits<face_vertex_mesh>, hmira::vertex_handle>);
static_assert(!hmira::reservable_mesh<face_vertex_mesh>);
static_assert(!hmira::triangle_only_mesh<halfedge_mesh>);
static_assert(!hmira::fault_injecting_traits<hmira::mesh_traits<halfedge_mesh>>);

#ifdef HMIRA_TEST_WITH_OPENMESH
static_assert(hmira::reservable_mesh<hmira_test::openmesh_poly> && hmira::edge_index_mesh<hmira_test::openmesh_poly>);
static_assert(hmira::bulk_growable_mesh<hmira_test::openmesh_poly>);
static_assert(hmira::orientation_reversible_mesh<hmira_test::openmesh_poly>);
static_assert(hmira::erase_preparing_mesh<hmira_test::openmesh_poly>);
static_assert(hmira::triangle_only_mesh<hmira_test::openmesh_tri>);
#endif
#ifdef HMIRA_TEST_WITH_CGAL
static_assert(hmira::reservable_mesh<hmira_test::cgal_surface_mesh> &&
              hmira::edge_index_mesh<hmira_test::cgal_surface_mesh>);
static_assert(hmira::bulk_growable_mesh<hmira_test::cgal_surface_mesh>);
static_assert(hmira::orientation_reversible_mesh<hmira_test::cgal_surface_mesh>);
static_assert(hmira::vertex_halfedge_restorable_mesh<hmira_test::cgal_surface_mesh>);
#endif

// The same model with its hooks listed: every listed hook must match, or this file would not
// compile (see tests/compile_fail/misspelt_hook.cpp for what a mismatch gives).
struct listed_traits : hmira::mesh_traits<halfedge_mesh> {
    static constexpr hmira::hook hooks[] = {hmira::hook::reserve, hmira::hook::bulk_growth,
                                            hmira::hook::reverse_orientation};
};
static_assert(hmira::detail::declares_hook<listed_traits>(hmira::hook::reserve));
static_assert(!hmira::detail::declares_hook<listed_traits>(hmira::hook::prepare_erase));
static_assert(!hmira::detail::declares_hook<hmira::mesh_traits<halfedge_mesh>>(hmira::hook::reserve));
static_assert(hmira::reservable_mesh<halfedge_mesh, listed_traits>);
static_assert(hmira::orientation_reversible_mesh<halfedge_mesh, listed_traits>);

// A hook the general path stands in for: without reverse_orientation, flip_normals re-links the
// halfedges itself.
struct unhooked_traits : hmira::mesh_traits<halfedge_mesh> {
    static void reverse_orientation() = delete;
};
static_assert(!hmira::orientation_reversible_mesh<halfedge_mesh, unhooked_traits>);

std::vector<std::vector<std::size_t>> face_loops(const halfedge_mesh& m) {
    using T = hmira::mesh_traits<halfedge_mesh>;
    std::vector<std::vector<std::size_t>> out;
    for (auto f : T::faces(m)) {
        std::vector<std::size_t> loop;
        for (auto v : T::face_vertices(m, f)) loop.push_back(T::vertex_index(m, v));
        std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
        out.push_back(loop);
    }
    return out;
}

TEST(hooks, the_hook_and_the_general_path_flip_to_the_same_loops) {
    halfedge_mesh hooked, general;
    ASSERT_TRUE(hmira::generate_dodecahedron(hooked));
    ASSERT_TRUE(hmira::generate_dodecahedron(general));
    const auto before = face_loops(hooked);
    EXPECT_EQ((hmira::flip_normals<halfedge_mesh, listed_traits>(hooked)), 12u);
    EXPECT_EQ((hmira::flip_normals<halfedge_mesh, unhooked_traits>(general)), 12u);
    EXPECT_TRUE(hmira::validate(hooked).empty());
    EXPECT_TRUE(hmira::validate(general).empty());
    const auto a = face_loops(hooked), b = face_loops(general);
    EXPECT_EQ(a, b);
    EXPECT_NE(a, before);
    // Reversed loops: each face's loop read backwards is the loop it had before.
    for (std::size_t f = 0; f < a.size(); ++f) {
        auto r = before[f];
        std::reverse(r.begin() + 1, r.end());
        EXPECT_EQ(a[f], r) << "face " << f;
    }
}

}  // namespace
