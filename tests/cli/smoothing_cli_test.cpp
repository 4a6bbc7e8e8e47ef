// `hmira smooth` end to end: a bumpy square's centre vertex flattens, its boundary and a
// --fix vertex stay exactly; a bad --mu is a usage error and writes nothing.
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

// A 3 x 3 vertex square with its centre (vertex 4) raised and vertex 1 on the boundary.
const char* bump =
    "OFF\n9 8 0\n0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 1\n2 1 0\n0 2 0\n1 2 0\n2 2 0\n"
    "3 0 1 4\n3 0 4 3\n3 1 2 5\n3 1 5 4\n3 3 4 7\n3 3 7 6\n3 4 5 8\n3 4 8 7\n";

TEST(cli_smooth, the_bump_flattens_and_the_boundary_stays) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "bump.off", bump);
    const auto r = hmira(dir, "smooth bump.off flat.off --method laplacian --iterations 3");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("smoothed 1 vertex"), std::string::npos) << r.out;
    hmira::face_vertex_mesh m;
    ASSERT_TRUE(hmira::io::read_mesh(m, dir / "flat.off"));
    ASSERT_EQ(m.vertex_count(), 9u);
    EXPECT_LT(m.position(hmira::vertex_handle(4)).z, 0.2);  // 1 -> 1/2 -> 1/4 -> 1/8
    EXPECT_EQ(m.position(hmira::vertex_handle(1)), (hmira::vec3<double>{1, 0, 0}));

    const auto fixed = hmira(dir, "smooth bump.off kept.off --fix 4");
    ASSERT_EQ(fixed.code, 0) << fixed.err;
    hmira::face_vertex_mesh k;
    ASSERT_TRUE(hmira::io::read_mesh(k, dir / "kept.off"));
    EXPECT_EQ(k.position(hmira::vertex_handle(4)), (hmira::vec3<double>{1, 1, 1}));
}

TEST(cli_smooth, a_bad_mu_is_a_usage_error) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "bump.off", bump);
    const auto r = hmira(dir, "smooth bump.off out.off --mu -0.1");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("mu"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.off"));
}

}  // namespace
