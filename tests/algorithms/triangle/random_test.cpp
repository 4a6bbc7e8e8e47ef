// Seeded random sequences of flips, splits and collapses on closed and holed triangle meshes,
// on every model that supports the operators. After each step: validate() and the model's own
// checker (CGAL is_valid_polygon_mesh, OpenMesh MeshCheckerT), V - E + F unchanged; refused
// steps change nothing; some steps are undone at once by their inverse, which must restore the
// mesh. On CGAL, is_collapse_ok is compared with CGAL::Euler::does_satisfy_link_condition.

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "algorithms/triangle/triangle_support.hpp"

#ifdef HMIRA_TEST_WITH_CGAL
#include <CGAL/boost/graph/Euler_operations.h>
#endif

namespace {

using namespace hmira_test;

template <class M>
class triangle_random : public ::testing::Test {};
TYPED_TEST_SUITE(triangle_random, all_models);

/// An 8 x 6 torus cut into triangles; with `holes`, four separated quads removed.
inline face_list test_surface(bool holes) {
    const std::size_t n = 8, m = 6;
    face_list t = triangulated(torus(n, m));
    if (!holes) return t;
    return without_faces(t, [&](std::size_t f) {
        const std::size_t q = f / 2, i = q / m, j = q % m;
        return i % 4 == 0 && j % 3 == 0;
    });
}

template <class M>
struct session {
    using T = hmira::default_traits<M>;
    using H = typename T::halfedge_handle;
    M mesh;
    std::mt19937_64 rng;
    long long chi0;
    std::size_t v0;
    std::size_t done[4] = {0, 0, 0, 0}, refused[4] = {0, 0, 0, 0}, undone = 0;
    std::size_t link_compared = 0, link_true = 0, link_false = 0;

    session(M m, std::uint64_t seed) : mesh(std::move(m)), rng(seed), chi0(chi(mesh)), v0(T::vertex_count(mesh)) {}

    std::size_t pick(std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); }
    H random_halfedge() {
        std::vector<H> hs;
        for (auto h : T::halfedges(mesh)) hs.push_back(h);
        return hs[pick(hs.size())];
    }
    typename T::face_handle random_face() {
        std::vector<typename T::face_handle> fs;
        for (auto f : T::faces(mesh)) fs.push_back(f);
        return fs[pick(fs.size())];
    }
    hmira::vec3<double> position(typename T::vertex_handle v) {
        const auto p = T::position(mesh, v);
        return {double(p[0]), double(p[1]), double(p[2])};
    }
    /// A random point of h's edge away from its ends: positions stay distinct, so the
    /// canonical forms (vertices named by position) stay unambiguous.
    hmira::vec3<double> along(H h) {
        const double t = std::uniform_real_distribution<double>(0.3, 0.7)(rng);
        return hmira::lerp(position(T::target(mesh, T::opposite(mesh, h))), position(T::target(mesh, h)), t);
    }
    canonical_form canon() {
        M copy = mesh;
        compact(copy);
        return canonical(copy);
    }
    void check(const char* what) {
        ASSERT_TRUE(valid_topology(mesh)) << "after " << what;
        ASSERT_EQ(chi(mesh), chi0) << "after " << what;
    }
    template <class R>
    void expect_refused(const snapshot& before, const R& r, const char* what) {
        ASSERT_FALSE(r) << what << " accepted what its check refused";
        ASSERT_EQ(take_snapshot(mesh), before) << "a refused " << what << " changed the mesh";
    }
    bool undo_now() { return pick(4) == 0; }

    void compare_link_condition() {
#ifdef HMIRA_TEST_WITH_CGAL
        if constexpr (std::is_same_v<M, cgal_surface_mesh>) {
            for (int i = 0; i < 4; ++i) {
                const auto h = random_halfedge();
                const bool ours = hmira::is_collapse_ok(mesh, h);
                const bool cgal = CGAL::Euler::does_satisfy_link_condition(mesh.edge(h), mesh);
                ASSERT_EQ(ours, cgal) << "halfedge " << h.idx();
                ++link_compared;
                ++(ours ? link_true : link_false);
            }
        }
#endif
    }

    void step() {
        compare_link_condition();
        const std::size_t v = T::vertex_count(mesh);
        std::size_t kind = pick(4);
        if (v > 2 * v0 && kind != 0) kind = 3;  // keep the mesh from growing without bound
        if (v < v0 / 2 && kind == 3) kind = 1;  // ... or from shrinking to nothing
        const auto before = take_snapshot(mesh);
        if (kind == 0) {
            const auto h = random_halfedge();
            if (!hmira::is_flip_ok(mesh, h)) {
                expect_refused(before, hmira::flip_edge(mesh, h), "flip");
                ++refused[0];
                return;
            }
            const auto start = undo_now() ? canon() : canonical_form{};
            auto r = hmira::flip_edge(mesh, h);
            ASSERT_TRUE(r) << r.error().message;
            check("flip");
            ++done[0];
            if (!start.faces.empty()) {
                ASSERT_TRUE(hmira::flip_edge(mesh, r->halfedge));
                check("flip back");
                ASSERT_TRUE(canon() == start) << "flipping twice changed the mesh";
                ++undone;
            }
        } else if (kind == 1 || kind == 2) {
            const auto start = undo_now() ? canon() : canonical_form{};
            typename T::halfedge_handle back;
            if (kind == 1) {
                const auto h = random_halfedge();
                auto r = hmira::split_edge(mesh, h, {.position = along(h)});
                ASSERT_TRUE(r) << r.error().message;
                back = r->halfedge;
            } else {
                const auto f = random_face();
                const auto h = T::face_halfedge(mesh, f);
                auto r = hmira::split_face(
                    mesh, f, {.position = (along(h) + position(T::target(mesh, T::next(mesh, h)))) * 0.5});
                ASSERT_TRUE(r) << r.error().message;
                back = r->halfedge;
            }
            check(kind == 1 ? "split_edge" : "split_face");
            ++done[kind];
            if (!start.faces.empty()) {
                auto r = hmira::collapse_edge(mesh, back, {.placement = hmira::collapse_placement::target});
                ASSERT_TRUE(r) << r.error().message;
                check("collapse of the split");
                ASSERT_TRUE(canon() == start) << "a split and the collapse of its new edge changed the mesh";
                ++undone;
            }
        } else {
            const auto h = random_halfedge();
            if (!hmira::is_collapse_ok(mesh, h)) {
                expect_refused(before, hmira::collapse_edge(mesh, h), "collapse");
                ++refused[3];
                return;
            }
            // Default placement (the midpoint) half of the time, elsewhere on the edge otherwise.
            auto r = pick(2) ? hmira::collapse_edge(mesh, h)
                             : hmira::collapse_edge(
                                   mesh, h, {.placement = hmira::collapse_placement::given, .position = along(h)});
            ASSERT_TRUE(r) << r.error().message;
            check("collapse");
            ++done[3];
        }
    }
};

TYPED_TEST(triangle_random, random_flips_splits_and_collapses_keep_the_mesh_valid) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
#ifdef HMIRA_SANITIZER_BUILD
        const std::vector<std::uint64_t> seeds{1};  // instrumented, each run of 600 steps costs seconds
#else
        const std::vector<std::uint64_t> seeds{1, 2};
#endif
        for (bool holes : {false, true}) {
            for (std::uint64_t seed : seeds) {
                session<M> s(mesh_from<M>(test_surface(holes)), seed * 7919 + holes);
                ASSERT_TRUE(valid_topology(s.mesh));
                for (int i = 0; i < 600; ++i) {
                    s.step();
                    if (::testing::Test::HasFatalFailure()) {
                        ADD_FAILURE() << "step " << i << ", seed " << seed << (holes ? ", holed" : ", closed");
                        return;
                    }
                }
                // Each kind of step ran and was refused some of the time.
                EXPECT_GT(s.done[0], 20u);
                EXPECT_GT(s.done[1], 20u);
                EXPECT_GT(s.done[2], 20u);
                EXPECT_GT(s.done[3], 20u);
                EXPECT_GT(s.refused[0] + s.refused[3], 0u);
                EXPECT_GT(s.undone, 20u);
                if (s.link_compared > 0) {
                    EXPECT_GT(s.link_true, 100u);
                    EXPECT_GT(s.link_false, 10u);
                }
            }
        }
    }
}

}  // namespace
