// hmira on CGAL::Surface_mesh objects, in place, for both kernels: what hmira algorithms do is
// visible through CGAL's own API (and CGAL's validity check), hmira's answers equal CGAL's
// circulators, and failures are errors, not null faces.
#include <gtest/gtest.h>

#include <algorithm>
#include <ranges>
#include <set>
#include <string>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/iterator.h>

#include <hmira/adapters/adapted_mesh.hpp>
#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/orientation/flip_normals.hpp>
#include <hmira/algorithms/topology/mesh_topology.hpp>
#include <hmira/algorithms/validation/validate.hpp>
#include <hmira/interop/cgal.hpp>

#include "support/checks.hpp"
#include "support/shapes.hpp"

namespace {

using sc_mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;
using epick_mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;

template <class M>
class cgal_interop : public ::testing::Test {};
using kernels = ::testing::Types<sc_mesh, epick_mesh>;
TYPED_TEST_SUITE(cgal_interop, kernels);

template <class M>
M native_grid(int nx, int ny) {
    M m;
    using P = typename M::Point;
    std::vector<typename M::Vertex_index> v;
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) v.push_back(m.add_vertex(P(i, j, 0)));
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const int a = j * (nx + 1) + i;
            m.add_face(v[a], v[a + 1], v[a + nx + 2], v[a + nx + 1]);
        }
    return m;
}

TYPED_TEST(cgal_interop, the_traits_model_the_halfedge_capabilities) {
    using M = TypeParam;
    static_assert(hmira::halfedge_mutable_mesh<M> && hmira::halfedge_index_mesh<M>);
    static_assert(hmira::polygon_mesh_builder<M> && hmira::position_mutable_mesh<M>);
    static_assert(!hmira::change_counted_mesh<M>, "Surface_mesh keeps no change counter");
    static_assert(std::is_same_v<typename hmira::mesh_traits<M>::scalar, double>);
}

TYPED_TEST(cgal_interop, flip_normals_runs_in_place_and_cgal_sees_a_valid_reversed_mesh) {
    using M = TypeParam;
    M m = native_grid<M>(4, 3);
    std::vector<std::vector<std::size_t>> before;
    for (auto f : m.faces()) {
        std::vector<std::size_t> loop;
        for (auto v : CGAL::vertices_around_face(m.halfedge(f), m)) loop.push_back(v.idx());
        before.push_back(loop);
    }
    EXPECT_EQ(hmira::flip_normals(m), 12u);
    ASSERT_TRUE(hmira_test::is_valid(m));
    EXPECT_TRUE(m.is_valid(false)) << "CGAL's own validity check, border convention included";
    for (auto f : m.faces()) {
        std::vector<std::size_t> loop;
        for (auto v : CGAL::vertices_around_face(m.halfedge(f), m)) loop.push_back(v.idx());
        auto expected = before[f.idx()];
        std::reverse(expected.begin(), expected.end());
        auto it = std::find(loop.begin(), loop.end(), expected[0]);
        ASSERT_NE(it, loop.end());
        std::rotate(loop.begin(), it, loop.end());
        EXPECT_EQ(loop, expected);
    }
    for (auto v : m.vertices())
        EXPECT_EQ(m.is_border(v, false), m.is_border(v, true)) << "border vertices keep a border halfedge";
}

TYPED_TEST(cgal_interop, hmira_adjacency_equals_cgal_circulators_as_multisets) {
    using M = TypeParam;
    using T = hmira::mesh_traits<M>;
    M m = native_grid<M>(5, 4);
    m.add_vertex(typename M::Point(9, 9, 9));  // isolated
    for (auto v : m.vertices()) {
        std::multiset<std::size_t> mine, theirs;
        for (auto w : T::adjacent_vertices(m, v)) mine.insert(w.idx());
        for (auto w : CGAL::vertices_around_target(v, m)) theirs.insert(w.idx());
        EXPECT_EQ(mine, theirs);
        std::multiset<std::size_t> mf, tf;
        for (auto f : T::vertex_faces(m, v)) mf.insert(f.idx());
        for (auto f : CGAL::faces_around_target(m.halfedge(v), m))
            if (f != M::null_face()) tf.insert(f.idx());
        if (m.halfedge(v) != M::null_halfedge()) {
            EXPECT_EQ(mf, tf);
        }
    }
}

// hmira's rings on Surface_mesh step like CGAL's circulators, without a step guard, so a face
// loop whose next links never return to its start is endless: validate must stop and say so.
TYPED_TEST(cgal_interop, validate_reports_a_face_loop_that_never_closes_instead_of_following_it) {
    using M = TypeParam;
    M m = native_grid<M>(2, 2);
    const auto f = *m.faces().begin();
    const auto h1 = m.next(m.halfedge(f));
    m.set_next(h1, h1);  // the loop from f's halfedge now cycles at h1 for ever
    const auto problems = hmira::validate(m);
    const bool named = std::any_of(problems.begin(), problems.end(), [&](const hmira::mesh_problem& p) {
        return p.kind == hmira::problem_kind::broken_link &&
               p.message.find("face " + std::to_string(f.idx()) + ": its loop does not return") == 0;
    });
    EXPECT_TRUE(named) << "problems found: " << problems.size();
}

TYPED_TEST(cgal_interop, rings_of_an_isolated_vertex_are_empty_and_rings_close_after_one_lap) {
    using M = TypeParam;
    using T = hmira::mesh_traits<M>;
    M m = native_grid<M>(1, 1);
    const auto lone = m.add_vertex(typename M::Point(5, 5, 5));
    EXPECT_TRUE(std::ranges::empty(T::adjacent_vertices(m, lone)));
    EXPECT_EQ(std::ranges::distance(T::vertex_edges(m, lone)), 0);
    // Corner 0 of the single quad: two neighbours, each once; the face: four corners.
    const auto corner = *m.vertices().begin();
    std::vector<typename M::Vertex_index> ring;
    for (auto w : T::adjacent_vertices(m, corner)) ring.push_back(w);
    ASSERT_EQ(ring.size(), 2u);
    EXPECT_NE(ring[0], ring[1]);
    EXPECT_EQ(std::ranges::distance(T::face_vertices(m, *m.faces().begin())), 4);
}

TYPED_TEST(cgal_interop, a_refused_face_is_an_error_and_leaves_the_mesh_unchanged) {
    using M = TypeParam;
    using T = hmira::mesh_traits<M>;
    M m;
    ASSERT_TRUE(hmira::generate_tetrahedron(m));
    std::vector<typename M::Vertex_index> vs(m.vertices().begin(), m.vertices().end());
    const std::array<typename M::Vertex_index, 3> again{vs[0], vs[1], vs[2]};
    ASSERT_FALSE(T::add_face(m, again));
    EXPECT_EQ(m.number_of_faces(), 4u);
    const std::array<typename M::Vertex_index, 3> repeated{vs[0], vs[0], vs[2]};
    EXPECT_EQ(T::add_face(m, repeated).error().code, hmira::errc::degenerate_face);
    EXPECT_TRUE(hmira_test::is_valid(m));
    EXPECT_TRUE(m.is_valid(false));
}

TYPED_TEST(cgal_interop, erasing_marks_cgal_removed_and_hides_the_element) {
    using M = TypeParam;
    using T = hmira::mesh_traits<M>;
    M m = native_grid<M>(2, 2);
    const typename M::Face_index f(0);
    T::erase_face(m, f);
    EXPECT_TRUE(m.is_removed(f));
    EXPECT_EQ(T::face_count(m), 3u);
    for (auto g : T::faces(m)) EXPECT_NE(g, f);
}

// The traits as they are without their one-pass reverse_orientation: flip_normals's generic
// pass through the raw mutators, the reference for the one-pass flip.
template <class M>
struct traits_without_reverse_orientation : hmira::mesh_traits<M> {
    static void reverse_orientation(M&) = delete;
};

// Every link of every live element, for comparing two meshes exactly.
template <class M>
std::vector<std::size_t> links(const M& m) {
    std::vector<std::size_t> out;
    for (auto h : m.halfedges()) {
        out.push_back(h.idx());
        out.push_back(m.next(h).idx());
        out.push_back(m.prev(h).idx());
        out.push_back(m.target(h).idx());
        out.push_back(m.face(h).idx());
    }
    for (auto v : m.vertices()) out.push_back(m.halfedge(v).idx());
    for (auto f : m.faces()) out.push_back(m.halfedge(f).idx());
    return out;
}

TYPED_TEST(cgal_interop, the_one_pass_flip_links_as_the_generic_pass_does_and_skips_removed_elements) {
    using M = TypeParam;
    M m = native_grid<M>(4, 3);
    // A corner face and an inner face removed the CGAL way: removed edges and a removed vertex
    // (their links are CGAL's free lists), a border through the middle, garbage not collected.
    CGAL::Euler::remove_face(m.halfedge(typename M::Face_index(0)), m);
    CGAL::Euler::remove_face(m.halfedge(typename M::Face_index(6)), m);
    // remove_face leaves a vertex it put on the border storing an interior halfedge; restore
    // Surface_mesh's border convention, which both flips keep.
    m.set_vertex_halfedge_to_border_halfedge();
    ASSERT_TRUE(m.has_garbage());
    ASSERT_TRUE(m.is_valid(false));
    ASSERT_TRUE(hmira_test::is_valid(m));
    const M original = m;
    M generic = m;
    EXPECT_EQ(hmira::flip_normals(m), 10u);
    EXPECT_EQ((hmira::flip_normals<M, traits_without_reverse_orientation<M>>(generic)), 10u);
    EXPECT_TRUE(m.is_valid(false)) << "CGAL's own validity check, border convention included";
    EXPECT_TRUE(hmira_test::is_valid(m));
    EXPECT_EQ(links(m), links(generic));
    EXPECT_NE(links(m), links(original));
    // Flipping twice gives back the very same links, free lists included (collecting the
    // garbage afterwards still works).
    EXPECT_EQ(hmira::flip_normals(m), 10u);
    EXPECT_EQ(links(m), links(original));
    m.collect_garbage();
    EXPECT_TRUE(m.is_valid(false));
    EXPECT_EQ(m.number_of_faces(), 10u);
}

TYPED_TEST(cgal_interop, generated_solids_are_closed_and_valid_for_cgal_too) {
    using M = TypeParam;
    M m;
    ASSERT_TRUE(hmira::generate_cube(m));
    ASSERT_TRUE(hmira::generate_dodecahedron(m));
    EXPECT_TRUE(m.is_valid(false));
    EXPECT_TRUE(hmira_test::is_valid(m));
    EXPECT_EQ(hmira::euler_characteristic(m), 4);
    EXPECT_GT(hmira_test::signed_volume(m), 0);
    hmira::flip_normals(m);
    EXPECT_TRUE(m.is_valid(false));
    EXPECT_LT(hmira_test::signed_volume(m), 0);
}

TYPED_TEST(cgal_interop, brute_force_adapters_work_on_a_surface_mesh) {
    using M = TypeParam;
    M m = native_grid<M>(3, 2);
    const auto a = hmira::adapt_brute_force(m);
    using A = hmira::default_traits<decltype(a)>;
    using T = hmira::mesh_traits<M>;
    for (auto v : m.vertices()) {
        std::multiset<std::size_t> mine, theirs;
        for (auto w : A::adjacent_vertices(a, v)) mine.insert(w.idx());
        for (auto w : T::adjacent_vertices(m, v)) theirs.insert(w.idx());
        EXPECT_EQ(mine, theirs);
    }
}

}  // namespace
