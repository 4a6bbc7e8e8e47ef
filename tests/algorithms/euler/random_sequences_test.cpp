// Seeded random sequences of thousands of Euler operators on random meshes, on every model
// that supports them. After each step the mesh is validated (relaxed mode) and
// V - E + F - R = 2 (S - H) is checked, S - H tracked from the operators applied; operators
// tried with arguments that break their preconditions must fail and change nothing. Then the
// inverses, applied in reverse order, must give back the start mesh.
//
// The generator only proposes steps whose result validate() can judge: it creates no
// parallel edges (its edge census keys edges by their end vertices), and it does not hide a
// vertex's last visible corner in an inner ring where the vertex also has other gaps
// (validate's fan check sees a face's outer loop only).

#include <gtest/gtest.h>

#include <cstdlib>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include <hmira/algorithms/euler/euler.hpp>

#include "algorithms/euler/euler_support.hpp"
#include "support/models.hpp"

namespace {

using namespace hmira_test;

template <class M>
struct random_session {
    using T = hmira::default_traits<M>;
    using V = typename T::vertex_handle;
    using H = typename T::halfedge_handle;
    using F = typename T::face_handle;
    using S = typename T::scalar;
    using hkey = std::pair<point_key, point_key>;
    static constexpr bool rings = hmira::euler_ring_mutable_mesh<M>;

    M mesh;
    std::mt19937_64 rng;
    long long s_minus_h;
    int fresh = 0;
    std::vector<std::function<void()>> undo;
    std::size_t applied = 0, rejected = 0;
    std::vector<std::size_t> applied_by_kind = std::vector<std::size_t>(12, 0);

    random_session(M m, std::uint64_t seed, long long s_h) : mesh(std::move(m)), rng(seed), s_minus_h(s_h) {}

    // ----- naming elements by position, so undo survives re-created handles -----------------
    V vertex(point_key k) {
        for (auto v : T::vertices(mesh))
            if (key_of<M, T>(mesh, v) == k) return v;
        ADD_FAILURE() << "no vertex at the recorded position";
        return V();
    }
    hkey key(H h) {
        return {key_of<M, T>(mesh, T::target(mesh, T::opposite(mesh, h))), key_of<M, T>(mesh, T::target(mesh, h))};
    }
    H he(const hkey& k) {
        const auto h = find_halfedge<M, T>(mesh, vertex(k.first), vertex(k.second));
        EXPECT_NE(h, T::null_halfedge()) << "a recorded halfedge is gone";
        return h;
    }
    hmira::vec3<S> new_position() {
        ++fresh;
        return {S(100 + fresh), S(0.5), S(-3)};
    }

    // ----- random choices ----------------------------------------------------------------------
    std::size_t pick(std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); }
    std::vector<H> all_halfedges() {
        std::vector<H> out;
        for (auto h : T::halfedges(mesh)) out.push_back(h);
        return out;
    }
    std::vector<F> all_faces() {
        std::vector<F> out;
        for (auto f : T::faces(mesh)) out.push_back(f);
        return out;
    }
    std::vector<H> loop(H start) {
        std::vector<H> out;
        auto h = start;
        do {
            out.push_back(h);
            h = T::next(mesh, h);
        } while (h != start);
        return out;
    }
    bool on_ring(H h) {
        const auto f = T::face(mesh, h);
        if (f == T::null_face()) return false;
        const auto fh = T::face_halfedge(mesh, f);
        for (auto x : loop(h))
            if (x == fh) return false;
        return true;
    }
    /// No boundary gap and no inner-ring corner around v: hiding one corner keeps one fan.
    bool clean(V v) {
        const auto start = T::vertex_halfedge(mesh, v);
        if (start == T::null_halfedge()) return false;
        auto h = start;
        do {
            if (T::face(mesh, h) == T::null_face() || on_ring(h)) return false;
            h = T::next(mesh, T::opposite(mesh, h));
        } while (h != start);
        return true;
    }
    /// Every vertex of the loop clean and met once.
    bool clean_loop(H start) {
        std::vector<V> seen;
        for (auto x : loop(start)) {
            const auto v = T::target(mesh, x);
            if (std::find(seen.begin(), seen.end(), v) != seen.end() || !clean(v)) return false;
            seen.push_back(v);
        }
        return true;
    }
    bool adjacent(V a, V b) { return find_halfedge<M, T>(mesh, a, b) != T::null_halfedge(); }

    /// A rejected operator must leave everything as it was.
    template <class R>
    void expect_rejected_cleanly(const snapshot& before, const R& r) {
        EXPECT_FALSE(r) << "the operator accepted arguments the generator thought invalid";
        const bool unchanged = take_snapshot<M, T>(mesh) == before;
        EXPECT_TRUE(unchanged) << "a failed operator changed the mesh: " << (r ? std::string() : r.error().message);
        ++rejected;
    }

    // ----- the steps ---------------------------------------------------------------------------
    bool step_make_vertex() {
        const auto p = new_position();
        hmira::make_vertex(mesh, p);
        ++s_minus_h;
        undo.push_back([this, k = point_key{double(p.x), double(p.y), double(p.z)}] {
            ASSERT_TRUE(hmira::kill_vertex(mesh, vertex(k)));
            --s_minus_h;
        });
        return true;
    }
    bool step_kill_vertex() {
        std::vector<V> isolated;
        for (auto v : T::vertices(mesh))
            if (T::vertex_halfedge(mesh, v) == T::null_halfedge()) isolated.push_back(v);
        if (isolated.empty()) {
            // A vertex with edges must be refused.
            auto hs = all_halfedges();
            if (hs.empty()) return false;
            const auto before = take_snapshot<M, T>(mesh);
            expect_rejected_cleanly(before, hmira::kill_vertex(mesh, T::target(mesh, hs[pick(hs.size())])));
            return false;
        }
        auto r = hmira::kill_vertex(mesh, isolated[pick(isolated.size())]);
        EXPECT_TRUE(r);
        --s_minus_h;
        undo.push_back([this, p = r->position] {
            hmira::make_vertex(mesh, p);
            ++s_minus_h;
        });
        return true;
    }
    bool step_make_edge_vertex() {
        const auto p = new_position();
        const point_key pk{double(p.x), double(p.y), double(p.z)};
        auto hs = all_halfedges();
        std::vector<V> isolated;
        for (auto v : T::vertices(mesh))
            if (T::vertex_halfedge(mesh, v) == T::null_halfedge()) isolated.push_back(v);
        if (!isolated.empty() && (hs.empty() || pick(4) == 0)) {
            auto r = hmira::make_edge_vertex(mesh, isolated[pick(isolated.size())], p);
            EXPECT_TRUE(r);
            undo.push_back([this, k = key(r->halfedge)] { ASSERT_TRUE(hmira::kill_edge_vertex(mesh, he(k))); });
            return true;
        }
        if (hs.empty()) return false;
        auto r = hmira::make_edge_vertex(mesh, hs[pick(hs.size())], p);
        EXPECT_TRUE(r);
        undo.push_back([this, k = key(r->halfedge)] { ASSERT_TRUE(hmira::kill_edge_vertex(mesh, he(k))); });
        (void)pk;
        return true;
    }
    bool step_kill_edge_vertex() {
        auto hs = all_halfedges();
        if (hs.empty()) return false;
        const auto h = hs[pick(hs.size())];
        const auto before = take_snapshot<M, T>(mesh);
        auto r = hmira::kill_edge_vertex(mesh, h);
        if (!r) {
            expect_rejected_cleanly(before, r);
            return false;
        }
        const bool isolated = r->corner == T::null_halfedge();
        undo.push_back([this, isolated, c = isolated ? hkey{} : key(r->corner), v = key_of<M, T>(mesh, r->vertex),
                        p = r->position] {
            auto m = isolated ? hmira::make_edge_vertex(mesh, vertex(v), p) : hmira::make_edge_vertex(mesh, he(c), p);
            ASSERT_TRUE(m);
        });
        return true;
    }
    bool step_make_edge_face() {
        auto fs = all_faces();
        if (fs.empty()) return false;
        const auto f = fs[pick(fs.size())];
        std::vector<H> starts{T::face_halfedge(mesh, f)};
        if constexpr (rings)
            for (auto r : T::inner_rings(mesh, f)) starts.push_back(r);
        const auto corners = loop(starts[pick(starts.size())]);
        for (int attempt = 0; attempt < 8; ++attempt) {
            const auto h0 = corners[pick(corners.size())], h1 = corners[pick(corners.size())];
            const auto s = T::target(mesh, h0), t = T::target(mesh, h1);
            if (s == t) {
                const auto before = take_snapshot<M, T>(mesh);
                expect_rejected_cleanly(before, hmira::make_edge_face(mesh, h0, h1));
                continue;
            }
            if (adjacent(s, t)) continue;
            auto r = hmira::make_edge_face(mesh, h0, h1);
            EXPECT_TRUE(r) << r.error().message;
            if (!r) return false;
            undo.push_back([this, k = key(r->halfedge)] {
                auto kill = hmira::kill_edge_face(mesh, he(k));
                ASSERT_TRUE(kill) << kill.error().message;
            });
            return true;
        }
        return false;
    }
    bool step_kill_edge_face() {
        auto hs = all_halfedges();
        if (hs.empty()) return false;
        const auto h = hs[pick(hs.size())];
        const auto f = T::face(mesh, h), g = T::face(mesh, T::opposite(mesh, h));
        const auto before = take_snapshot<M, T>(mesh);
        if (g == T::null_face() || f == g) {
            expect_rejected_cleanly(before, hmira::kill_edge_face(mesh, h));
            return false;
        }
        if (f == T::null_face() || on_ring(h)) return false;  // see the note at the top
        auto r = hmira::kill_edge_face(mesh, h);
        if (!r) {
            expect_rejected_cleanly(before, r);  // the edge is on a ring of g
            return false;
        }
        undo.push_back([this, h0 = key(r->h0), h1 = key(r->h1)] {
            auto m = hmira::make_edge_face(mesh, he(h0), he(h1));
            ASSERT_TRUE(m) << m.error().message;
        });
        return true;
    }
    bool step_fill_boundary_loop() {
        std::vector<H> boundary;
        for (auto h : T::halfedges(mesh))
            if (T::face(mesh, h) == T::null_face()) boundary.push_back(h);
        if (boundary.empty()) return false;
        const auto h = boundary[pick(boundary.size())];
        auto r = hmira::fill_boundary_loop(mesh, h);
        EXPECT_TRUE(r);
        undo.push_back([this, k = key(h)] { ASSERT_TRUE(hmira::open_face(mesh, T::face(mesh, he(k)))); });
        return true;
    }
    bool step_open_face() {
        auto fs = all_faces();
        if (fs.empty()) return false;
        const auto f = fs[pick(fs.size())];
        if (hmira::detail::euler::has_rings<M, T>(mesh, f)) {
            const auto before = take_snapshot<M, T>(mesh);
            expect_rejected_cleanly(before, hmira::open_face(mesh, f));
            return false;
        }
        if (!clean_loop(T::face_halfedge(mesh, f))) return false;
        auto r = hmira::open_face(mesh, f);
        EXPECT_TRUE(r);
        undo.push_back([this, k = key(r->halfedge)] { ASSERT_TRUE(hmira::fill_boundary_loop(mesh, he(k))); });
        return true;
    }
    bool step_kill_face_make_ring() {
        if constexpr (rings) {
            auto fs = all_faces();
            if (fs.size() < 2) return false;
            const auto f = fs[pick(fs.size())], host = fs[pick(fs.size())];
            const auto before = take_snapshot<M, T>(mesh);
            if (f == host || hmira::detail::euler::has_rings<M, T>(mesh, f)) {
                expect_rejected_cleanly(before, hmira::kill_face_make_ring(mesh, f, host));
                return false;
            }
            if (!clean_loop(T::face_halfedge(mesh, f))) return false;
            auto r = hmira::kill_face_make_ring(mesh, f, host);
            EXPECT_TRUE(r);
            --s_minus_h;
            undo.push_back([this, k = key(r->ring)] {
                ASSERT_TRUE(hmira::make_face_kill_ring(mesh, he(k)));
                ++s_minus_h;
            });
            return true;
        }
        return false;
    }
    bool step_make_face_kill_ring() {
        if constexpr (rings) {
            std::vector<H> ring_halfedges;
            for (auto f : T::faces(mesh))
                for (auto r : T::inner_rings(mesh, f)) ring_halfedges.push_back(r);
            if (ring_halfedges.empty()) {
                auto fs = all_faces();
                if (fs.empty()) return false;
                const auto before = take_snapshot<M, T>(mesh);
                expect_rejected_cleanly(before,
                                        hmira::make_face_kill_ring(mesh, T::face_halfedge(mesh, fs[pick(fs.size())])));
                return false;
            }
            const auto ring = ring_halfedges[pick(ring_halfedges.size())];
            const auto host = T::face(mesh, ring);
            auto r = hmira::make_face_kill_ring(mesh, loop(ring)[pick(loop(ring).size())]);
            EXPECT_TRUE(r);
            ++s_minus_h;
            undo.push_back([this, fk = key(T::face_halfedge(mesh, r->face)), hk = key(T::face_halfedge(mesh, host))] {
                ASSERT_TRUE(hmira::kill_face_make_ring(mesh, T::face(mesh, he(fk)), T::face(mesh, he(hk))));
                --s_minus_h;
            });
            return true;
        }
        return false;
    }
    bool step_make_edge_kill_ring() {
        if constexpr (rings) {
            std::vector<F> with_rings;
            for (auto f : T::faces(mesh))
                if (hmira::detail::euler::has_rings<M, T>(mesh, f)) with_rings.push_back(f);
            if (with_rings.empty()) return false;
            const auto f = with_rings[pick(with_rings.size())];
            std::vector<H> starts{T::face_halfedge(mesh, f)};
            for (auto r : T::inner_rings(mesh, f)) starts.push_back(r);
            const std::size_t a = pick(starts.size()), b = 1 + pick(starts.size() - 1);
            if (a == b) return false;
            const auto la = loop(starts[a]), lb = loop(starts[b]);
            const auto h0 = la[pick(la.size())], h1 = lb[pick(lb.size())];
            const auto s = T::target(mesh, h0), t = T::target(mesh, h1);
            if (s == t || adjacent(s, t)) return false;
            auto r = hmira::make_edge_kill_ring(mesh, h0, h1);
            EXPECT_TRUE(r) << r.error().message;
            if (!r) return false;
            undo.push_back([this, k = key(r->halfedge)] {
                auto kill = hmira::kill_edge_make_ring(mesh, he(k));
                ASSERT_TRUE(kill) << kill.error().message;
            });
            return true;
        }
        return false;
    }
    bool step_kill_edge_make_ring() {
        if constexpr (rings) {
            auto hs = all_halfedges();
            if (hs.empty()) return false;
            const auto h = hs[pick(hs.size())];
            const auto before = take_snapshot<M, T>(mesh);
            const auto f = T::face(mesh, h);
            if (f == T::null_face() || T::face(mesh, T::opposite(mesh, h)) != f) {
                expect_rejected_cleanly(before, hmira::kill_edge_make_ring(mesh, h));
                return false;
            }
            // The part after h becomes a ring: where the loop is the outer one, its vertices
            // must stay judgeable (see the note at the top).
            if (!on_ring(h)) {
                std::vector<V> part;
                for (auto x = T::next(mesh, h); x != T::opposite(mesh, h) && part.size() < 100000; x = T::next(mesh, x))
                    part.push_back(T::target(mesh, x));
                std::vector<V> rest;
                for (auto x = T::next(mesh, T::opposite(mesh, h)); x != h && rest.size() < 100000; x = T::next(mesh, x))
                    rest.push_back(T::target(mesh, x));
                for (auto v : part) {
                    if (!clean(v) && v != T::target(mesh, h)) return false;
                    if (std::count(part.begin(), part.end(), v) > 1 || std::count(rest.begin(), rest.end(), v) > 0)
                        return false;
                }
            }
            auto r = hmira::kill_edge_make_ring(mesh, h);
            if (!r) {
                expect_rejected_cleanly(before, r);
                return false;
            }
            undo.push_back([this, h0 = key(r->h0), h1 = key(r->h1)] {
                auto m = hmira::make_edge_kill_ring(mesh, he(h0), he(h1));
                ASSERT_TRUE(m) << m.error().message;
            });
            return true;
        }
        return false;
    }

    ::testing::AssertionResult check() {
        auto valid = is_valid_relaxed<M>(mesh);
        if (!valid) return valid;
        return euler_poincare_holds<M>(mesh, s_minus_h);
    }

    void run(std::size_t steps) {
        using step_fn = bool (random_session::*)();
        // Weights keep the mesh from growing without bound: each maker has its killer.
        const std::vector<std::pair<step_fn, int>> table = {
            {&random_session::step_make_vertex, 1},         {&random_session::step_kill_vertex, 2},
            {&random_session::step_make_edge_vertex, 4},    {&random_session::step_kill_edge_vertex, 6},
            {&random_session::step_make_edge_face, 4},      {&random_session::step_kill_edge_face, 5},
            {&random_session::step_fill_boundary_loop, 1},  {&random_session::step_open_face, 1},
            {&random_session::step_kill_face_make_ring, 1}, {&random_session::step_make_face_kill_ring, 1},
            {&random_session::step_make_edge_kill_ring, 2}, {&random_session::step_kill_edge_make_ring, 3},
        };
        int total = 0;
        for (const auto& [fn, w] : table) total += w;
        for (std::size_t i = 0; i < steps; ++i) {
            int r = static_cast<int>(pick(static_cast<std::size_t>(total)));
            std::size_t which = 0;
            while (r >= table[which].second) r -= table[which++].second;
            const std::size_t before = undo.size();
            const bool did = (this->*table[which].first)();
            if (::testing::Test::HasFatalFailure() || ::testing::Test::HasNonfatalFailure()) {
                ADD_FAILURE() << "step " << i << " (operator kind " << which << ") went wrong";
                return;
            }
            if (did) {
                ++applied;
                ++applied_by_kind[which];
                ASSERT_EQ(undo.size(), before + 1);
                auto ok = check();
                ASSERT_TRUE(ok) << "after step " << i << " (operator kind " << which << ")";
            }
        }
    }
    void unwind() {
        std::size_t i = 0;
        while (!undo.empty()) {
            undo.back()();
            undo.pop_back();
            ASSERT_FALSE(::testing::Test::HasFailure()) << "inverse " << i << " failed";
            auto ok = check();
            ASSERT_TRUE(ok) << "after inverse " << i;
            ++i;
        }
    }
};

template <class M>
class euler_random_sequences : public ::testing::Test {};
TYPED_TEST_SUITE(euler_random_sequences, all_models);

/// Runs `steps` random operators from a start mesh, then undoes them all.
template <class M>
void run_and_unwind(const face_list& shape, long long s_minus_h, std::uint64_t seed, std::size_t steps) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const M start = mesh_from<M>(shape);
    random_session<M> session(start, seed, s_minus_h);
    ASSERT_TRUE(session.check()) << "the start mesh";
    session.run(steps);
    if (::testing::Test::HasFailure()) return;
    EXPECT_GT(session.applied, steps / 3) << "too few steps applied to be a meaningful test";
    // Every operator kind the model supports must have run (ring kinds are 8 to 11).
    for (std::size_t k = 0; k < session.applied_by_kind.size(); ++k) {
        if (k < 8 || random_session<M>::rings) {
            EXPECT_GT(session.applied_by_kind[k], 0u) << "operator kind " << k << " never ran";
        }
    }
    std::string stats;
    for (auto n : session.applied_by_kind) stats += std::to_string(n) + " ";
    ::testing::Test::RecordProperty("applied_by_kind", stats);
    ::testing::Test::RecordProperty("rejected", static_cast<int>(session.rejected));
    session.unwind();
    if (::testing::Test::HasFailure()) return;
    EXPECT_EQ(session.s_minus_h, s_minus_h);
    M a = start;
    compact(a);
    compact(session.mesh);
    using T = hmira::default_traits<M>;
    EXPECT_EQ(T::vertex_count(session.mesh), T::vertex_count(a));
    EXPECT_EQ(T::edge_count(session.mesh), T::edge_count(a));
    EXPECT_EQ(T::face_count(session.mesh), T::face_count(a));
    EXPECT_TRUE(canonical<M>(session.mesh) == canonical<M>(a)) << "the inverses did not restore the start mesh";
}

#ifdef HMIRA_SANITIZER_BUILD
constexpr std::size_t steps = 800;
#else
constexpr std::size_t steps = 2500;
#endif

TYPED_TEST(euler_random_sequences, random_operators_then_inverses_in_reverse_restore_a_grid_with_a_hole) {
    if constexpr (!hmira::euler_mutable_mesh<TypeParam> || !indexed_halfedge_model<TypeParam>) {
        GTEST_SKIP() << "not an euler_mutable_mesh (no raw halfedge layer, or triangles only)";
    } else {
        // A 5 x 4 grid without the face at (2, 1): two boundary loops, S - H = 1.
        const auto shape = without_faces(grid(5, 4), [](std::size_t f) { return f == 7; });
        for (std::uint64_t seed : {11u, 12u}) run_and_unwind<TypeParam>(shape, 1, seed, steps);
    }
}

TYPED_TEST(euler_random_sequences, random_operators_then_inverses_in_reverse_restore_a_torus) {
    if constexpr (!hmira::euler_mutable_mesh<TypeParam> || !indexed_halfedge_model<TypeParam>) {
        GTEST_SKIP() << "not an euler_mutable_mesh (no raw halfedge layer, or triangles only)";
    } else {
        for (std::uint64_t seed : {21u, 22u}) run_and_unwind<TypeParam>(torus(6, 5), 0, seed, steps);
    }
}

}  // namespace
