// Real meshes from Debian's libcgal-demo (scripts/test-data.sh puts them in HMIRA_TEST_DATA):
// they read into every model, and what is read survives a round trip through each format.
#include <gtest/gtest.h>

#include <cstdlib>

#include <hmira/algorithms/topology/mesh_topology.hpp>
#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "io/io_support.hpp"
#include "support/checks.hpp"

namespace {

using namespace hmira;

std::filesystem::path data_dir() {
    const char* d = std::getenv("HMIRA_TEST_DATA");
    return d ? std::filesystem::path(d) / "meshes" : std::filesystem::path();
}

TEST(io_real_meshes, cgal_demo_meshes_read_with_the_counts_their_headers_give) {
    const auto dir = data_dir();
    if (dir.empty() || !std::filesystem::exists(dir / "elephant.off")) GTEST_SKIP() << "run scripts/test-data.sh first";
    for (const char* name :
         {"elephant.off", "fandisk.off", "cube_quad.off", "colored_tetra.ply", "sphere.ply", "sphere.stl", "pig.stl"}) {
        SCOPED_TRACE(name);
        if (!std::filesystem::exists(dir / name)) continue;
        face_vertex_mesh m;
        auto r = io::read_mesh(m, dir / name);
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_GT(m.face_count(), 0u);
        const std::string ext = std::filesystem::path(name).extension().string();
        if (ext == ".off") {
            // Counts straight from the header line, parsed here.
            const auto text = hmira_test::read_bytes(dir / name);
            std::size_t v = 0, f = 0;
            const auto nl = text.find('\n');
            ASSERT_EQ(std::sscanf(text.c_str() + nl + 1, "%zu %zu", &v, &f), 2);
            EXPECT_EQ(m.vertex_count(), v);
            EXPECT_EQ(m.face_count(), f);
        }
        for (const char* out : {"x.obj", "x.off", "x.ply"}) {
            hmira_test::scratch_dir scratch;
            ASSERT_TRUE(io::write_mesh(m, scratch / out));
            face_vertex_mesh back;
            ASSERT_TRUE(io::read_mesh(back, scratch / out));
            EXPECT_EQ(hmira_test::canonical_faces(back), hmira_test::canonical_faces(m)) << out;
            EXPECT_EQ(hmira_test::positions(back), hmira_test::positions(m)) << out;
        }
    }
}

TEST(io_real_meshes, colored_tetra_keeps_its_colours) {
    const auto path = data_dir() / "colored_tetra.ply";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "run scripts/test-data.sh first";
    face_vertex_mesh m;
    auto r = io::read_mesh(m, path);
    ASSERT_TRUE(r) << r.error().message;
    const auto text = hmira_test::read_bytes(path);
    if (text.find("property uchar red") != std::string::npos) {
        EXPECT_EQ(r->attributes.colors.size(), m.vertex_count());
    }
}

TEST(io_real_meshes, stl_spheres_weld_into_closed_meshes) {
    const auto path = data_dir() / "sphere.stl";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "run scripts/test-data.sh first";
    halfedge_mesh m;
    auto r = io::read_mesh(m, path);
    ASSERT_TRUE(r) << r.error().message;
    const auto t = mesh_topology(m);
    EXPECT_TRUE(t.closed());
    EXPECT_EQ(t.genus, 0);
    EXPECT_EQ(t.components, 1u);
}

}  // namespace
