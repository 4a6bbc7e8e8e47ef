// Subdivision and remeshing tell new elements from old ones by index. CGAL's Surface_mesh puts a
// new element into a removed element's slot while it holds garbage, which would make a new
// vertex look old. Each scheme must give exactly the result it gives on the same mesh without
// garbage, and leave the mesh's recycling setting as it found it.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

#include <hmira/algorithms/remeshing/isotropic_remeshing.hpp>
#include <hmira/algorithms/subdivision/catmull_clark.hpp>
#include <hmira/algorithms/subdivision/loop.hpp>
#include <hmira/algorithms/subdivision/sqrt3.hpp>

#include "support/shapes.hpp"
#include "algorithms/triangle/triangle_support.hpp"

#ifdef HMIRA_TEST_WITH_CGAL
#include <CGAL/boost/graph/Euler_operations.h>

namespace {

using namespace hmira_test;
using point = std::array<double, 3>;
using mesh = cgal_surface_mesh;

/// The shape built after a throwaway triangle that is then removed: its face, edges and
/// vertices leave free slots below every live element's index, which the next additions reuse.
mesh with_free_slots_below(const face_list& shape) {
    mesh m;
    const auto a = m.add_vertex({9, 9, 9});
    const auto b = m.add_vertex({10, 9, 9});
    const auto c = m.add_vertex({9, 10, 9});
    const auto f = m.add_face(a, b, c);
    std::vector<mesh::Vertex_index> vs;
    for (const auto& p : shape.points) vs.push_back(m.add_vertex({p[0], p[1], p[2]}));
    for (const auto& face : shape.faces) {
        std::vector<mesh::Vertex_index> loop;
        for (auto i : face) loop.push_back(vs[i]);
        [[maybe_unused]] const auto added = m.add_face(loop);
    }
    CGAL::Euler::remove_face(m.halfedge(f), m);
    return m;
}

/// Every face as its corners' positions, started at the smallest corner, then sorted: equal
/// for two meshes with the same geometry whatever their indices.
std::vector<std::vector<point>> geometry(const mesh& m) {
    std::vector<std::vector<point>> faces;
    for (auto f : m.faces()) {
        std::vector<point> corners;
        for (auto v : CGAL::vertices_around_face(m.halfedge(f), m)) {
            const auto& p = m.point(v);
            corners.push_back({p.x(), p.y(), p.z()});
        }
        std::ranges::rotate(corners, std::ranges::min_element(corners));
        faces.push_back(std::move(corners));
    }
    std::ranges::sort(faces);
    return faces;
}

void expect_same_result_with_and_without_garbage(const face_list& shape, auto&& scheme) {
    mesh clean = mesh_from<mesh>(shape);
    mesh dirty = with_free_slots_below(shape);
    ASSERT_TRUE(dirty.has_garbage());
    ASSERT_TRUE(dirty.does_recycle_garbage());
    ASSERT_TRUE(geometry(dirty) == geometry(clean));
    ASSERT_TRUE(scheme(clean));
    ASSERT_TRUE(scheme(dirty));
    EXPECT_TRUE(valid_topology(clean));
    EXPECT_TRUE(valid_topology(dirty));
    EXPECT_EQ(dirty.number_of_vertices(), clean.number_of_vertices());
    EXPECT_EQ(dirty.number_of_faces(), clean.number_of_faces());
    EXPECT_TRUE(geometry(dirty) == geometry(clean)) << "the result differs where the mesh held garbage";
    EXPECT_TRUE(dirty.does_recycle_garbage()) << "the mesh's recycling setting was not restored";
}

TEST(subdivision_garbage, loop_on_a_surface_mesh_with_free_slots_equals_loop_without) {
    expect_same_result_with_and_without_garbage(triangulated(torus(8, 6)),
                                                [](mesh& m) { return bool(hmira::loop_subdivide(m, {.levels = 2})); });
}

TEST(subdivision_garbage, catmull_clark_on_a_surface_mesh_with_free_slots_equals_catmull_clark_without) {
    expect_same_result_with_and_without_garbage(
        torus(8, 6), [](mesh& m) { return bool(hmira::catmull_clark_subdivide(m, {.levels = 2})); });
}

TEST(subdivision_garbage, sqrt3_on_a_surface_mesh_with_free_slots_equals_sqrt3_without) {
    expect_same_result_with_and_without_garbage(triangulated(torus(8, 6)),
                                                [](mesh& m) { return bool(hmira::sqrt3_subdivide(m, {.levels = 2})); });
}

TEST(subdivision_garbage, remeshing_a_surface_mesh_with_free_slots_equals_remeshing_without) {
    expect_same_result_with_and_without_garbage(triangulated(torus(12, 8)), [](mesh& m) {
        return bool(hmira::isotropic_remeshing(m, {.target_edge_length = 0.4, .iterations = 3}));
    });
}

}  // namespace
#endif
