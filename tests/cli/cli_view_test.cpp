// `hmira view` as a user runs it: the page is written only where a page belongs (an .html or
// .htm name that is none of the inputs), and every build can write it (the viewer bundle is
// committed, so a build without node embeds it too).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "io/io_support.hpp"
#include "support/cli_runner.hpp"

namespace {

using hmira_test::one_line_error;
using hmira_test::run_result;
using hmira_test::scratch_dir;

/// Runs `hmira <args>` (args already shell-quoted where needed) in `dir`.
run_result hmira(const scratch_dir& dir, const std::string& args) { return hmira_test::run_cli(HMIRA_CLI, dir, args); }

const char* cube_off =
    "OFF\n8 6 0\n-1 -1 -1\n1 -1 -1\n1 -1 1\n-1 -1 1\n-1 1 -1\n1 1 -1\n1 1 1\n-1 1 1\n"
    "4 0 1 2 3\n4 7 6 5 4\n4 0 4 5 1\n4 1 5 6 2\n4 2 6 7 3\n4 3 7 4 0\n";
const char* tetrahedron_off = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n";

/// A scratch folder holding a.off (a cube) and b.off (a tetrahedron).
struct two_meshes {
    scratch_dir dir;
    std::string a = cube_off, b = tetrahedron_off;
    two_meshes() {
        hmira_test::write_bytes(dir / "a.off", a);
        hmira_test::write_bytes(dir / "b.off", b);
    }
    /// Both meshes hold exactly what they held at the start.
    ::testing::AssertionResult untouched() const {
        if (hmira_test::read_bytes(dir / "a.off") != a) return ::testing::AssertionFailure() << "a.off changed";
        if (hmira_test::read_bytes(dir / "b.off") != b) return ::testing::AssertionFailure() << "b.off changed";
        return ::testing::AssertionSuccess();
    }
};

TEST(cli_view, an_output_that_is_not_an_html_page_is_refused_and_not_written) {
    two_meshes m;
    for (const std::string args : {"view a.off b.off", "view a.off a.off", "view a.off --compare b.off b.off",
                                   "view a.off --compare b.off a.off", "view a.off page.txt", "view a.off page"}) {
        SCOPED_TRACE(args);
        const auto r = hmira(m.dir, args);
        EXPECT_EQ(r.code, 2);
        const std::string output = args.substr(args.rfind(' ') + 1);
        EXPECT_TRUE(one_line_error(r, output));
        EXPECT_TRUE(m.untouched());
        EXPECT_EQ(m.dir.files(), (std::vector<std::string>{"a.off", "b.off"}));
    }
}

TEST(cli_view, an_output_that_is_an_input_under_another_name_is_refused) {
    two_meshes m;
    namespace fs = std::filesystem;
    fs::create_symlink("a.off", m.dir / "link.html");
    fs::create_hard_link(m.dir / "b.off", m.dir / "hard.htm");
    fs::create_directory(m.dir / "sub");
    for (const std::string args :
         {"view a.off link.html", "view b.off --compare a.off link.html", "view a.off --compare b.off hard.htm",
          "view a.off sub/../link.html", "view sub/../a.off ./link.html"}) {
        SCOPED_TRACE(args);
        const auto r = hmira(m.dir, args);
        EXPECT_EQ(r.code, 2);
        EXPECT_TRUE(one_line_error(r, args.substr(args.rfind(' ') + 1)));
        EXPECT_TRUE(m.untouched());
        EXPECT_TRUE(fs::is_symlink(m.dir / "link.html"));
        EXPECT_EQ(hmira_test::read_bytes(m.dir / "hard.htm"), m.b);
    }
}

TEST(cli_view, pages_are_written_by_every_build) {
    // The bundle is committed: this build embeds it whether or not node was there.
    two_meshes m;
    auto r = hmira(m.dir, "view a.off");
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string page = hmira_test::read_bytes(m.dir / "a.html");
    EXPECT_NE(page.find("<script type=\"application/json\" id=\"hmira-scene\">"), std::string::npos);
    EXPECT_NE(page.find("Three.js Authors"), std::string::npos) << "the three.js bundle is not in the page";
    // Any case of .html or .htm is a page name.
    r = hmira(m.dir, "view a.off --compare b.off Both.HTM");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(hmira_test::read_bytes(m.dir / "Both.HTM").find("Three.js Authors"), std::string::npos);
    EXPECT_TRUE(m.untouched());
}

TEST(cli_view, a_mesh_beyond_the_float_range_of_a_page_is_refused) {
    // Coordinates near the double maximum: the page's float positions would be infinite.
    scratch_dir dir;
    hmira_test::write_bytes(dir / "big.off",
                            "OFF\n4 4 0\n1.7e308 1.7e308 0\n1.7e308 -1.7e308 0\n-1.7e308 0 0\n0 0 1.7e308\n"
                            "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n");
    const auto r = hmira(dir, "view big.off big.html");
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(one_line_error(r, "big.off: vertex 0"));
    EXPECT_EQ(dir.files(), std::vector<std::string>{"big.off"});
    // 1e30 from the centre still fits a float: written.
    hmira_test::write_bytes(dir / "far.off", "OFF\n3 1 0\n1e30 0 0\n0 1e30 0\n0 0 1e30\n3 0 1 2\n");
    EXPECT_EQ(hmira(dir, "view far.off").code, 0);
}

}  // namespace
