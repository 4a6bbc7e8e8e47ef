// The ranges the meshes hand out (detail/element_range.hpp): they stay std::ranges views that
// compose with views::transform/filter, skip deleted elements, and the filtered circulators
// (vertex_faces, winged-edge adjacent_faces) yield exactly the faces found by an independent
// scan, including when the circulation starts on a boundary halfedge.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <ranges>
#include <set>
#include <vector>

#include <hmira/algorithms/euler/euler.hpp>
#include <hmira/algorithms/topology/mesh_topology.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>
#include <hmira/meshes/winged_edge_mesh.hpp>

#include "support/checks.hpp"
#include "support/shapes.hpp"

namespace {

using namespace hmira;

// ----- compile-time: what the ranges are ---------------------------------------------------
template <class R>
concept mesh_view = std::ranges::forward_range<R> && std::ranges::view<R> && std::ranges::borrowed_range<R> &&
                    std::ranges::common_range<R> && std::ranges::forward_range<const R>;
template <class R>
concept composes = requires(R r) {
    {
        r | std::views::transform([](auto x) { return x; })
    } -> std::ranges::forward_range;
    {
        r | std::views::filter([](auto) { return true; })
    } -> std::ranges::forward_range;
};
template <class R>
concept good_range = mesh_view<R> && composes<R>;

template <class M>
constexpr bool element_ranges_are_views() {
    using cm = const M&;
    return good_range<decltype(std::declval<cm>().vertices())> && good_range<decltype(std::declval<cm>().faces())> &&
           !std::ranges::sized_range<decltype(std::declval<cm>().vertices())>;
}
static_assert(element_ranges_are_views<face_vertex_mesh>());
static_assert(element_ranges_are_views<halfedge_mesh>());
static_assert(element_ranges_are_views<winged_edge_mesh>());

template <class M>
constexpr bool circulators_are_views() {
    using cm = const M&;
    return good_range<decltype(std::declval<cm>().edges())> && good_range<decltype(std::declval<cm>().halfedges())> &&
           good_range<decltype(std::declval<cm>().face_vertices(face_handle{}))> &&
           good_range<decltype(std::declval<cm>().adjacent_vertices(vertex_handle{}))> &&
           good_range<decltype(std::declval<cm>().vertex_edges(vertex_handle{}))> &&
           good_range<decltype(std::declval<cm>().vertex_faces(vertex_handle{}))> &&
           std::same_as<std::ranges::range_value_t<decltype(std::declval<cm>().vertex_faces(vertex_handle{}))>,
                        face_handle> &&
           std::same_as<std::ranges::range_value_t<decltype(std::declval<cm>().halfedges())>, halfedge_handle>;
}
static_assert(circulators_are_views<halfedge_mesh>());
static_assert(circulators_are_views<winged_edge_mesh>());
static_assert(good_range<decltype(std::declval<const winged_edge_mesh&>().adjacent_faces(face_handle{}))>);

template <class R>
std::vector<typename std::ranges::range_value_t<R>> collect(R&& r) {
    std::vector<typename std::ranges::range_value_t<R>> out;
    for (auto x : r) out.push_back(x);
    return out;
}

std::vector<std::uint32_t> indices(const auto& handles) {
    std::vector<std::uint32_t> out;
    for (auto h : handles) out.push_back(h.index);
    return out;
}

// ----- element ranges skip deleted elements ------------------------------------------------
// Removing faces from a face-vertex mesh may leave vertices used by no face (relaxed) and
// vertices whose remaining faces form separate fans (a pinch, which this model may hold);
// anything else validate() finds is a defect.
::testing::AssertionResult valid_after_removal(const face_vertex_mesh& m) {
    auto ps = validate(m, {.relaxed = true});
    std::erase_if(ps, [](const mesh_problem& p) {
        return p.kind == problem_kind::non_manifold_vertex && p.message.find("separate fans") != std::string::npos;
    });
    if (ps.empty()) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << hmira_test::describe(ps);
}

TEST(element_ranges, an_empty_mesh_gives_empty_ranges) {
    face_vertex_mesh fv;
    halfedge_mesh he;
    EXPECT_TRUE(fv.vertices().empty());
    EXPECT_FALSE(static_cast<bool>(fv.faces()));
    EXPECT_TRUE(he.halfedges().empty());
    EXPECT_TRUE(he.edges().empty());
    EXPECT_EQ(std::ranges::distance(he.vertices()), 0);
}

TEST(element_ranges, face_vertex_ranges_skip_exactly_the_removed_elements) {
    const auto g = hmira_test::grid(6, 5, true);
    std::mt19937 rng(7);
    for (int trial = 0; trial < 10; ++trial) {
        face_vertex_mesh m;
        ASSERT_TRUE(hmira_test::add_face_list(m, g));
        // The test's own record of what is gone.
        std::vector<bool> vertex_gone(g.points.size(), false), face_gone(g.faces.size(), false);
        for (int step = 0; step < 12; ++step) {
            if (rng() % 2) {
                const auto v = static_cast<std::uint32_t>(rng() % g.points.size());
                const auto before = m.change_count();
                auto r = m.remove_vertex(vertex_handle(v));
                if (vertex_gone[v]) {
                    // Cannot apply: refused, naming the vertex, and the mesh unchanged.
                    ASSERT_FALSE(r);
                    EXPECT_EQ(r.error().element, static_cast<long long>(v));
                    EXPECT_EQ(m.change_count(), before);
                } else {
                    ASSERT_TRUE(r) << r.error().message;
                    vertex_gone[v] = true;
                    for (std::size_t f = 0; f < g.faces.size(); ++f)
                        if (std::ranges::find(g.faces[f], std::size_t{v}) != g.faces[f].end()) face_gone[f] = true;
                }
            } else {
                const auto f = static_cast<std::uint32_t>(rng() % g.faces.size());
                const auto before = m.change_count();
                auto r = m.remove_face(face_handle(f));
                ASSERT_EQ(static_cast<bool>(r), !face_gone[f]);
                if (!r) {
                    EXPECT_EQ(r.error().element, static_cast<long long>(f));
                    EXPECT_EQ(m.change_count(), before);
                }
                face_gone[f] = true;
            }
            ASSERT_TRUE(valid_after_removal(m)) << "trial " << trial << " step " << step;
            std::vector<std::uint32_t> live_vertices, live_faces;
            for (std::uint32_t i = 0; i < g.points.size(); ++i)
                if (!vertex_gone[i]) live_vertices.push_back(i);
            for (std::uint32_t i = 0; i < g.faces.size(); ++i)
                if (!face_gone[i]) live_faces.push_back(i);
            EXPECT_EQ(indices(collect(m.vertices())), live_vertices);
            EXPECT_EQ(indices(collect(m.faces())), live_faces);
            EXPECT_EQ(static_cast<std::size_t>(std::ranges::distance(m.faces())), m.face_count());
            EXPECT_EQ(m.faces().empty(), live_faces.empty());
            if (!live_vertices.empty()) {
                EXPECT_EQ(m.vertices().front().index, live_vertices.front());
            }
            // Through views, as algorithms use them.
            auto doubled = m.vertices() | std::views::transform([](vertex_handle v) { return 2 * v.index; });
            std::vector<std::uint32_t> expected_doubled;
            for (auto i : live_vertices) expected_doubled.push_back(2 * i);
            EXPECT_EQ(std::vector<std::uint32_t>(doubled.begin(), doubled.end()), expected_doubled);
            EXPECT_EQ(std::ranges::count_if(m.faces(), [](face_handle f) { return f.index % 2 == 0; }),
                      std::ranges::count_if(live_faces, [](std::uint32_t f) { return f % 2 == 0; }));
        }
    }
}

template <class M>
class circulators : public ::testing::Test {};
using halfedge_models = ::testing::Types<halfedge_mesh, winged_edge_mesh>;
TYPED_TEST_SUITE(circulators, halfedge_models);

// Both halfedges of every live edge, in index order, after edges were killed.
TYPED_TEST(circulators, halfedges_are_both_sides_of_the_live_edges) {
    using M = TypeParam;
    M m;
    ASSERT_TRUE(hmira_test::add_face_list(m, hmira_test::torus(6, 5)));
    const long long chi = euler_characteristic(m);
    std::mt19937 rng(11);
    int killed = 0;
    for (int attempt = 0; attempt < 40 && killed < 6; ++attempt) {
        const auto e = edge_handle(static_cast<std::uint32_t>(rng() % m.edge_index_bound()));
        if (!m.is_valid(e)) continue;
        const auto h = M::edge_halfedge(e);
        if (m.face(h) == m.face(M::opposite(h))) continue;  // would not merge two faces
        auto r = kill_edge_face(m, h);
        if (!r) continue;
        ++killed;
        ASSERT_TRUE(hmira_test::is_valid(m)) << "after killing edge " << e.index;
        EXPECT_EQ(euler_characteristic(m), chi);  // KEF removes one edge and one face
        std::vector<std::uint32_t> expected;
        for (std::uint32_t i = 0; i < m.edge_index_bound(); ++i)
            if (m.is_valid(edge_handle(i))) {
                expected.push_back(2 * i);
                expected.push_back(2 * i + 1);
            }
        EXPECT_EQ(indices(collect(m.halfedges())), expected);
        EXPECT_EQ(expected.size(), 2 * m.edge_count());
    }
    EXPECT_EQ(killed, 6);
}

// vertex_faces against a scan of every face, on a grid with holes (boundary vertices whose
// stored halfedge is a boundary one, so the filter must skip the circulation's start).
TYPED_TEST(circulators, vertex_faces_are_the_faces_that_use_the_vertex) {
    using M = TypeParam;
    const auto g =
        hmira_test::without_faces(hmira_test::grid(6, 6), [](std::size_t f) { return f == 8 || f == 22 || f == 23; });
    M m;
    ASSERT_TRUE(hmira_test::add_face_list(m, g));
    ASSERT_TRUE(hmira_test::is_valid(m));
    std::map<std::uint32_t, std::multiset<std::uint32_t>> using_faces;
    for (std::uint32_t f = 0; f < g.faces.size(); ++f)
        for (auto v : g.faces[f]) using_faces[static_cast<std::uint32_t>(v)].insert(f);
    std::size_t boundary_starts = 0;
    for (auto v : m.vertices()) {
        const auto found = collect(m.vertex_faces(v));
        const auto idx = indices(found);
        EXPECT_EQ(std::multiset<std::uint32_t>(idx.begin(), idx.end()), using_faces[v.index]) << "vertex " << v.index;
        EXPECT_EQ(m.vertex_faces(v).empty(), using_faces[v.index].empty());
        if (m.is_boundary(v)) ++boundary_starts;
        // The same faces in circulation order: the non-boundary outgoing halfedges' faces.
        std::vector<face_handle> in_order;
        for (auto h : m.outgoing_halfedges(v))
            if (!m.face(h).is_null()) in_order.push_back(m.face(h));
        EXPECT_EQ(found, in_order) << "vertex " << v.index;
        if (!in_order.empty()) {
            EXPECT_EQ(m.vertex_faces(v).front(), in_order.front());
        }
    }
    EXPECT_GT(boundary_starts, 20u);
    // An isolated vertex has no faces.
    const auto lone = m.add_vertex({9, 9, 9});
    ASSERT_TRUE(hmira_test::is_valid(m, {.relaxed = true}));
    EXPECT_TRUE(m.vertex_faces(lone).empty());
    EXPECT_EQ(std::ranges::distance(m.vertex_faces(lone)), 0);
}

TEST(circulators_winged_edge, adjacent_faces_are_the_faces_across_each_edge) {
    // Two square holes (both triangles of quads 6 and 13) that share no vertex.
    const auto g = hmira_test::without_faces(hmira_test::grid(5, 4, true),
                                             [](std::size_t f) { return f / 2 == 6 || f / 2 == 13; });
    winged_edge_mesh m;
    ASSERT_TRUE(hmira_test::add_face_list(m, g));
    ASSERT_TRUE(hmira_test::is_valid(m));
    // Independently: two faces are adjacent when they share an (unordered) vertex pair.
    std::map<std::pair<std::size_t, std::size_t>, std::vector<std::uint32_t>> by_pair;
    for (std::uint32_t f = 0; f < g.faces.size(); ++f)
        for (std::size_t k = 0; k < g.faces[f].size(); ++k) {
            auto a = g.faces[f][k], b = g.faces[f][(k + 1) % g.faces[f].size()];
            by_pair[{std::min(a, b), std::max(a, b)}].push_back(f);
        }
    std::map<std::uint32_t, std::multiset<std::uint32_t>> expected;
    for (const auto& [pair, fs] : by_pair)
        if (fs.size() == 2) {
            expected[fs[0]].insert(fs[1]);
            expected[fs[1]].insert(fs[0]);
        }
    std::size_t with_boundary = 0;
    for (auto f : m.faces()) {
        const auto idx = indices(collect(m.adjacent_faces(f)));
        EXPECT_EQ(std::multiset<std::uint32_t>(idx.begin(), idx.end()), expected[f.index]) << "face " << f.index;
        if (idx.size() < 3) ++with_boundary;
    }
    EXPECT_GT(with_boundary, 5u);
}

}  // namespace
