// triangulate_polygon on random simple polygons with holes, on integer coordinates so that
// doubled areas are exact: the triangles' areas sum to the polygon's exactly, each is wound
// counter-clockwise, and no two overlap (checked pairwise by separating axes, in integers).
// Non-simple input is refused with a message naming the loop.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include <hmira/algorithms/triangulation/triangulate_polygon.hpp>

namespace {

using hmira::point2;
using loops_t = std::vector<std::vector<std::size_t>>;

long long cross(const point2& a, const point2& b, const point2& c) {
    const long long ax = (long long)a[0], ay = (long long)a[1], bx = (long long)b[0], by = (long long)b[1], cx = (long long)c[0],
                    cy = (long long)c[1];
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}
int sgn(long long x) { return (x > 0) - (x < 0); }

/// Twice the signed area of a loop, in integers.
long long twice_area(const std::vector<point2>& p, const std::vector<std::size_t>& loop) {
    long long s = 0;
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const auto& a = p[loop[i]];
        const auto& b = p[loop[(i + 1) % loop.size()]];
        s += (long long)a[0] * (long long)b[1] - (long long)b[0] * (long long)a[1];
    }
    return s;
}

/// Whether closed segments meet, in integers (the test's own check, not the library's).
bool meet(const point2& a, const point2& b, const point2& c, const point2& d) {
    const int o1 = sgn(cross(a, b, c)), o2 = sgn(cross(a, b, d)), o3 = sgn(cross(c, d, a)), o4 = sgn(cross(c, d, b));
    auto on = [](const point2& p, const point2& q, const point2& r) {
        return std::min(p[0], q[0]) <= r[0] && r[0] <= std::max(p[0], q[0]) && std::min(p[1], q[1]) <= r[1] && r[1] <= std::max(p[1], q[1]);
    };
    if (o1 * o2 < 0 && o3 * o4 < 0) return true;
    return (o1 == 0 && on(a, b, c)) || (o2 == 0 && on(a, b, d)) || (o3 == 0 && on(c, d, a)) || (o4 == 0 && on(c, d, b));
}

bool simple(const std::vector<point2>& p, const loops_t& loops) {
    std::vector<std::array<std::size_t, 4>> segs;  // loop, pos, a, b
    for (std::size_t l = 0; l < loops.size(); ++l)
        for (std::size_t i = 0; i < loops[l].size(); ++i) segs.push_back({l, i, loops[l][i], loops[l][(i + 1) % loops[l].size()]});
    for (std::size_t i = 0; i < segs.size(); ++i)
        for (std::size_t j = i + 1; j < segs.size(); ++j) {
            const auto& s = segs[i];
            const auto& t = segs[j];
            const std::size_t k = loops[s[0]].size();
            if (s[0] == t[0] && (t[1] == (s[1] + 1) % k || s[1] == (t[1] + 1) % k)) {
                // consecutive: must not fold back
                const std::size_t far = t[2] == s[3] ? t[3] : t[2];
                const std::size_t near = t[2] == s[3] ? s[2] : s[3];
                const std::size_t mid = t[2] == s[3] ? s[3] : s[2];
                if (cross(p[near], p[mid], p[far]) == 0 &&
                    ((p[far][0] - p[mid][0]) * (p[near][0] - p[mid][0]) + (p[far][1] - p[mid][1]) * (p[near][1] - p[mid][1])) > 0)
                    return false;
                continue;
            }
            if (meet(p[s[2]], p[s[3]], p[t[2]], p[t[3]])) return false;
        }
    return true;
}

/// Whether two counter-clockwise triangles of positive area share interior points: not if an
/// edge of either has the whole other triangle on or right of its line.
bool overlap(const std::vector<point2>& p, const std::array<std::size_t, 3>& t, const std::array<std::size_t, 3>& u) {
    auto separates = [&](const std::array<std::size_t, 3>& x, const std::array<std::size_t, 3>& y) {
        for (int e = 0; e < 3; ++e) {
            bool all_out = true;
            for (int k = 0; k < 3; ++k)
                if (cross(p[x[e]], p[x[(e + 1) % 3]], p[y[k]]) > 0) all_out = false;
            if (all_out) return true;
        }
        return false;
    };
    return !separates(t, u) && !separates(u, t);
}

/// A random star-shaped outer loop, holes inside its inscribed disc, sometimes collinear
/// corners (edge midpoints) and thin spikes: simple by construction or re-drawn.
struct random_polygon {
    std::vector<point2> points;
    loops_t loops;
};

random_polygon make_polygon(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> unit(0, 1);
    for (;;) {
        random_polygon r;
        const std::size_t k = 6 + std::size_t(unit(rng) * 40);
        std::vector<double> angles;
        for (std::size_t i = 0; i < k; ++i) angles.push_back(2 * std::numbers::pi * (double(i) + 0.8 * unit(rng)) / double(k));
        r.loops.emplace_back();
        for (std::size_t i = 0; i < k; ++i) {
            const double rad = 600 + 400 * unit(rng);
            const point2 q{std::round(rad * std::cos(angles[i])), std::round(rad * std::sin(angles[i]))};
            r.loops[0].push_back(r.points.size());
            r.points.push_back(q);
            if (unit(rng) < 0.2) {  // a thin spike inwards: two corners nearly on one line
                const point2 s{std::round(q[0] * 0.55), std::round(q[1] * 0.55)};
                const point2 s2{s[0] + 1, s[1]};
                r.loops[0].push_back(r.points.size());
                r.points.push_back(s);
                r.loops[0].push_back(r.points.size());
                r.points.push_back(s2);
            }
        }
        // Collinear corners: the midpoint of an edge with an even coordinate sum.
        std::vector<std::size_t> outer;
        for (std::size_t i = 0; i < r.loops[0].size(); ++i) {
            outer.push_back(r.loops[0][i]);
            const auto& a = r.points[r.loops[0][i]];
            const auto& b = r.points[r.loops[0][(i + 1) % r.loops[0].size()]];
            if (std::fmod(a[0] + b[0], 2) == 0 && std::fmod(a[1] + b[1], 2) == 0 && unit(rng) < 0.5) {
                outer.push_back(r.points.size());
                r.points.push_back({(a[0] + b[0]) / 2, (a[1] + b[1]) / 2});
            }
        }
        r.loops[0] = outer;
        // Holes: small clockwise stars in distinct cells of a 100-unit lattice within radius 300.
        const std::size_t holes = std::size_t(unit(rng) * 6);
        std::vector<std::pair<int, int>> used;
        for (std::size_t h = 0; h < holes; ++h) {
            const int cx = int(unit(rng) * 7) - 3, cy = int(unit(rng) * 7) - 3;
            if (cx * cx + cy * cy > 9 || std::find(used.begin(), used.end(), std::pair{cx, cy}) != used.end()) continue;
            used.push_back({cx, cy});
            const std::size_t m = 3 + std::size_t(unit(rng) * 6);
            std::vector<std::size_t> ring;
            for (std::size_t i = 0; i < m; ++i) {
                const double a = -2 * std::numbers::pi * (double(i) + 0.7 * unit(rng)) / double(m);  // clockwise
                const double rad = 10 + 35 * unit(rng);
                ring.push_back(r.points.size());
                r.points.push_back({std::round(100.0 * cx + rad * std::cos(a)), std::round(100.0 * cy + rad * std::sin(a))});
            }
            r.loops.push_back(ring);
        }
        bool ok = simple(r.points, r.loops) && twice_area(r.points, r.loops[0]) > 0;
        for (std::size_t l = 1; l < r.loops.size() && ok; ++l) ok = twice_area(r.points, r.loops[l]) < 0;
        if (ok) return r;
    }
}

TEST(triangulate_polygon, random_polygons_with_holes_are_covered_exactly_without_overlap) {
    std::mt19937_64 rng(20261201);
    std::size_t with_holes = 0;
    for (int round = 0; round < 300; ++round) {
        const auto poly = make_polygon(rng);
        std::size_t corners = 0;
        long long expected = 0;
        for (const auto& l : poly.loops) {
            corners += l.size();
            expected += twice_area(poly.points, l);  // holes are clockwise: they subtract
        }
        with_holes += poly.loops.size() > 1;
        auto r = hmira::triangulate_polygon(poly.points, poly.loops);
        ASSERT_TRUE(r) << "round " << round << ": " << r.error().message;
        // Euler: a polygon with H holes and n corners has n + 2H - 2 triangles.
        EXPECT_EQ(r->size(), corners + 2 * (poly.loops.size() - 1) - 2) << "round " << round;
        long long sum = 0;
        for (const auto& t : *r) {
            const long long a = cross(poly.points[t[0]], poly.points[t[1]], poly.points[t[2]]);
            ASSERT_GE(a, 0) << "round " << round << ": a triangle is wound clockwise";
            sum += a;
        }
        ASSERT_EQ(sum, expected) << "round " << round;
        for (std::size_t i = 0; i < r->size(); ++i)
            for (std::size_t j = i + 1; j < r->size(); ++j) {
                if (cross(poly.points[(*r)[i][0]], poly.points[(*r)[i][1]], poly.points[(*r)[i][2]]) == 0 ||
                    cross(poly.points[(*r)[j][0]], poly.points[(*r)[j][1]], poly.points[(*r)[j][2]]) == 0)
                    continue;
                ASSERT_FALSE(overlap(poly.points, (*r)[i], (*r)[j])) << "round " << round << ": triangles " << i << " and " << j;
            }
    }
    EXPECT_GT(with_holes, 100u);
}

TEST(triangulate_polygon, a_nearly_degenerate_sliver_is_triangulated_exactly) {
    // A long thin concave polygon whose reflex corner lies 2^-40 off the chord: floating
    // orientation would call it collinear.
    const double e = std::ldexp(1.0, -40);
    const std::vector<point2> p{{0, 0}, {1, 0}, {2, 0}, {2, 1e-9}, {1, e}, {0, 1e-9}};
    const loops_t loops{{0, 1, 2, 3, 4, 5}};
    auto r = hmira::triangulate_polygon(p, loops);
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_EQ(r->size(), 4u);
    for (const auto& t : *r)
        EXPECT_GE(hmira::predicates::orient2d(p[t[0]][0], p[t[0]][1], p[t[1]][0], p[t[1]][1], p[t[2]][0], p[t[2]][1]), 0);
}

TEST(triangulate_polygon, non_simple_input_is_refused_naming_the_loop) {
    const std::vector<point2> p{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 1}, {1, 2}, {2, 2}, {10, 10}, {11, 10}, {10, 11}, {2, 1}};
    auto refused = [&](const loops_t& loops, const char* words) {
        auto r = hmira::triangulate_polygon(p, loops);
        ASSERT_FALSE(r) << words;
        EXPECT_NE(r.error().message.find(words), std::string::npos) << r.error().message;
    };
    refused({{0, 2, 1, 3}}, "not simple");                     // a bow tie
    refused({{0, 3, 2, 1}}, "not counter-clockwise");          // wound the wrong way
    refused({{0, 1, 2, 3}, {4, 6, 5}}, "loop 1 (a hole) is not clockwise");
    refused({{0, 1, 2, 3}, {7, 9, 8}}, "hole loop 1 is not inside");
    refused({{0, 1, 2, 3}, {4, 5, 6, 10}, {4, 6, 5}}, "not simple");  // two holes sharing corners
    refused({{0, 1}}, "fewer than 3");
    refused({{0, 1, 2, 99}}, "names point 99");
    refused({{0, 1, 2, 0, 3}}, "not simple");                  // a corner visited twice
    const std::vector<point2> bad{{0, 0}, {1, 0}, {std::numeric_limits<double>::quiet_NaN(), 1}};
    auto r = hmira::triangulate_polygon(bad, loops_t{{0, 1, 2}});
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, hmira::errc::invalid_argument);
}

}  // namespace
