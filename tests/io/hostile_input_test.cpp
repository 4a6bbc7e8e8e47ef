// Hostile input: files built to crash, exhaust or fool the readers. Every one must end in a
// one-line error that names the file and the place, with the mesh being read into left as it
// was.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <vector>
#include <string>
#include <thread>

#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

#include "io/io_support.hpp"
#include "support/checks.hpp"

namespace {

using namespace hmira;
using hmira_test::scratch_dir;

/// Writes `bytes` to `file` in a scratch folder, reads it into a mesh holding a tetrahedron,
/// and returns the error message ("" if the file was accepted). The mesh must be unchanged.
std::string rejection(const std::string& file, const std::string& bytes) {
    scratch_dir dir;
    const auto in = dir / file;
    hmira_test::write_bytes(in, bytes);
    face_vertex_mesh mesh;
    EXPECT_TRUE(generate_tetrahedron(mesh));
    auto r = io::read_mesh(mesh, in);
    EXPECT_EQ(mesh.vertex_count(), 4u);
    EXPECT_EQ(mesh.face_count(), 4u);
    if (r) return "";
    const auto& msg = r.error().message;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    EXPECT_NE(msg.find(in.string()), std::string::npos) << msg;
    // The soup reader gives the same verdict.
    EXPECT_FALSE(io::read_soup(in));
    return msg;
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// ---- a binary vertex element without properties -------------------------------------------------
TEST(io_hostile, binary_ply_vertex_element_without_properties_is_rejected) {
    const std::string body = std::string("\003\000\000\000\000\001\000\000\000\002\000\000\000", 13);
    for (const char* format : {"binary_little_endian", "binary_big_endian"}) {
        SCOPED_TRACE(format);
        const std::string ply =
            std::string("ply\nformat ") + format +
            " 1.0\nelement vertex 3\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n" + body;
        const auto msg = rejection("noprops.ply", ply);
        EXPECT_TRUE(contains(msg, "noprops.ply:3")) << msg;
        EXPECT_TRUE(contains(msg, "no x, y and z")) << msg;
    }
}

// ---- colours that are no colours ----------------------------------------------------------------
const std::string ply_ascii_colour_head =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "property uchar red\nproperty uchar green\nproperty uchar blue\nelement face 1\nproperty list uchar int "
    "vertex_indices\nend_header\n";

TEST(io_hostile, nan_and_out_of_range_colours_are_rejected_with_their_line) {
    const std::string tri_faces = "3 0 1 2\n";
    auto coff = [&](const std::string& second) {
        return "COFF\n3 1 0\n0 0 0 255 0 0 255\n" + second + "\n0 1 0 0 0 255 255\n" + tri_faces;
    };
    auto msg = rejection("nan.off", coff("1 0 0 nan 0 0 255"));
    EXPECT_TRUE(contains(msg, "nan.off:4: colour of vertex 1")) << msg;
    EXPECT_TRUE(contains(msg, "is nan")) << msg;
    msg = rejection("big.off", coff("1 0 0 300 0 0 255"));
    EXPECT_TRUE(contains(msg, "big.off:4: colour of vertex 1: channel 0 is 300, outside 0..255")) << msg;
    msg = rejection("neg.off", coff("1 0 0 -1 0 0 255"));
    EXPECT_TRUE(contains(msg, "neg.off:4: colour of vertex 1")) << msg;
    msg = rejection("inf.off", "COFF\n3 1 0\n0 0 0 0.5 0 0\n1 0 0 inf 0 0\n0 1 0 0 0 1\n" + tri_faces);
    EXPECT_TRUE(contains(msg, "inf.off:4: colour of vertex 1")) << msg;

    msg = rejection("nan.ply", ply_ascii_colour_head + "0 0 0 255 0 0\n1 0 0 nan 0 0\n0 1 0 0 0 255\n" + tri_faces);
    EXPECT_TRUE(contains(msg, "nan.ply:14: vertex 1: colour channel red is nan, outside 0..255")) << msg;
    msg = rejection("big.ply", ply_ascii_colour_head + "0 0 0 255 0 0\n1 0 0 0 256 0\n0 1 0 0 0 255\n" + tri_faces);
    EXPECT_TRUE(contains(msg, "big.ply:14: vertex 1: colour channel green is 256, outside 0..255")) << msg;
    // A binary short channel can hold 300 as well.
    std::string bin =
        "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "property short red\nproperty short green\nproperty short blue\nelement face 1\nproperty list uchar int "
        "vertex_indices\nend_header\n";
    const auto header_size = bin.size();
    for (int v = 0; v < 3; ++v) {
        const float p[3] = {float(v == 1), float(v == 2), 0};
        const std::int16_t c[3] = {std::int16_t(v == 2 ? 300 : 0), 0, 0};
        bin.append(reinterpret_cast<const char*>(p), 12).append(reinterpret_cast<const char*>(c), 6);
    }
    const std::uint8_t k = 3;
    const std::int32_t idx[3] = {0, 1, 2};
    bin.append(reinterpret_cast<const char*>(&k), 1).append(reinterpret_cast<const char*>(idx), 12);
    msg = rejection("short.ply", bin);
    EXPECT_TRUE(contains(msg, "short.ply: byte offset " + std::to_string(header_size + 2 * 18 + 12) +
                                  ": vertex 2: colour channel red is 300"))
        << msg;
}

// ---- list properties where single values belong -------------------------------------------------
TEST(io_hostile, ascii_ply_with_a_list_coordinate_is_rejected_like_binary) {
    const std::string head =
        "element vertex 3\nproperty list uchar float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    auto msg = rejection("list.ply", "ply\nformat ascii 1.0\n" + head + "1 5 0 0\n1 6 0 0\n1 7 1 0\n3 0 1 2\n");
    EXPECT_TRUE(contains(msg, "list.ply:3: vertex property x is a list")) << msg;
    msg = rejection("listb.ply", "ply\nformat binary_little_endian 1.0\n" + head);
    EXPECT_TRUE(contains(msg, "listb.ply:3")) << msg;
}

// ---- non-finite coordinates and normals ---------------------------------------------------------
TEST(io_hostile, non_finite_coordinates_and_normals_are_rejected_in_every_format) {
    const std::string tri = "3 0 1 2\n";
    struct c {
        std::string file, bytes, where;
    };
    std::vector<c> cases = {
        {"a.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n", "a.obj:2: vertex 2 has a coordinate that is not finite"},
        {"b.obj", "v 0 0 0\nv 1 0 0\nv 0 1 inf\nf 1 2 3\n", "b.obj:3: vertex 3"},
        {"c.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 -inf\nf 1//1 2//1 3//1\n", "c.obj:4: normal 1 is not finite"},
        {"d.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 -inf\n" + tri,
         "d.off:5: vertex 2 has a coordinate that is not finite"},
        {"e.off", "NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 nan 1\n0 1 0 0 0 1\n" + tri,
         "e.off:4: normal of vertex 1 is not finite"},
        {"f.ply",
         "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face "
         "1\n"
         "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 nan 0\n" +
             tri,
         "f.ply:12: vertex 2 has a coordinate"},
        {"g.ply",
         "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nproperty "
         "float nx\n"
         "property float ny\nproperty float nz\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
         "0 0 0 0 0 1\n1 0 0 inf 0 1\n0 1 0 0 0 1\n" +
             tri,
         "g.ply:14: normal of vertex 1"},
        {"h.stl",
         "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 nan\nvertex 0 1 "
         "0\nendloop\nendfacet\nendsolid x\n",
         "h.stl:5: facet 0 has a vertex coordinate that is not finite"},
    };
    for (const auto& k : cases) {
        SCOPED_TRACE(k.file);
        const auto msg = rejection(k.file, k.bytes);
        EXPECT_TRUE(contains(msg, k.where)) << msg;
    }
    // Binary PLY (float fast path and double path) and binary STL give byte offsets.
    for (auto scalar : {io::ply_scalar::float32, io::ply_scalar::float64}) {
        face_vertex_mesh cube;
        ASSERT_TRUE(generate_cube(cube));
        // The writers refuse a non-finite coordinate, so the NaN is put into the bytes: vertex 5's y,
        // big-endian, a quiet NaN of the coordinate's width.
        auto formatted = io::format_ply(cube, {.ply = io::ply_encoding::binary_big_endian, .ply_coordinates = scalar});
        ASSERT_TRUE(formatted) << formatted.error().message;
        std::string bytes = std::move(*formatted);
        const std::size_t stride = scalar == io::ply_scalar::float32 ? 12 : 24;
        const std::size_t y = bytes.find("end_header\n") + 11 + 5 * stride + stride / 3;
        const std::string nan = scalar == io::ply_scalar::float32 ? std::string("\x7f\xc0\x00\x00", 4)
                                                                  : std::string("\x7f\xf8\x00\x00\x00\x00\x00\x00", 8);
        bytes.replace(y, nan.size(), nan);
        const auto msg = rejection("i.ply", bytes);
        EXPECT_TRUE(contains(msg, "i.ply: byte offset " + std::to_string(bytes.find("end_header\n") + 11 + 5 * stride) +
                                      ": vertex 5 is not finite"))
            << msg;
    }
    {
        face_vertex_mesh tetra;
        ASSERT_TRUE(generate_tetrahedron(tetra));
        // Triangle 0's first corner's z (after the 80-byte header, the count and the normal),
        // little-endian +infinity.
        auto formatted = io::format_stl(tetra);
        ASSERT_TRUE(formatted) << formatted.error().message;
        std::string bytes = std::move(*formatted);
        bytes.replace(84 + 12 + 8, 4, std::string("\x00\x00\x80\x7f", 4));
        const auto msg = rejection("j.stl", bytes);
        EXPECT_TRUE(contains(msg, "j.stl: byte offset")) << msg;
        EXPECT_TRUE(contains(msg, "has a vertex coordinate that is not finite")) << msg;
    }
}

// ---- a negative count is called negative --------------------------------------------------------
TEST(io_hostile, negative_off_counts_are_named_as_negative) {
    auto msg = rejection("neg.off", "OFF\n-3 1 0\n");
    EXPECT_TRUE(contains(msg, "neg.off:2: the vertex count -3 is negative")) << msg;
    msg = rejection("negf.off", "OFF\n3 -1 0\n");
    EXPECT_TRUE(contains(msg, "negf.off:2: the face count -1 is negative")) << msg;
}

// ---- a file that shrinks while it is read -------------------------------------------------------
TEST(io_hostile, a_file_truncated_between_open_and_read_is_an_io_error_not_a_crash) {
    scratch_dir dir;
    const auto in = dir / "shrinks.ply";
    face_vertex_mesh cube;
    ASSERT_TRUE(generate_cube(cube));
    ASSERT_TRUE(io::write_mesh(cube, in, {.ply = io::ply_encoding::binary_little_endian}));
    // Another process truncates the file after its size is known: reading the mapped pages past
    // the new end would raise SIGBUS, so the reader must notice and report an I/O error.
    io::detail::input_file_size_known_hook = [](const char* path) { ASSERT_EQ(::truncate(path, 100), 0); };
    face_vertex_mesh mesh;
    auto r = io::read_mesh(mesh, in);
    io::detail::input_file_size_known_hook = nullptr;
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, errc::io_error);
    EXPECT_TRUE(contains(r.error().message, in.string() + ": file shrank while reading")) << r.error().message;
    EXPECT_TRUE(contains(r.error().message, "100 read")) << r.error().message;
    EXPECT_EQ(mesh.vertex_count(), 0u);
}

// ---- endless non-regular inputs stop at the limit -----------------------------------------------
TEST(io_hostile, a_device_without_end_stops_at_the_input_limit_naming_file_and_limit) {
    scratch_dir dir;
    for (const char* device : {"/dev/zero", "/dev/urandom"}) {
        SCOPED_TRACE(device);
        const auto link = dir / (std::string(device).substr(5) + ".off");
        std::filesystem::create_symlink(device, link);
        face_vertex_mesh mesh;
        auto r = io::read_mesh(mesh, link, {.max_input_bytes = 1 << 20});
        ASSERT_FALSE(r);
        EXPECT_EQ(r.error().code, errc::unsupported);
        EXPECT_TRUE(contains(r.error().message, link.string() + ": not a regular file")) << r.error().message;
        EXPECT_TRUE(contains(r.error().message, "input limit of 1048576 bytes")) << r.error().message;
        EXPECT_FALSE(io::read_soup(link, {.max_input_bytes = 1 << 20}));
    }
}

TEST(io_hostile, a_fifo_is_read_whole_under_the_limit_and_refused_over_it) {
    scratch_dir dir;
    const auto fifo = dir / "pipe.off";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    std::signal(SIGPIPE, SIG_IGN);  // the reader stops early; the writer then sees EPIPE
    auto feed = [&](std::string bytes, std::size_t repeat) {
        return std::thread([=] {
            FILE* f = std::fopen(fifo.c_str(), "wb");
            if (!f) return;
            for (std::size_t i = 0; i < repeat; ++i)
                if (std::fwrite(bytes.data(), 1, bytes.size(), f) != bytes.size()) break;  // reader gone
            std::fclose(f);
        });
    };
    {
        auto writer = feed("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", 1);
        face_vertex_mesh mesh;
        auto r = io::read_mesh(mesh, fifo, {.max_input_bytes = 1 << 20});
        writer.join();
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_EQ(mesh.face_count(), 1u);
    }
    {
        auto writer = feed(std::string(1 << 16, '#'), 64);  // 4 MiB of comments
        face_vertex_mesh mesh;
        auto r = io::read_mesh(mesh, fifo, {.max_input_bytes = 1 << 20});
        writer.join();
        ASSERT_FALSE(r);
        EXPECT_TRUE(contains(r.error().message, "input limit of 1048576 bytes")) << r.error().message;
    }
}

}  // namespace
