// orient3d on an implicit line-plane point: exact against big-integer arithmetic on the rational
// point, zero against its own plane, and consistent with the segment crossing it stands for.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <hmira/predicates/implicit_point.hpp>

#include "algorithms/delaunay/exact_reference.hpp"

namespace {

using namespace hmira::predicates;
using hmira_test::bigint;

bigint B(double v) { return bigint(static_cast<std::int64_t>(v)); }

struct bvec {
    bigint x, y, z;
};
bvec sub(const point3& a, const point3& b) { return {B(a.x) - B(b.x), B(a.y) - B(b.y), B(a.z) - B(b.z)}; }
bvec cross(const bvec& u, const bvec& v) {
    return {u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
}
bigint dot(const bvec& u, const bvec& v) { return u.x * v.x + u.y * v.y + u.z * v.z; }

/// The reference: x = (ld p + ln (q - p)) / ld as a rational, then CGAL's orientation of
/// (x, b, c, d), ((b - x) x (c - x)) . (d - x), with the denominator cleared.
int reference(const line_plane_point& x, const point3& b, const point3& c, const point3& d) {
    const bvec n = cross(sub(x.s, x.r), sub(x.t, x.r));
    const bvec qp = sub(x.q, x.p);
    const bigint ln = dot(n, sub(x.r, x.p)), ld = dot(n, qp);
    // ld * X, componentwise
    const bvec X{ld * B(x.p.x) + ln * qp.x, ld * B(x.p.y) + ln * qp.y, ld * B(x.p.z) + ln * qp.z};
    auto scaled = [&](const point3& v) { return bvec{ld * B(v.x) - X.x, ld * B(v.y) - X.y, ld * B(v.z) - X.z}; };
    // ld^3 * orientation: the sign of ld^3 is that of ld.
    return dot(cross(scaled(b), scaled(c)), scaled(d)).sign() * ld.sign();
}

point3 random_point(std::mt19937_64& rng, int range) {
    std::uniform_int_distribution<int> c(-range, range);
    return {double(c(rng)), double(c(rng)), double(c(rng))};
}

TEST(implicit_point, orient3d_matches_big_integers) {
    std::mt19937_64 rng(41);
    int zeros = 0, tested = 0;
    for (int n = 0; n < 3000; ++n) {
        line_plane_point x{random_point(rng, 3), random_point(rng, 3), random_point(rng, 3), random_point(rng, 3),
                           random_point(rng, 3)};
        if (dot(cross(sub(x.s, x.r), sub(x.t, x.r)), sub(x.q, x.p)).sign() == 0) continue;  // parallel
        const point3 b = random_point(rng, 3), c = random_point(rng, 3), d = random_point(rng, 3);
        const int want = reference(x, b, c, d);
        zeros += want == 0;
        ++tested;
        ASSERT_EQ(orient3d(x, b, c, d), want) << n;
    }
    EXPECT_GT(tested, 1000);
    EXPECT_GT(zeros, 10);
}

TEST(implicit_point, lies_on_its_plane_and_on_its_line) {
    std::mt19937_64 rng(42);
    for (int n = 0; n < 500; ++n) {
        line_plane_point x{random_point(rng, 1000), random_point(rng, 1000), random_point(rng, 1000),
                           random_point(rng, 1000), random_point(rng, 1000)};
        if (dot(cross(sub(x.s, x.r), sub(x.t, x.r)), sub(x.q, x.p)).sign() == 0 || collinear(x.r, x.s, x.t)) continue;
        EXPECT_EQ(orient3d(x, x.r, x.s, x.t), 0);
        // On the line pq: coplanar with p, q and any fourth point.
        EXPECT_EQ(orient3d(x, x.p, x.q, random_point(rng, 1000)), 0);
        // The rounded point is for output; here it exists.
        const point3 a = approximate(x);
        EXPECT_TRUE(std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z));
    }
}

}  // namespace
