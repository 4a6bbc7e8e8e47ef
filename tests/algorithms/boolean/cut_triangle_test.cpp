// cut_triangle, the per-triangle constrained triangulation of mesh_boolean, under random points and
// segments on a small integer grid, where collinear points and strips of crossed triangles that
// pass a vertex twice or enclose one are common. Checked directly after every insertion: every
// triangle is counter-clockwise, the areas sum to the input triangle's (exact on the grid), every
// inserted point is a corner, and every inserted segment is a union of edges.
#include <gtest/gtest.h>

#include <random>
#include <set>

#include <hmira/algorithms/boolean/detail/cut_triangle.hpp>

namespace {

using namespace hmira::detail::boolean;
namespace pr = hmira::predicates;

/// Twice the signed area of the projection of abc (drop z), exact for small integers.
double area2(const point3& a, const point3& b, const point3& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

/// Proper crossing of the open segments pq and rs (they share no point but one interior one).
bool cross(const point3& p, const point3& q, const point3& r, const point3& s) {
    auto o = [](const point3& a, const point3& b, const point3& c) {
        const double v = area2(a, b, c);
        return (v > 0) - (v < 0);
    };
    return o(p, q, r) * o(p, q, s) < 0 && o(r, s, p) * o(r, s, q) < 0;
}

/// True when some inserted point lies on the open segment pq.
bool passes_a_point(const std::vector<point3>& pts, const point3& p, const point3& q) {
    for (const point3& x : pts) {
        if (area2(p, q, x) != 0 || (x.x == p.x && x.y == p.y) || (x.x == q.x && x.y == q.y)) continue;
        if ((x.x - p.x) * (x.x - q.x) + (x.y - p.y) * (x.y - q.y) < 0) return true;
    }
    return false;
}

TEST(cut_triangle, random_grid_points_and_segments_keep_a_conforming_triangulation) {
    std::mt19937_64 g(7);
    const point3 corners[3] = {{0, 0, 0}, {24, 0, 0}, {0, 24, 0}};
    for (int round = 0; round < 60; ++round) {
        std::vector<point3> raw(corners, corners + 3);
        std::uniform_int_distribution<int> coord(0, 24);
        std::set<std::pair<int, int>> seen{{0, 0}, {24, 0}, {0, 24}};
        const int n = 4 + round % 20;
        while (int(raw.size()) < n + 3) {
            const int x = coord(g), y = coord(g);
            if (x + y > 24 || !seen.insert({x, y}).second) continue;
            raw.push_back({double(x), double(y), double(x + 2 * y)});  // a tilted plane, z dropped
        }
        std::vector<pr::exact_point> pts(raw.begin(), raw.end());
        cut_triangle t(pts, {0, 1, 2}, 2);
        for (vid p = 3; p < pts.size(); ++p) ASSERT_TRUE(t.insert_point(p));
        std::vector<std::array<vid, 2>> segments;
        std::uniform_int_distribution<vid> pick(0, vid(pts.size() - 1));
        for (int k = 0; k < 2 * n; ++k) {
            const vid a = pick(g), b = pick(g);
            bool ok = a != b;
            for (const auto& s : segments)
                ok = ok && !cross(raw[a], raw[b], raw[s[0]], raw[s[1]]) &&
                     !passes_a_point({raw[s[0]]}, raw[a], raw[b]) && !passes_a_point({raw[s[1]]}, raw[a], raw[b]) &&
                     !passes_a_point({raw[a]}, raw[s[0]], raw[s[1]]) && !passes_a_point({raw[b]}, raw[s[0]], raw[s[1]]);
            if (!ok) continue;  // crossing or overlapping an earlier segment: not a valid cut
            ASSERT_TRUE(t.insert_segment(a, b)) << round << " " << k;
            segments.push_back({a, b});
        }
        double sum = 0;
        std::set<vid> used;
        std::set<std::array<vid, 2>> edges;
        for (const tri3& f : t.triangles()) {
            const double s = area2(raw[f[0]], raw[f[1]], raw[f[2]]);
            EXPECT_GT(s, 0) << round;
            sum += s;
            for (std::size_t m = 0; m < 3; ++m) {
                used.insert(f[m]);
                edges.insert({std::min(f[m], f[(m + 1) % 3]), std::max(f[m], f[(m + 1) % 3])});
            }
        }
        EXPECT_EQ(sum, 24.0 * 24.0) << round;
        EXPECT_EQ(used.size(), pts.size()) << round;
        for (const auto& c : t.constraints()) EXPECT_TRUE(edges.count(c)) << round;
        // Each segment is covered by constraint pieces along it: the pieces on its line, between its ends.
        for (const auto& s : segments) {
            std::size_t covered = 0;
            for (const auto& c : t.constraints())
                if (area2(raw[s[0]], raw[s[1]], raw[c[0]]) == 0 && area2(raw[s[0]], raw[s[1]], raw[c[1]]) == 0)
                    ++covered;
            EXPECT_GT(covered, 0u) << round;
        }
    }
}

}  // namespace
