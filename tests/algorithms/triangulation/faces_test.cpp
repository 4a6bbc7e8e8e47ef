// face_triangles and triangulate_faces on every model: a concave face in a tilted plane, a
// face with an inner ring, whole meshes (area and enclosed volume kept, every face a
// triangle, the mesh valid), and a self-crossing face refused by name with the mesh unchanged.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include <hmira/algorithms/euler/euler.hpp>
#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/triangulation/triangulate_faces.hpp>

#include "algorithms/euler/euler_support.hpp"
#include "support/models.hpp"

namespace {

using namespace hmira_test;

template <class M>
class triangulate_faces_test : public ::testing::Test {};
TYPED_TEST_SUITE(triangulate_faces_test, all_models);

using arr3 = std::array<double, 3>;

template <class M, class T = hmira::default_traits<M>>
arr3 pos(const M& m, typename T::vertex_handle v) {
    const auto p = T::position(m, v);
    return {double(p[0]), double(p[1]), double(p[2])};
}
arr3 tri_normal(const arr3& a, const arr3& b, const arr3& c) {
    const arr3 u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}
double norm(const arr3& n) { return std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]); }

/// An L-shaped hexagon (area 3) in the plane z = x + 2y... tilted: mapped by (x, y) -> (x, y, 0.5x + 0.25y).
face_list l_shape() {
    face_list g;
    for (auto [x, y] : {std::pair{0.0, 0.0}, {2.0, 0.0}, {2.0, 1.0}, {1.0, 1.0}, {1.0, 2.0}, {0.0, 2.0}})
        g.points.push_back({x, y, 0.5 * x + 0.25 * y});
    g.faces.push_back({0, 1, 2, 3, 4, 5});
    return g;
}

TYPED_TEST(triangulate_faces_test, a_concave_face_in_a_tilted_plane_becomes_four_triangles_covering_its_area) {
    using M = TypeParam;
    using T = hmira::default_traits<M>;
    if constexpr (requires { requires T::triangles_only; }) {
        GTEST_SKIP() << "triangles only";
    } else {
        M m = mesh_from<M>(l_shape());
        const auto f = *T::faces(m).begin();
        auto r = hmira::face_triangles(m, f);
        ASSERT_TRUE(r) << r.error().message;
        ASSERT_EQ(r->size(), 4u);
        // The plane's unit normal: (-0.5, -0.25, 1) / |.|; area scales by |n| / n_z.
        const arr3 n{-0.5, -0.25, 1.0};
        double area = 0;
        for (const auto& t : *r) {
            const auto tn = tri_normal(pos(m, t[0]), pos(m, t[1]), pos(m, t[2]));
            EXPECT_GT(tn[0] * n[0] + tn[1] * n[1] + tn[2] * n[2], 0) << "a triangle is wound against the face";
            area += norm(tn) / 2;
        }
        EXPECT_NEAR(area, 3.0 * norm(n), 1e-5);
    }
}

TYPED_TEST(triangulate_faces_test, a_self_crossing_face_is_refused_by_name_and_the_mesh_is_unchanged) {
    using M = TypeParam;
    using T = hmira::default_traits<M>;
    if constexpr (requires { requires T::triangles_only; }) {
        GTEST_SKIP() << "triangles only";
    } else {
        face_list g = l_shape();
        g.points.insert(g.points.end(), {{5, 0, 0}, {7, 1, 0}, {7, 0, 0}, {5, 1.5, 0}});
        g.faces.push_back({6, 7, 8, 9});  // a bow tie: edges 6-7 and 8-9 cross (net area nonzero)
        M m = mesh_from<M>(g);
        const auto bowtie = T::face_index(m, *std::next(T::faces(m).begin()));
        for (auto f : T::faces(m)) {
            auto r = hmira::face_triangles(m, f);
            if (T::face_index(m, f) != bowtie) continue;
            ASSERT_FALSE(r);
            EXPECT_EQ(r.error().code, hmira::errc::topology);
            EXPECT_NE(r.error().message.find("face " + std::to_string(bowtie)), std::string::npos) << r.error().message;
        }
        if constexpr (hmira::euler_mutable_mesh<M> && indexed_halfedge_model<M>) {
            const auto before = take_snapshot(m);
            auto r = hmira::triangulate_faces(m);
            ASSERT_FALSE(r);
            EXPECT_NE(r.error().message.find("face " + std::to_string(bowtie)), std::string::npos) << r.error().message;
            EXPECT_EQ(take_snapshot(m), before);
        }
    }
}

TYPED_TEST(triangulate_faces_test, a_whole_mesh_becomes_triangles_with_its_volume_kept) {
    using M = TypeParam;
    using T = hmira::default_traits<M>;
    if constexpr (!hmira::euler_mutable_mesh<M> || !indexed_halfedge_model<M>) {
        GTEST_SKIP() << "not an euler_mutable_mesh";
    } else {
        for (int shape = 0; shape < 3; ++shape) {
            M m;
            if (shape == 0) m = mesh_from<M>(torus(12, 8));
            if (shape == 1) {
                ASSERT_TRUE(hmira::generate_dodecahedron(m));
            }
            if (shape == 2) m = mesh_from<M>(l_shape());
            const auto v0 = T::vertex_count(m);
            const auto chi0 = (long long)T::vertex_count(m) - (long long)T::edge_count(m) + (long long)T::face_count(m);
            const double vol0 = signed_volume(m);
            std::size_t expected_faces = 0;
            for (auto f : T::faces(m)) expected_faces += std::size_t(std::ranges::distance(T::face_vertices(m, f))) - 2;
            auto r = hmira::triangulate_faces(m);
            ASSERT_TRUE(r) << r.error().message;
            EXPECT_TRUE(hmira_test::is_valid(m));
            EXPECT_EQ(T::vertex_count(m), v0);
            EXPECT_EQ(T::face_count(m), expected_faces);
            EXPECT_EQ((long long)T::vertex_count(m) - (long long)T::edge_count(m) + (long long)T::face_count(m), chi0);
            for (auto f : T::faces(m)) EXPECT_EQ(std::ranges::distance(T::face_vertices(m, f)), 3);
            EXPECT_NEAR(signed_volume(m), vol0, 1e-5 * (1 + std::fabs(vol0)));
        }
    }
}

/// The cube [-1,1]^3 whose top face has a square hole of half-size a, closed by a square face
/// (as in the extrude suite: makeEV chain, makeEF, killEmakeR).
template <class M, class T = hmira::default_traits<M>>
typename T::face_handle cube_with_ringed_top(M& m, double a) {
    using S = typename T::scalar;
    auto cube = hmira::generate_cube(m).value();
    const auto corner = T::face_halfedge(m, cube.faces[5]);
    const hmira::vec3<S> q[4] = {{S(-a), 1, S(-a)}, {S(-a), 1, S(a)}, {S(a), 1, S(a)}, {S(a), 1, S(-a)}};
    auto p0 = hmira::make_edge_vertex(m, corner, q[0]).value();
    auto prev = p0.halfedge;
    for (int i = 1; i < 4; ++i) prev = hmira::make_edge_vertex(m, prev, q[i]).value().halfedge;
    EXPECT_TRUE(hmira::make_edge_face(m, prev, p0.halfedge));
    const auto ring = hmira::kill_edge_make_ring(m, p0.halfedge).value();
    return T::face(m, ring.ring);
}

TYPED_TEST(triangulate_faces_test, a_face_with_an_inner_ring_is_triangulated_around_the_hole) {
    using M = TypeParam;
    using T = hmira::default_traits<M>;
    if constexpr (!hmira::euler_ring_mutable_mesh<M> || !indexed_halfedge_model<M>) {
        GTEST_SKIP() << "no inner rings";
    } else {
        M m;
        const auto top = cube_with_ringed_top(m, 0.5);
        auto r = hmira::face_triangles(m, top);
        ASSERT_TRUE(r) << r.error().message;
        // 8 corners, one hole: 8 + 2 - 2 = 8 triangles covering 4 - 1 = 3, all facing +y.
        EXPECT_EQ(r->size(), 8u);
        double area = 0;
        for (const auto& t : *r) {
            const auto tn = tri_normal(pos(m, t[0]), pos(m, t[1]), pos(m, t[2]));
            EXPECT_GT(tn[1], 0);
            area += norm(tn) / 2;
        }
        EXPECT_NEAR(area, 3.0, 1e-12);

        auto all = hmira::triangulate_faces(m);
        ASSERT_TRUE(all) << all.error().message;
        EXPECT_TRUE(hmira_test::is_valid(m));
        for (auto f : T::faces(m)) {
            EXPECT_EQ(std::ranges::distance(T::face_vertices(m, f)), 3);
            EXPECT_TRUE(std::ranges::empty(T::inner_rings(m, f)));
        }
        // A closed genus-0 surface again: V - E + F = 2; the cube's volume.
        EXPECT_EQ((long long)T::vertex_count(m) - (long long)T::edge_count(m) + (long long)T::face_count(m), 2);
        EXPECT_NEAR(signed_volume(m), 8.0, 1e-12);
    }
}

}  // namespace
