// Randomised: seeded random sequences of truncate, bevel (random segments) and extrude on random closed
// meshes (tori and lattice boxes) stay valid, manifold, closed and of the same genus, and
// every step has the delta its documentation gives.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include <hmira/algorithms/generators/torus.hpp>

#include "algorithms/editing/editing_support.hpp"

namespace {

using namespace hmira_test;

template <class M>
class random_edit_test : public ::testing::Test {};
TYPED_TEST_SUITE(random_edit_test, hmira_test::all_models);

template <class M, class T = hmira::default_traits<M>>
std::vector<typename T::vertex_handle> all_vertices(const M& m) {
    std::vector<typename T::vertex_handle> out;
    for (auto v : T::vertices(m)) out.push_back(v);
    return out;
}

TYPED_TEST(random_edit_test, random_edit_sequences_keep_closed_meshes_valid_and_manifold) {
    if constexpr (!hmira::extrudable_mesh<TypeParam>) {
        GTEST_SKIP() << "model cannot be edited";
    } else {
        using T = hmira::default_traits<TypeParam>;
#ifdef HMIRA_SANITIZER_BUILD
        const int steps = 25;
#else
        const int steps = 60;
#endif
        for (unsigned seed = 1; seed <= 4; ++seed) {
            std::mt19937 rng(seed);
            TypeParam m;
            long long chi = 0;
            if (seed % 2) {
                (void)hmira::generate_torus(m, {.major_radius = 3, .minor_radius = 1, .rings = 8 + seed, .sides = 6})
                    .value();
                chi = 0;
            } else {
                ASSERT_TRUE(add_face_list(m, lattice_box(2 + (int)seed, 2, 2)));
                chi = 2;
            }
            for (int step = 0; step < steps; ++step) {
                const auto before = count(m);
                const int op = (int)(rng() % 3);
                SCOPED_TRACE(::testing::Message() << "seed " << seed << " step " << step << " op " << op);
                if (op == 0) {
                    auto vs = all_vertices(m);
                    const auto v = vs[rng() % vs.size()];
                    const auto d = (long long)degree(m, v);
                    auto r = hmira::truncate(m, v, {.fraction = 0.2 + 0.1 * double(rng() % 3)});
                    ASSERT_TRUE(r) << r.error().message;
                    EXPECT_EQ(count(m), (counts{before.v + d - 1, before.e + d, before.f + 1}));
                } else if (op == 1) {
                    std::vector<typename T::face_handle> fs;
                    for (auto f : T::faces(m)) fs.push_back(f);
                    const auto f = fs[rng() % fs.size()];
                    const auto n = (long long)std::ranges::distance(T::face_vertices(m, f));
                    const double dist = (rng() % 2 ? 1.0 : -1.0) * 0.05;
                    auto r = hmira::extrude(m, f, {.distance = dist});
                    ASSERT_TRUE(r) << r.error().message;
                    EXPECT_EQ(count(m), (counts{before.v + n, before.e + 2 * n, before.f + n}));
                } else {
                    std::vector<typename T::edge_handle> es;
                    for (auto e : T::edges(m)) es.push_back(e);
                    const auto e = es[rng() % es.size()];
                    const int segments = 1 + (int)(rng() % 6);
                    auto r = hmira::bevel(m, e, {.width = 0.02, .segments = segments});
                    // Near-collinear corners after earlier edits may be refused; never a broken mesh.
                    if (!r) {
                        EXPECT_EQ(r.error().code, hmira::errc::unsupported) << r.error().message;
                        EXPECT_EQ(count(m), before);
                    } else {
                        // No face goes; the strip (segments faces, or one when both ends stay)
                        // and the vertex patches are new.
                        EXPECT_EQ(count(m).f, before.f + (long long)(r->strip_faces.size() + r->vertex_faces.size()));
                        EXPECT_TRUE(r->strip_faces.size() == 1 || r->strip_faces.size() == std::size_t(segments));
                    }
                }
                // Topology is checked strictly; geometry is not: a bevel clamped at half an edge
                // may, by design, make points from both ends coincide (documented).
                ASSERT_TRUE(valid_with_chi(m, chi, {.relaxed = false, .check_geometry = false}));
                const auto topo = hmira::mesh_topology(m);
                ASSERT_TRUE(topo.closed());
                ASSERT_EQ(topo.components, 1u);
            }
        }
    }
}

}  // namespace
