// fill_holes on loops the plain dynamic programme cannot close, the reasons it gives for any
// loop it leaves open, and cancellation through its progress callback (on the reference
// half-edge model): a rectangle whose corners the mesh already joins across (patch-23), a
// slit of coincident vertices (corner_with_sharp_edge) and long loops whose projection is not
// simple (b9_mesh) are closed and the mesh validates; a loop longer than max_size is reported
// with its vertex and length; a fill cancelled at any progress call returns errc::cancelled
// with the mesh exactly as it was.

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include <hmira/algorithms/holes/fill_hole.hpp>
#include <hmira/algorithms/validation/validate.hpp>
#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "support/snapshot.hpp"

namespace {

using mesh = hmira::halfedge_mesh;
using T = hmira::default_traits<mesh>;

bool load(mesh& m, const std::string& name) {
    const char* dir = std::getenv("HMIRA_TEST_DATA");
    if (!dir) return false;
    return bool(hmira::io::read_mesh(m, std::filesystem::path(dir) / "meshes" / name));
}

std::size_t boundary_loops(const mesh& m) {
    std::vector<char> seen(m.halfedge_index_bound(), 0);
    std::size_t loops = 0;
    for (auto h : m.halfedges()) {
        if (T::face(m, h) != T::null_face() || seen[T::halfedge_index(m, h)]) continue;
        ++loops;
        auto x = h;
        do {
            seen[T::halfedge_index(m, x)] = 1;
            x = T::next(m, x);
        } while (x != h);
    }
    return loops;
}

std::string problems(const mesh& m) {
    std::string out;
    for (const auto& p : hmira::validate(m)) out += p.message + "; ";
    return out;
}

/// Loads `name`, fills every hole, and checks that all are closed and the mesh validates.
void fills_every_hole(const std::string& name) {
    mesh m;
    if (!load(m, name)) GTEST_SKIP() << name << " not found (HMIRA_TEST_DATA)";
    ASSERT_EQ(problems(m), "") << name;
    const std::size_t loops = boundary_loops(m);
    ASSERT_GT(loops, 0u) << name;
    const long long chi = (long long)m.vertex_count() - (long long)m.edge_count() + (long long)m.face_count();
    auto r = hmira::fill_holes(m, 1000);
    ASSERT_TRUE(r) << r.error().message;
    std::string open;
    for (const auto& o : r->open) open += o.message + "; ";
    EXPECT_EQ(r->filled, loops) << name << ": left open: " << open;
    EXPECT_TRUE(r->open.empty()) << name;
    EXPECT_EQ(boundary_loops(m), 0u) << name;
    EXPECT_EQ(problems(m), "") << name;
    // Each closed loop adds one to V - E + F.
    EXPECT_EQ((long long)m.vertex_count() - (long long)m.edge_count() + (long long)m.face_count(),
              chi + (long long)r->filled)
        << name;
}

TEST(fill_holes_reasons, a_rectangle_whose_corners_are_joined_across_is_closed) { fills_every_hole("patch-23.off"); }
TEST(fill_holes_reasons, a_slit_of_coincident_vertices_is_closed) { fills_every_hole("corner_with_sharp_edge.off"); }
TEST(fill_holes_reasons, long_loops_whose_projection_is_not_simple_are_closed) { fills_every_hole("b9_mesh.off"); }

TEST(fill_holes_reasons, a_loop_longer_than_max_size_is_reported_with_its_vertex_and_length) {
    mesh m;
    if (!load(m, "patch-23.off")) GTEST_SKIP() << "patch-23.off not found (HMIRA_TEST_DATA)";
    const auto before = hmira_test::snapshot(m);
    auto r = hmira::fill_holes(m, 47);
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_EQ(r->filled, 0u);
    EXPECT_EQ(r->skipped, 1u);
    ASSERT_EQ(r->open.size(), 1u);
    EXPECT_EQ(r->open[0].reason, hmira::open_hole_reason::too_long);
    EXPECT_EQ(r->open[0].edges, 48u);  // counted from the file by hand
    // The named vertex is on the boundary.
    const auto v = hmira::vertex_handle(r->open[0].vertex);
    ASSERT_TRUE(m.is_valid(v));
    EXPECT_TRUE(m.is_boundary(v));
    EXPECT_TRUE(hmira_test::snapshot(m) == before);
    EXPECT_EQ(problems(m), "");
}

TEST(fill_holes_reasons, a_refused_loop_carries_fill_holes_reason) {
    // A loop too long for the programme whose projection crosses itself, with no fallback.
    mesh m;
    if (!load(m, "b9_mesh.off")) GTEST_SKIP() << "b9_mesh.off not found (HMIRA_TEST_DATA)";
    const auto loops = boundary_loops(m);
    hmira::fill_hole_options o;
    o.max_fallback_dynamic_programming_edges = 0;
    auto r = hmira::fill_holes(m, 1000, o);
    ASSERT_TRUE(r) << r.error().message;
    ASSERT_EQ(r->open.size(), 3u);  // the loops of 210, 428 and 240 edges
    for (const auto& h : r->open) {
        EXPECT_EQ(h.reason, hmira::open_hole_reason::refused);
        EXPECT_EQ(h.code, hmira::errc::unsupported);
        EXPECT_NE(h.message.find("not simple"), std::string::npos) << h.message;
        EXPECT_GT(h.edges, 200u);
    }
    EXPECT_EQ(r->filled + r->open.size(), loops);
    EXPECT_EQ(boundary_loops(m), 3u);
    EXPECT_EQ(problems(m), "");
}

TEST(fill_holes_reasons, a_fill_over_the_memory_limit_is_refused_before_anything_changes) {
    mesh m;
    if (!load(m, "patch-23.off")) GTEST_SKIP() << "patch-23.off not found (HMIRA_TEST_DATA)";
    const auto before = hmira_test::snapshot(m);
    hmira::fill_hole_options o;
    o.max_memory_bytes = 1000;  // the 48-edge loop's tables take 24 * 48^2 bytes
    auto r = hmira::fill_holes(m, 1000, o);
    ASSERT_TRUE(r) << r.error().message;
    ASSERT_EQ(r->open.size(), 1u);
    EXPECT_EQ(r->open[0].code, hmira::errc::unsupported);
    EXPECT_NE(r->open[0].message.find("MiB"), std::string::npos) << r->open[0].message;
    EXPECT_TRUE(hmira_test::snapshot(m) == before);
}

/// A progress callback that counts its calls and answers false at call `stop_at` (1-based; 0: never).
struct stopper {
    std::size_t stop_at = 0, calls = 0;
    hmira::progress_function callback() {
        return [this](double) { return ++calls != stop_at; };
    }
};

/// A sphere of radius 1 (latitude-longitude grid) with caps cut at both poles and a few
/// one-face holes, so that fill_holes has loops of several sizes to fill.
mesh holed_sphere(int rings, int segments) {
    std::vector<hmira::vec3<double>> p;
    std::vector<std::vector<std::size_t>> f;
    for (int i = 1; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            const double th = std::numbers::pi * i / rings, ph = 2 * std::numbers::pi * j / segments;
            p.push_back({std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)});
        }
    auto id = [&](int i, int j) { return std::size_t((i - 1) * segments + (j % segments)); };
    for (int i = 2; i < rings; ++i)  // rows 1 and rings - 1 are the caps' rims
        for (int j = 0; j < segments; ++j) {
            if (i == rings / 2 && j % 7 == 3) continue;  // small holes
            f.push_back({id(i - 1, j), id(i, j), id(i, j + 1)});
            f.push_back({id(i - 1, j), id(i, j + 1), id(i - 1, j + 1)});
        }
    mesh m;
    for (const auto& q : p) m.add_vertex(q);
    for (const auto& face : f) {
        std::vector<hmira::vertex_handle> vs;
        for (auto v : face) vs.push_back(hmira::vertex_handle(v));
        (void)m.add_face(vs);
    }
    return m;
}

TEST(fill_holes_reasons, cancelling_at_any_progress_call_leaves_the_mesh_as_it_was) {
    for (const bool refine : {false, true}) {
        hmira::fill_hole_options o;
        o.refine = refine;
        o.fair = refine ? hmira::fairing::thin_plate : hmira::fairing::none;
        // The number of calls a whole run makes, then a cancellation at several of them.
        mesh probe = holed_sphere(40, 60);
        ASSERT_EQ(problems(probe), "");
        stopper count;
        o.progress = count.callback();
        auto whole = hmira::fill_holes(probe, 1000, o);
        ASSERT_TRUE(whole) << whole.error().message;
        ASSERT_GE(whole->filled, 4u);
        ASSERT_GE(count.calls, 4u) << "too few progress calls to test";
        EXPECT_EQ(boundary_loops(probe), 0u);
        for (std::size_t k : {std::size_t(1), std::size_t(2), count.calls / 2, count.calls - 1, count.calls}) {
            mesh m = holed_sphere(40, 60);
            const auto before = hmira_test::snapshot(m);
            stopper s{k};
            o.progress = s.callback();
            auto r = hmira::fill_holes(m, 1000, o);
            ASSERT_FALSE(r) << "cancel at call " << k << " of " << count.calls << " (refine " << refine << ")";
            EXPECT_EQ(r.error().code, hmira::errc::cancelled);
            EXPECT_EQ(s.calls, k);
            EXPECT_TRUE(hmira_test::snapshot(m) == before)
                << "cancel at call " << k << " changed the mesh (refine " << refine << ")";
            EXPECT_EQ(problems(m), "");
        }
    }
}

TEST(fill_holes_reasons, cancelling_one_fill_hole_leaves_the_mesh_as_it_was) {
    hmira::fill_hole_options o;
    o.refine = true;
    o.fair = hmira::fairing::thin_plate;
    mesh probe = holed_sphere(40, 60);
    auto first_boundary = [](const mesh& m) {
        for (auto h : m.halfedges())
            if (T::face(m, h) == T::null_face()) return hmira::halfedge_handle(h);
        return hmira::halfedge_handle{};
    };
    stopper count;
    o.progress = count.callback();
    ASSERT_TRUE(hmira::fill_hole(probe, first_boundary(probe), o));
    ASSERT_GE(count.calls, 2u);
    for (std::size_t k = 1; k <= count.calls; ++k) {
        mesh m = holed_sphere(40, 60);
        const auto before = hmira_test::snapshot(m);
        stopper s{k};
        o.progress = s.callback();
        auto r = hmira::fill_hole(m, first_boundary(m), o);
        ASSERT_FALSE(r) << k;
        EXPECT_EQ(r.error().code, hmira::errc::cancelled);
        EXPECT_TRUE(hmira_test::snapshot(m) == before) << "cancel at call " << k;
    }
}

/// A flat annulus one edge wide around a round hole of n edges.
mesh ring_around_hole(std::size_t n) {
    mesh m;
    const double r = double(n) / (2 * std::numbers::pi);
    for (int ring = 0; ring < 2; ++ring)
        for (std::size_t i = 0; i < n; ++i) {
            const double a = 2 * std::numbers::pi * double(i) / double(n), rr = r + ring;
            m.add_vertex({rr * std::cos(a), rr * std::sin(a), 0.0});
        }
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t j = (i + 1) % n;
        (void)m.add_face(std::vector<hmira::vertex_handle>{hmira::vertex_handle(i), hmira::vertex_handle(j),
                                                           hmira::vertex_handle(n + j)});
        (void)m.add_face(std::vector<hmira::vertex_handle>{hmira::vertex_handle(i), hmira::vertex_handle(n + j),
                                                           hmira::vertex_handle(n + i)});
    }
    return m;
}

TEST(fill_holes_reasons, a_thin_plate_fill_of_a_16000_edge_hole_reports_progress_and_cancels_promptly) {
    // Under the sanitizers (-O0) a smaller hole: the property does not depend on the size.
#ifdef HMIRA_SANITIZER_BUILD
    mesh m = ring_around_hole(2000);
#else
    mesh m = ring_around_hole(16000);
#endif
    ASSERT_EQ(problems(m), "");
    ASSERT_EQ(boundary_loops(m), 2u);
    const auto before = hmira_test::snapshot(m);
    hmira::fill_hole_options o;
    o.fair = hmira::fairing::thin_plate;
    o.refine = true;
    std::size_t calls = 0;
    o.progress = [&](double) { return ++calls < 5; };
    auto r = hmira::fill_holes(m, 20000, o);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, hmira::errc::cancelled);
    EXPECT_EQ(calls, 5u) << "the fill went on reporting after it was cancelled";
    EXPECT_TRUE(hmira_test::snapshot(m) == before);
}

}  // namespace
