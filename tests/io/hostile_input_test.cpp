// Hostile input (issue 14): files built to crash, exhaust or fool the readers. Each case is a
// reproducer from the issue; every one must end in a one-line error that names the file and
// the place, with the mesh being read into left as it was.
#include <gtest/gtest.h>

#include <string>

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

}  // namespace
