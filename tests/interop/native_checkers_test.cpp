// After seeded random sequences of edits on OpenMesh and CGAL meshes, the libraries' own
// checkers must agree with hmira's validate(): CGAL::is_valid_polygon_mesh and OpenMesh's
// MeshCheckerT look at the structure hmira's traits wrote, through code hmira did not write.
// Polygon models take truncate, bevel, extrude and the Euler operators; OpenMesh's TriMesh
// takes the primitives it can honour (removing faces and vertices, re-adding faces). Every
// step is checked; a step that fails must leave the mesh unchanged.

#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <hmira/algorithms/editing/editing.hpp>
#include <hmira/algorithms/euler/euler.hpp>
#include <hmira/algorithms/primitives/primitives.hpp>

#include "algorithms/euler/euler_support.hpp"
#include "support/models.hpp"

#ifdef HMIRA_TEST_WITH_OPENMESH
#include <OpenMesh/Tools/Utils/MeshCheckerT.hh>
#endif
#ifdef HMIRA_TEST_WITH_CGAL
#include <CGAL/boost/graph/helpers.h>
#endif

namespace {

using namespace hmira_test;

/// What the mesh's own library says about it.
template <class M>
::testing::AssertionResult native_check(const M& m) {
#ifdef HMIRA_TEST_WITH_CGAL
    if constexpr (std::is_same_v<M, cgal_surface_mesh>) {
        if (CGAL::is_valid_polygon_mesh(m)) return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure() << "CGAL::is_valid_polygon_mesh rejects the mesh";
    }
#endif
#ifdef HMIRA_TEST_WITH_OPENMESH
    if constexpr (std::is_same_v<M, openmesh_poly> || std::is_same_v<M, openmesh_tri>) {
        std::ostringstream why;
        if (OpenMesh::Utils::MeshCheckerT<M>(m).check(OpenMesh::Utils::MeshCheckerT<M>::CHECK_ALL, why))
            return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure() << "OpenMesh MeshCheckerT: " << why.str();
    }
#endif
    (void)m;
    return ::testing::AssertionFailure() << "no native checker for this model";
}

// The native checkers look at connectivity, so validate() is asked about connectivity too
// (geometry, such as zero-area faces, is the editing suites' business).
template <class M>
::testing::AssertionResult both_agree_valid(const M& m) {
    const auto problems = hmira::validate(m, {.check_geometry = false});
    if (!problems.empty()) return ::testing::AssertionFailure() << "hmira::validate: " << describe(problems);
    return native_check(m);
}

template <class M>
struct edit_session {
    using T = hmira::default_traits<M>;
    using V = typename T::vertex_handle;
    using F = typename T::face_handle;
    using H = typename T::halfedge_handle;
    M mesh;
    std::mt19937_64 rng;
    std::size_t applied = 0, refused = 0;

    template <class R>
    auto pick(const R& range) {
        std::vector<std::ranges::range_value_t<R>> all(std::ranges::begin(range), std::ranges::end(range));
        return all[std::uniform_int_distribution<std::size_t>(0, all.size() - 1)(rng)];
    }
    V any_vertex() { return pick(T::vertices(mesh)); }
    F any_face() { return pick(T::faces(mesh)); }
    typename T::edge_handle any_edge() { return pick(T::edges(mesh)); }

    std::size_t degree(F f) {
        std::size_t n = 0;
        for ([[maybe_unused]] auto v : T::face_vertices(mesh, f)) ++n;
        return n;
    }

    /// Runs one step; on failure, the mesh must be as it was.
    template <class Step>
    void run(const char* what, Step step) {
        const auto before = take_snapshot(mesh);
        if (step()) {
            ++applied;
        } else {
            ++refused;
            EXPECT_TRUE(take_snapshot(mesh) == before) << what << " failed and changed the mesh";
        }
        ASSERT_TRUE(both_agree_valid(mesh)) << "after " << what << " (step " << applied + refused << ")";
    }

    void polygon_step() {
        switch (std::uniform_int_distribution<int>(0, 5)(rng)) {
            case 0:
                run("truncate", [&] { return bool(hmira::truncate(mesh, any_vertex(), {.fraction = 0.25})); });
                break;
            case 1: run("bevel", [&] { return bool(hmira::bevel(mesh, any_edge(), {.width = 0.05})); }); break;
            case 2: run("extrude", [&] { return bool(hmira::extrude(mesh, any_face(), {.distance = 0.3})); }); break;
            case 3:
                run("make_edge_face", [&] {
                    const auto f = any_face();
                    if (degree(f) < 4) return false;
                    const auto h0 = T::face_halfedge(mesh, f);
                    return bool(hmira::make_edge_face(mesh, h0, T::next(mesh, T::next(mesh, h0))));
                });
                break;
            case 4:
                // Split a vertex between two of its corners that are not neighbours, then maybe join it back.
                run("split_vertex", [&] {
                    const auto v = any_vertex();
                    std::vector<H> in;
                    const auto start = T::vertex_halfedge(mesh, v);
                    auto h = start;
                    do {
                        in.push_back(T::opposite(mesh, h));
                        h = T::next(mesh, T::opposite(mesh, h));
                    } while (h != start);
                    if (in.size() < 4) return false;
                    const auto p = T::position(mesh, v);
                    const typename T::scalar d(0.01);
                    const hmira::vec3<typename T::scalar> q{p[0] + d, p[1] + d, p[2] + d};
                    auto r = hmira::split_vertex(mesh, in[0], in[2], q);
                    if (!r) return false;
                    if (std::bernoulli_distribution(0.5)(rng)) {
                        EXPECT_TRUE(both_agree_valid(mesh)) << "after split_vertex";
                        return bool(hmira::join_vertices(mesh, r->halfedge));
                    }
                    return true;
                });
                break;
            default: remove_and_restore_face(); break;
        }
    }

    void remove_and_restore_face() {
        run("remove_face, add_face", [&] {
            // A face with a boundary side would leave a wire edge behind, which no polygon-mesh
            // checker accepts; it is refused here (the removal suites cover it).
            const auto f = any_face();
            const auto first = T::face_halfedge(mesh, f);
            auto side = first;
            do {
                if (T::face(mesh, T::opposite(mesh, side)) == T::null_face()) return false;
                side = T::next(mesh, side);
            } while (side != first);
            std::vector<V> corners;
            for (auto v : T::face_vertices(mesh, f)) corners.push_back(v);
            auto r = hmira::remove_face(mesh, f, {.remove_wire_edges = false, .remove_isolated_vertices = false});
            if (!r) return false;
            EXPECT_TRUE(native_check(mesh)) << "after remove_face";
            auto again = hmira::add_face(mesh, std::span<const V>(corners));
            EXPECT_TRUE(again) << again.error().message;
            return bool(again);
        });
    }

    bool interior(V v) {
        const auto h = T::vertex_halfedge(mesh, v);
        return h != T::null_halfedge() && T::face(mesh, h) != T::null_face();
    }

    // Removals that make no pinch (a vertex with two boundary gaps, which validate() calls
    // non-manifold, as it is): a face whose corners are all interior, a vertex whose
    // neighbours are.
    void triangle_step() {
        switch (std::uniform_int_distribution<int>(0, 2)(rng)) {
            case 0: remove_and_restore_face(); break;
            case 1:
                run("remove_face", [&] {
                    const auto f = any_face();
                    for (auto v : T::face_vertices(mesh, f))
                        if (!interior(v)) return false;
                    return bool(hmira::remove_face(mesh, f));
                });
                break;
            default:
                run("remove_vertex", [&] {
                    const auto v = any_vertex();
                    if (!interior(v)) return false;
                    const auto start = T::vertex_halfedge(mesh, v);
                    auto h = start;
                    do {
                        if (!interior(T::target(mesh, h))) return false;
                        h = T::next(mesh, T::opposite(mesh, h));
                    } while (h != start);
                    return bool(hmira::remove_vertex(mesh, v));
                });
        }
    }
};

template <class M>
class native_checkers : public ::testing::Test {};

using checked_models = ::testing::Types<
#ifdef HMIRA_TEST_WITH_OPENMESH
    openmesh_poly, openmesh_tri
#endif
#if defined(HMIRA_TEST_WITH_OPENMESH) && defined(HMIRA_TEST_WITH_CGAL)
    ,
#endif
#ifdef HMIRA_TEST_WITH_CGAL
    cgal_surface_mesh
#endif
    >;
TYPED_TEST_SUITE(native_checkers, checked_models);

TYPED_TEST(native_checkers, agree_with_validate_after_random_edit_sequences) {
    using T = hmira::default_traits<TypeParam>;
    constexpr bool polygons = hmira::euler_mutable_mesh<TypeParam> && hmira::extrudable_mesh<TypeParam>;
    for (std::uint64_t seed : {1u, 2u, 3u}) {
        edit_session<TypeParam> s{polygons ? mesh_from<TypeParam>(seed == 2 ? grid(5, 4) : torus(6, 8))
                                           : mesh_from<TypeParam>(grid(12, 12, true)),
                                  std::mt19937_64(seed)};
        ASSERT_TRUE(both_agree_valid(s.mesh));
        for (int step = 0; step < 60 && !::testing::Test::HasFatalFailure(); ++step) {
            if constexpr (polygons)
                s.polygon_step();
            else
                s.triangle_step();
        }
        EXPECT_GT(s.applied, 20u) << "seed " << seed << ": too few steps applied to mean anything";
        std::printf("seed %llu: %zu steps applied, %zu refused; V %zu, F %zu\n", static_cast<unsigned long long>(seed),
                    s.applied, s.refused, static_cast<std::size_t>(T::vertex_count(s.mesh)),
                    static_cast<std::size_t>(T::face_count(s.mesh)));
        // And once more with the deleted elements gone.
        compact(s.mesh);
        EXPECT_TRUE(both_agree_valid(s.mesh)) << "after garbage collection, seed " << seed;
        EXPECT_GT(T::face_count(s.mesh), 0u);
    }
}

TYPED_TEST(native_checkers, agree_that_a_broken_face_loop_is_broken) {
    // The checkers are not vacuous: a face loop with one halfedge claiming no face is caught
    // by both.
    using T = hmira::default_traits<TypeParam>;
    auto m = mesh_from<TypeParam>(grid(3, 3, true));
    ASSERT_TRUE(both_agree_valid(m));
    auto faces = T::faces(m);
    const auto h = T::face_halfedge(m, *faces.begin());
    T::set_face(m, T::next(m, h), T::null_face());
    EXPECT_FALSE(hmira::validate(m, {.check_geometry = false}).empty());
    EXPECT_FALSE(native_check(m));
}

}  // namespace
