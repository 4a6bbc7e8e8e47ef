// catmull_clark_subdivide on every model that supports it: exact V/E/F per level on closed and
// open polygon meshes (V + E + F, 2E + C, C with C the sum of face degrees, counted here from
// the face list), validate and the native checkers after each level, the genus and boundary
// loops kept, a cube's positions after one level computed by hand from the masks, a planar
// grid staying planar, a bilinear patch reproduced, and refusals and cancellations leaving
// the mesh exactly as it was.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include <hmira/algorithms/euler/make_face_kill_ring.hpp>
#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/subdivision/catmull_clark.hpp>

#include "algorithms/subdivision/subdivision_support.hpp"
#include "algorithms/triangle/triangle_support.hpp"
#include "support/cancel_points.hpp"

namespace {

using namespace hmira_test;

/// Skips the current typed test on a model catmull_clark_subdivide does not accept.
#define HMIRA_REQUIRE_CATMULL_CLARK(M)                                                                      \
    if constexpr (!hmira::catmull_clark_subdividable_mesh<M> || !::hmira_test::indexed_halfedge_model<M>) { \
        GTEST_SKIP() << "not a catmull_clark_subdividable_mesh";                                            \
        return;                                                                                             \
    }

template <class M>
class catmull_clark_test : public ::testing::Test {};
TYPED_TEST_SUITE(catmull_clark_test, all_models);

/// V, E, F and the sum of face degrees of a face list, counted from the list itself.
struct vefc {
    long long v = 0, e = 0, f = 0, c = 0;
};
vefc counts_of(const face_list& g) {
    std::set<std::pair<std::size_t, std::size_t>> edges;
    vefc out{(long long)g.points.size(), 0, (long long)g.faces.size(), 0};
    for (const auto& f : g.faces) {
        out.c += (long long)f.size();
        for (std::size_t i = 0; i < f.size(); ++i) edges.insert(std::minmax(f[i], f[(i + 1) % f.size()]));
    }
    out.e = (long long)edges.size();
    return out;
}
vefc after_one_level(const vefc& k) { return {k.v + k.e + k.f, 2 * k.e + k.c, k.c, 4 * k.c}; }

/// A grid with a pentagon, a hexagon and triangles mixed in, open (one boundary loop).
face_list mixed_patch() {
    face_list g = grid(4, 3);
    // Cut two quads into triangles, merge two quads into a hexagon.
    face_list out{g.points, {}};
    for (std::size_t i = 0; i < g.faces.size(); ++i) {
        const auto& f = g.faces[i];
        if (i == 0 || i == 5) {
            out.faces.push_back({f[0], f[1], f[2]});
            out.faces.push_back({f[0], f[2], f[3]});
        } else if (i == 9) {  // quads 9 and 10 share the edge (f[1], f[2]): one hexagon
            const auto& n = g.faces[10];
            out.faces.push_back({f[0], f[1], n[1], n[2], f[2], f[3]});
        } else if (i != 10) {
            out.faces.push_back(f);
        }
    }
    return out;
}

template <class M, class T = hmira::default_traits<M>>
long long boundary_loops(const M& m) {
    std::set<std::size_t> seen;
    long long loops = 0;
    for (auto h : T::halfedges(m)) {
        if (T::face(m, h) != T::null_face() || seen.count(T::halfedge_index(m, h))) continue;
        ++loops;
        auto x = h;
        do {
            seen.insert(T::halfedge_index(m, x));
            x = T::next(m, x);
        } while (x != h);
    }
    return loops;
}

template <class M, class T = hmira::default_traits<M>>
bool all_quads(const M& m) {
    for (auto f : T::faces(m))
        if (hmira::detail::triangle_ops::loop_length<M, T>(m, T::face_halfedge(m, f), 5) != 4) return false;
    return true;
}

TYPED_TEST(catmull_clark_test, each_level_gives_the_exact_counts_on_closed_and_open_meshes_and_keeps_the_topology) {
    using M = TypeParam;
    HMIRA_REQUIRE_CATMULL_CLARK(M)
    else {
        using T = hmira::default_traits<M>;
        const face_list shapes[] = {torus(6, 5), mixed_patch(), without_faces(torus(8, 6), [](std::size_t f) {
                                        return f == 3 || f == 20 || f == 37;
                                    })};
        for (const auto& shape : shapes) {
            M m = mesh_from<M>(shape);
            vefc k = counts_of(shape);
            ASSERT_EQ((long long)T::edge_count(m), k.e);
            const long long euler = chi(m), loops = boundary_loops(m);
            for (int level = 1; level <= 3; ++level) {
                auto r = hmira::catmull_clark_subdivide(m);
                ASSERT_TRUE(r) << r.error().message;
                k = after_one_level(k);
                EXPECT_EQ((long long)T::vertex_count(m), k.v) << "level " << level;
                EXPECT_EQ((long long)T::edge_count(m), k.e) << "level " << level;
                EXPECT_EQ((long long)T::face_count(m), k.f) << "level " << level;
                EXPECT_EQ((long long)r->vertices, k.v);
                EXPECT_EQ((long long)r->edges, k.e);
                EXPECT_EQ((long long)r->faces, k.f);
                EXPECT_EQ(chi(m), euler) << "level " << level;
                EXPECT_EQ(boundary_loops(m), loops) << "level " << level;
                EXPECT_TRUE(all_quads(m));
                ASSERT_TRUE(valid_topology(m)) << "level " << level;
            }
        }
    }
}

TYPED_TEST(catmull_clark_test, levels_option_equals_repeated_single_levels) {
    using M = TypeParam;
    HMIRA_REQUIRE_CATMULL_CLARK(M)
    else {
        M a = mesh_from<M>(mixed_patch()), b = mesh_from<M>(mixed_patch());
        ASSERT_TRUE(hmira::catmull_clark_subdivide(a, {.levels = 2}));
        ASSERT_TRUE(hmira::catmull_clark_subdivide(b));
        ASSERT_TRUE(hmira::catmull_clark_subdivide(b));
        EXPECT_EQ(take_snapshot(a).positions, take_snapshot(b).positions);
        EXPECT_TRUE(canonical(a) == canonical(b));
        EXPECT_TRUE(valid_topology(a));
    }
}

TYPED_TEST(catmull_clark_test, a_cube_after_one_level_has_the_positions_of_the_masks) {
    using M = TypeParam;
    HMIRA_REQUIRE_CATMULL_CLARK(M)
    else {
        using T = hmira::default_traits<M>;
        M m;
        ASSERT_TRUE(hmira::generate_cube(m));  // [-1, 1]^3
        ASSERT_TRUE(hmira::catmull_clark_subdivide(m));
        ASSERT_TRUE(valid_topology(m));
        // By hand, for the corner (1, 1, 1) and its symmetric images: the face points are the
        // face centres (+-1, 0, 0)...; the edge (1,1,1)-(1,1,-1) has the point
        // ((1,1,1) + (1,1,-1) + (1,0,0) + (0,1,0)) / 4 = (3/4, 3/4, 0); the corner has valence 3,
        // Q = (1/3, 1/3, 1/3), R = (2/3, 2/3, 2/3), so (Q + 2R + 0 S) / 3 = (5/9, 5/9, 5/9).
        std::vector<std::array<double, 3>> expected;
        for (double x : {-1.0, 1.0})
            for (double y : {-1.0, 1.0}) {
                for (double z : {-1.0, 1.0}) expected.push_back({5 * x / 9, 5 * y / 9, 5 * z / 9});
                expected.push_back({0.75 * x, 0.75 * y, 0.0});
                expected.push_back({0.75 * x, 0.0, 0.75 * y});
                expected.push_back({0.0, 0.75 * x, 0.75 * y});
            }
        for (std::size_t axis = 0; axis < 3; ++axis)
            for (double s : {-1.0, 1.0}) {
                std::array<double, 3> p{0, 0, 0};
                p[axis] = s;
                expected.push_back(p);
            }
        ASSERT_EQ(expected.size(), 26u);
        ASSERT_EQ(T::vertex_count(m), 26u);
        // Each vertex matches one expected point (to float precision: OpenMesh's default is float).
        std::vector<bool> used(expected.size(), false);
        for (auto v : T::vertices(m)) {
            const auto p = T::position(m, v);
            bool matched = false;
            for (std::size_t i = 0; i < expected.size() && !matched; ++i) {
                if (used[i]) continue;
                const auto& q = expected[i];
                if (std::abs(double(p[0]) - q[0]) < 1e-6 && std::abs(double(p[1]) - q[1]) < 1e-6 &&
                    std::abs(double(p[2]) - q[2]) < 1e-6)
                    used[i] = matched = true;
            }
            EXPECT_TRUE(matched) << double(p[0]) << ", " << double(p[1]) << ", " << double(p[2]);
        }
    }
}

TYPED_TEST(catmull_clark_test, a_planar_grid_stays_planar_and_its_sides_stay_on_their_lines) {
    using M = TypeParam;
    HMIRA_REQUIRE_CATMULL_CLARK(M)
    else {
        using T = hmira::default_traits<M>;
        M m = mesh_from<M>(grid(4, 3));
        ASSERT_TRUE(hmira::catmull_clark_subdivide(m, {.levels = 2}));
        ASSERT_TRUE(valid_topology(m));
        for (auto v : T::vertices(m)) {
            const auto p = T::position(m, v);
            EXPECT_EQ(double(p[2]), 0.0);
            EXPECT_TRUE(p[0] >= 0 && p[0] <= 4 && p[1] >= 0 && p[1] <= 3);
            const auto s = T::vertex_halfedge(m, v);
            // The boundary is the cubic B-spline of the rectangle: away from the corners (beyond
            // one unit) it stays on the sides.
            if (T::face(m, s) == T::null_face()) {
                if (p[0] >= 1 && p[0] <= 3) {
                    EXPECT_TRUE(p[1] == 0 || p[1] == 3) << double(p[0]) << ", " << double(p[1]);
                }
                if (p[1] >= 1 && p[1] <= 2) {
                    EXPECT_TRUE(p[0] == 0 || p[0] == 4) << double(p[0]) << ", " << double(p[1]);
                }
            }
        }
    }
}

TYPED_TEST(catmull_clark_test, a_bilinear_patch_is_reproduced_away_from_its_corners) {
    using M = TypeParam;
    HMIRA_REQUIRE_CATMULL_CLARK(M)
    else {
        using T = hmira::default_traits<M>;
        // z = x y on a regular grid: bicubic B-splines reproduce it, so every face, edge and
        // regular vertex point lies on it again, and so does the boundary (z is linear along
        // each side); only the grid's corners (two boundary neighbours in different
        // directions) leave it.
        face_list g = grid(4, 4);
        for (auto& p : g.points) p.z = p.x * p.y;
        M m = mesh_from<M>(g);
        ASSERT_TRUE(hmira::catmull_clark_subdivide(m));
        ASSERT_TRUE(valid_topology(m));
        int off = 0;
        for (auto v : T::vertices(m)) {
            const auto p = T::position(m, v);
            const double x = p[0], y = p[1], z = p[2];
            if (std::abs(z - x * y) > 1e-12) {
                ++off;
                EXPECT_TRUE((x == 0.125 || x == 3.875) && (y == 0.125 || y == 3.875)) << x << ", " << y << ", " << z;
            }
        }
        EXPECT_EQ(off, 4);
        // The regular interior vertex (2, 2) in particular stays exactly where it was.
        bool found = false;
        for (auto v : T::vertices(m)) {
            const auto p = T::position(m, v);
            if (p[0] == 2 && p[1] == 2) found = (p[2] == 4);
        }
        EXPECT_TRUE(found);
    }
}

TYPED_TEST(catmull_clark_test, too_many_levels_are_refused_and_the_mesh_is_unchanged) {
    using M = TypeParam;
    HMIRA_REQUIRE_CATMULL_CLARK(M)
    else {
        M m = mesh_from<M>(torus(64, 64));
        const auto before = take_snapshot(m);
        auto r = hmira::catmull_clark_subdivide(m, {.levels = 11});
        ASSERT_FALSE(r);
        EXPECT_EQ(r.error().code, hmira::errc::invalid_argument);
        EXPECT_NE(r.error().message.find("levels"), std::string::npos);
        EXPECT_EQ(take_snapshot(m), before);
        // Ten levels of a 4096-face torus would make 4096 * 4^10 = 2^34 faces: refused before
        // anything is allocated.
        r = hmira::catmull_clark_subdivide(m, {.levels = 10});
        ASSERT_FALSE(r);
        EXPECT_EQ(r.error().code, hmira::errc::invalid_argument);
        EXPECT_NE(r.error().message.find("2^31"), std::string::npos) << r.error().message;
        EXPECT_EQ(take_snapshot(m), before);
    }
}

TYPED_TEST(catmull_clark_test, a_cancellation_at_any_point_leaves_the_mesh_unchanged) {
    using M = TypeParam;
    HMIRA_REQUIRE_CATMULL_CLARK(M)
    else {
        // 4096 quads; three levels make 16384-element blocks in every phase of levels 2 and 3.
        const M original = mesh_from<M>(torus(64, 64));
        const auto before = take_snapshot(original);
        int calls_to_finish = 0;
        {
            M m = original;
            double last = -1;
            auto r = hmira::catmull_clark_subdivide(m, {.levels = 3, .progress = [&](double f) {
                                                            EXPECT_GE(f, last);
                                                            EXPECT_LE(f, 1.0);
                                                            last = f;
                                                            ++calls_to_finish;
                                                            return true;
                                                        }});
            ASSERT_TRUE(r) << r.error().message;
            EXPECT_EQ(r->faces, 4096u * 64u);
        }
        ASSERT_GT(calls_to_finish, 8);
        for (const int stop_at : hmira_test::cancel_points(calls_to_finish, 9)) {
            M m = original;
            int calls = 0;
            auto r =
                hmira::catmull_clark_subdivide(m, {.levels = 3, .progress = [&](double) { return ++calls < stop_at; }});
            ASSERT_FALSE(r) << "stop at call " << stop_at;
            EXPECT_EQ(r.error().code, hmira::errc::cancelled);
            EXPECT_NE(r.error().message.find("cancelled"), std::string::npos);
            EXPECT_EQ(take_snapshot(m), before) << "stop at call " << stop_at;
            EXPECT_TRUE(valid_topology(m));
        }
    }
}

TEST(catmull_clark, a_face_with_an_inner_ring_is_refused_by_name_and_the_mesh_is_unchanged) {
    using M = hmira::halfedge_mesh;
    face_list g{{{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}, {1, 1, 0}, {1, 3, 0}, {3, 3, 0}, {3, 1, 0}},
                {{0, 1, 2, 3}, {4, 5, 6, 7}}};
    M m = mesh_from<M>(g);
    ASSERT_TRUE(hmira::kill_face_make_ring(m, hmira::face_handle(1), hmira::face_handle(0)));
    const auto before = take_snapshot(m);
    auto r = hmira::catmull_clark_subdivide(m);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, hmira::errc::unsupported);
    EXPECT_NE(r.error().message.find("face 0 has inner rings"), std::string::npos) << r.error().message;
    EXPECT_EQ(r.error().element, 0);
    EXPECT_EQ(take_snapshot(m), before);
}

TEST(catmull_clark, an_isolated_vertex_stays_put) {
    using M = hmira::halfedge_mesh;
    M m = mesh_from<M>(grid(1, 1));
    const auto lone = m.add_vertex({7, 8, 9});
    ASSERT_TRUE(hmira::catmull_clark_subdivide(m));
    EXPECT_EQ(m.position(lone), (hmira::vec3<double>{7, 8, 9}));
    EXPECT_EQ(m.vertex_count(), 1u + 4 + 4 + 1);
    EXPECT_EQ(m.face_count(), 4u);
}

TYPED_TEST(catmull_clark_test, coordinates_near_the_largest_double_subdivide_to_finite_positions) {
    using M = TypeParam;
    HMIRA_REQUIRE_CATMULL_CLARK(M)
    else {
        if constexpr (double(std::numeric_limits<typename hmira::default_traits<M>::scalar>::max()) < 1e308) {
            GTEST_SKIP() << "float positions cannot hold 1.7e308";
        } else {
            expect_huge_coordinates_subdivide_like_small_ones<M>(
                [](M& m) { return hmira::catmull_clark_subdivide(m, {.levels = 2}); });
        }
    }
}

TYPED_TEST(catmull_clark_test, the_callback_comes_at_least_once_per_65536_elements) {
    using M = TypeParam;
    HMIRA_REQUIRE_CATMULL_CLARK(M)
    else {
        // 4096 quads; the levels' inputs: (V, E, F) = (4096, 8192, 4096), (16384, 32768, 16384),
        // (65536, 131072, 65536). Instrumented, the first two levels only (81920 elements).
        constexpr std::size_t levels = hmira_test::sanitizer_build ? 2 : 3;
        constexpr std::size_t elements = hmira_test::sanitizer_build ? 81920 : 344064;
        expect_cancellation_restores(mesh_from<M>(torus(64, 64)), elements, [](M& x, hmira::progress_function p) {
            return hmira::catmull_clark_subdivide(x, {.levels = levels, .progress = std::move(p)});
        });
    }
}

}  // namespace
