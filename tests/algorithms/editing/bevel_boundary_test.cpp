// Bevel of boundary edges: on open quad grids, boundary edges alone, runs of
// them, a whole boundary loop, and boundary and interior edges meeting, for flat and rounded
// profiles. Each case checks the V/E/F change against counts derived by hand in the comments,
// that the planar grid keeps its exact area (a boundary strip replaces part of its one face),
// validate() and the model's own checker after every edit; refusals leave the mesh unchanged.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <sstream>
#include <type_traits>
#include <vector>

#include "algorithms/editing/editing_support.hpp"

#ifdef HMIRA_TEST_WITH_OPENMESH
#include <OpenMesh/Tools/Utils/MeshCheckerT.hh>
#endif
#ifdef HMIRA_TEST_WITH_CGAL
#include <CGAL/boost/graph/helpers.h>
#endif

namespace {

using namespace hmira_test;

/// The models bevel() accepts (face-vertex and triangle-only models cannot be bevelled).
using bevel_models = ::testing::Types<hmira::halfedge_mesh
#ifdef HMIRA_TEST_HAS_WINGED_EDGE
                                      ,
                                      hmira::winged_edge_mesh
#endif
#ifdef HMIRA_TEST_WITH_OPENMESH
                                      ,
                                      openmesh_poly
#endif
#ifdef HMIRA_TEST_WITH_CGAL
                                      ,
                                      cgal_surface_mesh
#endif
                                      >;

template <class M>
class bevel_boundary_test : public ::testing::Test {
    static_assert(hmira::bevelable_mesh<M>);
};
TYPED_TEST_SUITE(bevel_boundary_test, bevel_models);

/// What the mesh's own library says about it (hmira's meshes have only validate()).
template <class M>
::testing::AssertionResult native_check(const M& m) {
#ifdef HMIRA_TEST_WITH_CGAL
    if constexpr (std::is_same_v<M, cgal_surface_mesh>) {
        if (CGAL::is_valid_polygon_mesh(m)) return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure() << "CGAL::is_valid_polygon_mesh rejects the mesh";
    }
#endif
#ifdef HMIRA_TEST_WITH_OPENMESH
    if constexpr (std::is_same_v<M, openmesh_poly>) {
        std::ostringstream why;
        if (OpenMesh::Utils::MeshCheckerT<M>(m).check(OpenMesh::Utils::MeshCheckerT<M>::CHECK_ALL, why))
            return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure() << "OpenMesh MeshCheckerT: " << why.str();
    }
#endif
    (void)m;
    return ::testing::AssertionSuccess();
}

/// validate() (with geometry) and the native checker.
template <class M>
::testing::AssertionResult valid_everywhere(const M& m) {
    if (auto v = hmira_test::is_valid(m); !v) return v;
    return native_check(m);
}

/// Relative tolerance on areas: exact up to rounding in double, float models store floats.
template <class M, class T = hmira::default_traits<M>>
double area_tol() {
    return std::is_same_v<typename T::scalar, float> ? 1e-6 : 1e-12;
}

/// The open nx x ny grid of unit quads in z = 0 (the test's own face list).
template <class M>
M open_grid(std::size_t nx, std::size_t ny) {
    M m;
    if (!add_face_list(m, grid(nx, ny))) ADD_FAILURE() << "the model refused the grid";
    return m;
}

/// The edge between the vertices at a and b.
template <class M, class T = hmira::default_traits<M>>
typename T::edge_handle edge_at(const M& m, std::array<double, 3> a, std::array<double, 3> b) {
    for (auto e : T::edges(m)) {
        const auto ev = T::edge_vertices(m, e);
        const auto pa = p3<M, T>(m, ev[0]), pb = p3<M, T>(m, ev[1]);
        if ((dist(pa, a) < 1e-9 && dist(pb, b) < 1e-9) || (dist(pa, b) < 1e-9 && dist(pb, a) < 1e-9)) return e;
    }
    ADD_FAILURE() << "no edge between (" << a[0] << ", " << a[1] << ") and (" << b[0] << ", " << b[1] << ")";
    return typename T::edge_handle();
}

/// The true area of f (half the length of its Newell normal).
template <class M, class T = hmira::default_traits<M>>
double face_area(const M& m, typename T::face_handle f) {
    const auto n = newell<M, T>(m, f);
    return std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) / 2;
}

template <class M, class T = hmira::default_traits<M>>
double total_area(const M& m) {
    double a = 0;
    for (auto f : T::faces(m)) a += face_area<M, T>(m, f);
    return a;
}

/// Every vertex stays in the grid's plane and every face faces +z (no face folded over).
template <class M, class T = hmira::default_traits<M>>
::testing::AssertionResult flat_and_facing_up(const M& m) {
    for (auto v : T::vertices(m))
        if (p3<M, T>(m, v)[2] != 0)
            return ::testing::AssertionFailure() << "vertex " << T::vertex_index(m, v) << " left the plane";
    for (auto f : T::faces(m))
        if (!(newell<M, T>(m, f)[2] > 0))
            return ::testing::AssertionFailure() << "face " << T::face_index(m, f) << " does not face +z";
    return ::testing::AssertionSuccess();
}

/// Everything "unchanged" compares: counts, each live vertex's index and position, and the
/// faces as loops of vertex indices.
template <class M, class T = hmira::default_traits<M>>
struct snapshot {
    counts c;
    std::vector<std::pair<std::size_t, std::array<double, 3>>> positions;
    std::multiset<std::vector<std::size_t>> faces;
    explicit snapshot(const M& m) : c(count<M, T>(m)), faces(canonical_faces<M, T>(m)) {
        for (auto v : T::vertices(m)) positions.push_back({T::vertex_index(m, v), p3<M, T>(m, v)});
    }
    friend bool operator==(const snapshot&, const snapshot&) = default;
};

/// The sum of the strip faces' areas.
template <class M, class R>
double strip_area(const M& m, const R& r) {
    double a = 0;
    for (auto f : r.strip_faces) a += face_area(m, f);
    return a;
}

constexpr double w = 0.2;  // the bevel width of these tests: far from any clamp

TYPED_TEST(bevel_boundary_test, one_boundary_edge_gives_a_strip_in_its_one_face_and_keeps_its_ends) {
    // Bottom edge (1,0)-(2,0) of a 3 x 2 grid; both ends have degree 3, their corners in the
    // face slide along the vertical edges (1,0)-(1,1) and (2,0)-(2,1). Flat: 2 slides (V + 2,
    // E + 2), one cut (E + 1, F + 1). With s segments the end edges (1,0)-(1,w) and (2,0)-(2,w)
    // are split s - 1 times each and the strip cut s - 1 times: V + 2s, E + 3s, F + s.
    for (long long s : {1, 2, 3, 5}) {
        SCOPED_TRACE(::testing::Message() << "segments " << s);
        auto m = open_grid<TypeParam>(3, 2);
        const auto before = count(m);
        auto r = hmira::bevel(m, edge_at(m, {1, 0, 0}, {2, 0, 0}), {.width = w, .segments = int(s)});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(valid_everywhere(m));
        EXPECT_EQ(count(m), (counts{before.v + 2 * s, before.e + 3 * s, before.f + s}));
        EXPECT_EQ(hmira::mesh_topology(m).boundary_loops, 1u);
        EXPECT_TRUE(flat_and_facing_up(m));
        EXPECT_NEAR(total_area(m), 6.0, 6.0 * area_tol<TypeParam>());
        ASSERT_EQ(r->strip_faces.size(), std::size_t(s));
        // The strip is the band 0 <= y <= w under the edge, cut into s equal bands.
        EXPECT_NEAR(strip_area(m, *r), w, area_tol<TypeParam>());
        for (auto f : r->strip_faces) EXPECT_NEAR(face_area(m, f), w / double(s), area_tol<TypeParam>());
        EXPECT_TRUE(has_vertex_at(m, {1, 0, 0}));
        EXPECT_TRUE(has_vertex_at(m, {2, 0, 0}));
        for (long long j = 1; j <= s; ++j) {
            EXPECT_TRUE(has_vertex_at(m, {1, w * double(j) / double(s), 0}));
            EXPECT_TRUE(has_vertex_at(m, {2, w * double(j) / double(s), 0}));
        }
        EXPECT_DOUBLE_EQ(r->width, w);
        EXPECT_EQ(r->limited_edges, 0u);
    }
}

TYPED_TEST(bevel_boundary_test, a_run_of_boundary_edges_shares_one_slide_where_two_strips_meet) {
    // The whole bottom side of a 3 x 2 grid: k = 3 edges through 4 boundary vertices, each of
    // which gets one slid point (the corners (0,0) and (3,0) along the vertical boundary
    // edges; (1,0) and (2,0) shared by both strips). Flat: V + 4, E + 4 + 3, F + 3; with s
    // segments the 4 end edges are split s - 1 times and each strip cut s - 1 times:
    // V + 4s, E + 4s + 3s, F + 3s.
    for (long long s : {1, 2, 4}) {
        SCOPED_TRACE(::testing::Message() << "segments " << s);
        auto m = open_grid<TypeParam>(3, 2);
        const auto before = count(m);
        std::vector<typename hmira::default_traits<TypeParam>::edge_handle> es;
        for (int i = 0; i < 3; ++i) es.push_back(edge_at(m, {double(i), 0, 0}, {double(i + 1), 0, 0}));
        auto r = hmira::bevel(m, es, {.width = w, .segments = int(s)});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(valid_everywhere(m));
        EXPECT_EQ(count(m), (counts{before.v + 4 * s, before.e + 7 * s, before.f + 3 * s}));
        EXPECT_TRUE(flat_and_facing_up(m));
        EXPECT_NEAR(total_area(m), 6.0, 6.0 * area_tol<TypeParam>());
        EXPECT_NEAR(strip_area(m, *r), 3 * w, area_tol<TypeParam>());
        EXPECT_TRUE(has_vertex_at(m, {0, w, 0}));
        EXPECT_TRUE(has_vertex_at(m, {3, w, 0}));
        EXPECT_EQ(hmira::mesh_topology(m).boundary_loops, 1u);
    }
}

TYPED_TEST(bevel_boundary_test, the_whole_boundary_loop_gives_a_frame_with_mitres_at_the_corners) {
    // All K = 2 (3 + 2) = 10 boundary edges of a 3 x 2 grid. The 6 side vertices slide along
    // their inner edge; each of the 4 corners (degree 2, both edges bevelled) gets an inner
    // point at (w, w) from it, hung by makeEV: K new points, K end edges, K cuts. Flat:
    // V + 10, E + 20, F + 10; with s segments each end edge is split s - 1 times and each strip
    // cut s - 1 times: V + 10s, E + 20s, F + 10s. The strips fill the frame between the old
    // boundary and the rectangle inset by w: 6 - (3 - 2w)(2 - 2w).
    for (long long s : {1, 2, 3}) {
        SCOPED_TRACE(::testing::Message() << "segments " << s);
        auto m = open_grid<TypeParam>(3, 2);
        const auto before = count(m);
        std::vector<typename hmira::default_traits<TypeParam>::edge_handle> es;
        using T = hmira::default_traits<TypeParam>;
        for (auto e : T::edges(m)) {
            const auto h = T::edge_halfedge(m, e);
            if (T::face(m, h) == T::null_face() || T::face(m, T::opposite(m, h)) == T::null_face()) es.push_back(e);
        }
        ASSERT_EQ(es.size(), 10u);
        auto r = hmira::bevel(m, es, {.width = w, .segments = int(s)});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(valid_everywhere(m));
        EXPECT_EQ(count(m), (counts{before.v + 10 * s, before.e + 20 * s, before.f + 10 * s}));
        EXPECT_TRUE(flat_and_facing_up(m));
        EXPECT_NEAR(total_area(m), 6.0, 6.0 * area_tol<TypeParam>());
        EXPECT_NEAR(strip_area(m, *r), 6.0 - (3 - 2 * w) * (2 - 2 * w), area_tol<TypeParam>());
        for (auto p : std::vector<std::array<double, 3>>{{w, w, 0}, {3 - w, w, 0}, {3 - w, 2 - w, 0}, {w, 2 - w, 0}})
            EXPECT_TRUE(has_vertex_at(m, p));
        // The corners stay on the boundary.
        EXPECT_TRUE(has_vertex_at(m, {0, 0, 0}));
        EXPECT_TRUE(has_vertex_at(m, {3, 2, 0}));
    }
}

TYPED_TEST(bevel_boundary_test, an_interior_edge_ending_on_the_boundary_dissolves_its_boundary_end) {
    // Interior edge (1,0)-(1,1) of a 3 x 2 grid (no boundary edge selected): its boundary end
    // (1,0) has degree 3 and every corner next to the edge, so it goes: its two slid points on
    // the boundary are joined by one (boundary) edge. (1,1) has degree 4 and stays: the strip
    // ends in it. Flat: 4 slides (V + 4, E + 4), two cuts and the kill of the edge (E + 1,
    // F + 1), (1,0) dissolved (V - 1, E - 1): V + 3, E + 4, F + 1. With s segments the one end
    // edge is split s - 1 times and the strip cut s - 1 times (a fan from (1,1)):
    // V + 3 + (s - 1), E + 4 + 2 (s - 1), F + 1 + (s - 1).
    for (long long s : {1, 2, 3}) {
        SCOPED_TRACE(::testing::Message() << "segments " << s);
        auto m = open_grid<TypeParam>(3, 2);
        const auto before = count(m);
        auto r = hmira::bevel(m, edge_at(m, {1, 0, 0}, {1, 1, 0}), {.width = w, .segments = int(s)});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(valid_everywhere(m));
        EXPECT_EQ(count(m), (counts{before.v + 3 + (s - 1), before.e + 4 + 2 * (s - 1), before.f + 1 + (s - 1)}));
        EXPECT_TRUE(flat_and_facing_up(m));
        EXPECT_NEAR(total_area(m), 6.0, 6.0 * area_tol<TypeParam>());
        if (s % 2) {
            EXPECT_FALSE(has_vertex_at(m, {1, 0, 0}));  // even s: an arc point lands there
        }
        EXPECT_TRUE(has_vertex_at(m, {1 - w, 0, 0}));
        EXPECT_TRUE(has_vertex_at(m, {1 + w, 0, 0}));
        // The strip: the band |x - 1| <= w from y = 0 to y = 1 (its tip (1,1) lies on the line
        // through the two slid points there).
        EXPECT_NEAR(strip_area(m, *r), 2 * w, area_tol<TypeParam>() * 10);
    }
}

TYPED_TEST(bevel_boundary_test, boundary_and_interior_edges_meeting_at_a_boundary_vertex_keep_it) {
    // Interior edge a = (1,0)-(1,1) and boundary edge b = (1,0)-(2,0) of a 3 x 2 grid. At (1,0)
    // (degree 3) the corner between a and the left boundary edge slides along that edge, the
    // corner between a and b gets an inner point (1 + w, w); (1,0) stays because b's strip runs
    // along the boundary up to it. (1,1) keeps a's other end (2 slides), (2,0) keeps b's (1
    // slide up (2,0)-(2,1)). Flat: 5 new points (V + 5, E + 5), a: two cuts and a kill (E + 1,
    // F + 1), b: one cut (E + 1, F + 1): V + 5, E + 7, F + 2. With s segments a's strip has
    // both ends pointed and stays one face; b's two end edges are split s - 1 times each and
    // its strip cut s - 1 times: V + 5 + 2 (s - 1), E + 7 + 3 (s - 1), F + 2 + (s - 1).
    for (long long s : {1, 2, 3}) {
        SCOPED_TRACE(::testing::Message() << "segments " << s);
        auto m = open_grid<TypeParam>(3, 2);
        const auto before = count(m);
        std::vector<typename hmira::default_traits<TypeParam>::edge_handle> es{edge_at(m, {1, 0, 0}, {1, 1, 0}),
                                                                               edge_at(m, {1, 0, 0}, {2, 0, 0})};
        auto r = hmira::bevel(m, es, {.width = w, .segments = int(s)});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(valid_everywhere(m));
        EXPECT_EQ(count(m), (counts{before.v + 5 + 2 * (s - 1), before.e + 7 + 3 * (s - 1), before.f + 2 + (s - 1)}));
        EXPECT_TRUE(flat_and_facing_up(m));
        EXPECT_NEAR(total_area(m), 6.0, 6.0 * area_tol<TypeParam>());
        EXPECT_TRUE(has_vertex_at(m, {1, 0, 0}));
        EXPECT_TRUE(has_vertex_at(m, {1 + w, w, 0}));
        EXPECT_TRUE(has_vertex_at(m, {1 - w, 0, 0}));
        EXPECT_TRUE(has_vertex_at(m, {2, w, 0}));
        // b's strip: the trapezoid (1,0) (2,0) (2,w) (1+w,w), w (2 - w) / 2; a's: the band
        // |x - 1| <= w from y = 0 to 1 less the triangle (1,0) (1+w,0) (1+w,w) that b took.
        EXPECT_NEAR(strip_area(m, *r), w * (2 - w) / 2 + (2 * w - w * w / 2), area_tol<TypeParam>() * 10);
    }
}

TYPED_TEST(bevel_boundary_test, a_refused_boundary_bevel_leaves_the_mesh_unchanged) {
    using T = hmira::default_traits<TypeParam>;
    // A pentagon with a straight corner at (1,0): the offset of the boundary edge
    // (0,0)-(1,0) there is undefined (collinear edges), so the bevel is refused, also when
    // good edges come first in the selection.
    {
        TypeParam m;
        face_list p;
        p.points = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}};
        p.faces = {{0, 1, 2, 3, 4}};
        ASSERT_TRUE(add_face_list(m, p));
        const snapshot<TypeParam> before(m);
        std::vector<typename T::edge_handle> es{edge_at(m, {2, 0, 0}, {2, 1, 0}), edge_at(m, {0, 0, 0}, {1, 0, 0})};
        for (int s : {1, 3}) {
            auto r = hmira::bevel(m, es, {.width = w, .segments = s});
            ASSERT_FALSE(r);
            EXPECT_EQ(r.error().code, hmira::errc::unsupported) << r.error().message;
            EXPECT_NE(r.error().message.find("collinear"), std::string::npos) << r.error().message;
            EXPECT_TRUE(snapshot<TypeParam>(m) == before);
            EXPECT_TRUE(valid_everywhere(m));
        }
    }
    // A bowtie: the boundary edge c-a ends in a pinched vertex (two boundary gaps).
    {
        TypeParam m;
        const auto c = T::add_vertex(m, {0, 0, 0});
        const auto a = T::add_vertex(m, {1, 0, 0}), b = T::add_vertex(m, {1, 1, 0});
        const auto d = T::add_vertex(m, {-1, 0, 0}), e = T::add_vertex(m, {-1, -1, 0});
        const typename T::vertex_handle f1[] = {c, a, b}, f2[] = {c, d, e};
        if (!T::add_face(m, f1) || !T::add_face(m, f2)) return;  // the model holds no pinched vertex
        const snapshot<TypeParam> before(m);
        auto r = hmira::bevel(m, edge_at(m, {0, 0, 0}, {1, 0, 0}), {.width = w});
        ASSERT_FALSE(r);
        EXPECT_EQ(r.error().code, hmira::errc::non_manifold) << r.error().message;
        EXPECT_TRUE(snapshot<TypeParam>(m) == before);
    }
}

TYPED_TEST(bevel_boundary_test, random_selections_on_an_open_grid_keep_it_valid_with_its_projected_area) {
    // Any selection of boundary and interior edges, flat or rounded: the result validates, the
    // native checker agrees, and since the boundary keeps its shape (kept ends, slides along
    // straight sides) the area projected on the grid's plane stays 4 x 3 = 12 exactly
    // (corner patches of rounded bevels may leave the plane, the projection may not change).
    using T = hmira::default_traits<TypeParam>;
    std::mt19937_64 rng(13);
    for (int trial = 0; trial < 40; ++trial) {
        SCOPED_TRACE(::testing::Message() << "trial " << trial);
        auto m = open_grid<TypeParam>(4, 3);
        std::vector<typename T::edge_handle> es;
        const double p = std::uniform_real_distribution<double>(0.1, 0.6)(rng);
        for (auto e : T::edges(m))
            if (std::bernoulli_distribution(p)(rng)) es.push_back(e);
        if (es.empty()) continue;
        const int s = std::uniform_int_distribution<int>(1, 4)(rng);
        const snapshot<TypeParam> before(m);
        auto r = hmira::bevel(m, es, {.width = w, .segments = s});
        if (!r) {
            EXPECT_TRUE(snapshot<TypeParam>(m) == before) << r.error().message;
            ADD_FAILURE() << "a bevel of grid edges at width " << w << " was refused: " << r.error().message;
            continue;
        }
        EXPECT_TRUE(valid_everywhere(m));
        double projected = 0;
        for (auto f : T::faces(m)) projected += newell(m, f)[2] / 2;
        EXPECT_NEAR(projected, 12.0, 12.0 * area_tol<TypeParam>());
    }
}

}  // namespace
