// What the writers make of faces that are not plain convex loops: STL writes a concave face
// and a face with an inner ring as triangles covering exactly the face (read back, the area
// is the polygon's), fans a zero-area face, and refuses a self-crossing face by name without
// touching an existing file; OBJ, OFF and PLY refuse a ringed face by name, never dropping the
// ring.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <hmira/algorithms/euler/euler.hpp>
#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "algorithms/euler/euler_support.hpp"
#include "io/io_support.hpp"
#include "support/checks.hpp"

namespace {

using namespace hmira;
using hmira_test::face_list;
using hmira_test::mesh_from;
using hmira_test::read_bytes;
using hmira_test::scratch_dir;
using hmira_test::write_bytes;
using T = default_traits<halfedge_mesh>;

/// Area of every face of a triangle mesh read back from a file, and the sum of the triangles'
/// normals' z components (twice the signed area seen from +z).
struct read_back {
    double area = 0;
    double signed_z = 0;
    std::size_t triangles = 0;
};

read_back read_stl_area(const std::filesystem::path& p) {
    face_vertex_mesh m;
    auto r = io::read_stl(m, p);
    EXPECT_TRUE(r) << r.error().message;
    using U = default_traits<face_vertex_mesh>;
    read_back out;
    for (auto f : U::faces(m)) {
        std::vector<vec3<double>> c;
        for (auto v : U::face_vertices(m, f)) c.push_back(U::position(m, v));
        EXPECT_EQ(c.size(), 3u);
        const auto n = cross(c[1] - c[0], c[2] - c[0]);
        out.area += std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z) / 2;
        out.signed_z += n.z / 2;
        ++out.triangles;
    }
    return out;
}

/// An L-shaped hexagon of area 3 in z = 0, wound +z, listed from a corner whose fan overlaps
/// itself (a fan from (0,0) covers 3.5).
face_list l_shape() {
    face_list g;
    for (auto [x, y] : {std::pair{0.0, 0.0}, {2.0, 0.0}, {2.0, 1.0}, {1.0, 1.0}, {1.0, 2.0}, {0.0, 2.0}})
        g.points.push_back({x, y, 0});
    g.faces.push_back({0, 1, 2, 3, 4, 5});
    return g;
}

/// The cube [-1,1]^3 whose top face (y = 1) has a square hole of half-size 0.5, closed by a
/// square face: the top face is a ring of area 4 - 1 = 3 and the surface's area is 24.
T::face_handle cube_with_ringed_top(halfedge_mesh& m) {
    auto cube = generate_cube(m).value();
    const auto corner = T::face_halfedge(m, cube.faces[5]);
    const vec3<double> q[4] = {{-0.5, 1, -0.5}, {-0.5, 1, 0.5}, {0.5, 1, 0.5}, {0.5, 1, -0.5}};
    auto p0 = make_edge_vertex(m, corner, q[0]).value();
    auto prev = p0.halfedge;
    for (int i = 1; i < 4; ++i) prev = make_edge_vertex(m, prev, q[i]).value().halfedge;
    EXPECT_TRUE(make_edge_face(m, prev, p0.halfedge));
    const auto ring = kill_edge_make_ring(m, p0.halfedge).value();
    EXPECT_TRUE(hmira_test::is_valid(m));
    return T::face(m, ring.ring);
}

TEST(stl_writer, a_concave_face_is_written_as_triangles_covering_exactly_its_area) {
    const auto m = mesh_from<halfedge_mesh>(l_shape());
    scratch_dir dir;
    for (auto enc : {io::stl_encoding::binary, io::stl_encoding::ascii}) {
        ASSERT_TRUE(io::write_stl(m, dir / "l.stl", {.stl = enc}));
        const auto back = read_stl_area(dir / "l.stl");
        EXPECT_EQ(back.triangles, 4u);  // n - 2
        EXPECT_NEAR(back.area, 3.0, 1e-12);
        EXPECT_NEAR(back.signed_z, 3.0, 1e-12);  // every triangle faces +z: no overlap, no flip
    }
}

TEST(stl_writer, a_face_with_an_inner_ring_is_written_around_its_hole) {
    halfedge_mesh m;
    const auto top = cube_with_ringed_top(m);
    ASSERT_EQ(std::ranges::distance(T::inner_rings(m, top)), 1);
    scratch_dir dir;
    ASSERT_TRUE(io::write_stl(m, dir / "ring.stl"));
    const auto back = read_stl_area(dir / "ring.stl");
    // 5 squares (10 triangles), the ring (8 + 2 - 2 = 8), the square in the hole (2).
    EXPECT_EQ(back.triangles, 20u);
    EXPECT_NEAR(back.area, 24.0, 1e-12);  // a fan of the outer loop would cover the hole: 25
}

TEST(stl_writer, a_face_without_area_is_fanned_into_zero_area_triangles) {
    face_list g;
    g.points = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {1, 1, 0}};
    g.faces = {{0, 1, 2, 3}, {0, 3, 4}};  // a flat sliver, as a bevel at its clamp limit makes
    auto m = mesh_from<face_vertex_mesh>(g);
    const auto bytes = io::format_stl(m).value();
    ASSERT_EQ(bytes.size(), 84u + 50u * 3u);  // two fan triangles and the real one
}

TEST(stl_writer, a_self_crossing_face_is_refused_by_name_and_the_existing_file_stays) {
    face_list g = l_shape();
    g.points.insert(g.points.end(), {{5, 0, 0}, {7, 1, 0}, {7, 0, 0}, {5, 1.5, 0}});
    g.faces.push_back({6, 7, 8, 9});  // a bow tie
    const auto m = mesh_from<halfedge_mesh>(g);
    const auto bowtie = T::face_index(m, *std::next(T::faces(m).begin()));
    scratch_dir dir;
    write_bytes(dir / "old.stl", "previous content");
    auto r = io::write_stl(m, dir / "old.stl");
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, errc::topology);
    EXPECT_NE(r.error().message.find("face " + std::to_string(bowtie)), std::string::npos) << r.error().message;
    EXPECT_EQ(read_bytes(dir / "old.stl"), "previous content");
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1);  // no temporary left
    const auto formatted = io::format_stl(m);
    ASSERT_FALSE(formatted);
    EXPECT_EQ(formatted.error().code, errc::topology);
}

TEST(polygon_writers, a_face_with_an_inner_ring_is_refused_by_name_never_dropped) {
    halfedge_mesh m;
    const auto top = cube_with_ringed_top(m);
    const std::string name = "face " + std::to_string(T::face_index(m, top));
    scratch_dir dir;
    for (const char* file : {"r.obj", "r.off", "r.ply"}) {
        write_bytes(dir / file, "previous content");
        auto r = io::write_mesh(m, dir / file);
        ASSERT_FALSE(r) << file;
        EXPECT_EQ(r.error().code, errc::unsupported);
        EXPECT_EQ(r.error().element, (long long)T::face_index(m, top));
        EXPECT_NE(r.error().message.find(name + " has inner rings"), std::string::npos) << r.error().message;
        EXPECT_EQ(read_bytes(dir / file), "previous content") << file;
    }
    for (const auto& formatted : {io::format_obj(m), io::format_off(m), io::format_ply(m)}) {
        ASSERT_FALSE(formatted);
        EXPECT_EQ(formatted.error().code, errc::unsupported);
        EXPECT_EQ(formatted.error().element, (long long)T::face_index(m, top));
    }

    // Cut into triangles first, the same mesh writes, and OBJ keeps the area (20 + 3 + 1).
    ASSERT_TRUE(triangulate_faces(m));
    ASSERT_TRUE(io::write_obj(m, dir / "r.obj"));
    face_vertex_mesh back;
    ASSERT_TRUE(io::read_obj(back, dir / "r.obj"));
    using U = default_traits<face_vertex_mesh>;
    double area = 0;
    for (auto f : U::faces(back)) {
        std::vector<vec3<double>> c;
        for (auto v : U::face_vertices(back, f)) c.push_back(U::position(back, v));
        const auto n = cross(c[1] - c[0], c[2] - c[0]);
        area += std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z) / 2;
    }
    EXPECT_NEAR(area, 24.0, 1e-12);
}

}  // namespace
