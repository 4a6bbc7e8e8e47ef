// default_iso and samples_range: the midpoint of a scan-like volume (all samples positive, where
// an iso of 0 has no surface) gives a closed surface, a NaN is named by its sample, and a
// constant volume has its one value as the midpoint (and so no surface).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <hmira/algorithms/conversion/iso_level.hpp>
#include <hmira/algorithms/conversion/marching_cubes.hpp>
#include <hmira/grids/dense_grid.hpp>

namespace {

using namespace hmira;

dense_grid<float> scan(std::size_t n) {
    dense_grid<float> g(grid_geometry{{n, n, n}, {0, 0, 0}, {1, 1, 1}}, 1000.0f);
    const double c = double(n - 1) / 2;
    for (std::size_t k = 0; k < n; ++k)
        for (std::size_t j = 0; j < n; ++j)
            for (std::size_t i = 0; i < n; ++i)
                if (std::hypot(double(i) - c, double(j) - c, double(k) - c) < double(n) / 4) g.set(i, j, k, 200.0f);
    return g;
}

TEST(IsoLevel, midpoint_of_a_scan_gives_a_surface_where_zero_gives_an_error) {
    const auto g = scan(16);
    const auto range = samples_range(g);
    ASSERT_TRUE(range);
    EXPECT_EQ(range->min, 200.0);
    EXPECT_EQ(range->max, 1000.0);
    const auto iso = default_iso(g);
    ASSERT_TRUE(iso);
    EXPECT_EQ(*iso, 600.0);
    EXPECT_FALSE(marching_cubes_indexed<double>(g, {.iso = 0.0}));
    const auto tri = marching_cubes_indexed<double>(g, {.iso = *iso});
    ASSERT_TRUE(tri);
    EXPECT_GT(tri->triangles.size(), 0u);
}

TEST(IsoLevel, a_nan_sample_is_named) {
    auto g = scan(6);
    g.set(1, 2, 3, std::numeric_limits<float>::quiet_NaN());
    const auto r = default_iso(g);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, errc::invalid_argument);
    EXPECT_NE(r.error().message.find("sample (1, 2, 3) is nan"), std::string::npos) << r.error().message;
}

TEST(IsoLevel, midpoint_of_extreme_values_does_not_overflow) {
    dense_grid<double> g(grid_geometry{{2, 2, 2}, {0, 0, 0}, {1, 1, 1}}, std::numeric_limits<double>::max());
    g.set(0, 0, 0, -std::numeric_limits<double>::max());
    const auto iso = default_iso(g);
    ASSERT_TRUE(iso);
    EXPECT_EQ(*iso, 0.0);
}

}  // namespace
