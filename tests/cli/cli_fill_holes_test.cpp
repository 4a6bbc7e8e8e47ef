// `hmira fill-holes` end to end: --max-edges takes whole numbers >= 3 only (a negative or
// overflowing value is a usage error, not a wrapped "fill everything"), simple loops the
// dynamic programme alone cannot close are filled and the result validates, and a loop left
// open is named with its reason in the summary.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "support/cli_runner.hpp"

namespace {

using hmira_test::one_line_error;
using hmira_test::scratch_dir;

hmira_test::run_result hmira(const scratch_dir& dir, const std::string& args) {
    return hmira_test::run_cli(HMIRA_CLI, dir, args);
}

std::string data(const std::string& name) {
    const char* dir = std::getenv("HMIRA_TEST_DATA");
    if (!dir) return {};
    const auto p = std::filesystem::path(dir) / "meshes" / name;
    return std::filesystem::exists(p) ? p.string() : std::string{};
}

TEST(cli_fill_holes, max_edges_out_of_range_is_a_usage_error) {
    const std::string in = data("patch-23.off");
    if (in.empty()) GTEST_SKIP() << "patch-23.off not found (HMIRA_TEST_DATA)";
    scratch_dir dir;
    for (const std::string bad : {"-1", "18446744073709551616", "2", "0", "x", "3.5"}) {
        const auto r = hmira(dir, "fill-holes '" + in + "' out.off --max-edges=" + bad);
        EXPECT_EQ(r.code, 2) << bad << ": " << r.err;
        EXPECT_TRUE(one_line_error(r, "--max-edges")) << bad;
        EXPECT_FALSE(std::filesystem::exists(dir / "out.off")) << bad;
    }
    const auto r = hmira(dir, "fill-holes '" + in + "' out.off --max-edges 18446744073709551615");
    EXPECT_EQ(r.code, 0) << r.err;
}

/// Fills `name` and validates the output: no boundary left and no problem.
void fills_and_validates(const std::string& name) {
    const std::string in = data(name);
    if (in.empty()) GTEST_SKIP() << name << " not found (HMIRA_TEST_DATA)";
    scratch_dir dir;
    const auto r = hmira(dir, "fill-holes '" + in + "' out.off");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("filled 1 hole"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("open"), std::string::npos) << r.out;
    const auto v = hmira(dir, "validate out.off");
    EXPECT_EQ(v.code, 0) << v.out << v.err;
}

TEST(cli_fill_holes, a_rectangle_whose_corners_are_joined_across_is_filled) { fills_and_validates("patch-23.off"); }
TEST(cli_fill_holes, a_slit_of_coincident_vertices_is_filled) { fills_and_validates("corner_with_sharp_edge.off"); }

TEST(cli_fill_holes, a_loop_left_open_is_named_with_its_reason) {
    const std::string in = data("patch-23.off");
    if (in.empty()) GTEST_SKIP() << "patch-23.off not found (HMIRA_TEST_DATA)";
    scratch_dir dir;
    const auto r = hmira(dir, "fill-holes '" + in + "' out.off --max-edges 40");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("left 1 hole open"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("hole at vertex "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(": 48 edges > --max-edges 40"), std::string::npos) << r.out;
}

}  // namespace
