// The `hmira` tool under hostile input and faults: non-finite numbers in files and
// options, the documented exit code of every documented failure, interrupted and failing
// writes, long and strange file names. Each case runs the built binary as a separate process.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <sys/wait.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <hmira/algorithms/validation/validate.hpp>
#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

#include "io/io_support.hpp"
#include "support/cli_runner.hpp"

namespace {

using hmira_test::one_line_error;
using hmira_test::run_result;
using hmira_test::scratch_dir;

/// Runs `[env] hmira <args>` (args already shell-quoted where needed) in `dir`.
run_result hmira(const scratch_dir& dir, const std::string& args, const std::string& env = "") {
    return hmira_test::run_cli(HMIRA_CLI, dir, args, env);
}

const char* cube_off =
    "OFF\n8 6 0\n-1 -1 -1\n1 -1 -1\n1 -1 1\n-1 -1 1\n-1 1 -1\n1 1 -1\n1 1 1\n-1 1 1\n"
    "4 0 1 2 3\n4 7 6 5 4\n4 0 4 5 1\n4 1 5 6 2\n4 2 6 7 3\n4 3 7 4 0\n";

/// The cube with vertex 6 replaced by `coordinates`.
std::string cube_with_vertex_6(const std::string& coordinates) {
    std::string s = cube_off;
    const auto at = s.find("1 1 1\n");
    return s.replace(at, 5, coordinates);
}

/// An INRIMAGE-4 volume of 2x2x2 unsigned bytes with `extra` header lines overriding the
/// defaults (later keys win in hmira's reader, as they are read in order).
std::string inr(const std::string& extra, std::size_t samples = 8) {
    std::string h =
        "#INRIMAGE-4#{\nXDIM=2\nYDIM=2\nZDIM=2\nVDIM=1\nTYPE=unsigned fixed\nPIXSIZE=8 "
        "bits\nCPU=decm\nVX=1\nVY=1\nVZ=1\n" +
        extra;
    h += std::string(252 - h.size(), '\n') + "##}\n";
    return h + std::string(samples, '\1');
}

std::string data_file(const std::string& name) {
    const char* data = std::getenv("HMIRA_TEST_DATA");
    return data ? std::string(data) + "/meshes/" + name : std::string();
}

// ---- non-finite numbers --------------------------------------------------------------------

// The readers refuse a non-finite coordinate with file:line and the vertex; validate and info
// therefore never see one from a file (validate's own non-finite check is for meshes built in
// memory: tests/algorithms/validate_test.cpp).
TEST(cli_faults, validate_and_info_refuse_a_nan_or_infinite_vertex_naming_file_line_and_vertex) {
    scratch_dir dir;
    for (const std::string bad : {"nan 1 1", "1 inf 1", "1 1 -inf"}) {
        SCOPED_TRACE(bad);
        hmira_test::write_bytes(dir / "bad.off", cube_with_vertex_6(bad));
        for (const std::string cmd :
             {"validate bad.off", "validate bad.off --relaxed --no-geometry", "info bad.off", "info --json bad.off"}) {
            SCOPED_TRACE(cmd);
            const auto r = hmira(dir, cmd);
            EXPECT_EQ(r.code, 1);
            EXPECT_TRUE(one_line_error(r, "bad.off:9: vertex 6 has a coordinate that is not finite"));
            EXPECT_EQ(r.out.find("nan"), std::string::npos) << r.out;
        }
    }
    hmira_test::write_bytes(dir / "good.off", cube_off);
    EXPECT_EQ(hmira(dir, "validate good.off").code, 0);
    EXPECT_NE(hmira(dir, "info --json good.off").out.find("\"non_finite_vertices\": 0,"), std::string::npos);
}

TEST(cli_faults, edits_and_voxelize_refuse_a_non_finite_vertex_and_write_nothing) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "bad.off", cube_with_vertex_6("nan 1 1"));
    hmira_test::write_bytes(dir / "inf.off", cube_with_vertex_6("1 inf 1"));
    for (const std::string input : {"bad.off", "inf.off"})
        for (const std::string cmd :
             {"truncate IN out.off --all", "truncate IN out.off --vertex 0", "bevel IN out.off --angle 30",
              "bevel IN out.off --all", "bevel IN out.off --vertices-all", "bevel IN out.off --edge 0,1",
              "extrude IN out.off --face 0", "voxelize IN out.raw -n 8", "voxelize IN out.binvox -n 8"}) {
            std::string line = cmd;
            line.replace(line.find("IN"), 2, input);
            SCOPED_TRACE(line);
            const auto r = hmira(dir, line);
            EXPECT_EQ(r.code, 1);
            EXPECT_TRUE(one_line_error(r, input + ":9: vertex 6 has a coordinate that is not finite"));
            EXPECT_EQ(r.err.find("collinear"), std::string::npos) << r.err;
            EXPECT_EQ(dir.files(), (std::vector<std::string>{"bad.off", "inf.off"}));
        }
}

TEST(cli_faults, every_numeric_option_refuses_nan_and_infinity_naming_the_option) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "c.off", cube_off);
    struct option_case {
        std::string command, option;
    };
    const std::vector<option_case> cases = {
        {"generate cube x.obj --scale V", "--scale"},
        {"bevel c.off x.off --angle V", "--angle"},
        {"bevel c.off x.off --all --width V", "--width"},
        {"truncate c.off x.off --all --fraction V", "--fraction"},
        {"truncate c.off x.off --all --distance V", "--distance"},
        {"extrude c.off x.off --face 0 --distance V", "--distance"},
        {"extrude c.off x.off --face 0 --direction V,0,1", "--direction"},
        {"mc sphere x.obj --iso V", "--iso"},
        {"mc v.raw x.obj --dims 2,2,2 --spacing V", "--spacing"},
        {"mc v.raw x.obj --dims 2,2,2 --origin V,0,0", "--origin"},
        {"mc v.raw x.obj --dims V,2,2", "--dims"},
        {"info c.off --threads V", "--threads"},
        {"voxelize c.off x.raw -n V", "--resolution"},
        {"voxelize c.off x.raw --padding V", "--padding"},
        {"bevel c.off x.off --edge 0,1 --segments V", "--segments"},
        {"truncate c.off x.off --vertex V", "--vertex"},
        {"extrude c.off x.off --face V", "--face"},
        {"validate c.off --max V", "--max"},
    };
    for (const auto& c : cases)
        for (const std::string value : {"nan", "NaN", "inf", "-inf", "infinity"}) {
            std::string line = c.command;
            line.replace(line.find('V'), 1, value);
            SCOPED_TRACE(line);
            const auto r = hmira(dir, line);
            EXPECT_EQ(r.code, 2);
            EXPECT_TRUE(one_line_error(r, c.option)) << r.err;
            EXPECT_EQ(dir.files(), std::vector<std::string>{"c.off"});
        }
}

// ---- messages -------------------------------------------------------------------------------

TEST(cli_faults, bevel_angle_nan_names_the_option_not_the_selection) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "c.off", cube_off);
    const auto r = hmira(dir, "bevel c.off x.off --angle nan");
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(one_line_error(r, "--angle: expected a finite number in [0, 180], got 'nan'"));
    EXPECT_EQ(r.err.find("choose edges"), std::string::npos);
}

TEST(cli_faults, range_errors_print_their_bounds_compactly) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "c.off", cube_off);
    for (const std::string line : {"generate cube x.obj --scale -1", "bevel c.off x.off --all --width -2",
                                   "truncate c.off x.off --all --distance 0", "truncate c.off x.off --vertex -1",
                                   "info c.off --threads -3", "bevel c.off x.off --angle 1e308"}) {
        SCOPED_TRACE(line);
        const auto r = hmira(dir, line);
        EXPECT_EQ(r.code, 2);
        EXPECT_TRUE(one_line_error(r, "expected a"));
        EXPECT_LT(r.err.size(), 160u) << r.err;
        EXPECT_EQ(r.err.find("1797693134862315"), std::string::npos) << r.err;
    }
    EXPECT_TRUE(
        one_line_error(hmira(dir, "generate cube x.obj --scale -1"), "--scale: expected a finite number > 0, got -1"));
}

TEST(cli_faults, bevel_vertices_all_blames_bevel_and_says_why_not_truncate) {
    scratch_dir dir;
    std::string iso = cube_off;
    iso.replace(iso.find("8 6 0"), 5, "9 6 0");
    iso.insert(iso.find("4 0 1 2 3"), "5 5 5\n");  // vertex 8, used by no face
    hmira_test::write_bytes(dir / "iso.off", iso);
    for (const std::string sel : {"--vertices-all", "--vertex 8"}) {
        SCOPED_TRACE(sel);
        const auto r = hmira(dir, "bevel iso.off x.off " + sel);
        EXPECT_EQ(r.code, 1);
        EXPECT_TRUE(one_line_error(
            r, "bevel " + sel.substr(0, sel.find(' ')) + ": vertex 8 is used by no face, so it has no corner to cut"));
        EXPECT_EQ(r.err.find("truncate"), std::string::npos) << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir / "x.off"));
    }
}

TEST(cli_faults, a_control_character_in_a_file_name_cannot_split_the_error_line) {
    scratch_dir dir;
    for (const std::string name : {"'a\nb.off'", "'tab\there.off'", "$'esc\\x1b[31m.off'"}) {
        SCOPED_TRACE(name);
        const auto r = hmira(dir, "info " + name);
        EXPECT_EQ(r.code, 3);
        EXPECT_TRUE(one_line_error(r, "cannot open"));
        EXPECT_EQ(r.err.find('\x1b'), std::string::npos);
        EXPECT_EQ(r.err.find('\t'), std::string::npos);
    }
    EXPECT_TRUE(one_line_error(hmira(dir, "info 'a\nb.off'"), "a\\nb.off"));
}

// ---- the exit code of every documented failure -----------------------------------------------

/// Every failure docs/cli.md documents, with the code it documents: 1 invalid input, 2 usage,
/// 3 I/O, (4 internal has no reproducer by design).
TEST(cli_faults, every_documented_failure_exits_with_its_documented_code) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "c.off", cube_off);
    hmira_test::write_bytes(dir / "nan.off", cube_with_vertex_6("nan 1 1"));
    hmira_test::write_bytes(dir / "empty.off", "OFF\n0 0 0\n");
    hmira_test::write_bytes(dir / "bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n");
    hmira_test::write_bytes(dir / "open.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    hmira_test::write_bytes(dir / "nonmanifold.off",
                            "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n");
    hmira_test::write_bytes(dir / "pts.xyz", "0 0\n1 0\n");
    hmira_test::write_bytes(dir / "v.raw", std::string(7, '\0'));
    hmira_test::write_bytes(dir / "nan.raw", std::string("\0\0\xc0\x7f", 4) + std::string(28, '\0'));
    hmira_test::write_bytes(dir / "ok.inr", inr(""));
    hmira_test::write_bytes(dir / "xdim0.inr", inr("XDIM=0\n", 0));
    hmira_test::write_bytes(dir / "vx0.inr", inr("VX=0\n"));
    hmira_test::write_bytes(dir / "vxnan.inr", inr("VX=nan\n"));
    hmira_test::write_bytes(dir / "vxneg.inr", inr("VX=-1\n"));
    hmira_test::write_bytes(dir / "txinf.inr", inr("TX=inf\n"));
    hmira_test::write_bytes(dir / "huge.inr", inr("XDIM=100000\nYDIM=100000\nZDIM=100000\n", 0));
    hmira_test::write_bytes(dir / "short.inr", inr("", 3));
    std::filesystem::create_directory(dir / "folder");
    struct failure {
        std::string command;
        int code;
    };
    std::vector<failure> failures = {
        // 1: invalid input
        {"info bad.off", 1},
        {"validate nonmanifold.off", 1},
        {"validate nan.off", 1},
        // (truncate of nonmanifold.off is not here: the editing commands repair the file on reading.)
        {"truncate nan.off x.off --all", 1},
        {"bevel open.off x.off --all", 1},
        {"bevel c.off x.off --angle 180", 1},
        {"extrude c.off x.off --all", 1},
        {"voxelize empty.off x.binvox", 1},
        {"voxelize nan.off x.binvox", 1},
        {"delaunay pts.xyz x.off", 1},
        {"mc v.raw x.obj --dims 2,2,2 --type uint8", 1},
        {"mc nan.raw x.obj --dims 2,2,2", 1},
        {"mc xdim0.inr x.obj", 1},
        {"mc vx0.inr x.obj", 1},
        {"mc vxnan.inr x.obj", 1},
        {"mc vxneg.inr x.obj", 1},
        {"mc txinf.inr x.obj", 1},
        {"mc huge.inr x.obj", 1},
        {"mc short.inr x.obj", 1},
        // 2: usage
        {"", 2},
        {"frobnicate", 2},
        {"info", 2},
        {"info c.off --no-such-option", 2},
        {"info c.xyz", 2},
        {"convert c.off c.abc", 2},
        {"generate cube x.obj --scale 0", 2},
        {"generate sphere x.obj", 2},
        {"truncate c.off x.off", 2},
        {"truncate c.off x.off --vertex 8", 2},
        {"truncate c.off x.off --all --fraction 1", 2},
        {"truncate c.off x.off --all --distance 0", 2},
        {"truncate c.off x.off --all --vertex 1", 2},
        {"bevel c.off x.off", 2},
        {"bevel c.off x.off --edge 0,6", 2},
        {"bevel c.off x.off --edge 0,9", 2},
        {"bevel c.off x.off --angle 181", 2},
        {"bevel c.off x.off --vertex 0 --segments 2", 2},
        {"extrude c.off x.off", 2},
        {"extrude c.off x.off --face 6", 2},
        {"extrude c.off x.off --face 0 --distance 0", 2},
        {"extrude c.off x.off --face 0 --direction 0,0,0", 2},
        {"voxelize c.off x.vox", 2},
        {"voxelize c.off x.raw -n 0", 2},
        {"voxelize c.off x.raw -n 2049", 2},
        {"mc v.raw x.obj", 2},
        {"mc v.raw x.obj --dims 1000000,1000000,1000000", 2},
        {"mc sphere x.obj --dims 2,2,2", 2},
        {"mc teapot x.obj", 2},
        {"mc sphere x.obj -n 1", 2},
        // 3: I/O
        {"info missing.off", 3},
        {"info folder", 3},
        {"convert c.off folder", 3},
        {"convert c.off no/such/folder/x.off", 3},
        {"mc missing.inr x.obj", 3},
        {"delaunay missing.xyz x.off", 3},
        {"boolean c.off nan.off x.off", 1},
        {"boolean c.off c.off x.off --op minus", 2},
        {"boolean c.off missing.off x.off", 3},
    };
    if (const auto deg = data_file("degtri_sliding.off"); !deg.empty() && std::filesystem::exists(deg))
        failures.push_back({"extrude '" + deg + "' x.off --all --mode individual", 1});
    for (const auto& f : failures) {
        SCOPED_TRACE(f.command);
        const auto r = hmira(dir, f.command);
        EXPECT_EQ(r.code, f.code) << r.err;
        if (f.command.rfind("validate nonmanifold", 0) == 0)
            EXPECT_NE(r.out.find("problem(s)"), std::string::npos) << r.out;  // problems go to stdout
        else
            EXPECT_TRUE(one_line_error(r, ""));
        EXPECT_FALSE(std::filesystem::exists(dir / "x.off") || std::filesystem::exists(dir / "x.obj") ||
                     std::filesystem::exists(dir / "x.binvox") || std::filesystem::exists(dir / "x.raw"));
    }
}

// ---- signals during a write -------------------------------------------------------------------

/// Whether `dir` takes unnamed temporaries (O_TMPFILE), with which even SIGKILL leaves nothing.
bool has_unnamed_temporaries(const std::filesystem::path& dir) {
#ifdef O_TMPFILE
    const int fd = ::open(dir.c_str(), O_TMPFILE | O_WRONLY, 0600);
    if (fd < 0) return false;
    ::close(fd);
    return true;
#else
    (void)dir;
    return false;
#endif
}

TEST(cli_faults, a_signal_during_a_write_leaves_the_old_file_and_no_temporary) {
    scratch_dir dir;
    ASSERT_EQ(hmira(dir, "mc sphere out.ply -n 64").code, 0);  // an existing output
    const std::string before = hmira_test::read_bytes(dir / "out.ply");
    ASSERT_GT(before.size(), std::size_t{1} << 17) << "the new output must take more than one 64 KiB chunk";
    struct signal_case {
        const char* name;
        int sig;
    };
    for (const auto& [name, sig] :
         {signal_case{"INT", SIGINT}, signal_case{"TERM", SIGTERM}, signal_case{"HUP", SIGHUP}})
        for (const std::string named : {"1", "0"}) {
            SCOPED_TRACE(std::string(name) + (named == "1" ? " (named temporary)" : " (O_TMPFILE where available)"));
            const auto r =
                hmira(dir, "mc sphere out.ply -n 80",
                      std::string("HMIRA_TEST_SIGNAL_DURING_WRITE=") + name + " HMIRA_TEST_NAMED_TEMPORARY=" + named);
            EXPECT_EQ(r.signal, sig) << "exit " << r.code << ": " << r.err;
            EXPECT_EQ(dir.files(), std::vector<std::string>{"out.ply"});
            EXPECT_EQ(hmira_test::read_bytes(dir / "out.ply"), before);
        }
    // Unhooked, the same run replaces the file: the hook, not the command, stopped the writes above.
    ASSERT_EQ(hmira(dir, "mc sphere out.ply -n 80").code, 0);
    EXPECT_NE(hmira_test::read_bytes(dir / "out.ply"), before);
    EXPECT_EQ(dir.files(), std::vector<std::string>{"out.ply"});
}

TEST(cli_faults, sigkill_during_a_write_leaves_nothing_where_unnamed_temporaries_exist) {
    scratch_dir dir;
    if (!has_unnamed_temporaries(dir.path())) GTEST_SKIP() << "no O_TMPFILE in " << dir.path();
    hmira_test::write_bytes(dir / "out.ply", "old");
    const auto r = hmira(dir, "mc sphere out.ply -n 80", "HMIRA_TEST_SIGNAL_DURING_WRITE=KILL");
    EXPECT_EQ(r.signal, SIGKILL);
    EXPECT_EQ(dir.files(), std::vector<std::string>{"out.ply"});
    EXPECT_EQ(hmira_test::read_bytes(dir / "out.ply"), "old");
}

// ---- a .raw volume and its sidecar --------------------------------------------------------------

TEST(cli_faults, voxelize_raw_never_leaves_a_sidecar_without_its_data_nor_deletes_an_old_file) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "c.off", cube_off);
    // The .raw cannot be written (a folder has its name): the old sidecar stays as it was.
    std::filesystem::create_directory(dir / "a.raw");
    hmira_test::write_bytes(dir / "a.raw.txt", "old sidecar");
    auto r = hmira(dir, "voxelize c.off a.raw -n 8");
    EXPECT_EQ(r.code, 3);
    EXPECT_TRUE(one_line_error(r, "a.raw"));
    EXPECT_EQ(hmira_test::read_bytes(dir / "a.raw.txt"), "old sidecar");
    // The sidecar cannot be written: the old .raw stays as it was.
    hmira_test::write_bytes(dir / "b.raw", "old raw");
    std::filesystem::create_directory(dir / "b.raw.txt");
    r = hmira(dir, "voxelize c.off b.raw -n 8");
    EXPECT_EQ(r.code, 3);
    EXPECT_TRUE(one_line_error(r, "b.raw.txt"));
    EXPECT_EQ(hmira_test::read_bytes(dir / "b.raw"), "old raw");
    // Killed while writing: neither file appears.
    r = hmira(dir, "voxelize c.off k.raw -n 8", "HMIRA_TEST_SIGNAL_DURING_WRITE=TERM HMIRA_TEST_NAMED_TEMPORARY=1");
    EXPECT_EQ(r.signal, SIGTERM);
    EXPECT_EQ(dir.files(), (std::vector<std::string>{"a.raw", "a.raw.txt", "b.raw", "b.raw.txt", "c.off"}));
    // And unhindered, both appear, the sidecar describing the data.
    r = hmira(dir, "voxelize c.off ok.raw -n 8");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(hmira_test::read_bytes(dir / "ok.raw.txt").find("dims: 12,12,12\n"), std::string::npos);
    EXPECT_EQ(std::filesystem::file_size(dir / "ok.raw"), 12u * 12u * 12u);
}

// ---- long names, and why a temporary cannot be made ---------------------------------------------

TEST(cli_faults, an_output_name_of_any_legal_length_is_written) {
    scratch_dir dir;
    for (std::size_t length : {250u, 255u}) {
        const std::string name = std::string(length - 4, 'n') + ".obj";
        SCOPED_TRACE(length);
        const auto r = hmira(dir, "generate cube " + name);
        ASSERT_EQ(r.code, 0) << r.err;
        EXPECT_EQ(dir.files(), std::vector<std::string>{name});
        hmira::face_vertex_mesh m;
        EXPECT_TRUE(hmira::io::read_mesh(m, dir / name));
        EXPECT_EQ(m.vertex_count(), 8u);
        std::filesystem::remove(dir / name);
    }
    const auto r =
        hmira(dir, "generate cube " + std::string(256 - 4, 'n') + ".obj");  // one byte too long for any file system
    EXPECT_EQ(r.code, 3);
    EXPECT_TRUE(dir.files().empty());
}

TEST(cli_faults, a_temporary_that_cannot_be_created_is_reported_with_the_reason) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "c.off", cube_off);
    // /sys refuses new files even to root, the tests' usual user in containers.
    const auto r = hmira(dir, "convert c.off /sys/hmira-test.off");
    EXPECT_EQ(r.code, 3);
    EXPECT_TRUE(one_line_error(r, "/sys/hmira-test.off: cannot create a temporary file in /sys: "));
    const auto reason = r.err.substr(r.err.rfind(": ") + 2);
    EXPECT_GT(reason.size(), 3u) << r.err;
}

// ---- --max-input-bytes ---------------------------------------------------------------------------

TEST(cli_faults, every_reading_subcommand_takes_max_input_bytes_with_binary_suffixes) {
    scratch_dir dir;
    for (const std::string sub :
         {"info", "validate", "convert", "flip", "delaunay", "mc", "truncate", "bevel", "extrude", "voxelize"}) {
        const auto r = hmira(dir, sub + " --help");
        EXPECT_NE(r.out.find("--max-input-bytes"), std::string::npos) << sub;
        EXPECT_NE(r.out.find("=4G"), std::string::npos) << sub;
    }
    EXPECT_EQ(hmira(dir, "generate --help").out.find("--max-input-bytes"), std::string::npos)
        << "generate reads nothing";
    hmira_test::write_bytes(dir / "c.off", cube_off);
    for (const std::string ok :
         {"1", "512", "1K", "64M", "4G", "1T", "2KiB", "3MiB", "4GiB", "1TiB", "18446744073709551615"})
        EXPECT_EQ(hmira(dir, "info c.off --max-input-bytes " + ok).code, 0) << ok;
    for (const std::string bad :
         {"0", "-1", "nan", "inf", "1.5G", "4X", "G", "1Gi", "16777216T", "18446744073709551616", "''"}) {
        SCOPED_TRACE(bad);
        const auto r = hmira(dir, "info c.off --max-input-bytes " + bad);
        EXPECT_EQ(r.code, 2);
        EXPECT_TRUE(one_line_error(r, "--max-input-bytes"));
    }
}

/// Runs `hmira <args>` with `input` (a FIFO in `dir`) fed `bytes` by a background writer.
run_result hmira_from_fifo(const scratch_dir& dir, const std::string& fifo, const std::string& bytes,
                           const std::string& args) {
    hmira_test::write_bytes(dir / "feed", bytes);
    std::filesystem::remove(dir / fifo);
    EXPECT_EQ(::mkfifo((dir / fifo).c_str(), 0600), 0);
    // The writer may meet a reader that stopped early: its own failure does not matter.
    const std::string feed =
        "(cat '" + (dir / "feed").string() + "' > '" + (dir / fifo).string() + "' 2>/dev/null &) ; ";
    auto r = hmira(dir, args, feed);
    std::filesystem::remove(dir / fifo);
    std::filesystem::remove(dir / "feed");
    return r;
}

TEST(cli_faults, a_fifo_input_under_the_cap_is_read) {
    scratch_dir dir;
    const auto r = hmira_from_fifo(dir, "p.off", cube_off, "info p.off --max-input-bytes 1M");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("vertices:        8"), std::string::npos) << r.out;
}

// The CLI passes --max-input-bytes to the readers (read_options::max_input_bytes), which stop
// reading a pipe at the cap.
TEST(cli_faults, a_fifo_input_over_the_cap_is_refused_with_exit_1) {
    scratch_dir dir;
    std::string big = cube_off;
    big += std::string(4096, '\n');  // blank lines after the mesh: the cap, not the parser, must stop it
    const auto r = hmira_from_fifo(dir, "p.off", big, "info p.off --max-input-bytes 1K");
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_TRUE(one_line_error(r, "p.off"));
}

}  // namespace
