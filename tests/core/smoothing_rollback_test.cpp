// laplacian_smooth and taubin_smooth under the rollback rule (docs/new-algorithm.md): they move
// vertices only, so what a cancellation or a refusal restores is the starting positions.
#include <hmira/algorithms/smoothing/laplacian_smooth.hpp>

#include "core/rollback_support.hpp"

namespace {

template <class M>
struct smooth_rollback : ::testing::Test {};
TYPED_TEST_SUITE(smooth_rollback, hmira_test::all_models);

// 2048 vertices: a step visits them all, and the callback comes every 65536 visits.
const hmira_test::face_list& shape() {
    static const auto g = hmira_test::triangulated(hmira_test::torus(64, 32));
    return g;
}

TYPED_TEST(smooth_rollback, a_late_cancellation_of_laplacian_leaves_the_mesh_bit_identical) {
    using M = TypeParam;
    if constexpr (!hmira::smoothable_mesh<M>) {
        GTEST_SKIP() << "not a smoothable model";
    } else {
        for (const auto weights : {hmira::laplacian_weights::uniform, hmira::laplacian_weights::cotangent}) {
            hmira_test::expect_cancel_restores([] { return hmira_test::build<M>(shape()); },
                                               [&](M& m, const hmira::progress_function& p) {
                                                   return hmira::laplacian_smooth(
                                                       m, {.iterations = 100, .weights = weights, .progress = p});
                                               });
        }
    }
}

TYPED_TEST(smooth_rollback, a_late_cancellation_of_taubin_leaves_the_mesh_bit_identical) {
    using M = TypeParam;
    if constexpr (!hmira::smoothable_mesh<M>) {
        GTEST_SKIP() << "not a smoothable model";
    } else {
        hmira_test::expect_cancel_restores([] { return hmira_test::build<M>(shape()); },
                                           [](M& m, const hmira::progress_function& p) {
                                               return hmira::taubin_smooth(m, {.iterations = 50, .progress = p});
                                           });
    }
}

TYPED_TEST(smooth_rollback, a_refused_call_leaves_the_mesh_bit_identical) {
    using M = TypeParam;
    if constexpr (!hmira::smoothable_mesh<M>) {
        GTEST_SKIP() << "not a smoothable model";
    } else {
        const auto make = [] { return hmira_test::build<M>(shape()); };
        hmira_test::expect_failure_leaves_mesh(
            make, [](M& m) { return hmira::laplacian_smooth(m, {.lambda = 0}); }, hmira::errc::invalid_argument);
        hmira_test::expect_failure_leaves_mesh(
            make, [](M& m) { return hmira::taubin_smooth(m, {.fixed_vertices = {1u << 30}}); },
            hmira::errc::invalid_argument);
    }
}

TYPED_TEST(smooth_rollback, a_refusal_after_some_steps_leaves_the_mesh_bit_identical) {
    using M = TypeParam;
    if constexpr (!hmira::smoothable_mesh<M>) {
        GTEST_SKIP() << "not a smoothable model";
    } else if constexpr (!std::is_same_v<typename hmira::default_traits<M>::scalar, double>) {
        GTEST_SKIP() << "a float model cannot hold coordinates near the largest double";
    } else {
        // Taubin's inflating step extrapolates: near the largest double it would leave the range
        // of double some steps in, and the call is refused after it has moved every vertex.
        auto g = hmira_test::triangulated(hmira_test::torus(16, 8));
        for (auto& p : g.points) p = p * 0x1p1020;
        hmira_test::expect_failure_leaves_mesh(
            [&] { return hmira_test::build<M>(g); },
            [](M& m) { return hmira::taubin_smooth(m, {.iterations = 2000, .lambda = 0.9, .mu = -1}); },
            hmira::errc::unsupported);
    }
}

}  // namespace
