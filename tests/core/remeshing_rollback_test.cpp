// isotropic_remeshing under the rollback rule (docs/new-algorithm.md): it rewrites the mesh
// in place over a copy taken before the first change, which a cancellation restores.
#include <hmira/algorithms/remeshing/isotropic_remeshing.hpp>

#include "core/rollback_support.hpp"

namespace {

template <class M>
struct remesh_rollback : ::testing::Test {};
TYPED_TEST_SUITE(remesh_rollback, hmira_test::all_models);

TYPED_TEST(remesh_rollback, a_late_cancellation_leaves_the_mesh_bit_identical) {
    using M = TypeParam;
    if constexpr (!hmira::remeshable_mesh<M>) {
        GTEST_SKIP() << "not a remeshable model";
    } else {
        const auto g = hmira_test::triangulated(hmira_test::torus(24, 16));
        hmira_test::expect_cancel_restores([&] { return hmira_test::build<M>(g); },
                                           [](M& m, const hmira::progress_function& p) {
                                               return hmira::isotropic_remeshing(
                                                   m, {.target_edge_length = 0.3, .iterations = 2, .progress = p});
                                           });
    }
}

TYPED_TEST(remesh_rollback, a_late_cancellation_of_a_rescaled_mesh_leaves_it_bit_identical) {
    using M = TypeParam;
    if constexpr (!hmira::remeshable_mesh<M>) {
        GTEST_SKIP() << "not a remeshable model";
    } else if constexpr (!std::is_same_v<typename hmira::default_traits<M>::scalar, double>) {
        GTEST_SKIP() << "a float model cannot hold the scale";
    } else {
        // Far from unit size the remesher scales the mesh before it starts: the copy must
        // restore the unscaled positions too.
        auto g = hmira_test::triangulated(hmira_test::torus(24, 16));
        for (auto& p : g.points) p = p * 0x1p300;
        hmira_test::expect_cancel_restores(
            [&] { return hmira_test::build<M>(g); },
            [](M& m, const hmira::progress_function& p) {
                return hmira::isotropic_remeshing(
                    m, {.target_edge_length = 0.3 * 0x1p300, .iterations = 2, .progress = p});
            });
    }
}

TYPED_TEST(remesh_rollback, a_refused_call_leaves_the_mesh_bit_identical) {
    using M = TypeParam;
    if constexpr (!hmira::remeshable_mesh<M>) {
        GTEST_SKIP() << "not a remeshable model";
    } else {
        const auto g = hmira_test::triangulated(hmira_test::torus(12, 8));
        const auto make = [&] { return hmira_test::build<M>(g); };
        hmira_test::expect_failure_leaves_mesh(
            make, [](M& m) { return hmira::isotropic_remeshing(m, {.target_edge_length = -1}); },
            hmira::errc::invalid_argument);
        hmira_test::expect_failure_leaves_mesh(
            make,
            [](M& m) {
                return hmira::isotropic_remeshing(m, {.target_edge_length = 0.3, .feature_edges = {1u << 30}});
            },
            hmira::errc::invalid_argument);
    }
}

}  // namespace
