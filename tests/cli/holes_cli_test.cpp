// `hmira fill-holes` end to end: a cube missing two faces comes back closed (read back with
// the library: no boundary edge, V - E + F = 2); --max-edges below 3 is a usage error;
// --refine --fair thin-plate fills a planar hole with new vertices in its plane.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <utility>

#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

#include "io/io_support.hpp"
#include "support/cli_runner.hpp"

namespace {

using hmira_test::scratch_dir;

using hmira_test::run_result;

run_result hmira(const scratch_dir& dir, const std::string& args) { return hmira_test::run_cli(HMIRA_CLI, dir, args); }

const char* open_cube =
    "OFF\n8 4 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
    "4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";  // the four sides; bottom and top missing

TEST(cli_fill_holes, a_cube_without_top_and_bottom_comes_back_closed) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "open.off", open_cube);
    const auto r = hmira(dir, "fill-holes open.off closed.off");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("filled 2 holes with 4 triangles"), std::string::npos) << r.out;
    hmira::face_vertex_mesh m;
    ASSERT_TRUE(hmira::io::read_mesh(m, dir / "closed.off"));
    EXPECT_EQ(m.vertex_count(), 8u);
    EXPECT_EQ(m.face_count(), 8u);
    // Every edge used twice, in opposite directions: closed and consistently wound.
    std::map<std::pair<std::size_t, std::size_t>, int> directed;
    for (auto f : m.faces()) {
        const auto vs = m.face_vertices(f);
        for (std::size_t i = 0; i < vs.size(); ++i) ++directed[{vs[i].index, vs[(i + 1) % vs.size()].index}];
    }
    EXPECT_EQ(directed.size(), 2u * 14u);  // 12 cube edges + 2 diagonals, both directions
    for (const auto& [e, n] : directed) {
        EXPECT_EQ(n, 1);
        EXPECT_EQ(directed.count({e.second, e.first}), 1u);
    }
}

/// An 8 x 8 grid of unit squares (two triangles each) in z = 0 without its middle 4 x 4 squares.
std::string holed_grid() {
    std::string pts, faces;
    std::size_t n_faces = 0;
    for (int j = 0; j <= 8; ++j)
        for (int i = 0; i <= 8; ++i) pts += std::to_string(i) + " " + std::to_string(j) + " 0\n";
    auto id = [](int i, int j) { return std::to_string(j * 9 + i); };
    for (int j = 0; j < 8; ++j)
        for (int i = 0; i < 8; ++i) {
            if (i >= 2 && i < 6 && j >= 2 && j < 6) continue;
            faces += "3 " + id(i, j) + " " + id(i + 1, j) + " " + id(i + 1, j + 1) + "\n";
            faces += "3 " + id(i, j) + " " + id(i + 1, j + 1) + " " + id(i, j + 1) + "\n";
            n_faces += 2;
        }
    return "OFF\n81 " + std::to_string(n_faces) + " 0\n" + pts + faces;
}

TEST(cli_fill_holes, refine_and_fair_add_vertices_in_the_holes_plane) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "grid.off", holed_grid());
    const auto r = hmira(dir, "fill-holes grid.off filled.off --max-edges 16 --refine --fair thin-plate");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("filled 1 hole with"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("vert"), std::string::npos) << r.out;
    hmira::face_vertex_mesh m;
    ASSERT_TRUE(hmira::io::read_mesh(m, dir / "filled.off"));
    // The 4 x 4 hole (16 loop edges of length 1) gets more than its 14 bare triangles.
    EXPECT_GT(m.vertex_count(), 81u);
    EXPECT_EQ(m.face_count(), 96u + 14u + 2 * (m.vertex_count() - 81u));
    for (auto v : m.vertices()) {
        const auto p = m.position(v);
        EXPECT_EQ(p[2], 0.0);  // every fixed neighbour lies in z = 0, so the thin plate does too
        EXPECT_GE(p[0], 0.0);
        EXPECT_LE(p[0], 8.0);
    }
}

TEST(cli_fill_holes, an_unknown_fairing_is_a_usage_error) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "grid.off", holed_grid());
    const auto r = hmira(dir, "fill-holes grid.off filled.off --fair soap");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "filled.off"));
}

TEST(cli_fill_holes, max_edges_below_three_is_a_usage_error) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "open.off", open_cube);
    const auto r = hmira(dir, "fill-holes open.off closed.off --max-edges 2");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "closed.off"));
}

}  // namespace
