// `hmira smooth` and `hmira subdivide` on coordinates near the largest double, where sums
// overflow: every scheme and smoother writes finite coordinates (the subdivisions equal to
// 2^600 times those of the same mesh scaled by 2^-600), or, where the true result lies beyond
// the range of double, refuses with exit 1 and writes nothing; and Ctrl-C stops a long
// smoothing with nothing written.
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

#include "support/cli_runner.hpp"

namespace {

using hmira_test::scratch_dir;

hmira_test::run_result hmira(const scratch_dir& dir, const std::string& args) {
    return hmira_test::run_cli(HMIRA_CLI, dir, args);
}

// The tetrahedron from the report, and the same scaled by 2^-600 (printed exactly: 17 digits).
const char* huge_off =
    "OFF\n4 4 0\n1.7e308 1.7e308 0\n1.7e308 -1.7e308 0\n-1.7e308 0 0\n0 0 1.7e308\n"
    "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n";

std::string small_off() {
    char c[64];
    std::snprintf(c, sizeof c, "%.17g", std::ldexp(1.7e308, -600));
    const std::string s = c;
    return "OFF\n4 4 0\n" + s + " " + s + " 0\n" + s + " -" + s + " 0\n-" + s + " 0 0\n0 0 " + s +
           "\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n";
}

std::vector<std::array<double, 3>> points_of(const std::filesystem::path& p) {
    hmira::face_vertex_mesh m;
    EXPECT_TRUE(hmira::io::read_mesh(m, p)) << p;
    std::vector<std::array<double, 3>> out;
    for (auto v : m.vertices()) {
        const auto q = m.position(v);
        out.push_back({q.x, q.y, q.z});
    }
    return out;
}

::testing::AssertionResult all_finite(const std::vector<std::array<double, 3>>& points) {
    if (points.empty()) return ::testing::AssertionFailure() << "no vertices";
    for (std::size_t i = 0; i < points.size(); ++i)
        for (double x : points[i])
            if (!std::isfinite(x)) return ::testing::AssertionFailure() << "vertex " << i << " has " << x;
    return ::testing::AssertionSuccess();
}

TEST(cli_smooth_subdivide, every_scheme_subdivides_huge_coordinates_to_a_finite_file) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "b.off", huge_off);
    hmira_test::write_bytes(dir / "small.off", small_off());
    for (const std::string scheme : {"loop", "sqrt3", "catmull-clark"}) {
        SCOPED_TRACE(scheme);
        for (const std::string levels : {"1", "2"}) {
            auto r = hmira(dir, "subdivide b.off s.off --scheme " + scheme + " -k " + levels);
            ASSERT_EQ(r.code, 0) << r.err;
            EXPECT_EQ(hmira(dir, "info s.off").code, 0);
            r = hmira(dir, "subdivide small.off t.off --scheme " + scheme + " -k " + levels);
            ASSERT_EQ(r.code, 0) << r.err;
            const auto huge = points_of(dir / "s.off"), small = points_of(dir / "t.off");
            EXPECT_TRUE(all_finite(huge));
            ASSERT_EQ(huge.size(), small.size());
            for (std::size_t i = 0; i < huge.size(); ++i)
                for (int d = 0; d < 3; ++d) {
                    EXPECT_LE(std::abs(huge[i][d]), 1.7e308);
                    EXPECT_NEAR(huge[i][d] / 1e308, std::ldexp(small[i][d], 600) / 1e308, 1e-15) << "vertex " << i;
                }
        }
    }
}

TEST(cli_smooth_subdivide, smoothing_huge_coordinates_writes_the_finite_result) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "b.off", huge_off);
    // One Laplacian step of 1/2: each vertex halfway to the mean of the other three (worked
    // out in exact arithmetic).
    auto r = hmira(dir, "smooth b.off s.off --method laplacian --iterations 1");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(hmira(dir, "info s.off").code, 0);
    const double t = 1.7e308 / 6;
    const std::vector<std::array<double, 3>> want{{3 * t, 2 * t, t}, {3 * t, -2 * t, t}, {-t, 0, t}, {t, 0, 3 * t}};
    const auto got = points_of(dir / "s.off");
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < got.size(); ++i)
        for (int d = 0; d < 3; ++d) EXPECT_NEAR(got[i][d] / 1e308, want[i][d] / 1e308, 1e-15) << "vertex " << i;
    // Taubin (the default), uniform and cotangent: finite, and within the input's range (the
    // filter shrinks this tetrahedron).
    for (const std::string weights : {"uniform", "cotangent"}) {
        r = hmira(dir, "smooth b.off s.off --weights " + weights);
        ASSERT_EQ(r.code, 0) << r.err;
        EXPECT_EQ(hmira(dir, "info s.off").code, 0);
        const auto p = points_of(dir / "s.off");
        EXPECT_TRUE(all_finite(p));
        for (const auto& q : p)
            for (double x : q) EXPECT_LE(std::abs(x), 1.7e308);
    }
}

TEST(cli_smooth_subdivide, a_taubin_step_beyond_the_range_of_double_exits_1_and_writes_nothing) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "b.off", huge_off);
    // mu = -1 after a small lambda puts vertex 0's x near 3.4e308.
    const auto r = hmira(dir, "smooth b.off s.off --lambda 0.01 --mu -1");
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_EQ(r.err.rfind("hmira: error: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find("vertex "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("beyond the range of double"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "s.off"));
}

TEST(cli_smooth_subdivide, ctrl_c_stops_a_long_smoothing_and_writes_nothing) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "t.off",
                            "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n");
    ASSERT_EQ(hmira(dir, "subdivide t.off b.off -k 5").code, 0);  // 4096 faces: a million iterations take minutes
    const auto r = hmira_test::run_cli(HMIRA_CLI, dir, "smooth b.off s.off --iterations 1000000", "",
                                       "timeout --preserve-status -s INT 0.5");
    EXPECT_EQ(r.code, 128 + 2);  // ended by SIGINT
    EXPECT_LT(r.seconds, 10.0);
    EXPECT_FALSE(std::filesystem::exists(dir / "s.off"));
}

}  // namespace
