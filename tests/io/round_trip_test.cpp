// Round trips through every format and encoding: what a writer writes, the reader reads back
// as the same mesh (same positions, same faces with the same winding), on every mesh model.
// Compared through canonical forms computed by the test, not by the I/O code.
#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <random>

#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/topology/mesh_topology.hpp>
#include <hmira/io/mesh_io.hpp>

#include "io/io_support.hpp"
#include "support/checks.hpp"
#include "support/models.hpp"
#include "support/shapes.hpp"

namespace {

using namespace hmira;
using hmira_test::scratch_dir;

struct format_case {
    const char* name;
    const char* extension;
    io::write_options options;
    bool exact;       // coordinates come back bit for bit
    bool polygons;    // polygons stay polygons (STL triangulates)
    bool attributes;  // normals and colours survive
};

std::vector<format_case> all_formats() {
    return {
        {"obj", ".obj", {}, true, true, true},
        {"off", ".off", {}, true, true, true},
        {"ply_ascii", ".ply", {.ply = io::ply_encoding::ascii}, true, true, true},
        {"ply_binary_le", ".ply", {.ply = io::ply_encoding::binary_little_endian}, true, true, true},
        {"ply_binary_be", ".ply", {.ply = io::ply_encoding::binary_big_endian}, true, true, true},
        {"stl_binary", ".stl", {.stl = io::stl_encoding::binary}, false, false, false},
        {"stl_ascii", ".stl", {.stl = io::stl_encoding::ascii}, false, false, false},
    };
}

/// A closed quad torus with coordinates that need all 17 significant digits, so that any
/// rounding in the text formats shows up.
hmira_test::face_list jittered_torus() {
    auto g = hmira_test::torus(12, 8);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> d(-1e-3, 1e-3);
    for (auto& p : g.points) p += vec3<double>{d(rng), d(rng), d(rng)};
    return g;
}

/// Triangles with a boundary, plus an open polygon fan of degree 7.
hmira_test::face_list open_mixed() {
    auto g = hmira_test::grid(5, 4, true);
    const std::size_t base = g.points.size();
    for (int i = 0; i < 7; ++i) g.points.push_back({10 + std::cos(i * 0.9), std::sin(i * 0.9), 0.25 * i});
    g.faces.push_back({base, base + 1, base + 2, base + 3, base + 4, base + 5, base + 6});
    return g;
}

template <class M>
class io_round_trip : public ::testing::Test {};
TYPED_TEST_SUITE(io_round_trip, hmira_test::all_models);

template <class M>
void check_round_trip(const M& original, const format_case& fc, const std::string& label) {
    SCOPED_TRACE(std::string(fc.name) + " / " + label);
    scratch_dir dir;
    const auto path = dir / ("mesh" + std::string(fc.extension));
    auto w = io::write_mesh(original, path, fc.options);
    ASSERT_TRUE(w) << w.error().message;
    M back;
    auto r = io::read_mesh(back, path);
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_TRUE(hmira_test::is_valid(back));
    if (fc.exact) {
        EXPECT_EQ(hmira_test::positions(back), hmira_test::positions(original));
        EXPECT_EQ(hmira_test::canonical_faces(back), hmira_test::canonical_faces(original));
    } else {
        EXPECT_EQ(default_traits<M>::vertex_count(back),
                  default_traits<M>::vertex_count(original));  // welded back to shared vertices
    }
    auto round = fc.exact ? hmira_test::exact : hmira_test::to_float;
    EXPECT_EQ(hmira_test::geometric_faces(back, round, !fc.polygons),
              hmira_test::geometric_faces(original, round, !fc.polygons));
    EXPECT_EQ(dir.files(), std::vector<std::string>{path.filename().string()}) << "a temporary file was left behind";
}

TYPED_TEST(io_round_trip, write_then_read_gives_the_same_mesh_in_every_format) {
    const auto shapes = std::vector<std::pair<std::string, hmira_test::face_list>>{{"torus", jittered_torus()},
                                                                                   {"open mixed", open_mixed()}};
    for (const auto& fc : all_formats()) {
        for (const auto& [label, shape] : shapes) {
            TypeParam m;
            ASSERT_TRUE(hmira_test::add_face_list(m, shape));
            check_round_trip(m, fc, label);
        }
        TypeParam d;
        ASSERT_TRUE(generate_dodecahedron(d, {.scale = 1.7}));
        check_round_trip(d, fc, "dodecahedron");
    }
}

TYPED_TEST(io_round_trip, polygons_stay_polygons_and_stl_welds_to_a_closed_mesh) {
    TypeParam cube;
    ASSERT_TRUE(generate_cube(cube));
    scratch_dir dir;
    for (const char* ext : {".obj", ".off", ".ply"}) {
        ASSERT_TRUE(io::write_mesh(cube, dir / (std::string("c") + ext)));
        TypeParam back;
        ASSERT_TRUE(io::read_mesh(back, dir / (std::string("c") + ext)));
        for (auto f : default_traits<TypeParam>::faces(back))
            EXPECT_EQ(std::ranges::distance(default_traits<TypeParam>::face_vertices(back, f)), 4) << ext;
    }
    ASSERT_TRUE(io::write_mesh(cube, dir / "c.stl"));
    TypeParam back;
    auto r = io::read_mesh(back, dir / "c.stl");
    ASSERT_TRUE(r);
    const auto topo = mesh_topology(back);
    EXPECT_EQ(topo.vertices, 8u);
    EXPECT_EQ(topo.faces, 12u);
    EXPECT_TRUE(topo.closed());
    EXPECT_EQ(topo.genus, 0);
    EXPECT_EQ(r->dropped_triangles, 0u);
}

TEST(io_attributes, normals_and_colours_survive_every_format_that_has_them) {
    face_vertex_mesh m;
    ASSERT_TRUE(generate_icosahedron(m));
    auto normals = m.add_vertex_property<vec3<float>>("v:normal");
    auto colors = m.add_vertex_property<std::array<std::uint8_t, 4>>("v:color");
    std::uint8_t k = 3;
    for (auto v : m.vertices()) {
        const auto p = m.position(v);
        normals[v] = vec3<float>{float(p.x), float(p.y), float(p.z)} * (1.0f / 1.9021f);
        colors[v] = {k, std::uint8_t(k * 7), std::uint8_t(255 - k), 255};
        k = std::uint8_t(k + 17);
    }
    for (const auto& fc : all_formats()) {
        if (!fc.attributes) continue;
        SCOPED_TRACE(fc.name);
        scratch_dir dir;
        const auto path = dir / ("m" + std::string(fc.extension));
        ASSERT_TRUE(io::write_mesh(m, path, fc.options));
        face_vertex_mesh back;
        auto r = io::read_mesh(back, path);
        ASSERT_TRUE(r) << r.error().message;
        ASSERT_EQ(r->attributes.normals.size(), m.vertex_count());
        ASSERT_EQ(r->attributes.colors.size(), m.vertex_count());
        auto bn = back.get_vertex_property<vec3<float>>("v:normal");
        auto bc = back.get_vertex_property<std::array<std::uint8_t, 4>>("v:color");
        ASSERT_TRUE(bn && bc);
        for (auto v : m.vertices()) {
            EXPECT_EQ((*bn)[v], normals[v]);
            EXPECT_EQ((*bc)[v], colors[v]);
            EXPECT_EQ(r->attributes.normals[v.index], normals[v]);
        }
    }
}

TEST(io_attributes, explicit_attributes_are_written_for_meshes_without_properties) {
    halfedge_mesh m;
    ASSERT_TRUE(generate_tetrahedron(m));
    io::mesh_attributes a;
    a.colors = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {9, 9, 9, 128}};
    scratch_dir dir;
    ASSERT_TRUE(io::write_mesh(m, dir / "t.ply", {.attributes = &a}));
    auto soup = io::read_soup(dir / "t.ply");
    ASSERT_TRUE(soup);
    EXPECT_EQ(soup->attributes.colors, a.colors);
    EXPECT_TRUE(soup->attributes.normals.empty());
    ASSERT_TRUE(io::write_mesh(m, dir / "plain.ply", {.attributes = &a, .write_attributes = false}));
    EXPECT_TRUE(io::read_soup(dir / "plain.ply")->attributes.empty());
}

TEST(io_obj, negative_indices_mean_the_same_faces_as_positive_ones) {
    const std::string body = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
    auto pos = io::parse_obj(body + "f 1 2 3 4\n", "p.obj");
    auto neg = io::parse_obj(body + "f -4 -3 -2 -1\n", "n.obj");
    auto mixed = io::parse_obj("v 0 0 0\nv 1 0 0\nv 1 1 0\nf -3/1 2/1 -1/7\nv 0 1 0\nf 1 3 -1\n", "m.obj");
    ASSERT_TRUE(pos && neg && mixed) << (mixed ? "" : mixed.error().message);
    EXPECT_EQ(pos->indices, neg->indices);
    EXPECT_EQ(mixed->indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
    EXPECT_EQ(mixed->face_offsets, (std::vector<std::uint64_t>{0, 3, 6}));
}

TEST(io_obj, texture_and_normal_references_and_other_records_are_accepted) {
    auto s = io::parse_obj(
        "# c\r\nmtllib x.mtl\r\no thing\r\nv 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nvt 0 0\r\nvn 0 0 1\r\ng g\r\ns "
        "off\r\nusemtl m\r\nf 1/1/1 2/1/1 3/1/1 # tri\r\nl 1 2\r\n",
        "x.obj");
    ASSERT_TRUE(s) << s.error().message;
    EXPECT_EQ(s->face_count(), 1u);
    ASSERT_EQ(s->attributes.normals.size(), 3u);
    EXPECT_EQ(s->attributes.normals[2], (vec3<float>{0, 0, 1}));
}

TEST(io_ply, big_endian_bytes_built_by_hand_read_as_the_same_numbers) {
    // Independent of the writer: the bytes of a big-endian file assembled here.
    std::string f =
        "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty double z\n"
        "element face 1\nproperty list uchar uint vertex_indices\nend_header\n";
    auto be32 = [&](std::uint32_t u) {
        for (int s = 24; s >= 0; s -= 8) f += char((u >> s) & 0xff);
    };
    auto be64 = [&](std::uint64_t u) {
        for (int s = 56; s >= 0; s -= 8) f += char((u >> s) & 0xff);
    };
    const double zs[3] = {0.1, -2.5, 1e300};
    for (int i = 0; i < 3; ++i) {
        be32(std::bit_cast<std::uint32_t>(float(i) + 0.5f));
        be32(std::bit_cast<std::uint32_t>(-float(i)));
        be64(std::bit_cast<std::uint64_t>(zs[i]));
    }
    f += char(3);
    be32(2), be32(0), be32(1);
    auto s = io::parse_ply(f, "be.ply");
    ASSERT_TRUE(s) << s.error().message;
    ASSERT_EQ(s->points.size(), 3u);
    for (int i = 0; i < 3; ++i)
        EXPECT_EQ(s->points[std::size_t(i)], (std::array<double, 3>{i + 0.5, -double(i), zs[i]}));
    EXPECT_EQ(s->indices, (std::vector<std::uint32_t>{2, 0, 1}));
}

TEST(io_ply, unknown_elements_and_properties_are_skipped) {
    const std::string f =
        "ply\nformat ascii 1.0\ncomment hi\nelement vertex 3\nproperty float x\nproperty float y\nproperty float "
        "z\nproperty float quality\n"
        "element face 1\nproperty uchar flags\nproperty list uchar int vertex_indices\nproperty list uchar float "
        "texcoord\n"
        "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n"
        "0 0 0 9\n1 0 0 9\n0 1 0 9\n7 3 0 1 2 2 0.5 0.5\n0 1\n";
    auto s = io::parse_ply(f, "x.ply");
    ASSERT_TRUE(s) << s.error().message;
    EXPECT_EQ(s->indices, (std::vector<std::uint32_t>{0, 1, 2}));
}

TEST(io_stl, welding_uses_exact_equality_and_treats_minus_zero_as_zero) {
    const std::string f =
        "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
        "facet normal 0 0 1\nouter loop\nvertex -0 1 0\nvertex 1 0 0\nvertex 1 1.0000001 "
        "0\nendloop\nendfacet\nendsolid t\n";
    auto s = io::parse_stl(f, "t.stl");
    ASSERT_TRUE(s) << s.error().message;
    EXPECT_EQ(s->soup.points.size(), 4u);  // (-0,1,0) welds with (0,1,0); 1.0000001 does not weld with 1
    auto loose = io::parse_stl(f, "t.stl", {.weld_stl = false});
    EXPECT_EQ(loose->soup.points.size(), 6u);
}

TEST(io_stl, triangles_that_weld_to_a_line_are_dropped_and_counted) {
    const std::string f =
        "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
        "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 0 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n";
    auto s = io::parse_stl(f, "t.stl");
    ASSERT_TRUE(s);
    EXPECT_EQ(s->soup.face_count(), 1u);
    EXPECT_EQ(s->dropped_triangles, 1u);
}

TEST(io_stl, binary_file_starting_with_solid_is_read_as_binary) {
    face_vertex_mesh m;
    ASSERT_TRUE(generate_octahedron(m));
    auto bytes = io::format_stl(m).value();
    std::memcpy(bytes.data(), "solid but binary", 16);
    auto s = io::parse_stl(bytes, "b.stl");
    ASSERT_TRUE(s) << s.error().message;
    EXPECT_TRUE(s->binary);
    EXPECT_EQ(s->soup.points.size(), 6u);
}

TEST(io_dispatch, the_extension_picks_the_format_case_insensitively) {
    EXPECT_EQ(io::format_from_extension("a/b.PLY"), io::file_format::ply);
    EXPECT_EQ(io::format_from_extension("x.Obj"), io::file_format::obj);
    EXPECT_FALSE(io::format_from_extension("x.mesh"));
    face_vertex_mesh m;
    ASSERT_TRUE(generate_tetrahedron(m));
    scratch_dir dir;
    ASSERT_TRUE(io::write_mesh(m, dir / "T.STL"));
    EXPECT_EQ(hmira_test::read_bytes(dir / "T.STL").size(), 84u + 4u * 50u);
}

TEST(io_write, writing_over_an_existing_file_replaces_it_whole) {
    face_vertex_mesh big, small;
    ASSERT_TRUE(generate_dodecahedron(big));
    ASSERT_TRUE(generate_tetrahedron(small));
    scratch_dir dir;
    ASSERT_TRUE(io::write_mesh(big, dir / "m.off"));
    ASSERT_TRUE(io::write_mesh(small, dir / "m.off"));
    EXPECT_EQ(hmira_test::read_bytes(dir / "m.off"), io::format_off(small).value());
}

}  // namespace
