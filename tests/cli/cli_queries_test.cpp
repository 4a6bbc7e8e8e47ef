// `hmira distance`, `sample`, `sdf` and `offset` end to end: the built binary on small meshes
// written here, its outputs read back and checked against what the geometry says (a parallel
// copy's distance, points on the octahedron, the field's sign, the offset shell's distance).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <hmira/algorithms/spatial/signed_distance.hpp>
#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

#include "io/io_support.hpp"
#include "support/cli_runner.hpp"

namespace {

using hmira_test::run_result;
using hmira_test::scratch_dir;

run_result hmira(const scratch_dir& dir, const std::string& args) { return hmira_test::run_cli(HMIRA_CLI, dir, args); }

void write_text(const std::filesystem::path& p, const std::string& text) { std::ofstream(p) << text; }

const char* octahedron_off =
    "OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n"
    "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n";

std::string file_bytes(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

TEST(cli_queries, distance_of_a_parallel_copy_is_the_shift) {
    scratch_dir dir;
    write_text(dir / "a.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
    write_text(dir / "b.off", "OFF\n4 1 0\n0 0 0.25\n1 0 0.25\n1 1 0.25\n0 1 0.25\n4 0 1 2 3\n");
    const auto r = hmira(dir, "distance a.off b.off --json --samples 2000");
    ASSERT_EQ(r.code, 0) << r.err;
    const auto at = r.out.find("\"symmetric\": ");
    ASSERT_NE(at, std::string::npos) << r.out;
    EXPECT_NEAR(std::strtod(r.out.c_str() + at + 13, nullptr), 0.25, 1e-12) << r.out;
    EXPECT_NE(r.out.find("\"b_to_a\": {\"max\": "), std::string::npos) << r.out;
    const auto text = hmira(dir, "distance a.off b.off --samples 2000");
    ASSERT_EQ(text.code, 0);
    EXPECT_NE(text.out.find("Hausdorff distance: 0.25"), std::string::npos) << text.out;
    EXPECT_EQ(hmira(dir, "distance a.off missing.off").code, 3);
}

TEST(cli_queries, sample_writes_reproducible_points_on_the_surface) {
    scratch_dir dir;
    write_text(dir / "oct.off", octahedron_off);
    ASSERT_EQ(hmira(dir, "sample oct.off p1.ply --count 500 --seed 3").code, 0);
    ASSERT_EQ(hmira(dir, "sample oct.off p2.ply --count 500 --seed 3").code, 0);
    const auto blue = hmira(dir, "sample oct.off p3.ply --count 200 --method poisson_disk");
    ASSERT_EQ(blue.code, 0) << blue.err;
    EXPECT_EQ(file_bytes(dir / "p1.ply"), file_bytes(dir / "p2.ply"));
    hmira::face_vertex_mesh cloud;
    ASSERT_TRUE(hmira::io::read_mesh(cloud, dir / "p1.ply"));
    ASSERT_EQ(cloud.vertex_count(), 500u);
    for (auto v : cloud.vertices()) {
        const auto p = cloud.position(v);
        EXPECT_NEAR(std::abs(p.x) + std::abs(p.y) + std::abs(p.z), 1, 1e-6);
    }
    EXPECT_EQ(hmira(dir, "sample oct.off p4.ply --method nope").code, 2);
}

TEST(cli_queries, sdf_writes_a_signed_field_with_its_sidecar) {
    scratch_dir dir;
    write_text(dir / "oct.off", octahedron_off);
    const auto r = hmira(dir, "sdf oct.off f.raw -n 9 --padding 0");
    ASSERT_EQ(r.code, 0) << r.err;
    const auto side = file_bytes(dir / "f.raw.txt");
    EXPECT_NE(side.find("dims: 9,9,9"), std::string::npos) << side;
    EXPECT_NE(side.find("type: float32"), std::string::npos) << side;
    const auto raw = file_bytes(dir / "f.raw");
    ASSERT_EQ(raw.size(), 9u * 9 * 9 * 4);
    std::vector<float> f(9 * 9 * 9);
    std::memcpy(f.data(), raw.data(), raw.size());
    // Grid samples at the centres of 9 voxels across [-1, 1]: the middle one is the origin,
    // 1/sqrt(3) inside every face; the corners are outside.
    EXPECT_NEAR(f[4 + 9 * (4 + 9 * 4)], -1 / std::sqrt(3.0), 1e-6);
    EXPECT_GT(f[0], 0);
    EXPECT_GT(f[f.size() - 1], 0);
}

TEST(cli_queries, offset_shell_lies_at_the_distance) {
    scratch_dir dir;
    write_text(dir / "oct.off", octahedron_off);
    const auto r = hmira(dir, "offset oct.off shell.off --distance 0.2 -n 32");
    ASSERT_EQ(r.code, 0) << r.err;
    hmira::face_vertex_mesh oct, shell;
    ASSERT_TRUE(hmira::io::read_mesh(oct, dir / "oct.off"));
    ASSERT_TRUE(hmira::io::read_mesh(shell, dir / "shell.off"));
    ASSERT_GT(shell.face_count(), 100u);
    std::vector<hmira::vec3<double>> q;
    for (auto v : shell.vertices()) q.push_back(shell.position(v));
    const auto d = hmira::signed_distance(oct, q);
    ASSERT_TRUE(d);
    for (double x : d->distances) EXPECT_NEAR(x, 0.2, 2.4 / 25);
}

}  // namespace
