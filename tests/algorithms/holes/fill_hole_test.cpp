// fill_hole and fill_holes on every model that supports them: holes cut into a triangulated
// torus and into real meshes by deleting face patches are closed, V - E + F (so the genus) is
// that of the uncut mesh, the mesh and the model's own checker are happy, and a flat hole's
// patch has the hole's area. A refused fill changes nothing. Refined patches match the edge
// length around the hole; fairing a cap cut from a sphere gives a flat disc (membrane) or
// comes back close to the sphere (thin plate); the fixed vertices never move.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <random>
#include <set>
#include <type_traits>
#include <vector>

#include <hmira/algorithms/holes/fill_hole.hpp>
#include <hmira/io/mesh_io.hpp>

#include "algorithms/triangle/triangle_support.hpp"

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
            for (auto x = hole;;) {
                ++len;
                x = T::next(m, x);
                if (x == hole) break;
            }
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
        for (const auto& o :
             {hmira::fill_hole_options{.refine = true, .refine_density = 0.0},
              hmira::fill_hole_options{.refine = true, .refine_density = std::nan("")},
              hmira::fill_hole_options{.fair = hmira::fairing::thin_plate, .fairing_tolerance = -1.0}}) {
            auto t = hmira::fill_holes(m, 10, o);
            ASSERT_FALSE(t);
            EXPECT_EQ(t.error().code, hmira::errc::invalid_argument);
            EXPECT_NE(t.error().message.find("option"), std::string::npos) << t.error().message;
            EXPECT_EQ(take_snapshot(m), before);
        }
    }
}

/// A UV sphere of radius 1: `bands` latitude bands of `segments` quads (triangles at the
/// poles), split into triangles, wound outward.
face_list uv_sphere(std::size_t bands, std::size_t segments) {
    face_list g;
    g.points.push_back({0, 0, 1});
    for (std::size_t j = 1; j < bands; ++j)
        for (std::size_t i = 0; i < segments; ++i) {
            const double t = std::numbers::pi * double(j) / double(bands),
                         u = 2 * std::numbers::pi * double(i) / double(segments);
            g.points.push_back({std::sin(t) * std::cos(u), std::sin(t) * std::sin(u), std::cos(t)});
        }
    g.points.push_back({0, 0, -1});
    const std::size_t south = g.points.size() - 1;
    auto id = [&](std::size_t j, std::size_t i) { return 1 + (j - 1) * segments + i % segments; };
    for (std::size_t i = 0; i < segments; ++i) {
        g.faces.push_back({0, id(1, i), id(1, i + 1)});
        g.faces.push_back({south, id(bands - 1, i + 1), id(bands - 1, i)});
        for (std::size_t j = 1; j + 1 < bands; ++j) {
            g.faces.push_back({id(j, i), id(j + 1, i), id(j + 1, i + 1)});
            g.faces.push_back({id(j, i), id(j + 1, i + 1), id(j, i + 1)});
        }
    }
    return g;
}

/// Positions of the vertices a mesh had, by index, to show that a fill moved none of them.
template <class M, class T = hmira::default_traits<M>>
std::vector<std::array<double, 3>> positions(const M& m) {
    std::vector<std::array<double, 3>> out(T::vertex_index_bound(m));
    for (auto v : T::vertices(m)) {
        const auto p = T::position(m, v);
        out[T::vertex_index(m, v)] = {double(p[0]), double(p[1]), double(p[2])};
    }
    return out;
}
template <class M, class T = hmira::default_traits<M>>
bool old_vertices_kept(const M& m, const std::vector<std::array<double, 3>>& before) {
    for (auto v : T::vertices(m)) {
        const auto i = T::vertex_index(m, v);
        if (i >= before.size()) continue;
        const auto p = T::position(m, v);
        if (std::array<double, 3>{double(p[0]), double(p[1]), double(p[2])} != before[i]) return false;
    }
    return true;
}

template <class M, class T = hmira::default_traits<M>>
hmira::vec3<double> at(const M& m, typename T::vertex_handle v) {
    const auto p = T::position(m, v);
    return {double(p[0]), double(p[1]), double(p[2])};
}

/// Mean length of a loop's edges.
template <class M, class T = hmira::default_traits<M>>
double loop_mean_edge(const M& m, typename T::halfedge_handle h) {
    double sum = 0;
    std::size_t n = 0;
    auto x = h;
    do {
        const auto d = at(m, T::target(m, x)) - at(m, T::target(m, T::opposite(m, x)));
        sum += std::sqrt(hmira::dot(d, d));
        ++n;
        x = T::next(m, x);
    } while (x != h);
    return sum / double(n);
}

/// Mean length of the edges inside a patch (both faces in it).
template <class M, class T = hmira::default_traits<M>>
double patch_mean_edge(const M& m, const std::vector<typename T::face_handle>& faces) {
    std::set<std::size_t> in;
    for (auto f : faces) in.insert(T::face_index(m, f));
    double sum = 0;
    std::size_t n = 0;
    for (auto f : faces) {
        const auto h0 = T::face_halfedge(m, f);
        auto x = h0;
        do {
            const auto o = T::face(m, T::opposite(m, x));
            if (o != T::null_face() && in.count(T::face_index(m, o))) {
                const auto d = at(m, T::target(m, x)) - at(m, T::target(m, T::opposite(m, x)));
                sum += std::sqrt(hmira::dot(d, d));
                ++n;
            }
            x = T::next(m, x);
        } while (x != h0);
    }
    return n ? sum / double(n) : 0;
}

TYPED_TEST(fill_hole_test, fairing_a_cap_cut_from_a_sphere_gives_a_flat_disc_or_a_cap_close_to_the_sphere) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        // 12 bands of 32 segments; the top 3 bands removed: a planar loop of 32 edges at z0 = cos 45 deg.
        const face_list full = uv_sphere(12, 32);
        const double z0 = std::cos(std::numbers::pi * 3 / 12);
        const face_list cut = used_points_only(without_faces(full, [&](std::size_t f) {
            for (auto v : full.faces[f])
                if (full.points[v].z > z0 + 1e-9) return true;
            return false;
        }));
        struct run {
            double mean_distance = 0, max_off_plane = 0;
            std::size_t added = 0;
        };
        auto fill = [&](hmira::fairing how) {
            M m = mesh_from<M>(cut);
            const auto before = positions(m);
            const auto loops = boundary_loops(m);
            EXPECT_EQ(loops.size(), 1u);
            const double boundary_mean = loop_mean_edge(m, loops[0]);
            auto r = hmira::fill_hole(m, loops[0], {.refine = true, .fair = how});
            EXPECT_TRUE(r) << r.error().message;
            run out;
            if (!r) return out;
            EXPECT_TRUE(r->faired);
            EXPECT_TRUE(valid_topology(m));
            EXPECT_TRUE(boundary_loops(m).empty());
            EXPECT_EQ(chi(m), 2);
            EXPECT_TRUE(old_vertices_kept(m, before)) << "a fixed vertex moved";
            EXPECT_EQ(T::face_count(m), cut.faces.size() + 30 + 2 * r->vertices.size());
            const double patch_mean = patch_mean_edge(m, r->faces);
            EXPECT_GT(patch_mean, 0.5 * boundary_mean);
            EXPECT_LT(patch_mean, 2.0 * boundary_mean);
            out.added = r->vertices.size();
            const double loop_z = at(m, T::target(m, loops[0])).z;  // z0 in the model's scalar
            for (auto v : r->vertices) {
                const auto p = at(m, v);
                out.mean_distance += std::fabs(std::sqrt(hmira::dot(p, p)) - 1);
                out.max_off_plane = std::max(out.max_off_plane, std::fabs(p.z - loop_z));
            }
            if (out.added) out.mean_distance /= double(out.added);
            return out;
        };
        const run flat = fill(hmira::fairing::none), membrane = fill(hmira::fairing::membrane),
                  plate = fill(hmira::fairing::thin_plate);
        // The removed cap of area 2 pi (1 - z0) ~ 1.84, in triangles of edge ~ 0.14 (the loop's):
        // many vertices, not a handful.
        EXPECT_GT(flat.added, 20u);
        EXPECT_EQ(membrane.added, flat.added);
        // Centroids of points in the plane z = z0 stay in it; a harmonic function with constant
        // boundary values is that constant: both patches are the flat disc.
        const double rounding = 8 * std::numeric_limits<typename T::scalar>::epsilon();
        EXPECT_LE(flat.max_off_plane, rounding);
        EXPECT_LT(membrane.max_off_plane, 1e-8 + rounding);
        // Over the flat disc (radius r0 = sin 45 deg), 1 - |p| runs from 0 at the loop to
        // 1 - z0 = 0.29 at the centre; its area mean is 1 - 2 (1 - z0^3) / (3 r0^2) = 0.138.
        // Vertices gather towards the centre, so their mean lies above that, below the maximum.
        EXPECT_GT(flat.mean_distance, 0.1);
        EXPECT_LT(flat.mean_distance, 1 - z0);
        // The thin plate continues the sphere's slope across the loop: a cap, far closer.
        EXPECT_LT(plate.mean_distance, flat.mean_distance / 5)
            << plate.mean_distance << " vs flat " << flat.mean_distance;
        EXPECT_GT(plate.max_off_plane, 0.15);  // it rises towards the pole (at 1 - z0 = 0.29 above)
    }
}

TYPED_TEST(fill_hole_test, an_unconverged_fairing_moves_no_vertex) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        using T = hmira::default_traits<M>;
        const face_list full = uv_sphere(12, 32);
        const face_list cut = used_points_only(without_faces(full, [&](std::size_t f) {
            for (auto v : full.faces[f])
                if (full.points[v].z > 0.5) return true;
            return false;
        }));
        M refined = mesh_from<M>(cut), starved = mesh_from<M>(cut);
        auto a = hmira::fill_hole(refined, boundary_loops(refined)[0], {.refine = true});
        auto b = hmira::fill_hole(starved, boundary_loops(starved)[0],
                                  {.refine = true, .fair = hmira::fairing::thin_plate, .max_fairing_iterations = 1});
        ASSERT_TRUE(a && b);
        EXPECT_TRUE(a->faired);
        EXPECT_FALSE(b->faired);
        EXPECT_TRUE(valid_topology(starved));
        ASSERT_EQ(a->vertices.size(), b->vertices.size());
        ASSERT_GT(a->vertices.size(), 0u);
        // Same input, same refinement: the unconverged solve left every vertex where refinement put it.
        EXPECT_EQ(positions(starved), positions(refined));
        (void)T::face_count(starved);
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
    for (int i = 0; i < 6; ++i)
        seeds.push_back(std::uniform_int_distribution<std::size_t>(0, full.points.size() - 1)(rng));
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

    // The same holes, refined and faired (thin plate), one by one.
    M fine = mesh_from<M>(cut_holes(full, seeds, 3));
    const auto before = positions(fine);
    std::size_t filled = 0, added = 0;
    for (auto hole : boundary_loops(fine)) {
        const double boundary_mean = loop_mean_edge(fine, hole);
        auto f = hmira::fill_hole(fine, hole, {.refine = true, .fair = hmira::fairing::thin_plate});
        if (!f) continue;  // a loop the file had may be refused; the count is checked below
        ++filled;
        added += f->vertices.size();
        EXPECT_TRUE(f->faired) << name;
        if (!f->vertices.empty()) {
            const double patch_mean = patch_mean_edge(fine, f->faces);
            EXPECT_GT(patch_mean, 0.5 * boundary_mean) << name;
            EXPECT_LT(patch_mean, 2.0 * boundary_mean) << name;
        }
    }
    EXPECT_GE(filled, loops_cut - loops_full) << name;
    EXPECT_GT(added, 0u) << name;
    EXPECT_TRUE(valid_topology(fine)) << name;
    EXPECT_EQ(boundary_loops(fine).size(), loops_cut - filled) << name;
    EXPECT_EQ(chi(fine), chi_full + (long long)(loops_full - boundary_loops(fine).size()))
        << name << ": the genus changed";
    EXPECT_TRUE(old_vertices_kept(fine, before)) << name << ": a vertex outside the patches moved";
    (void)T::face_count(m);
}

TYPED_TEST(fill_hole_test, holes_cut_into_real_meshes_are_closed_and_the_genus_kept) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
#ifdef HMIRA_SANITIZER_BUILD
        // Under the sanitizers (-O0) the two large meshes run on the reference model only.
        std::vector<const char*> names{"fandisk.off"};
        if (std::is_same_v<M, hmira::halfedge_mesh>) names = {"fandisk.off", "bunny00.off", "armadillo.off"};
#else
        const std::vector<const char*> names{"fandisk.off", "bunny00.off", "armadillo.off"};
#endif
        for (const char* name : names) {
            fill_real_mesh<M>(name);
            if (::testing::Test::HasFatalFailure() || ::testing::Test::IsSkipped()) return;
        }
    }
}

}  // namespace
