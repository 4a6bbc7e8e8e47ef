// decimate under the rollback rule (docs/new-algorithm.md): a whole-mesh rewrite restores the
// copy it took when the callback cancels late; a refused call changes nothing.
#include <hmira/algorithms/decimation/decimate.hpp>

#include "core/rollback_support.hpp"

namespace {

template <class M>
struct decimate_rollback : ::testing::Test {};
TYPED_TEST_SUITE(decimate_rollback, hmira_test::all_models);

TYPED_TEST(decimate_rollback, a_late_cancellation_leaves_the_mesh_bit_identical) {
    using M = TypeParam;
    if constexpr (!hmira::decimatable_mesh<M>) {
        GTEST_SKIP() << "not a decimatable model";
    } else {
        const auto g = hmira_test::triangulated(hmira_test::torus(96, 64));
        hmira_test::expect_cancel_restores([&] { return hmira_test::build<M>(g); },
                                           [](M& m, const hmira::progress_function& p) {
                                               return hmira::decimate(m, {.target_ratio = 0.1, .progress = p});
                                           });
    }
}

TYPED_TEST(decimate_rollback, a_refused_call_leaves_the_mesh_bit_identical) {
    using M = TypeParam;
    if constexpr (!hmira::decimatable_mesh<M>) {
        GTEST_SKIP() << "not a decimatable model";
    } else {
        const auto g = hmira_test::triangulated(hmira_test::torus(12, 8));
        const auto make = [&] { return hmira_test::build<M>(g); };
        hmira_test::expect_failure_leaves_mesh(
            make, [](M& m) { return hmira::decimate(m, {.target_ratio = 0.5, .max_normal_angle = 200}); },
            hmira::errc::invalid_argument);
        hmira_test::expect_failure_leaves_mesh(
            make, [](M& m) { return hmira::decimate(m, {.target_ratio = 0.5, .locked_vertices = {100000}}); },
            hmira::errc::invalid_argument);
    }
}

}  // namespace
