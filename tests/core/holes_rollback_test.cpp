// fill_hole and fill_holes under the rollback rule (docs/new-algorithm.md): their patches are
// local edits, journaled on every shipped half-edge model, so a late cancellation (during
// refinement and fairing) is undone from the journal; a refused call changes nothing.
#include <hmira/algorithms/holes/fill_hole.hpp>

#include "core/rollback_support.hpp"

namespace {

template <class M>
struct holes_rollback : ::testing::Test {};
TYPED_TEST_SUITE(holes_rollback, hmira_test::all_models);

/// A triangulated torus with two holes: one of 4 x 4 quads and one of 8 x 6 quads.
const hmira_test::face_list& holed() {
    static const auto g = hmira_test::compacted(
        hmira_test::triangulated(hmira_test::without_faces(hmira_test::torus(48, 24), [](std::size_t f) {
            const std::size_t i = f / 24, j = f % 24;
            return (i >= 4 && i < 8 && j >= 4 && j < 8) || (i >= 20 && i < 28 && j >= 10 && j < 16);
        })));
    return g;
}

TYPED_TEST(holes_rollback, a_late_cancellation_of_fill_holes_leaves_the_mesh_bit_identical) {
    using M = TypeParam;
    if constexpr (!hmira::hole_fillable_mesh<M>) {
        GTEST_SKIP() << "not a model fill_holes runs on";
    } else {
        hmira_test::expect_cancel_restores(
            [] { return hmira_test::build<M>(holed()); },
            [](M& m, const hmira::progress_function& p) {
                return hmira::fill_holes(m, 100, {.refine = true, .fair = hmira::fairing::thin_plate, .progress = p});
            });
    }
}

TYPED_TEST(holes_rollback, a_late_cancellation_of_fill_hole_leaves_the_mesh_bit_identical) {
    using M = TypeParam;
    using T = hmira::default_traits<M>;
    if constexpr (!hmira::hole_fillable_mesh<M>) {
        GTEST_SKIP() << "not a model fill_hole runs on";
    } else {
        hmira_test::expect_cancel_restores(
            [] { return hmira_test::build<M>(holed()); },
            [](M& m, const hmira::progress_function& p) {
                // The longer loop: the hole of 8 x 6 quads.
                typename T::halfedge_handle longest{};
                std::size_t most = 0;
                for (auto h : T::halfedges(m)) {
                    if (T::face(m, h) != T::null_face()) continue;
                    std::size_t n = 0;
                    auto x = h;
                    do {
                        ++n;
                        x = T::next(m, x);
                    } while (x != h);
                    if (n > most) most = n, longest = h;
                }
                return hmira::fill_hole(m, longest, {.refine = true, .fair = hmira::fairing::membrane, .progress = p});
            });
    }
}

TYPED_TEST(holes_rollback, a_refused_call_leaves_the_mesh_bit_identical) {
    using M = TypeParam;
    if constexpr (!hmira::hole_fillable_mesh<M>) {
        GTEST_SKIP() << "not a model fill_holes runs on";
    } else {
        const auto make = [] { return hmira_test::build<M>(holed()); };
        hmira_test::expect_failure_leaves_mesh(
            make, [](M& m) { return hmira::fill_holes(m, 2); }, hmira::errc::invalid_argument);
        hmira_test::expect_failure_leaves_mesh(
            make, [](M& m) { return hmira::fill_holes(m, 100, {.refine_density = -1}); },
            hmira::errc::invalid_argument);
    }
}

}  // namespace
