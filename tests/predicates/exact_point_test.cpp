// Predicates on explicit and implicit points (line-plane, three-plane), checked against big-integer
// arithmetic on the rational points, on small integer input where ties are frequent; the filter
// must never change an answer, and points built in different ways that coincide must compare equal.
#include <gtest/gtest.h>

#include <random>

#include <hmira/predicates/exact_point.hpp>

#include "algorithms/delaunay/exact_reference.hpp"

namespace {

using namespace hmira::predicates;
using hmira_test::bigint;

bigint B(double v) { return bigint(static_cast<std::int64_t>(v)); }

/// A rational point (x, y, z) / w with w != 0, in big integers.
struct rpoint {
    bigint x, y, z, w;
    const bigint& at(int k) const { return k == 0 ? x : k == 1 ? y : z; }
};
struct bvec {
    bigint x, y, z;
};
bvec sub(const point3& a, const point3& b) { return {B(a.x) - B(b.x), B(a.y) - B(b.y), B(a.z) - B(b.z)}; }
bvec cross(const bvec& u, const bvec& v) {
    return {u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
}
bigint dot(const bvec& u, const bvec& v) { return u.x * v.x + u.y * v.y + u.z * v.z; }
bvec as_b(const point3& p) { return {B(p.x), B(p.y), B(p.z)}; }

rpoint ref(const point3& p) { return {B(p.x), B(p.y), B(p.z), bigint(1)}; }
rpoint ref(const line_plane_point& l) {
    const bvec n = cross(sub(l.s, l.r), sub(l.t, l.r)), qp = sub(l.q, l.p);
    const bigint ln = dot(n, sub(l.r, l.p)), ld = dot(n, qp);
    return {ld * B(l.p.x) + ln * qp.x, ld * B(l.p.y) + ln * qp.y, ld * B(l.p.z) + ln * qp.z, ld};
}
/// Three planes n_i . x = d_i, solved by determinants of the 3x3 system (columns replaced).
rpoint ref(const three_plane_point& t) {
    auto plane = [](const std::array<point3, 3>& p, bvec& n, bigint& d) {
        n = cross(sub(p[1], p[0]), sub(p[2], p[0]));
        d = dot(n, as_b(p[0]));
    };
    bvec n[3];
    bigint d[3];
    plane(t.a, n[0], d[0]);
    plane(t.b, n[1], d[1]);
    plane(t.c, n[2], d[2]);
    auto det = [](const bvec& r0, const bvec& r1, const bvec& r2) { return dot(r0, cross(r1, r2)); };
    const bvec c0{n[0].x, n[1].x, n[2].x}, c1{n[0].y, n[1].y, n[2].y}, c2{n[0].z, n[1].z, n[2].z};
    const bvec dd{d[0], d[1], d[2]};
    // Cramer with columns: det[c0 c1 c2] = det of the transposed rows.
    return {det(dd, c1, c2), det(c0, dd, c2), det(c0, c1, dd), det(c0, c1, c2)};
}

int ref_orient2d(int drop, const rpoint& a, const rpoint& b, const rpoint& c) {
    const int u = (drop + 1) % 3, v = (drop + 2) % 3;
    // orient2d(a / wa, b / wb, c / wc) scaled by wa^2 wb^2 wc^2 (positive) ... via the 3x3
    // homogeneous determinant times the sign of wa wb wc.
    const bigint d = a.at(u) * (b.at(v) * c.w - b.w * c.at(v)) - a.at(v) * (b.at(u) * c.w - b.w * c.at(u)) +
                     a.w * (b.at(u) * c.at(v) - b.at(v) * c.at(u));
    return d.sign() * a.w.sign() * b.w.sign() * c.w.sign();
}
int ref_compare(int k, const rpoint& a, const rpoint& b) {
    return (a.at(k) * b.w * b.w * a.w - b.at(k) * a.w * a.w * b.w).sign();
}

point3 rnd(std::mt19937_64& g, int r) {
    std::uniform_int_distribution<int> c(-r, r);
    return {double(c(g)), double(c(g)), double(c(g))};
}

/// A random point of each kind (small coordinates: many coincidences), with its reference.
std::pair<exact_point, rpoint> random_point(std::mt19937_64& g, int r) {
    for (;;) {
        const int k = int(g() % 3);
        if (k == 0) {
            const point3 p = rnd(g, r);
            return {exact_point(p), ref(p)};
        }
        if (k == 1) {
            line_plane_point l{rnd(g, r), rnd(g, r), rnd(g, r), rnd(g, r), rnd(g, r)};
            rpoint x = ref(l);
            if (x.w.sign() != 0) return {exact_point(l), x};
        } else {
            three_plane_point t{{rnd(g, r), rnd(g, r), rnd(g, r)},
                                {rnd(g, r), rnd(g, r), rnd(g, r)},
                                {rnd(g, r), rnd(g, r), rnd(g, r)}};
            rpoint x = ref(t);
            if (x.w.sign() != 0) return {exact_point(t), x};
        }
    }
}

TEST(exact_point, orient2d_matches_big_integers_on_every_kind) {
    std::mt19937_64 g(7);
    int zeros = 0;
    for (int n = 0; n < 3000; ++n) {
        auto [a, ra] = random_point(g, 2);
        auto [b, rb] = random_point(g, 2);
        auto [c, rc] = random_point(g, 2);
        const int drop = int(n % 3);
        const int want = ref_orient2d(drop, ra, rb, rc);
        zeros += want == 0;
        ASSERT_EQ(orient2d(drop, a, b, c), want) << n;
    }
    EXPECT_GT(zeros, 100);
}

TEST(exact_point, coordinate_order_matches_big_integers) {
    std::mt19937_64 g(8);
    int ties = 0;
    for (int n = 0; n < 3000; ++n) {
        auto [a, ra] = random_point(g, 2);
        auto [b, rb] = random_point(g, 2);
        for (int k = 0; k < 3; ++k) {
            const int want = ref_compare(k, ra, rb);
            ties += want == 0;
            ASSERT_EQ(compare_coordinate(k, a, b), want) << n << " axis " << k;
        }
    }
    EXPECT_GT(ties, 100);
}

TEST(exact_point, orient3d_against_a_plane_matches_big_integers) {
    std::mt19937_64 g(9);
    int zeros = 0;
    for (int n = 0; n < 2000; ++n) {
        const point3 a = rnd(g, 2), b = rnd(g, 2), c = rnd(g, 2);
        auto [d, rd] = random_point(g, 2);
        const bvec nrm = cross(sub(b, a), sub(c, a));
        const bvec dd{rd.x - B(a.x) * rd.w, rd.y - B(a.y) * rd.w, rd.z - B(a.z) * rd.w};
        const int want = dot(nrm, dd).sign() * rd.w.sign();
        zeros += want == 0;
        ASSERT_EQ(orient3d(a, b, c, d), want) << n;
    }
    EXPECT_GT(zeros, 50);
}

TEST(exact_point, three_plane_point_lies_on_its_planes) {
    std::mt19937_64 g(10);
    int tested = 0;
    for (int n = 0; n < 500; ++n) {
        three_plane_point t{{rnd(g, 1000), rnd(g, 1000), rnd(g, 1000)},
                            {rnd(g, 1000), rnd(g, 1000), rnd(g, 1000)},
                            {rnd(g, 1000), rnd(g, 1000), rnd(g, 1000)}};
        if (ref(t).w.sign() == 0) continue;
        ++tested;
        const exact_point x(t);
        EXPECT_EQ(orient3d(t.a[0], t.a[1], t.a[2], x), 0);
        EXPECT_EQ(orient3d(t.b[0], t.b[1], t.b[2], x), 0);
        EXPECT_EQ(orient3d(t.c[0], t.c[1], t.c[2], x), 0);
    }
    EXPECT_GT(tested, 400);
}

TEST(exact_point, one_point_built_three_ways_is_one_point) {
    // Two edges crossing at (1/3, 1/3, 0) inside the plane z = 0, and the three planes through it.
    const point3 o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
    // The line through (1/3 - 1, 1/3, -1) and (1/3 + 1, 1/3, 1) scaled by 3 to stay integral.
    const line_plane_point l1{{-2, 1, -3}, {4, 1, 3}, {0, 0, 0}, {3, 0, 0}, {0, 3, 0}};
    const line_plane_point l2{{1, -2, -3}, {1, 4, 3}, {0, 0, 0}, {3, 0, 0}, {0, 3, 0}};
    const three_plane_point t{{o, x, y},
                              {point3{1, 0, 0}, point3{1, 1, 0}, point3{1, 0, 1}},
                              {point3{0, 1, 0}, point3{1, 1, 0}, point3{0, 1, 1}}};
    const exact_point a(l1), b(l2), c(t), d(point3{1, 1, 0});
    EXPECT_TRUE(same_point(a, b));
    EXPECT_TRUE(same_point(a, c));
    EXPECT_TRUE(same_point(c, d));
    EXPECT_EQ(compare_xyz(a, exact_point(point3{1, 1, 1e-9})), -1);
    EXPECT_EQ(compare_xyz(a, exact_point(point3{1, 1, -1e-9})), 1);
    (void)z;
}

TEST(exact_point, filter_survives_large_and_tiny_coordinates) {
    // A crossing far from the origin, then one of tiny magnitude: same answers as exact.
    for (double s : {0x1p-20, 1e-3, 1.0, 1e6, 0x1p30}) {
        const line_plane_point l{{-s, 0.5 * s, -s}, {s, 0.5 * s, s}, {0, 0, 0}, {s, 0, 0}, {0, s, 0}};
        const exact_point p(l), q(point3{0, 0.5 * s, 0});
        EXPECT_TRUE(same_point(p, q)) << s;
        EXPECT_EQ(orient2d(2, exact_point(point3{-s, 0, 0}), exact_point(point3{s, 0, 0}), p), 1) << s;
        EXPECT_EQ(orient2d(2, exact_point(point3{-s, 0.5 * s, 0}), exact_point(point3{s, 0.5 * s, 0}), p), 0) << s;
    }
}

}  // namespace

namespace {

// The filter must settle the common case on its own: random line-plane points in general
// position against random explicit points, every interval sign decided and equal to the exact one.
TEST(exact_point, filter_decides_general_position) {
    std::mt19937_64 g(11);
    std::uniform_real_distribution<double> u(-1, 1);
    auto rp = [&] { return point3{u(g), u(g), u(g)}; };
    int decided = 0;
    for (int n = 0; n < 2000; ++n) {
        const exact_point x(line_plane_point{rp(), rp(), rp(), rp(), rp()}), a(rp()), b(rp());
        const int f = detail::orient2d_homogeneous<detail::interval>(n % 3, a, b, x).sign();
        const int e = detail::orient2d_homogeneous<detail::exact_number>(n % 3, a, b, x).sign();
        if (f != 2) {
            ++decided;
            ASSERT_EQ(f, e) << n;
        }
        const int fc = detail::compare_homogeneous<detail::interval>(0, x, a).sign();
        if (fc != 2) {
            ASSERT_EQ(fc, detail::compare_homogeneous<detail::exact_number>(0, x, a).sign()) << n;
        }
    }
    EXPECT_GT(decided, 1990);
}

}  // namespace
