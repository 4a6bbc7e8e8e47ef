// Extrusion: one face, a region, individual faces, faces with inner rings (holes);
// exact deltas, validity, Euler-Poincare with rings, walls of quads, outward orientation, the
// volume added; random region extrusions; rejected input leaves the mesh unchanged.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <vector>

#include <hmira/algorithms/generators/grid.hpp>

#include "algorithms/editing/editing_support.hpp"
#include "algorithms/euler/euler_support.hpp"

namespace {

using namespace hmira_test;

template <class M>
class extrude_test : public ::testing::Test {};
TYPED_TEST_SUITE(extrude_test, hmira_test::all_models);

#define SKIP_UNLESS_EXTRUDABLE()                                                         \
    if constexpr (!hmira::extrudable_mesh<TypeParam>) {                                  \
        GTEST_SKIP() << "model cannot be edited (no Euler operators or triangles only)"; \
    } else

template <class M>
M box(int nx, int ny, int nz) {
    M m;
    EXPECT_TRUE(add_face_list(m, lattice_box(nx, ny, nz)));
    return m;
}

TYPED_TEST(extrude_test, one_cube_face_moved_out_by_d_adds_area_times_d) {
    SKIP_UNLESS_EXTRUDABLE() {
        using T = hmira::default_traits<TypeParam>;
        for (double d : {0.5, 2.0}) {
            TypeParam m;
            auto cube = hmira::generate_cube(m).value();
            const auto top = cube.faces[5];  // y = +1, area 4
            const auto before = count(m);
            const double vol = signed_volume(m);
            auto r = hmira::extrude(m, top, {.distance = d});
            ASSERT_TRUE(r) << r.error().message;
            EXPECT_EQ(count(m), (counts{before.v + 4, before.e + 8, before.f + 4}));
            EXPECT_TRUE(valid_with_chi(m, 2));
            EXPECT_NEAR(signed_volume(m), vol + 4 * d, tol<TypeParam>());
            EXPECT_TRUE(faces_point_outward(m, {0, d / 2, 0}));
            ASSERT_EQ(r->top_faces.size(), 1u);
            EXPECT_EQ(r->top_faces[0], top);
            EXPECT_EQ(r->side_faces.size(), 4u);
            EXPECT_EQ(r->vertices.size(), 4u);
            for (auto v : T::face_vertices(m, top)) EXPECT_NEAR(p3(m, v)[1], 1 + d, tol<TypeParam>());
            for (auto f : r->side_faces) EXPECT_EQ(std::ranges::distance(T::face_vertices(m, f)), 4);
            EXPECT_EQ(face_sizes(m), (std::map<std::size_t, std::size_t>{{4, 10}}));
        }
    }
}

TYPED_TEST(extrude_test, a_negative_distance_digs_a_pocket_that_removes_area_times_d) {
    SKIP_UNLESS_EXTRUDABLE() {
        using T = hmira::default_traits<TypeParam>;
        TypeParam m;
        auto cube = hmira::generate_cube(m).value();
        const double vol = signed_volume(m);
        auto r = hmira::extrude(m, cube.faces[5], {.distance = -0.75});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(valid_with_chi(m, 2));
        EXPECT_NEAR(signed_volume(m), vol - 4 * 0.75, tol<TypeParam>());
        // The pocket floor still faces +y, out of the solid; each wall faces into the pocket.
        EXPECT_GT(newell(m, cube.faces[5])[1], 0);
        for (auto f : r->side_faces) {
            const auto n = newell(m, f);
            const auto c = centroid(m, f);
            EXPECT_LT(n[0] * c[0] + n[2] * c[2], 0) << "wall faces away from the pocket";
            EXPECT_NEAR(n[1], 0, tol<TypeParam>());
        }
        (void)sizeof(T);
    }
}

TYPED_TEST(extrude_test, an_oblique_direction_adds_the_projected_volume) {
    SKIP_UNLESS_EXTRUDABLE() {
        TypeParam m;
        auto cube = hmira::generate_cube(m).value();
        const double vol = signed_volume(m);
        auto r = hmira::extrude(m, cube.faces[5], {.distance = 1.0, .direction = hmira::vec3<double>{0, 1, 1}});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(valid_with_chi(m, 2));
        EXPECT_NEAR(signed_volume(m), vol + 4 * std::sqrt(0.5), tol<TypeParam>());
    }
}

TYPED_TEST(extrude_test, a_region_moves_as_one_piece_with_walls_only_on_its_outline) {
    SKIP_UNLESS_EXTRUDABLE() {
        using T = hmira::default_traits<TypeParam>;
        auto m = box<TypeParam>(3, 3, 1);
        const auto region = faces_on_plane(m, 2, 1.0);  // the 9 top quads
        ASSERT_EQ(region.size(), 9u);
        const auto before = count(m);
        const double vol = signed_volume(m);
        auto r = hmira::extrude(m, region, {.distance = 0.5});
        ASSERT_TRUE(r) << r.error().message;
        // Outline of 12 edges: 12 new vertices, 24 new edges, 12 walls; 4 inner vertices move.
        EXPECT_EQ(count(m), (counts{before.v + 12, before.e + 24, before.f + 12}));
        EXPECT_TRUE(valid_with_chi(m, 2));
        EXPECT_NEAR(signed_volume(m), vol + 9 * 0.5, tol<TypeParam>());
        EXPECT_TRUE(faces_point_outward(m, {1.5, 1.5, 0.75}));
        EXPECT_EQ(r->side_faces.size(), 12u);
        for (auto f : region)
            for (auto v : T::face_vertices(m, f)) EXPECT_NEAR(p3(m, v)[2], 1.5, tol<TypeParam>());
        EXPECT_EQ(face_sizes(m).size(), 1u);  // quads only
        EXPECT_FALSE(has_vertex_at(m, {1, 1, 1}));
        EXPECT_TRUE(has_vertex_at(m, {1, 1, 1.5}));
        EXPECT_TRUE(has_vertex_at(m, {0, 1, 1}));  // the outline stays, with its copy above
        EXPECT_TRUE(has_vertex_at(m, {0, 1, 1.5}));
    }
}

TYPED_TEST(extrude_test, a_region_reaching_the_boundary_keeps_the_boundary_valid) {
    SKIP_UNLESS_EXTRUDABLE() {
        TypeParam m;
        auto g = hmira::generate_grid(m, {.columns = 4, .rows = 3}).value();
        // The first row of cells: its outline runs along the grid's boundary on three sides.
        std::vector<typename hmira::default_traits<TypeParam>::face_handle> region(g.faces.begin(),
                                                                                   g.faces.begin() + 4);
        const auto before = count(m);
        auto r = hmira::extrude(m, region, {.distance = 1.0});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_EQ(count(m), (counts{before.v + 10, before.e + 20, before.f + 10}));
        EXPECT_TRUE(valid_with_chi(m, 1));
        EXPECT_EQ(hmira::mesh_topology(m).boundary_loops, 1u);
    }
}

TYPED_TEST(extrude_test, individual_mode_extrudes_each_face_along_its_own_normal) {
    SKIP_UNLESS_EXTRUDABLE() {
        auto m = box<TypeParam>(2, 1, 1);
        std::vector<typename hmira::default_traits<TypeParam>::face_handle> sel = faces_on_plane(m, 2, 1.0);
        const auto side = faces_on_plane(m, 0, 2.0);  // the +x end
        sel.insert(sel.end(), side.begin(), side.end());
        ASSERT_EQ(sel.size(), 3u);
        const auto before = count(m);
        const double vol = signed_volume(m);
        auto r = hmira::extrude(m, sel, {.distance = 0.25, .mode = hmira::extrude_mode::individual});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_EQ(count(m), (counts{before.v + 12, before.e + 24, before.f + 12}));
        EXPECT_TRUE(valid_with_chi(m, 2));
        EXPECT_NEAR(signed_volume(m), vol + 3 * 0.25, tol<TypeParam>());
        EXPECT_TRUE(has_vertex_at(m, {2.25, 0, 0}));
        EXPECT_TRUE(has_vertex_at(m, {2, 0, 1.25}));
    }
}

TYPED_TEST(extrude_test, a_single_face_region_equals_individual_mode) {
    SKIP_UNLESS_EXTRUDABLE() {
        TypeParam a, b;
        auto ca = hmira::generate_cube(a).value();
        auto cb = hmira::generate_cube(b).value();
        ASSERT_TRUE(hmira::extrude(a, ca.faces[2], {.distance = 0.3}));
        ASSERT_TRUE(hmira::extrude(b, cb.faces[2], {.distance = 0.3, .mode = hmira::extrude_mode::individual}));
        EXPECT_EQ(canonical_faces(a), canonical_faces(b));
    }
}

TYPED_TEST(extrude_test, bad_input_is_rejected_and_leaves_the_mesh_unchanged) {
    SKIP_UNLESS_EXTRUDABLE() {
        using F = typename hmira::default_traits<TypeParam>::face_handle;
        auto m = box<TypeParam>(3, 3, 1);
        const auto top = faces_on_plane(m, 2, 1.0);
        const auto faces_before = canonical_faces(m);
        const auto before = count(m);
        const auto check = [&](auto r, hmira::errc code) {
            ASSERT_FALSE(r);
            EXPECT_EQ(r.error().code, code) << r.error().message;
            EXPECT_EQ(count(m), before);
            EXPECT_EQ(canonical_faces(m), faces_before);
        };
        for (double d : {0.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
            check(hmira::extrude(m, top[0], {.distance = d}), hmira::errc::invalid_argument);
        check(hmira::extrude(m, top[0], {.direction = hmira::vec3<double>{0, 0, 0}}), hmira::errc::invalid_argument);
        check(hmira::extrude(m, std::vector<F>{}), hmira::errc::invalid_argument);
        // Two faces that share no edge: not a region.
        const auto bottom = faces_on_plane(m, 2, 0.0);
        check(hmira::extrude(m, std::vector<F>{top[0], bottom[0]}), hmira::errc::topology);
        // Every face: no outline.
        std::vector<F> all;
        for (auto f : hmira::default_traits<TypeParam>::faces(m)) all.push_back(f);
        check(hmira::extrude(m, all), hmira::errc::topology);
        // Diagonal neighbours joined by an edge-neighbour on one side only: pinched at a vertex.
        std::vector<F> pinched;
        for (auto f : top) {
            const auto c = centroid(m, f);
            if ((std::abs(c[0] - 0.5) < 1e-9 && std::abs(c[1] - 0.5) < 1e-9) ||
                (std::abs(c[0] - 1.5) < 1e-9 && std::abs(c[1] - 1.5) < 1e-9))
                pinched.push_back(f);
        }
        ASSERT_EQ(pinched.size(), 2u);
        check(hmira::extrude(m, pinched), hmira::errc::topology);
    }
}

// ----- faces with inner rings ---------------------------------------------------------------

#define SKIP_UNLESS_RINGS()                                                                           \
    if constexpr (!hmira::extrudable_mesh<TypeParam> || !hmira::euler_ring_mutable_mesh<TypeParam>) { \
        GTEST_SKIP() << "model has no inner rings";                                                   \
    } else

/// The cube [-1,1]^3 whose top face (y = 1) has a square hole of half-size a, closed by a
/// square face of its own at the same height. Built with the Euler operators: a chain of
/// makeEV from a corner of the top into the face, makeEF closing the square, and killEmakeR
/// on the chain's first edge, which leaves the square's other side as a ring of the top.
/// Returns the ringed face. V 12, E 16, F 7, R 1 (S - H = 1).
template <class M, class T = hmira::default_traits<M>>
typename T::face_handle cube_with_ringed_top(M& m, double a) {
    using S = typename T::scalar;
    auto cube = hmira::generate_cube(m).value();
    const auto corner = T::face_halfedge(m, cube.faces[5]);
    // Wound +y like the top, so that the square face faces out of the cube.
    const hmira::vec3<S> q[4] = {{S(-a), 1, S(-a)}, {S(-a), 1, S(a)}, {S(a), 1, S(a)}, {S(a), 1, S(-a)}};
    auto p0 = hmira::make_edge_vertex(m, corner, q[0]).value();
    auto prev = p0.halfedge;
    for (int i = 1; i < 4; ++i) prev = hmira::make_edge_vertex(m, prev, q[i]).value().halfedge;
    EXPECT_TRUE(hmira::make_edge_face(m, prev, p0.halfedge));
    const auto ring = hmira::kill_edge_make_ring(m, p0.halfedge).value();
    return T::face(m, ring.ring);
}

/// Signed volume over every loop of every face (rings, wound against their face, subtract),
/// fan-triangulated from each loop's first vertex; computed here from the halfedges.
template <class M, class T = hmira::default_traits<M>>
double volume_with_rings(const M& m) {
    double vol = 0;
    for (auto f : T::faces(m)) {
        std::vector<typename T::halfedge_handle> starts{T::face_halfedge(m, f)};
        for (auto r : T::inner_rings(m, f)) starts.push_back(r);
        for (auto s : starts) {
            std::vector<std::array<double, 3>> p;
            auto h = s;
            do {
                p.push_back(p3(m, T::target(m, h)));
                h = T::next(m, h);
            } while (h != s);
            for (std::size_t i = 1; i + 1 < p.size(); ++i) {
                const auto &a = p[0], &b = p[i], &c = p[i + 1];
                vol += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                        a[2] * (b[0] * c[1] - b[1] * c[0])) /
                       6;
            }
        }
    }
    return vol;
}

/// Checks validity and V - E + F - R = 2 (S - H) (rings counted, walked from the halfedges).
template <class M>
::testing::AssertionResult valid_with_rings(const M& m, long long s_minus_h) {
    if (auto v = hmira_test::is_valid(m); !v) return v;
    return euler_poincare_holds(m, s_minus_h);
}

TYPED_TEST(extrude_test, a_face_with_a_hole_extrudes_with_walls_along_its_outer_loop_and_its_ring) {
    SKIP_UNLESS_RINGS() {
        using T = hmira::default_traits<TypeParam>;
        for (double d : {0.5, -0.5, 1.25}) {
            for (auto mode : {hmira::extrude_mode::region, hmira::extrude_mode::individual}) {
                SCOPED_TRACE("d = " + std::to_string(d));
                TypeParam m;
                const auto top = cube_with_ringed_top(m, 0.5);
                ASSERT_TRUE(valid_with_rings(m, 1));
                ASSERT_EQ(count_euler(m).rings, 1);
                ASSERT_NEAR(volume_with_rings(m), 8.0, 1e-12);
                const auto before = count(m);
                auto r = hmira::extrude(m, top, {.distance = d, .mode = mode});
                ASSERT_TRUE(r) << r.error().message;
                // Outer loop of 4 and ring of 4: 8 corners, so V + 8, E + 16, F + 8; R stays 1.
                EXPECT_EQ(count(m), (counts{before.v + 8, before.e + 16, before.f + 8}));
                EXPECT_EQ(count_euler(m).rings, 1);
                EXPECT_TRUE(valid_with_rings(m, 1));
                // The slab (outer area 4 - hole area 1) times d.
                EXPECT_NEAR(volume_with_rings(m), 8.0 + 3.0 * d, 1e-12);
                ASSERT_EQ(r->top_faces.size(), 1u);
                EXPECT_EQ(r->top_faces[0], top);
                ASSERT_EQ(r->side_faces.size(), 8u);
                EXPECT_EQ(r->vertices.size(), 8u);
                // The top keeps its hole, now at y = 1 + d.
                ASSERT_EQ(std::ranges::distance(T::inner_rings(m, top)), 1);
                const auto ring = *T::inner_rings(m, top).begin();
                auto h = ring;
                int n = 0;
                do {
                    const auto p = p3(m, T::target(m, h));
                    EXPECT_NEAR(p[1], 1 + d, 1e-12);
                    EXPECT_NEAR(std::max(std::abs(p[0]), std::abs(p[2])), 0.5, 1e-12);
                    ++n;
                    h = T::next(m, h);
                } while (h != ring);
                EXPECT_EQ(n, 4);
                for (auto v : T::face_vertices(m, top)) EXPECT_NEAR(p3(m, v)[1], 1 + d, 1e-12);
                // Walls: quads, vertical; the outer ones face away from the axis x = z = 0 and
                // the ring's face into the hole (for d > 0; a pocket turns both around).
                for (std::size_t i = 0; i < r->side_faces.size(); ++i) {
                    const auto f = r->side_faces[i];
                    EXPECT_EQ(std::ranges::distance(T::face_vertices(m, f)), 4);
                    const auto nrm = newell(m, f);
                    const auto c = centroid(m, f);
                    EXPECT_NEAR(nrm[1], 0, 1e-12);
                    const double radial = nrm[0] * c[0] + nrm[2] * c[2];
                    const bool ring_wall = i >= 4;  // outer loop's walls first
                    EXPECT_GT((ring_wall ? -radial : radial) * d, 0) << "wall " << i << " faces the wrong way";
                }
                EXPECT_GT(newell(m, top)[1], 0);
            }
        }
    }
}

TYPED_TEST(extrude_test, a_region_holding_a_ringed_face_gets_walls_along_its_whole_outline_ring_included) {
    SKIP_UNLESS_RINGS() {
        using T = hmira::default_traits<TypeParam>;
        TypeParam m;
        const auto top = cube_with_ringed_top(m, 0.5);
        // The top and the +x side: outline of 6 outer edges plus the ring's 4.
        typename T::face_handle side{};
        for (auto f : T::faces(m))
            if (std::abs(centroid(m, f)[0] - 1) < 1e-12) side = f;
        const std::vector<typename T::face_handle> region{top, side};
        const auto before = count(m);
        // Oblique, so that no wall lies along the move (a wall on an edge parallel to it would
        // have no area).
        const std::array<double, 3> dir{0.25, 1, 0.5};
        const double len = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
        const std::array<double, 3> t{0.5 * dir[0] / len, 0.5 * dir[1] / len, 0.5 * dir[2] / len};
        auto r = hmira::extrude(m, region, {.distance = 0.5, .direction = hmira::vec3<double>{dir[0], dir[1], dir[2]}});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_EQ(count(m), (counts{before.v + 10, before.e + 20, before.f + 10}));
        EXPECT_EQ(r->side_faces.size(), 10u);
        EXPECT_EQ(r->vertices.size(), 10u);
        EXPECT_EQ(count_euler(m).rings, 1);
        EXPECT_TRUE(valid_with_rings(m, 1));
        // A region translated by t adds t . (its vector area): the top's (0, 4 - 1, 0) and the
        // side's (4, 0, 0).
        EXPECT_NEAR(volume_with_rings(m), 8.0 + t[0] * 4 + t[1] * 3, 1e-12);
        for (auto f : r->side_faces) EXPECT_EQ(std::ranges::distance(T::face_vertices(m, f)), 4);
        // The region keeps its vertices (moved); the copies stay where the outline was.
        for (auto v : r->vertices) {
            const auto p = p3(m, v);
            EXPECT_TRUE(std::abs(p[1] - 1) < 1e-12 || std::abs(p[0] - 1) < 1e-12) << "copy off the old outline";
        }
        auto moved = [&](std::array<double, 3> p) {
            return std::array<double, 3>{p[0] + t[0], p[1] + t[1], p[2] + t[2]};
        };
        EXPECT_TRUE(has_vertex_at(m, moved({1, 1, 1})));
        EXPECT_TRUE(has_vertex_at(m, {1, 1, 1}));  // on the outline (the front is outside): copied
        EXPECT_TRUE(has_vertex_at(m, {1, -1, 1}));
        EXPECT_TRUE(has_vertex_at(m, moved({1, -1, 1})));
        EXPECT_TRUE(has_vertex_at(m, {0.5, 1.0, 0.5}));
        EXPECT_TRUE(has_vertex_at(m, moved({0.5, 1.0, 0.5})));
        ASSERT_EQ(std::ranges::distance(T::inner_rings(m, top)), 1);
    }
}

TYPED_TEST(extrude_test, a_region_holding_a_ringed_face_and_its_plug_has_no_wall_on_the_ring) {
    SKIP_UNLESS_RINGS() {
        using T = hmira::default_traits<TypeParam>;
        TypeParam m;
        const auto top = cube_with_ringed_top(m, 0.5);
        const auto plug = T::face(m, T::opposite(m, *T::inner_rings(m, top).begin()));
        const auto before = count(m);
        auto r = hmira::extrude(m, std::vector<typename T::face_handle>{top, plug}, {.distance = 0.5});
        ASSERT_TRUE(r) << r.error().message;
        // The ring lies inside the region: the outline is the top's outer loop of 4.
        EXPECT_EQ(count(m), (counts{before.v + 4, before.e + 8, before.f + 4}));
        EXPECT_TRUE(valid_with_rings(m, 1));
        EXPECT_NEAR(volume_with_rings(m), 8.0 + 4 * 0.5, 1e-12);
        // The ring's vertices moved with the region; none stayed behind.
        EXPECT_TRUE(has_vertex_at(m, {0.5, 1.5, 0.5}));
        EXPECT_FALSE(has_vertex_at(m, {0.5, 1.0, 0.5}));
        EXPECT_TRUE(faces_point_outward(m, {0, 0.25, 0}));
    }
}

TYPED_TEST(extrude_test, the_face_inside_a_hole_extrudes_as_a_plug_with_walls_against_the_ring) {
    SKIP_UNLESS_RINGS() {
        using T = hmira::default_traits<TypeParam>;
        TypeParam m;
        const auto top = cube_with_ringed_top(m, 0.5);
        const auto ring = *T::inner_rings(m, top).begin();
        const auto plug = T::face(m, T::opposite(m, ring));
        ASSERT_NE(plug, top);
        const auto before = count(m);
        auto r = hmira::extrude(m, plug, {.distance = 0.75});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_EQ(count(m), (counts{before.v + 4, before.e + 8, before.f + 4}));
        EXPECT_TRUE(valid_with_rings(m, 1));
        EXPECT_NEAR(volume_with_rings(m), 8.0 + 0.75, 1e-12);
        // The ring of the top now bounds the walls' bottom edges.
        for (auto f : r->side_faces) {
            const auto nrm = newell(m, f);
            const auto c = centroid(m, f);
            EXPECT_GT(nrm[0] * c[0] + nrm[2] * c[2], 0);
        }
    }
}

TYPED_TEST(extrude_test, rejected_extrusions_of_ringed_faces_leave_the_mesh_unchanged) {
    SKIP_UNLESS_RINGS() {
        using T = hmira::default_traits<TypeParam>;
        TypeParam m;
        const auto top = cube_with_ringed_top(m, 0.5);
        const auto snap = take_snapshot(m);
        auto check = [&](auto r, hmira::errc code) {
            ASSERT_FALSE(r);
            EXPECT_EQ(r.error().code, code) << r.error().message;
            EXPECT_TRUE(take_snapshot(m) == snap);
        };
        check(hmira::extrude(m, top, {.distance = 0.0}), hmira::errc::invalid_argument);
        std::vector<typename T::face_handle> all;
        for (auto f : T::faces(m)) all.push_back(f);
        check(hmira::extrude(m, all), hmira::errc::topology);  // no outline
        // The top and the bottom: no shared edge.
        typename T::face_handle bottom{};
        for (auto f : T::faces(m))
            if (std::abs(centroid(m, f)[1] + 1) < 1e-12) bottom = f;
        check(hmira::extrude(m, std::vector<typename T::face_handle>{top, bottom}), hmira::errc::topology);
    }
}

// ----- random region extrusions --------------------------------------------------------------

/// A connected region grown from a random face by random edge steps (at most `size` faces).
template <class M, class T = hmira::default_traits<M>>
std::vector<typename T::face_handle> random_region(const M& m, std::mt19937_64& rng, std::size_t size) {
    std::vector<typename T::face_handle> fs;
    for (auto f : T::faces(m)) fs.push_back(f);
    std::vector<typename T::face_handle> region{fs[std::uniform_int_distribution<std::size_t>(0, fs.size() - 1)(rng)]};
    for (int tries = 0; region.size() < size && tries < 50; ++tries) {
        const auto f = region[std::uniform_int_distribution<std::size_t>(0, region.size() - 1)(rng)];
        std::vector<typename T::face_handle> around;
        for (auto h = T::face_halfedge(m, f);;) {
            const auto g = T::face(m, T::opposite(m, h));
            if (g != T::null_face() && std::find(region.begin(), region.end(), g) == region.end()) around.push_back(g);
            h = T::next(m, h);
            if (h == T::face_halfedge(m, f)) break;
        }
        if (!around.empty())
            region.push_back(around[std::uniform_int_distribution<std::size_t>(0, around.size() - 1)(rng)]);
    }
    return region;
}

TYPED_TEST(extrude_test, random_region_extrusions_on_closed_meshes_stay_valid_manifold_and_exact) {
    SKIP_UNLESS_EXTRUDABLE() {
        using T = hmira::default_traits<TypeParam>;
        for (std::uint64_t seed : {11u, 12u, 13u}) {
            std::mt19937_64 rng(seed);
            for (int shape = 0; shape < 2; ++shape) {
                SCOPED_TRACE("seed " + std::to_string(seed) + (shape ? ", torus" : ", box"));
                TypeParam m = shape ? mesh_from<TypeParam>(torus(8, 6)) : box<TypeParam>(3, 2, 2);
                const long long chi = shape ? 0 : 2;
                std::size_t done = 0, pinched = 0;
                for (int step = 0; step < 20; ++step) {
                    const auto region = random_region(m, rng, 1 + step % 10);
                    // Expected from the region alone: its outline b, and whether an outline
                    // vertex is reached twice (pinched).
                    std::set<std::size_t> in;
                    for (auto f : region) in.insert(T::face_index(m, f));
                    long long b = 0;
                    std::multiset<std::size_t> ends;
                    for (auto f : region)
                        for (auto h = T::face_halfedge(m, f);;) {
                            const auto g = T::face(m, T::opposite(m, h));
                            if (g == T::null_face() || !in.contains(T::face_index(m, g))) {
                                ++b;
                                ends.insert(T::vertex_index(m, T::target(m, h)));
                            }
                            h = T::next(m, h);
                            if (h == T::face_halfedge(m, f)) break;
                        }
                    bool pinch = false;
                    for (auto e : ends) pinch |= ends.count(e) > 1;
                    std::array<double, 3> area{0, 0, 0};  // twice the region's vector area
                    for (auto f : region) {
                        const auto n = newell(m, f);
                        for (int i = 0; i < 3; ++i) area[i] += n[i];
                    }
                    const double vol = signed_volume(m);
                    const auto before = count(m);
                    const auto faces_before = canonical_faces(m);
                    const double dist =
                        std::uniform_real_distribution<double>(0.05, 0.6)(rng) * (step % 3 == 0 ? -1 : 1);
                    auto r = hmira::extrude(m, region, {.distance = dist});
                    if (pinch && region.size() > 1) {
                        ASSERT_FALSE(r);
                        EXPECT_EQ(r.error().code, hmira::errc::topology) << r.error().message;
                        EXPECT_EQ(count(m), before);
                        EXPECT_EQ(canonical_faces(m), faces_before);
                        ++pinched;
                        continue;
                    }
                    if (!r) {
                        // Only a region whose normals cancel may fail otherwise.
                        EXPECT_EQ(r.error().code, hmira::errc::invalid_argument) << r.error().message;
                        EXPECT_EQ(count(m), before);
                        EXPECT_EQ(canonical_faces(m), faces_before);
                        continue;
                    }
                    ++done;
                    // Moved by dist along the mean normal: the volume grows by dist x |area|.
                    EXPECT_NEAR(signed_volume(m),
                                vol + dist * std::sqrt(area[0] * area[0] + area[1] * area[1] + area[2] * area[2]) / 2,
                                1000 * tol<TypeParam>());
                    EXPECT_EQ(count(m), (counts{before.v + b, before.e + 2 * b, before.f + b}));
                    EXPECT_EQ((long long)r->side_faces.size(), b);
                    EXPECT_TRUE(valid_with_chi(m, chi, {.check_geometry = false}));
                    for (auto f : r->side_faces) EXPECT_EQ(std::ranges::distance(T::face_vertices(m, f)), 4);
                    for (auto v : T::vertices(m))
                        EXPECT_GE(degree(m, v), 3u) << "a vertex of degree < 3 on a closed mesh";
                }
                EXPECT_GT(done, pinched);
            }
        }
    }
}

TYPED_TEST(extrude_test, region_extrusion_reports_the_outline_copies_left_behind) {
    SKIP_UNLESS_EXTRUDABLE() {
        using T = hmira::default_traits<TypeParam>;
        auto m = box<TypeParam>(2, 1, 1);
        const auto region = faces_on_plane(m, 2, 1.0);  // the 2 top quads, outline of 6
        std::set<std::array<double, 3>> outline;
        for (auto f : region)
            for (auto v : T::face_vertices(m, f)) outline.insert(p3(m, v));
        auto r = hmira::extrude(m, region, {.distance = 0.5});
        ASSERT_TRUE(r) << r.error().message;
        ASSERT_EQ(r->vertices.size(), 6u);
        std::set<std::array<double, 3>> copies;
        for (auto v : r->vertices) copies.insert(p3(m, v));
        EXPECT_EQ(copies, outline);  // every outline vertex of the region, all of them at z = 1
        for (auto f : region)
            for (auto v : T::face_vertices(m, f)) EXPECT_NEAR(p3(m, v)[2], 1.5, tol<TypeParam>());
    }
}

}  // namespace
