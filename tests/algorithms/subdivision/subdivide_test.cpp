// subdivide(): the scheme chosen by value or by name runs the scheme's own function, with the
// same result; the names every front end reads are those of core/enum_names.hpp.
#include <gtest/gtest.h>

#include <string>

#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/generators/torus.hpp>
#include <hmira/algorithms/smoothing/laplacian_smooth.hpp>
#include <hmira/algorithms/subdivision/subdivide.hpp>
#include <hmira/algorithms/triangulation/triangulate_faces.hpp>
#include <hmira/algorithms/validation/validate.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "support/snapshot.hpp"

namespace {

using hmira::halfedge_mesh;
using hmira::subdivision_scheme;

TEST(enum_names, every_scheme_and_weight_round_trips_through_its_name) {
    EXPECT_EQ(hmira::to_string(subdivision_scheme::loop), "loop");
    EXPECT_EQ(hmira::to_string(subdivision_scheme::sqrt3), "sqrt3");
    EXPECT_EQ(hmira::to_string(subdivision_scheme::catmull_clark), "catmull-clark");
    for (auto s : {subdivision_scheme::loop, subdivision_scheme::sqrt3, subdivision_scheme::catmull_clark})
        EXPECT_EQ(hmira::from_string<subdivision_scheme>(hmira::to_string(s)), s);
    EXPECT_EQ(hmira::from_string<hmira::laplacian_weights>("cotangent"), hmira::laplacian_weights::cotangent);
    EXPECT_EQ(hmira::from_string<hmira::laplacian_weights>("uniform"), hmira::laplacian_weights::uniform);
    EXPECT_FALSE(hmira::from_string<subdivision_scheme>("Loop"));
    EXPECT_FALSE(hmira::from_string<subdivision_scheme>("catmull_clark"));
    EXPECT_FALSE(hmira::from_string<subdivision_scheme>(""));
    EXPECT_EQ(hmira::quoted_names<subdivision_scheme>(), "'loop', 'sqrt3', 'catmull-clark'");
    static_assert(hmira::from_string<subdivision_scheme>("sqrt3") == subdivision_scheme::sqrt3);
}

TEST(subdivide, each_scheme_gives_what_its_own_function_gives) {
    for (auto scheme : {subdivision_scheme::loop, subdivision_scheme::sqrt3, subdivision_scheme::catmull_clark}) {
        SCOPED_TRACE(std::string(hmira::to_string(scheme)));
        halfedge_mesh a, b;
        ASSERT_TRUE(hmira::generate_icosahedron(a));
        ASSERT_TRUE(hmira::generate_icosahedron(b));
        const auto r = hmira::subdivide(a, {.scheme = scheme, .levels = 2});
        ASSERT_TRUE(r) << r.error().message;
        std::size_t faces = 0;
        if (scheme == subdivision_scheme::loop)
            faces = hmira::loop_subdivide(b, {.levels = 2}).value().faces;
        else if (scheme == subdivision_scheme::sqrt3)
            faces = hmira::sqrt3_subdivide(b, {.levels = 2}).value().faces;
        else
            faces = hmira::catmull_clark_subdivide(b, {.levels = 2}).value().faces;
        EXPECT_EQ(r->faces, faces);
        EXPECT_EQ(r->faces, a.face_count());
        EXPECT_EQ(r->vertices, a.vertex_count());
        EXPECT_TRUE(hmira::validate(a).empty());
        EXPECT_TRUE(hmira_test::snapshot(a) == hmira_test::snapshot(b));
    }
    // Counts independent of the code: 20 triangles become 320 (Loop), 180 (sqrt(3)), and
    // Catmull-Clark makes 3 quads per triangle, then 4 per quad: 240.
    halfedge_mesh m;
    ASSERT_TRUE(hmira::generate_icosahedron(m));
    EXPECT_EQ(hmira::subdivide(m, {.scheme = subdivision_scheme::catmull_clark, .levels = 2}).value().faces, 240u);
}

TEST(subdivide, a_cancelled_call_leaves_the_mesh_unchanged) {
    // Large enough (40,000 triangles) for every scheme to report progress within its first level.
    halfedge_mesh m;
    ASSERT_TRUE(hmira::generate_torus(m, {.rings = 200, .sides = 100}));
    ASSERT_TRUE(hmira::triangulate_faces(m));
    const auto before = hmira_test::snapshot(m);
    for (auto scheme : {subdivision_scheme::loop, subdivision_scheme::sqrt3, subdivision_scheme::catmull_clark}) {
        SCOPED_TRACE(std::string(hmira::to_string(scheme)));
        auto r = hmira::subdivide(m, {.scheme = scheme, .levels = 1, .progress = [](double) { return false; }});
        ASSERT_FALSE(r);
        EXPECT_EQ(r.error().code, hmira::errc::cancelled);
        EXPECT_TRUE(hmira_test::snapshot(m) == before);
    }
}

}  // namespace
