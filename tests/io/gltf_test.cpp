// glTF 2.0: what write_gltf writes (.glb and .gltf), read_gltf reads back as the same triangles
// and positions (float-exact); hand-built files check node transforms, strided views, byte and
// short indices and colours; hostile bytes give one-line errors naming what and where.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include <hmira/io/gltf.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "io/io_support.hpp"

namespace {

using namespace hmira;
using hmira_test::scratch_dir;

halfedge_mesh cube_of_quads() {
    halfedge_mesh m;
    const double p[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    std::vector<vertex_handle> v;
    for (auto& q : p) v.push_back(m.add_vertex({q[0], q[1], q[2]}));
    const int f[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    for (auto& q : f) EXPECT_TRUE(m.add_face({v[q[0]], v[q[1]], v[q[2]], v[q[3]]}));
    return m;
}

// The signed volume by the divergence theorem, computed here from the soup.
double volume(const io::polygon_soup& s) {
    double sum = 0;
    for (std::size_t f = 0; f < s.face_count(); ++f) {
        const auto& a = s.points[s.indices[s.face_offsets[f]]];
        const auto& b = s.points[s.indices[s.face_offsets[f] + 1]];
        const auto& c = s.points[s.indices[s.face_offsets[f] + 2]];
        sum += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
               a[2] * (b[0] * c[1] - b[1] * c[0]);
    }
    return sum / 6;
}

std::string glb_of(const std::string& json, const std::string& bin) {
    std::string j = json, b = bin;
    while (j.size() % 4) j += ' ';
    while (b.size() % 4) b += '\0';
    std::string out;
    auto u32 = [&](std::uint32_t x) { out.append(reinterpret_cast<const char*>(&x), 4); };
    u32(0x46546c67), u32(2), u32(static_cast<std::uint32_t>(12 + 8 + j.size() + (b.empty() ? 0 : 8 + b.size())));
    u32(static_cast<std::uint32_t>(j.size())), u32(0x4e4f534a);
    out += j;
    if (!b.empty()) {
        u32(static_cast<std::uint32_t>(b.size())), u32(0x004e4942);
        out += b;
    }
    return out;
}

template <class... X>
std::string bytes_of(const X&... x) {
    std::string out;
    (out.append(reinterpret_cast<const char*>(&x), sizeof x), ...);
    return out;
}

TEST(gltf, glb_and_gltf_round_trip_the_triangulated_cube) {
    scratch_dir dir;
    const auto cube = cube_of_quads();
    for (const char* name : {"cube.glb", "cube.gltf"}) {
        ASSERT_TRUE(io::write_gltf(cube, dir / name)) << name;
        halfedge_mesh back;
        auto r = io::read_gltf(back, dir / name);
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_EQ(r->format, std::string(name).ends_with("glb") ? "glb" : "gltf");
        EXPECT_TRUE(r->repair.clean());
        EXPECT_EQ(back.vertex_count(), 8u);
        EXPECT_EQ(back.face_count(), 12u);
        for (auto v : back.vertices()) EXPECT_EQ(back.position(v), cube.position(vertex_handle(v.index))) << name;
        auto bytes = io::detail::read_file(dir / name);
        ASSERT_TRUE(bytes);
        auto soup = io::parse_gltf(*bytes, name);
        ASSERT_TRUE(soup) << soup.error().message;
        EXPECT_DOUBLE_EQ(volume(*soup), 1.0);  // closed, outward: the triangulation kept the winding
    }
}

TEST(gltf, node_transforms_strides_short_indices_and_colours_are_read) {
    // One triangle, positions interleaved with padding (stride 16), uint16 indices, byte colours,
    // placed by a parent node's translation and a child's scale.
    std::string bin;
    const float p[3][4] = {{0, 0, 0, 9}, {1, 0, 0, 9}, {0, 1, 0, 9}};
    for (auto& q : p) bin += bytes_of(q[0], q[1], q[2], q[3]);
    bin += bytes_of(std::uint16_t{0}, std::uint16_t{1}, std::uint16_t{2}, std::uint16_t{0});
    const std::uint8_t colours[12] = {255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 255, 0};
    bin.append(reinterpret_cast<const char*>(colours), 12);
    const std::string json =
        R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)"
        R"("nodes":[{"translation":[10,0,0],"children":[1]},{"scale":[2,2,2],"mesh":0}],)"
        R"("meshes":[{"primitives":[{"attributes":{"POSITION":0,"COLOR_0":2},"indices":1}]}],)"
        R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},)"
        R"({"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"},)"
        R"({"bufferView":2,"componentType":5121,"normalized":true,"count":3,"type":"VEC4"}],)"
        R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48,"byteStride":16},)"
        R"({"buffer":0,"byteOffset":48,"byteLength":8},{"buffer":0,"byteOffset":56,"byteLength":12}],)"
        R"("buffers":[{"byteLength":68}]})";
    auto soup = io::parse_gltf(glb_of(json, bin), "t.glb");
    ASSERT_TRUE(soup) << soup.error().message;
    ASSERT_EQ(soup->points.size(), 3u);
    EXPECT_EQ(soup->points[1], (std::array<double, 3>{12, 0, 0}));
    EXPECT_EQ(soup->points[2], (std::array<double, 3>{10, 2, 0}));
    EXPECT_EQ(soup->indices, (std::vector<std::uint32_t>{0, 1, 2}));
    ASSERT_EQ(soup->attributes.colors.size(), 3u);
    EXPECT_EQ(soup->attributes.colors[1], (std::array<std::uint8_t, 4>{0, 255, 0, 128}));
}

TEST(gltf, hostile_bytes_give_one_line_errors_naming_the_place) {
    const std::string head = R"({"asset":{"version":"2.0"},)";
    const std::string tri = R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],)";
    const std::string bin = bytes_of(0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f) + bytes_of(0u, 1u, 7u);
    const std::string views =
        R"("bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":12}],)"
        R"("buffers":[{"byteLength":48}]})";
    auto accessors = [](const std::string& position_count) {
        return R"("accessors":[{"bufferView":0,"componentType":5126,"count":)" + position_count +
               R"(,"type":"VEC3"},{"bufferView":1,"componentType":5125,"count":3,"type":"SCALAR"}],)";
    };
    struct bad {
        std::string bytes, expect;
    };
    const std::vector<bad> cases = {
        {"", "byte offset 0"},
        {"{\"asset\":", "byte offset 9"},
        {std::string(200, '['), "nested deeper"},
        {glb_of(head + tri + accessors("3") + views, bin).substr(0, 30), "GLB header says"},
        {glb_of(head + tri + accessors("3") + views, bin), "indices of meshes[0].primitives[0]: index 2 is 7"},
        {glb_of(head + tri + accessors("4294967296") + views, bin), "run past bufferViews[0]"},
        {glb_of(head + tri + accessors("3") + views, ""), "no GLB binary chunk"},
        {glb_of(R"({"asset":{"version":"1.0"}})", ""), "not a glTF 2.x"},
        {glb_of(head + R"("scenes":[{"nodes":[0]}],"nodes":[{"children":[0]}]})", ""), "cycle"},
        {glb_of(head + R"("meshes":[{"primitives":[{"attributes":{"POSITION":5}}]}]})", ""), "accessors[5]"},
        {head + R"("buffers":[{"byteLength":3,"uri":"../../etc/passwd"}]})", "cannot be read from memory"},
        {head + R"("buffers":[{"byteLength":3,"uri":"data:application/octet-stream;base64,@@@@"}]})", "not base64"},
    };
    for (const auto& c : cases) {
        auto r = io::parse_gltf(c.bytes, "x.glb");
        ASSERT_FALSE(r) << c.expect;
        EXPECT_NE(r.error().message.find(c.expect), std::string::npos) << r.error().message;
        EXPECT_EQ(r.error().message.find('\n'), std::string::npos) << r.error().message;
        EXPECT_EQ(r.error().message.rfind("x.glb", 0), 0u) << r.error().message;
    }
}

TEST(gltf, external_buffers_are_read_from_beside_the_file_only) {
    scratch_dir dir;
    const std::string bin = bytes_of(0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f);
    {
        std::ofstream(dir / "my data.bin", std::ios::binary) << bin;
        std::ofstream(dir / "t.gltf")
            << R"({"asset":{"version":"2.0"},"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
               R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}],)"
               R"("bufferViews":[{"buffer":0,"byteLength":36}],"buffers":[{"byteLength":36,"uri":"my%20data.bin"}]})";
        std::ofstream(dir / "u.gltf")
            << R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":1,"uri":"/etc/hostname"}]})";
    }
    halfedge_mesh m;
    auto r = io::read_gltf(m, dir / "t.gltf");
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_EQ(m.face_count(), 1u);
    auto refused = io::read_gltf(m, dir / "u.gltf");
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().message.find("not a relative path"), std::string::npos) << refused.error().message;
    EXPECT_EQ(m.face_count(), 1u);  // unchanged on error
}

}  // namespace
