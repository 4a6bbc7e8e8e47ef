// The halfedge mesh's add_face: faces in any order build the same valid mesh, bad faces are
// refused with the mesh left exactly as it was, and garbage collection keeps properties in step.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/topology/mesh_topology.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "support/checks.hpp"
#include "support/shapes.hpp"

namespace {

using namespace hmira;

// Everything observable about the mesh's connectivity, in index terms.
struct snapshot {
    std::vector<std::array<std::uint32_t, 4>> halfedges;  // target, face, next, prev
    std::vector<std::uint32_t> vertex_out, face_he;
    std::size_t v, e, f;
    bool operator==(const snapshot&) const = default;
};
snapshot snap(const halfedge_mesh& m) {
    snapshot s{{}, {}, {}, m.vertex_count(), m.edge_count(), m.face_count()};
    for (std::uint32_t h = 0; h < m.halfedge_index_bound(); ++h) {
        const halfedge_handle hh(h);
        s.halfedges.push_back({m.target(hh).index, m.face(hh).index, m.next(hh).index, m.prev(hh).index});
    }
    for (auto v : m.vertices()) s.vertex_out.push_back(m.vertex_halfedge(v).index);
    for (auto f : m.faces()) s.face_he.push_back(m.face_halfedge(f).index);
    return s;
}

// Faces added out of order may meet at a vertex in separate fans before the faces between them
// arrive (a pinch, reported as non_manifold_vertex); everything else must be valid at every step.
::testing::AssertionResult valid_but_maybe_pinched(const halfedge_mesh& m) {
    auto ps = validate(m, {.relaxed = true, .check_geometry = false});
    std::erase_if(ps, [](const mesh_problem& p) {
        return p.kind == problem_kind::non_manifold_vertex && p.message.find("separate fans") != std::string::npos;
    });
    if (ps.empty()) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << hmira_test::describe(ps);
}

void add_in_order(halfedge_mesh& m, const hmira_test::face_list& g, const std::vector<std::size_t>& order) {
    std::vector<vertex_handle> vs;
    for (const auto& p : g.points) vs.push_back(m.add_vertex(p));
    for (auto fi : order) {
        std::vector<vertex_handle> corners;
        for (auto i : g.faces[fi]) corners.push_back(vs[i]);
        auto r = m.add_face(corners);
        ASSERT_TRUE(r) << "face " << fi << ": " << r.error().message;
        ASSERT_TRUE(valid_but_maybe_pinched(m)) << "after face " << fi;
    }
}

TEST(halfedge_mesh, faces_added_in_any_order_build_the_same_valid_surface) {
    const std::vector<hmira_test::face_list> shapes{
        hmira_test::grid(7, 5, true), hmira_test::grid(6, 6), hmira_test::torus(8, 6),
        hmira_test::without_faces(hmira_test::grid(9, 9, true),
                                  [](std::size_t f) { return (f / 2) % 9 % 3 == 1 && (f / 2) / 9 % 3 == 1; })};
    std::mt19937 rng(12345);
    for (const auto& g : shapes) {
        for (int trial = 0; trial < 12; ++trial) {
            std::vector<std::size_t> order(g.faces.size());
            std::iota(order.begin(), order.end(), 0);
            std::shuffle(order.begin(), order.end(), rng);
            halfedge_mesh m;
            add_in_order(m, g, order);
            if (HasFatalFailure()) return;
            EXPECT_TRUE(hmira_test::is_valid(m));
            std::multiset<std::vector<std::size_t>> expected;
            for (auto f : g.faces) {
                std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
                expected.insert(f);
            }
            EXPECT_EQ(hmira_test::canonical_faces(m), expected);
        }
    }
}

TEST(halfedge_mesh, face_vertices_come_back_in_the_order_given) {
    halfedge_mesh m;
    std::vector<vertex_handle> v;
    for (int i = 0; i < 5; ++i) v.push_back(m.add_vertex({std::cos(i * 1.2566), std::sin(i * 1.2566), 0}));
    auto f = m.add_face({v[2], v[3], v[4], v[0], v[1]});
    ASSERT_TRUE(f);
    std::vector<vertex_handle> got(m.face_vertices(*f).begin(), m.face_vertices(*f).end());
    EXPECT_EQ(got, (std::vector<vertex_handle>{v[2], v[3], v[4], v[0], v[1]}));
}

TEST(halfedge_mesh, refused_faces_leave_the_mesh_unchanged) {
    halfedge_mesh m;
    auto g = hmira_test::grid(3, 3);
    std::vector<vertex_handle> v;
    ASSERT_TRUE(hmira_test::add_face_list(m, g, &v));
    const auto extra = m.add_vertex({5, 5, 5});
    const auto before = snap(m);
    struct bad_case {
        std::vector<vertex_handle> face;
        errc code;
    };
    const std::vector<bad_case> cases{
        {{v[0], v[1]}, errc::degenerate_face},                      // too few
        {{v[0], v[1], v[0]}, errc::degenerate_face},                // repeated
        {{v[0], v[1], vertex_handle(999u)}, errc::invalid_handle},  // missing vertex
        {{v[0], v[1], v[5], v[4]}, errc::orientation_conflict},     // same direction as an existing face
        {{v[5], extra, v[6]}, errc::non_manifold},                  // v[5] is interior
        {{v[1], v[0], extra}, errc::non_manifold},                  // edge 0-1 side taken? no: 1->0 is boundary
    };
    for (std::size_t i = 0; i + 1 < cases.size(); ++i) {
        auto r = m.add_face(cases[i].face);
        ASSERT_FALSE(r) << "case " << i;
        EXPECT_EQ(r.error().code, cases[i].code) << "case " << i << ": " << r.error().message;
        EXPECT_FALSE(r.error().message.empty());
        EXPECT_EQ(snap(m), before) << "case " << i << " changed the mesh";
    }
    // The last case is legal: the boundary edge 1->0 takes a face on its free side.
    EXPECT_TRUE(m.add_face(cases.back().face));
    EXPECT_TRUE(hmira_test::is_valid(m));
}

TEST(halfedge_mesh, a_third_face_on_an_edge_is_refused) {
    halfedge_mesh m;
    ASSERT_TRUE(generate_tetrahedron(m));
    const auto before = snap(m);
    const auto x = m.add_vertex({3, 3, 3});
    const auto snapshot_with_x = snap(m);
    auto r = m.add_face({vertex_handle(0u), vertex_handle(1u), x});
    ASSERT_FALSE(r);
    EXPECT_EQ(snap(m), snapshot_with_x);
    (void)before;
}

TEST(halfedge_mesh, random_face_soups_never_break_the_mesh) {
    // Random triangles over few vertices: most are refused; whatever is accepted must leave a
    // valid manifold, and a refusal must change nothing.
    std::mt19937 rng(99);
    for (int trial = 0; trial < 300; ++trial) {
        halfedge_mesh m;
        std::vector<vertex_handle> v;
        for (int i = 0; i < 12; ++i)
            v.push_back(m.add_vertex({double(rng() % 100), double(rng() % 100), double(rng() % 100)}));
        for (int k = 0; k < 60; ++k) {
            const auto a = v[rng() % 12], b = v[rng() % 12], c = v[rng() % 12];
            const auto before = snap(m);
            auto r = m.add_face({a, b, c});
            if (!r) {
                EXPECT_EQ(snap(m), before) << r.error().message;
            }
            ASSERT_TRUE(valid_but_maybe_pinched(m)) << "trial " << trial << " step " << k;
        }
    }
}

TEST(halfedge_mesh, collect_garbage_renumbers_and_keeps_properties_in_step) {
    halfedge_mesh m;
    ASSERT_TRUE(generate_octahedron(m));
    auto tag = m.add_vertex_property<int>("tag", -1);
    auto ftag = m.add_face_property<std::string>("name");
    for (auto v : m.vertices()) tag[v] = int(v.index) * 10;
    for (auto f : m.faces()) ftag[f] = "f" + std::to_string(f.index);
    const auto lonely = m.add_vertex({9, 9, 9});
    tag[lonely] = 777;
    const auto spare = m.add_vertex({8, 8, 8});
    m.erase_vertex(spare);
    const auto before = hmira_test::canonical_faces(m);
    auto map = m.collect_garbage();
    EXPECT_EQ(map.vertices[spare.index], UINT32_MAX);
    EXPECT_EQ(map.vertices[lonely.index], lonely.index);
    EXPECT_EQ(m.vertex_count(), 7u);
    EXPECT_EQ(tag[vertex_handle(map.vertices[lonely.index])], 777);
    for (std::uint32_t i = 0; i < 6; ++i) EXPECT_EQ(tag[vertex_handle(map.vertices[i])], int(i) * 10);
    for (auto f : m.faces()) EXPECT_EQ(ftag[f], "f" + std::to_string(f.index));
    EXPECT_EQ(hmira_test::canonical_faces(m), before);
    EXPECT_TRUE(hmira_test::is_valid(m, {.relaxed = true}));
}

TEST(halfedge_mesh, properties_grow_with_the_mesh_and_copies_are_independent) {
    halfedge_mesh m;
    auto w = m.add_vertex_property<double>("w", 1.5);
    const auto a = m.add_vertex({0, 0, 0});
    EXPECT_EQ(w[a], 1.5);
    w[a] = 2;
    halfedge_mesh copy = m;
    auto cw = copy.get_vertex_property<double>("w");
    ASSERT_TRUE(cw);
    (*cw)[a] = 3;
    EXPECT_EQ(w[a], 2);
    EXPECT_FALSE(m.add_vertex_property<int>("w").valid()) << "same name, other type must be refused";
    EXPECT_TRUE(m.remove_vertex_property("w"));
    EXPECT_FALSE(m.get_vertex_property<double>("w"));
}

TEST(halfedge_mesh, local_queries_match_the_face_lists) {
    halfedge_mesh m;
    ASSERT_TRUE(hmira_test::add_face_list(m, hmira_test::torus(7, 5)));
    // Neighbours from the faces, computed here independently.
    std::map<std::uint32_t, std::set<std::uint32_t>> nb;
    std::map<std::uint32_t, std::multiset<std::uint32_t>> vf;
    for (auto f : m.faces()) {
        std::vector<vertex_handle> loop(m.face_vertices(f).begin(), m.face_vertices(f).end());
        for (std::size_t i = 0; i < loop.size(); ++i) {
            nb[loop[i].index].insert(loop[(i + 1) % loop.size()].index);
            nb[loop[(i + 1) % loop.size()].index].insert(loop[i].index);
            vf[loop[i].index].insert(f.index);
        }
    }
    for (auto v : m.vertices()) {
        std::set<std::uint32_t> got;
        for (auto w : m.adjacent_vertices(v)) got.insert(w.index);
        EXPECT_EQ(got, nb[v.index]);
        std::multiset<std::uint32_t> faces;
        for (auto f : m.vertex_faces(v)) faces.insert(f.index);
        EXPECT_EQ(faces, vf[v.index]);
        EXPECT_EQ(m.valence(v), 4u);
    }
    for (auto f : m.faces()) EXPECT_EQ(m.adjacent_faces(f).size(), 4u);
}

}  // namespace
