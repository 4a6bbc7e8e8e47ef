// Platonic solids: counts, outward winding, regularity and volume, checked on every model
// against values from geometry, not from the generator.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <hmira/algorithms/generators/grid.hpp>
#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/generators/torus.hpp>
#include <hmira/algorithms/topology/mesh_topology.hpp>

#include "support/checks.hpp"
#include "support/models.hpp"

namespace {

using namespace hmira;

struct solid_spec {
    const char* name;
    std::size_t v, e, f, face_degree;
    double volume;  // of the canonical solid (scale 1), from the textbook formula
};

constexpr double phi = std::numbers::phi;
// Edge lengths of the canonical solids: tetrahedron 2*sqrt(2), cube 2, octahedron sqrt(2),
// icosahedron 2, dodecahedron 2/phi.
const solid_spec tetrahedron{"tetrahedron", 4, 6, 4, 3, std::pow(2 * std::sqrt(2.0), 3) / (6 * std::sqrt(2.0))};
const solid_spec cube{"cube", 8, 12, 6, 4, 8.0};
const solid_spec octahedron{"octahedron", 6, 12, 8, 3, std::sqrt(2.0) / 3 * std::pow(std::sqrt(2.0), 3)};
const solid_spec icosahedron{"icosahedron", 12, 30, 20, 3, 5 * (3 + std::sqrt(5.0)) / 12 * 8};
const solid_spec dodecahedron{"dodecahedron", 20, 30, 12, 5, (15 + 7 * std::sqrt(5.0)) / 4 * std::pow(2 / phi, 3)};

template <class M>
class generators : public ::testing::Test {};
TYPED_TEST_SUITE(generators, hmira_test::all_models);

template <class M, class Gen>
void check_solid(const solid_spec& spec, Gen generate) {
    using T = default_traits<M>;
    M mesh;
    auto made = generate(mesh, solid_options{});
    ASSERT_TRUE(made) << made.error().message;
    EXPECT_EQ(made->vertices.size(), spec.v);
    EXPECT_EQ(made->faces.size(), spec.f);
    ASSERT_TRUE(hmira_test::is_valid(mesh)) << spec.name;

    const auto topo = mesh_topology(mesh);
    EXPECT_EQ(topo.vertices, spec.v) << spec.name;
    EXPECT_EQ(topo.edges, spec.e) << spec.name;
    EXPECT_EQ(topo.faces, spec.f) << spec.name;
    EXPECT_EQ(topo.euler_characteristic, 2) << spec.name;
    EXPECT_EQ(topo.components, 1u);
    EXPECT_TRUE(topo.closed());
    EXPECT_EQ(topo.genus, 0);

    // Outward winding: each face's Newell normal points away from the centre.
    double edge_min = 1e300, edge_max = 0;
    for (auto f : T::faces(mesh)) {
        std::vector<vec3<double>> p;
        for (auto v : T::face_vertices(mesh, f)) {
            const auto q = T::position(mesh, v);
            p.push_back({double(q[0]), double(q[1]), double(q[2])});
        }
        EXPECT_EQ(p.size(), spec.face_degree);
        vec3<double> n{}, c{};
        for (std::size_t i = 0; i < p.size(); ++i) {
            n += cross(p[i], p[(i + 1) % p.size()]);
            c += p[i];
            const double len = norm(p[(i + 1) % p.size()] - p[i]);
            edge_min = std::min(edge_min, len);
            edge_max = std::max(edge_max, len);
        }
        EXPECT_GT(dot(n, c), 0) << spec.name << ": face " << T::face_index(mesh, f) << " is wound inward";
    }
    EXPECT_NEAR(edge_min, edge_max, 1e-5) << spec.name << " is not regular";
    EXPECT_NEAR(hmira_test::signed_volume(mesh), spec.volume, 1e-4 * spec.volume) << spec.name;
}

TYPED_TEST(generators, every_platonic_solid_is_closed_outward_regular_and_of_the_right_volume) {
    using M = TypeParam;
    using T = default_traits<M>;
    check_solid<M>(tetrahedron, [](M& m, solid_options o) { return generate_tetrahedron(m, o); });
    check_solid<M>(octahedron, [](M& m, solid_options o) { return generate_octahedron(m, o); });
    check_solid<M>(icosahedron, [](M& m, solid_options o) { return generate_icosahedron(m, o); });
    if constexpr (polygon_mesh_builder<M, T>) {
        check_solid<M>(cube, [](M& m, solid_options o) { return generate_cube(m, o); });
        check_solid<M>(dodecahedron, [](M& m, solid_options o) { return generate_dodecahedron(m, o); });
    }
}

TYPED_TEST(generators, options_scale_and_move_the_solid) {
    using M = TypeParam;
    M mesh;
    auto made = generate_icosahedron(mesh, {.scale = 2.5, .center = {1, -2, 3}});
    ASSERT_TRUE(made);
    EXPECT_NEAR(hmira_test::signed_volume(mesh), icosahedron.volume * 2.5 * 2.5 * 2.5, 1e-3);
    vec3<double> c{};
    for (auto v : made->vertices) {
        const auto q = default_traits<M>::position(mesh, v);
        c += vec3<double>{double(q[0]), double(q[1]), double(q[2])};
    }
    c /= double(made->vertices.size());
    EXPECT_NEAR(c.x, 1, 1e-5);
    EXPECT_NEAR(c.y, -2, 1e-5);
    EXPECT_NEAR(c.z, 3, 1e-5);
}

TYPED_TEST(generators, generating_into_a_nonempty_mesh_adds_a_separate_component) {
    using M = TypeParam;
    M mesh;
    ASSERT_TRUE(generate_tetrahedron(mesh));
    ASSERT_TRUE(generate_octahedron(mesh, {.center = {5, 0, 0}}));
    ASSERT_TRUE(hmira_test::is_valid(mesh));
    const auto topo = mesh_topology(mesh);
    EXPECT_EQ(topo.components, 2u);
    EXPECT_EQ(topo.euler_characteristic, 4);
}

TYPED_TEST(generators, torus_is_closed_genus_one_with_rings_times_sides_quads) {
    using M = TypeParam;
    if constexpr (polygon_mesh_builder<M>) {
        for (auto [rings, sides] : std::vector<std::pair<std::size_t, std::size_t>>{{3, 3}, {12, 5}, {40, 17}}) {
            M mesh;
            auto made = generate_torus(mesh, {.major_radius = 2, .minor_radius = 0.5, .rings = rings, .sides = sides});
            ASSERT_TRUE(made);
            ASSERT_TRUE(hmira_test::is_valid(mesh));
            const auto topo = mesh_topology(mesh);
            EXPECT_EQ(topo.vertices, rings * sides);
            EXPECT_EQ(topo.edges, 2 * rings * sides);
            EXPECT_EQ(topo.faces, rings * sides);
            EXPECT_EQ(topo.genus, 1);
            EXPECT_TRUE(topo.closed());
            EXPECT_GT(hmira_test::signed_volume(mesh), 0) << "torus must be wound outward";
        }
        M mesh;
        EXPECT_EQ(generate_torus(mesh, {.major_radius = 1, .minor_radius = 2}).error().code, errc::invalid_argument);
        EXPECT_EQ(generate_torus(mesh, {.rings = 2}).error().code, errc::invalid_argument);
        EXPECT_EQ(default_traits<M>::vertex_count(mesh), 0u) << "a refused torus must add nothing";
    }
}

TYPED_TEST(generators, grid_is_a_disk_with_one_boundary_loop) {
    using M = TypeParam;
    for (bool triangles : {true, false}) {
        if (!triangles && !polygon_mesh_builder<M>) continue;
        M mesh;
        auto made = generate_grid(mesh, {.columns = 7, .rows = 4, .triangles = triangles});
        ASSERT_TRUE(made);
        ASSERT_TRUE(hmira_test::is_valid(mesh));
        const auto topo = mesh_topology(mesh);
        EXPECT_EQ(topo.vertices, 8u * 5u);
        EXPECT_EQ(topo.faces, triangles ? 56u : 28u);
        EXPECT_EQ(topo.boundary_loops, 1u);
        EXPECT_EQ(topo.boundary_edges, 2u * (7 + 4));
        EXPECT_EQ(topo.euler_characteristic, 1);
    }
    M mesh;
    EXPECT_FALSE(generate_grid(mesh, {.columns = 0}));
}

// The thesis's appendix-C cube lists face (b, c, g, f), which is wound inward. The library
// must notice: face-vertex validation reports the orientation conflict, and the halfedge
// mesh refuses the face.
TEST(generators, thesis_cube_with_inward_face_is_caught) {
    const std::vector<std::array<int, 4>> thesis_faces{{0, 1, 2, 3}, {1, 2, 6, 5}, {2, 6, 7, 3},
                                                       {0, 3, 7, 4}, {4, 5, 1, 0}, {7, 6, 5, 4}};
    const std::vector<vec3<double>> p{{-1, -1, -1}, {1, -1, -1}, {1, -1, 1}, {-1, -1, 1},
                                      {-1, 1, -1},  {1, 1, -1},  {1, 1, 1},  {-1, 1, 1}};
    face_vertex_mesh fv;
    halfedge_mesh he;
    std::vector<vertex_handle> a, b;
    for (auto q : p) {
        a.push_back(fv.add_vertex(q));
        b.push_back(he.add_vertex(q));
    }
    bool rejected = false;
    for (auto f : thesis_faces) {
        ASSERT_TRUE(fv.add_face({a[f[0]], a[f[1]], a[f[2]], a[f[3]]}));
        auto r = he.add_face({b[f[0]], b[f[1]], b[f[2]], b[f[3]]});
        if (!r) {
            rejected = true;
            EXPECT_EQ(r.error().code, errc::orientation_conflict) << r.error().message;
        }
    }
    EXPECT_TRUE(rejected);
    const auto problems = validate(fv);
    EXPECT_TRUE(std::any_of(problems.begin(), problems.end(),
                            [](const mesh_problem& p) { return p.kind == problem_kind::inconsistent_orientation; }));
}

}  // namespace
