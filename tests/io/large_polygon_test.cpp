// A face with very many corners reads in O(k log k). The guard is the ctest TIMEOUT on this
// binary (about 10x the expected time), not a timed assertion: a pairwise check for repeated
// corners, O(k^2), would take many seconds on the 400k-gon and exceed it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

#include "io/io_support.hpp"

namespace {

using namespace hmira;

/// OBJ text of one k-gon on the unit circle; `repeat_last` makes the last corner repeat the
/// middle one.
std::string k_gon_obj(std::size_t k, bool repeat_last) {
    std::string text;
    text.reserve(k * 40);
    for (std::size_t i = 0; i < k; ++i) {
        const double a = 2 * std::numbers::pi * double(i) / double(k);
        text += "v ";
        text += std::to_string(std::cos(a));
        text += ' ';
        text += std::to_string(std::sin(a));
        text += " 0\n";
    }
    text += "f";
    for (std::size_t i = 0; i < k; ++i) {
        text += ' ';
        text += std::to_string(repeat_last && i + 1 == k ? k / 2 + 1 : i + 1);
    }
    text += "\n";
    return text;
}

TEST(io_large_polygon, a_400k_gon_reads_into_a_face_vertex_mesh) {
    hmira_test::scratch_dir dir;
    const auto in = dir / "k.obj";
    constexpr std::size_t k = 400000;
    hmira_test::write_bytes(in, k_gon_obj(k, false));
    face_vertex_mesh m;
    auto r = io::read_mesh(m, in);
    ASSERT_TRUE(r) << r.error().message;
    ASSERT_EQ(m.face_count(), 1u);
    const auto corners = m.face_vertices(face_handle(0));
    ASSERT_EQ(corners.size(), k);
    for (std::size_t i = 0; i < k; i += 9973) EXPECT_EQ(corners[i].index, i);
}

TEST(io_large_polygon, a_repeated_corner_in_a_long_face_is_still_found) {
    hmira_test::scratch_dir dir;
    const auto in = dir / "rep.obj";
    hmira_test::write_bytes(in, k_gon_obj(1000, true));
    face_vertex_mesh m;
    auto r = io::read_mesh(m, in);
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().message.find("vertex 500 appears twice"), std::string::npos) << r.error().message;
    EXPECT_EQ(m.face_count(), 0u);
    // and through add_face directly, short and long faces alike, leaving the mesh unchanged
    face_vertex_mesh direct;
    std::vector<vertex_handle> vs;
    for (int i = 0; i < 40; ++i) vs.push_back(direct.add_vertex({double(i), 0, 0}));
    for (std::size_t n : {4u, 16u, 17u, 40u}) {
        std::vector<vertex_handle> face(vs.begin(), vs.begin() + static_cast<long>(n));
        face.back() = face.front();
        const auto faces_before = direct.face_count();
        auto f = direct.add_face(face);
        ASSERT_FALSE(f) << n;
        EXPECT_EQ(f.error().code, errc::degenerate_face);
        EXPECT_EQ(direct.face_count(), faces_before);
        face.back() = vs[n - 1];
        EXPECT_TRUE(direct.add_face(face)) << n;
    }
    EXPECT_EQ(direct.face_count(), 4u);
}

}  // namespace
