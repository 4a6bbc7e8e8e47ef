// tests/algorithms/delaunay/delaunay_cgal_test.cpp
// Against CGAL's Delaunay_triangulation_2 (exact predicates kernel): on inputs in general
// position the Delaunay triangulation is unique, so both must produce the same triangle set.
#include <gtest/gtest.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include <hmira/algorithms/delaunay/delaunay_triangulation.hpp>

#include "delaunay_checks.hpp"

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb>;
using Dt = CGAL::Delaunay_triangulation_2<K, Tds>;

std::vector<std::array<std::uint32_t, 3>> cgal_triangles(const std::vector<hmira_test::point3>& pts) {
    std::vector<std::pair<K::Point_2, std::uint32_t>> in;
    in.reserve(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) in.emplace_back(K::Point_2(pts[i].x, pts[i].y), std::uint32_t(i));
    Dt dt(in.begin(), in.end());
    std::vector<std::array<std::uint32_t, 3>> out;
    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
        std::array<std::uint32_t, 3> t = {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
        std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
        out.push_back(t);
    }
    std::sort(out.begin(), out.end());
    return out;
}

TEST(delaunay_cgal, same_triangles_as_cgal_on_uniform_points) {
    for (std::uint64_t seed : {1u, 2u, 3u}) {
        for (std::size_t n : {std::size_t(10), std::size_t(1000), std::size_t(100000)}) {
#ifdef HMIRA_SANITIZER_BUILD
            if (n == 100000 && seed != 1) continue;  // instrumented CGAL takes ~10 s per 10^5 points
#endif
            const auto pts = hmira_test::uniform_points(n, seed);
            const auto d = hmira::delaunay_triangulation(pts);
            ASSERT_TRUE(d);
            EXPECT_EQ(hmira_test::canonical_triangles(*d), cgal_triangles(pts)) << "seed " << seed << " n " << n;
        }
    }
}

TEST(delaunay_cgal, same_triangles_as_cgal_on_clustered_and_far_from_origin_points) {
    auto pts = hmira_test::clustered_points(50000, 7);
    EXPECT_EQ(hmira_test::canonical_triangles(*hmira::delaunay_triangulation(pts)), cgal_triangles(pts));
    auto far = hmira_test::uniform_points(20000, 8);
    for (auto& p : far) p.x = 1e6 + p.x * 1e-3, p.y = -3e5 + p.y * 1e-3;
    EXPECT_EQ(hmira_test::canonical_triangles(*hmira::delaunay_triangulation(far)), cgal_triangles(far));
}

}  // namespace
