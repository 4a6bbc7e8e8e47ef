// mesh_boolean on closed meshes of the test data (HMIRA_TEST_DATA): each mesh against a rotated and
// translated copy of itself and of the next one, under union, intersection and difference. Checked
// independently of the arrangement: the volume identity vol(A u B) + vol(A n B) = vol(A) + vol(B)
// and vol(A - B) = vol(A) - vol(A n B), closedness (every directed edge has its reverse), and
// self_intersections() of each result against the count of rounding intersections in the report.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>

#include <hmira/algorithms/boolean/mesh_boolean.hpp>
#include <hmira/algorithms/validation/self_intersections.hpp>
#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

#include "algorithms/boolean/boolean_support.hpp"
#include "support/checks.hpp"

namespace {

using namespace hmira;
using mesh = hmira::face_vertex_mesh;
using tr = default_traits<mesh>;

using box3 = std::array<std::array<double, 3>, 2>;

box3 bounds(const mesh& m) {
    box3 b{{{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}}};
    for (auto v : tr::vertices(m)) {
        const auto p = tr::position(m, v);
        for (std::size_t k = 0; k < 3; ++k)
            b[0][k] = std::min(b[0][k], double(p[k])), b[1][k] = std::max(b[1][k], double(p[k]));
    }
    return b;
}

double diagonal(const box3& b) { return std::hypot(b[1][0] - b[0][0], b[1][1] - b[0][1], b[1][2] - b[0][2]); }

/// m rotated by a fixed rotation about its bounding box's centre, scaled to the size of the box
/// `to` and placed at its centre moved by `shift` times its extent, so that it crosses a
/// mesh with that box in general position.
/// The rotation is the quaternion (w, x, y, z), normalised.
mesh moved(const mesh& m, const box3& to, double shift, std::array<double, 4> quaternion = {0.9, 0.21, -0.3, 0.17}) {
    const auto [w, x, y, z] = quaternion;
    const double n = std::sqrt(w * w + x * x + y * y + z * z);
    const double q[4] = {w / n, x / n, y / n, z / n};
    const double r[3][3] = {
        {1 - 2 * (q[2] * q[2] + q[3] * q[3]), 2 * (q[1] * q[2] - q[3] * q[0]), 2 * (q[1] * q[3] + q[2] * q[0])},
        {2 * (q[1] * q[2] + q[3] * q[0]), 1 - 2 * (q[1] * q[1] + q[3] * q[3]), 2 * (q[2] * q[3] - q[1] * q[0])},
        {2 * (q[1] * q[3] - q[2] * q[0]), 2 * (q[2] * q[3] + q[1] * q[0]), 1 - 2 * (q[1] * q[1] + q[2] * q[2])}};
    const box3 from = bounds(m);
    const double scale = diagonal(to) / diagonal(from);
    io::polygon_soup s;
    for (auto v : tr::vertices(m)) {
        const auto p = tr::position(m, v);
        std::array<double, 3> d{};
        for (std::size_t k = 0; k < 3; ++k) d[k] = (double(p[k]) - 0.5 * (from[0][k] + from[1][k])) * scale;
        std::array<double, 3> o{};
        for (std::size_t k = 0; k < 3; ++k)
            o[k] = 0.5 * (to[0][k] + to[1][k]) + r[k][0] * d[0] + r[k][1] * d[1] + r[k][2] * d[2] +
                   shift * (to[1][k] - to[0][k]) * (1.0 + 0.1 * double(k));
        s.points.push_back(o);
    }
    for (auto f : tr::faces(m)) {
        for (auto v : tr::face_vertices(m, f)) s.indices.push_back(std::uint32_t(tr::vertex_index(m, v)));
        s.face_offsets.push_back(s.indices.size());
    }
    mesh out;
    EXPECT_TRUE(bool(detail::copy::build<mesh, tr>(out, s)));
    return out;
}

using hmira_test::closed;

/// The closed, self-intersection-free meshes of the test data used here, smallest first, each
/// small enough that the whole test stays short under the sanitizers.
const char* const names[] = {"colored_tetra.ply", "cube.off", "icosahedron.off", "hole.off", "cross.off"};

std::filesystem::path data_dir() {
    const char* dir = std::getenv("HMIRA_TEST_DATA");
    return dir ? std::filesystem::path(dir) / "meshes" : std::filesystem::path();
}

/// op(a, b) for the three operations, checked against each other and the input volumes; when
/// `crossing`, the surfaces must cross.
void check_pair(const mesh& a, const mesh& b, bool crossing) {
    const double va = hmira_test::signed_volume(a), vb = hmira_test::signed_volume(b);
    double vol[3] = {0, 0, 0};
    std::size_t cut = 0;
    const boolean_op ops[3] = {boolean_op::union_, boolean_op::intersection, boolean_op::difference};
    for (int k = 0; k < 3; ++k) {
        SCOPED_TRACE(k == 0 ? "union" : (k == 1 ? "intersection" : "difference"));
        mesh out;
        auto r = mesh_boolean(out, a, b, {.op = ops[k]});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(closed(out));
        auto si = self_intersections(out);
        ASSERT_TRUE(si);
        EXPECT_TRUE(si->empty() || si->size() == r->rounding_intersections) << si->size();
        vol[k] = hmira_test::signed_volume(out);
        cut = r->cut_triangles;
    }
    const double scale = va + vb;
    EXPECT_NEAR(vol[0] + vol[1], va + vb, 1e-9 * scale);
    EXPECT_NEAR(vol[2], va - vol[1], 1e-9 * scale);
    if (crossing) {
        EXPECT_GT(cut, 0u);  // the surfaces cross: the arrangement was exercised
    }
}

TEST(mesh_boolean_real_meshes, each_mesh_against_moved_copies_of_itself_and_the_next) {
    const auto dir = data_dir();
    if (dir.empty() || !std::filesystem::exists(dir / names[0])) GTEST_SKIP() << "HMIRA_TEST_DATA not set";
    std::vector<mesh> meshes;
    for (const char* name : names) {
        mesh m;
        auto r = io::read_mesh(m, dir / name);
        ASSERT_TRUE(r) << name << ": " << r.error().message;
        ASSERT_TRUE(closed(m)) << name;
        auto si = self_intersections(m);
        ASSERT_TRUE(si && si->empty()) << name;
        meshes.push_back(std::move(m));
    }
    for (std::size_t i = 0; i < meshes.size(); ++i) {
        SCOPED_TRACE(names[i]);
        {
            SCOPED_TRACE("against itself");
            check_pair(meshes[i], moved(meshes[i], bounds(meshes[i]), 0.15), true);
        }
        const std::size_t j = (i + 1) % meshes.size();
        SCOPED_TRACE(std::string("against ") + names[j]);
        check_pair(meshes[i], moved(meshes[j], bounds(meshes[i]), 0.2), false);
    }
}

/// name against a copy rotated by the quaternion q and moved by `shift`, both read from the test data.
void check_moved_copy(const char* name, std::array<double, 4> q, double shift) {
    const auto dir = data_dir();
    if (dir.empty() || !std::filesystem::exists(dir / name)) GTEST_SKIP() << "HMIRA_TEST_DATA not set";
    mesh m;
    ASSERT_TRUE(io::read_mesh(m, dir / name));
    check_pair(m, moved(m, bounds(m), shift, q), true);
}

// In these two, a cut inserted into a triangle crosses a strip of triangles whose outline passes
// one vertex twice, or encloses a vertex whose triangles the cut all crosses.
TEST(mesh_boolean_real_meshes, mpi_triang_against_a_rotated_copy) {
    check_moved_copy("mpi_triang.off",
                     {-0.38683176162103994, -0.039399956754155308, 0.68682363917932543, -0.24894784633514505},
                     0.2353760662451162);
}

TEST(mesh_boolean_real_meshes, anchor_against_a_rotated_copy) {
    check_moved_copy("anchor.off",
                     {0.031051152150535638, -1.7340822205750985, -2.3271919942491852, -0.12280543689105411},
                     0.25695500502311425);
}

}  // namespace
