// `hmira fill-holes` end to end: a cube missing two faces comes back closed (read back with
// the library: no boundary edge, V - E + F = 2); --max-edges below 3 is a usage error.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <map>
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

TEST(cli_fill_holes, max_edges_below_three_is_a_usage_error) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "open.off", open_cube);
    const auto r = hmira(dir, "fill-holes open.off closed.off --max-edges 2");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "closed.off"));
}

}  // namespace
