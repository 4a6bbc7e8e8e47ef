// Cancelling truncate, bevel and extrude through their options' progress callback: the edit
// reports once every 1024 elements it builds; when the callback returns false
// at the k-th report the edit stops, returns an error ending in "cancelled", and leaves the
// mesh exactly as it was (every live element, its links and its position).
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/editing/editing_support.hpp"
#include "support/cancel_points.hpp"

namespace {

using hmira_test::face_list;

/// What the mesh looks like through its traits: counts, every vertex with its position, every
/// face with its vertex loop from its own face_halfedge (so a rotated loop also counts as a
/// change), and the links of every halfedge.
struct snapshot {
    std::vector<double> data;
    bool operator==(const snapshot&) const = default;
};

template <class M, class T = hmira::default_traits<M>>
snapshot take_snapshot(const M& m) {
    snapshot s;
    auto& d = s.data;
    d.push_back(double(T::vertex_count(m)));
    d.push_back(double(T::edge_count(m)));
    d.push_back(double(T::face_count(m)));
    for (auto v : T::vertices(m)) {
        const auto p = T::position(m, v);
        d.insert(d.end(), {double(T::vertex_index(m, v)), double(p[0]), double(p[1]), double(p[2])});
    }
    for (auto f : T::faces(m)) {
        d.push_back(-1.0 - double(T::face_index(m, f)));
        for (auto v : T::face_vertices(m, f)) d.push_back(double(T::vertex_index(m, v)));
    }
    for (auto h : T::halfedges(m)) {
        d.push_back(double(T::halfedge_index(m, h)));
        d.push_back(double(T::halfedge_index(m, T::next(m, h))));
        d.push_back(double(T::vertex_index(m, T::target(m, h))));
    }
    return s;
}

/// A progress callback that records every fraction it is given and answers false at its
/// `stop_at`-th call (1-based; 0: never).
struct recorder {
    std::size_t stop_at = 0;
    std::vector<double> fractions = {};
    hmira::progress_function callback() {
        return [this](double f) {
            fractions.push_back(f);
            return fractions.size() != stop_at;
        };
    }
};

/// One edit on the whole of a test shape, and how many progress calls the test expects from
/// the edit's documented blocks: one per 1024 elements (cut points plus new faces for truncate,
/// faces for individual extrusion, outline edges twice for region extrusion; for bevel, which
/// also steps while it plans, the selected edges three times, the touched vertices twice and
/// the new inner corner points), counted here from the shape, not from the edit.
struct edit_case {
    std::string name;
    face_list shape;
    std::size_t elements;  // the elements the edit steps through
    // The fraction is exactly steps / elements at every report; else (bevel learns its total
    // phase by phase) the fractions only rise.
    bool exact_fractions;
    // Runs the edit with the callback on mesh M; returns the error message, if any.
    std::function<std::optional<std::string>(void* mesh, const hmira::progress_function&)> run;
};

std::optional<std::string> message_of(const auto& r) {
    if (r) return std::nullopt;
    return r.error().message;
}

template <class M>
std::vector<edit_case> cases() {
    using T = hmira::default_traits<M>;
    std::vector<edit_case> out;
    // A 24^3 lattice box: 3456 quads, 3458 vertices, 6912 edges.
    const face_list box = hmira_test::lattice_box(24, 24, 24);
    const std::size_t V = 3458, E = 6912, F = 3456;
    out.push_back({"truncate all", box, E + V, true, [](void* p, const hmira::progress_function& cb) {
                       auto& m = *static_cast<M*>(p);
                       std::vector<typename T::vertex_handle> vs;
                       for (auto v : T::vertices(m)) vs.push_back(v);
                       return message_of(
                           hmira::truncate<M>(m, vs, {.fraction = 0.25, .distance = 0.0, .progress = cb}));
                   }});
    // Every corner of every quad lies between two bevelled edges: 4F inner points, no slides.
    out.push_back(
        {"bevel all edges", box, 3 * E + 2 * V + 4 * F, false, [](void* p, const hmira::progress_function& cb) {
             auto& m = *static_cast<M*>(p);
             std::vector<typename T::edge_handle> es;
             for (auto e : T::edges(m)) es.push_back(e);
             return message_of(hmira::bevel<M>(
                 m, es, {.width = 0.1, .segments = 1, .clamp_overlap = true, .clamp_globally = false, .progress = cb}));
         }});
    out.push_back({"bevel_vertices all", box, E + V, true, [](void* p, const hmira::progress_function& cb) {
                       auto& m = *static_cast<M*>(p);
                       std::vector<typename T::vertex_handle> vs;
                       for (auto v : T::vertices(m)) vs.push_back(v);
                       return message_of(hmira::bevel_vertices<M>(m, vs, {.width = 0.2, .progress = cb}));
                   }});
    out.push_back({"extrude individual all", box, F, true, [](void* p, const hmira::progress_function& cb) {
                       auto& m = *static_cast<M*>(p);
                       std::vector<typename T::face_handle> fs;
                       for (auto f : T::faces(m)) fs.push_back(f);
                       return message_of(hmira::extrude<M>(m, fs,
                                                           {.distance = 0.5,
                                                            .direction = std::nullopt,
                                                            .mode = hmira::extrude_mode::individual,
                                                            .progress = cb}));
                   }});
    // A comb on a 64 x 64 grid of unit cells: every even row of cells and the first column,
    // connected and with a long outline.
    const face_list grid = hmira_test::grid(64, 64);
    std::size_t outline = 0;
    {
        // Counted from the cell pattern: a selected cell's edge is on the outline when the
        // cell across is outside the grid or not selected.
        auto selected = [](long i, long j) { return i >= 0 && j >= 0 && i < 64 && j < 64 && (j % 2 == 0 || i == 0); };
        for (long j = 0; j < 64; ++j)
            for (long i = 0; i < 64; ++i)
                if (selected(i, j))
                    outline += std::size_t(!selected(i - 1, j)) + std::size_t(!selected(i + 1, j)) +
                               std::size_t(!selected(i, j - 1)) + std::size_t(!selected(i, j + 1));
    }
    out.push_back(
        {"extrude region (comb)", grid, 2 * outline, true, [](void* p, const hmira::progress_function& cb) {
             auto& m = *static_cast<M*>(p);
             std::vector<typename T::face_handle> fs;
             for (auto f : T::faces(m)) {
                 const auto c = hmira_test::centroid<M, T>(m, f);
                 const long i = std::lround(c[0] - 0.5), j = std::lround(c[1] - 0.5);
                 if (j % 2 == 0 || i == 0) fs.push_back(f);
             }
             return message_of(hmira::extrude<M>(
                 m, fs,
                 {.distance = 1.0, .direction = std::nullopt, .mode = hmira::extrude_mode::region, .progress = cb}));
         }});
    return out;
}

template <class M>
struct cancel_test : ::testing::Test {};
TYPED_TEST_SUITE(cancel_test, hmira_test::all_models);

TYPED_TEST(cancel_test, uncancelled_edit_reports_once_per_block_with_rising_fractions) {
    using M = TypeParam;
    if constexpr (!hmira::extrudable_mesh<M>) {
        GTEST_SKIP() << "not an editable model";
    } else {
        for (const auto& c : cases<M>()) {
            SCOPED_TRACE(c.name);
            M m;
            ASSERT_TRUE(hmira_test::add_face_list(m, c.shape));
            recorder rec;
            const auto error = c.run(&m, rec.callback());
            ASSERT_FALSE(error) << *error;
            EXPECT_TRUE(hmira_test::is_valid(m));
            ASSERT_EQ(rec.fractions.size(), c.elements / 1024);
            for (std::size_t i = 0; i < rec.fractions.size(); ++i) {
                if (c.exact_fractions) {
                    EXPECT_DOUBLE_EQ(rec.fractions[i], double((i + 1) * 1024) / double(c.elements));
                } else {
                    EXPECT_GT(rec.fractions[i], 0.0);
                    EXPECT_LE(rec.fractions[i], 1.0);
                    if (i > 0) {
                        EXPECT_GE(rec.fractions[i], rec.fractions[i - 1]);
                    }
                }
            }
        }
    }
}

TYPED_TEST(cancel_test, cancel_at_kth_report_leaves_the_mesh_unchanged) {
    using M = TypeParam;
    if constexpr (!hmira::extrudable_mesh<M>) {
        GTEST_SKIP() << "not an editable model";
    } else {
        for (const auto& c : cases<M>()) {
            const std::size_t reports = c.elements / 1024;
            ASSERT_GE(reports, 3u) << c.name << ": the shape is too small to cancel in the middle";
            M fresh;
            ASSERT_TRUE(hmira_test::add_face_list(fresh, c.shape));
            ASSERT_FALSE(c.run(&fresh, {}));
#ifdef HMIRA_SANITIZER_BUILD
            // Instrumented, each stop costs seconds: the first and the last report only.
            const std::vector<std::size_t> stops{1, reports};
#else
            const std::vector<std::size_t> stops{1, 2, reports / 2 + 1, reports};
#endif
            for (std::size_t k : stops) {
                SCOPED_TRACE(c.name + ", cancelled at report " + std::to_string(k));
                M m;
                ASSERT_TRUE(hmira_test::add_face_list(m, c.shape));
                const auto before = take_snapshot(m);
                recorder rec{.stop_at = k};
                const auto error = c.run(&m, rec.callback());
                ASSERT_TRUE(error) << "the edit ignored the cancellation";
                EXPECT_TRUE(error->ends_with("cancelled")) << *error;
                EXPECT_EQ(rec.fractions.size(), k) << "the edit went on reporting after it was cancelled";
                EXPECT_TRUE(hmira_test::is_valid(m));
                EXPECT_TRUE(take_snapshot(m) == before) << "the cancelled edit changed the mesh";
                // The rolled-back mesh still takes the whole edit, with the same result as a fresh one
                // (instrumented, after the last stop only, which changed the most before rolling back).
                if (hmira_test::sanitizer_build && k != stops.back()) continue;
                ASSERT_FALSE(c.run(&m, {}));
                EXPECT_TRUE(hmira_test::is_valid(m));
                EXPECT_EQ(hmira_test::count(m), hmira_test::count(fresh));
            }
        }
    }
}

// Ctrl-C must be heard early: bevel plans (hash tables over every edge, corner and vertex)
// for as long as it then builds, so its first report comes before it changes anything, and the
// build's phases report too. A bevel that reported only while cutting strips let a Python
// Ctrl-C wait most of the call.
TYPED_TEST(cancel_test, bevel_reports_while_it_plans_and_in_every_build_phase) {
    using M = TypeParam;
    using T = hmira::default_traits<M>;
    if constexpr (!hmira::extrudable_mesh<M>) {
        GTEST_SKIP() << "not an editable model";
    } else {
        M m;
        ASSERT_TRUE(hmira_test::add_face_list(m, hmira_test::lattice_box(24, 24, 24)));
        const std::size_t V = T::vertex_count(m), F = T::face_count(m);
        std::vector<typename T::edge_handle> es;
        for (auto e : T::edges(m)) es.push_back(e);
        std::vector<std::size_t> vertices_at_report, faces_at_report;
        const hmira::progress_function cb = [&](double) {
            vertices_at_report.push_back(T::vertex_count(m));
            faces_at_report.push_back(T::face_count(m));
            return true;
        };
        ASSERT_TRUE(hmira::bevel<M>(m, es, {.width = 0.1, .segments = 1, .progress = cb}));
        EXPECT_TRUE(hmira_test::is_valid(m));
        ASSERT_FALSE(vertices_at_report.empty());
        EXPECT_EQ(vertices_at_report.front(), V) << "the first report came after the bevel had changed the mesh";
        // Reports while the corner points are made (vertices grow), then while the strips are
        // cut and the old vertices replaced by polygons (both add faces).
        const std::size_t E = es.size();
        std::size_t growing_vertices = 0, growing_faces = 0;
        for (std::size_t i = 1; i < vertices_at_report.size(); ++i) {
            growing_vertices += vertices_at_report[i] > vertices_at_report[i - 1] ? 1 : 0;
            growing_faces += faces_at_report[i] > faces_at_report[i - 1] ? 1 : 0;
        }
        EXPECT_GE(growing_vertices, 4 * F / 1024 - 1);
        EXPECT_GE(growing_faces, (E + V) / 1024 - 1);
    }
}

}  // namespace
