// `hmira self-intersections` and `hmira validate --self-intersections` end to end: the pairs
// listed, the exit codes, and a clean mesh left alone.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "support/cli_runner.hpp"

namespace {

using hmira_test::run_result;
using hmira_test::scratch_dir;

run_result hmira(const scratch_dir& dir, const std::string& args) { return hmira_test::run_cli(HMIRA_CLI, dir, args); }

std::string mesh_file(const char* name) {
    const char* d = std::getenv("HMIRA_TEST_DATA");
    return d && *d ? (std::filesystem::path(d) / "meshes" / name).string() : std::string();
}

TEST(cli_self_intersections, lists_the_pairs_and_exits_1) {
    const auto file = mesh_file("tetra_intersected_by_triangle.off");
    if (file.empty()) GTEST_SKIP() << "HMIRA_TEST_DATA not set";
    scratch_dir dir;
    const auto r = hmira(dir, "self-intersections '" + file + "'");
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_NE(r.out.find("intersecting pair"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(" 4\n"), std::string::npos) << r.out;  // the lone triangle, face 4
}

TEST(cli_self_intersections, a_clean_mesh_exits_0) {
    const auto file = mesh_file("sphere.off");
    if (file.empty()) GTEST_SKIP() << "HMIRA_TEST_DATA not set";
    scratch_dir dir;
    const auto r = hmira(dir, "self-intersections '" + file + "'");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("no self-intersections"), std::string::npos) << r.out;
}

TEST(cli_self_intersections, validate_checks_them_only_when_asked) {
    const auto file = mesh_file("tetra_intersected_by_triangle.off");
    if (file.empty()) GTEST_SKIP() << "HMIRA_TEST_DATA not set";
    scratch_dir dir;
    const auto plain = hmira(dir, "validate '" + file + "'");
    EXPECT_EQ(plain.out.find("self-intersection"), std::string::npos) << plain.out;
    const auto checked = hmira(dir, "validate --self-intersections '" + file + "'");
    EXPECT_EQ(checked.code, 1);
    EXPECT_NE(checked.out.find("self-intersection: faces "), std::string::npos) << checked.out;
}

}  // namespace
