// self_intersections reports exactly the pairs of faces that meet other than along what they
// share: checked against an all-pairs separating-axis reference in integers (independent of the
// predicates) on random soups and on meshes with random positions, on every model.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <random>
#include <set>

#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/validation/self_intersections.hpp>
#include <hmira/algorithms/validation/validate.hpp>
#include <hmira/io/mesh_io.hpp>

#include "predicates/sat_reference.hpp"
#include "support/models.hpp"
#include "support/shapes.hpp"

namespace {

using hmira::face_pair;
using hmira_test::face_list;
using hmira_test::ivec;

ivec iv(const hmira::vec3<double>& p) { return {(long long)p.x, (long long)p.y, (long long)p.z}; }

bool proper(const ivec& a, const ivec& b, const ivec& c) {
    using namespace hmira_test;
    return !izero(icross(isub(b, a), isub(c, a)));
}

/// Triangles s and t (vertex indices) meet other than along what they share by index: the
/// rule self_intersections documents, decided by separating axes. Both must be proper.
bool reference_cross(const std::vector<ivec>& p, const std::vector<std::size_t>& s, const std::vector<std::size_t>& t) {
    using namespace hmira_test;
    std::vector<std::size_t> s_own, t_own, common;
    for (auto v : s) (std::find(t.begin(), t.end(), v) == t.end() ? s_own : common).push_back(v);
    for (auto v : t)
        if (std::find(s.begin(), s.end(), v) == s.end()) t_own.push_back(v);
    const std::array<ivec, 3> ts{p[s[0]], p[s[1]], p[s[2]]}, tt{p[t[0]], p[t[1]], p[t[2]]};
    switch (common.size()) {
        case 0: return sat_triangles_meet(ts, tt);
        case 1:
            return sat_segment_meets_triangle(p[s_own[0]], p[s_own[1]], tt) ||
                   sat_segment_meets_triangle(p[t_own[0]], p[t_own[1]], ts);
        case 2: {
            // Coplanar with the third corners on the same side of the edge: normals of the two
            // triangles, both taken from the common edge, parallel and pointing the same way.
            const ivec e = isub(p[common[1]], p[common[0]]);
            const ivec ns = icross(e, isub(p[s_own[0]], p[common[0]]));
            const ivec nt = icross(e, isub(p[t_own[0]], p[common[0]]));
            return izero(icross(ns, nt)) && idot(ns, nt) > 0;
        }
        default: return true;
    }
}

/// All pairs of faces of a triangle face list, by the reference.
std::vector<face_pair> reference_pairs(const face_list& g) {
    std::vector<ivec> p;
    for (const auto& q : g.points) p.push_back(iv(q));
    std::vector<face_pair> out;
    for (std::size_t i = 0; i < g.faces.size(); ++i)
        for (std::size_t j = i + 1; j < g.faces.size(); ++j)
            if (reference_cross(p, g.faces[i], g.faces[j])) out.push_back({i, j});
    return out;
}

/// Random proper triangles with small integer corners, each with its own three vertices.
face_list random_soup(std::mt19937_64& rng, std::size_t n, int range) {
    std::uniform_int_distribution<int> c(0, range);
    face_list g;
    while (g.faces.size() < n) {
        const ivec a{c(rng), c(rng), c(rng)}, b{c(rng), c(rng), c(rng)}, d{c(rng), c(rng), c(rng)};
        if (!proper(a, b, d)) continue;
        const std::size_t base = g.points.size();
        for (const ivec& v : {a, b, d}) g.points.push_back({double(v[0]), double(v[1]), double(v[2])});
        g.faces.push_back({base, base + 1, base + 2});
    }
    return g;
}

/// n random proper triangles of extent at most `size`, scattered over [0, range]^3.
face_list random_small_soup(std::mt19937_64& rng, std::size_t n, int range, int size) {
    std::uniform_int_distribution<int> at(0, range), c(0, size);
    face_list g;
    while (g.faces.size() < n) {
        const ivec o{at(rng), at(rng), at(rng)};
        auto corner = [&] { return ivec{o[0] + c(rng), o[1] + c(rng), o[2] + c(rng)}; };
        const ivec a = corner(), b = corner(), d = corner();
        if (!proper(a, b, d)) continue;
        const std::size_t base = g.points.size();
        for (const ivec& v : {a, b, d}) g.points.push_back({double(v[0]), double(v[1]), double(v[2])});
        g.faces.push_back({base, base + 1, base + 2});
    }
    return g;
}

/// A triangulated grid whose vertices are moved to random small integer positions, redrawn
/// until no triangle is flat: folds, shared-edge overlaps and shared-vertex crossings abound.
face_list random_folded_grid(std::mt19937_64& rng, std::size_t nx, std::size_t ny, int range) {
    face_list g = hmira_test::grid(nx, ny, true);
    std::uniform_int_distribution<int> c(0, range);
    for (;;) {
        for (auto& q : g.points) q = {double(c(rng)), double(c(rng)), double(c(rng))};
        bool ok = true;
        for (const auto& f : g.faces) ok &= proper(iv(g.points[f[0]]), iv(g.points[f[1]]), iv(g.points[f[2]]));
        if (ok) return g;
    }
}

template <class M>
class self_intersections_typed : public ::testing::Test {};
TYPED_TEST_SUITE(self_intersections_typed, hmira_test::all_models);

template <class M>
std::vector<face_pair> found(const M& m, const hmira::self_intersections_options& o = {}) {
    auto r = hmira::self_intersections(m, o);
    EXPECT_TRUE(r) << (r ? "" : r.error().message);
    return r ? *r : std::vector<face_pair>{};
}

TYPED_TEST(self_intersections_typed, matches_all_pairs_on_random_soups) {
    std::mt19937_64 rng(21);
    std::size_t reported = 0;
    for (int round = 0; round < 6; ++round) {
        const face_list g = random_soup(rng, 40, round % 2 ? 6 : 12);
        TypeParam m;
        ASSERT_TRUE(hmira_test::add_face_list(m, g));
        const auto want = reference_pairs(g);
        reported += want.size();
        ASSERT_EQ(found(m), want) << "round " << round;
    }
    EXPECT_GT(reported, 20u);
}

TYPED_TEST(self_intersections_typed, matches_all_pairs_on_folded_meshes_with_shared_corners) {
    std::mt19937_64 rng(22);
    for (int round = 0; round < 4; ++round) {
        const face_list g = random_folded_grid(rng, 4, 3, 4);
        TypeParam m;
        ASSERT_TRUE(hmira_test::add_face_list(m, g));
        ASSERT_EQ(found(m), reference_pairs(g)) << "round " << round;
    }
}

TYPED_TEST(self_intersections_typed, clean_closed_meshes_report_nothing) {
    // Quads cut into triangles, so that triangle-only models hold them too.
    face_list g = hmira_test::torus(12, 8);
    std::vector<std::vector<std::size_t>> tris;
    for (const auto& f : g.faces) {
        tris.push_back({f[0], f[1], f[2]});
        tris.push_back({f[0], f[2], f[3]});
    }
    g.faces = tris;
    TypeParam torus;
    ASSERT_TRUE(hmira_test::add_face_list(torus, g));
    EXPECT_TRUE(found(torus).empty());
}

TYPED_TEST(self_intersections_typed, a_thread_count_does_not_change_the_answer) {
    std::mt19937_64 rng(23);
    const face_list g = random_small_soup(rng, 3000, 60, 4);
    TypeParam m;
    ASSERT_TRUE(hmira_test::add_face_list(m, g));
    const auto all = found(m);
    EXPECT_FALSE(all.empty());
    EXPECT_EQ(found(m, {.threads = 1}), all);
    EXPECT_EQ(found(m, {.threads = 2}), all);
}

/// A single mesh of the two triangles given, corners by index into `points`.
face_list two(std::vector<hmira::vec3<double>> points, std::vector<std::size_t> s, std::vector<std::size_t> t) {
    return {std::move(points), {std::move(s), std::move(t)}};
}

std::vector<face_pair> on_face_vertex_mesh(const face_list& g) {
    hmira::face_vertex_mesh m;
    EXPECT_TRUE(hmira_test::add_face_list(m, g));
    return found(m);
}

const std::vector<face_pair> none{}, first_pair{{0, 1}};

TEST(self_intersections, clean_polygon_meshes_report_nothing) {
    hmira::halfedge_mesh cube;
    ASSERT_TRUE(hmira::generate_cube(cube));
    EXPECT_TRUE(found(cube).empty());
    hmira::face_vertex_mesh torus;
    ASSERT_TRUE(hmira_test::add_face_list(torus, hmira_test::torus(12, 8)));
    EXPECT_TRUE(found(torus).empty());
}

TEST(self_intersections, faces_meeting_only_along_their_shared_edge_are_not_reported) {
    // A flat neighbour and a bent one.
    EXPECT_EQ(on_face_vertex_mesh(two({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, {0, 1, 2}, {1, 3, 2})), none);
    EXPECT_EQ(on_face_vertex_mesh(two({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 1}}, {0, 1, 2}, {1, 3, 2})), none);
}

TEST(self_intersections, faces_folded_onto_each_other_across_a_shared_edge_are_reported) {
    EXPECT_EQ(on_face_vertex_mesh(two({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.2, 0.1, 0}}, {0, 1, 2}, {1, 0, 3})),
              first_pair);
}

TEST(self_intersections, faces_sharing_a_vertex_are_reported_only_when_they_meet_elsewhere) {
    // Touching only at the shared corner: not reported.
    EXPECT_EQ(on_face_vertex_mesh(two({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 1}}, {0, 1, 2}, {0, 3, 4})),
              none);
    // Folding through the other face: reported.
    EXPECT_EQ(on_face_vertex_mesh(
                  two({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0.2, -1}, {0.2, 0.5, 1}}, {0, 1, 2}, {0, 3, 4})),
              first_pair);
    // Overlapping in one plane: reported.
    EXPECT_EQ(on_face_vertex_mesh(two({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {-1, 2, 0}}, {0, 1, 2}, {0, 3, 4})),
              first_pair);
}

TEST(self_intersections, touching_without_sharing_is_reported) {
    // A corner of one triangle on the face of the other, vertices not shared.
    EXPECT_EQ(on_face_vertex_mesh(
                  two({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, 0}, {1, 1, 1}, {0, 1, 1}}, {0, 1, 2}, {3, 4, 5})),
              first_pair);
    // The same corner an ulp above the face: apart.
    EXPECT_EQ(on_face_vertex_mesh(
                  two({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, 0x1p-1074 * 0x1p900}, {1, 1, 1}, {0, 1, 1}},
                      {0, 1, 2}, {3, 4, 5})),
              none);
}

TEST(self_intersections, polygon_faces_are_reported_by_face_index) {
    // Two unit squares crossing at right angles, and a third far away.
    face_list g{{{0, 0, 0},
                 {2, 0, 0},
                 {2, 2, 0},
                 {0, 2, 0},
                 {1, 1, -1},
                 {1, 1, 1},
                 {1, 3, 1},
                 {1, 3, -1},
                 {5, 5, 5},
                 {6, 5, 5},
                 {6, 6, 5},
                 {5, 6, 5}},
                {{8, 9, 10, 11}, {0, 1, 2, 3}, {4, 5, 6, 7}}};
    EXPECT_EQ(on_face_vertex_mesh(g), (std::vector<face_pair>{{1, 2}}));
}

TEST(self_intersections, the_tetrahedron_with_a_triangle_through_it_is_reported) {
    const char* dir = std::getenv("HMIRA_TEST_DATA");
    if (!dir || !*dir) GTEST_SKIP() << "HMIRA_TEST_DATA not set";
    hmira::face_vertex_mesh m;
    ASSERT_TRUE(hmira::io::read_mesh(m, std::filesystem::path(dir) / "meshes/tetra_intersected_by_triangle.off"));
    const auto pairs = found(m);
    ASSERT_FALSE(pairs.empty());
    for (const auto& p : pairs) EXPECT_EQ(p[1], 4u);  // always the lone triangle against the tetrahedron
    hmira::face_vertex_mesh sphere;
    ASSERT_TRUE(hmira::io::read_mesh(sphere, std::filesystem::path(dir) / "meshes/sphere.off"));
    EXPECT_TRUE(found(sphere).empty());
}

TEST(self_intersections, validate_reports_them_only_when_asked) {
    hmira::face_vertex_mesh m;
    ASSERT_TRUE(hmira_test::add_face_list(
        m, two({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0.2, -1}, {0.2, 0.5, 1}}, {0, 1, 2}, {0, 3, 4})));
    auto kind_count = [](const std::vector<hmira::mesh_problem>& ps) {
        return std::count_if(ps.begin(), ps.end(),
                             [](const auto& p) { return p.kind == hmira::problem_kind::self_intersection; });
    };
    EXPECT_EQ(kind_count(hmira::validate(m)), 0);
    const auto ps = hmira::validate(m, {.check_self_intersections = true});
    ASSERT_EQ(kind_count(ps), 1);
    EXPECT_EQ(ps.back().element, 0u);
    EXPECT_EQ(ps.back().message, "faces 0 and 1 intersect");
    EXPECT_STREQ(hmira::to_string(hmira::problem_kind::self_intersection), "self-intersection");
}

TEST(self_intersections, refuses_coordinates_outside_the_predicates_range) {
    face_list g = two({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, {0, 1, 2}, {1, 3, 2});
    g.points[3].y = std::numeric_limits<double>::quiet_NaN();
    hmira::face_vertex_mesh m;
    ASSERT_TRUE(hmira_test::add_face_list(m, g));
    const auto r = hmira::self_intersections(m);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, hmira::errc::invalid_argument);
    EXPECT_EQ(r.error().element, 3);
}

TEST(self_intersections, can_be_cancelled) {
    std::mt19937_64 rng(24);
    hmira::face_vertex_mesh m;
    ASSERT_TRUE(hmira_test::add_face_list(m, random_small_soup(rng, 5000, 60, 4)));
    int calls = 0;
    const auto r = hmira::self_intersections(m, {.progress = [&](double) { return ++calls < 2; }});
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, hmira::errc::cancelled);
}

}  // namespace
