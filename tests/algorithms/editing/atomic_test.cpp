// Atomicity of truncate, bevel and extrude: every call either succeeds
// with a valid mesh, or fails with the mesh unchanged as seen through the traits (the same live
// handles with the same indices, connectivity and positions). Checked three ways: seeded
// random selections on awkward meshes; a failure injected into the k-th inner operator call;
// std::bad_alloc thrown from the k-th raw mutation, for every k of an edit.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <new>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <hmira/algorithms/primitives/primitives.hpp>

#include "algorithms/editing/editing_support.hpp"
#include "algorithms/euler/euler_support.hpp"
#include "support/snapshot.hpp"

namespace {

/// The model's traits, with test hooks: the k-th inner operator call of an edit fails
/// (fail_inner_call, read by the editing code), or the k-th raw mutation throws bad_alloc.
template <class M>
struct faulty_traits : hmira::default_traits<M> {
    using base = hmira::default_traits<M>;
    using H = typename base::halfedge_handle;
    using V = typename base::vertex_handle;
    using F = typename base::face_handle;
    using E = typename base::edge_handle;
    using P = hmira::vec3<typename base::scalar>;
    static inline long long fail_inner_at = -1, throw_at = -1;  // countdowns; -1: off
    static inline long long inner_calls = 0, mutations = 0;
    static void reset() {
        fail_inner_at = throw_at = -1;
        inner_calls = mutations = 0;
    }
    static bool fail_inner_call() {
        ++inner_calls;
        return fail_inner_at >= 0 && fail_inner_at-- == 0;
    }
    static void tick() {
        ++mutations;
        if (throw_at >= 0 && throw_at-- == 0) throw std::bad_alloc();
    }
    static void set_next(M& m, H h, H n) {
        tick();
        base::set_next(m, h, n);
    }
    static void set_target(M& m, H h, V v) {
        tick();
        base::set_target(m, h, v);
    }
    static void set_face(M& m, H h, F f) {
        tick();
        base::set_face(m, h, f);
    }
    static void set_vertex_halfedge(M& m, V v, H h) {
        tick();
        base::set_vertex_halfedge(m, v, h);
    }
    static void set_face_halfedge(M& m, F f, H h) {
        tick();
        base::set_face_halfedge(m, f, h);
    }
    static void set_position(M& m, V v, const P& p) {
        tick();
        base::set_position(m, v, p);
    }
    static H new_edge(M& m, V a, V b) {
        tick();
        return base::new_edge(m, a, b);
    }
    static F new_face(M& m) {
        tick();
        return base::new_face(m);
    }
    static V add_vertex(M& m, const P& p) {
        tick();
        return base::add_vertex(m, p);
    }
    // Erasing only marks an element on every model and never allocates; the journal relies
    // on that (its commit erases last), so erasures are counted but never throw.
    static void erase_edge(M& m, E e) {
        ++mutations;
        base::erase_edge(m, e);
    }
    static void erase_face(M& m, F f) {
        ++mutations;
        base::erase_face(m, f);
    }
    static void erase_vertex(M& m, V v) {
        ++mutations;
        base::erase_vertex(m, v);
    }
};

template <class M>
struct atomic_test : ::testing::Test {};
TYPED_TEST_SUITE(atomic_test, hmira_test::all_models);

#define HMIRA_REQUIRE_EDITING(M)                                                        \
    if constexpr (!hmira::extrudable_mesh<M>) {                                         \
        GTEST_SKIP() << "not an editable model (no Euler operators or triangles only)"; \
        return;                                                                         \
    }

template <class M, class T = hmira::default_traits<M>>
std::vector<typename T::vertex_handle> all_vertices(const M& m) {
    std::vector<typename T::vertex_handle> out;
    for (auto v : T::vertices(m)) out.push_back(v);
    return out;
}
template <class M, class T = hmira::default_traits<M>>
std::vector<typename T::edge_handle> all_edge_handles(const M& m) {
    std::vector<typename T::edge_handle> out;
    for (auto e : T::edges(m)) out.push_back(e);
    return out;
}
template <class M, class T = hmira::default_traits<M>>
std::vector<typename T::face_handle> all_face_handles(const M& m) {
    std::vector<typename T::face_handle> out;
    for (auto f : T::faces(m)) out.push_back(f);
    return out;
}

/// One edit, named for messages, applied through traits T to a selection chosen by `rng`.
enum class edit_kind { truncate, bevel1, bevel2, bevel3, extrude_region, extrude_individual };
constexpr edit_kind all_edits[] = {edit_kind::truncate, edit_kind::bevel1,         edit_kind::bevel2,
                                   edit_kind::bevel3,   edit_kind::extrude_region, edit_kind::extrude_individual};
const char* name_of(edit_kind k) {
    switch (k) {
        case edit_kind::truncate: return "truncate";
        case edit_kind::bevel1: return "bevel segments=1";
        case edit_kind::bevel2: return "bevel segments=2";
        case edit_kind::bevel3: return "bevel segments=3";
        case edit_kind::extrude_region: return "extrude region";
        case edit_kind::extrude_individual: return "extrude individual";
    }
    return "?";
}

/// A selection and options, fixed before the call so that the same edit can be replayed.
template <class M>
struct planned_edit {
    using T = hmira::default_traits<M>;
    edit_kind kind{};
    std::vector<typename T::vertex_handle> vertices = {};
    std::vector<typename T::edge_handle> edges = {};
    std::vector<typename T::face_handle> faces = {};
    double amount = 0.1;
    bool clamp = true;
};

template <class M>
planned_edit<M> plan_edit(const M& m, edit_kind kind, std::mt19937& rng, bool everything = false) {
    planned_edit<M> p;
    p.kind = kind;
    std::uniform_real_distribution<double> u(0.0, 1.0);
    auto pick = [&](auto all) {
        std::shuffle(all.begin(), all.end(), rng);
        if (!everything) all.resize(std::min<std::size_t>(all.size(), 1 + rng() % 5));
        return all;
    };
    switch (kind) {
        case edit_kind::truncate:
            p.vertices = pick(all_vertices(m));
            p.amount = u(rng) < 0.2 ? 0.5 : 0.05 + 0.9 * u(rng);
            break;
        case edit_kind::bevel1:
        case edit_kind::bevel2:
        case edit_kind::bevel3:
            p.edges = pick(all_edge_handles(m));
            p.amount = 0.02 + 0.6 * u(rng);
            p.clamp = u(rng) < 0.8;
            break;
        case edit_kind::extrude_region:
        case edit_kind::extrude_individual:
            p.faces = pick(all_face_handles(m));
            p.amount = (u(rng) < 0.5 ? -1 : 1) * (0.05 + u(rng));
            break;
    }
    return p;
}

/// Runs the planned edit through traits T; returns the error, if any.
template <class M, class T>
std::optional<hmira::error> run(M& m, const planned_edit<M>& p) {
    auto err = [](const auto& r) -> std::optional<hmira::error> {
        if (r) return std::nullopt;
        return r.error();
    };
    switch (p.kind) {
        case edit_kind::truncate: return err(hmira::truncate<M, T>(m, p.vertices, {.fraction = p.amount}));
        case edit_kind::bevel1:
            return err(hmira::bevel<M, T>(m, p.edges, {.width = p.amount, .segments = 1, .clamp_overlap = p.clamp}));
        case edit_kind::bevel2:
            return err(hmira::bevel<M, T>(m, p.edges, {.width = p.amount, .segments = 2, .clamp_overlap = p.clamp}));
        case edit_kind::bevel3:
            return err(hmira::bevel<M, T>(m, p.edges, {.width = p.amount, .segments = 3, .clamp_overlap = p.clamp}));
        case edit_kind::extrude_region:
            return err(hmira::extrude<M, T>(m, p.faces, {.distance = p.amount, .mode = hmira::extrude_mode::region}));
        case edit_kind::extrude_individual:
            return err(
                hmira::extrude<M, T>(m, p.faces, {.distance = p.amount, .mode = hmira::extrude_mode::individual}));
    }
    return std::nullopt;
}

/// The meshes the suites try: closed and convex, genus 1, open with near-degenerate geometry,
/// and holes cut diagonally so that vertices are pinched between two boundary gaps.
struct named_shape {
    std::string name;
    hmira_test::face_list shape;
};
std::vector<named_shape> shapes() {
    std::vector<named_shape> out;
    out.push_back({"box 2x2x1", hmira_test::lattice_box(2, 2, 1)});
    out.push_back({"torus 6x4", hmira_test::torus(6, 4)});
    auto g = hmira_test::grid(4, 3);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> jitter(-0.2, 0.2);
    for (auto& p : g.points) {
        p.x += jitter(rng);
        p.y += jitter(rng);
        p.z += 0.3 * jitter(rng);
    }
    g.points[6].x = g.points[7].x - 1e-7;  // a near-zero edge
    g.points[6].y = g.points[7].y;
    out.push_back({"jittered open grid with a tiny edge", g});
    // Faces 6 and 12 of a 5x5 grid touch at one corner only: removing the faces around that
    // corner pinches it.
    out.push_back({"grid with diagonal holes (pinched)",
                   hmira_test::without_faces(hmira_test::grid(5, 5),
                                             [](std::size_t f) { return f == 7 || f == 11 || f == 18 || f == 22; })});
    return out;
}

template <class M>
std::string describe(const M& m, const planned_edit<M>& p) {
    using T = hmira::default_traits<M>;
    std::ostringstream o;
    o << name_of(p.kind) << " amount " << p.amount << (p.clamp ? "" : " unclamped") << "; vertices";
    for (auto v : p.vertices) o << ' ' << T::vertex_index(m, v);
    o << "; edges";
    for (auto e : p.edges) o << ' ' << T::edge_index(m, e);
    o << "; faces";
    for (auto f : p.faces) o << ' ' << T::face_index(m, f);
    return o.str();
}

template <class M>
bool build(M& m, const hmira_test::face_list& g) {
    return hmira_test::add_face_list(m, g);
}

/// The cube [-1,1]^3 whose top face (y = 1) has a square inner ring of half-size a, built
/// with Euler operators (a chain of makeEV into the top, makeEF closing the square, killEmakeR
/// on the chain's first edge). With `plugged` the square stays a face of its own (V 12, E 16,
/// F 7, R 1); without, it is removed and the ring borders a hole in the top (F 6).
/// Returns the ringed face.
template <class M, class T = hmira::default_traits<M>>
typename T::face_handle ringed_cube(M& m, double a, bool plugged) {
    using S = typename T::scalar;
    auto cube = hmira::generate_cube(m);
    EXPECT_TRUE(cube);
    const auto corner = T::face_halfedge(m, cube.value().faces[5]);
    const hmira::vec3<S> q[4] = {{S(-a), 1, S(-a)}, {S(-a), 1, S(a)}, {S(a), 1, S(a)}, {S(a), 1, S(-a)}};
    auto p0 = hmira::make_edge_vertex<M, T>(m, corner, q[0]);
    EXPECT_TRUE(p0);
    auto prev = p0.value().halfedge;
    for (int i = 1; i < 4; ++i) {
        auto next = hmira::make_edge_vertex<M, T>(m, prev, q[i]);
        EXPECT_TRUE(next);
        prev = next.value().halfedge;
    }
    EXPECT_TRUE((hmira::make_edge_face<M, T>(m, prev, p0.value().halfedge)));
    const auto ring = hmira::kill_edge_make_ring<M, T>(m, p0.value().halfedge);
    EXPECT_TRUE(ring);
    const auto top = T::face(m, ring.value().ring);
    if (!plugged) {
        EXPECT_TRUE((hmira::remove_face<M, T>(m, T::face(m, T::opposite(m, ring.value().ring)))));
    }
    return top;
}

/// The bases the random suite edits: the shapes above, and on a model with inner rings a cube
/// whose top has a ring, plugged by a face or open.
template <class M>
std::vector<std::pair<std::string, M>> bases() {
    std::vector<std::pair<std::string, M>> out;
    for (const auto& s : shapes()) {
        M m;
        if (build(m, s.shape)) out.emplace_back(s.name, std::move(m));  // a model may refuse a pinched shape
    }
    if constexpr (hmira::euler_ring_mutable_mesh<M>) {
        for (bool plugged : {true, false}) {
            M m;
            ringed_cube(m, 0.5, plugged);
            out.emplace_back(plugged ? "cube with a plugged ring in its top" : "cube with an open ring in its top",
                             std::move(m));
        }
    }
    return out;
}

TYPED_TEST(atomic_test, random_edits_either_succeed_validly_or_change_nothing) {
    using M = TypeParam;
    HMIRA_REQUIRE_EDITING(M)
    else {
        using T = hmira::default_traits<M>;
        std::mt19937 rng(1313);
        std::size_t succeeded = 0, refused = 0;
        std::size_t ringed = 0;
        for (const auto& [name, base] : bases<M>()) {
            const struct {
                const std::string& name;
            } s{name};
            if constexpr (hmira::inner_ring_mesh<M, T>)
                for (auto f : T::faces(base)) ringed += std::ranges::empty(T::inner_rings(base, f)) ? 0 : 1;
            const long long chi = hmira_test::count_euler(base).lhs();
            const std::size_t base_problems = hmira::validate<M, T>(base, {.check_geometry = false}).size();
            for (auto kind : all_edits)
                for (int trial = 0; trial < 12; ++trial) {
                    M m = base;
                    const auto p = plan_edit(m, kind, rng, trial == 0);
                    const auto before = hmira_test::snapshot(m);
                    const auto e = run<M, T>(m, p);
                    SCOPED_TRACE(s.name + ", " + name_of(kind) + ", trial " + std::to_string(trial));
                    if (e) {
                        ++refused;
                        EXPECT_FALSE(e->message.empty());
                        ASSERT_TRUE(hmira_test::snapshot(m) == before)
                            << "refused (" << e->message << ") but changed the mesh";
                        continue;
                    }
                    ++succeeded;
                    // A pinched input stays pinched where it was not edited: the same problems.
                    const auto problems = hmira::validate<M, T>(m, {.check_geometry = false});
                    ASSERT_EQ(problems.size(), base_problems) << describe(base, p) << hmira_test::describe(problems);
                    for (const auto& q : problems)
                        ASSERT_NE(q.message.find("separate fans"), std::string::npos) << q.message;
                    ASSERT_EQ(hmira_test::count_euler(m).lhs(), chi) << "Euler-Poincare changed";
                    if (s.name == "box 2x2x1" &&
                        (kind == edit_kind::truncate || (kind == edit_kind::bevel1 && p.clamp))) {
                        EXPECT_TRUE((hmira_test::faces_point_outward<M, T>(m, {1, 1, 0.5})));
                    }
                }
        }
        EXPECT_GT(succeeded, 50u);
        EXPECT_GT(refused, 5u);  // the pinched vertices and boundary edges must be refused sometimes
        if constexpr (hmira::euler_ring_mutable_mesh<M>) {
            EXPECT_EQ(ringed, 2u) << "both ringed bases were edited";
        }
    }
}

/// Runs the edit once to count its inner calls and raw mutations, then once per k with the
/// k-th of them failing; each failed run must leave the mesh exactly as it was, and a later
/// clean run must still succeed.
template <class M>
void check_every_fault(const M& base, const planned_edit<M>& p, const std::string& what) {
    using FT = faulty_traits<M>;
    SCOPED_TRACE(what);
    FT::reset();
    {
        M m = base;
        const auto e = run<M, FT>(m, p);
        ASSERT_FALSE(e) << e->message;
        ASSERT_TRUE(hmira_test::is_valid(m, {.check_geometry = false}));
    }
    const long long inner = FT::inner_calls, raw = FT::mutations;
    ASSERT_GT(inner, 0);
    ASSERT_GT(raw, 0);
    const auto before = hmira_test::snapshot(base);
    for (long long k = 0; k < inner; ++k) {
        M m = base;
        FT::reset();
        FT::fail_inner_at = k;
        const auto e = run<M, FT>(m, p);
        ASSERT_TRUE(e) << "inner call " << k << " was made to fail but the edit succeeded";
        ASSERT_TRUE(hmira_test::snapshot(m) == before)
            << "inner call " << k << " of " << inner << " failed: mesh changed";
        FT::reset();
        ASSERT_FALSE((run<M, FT>(m, p))) << "the edit no longer applies after the rollback of inner call " << k;
        ASSERT_TRUE(hmira_test::is_valid(m, {.check_geometry = false}));
    }
    long long throwing = 0;
    for (long long k = 0; k < raw; ++k) {
        M m = base;
        FT::reset();
        FT::throw_at = k;
        bool threw = false;
        try {
            (void)run<M, FT>(m, p);
        } catch (const std::bad_alloc&) {
            threw = true;
        }
        if (!threw) continue;  // the k-th mutation is an erasure, which never throws
        ++throwing;
        ASSERT_TRUE(hmira_test::snapshot(m) == before)
            << "bad_alloc from mutation " << k << " of " << raw << ": mesh changed";
        FT::reset();
        ASSERT_FALSE((run<M, FT>(m, p))) << "the edit no longer applies after the rollback of mutation " << k;
        ASSERT_TRUE(hmira_test::is_valid(m, {.check_geometry = false}));
    }
    EXPECT_GT(throwing, raw / 2);
}

TYPED_TEST(atomic_test, a_failure_or_bad_alloc_at_every_step_of_an_edit_leaves_the_mesh_unchanged) {
    using M = TypeParam;
    HMIRA_REQUIRE_EDITING(M)
    else {
        using T = hmira::default_traits<M>;
        M box;
        ASSERT_TRUE(build(box, hmira_test::lattice_box(2, 1, 1)));
        M open;
        ASSERT_TRUE(build(open, hmira_test::grid(3, 2)));
        std::mt19937 rng(99);
        for (auto kind : all_edits) {
            // Deterministic selections of a few elements (the whole box for one bevel).
            auto p = plan_edit(box, kind, rng);
            if (kind == edit_kind::bevel3) {  // the three edges of one corner: a grid-filled patch
                p.edges.clear();
                const auto v = *T::vertices(box).begin();
                auto h = T::vertex_halfedge(box, v);
                for (int i = 0; i < 3; ++i, h = T::next(box, T::opposite(box, h))) p.edges.push_back(T::edge(box, h));
            }
            p.clamp = true;
            if (kind == edit_kind::truncate) p.amount = 0.3;
            if (kind == edit_kind::bevel1 || kind == edit_kind::bevel2 || kind == edit_kind::bevel3) p.amount = 0.2;
            if (kind == edit_kind::extrude_region) {  // two faces sharing an edge
                const auto f = all_face_handles<M, T>(box)[0];
                p.faces = {f, T::face(box, T::opposite(box, T::face_halfedge(box, f)))};
            }
            check_every_fault(box, p, std::string("box, ") + name_of(kind));
        }
        // Boundary vertices and an open region.
        planned_edit<M> t{.kind = edit_kind::truncate,
                          .vertices = all_vertices<M, T>(open),
                          .edges = {},
                          .faces = {},
                          .amount = 0.25,
                          .clamp = true};
        check_every_fault(open, t, "open grid, truncate all");
        planned_edit<M> x{.kind = edit_kind::extrude_region,
                          .vertices = {},
                          .edges = {},
                          .faces = all_face_handles<M, T>(open),
                          .amount = 0.5,
                          .clamp = true};
        check_every_fault(open, x, "open grid, extrude all as a region");
        if constexpr (hmira::euler_ring_mutable_mesh<M, T>) {
            // Faces with holes: the ringed face extruded both ways, the ring's vertices cut
            // where the ring borders a hole, the ring's edges bevelled where it holds a plug.
            M plugged;
            const auto top = ringed_cube<M, T>(plugged, 0.5, true);
            for (auto mode : {edit_kind::extrude_region, edit_kind::extrude_individual}) {
                planned_edit<M> e{
                    .kind = mode, .vertices = {}, .edges = {}, .faces = {top}, .amount = 0.5, .clamp = true};
                check_every_fault(plugged, e, std::string("ringed top, ") + name_of(mode));
            }
            std::vector<typename T::edge_handle> ring_edges;
            std::vector<typename T::vertex_handle> ring_vertices;
            const auto r = *T::inner_rings(plugged, top).begin();
            auto h = r;
            do {
                ring_edges.push_back(T::edge(plugged, h));
                ring_vertices.push_back(T::target(plugged, h));
                h = T::next(plugged, h);
            } while (h != r);
            planned_edit<M> b{.kind = edit_kind::bevel1,
                              .vertices = {},
                              .edges = ring_edges,
                              .faces = {},
                              .amount = 0.1,
                              .clamp = true};
            {
                // The ring lies flat in the top face, so its bevelled corners would be faces of
                // zero area: bevel refuses the selection and leaves the mesh as it was.
                using FT = faulty_traits<M>;
                FT::reset();
                M m = plugged;
                const auto before = hmira_test::snapshot(m);
                const auto e = run<M, FT>(m, b);
                ASSERT_TRUE(e) << "a flat ring's edges were bevelled";
                EXPECT_TRUE(hmira_test::snapshot(m) == before) << e->message;
            }
            planned_edit<M> t2{.kind = edit_kind::truncate,
                               .vertices = ring_vertices,
                               .edges = {},
                               .faces = {},
                               .amount = 0.25,
                               .clamp = true};
            check_every_fault(plugged, t2, "plugged ring, truncate its vertices");
        }
    }
}

TYPED_TEST(atomic_test, deleted_handles_are_refused_as_invalid_handles_where_the_model_can_tell) {
    using M = TypeParam;
    HMIRA_REQUIRE_EDITING(M)
    else {
        using T = hmira::default_traits<M>;
        M m;
        ASSERT_TRUE(build(m, hmira_test::lattice_box(1, 1, 1)));
        // Grow a spike out of a corner and kill it again: its vertex and edge are now deleted.
        const auto corner = T::face_halfedge(m, *T::faces(m).begin());
        const auto spike = hmira::make_edge_vertex<M, T>(m, corner, {0.5, 0.5, 3});
        ASSERT_TRUE(spike);
        const auto dead_vertex = spike.value().vertex;
        const auto dead_halfedge = spike.value().halfedge;
        const auto dead_edge = T::edge(m, dead_halfedge);
        ASSERT_TRUE((hmira::kill_edge_vertex<M, T>(m, dead_halfedge)));
        const auto before = hmira_test::snapshot(m);
        const typename T::vertex_handle vs[] = {dead_vertex};
        auto t = hmira::truncate<M, T>(m, vs);
        ASSERT_FALSE(t);
        EXPECT_EQ(t.error().code, hmira::errc::invalid_handle) << t.error().message;
        EXPECT_TRUE(hmira_test::snapshot(m) == before) << "truncate";
        auto b = hmira::bevel<M, T>(m, dead_edge);
        ASSERT_FALSE(b);
        EXPECT_EQ(b.error().code, hmira::errc::invalid_handle) << b.error().message;
        EXPECT_TRUE(hmira_test::snapshot(m) == before) << "bevel";
        auto e = hmira::make_edge_vertex<M, T>(m, dead_halfedge, {0, 0, 0});
        ASSERT_FALSE(e);
        EXPECT_EQ(e.error().code, hmira::errc::invalid_handle) << e.error().message;
        EXPECT_TRUE(hmira_test::snapshot(m) == before) << "make_edge_vertex";
        auto k = hmira::kill_edge_vertex<M, T>(m, dead_halfedge);
        ASSERT_FALSE(k);
        EXPECT_EQ(k.error().code, hmira::errc::invalid_handle) << k.error().message;
        EXPECT_TRUE(hmira_test::snapshot(m) == before);
        // A deleted face: killEF(h) keeps h's own face and deletes the one across h (this case
        // once took face(h), which survives, and so wrongly saw the extrude succeed).
        const auto h = T::face_halfedge(m, *T::faces(m).begin());
        const auto gone = T::face(m, T::opposite(m, h));
        ASSERT_NE(gone, T::null_face());
        ASSERT_TRUE((hmira::kill_edge_face<M, T>(m, h)));
        ASSERT_TRUE((T::is_removed(m, gone)));
        const auto after_kill = hmira_test::snapshot(m);
        auto x = hmira::extrude<M, T>(m, gone, {.distance = 1});
        ASSERT_FALSE(x);
        EXPECT_EQ(x.error().code, hmira::errc::invalid_handle) << x.error().message;
        EXPECT_TRUE(hmira_test::snapshot(m) == after_kill) << "extrude";
    }
}

/// Every line of include/ that discards a call's result with (void) or dereferences a call's
/// result with ->, which for a result<T> would throw or hide an error.
TEST(atomic_source, no_result_is_discarded_or_dereferenced_unchecked_in_include) {
    const std::filesystem::path root = std::filesystem::path(HMIRA_SOURCE_DIR) / "include";
    ASSERT_TRUE(std::filesystem::is_directory(root)) << root;
    const std::regex discarded(R"(\(void\)\s*[A-Za-z_][A-Za-z_0-9:]*\s*(<[^;]*>)?\s*\()");
    const std::regex arrow_on_call(R"([A-Za-z_0-9>]\s*\([^()]*(\([^()]*\)[^()]*)*\)\s*->\s*[A-Za-z_])");
    // `*begin()`, `*std::prev(it)` and the like dereference iterators, not results.
    const std::regex star_on_call(
        R"((=|return|\()\s*\*\s*(?!begin\b|end\b|std::prev\b|std::next\b)[A-Za-z_][A-Za-z_0-9:]*\s*(<[^;]*>)?\s*\()");
    // A trailing return type (`[...](...) -> T {`, `auto f(...) -> T`) is no dereference.
    const std::regex trailing_return(
        R"(\)\s*->\s*(decltype\b|[A-Za-z_:]+\s*<[^;]*>\s*(\{|$|requires)|[A-Za-z_:]+\s*(\{|$|requires)))");
    std::vector<std::string> hits;
    std::size_t files = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
        if (!entry.is_regular_file() || entry.path().extension() != ".hpp") continue;
        ++files;
        std::ifstream in(entry.path());
        std::string line;
        for (int n = 1; std::getline(in, line); ++n) {
            const auto code = line.substr(0, line.find("//"));
            // Each pattern needs its literal token; skipping the regexes on the other lines keeps
            // the scan to seconds under the sanitizers (std::regex at -O0 took 111 s otherwise).
            const bool has_void = code.find("(void)") != std::string::npos;
            const bool has_arrow = code.find("->") != std::string::npos;
            const bool has_star = code.find('*') != std::string::npos;
            if ((has_void && std::regex_search(code, discarded)) ||
                (has_arrow && !std::regex_search(code, trailing_return) && std::regex_search(code, arrow_on_call)) ||
                (has_star && std::regex_search(code, star_on_call)))
                hits.push_back(entry.path().lexically_relative(root).string() + ":" + std::to_string(n) + ": " + line);
        }
    }
    EXPECT_GT(files, 50u);
    std::ostringstream all;
    for (const auto& h : hits) all << "\n  " << h;
    EXPECT_TRUE(hits.empty()) << hits.size() << " line(s):" << all.str();
}

TEST(atomic_source, the_pattern_catches_the_forms_it_forbids) {
    // The same expressions as above, on known lines: the check must be able to fail.
    const std::regex discarded(R"(\(void\)\s*[A-Za-z_][A-Za-z_0-9:]*\s*(<[^;]*>)?\s*\()");
    const std::regex arrow_on_call(R"([A-Za-z_0-9>]\s*\([^()]*(\([^()]*\)[^()]*)*\)\s*->\s*[A-Za-z_])");
    EXPECT_TRUE(std::regex_search("(void)make_edge_face<M, T>(m, a, b);", discarded));
    EXPECT_TRUE(std::regex_search("(void)kill_edge_face<M, T>(m, T::opposite(m, h));", discarded));
    EXPECT_TRUE(std::regex_search("const auto ux = make_edge_vertex<M, T>(m, c, p)->halfedge;", arrow_on_call));
    EXPECT_TRUE(std::regex_search("x = make_edge_face<M, T>(mesh, h0, h1)->face;", arrow_on_call));
    EXPECT_FALSE(std::regex_search("(void)m;", discarded));
}

}  // namespace
