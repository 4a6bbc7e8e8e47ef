// `hmira triangulate` end to end: a concave hexagon and a ringless quad come out as triangles
// with the same area (read back with the library); a self-crossing face is refused by its
// file index, in one line, and no output is written.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
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

double area(const hmira::face_vertex_mesh& m) {
    double a = 0;
    for (auto f : m.faces()) {
        const auto vs = m.face_vertices(f);
        for (std::size_t i = 1; i + 1 < vs.size(); ++i) {
            const auto p = m.position(vs[0]), q = m.position(vs[i]), r = m.position(vs[i + 1]);
            const auto n = hmira::cross(q - p, r - p);
            a += std::sqrt(hmira::dot(n, n)) / 2;
        }
    }
    return a;
}

TEST(cli_triangulate, a_concave_face_and_a_quad_become_triangles_of_the_same_area) {
    scratch_dir dir;
    // An L-shaped hexagon (area 3; a fan from its first corner would overlap) and a unit quad.
    hmira_test::write_bytes(dir / "in.obj",
                            "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\nv 5 0 0\nv 6 0 0\nv 6 1 0\nv 5 1 0\n"
                            "f 4 5 6 1 2 3\nf 7 8 9 10\n");
    const auto r = hmira(dir, "triangulate in.obj out.obj");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("cut 2 faces into 6 triangles"), std::string::npos) << r.out;
    hmira::face_vertex_mesh m;
    ASSERT_TRUE(hmira::io::read_mesh(m, dir / "out.obj"));
    EXPECT_EQ(m.face_count(), 6u);
    for (auto f : m.faces()) EXPECT_EQ(m.face_vertices(f).size(), 3u);
    EXPECT_NEAR(area(m), 4.0, 1e-12);
}

TEST(cli_triangulate, delaunay_picks_the_diagonal_between_the_obtuse_corners) {
    scratch_dir dir;
    // A rhombus whose corners 1 and 3 are obtuse (about 118 degrees): ear clipping from
    // corner 1 cuts the long diagonal 4-2 (file numbers), the Delaunay one is the short 1-3.
    hmira_test::write_bytes(dir / "in.obj", "v 0 0 0\nv 3 -5 0\nv 6 0 0\nv 3 5 0\nf 1 2 3 4\n");
    auto diagonal_joins = [&](const char* args, std::size_t a, std::size_t b) {
        const auto r = hmira(dir, args);
        EXPECT_EQ(r.code, 0) << r.err;
        hmira::face_vertex_mesh m;
        EXPECT_TRUE(hmira::io::read_mesh(m, dir / "out.obj"));
        EXPECT_EQ(m.face_count(), 2u);
        for (auto f : m.faces()) {
            bool has_a = false, has_b = false;
            for (auto v : m.face_vertices(f)) {
                has_a |= v.index == a;
                has_b |= v.index == b;
            }
            if (!has_a || !has_b) return false;
        }
        return m.face_count() == 2;
    };
    EXPECT_TRUE(diagonal_joins("triangulate in.obj out.obj", 1, 3));
    EXPECT_TRUE(diagonal_joins("triangulate --delaunay in.obj out.obj", 0, 2));
}

TEST(cli_triangulate, a_self_crossing_face_is_refused_by_index_and_nothing_is_written) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "in.obj",
                            "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 0 0\nv 7 1 0\nv 7 0 0\nv 5 1.5 0\nf 1 2 3\nf 4 5 6 7\n");
    const auto r = hmira(dir, "triangulate in.obj out.obj");
    EXPECT_EQ(r.code, 1);
    EXPECT_EQ(r.err.rfind("hmira: error: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find("face 1"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("not simple"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.obj"));
}

}  // namespace
