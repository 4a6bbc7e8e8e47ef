// Hostile input (issue 14): files built to crash, exhaust or fool the readers. Each case is a
// reproducer from the issue; every one must end in a one-line error that names the file and
// the place, with the mesh being read into left as it was.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <filesystem>
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

// ---- D1: a binary vertex element without properties -------------------------------------------
TEST(io_hostile, binary_ply_vertex_element_without_properties_is_rejected) {
    const std::string body = std::string("\003\000\000\000\000\001\000\000\000\002\000\000\000", 13);
    for (const char* format : {"binary_little_endian", "binary_big_endian"}) {
        SCOPED_TRACE(format);
        const std::string ply = std::string("ply\nformat ") + format +
                                " 1.0\nelement vertex 3\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n" + body;
        const auto msg = rejection("noprops.ply", ply);
        EXPECT_TRUE(contains(msg, "noprops.ply:3")) << msg;
        EXPECT_TRUE(contains(msg, "no x, y and z")) << msg;
    }
}

// ---- D2: a file that shrinks while it is read -------------------------------------------------
TEST(io_hostile, a_file_truncated_between_open_and_read_is_an_io_error_not_a_crash) {
    scratch_dir dir;
    const auto in = dir / "shrinks.ply";
    face_vertex_mesh cube;
    ASSERT_TRUE(generate_cube(cube));
    ASSERT_TRUE(io::write_mesh(cube, in, {.ply = io::ply_encoding::binary_little_endian}));
    // Another process truncates the file after its size is known: what used to be a SIGBUS
    // on the mapped pages.
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

// ---- D3: endless non-regular inputs stop at the limit ------------------------------------------
TEST(io_hostile, a_device_without_end_stops_at_the_input_limit_naming_file_and_limit) {
    scratch_dir dir;
    for (const char* device : {"/dev/zero", "/dev/urandom"}) {
        SCOPED_TRACE(device);
        const auto link = dir / (std::string(device).substr(5) + ".off");
        std::filesystem::create_symlink(device, link);
        face_vertex_mesh mesh;
        auto r = io::read_mesh(mesh, link, {.max_input_bytes = 1 << 20});
        ASSERT_FALSE(r);
        EXPECT_EQ(r.error().code, errc::io_error);
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
