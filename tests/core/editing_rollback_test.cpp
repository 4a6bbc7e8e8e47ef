// truncate, bevel and extrude under the rollback rule (docs/new-algorithm.md): they are chains
// of Euler operators run through the editing journal, so a cancellation at the last report
// and a refusal leave the mesh bit for bit as it was.
#include <hmira/algorithms/editing/editing.hpp>

#include "core/rollback_support.hpp"

namespace {

template <class M>
struct editing_rollback : ::testing::Test {};
TYPED_TEST_SUITE(editing_rollback, hmira_test::all_models);

// 3072 quads, vertices and 6144 edges: the edits report once every 1024 elements.
const hmira_test::face_list& shape() {
    static const auto g = hmira_test::torus(64, 48);
    return g;
}

template <class M>
auto all_vertices(const M& m) {
    using T = hmira::default_traits<M>;
    std::vector<typename T::vertex_handle> out;
    for (auto v : T::vertices(m)) out.push_back(v);
    return out;
}

template <class M>
auto all_edges(const M& m) {
    using T = hmira::default_traits<M>;
    std::vector<typename T::edge_handle> out;
    for (auto e : T::edges(m)) out.push_back(e);
    return out;
}

template <class M>
auto all_faces(const M& m) {
    using T = hmira::default_traits<M>;
    std::vector<typename T::face_handle> out;
    for (auto f : T::faces(m)) out.push_back(f);
    return out;
}

TYPED_TEST(editing_rollback, a_late_cancellation_leaves_the_mesh_bit_identical) {
    using M = TypeParam;
    if constexpr (!hmira::extrudable_mesh<M>) {
        GTEST_SKIP() << "not an editable model";
    } else {
        const auto make = [] { return hmira_test::build<M>(shape()); };
        {
            SCOPED_TRACE("truncate");
            hmira_test::expect_cancel_restores(make, [](M& m, const hmira::progress_function& p) {
                return hmira::truncate<M>(m, all_vertices(m), {.fraction = 0.25, .progress = p});
            });
        }
        {
            SCOPED_TRACE("bevel");
            hmira_test::expect_cancel_restores(make, [](M& m, const hmira::progress_function& p) {
                return hmira::bevel<M>(m, all_edges(m), {.width = 0.01, .progress = p});
            });
        }
        {
            SCOPED_TRACE("extrude");
            hmira_test::expect_cancel_restores(make, [](M& m, const hmira::progress_function& p) {
                return hmira::extrude<M>(m, all_faces(m),
                                         {.distance = 0.1, .mode = hmira::extrude_mode::individual, .progress = p});
            });
        }
    }
}

TYPED_TEST(editing_rollback, a_refused_call_leaves_the_mesh_bit_identical) {
    using M = TypeParam;
    if constexpr (!hmira::extrudable_mesh<M>) {
        GTEST_SKIP() << "not an editable model";
    } else {
        const auto make = [] { return hmira_test::build<M>(shape()); };
        hmira_test::expect_failure_leaves_mesh(
            make, [](M& m) { return hmira::truncate<M>(m, all_vertices(m), {.fraction = 1.5}); },
            hmira::errc::invalid_argument);
        hmira_test::expect_failure_leaves_mesh(
            make, [](M& m) { return hmira::bevel<M>(m, all_edges(m), {.width = -1}); }, hmira::errc::invalid_argument);
        hmira_test::expect_failure_leaves_mesh(
            make, [](M& m) { return hmira::bevel<M>(m, all_edges(m), {.segments = 100}); },
            hmira::errc::invalid_argument);
        hmira_test::expect_failure_leaves_mesh(
            make,
            [](M& m) {
                return hmira::extrude<M>(m, all_faces(m), {.distance = std::numeric_limits<double>::quiet_NaN()});
            },
            hmira::errc::invalid_argument);
    }
}

}  // namespace
