// `hmira mc` and `hmira voxelize` on volumes and grids they cannot handle: non-finite samples,
// an iso value outside the samples' range, a grid larger than the memory free. Each case runs
// the built binary as a separate process and checks the exit code, the one-line error and that
// no output was written.
#include <gtest/gtest.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <hmira/algorithms/topology/mesh_topology.hpp>
#include <hmira/io/mesh_io.hpp>
#include <hmira/io/volume/inr.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

#include "io/io_support.hpp"
#include "support/cli_runner.hpp"

namespace {

using hmira_test::one_line_error;
using hmira_test::run_result;
using hmira_test::scratch_dir;

/// Runs `[prefix] hmira <args>` in `dir`; `prefix` is shell text run first ("ulimit -v N &&").
run_result hmira(const scratch_dir& dir, const std::string& args, const std::string& prefix = "") {
    return hmira_test::run_cli(HMIRA_CLI, dir, args, prefix);
}

std::filesystem::path data_dir() {
    const char* d = std::getenv("HMIRA_TEST_DATA");
    return d ? std::filesystem::path(d) : std::filesystem::path();
}

/// An n^3 float32 sphere field (negative inside), x fastest, with `bad` at sample (i, j, k).
std::vector<float> sphere_samples(std::size_t n, std::size_t i, std::size_t j, std::size_t k, float bad) {
    std::vector<float> v(n * n * n);
    for (std::size_t z = 0; z < n; ++z)
        for (std::size_t y = 0; y < n; ++y)
            for (std::size_t x = 0; x < n; ++x) {
                const double c = double(n - 1) / 2, dx = double(x) - c, dy = double(y) - c, dz = double(z) - c;
                v[x + n * (y + n * z)] = float(std::sqrt(dx * dx + dy * dy + dz * dz) - double(n) / 3);
            }
    v[i + n * (j + n * k)] = bad;
    return v;
}

std::string bytes_of(const std::vector<float>& v) {
    std::string b(v.size() * sizeof(float), '\0');
    std::memcpy(b.data(), v.data(), b.size());
    return b;
}

/// The same samples as an INRIMAGE-4 file (little-endian float).
std::string inr_of(const std::vector<float>& v, std::size_t n) {
    const std::string d = std::to_string(n);
    std::string h = "#INRIMAGE-4#{\nXDIM=" + d + "\nYDIM=" + d + "\nZDIM=" + d +
                    "\nVDIM=1\nTYPE=float\nPIXSIZE=32 bits\nCPU=decm\nVX=1\nVY=1\nVZ=1\n";
    h.resize(252, '\n');
    return h + "##}\n" + bytes_of(v);
}

TEST(CliMarchingCubes, infinite_samples_are_refused_on_every_path_and_nothing_is_written) {
    scratch_dir dir;
    const std::size_t n = 12;
    for (float bad : {std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity()}) {
        const auto samples = sphere_samples(n, 7, 3, 9, bad);
        hmira_test::write_bytes(dir.path() / "v.raw", bytes_of(samples));
        hmira_test::write_bytes(dir.path() / "v.inr", inr_of(samples, n));
        const std::string name = std::string("sample (7, 3, 9) is ") + (bad > 0 ? "inf" : "-inf");
        // Slab by slab (the default for .raw and .inr), in slabs of 2 slices, and the whole
        // volume at once (--normals).
        for (const std::string source : {"v.raw --dims 12,12,12", "v.inr"})
            for (const std::string how : {"", "--slab-slices 2", "--normals"}) {
                const auto r = hmira(dir, "mc " + source + " out.ply " + how);
                EXPECT_EQ(r.code, 1) << source << " " << how << ": " << r.err;
                EXPECT_TRUE(one_line_error(r, name)) << source << " " << how;
                EXPECT_FALSE(std::filesystem::exists(dir.path() / "out.ply")) << source << " " << how;
            }
    }
    // Without the bad sample the same volume meshes.
    hmira_test::write_bytes(dir.path() / "v.raw", bytes_of(sphere_samples(n, 0, 0, 0, 5.0f)));
    const auto r = hmira(dir, "mc v.raw out.ply --dims 12,12,12");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "out.ply"));
}

TEST(CliMarchingCubes, an_iso_outside_the_volumes_range_is_an_error_naming_the_range) {
    if (data_dir().empty()) GTEST_SKIP() << "HMIRA_TEST_DATA not set";
    const auto skull = data_dir() / "images" / "skull_2.9.inr";
    const auto liver = data_dir() / "images" / "liver.inr.gz";
    if (!std::filesystem::exists(skull) || !std::filesystem::exists(liver)) GTEST_SKIP() << "volumes missing";
    scratch_dir dir;
    // The skull's range, read independently of marching cubes.
    auto grid = hmira::io::read_inr(skull);
    ASSERT_TRUE(grid) << grid.error().message;
    const auto [lo, hi] = std::minmax_element(grid->values().begin(), grid->values().end());
    ASSERT_GT(*lo, 0.0f);
    // As the shortest decimal text that reads back as the same double.
    auto text = [](double x) {
        char b[32];
        return std::string(b, std::to_chars(b, b + sizeof b, x).ptr);
    };
    const std::string range = "range [" + text(double(*lo)) + ", " + text(double(*hi)) + "]";
    for (const std::string how : {"", "--slab-slices 5", "--normals"}) {
        const auto r = hmira(dir, "mc '" + skull.string() + "' s.ply --iso 0 " + how);
        EXPECT_EQ(r.code, 1) << how << ": " << r.err;
        EXPECT_TRUE(one_line_error(r, std::string("iso 0 is outside the samples' ") + range)) << how;
        EXPECT_FALSE(std::filesystem::exists(dir.path() / "s.ply")) << how;
    }
    // Without --iso, a volume is cut at the midpoint of its range: never an empty surface, whole or by slabs.
    for (const std::string how : {"", "--slab-slices 5"}) {
        const auto r = hmira(dir, "mc '" + skull.string() + "' d.ply --inside above " + how);
        EXPECT_EQ(r.code, 0) << how << ": " << r.err;
        EXPECT_EQ(r.out.find(" 0 triangles"), std::string::npos) << r.out;
    }
    // Both volumes at the gallery's commands (the liver, 0 and 1, has 0 in its range).
    for (const std::string& cmd : {"mc '" + skull.string() + "' s.ply --iso 2.9 --inside above",
                                   "mc '" + liver.string() + "' l.ply --iso 0.5 --inside above"}) {
        const auto r = hmira(dir, cmd);
        EXPECT_EQ(r.code, 0) << cmd << ": " << r.err;
        EXPECT_EQ(r.out.find(" 0 triangles"), std::string::npos) << r.out;
    }
}

TEST(CliMarchingCubes, an_iso_at_the_end_of_the_range_is_accepted) {
    scratch_dir dir;
    // Samples 0 and 1 only: iso 1 with inside below puts every sample inside, and is accepted.
    std::string b(4 * 4 * 4, '\0');
    b[21] = 1;
    hmira_test::write_bytes(dir.path() / "b.raw", b);
    const auto r = hmira(dir, "mc b.raw out.ply --dims 4,4,4 --type uint8 --iso 1");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find(" 0 triangles"), std::string::npos) << r.out;
    const auto off = hmira(dir, "mc b.raw out2.ply --dims 4,4,4 --type uint8 --iso 1.5 --inside above");
    EXPECT_EQ(off.code, 1) << off.err;
    EXPECT_TRUE(one_line_error(off, "iso 1.5 is outside the samples' range [0, 1]"));
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "out2.ply"));
}

TEST(CliMarchingCubes, decimate_ratio_writes_the_decimated_closed_surface_on_both_paths) {
    scratch_dir dir;
    const std::size_t n = 20;
    hmira_test::write_bytes(dir.path() / "s.raw", bytes_of(sphere_samples(n, 0, 0, 0, 10.0f)));
    const std::string grid = " --dims 20,20,20 --iso 0";
    ASSERT_EQ(hmira(dir, "mc s.raw full.ply" + grid).code, 0);
    hmira::face_vertex_mesh full;
    ASSERT_TRUE(hmira::io::read_mesh(full, dir.path() / "full.ply"));
    // The .raw file read slab by slab, and the named shape sampled whole: both decimate.
    for (const std::string& args : {"mc s.raw d.ply --slab-slices 6 --decimate-ratio 0.2" + grid,
                                    std::string("mc sphere d.ply --resolution 20 --decimate-ratio 0.2")}) {
        const auto r = hmira(dir, args);
        ASSERT_EQ(r.code, 0) << args << ": " << r.err;
        EXPECT_NE(r.out.find("decimated to "), std::string::npos) << r.out;
        hmira::face_vertex_mesh m;
        ASSERT_TRUE(hmira::io::read_mesh(m, dir.path() / "d.ply"));
        const auto t = hmira::mesh_topology(m);
        EXPECT_TRUE(t.closed()) << args;
        EXPECT_EQ(t.genus, 0) << args;
        EXPECT_EQ(t.non_manifold_edges, 0u) << args;
        if (args.starts_with("mc s.raw")) {
            // A fifth of the full surface's triangles (rounded up; one fewer at most).
            const std::size_t target = (full.face_count() + 4) / 5;
            EXPECT_LE(m.face_count(), target) << args;
            EXPECT_GE(m.face_count() + 1, target) << args;
        }
    }
    const auto bad = hmira(dir, "mc sphere e.ply --decimate-ratio 1.5");
    EXPECT_EQ(bad.code, 2);
    EXPECT_TRUE(one_line_error(bad, "--decimate-ratio must be in [0, 1]"));
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "e.ply"));
}

TEST(CliVoxelize, a_grid_larger_than_the_free_memory_is_refused_at_once_naming_the_estimate) {
    scratch_dir dir;
    // A 2 x 1 x 1 box: at -n 2048 --padding 1024 the grid is 4096 x 3072 x 3072 voxels, whose
    // bits (64 words a row) take 8 * 64 * 3072 * 3072 bytes, about 4.8 GB; run as if only 3 GB
    // were free (HMIRA_TEST_MEMAVAILABLE: an address-space limit would stop the sanitizers).
    hmira_test::write_bytes(dir.path() / "box.off",
                            "OFF\n8 6 0\n0 0 0\n2 0 0\n2 0 1\n0 0 1\n0 1 0\n2 1 0\n2 1 1\n0 1 1\n"
                            "4 0 1 2 3\n4 7 6 5 4\n4 0 4 5 1\n4 1 5 6 2\n4 2 6 7 3\n4 3 7 4 0\n");
    const auto r = hmira(dir, "voxelize box.off out.raw -n 2048 --padding 1024", "HMIRA_TEST_MEMAVAILABLE=3000000000");
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_TRUE(one_line_error(r, "4096 x 3072 x 3072 voxels (--resolution 2048, --padding 1024) needs about 4.8 GB"));
    EXPECT_NE(r.err.find("of memory is free"), std::string::npos) << r.err;
    EXPECT_LT(r.seconds, 10.0);
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "out.raw"));
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "out.raw.txt"));
    // A grid that fits still voxelizes under the same limit.
    const auto small = hmira(dir, "voxelize box.off out.raw -n 32", "HMIRA_TEST_MEMAVAILABLE=3000000000");
    EXPECT_EQ(small.code, 0) << small.err;
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "out.raw"));
}

}  // namespace
