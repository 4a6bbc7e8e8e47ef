// `hmira boolean` end to end: two box files in, the output file read back by the test's own
// OFF reader and its volume computed there (divergence theorem), against the volume known by
// hand; the op name checked, a missing input, and an output that is an input refused. Also
// `hmira repair --solid` on both boxes in one file (a self-intersecting soup): their union.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_runner.hpp"

namespace {

using hmira_test::run_result;
using hmira_test::scratch_dir;
using vec = std::array<double, 3>;

run_result hmira(const scratch_dir& dir, const std::string& args) { return hmira_test::run_cli(HMIRA_CLI, dir, args); }

/// Writes the box [lo, hi] as six outward quads.
void write_box(const std::filesystem::path& path, vec lo, vec hi) {
    std::ofstream f(path);
    f << "OFF\n8 6 0\n";
    for (int i = 0; i < 8; ++i)
        f << (i & 1 ? hi[0] : lo[0]) << ' ' << (i & 2 ? hi[1] : lo[1]) << ' ' << (i & 4 ? hi[2] : lo[2]) << '\n';
    f << "4 0 2 3 1\n4 4 5 7 6\n4 0 1 5 4\n4 2 6 7 3\n4 0 4 6 2\n4 1 3 7 5\n";
}

/// An OFF file's points and polygons, read without hmira.
struct off_mesh {
    std::vector<vec> points;
    std::vector<std::vector<std::size_t>> faces;
};

off_mesh read_off(const std::filesystem::path& path) {
    std::ifstream f(path);
    std::string head;
    std::size_t nv = 0, nf = 0, ne = 0;
    f >> head >> nv >> nf >> ne;
    EXPECT_EQ(head, "OFF");
    off_mesh m;
    m.points.resize(nv);
    for (auto& p : m.points) f >> p[0] >> p[1] >> p[2];
    m.faces.resize(nf);
    for (auto& loop : m.faces) {
        std::size_t n = 0;
        f >> n;
        loop.resize(n);
        for (auto& v : loop) f >> v;
    }
    EXPECT_TRUE(bool(f)) << path;
    return m;
}

/// Signed volume by the divergence theorem, each polygon fanned from its first corner.
double volume(const off_mesh& m) {
    double six = 0;
    for (const auto& loop : m.faces)
        for (std::size_t i = 1; i + 1 < loop.size(); ++i) {
            const vec& a = m.points[loop[0]];
            const vec& b = m.points[loop[i]];
            const vec& c = m.points[loop[i + 1]];
            six += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                   a[2] * (b[0] * c[1] - b[1] * c[0]);
        }
    return six / 6;
}

/// Every directed edge has its reverse: the surface is closed.
bool closed(const off_mesh& m) {
    std::map<std::pair<std::size_t, std::size_t>, int> count;
    for (const auto& loop : m.faces)
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const std::size_t a = loop[i], b = loop[(i + 1) % loop.size()];
            count[{std::min(a, b), std::max(a, b)}] += a < b ? 1 : -1;
        }
    for (const auto& [e, c] : count)
        if (c != 0) return false;
    return true;
}

// A = [0,2]^3, B = [1,3] x [0.5,1.5] x [0.5,3]: A n B = [1,2] x [0.5,1.5] x [0.5,2], volume 1.5;
// vol A = 8, vol B = 5.
struct cli_boolean : ::testing::Test {
    scratch_dir dir;
    void SetUp() override {
        write_box(dir.path() / "a.off", {0, 0, 0}, {2, 2, 2});
        write_box(dir.path() / "b.off", {1, 0.5, 0.5}, {3, 1.5, 3});
    }
};

TEST_F(cli_boolean, box_minus_box_has_the_volume_known_by_hand) {
    const auto r = hmira(dir, "boolean a.off b.off out.off --op difference");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("difference of a.off (6 faces) and b.off (6 faces)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("cut triangles"), std::string::npos) << r.out;
    const auto out = read_off(dir.path() / "out.off");
    EXPECT_TRUE(closed(out));
    EXPECT_NEAR(volume(out), 8 - 1.5, 1e-12);
    for (const auto& loop : out.faces) EXPECT_EQ(loop.size(), 3u);
}

TEST_F(cli_boolean, every_op_has_the_volume_known_by_hand_and_union_is_the_default) {
    const std::map<std::string, double> expected{
        {"", 8 + 5 - 1.5}, {"--op union", 8 + 5 - 1.5}, {"--op intersection", 1.5}, {"--op xor", 8 + 5 - 3}};
    for (const auto& [op, v] : expected) {
        const auto r = hmira(dir, "boolean a.off b.off out.off " + op);
        ASSERT_EQ(r.code, 0) << op << ": " << r.err;
        EXPECT_NEAR(volume(read_off(dir.path() / "out.off")), v, 1e-12) << op;
    }
}

TEST_F(cli_boolean, json_reports_the_counts) {
    const auto r = hmira(dir, "boolean a.off b.off out.off --op intersection --json");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out.rfind("{\"op\": \"intersection\", \"faces_a\": 6, \"faces_b\": 6, \"faces\": ", 0), 0u) << r.out;
    EXPECT_NE(r.out.find("\"rounding_intersections\": 0}"), std::string::npos) << r.out;
}

TEST_F(cli_boolean, an_unknown_op_is_a_usage_error) {
    const auto r = hmira(dir, "boolean a.off b.off out.off --op minus");
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(hmira_test::one_line_error(r, "--op"));
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "out.off"));
}

TEST_F(cli_boolean, a_missing_input_is_an_io_failure) {
    const auto r = hmira(dir, "boolean a.off missing.off out.off");
    EXPECT_EQ(r.code, 3);
    EXPECT_TRUE(hmira_test::one_line_error(r, "missing.off"));
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "out.off"));
}

TEST_F(cli_boolean, an_output_that_is_an_input_is_refused_and_left_alone) {
    std::ostringstream before;
    before << std::ifstream(dir.path() / "b.off").rdbuf();
    const auto r = hmira(dir, "boolean a.off b.off ./b.off --op difference");
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(hmira_test::one_line_error(r, "input"));
    std::ostringstream after;
    after << std::ifstream(dir.path() / "b.off").rdbuf();
    EXPECT_EQ(before.str(), after.str());
}

TEST_F(cli_boolean, repair_solid_of_two_overlapping_boxes_in_one_file_is_their_union) {
    {
        std::ofstream f(dir.path() / "both.off");
        f << "OFF\n16 12 0\n";
        for (const auto& [lo, hi] :
             {std::pair{vec{0, 0, 0}, vec{2, 2, 2}}, std::pair{vec{1, 0.5, 0.5}, vec{3, 1.5, 3}}})
            for (int i = 0; i < 8; ++i)
                f << (i & 1 ? hi[0] : lo[0]) << ' ' << (i & 2 ? hi[1] : lo[1]) << ' ' << (i & 4 ? hi[2] : lo[2])
                  << '\n';
        for (int base : {0, 8})
            for (const auto& q : {std::array{0, 2, 3, 1}, std::array{4, 5, 7, 6}, std::array{0, 1, 5, 4},
                                  std::array{2, 6, 7, 3}, std::array{0, 4, 6, 2}, std::array{1, 3, 7, 5}})
                f << "4 " << base + q[0] << ' ' << base + q[1] << ' ' << base + q[2] << ' ' << base + q[3] << '\n';
    }
    const auto r = hmira(dir, "repair both.off solid.off --solid");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("solid of both.off (12 faces)"), std::string::npos) << r.out;
    const auto out = read_off(dir.path() / "solid.off");
    EXPECT_TRUE(closed(out));
    EXPECT_NEAR(volume(out), 8 + 5 - 1.5, 1e-12);
    const auto j = hmira(dir, "repair both.off solid.off --solid --json");
    ASSERT_EQ(j.code, 0) << j.err;
    EXPECT_EQ(j.out.rfind("{\"solid\": true, \"faces_in\": 12, \"faces\": ", 0), 0u) << j.out;
    // Without --solid the file is written as read: both boxes, overlapping.
    const auto plain = hmira(dir, "repair both.off plain.off");
    ASSERT_EQ(plain.code, 0) << plain.err;
    EXPECT_NEAR(volume(read_off(dir.path() / "plain.off")), 8 + 5, 1e-12);
}

}  // namespace
