// loop_subdivide, sqrt3_subdivide and catmull_clark_subdivide under the rollback rule
// (docs/new-algorithm.md): a whole-mesh rewrite restores the copy it took when the callback
// cancels late; a refused call changes nothing.
#include <hmira/algorithms/subdivision/subdivide.hpp>

#include "core/rollback_support.hpp"

namespace {

template <class M>
struct subdivide_rollback : ::testing::Test {};
TYPED_TEST_SUITE(subdivide_rollback, hmira_test::all_models);

// The levels count 16384 elements between two calls of the callback.
const hmira_test::face_list& quads() {
    static const auto g = hmira_test::torus(64, 48);
    return g;
}
const hmira_test::face_list& triangles() {
    static const auto g = hmira_test::triangulated(quads());
    return g;
}

TYPED_TEST(subdivide_rollback, a_late_cancellation_of_loop_leaves_the_mesh_bit_identical) {
    using M = TypeParam;
    if constexpr (!hmira::loop_subdividable_mesh<M>) {
        GTEST_SKIP() << "not a model loop_subdivide runs on";
    } else {
        hmira_test::expect_cancel_restores([] { return hmira_test::build<M>(triangles()); },
                                           [](M& m, const hmira::progress_function& p) {
                                               return hmira::loop_subdivide(m, {.levels = 2, .progress = p});
                                           });
    }
}

TYPED_TEST(subdivide_rollback, a_late_cancellation_of_sqrt3_leaves_the_mesh_bit_identical) {
    using M = TypeParam;
    if constexpr (!hmira::sqrt3_subdividable_mesh<M>) {
        GTEST_SKIP() << "not a model sqrt3_subdivide runs on";
    } else {
        // Open: the second level trisects the boundary too.
        const auto g = hmira_test::triangulated(hmira_test::grid(96, 64));
        hmira_test::expect_cancel_restores([&] { return hmira_test::build<M>(g); },
                                           [](M& m, const hmira::progress_function& p) {
                                               return hmira::sqrt3_subdivide(m, {.levels = 2, .progress = p});
                                           });
    }
}

TYPED_TEST(subdivide_rollback, a_late_cancellation_of_catmull_clark_leaves_the_mesh_bit_identical) {
    using M = TypeParam;
    if constexpr (!hmira::catmull_clark_subdividable_mesh<M>) {
        GTEST_SKIP() << "not a model catmull_clark_subdivide runs on";
    } else {
        hmira_test::expect_cancel_restores([] { return hmira_test::build<M>(quads()); },
                                           [](M& m, const hmira::progress_function& p) {
                                               return hmira::catmull_clark_subdivide(m, {.levels = 2, .progress = p});
                                           });
    }
}

TYPED_TEST(subdivide_rollback, a_late_cancellation_through_subdivide_leaves_the_mesh_bit_identical) {
    using M = TypeParam;
    if constexpr (!hmira::subdividable_mesh<M>) {
        GTEST_SKIP() << "not a model every scheme runs on";
    } else {
        hmira_test::expect_cancel_restores(
            [] { return hmira_test::build<M>(triangles()); },
            [](M& m, const hmira::progress_function& p) {
                return hmira::subdivide(m, {.scheme = hmira::subdivision_scheme::sqrt3, .levels = 2, .progress = p});
            });
    }
}

TYPED_TEST(subdivide_rollback, a_refused_call_leaves_the_mesh_bit_identical) {
    using M = TypeParam;
    if constexpr (!hmira::loop_subdividable_mesh<M>) {
        GTEST_SKIP() << "not a model loop_subdivide runs on";
    } else {
        const auto g = hmira_test::triangulated(hmira_test::torus(8, 6));
        const auto make = [&] { return hmira_test::build<M>(g); };
        hmira_test::expect_failure_leaves_mesh(
            make, [](M& m) { return hmira::loop_subdivide(m, {.levels = 11}); }, hmira::errc::invalid_argument);
        hmira_test::expect_failure_leaves_mesh(
            make, [](M& m) { return hmira::sqrt3_subdivide(m, {.levels = 21}); }, hmira::errc::invalid_argument);
        if constexpr (hmira::catmull_clark_subdividable_mesh<M>) {
            hmira_test::expect_failure_leaves_mesh(
                make, [](M& m) { return hmira::catmull_clark_subdivide(m, {.levels = 11}); },
                hmira::errc::invalid_argument);
        }
    }
}

TYPED_TEST(subdivide_rollback, a_polygon_mesh_refused_by_loop_and_sqrt3_is_left_bit_identical) {
    using M = TypeParam;
    if constexpr (!hmira::catmull_clark_subdividable_mesh<M>) {
        GTEST_SKIP() << "not a polygon model";
    } else {
        const auto make = [] { return hmira_test::build<M>(hmira_test::torus(8, 6)); };
        hmira_test::expect_failure_leaves_mesh(
            make, [](M& m) { return hmira::loop_subdivide(m); }, hmira::errc::topology);
        hmira_test::expect_failure_leaves_mesh(
            make, [](M& m) { return hmira::sqrt3_subdivide(m); }, hmira::errc::topology);
    }
}

}  // namespace
