// tests/algorithms/repair/repair_cli_test.cpp
// The edit commands repair what the halfedge mesh cannot hold and say so in one line;
// `validate` still describes the file as it is; --vertex N covers every copy of vertex N.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

#include "io/io_support.hpp"
#include "support/cli_runner.hpp"
#include "support/checks.hpp"

namespace {

using hmira_test::scratch_dir;

using hmira_test::run_result;

run_result hmira(const scratch_dir& dir, const std::string& args) { return hmira_test::run_cli(HMIRA_CLI, dir, args); }

std::size_t lines(const std::string& s) { return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n')); }

hmira::face_vertex_mesh read(const std::filesystem::path& p) {
    hmira::face_vertex_mesh m;
    auto r = hmira::io::read_mesh(m, p);
    EXPECT_TRUE(r) << r.error().message;
    return m;
}

// Two tetrahedra touching at vertex 0 (a bow tie), the first one's face 0 wound the wrong way.
const char* bow_tie =
    "OFF\n7 8 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n-1 0 0\n0 -1 0\n0 0 -1\n"
    "3 0 1 2\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
    "3 0 4 5\n3 0 5 6\n3 0 6 4\n3 4 6 5\n";

TEST(RepairCli, a_split_vertex_is_truncated_in_every_copy) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "bow.off", bow_tie);
    const auto r = hmira(dir, "truncate bow.off t.off --vertex 0");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("bow.off: repaired for editing: flipped 1 face (0); split 1 vertex (0) into 1 extra copy"),
              std::string::npos)
        << r.out;
    EXPECT_EQ(lines(r.out), 2u) << r.out;  // the note and the result
    const auto m = read(dir / "t.off");
    EXPECT_TRUE(hmira_test::is_valid(m));
    EXPECT_EQ(m.face_count(), 8u + 2u);              // both corners at vertex 0 cut off
    EXPECT_EQ(m.vertex_count(), 7u + 1u - 2u + 6u);  // a copy added, both copies replaced by 3 new vertices each
}

TEST(RepairCli, validate_still_describes_the_file_as_it_is) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "bow.off", bow_tie);
    const auto r = hmira(dir, "validate bow.off");
    EXPECT_NE(r.code, 0);
    EXPECT_NE(r.out.find("non-manifold vertex"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("inconsistent orientation"), std::string::npos) << r.out;
}

TEST(RepairCli, pig_stl_can_be_truncated_with_a_repair_note) {
    const char* data = std::getenv("HMIRA_TEST_DATA");
    const std::filesystem::path pig = std::filesystem::path(data ? data : "") / "meshes" / "pig.stl";
    if (!data || !std::filesystem::exists(pig)) GTEST_SKIP() << "no test data (HMIRA_TEST_DATA)";
    scratch_dir dir;
    const auto r = hmira(dir, "truncate '" + pig.string() + "' pig.off --all");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("pig.stl: repaired for editing: split 421 vertices (90, 211, 213, 215, 217, 229, 241, 253, "
                         "...) into 443 extra copies"),
              std::string::npos)
        << r.out;
    EXPECT_EQ(lines(r.out), 2u) << r.out;
    const auto v = hmira(dir, "validate pig.off");
    EXPECT_EQ(v.code, 0) << v.out << v.err;
    EXPECT_TRUE(hmira_test::is_valid(read(dir / "pig.off")));
}

}  // namespace
