// triangulate_polygon on random simple polygons with holes, on integer coordinates so that
// doubled areas are exact: the triangles' areas sum to the polygon's exactly, each is wound
// counter-clockwise, and no two overlap (checked pairwise by separating axes, in integers).
// Non-simple input is refused with a message naming the loop.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <random>
#include <vector>

#include <hmira/algorithms/triangulation/triangulate_polygon.hpp>

namespace {

using hmira::point2;
using loops_t = std::vector<std::vector<std::size_t>>;

long long cross(const point2& a, const point2& b, const point2& c) {
    const long long ax = (long long)a[0], ay = (long long)a[1], bx = (long long)b[0], by = (long long)b[1],
                    cx = (long long)c[0], cy = (long long)c[1];
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
        return std::min(p[0], q[0]) <= r[0] && r[0] <= std::max(p[0], q[0]) && std::min(p[1], q[1]) <= r[1] &&
               r[1] <= std::max(p[1], q[1]);
    };
    if (o1 * o2 < 0 && o3 * o4 < 0) return true;
    return (o1 == 0 && on(a, b, c)) || (o2 == 0 && on(a, b, d)) || (o3 == 0 && on(c, d, a)) || (o4 == 0 && on(c, d, b));
}

bool simple(const std::vector<point2>& p, const loops_t& loops) {
    std::vector<std::array<std::size_t, 4>> segs;  // loop, pos, a, b
    for (std::size_t l = 0; l < loops.size(); ++l)
        for (std::size_t i = 0; i < loops[l].size(); ++i)
            segs.push_back({l, i, loops[l][i], loops[l][(i + 1) % loops[l].size()]});
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
                if (cross(p[near], p[mid], p[far]) == 0 && ((p[far][0] - p[mid][0]) * (p[near][0] - p[mid][0]) +
                                                            (p[far][1] - p[mid][1]) * (p[near][1] - p[mid][1])) > 0)
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

/// No two triangles of positive area share interior points (all pairs, in integers).
void expect_no_overlap(const std::vector<point2>& p, const std::vector<std::array<std::size_t, 3>>& tris, int round) {
    for (std::size_t i = 0; i < tris.size(); ++i)
        for (std::size_t j = i + 1; j < tris.size(); ++j) {
            if (cross(p[tris[i][0]], p[tris[i][1]], p[tris[i][2]]) == 0 ||
                cross(p[tris[j][0]], p[tris[j][1]], p[tris[j][2]]) == 0)
                continue;
            ASSERT_FALSE(overlap(p, tris[i], tris[j])) << "round " << round << ": triangles " << i << " and " << j;
        }
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
        for (std::size_t i = 0; i < k; ++i)
            angles.push_back(2 * std::numbers::pi * (double(i) + 0.8 * unit(rng)) / double(k));
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
                r.points.push_back(
                    {std::round(100.0 * cx + rad * std::cos(a)), std::round(100.0 * cy + rad * std::sin(a))});
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
        ASSERT_NO_FATAL_FAILURE(expect_no_overlap(poly.points, *r, round));
    }
    EXPECT_GT(with_holes, 100u);
}

/// Checks a triangulation of one counter-clockwise loop without looking at every pair: every
/// loop edge is used once, every other edge twice in opposite directions, every triangle is
/// counter-clockwise, and the areas add up exactly. A disc whose triangles all wind positively
/// and whose boundary is the simple loop covers each point once, so nothing overlaps.
void expect_exact_disc(const std::vector<point2>& p, const std::vector<std::size_t>& loop,
                       const std::vector<std::array<std::size_t, 3>>& tris) {
    ASSERT_EQ(tris.size(), loop.size() - 2);
    std::map<std::pair<std::size_t, std::size_t>, int> uses;
    long long sum = 0;
    for (const auto& t : tris) {
        const long long a = cross(p[t[0]], p[t[1]], p[t[2]]);
        ASSERT_GE(a, 0) << "a triangle is wound clockwise";
        sum += a;
        for (int k = 0; k < 3; ++k) ++uses[{t[k], t[(k + 1) % 3]}];
    }
    ASSERT_EQ(sum, twice_area(p, loop));
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const std::pair<std::size_t, std::size_t> e{loop[i], loop[(i + 1) % loop.size()]};
        ASSERT_EQ(uses[e], 1) << "loop edge " << i;
        uses.erase(e);
    }
    for (const auto& [e, n] : uses) {
        ASSERT_EQ(n, 1) << "edge " << e.first << "-" << e.second << " used twice the same way";
        ASSERT_EQ(uses.count({e.second, e.first}), 1u) << "inner edge " << e.first << "-" << e.second << " has no twin";
    }
}

/// The in-circle determinant of d against counter-clockwise a, b, c, in integers (the test's
/// own, not the library's): positive when d lies strictly inside.
int incircle_sign(const point2& a, const point2& b, const point2& c, const point2& d) {
    using i128 = __int128;
    const i128 adx = i128(a[0] - d[0]), ady = i128(a[1] - d[1]), bdx = i128(b[0] - d[0]), bdy = i128(b[1] - d[1]),
               cdx = i128(c[0] - d[0]), cdy = i128(c[1] - d[1]);
    const i128 det = (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
                     (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
                     (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
    return (det > 0) - (det < 0);
}

/// The smallest angle of any triangle of positive area, in radians.
double smallest_angle(const std::vector<point2>& p, const std::vector<std::array<std::size_t, 3>>& tris) {
    double best = std::numbers::pi;
    for (const auto& t : tris) {
        if (cross(p[t[0]], p[t[1]], p[t[2]]) == 0) continue;
        for (int k = 0; k < 3; ++k) {
            const auto& o = p[t[k]];
            const auto& u = p[t[(k + 1) % 3]];
            const auto& v = p[t[(k + 2) % 3]];
            const double ux = u[0] - o[0], uy = u[1] - o[1], vx = v[0] - o[0], vy = v[1] - o[1];
            best = std::min(best, std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy));
        }
    }
    return best;
}

TEST(triangulate_polygon, the_delaunay_option_gives_locally_delaunay_triangles_with_a_larger_smallest_angle) {
    std::mt19937_64 rng(20261202);
    std::size_t improved = 0;
    for (int round = 0; round < 300; ++round) {
        const auto poly = make_polygon(rng);
        long long expected = 0;
        for (const auto& l : poly.loops) expected += twice_area(poly.points, l);
        auto plain = hmira::triangulate_polygon(poly.points, poly.loops);
        auto r = hmira::triangulate_polygon(poly.points, poly.loops, {.delaunay = true});
        ASSERT_TRUE(plain && r) << "round " << round;
        ASSERT_EQ(r->size(), plain->size()) << "round " << round;
        long long sum = 0;
        std::map<std::pair<std::size_t, std::size_t>, std::pair<std::size_t, int>>
            side;  // -> triangle, corner opposite
        for (std::size_t i = 0; i < r->size(); ++i) {
            const auto& t = (*r)[i];
            const long long a = cross(poly.points[t[0]], poly.points[t[1]], poly.points[t[2]]);
            ASSERT_GE(a, 0) << "round " << round;
            sum += a;
            for (int k = 0; k < 3; ++k) side[{t[k], t[(k + 1) % 3]}] = {i, (k + 2) % 3};
        }
        ASSERT_EQ(sum, expected) << "round " << round;
        ASSERT_NO_FATAL_FAILURE(expect_no_overlap(poly.points, *r, round));
        // Locally Delaunay: across every inner side of two proper triangles forming a convex
        // quadrilateral, the far corner is not strictly inside the circumcircle.
        for (const auto& [e, tk] : side) {
            const auto it = side.find({e.second, e.first});
            if (it == side.end()) continue;
            const auto& t = (*r)[tk.first];
            const auto& u = (*r)[it->second.first];
            const auto& P = poly.points;
            const auto a = e.first, b = e.second, c = t[std::size_t(tk.second)], d = u[std::size_t(it->second.second)];
            if (cross(P[a], P[b], P[c]) <= 0 || cross(P[b], P[a], P[d]) <= 0 || cross(P[d], P[c], P[a]) <= 0 ||
                cross(P[c], P[d], P[b]) <= 0)
                continue;
            ASSERT_LE(incircle_sign(P[a], P[b], P[c], P[d]), 0) << "round " << round << ": side " << a << "-" << b;
        }
        const double before = smallest_angle(poly.points, *plain), after = smallest_angle(poly.points, *r);
        EXPECT_GE(after, before - 1e-12) << "round " << round;
        improved += after > before + 1e-9;
    }
    EXPECT_GT(improved, 100u);  // ear clipping leaves slivers that the flips remove
}

TEST(triangulate_polygon, random_loops_on_a_small_lattice_are_refused_exactly_when_not_simple) {
    // Corners on a 5 x 5 lattice: collinear runs, touching edges, repeated corners and folds
    // are everywhere. The library's verdict must match the test's own all-pairs check.
    std::mt19937_64 rng(7);
    std::uniform_int_distribution<int> coord(0, 4), size(3, 9);
    std::vector<point2> lattice;
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 5; ++x) lattice.push_back({double(x), double(y)});
    std::size_t accepted = 0, refused = 0;
    for (int round = 0; round < 20000; ++round) {
        std::vector<std::size_t> loop;
        const int n = size(rng);
        for (int i = 0; i < n; ++i) loop.push_back(std::size_t(coord(rng) * 5 + coord(rng)));
        const loops_t loops{loop};
        auto r = hmira::triangulate_polygon(lattice, loops);
        if (simple(lattice, loops) && twice_area(lattice, loop) > 0) {
            ASSERT_TRUE(r) << "round " << round << ": " << r.error().message;
            expect_exact_disc(lattice, loop, *r);
            ++accepted;
        } else {
            ASSERT_FALSE(r) << "round " << round
                            << ": a loop that is not simple, or is clockwise or flat, was triangulated";
            EXPECT_EQ(r.error().code, hmira::errc::topology) << r.error().message;
            ++refused;
        }
    }
    EXPECT_GT(accepted, 500u);
    EXPECT_GT(refused, 500u);
}

TEST(triangulate_polygon, big_jagged_polygons_take_near_linear_time_and_stay_exact) {
    // Star-shaped loops with many corners: a smooth circle, alternating spikes (half the
    // corners reflex) and random radii (reflex corners everywhere). All-pairs tests would take
    // minutes here; the sweeps take well under a second each (ctest TIMEOUT).
#ifdef HMIRA_SANITIZER_BUILD
    const std::size_t n = 20000;
#else
    const std::size_t n = 200000;
#endif
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0, 1);
    for (int kind = 0; kind < 3; ++kind) {
        std::vector<point2> p;
        std::vector<std::size_t> loop;
        for (std::size_t i = 0; i < n; ++i) {
            const double a = 2 * std::numbers::pi * double(i) / double(n);
            const double rad = 1e6 * (kind == 0 ? 1.0 : kind == 1 ? (i % 2 ? 0.5 : 1.0) : 0.7 + 0.3 * unit(rng));
            loop.push_back(p.size());
            p.push_back({std::round(rad * std::cos(a)), std::round(rad * std::sin(a))});
        }
        auto r = hmira::triangulate_polygon(p, loops_t{loop});
        ASSERT_TRUE(r) << "kind " << kind << ": " << r.error().message;
        expect_exact_disc(p, loop, *r);
    }
}

TEST(triangulate_polygon, a_polygon_with_thousands_of_holes_is_refused_in_bounded_time) {
    // Each hole is checked against the outer loop and every other hole: quadratic in the
    // holes, so 20,000 of them must hit the work limit and be refused, not run for an hour.
    std::vector<point2> p{{0, 0}, {1000, 0}, {1000, 1000}, {0, 1000}};
    loops_t loops{{0, 1, 2, 3}};
    for (int y = 0; y < 200; ++y)
        for (int x = 0; x < 100; ++x) {
            const double x0 = 5.0 * x + 2, y0 = 5.0 * y + 2;
            loops.push_back({p.size(), p.size() + 1, p.size() + 2});  // clockwise
            p.push_back({x0, y0});
            p.push_back({x0, y0 + 1});
            p.push_back({x0 + 1, y0});
        }
    auto r = hmira::triangulate_polygon(p, loops);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, hmira::errc::unsupported);
    EXPECT_NE(r.error().message.find("60004 corners are too intricate"), std::string::npos) << r.error().message;
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
        EXPECT_GE(hmira::predicates::orient2d(p[t[0]][0], p[t[0]][1], p[t[1]][0], p[t[1]][1], p[t[2]][0], p[t[2]][1]),
                  0);
}

TEST(triangulate_polygon, non_simple_input_is_refused_naming_the_loop) {
    const std::vector<point2> p{{0, 0}, {4, 0},   {4, 4},   {0, 4},   {1, 1}, {1, 2},
                                {2, 2}, {10, 10}, {11, 10}, {10, 11}, {2, 1}};
    auto refused = [&](const loops_t& loops, const char* words) {
        auto r = hmira::triangulate_polygon(p, loops);
        ASSERT_FALSE(r) << words;
        EXPECT_NE(r.error().message.find(words), std::string::npos) << r.error().message;
    };
    refused({{0, 2, 1, 3}}, "not simple");             // a bow tie
    refused({{0, 3, 2, 1}}, "not counter-clockwise");  // wound the wrong way
    refused({{0, 1, 2, 3}, {4, 6, 5}}, "loop 1 (a hole) is not clockwise");
    refused({{0, 1, 2, 3}, {7, 9, 8}}, "hole loop 1 is not inside");
    refused({{0, 1, 2, 3}, {4, 5, 6, 10}, {4, 6, 5}}, "not simple");  // two holes sharing corners
    refused({{0, 1}}, "fewer than 3");
    refused({{0, 1, 2, 99}}, "names point 99");
    refused({{0, 1, 2, 0, 3}}, "not simple");  // a corner visited twice
    const std::vector<point2> bad{{0, 0}, {1, 0}, {std::numeric_limits<double>::quiet_NaN(), 1}};
    auto r = hmira::triangulate_polygon(bad, loops_t{{0, 1, 2}});
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, hmira::errc::invalid_argument);
}

}  // namespace
