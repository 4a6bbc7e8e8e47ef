// No file of any format holds a non-finite coordinate: every writer refuses a mesh with one,
// naming the vertex, before writing a byte, and leaves an existing file as it was.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "io/io_support.hpp"

namespace {

using namespace hmira;
using hmira_test::read_bytes;
using hmira_test::scratch_dir;
using hmira_test::write_bytes;

template <class M>
class writer_non_finite : public ::testing::Test {};
using models = ::testing::Types<face_vertex_mesh, halfedge_mesh>;
TYPED_TEST_SUITE(writer_non_finite, models);

TYPED_TEST(writer_non_finite, every_writer_refuses_a_non_finite_coordinate_naming_the_vertex_and_writes_nothing) {
    using M = TypeParam;
    using T = default_traits<M>;
    for (const double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity()}) {
        M m;
        ASSERT_TRUE(generate_cube(m));
        auto v = *std::next(T::vertices(m).begin(), 5);
        T::set_position(m, v, {0.5, bad, 0.25});
        scratch_dir dir;
        long files = 0;
        for (const char* file : {"c.obj", "c.off", "c.ply", "c.stl"}) {
            SCOPED_TRACE(std::string(file) + " with " + std::to_string(bad));
            write_bytes(dir / file, "previous content");
            ++files;
            auto r = io::write_mesh(m, dir / file);
            ASSERT_FALSE(r);
            EXPECT_EQ(r.error().code, errc::unsupported) << r.error().message;
            EXPECT_EQ(r.error().element, 5);
            EXPECT_NE(r.error().message.find("vertex 5 has a coordinate that is not finite"), std::string::npos)
                << r.error().message;
            EXPECT_EQ(read_bytes(dir / file), "previous content");
            EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), files)
                << "a temporary was left";
        }
        std::ostringstream stream;
        for (const auto& to : {io::write_obj_to(m, stream), io::write_off_to(m, stream), io::write_ply_to(m, stream),
                               io::write_stl_to(m, stream)}) {
            ASSERT_FALSE(to);
            EXPECT_EQ(to.error().element, 5);
        }
        EXPECT_TRUE(stream.str().empty()) << "a refused writer wrote bytes";
        for (const auto& formatted : {io::format_obj(m), io::format_off(m), io::format_ply(m), io::format_stl(m)})
            EXPECT_FALSE(formatted);
    }
}

TYPED_TEST(writer_non_finite, float_files_refuse_a_coordinate_beyond_float_range_naming_the_vertex) {
    using M = TypeParam;
    using T = default_traits<M>;
    M m;
    ASSERT_TRUE(generate_tetrahedron(m));
    auto v = *std::next(T::vertices(m).begin(), 2);
    T::set_position(m, v, {0, 1e39, 0});
    scratch_dir dir;
    for (const auto& [file, options] : {std::pair<const char*, io::write_options>{"f.stl", {}},
                                        {"f.ply", {.ply_coordinates = io::ply_scalar::float32}}}) {
        SCOPED_TRACE(file);
        auto r = io::write_mesh(m, dir / file, options);
        ASSERT_FALSE(r);
        EXPECT_EQ(r.error().code, errc::unsupported);
        EXPECT_EQ(r.error().element, 2);
        EXPECT_NE(r.error().message.find((dir / file).string() + ": "), std::string::npos) << r.error().message;
        EXPECT_NE(r.error().message.find("vertex 2 has a coordinate (1e+39) beyond the range of float"),
                  std::string::npos)
            << r.error().message;
        EXPECT_FALSE(std::filesystem::exists(dir / file));
    }
    // Double coordinates hold it: the default PLY, OBJ and OFF write it.
    for (const char* file : {"d.ply", "d.obj", "d.off"}) EXPECT_TRUE(io::write_mesh(m, dir / file)) << file;
}

TYPED_TEST(writer_non_finite, the_largest_finite_coordinates_are_written_and_read_back_exactly) {
    using M = TypeParam;
    using T = default_traits<M>;
    M m;
    ASSERT_TRUE(generate_tetrahedron(m));
    const double big = std::numeric_limits<double>::max();
    auto v = *T::vertices(m).begin();
    T::set_position(m, v, {big, -big, std::numeric_limits<double>::denorm_min()});
    scratch_dir dir;
    for (const char* file : {"t.obj", "t.off", "t.ply"}) {
        SCOPED_TRACE(file);
        ASSERT_TRUE(io::write_mesh(m, dir / file));
        M back;
        ASSERT_TRUE(io::read_mesh(back, dir / file));
        const auto p = T::position(back, *T::vertices(back).begin());
        EXPECT_EQ(p[0], big);
        EXPECT_EQ(p[1], -big);
        EXPECT_EQ(p[2], std::numeric_limits<double>::denorm_min());
    }
}

}  // namespace
