// The exact intersection tests agree with a separating-axis reference in integers on random
// small-integer triangles (many touch, share corners or lie in one plane), and decide the
// flat and coplanar cases the reference does not cover by construction.
#include <gtest/gtest.h>

#include <random>

#include <hmira/predicates/intersect3d.hpp>

#include "predicates/sat_reference.hpp"

namespace {

using namespace hmira::predicates;
using hmira_test::ivec;

point3 pt(const ivec& v) { return {double(v[0]), double(v[1]), double(v[2])}; }

bool proper(const std::array<ivec, 3>& t) {
    using namespace hmira_test;
    return !izero(icross(isub(t[1], t[0]), isub(t[2], t[0])));
}

std::array<ivec, 3> random_triangle(std::mt19937_64& rng, int range, bool flat_in_z) {
    std::uniform_int_distribution<int> c(0, range);
    std::array<ivec, 3> t;
    do {
        for (auto& v : t) v = {c(rng), c(rng), flat_in_z ? 0 : c(rng)};
    } while (!proper(t));
    return t;
}

TEST(triangles_intersect, agrees_with_separating_axes_on_random_small_triangles) {
    std::mt19937_64 rng(3);
    int meets = 0, total = 0;
    for (int n = 0; n < 6000; ++n) {
        const bool coplanar = n % 3 == 0;  // a third in the plane z = 0
        const auto s = random_triangle(rng, 4, coplanar), t = random_triangle(rng, 4, coplanar);
        const bool want = hmira_test::sat_triangles_meet(s, t);
        meets += want;
        ++total;
        ASSERT_EQ(triangles_intersect(pt(s[0]), pt(s[1]), pt(s[2]), pt(t[0]), pt(t[1]), pt(t[2])), want) << n;
        ASSERT_EQ(triangles_intersect(pt(t[1]), pt(t[2]), pt(t[0]), pt(s[2]), pt(s[1]), pt(s[0])), want) << n;
    }
    EXPECT_GT(meets, total / 5);
    EXPECT_LT(meets, total * 4 / 5);
}

TEST(segment_intersects_triangle, agrees_with_separating_axes_on_random_small_input) {
    std::mt19937_64 rng(4);
    std::uniform_int_distribution<int> c(0, 4);
    int meets = 0;
    for (int n = 0; n < 6000; ++n) {
        const bool coplanar = n % 3 == 0;
        const auto t = random_triangle(rng, 4, coplanar);
        ivec p, q;
        do {
            p = {c(rng), c(rng), coplanar ? 0 : c(rng)};
            q = {c(rng), c(rng), coplanar ? 0 : c(rng)};
        } while (p == q);
        const bool want = hmira_test::sat_segment_meets_triangle(p, q, t);
        meets += want;
        ASSERT_EQ(segment_intersects_triangle(pt(p), pt(q), pt(t[0]), pt(t[1]), pt(t[2])), want) << n;
        ASSERT_EQ(segment_intersects_triangle(pt(q), pt(p), pt(t[2]), pt(t[0]), pt(t[1])), want) << n;
    }
    EXPECT_GT(meets, 1000);
}

TEST(segment_intersects_triangle, treats_a_flat_triangle_as_its_edges) {
    const point3 a{0, 0, 0}, b{2, 0, 0}, c{1, 0, 0};  // collinear
    EXPECT_TRUE(segment_intersects_triangle({1, -1, 0}, {1, 1, 0}, a, b, c));
    EXPECT_TRUE(segment_intersects_triangle({2, 0, -1}, {2, 0, 1}, a, b, c));
    EXPECT_FALSE(segment_intersects_triangle({3, -1, 0}, {3, 1, 0}, a, b, c));
    EXPECT_FALSE(segment_intersects_triangle({1, 1, 0}, {1, 1, 1}, a, b, c));
}

TEST(segments_intersect, decides_collinear_overlap_touching_and_points) {
    EXPECT_TRUE(segments_intersect({0, 0, 0}, {2, 2, 2}, {1, 1, 1}, {3, 3, 3}));
    EXPECT_TRUE(segments_intersect({0, 0, 0}, {1, 1, 1}, {1, 1, 1}, {3, 3, 3}));
    EXPECT_FALSE(segments_intersect({0, 0, 0}, {1, 1, 1}, {1.5, 1.5, 1.5}, {3, 3, 3}));
    EXPECT_FALSE(segments_intersect({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0.5}));
    EXPECT_TRUE(point_on_segment({0.5, 0.5, 0}, {0, 0, 0}, {1, 1, 0}));
    EXPECT_FALSE(point_on_segment({0.5, 0.5, 0x1p-60}, {0, 0, 0}, {1, 1, 0}));
    EXPECT_TRUE(point_on_segment({1, 1, 1}, {1, 1, 1}, {1, 1, 1}));
}

TEST(point_in_triangle, is_closed_and_exact) {
    const point3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
    EXPECT_TRUE(point_in_triangle({0.5, 0.5, 0}, a, b, c));  // on the hypotenuse
    EXPECT_TRUE(point_in_triangle(b, a, b, c));
    EXPECT_FALSE(point_in_triangle({0.5, std::nextafter(0.5, 1.0), 0}, a, b, c));
    EXPECT_FALSE(point_in_triangle({0.25, 0.25, 0x1p-200}, a, b, c));
}

TEST(triangles_intersect, decides_a_crossing_a_few_ulps_away) {
    // Triangle def crosses the plane z = 0 or stops an ulp short of it.
    const point3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
    EXPECT_TRUE(triangles_intersect(a, b, c, {0.2, 0.2, 0}, {0.3, 0.2, 1}, {0.2, 0.3, 1}));
    EXPECT_FALSE(triangles_intersect(a, b, c, {0.2, 0.2, 0x1p-100}, {0.3, 0.2, 1}, {0.2, 0.3, 1}));
    EXPECT_TRUE(triangles_intersect(a, b, c, {0.2, 0.2, -0x1p-100}, {0.3, 0.2, 1}, {0.2, 0.3, 1}));
}

}  // namespace
