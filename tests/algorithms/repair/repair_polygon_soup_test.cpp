// tests/algorithms/repair/repair_polygon_soup_test.cpp
// repair_polygon_soup on clean and damaged soups: what it reports is what was injected, the
// output is a manifold, consistently oriented soup by an independent check, and every
// half-edge model takes it whole.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>
#include <random>
#include <set>

#include <hmira/algorithms/repair/repair_polygon_soup.hpp>
#include <hmira/io/mesh_io.hpp>

#include "support/checks.hpp"
#include "support/models.hpp"

namespace {

using hmira::io::polygon_soup;

/// A closed triangulated torus of n x m quads, each split in two, outward oriented.
polygon_soup torus(std::uint32_t n = 8, std::uint32_t m = 6, double shift = 0) {
    polygon_soup s;
    for (std::uint32_t i = 0; i < n; ++i)
        for (std::uint32_t j = 0; j < m; ++j) {
            const double u = 2 * 3.14159265358979 * i / n, v = 2 * 3.14159265358979 * j / m;
            s.points.push_back({(2 + std::cos(v)) * std::cos(u) + shift, (2 + std::cos(v)) * std::sin(u), std::sin(v)});
        }
    auto id = [&](std::uint32_t i, std::uint32_t j) { return (i % n) * m + (j % m); };
    for (std::uint32_t i = 0; i < n; ++i)
        for (std::uint32_t j = 0; j < m; ++j) {
            for (auto t : {std::array{id(i, j), id(i + 1, j), id(i + 1, j + 1)},
                           std::array{id(i, j), id(i + 1, j + 1), id(i, j + 1)}}) {
                s.indices.insert(s.indices.end(), t.begin(), t.end());
                s.face_offsets.push_back(s.indices.size());
            }
        }
    return s;
}

std::vector<std::vector<std::uint32_t>> faces_of(const polygon_soup& s) {
    std::vector<std::vector<std::uint32_t>> f;
    for (std::size_t i = 0; i < s.face_count(); ++i)
        f.emplace_back(s.indices.begin() + static_cast<long>(s.face_offsets[i]),
                       s.indices.begin() + static_cast<long>(s.face_offsets[i + 1]));
    return f;
}

polygon_soup soup_of(std::vector<std::array<double, 3>> points, const std::vector<std::vector<std::uint32_t>>& faces) {
    polygon_soup s;
    s.points = std::move(points);
    for (const auto& f : faces) {
        s.indices.insert(s.indices.end(), f.begin(), f.end());
        s.face_offsets.push_back(s.indices.size());
    }
    return s;
}

hmira::repaired_polygon_soup repair(const polygon_soup& s, hmira::soup_repair_options o = {}) {
    auto r = hmira::repair_polygon_soup(s.points.size(), s.face_offsets, s.indices, o);
    EXPECT_TRUE(r) << (r ? "" : r.error().message);
    return std::move(*r);
}

/// Independent check of the repair's postcondition, straight from the arrays: no repeated
/// vertex in a face, every edge has one or two faces, two faces run it opposite ways, and the
/// corners around each vertex form one fan (a path or a cycle through shared edges).
::testing::AssertionResult is_oriented_manifold(const hmira::repaired_polygon_soup& r) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> undirected;
    std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> around(
        r.vertex_count);  // (prev, next) per corner
    for (std::size_t f = 0; f < r.face_count(); ++f) {
        const auto b = r.face_offsets[f], e = r.face_offsets[f + 1];
        std::set<std::uint32_t> distinct(r.corners.begin() + static_cast<long>(b),
                                         r.corners.begin() + static_cast<long>(e));
        if (distinct.size() != e - b || e - b < 3)
            return ::testing::AssertionFailure() << "face " << f << " repeats a vertex";
        for (auto k = b; k < e; ++k) {
            const auto a = r.corners[k], z = r.corners[k + 1 == e ? b : k + 1], p = r.corners[k == b ? e - 1 : k - 1];
            if (a >= r.vertex_count) return ::testing::AssertionFailure() << "face " << f << " names vertex " << a;
            if (++directed[{a, z}] > 1) return ::testing::AssertionFailure() << "two faces run edge " << a << "->" << z;
            if (++undirected[{std::min(a, z), std::max(a, z)}] > 2)
                return ::testing::AssertionFailure() << "edge " << a << "-" << z << " has 3 faces";
            around[a].push_back({p, z});
        }
    }
    for (std::uint32_t v = 0; v < r.vertex_count; ++v) {
        // Corners chain when one's next neighbour is another's previous one; one fan = one chain.
        const auto& cs = around[v];
        if (cs.size() < 2) continue;
        std::map<std::uint32_t, std::size_t> by_prev;
        for (std::size_t i = 0; i < cs.size(); ++i) by_prev[cs[i].first] = i;
        std::size_t start = 0;
        for (std::size_t i = 0; i < cs.size(); ++i) {
            bool has_pred = false;
            for (const auto& c : cs) has_pred |= c.second == cs[i].first;
            if (!has_pred) start = i;
        }
        std::size_t walked = 1;
        for (std::size_t i = start; walked <= cs.size();) {
            auto it = by_prev.find(cs[i].second);
            if (it == by_prev.end() || it->second == start) break;
            i = it->second;
            ++walked;
        }
        if (walked != cs.size())
            return ::testing::AssertionFailure()
                   << "vertex " << v << ": its " << cs.size() << " faces form several fans";
    }
    return ::testing::AssertionSuccess();
}

TEST(RepairPolygonSoup, clean_soup_comes_back_unchanged) {
    const auto s = torus();
    const auto r = repair(s);
    EXPECT_TRUE(r.report.clean()) << r.report.summary();
    EXPECT_EQ(r.report.summary(), "no repair needed");
    EXPECT_EQ(r.corners, s.indices);
    EXPECT_EQ(r.face_offsets, s.face_offsets);
    EXPECT_EQ(r.vertex_count, s.points.size());
}

TEST(RepairPolygonSoup, flipped_faces_are_turned_back_and_listed) {
    const auto s = torus();
    auto faces = faces_of(s);
    const std::vector<std::size_t> flipped{3, 17, 18, 40, 41, 42, 77};  // fewer than half
    for (auto f : flipped) std::reverse(faces[f].begin(), faces[f].end());
    const auto r = repair(soup_of(s.points, faces));
    EXPECT_EQ(r.report.flipped_faces.count, flipped.size());
    EXPECT_EQ(r.report.flipped_faces.first, flipped);
    EXPECT_EQ(r.corners, s.indices);  // exactly the torus again
    EXPECT_EQ(r.report.added_vertices, 0u);
    EXPECT_TRUE(is_oriented_manifold(r));
}

TEST(RepairPolygonSoup, most_faces_decide_the_orientation) {
    const auto s = torus(4, 3);
    auto faces = faces_of(s);
    for (std::size_t f = 0; f < faces.size(); ++f)
        if (f != 5) std::reverse(faces[f].begin(), faces[f].end());
    const auto r = repair(soup_of(s.points, faces));
    EXPECT_EQ(r.report.flipped_faces.count, 1u);
    EXPECT_EQ(r.report.flipped_faces.first, (std::vector<std::size_t>{5}));
}

TEST(RepairPolygonSoup, degenerate_faces_are_dropped_and_repeats_merged) {
    const auto s = torus();
    auto faces = faces_of(s);
    // Inserted at 0, 10 and 20 (after insertion): a b a, a a b, a b c a b (pinched).
    faces.insert(faces.begin() + 20, {1, 2, 3, 1, 2});
    faces.insert(faces.begin() + 10, {4, 4, 5});
    faces.insert(faces.begin(), {7, 8, 7});
    // Face 30 gets a doubled corner that merging removes.
    faces[30].insert(faces[30].begin() + 1, faces[30][1]);
    const auto r = repair(soup_of(s.points, faces));
    EXPECT_EQ(r.report.degenerate_faces.count, 3u);
    EXPECT_EQ(r.report.degenerate_faces.first, (std::vector<std::size_t>{0, 11, 22}));
    EXPECT_EQ(r.report.merged_corners.first, (std::vector<std::size_t>{30}));
    EXPECT_EQ(r.face_count(), faces.size() - 3);
    EXPECT_EQ(r.corners, s.indices);
    for (std::size_t i = 0; i < r.face_count(); ++i) EXPECT_NE(r.face_source[i], 0u);
    EXPECT_EQ(r.face_source[10], 12u);
    EXPECT_TRUE(is_oriented_manifold(r));
}

TEST(RepairPolygonSoup, a_third_face_on_an_edge_is_cut_free_or_dropped) {
    auto s = torus();
    auto faces = faces_of(s);
    const auto n = static_cast<std::uint32_t>(s.points.size());
    s.points.push_back({9, 9, 9});
    faces.push_back({faces[0][0], faces[0][1], n});  // runs the edge like face 0
    const auto dup = repair(soup_of(s.points, faces));
    EXPECT_EQ(dup.report.nonmanifold_edges, 1u);
    EXPECT_EQ(dup.report.nonmanifold_edge_faces.first, (std::vector<std::size_t>{faces.size() - 1}));
    EXPECT_EQ(dup.face_count(), faces.size());
    EXPECT_EQ(dup.report.added_vertices, 2u);  // the extra face's ends of the edge
    EXPECT_EQ(dup.report.split_vertices.first,
              (std::vector<std::size_t>{std::min(faces[0][0], faces[0][1]), std::max(faces[0][0], faces[0][1])}));
    EXPECT_TRUE(is_oriented_manifold(dup));
    for (std::size_t v = 0; v < dup.vertex_count; ++v)
        EXPECT_EQ(v < s.points.size() ? v : dup.copied_from[v - s.points.size()], dup.source_vertex(v));

    const auto drop =
        repair(soup_of(s.points, faces), {.nonmanifold_edges = hmira::nonmanifold_edge_policy::drop_faces});
    EXPECT_EQ(drop.face_count(), faces.size() - 1);
    EXPECT_EQ(drop.report.dropped_faces, 1u);
    EXPECT_EQ(drop.corners, s.indices);
}

TEST(RepairPolygonSoup, two_surfaces_sharing_a_vertex_get_one_copy_each_extra) {
    auto a = torus(), b = torus(8, 6, 10);
    auto faces = faces_of(a);
    const auto n = static_cast<std::uint32_t>(a.points.size());
    for (auto f : faces_of(b)) {
        for (auto& v : f) v = v == 0 ? 0 : v + n;  // b's vertex 0 is a's vertex 0
        faces.push_back(f);
    }
    auto points = a.points;
    points.insert(points.end(), b.points.begin(), b.points.end());
    const auto r = repair(soup_of(points, faces));
    EXPECT_EQ(r.report.split_vertices.first, (std::vector<std::size_t>{0}));
    EXPECT_EQ(r.report.added_vertices, 1u);
    EXPECT_EQ(r.copied_from, (std::vector<std::uint32_t>{0}));
    EXPECT_EQ(r.face_count(), faces.size());
    EXPECT_EQ(r.report.flipped_faces.count, 0u);
    EXPECT_TRUE(is_oriented_manifold(r));
}

TEST(RepairPolygonSoup, a_moebius_band_is_opened_at_one_edge) {
    // A ring of 8 quads whose last one joins the first with a half twist.
    std::vector<std::array<double, 3>> points;
    const std::uint32_t n = 8;
    for (std::uint32_t i = 0; i < n; ++i) points.push_back({double(i), 0, 0}), points.push_back({double(i), 1, 0});
    std::vector<std::vector<std::uint32_t>> faces;
    for (std::uint32_t i = 0; i + 1 < n; ++i) faces.push_back({2 * i, 2 * i + 2, 2 * i + 3, 2 * i + 1});
    faces.push_back({2 * (n - 1), 1, 0, 2 * (n - 1) + 1});  // the twist
    const auto r = repair(soup_of(points, faces));
    EXPECT_EQ(r.report.orientation_cuts, 1u);
    EXPECT_EQ(r.face_count(), faces.size());
    EXPECT_TRUE(is_oriented_manifold(r));
}

TEST(RepairPolygonSoup, bad_arrays_are_refused_with_the_face) {
    const std::vector<std::uint64_t> offsets{0, 3, 6};
    const std::vector<std::uint32_t> corners{0, 1, 2, 0, 1, 9};
    auto r = hmira::repair_polygon_soup(4, offsets, corners);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().element, 1);
    EXPECT_NE(r.error().message.find("face 1 names vertex 9"), std::string::npos) << r.error().message;
    const std::vector<std::uint64_t> decreasing{0, 4, 3, 6};
    auto d = hmira::repair_polygon_soup(4, decreasing, corners);
    ASSERT_FALSE(d);
    EXPECT_EQ(d.error().element, 1);
    EXPECT_FALSE(hmira::repair_polygon_soup(4, std::vector<std::uint64_t>{0, 3}, corners));
}

/// What a random damaged soup was given, to compare with the report.
struct damaged {
    polygon_soup soup;
    std::size_t degenerate = 0, extra_faces = 0, flipped = 0;
    std::set<std::size_t> shared_vertices;
};

/// Two tori (the second shifted) sharing vertex 0, with some faces flipped (fewer than half of
/// each torus), extra faces on vertex-disjoint edges away from vertex 0, and degenerate faces,
/// all at random places in the face order.
damaged random_damage(std::mt19937& rng) {
    auto a = torus(6 + rng() % 6, 4 + rng() % 4), b = torus(5 + rng() % 4, 4 + rng() % 3, 10);
    const auto na = static_cast<std::uint32_t>(a.points.size());
    damaged d;
    auto faces = faces_of(a);
    const std::size_t fa = faces.size();
    for (auto f : faces_of(b)) {
        for (auto& v : f) v = v == 0 ? 0 : v + na - 1;  // b's vertex 0 is a's vertex 0
        faces.push_back(f);
    }
    d.soup.points = a.points;
    d.soup.points.insert(d.soup.points.end(), b.points.begin() + 1, b.points.end());
    d.shared_vertices.insert(0);
    // Extra faces on edges of torus a whose vertices no other extra face or vertex 0 touches.
    std::set<std::uint32_t> touched{0};
    std::vector<std::vector<std::uint32_t>> extra;
    for (std::size_t tries = 0; tries < 40 && extra.size() < 4; ++tries) {
        const auto& f = faces[rng() % fa];
        const auto p = f[0], q = f[1];
        bool free = true;
        for (auto w : f) free &= !touched.count(w);  // the whole face, so no two extras share a fan
        if (!free) continue;
        touched.insert(f.begin(), f.end());
        const auto x = static_cast<std::uint32_t>(d.soup.points.size());
        d.soup.points.push_back({20.0 + double(x), 0, 0});
        extra.push_back(rng() % 2 ? std::vector<std::uint32_t>{p, q, x} : std::vector<std::uint32_t>{q, p, x});
        d.shared_vertices.insert(p), d.shared_vertices.insert(q);
    }
    // Flip up to a third of each torus, but not the faces on an extra face's edge: with
    // those flipped, which two of the three faces belong together is a guess.
    auto on_extra_edge = [&](const std::vector<std::uint32_t>& f) {
        for (const auto& e : extra)
            for (std::size_t i = 0; i < f.size(); ++i) {
                const auto a = f[i], b = f[(i + 1) % f.size()];
                if ((a == e[0] && b == e[1]) || (a == e[1] && b == e[0])) return true;
            }
        return false;
    };
    for (auto [lo, hi] : {std::pair{std::size_t{0}, fa}, std::pair{fa, faces.size()}}) {
        std::vector<std::size_t> ids;
        for (auto i = lo; i < hi; ++i)
            if (!on_extra_edge(faces[i])) ids.push_back(i);
        std::shuffle(ids.begin(), ids.end(), rng);
        const std::size_t k = rng() % ((hi - lo) / 3);
        for (std::size_t i = 0; i < k; ++i) std::reverse(faces[ids[i]].begin(), faces[ids[i]].end());
        d.flipped += k;
    }
    d.extra_faces = extra.size();
    // Extra faces go after all the tori's faces, so the tori keep their edges.
    for (auto& e : extra) faces.push_back(e);
    // Degenerate faces anywhere.
    const std::size_t nd = rng() % 5;
    for (std::size_t i = 0; i < nd; ++i) {
        const auto v = static_cast<std::uint32_t>(rng() % d.soup.points.size()),
                   w = static_cast<std::uint32_t>((v + 1) % d.soup.points.size());
        std::vector<std::uint32_t> bad =
            rng() % 2 ? std::vector<std::uint32_t>{v, w, v} : std::vector<std::uint32_t>{v, v, w, w};
        faces.insert(faces.begin() + static_cast<long>(rng() % (faces.size() + 1)), bad);
    }
    d.degenerate = nd;
    for (const auto& f : faces) {
        d.soup.indices.insert(d.soup.indices.end(), f.begin(), f.end());
        d.soup.face_offsets.push_back(d.soup.indices.size());
    }
    return d;
}

TEST(RepairPolygonSoup, random_damage_is_repaired_and_reported_exactly) {
    std::mt19937 rng(20261201);
    for (int round = 0; round < 60; ++round) {
        SCOPED_TRACE("round " + std::to_string(round));
        const auto d = random_damage(rng);
        const auto r = repair(d.soup);
        EXPECT_TRUE(is_oriented_manifold(r));
        EXPECT_EQ(r.report.degenerate_faces.count, d.degenerate);
        EXPECT_EQ(r.face_count(), d.soup.face_count() - d.degenerate);  // no face lost
        EXPECT_EQ(r.report.nonmanifold_edges, d.extra_faces);
        EXPECT_EQ(r.report.nonmanifold_edge_faces.count, d.extra_faces);
        EXPECT_EQ(r.report.flipped_faces.count, d.flipped);
        EXPECT_EQ(r.report.orientation_cuts, 0u);
        EXPECT_EQ(r.report.split_vertices.count, d.shared_vertices.size());
        EXPECT_EQ(r.report.added_vertices, d.shared_vertices.size());
        EXPECT_EQ(r.report.detached_faces.count, 0u);

        const auto dropped = repair(d.soup, {.nonmanifold_edges = hmira::nonmanifold_edge_policy::drop_faces});
        EXPECT_TRUE(is_oriented_manifold(dropped));
        EXPECT_EQ(dropped.face_count(), d.soup.face_count() - d.degenerate - d.extra_faces);
        EXPECT_EQ(dropped.report.added_vertices, 1u);  // only the shared vertex 0
    }
}

/// A soup with nothing but trouble: few vertices and many random faces, so edges carry many
/// faces, fans tangle and orientations clash. `degenerate` gets the number of faces with a
/// repeat that merging consecutive corners cannot remove (computed here, not by the repair).
polygon_soup random_tangle(std::mt19937& rng, std::size_t& degenerate) {
    const std::uint32_t nv = 4 + rng() % 12;
    polygon_soup s;
    for (std::uint32_t v = 0; v < nv; ++v) s.points.push_back({double(v), double(v * v % 7), double(v % 3)});
    const std::size_t nf = 1 + rng() % 40;
    degenerate = 0;
    for (std::size_t f = 0; f < nf; ++f) {
        const std::size_t k = 3 + rng() % 3;
        for (std::size_t i = 0; i < k; ++i) s.indices.push_back(static_cast<std::uint32_t>(rng() % nv));
        std::vector<std::uint32_t> loop(s.indices.end() - static_cast<long>(k), s.indices.end()), merged;
        for (auto v : loop)
            if (merged.empty() || merged.back() != v) merged.push_back(v);
        while (merged.size() > 1 && merged.back() == merged.front()) merged.pop_back();
        degenerate +=
            merged.size() < 3 || std::set<std::uint32_t>(merged.begin(), merged.end()).size() != merged.size();
        s.face_offsets.push_back(s.indices.size());
    }
    return s;
}

/// Soups with nothing but trouble: few vertices, many random faces, so edges carry many faces,
/// fans tangle and orientations clash. Only the postcondition can be checked.
TEST(RepairPolygonSoup, random_tangles_come_out_manifold_without_losing_faces) {
    std::mt19937 rng(7);
    for (int round = 0; round < 300; ++round) {
        SCOPED_TRACE("round " + std::to_string(round));
        std::size_t degenerate = 0;
        const auto s = random_tangle(rng, degenerate);
        const std::size_t nf = s.face_count();
        for (auto policy :
             {hmira::nonmanifold_edge_policy::duplicate_vertices, hmira::nonmanifold_edge_policy::drop_faces}) {
            const auto r = repair(s, {.nonmanifold_edges = policy});
            EXPECT_TRUE(is_oriented_manifold(r));
            EXPECT_EQ(r.report.degenerate_faces.count, degenerate);
            if (policy == hmira::nonmanifold_edge_policy::duplicate_vertices)
                EXPECT_EQ(r.face_count(), nf - degenerate);
            else
                EXPECT_EQ(r.face_count(), nf - degenerate - r.report.nonmanifold_edge_faces.count);
            EXPECT_EQ(r.report.dropped_faces, nf - r.face_count());
            for (std::size_t f = 0; f < r.face_count(); ++f)  // each face keeps its file vertices
                for (auto k = r.face_offsets[f]; k < r.face_offsets[f + 1]; ++k) {
                    const auto src = r.face_source[f];
                    const auto b = s.face_offsets[src], e = s.face_offsets[src + 1];
                    EXPECT_NE(std::find(s.indices.begin() + static_cast<long>(b),
                                        s.indices.begin() + static_cast<long>(e), r.source_vertex(r.corners[k])),
                              s.indices.begin() + static_cast<long>(e));
                }
        }
    }
}

// ---- reading into every half-edge model --------------------------------------------------

template <class M>
class RepairRead : public ::testing::Test {};

using halfedge_models = ::testing::Types<hmira::halfedge_mesh
#ifdef HMIRA_TEST_HAS_WINGED_EDGE
                                         ,
                                         hmira::winged_edge_mesh
#endif
#ifdef HMIRA_TEST_WITH_OPENMESH
                                         ,
                                         hmira_test::openmesh_poly, hmira_test::openmesh_tri
#endif
#ifdef HMIRA_TEST_WITH_CGAL
                                         ,
                                         hmira_test::cgal_surface_mesh
#endif
                                         >;
TYPED_TEST_SUITE(RepairRead, halfedge_models);

TYPED_TEST(RepairRead, damaged_soups_build_whole_and_valid) {
    using M = TypeParam;
    using T = hmira::default_traits<M>;
    std::mt19937 rng(99);
    for (int round = 0; round < 25; ++round) {
        SCOPED_TRACE("round " + std::to_string(round));
        auto d = random_damage(rng);
        const std::size_t faces = d.soup.face_count(), points = d.soup.points.size();
        M mesh;
        auto report = hmira::io::build_from_soup<M>(mesh, std::move(d.soup), "random");
        ASSERT_TRUE(report) << report.error().message;
        EXPECT_TRUE(hmira_test::is_valid(mesh));
        EXPECT_EQ(T::face_count(mesh), faces - d.degenerate);
        EXPECT_EQ(T::vertex_count(mesh), points + d.shared_vertices.size());
        EXPECT_EQ(report->file_vertices, points);
        EXPECT_EQ(report->copied_from.size(), d.shared_vertices.size());
        EXPECT_EQ(std::set<std::size_t>(report->copied_from.begin(), report->copied_from.end()), d.shared_vertices);
        EXPECT_EQ(report->face_source.size(), d.degenerate ? faces - d.degenerate : 0u);
        EXPECT_EQ(report->repair.flipped_faces.count, d.flipped);
    }
}

TYPED_TEST(RepairRead, tangles_build_whole_in_any_model) {
    using M = TypeParam;
    using T = hmira::default_traits<M>;
    std::mt19937 rng(31);
    for (int round = 0; round < 200; ++round) {
        SCOPED_TRACE("round " + std::to_string(round));
        std::size_t degenerate = 0;
        auto s = random_tangle(rng, degenerate);
        const std::size_t faces = s.face_count();
        if constexpr (requires { requires T::triangles_only; }) {  // a triangle soup for TriMesh
            s.face_offsets.assign(1, 0);
            s.indices.resize(s.indices.size() / 3 * 3);
            for (std::size_t k = 3; k <= s.indices.size(); k += 3) s.face_offsets.push_back(k);
        }
        M mesh;
        auto report = hmira::io::build_from_soup<M>(mesh, std::move(s), "tangle");
        ASSERT_TRUE(report) << report.error().message;
        if constexpr (!requires { requires T::triangles_only; }) {
            EXPECT_EQ(T::face_count(mesh), faces - degenerate);
        }
        // Unused file vertices stay (isolated) and random points may be collinear: those two
        // findings are the file's, not the repair's.
        for (const auto& p : hmira::validate<M>(mesh))
            EXPECT_TRUE(p.kind == hmira::problem_kind::isolated_vertex || p.kind == hmira::problem_kind::zero_area_face)
                << p.message;
    }
}

TYPED_TEST(RepairRead, without_repair_a_damaged_file_is_refused_and_the_mesh_kept) {
    using M = TypeParam;
    using T = hmira::default_traits<M>;
    M mesh;
    ASSERT_TRUE(hmira::io::build_from_soup<M>(mesh, torus(4, 3), "clean"));
    const auto before = hmira_test::canonical_faces(mesh);
    auto s = torus();
    auto faces = faces_of(s);
    std::reverse(faces[5].begin(), faces[5].end());
    auto r = hmira::io::build_from_soup<M>(mesh, soup_of(s.points, faces), "flipped.off", {.repair = false});
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().element, 5);
    EXPECT_NE(r.error().message.find("flipped.off: face 5 "), std::string::npos) << r.error().message;
    EXPECT_EQ(hmira_test::canonical_faces(mesh), before);
    EXPECT_EQ(T::face_count(mesh), 24u);
}

/// A file on disk: pig-like damage (a non-manifold edge and a flipped face) read by read_mesh.
TYPED_TEST(RepairRead, read_mesh_repairs_a_file_and_says_so) {
    using M = TypeParam;
    using T = hmira::default_traits<M>;
    auto s = torus();
    auto faces = faces_of(s);
    std::reverse(faces[2].begin(), faces[2].end());
    const auto n = static_cast<std::uint32_t>(s.points.size());
    s.points.push_back({5, 5, 5});
    faces.push_back({faces[10][1], faces[10][0], n});
    const auto path =
        std::filesystem::temp_directory_path() / ("hmira_repair_read_" + std::to_string(::getpid()) + ".off");
    {
        std::ofstream out(path);
        out << "OFF\n" << s.points.size() << ' ' << faces.size() << " 0\n";
        for (const auto& p : s.points) out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
        for (const auto& f : faces) {
            out << f.size();
            for (auto v : f) out << ' ' << v;
            out << '\n';
        }
    }
    M mesh;
    auto r = hmira::io::read_mesh(mesh, path);
    std::filesystem::remove(path);
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_TRUE(hmira_test::is_valid(mesh));
    EXPECT_EQ(T::face_count(mesh), faces.size());
    EXPECT_EQ(r->repair.flipped_faces.first, (std::vector<std::size_t>{2}));
    EXPECT_EQ(r->repair.nonmanifold_edge_faces.first, (std::vector<std::size_t>{faces.size() - 1}));
    EXPECT_EQ(r->file_vertices, s.points.size());
    EXPECT_EQ(r->copied_from.size(), 2u);
    EXPECT_EQ(r->repair.summary().find("no repair"), std::string::npos);
}

#ifdef HMIRA_TEST_WITH_OPENMESH
TEST(RepairReadOpenMesh, reading_keeps_requested_properties) {
    hmira_test::openmesh_poly mesh;
    mesh.request_vertex_normals();
    mesh.request_face_status();
    OpenMesh::VPropHandleT<int> mine;
    mesh.add_property(mine, "mine");
    ASSERT_TRUE(hmira::io::build_from_soup(mesh, torus(), "torus"));
    EXPECT_TRUE(mesh.has_vertex_normals());
    EXPECT_TRUE(mesh.has_face_status());
    EXPECT_TRUE(mine.is_valid());
    EXPECT_EQ(mesh.n_faces(), 96u);
    for (auto f : mesh.faces()) EXPECT_FALSE(mesh.status(f).deleted());
}
#endif

#ifdef HMIRA_TEST_WITH_CGAL
TEST(RepairReadCgal, reading_keeps_property_maps) {
    hmira_test::cgal_surface_mesh mesh;
    auto [map, created] = mesh.add_property_map<hmira_test::cgal_surface_mesh::Vertex_index, int>("v:mine", 3);
    ASSERT_TRUE(created);
    ASSERT_TRUE(hmira::io::build_from_soup(mesh, torus(), "torus"));
    auto again = mesh.property_map<hmira_test::cgal_surface_mesh::Vertex_index, int>("v:mine");
    EXPECT_TRUE(again.second);
    EXPECT_EQ(mesh.number_of_faces(), 96u);
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
}
#endif

}  // namespace
