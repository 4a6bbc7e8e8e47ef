// tests/io/ply_face_vertex_test.cpp
// read_mesh of a PLY file into face_vertex_mesh parses straight into the mesh's own arrays:
// the result must be the file's content exactly, in every PLY encoding, with its
// attributes; and a file the mesh refuses must leave the mesh as it was.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

#include "io_support.hpp"

namespace {

using hmira::face_vertex_mesh;
namespace io = hmira::io;

// A quad and a triangle on five vertices, with normals and colours: the expected values are
// written out here, not computed by the reader.
const std::string small_ascii_ply =
    "ply\nformat ascii 1.0\nelement vertex 5\nproperty double x\nproperty double y\nproperty double z\n"
    "property float nx\nproperty float ny\nproperty float nz\n"
    "property uchar red\nproperty uchar green\nproperty uchar blue\n"
    "element face 2\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0 0 0 1 10 20 30\n1.5 0 0 0 0 1 40 50 60\n1.5 1 0 0 0 1 70 80 90\n0 1 0.25 0 0 1 1 2 3\n3 0 -1 0 1 0 4 5 6\n"
    "4 0 1 2 3\n3 1 4 2\n";

const std::vector<hmira::vec3<double>> expected_points{{0, 0, 0}, {1.5, 0, 0}, {1.5, 1, 0}, {0, 1, 0.25}, {3, 0, -1}};
const std::vector<std::vector<std::uint32_t>> expected_faces{{0, 1, 2, 3}, {1, 4, 2}};

void expect_small_mesh(const face_vertex_mesh& m) {
    ASSERT_EQ(m.vertex_count(), expected_points.size());
    ASSERT_EQ(m.face_count(), expected_faces.size());
    for (std::uint32_t i = 0; i < expected_points.size(); ++i)
        EXPECT_EQ(m.position(hmira::vertex_handle(i)), expected_points[i]) << "vertex " << i;
    for (std::uint32_t f = 0; f < expected_faces.size(); ++f) {
        std::vector<std::uint32_t> got;
        for (auto v : m.face_vertices(hmira::face_handle(f))) got.push_back(v.index);
        EXPECT_EQ(got, expected_faces[f]) << "face " << f;
    }
    auto colors = m.get_vertex_property<std::array<std::uint8_t, 4>>("v:color");
    ASSERT_TRUE(colors.has_value());
    EXPECT_EQ((*colors)[hmira::vertex_handle(1u)], (std::array<std::uint8_t, 4>{40, 50, 60, 255}));
    auto normals = m.get_vertex_property<hmira::vec3<float>>("v:normal");
    ASSERT_TRUE(normals.has_value());
    EXPECT_EQ((*normals)[hmira::vertex_handle(4u)], (hmira::vec3<float>{0, 1, 0}));
}

TEST(ply_into_face_vertex_mesh, every_encoding_reads_back_the_file_exactly) {
    hmira_test::scratch_dir dir;
    hmira_test::write_bytes(dir / "small.ply", small_ascii_ply);
    face_vertex_mesh m;
    auto r = io::read_mesh(m, dir / "small.ply");
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_EQ(r->format, "ply (ascii)");
    EXPECT_EQ(r->file_vertices, 5u);
    EXPECT_EQ(r->attributes.colors.size(), 5u);
    expect_small_mesh(m);
    for (auto encoding :
         {io::ply_encoding::binary_little_endian, io::ply_encoding::binary_big_endian, io::ply_encoding::ascii}) {
        const auto path = dir / "again.ply";
        ASSERT_TRUE(io::write_mesh(m, path, {.ply = encoding, .ply_coordinates = io::ply_scalar::float64}));
        face_vertex_mesh again;
        auto r2 = io::read_mesh(again, path);
        ASSERT_TRUE(r2) << r2.error().message;
        EXPECT_EQ(r2->format, std::string("ply (") + io::to_string(encoding) + ")");
        expect_small_mesh(again);
        // The soup reader, which does not build a mesh, sees the same file.
        auto soup = io::read_soup(path);
        ASSERT_TRUE(soup);
        ASSERT_EQ(soup->points.size(), again.vertex_count());
        for (std::uint32_t i = 0; i < soup->points.size(); ++i) {
            const auto p = again.position(hmira::vertex_handle(i));
            EXPECT_EQ((std::array<double, 3>{p.x, p.y, p.z}), soup->points[i]);
        }
    }
}

TEST(ply_into_face_vertex_mesh, float_coordinates_widen_exactly) {
    hmira_test::scratch_dir dir;
    hmira_test::write_bytes(dir / "small.ply", small_ascii_ply);
    face_vertex_mesh m;
    ASSERT_TRUE(io::read_mesh(m, dir / "small.ply"));
    ASSERT_TRUE(io::write_mesh(m, dir / "f.ply", {.ply_coordinates = io::ply_scalar::float32}));
    face_vertex_mesh again;
    ASSERT_TRUE(io::read_mesh(again, dir / "f.ply"));
    expect_small_mesh(again);  // every coordinate above is exact in float
}

TEST(ply_into_face_vertex_mesh, a_face_the_mesh_refuses_leaves_the_mesh_unchanged) {
    hmira_test::scratch_dir dir;
    hmira_test::write_bytes(dir / "small.ply", small_ascii_ply);
    // Vertex 4 twice in face 1: the parser takes it, the mesh does not.
    std::string bad = small_ascii_ply;
    bad.replace(bad.find("3 1 4 2"), 7, "3 1 4 4");
    for (auto encoding : {io::ply_encoding::ascii, io::ply_encoding::binary_little_endian}) {
        std::string name = "bad.ply";
        hmira_test::write_bytes(dir / name, bad);
        if (encoding != io::ply_encoding::ascii) {
            // The same content in binary: written from a soup-built copy would refuse too, so
            // patch the binary file of the good mesh instead (last index of the last face).
            face_vertex_mesh good;
            ASSERT_TRUE(io::read_mesh(good, dir / "small.ply"));
            ASSERT_TRUE(io::write_mesh(good, dir / "good_bin.ply",
                                       {.ply = encoding, .ply_coordinates = io::ply_scalar::float64}));
            std::string bytes = hmira_test::read_bytes(dir / "good_bin.ply");
            ASSERT_EQ(bytes.substr(bytes.size() - 4), std::string("\x02\x00\x00\x00", 4));
            bytes.replace(bytes.size() - 4, 4, std::string("\x04\x00\x00\x00", 4));
            name = "bad_bin.ply";
            hmira_test::write_bytes(dir / name, bytes);
        }
        face_vertex_mesh m;
        const auto a = m.add_vertex({7, 7, 7}), b = m.add_vertex({8, 7, 7}), c = m.add_vertex({7, 8, 7});
        ASSERT_TRUE(m.add_face({a, b, c}));
        const auto changes = m.change_count();
        auto r = io::read_mesh(m, dir / name);
        ASSERT_FALSE(r);
        EXPECT_EQ(r.error().code, hmira::errc::degenerate_face) << r.error().message;
        EXPECT_EQ(r.error().element, 1) << r.error().message;
        EXPECT_NE(r.error().message.find("face 1 rejected"), std::string::npos) << r.error().message;
        EXPECT_EQ(m.change_count(), changes);
        EXPECT_EQ(m.vertex_count(), 3u);
        EXPECT_EQ(m.face_count(), 1u);
        EXPECT_EQ(m.position(b), (hmira::vec3<double>{8, 7, 7}));
    }
}

}  // namespace
