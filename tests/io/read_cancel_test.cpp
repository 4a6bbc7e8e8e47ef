// Reading is cancellable: every reader reports its progress to read_options::progress, and a
// progress function that returns false stops it with errc::cancelled and the mesh it was
// reading into unchanged.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/generators/torus.hpp>
#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "io/io_support.hpp"
#include "support/snapshot.hpp"

namespace {

using namespace hmira;
using hmira_test::scratch_dir;

struct format_case {
    std::string file;
    io::write_options options;
};

std::vector<format_case> every_format() {
    return {{"t.obj", {}},
            {"t.off", {}},
            {"t_ascii.ply", {.ply = io::ply_encoding::ascii}},
            {"t_le.ply", {.ply = io::ply_encoding::binary_little_endian}},
            {"t_be.ply", {.ply = io::ply_encoding::binary_big_endian}},
            {"t_ascii.stl", {.stl = io::stl_encoding::ascii}},
            {"t_binary.stl", {.stl = io::stl_encoding::binary}}};
}

TEST(read_cancel, a_progress_function_that_says_stop_cancels_every_reader_and_leaves_the_mesh_unchanged) {
    scratch_dir dir;
    halfedge_mesh torus;
    ASSERT_TRUE(generate_torus(torus));
    for (const auto& c : every_format()) {
        SCOPED_TRACE(c.file);
        ASSERT_TRUE(io::write_mesh(torus, dir / c.file, c.options));
        halfedge_mesh m;
        ASSERT_TRUE(generate_cube(m));
        const auto before = hmira_test::snapshot(m);
        int calls = 0;
        auto r = io::read_mesh(m, dir / c.file, {.progress = [&](double) { return ++calls < 1; }});
        ASSERT_FALSE(r) << "the reader ignored the cancellation";
        EXPECT_EQ(r.error().code, errc::cancelled) << r.error().message;
        EXPECT_NE(r.error().message.find("cancelled"), std::string::npos) << r.error().message;
        EXPECT_NE(r.error().message.find(c.file), std::string::npos) << r.error().message;
        EXPECT_EQ(calls, 1) << "the reader went on reporting after it was cancelled";
        EXPECT_TRUE(hmira_test::snapshot(m) == before) << "the cancelled read changed the mesh";

        auto s = io::read_soup(dir / c.file, {.progress = [](double) { return false; }});
        ASSERT_FALSE(s);
        EXPECT_EQ(s.error().code, errc::cancelled);
    }
}

TEST(read_cancel, an_uncancelled_read_reports_rising_fractions_ending_at_one_and_reads_the_same_mesh) {
    scratch_dir dir;
    halfedge_mesh torus;
    ASSERT_TRUE(generate_torus(torus));
    for (const auto& c : every_format()) {
        SCOPED_TRACE(c.file);
        ASSERT_TRUE(io::write_mesh(torus, dir / c.file, c.options));
        std::vector<double> seen;
        halfedge_mesh with, without;
        ASSERT_TRUE(io::read_mesh(with, dir / c.file, {.progress = [&](double f) {
                                      seen.push_back(f);
                                      return true;
                                  }}));
        ASSERT_TRUE(io::read_mesh(without, dir / c.file));
        ASSERT_FALSE(seen.empty());
        EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
        EXPECT_GE(seen.front(), 0.0);
        EXPECT_EQ(seen.back(), 1.0);
        EXPECT_TRUE(hmira_test::snapshot(with) == hmira_test::snapshot(without));
    }
}

}  // namespace
