// marching_cubes into a mesh is atomic: whatever stops it part way (a
// cancel at any progress call, a triangle the mesh refuses, std::bad_alloc from any builder
// call, a NaN sample) leaves a mesh that already held elements exactly as it was, on every
// model; a clean run afterwards still adds the whole surface.
#include <gtest/gtest.h>

#include <limits>
#include <new>
#include <string>

#include <hmira/algorithms/conversion/marching_cubes.hpp>
#include <hmira/grids/dense_grid.hpp>
#include <hmira/grids/implicit_shapes.hpp>
#include <hmira/grids/sample.hpp>

#include "support/checks.hpp"
#include "support/models.hpp"
#include "support/shapes.hpp"
#include "support/snapshot.hpp"

namespace {

/// The model's traits, with a countdown to a refused triangle and one to a thrown bad_alloc
/// (from add_vertex or add_face, before the model is called).
template <class M>
struct faulty_builder_traits : hmira::default_traits<M> {
    using base = hmira::default_traits<M>;
    using V = typename base::vertex_handle;
    using F = typename base::face_handle;
    static inline long long refuse_at = -1, throw_at = -1;  // countdowns; -1: off
    static inline long long face_calls = 0, calls = 0;      // not `faces`: that would hide T::faces
    static void reset() {
        refuse_at = throw_at = -1;
        face_calls = calls = 0;
    }
    static void tick() {
        ++calls;
        if (throw_at >= 0 && throw_at-- == 0) throw std::bad_alloc();
    }
    static V add_vertex(M& m, const hmira::vec3<typename base::scalar>& p) {
        tick();
        return base::add_vertex(m, p);
    }
    static hmira::result<F> add_face(M& m, std::span<const V> vs) {
        tick();
        ++face_calls;
        if (refuse_at >= 0 && refuse_at-- == 0) return hmira::fail(hmira::errc::non_manifold, "injected refusal");
        return base::add_face(m, vs);
    }
};

static_assert(hmira::detail::mc::can_undo_insertion<hmira::halfedge_mesh, faulty_builder_traits<hmira::halfedge_mesh>>);
static_assert(
    hmira::detail::mc::can_undo_insertion<hmira::face_vertex_mesh, faulty_builder_traits<hmira::face_vertex_mesh>>);

template <class M>
struct mc_atomic : ::testing::Test {};
TYPED_TEST_SUITE(mc_atomic, hmira_test::all_models);

/// A mesh that already holds something: an open grid of triangles (every model takes them).
template <class M>
M with_content() {
    M m;
    EXPECT_TRUE(hmira_test::add_face_list(m, hmira_test::grid(3, 2, true)));
    return m;
}

/// A small sphere: a few hundred triangles, so every k can be tried.
hmira::dense_grid<double> small_sphere() {
    auto g =
        hmira::sample_function<double>(hmira::cube_geometry(7, -1, 1), hmira::sphere_field{{0.05, -0.03, 0.02}, 0.6});
    EXPECT_TRUE(g);
    return std::move(*g);
}

/// What a clean run on `base` gives: its counts after the call.
template <class M, class T = hmira::default_traits<M>>
void expect_clean_run_adds_the_sphere(M& m, std::size_t base_v, std::size_t base_f, std::size_t sphere_v,
                                      std::size_t sphere_f) {
    auto r = hmira::marching_cubes<M, T>(m, small_sphere());
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_EQ(r.value().vertices.size(), sphere_v);
    EXPECT_EQ(r.value().faces.size(), sphere_f);
    EXPECT_EQ(T::vertex_count(m), base_v + sphere_v);
    EXPECT_EQ(T::face_count(m), base_f + sphere_f);
    EXPECT_TRUE((hmira_test::is_valid<M, T>(m, {.check_geometry = false})));
}

TYPED_TEST(mc_atomic, a_cancel_at_every_progress_call_leaves_the_mesh_unchanged) {
    using M = TypeParam;
    using T = hmira::default_traits<M>;
    const M base = with_content<M>();
    const auto before = hmira_test::snapshot<M, T>(base);
    const auto grid = small_sphere();
    const auto expected = hmira::marching_cubes_indexed(grid);
    ASSERT_TRUE(expected);
    const std::size_t sphere_v = expected.value().positions.size(), sphere_f = expected.value().triangles.size();
    ASSERT_GT(sphere_f, 100u);

    long long calls = 0;
    double last = -1;
    {
        M m = base;
        auto r = hmira::marching_cubes<M, T>(m, grid, {.threads = 1, .progress = [&](double done) {
                                                           EXPECT_GE(done, last) << "progress went backwards";
                                                           last = done;
                                                           ++calls;
                                                           return true;
                                                       }});
        ASSERT_TRUE(r) << r.error().message;
    }
    // Three extraction passes over 7 slices, then the insertion's own reports.
    ASSERT_GT(calls, 3 * 7 + 32);
    EXPECT_DOUBLE_EQ(last, 1.0);
    for (long long k = 0; k < calls; ++k) {
        M m = base;
        long long seen = 0;
        auto r = hmira::marching_cubes<M, T>(m, grid, {.threads = 1, .progress = [&](double) { return seen++ < k; }});
        ASSERT_FALSE(r) << "cancelled at call " << k << " but succeeded";
        EXPECT_EQ(r.error().code, hmira::errc::cancelled);
        EXPECT_NE(r.error().message.find("cancelled"), std::string::npos) << r.error().message;
        ASSERT_TRUE((hmira_test::snapshot<M, T>(m) == before))
            << "cancelled at progress call " << k << " of " << calls << ": mesh changed";
        expect_clean_run_adds_the_sphere<M, T>(m, T::vertex_count(base), T::face_count(base), sphere_v, sphere_f);
    }
}

TYPED_TEST(mc_atomic, a_refused_triangle_or_bad_alloc_at_every_step_leaves_the_mesh_unchanged) {
    using M = TypeParam;
    using T = hmira::default_traits<M>;
    using FT = faulty_builder_traits<M>;
    const M base = with_content<M>();
    const auto before = hmira_test::snapshot<M, T>(base);
    const auto grid = small_sphere();
    FT::reset();
    {
        M m = base;
        ASSERT_TRUE((hmira::marching_cubes<M, FT>(m, grid)));
    }
    const long long faces = FT::face_calls, calls = FT::calls;
    ASSERT_GT(faces, 100);
    ASSERT_GT(calls, faces);
    for (long long k = 0; k < faces; ++k) {
        M m = base;
        FT::reset();
        FT::refuse_at = k;
        auto r = hmira::marching_cubes<M, FT>(m, grid);
        ASSERT_FALSE(r) << "triangle " << k << " was refused but the call succeeded";
        EXPECT_EQ(r.error().code, hmira::errc::non_manifold);
        EXPECT_NE(r.error().message.find("triangle " + std::to_string(k) + " "), std::string::npos)
            << r.error().message;
        ASSERT_TRUE((hmira_test::snapshot<M, T>(m) == before))
            << "triangle " << k << " of " << faces << " refused: mesh changed";
    }
    for (long long k = 0; k < calls; ++k) {
        M m = base;
        FT::reset();
        FT::throw_at = k;
        EXPECT_THROW(((void)hmira::marching_cubes<M, FT>(m, grid)), std::bad_alloc) << "call " << k;
        ASSERT_TRUE((hmira_test::snapshot<M, T>(m) == before))
            << "bad_alloc from builder call " << k << " of " << calls << ": mesh changed";
        if (k % 97 == 0) {  // and the mesh still takes the whole surface afterwards
            FT::reset();
            ASSERT_TRUE((hmira::marching_cubes<M, FT>(m, grid)));
            EXPECT_TRUE((hmira_test::is_valid<M, T>(m, {.check_geometry = false})));
        }
    }
}

TYPED_TEST(mc_atomic, bad_volumes_are_refused_before_the_mesh_is_touched) {
    using M = TypeParam;
    using T = hmira::default_traits<M>;
    M m = with_content<M>();
    const auto before = hmira_test::snapshot<M, T>(m);
    auto grid = small_sphere();
    grid.set(3, 3, 6, std::numeric_limits<double>::quiet_NaN());  // in the last slice
    auto r = hmira::marching_cubes<M, T>(m, grid);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, hmira::errc::invalid_argument);
    EXPECT_NE(r.error().message.find("sample (3, 3, 6) is NaN"), std::string::npos) << r.error().message;
    EXPECT_TRUE((hmira_test::snapshot<M, T>(m) == before));
    // Infinite samples are refused the same way: they would interpolate NaN vertices.
    for (double bad : {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()}) {
        auto inf_grid = small_sphere();
        inf_grid.set(2, 4, 1, bad);
        auto q = hmira::marching_cubes<M, T>(m, inf_grid);
        ASSERT_FALSE(q);
        EXPECT_EQ(q.error().code, hmira::errc::invalid_argument);
        EXPECT_NE(q.error().message.find(bad > 0 ? "sample (2, 4, 1) is inf" : "sample (2, 4, 1) is -inf"),
                  std::string::npos)
            << q.error().message;
        EXPECT_TRUE((hmira_test::snapshot<M, T>(m) == before));
    }
    // An iso outside the samples' range gives no surface: refused, the mesh untouched.
    auto far = hmira::marching_cubes<M, T>(m, small_sphere(), {.iso = 1000.0});
    ASSERT_FALSE(far);
    EXPECT_NE(far.error().message.find("iso 1000 is outside the samples' range"), std::string::npos)
        << far.error().message;
    EXPECT_TRUE((hmira_test::snapshot<M, T>(m) == before));
    EXPECT_FALSE((hmira::marching_cubes<M, T>(m, small_sphere(), {.iso = std::numeric_limits<double>::quiet_NaN()})));
    EXPECT_TRUE((hmira_test::snapshot<M, T>(m) == before));
}

TEST(mc_atomic_properties, a_cancelled_insertion_keeps_the_users_properties_and_their_values) {
    hmira::halfedge_mesh m;
    ASSERT_TRUE(hmira_test::add_face_list(m, hmira_test::grid(2, 2, true)));
    auto weight = m.add_vertex_property<double>("weight", -1.0);
    for (auto v : m.vertices()) weight[v] = 10.0 + v.index;
    const std::size_t n = m.vertex_count();
    long long seen = 0;
    auto r =
        hmira::marching_cubes(m, small_sphere(), {.progress = [&](double done) { return done < 0.75 || seen++ < 0; }});
    ASSERT_FALSE(r);
    auto again = m.get_vertex_property<double>("weight");
    ASSERT_TRUE(again);
    EXPECT_EQ(m.vertex_count(), n);
    for (auto v : m.vertices()) EXPECT_EQ((*again)[v], 10.0 + v.index);
    EXPECT_TRUE(hmira_test::is_valid(m));
}

}  // namespace
