// tests/algorithms/delaunay/delaunay_large_test.cpp
// The full-size cases: 10^6 uniform and clustered points and the 1000 x 1000 integer
// lattice, with every property checked. Labelled "large"; under the sanitizers the inputs
// shrink to keep the CI pass short.
#include <gtest/gtest.h>

#include <hmira/algorithms/delaunay/delaunay_triangulation.hpp>

#include "delaunay_checks.hpp"

namespace {

#ifdef HMIRA_SANITIZER_BUILD
constexpr std::size_t million = 50000;
constexpr int lattice_side = 200;
#else
constexpr std::size_t million = 1000000;
constexpr int lattice_side = 1000;
#endif

TEST(delaunay_large, million_uniform_points) {
    const auto pts = hmira_test::uniform_points(million, 101);
    const auto d = hmira::delaunay_triangulation(pts);
    ASSERT_TRUE(d) << d.error().message;
    EXPECT_TRUE(hmira_test::is_delaunay_triangulation(pts, *d));
}

TEST(delaunay_large, million_clustered_points) {
    const auto pts = hmira_test::clustered_points(million, 102);
    const auto d = hmira::delaunay_triangulation(pts);
    ASSERT_TRUE(d) << d.error().message;
    EXPECT_TRUE(hmira_test::is_delaunay_triangulation(pts, *d));
}

TEST(delaunay_large, thousand_by_thousand_integer_lattice) {
    const auto pts = hmira_test::lattice_points(lattice_side);
    const auto d = hmira::delaunay_triangulation(pts);
    ASSERT_TRUE(d) << d.error().message;
    EXPECT_TRUE(hmira_test::is_delaunay_triangulation(pts, *d));
    EXPECT_EQ(d->triangles.size(), std::size_t(2) * (lattice_side - 1) * (lattice_side - 1));
}

}  // namespace
