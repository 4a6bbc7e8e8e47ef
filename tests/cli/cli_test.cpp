// The `hmira` tool end to end: each subcommand run as a separate process on real files, its
// exit code, stdout and stderr checked, and its output files read back with the library.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>

#include <hmira/algorithms/topology/mesh_topology.hpp>
#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

#include "io/io_support.hpp"
#include "support/checks.hpp"

namespace {

using hmira_test::scratch_dir;

struct run_result {
    int code = -1;
    std::string out, err;
};

/// Runs `hmira <args>` (args already shell-quoted where needed) in `dir`.
run_result hmira(const scratch_dir& dir, const std::string& args) {
    const auto out = dir / ".stdout", err = dir / ".stderr";
    const std::string cmd = "cd '" + dir.path().string() + "' && '" + std::string(HMIRA_CLI) + "' " + args + " >'" + out.string() + "' 2>'" + err.string() + "' </dev/null";
    const int status = std::system(cmd.c_str());
    run_result r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = hmira_test::read_bytes(out);
    r.err = hmira_test::read_bytes(err);
    std::filesystem::remove(out);
    std::filesystem::remove(err);
    return r;
}

/// Checks the one-line error format.
void expect_one_line_error(const run_result& r, const std::string& part) {
    EXPECT_EQ(r.err.rfind("hmira: error: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(part), std::string::npos) << "'" << part << "' not in: " << r.err;
}

const std::vector<std::string> subcommands = {"info", "validate", "convert", "generate", "flip", "delaunay", "mc"};

TEST(cli, every_subcommand_has_help_with_an_example_and_the_common_options) {
    scratch_dir dir;
    for (const auto& sub : subcommands) {
        SCOPED_TRACE(sub);
        const auto r = hmira(dir, sub + " --help");
        EXPECT_EQ(r.code, 0);
        EXPECT_NE(r.out.find("Example:\n  hmira " + sub), std::string::npos) << r.out;
        EXPECT_NE(r.out.find("--threads"), std::string::npos);
        EXPECT_NE(r.out.find("--quiet"), std::string::npos);
        EXPECT_NE(r.out.find("Exit codes:"), std::string::npos);
    }
    const auto top = hmira(dir, "--help");
    EXPECT_EQ(top.code, 0);
    for (const auto& sub : subcommands) EXPECT_NE(top.out.find("  " + sub + " "), std::string::npos) << sub;
}

TEST(cli, generated_solids_have_the_textbook_counts_in_every_format) {
    struct solid { const char* name; std::size_t v, e, f; };
    const solid solids[] = {{"tetrahedron", 4, 6, 4}, {"cube", 8, 12, 6}, {"octahedron", 6, 12, 8}, {"dodecahedron", 20, 30, 12}, {"icosahedron", 12, 30, 20}};
    scratch_dir dir;
    for (const auto& s : solids)
        for (const char* ext : {"obj", "off", "ply"}) {
            SCOPED_TRACE(std::string(s.name) + "." + ext);
            const std::string file = std::string(s.name) + "." + ext;
            const auto g = hmira(dir, std::string("generate ") + s.name + " " + file + " --scale 3");
            ASSERT_EQ(g.code, 0) << g.err;
            const auto info = hmira(dir, "info --json " + file);
            ASSERT_EQ(info.code, 0) << info.err;
            EXPECT_NE(info.out.find("\"vertices\": " + std::to_string(s.v) + ","), std::string::npos) << info.out;
            EXPECT_NE(info.out.find("\"edges\": " + std::to_string(s.e) + ","), std::string::npos) << info.out;
            EXPECT_NE(info.out.find("\"faces\": " + std::to_string(s.f) + ","), std::string::npos) << info.out;
            EXPECT_NE(info.out.find("\"genus\": 0,"), std::string::npos);
            EXPECT_NE(info.out.find("\"closed\": true"), std::string::npos);
            EXPECT_NE(info.out.find("\"manifold\": true"), std::string::npos);
            EXPECT_NE(info.out.find("\"problems\": 0"), std::string::npos);
            hmira::face_vertex_mesh m;
            ASSERT_TRUE(hmira::io::read_mesh(m, dir / file));
            EXPECT_GT(hmira_test::signed_volume(m), 0.0) << "wound outward";
        }
}

TEST(cli, info_text_names_every_quantity) {
    scratch_dir dir;
    ASSERT_EQ(hmira(dir, "generate cube c.off").code, 0);
    const auto r = hmira(dir, "info c.off");
    ASSERT_EQ(r.code, 0);
    for (const char* key : {"vertices:", "edges:", "faces:", "components:", "boundary loops:", "genus:", "closed:", "manifold:", "bounding box:", "validate:"})
        EXPECT_NE(r.out.find(key), std::string::npos) << key;
    EXPECT_NE(r.out.find("[-1, -1, -1] .. [1, 1, 1]"), std::string::npos) << r.out;
}

TEST(cli, convert_keeps_the_mesh_through_every_format) {
    scratch_dir dir;
    ASSERT_EQ(hmira(dir, "generate dodecahedron d.off").code, 0);
    hmira::face_vertex_mesh original;
    ASSERT_TRUE(hmira::io::read_mesh(original, dir / "d.off"));
    for (const std::string target : {"d.obj", "d.ply", "d_ascii.ply --ascii", "d_be.ply --big-endian", "d.stl", "d_ascii.stl --ascii"}) {
        SCOPED_TRACE(target);
        const auto r = hmira(dir, "convert d.off " + target);
        ASSERT_EQ(r.code, 0) << r.err;
        const auto file = target.substr(0, target.find(' '));
        hmira::face_vertex_mesh back;
        ASSERT_TRUE(hmira::io::read_mesh(back, dir / file));
        const bool stl = file.ends_with(".stl");
        auto round = stl ? hmira_test::to_float : hmira_test::exact;
        EXPECT_EQ(hmira_test::geometric_faces(back, round, stl), hmira_test::geometric_faces(original, round, stl));
    }
}

TEST(cli, flip_twice_gives_back_the_same_file_and_once_turns_the_volume_negative) {
    scratch_dir dir;
    ASSERT_EQ(hmira(dir, "generate icosahedron i.off").code, 0);
    ASSERT_EQ(hmira(dir, "flip i.off once.off").code, 0);
    ASSERT_EQ(hmira(dir, "flip once.off twice.off").code, 0);
    hmira::face_vertex_mesh once;
    ASSERT_TRUE(hmira::io::read_mesh(once, dir / "once.off"));
    EXPECT_LT(hmira_test::signed_volume(once), 0.0);
    hmira::face_vertex_mesh a, b;
    ASSERT_TRUE(hmira::io::read_mesh(a, dir / "i.off"));
    ASSERT_TRUE(hmira::io::read_mesh(b, dir / "twice.off"));
    EXPECT_EQ(hmira_test::canonical_faces(a), hmira_test::canonical_faces(b));
}

TEST(cli, validate_exits_zero_on_a_good_mesh_and_one_listing_problems_on_a_bad_one) {
    scratch_dir dir;
    ASSERT_EQ(hmira(dir, "generate cube c.obj").code, 0);
    EXPECT_EQ(hmira(dir, "validate c.obj").code, 0);
    hmira_test::write_bytes(dir / "fin.off", "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n");
    const auto r = hmira(dir, "validate fin.off");
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.out.find("non-manifold edge"), std::string::npos) << r.out;
    const auto info = hmira(dir, "info fin.off");
    EXPECT_EQ(info.code, 0);
    EXPECT_NE(info.out.find("manifold:        no"), std::string::npos) << info.out;
}

TEST(cli, quiet_prints_nothing_on_success) {
    scratch_dir dir;
    const auto r = hmira(dir, "generate cube c.ply --quiet --threads 1");
    EXPECT_EQ(r.code, 0);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(hmira(dir, "info -q c.ply").out, "");
}

// ---- exit codes --------------------------------------------------------------------------------
TEST(cli, usage_errors_exit_2) {
    scratch_dir dir;
    for (const std::string args : {"", "bogus", "info", "info --frobnicate x.off", "generate sphere s.off", "generate cube c.off --scale -1",
                                   "convert a.off", "info --threads -3 x.off"}) {
        SCOPED_TRACE(args);
        const auto r = hmira(dir, args);
        EXPECT_EQ(r.code, 2) << r.err;
        expect_one_line_error(r, "");
    }
    ASSERT_EQ(hmira(dir, "generate cube c.off").code, 0);
    const auto r = hmira(dir, "convert c.off c.xyz");
    EXPECT_EQ(r.code, 2);
    expect_one_line_error(r, "unknown mesh format '.xyz'");
    EXPECT_FALSE(std::filesystem::exists(dir / "c.xyz"));
}

TEST(cli, malformed_input_exits_1_with_file_and_line_and_writes_nothing) {
    scratch_dir dir;
    hmira_test::write_bytes(dir / "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
    const auto r = hmira(dir, "convert bad.obj out.ply");
    EXPECT_EQ(r.code, 1);
    expect_one_line_error(r, "bad.obj:4: vertex index 9 is out of range");
    EXPECT_FALSE(std::filesystem::exists(dir / "out.ply"));
    EXPECT_EQ(hmira(dir, "info bad.obj").code, 1);
    EXPECT_EQ(hmira(dir, "validate bad.obj").code, 1);
    EXPECT_EQ(hmira(dir, "flip bad.obj bad.obj").code, 1);
    EXPECT_EQ(hmira_test::read_bytes(dir / "bad.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n") << "the input was touched";
}

TEST(cli, io_failures_exit_3) {
    scratch_dir dir;
    const auto missing = hmira(dir, "info missing.off");
    EXPECT_EQ(missing.code, 3);
    expect_one_line_error(missing, "missing.off: cannot open");
    std::filesystem::create_directory(dir / "folder.ply");
    const auto folder = hmira(dir, "info folder.ply");
    EXPECT_EQ(folder.code, 3);
    expect_one_line_error(folder, "is a directory");
    const auto plain_folder = hmira(dir, "validate .");
    EXPECT_EQ(plain_folder.code, 3);
    const auto nowhere = hmira(dir, "generate cube no/such/folder/c.off");
    EXPECT_EQ(nowhere.code, 3);
    expect_one_line_error(nowhere, "does not exist");
}

TEST(cli, delaunay_triangulates_points_from_xyz_csv_and_ply) {
    scratch_dir dir;
    // A square with its centre: the Delaunay triangulation is the 4 triangles around the centre.
    hmira_test::write_bytes(dir / "p.xyz", "# square\n0 0 1\n2 0 2\n2 2 3\n0 2 4\n1 1 5\n");
    hmira_test::write_bytes(dir / "p.csv", "x,y,z\n0,0,1\n2,0,2\n2,2,3\n0,2,4\n1,1,5\n");
    for (const char* in : {"p.xyz", "p.csv"}) {
        SCOPED_TRACE(in);
        const auto r = hmira(dir, std::string("delaunay ") + in + " t.off");
        ASSERT_EQ(r.code, 0) << r.err;
        hmira::face_vertex_mesh m;
        ASSERT_TRUE(hmira::io::read_mesh(m, dir / "t.off"));
        EXPECT_EQ(m.vertex_count(), 5u);
        EXPECT_EQ(m.face_count(), 4u);
        for (auto f : m.faces()) {
            auto fv = m.face_vertices(f);
            ASSERT_EQ(fv.size(), 3u);
            const auto a = m.position(fv[0]), b = m.position(fv[1]), c = m.position(fv[2]);
            EXPECT_GT((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x), 0.0) << "counter-clockwise";
            bool uses_centre = false;
            for (auto v : fv) uses_centre |= m.position(v).x == 1.0 && m.position(v).y == 1.0 && m.position(v).z == 5.0;
            EXPECT_TRUE(uses_centre);
        }
    }
    ASSERT_EQ(hmira(dir, "convert t.off pts.ply").code, 0);
    const auto from_ply = hmira(dir, "delaunay pts.ply t2.obj");
    EXPECT_EQ(from_ply.code, 0) << from_ply.err;
    hmira_test::write_bytes(dir / "bad.xyz", "0 0\n1 zz\n");
    const auto bad = hmira(dir, "delaunay bad.xyz never.off");
    EXPECT_EQ(bad.code, 1);
    expect_one_line_error(bad, "bad.xyz:2");
    EXPECT_FALSE(std::filesystem::exists(dir / "never.off"));
    EXPECT_EQ(hmira(dir, "delaunay missing.xyz x.off").code, 3);
    EXPECT_EQ(hmira(dir, "delaunay p.las x.off").code, 2);
}

TEST(cli, marching_cubes_of_named_shapes_has_their_topology) {
    scratch_dir dir;
    ASSERT_EQ(hmira(dir, "mc torus t.off -n 48").code, 0);
    const auto t = hmira(dir, "info --json t.off");
    EXPECT_NE(t.out.find("\"genus\": 1,"), std::string::npos) << t.out;
    EXPECT_NE(t.out.find("\"closed\": true"), std::string::npos) << t.out;
    ASSERT_EQ(hmira(dir, "mc sphere s.ply -n 40 --normals").code, 0);
    hmira::face_vertex_mesh s;
    auto r = hmira::io::read_mesh(s, dir / "s.ply");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->attributes.normals.size(), s.vertex_count());
    EXPECT_NEAR(hmira_test::signed_volume(s), 4.0 / 3.0 * 3.14159265358979, 0.1) << "unit sphere, wound outward";
    EXPECT_EQ(hmira(dir, "mc cube c.off").code, 2);
    EXPECT_EQ(hmira(dir, "mc sphere c.off -n 1").code, 2);
    EXPECT_FALSE(std::filesystem::exists(dir / "c.off"));
}

TEST(cli, real_cgal_demo_meshes_are_described) {
    const char* data = std::getenv("HMIRA_TEST_DATA");
    const auto elephant = data ? std::filesystem::absolute(std::filesystem::path(data) / "meshes" / "elephant.off") : std::filesystem::path();
    if (!data || !std::filesystem::exists(elephant)) GTEST_SKIP() << "run scripts/test-data.sh first";
    scratch_dir dir;
    const auto r = hmira(dir, "info --json '" + elephant.string() + "'");
    ASSERT_EQ(r.code, 0) << r.err;
    hmira::face_vertex_mesh m;
    ASSERT_TRUE(hmira::io::read_mesh(m, elephant));
    const auto t = hmira::mesh_topology(m);
    EXPECT_NE(r.out.find("\"faces\": " + std::to_string(t.faces) + ","), std::string::npos);
    EXPECT_NE(r.out.find("\"genus\": " + std::to_string(t.genus) + ","), std::string::npos);
    EXPECT_EQ(hmira(dir, "convert '" + elephant.string() + "' e.stl").code, 0);
    const auto back = hmira(dir, "info --json e.stl");
    EXPECT_NE(back.out.find("\"vertices\": " + std::to_string(t.vertices) + ","), std::string::npos) << back.out;
}

}  // namespace
