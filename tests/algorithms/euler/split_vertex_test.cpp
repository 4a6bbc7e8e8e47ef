// The general makeEV (split_vertex) and its inverse (join_vertices) on every model that
// supports them: seeded random splits undone by joins in reverse order, and random joins
// redone by splits, restore the mesh exactly (same counts, same connectivity up to the new
// handles, same positions); every state in between is valid and satisfies Euler-Poincare;
// a join that would collapse a triangle, double an edge or pinch the surface is refused and
// changes nothing.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <string>
#include <vector>

#include <hmira/algorithms/euler/euler.hpp>

#include "algorithms/euler/euler_support.hpp"
#include "support/models.hpp"

namespace {

using namespace hmira_test;

template <class M>
class split_vertex_test : public ::testing::Test {};
TYPED_TEST_SUITE(split_vertex_test, all_models);

template <class M>
::testing::AssertionResult same_mesh(M a, M b) {
    compact(a);
    compact(b);
    if (canonical<M>(a) == canonical<M>(b)) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "the canonical forms differ";
}

/// The halfedges into v in rotation order (x -> opposite(next(x))), walked here.
template <class M, class T = hmira::default_traits<M>>
std::vector<typename T::halfedge_handle> incoming(const M& m, typename T::vertex_handle v) {
    std::vector<typename T::halfedge_handle> out;
    const auto s = T::vertex_halfedge(m, v);
    if (s == T::null_halfedge()) return out;
    auto x = T::opposite(m, s);
    do {
        out.push_back(x);
        x = T::opposite(m, T::next(m, x));
    } while (x != T::opposite(m, s) && out.size() < 10000);
    return out;
}

template <class M, class T = hmira::default_traits<M>>
std::set<point_key> neighbour_keys(const M& m, typename T::vertex_handle v) {
    std::set<point_key> out;
    for (auto x : incoming<M, T>(m, v)) out.insert(key_of<M, T>(m, T::target(m, T::opposite(m, x))));
    return out;
}

template <class M, class T = hmira::default_traits<M>>
bool on_boundary(const M& m, typename T::vertex_handle v) {
    for (auto x : incoming<M, T>(m, v))
        if (T::face(m, x) == T::null_face()) return true;
    return false;
}

template <class M, class T = hmira::default_traits<M>>
std::vector<typename T::vertex_handle> live_vertices(const M& m) {
    std::vector<typename T::vertex_handle> out;
    for (auto v : T::vertices(m))
        if (T::vertex_halfedge(m, v) != T::null_halfedge()) out.push_back(v);
    return out;
}

struct shape {
    const char* name;
    face_list faces;
    long long s_minus_h;
};

std::vector<shape> shapes() {
    return {{"quad grid", grid(4, 3), 1},
            {"triangle grid", grid(3, 3, true), 1},
            {"torus", torus(6, 5), 0},
            {"grid with a hole", without_faces(grid(4, 4), [](std::size_t f) { return f == 5 || f == 6; }), 1}};
}

/// Splits random vertices between random corners (n of them), each step checked against the
/// counts and degrees expected from the corners, then joins them back in reverse order.
template <class M>
void split_then_join_round_trip(const shape& s, std::uint64_t seed, int n) {
    using T = hmira::default_traits<M>;
    using H = typename T::halfedge_handle;
    SCOPED_TRACE(std::string(s.name) + ", seed " + std::to_string(seed));
    auto m = mesh_from<M>(s.faces);
    const auto start = m;
    std::mt19937_64 rng(seed);
    auto pick = [&](std::size_t k) { return std::uniform_int_distribution<std::size_t>(0, k - 1)(rng); };
    std::vector<H> made;
    for (int step = 0; step < n; ++step) {
        const auto vs = live_vertices(m);
        const auto v = vs[pick(vs.size())];
        const auto in = incoming(m, v);
        // Distinct corners keep a manifold polygon mesh manifold (an edge with a face or the
        // boundary on each side); equal corners, the antenna, are undone at once below.
        const std::size_t i0 = pick(in.size()), i1 = (i0 + 1 + pick(in.size() - 1)) % in.size();
        const std::size_t moved = (i1 + in.size() - i0) % in.size();  // edges strictly between the corners
        const auto before = count_euler(m);
        const hmira::vec3<typename T::scalar> p{typename T::scalar(10 + step), typename T::scalar(seed % 7),
                                                typename T::scalar(-3)};
        auto r = hmira::split_vertex(m, in[i0], in[i1], p);
        ASSERT_TRUE(r) << r.error().message;
        const auto after = count_euler(m);
        EXPECT_EQ(after.v, before.v + 1);
        EXPECT_EQ(after.e, before.e + 1);
        EXPECT_EQ(after.faces, before.faces);
        EXPECT_EQ(after.boundary_loops, before.boundary_loops);
        EXPECT_EQ(T::target(m, r->halfedge), r->vertex);
        EXPECT_EQ(T::target(m, T::opposite(m, r->halfedge)), v);
        EXPECT_EQ(incoming(m, r->vertex).size(), moved + 1);
        EXPECT_EQ(incoming(m, v).size(), in.size() - moved + 1);
        EXPECT_EQ(T::next(m, in[i0]), r->halfedge);
        EXPECT_EQ(T::face(m, r->halfedge), T::face(m, in[i0]));
        EXPECT_EQ(T::face(m, T::opposite(m, r->halfedge)), T::face(m, in[i1]));
        EXPECT_TRUE(is_valid_relaxed(m));
        EXPECT_TRUE(euler_poincare_holds(m, s.s_minus_h));
        made.push_back(r->halfedge);
        if (step % 5 == 0) {
            const auto corner = in[pick(in.size())];
            const auto before_antenna = m;
            auto a = hmira::split_vertex(m, corner, corner, {-1, -1, typename T::scalar(step)});
            ASSERT_TRUE(a) << a.error().message;
            EXPECT_EQ(T::next(m, a->halfedge), T::opposite(m, a->halfedge));
            EXPECT_TRUE(is_valid_relaxed(m));
            EXPECT_TRUE(euler_poincare_holds(m, s.s_minus_h));
            auto k = hmira::join_vertices(m, a->halfedge);
            ASSERT_TRUE(k) << k.error().message;
            EXPECT_EQ(k->h0, corner);
            EXPECT_TRUE(same_mesh(m, before_antenna));
        }
    }
    for (auto it = made.rbegin(); it != made.rend(); ++it) {
        const auto before = count_euler(m);
        auto k = hmira::join_vertices(m, *it);
        ASSERT_TRUE(k) << k.error().message;
        const auto after = count_euler(m);
        EXPECT_EQ(after.v, before.v - 1);
        EXPECT_EQ(after.e, before.e - 1);
        EXPECT_TRUE(is_valid_relaxed(m));
        EXPECT_TRUE(euler_poincare_holds(m, s.s_minus_h));
    }
    EXPECT_TRUE(hmira_test::is_valid(m));
    EXPECT_TRUE(same_mesh(m, start));
}

TYPED_TEST(split_vertex_test, random_splits_undone_by_joins_in_reverse_restore_the_mesh) {
    HMIRA_REQUIRE_EULER(TypeParam)
    else {
        for (const auto& s : shapes())
            for (std::uint64_t seed : {1u, 2u, 3u, 4u}) split_then_join_round_trip<TypeParam>(s, seed, 25);
    }
}

TYPED_TEST(split_vertex_test, split_with_equal_corners_is_make_edge_vertex) {
    HMIRA_REQUIRE_EULER(TypeParam)
    else {
        using T = hmira::default_traits<TypeParam>;
        auto a = mesh_from<TypeParam>(grid(2, 2));
        auto b = a;
        const auto corner_a = find_halfedge(a, live_vertices(a)[1], live_vertices(a)[4]);
        const auto corner_b = find_halfedge(b, live_vertices(b)[1], live_vertices(b)[4]);
        ASSERT_NE(corner_a, T::null_halfedge());
        auto r = hmira::split_vertex(a, corner_a, corner_a, {5, 5, 5});
        ASSERT_TRUE(r) << r.error().message;
        ASSERT_TRUE(hmira::make_edge_vertex(b, corner_b, {5, 5, 5}));
        EXPECT_EQ(T::next(a, r->halfedge), T::opposite(a, r->halfedge));  // the new vertex has degree 1
        EXPECT_TRUE(same_mesh(a, b));
        // Its inverse is then the plain killEV, with both corners the one corner.
        auto k = hmira::join_vertices(a, r->halfedge);
        ASSERT_TRUE(k) << k.error().message;
        EXPECT_EQ(k->h0, corner_a);
        EXPECT_EQ(k->h1, corner_a);
        EXPECT_TRUE(same_mesh(a, mesh_from<TypeParam>(grid(2, 2))));
    }
}

TYPED_TEST(split_vertex_test, random_joins_are_refused_exactly_where_they_would_break_the_mesh_and_splits_redo_them) {
    HMIRA_REQUIRE_EULER(TypeParam)
    else {
        using T = hmira::default_traits<TypeParam>;
        for (const auto& s : shapes()) {
            SCOPED_TRACE(s.name);
            auto m = mesh_from<TypeParam>(s.faces);
            std::mt19937_64 rng(99);
            std::size_t joined = 0, refused = 0;
            for (int step = 0; step < 40; ++step) {
                std::vector<typename T::halfedge_handle> hs;
                for (auto h : T::halfedges(m)) hs.push_back(h);
                const auto h = hs[std::uniform_int_distribution<std::size_t>(0, hs.size() - 1)(rng)];
                const auto o = T::opposite(m, h);
                const auto v = T::target(m, o), w = T::target(m, h);
                // Expected from the neighbourhoods, walked here.
                const auto nv = neighbour_keys(m, v), nw = neighbour_keys(m, w);
                std::vector<point_key> common;
                std::set_intersection(nv.begin(), nv.end(), nw.begin(), nw.end(), std::back_inserter(common));
                const bool interior_edge = T::face(m, h) != T::null_face() && T::face(m, o) != T::null_face();
                const bool pinch = interior_edge && on_boundary(m, v) && on_boundary(m, w);
                const bool ok = common.empty() && !pinch && (nv.size() >= 2 || nw.size() == 1);
                const auto snap = take_snapshot(m);
                const auto before = m;
                const auto start_counts = count_euler(m);
                auto k = hmira::join_vertices(m, h);
                ASSERT_EQ(bool(k), ok) << (k ? std::string("joined") : k.error().message);
                if (!k) {
                    ++refused;
                    EXPECT_TRUE(k.error().code == hmira::errc::topology || k.error().code == hmira::errc::non_manifold);
                    EXPECT_TRUE(take_snapshot(m) == snap) << "a refused join changed the mesh";
                    continue;
                }
                ++joined;
                EXPECT_EQ(count_euler(m).v, start_counts.v - 1);
                EXPECT_EQ(count_euler(m).e, start_counts.e - 1);
                EXPECT_TRUE(hmira_test::is_valid(m, {.check_geometry = false}));
                EXPECT_TRUE(euler_poincare_holds(m, s.s_minus_h));
                EXPECT_EQ(k->vertex, v);
                // Redo: the split with the returned corners gives the mesh back.
                auto r = hmira::split_vertex(m, k->h0, k->h1, k->position);
                ASSERT_TRUE(r) << r.error().message;
                EXPECT_TRUE(same_mesh(m, before));
                // Keep half of the joins, to explore meshes with merged vertices.
                if (step % 2 == 0) {
                    ASSERT_TRUE(hmira::join_vertices(m, r->halfedge));
                }
                EXPECT_TRUE(euler_poincare_holds(m, s.s_minus_h));
            }
            // Every edge of a triangle grid is a side of a triangle; the others have joinable edges.
            if (std::string(s.name) == "triangle grid") {
                EXPECT_EQ(joined, 0u);
            } else {
                EXPECT_GT(joined, 0u);
            }
            EXPECT_GT(refused, 0u);
        }
    }
}

TYPED_TEST(split_vertex_test, refused_operations_name_the_reason_and_change_nothing) {
    HMIRA_REQUIRE_EULER(TypeParam)
    else {
        using T = hmira::default_traits<TypeParam>;
        auto vertex_at = [](const TypeParam& m, double x, double y) {
            for (auto v : T::vertices(m))
                if (key_of(m, v) == point_key{x, y, 0}) return v;
            ADD_FAILURE() << "no vertex at " << x << ", " << y;
            return typename T::vertex_handle();
        };
        auto expect_refused = [](TypeParam& m, auto op, hmira::errc code, const std::string& words) {
            const auto snap = take_snapshot(m);
            const auto r = op(m);
            ASSERT_FALSE(r);
            EXPECT_EQ(r.error().code, code) << r.error().message;
            EXPECT_NE(r.error().message.find(words), std::string::npos) << r.error().message;
            EXPECT_TRUE(take_snapshot(m) == snap);
        };
        {  // A triangle on the edge.
            auto m = mesh_from<TypeParam>(grid(2, 2, true));
            const auto h = find_halfedge(m, vertex_at(m, 1, 1), vertex_at(m, 2, 2));
            expect_refused(
                m, [&](TypeParam& x) { return hmira::join_vertices(x, h); }, hmira::errc::topology, "triangle");
        }
        {  // An interior edge between two boundary vertices: joining pinches the strip.
            auto m = mesh_from<TypeParam>(grid(3, 1));
            const auto h = find_halfedge(m, vertex_at(m, 1, 0), vertex_at(m, 1, 1));
            expect_refused(
                m, [&](TypeParam& x) { return hmira::join_vertices(x, h); }, hmira::errc::non_manifold, "pinches");
        }
        {  // A common neighbour without a triangle: around a torus of 3 x 4 quads, each ring
            // of 3 vertices is a cycle of edges that bounds no face.
            const auto t = torus(3, 4);
            auto m = mesh_from<TypeParam>(t);
            auto at = [&](std::size_t i) {
                for (auto v : T::vertices(m)) {
                    const auto [x, y, z] = key_of(m, v);
                    if (std::abs(x - t.points[i].x) + std::abs(y - t.points[i].y) + std::abs(z - t.points[i].z) < 1e-5)
                        return v;
                }
                return typename T::vertex_handle();
            };
            const auto h = find_halfedge(m, at(0), at(4));  // (i, j) = (0, 0) -> (1, 0)
            ASSERT_NE(h, T::null_halfedge());
            expect_refused(
                m, [&](TypeParam& x) { return hmira::join_vertices(x, h); }, hmira::errc::non_manifold,
                "common neighbour");
        }
        {  // A survivor of degree 1.
            auto m = mesh_from<TypeParam>(grid(1, 1));
            const auto corner = find_halfedge(m, vertex_at(m, 1, 0), vertex_at(m, 1, 1));
            auto r = hmira::split_vertex(m, corner, corner, {0.5, 0.5, 0});
            ASSERT_TRUE(r);
            const auto back = T::opposite(m, r->halfedge);
            expect_refused(
                m, [&](TypeParam& x) { return hmira::join_vertices(x, back); }, hmira::errc::topology, "degree 1");
        }
        {  // Corners at two different vertices, and a missing corner.
            auto m = mesh_from<TypeParam>(grid(2, 2));
            const auto a = find_halfedge(m, vertex_at(m, 0, 1), vertex_at(m, 1, 1));
            const auto b = find_halfedge(m, vertex_at(m, 1, 1), vertex_at(m, 2, 1));
            expect_refused(
                m,
                [&](TypeParam& x) {
                    return hmira::split_vertex(x, a, b, {9, 9, 9});
                },
                hmira::errc::topology, "different vertices");
            expect_refused(
                m,
                [&](TypeParam& x) {
                    return hmira::split_vertex(x, a, T::null_halfedge(), {9, 9, 9});
                },
                hmira::errc::invalid_handle, "does not exist");
            expect_refused(
                m, [&](TypeParam& x) { return hmira::join_vertices(x, T::null_halfedge()); },
                hmira::errc::invalid_handle, "does not exist");
        }
    }
}

TEST(split_vertex_rings, splits_and_joins_on_an_inner_ring_keep_the_ring) {
    using M = hmira::halfedge_mesh;
    using T = hmira::default_traits<M>;
    static_assert(hmira::euler_ring_mutable_mesh<M>);
    // A square with a square hole: the outer face holds the inner square's loop as a ring,
    // the inner square is a face of its own (S - H = 1, R = 1).
    auto m = mesh_from<M>(grid(1, 1));
    const auto f = *T::faces(m).begin();
    auto corner = T::face_halfedge(m, f);
    auto a = hmira::make_edge_vertex(m, corner, {0.25, 0.25, 0});
    ASSERT_TRUE(a);
    auto b = hmira::make_edge_vertex(m, a->halfedge, {0.75, 0.25, 0});
    auto c = hmira::make_edge_vertex(m, b->halfedge, {0.75, 0.75, 0});
    auto d = hmira::make_edge_vertex(m, c->halfedge, {0.25, 0.75, 0});
    ASSERT_TRUE(b && c && d);
    ASSERT_TRUE(hmira::make_edge_face(m, d->halfedge, a->halfedge));
    ASSERT_TRUE(hmira::kill_edge_make_ring(m, a->halfedge).has_value() ||
                hmira::kill_edge_make_ring(m, T::opposite(m, a->halfedge)).has_value());
    ASSERT_TRUE(euler_poincare_holds(m, 1));
    ASSERT_EQ(count_euler(m).rings, 1);
    ASSERT_TRUE(hmira_test::is_valid(m));
    const auto start = m;
    std::mt19937_64 rng(5);
    std::vector<T::halfedge_handle> made;
    for (int step = 0; step < 30; ++step) {
        const auto vs = live_vertices(m);
        const auto v = vs[std::uniform_int_distribution<std::size_t>(0, vs.size() - 1)(rng)];
        const auto in = incoming(m, v);
        std::uniform_int_distribution<std::size_t> d2(0, in.size() - 1);
        const auto i0 = d2(rng);
        auto r = hmira::split_vertex(m, in[i0], in[(i0 + 1 + d2(rng) % (in.size() - 1)) % in.size()],
                                     {double(step), 7.0, 1.0});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(is_valid_relaxed(m));
        EXPECT_TRUE(euler_poincare_holds(m, 1));
        EXPECT_EQ(count_euler(m).rings, 1);
        made.push_back(r->halfedge);
    }
    for (auto it = made.rbegin(); it != made.rend(); ++it) {
        auto k = hmira::join_vertices(m, *it);
        ASSERT_TRUE(k) << k.error().message;
        EXPECT_TRUE(is_valid_relaxed(m));
        EXPECT_TRUE(euler_poincare_holds(m, 1));
    }
    EXPECT_TRUE(same_mesh(m, start));
}

}  // namespace
