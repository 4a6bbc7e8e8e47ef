// `hmira remesh` end to end: lengths reached, a square kept, refusals that write nothing, one-line errors.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/geometry/mean_edge_length.hpp>
#include <hmira/algorithms/remeshing/isotropic_remeshing.hpp>
#include <hmira/algorithms/subdivision/loop.hpp>
#include <hmira/io/mesh_io.hpp>

#include <hmira/meshes/face_vertex_mesh.hpp>
#include "io/io_support.hpp"
#include "support/cli_runner.hpp"
#include "algorithms/remeshing/remeshing_support.hpp"
#include "algorithms/triangle/triangle_support.hpp"

namespace {

using namespace hmira_test;

hmira_test::run_result hmira_cli(const hmira_test::scratch_dir& dir, const std::string& args) {
    return hmira_test::run_cli(HMIRA_CLI, dir, args);
}

/// A 6 x 6 square of triangles as OFF text.
std::string square_off() {
    const auto g = grid(6, 6, true);
    std::string s = "OFF\n" + std::to_string(g.points.size()) + " " + std::to_string(g.faces.size()) + " 0\n";
    for (const auto& p : g.points) s += std::to_string(p.x) + " " + std::to_string(p.y) + " 0\n";
    for (const auto& f : g.faces)
        s += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) + "\n";
    return s;
}

TEST(cli_remesh, remeshes_to_the_length_and_keeps_the_square) {
    hmira_test::scratch_dir dir;
    hmira_test::write_bytes(dir / "square.off", square_off());
    const auto r = hmira_cli(dir, "remesh square.off fine.off --length 0.4 -k 4");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("remeshed to edge length 0.4"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("24 feature edges kept"), std::string::npos) << r.out;
    hmira::halfedge_mesh m;
    ASSERT_TRUE(hmira::io::read_mesh(m, dir / "fine.off"));
    EXPECT_TRUE(hmira_test::is_valid(m));
    EXPECT_GE(fraction_in_band(m, 0.4), 0.9);
    const auto positions = all_positions(m);
    for (double c : {0.0, 6.0})
        for (double d : {0.0, 6.0}) EXPECT_TRUE(positions.count({c, d, 0.0}));
}

TEST(cli_remesh, bad_options_and_polygons_are_refused_and_nothing_is_written) {
    hmira_test::scratch_dir dir;
    hmira_test::write_bytes(dir / "square.off", square_off());
    for (const char* args :
         {"--length nan", "--length -1", "--length 0", "--length inf", "--features 200", "-k 0", "--length 1e-9"}) {
        const auto r = hmira_cli(dir, std::string("remesh square.off out.off ") + args);
        EXPECT_EQ(r.code, 2) << args << ": " << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir / "out.off")) << args;
    }
    hmira_test::write_bytes(dir / "quad.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
    const auto q = hmira_cli(dir, "remesh quad.off out.off");
    EXPECT_EQ(q.code, 1) << q.err;
    EXPECT_NE(q.err.find("not a triangle"), std::string::npos) << q.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.off"));
}

TEST(cli_remesh, failures_say_what_in_one_line_and_keep_an_existing_output) {
    hmira_test::scratch_dir dir;
    hmira_test::write_bytes(dir / "square.off", square_off());
    hmira_test::write_bytes(dir / "out.off", "an earlier output\n");
    const std::tuple<const char*, int, const char*> cases[] = {
        {"square.off out.off --length nan", 2, "--length"},
        {"square.off out.off --length 0.4 --features nan", 2, "--features"},
        {"square.off out.off --length 0.4 -k nan", 2, "--iterations"},  // -k is --iterations
        {"square.off out.off --length 0.4 --no-such-option", 2, "--no-such-option"},
        {"missing.off out.off --length 0.4", 3, "missing.off"},
    };
    for (const auto& [args, code, what] : cases) {
        SCOPED_TRACE(args);
        const auto r = hmira_cli(dir, std::string("remesh ") + args);
        EXPECT_EQ(r.code, code) << r.err;
        EXPECT_NE(r.err.find(what), std::string::npos) << r.err;
        EXPECT_LE(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_EQ(hmira_test::read_bytes(dir / "out.off"), "an earlier output\n");
        std::size_t entries = 0;
        for (const auto& e : std::filesystem::directory_iterator(dir.path()))
            entries += e.path().filename().string()[0] != '.';
        EXPECT_EQ(entries, 2u) << "a temporary left behind";
    }
}

}  // namespace
