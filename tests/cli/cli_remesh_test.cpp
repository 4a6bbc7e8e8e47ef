// `hmira remesh` at the edges of what doubles hold, and its refusal of runs too large for the
// machine's memory; `hmira extrude` with a direction too short or too long to normalise. Each
// case runs the built binary as a separate process.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <hmira/algorithms/validation/validate.hpp>
#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "io/io_support.hpp"
#include "support/cli_runner.hpp"
#include "support/checks.hpp"

namespace {

using hmira_test::one_line_error;
using hmira_test::run_result;
using hmira_test::scratch_dir;

/// Runs `[env] hmira <args>` (args already shell-quoted where needed) in `dir`.
run_result hmira(const scratch_dir& dir, const std::string& args, const std::string& env = "") {
    return hmira_test::run_cli(HMIRA_CLI, dir, args, env);
}

std::string number(double x) {
    char b[40];
    std::snprintf(b, sizeof b, "%.17g", x);
    return b;
}

/// The octahedron with vertices at +-s on the axes, shifted by `offset` along x, as OFF text:
/// 12 edges of length s sqrt 2, 8 faces of area (sqrt 3 / 2) s^2.
std::string octahedron_off(double s, double offset = 0) {
    std::string t = "OFF\n6 8 0\n";
    const double p[6][3] = {{s, 0, 0}, {-s, 0, 0}, {0, s, 0}, {0, -s, 0}, {0, 0, s}, {0, 0, -s}};
    for (const auto& v : p) t += number(v[0] + offset) + " " + number(v[1]) + " " + number(v[2]) + "\n";
    t += "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n";
    return t;
}

/// Every coordinate of the OFF file at `path` finite, and the mesh valid. The validation runs
/// on a copy scaled by a power of two to about unit size (`scale`: the mesh's size), since
/// validate's zero-area test squares coordinates.
::testing::AssertionResult finite_and_valid(const std::filesystem::path& path, double scale = 1) {
    hmira::halfedge_mesh m;
    if (auto r = hmira::io::read_mesh(m, path); !r) return ::testing::AssertionFailure() << r.error().message;
    for (auto v : m.vertices()) {
        const auto p = m.position(v);
        if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)))
            return ::testing::AssertionFailure() << "vertex " << v.index << " is not finite";
        m.set_position(v, p * std::ldexp(1.0, -std::ilogb(scale)));
    }
    if (!hmira_test::is_valid(m)) return ::testing::AssertionFailure() << "invalid mesh";
    if (m.face_count() == 0) return ::testing::AssertionFailure() << "no faces";
    return ::testing::AssertionSuccess();
}

// Without --length the target is the mean edge length, which must not come out infinite or 0
// (squared coordinates above ~1e154 or below ~1e-154) and be reported as a bad option (exit 2)
// the user never gave. What no scaling can help is refused as input, naming the scale.
TEST(cli_remesh_scale, an_input_no_rescaling_helps_is_refused_as_input_naming_its_scale) {
    scratch_dir dir;
    const struct {
        const char* name;
        std::string text;
        const char* says;
    } cases[] = {
        {"tiny.off", octahedron_off(1e-300), "the mesh spans only 2e-300, too small to remesh"},
        {"huge.off", octahedron_off(1e308), "a coordinate reaches 1e+308, too large to remesh"},
        {"point.off", octahedron_off(0, 5), "all vertices coincide"},
    };
    for (const auto& c : cases) {
        for (const char* length : {"", " --length 0.5"}) {
            SCOPED_TRACE(std::string(c.name) + length);
            hmira_test::write_bytes(dir / c.name, c.text);
            const auto r = hmira(dir, std::string("remesh ") + c.name + " out.off" + length);
            EXPECT_EQ(r.code, 1) << r.err;
            EXPECT_TRUE(one_line_error(r, c.name));
            EXPECT_TRUE(one_line_error(r, c.says));
            EXPECT_EQ(r.err.find("nan"), std::string::npos) << r.err;
            EXPECT_FALSE(std::filesystem::exists(dir / "out.off"));
        }
    }
}

TEST(cli_remesh_scale, meshes_far_from_unit_size_remesh_at_their_mean_edge_length) {
    scratch_dir dir;
    for (const double s : {1e-290, 1e-170, 1e-140, 1e140, 1e200, 1e306}) {
        SCOPED_TRACE(s);
        hmira_test::write_bytes(dir / "in.off", octahedron_off(s));
        const auto r = hmira(dir, "remesh in.off out.off -k 2");
        ASSERT_EQ(r.code, 0) << r.err;
        // The mean edge length, s sqrt 2, as the report prints it (6 significant digits).
        char want[64];
        std::snprintf(want, sizeof want, "remeshed to edge length %g", s * std::sqrt(2.0));
        EXPECT_NE(r.out.find(want), std::string::npos) << r.out;
        EXPECT_TRUE(finite_and_valid(dir / "out.off", s));
        std::filesystem::remove(dir / "out.off");
    }
}

// An explicit --length on a 1e-200 mesh: area and L^2 both underflow to 0 when squared
// directly, so the estimate must not be their ratio (NaN).
TEST(cli_remesh_scale, an_explicit_length_on_a_tiny_mesh_remeshes_it) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "tiny.off", octahedron_off(1e-200));
    const auto r = hmira(dir, "remesh tiny.off out.off --length 5e-201 -k 2");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("remeshed to edge length 5e-201"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("nan"), std::string::npos) << r.out;
    EXPECT_TRUE(finite_and_valid(dir / "out.off", 1e-200));
    hmira::halfedge_mesh m;
    ASSERT_TRUE(hmira::io::read_mesh(m, dir / "out.off"));
    EXPECT_GT(m.face_count(), 8u);  // refined: the octahedron's edges are 1.4e-200 long
}

TEST(cli_remesh_scale, a_length_absurdly_small_for_the_mesh_is_a_usage_error_without_nan) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "in.off", octahedron_off(1));
    for (const char* length : {"1e-200", "1e-320"}) {
        SCOPED_TRACE(length);
        const auto r = hmira(dir, std::string("remesh in.off out.off --length ") + length);
        EXPECT_EQ(r.code, 2) << r.err;
        EXPECT_TRUE(one_line_error(r, "would make more than 1e308 triangles needing more than 1e308 bytes of memory"));
        EXPECT_EQ(r.err.find("nan"), std::string::npos) << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir / "out.off"));
    }
}

// An estimate above the free memory is refused up front, naming it, rather than running
// until the memory runs out (the fixed limit of 2^28 triangles is far beyond most machines).
TEST(cli_remesh_memory, an_estimate_above_the_free_memory_is_refused_at_once_naming_it) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "in.off", octahedron_off(1));
    // Area 8 (sqrt 3 / 2) over (sqrt 3 / 4) L^2: 16 / L^2 = 1.6e7 triangles at L = 0.001.
    const auto r = hmira(dir, "remesh in.off out.off --length 0.001", "HMIRA_TEST_MEMAVAILABLE=1073741824");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_TRUE(one_line_error(r, "in.off: --length 0.001 would make about 1.6e+07 triangles needing about"));
    EXPECT_TRUE(one_line_error(r, "GiB of memory, more than the 1 GiB free"));
    EXPECT_LT(r.seconds, 10.0);
    EXPECT_FALSE(std::filesystem::exists(dir / "out.off"));
    // A length whose estimate fits in the same memory runs.
    const auto fits = hmira(dir, "remesh in.off out.off --length 0.1 -k 1", "HMIRA_TEST_MEMAVAILABLE=1073741824");
    EXPECT_EQ(fits.code, 0) << fits.err;
    EXPECT_TRUE(finite_and_valid(dir / "out.off"));
}

TEST(cli_remesh_memory, a_length_far_beyond_any_memory_is_refused_at_once) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "in.off", octahedron_off(1));
    const auto r = hmira(dir, "remesh in.off out.off --length 1e-6");  // 1.6e13 triangles
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_TRUE(one_line_error(r, "would make about 1.6e+13 triangles"));
    EXPECT_LT(r.seconds, 10.0);
    EXPECT_FALSE(std::filesystem::exists(dir / "out.off"));
}

TEST(cli_remesh_memory, the_elephant_at_a_tiny_length_is_refused_without_running) {
    const char* data = std::getenv("HMIRA_TEST_DATA");
    const std::filesystem::path elephant = data ? std::filesystem::path(data) / "meshes" / "elephant.off" : "";
    if (!data || !std::filesystem::exists(elephant)) GTEST_SKIP() << "run scripts/test-data.sh first";
    scratch_dir dir;
    const auto r = hmira(dir, "remesh '" + elephant.string() + "' out.off --length 0.0005",
                         "HMIRA_TEST_MEMAVAILABLE=2147483648");  // 2.74 GiB needed
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_TRUE(one_line_error(r, "about 2.74 GiB of memory, more than the 2 GiB free"));
    EXPECT_LT(r.seconds, 10.0);
    EXPECT_FALSE(std::filesystem::exists(dir / "out.off"));
}

// A direction whose squared length underflows to 0 (or overflows) has no length to normalise
// by: a bad option value, though not all its components are 0.
TEST(cli_extrude_direction, a_direction_that_cannot_be_normalised_is_a_usage_error) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "in.off", octahedron_off(1));
    for (const char* d : {"1e-320,0,0", "0,1e-170,1e-170", "1e200,0,0", "1e300,1e300,1e300"}) {
        SCOPED_TRACE(d);
        const auto r = hmira(dir, std::string("extrude in.off out.off --face 0 --direction ") + d);
        EXPECT_EQ(r.code, 2) << r.err;
        EXPECT_TRUE(one_line_error(r, std::string("--direction ") + d + ": cannot be normalised"));
        EXPECT_FALSE(std::filesystem::exists(dir / "out.off"));
    }
    // Short and long ones that can still be normalised move the face by --distance along +x.
    for (const char* d : {"1e-150,0,0", "1e150,0,0"}) {
        SCOPED_TRACE(d);
        const auto r = hmira(dir, std::string("extrude in.off out.off --face 0 --distance 2 --direction ") + d);
        ASSERT_EQ(r.code, 0) << r.err;
        hmira::halfedge_mesh m;
        ASSERT_TRUE(hmira::io::read_mesh(m, dir / "out.off"));
        EXPECT_TRUE(hmira_test::is_valid(m));
        double largest_x = -1;
        for (auto v : m.vertices()) largest_x = std::max(largest_x, double(m.position(v).x));
        EXPECT_EQ(largest_x, 3.0);  // vertex (1, 0, 0) of face 0, moved by 2 along x
        std::filesystem::remove(dir / "out.off");
    }
}

}  // namespace
