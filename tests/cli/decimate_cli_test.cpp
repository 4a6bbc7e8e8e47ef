// `hmira decimate` end to end: face counts, exit codes, one-line errors, outputs left alone.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <hmira/algorithms/decimation/decimate.hpp>
#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/subdivision/loop.hpp>
#include <filesystem>
#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "io/io_support.hpp"
#include "support/cli_runner.hpp"
#include "algorithms/decimation/decimation_support.hpp"
#include "algorithms/triangle/triangle_support.hpp"

namespace {

using namespace hmira_test;

hmira_test::run_result hmira_cli(const hmira_test::scratch_dir& dir, const std::string& args) {
    return hmira_test::run_cli(HMIRA_CLI, dir, args);
}

/// A face list as OFF text (positions printed to 17 digits).
std::string off_text(const face_list& t) {
    std::ostringstream s;
    s.precision(17);
    s << "OFF\n" << t.points.size() << " " << t.faces.size() << " 0\n";
    for (const auto& p : t.points) s << p.x << " " << p.y << " " << p.z << "\n";
    for (const auto& f : t.faces) {
        s << f.size();
        for (auto i : f) s << " " << i;
        s << "\n";
    }
    return s.str();
}

/// The names in `dir` other than the runner's own .stdout and .stderr.
std::set<std::string> names_in(const hmira_test::scratch_dir& dir) {
    std::set<std::string> out;
    for (const auto& e : std::filesystem::directory_iterator(dir.path()))
        if (e.path().filename().string()[0] != '.') out.insert(e.path().filename().string());
    return out;
}

TEST(cli_decimate, reaches_the_requested_face_count_and_writes_a_valid_mesh_of_the_same_genus) {
    hmira_test::scratch_dir dir;
    const face_list torus_faces = bumpy_torus(20, 12, false, 7);  // 480 triangles, genus 1
    ASSERT_EQ(torus_faces.faces.size(), 480u);
    hmira_test::write_bytes(dir / "torus.off", off_text(torus_faces));
    for (const auto& [args, target] : {std::pair<std::string, std::size_t>{"--faces 100", 100}, {"--ratio 0.5", 240}}) {
        SCOPED_TRACE(args);
        const auto r = hmira_cli(dir, "decimate torus.off small.off " + args);
        ASSERT_EQ(r.code, 0) << r.err;
        EXPECT_NE(r.out.find("decimated to"), std::string::npos) << r.out;
        hmira::halfedge_mesh m;
        ASSERT_TRUE(hmira::io::read_mesh(m, dir / "small.off"));
        EXPECT_TRUE(is_valid(m));
        EXPECT_TRUE(natively_valid(m));
        EXPECT_EQ(chi(m), 0);
        const std::size_t faces = hmira::default_traits<hmira::halfedge_mesh>::face_count(m);
        EXPECT_LE(faces, target);
        EXPECT_GE(faces + 1, target);
    }
}

TEST(cli_decimate, bad_command_lines_exit_2_naming_the_option_and_leave_the_output_alone) {
    hmira_test::scratch_dir dir;
    hmira_test::write_bytes(dir / "torus.off", off_text(bumpy_torus(20, 12, false, 7)));
    hmira_test::write_bytes(dir / "out.off", "an earlier output\n");
    const std::pair<const char*, const char*> cases[] = {
        {"", "--faces"},  // no target at all
        {"--ratio nan", "--ratio"},
        {"--ratio inf", "--ratio"},
        {"--ratio 1.5", "--ratio"},
        {"--max-error nan", "--max-error"},
        {"--max-error -1", "--max-error"},
        {"--faces nan", "--faces"},
        {"--faces -3", "--faces"},
        {"--faces 10 --max-normal-angle 200", "--max-normal-angle"},
        {"--faces 10 --max-aspect-ratio 0.5", "--max-aspect-ratio"},
        {"--faces 10 --fix 100000", "--fix"},
        {"--faces 10 --no-such-option", "--no-such-option"},
    };
    for (const auto& [args, option] : cases) {
        SCOPED_TRACE(args);
        const auto r = hmira_cli(dir, std::string("decimate torus.off out.off ") + args);
        EXPECT_EQ(r.code, 2) << r.err;
        EXPECT_NE(r.err.find(option), std::string::npos) << r.err;
        EXPECT_LE(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_EQ(hmira_test::read_bytes(dir / "out.off"), "an earlier output\n");
        EXPECT_EQ(names_in(dir), (std::set<std::string>{"out.off", "torus.off"}));
    }
}

TEST(cli_decimate, a_missing_input_exits_3_naming_the_file_and_writes_nothing) {
    hmira_test::scratch_dir dir;
    const auto r = hmira_cli(dir, "decimate missing.off out.off --faces 10");
    EXPECT_EQ(r.code, 3) << r.err;
    EXPECT_NE(r.err.find("missing.off"), std::string::npos) << r.err;
    EXPECT_LE(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(names_in(dir).empty());
}

}  // namespace
