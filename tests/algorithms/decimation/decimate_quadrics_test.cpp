// decimate's quadrics carried from one run to the next (start_quadrics, return_quadrics): two runs
// with carried quadrics make the same mesh as one run, the returned quadrics add up to the planes of
// the input faces, and starting quadrics of the wrong size or not finite are refused by name.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <hmira/algorithms/decimation/decimate.hpp>

#include "algorithms/decimation/decimation_support.hpp"
#include "algorithms/triangle/triangle_support.hpp"

namespace {

using namespace hmira_test;

template <class M>
class decimate_quadrics_test : public ::testing::Test {};
TYPED_TEST_SUITE(decimate_quadrics_test, all_models);

/// The quadric x^T A x + 2 b.x + c of 10 numbers (start_quadrics' layout) at p.
double quadric_at(const double* q, const hmira::vec3<double>& p) {
    return q[0] * p.x * p.x + q[3] * p.y * p.y + q[5] * p.z * p.z +
           2 * (q[1] * p.x * p.y + q[2] * p.x * p.z + q[4] * p.y * p.z + q[6] * p.x + q[7] * p.y + q[8] * p.z) + q[9];
}

TYPED_TEST(decimate_quadrics_test, two_runs_with_carried_quadrics_make_the_mesh_of_one_run) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        // With holes and boundary edges that may collapse, and with feature edges: the planes of
        // edges are carried as well as those of faces.
        const face_list input = bumpy_torus(12, 8, true, 11);
        for (const bool features : {false, true}) {
            hmira::decimate_options one{.target_faces = 40, .keep_boundary = features};
            if (features) one.feature_angle = 20;
            M whole = mesh_from<M>(input), steps = mesh_from<M>(input), forgetful = mesh_from<M>(input);
            ASSERT_TRUE(hmira::decimate(whole, one));
            hmira::decimate_options first = one;
            first.target_faces = 90;
            first.return_quadrics = true;
            auto r = hmira::decimate(steps, first);
            ASSERT_TRUE(r);
            ASSERT_LE(r->faces, 90u);
            ASSERT_GT(r->faces, 40u);
            hmira::decimate_options second = one;
            second.start_quadrics = r->quadrics;
            ASSERT_TRUE(hmira::decimate(steps, second));
            EXPECT_EQ(take_snapshot(steps), take_snapshot(whole)) << "features " << features;
            // Starting again from the planes of the coarse faces forgets the first run's planes.
            ASSERT_TRUE(hmira::decimate(forgetful, {.target_faces = 90, .keep_boundary = features}));
            ASSERT_TRUE(hmira::decimate(forgetful, {.target_faces = 40, .keep_boundary = features}));
            EXPECT_NE(take_snapshot(forgetful), take_snapshot(whole));
        }
    }
}

TYPED_TEST(decimate_quadrics_test, returned_quadrics_add_up_to_three_times_the_planes_of_the_input_faces) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        const face_list input = bumpy_torus(10, 7, false, 4);
        M m = mesh_from<M>(input);
        // Each face's plane, summed in every corner's quadric (unweighted), and a collapse adds
        // the quadric that goes to the one that stays: the sum over the vertices never changes.
        const std::array<hmira::vec3<double>, 3> probes = {{{0.3, -1.2, 0.4}, {2, 0.5, -0.1}, {-0.7, 0.1, 1.5}}};
        std::array<double, 3> planes{};
        using S = typename T::scalar;  // the positions as the model holds them
        const auto at = [&](std::size_t i) {
            const auto& p = input.points[i];
            return hmira::vec3<double>{double(S(p.x)), double(S(p.y)), double(S(p.z))};
        };
        for (const auto& f : input.faces) {
            const auto a = at(f[0]), b = at(f[1]), c = at(f[2]);
            const auto n = hmira::cross(b - a, c - a);
            for (std::size_t i = 0; i < 3; ++i) {
                const double d = hmira::dot(n, probes[i] - a);
                planes[i] += 3 * d * d / hmira::squared_norm(n);
            }
        }
        auto r = hmira::decimate(m, {.target_faces = 60, .area_weighted = false, .return_quadrics = true});
        ASSERT_TRUE(r);
        ASSERT_EQ(r->quadrics.size(), 10 * T::vertex_index_bound(m));
        std::vector<char> live(T::vertex_index_bound(m), 0);
        for (auto v : T::vertices(m)) live[T::vertex_index(m, v)] = 1;
        std::array<double, 3> sums{};
        for (std::size_t v = 0; v < live.size(); ++v) {
            const double* q = r->quadrics.data() + 10 * v;
            if (!live[v]) {
                for (std::size_t k = 0; k < 10; ++k) EXPECT_EQ(q[k], 0.0) << "removed vertex " << v;
                continue;
            }
            for (std::size_t i = 0; i < 3; ++i) sums[i] += quadric_at(q, probes[i]);
        }
        for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(sums[i], planes[i], 1e-9 * planes[i]) << "probe " << i;
    }
}

TYPED_TEST(decimate_quadrics_test, starting_quadrics_of_the_wrong_size_or_not_finite_are_refused) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        M m = mesh_from<M>(bumpy_torus(8, 6, false, 5));
        const auto before = take_snapshot(m);
        std::vector<double> bad(10 * T::vertex_index_bound(m), 0.0);
        bad[10 * 3 + 9] = std::numeric_limits<double>::infinity();
        const std::pair<std::vector<double>, const char*> cases[] = {
            {std::vector<double>(10 * T::vertex_index_bound(m) - 1, 0.0), "needs 10 numbers per vertex index"},
            {bad, "non-finite number at vertex 3"},
        };
        for (const auto& [quadrics, what] : cases) {
            auto r = hmira::decimate(m, {.target_faces = 10, .start_quadrics = quadrics});
            ASSERT_FALSE(r) << what;
            EXPECT_EQ(r.error().code, hmira::errc::invalid_argument);
            EXPECT_NE(r.error().message.find("start_quadrics"), std::string::npos) << r.error().message;
            EXPECT_NE(r.error().message.find(what), std::string::npos) << r.error().message;
            EXPECT_EQ(take_snapshot(m), before) << what;
        }
    }
}

}  // namespace
