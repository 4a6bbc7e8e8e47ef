// fill_hole and fill_holes on every model that supports them: holes cut into a triangulated
// torus and into real meshes by deleting face patches are closed, V - E + F (so the genus) is
// that of the uncut mesh, the mesh and the model's own checker are happy, and a flat hole's
// patch has the hole's area. A refused fill changes nothing.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <set>
#include <vector>

#include <hmira/algorithms/holes/fill_hole.hpp>
#include <hmira/io/mesh_io.hpp>

#include "triangle/triangle_support.hpp"

namespace {

using namespace hmira_test;

template <class M>
class fill_hole_test : public ::testing::Test {};
TYPED_TEST_SUITE(fill_hole_test, all_models);

template <class M, class T = hmira::default_traits<M>>
std::vector<typename T::halfedge_handle> boundary_loops(const M& m) {
    std::vector<typename T::halfedge_handle> out;
    std::set<std::size_t> seen;
    for (auto h : T::halfedges(m)) {
        if (T::face(m, h) != T::null_face() || seen.count(T::halfedge_index(m, h))) continue;
        auto x = h;
        do {
            seen.insert(T::halfedge_index(m, x));
            x = T::next(m, x);
        } while (x != h);
        out.push_back(h);
    }
    return out;
}

/// The face list without points that no face uses (cut-out vertices would be isolated).
face_list used_points_only(const face_list& g) {
    std::vector<std::size_t> map(g.points.size(), g.points.size());
    face_list out;
    for (const auto& f : g.faces) {
        std::vector<std::size_t> face;
        for (auto v : f) {
            if (map[v] == g.points.size()) {
                map[v] = out.points.size();
                out.points.push_back(g.points[v]);
            }
            face.push_back(map[v]);
        }
        out.faces.push_back(face);
    }
    return out;
}

/// Removes the faces within `rings` face rings of each seed vertex (a disc each, if the seeds
/// lie far apart), from a face list: the test's own hole cutter.
face_list cut_holes(const face_list& g, const std::vector<std::size_t>& seeds, int rings) {
    std::vector<std::vector<std::size_t>> faces_of(g.points.size());
    for (std::size_t f = 0; f < g.faces.size(); ++f)
        for (auto v : g.faces[f]) faces_of[v].push_back(f);
    std::vector<char> drop(g.faces.size(), 0);
    for (auto s : seeds) {
        std::set<std::size_t> verts{s};
        for (int r = 0; r < rings; ++r) {
            std::set<std::size_t> next = verts;
            for (auto v : verts)
                for (auto f : faces_of[v]) {
                    drop[f] = 1;
                    for (auto w : g.faces[f]) next.insert(w);
                }
            verts = next;
        }
    }
    return used_points_only(without_faces(g, [&](std::size_t f) { return drop[f] != 0; }));
}

TYPED_TEST(fill_hole_test, holes_in_a_torus_are_closed_and_the_genus_kept) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        const face_list full = triangulated(torus(24, 16));
        // Three far-apart discs of two face rings each.
        M m = mesh_from<M>(cut_holes(full, {0, 8 * 16 + 5, 16 * 16 + 11}, 2));
        ASSERT_TRUE(valid_topology(m));
        const auto loops = boundary_loops(m);
        ASSERT_EQ(loops.size(), 3u);
        const auto f0 = T::face_count(m);
        auto r = hmira::fill_holes(m, 1000);
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_EQ(r->filled, 3u);
        EXPECT_EQ(r->skipped, 0u);
        EXPECT_TRUE(valid_topology(m));
        EXPECT_TRUE(boundary_loops(m).empty());
        EXPECT_EQ(chi(m), 0);  // a closed torus again
        EXPECT_EQ(T::face_count(m), f0 + r->faces_added);
    }
}

TYPED_TEST(fill_hole_test, a_flat_hole_gets_a_flat_patch_of_the_holes_area_by_either_method) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        for (std::size_t dp_limit : {200u, 0u}) {
            // A 6 x 6 triangulated grid without its middle 2 x 2 squares: a square hole of area 4.
            M m = mesh_from<M>(used_points_only(without_faces(grid(6, 6, true), [](std::size_t f) {
                const std::size_t q = f / 2, i = q % 6, j = q / 6;
                return (i == 2 || i == 3) && (j == 2 || j == 3);
            })));
            auto loops = boundary_loops(m);
            ASSERT_EQ(loops.size(), 2u);
            // The inner loop is the one of 8 edges.
            auto hole = loops[0];
            std::size_t len = 0;
            for (auto x = hole;; ) { ++len; x = T::next(m, x); if (x == hole) break; }
            if (len != 8) hole = loops[1];
            auto r = hmira::fill_hole(m, hole, {.max_dynamic_programming_edges = dp_limit});
            ASSERT_TRUE(r) << r.error().message;
            EXPECT_EQ(r->faces.size(), 6u);
            double area = 0;
            for (auto f : r->faces) {
                std::vector<hmira::vec3<double>> p;
                for (auto v : T::face_vertices(m, f)) {
                    const auto q = T::position(m, v);
                    p.push_back({double(q[0]), double(q[1]), double(q[2])});
                }
                ASSERT_EQ(p.size(), 3u);
                const auto n = hmira::cross(p[1] - p[0], p[2] - p[0]);
                EXPECT_GT(n.z, 0) << "a patch triangle is wound against the grid";
                EXPECT_EQ(n.x, 0);
                EXPECT_EQ(n.y, 0);
                area += n.z / 2;
            }
            EXPECT_NEAR(area, 4.0, 1e-6);
            EXPECT_TRUE(valid_topology(m));
            EXPECT_EQ(boundary_loops(m).size(), 1u);
        }
    }
}

TYPED_TEST(fill_hole_test, a_halfedge_with_a_face_is_refused_and_nothing_changes) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        M m = mesh_from<M>(grid(3, 3, true));
        typename T::halfedge_handle inner{};
        for (auto h : T::halfedges(m))
            if (T::face(m, h) != T::null_face()) inner = h;
        const auto before = take_snapshot(m);
        auto r = hmira::fill_hole(m, inner);
        ASSERT_FALSE(r);
        EXPECT_EQ(r.error().code, hmira::errc::topology);
        EXPECT_EQ(take_snapshot(m), before);
        auto s = hmira::fill_holes(m, 2);
        ASSERT_FALSE(s);
        EXPECT_EQ(s.error().code, hmira::errc::invalid_argument);
    }
}

/// A real mesh from the test data, as a face list.
face_list load(const std::string& name) {
    const char* dir = std::getenv("HMIRA_TEST_DATA");
    face_list g;
    if (!dir) return g;
    hmira::face_vertex_mesh m;
    if (!hmira::io::read_mesh(m, std::filesystem::path(dir) / "meshes" / name)) return g;
    for (auto v : m.vertices()) g.points.push_back(m.position(v));
    for (auto f : m.faces()) {
        std::vector<std::size_t> face;
        for (auto v : m.face_vertices(f)) face.push_back(v.index);
        g.faces.push_back(face);
    }
    return g;
}

template <class M>
void fill_real_mesh(const std::string& name) {
    using T = hmira::default_traits<M>;
    const face_list full = load(name);
    if (full.points.empty()) GTEST_SKIP() << name << " not found (HMIRA_TEST_DATA)";
    M whole = mesh_from<M>(full);
    const long long chi_full = chi(whole);
    const auto loops_full = boundary_loops(whole).size();
    std::mt19937_64 rng(42);
    std::vector<std::size_t> seeds;
    for (int i = 0; i < 6; ++i) seeds.push_back(std::uniform_int_distribution<std::size_t>(0, full.points.size() - 1)(rng));
    M m = mesh_from<M>(cut_holes(full, seeds, 3));
    ASSERT_TRUE(valid_topology(m)) << name;
    const auto loops_cut = boundary_loops(m).size();
    ASSERT_GT(loops_cut, loops_full) << name;
    auto r = hmira::fill_holes(m, 2000);
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_EQ(r->skipped, loops_full) << name;  // only holes the file had stay (none are longer)
    EXPECT_TRUE(valid_topology(m)) << name;
    EXPECT_EQ(boundary_loops(m).size(), loops_full) << name;
    EXPECT_EQ(chi(m), chi_full) << name << ": the genus changed";
    (void)T::face_count(m);
}

TYPED_TEST(fill_hole_test, holes_cut_into_real_meshes_are_closed_and_the_genus_kept) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        for (const char* name : {"fandisk.off", "bunny00.off", "armadillo.off"}) {
            fill_real_mesh<M>(name);
            if (::testing::Test::HasFatalFailure() || ::testing::Test::IsSkipped()) return;
        }
    }
}

}  // namespace
