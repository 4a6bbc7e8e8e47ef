// `hmira bevel` end to end on files the reader repairs for editing: `--edge A,B` names the
// file's vertices, so it selects every edge joining a copy of A to a copy of B (repair cuts a
// face free from a non-manifold edge, or splits a pinched vertex, by copying vertices); and
// boundary edges bevel, with the strip in their one face.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

#include "io/io_support.hpp"
#include "support/cli_runner.hpp"

namespace {

using hmira_test::scratch_dir;

hmira_test::run_result hmira(const scratch_dir& dir, const std::string& args) {
    return hmira_test::run_cli(HMIRA_CLI, dir, args);
}

hmira::face_vertex_mesh read_back(const std::filesystem::path& p) {
    hmira::face_vertex_mesh m;
    auto r = hmira::io::read_mesh(m, p);
    EXPECT_TRUE(r) << p << ": " << (r ? std::string() : r.error().message);
    return m;
}

TEST(cli_bevel, an_edge_named_by_the_files_vertices_selects_every_copy_the_repair_made) {
    scratch_dir dir;
    // Three triangles on the edge 0-1: repair cuts the third face free with copies 5, 6 of
    // vertices 0, 1. The file's edge 0,1 is then two edges: 0-1 between the first two faces
    // (interior) and 5-6, the boundary of the lone triangle.
    hmira_test::write_bytes(dir / "fin.off",
                            "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n");
    for (const std::string edge : {"0,1", "1,0"}) {
        SCOPED_TRACE(edge);
        const auto r = hmira(dir, "bevel fin.off b.off --edge " + edge + " --width 0.1");
        ASSERT_EQ(r.code, 0) << r.err;
        EXPECT_NE(r.out.find("fin.off: repaired for editing"), std::string::npos) << r.out;
        EXPECT_NE(r.out.find("bevelled 2 edges"), std::string::npos) << r.out;
        // 0-1: both ends (degree 3, on the boundary) go, each for two slid points: V + 2,
        // E + 3, F + 1. 5-6: a boundary edge whose ends stay: V + 2, E + 3, F + 1. From the
        // repaired 7 vertices, 8 edges, 3 faces.
        EXPECT_NE(r.out.find("V 7 -> 11, E 8 -> 14, F 3 -> 5"), std::string::npos) << r.out;
        const auto m = read_back(dir / "b.off");
        EXPECT_EQ(m.vertex_count(), 11u);
        EXPECT_EQ(m.face_count(), 5u);
    }
}

TEST(cli_bevel, an_edge_at_a_split_vertex_is_found_on_whichever_copy_holds_it) {
    scratch_dir dir;
    // Two triangles pinched at vertex 0 (a bowtie): repair splits 0 into two copies, one per
    // fan, so the edges 0,1 and 0,3 leave different copies. Both are boundary edges of their
    // triangle: V + 2, E + 3, F + 1 each.
    hmira_test::write_bytes(dir / "bowtie.off", "OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n-1 0 0\n-1 -1 0\n3 0 1 2\n3 0 3 4\n");
    for (const std::string edge : {"0,1", "0,3", "3,0"}) {
        SCOPED_TRACE(edge);
        const auto r = hmira(dir, "bevel bowtie.off b.off --edge " + edge + " --width 0.1");
        ASSERT_EQ(r.code, 0) << r.err;
        EXPECT_NE(r.out.find("bevelled 1 edge"), std::string::npos) << r.out;
        EXPECT_NE(r.out.find("V 6 -> 8, E 6 -> 9, F 2 -> 3"), std::string::npos) << r.out;
    }
    // Both at once, and an edge that does not exist on any copy.
    const auto both = hmira(dir, "bevel bowtie.off b.off --edge 0,1 --edge 3,0 --width 0.1");
    ASSERT_EQ(both.code, 0) << both.err;
    EXPECT_NE(both.out.find("V 6 -> 10, E 6 -> 12, F 2 -> 4"), std::string::npos) << both.out;
    const auto none = hmira(dir, "bevel bowtie.off n.off --edge 1,3 --width 0.1");
    EXPECT_EQ(none.code, 2) << none.err;
    EXPECT_NE(none.err.find("--edge 1,3: vertices 1 and 3 of bowtie.off are not joined by an edge"), std::string::npos)
        << none.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "n.off"));
    // A copy's index is not a file vertex.
    const auto copy = hmira(dir, "bevel bowtie.off n.off --edge 5,1 --width 0.1");
    EXPECT_EQ(copy.code, 2) << copy.err;
    EXPECT_NE(copy.err.find("--edge 5,1"), std::string::npos) << copy.err;
}

TEST(cli_bevel, a_boundary_edge_bevels_inside_its_one_face) {
    scratch_dir dir;
    // A unit square of two triangles; its side 0-1 bevels into a strip 0.25 wide inside the
    // first triangle: V + 2, E + 3, F + 1.
    hmira_test::write_bytes(dir / "square.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n");
    const auto r = hmira(dir, "bevel square.off b.off --edge 0,1 --width 0.25");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("V 4 -> 6, E 5 -> 8, F 2 -> 3"), std::string::npos) << r.out;
    const auto m = read_back(dir / "b.off");
    EXPECT_EQ(m.face_count(), 3u);
}

TEST(cli_bevel, sharp_edges_of_real_meshes_bevel_to_a_mesh_that_validates) {
    // --angle 40 --width 0.001: the clamp shrinks the width on short edges down to where points
    // from both ends of an edge meet, which left faces of zero area. Edges that would leave one
    // are skipped and counted; every output validates, as its input does.
    const char* data = std::getenv("HMIRA_TEST_DATA");
    if (!data || !std::filesystem::exists(std::filesystem::path(data) / "meshes" / "man.off"))
        GTEST_SKIP() << "run scripts/test-data.sh first";
    scratch_dir dir;
    for (const std::string name : {"man", "bull", "cheese"}) {
        SCOPED_TRACE(name);
        const auto in = std::filesystem::absolute(std::filesystem::path(data) / "meshes" / (name + ".off"));
        ASSERT_EQ(hmira(dir, "validate '" + in.string() + "'").code, 0) << "the input validates";
        const auto b = hmira(dir, "bevel '" + in.string() + "' " + name + ".off --angle 40 --width 0.001");
        ASSERT_EQ(b.code, 0) << b.err;
        EXPECT_NE(b.out.find("bevelled "), std::string::npos) << b.out;
        EXPECT_NE(b.out.find("whose strip would leave a face of zero area"), std::string::npos) << b.out;
        const auto v = hmira(dir, "validate " + name + ".off");
        EXPECT_EQ(v.code, 0) << v.out << v.err;
        EXPECT_EQ(v.out.find("zero area"), std::string::npos) << v.out;
    }
}

}  // namespace
