// `hmira subdivide` end to end: a tetrahedron, two Loop levels, has 4 * 16 faces and
// 4 + 6 + 24 = 34 vertices (read back with the library); a quad mesh is refused in one line
// with exit code 1; an unknown scheme is a usage error. Catmull-Clark: a cube, two levels,
// has 6 * 4 * 4 = 96 quads and 8 + 12 + 6 = 26, then 26 + 48 + 24 = 98 vertices; a tetrahedron
// (triangles) one level, 12 quads and 4 + 6 + 4 = 14 vertices.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>

#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

#include "io/io_support.hpp"
#include "support/cli_runner.hpp"

namespace {

using hmira_test::scratch_dir;

using hmira_test::run_result;

run_result hmira(const scratch_dir& dir, const std::string& args) { return hmira_test::run_cli(HMIRA_CLI, dir, args); }

TEST(cli_subdivide, two_loop_levels_of_a_tetrahedron) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "tet.off",
                            "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
    const auto r = hmira(dir, "subdivide tet.off out.off --scheme loop -k 2");
    ASSERT_EQ(r.code, 0) << r.err;
    hmira::face_vertex_mesh m;
    ASSERT_TRUE(hmira::io::read_mesh(m, dir / "out.off"));
    EXPECT_EQ(m.face_count(), 64u);
    EXPECT_EQ(m.vertex_count(), 34u);  // 4 + 6 edges, then 10 + 24 edges
}

TEST(cli_subdivide, catmull_clark_of_a_cube_and_of_a_tetrahedron) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "cube.off",
                            "OFF\n8 6 0\n-1 -1 -1\n1 -1 -1\n1 -1 1\n-1 -1 1\n-1 1 -1\n1 1 -1\n1 1 1\n-1 1 1\n"
                            "4 0 1 2 3\n4 1 5 6 2\n4 2 6 7 3\n4 0 3 7 4\n4 4 5 1 0\n4 7 6 5 4\n");
    auto r = hmira(dir, "subdivide cube.off out.off --scheme catmull-clark -k 2");
    ASSERT_EQ(r.code, 0) << r.err;
    hmira::face_vertex_mesh m;
    ASSERT_TRUE(hmira::io::read_mesh(m, dir / "out.off"));
    EXPECT_EQ(m.face_count(), 96u);
    EXPECT_EQ(m.vertex_count(), 98u);
    for (auto f : m.faces()) EXPECT_EQ(std::ranges::distance(m.face_vertices(f)), 4);
    // The file's vertices come first and in order: corner 6 = (1, 1, 1) moved to (5/9, 5/9, 5/9)
    // after one level, and further in after the second, staying on the diagonal.
    const auto p = m.position(hmira::vertex_handle(6));
    EXPECT_EQ(p.x, p.y);
    EXPECT_EQ(p.y, p.z);
    EXPECT_LT(p.x, 5.0 / 9.0);
    EXPECT_GT(p.x, 0.3);

    hmira_test::write_bytes(dir / "tet.off",
                            "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
    r = hmira(dir, "subdivide tet.off tet-cc.off --scheme catmull-clark");
    ASSERT_EQ(r.code, 0) << r.err;
    hmira::face_vertex_mesh t;
    ASSERT_TRUE(hmira::io::read_mesh(t, dir / "tet-cc.off"));
    EXPECT_EQ(t.face_count(), 12u);
    EXPECT_EQ(t.vertex_count(), 14u);
}

TEST(cli_subdivide, two_sqrt3_levels_of_a_tetrahedron) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "tet.off",
                            "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
    const auto r = hmira(dir, "subdivide tet.off out.off --scheme sqrt3 -k 2");
    ASSERT_EQ(r.code, 0) << r.err;
    hmira::face_vertex_mesh m;
    ASSERT_TRUE(hmira::io::read_mesh(m, dir / "out.off"));
    EXPECT_EQ(m.face_count(), 36u);    // 4 * 3 * 3
    EXPECT_EQ(m.vertex_count(), 20u);  // 4 + 4 faces, then 8 + 12 faces
    // Valence 3: alpha = 5/9, so corner 0 = (0, 0, 0) moves to 5/27 of its three neighbours
    // after the first level, keeping the tetrahedron's symmetry about the x = y = z diagonal.
    const auto p = m.position(hmira::vertex_handle(0));
    EXPECT_NEAR(p.x, p.y, 1e-12);
    EXPECT_NEAR(p.y, p.z, 1e-12);
    EXPECT_GT(p.x, 0.0);
}

TEST(cli_subdivide, refusals) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "quad.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
    auto r = hmira(dir, "subdivide quad.off out.off");
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_NE(r.err.find("face 0 is not a triangle"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.off"));
    r = hmira(dir, "subdivide quad.off out.off --scheme butterfly");
    EXPECT_EQ(r.code, 2) << r.err;
}

}  // namespace
