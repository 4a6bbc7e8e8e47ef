// The guide's own test: a third structure, not in the examples, plugged in by following
// docs/own-mesh.md step by step. A flat vertex buffer with a stride (position, normal, uv per
// vertex, as a renderer uploads it) and a flat triangle index buffer. vertex_normals writes its
// result back into the buffer's normal slots, the use such a structure exists for.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <ranges>
#include <span>
#include <vector>

#include <hmira/adapters/adapted_mesh.hpp>
#include <hmira/algorithms/generators/grid.hpp>
#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/geometry/vertex_normals.hpp>
#include <hmira/algorithms/topology/mesh_topology.hpp>
#include <hmira/algorithms/validation/validate.hpp>

namespace render {

struct gpu_mesh {
    static constexpr std::size_t stride = 8;  // x y z  nx ny nz  u v
    std::vector<float> vertex_data;
    std::vector<std::uint32_t> indices;  // three per triangle

    std::size_t vertex_total() const { return vertex_data.size() / stride; }
    std::size_t triangle_total() const { return indices.size() / 3; }
};

}  // namespace render

template <>
struct hmira::mesh_traits<render::gpu_mesh> {
    using mesh = render::gpu_mesh;
    using vertex_handle = std::uint32_t;
    using face_handle = std::uint32_t;
    using scalar = float;
    static constexpr bool triangles_only = true;

    // The bound is cast to the handle type: iota(0u, size_t) would not compile.
    static auto vertices(const mesh& m) {
        return std::views::iota(std::uint32_t{0}, static_cast<std::uint32_t>(m.vertex_total()));
    }
    static auto faces(const mesh& m) {
        return std::views::iota(std::uint32_t{0}, static_cast<std::uint32_t>(m.triangle_total()));
    }
    static std::size_t vertex_count(const mesh& m) { return m.vertex_total(); }
    static std::size_t face_count(const mesh& m) { return m.triangle_total(); }
    static std::size_t vertex_index(const mesh&, std::uint32_t v) { return v; }
    static std::size_t vertex_index_bound(const mesh& m) { return m.vertex_total(); }
    static std::size_t face_index(const mesh&, std::uint32_t f) { return f; }
    static std::size_t face_index_bound(const mesh& m) { return m.triangle_total(); }
    // A view into the index buffer: three entries per triangle.
    static std::span<const std::uint32_t> face_vertices(const mesh& m, std::uint32_t f) {
        return std::span<const std::uint32_t>(m.indices).subspan(3 * std::size_t(f), 3);
    }
    static hmira::vec3<float> position(const mesh& m, std::uint32_t v) {
        const float* p = m.vertex_data.data() + mesh::stride * v;
        return {p[0], p[1], p[2]};
    }
    static std::uint32_t add_vertex(mesh& m, const hmira::vec3<float>& p) {
        m.vertex_data.insert(m.vertex_data.end(), {p.x, p.y, p.z, 0, 0, 0, 0, 0});
        return static_cast<std::uint32_t>(m.vertex_total() - 1);
    }
    static hmira::result<std::uint32_t> add_face(mesh& m, std::span<const std::uint32_t> vs) {
        if (vs.size() != 3) return hmira::fail(hmira::errc::unsupported, "gpu_mesh: triangles only");
        for (auto v : vs)
            if (v >= m.vertex_total()) return hmira::fail(hmira::errc::invalid_handle, "gpu_mesh: no such vertex", v);
        m.indices.insert(m.indices.end(), vs.begin(), vs.end());
        return static_cast<std::uint32_t>(m.triangle_total() - 1);
    }
};

namespace {

using render::gpu_mesh;
static_assert(hmira::face_vertex_range_mesh<gpu_mesh> && hmira::positioned_mesh<gpu_mesh>);
static_assert(hmira::vertex_index_mesh<gpu_mesh> && hmira::face_index_mesh<gpu_mesh>);
static_assert(hmira::mesh_builder<gpu_mesh> && !hmira::polygon_mesh_builder<gpu_mesh>);
static_assert(hmira::vertex_normals_mesh<gpu_mesh>);
static_assert(!hmira::vertex_adjacency_mesh<gpu_mesh>);
static_assert(hmira::vertex_adjacency_mesh<hmira::with_brute_force_adjacency<gpu_mesh>>);

TEST(third_structure, a_strided_buffer_is_built_validated_and_measured_through_its_traits) {
    gpu_mesh m;
    ASSERT_TRUE(hmira::generate_icosahedron(m));
    EXPECT_EQ(m.vertex_data.size(), 12 * gpu_mesh::stride);
    EXPECT_EQ(m.indices.size(), 60u);
    EXPECT_TRUE(hmira::validate(m).empty());
    const auto t = hmira::mesh_topology(m);
    EXPECT_EQ(t.vertices, 12u);
    EXPECT_EQ(t.edges, 30u);
    EXPECT_EQ(t.euler_characteristic, 2);
}

TEST(third_structure, vertex_normals_fill_the_normal_slots_of_the_buffer) {
    gpu_mesh m;
    ASSERT_TRUE(hmira::generate_icosahedron(m));
    const auto normals = hmira::vertex_normals(m);
    for (std::uint32_t v = 0; v < m.vertex_total(); ++v) {
        float* slot = m.vertex_data.data() + gpu_mesh::stride * v + 3;
        slot[0] = normals[v].x;
        slot[1] = normals[v].y;
        slot[2] = normals[v].z;
    }
    // A centred icosahedron's vertex normal is the vertex's own direction.
    for (std::uint32_t v = 0; v < m.vertex_total(); ++v) {
        const float* p = m.vertex_data.data() + gpu_mesh::stride * v;
        const float r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(p[3 + k], p[k] / r, 1e-6f);
    }
}

TEST(third_structure, quads_are_refused_and_adjacency_comes_from_an_adapter) {
    gpu_mesh m;
    auto quads = hmira::generate_grid(m, {.columns = 2, .rows = 2});
    EXPECT_FALSE(quads) << "a triangles-only mesh refuses a quad grid at run time";
    gpu_mesh tri;
    ASSERT_TRUE(hmira::generate_grid(tri, {.columns = 2, .rows = 2, .triangles = true}));
    EXPECT_TRUE(hmira::validate(tri).empty());
    const auto a = hmira::adapt_brute_force(tri);
    using A = hmira::default_traits<decltype(a)>;
    // The centre vertex (index 4) of a 2 x 2 grid split along the diagonals a-c has 6 neighbours.
    EXPECT_EQ(std::ranges::distance(A::adjacent_vertices(a, 4u)), 6);
    EXPECT_EQ(std::ranges::distance(A::vertex_faces(a, 4u)), 6);
}

}  // namespace
