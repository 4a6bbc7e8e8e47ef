// `hmira triangulate` on one big concave face: a comb of 10,000 trapezoid teeth (1 wide at the
// base, 0.5 at the tip, 10 high) on a bar, 40,003 corners in one OFF face, once refused as "too
// intricate ... work limit". It must come out as 40,001 triangles, a valid mesh with every
// triangle facing the face's way and the face's area exactly.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include <hmira/algorithms/validation/validate.hpp>
#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

#include "io/io_support.hpp"
#include "support/cli_runner.hpp"

namespace {

using hmira_test::scratch_dir;

hmira_test::run_result hmira(const scratch_dir& dir, const std::string& args) {
    return hmira_test::run_cli(HMIRA_CLI, dir, args);
}

/// The comb as OFF, counter-clockwise seen from +z; its area is 20,000 for the bar plus 75,000 for the teeth.
std::string comb_off(std::size_t teeth, double& area) {
    std::string v, f = std::to_string(4 * teeth + 3);
    std::size_t n = 0;
    char line[96];
    auto add = [&](double x, double y) {
        std::snprintf(line, sizeof line, "%.17g %.17g 0\n", x, y);
        v += line;
        f += " " + std::to_string(n++);
    };
    const double width = 2.0 * double(teeth);
    add(0, -1);
    add(width, -1);
    add(width, 0);
    for (std::size_t k = teeth; k-- > 0;) {
        const double x = 2.0 * double(k);
        add(x + 1, 0);
        add(x + 0.75, 10);
        add(x + 0.25, 10);
        add(x, 0);
    }
    area = width * 1 + double(teeth) * (1 + 0.5) / 2 * 10;
    return "OFF\n" + std::to_string(n) + " 1 0\n" + v + f + "\n";
}

TEST(cli_triangulate, a_comb_of_forty_thousand_corners_becomes_forty_thousand_and_one_triangles) {
    scratch_dir dir;
    double area = 0;
    hmira_test::write_bytes(dir / "comb.off", comb_off(10000, area));
    const auto r = hmira(dir, "triangulate comb.off out.off");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("cut 1 face into 40001 triangles"), std::string::npos) << r.out;
    hmira::face_vertex_mesh m;
    ASSERT_TRUE(hmira::io::read_mesh(m, dir / "out.off"));
    EXPECT_EQ(m.vertex_count(), 40003u);
    ASSERT_EQ(m.face_count(), 40001u);
    EXPECT_TRUE(hmira::validate(m).empty());
    double sum = 0;
    for (auto f : m.faces()) {
        const auto vs = m.face_vertices(f);
        ASSERT_EQ(vs.size(), 3u);
        const auto p = m.position(vs[0]), q = m.position(vs[1]), s = m.position(vs[2]);
        const double z = (q.x - p.x) * (s.y - p.y) - (q.y - p.y) * (s.x - p.x);  // exact: quarters below 2^15
        ASSERT_GT(z, 0) << "a triangle faces away or has no area";
        sum += z / 2;
    }
    EXPECT_EQ(sum, area);
}

}  // namespace
