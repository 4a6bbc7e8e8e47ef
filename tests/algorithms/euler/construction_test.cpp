// Builds a cube and a genus-1 solid (a cube with a square through-hole) from nothing with the
// Euler operators only, checking validity and V - E + F - R = 2 (S - H) after every step,
// with S and H tracked here; then takes both apart again with the inverses.

#include <gtest/gtest.h>

#include <functional>
#include <vector>

#include <hmira/algorithms/euler/euler.hpp>

#include "algorithms/euler/euler_support.hpp"
#include "support/models.hpp"

namespace {

using hmira::vec3;

template <class M>
class euler_construction : public ::testing::Test {};

TYPED_TEST_SUITE(euler_construction, hmira_test::all_models);

/// Runs the construction, keeping S and H and an undo list; every step is checked.
template <class M>
struct builder {
    using T = hmira::default_traits<M>;
    using V = typename T::vertex_handle;
    using H = typename T::halfedge_handle;
    using F = typename T::face_handle;
    M mesh;
    long long shells = 0, holes = 0;
    std::vector<std::function<void()>> undo;

    ::testing::AssertionResult check(const char* what) {
        auto valid = hmira_test::is_valid_relaxed<M>(mesh);
        if (!valid) return ::testing::AssertionFailure() << "after " << what << ": " << valid.message();
        auto euler = hmira_test::euler_poincare_holds<M>(mesh, shells - holes);
        if (!euler) return ::testing::AssertionFailure() << "after " << what << ": " << euler.message();
        return ::testing::AssertionSuccess();
    }
    H he(V a, V b) { return hmira_test::find_halfedge<M>(mesh, a, b); }
    // Undo steps name halfedges by their end vertices: an edge killed and made again by a
    // later step (and its undo) comes back under a new handle.
    std::pair<V, V> ends(H h) { return {T::target(mesh, T::opposite(mesh, h)), T::target(mesh, h)}; }
    H he(std::pair<V, V> e) { return he(e.first, e.second); }

    static vec3<typename T::scalar> at(vec3<double> p) {
        using S = typename T::scalar;
        return {S(p.x), S(p.y), S(p.z)};
    }
    V mv(vec3<double> p) {
        auto r = hmira::make_vertex(mesh, at(p));
        ++shells;
        undo.push_back([this, v = r.vertex] {
            ASSERT_TRUE(hmira::kill_vertex(mesh, v));
            --shells;
        });
        return r.vertex;
    }
    template <class Corner>
    V mev(Corner corner, vec3<double> p) {
        auto r = hmira::make_edge_vertex(mesh, corner, at(p));
        EXPECT_TRUE(r) << r.error().message;
        undo.push_back([this, e = ends(r->halfedge)] { ASSERT_TRUE(hmira::kill_edge_vertex(mesh, he(e))); });
        return r->vertex;
    }
    F mef(H h0, H h1) {
        auto r = hmira::make_edge_face(mesh, h0, h1);
        EXPECT_TRUE(r) << r.error().message;
        undo.push_back([this, e = ends(r->halfedge)] {
            auto k = hmira::kill_edge_face(mesh, he(e));
            ASSERT_TRUE(k) << k.error().message;
        });
        return r->face;
    }
    F fill(H h) {
        auto r = hmira::fill_boundary_loop(mesh, h);
        EXPECT_TRUE(r) << r.error().message;
        undo.push_back([this, e = ends(h)] { ASSERT_TRUE(hmira::open_face(mesh, T::face(mesh, he(e)))); });
        return r->face;
    }
    void kemr(H h) {
        auto r = hmira::kill_edge_make_ring(mesh, h);
        ASSERT_TRUE(r) << r.error().message;
        undo.push_back([this, h0 = ends(r->h0), h1 = ends(r->h1)] {
            auto m = hmira::make_edge_kill_ring(mesh, he(h0), he(h1));
            ASSERT_TRUE(m) << m.error().message;
        });
    }
    void kfmr(F f, F host) {
        auto r = hmira::kill_face_make_ring(mesh, f, host);
        ASSERT_TRUE(r) << r.error().message;
        ++holes;  // both faces are on the one shell: the ring opens a through-hole
        undo.push_back([this, ring = ends(r->ring)] {
            auto m = hmira::make_face_kill_ring(mesh, he(ring));
            ASSERT_TRUE(m) << m.error().message;
            --holes;
        });
    }
    /// Undoes everything, newest first, checking each intermediate state.
    void take_apart() {
        while (!undo.empty()) {
            undo.back()();
            undo.pop_back();
            ASSERT_TRUE(check("an inverse"));
        }
    }
};

struct cube_vertices {
    // The thesis's [-1, 1]^3 cube: a b c d at the bottom (z = -1), e f g h above them.
    template <class V>
    struct named {
        V a, b, c, d, e, f, g, h;
    };
};

/// Mantyla's cube: makeV, 3 makeEV and a makeEF for the bottom face, 4 makeEV up the sides,
/// 4 makeEF for the side faces, and the remaining boundary loop becomes the top face.
template <class M>
auto build_cube(builder<M>& b) {
    using V = typename builder<M>::V;
    cube_vertices::named<V> n;
    n.a = b.mv({-1, -1, -1});
    EXPECT_TRUE(b.check("makeV a"));
    n.b = b.mev(n.a, {1, -1, -1});
    EXPECT_TRUE(b.check("makeEV a-b"));
    n.c = b.mev(b.he(n.a, n.b), {1, 1, -1});
    EXPECT_TRUE(b.check("makeEV b-c"));
    n.d = b.mev(b.he(n.b, n.c), {-1, 1, -1});
    EXPECT_TRUE(b.check("makeEV c-d"));
    // The bottom face a d c b (seen from below) goes on the side of b->a.
    b.mef(b.he(n.c, n.d), b.he(n.b, n.a));
    EXPECT_TRUE(b.check("makeEF bottom"));
    n.e = b.mev(b.he(n.d, n.a), {-1, -1, 1});
    n.f = b.mev(b.he(n.a, n.b), {1, -1, 1});
    n.g = b.mev(b.he(n.b, n.c), {1, 1, 1});
    n.h = b.mev(b.he(n.c, n.d), {-1, 1, 1});
    EXPECT_TRUE(b.check("makeEV up the sides"));
    b.mef(b.he(n.a, n.e), b.he(n.b, n.f));  // a b f e
    EXPECT_TRUE(b.check("makeEF side 1"));
    b.mef(b.he(n.e, n.f), b.he(n.c, n.g));  // b c g f
    EXPECT_TRUE(b.check("makeEF side 2"));
    b.mef(b.he(n.f, n.g), b.he(n.d, n.h));  // c d h g
    EXPECT_TRUE(b.check("makeEF side 3"));
    b.mef(b.he(n.g, n.h), b.he(n.a, n.e));  // d a e h
    EXPECT_TRUE(b.check("makeEF side 4"));
    b.fill(b.he(n.e, n.f));  // e f g h
    EXPECT_TRUE(b.check("filling the top"));
    return n;
}

TYPED_TEST(euler_construction, cube_from_nothing_matches_the_generated_cube_and_comes_apart_again) {
    if constexpr (!hmira::euler_mutable_mesh<TypeParam> || !hmira_test::indexed_halfedge_model<TypeParam>) {
        GTEST_SKIP() << "not an euler_mutable_mesh (no raw halfedge layer, or triangles only)";
    } else {
        builder<TypeParam> b;
        build_cube(b);
        EXPECT_EQ(b.shells, 1);
        EXPECT_TRUE(hmira_test::is_valid<TypeParam>(b.mesh));  // strict: a closed surface
        const auto k = hmira_test::count_euler<TypeParam>(b.mesh);
        EXPECT_EQ(k.v, 8);
        EXPECT_EQ(k.e, 12);
        EXPECT_EQ(k.faces, 6);
        EXPECT_EQ(k.boundary_loops, 0);
        EXPECT_NEAR(hmira_test::signed_volume<TypeParam>(b.mesh), 8.0, 1e-12);

        // The cube written out by hand, each face counter-clockwise seen from outside.
        using P = hmira_test::point_key;
        const P A{-1, -1, -1}, B{1, -1, -1}, C{1, 1, -1}, D{-1, 1, -1}, E{-1, -1, 1}, F{1, -1, 1}, G{1, 1, 1},
            H{-1, 1, 1};
        hmira_test::canonical_form expected;
        for (auto l :
             {std::vector<P>{A, D, C, B}, {A, B, F, E}, {B, C, G, F}, {C, D, H, G}, {D, A, E, H}, {E, F, G, H}}) {
            std::rotate(l.begin(), std::min_element(l.begin(), l.end()), l.end());
            expected.faces.insert({l, {}});
        }
        EXPECT_TRUE(hmira_test::canonical<TypeParam>(b.mesh) == expected);

        b.take_apart();
        EXPECT_EQ(hmira::default_traits<TypeParam>::vertex_count(b.mesh), 0u);
        EXPECT_EQ(hmira::default_traits<TypeParam>::edge_count(b.mesh), 0u);
        EXPECT_EQ(hmira::default_traits<TypeParam>::face_count(b.mesh), 0u);
    }
}

TYPED_TEST(euler_construction, genus_one_solid_from_nothing_has_the_expected_faces_and_rings) {
    if constexpr (!hmira::euler_ring_mutable_mesh<TypeParam> || !hmira_test::indexed_halfedge_model<TypeParam>) {
        GTEST_SKIP() << "the model has no inner rings";
    } else {
        using T = hmira::default_traits<TypeParam>;
        builder<TypeParam> b;
        const auto n = build_cube(b);
        const auto top = T::face(b.mesh, b.he(n.e, n.f));
        const auto bottom = T::face(b.mesh, b.he(n.a, n.d));

        // A square ring in the top face: a strut from e, three more edges, a face closing the
        // inner square, then the strut dies and leaves the square's outline as a ring.
        const auto p0 = b.mev(b.he(n.h, n.e), {-0.5, -0.5, 1});
        const auto p1 = b.mev(b.he(n.e, p0), {0.5, -0.5, 1});
        const auto p2 = b.mev(b.he(p0, p1), {0.5, 0.5, 1});
        const auto p3 = b.mev(b.he(p1, p2), {-0.5, 0.5, 1});
        ASSERT_TRUE(b.check("the strut and the inner square's sides"));
        const auto inner = b.mef(b.he(n.e, p0), b.he(p2, p3));
        ASSERT_TRUE(b.check("makeEF inner square"));
        b.kemr(b.he(n.e, p0));
        ASSERT_TRUE(b.check("killEmakeR strut"));
        ASSERT_EQ(std::ranges::distance(T::inner_rings(b.mesh, top)), 1);

        // Sink the inner square to the bottom: four struts down, four tunnel walls.
        const auto q0 = b.mev(b.he(p3, p0), {-0.5, -0.5, -1});
        const auto q1 = b.mev(b.he(p0, p1), {0.5, -0.5, -1});
        const auto q2 = b.mev(b.he(p1, p2), {0.5, 0.5, -1});
        const auto q3 = b.mev(b.he(p2, p3), {-0.5, 0.5, -1});
        ASSERT_TRUE(b.check("struts down the tunnel"));
        b.mef(b.he(p0, q0), b.he(p1, q1));
        b.mef(b.he(q0, q1), b.he(p2, q2));
        b.mef(b.he(q1, q2), b.he(p3, q3));
        b.mef(b.he(q2, q3), b.he(p0, q0));
        ASSERT_TRUE(b.check("tunnel walls"));
        // What is left of the inner square now lies on the bottom, facing up, against the
        // bottom face: it becomes the bottom face's ring, and the solid gets its hole.
        ASSERT_EQ(T::face(b.mesh, b.he(q0, q1)), inner);
        b.kfmr(inner, bottom);
        ASSERT_TRUE(b.check("killFmakeR"));
        EXPECT_EQ(b.holes, 1);
        EXPECT_TRUE(hmira_test::is_valid<TypeParam>(b.mesh));

        const auto k = hmira_test::count_euler<TypeParam>(b.mesh);
        EXPECT_EQ(k.v, 16);
        EXPECT_EQ(k.e, 24);
        EXPECT_EQ(k.faces, 10);
        EXPECT_EQ(k.rings, 2);
        EXPECT_EQ(k.boundary_loops, 0);
        EXPECT_EQ(k.lhs(), 0);  // 2 (S - H) with S = 1, H = 1

        // The expected solid, written out by hand: 4 outer walls, 4 tunnel walls, top and
        // bottom with square rings wound against them.
        using P = hmira_test::point_key;
        auto loop = [](std::vector<P> l) {
            std::rotate(l.begin(), std::min_element(l.begin(), l.end()), l.end());
            return l;
        };
        const P A{-1, -1, -1}, B{1, -1, -1}, C{1, 1, -1}, D{-1, 1, -1}, E{-1, -1, 1}, F{1, -1, 1}, G{1, 1, 1},
            Hh{-1, 1, 1};
        const P P0{-0.5, -0.5, 1}, P1{0.5, -0.5, 1}, P2{0.5, 0.5, 1}, P3{-0.5, 0.5, 1};
        const P Q0{-0.5, -0.5, -1}, Q1{0.5, -0.5, -1}, Q2{0.5, 0.5, -1}, Q3{-0.5, 0.5, -1};
        hmira_test::canonical_form expected;
        expected.faces.insert({loop({A, B, F, E}), {}});
        expected.faces.insert({loop({B, C, G, F}), {}});
        expected.faces.insert({loop({C, D, Hh, G}), {}});
        expected.faces.insert({loop({D, A, E, Hh}), {}});
        expected.faces.insert({loop({E, F, G, Hh}), {loop({P0, P3, P2, P1})}});
        expected.faces.insert({loop({A, D, C, B}), {loop({Q0, Q1, Q2, Q3})}});
        expected.faces.insert({loop({P0, P1, Q1, Q0}), {}});
        expected.faces.insert({loop({P1, P2, Q2, Q1}), {}});
        expected.faces.insert({loop({P2, P3, Q3, Q2}), {}});
        expected.faces.insert({loop({P3, P0, Q0, Q3}), {}});
        EXPECT_TRUE(hmira_test::canonical<TypeParam>(b.mesh) == expected);

        b.take_apart();
        EXPECT_EQ(T::vertex_count(b.mesh), 0u);
        EXPECT_EQ(T::edge_count(b.mesh), 0u);
        EXPECT_EQ(T::face_count(b.mesh), 0u);
        EXPECT_EQ(b.shells, 0);
        EXPECT_EQ(b.holes, 0);
    }
}

}  // namespace
