// add_face on polygons of every size: link_face runs unrolled copies for triangles and quads and
// a general one (with scratch buffers past 8 corners), so random polygon soups of 3 to 11
// corners go through all three. Whether a face can be added does not depend on which corner
// the list starts at, so a second mesh fed every face rotated must accept and refuse exactly
// the same faces; a refusal must change nothing, an acceptance must keep the mesh valid
// (pinches aside) with the face's corners in the order given.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include <hmira/algorithms/topology/mesh_topology.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>
#include <hmira/meshes/winged_edge_mesh.hpp>

#include "support/checks.hpp"
#include "support/snapshot.hpp"

namespace {

using namespace hmira;

// Faces added out of order may meet at a vertex in separate fans before the faces between them
// arrive (a pinch); everything else must be valid at every step.
template <class M>
::testing::AssertionResult valid_but_maybe_pinched(const M& m) {
    auto ps = validate(m, {.relaxed = true, .check_geometry = false});
    std::erase_if(ps, [](const mesh_problem& p) {
        return p.kind == problem_kind::non_manifold_vertex && p.message.find("separate fans") != std::string::npos;
    });
    if (ps.empty()) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << hmira_test::describe(ps);
}

template <class M>
void soups_agree_with_their_rotations(unsigned seed, int vertices, std::size_t max_corners) {
    std::mt19937 rng(seed);
    std::size_t accepted = 0, refused = 0, accepted_large = 0;
    for (int trial = 0; trial < 40; ++trial) {
        M a, b;
        std::vector<vertex_handle> va, vb;
        for (int i = 0; i < vertices; ++i) {
            const vec3<double> p{double(i), double(i * i % 7), double(i % 3)};
            va.push_back(a.add_vertex(p));
            vb.push_back(b.add_vertex(p));
        }
        for (int step = 0; step < 80; ++step) {
            // Mostly triangles and quads (the unrolled paths), some larger polygons.
            const std::size_t n = rng() % 3 != 0 ? 3 + rng() % 2 : 3 + rng() % (max_corners - 2);
            std::vector<int> ids(static_cast<std::size_t>(vertices));
            for (int i = 0; i < vertices; ++i) ids[std::size_t(i)] = i;
            std::shuffle(ids.begin(), ids.end(), rng);
            ids.resize(n);
            const std::size_t k = rng() % n;
            std::vector<vertex_handle> fa, fb;
            for (std::size_t i = 0; i < n; ++i) {
                fa.push_back(va[std::size_t(ids[i])]);
                fb.push_back(vb[std::size_t(ids[(i + k) % n])]);
            }
            const auto before_a = hmira_test::snapshot(a), before_b = hmira_test::snapshot(b);
            const auto ra = a.add_face(fa);
            const auto rb = b.add_face(fb);
            ASSERT_EQ(bool(ra), bool(rb)) << "trial " << trial << " step " << step << " n " << n << " rotation " << k
                                          << ": " << (ra ? rb.error().message : ra.error().message);
            if (!ra) {
                ++refused;
                EXPECT_FALSE(ra.error().message.empty());
                EXPECT_EQ(hmira_test::snapshot(a), before_a) << ra.error().message;
                EXPECT_EQ(hmira_test::snapshot(b), before_b) << rb.error().message;
                continue;
            }
            ++accepted;
            if (n > 8) ++accepted_large;
            std::vector<vertex_handle> got;
            for (auto v : a.face_vertices(*ra)) got.push_back(v);
            EXPECT_EQ(got, fa);
            ASSERT_EQ(a.face_count(), b.face_count());
            ASSERT_EQ(a.edge_count(), b.edge_count());
            ASSERT_TRUE(valid_but_maybe_pinched(a)) << "trial " << trial << " step " << step;
            ASSERT_TRUE(valid_but_maybe_pinched(b)) << "trial " << trial << " step " << step;
        }
    }
    // The soups must exercise both outcomes, large polygons included.
    EXPECT_GT(accepted, 500u);
    EXPECT_GT(refused, 500u);
    EXPECT_GT(accepted_large, 20u);
}

TEST(link_face, halfedge_mesh_polygon_soups_agree_with_their_rotations) {
    soups_agree_with_their_rotations<halfedge_mesh>(7, 16, 11);
    soups_agree_with_their_rotations<halfedge_mesh>(8, 24, 11);
}

TEST(link_face, winged_edge_mesh_polygon_soups_agree_with_their_rotations) {
    soups_agree_with_their_rotations<winged_edge_mesh>(9, 16, 11);
}

// The first failure is reported in corner order on every path: an interior corner before the
// edge check of the same corner, and a corner's edge before the next corner's interior check.
TEST(link_face, first_failure_in_corner_order_for_every_size) {
    for (std::size_t n : {3u, 4u, 5u, 9u, 12u}) {
        halfedge_mesh m;
        // A closed fan: hub 0 with rim 1..n, so vertex 0 is interior.
        std::vector<vertex_handle> v;
        for (std::size_t i = 0; i <= n + 1 + 2 * n; ++i) v.push_back(m.add_vertex({double(i), 0, 0}));
        for (std::size_t i = 1; i <= n; ++i) ASSERT_TRUE(m.add_face({v[0], v[i], v[i % n + 1]}));
        ASSERT_FALSE(m.is_boundary(v[0]));
        const auto before = hmira_test::snapshot(m);
        // n corners: the rim edge 1 -> 2 already carries a face (non-manifold edge: it is
        // used in this direction) at corner 0, the interior hub at corner 1.
        std::vector<vertex_handle> face{v[1], v[2], v[0]};
        for (std::size_t i = 3; face.size() < n; ++i) face.push_back(v[n + i]);
        auto r = m.add_face(face);
        ASSERT_FALSE(r) << n;
        EXPECT_EQ(r.error().code, errc::orientation_conflict) << n << ": " << r.error().message;
        EXPECT_EQ(hmira_test::snapshot(m), before);
        // Interior hub first: reported as the interior vertex.
        std::vector<vertex_handle> face2{v[0], v[2], v[1]};
        for (std::size_t i = 3; face2.size() < n; ++i) face2.push_back(v[n + i]);
        auto r2 = m.add_face(face2);
        ASSERT_FALSE(r2) << n;
        EXPECT_EQ(r2.error().code, errc::non_manifold) << n;
        EXPECT_NE(r2.error().message.find("interior"), std::string::npos) << n << ": " << r2.error().message;
        EXPECT_EQ(hmira_test::snapshot(m), before);
    }
}

}  // namespace
