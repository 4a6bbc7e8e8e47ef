// Bad input: every malformed file is rejected with one clear message that says where
// (file:line for text, byte offset and element for binary), the mesh being read into keeps
// its content, and a conversion that stops there leaves no output file behind.
#include <gtest/gtest.h>

#include <cstring>

#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "io/io_support.hpp"
#include "support/checks.hpp"
#include "support/shapes.hpp"

namespace {

using namespace hmira;
using hmira_test::scratch_dir;

struct bad_case {
    const char* what;
    const char* file;  // name inside the scratch folder
    std::string content;
    std::vector<std::string> message_parts;  // each must appear in the message
};

/// Reads `c` into a mesh that already holds a tetrahedron, as `hmira convert` would, and
/// checks the error, the untouched mesh and the missing output.
void expect_rejected(const bad_case& c) {
    SCOPED_TRACE(c.what);
    scratch_dir dir;
    const auto in = dir / c.file;
    hmira_test::write_bytes(in, c.content);
    const auto out = dir / "out.off";
    for (int model = 0; model < 2; ++model) {
        auto check = [&](auto& mesh) {
            ASSERT_TRUE(generate_tetrahedron(mesh));
            const auto before = hmira_test::canonical_faces(mesh);
            const auto before_points = hmira_test::positions(mesh);
            auto r = io::read_mesh(mesh, in);
            ASSERT_FALSE(r) << "accepted";
            if (r) return;
            const auto& msg = r.error().message;
            EXPECT_EQ(msg.find('\n'), std::string::npos) << "one line: " << msg;
            EXPECT_NE(msg.find(in.string()), std::string::npos) << msg;
            for (const auto& part : c.message_parts)
                EXPECT_NE(msg.find(part), std::string::npos) << "'" << part << "' not in: " << msg;
            EXPECT_EQ(hmira_test::canonical_faces(mesh), before);
            EXPECT_EQ(hmira_test::positions(mesh), before_points);
            if (r) (void)io::write_mesh(mesh, out);  // what convert does only on success
        };
        if (model == 0) {
            face_vertex_mesh m;
            check(m);
        } else {
            halfedge_mesh m;
            check(m);
        }
    }
    EXPECT_FALSE(std::filesystem::exists(out));
    EXPECT_EQ(dir.files(), std::vector<std::string>{c.file});
    // The soup reader gives the same verdict.
    EXPECT_FALSE(io::read_soup(in));
}

std::string off_cube() {
    face_vertex_mesh m;
    (void)generate_cube(m);
    return io::format_off(m).value();
}

std::string binary_ply_cube(io::ply_encoding e = io::ply_encoding::binary_little_endian) {
    face_vertex_mesh m;
    (void)generate_cube(m);
    return io::format_ply(m, {.ply = e, .ply_coordinates = io::ply_scalar::float32}).value();
}

std::string binary_stl_tetra() {
    face_vertex_mesh m;
    (void)generate_tetrahedron(m);
    return io::format_stl(m).value();
}

const std::string ply_ascii_head =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face "
    "1\nproperty list uchar int vertex_indices\nend_header\n";
const std::string tri_obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
const std::string stl_facet =
    "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n endloop\nendfacet\n";

// ---- truncated files --------------------------------------------------------------------------
TEST(io_bad_input, truncated_off_names_the_line_and_the_missing_vertices) {
    auto text = off_cube();
    std::size_t cut = 0;
    for (int line = 0; line < 3; ++line) cut = text.find('\n', cut) + 1;  // "OFF", counts, one vertex
    text.resize(cut);
    expect_rejected({"truncated off", "t.off", text, {"t.off:4", "file ends after 1 of 8 vertices"}});
}

TEST(io_bad_input, truncated_binary_ply_names_the_byte_offset_and_element) {
    auto bytes = binary_ply_cube();
    bytes.resize(bytes.size() - 5);
    expect_rejected({"truncated ply", "t.ply", bytes, {"byte offset", "file ends inside face 5 of 6"}});
    auto bytes2 = binary_ply_cube();
    bytes2.resize(bytes2.find("end_header\n") + 11 + 40);  // inside the vertices
    expect_rejected({"truncated ply vertices", "v.ply", bytes2, {"byte offset", "vertex 3 of 8"}});
}

TEST(io_bad_input, truncated_ascii_stl_and_ply_name_the_line) {
    expect_rejected({"truncated stl",
                     "t.stl",
                     "solid x\n" + stl_facet + "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n",
                     {"t.stl:", "truncated"}});
    expect_rejected({"truncated ascii ply",
                     "t.ply",
                     ply_ascii_head + "0 0 0\n1 0 0\n",
                     {"t.ply:12", "file ends after 2 of 3 vertex"}});
}

TEST(io_bad_input, truncated_binary_stl_reports_the_size_mismatch) {
    auto bytes = binary_stl_tetra();
    bytes.resize(bytes.size() - 20);
    expect_rejected({"short stl", "s.stl", bytes, {"byte offset 80", "4 triangles", "284 bytes", "264"}});
}

// ---- wrong counts in the header ----------------------------------------------------------------
TEST(io_bad_input, off_counts_that_do_not_match_the_content_are_reported) {
    auto text = off_cube();
    auto too_small = text;
    too_small.replace(too_small.find("8 6"), 3, "8 5");
    expect_rejected(
        {"off count too small", "s.off", too_small, {"s.off:16", "unexpected content after the last face"}});
    auto too_large = text;
    too_large.replace(too_large.find("8 6"), 3, "8 7");
    expect_rejected({"off count too large", "l.off", too_large, {"file ends after 6 of 7 faces"}});
}

TEST(io_bad_input, ply_counts_that_do_not_match_the_content_are_reported) {
    auto bytes = binary_ply_cube();
    bytes.replace(bytes.find("element face 6"), 14, "element face 5");
    expect_rejected({"ply count too small", "s.ply", bytes, {"byte offset", "bytes after the last element"}});
    auto ascii = ply_ascii_head + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    ascii.replace(ascii.find("face 1"), 6, "face 2");
    expect_rejected({"ascii ply count too large", "l.ply", ascii, {"file ends after 1 of 2 face"}});
}

// ---- out-of-range and zero indices -------------------------------------------------------------
TEST(io_bad_input, out_of_range_and_zero_indices_are_rejected_with_their_line) {
    expect_rejected(
        {"obj index too large", "a.obj", tri_obj + "f 1 2 4\n", {"a.obj:4", "vertex index 4 is out of range"}});
    expect_rejected(
        {"obj negative too far", "b.obj", tri_obj + "f -1 -2 -4\n", {"b.obj:4", "vertex index -4 is out of range"}});
    expect_rejected({"obj zero index", "c.obj", tri_obj + "f 0 1 2\n", {"c.obj:4", "vertex index 0"}});
    expect_rejected({"off index",
                     "d.off",
                     "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
                     {"d.off:6", "uses vertex 3, out of range [0, 3)"}});
    expect_rejected(
        {"off negative index", "e.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", {"e.off:6", "uses vertex -1"}});
    expect_rejected(
        {"ascii ply index", "f.ply", ply_ascii_head + "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", {"f.ply:13", "uses vertex 7"}});
    auto bytes = binary_ply_cube();
    const auto at = bytes.size() - 4;  // last index of the last face
    const std::int32_t bad = 99;
    std::memcpy(bytes.data() + at, &bad, 4);
    expect_rejected(
        {"binary ply index", "g.ply", bytes, {"byte offset " + std::to_string(at), "face 5 uses vertex 99"}});
}

// ---- non-numbers -------------------------------------------------------------------------------
TEST(io_bad_input, non_numbers_are_quoted_with_their_line) {
    expect_rejected({"obj coordinate", "a.obj", "v 0 0 0\nv 1 x 0\n", {"a.obj:2", "'x' is not a number"}});
    expect_rejected({"obj index", "b.obj", tri_obj + "f 1 2 three\n", {"b.obj:4", "'three' is not a vertex index"}});
    expect_rejected({"off coordinate",
                     "c.off",
                     "OFF\n3 1 0\n0 0 0\n1 0 0,5 0\n0 1 0\n3 0 1 2\n",
                     {"c.off:4", "'0,5' is not a number"}});
    expect_rejected({"off counts", "d.off", "OFF\nthree 1 0\n", {"d.off:2", "'three' is not a number"}});
    expect_rejected({"ply value",
                     "e.ply",
                     ply_ascii_head + "0 0 0\n1 nan? 0\n0 1 0\n3 0 1 2\n",
                     {"e.ply:11", "'nan?' is not a number"}});
    expect_rejected({"stl vertex",
                     "f.stl",
                     "solid x\nfacet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 zero\n",
                     {"f.stl:5", "'zero' is not a number"}});
}

// ---- faces with fewer than 3 vertices ------------------------------------------------------------
TEST(io_bad_input, faces_with_fewer_than_three_vertices_are_rejected) {
    expect_rejected({"obj", "a.obj", tri_obj + "f 1 2\n", {"a.obj:4", "at least 3 vertices, got 2"}});
    expect_rejected({"off", "b.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", {"b.off:6", "face 0 has 2 vertices"}});
    expect_rejected(
        {"ascii ply", "c.ply", ply_ascii_head + "0 0 0\n1 0 0\n0 1 0\n2 0 1\n", {"c.ply:13", "face 0 has 2 vertices"}});
    auto bytes = binary_ply_cube();
    const auto faces_at = bytes.size() - 6 * 17;
    bytes[faces_at + 17] = 2;  // face 1 claims 2 corners
    expect_rejected(
        {"binary ply", "d.ply", bytes, {"byte offset " + std::to_string(faces_at + 17), "face 1 has 2 vertices"}});
    expect_rejected(
        {"stl",
         "e.stl",
         "solid x\nfacet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n endloop\nendfacet\nendsolid\n",
         {"e.stl:6", "has 2 vertices"}});
}

// ---- not a file --------------------------------------------------------------------------------
TEST(io_bad_input, a_directory_or_missing_file_is_an_io_error) {
    scratch_dir dir;
    std::filesystem::create_directory(dir / "folder.off");
    face_vertex_mesh m;
    ASSERT_TRUE(generate_tetrahedron(m));
    auto r = io::read_mesh(m, dir / "folder.off");
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, errc::io_error);
    EXPECT_NE(r.error().message.find("is a directory"), std::string::npos) << r.error().message;
    auto missing = io::read_mesh(m, dir / "nope.ply");
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error().code, errc::io_error);
    EXPECT_NE(missing.error().message.find("No such file"), std::string::npos) << missing.error().message;
    EXPECT_EQ(m.face_count(), 4u);
}

TEST(io_bad_input, an_unknown_extension_is_refused_for_reading_and_writing) {
    scratch_dir dir;
    face_vertex_mesh m;
    ASSERT_TRUE(generate_tetrahedron(m));
    auto w = io::write_mesh(m, dir / "m.xyz");
    ASSERT_FALSE(w);
    EXPECT_EQ(w.error().code, errc::unknown_format);
    EXPECT_TRUE(dir.files().empty());
    EXPECT_FALSE(io::read_mesh(m, dir / "m.xyz"));
}

TEST(io_bad_input, a_failed_write_leaves_the_existing_file_and_no_temporary) {
    scratch_dir dir;
    face_vertex_mesh m;
    ASSERT_TRUE(generate_tetrahedron(m));
    std::filesystem::create_directory(dir / "taken.off");
    EXPECT_FALSE(io::write_mesh(m, dir / "taken.off"));
    EXPECT_FALSE(io::write_mesh(m, dir / "no-such-folder" / "m.off"));
    EXPECT_EQ(dir.files(), std::vector<std::string>{"taken.off"});
}

TEST(io_bad_input, faces_the_mesh_rejects_leave_it_unchanged_and_are_named) {
    // Three triangles on one edge: a face-vertex mesh takes it, a halfedge mesh cannot.
    const std::string text = "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n";
    scratch_dir dir;
    hmira_test::write_bytes(dir / "nm.off", text);
    face_vertex_mesh fv;
    EXPECT_TRUE(io::read_mesh(fv, dir / "nm.off"));
    halfedge_mesh he;
    ASSERT_TRUE(generate_cube(he));
    // Without repair the file is refused, naming the face; by default it is repaired.
    auto r = io::read_mesh(he, dir / "nm.off", {.repair = false});
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().message.find("nm.off: face 2 "), std::string::npos) << r.error().message;
    EXPECT_EQ(he.face_count(), 6u);
    auto repaired = io::read_mesh(he, dir / "nm.off");
    ASSERT_TRUE(repaired) << repaired.error().message;
    EXPECT_EQ(he.face_count(), 3u);
    EXPECT_EQ(repaired->repair.nonmanifold_edge_faces.first, std::vector<std::size_t>{2});
}

TEST(io_bad_input, garbage_headers_are_named) {
    expect_rejected({"not off", "a.off", "OFX\n", {"a.off:1", "expected an 'OFF' header"}});
    expect_rejected({"not ply", "b.ply", "plx\n", {"b.ply:1", "not a PLY file"}});
    expect_rejected({"ply without end", "c.ply", "ply\nformat ascii 1.0\nelement vertex 1\n", {"no 'end_header'"}});
    expect_rejected({"empty stl", "d.stl", "", {"too short for a binary STL"}});
}

}  // namespace
