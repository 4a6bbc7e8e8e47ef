// The `hmira` tool end to end: each subcommand run as a separate process on real files, its
// exit code, stdout and stderr checked, and its output files read back with the library.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <numbers>
#include <set>

#include <hmira/algorithms/topology/mesh_topology.hpp>
#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

#include "io/io_support.hpp"
#include "support/cli_runner.hpp"
#include "support/checks.hpp"

namespace {

using hmira_test::run_result;
using hmira_test::scratch_dir;

/// Runs `hmira <args>` (args already shell-quoted where needed) in `dir`.
run_result hmira(const scratch_dir& dir, const std::string& args) { return hmira_test::run_cli(HMIRA_CLI, dir, args); }

/// Checks the one-line error format.
void expect_one_line_error(const run_result& r, const std::string& part) {
    EXPECT_TRUE(hmira_test::one_line_error(r, part));
}

const std::vector<std::string> subcommands = {
    "info",  "validate", "convert",  "generate", "flip",        "delaunay",   "mc",        "truncate",
    "bevel", "extrude",  "voxelize", "view",     "triangulate", "fill-holes", "subdivide", "smooth"};

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
    struct solid {
        const char* name;
        std::size_t v, e, f;
    };
    const solid solids[] = {{"tetrahedron", 4, 6, 4},
                            {"cube", 8, 12, 6},
                            {"octahedron", 6, 12, 8},
                            {"dodecahedron", 20, 30, 12},
                            {"icosahedron", 12, 30, 20}};
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
    for (const char* key : {"vertices:", "edges:", "faces:", "components:", "boundary loops:", "genus:", "closed:",
                            "manifold:", "bounding box:", "validate:"})
        EXPECT_NE(r.out.find(key), std::string::npos) << key;
    EXPECT_NE(r.out.find("[-1, -1, -1] .. [1, 1, 1]"), std::string::npos) << r.out;
}

TEST(cli, convert_keeps_the_mesh_through_every_format) {
    scratch_dir dir;
    ASSERT_EQ(hmira(dir, "generate dodecahedron d.off").code, 0);
    hmira::face_vertex_mesh original;
    ASSERT_TRUE(hmira::io::read_mesh(original, dir / "d.off"));
    for (const std::string target :
         {"d.obj", "d.ply", "d_ascii.ply --ascii", "d_be.ply --big-endian", "d.stl", "d_ascii.stl --ascii"}) {
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
    hmira_test::write_bytes(dir / "fin.off",
                            "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n");
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
    for (const std::string args : {"", "bogus", "info", "info --frobnicate x.off", "generate sphere s.off",
                                   "generate cube c.off --scale -1", "convert a.off", "info --threads -3 x.off"}) {
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
    EXPECT_EQ(hmira_test::read_bytes(dir / "bad.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n")
        << "the input was touched";
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
    const auto elephant = data ? std::filesystem::absolute(std::filesystem::path(data) / "meshes" / "elephant.off")
                               : std::filesystem::path();
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

// ---- truncate, bevel, extrude, voxelize, mc on .raw ---------------------------------------------
// Expected counts, positions and volumes below come from the cube's geometry, worked out by
// hand; the output files are read back with the library's reader and checked here.

hmira::face_vertex_mesh read_back(const std::filesystem::path& p) {
    hmira::face_vertex_mesh m;
    auto r = hmira::io::read_mesh(m, p);
    EXPECT_TRUE(r) << p << ": " << (r ? std::string() : r.error().message);
    return m;
}

using point = std::array<double, 3>;

point at(const hmira::face_vertex_mesh& m, std::size_t i) {
    const auto p = m.position(hmira::vertex_handle(i));
    return {p.x, p.y, p.z};
}

bool near(const point& a, const point& b, double eps = 1e-12) {
    return std::abs(a[0] - b[0]) <= eps && std::abs(a[1] - b[1]) <= eps && std::abs(a[2] - b[2]) <= eps;
}

/// V, E, F counted here from the face lists (an edge is an unordered pair of vertices).
struct vef {
    std::size_t v = 0, e = 0, f = 0;
    bool operator==(const vef&) const = default;
};
std::ostream& operator<<(std::ostream& os, const vef& c) { return os << "V " << c.v << ", E " << c.e << ", F " << c.f; }

vef counts(const hmira::face_vertex_mesh& m) {
    std::set<std::pair<std::size_t, std::size_t>> edges;
    for (auto f : m.faces()) {
        const auto fv = m.face_vertices(f);
        for (std::size_t i = 0; i < fv.size(); ++i)
            edges.insert(std::minmax<std::size_t>(fv[i].index, fv[(i + 1) % fv.size()].index));
    }
    return {m.vertex_count(), edges.size(), m.face_count()};
}

/// Closed and consistently oriented: every directed edge is used by one face, its reverse by one.
::testing::AssertionResult closed_and_oriented(const hmira::face_vertex_mesh& m) {
    std::map<std::pair<std::size_t, std::size_t>, int> directed;
    for (auto f : m.faces()) {
        const auto fv = m.face_vertices(f);
        for (std::size_t i = 0; i < fv.size(); ++i) ++directed[{fv[i].index, fv[(i + 1) % fv.size()].index}];
    }
    for (const auto& [ab, n] : directed) {
        if (n != 1)
            return ::testing::AssertionFailure()
                   << "edge " << ab.first << "->" << ab.second << " is run by " << n << " faces";
        if (!directed.contains({ab.second, ab.first}))
            return ::testing::AssertionFailure() << "edge " << ab.first << "->" << ab.second << " has no twin";
    }
    return ::testing::AssertionSuccess();
}

/// What every edit must leave: a valid, closed, outward-oriented surface of the same genus
/// (Euler-Poincare V - E + F = 2 - 2g for one component).
void expect_sound(const hmira::face_vertex_mesh& m, long long genus = 0) {
    EXPECT_TRUE(hmira_test::is_valid(m));
    EXPECT_TRUE(closed_and_oriented(m));
    const auto c = counts(m);
    EXPECT_EQ(static_cast<long long>(c.v) - static_cast<long long>(c.e) + static_cast<long long>(c.f), 2 - 2 * genus)
        << "Euler-Poincare";
    EXPECT_GT(hmira_test::signed_volume(m), 0.0) << "wound outward";
}

/// `args` must fail with `code` and a one-line error containing `part`, leave an existing
/// `output` as it was, and create neither it nor a temporary when it does not exist.
void expect_refused(const scratch_dir& dir, const std::string& args, int code, const std::string& part,
                    const std::string& output) {
    SCOPED_TRACE(args);
    hmira_test::write_bytes(dir / output, "keep");
    const auto files = dir.files();
    const auto r = hmira(dir, args);
    EXPECT_EQ(r.code, code) << r.err;
    expect_one_line_error(r, part);
    EXPECT_EQ(hmira_test::read_bytes(dir / output), "keep") << "the existing output was touched";
    EXPECT_EQ(dir.files(), files) << "a file was left behind";
    std::filesystem::remove(dir / output);
    EXPECT_EQ(hmira(dir, args).code, code);
    EXPECT_FALSE(std::filesystem::exists(dir / output));
}

std::size_t faces_with(const hmira::face_vertex_mesh& m, std::size_t corners) {
    std::size_t n = 0;
    for (auto f : m.faces()) n += m.face_vertices(f).size() == corners ? 1 : 0;
    return n;
}

TEST(cli, truncate_all_turns_the_cube_into_the_truncated_cube) {
    scratch_dir dir;
    ASSERT_EQ(hmira(dir, "generate cube c.obj").code, 0);
    const auto r = hmira(dir, "truncate c.obj t.obj --all");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("c.obj: truncated 8 vertices: V 8 -> 24, E 12 -> 36, F 6 -> 14"), std::string::npos) << r.out;
    const auto t = read_back(dir / "t.obj");
    EXPECT_EQ(counts(t), (vef{24, 36, 14}));
    EXPECT_EQ(faces_with(t, 3), 8u);
    EXPECT_EQ(faces_with(t, 8), 6u);
    expect_sound(t);
    // Every cut point lies on a cube edge, a third of the way (2/3) from a corner.
    for (auto v : t.vertices()) {
        const auto p = at(t, v.index);
        int ones = 0, thirds = 0;
        for (double x : p) ones += std::abs(std::abs(x) - 1) < 1e-12, thirds += std::abs(std::abs(x) - 1.0 / 3) < 1e-12;
        EXPECT_TRUE(ones == 2 && thirds == 1) << p[0] << " " << p[1] << " " << p[2];
    }
    // Eight corner tetrahedra with legs 2/3 are cut off a cube of volume 8.
    EXPECT_NEAR(hmira_test::signed_volume(t), 8 - 8 * std::pow(2.0 / 3, 3) / 6, 1e-12);

    ASSERT_EQ(hmira(dir, "truncate c.obj half.obj --all --fraction 0.5 -q").code, 0);
    const auto half = read_back(dir / "half.obj");
    EXPECT_EQ(counts(half), (vef{12, 24, 14})) << "cuboctahedron";
    EXPECT_EQ(faces_with(half, 3), 8u);
    EXPECT_EQ(faces_with(half, 4), 6u);
    expect_sound(half);
    EXPECT_NEAR(hmira_test::signed_volume(half), 20.0 / 3, 1e-12);

    ASSERT_EQ(hmira(dir, "truncate c.obj d.obj --all --distance 0.5 -q").code, 0);
    const auto d = read_back(dir / "d.obj");
    EXPECT_EQ(counts(d), (vef{24, 36, 14}));
    expect_sound(d);
    EXPECT_NEAR(hmira_test::signed_volume(d), 8 - 8 * std::pow(0.5, 3) / 6, 1e-12);
}

TEST(cli, truncate_keeps_the_file_vertices_first_and_in_their_order) {
    scratch_dir dir;
    ASSERT_EQ(hmira(dir, "generate cube c.off").code, 0);
    const auto c = read_back(dir / "c.off");
    for (const auto& cut :
         {std::vector<std::size_t>{5}, std::vector<std::size_t>{0, 6}, std::vector<std::size_t>{7, 2, 3}}) {
        std::string args = "truncate c.off t.off";
        for (auto i : cut) args += " --vertex " + std::to_string(i);
        SCOPED_TRACE(args);
        const auto r = hmira(dir, args);
        ASSERT_EQ(r.code, 0) << r.err;
        const auto t = read_back(dir / "t.off");
        // Each corner of degree 3 becomes a triangle: V + 2, E + 3, F + 1.
        EXPECT_EQ(counts(t), (vef{8 + 2 * cut.size(), 12 + 3 * cut.size(), 6 + cut.size()}));
        expect_sound(t);
        std::size_t next = 0;
        for (std::size_t i = 0; i < 8; ++i) {
            if (std::find(cut.begin(), cut.end(), i) != cut.end()) continue;
            EXPECT_TRUE(near(at(t, next), at(c, i))) << "file vertex " << i;
            ++next;
        }
        // Then the cut points: a third of the way from each cut corner to its three neighbours.
        std::vector<point> expected;
        for (auto i : cut)
            for (std::size_t j = 0; j < 8; ++j) {
                const auto a = at(c, i), b = at(c, j);
                const double d2 =
                    (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]);
                if (std::abs(d2 - 4) < 1e-12)
                    expected.push_back({a[0] + (b[0] - a[0]) / 3, a[1] + (b[1] - a[1]) / 3, a[2] + (b[2] - a[2]) / 3});
            }
        ASSERT_EQ(t.vertex_count() - next, expected.size());
        for (std::size_t k = next; k < t.vertex_count(); ++k)
            EXPECT_TRUE(
                std::any_of(expected.begin(), expected.end(), [&](const point& e) { return near(e, at(t, k), 1e-12); }))
                << "new vertex " << k;
        EXPECT_NEAR(hmira_test::signed_volume(t), 8 - double(cut.size()) * std::pow(2.0 / 3, 3) / 6, 1e-12);
    }
}

TEST(cli, bevel_one_cube_edge_is_a_chamfer_named_by_its_end_vertices) {
    scratch_dir dir;
    ASSERT_EQ(hmira(dir, "generate cube c.obj").code, 0);
    const auto c = read_back(dir / "c.obj");
    // Vertices 0 (-1,-1,-1) and 1 (1,-1,-1) of the generated cube share an edge along x.
    ASSERT_TRUE(near(at(c, 0), {-1, -1, -1}) && near(at(c, 1), {1, -1, -1}));
    const double w = 0.25;
    for (const char* edge : {"0,1", "1,0"}) {
        SCOPED_TRACE(edge);
        const auto r = hmira(dir, std::string("bevel c.obj b.obj --width 0.25 --edge ") + edge);
        ASSERT_EQ(r.code, 0) << r.err;
        EXPECT_NE(r.out.find("V 8 -> 10, E 12 -> 15, F 6 -> 7"), std::string::npos) << r.out;
        const auto b = read_back(dir / "b.obj");
        EXPECT_EQ(counts(b), (vef{10, 15, 7}));
        expect_sound(b);
        // Both corners go; the other six file vertices come first, in order.
        for (std::size_t i = 2; i < 8; ++i) EXPECT_TRUE(near(at(b, i - 2), at(c, i))) << "file vertex " << i;
        // The new edges run at width w from the old one inside the faces y = -1 and z = -1.
        const std::vector<point> expected{{-1, -1 + w, -1}, {1, -1 + w, -1}, {-1, -1, -1 + w}, {1, -1, -1 + w}};
        for (std::size_t k = 6; k < 10; ++k)
            EXPECT_TRUE(
                std::any_of(expected.begin(), expected.end(), [&](const point& e) { return near(e, at(b, k)); }))
                << "new vertex " << k;
        // A prism of cross-section w^2 / 2 and length 2 is cut away.
        EXPECT_NEAR(hmira_test::signed_volume(b), 8 - w * w, 1e-12);
    }
    const auto twice = hmira(dir, "bevel c.obj b.obj --edge 0,1 --edge 1,0 --width 0.25");
    ASSERT_EQ(twice.code, 0) << twice.err;
    EXPECT_NE(twice.out.find(
                  "bevelled 1 edge: width 0.25 requested, smallest used 0.25, 0 edges limited by the clamp: V 8 -> 10"),
              std::string::npos)
        << "one edge named twice: " << twice.out;
    // Rounded: an arc of 3 segments removes less than the chamfer, more than the true quarter circle.
    ASSERT_EQ(hmira(dir, "bevel c.obj r.obj --edge 0,1 --width 0.25 --segments 3 -q").code, 0);
    const auto round = read_back(dir / "r.obj");
    expect_sound(round);
    EXPECT_EQ(round.face_count(), 6u + 3u);
    const double vr = hmira_test::signed_volume(round);
    EXPECT_GT(vr, 8 - w * w + 1e-9);
    EXPECT_LT(vr, 8 - 2 * w * w * (1 - std::numbers::pi / 4) - 1e-9);
}

TEST(cli, bevel_selects_sharp_edges_by_angle_and_bevels_vertices_like_truncate) {
    scratch_dir dir;
    ASSERT_EQ(hmira(dir, "generate cube c.obj").code, 0);
    // All twelve cube edges are at 90 degrees: a strip per edge, a triangle per corner.
    for (const char* how : {"--angle 80", "--angle 90", "--all"}) {
        SCOPED_TRACE(how);
        const auto r = hmira(dir, std::string("bevel c.obj b.obj --width 0.2 ") + how);
        ASSERT_EQ(r.code, 0) << r.err;
        EXPECT_NE(r.out.find("bevelled 12 edges"), std::string::npos) << r.out;
        const auto b = read_back(dir / "b.obj");
        EXPECT_EQ(counts(b), (vef{24, 48, 26}));
        EXPECT_EQ(faces_with(b, 3), 8u);
        expect_sound(b);
    }
    expect_refused(dir, "bevel c.obj b.obj --angle 91", 1, "no edge has a dihedral angle of at least 91 degrees",
                   "b.obj");
    // The icosahedron's dihedral angle between face normals is 180 - 138.19 = 41.81 degrees.
    ASSERT_EQ(hmira(dir, "generate icosahedron i.off").code, 0);
    EXPECT_EQ(hmira(dir, "bevel i.off x.off --angle 42 -q").code, 1);
    ASSERT_EQ(hmira(dir, "bevel i.off x.off --angle 41 --width 0.05 -q").code, 0);
    const auto x = read_back(dir / "x.off");
    expect_sound(x);
    EXPECT_EQ(x.face_count(), 20u + 30u + 12u) << "a strip per edge, a pentagon per corner";
    // Vertex-only mode is truncation at the width's distance along each edge.
    ASSERT_EQ(hmira(dir, "bevel c.obj bv.obj --vertex 0 --vertex 6 --width 0.5 -q").code, 0);
    ASSERT_EQ(hmira(dir, "truncate c.obj tv.obj --vertex 0,6 --distance 0.5 -q").code, 0);
    EXPECT_EQ(hmira_test::read_bytes(dir / "bv.obj"), hmira_test::read_bytes(dir / "tv.obj"));
    ASSERT_EQ(hmira(dir, "bevel c.obj ba.obj --vertices-all --width 0.5 -q").code, 0);
    const auto ba = read_back(dir / "ba.obj");
    EXPECT_EQ(counts(ba), (vef{24, 36, 14}));
    expect_sound(ba);
    EXPECT_NEAR(hmira_test::signed_volume(ba), 8 - 8 * std::pow(0.5, 3) / 6, 1e-12);
}

/// Newell's normal of face f, computed here.
point face_normal(const hmira::face_vertex_mesh& m, std::size_t f) {
    point n{0, 0, 0};
    const auto fv = m.face_vertices(hmira::face_handle(f));
    for (std::size_t i = 0; i < fv.size(); ++i) {
        const auto a = at(m, fv[i].index), b = at(m, fv[(i + 1) % fv.size()].index);
        n[0] += (a[1] - b[1]) * (a[2] + b[2]);
        n[1] += (a[2] - b[2]) * (a[0] + b[0]);
        n[2] += (a[0] - b[0]) * (a[1] + b[1]);
    }
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    return {n[0] / len, n[1] / len, n[2] / len};
}

TEST(cli, extrude_one_face_of_the_unit_cube_doubles_its_volume) {
    scratch_dir dir;
    ASSERT_EQ(hmira(dir, "generate cube u.obj --scale 0.5").code, 0);
    const auto u = read_back(dir / "u.obj");
    ASSERT_NEAR(hmira_test::signed_volume(u), 1.0, 1e-12);
    for (std::size_t f = 0; f < 6; ++f) {
        SCOPED_TRACE("face " + std::to_string(f));
        const auto r = hmira(dir, "extrude u.obj e.obj --distance 1 --face " + std::to_string(f));
        ASSERT_EQ(r.code, 0) << r.err;
        EXPECT_NE(r.out.find("V 8 -> 12, E 12 -> 20, F 6 -> 10"), std::string::npos) << r.out;
        const auto e = read_back(dir / "e.obj");
        EXPECT_EQ(counts(e), (vef{12, 20, 10}));
        expect_sound(e);
        EXPECT_NEAR(hmira_test::signed_volume(e), 2.0, 1e-12);
        for (std::size_t i = 0; i < 8; ++i) EXPECT_TRUE(near(at(e, i), at(u, i))) << "file vertex " << i;
        // The new vertices are the face's corners moved by its outward unit normal.
        const auto n = face_normal(u, f);
        for (std::size_t k = 8; k < 12; ++k) {
            bool found = false;
            for (auto v : u.face_vertices(hmira::face_handle(f))) {
                const auto p = at(u, v.index);
                found |= near(at(e, k), {p[0] + n[0], p[1] + n[1], p[2] + n[2]}, 1e-12);
            }
            EXPECT_TRUE(found) << "new vertex " << k;
        }
    }
    // A given direction is normalised; a negative distance makes a pocket.
    ASSERT_EQ(hmira(dir, "extrude u.obj d.obj --face 0 --distance 0.5 --direction 0,-7,0 -q").code, 0);
    EXPECT_NEAR(hmira_test::signed_volume(read_back(dir / "d.obj")), 1.5, 1e-12);
    ASSERT_EQ(hmira(dir, "extrude u.obj p.obj --face 0 --distance -0.25 -q").code, 0);
    const auto p = read_back(dir / "p.obj");
    expect_sound(p);
    EXPECT_NEAR(hmira_test::signed_volume(p), 0.75, 1e-12);
    // Two neighbouring faces as one region: walls on the 6 outline edges only.
    ASSERT_EQ(hmira(dir, "extrude u.obj r.obj --face 0,1 -q").code, 0);
    const auto reg = read_back(dir / "r.obj");
    EXPECT_EQ(counts(reg), (vef{14, 24, 12}));
    expect_sound(reg);
    // The file's vertices stay where they were (region mode moves the region's own vertices,
    // and the tool gives the file's indices to the ones left behind); the 6 outline vertices,
    // moved by the unit mean normal of the two faces, follow.
    for (std::size_t i = 0; i < 8; ++i) EXPECT_TRUE(near(at(reg, i), at(u, i))) << "file vertex " << i;
    const auto n0 = face_normal(u, 0), n1 = face_normal(u, 1);
    const double len = std::sqrt((n0[0] + n1[0]) * (n0[0] + n1[0]) + (n0[1] + n1[1]) * (n0[1] + n1[1]) +
                                 (n0[2] + n1[2]) * (n0[2] + n1[2]));
    const point mean{(n0[0] + n1[0]) / len, (n0[1] + n1[1]) / len, (n0[2] + n1[2]) / len};
    std::set<std::size_t> outline;
    for (std::size_t f : {0, 1})
        for (auto v : u.face_vertices(hmira::face_handle(f))) outline.insert(v.index);
    ASSERT_EQ(outline.size(), 6u);
    for (std::size_t k = 8; k < 14; ++k)
        EXPECT_TRUE(std::any_of(outline.begin(), outline.end(),
                                [&](std::size_t i) {
                                    const auto p = at(u, i);
                                    return near(at(reg, k), {p[0] + mean[0], p[1] + mean[1], p[2] + mean[2]}, 1e-12);
                                }))
            << "new vertex " << k;
    // Every face on its own: six prisms of volume 1 each on the unit cube.
    ASSERT_EQ(hmira(dir, "extrude u.obj all.obj --all --mode individual -q").code, 0);
    const auto all = read_back(dir / "all.obj");
    EXPECT_EQ(counts(all), (vef{32, 60, 30}));
    EXPECT_TRUE(hmira_test::is_valid(all));
    EXPECT_NEAR(hmira_test::signed_volume(all), 7.0, 1e-12);
    expect_refused(dir, "extrude u.obj x.obj --all", 1, "no outline", "x.obj");
}

/// Decodes a .binvox file here (header, then (value, count) runs): its dimension and voxels.
std::pair<std::size_t, std::vector<std::uint8_t>> read_binvox(const std::filesystem::path& p) {
    const auto bytes = hmira_test::read_bytes(p);
    const auto data = bytes.find("\ndata\n");
    EXPECT_NE(data, std::string::npos);
    const auto dim = bytes.find("dim ");
    const std::size_t d = std::stoul(bytes.substr(dim + 4));
    std::vector<std::uint8_t> voxels;
    for (std::size_t i = data + 6; i + 1 < bytes.size(); i += 2)
        voxels.insert(voxels.end(), static_cast<unsigned char>(bytes[i + 1]), static_cast<std::uint8_t>(bytes[i]));
    EXPECT_EQ(voxels.size(), d * d * d);
    return {d, voxels};
}

TEST(cli, voxelize_a_cube_sets_the_voxels_its_geometry_predicts) {
    scratch_dir dir;
    ASSERT_EQ(hmira(dir, "generate cube c.obj").code, 0);
    // The cube [-1, 1]^3 at N = 16 voxels of 1/8: every voxel boundary is exact in binary, so
    // "the box touches the surface" is decided without rounding.
    const std::size_t n = 16;
    ASSERT_EQ(hmira(dir, "voxelize c.obj s.raw -n 16 --padding 0 --surface -q").code, 0);
    const auto raw = hmira_test::read_bytes(dir / "s.raw");
    ASSERT_EQ(raw.size(), n * n * n);
    std::size_t set = 0;
    for (std::size_t k = 0; k < n; ++k)
        for (std::size_t j = 0; j < n; ++j)
            for (std::size_t i = 0; i < n; ++i) {
                const bool shell = i == 0 || j == 0 || k == 0 || i == n - 1 || j == n - 1 || k == n - 1;
                const char v = raw[i + n * (j + n * k)];
                EXPECT_EQ(v, shell ? 1 : 0) << i << " " << j << " " << k;
                set += v == 1;
            }
    EXPECT_EQ(set, n * n * n - (n - 2) * (n - 2) * (n - 2));
    // --mode surface is --surface; --mode conservative (the default) adds the inside.
    ASSERT_EQ(hmira(dir, "voxelize c.obj m.raw -n 16 --padding 0 --mode surface -q").code, 0);
    EXPECT_EQ(hmira_test::read_bytes(dir / "m.raw"), raw);
    ASSERT_EQ(hmira(dir, "voxelize c.obj cons.raw -n 16 --padding 0 --mode conservative -q").code, 0);
    EXPECT_EQ(hmira_test::read_bytes(dir / "cons.raw"), std::string(n * n * n, '\1'));
    // --mode centres: every centre of the 16^3 grid lies strictly inside the cube.
    ASSERT_EQ(hmira(dir, "voxelize c.obj cen.raw -n 16 --padding 1 --mode centres -q").code, 0);
    const auto centres = hmira_test::read_bytes(dir / "cen.raw");
    ASSERT_EQ(centres.size(), (n + 2) * (n + 2) * (n + 2));
    EXPECT_EQ(std::count(centres.begin(), centres.end(), '\1'), std::ptrdiff_t(n * n * n));
    expect_refused(dir, "voxelize c.obj x.raw --mode centre", 2, "--mode", "x.raw");
    expect_refused(dir, "voxelize c.obj x.raw --mode surface --surface", 2, "--surface", "x.raw");
    const auto sidecar = hmira_test::read_bytes(dir / "s.raw.txt");
    for (const char* line :
         {"dims: 16,16,16\n", "type: uint8\n", "spacing: 0.125,0.125,0.125\n", "origin: -0.9375,-0.9375,-0.9375"})
        EXPECT_NE(sidecar.find(line), std::string::npos) << line << " not in:\n" << sidecar;

    // Solid, default padding 2: the cube's 16^3 voxels plus the first padding layer, whose
    // closed boxes touch the cube's faces; the outer layer stays empty.
    const auto r = hmira(dir, "voxelize c.obj c.binvox --resolution 16");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("20 x 20 x 20 voxels"), std::string::npos) << r.out;
    const auto [d, voxels] = read_binvox(dir / "c.binvox");
    EXPECT_EQ(d, n + 4);
    EXPECT_EQ(static_cast<std::size_t>(std::count(voxels.begin(), voxels.end(), 1)), (n + 2) * (n + 2) * (n + 2));
    EXPECT_NE(hmira_test::read_bytes(dir / "c.binvox").find("translate -1.25 -1.25 -1.25\nscale 2.5\n"),
              std::string::npos);

    ASSERT_EQ(hmira(dir, "voxelize c.obj p0.binvox -n 16 --padding 0 --threads 1 -q").code, 0);
    const auto [d0, v0] = read_binvox(dir / "p0.binvox");
    EXPECT_EQ(d0, n);
    EXPECT_EQ(static_cast<std::size_t>(std::count(v0.begin(), v0.end(), 1)), n * n * n);

    // The sidecar's mc command gives back a closed surface around the voxels.
    ASSERT_EQ(hmira(dir, "generate icosahedron i.off").code, 0);
    ASSERT_EQ(hmira(dir, "voxelize i.off i.raw -n 24 -q").code, 0);
    const auto text = hmira_test::read_bytes(dir / "i.raw.txt");
    const auto mc = text.find("mc: hmira ");
    ASSERT_NE(mc, std::string::npos) << text;
    auto command = text.substr(mc + 10, text.find('\n', mc) - mc - 10);
    const auto back = hmira(dir, command + " -q");
    ASSERT_EQ(back.code, 0) << command << ": " << back.err;
    const auto surface = read_back(dir / "surface.obj");
    expect_sound(surface);

    expect_refused(dir, "voxelize c.obj c.vox", 2, "unknown voxel format '.vox'", "c.vox");
    expect_refused(dir, "voxelize c.obj c.raw -n 0", 2, "resolution", "c.raw");
    expect_refused(dir, "voxelize missing.obj c.raw", 3, "missing.obj", "c.raw");
}

/// Writes the samples of f(x, y, z) on a grid as raw bytes of type T, little or big endian.
template <class T, class F>
void write_raw_volume(const std::filesystem::path& p, std::size_t n, double origin, double h, bool big_endian, F f) {
    std::string bytes;
    for (std::size_t k = 0; k < n; ++k)
        for (std::size_t j = 0; j < n; ++j)
            for (std::size_t i = 0; i < n; ++i) {
                const T v = f(origin + h * double(i), origin + h * double(j), origin + h * double(k));
                char b[sizeof(T)];
                std::memcpy(b, &v, sizeof(T));
                if (big_endian != (std::endian::native == std::endian::big)) std::reverse(b, b + sizeof(T));
                bytes.append(b, sizeof(T));
            }
    hmira_test::write_bytes(p, bytes);
}

TEST(cli, mc_reads_raw_volumes_of_every_sample_type_into_a_closed_sphere) {
    scratch_dir dir;
    // A sphere of radius 0.8 sampled on 24^3 points, spacing 0.1, from -1.15.
    const double r0 = 0.8;
    auto dist = [&](double x, double y, double z) { return std::sqrt(x * x + y * y + z * z) - r0; };
    write_raw_volume<float>(dir / "f.raw", 24, -1.15, 0.1, false,
                            [&](double x, double y, double z) { return float(dist(x, y, z)); });
    write_raw_volume<std::int16_t>(dir / "s.raw", 24, -1.15, 0.1, true, [&](double x, double y, double z) {
        return std::int16_t(std::lround(1000 * dist(x, y, z)));
    });
    write_raw_volume<std::uint8_t>(dir / "u.raw", 24, -1.15, 0.1, false, [&](double x, double y, double z) {
        return std::uint8_t(dist(x, y, z) < 0 ? 200 : 0);
    });
    write_raw_volume<double>(dir / "d.raw", 24, -1.15, 0.1, true,
                             [&](double x, double y, double z) { return dist(x, y, z); });
    // Signed distances: the surface is their zero level, not the default midpoint of the range.
    const std::string grid = " --dims 24,24,24 --origin -1.15,-1.15,-1.15";
    const std::string sdf = grid + " --iso 0";
    for (const std::string& run : {"mc f.raw out.off" + sdf + " --spacing 0.1",
                                   "mc f.raw out.off" + sdf + " --type float32 --spacing 0.1,0.1,0.1",
                                   "mc s.raw out.off" + sdf + " --type int16 --endian big --spacing 0.1",
                                   "mc d.raw out.off" + sdf + " --type float64 --endian big --spacing 0.1"}) {
        SCOPED_TRACE(run);
        const auto r = hmira(dir, run);
        ASSERT_EQ(r.code, 0) << r.err;
        const auto m = read_back(dir / "out.off");
        expect_sound(m);
        EXPECT_NEAR(hmira_test::signed_volume(m), 4.0 / 3 * std::numbers::pi * r0 * r0 * r0, 0.03);
        for (auto v : m.vertices()) {
            const auto p = at(m, v.index);
            EXPECT_NEAR(dist(p[0], p[1], p[2]), 0.0, 0.01);
        }
    }
    // Occupancy bytes: inside is above the iso value.
    const auto u = hmira(dir, "mc u.raw occ.obj" + grid + " --type uint8 --spacing 0.1 --iso 100 --inside above");
    ASSERT_EQ(u.code, 0) << u.err;
    expect_sound(read_back(dir / "occ.obj"));

    expect_refused(dir, "mc f.raw x.off --type float32", 2, "--dims", "x.off");
    expect_refused(dir, "mc f.raw x.off --dims 24,24", 2, "--dims 24,24", "x.off");
    expect_refused(dir, "mc f.raw x.off --dims 23,24,24", 1, "f.raw: holds 55296 bytes", "x.off");
    expect_refused(dir, "mc f.raw x.off --dims 24,24,24 --type complex64", 2, "--type", "x.off");
    expect_refused(dir, "mc sphere x.off --dims 24,24,24", 2, ".raw volumes only", "x.off");
    expect_refused(dir, "mc missing.raw x.off --dims 24,24,24", 3, "missing.raw", "x.off");
}

TEST(cli, mc_reads_inr_and_inr_gz_volumes_by_name) {
    scratch_dir dir;
    // The same sphere as an INRIMAGE-4 file: a 256-byte text header, then float samples.
    const double r0 = 0.8;
    write_raw_volume<float>(dir / "samples", 24, -1.15, 0.1, false,
                            [&](double x, double y, double z) { return float(std::sqrt(x * x + y * y + z * z) - r0); });
    std::string header =
        "#INRIMAGE-4#{\nXDIM=24\nYDIM=24\nZDIM=24\nVDIM=1\nTYPE=float\nPIXSIZE=32 "
        "bits\nCPU=decm\nVX=0.1\nVY=0.1\nVZ=0.1\n";
    header += std::string(252 - header.size(), '\n') + "##}\n";
    ASSERT_EQ(header.size(), 256u);
    hmira_test::write_bytes(dir / "s.inr", header + hmira_test::read_bytes(dir / "samples"));
    const auto r = hmira(dir, "mc s.inr a.off --iso 0");
    ASSERT_EQ(r.code, 0) << r.err;
    const auto a = read_back(dir / "a.off");
    expect_sound(a);
    EXPECT_NEAR(hmira_test::signed_volume(a), 4.0 / 3 * std::numbers::pi * r0 * r0 * r0, 0.03);
    // Gzipped, named .inr.gz (or upper case): the same surface.
    ASSERT_EQ(std::system(("cd '" + dir.path().string() + "' && gzip -c s.inr > S.INR.GZ").c_str()), 0);
    const auto gz = hmira(dir, "mc S.INR.GZ b.off --iso 0");
    if (gz.code != 0 && gz.err.find("zlib") != std::string::npos)
        GTEST_SKIP() << "hmira built without zlib: " << gz.err;
    ASSERT_EQ(gz.code, 0) << gz.err;
    EXPECT_EQ(hmira_test::read_bytes(dir / "b.off"), hmira_test::read_bytes(dir / "a.off"));
}

TEST(cli, editing_refuses_bad_selections_unknown_options_and_non_manifold_input) {
    scratch_dir dir;
    ASSERT_EQ(hmira(dir, "generate cube c.obj").code, 0);
    // Out-of-range indices and edges that do not exist: usage errors naming the index.
    expect_refused(dir, "truncate c.obj t.obj --vertex 8", 2,
                   "--vertex: vertex 8 does not exist: c.obj has 8 vertices (0..7", "t.obj");
    expect_refused(dir, "truncate c.obj t.obj --vertex -1", 2, "--vertex", "t.obj");
    expect_refused(dir, "bevel c.obj t.obj --edge 0,8", 2, "--edge 0,8: vertex 8 does not exist", "t.obj");
    expect_refused(dir, "bevel c.obj t.obj --edge 0,6", 2,
                   "--edge 0,6: vertices 0 and 6 of c.obj are not joined by an edge", "t.obj");
    expect_refused(dir, "bevel c.obj t.obj --edge 0-1", 2, "--edge 0-1: expected two vertex indices", "t.obj");
    expect_refused(dir, "bevel c.obj t.obj --vertex 9", 2, "vertex 9 does not exist", "t.obj");
    expect_refused(dir, "extrude c.obj t.obj --face 6", 2, "--face: face 6 does not exist: c.obj has 6 faces (0..5",
                   "t.obj");
    // Unknown options, missing or conflicting selections, values out of range.
    expect_refused(dir, "truncate c.obj t.obj --all --bogus", 2, "--bogus", "t.obj");
    expect_refused(dir, "bevel c.obj t.obj --edge 0,1 --frobnicate 3", 2, "--frobnicate", "t.obj");
    expect_refused(dir, "truncate c.obj t.obj", 2, "--vertex N", "t.obj");
    expect_refused(dir, "bevel c.obj t.obj", 2, "--edge A,B", "t.obj");
    expect_refused(dir, "extrude c.obj t.obj", 2, "--face N", "t.obj");
    expect_refused(dir, "bevel c.obj t.obj --edge 0,1 --all", 2, "excludes", "t.obj");
    expect_refused(dir, "bevel c.obj t.obj --vertex 0 --segments 2", 2, "flat cuts only", "t.obj");
    expect_refused(dir, "bevel c.obj t.obj --vertex 0 --no-clamp", 2, "drop --no-clamp", "t.obj");
    expect_refused(dir, "truncate c.obj t.obj --all --fraction 1", 2,
                   "--fraction: expected a finite number in (0, 1), got 1", "t.obj");
    expect_refused(dir, "bevel c.obj t.obj --all --width 0", 2, "--width", "t.obj");
    expect_refused(dir, "extrude c.obj t.obj --face 0 --direction 1,2", 2, "--direction 1,2", "t.obj");
    expect_refused(dir, "extrude c.obj t.obj --face 0 --distance 0", 2,
                   "--distance: expected a finite number other than 0, got 0", "t.obj");
    expect_refused(dir, "extrude c.obj t.obj --face 0 --mode sideways", 2, "--mode", "t.obj");
    // Operations the mesh does not allow: invalid input, the library's reason.
    hmira_test::write_bytes(dir / "square.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n");
    hmira_test::write_bytes(dir / "straight.off", "OFF\n5 1 0\n0 0 0\n1 0 0\n2 0 0\n2 1 0\n0 1 0\n5 0 1 2 3 4\n");
    expect_refused(dir, "bevel straight.off t.off --edge 0,1", 1,
                   "straight.off: bevel: the edges of a face corner at vertex 1 are collinear", "t.off");
    // Three triangles on one edge: repaired for editing (the third face cut free), with a note.
    hmira_test::write_bytes(dir / "fin.off",
                            "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n");
    for (const std::string cmd :
         {"truncate fin.off t.off --all", "truncate fin.off t.off --vertex 2", "extrude fin.off t.off --face 0"}) {
        SCOPED_TRACE(cmd);
        const auto r = hmira(dir, cmd);
        EXPECT_EQ(r.code, 0) << r.err;
        EXPECT_NE(r.out.find("fin.off: repaired for editing: 1 non-manifold edge: cut free 1 extra face (2)"),
                  std::string::npos)
            << r.out;
    }
    // Missing input.
    expect_refused(dir, "truncate nothere.obj t.obj --all", 3, "nothere.obj", "t.obj");
}

TEST(cli, edits_drop_degenerate_faces_with_a_note_while_validate_and_info_describe_the_file_as_it_is) {
    scratch_dir dir;
    // Face 2 repeats vertex 1: no polygon mesh holds it. Faces 0, 1 and 3 form an open square
    // and a triangle on it.
    hmira_test::write_bytes(dir / "deg.off",
                            "OFF\n5 4 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 1\n3 0 1 2\n3 0 2 3\n3 1 1 2\n3 2 1 4\n");
    for (const std::string cmd :
         {"truncate deg.off t.off --vertex 2", "truncate deg.off t.off --all", "extrude deg.off t.off --face 1",
          "extrude deg.off t.off --face 3", "bevel deg.off t.off --edge 0,2", "smooth deg.off t.off",
          "subdivide deg.off t.off", "fill-holes deg.off t.off"}) {
        SCOPED_TRACE(cmd);
        std::filesystem::remove(dir / "t.off");
        const auto r = hmira(dir, cmd);
        EXPECT_EQ(r.code, 0) << r.err;
        EXPECT_NE(r.out.find("deg.off: repaired for editing: 1 degenerate face dropped (file face 2)"),
                  std::string::npos)
            << r.out;
        EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n') - std::count(r.out.begin(), r.out.end(), '\r'), 2)
            << "one note line and one result line:\n"
            << r.out;
        ASSERT_TRUE(std::filesystem::exists(dir / "t.off"));
        const auto out = read_back(dir / "t.off");
        EXPECT_TRUE(hmira_test::is_valid(out, {.check_geometry = false}));
    }
    // --face N still names the file's face N: face 3 is the triangle (a quad of side walls
    // around it), face 2 is gone, face 4 never existed.
    ASSERT_EQ(hmira(dir, "extrude deg.off t.off --face 3 --distance 1").code, 0);
    const auto x = read_back(dir / "t.off");
    EXPECT_EQ(x.face_count(), 3u + 3u);  // 3 kept faces, the triangle moved, 3 side walls
    expect_refused(dir, "extrude deg.off t2.off --face 2", 2,
                   "--face: face 2 of deg.off is degenerate (fewer than 3 distinct corners) and was dropped", "t2.off");
    expect_refused(dir, "extrude deg.off t2.off --face 4", 2,
                   "--face: face 4 does not exist: deg.off has 4 faces (0..3", "t2.off");
    // validate and info describe the file as it is: the degenerate face is named, nothing repaired.
    const auto v = hmira(dir, "validate deg.off");
    EXPECT_NE(v.code, 0);
    EXPECT_NE((v.out + v.err).find("face 2"), std::string::npos) << v.out << v.err;
    EXPECT_EQ((v.out + v.err).find("repaired"), std::string::npos) << v.out << v.err;
    const auto i = hmira(dir, "info deg.off");
    EXPECT_NE((i.out + i.err).find("face 2"), std::string::npos) << i.out << i.err;
    EXPECT_EQ((i.out + i.err).find("repaired"), std::string::npos) << i.out << i.err;
}

TEST(cli, editing_and_voxelizing_real_cgal_demo_meshes) {
    const char* data = std::getenv("HMIRA_TEST_DATA");
    const auto folder =
        data ? std::filesystem::absolute(std::filesystem::path(data) / "meshes") : std::filesystem::path();
    if (!data || !std::filesystem::exists(folder / "elephant.off") || !std::filesystem::exists(folder / "fandisk.off"))
        GTEST_SKIP() << "run scripts/test-data.sh first";
    const std::string elephant = "'" + (folder / "elephant.off").string() + "'";
    scratch_dir dir;
    const auto in = read_back(folder / "elephant.off");
    const auto before = counts(in);
    const long long genus =
        (2 - (static_cast<long long>(before.v) - static_cast<long long>(before.e) + static_cast<long long>(before.f))) /
        2;
    ASSERT_EQ(genus, 3);
    // Truncate vertex 0, of degree d (counted here): V + d - 1, E + d, F + 1.
    std::set<std::size_t> neighbours;
    for (auto f : in.faces()) {
        const auto fv = in.face_vertices(f);
        for (std::size_t i = 0; i < fv.size(); ++i)
            if (fv[i].index == 0)
                neighbours.insert({fv[(i + 1) % fv.size()].index, fv[(i + fv.size() - 1) % fv.size()].index});
    }
    const std::size_t d = neighbours.size();
    ASSERT_GE(d, 3u);
    const auto t = hmira(dir, "truncate " + elephant + " t.off --vertex 0");
    ASSERT_EQ(t.code, 0) << t.err;
    const auto tm = read_back(dir / "t.off");
    EXPECT_EQ(counts(tm), (vef{before.v + d - 1, before.e + d, before.f + 1}));
    expect_sound(tm, genus);
    for (std::size_t i = 1; i < before.v; ++i)
        if (!near(at(tm, i - 1), at(in, i))) {
            ADD_FAILURE() << "file vertex " << i << " moved or was renumbered";
            break;
        }
    // Extrude face 0 (a triangle) by 0.01 along its normal: the volume grows by area x 0.01.
    const auto e = hmira(dir, "extrude " + elephant + " e.ply --face 0 --distance 0.01");
    ASSERT_EQ(e.code, 0) << e.err;
    const auto em = read_back(dir / "e.ply");
    EXPECT_EQ(counts(em), (vef{before.v + 3, before.e + 6, before.f + 3}));
    expect_sound(em, genus);
    const auto fv = in.face_vertices(hmira::face_handle(std::size_t{0}));
    ASSERT_EQ(fv.size(), 3u);
    const auto a = at(in, fv[0].index), b = at(in, fv[1].index), c = at(in, fv[2].index);
    const point ab{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, ac{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double area =
        0.5 * std::sqrt(std::pow(ab[1] * ac[2] - ab[2] * ac[1], 2) + std::pow(ab[2] * ac[0] - ab[0] * ac[2], 2) +
                        std::pow(ab[0] * ac[1] - ab[1] * ac[0], 2));
    EXPECT_NEAR(hmira_test::signed_volume(em) - hmira_test::signed_volume(in), area * 0.01, 1e-12);
    // Bevel fandisk's sharp edges: still one closed, valid sphere.
    const auto bv = hmira(dir, "bevel '" + (folder / "fandisk.off").string() + "' f.obj --angle 60 --width 0.002");
    ASSERT_EQ(bv.code, 0) << bv.err;
    const auto fm = read_back(dir / "f.obj");
    expect_sound(fm, 0);
    EXPECT_GT(fm.face_count(), 12946u);
    // Voxelize: the solid holds the surface voxels and more.
    ASSERT_EQ(hmira(dir, "voxelize " + elephant + " s.binvox -n 64 -q --surface").code, 0);
    ASSERT_EQ(hmira(dir, "voxelize " + elephant + " v.binvox -n 64 -q").code, 0);
    const auto [ds, vs] = read_binvox(dir / "s.binvox");
    const auto [dv, vv] = read_binvox(dir / "v.binvox");
    ASSERT_EQ(ds, dv);
    std::size_t surface = 0, solid = 0, lost = 0;
    for (std::size_t i = 0; i < vs.size(); ++i) surface += vs[i], solid += vv[i], lost += vs[i] && !vv[i];
    EXPECT_GT(surface, 1000u);
    EXPECT_GT(solid, surface);
    EXPECT_EQ(lost, 0u);
}

}  // namespace
