// Standing rules every `hmira` subcommand that writes a file keeps, checked over all of them
// (the list of `hmira --help`) with hostile inputs, as separate processes:
//   1. no output ever holds a non-finite coordinate: a run either writes a file whose every
//      coordinate is finite (read back with the library's reader) or fails and writes nothing;
//   2. no run overwrites one of its inputs (under any spelling of its name), nor an existing
//      file whose extension is not the format the subcommand writes;
//   3. a long loop can be interrupted: SIGINT ends `hmira smooth` promptly and leaves no output.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <ostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

#include "io/io_support.hpp"
#include "support/cli_runner.hpp"

namespace {

using hmira_test::scratch_dir;
namespace fs = std::filesystem;

using hmira_test::one_line_error;
using hmira_test::run_result;

/// Runs `hmira <args>` (args already shell-quoted where needed) in `dir`. A run that has not
/// ended after 120 s is killed (exit 137 from timeout(1)): a hang fails the case, not the suite.
run_result hmira(const scratch_dir& dir, const std::string& args) {
    return hmira_test::run_cli(HMIRA_CLI, dir, args, "", "timeout -s KILL 120");
}

// ---- the hostile inputs ---------------------------------------------------------------------

/// A tetrahedron near the largest double: any sum, difference or midpoint of two corners overflows.
const char* overflow_off =
    "OFF\n4 4 0\n1.7e308 1.7e308 0\n1.7e308 -1.7e308 0\n-1.7e308 0 0\n0 0 1.7e308\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 "
    "3\n";
/// A cube 1e-300 across: products of coordinates underflow to zero (lengths, areas, normals).
const char* tiny_off =
    "OFF\n8 6 0\n-1e-300 -1e-300 -1e-300\n1e-300 -1e-300 -1e-300\n1e-300 -1e-300 1e-300\n-1e-300 -1e-300 1e-300\n"
    "-1e-300 1e-300 -1e-300\n1e-300 1e-300 -1e-300\n1e-300 1e-300 1e-300\n-1e-300 1e-300 1e-300\n"
    "4 0 1 2 3\n4 7 6 5 4\n4 0 4 5 1\n4 1 5 6 2\n4 2 6 7 3\n4 3 7 4 0\n";
const char* cube_off =
    "OFF\n8 6 0\n-1 -1 -1\n1 -1 -1\n1 -1 1\n-1 -1 1\n-1 1 -1\n1 1 -1\n1 1 1\n-1 1 1\n"
    "4 0 1 2 3\n4 7 6 5 4\n4 0 4 5 1\n4 1 5 6 2\n4 2 6 7 3\n4 3 7 4 0\n";

/// The vertex lines of an OFF text as an .xyz point file (for delaunay).
std::string points_of(const std::string& off) {
    std::istringstream in(off);
    std::string line, out;
    std::getline(in, line);
    std::getline(in, line);
    std::istringstream counts(line);
    std::size_t n = 0;
    counts >> n;
    for (std::size_t i = 0; i < n && std::getline(in, line); ++i) out += line + "\n";
    return out;
}

struct input {
    const char* name;
    const char* off;
};
const input inputs[] = {{"overflow", overflow_off}, {"tiny", tiny_off}, {"cube", cube_off}};

// ---- every subcommand that writes ------------------------------------------------------------

/// A run of a writing subcommand: `args` with IN (the input file) and OUT (the output) put in.
struct writer {
    const char* name;  ///< test name part
    const char* args;
    const char* input_ext;  ///< ".off" (a mesh) or ".xyz" (points)
    const char* output;     ///< output name (its extension picks the format)
};

// Every writing subcommand of `hmira --help` but view (an HTML page: tests/cli/cli_view_test.cpp
// checks it refuses what its float positions cannot hold), voxelize (checked below: its
// outputs hold voxels, and the .raw sidecar's origin and spacing) and sdf (a float32 volume:
// tests/cli/cli_queries_test.cpp).
const writer writers[] = {
    {"convert_off", "convert IN OUT", ".off", "out.off"},
    {"convert_obj", "convert IN OUT", ".off", "out.obj"},
    {"convert_ply", "convert IN OUT", ".off", "out.ply"},
    {"convert_ply_float", "convert IN OUT --float", ".off", "out.ply"},
    {"convert_stl", "convert IN OUT", ".off", "out.stl"},
    {"flip", "flip IN OUT", ".off", "out.off"},
    {"triangulate", "triangulate IN OUT", ".off", "out.off"},
    {"triangulate_delaunay", "triangulate IN OUT --delaunay", ".off", "out.off"},
    {"fill_holes", "fill-holes IN OUT --refine --fair thin-plate", ".off", "out.off"},
    {"subdivide_loop", "subdivide IN OUT", ".off", "out.off"},
    {"subdivide_sqrt3", "subdivide IN OUT --scheme sqrt3", ".off", "out.off"},
    {"subdivide_catmull_clark", "subdivide IN OUT --scheme catmull-clark", ".off", "out.off"},
    {"smooth_taubin", "smooth IN OUT", ".off", "out.off"},
    {"smooth_laplacian_cotangent", "smooth IN OUT --method laplacian --weights cotangent --move-boundary", ".off",
     "out.off"},
    {"decimate", "decimate IN OUT --ratio 0.5", ".off", "out.off"},
    {"remesh", "remesh IN OUT", ".off", "out.off"},
    {"truncate", "truncate IN OUT --all", ".off", "out.off"},
    {"bevel", "bevel IN OUT --all --segments 2", ".off", "out.off"},
    {"bevel_vertices", "bevel IN OUT --vertices-all", ".off", "out.off"},
    {"extrude", "extrude IN OUT --all --mode individual", ".off", "out.off"},
    {"delaunay", "delaunay IN OUT", ".xyz", "out.off"},
    {"offset", "offset IN OUT --distance 0.1 -n 16", ".off", "out.off"},
    {"sample", "sample IN OUT --count 100", ".off", "out.ply"},
};

// gtest prints a failing case's parameters with these.
void PrintTo(const writer& w, std::ostream* os) { *os << w.args << " -> " << w.output; }
void PrintTo(const input& in, std::ostream* os) { *os << in.name; }

std::string with(std::string args, const std::string& in, const std::string& out) {
    args.replace(args.find("IN"), 2, in);
    args.replace(args.find("OUT"), 3, out);
    return args;
}

/// Rule 1 on one finished run: either it succeeded and `output` reads back with every coordinate
/// finite, or it failed with a documented error (not a crash, not an internal error) and wrote
/// nothing, not even a temporary.
void expect_finite_or_nothing(const scratch_dir& dir, const run_result& r, const std::string& output,
                              std::vector<std::string> inputs_there) {
    if (r.code != 0) {
        EXPECT_TRUE(r.code == 1 || r.code == 2)
            << "exit " << r.code << " (128 + N: signal N; 137: still running after 120 s): " << r.err;
        std::sort(inputs_there.begin(), inputs_there.end());
        EXPECT_EQ(dir.files(), inputs_there) << "a failed run left a file";
        return;
    }
    hmira::face_vertex_mesh m;
    const auto read = hmira::io::read_mesh(m, (dir / output).string());
    ASSERT_TRUE(read) << output << " does not read back: " << read.error().message;
    for (auto v : m.vertices()) {
        const auto p = m.position(v);
        ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))
            << output << ": vertex " << v.index << " is (" << p.x << ", " << p.y << ", " << p.z << ")";
    }
}

class cli_contract_finite : public ::testing::TestWithParam<std::tuple<writer, input>> {};

TEST_P(cli_contract_finite, every_written_coordinate_is_finite) {
    const auto& [w, in] = GetParam();
    scratch_dir dir;
    const std::string input_name = std::string("in") + w.input_ext;
    hmira_test::write_bytes(dir / input_name,
                            std::string(w.input_ext) == ".xyz" ? points_of(in.off) : std::string(in.off));
    const auto r = hmira(dir, with(w.args, input_name, w.output));
    SCOPED_TRACE(with(w.args, input_name, w.output) + " on " + in.name + ": exit " + std::to_string(r.code) + ", " +
                 r.err);
    expect_finite_or_nothing(dir, r, w.output, {input_name});
}

std::string case_name(const ::testing::TestParamInfo<std::tuple<writer, input>>& info) {
    return std::string(std::get<0>(info.param).name) + "_" + std::get<1>(info.param).name;
}

INSTANTIATE_TEST_SUITE_P(all_writers, cli_contract_finite,
                         ::testing::Combine(::testing::ValuesIn(writers), ::testing::ValuesIn(inputs)), case_name);

TEST(cli_contract, generate_writes_finite_coordinates_at_any_scale) {
    scratch_dir dir;
    for (const std::string solid : {"tetrahedron", "cube", "octahedron", "dodecahedron", "icosahedron"})
        for (const std::string scale : {"1.7e308", "1e-300", "1"}) {
            SCOPED_TRACE(solid + " --scale " + scale);
            const auto r = hmira(dir, "generate " + solid + " out.off --scale " + scale);
            expect_finite_or_nothing(dir, r, "out.off",
                                     r.code == 0 ? std::vector<std::string>{"out.off"} : std::vector<std::string>{});
            fs::remove(dir / "out.off");
        }
}

/// A 3x3x3 .raw volume of unsigned bytes, 1 inside at the centre, 0 around it.
std::string centre_voxel_raw() {
    std::string v(27, '\0');
    v[13] = '\1';
    return v;
}

/// mc on a .raw volume: `slab` reads it by slabs (a separate write path).
void mc_extreme_grids(bool slab) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "v.raw", centre_voxel_raw());
    for (const std::string options :
         {"--spacing 1e308", "--spacing 1e308 --origin -1.7e308,-1.7e308,-1.7e308", "--spacing 1e-300",
          "--origin 1.7e308,1.7e308,1.7e308", "--spacing 1e308 --origin 1e308,1e308,1e308", "--spacing 1"}) {
        SCOPED_TRACE(options);
        const auto r = hmira(dir, "mc v.raw out.off --dims 3,3,3 --type uint8 --iso 0.5 --inside above " + options +
                                      (slab ? " --slab-slices 1" : ""));
        expect_finite_or_nothing(
            dir, r, "out.off",
            r.code == 0 ? std::vector<std::string>{"out.off", "v.raw"} : std::vector<std::string>{"v.raw"});
        fs::remove(dir / "out.off");
    }
}

TEST(cli_contract, mc_writes_finite_coordinates_for_extreme_spacing_and_origin) { mc_extreme_grids(false); }

TEST(cli_contract, mc_by_slabs_writes_finite_coordinates_for_extreme_spacing_and_origin) { mc_extreme_grids(true); }

/// The numbers after `key` on the line of `text` that starts with it.
std::vector<double> numbers_after(const std::string& text, const std::string& key) {
    std::vector<double> out;
    const auto at = text.find("\n" + key + " ");
    if (at == std::string::npos) return out;
    std::istringstream line(text.substr(at + key.size() + 2, text.find('\n', at + 1) - at - key.size() - 2));
    for (double x; line >> x;) out.push_back(x);
    return out;
}

TEST(cli_contract, voxelize_headers_and_sidecars_hold_finite_numbers) {
    for (const auto& in : inputs) {
        SCOPED_TRACE(in.name);
        scratch_dir dir;
        hmira_test::write_bytes(dir / "in.off", in.off);
        auto r = hmira(dir, "voxelize in.off out.binvox -n 8");
        if (r.code == 0) {
            const std::string header = hmira_test::read_bytes(dir / "out.binvox");
            const auto translate = numbers_after(header, "translate"), scale = numbers_after(header, "scale");
            ASSERT_EQ(translate.size(), 3u) << header.substr(0, 200);
            ASSERT_EQ(scale.size(), 1u) << header.substr(0, 200);
            for (double x : translate) EXPECT_TRUE(std::isfinite(x)) << header.substr(0, 200);
            EXPECT_TRUE(std::isfinite(scale[0]) && scale[0] > 0) << header.substr(0, 200);
        } else {
            expect_finite_or_nothing(dir, r, "out.binvox", {"in.off"});
        }
        r = hmira(dir, "voxelize in.off out.raw -n 8");
        if (r.code == 0) {
            const std::string sidecar = hmira_test::read_bytes(dir / "out.raw.txt");
            for (const std::string key : {"origin:", "spacing:"}) {
                const auto at = sidecar.find(key);
                ASSERT_NE(at, std::string::npos) << sidecar;
                std::string values = sidecar.substr(at + key.size(), sidecar.find('\n', at) - at - key.size());
                std::replace(values.begin(), values.end(), ',', ' ');
                std::istringstream line(values);
                int n = 0;
                for (double x; line >> x; ++n) EXPECT_TRUE(std::isfinite(x)) << sidecar;
                EXPECT_GE(n, 1) << sidecar;
            }
        }
    }
}

// ---- rule 2: inputs and files of other formats are never written over --------------------------

/// Every writing subcommand with an input, in the form IN OUT.
const char* with_input[] = {
    "convert IN OUT",
    "flip IN OUT",
    "triangulate IN OUT",
    "fill-holes IN OUT",
    "subdivide IN OUT --scheme catmull-clark",
    "smooth IN OUT",
    "decimate IN OUT --ratio 0.5",
    "remesh IN OUT",
    "truncate IN OUT --all",
    "bevel IN OUT --all",
    "extrude IN OUT --all --mode individual",
    "voxelize IN OUT -n 4",
    "view IN OUT",
    "boolean IN in.off OUT --op difference",
};

/// An octahedron: triangles, closed, so that every subcommand above gets as far as writing.
const char* octahedron_off =
    "OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n"
    "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n";

TEST(cli_contract, no_subcommand_writes_over_its_input_under_any_name) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "in.off", octahedron_off);
    fs::create_symlink("in.off", dir / "alias.off");
    fs::create_hard_link(dir / "in.off", dir / "hard.off");
    fs::create_directory(dir / "sub");
    const auto files = dir.files();
    for (const std::string args : with_input)
        for (const std::string& out : std::vector<std::string>{"in.off", "./in.off", "sub/../in.off", "alias.off",
                                                               "hard.off", fs::absolute(dir / "in.off").string()}) {
            const std::string run = with(args, "in.off", out);
            SCOPED_TRACE(run);
            const auto r = hmira(dir, run);
            EXPECT_EQ(r.code, 2) << r.out << r.err;
            EXPECT_EQ(hmira_test::read_bytes(dir / "in.off"), octahedron_off);
            EXPECT_TRUE(fs::is_symlink(dir / "alias.off"));
            EXPECT_EQ(dir.files(), files);
        }
    // delaunay reads points; a .ply of points is a mesh file it could write.
    hmira_test::write_bytes(
        dir / "p.ply",
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
        "end_header\n0 0 0\n1 0 0\n0 1 0\n");
    const std::string points = hmira_test::read_bytes(dir / "p.ply");
    for (const std::string out : {"p.ply", "./p.ply"}) {
        const auto r = hmira(dir, "delaunay p.ply " + out);
        EXPECT_EQ(r.code, 2) << r.out;
        EXPECT_EQ(hmira_test::read_bytes(dir / "p.ply"), points);
    }
    // mc reads a volume: a volume's name is no mesh format it writes.
    hmira_test::write_bytes(dir / "v.raw", centre_voxel_raw());
    const auto r = hmira(dir, "mc v.raw v.raw --dims 3,3,3 --type uint8 --iso 0.5 --inside above");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(hmira_test::read_bytes(dir / "v.raw"), centre_voxel_raw());
}

TEST(cli_contract, an_existing_file_of_another_format_is_never_written_over) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "in.off", octahedron_off);
    hmira_test::write_bytes(dir / "notes.txt", "notes");
    hmira_test::write_bytes(dir / "page.html", "<p>page</p>");
    hmira_test::write_bytes(dir / "grid.binvox", "binvox");
    hmira_test::write_bytes(dir / "other.off", "OFF\n0 0 0\n");
    const auto files = dir.files();
    auto check = [&](const std::string& run) {
        SCOPED_TRACE(run);
        const auto r = hmira(dir, run);
        EXPECT_EQ(r.code, 2) << r.out;
        EXPECT_EQ(hmira_test::read_bytes(dir / "notes.txt"), "notes");
        EXPECT_EQ(hmira_test::read_bytes(dir / "page.html"), "<p>page</p>");
        EXPECT_EQ(hmira_test::read_bytes(dir / "grid.binvox"), "binvox");
        EXPECT_EQ(hmira_test::read_bytes(dir / "other.off"), "OFF\n0 0 0\n");
        EXPECT_EQ(hmira_test::read_bytes(dir / "in.off"), octahedron_off);
        EXPECT_EQ(dir.files(), files);
    };
    // Mesh writers: a text file, a page and a voxel file are not meshes.
    for (const std::string args : with_input) {
        const std::string a = args;
        if (a.rfind("voxelize", 0) == 0 || a.rfind("view", 0) == 0) continue;
        for (const std::string out : {"notes.txt", "page.html", "grid.binvox"}) check(with(a, "in.off", out));
    }
    for (const std::string out : {"notes.txt", "page.html", "grid.binvox"}) {
        check("generate cube " + out);
        check("mc sphere " + out + " -n 8");
        check("delaunay in.off " + out);  // and an .off is no point file
    }
    // voxelize writes voxels, view a page: neither writes over a mesh or a text file.
    for (const std::string out : {"other.off", "notes.txt", "page.html"}) check("voxelize in.off " + out + " -n 4");
    for (const std::string out : {"other.off", "notes.txt", "grid.binvox"}) check("view in.off " + out);
}

// ---- rule 3: a long loop is interruptible ------------------------------------------------------

TEST(cli_contract, sigint_stops_a_long_smooth_promptly_and_leaves_no_output) {
    scratch_dir dir;
    ASSERT_EQ(hmira(dir, "mc sphere s.off -n 48").code, 0);
    const pid_t pid = hmira_test::start_cli(HMIRA_CLI, dir, {"smooth", "s.off", "out.off", "--iterations", "1000000"});
    ASSERT_GE(pid, 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, WNOHANG), 0) << "smooth ended before the signal: the test needs a longer run";
    const auto sent = std::chrono::steady_clock::now();
    ASSERT_EQ(::kill(pid, SIGINT), 0);
    // Generous: the bound is on the work between two cancellation checks, not on speed.
    pid_t done = 0;
    while ((done = ::waitpid(pid, &status, WNOHANG)) == 0 &&
           std::chrono::steady_clock::now() - sent < std::chrono::seconds(20))
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    if (done == 0) {
        ::kill(pid, SIGKILL);
        ::waitpid(pid, &status, 0);
        FAIL() << "hmira smooth still ran 20 s after SIGINT";
    }
    // Ended by the signal (the cleanup handler re-raises it), or a cancellation's exit code.
    EXPECT_TRUE(WIFSIGNALED(status) ? WTERMSIG(status) == SIGINT : WEXITSTATUS(status) != 0) << "status " << status;
    EXPECT_EQ(dir.files(), std::vector<std::string>{"s.off"});
}

}  // namespace
