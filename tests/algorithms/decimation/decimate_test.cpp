// decimate on every model that supports the triangle operators: exact face counts, genus and
// boundary loops kept, boundary and locked vertices bit for bit, a flat grid staying flat,
// max_error honoured, seeded random runs checked by validate() and the native checkers after
// each run, determinism, and refusals and cancellations that leave the mesh unchanged.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <hmira/algorithms/decimation/decimate.hpp>
#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/subdivision/loop.hpp>

#include "algorithms/decimation/decimation_support.hpp"
#include "algorithms/triangle/triangle_support.hpp"

namespace {

using namespace hmira_test;

template <class M>
class decimate_test : public ::testing::Test {};
TYPED_TEST_SUITE(decimate_test, all_models);

#ifdef HMIRA_SANITIZE
constexpr std::size_t scale = 1;
#else
constexpr std::size_t scale = 2;
#endif

/// Number of boundary loops, counted by walking the boundary halfedges.
template <class M, class T = hmira::default_traits<M>>
std::size_t boundary_loops(const M& m) {
    std::set<std::size_t> seen;
    std::size_t loops = 0;
    for (auto h : T::halfedges(m)) {
        if (T::face(m, h) != T::null_face() || seen.count(T::halfedge_index(m, h))) continue;
        ++loops;
        auto x = h;
        do {
            seen.insert(T::halfedge_index(m, x));
            x = T::next(m, x);
        } while (x != h);
    }
    return loops;
}

/// Positions by vertex index, for the vertices `pick` selects.
template <class M, class T = hmira::default_traits<M>, class Pick>
std::map<std::size_t, hmira::vec3<double>> positions_of(const M& m, Pick pick) {
    std::map<std::size_t, hmira::vec3<double>> out;
    for (auto v : T::vertices(m))
        if (pick(v)) {
            const auto p = T::position(m, v);
            out[T::vertex_index(m, v)] = {double(p[0]), double(p[1]), double(p[2])};
        }
    return out;
}

template <class M, class T = hmira::default_traits<M>>
bool on_boundary(const M& m, typename T::vertex_handle v) {
    const auto h = T::vertex_halfedge(m, v);
    return h != T::null_halfedge() && T::face(m, h) == T::null_face();
}

TEST(decimate_quadric, the_minimiser_of_three_axis_planes_is_their_corner_at_zero_error) {
    using hmira::detail::decimation::quadric;
    quadric q = quadric::of_plane({1, 0, 0}, {1, 5, 5}) + quadric::of_plane({0, 1, 0}, {7, 2, 7}) +
                quadric::of_plane({0, 0, 1}, {9, 9, 3});
    const auto x = q.minimiser();
    ASSERT_TRUE(x);
    EXPECT_NEAR(x->x, 1, 1e-12);
    EXPECT_NEAR(x->y, 2, 1e-12);
    EXPECT_NEAR(x->z, 3, 1e-12);
    EXPECT_NEAR(q(*x), 0, 1e-12);
    // Distances 1, 2 and 2 from the three planes: 1 + 4 + 4.
    EXPECT_NEAR(q({2, 4, 5}), 9, 1e-12);
    // Two parallel planes pin no point.
    EXPECT_FALSE((quadric::of_plane({0, 0, 1}, {0, 0, 0}) + quadric::of_plane({0, 0, 1}, {0, 0, 1})).minimiser());
}

TEST(decimate_heap, keys_leave_cheapest_first_with_ties_by_key_and_costs_can_change) {
    hmira::detail::decimation::indexed_heap heap(10);
    const double costs[10] = {5, 3, 8, 3, 9, 1, 7, 2, 6, 4};
    for (std::uint32_t k = 0; k < 10; ++k) heap.set(k, costs[k]);
    heap.set(4, 0.5);  // lowered
    heap.set(5, 10);   // raised
    heap.erase(7);
    std::vector<std::uint32_t> order;
    while (!heap.empty()) {
        order.push_back(heap.top_key());
        heap.erase(heap.top_key());
    }
    EXPECT_EQ(order, (std::vector<std::uint32_t>{4, 1, 3, 9, 0, 8, 6, 2, 5}));
}

TYPED_TEST(decimate_test, face_targets_are_met_exactly_and_the_genus_kept) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        const face_list input = bumpy_torus(20 * scale, 12 * scale, false, 1);
        const std::size_t f0 = input.faces.size();
        for (const std::size_t target : {f0 - 1, f0 / 2 + 1, f0 / 5, std::size_t(40)}) {
            M m = mesh_from<M>(input);
            auto r = hmira::decimate(m, {.target_faces = target});
            ASSERT_TRUE(r) << r.error().message;
            EXPECT_EQ(r.value().stopped_by, hmira::decimate_stop::target_faces) << r.value().note;
            EXPECT_LE(r.value().faces, target);
            EXPECT_GE(r.value().faces + 1, target);
            EXPECT_EQ(T::face_count(m), r.value().faces);
            EXPECT_EQ(T::vertex_count(m), r.value().vertices);
            EXPECT_EQ(chi(m), 0);
            EXPECT_TRUE(valid_topology(m));
        }
        M m = mesh_from<M>(input);
        auto r = hmira::decimate(m, {.target_ratio = 0.25});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_EQ(r.value().faces, f0 / 4);  // f0 is even: interior collapses land exactly
        EXPECT_TRUE(valid_topology(m));
    }
}

TYPED_TEST(decimate_test, a_closed_surface_goes_down_to_the_smallest_it_can_be_and_says_why) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        M m;
        ASSERT_TRUE(hmira::generate_icosahedron(m));
        ASSERT_TRUE(hmira::loop_subdivide(m, {.levels = 1}));
        // A sphere cannot lose faces below a tetrahedron (4): the link condition stops it.
        auto r = hmira::decimate(m, {.target_faces = 0, .max_normal_angle = 180});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_EQ(r.value().stopped_by, hmira::decimate_stop::constraints);
        EXPECT_NE(r.value().note.find("constraints"), std::string::npos) << r.value().note;
        EXPECT_GE(r.value().faces, 4u);
        EXPECT_LE(r.value().faces, 8u);
        EXPECT_EQ(chi(m), 2);
        EXPECT_TRUE(valid_topology(m));
        EXPECT_EQ(T::face_count(m), r.value().faces);
    }
}

TYPED_TEST(decimate_test, seeded_random_runs_stay_valid_and_keep_genus_boundary_loops_and_boundary_positions) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        std::mt19937_64 rng(19);
        for (int run = 0; run < 12; ++run) {
            const bool holes = run % 2 == 1;
            M m = mesh_from<M>(bumpy_torus(10 * scale + run, 8 * scale + run % 3, holes, std::uint64_t(run)));
            const long long chi0 = chi(m);
            const std::size_t loops0 = boundary_loops(m), f0 = T::face_count(m);
            const auto boundary0 = positions_of(m, [&](auto v) { return on_boundary(m, v); });
            hmira::decimate_options options{.target_faces =
                                                std::uniform_int_distribution<std::size_t>(f0 / 20, f0 - 1)(rng)};
            options.max_normal_angle = std::uniform_real_distribution<double>(30, 180)(rng);
            if (run % 3 == 0) options.max_aspect_ratio = 8;
            auto r = hmira::decimate(m, options);
            ASSERT_TRUE(r) << r.error().message;
            ASSERT_TRUE(valid_topology(m)) << "run " << run;
            EXPECT_EQ(chi(m), chi0) << "run " << run;
            EXPECT_EQ(boundary_loops(m), loops0) << "run " << run;
            EXPECT_EQ(positions_of(m, [&](auto v) { return on_boundary(m, v); }), boundary0) << "run " << run;
            if (r.value().stopped_by != hmira::decimate_stop::target_faces)
                EXPECT_FALSE(r.value().note.empty());
            else
                EXPECT_LE(r.value().faces, *options.target_faces);
            // Without keep_boundary the boundary may shrink, but the surface stays valid.
            M n = mesh_from<M>(bumpy_torus(10 * scale, 8 * scale, holes, std::uint64_t(run)));
            const long long chi1 = chi(n);
            const std::size_t loops1 = boundary_loops(n);
            auto s = hmira::decimate(n, {.target_ratio = 0.3, .keep_boundary = false});
            ASSERT_TRUE(s) << s.error().message;
            ASSERT_TRUE(valid_topology(n)) << "run " << run << " without keep_boundary";
            EXPECT_EQ(chi(n), chi1) << "run " << run << " without keep_boundary";
            EXPECT_EQ(boundary_loops(n), loops1) << "run " << run << " without keep_boundary";
        }
    }
}

TYPED_TEST(decimate_test, locked_vertices_keep_their_handles_and_positions_bit_for_bit) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        M m = mesh_from<M>(bumpy_torus(16 * scale, 10 * scale, true, 7));
        std::vector<std::size_t> locked;
        std::size_t i = 0;
        for (auto v : T::vertices(m))
            if (i++ % 7 == 3) locked.push_back(T::vertex_index(m, v));
        const std::set<std::size_t> lock_set(locked.begin(), locked.end());
        const auto before = positions_of(m, [&](auto v) { return lock_set.count(T::vertex_index(m, v)) > 0; });
        auto r = hmira::decimate(m, {.target_ratio = 0.1, .keep_boundary = false, .locked_vertices = locked});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(valid_topology(m));
        const auto after = positions_of(m, [&](auto v) { return lock_set.count(T::vertex_index(m, v)) > 0; });
        EXPECT_EQ(after, before);  // same indices alive, same coordinates to the bit
        EXPECT_LT(r.value().faces, T::face_count(mesh_from<M>(bumpy_torus(16 * scale, 10 * scale, true, 7))));
    }
}

TYPED_TEST(decimate_test, a_flat_grid_stays_in_its_plane_and_keeps_its_outline) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        M m = mesh_from<M>(grid(12, 9, true));
        auto r = hmira::decimate(m, {.max_error = 1e-9});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(valid_topology(m));
        for (auto v : T::vertices(m)) EXPECT_EQ(double(T::position(m, v)[2]), 0.0);
        // The 42 boundary vertices stay, and every interior one can go: a fan of the outline.
        EXPECT_EQ(T::vertex_count(m), 42u);
        EXPECT_EQ(r.value().faces, 40u);
        EXPECT_EQ(r.value().stopped_by, hmira::decimate_stop::constraints);
        EXPECT_LE(r.value().error, 1e-9);
    }
}

TYPED_TEST(decimate_test, max_error_stops_before_any_collapse_that_exceeds_it) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        M m;
        ASSERT_TRUE(hmira::generate_icosahedron(m));
        ASSERT_TRUE(hmira::loop_subdivide(m, {.levels = 2}));
        M coarse = m;
        auto r = hmira::decimate(m, {.target_faces = 10, .max_error = 0.01});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_EQ(r.value().stopped_by, hmira::decimate_stop::max_error);
        EXPECT_LE(r.value().error, 0.01);
        EXPECT_GT(r.value().faces, 10u);
        EXPECT_NE(r.value().note.find("max_error"), std::string::npos);
        EXPECT_TRUE(valid_topology(m));
        // A looser bound goes further.
        auto s = hmira::decimate(coarse, {.max_error = 0.1});
        ASSERT_TRUE(s) << s.error().message;
        EXPECT_LT(s.value().faces, r.value().faces);
    }
}

/// Longest edge over the height onto it, 1 for an equilateral triangle (computed here, not by
/// the library).
template <class M, class T = hmira::default_traits<M>>
double worst_aspect_ratio(const M& m) {
    double worst = 0;
    for (auto f : T::faces(m)) {
        std::vector<hmira::vec3<double>> p;
        for (auto v : T::face_vertices(m, f)) {
            const auto q = T::position(m, v);
            p.push_back({double(q[0]), double(q[1]), double(q[2])});
        }
        const double area2 = hmira::norm(hmira::cross(p[1] - p[0], p[2] - p[0]));
        const double longest = std::max(
            {hmira::squared_norm(p[1] - p[0]), hmira::squared_norm(p[2] - p[1]), hmira::squared_norm(p[0] - p[2])});
        worst = std::max(worst, longest / area2 * std::sqrt(3.0) / 2);
    }
    return worst;
}

TYPED_TEST(decimate_test, no_face_ends_thinner_than_the_aspect_limit) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        M m = mesh_from<M>(bumpy_torus(16 * scale, 10 * scale, false, 13));
        const double before = worst_aspect_ratio(m);
        ASSERT_LT(before, 4.0);
        M free = m;
        ASSERT_TRUE(hmira::decimate(free, {.target_ratio = 0.1}));
        EXPECT_GT(worst_aspect_ratio(free), 4.0);  // the limit below has work to do
        auto r = hmira::decimate(m, {.target_ratio = 0.1, .max_normal_angle = 180, .max_aspect_ratio = 4});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(valid_topology(m));
        EXPECT_LE(worst_aspect_ratio(m), 4.0 + 1e-9);
        EXPECT_LT(T::face_count(m), T::face_count(mesh_from<M>(bumpy_torus(16 * scale, 10 * scale, false, 13))) / 2);
    }
}

TYPED_TEST(decimate_test, runs_are_deterministic) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        const face_list input = bumpy_torus(14 * scale, 9 * scale, true, 3);
        M a = mesh_from<M>(input), b = mesh_from<M>(input);
        ASSERT_TRUE(hmira::decimate(a, {.target_ratio = 0.2}));
        ASSERT_TRUE(hmira::decimate(b, {.target_ratio = 0.2}));
        EXPECT_EQ(take_snapshot(a), take_snapshot(b));
    }
}

/// The vertices at a crease of at least `degrees` (an edge whose two triangles' normals differ by that
/// much), found here from the positions alone.
template <class M, class T = hmira::default_traits<M>>
std::vector<hmira::vec3<double>> crease_vertices(const M& m, double degrees) {
    std::vector<hmira::vec3<double>> out;
    auto pos = [&](auto v) {
        const auto p = T::position(m, v);
        return hmira::vec3<double>{double(p[0]), double(p[1]), double(p[2])};
    };
    auto normal = [&](auto h) {
        const auto a = pos(T::target(m, T::opposite(m, h))), b = pos(T::target(m, h));
        return hmira::cross(b - a, pos(T::target(m, T::next(m, h))) - a);
    };
    const double c = std::cos(degrees * 3.14159265358979323846 / 180);
    for (auto e : T::edges(m)) {
        const auto h = T::edge_halfedge(m, e), o = T::opposite(m, h);
        const auto n0 = normal(h), n1 = normal(o);
        if (hmira::dot(n0, n1) <= c * hmira::norm(n0) * hmira::norm(n1)) {
            out.push_back(pos(T::target(m, h)));
            out.push_back(pos(T::target(m, o)));
        }
    }
    return out;
}

/// How far a point is from the rims of capped_cylinder (the unit circles at z = 0 and z = 1).
double off_rim(const hmira::vec3<double>& p) {
    return std::max(std::fabs(std::hypot(p.x, p.y) - 1), std::min(std::fabs(p.z), std::fabs(p.z - 1)));
}

TYPED_TEST(decimate_test, kept_feature_lines_run_through_the_input_rims_and_plain_decimation_leaves_them) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        const face_list input = capped_cylinder(48, 8);
        M kept = mesh_from<M>(input), plain = mesh_from<M>(input);
        auto r = hmira::decimate(kept, {.target_ratio = 0.15, .feature_angle = 45, .keep_features = true});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(valid_topology(kept));
        EXPECT_EQ(chi(kept), 2);
        // Every vertex on a crease of the result (found again from its positions) is a rim vertex of
        // the input, exactly where it was: on the unit circle, at z = 0 or 1 (up to the rounding of cos, sin
        // and float positions).
        const auto creases = crease_vertices(kept, 45);
        ASSERT_GE(creases.size(), 12u);  // both rims are still there, at least triangles
        using T = hmira::default_traits<M>;
        const double tolerance = sizeof(typename T::scalar) < sizeof(double) ? 1e-6 : 1e-12;  // float models
        for (const auto& p : creases) EXPECT_LE(off_rim(p), tolerance) << p.x << " " << p.y << " " << p.z;
        // Without keep_features the rims are free to move off the circles, and do: the check above fails.
        ASSERT_TRUE(hmira::decimate(plain, {.target_ratio = 0.15}));
        double worst = 0;
        for (const auto& p : crease_vertices(plain, 45)) worst = std::max(worst, off_rim(p));
        EXPECT_GT(worst, 10 * tolerance);
    }
}

TYPED_TEST(decimate_test, no_collapse_leaves_an_angle_under_the_minimum_it_did_not_find) {
    using M = TypeParam;
    using T = hmira::default_traits<M>;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        M m = mesh_from<M>(bumpy_torus(20 * scale, 12 * scale, false, 5));
        // The smallest angle of every face, from its sides by the law of cosines.
        auto smallest = [&] {
            double out = 180;
            for (auto f : T::faces(m)) {
                std::vector<hmira::vec3<double>> p;
                for (auto v : T::face_vertices(m, f)) {
                    const auto q = T::position(m, v);
                    p.push_back({double(q[0]), double(q[1]), double(q[2])});
                }
                for (int i = 0; i < 3; ++i) {
                    const auto u = p[(i + 1) % 3] - p[i], w = p[(i + 2) % 3] - p[i];
                    out = std::min(out, std::acos(hmira::dot(u, w) / (hmira::norm(u) * hmira::norm(w))) * 180 /
                                            3.14159265358979323846);
                }
            }
            return out;
        };
        // A limit below every angle of the input: the result may not go under it.
        const double limit = std::min(15.0, 0.9 * smallest());
        ASSERT_TRUE(hmira::decimate(m, {.target_ratio = 0.05, .min_angle = limit}));
        EXPECT_TRUE(valid_topology(m));
        EXPECT_GE(smallest(), limit - 1e-9);
    }
}

TYPED_TEST(decimate_test, polygon_input_is_triangulated_first_with_a_note) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else if constexpr (!hmira::triangulable_mesh<M>) {
        GTEST_SKIP() << "triangles only";
    }
    else {
        using T = hmira::default_traits<M>;
        M m = mesh_from<M>(torus(12, 8));
        auto r = hmira::decimate(m, {.target_faces = 60});
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(r.value().triangulated);
        EXPECT_NE(r.value().note.find("triangulated"), std::string::npos);
        EXPECT_LE(r.value().faces, 60u);
        EXPECT_GE(r.value().faces, 59u);
        for (auto f : T::faces(m))
            EXPECT_TRUE((hmira::detail::triangle_ops::in_triangle<M, T>(m, T::face_halfedge(m, f))));
        EXPECT_EQ(chi(m), 0);
        EXPECT_TRUE(valid_topology(m));
    }
}

TYPED_TEST(decimate_test, bad_options_are_refused_by_name_and_change_nothing) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        M m = mesh_from<M>(bumpy_torus(8, 6, false, 5));
        const auto before = take_snapshot(m);
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const std::pair<hmira::decimate_options, const char*> cases[] = {
            {{}, "target_faces, target_ratio or max_error"},
            {{.target_ratio = nan}, "target_ratio"},
            {{.target_ratio = 1.5}, "target_ratio"},
            {{.max_error = -1}, "max_error"},
            {{.max_error = nan}, "max_error"},
            {{.target_faces = 10, .max_normal_angle = nan}, "max_normal_angle"},
            {{.target_faces = 10, .max_aspect_ratio = 0.5}, "max_aspect_ratio"},
            {{.target_faces = 10, .locked_vertices = {T::vertex_index_bound(m) + 3}}, "locked_vertices"},
            {{.target_faces = 10, .min_angle = 61}, "min_angle"},
            {{.target_faces = 10, .feature_angle = -1}, "feature_angle"},
            {{.target_faces = 10, .feature_edges = {T::edge_index_bound(m) + 3}}, "feature_edges"},
        };
        for (const auto& [options, name] : cases) {
            auto r = hmira::decimate(m, options);
            ASSERT_FALSE(r) << name;
            EXPECT_EQ(r.error().code, hmira::errc::invalid_argument);
            EXPECT_NE(r.error().message.find(name), std::string::npos) << r.error().message;
            EXPECT_EQ(take_snapshot(m), before) << name;
        }
        // A non-finite position is named.
        auto v = *T::vertices(m).begin();
        const auto p = T::position(m, v);
        using S = typename T::scalar;
        T::set_position(m, v, hmira::vec3<S>{S(nan), S(p[1]), S(p[2])});
        auto r = hmira::decimate(m, {.target_faces = 10});
        ASSERT_FALSE(r);
        EXPECT_NE(r.error().message.find("vertex " + std::to_string(T::vertex_index(m, v))), std::string::npos);
        T::set_position(m, v, p);  // NaN never compares equal; with it put back, nothing else moved
        EXPECT_EQ(take_snapshot(m), before);
    }
}

TYPED_TEST(decimate_test, a_cancelled_run_restores_the_mesh_and_progress_rises) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        M m = mesh_from<M>(bumpy_torus(80, 64, true, 11));
        const auto before = take_snapshot(m);
        std::vector<double> seen;
        auto r = hmira::decimate(m, {.target_faces = 50, .progress = [&](double f) {
                                         seen.push_back(f);
                                         return seen.size() < 2;
                                     }});
        ASSERT_FALSE(r);
        EXPECT_EQ(r.error().code, hmira::errc::cancelled);
        EXPECT_NE(r.error().message.find("cancelled"), std::string::npos);
        EXPECT_EQ(seen.size(), 2u);
        EXPECT_EQ(take_snapshot(m), before);
        EXPECT_TRUE(valid_topology(m));
        // Uncancelled, the fractions rise and the run completes.
        seen.clear();
        auto s = hmira::decimate(m, {.target_faces = 50, .progress = [&](double f) {
                                         seen.push_back(f);
                                         return true;
                                     }});
        ASSERT_TRUE(s) << s.error().message;
        ASSERT_FALSE(seen.empty());
        EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
        EXPECT_LE(seen.back(), 1.0);
        EXPECT_TRUE(valid_topology(m));
    }
}

}  // namespace
