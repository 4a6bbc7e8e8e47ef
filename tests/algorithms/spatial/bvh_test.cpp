// bvh: every query agrees with a brute-force scan written here with other formulas (plane
// projection, point-in-polygon on the whole face, edge clamping; plane hit plus the same
// point-in-polygon), on random meshes of every model and on concave polygon faces, so a fan or
// a wrong triangulation shows up. Degenerate triangles never hit; refit answers as a rebuild and
// refitting back gives the same tree; a tree refuses a mesh whose connectivity changed; the tree
// and the answers do not depend on the thread count; non-finite queries are refused by index or
// propagate as NaN.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <type_traits>
#include <vector>

#include <hmira/algorithms/spatial/bvh.hpp>
#include <hmira/algorithms/triangle/flip_edge.hpp>

#include "algorithms/euler/euler_support.hpp"
#include "support/models.hpp"
#include "support/shapes.hpp"

namespace {

using namespace hmira_test;
using v3 = hmira::vec3<double>;
constexpr double inf = std::numeric_limits<double>::infinity();

#ifdef HMIRA_SANITIZER_BUILD
constexpr int queries = 40;
constexpr std::size_t grid_n = 6;
#else
constexpr int queries = 200;
constexpr std::size_t grid_n = 12;
#endif

/// A face as the brute force sees it: its index and its corners' positions.
struct polygon {
    std::size_t face;
    std::vector<v3> corners;
};

template <class M, class T = hmira::default_traits<M>>
std::vector<polygon> polygons_of(const M& m) {
    std::vector<polygon> out;
    for (auto f : T::faces(m)) {
        polygon p{T::face_index(m, f), {}};
        for (auto v : T::face_vertices(m, f)) {
            const auto q = T::position(m, v);
            p.corners.push_back({double(q[0]), double(q[1]), double(q[2])});
        }
        out.push_back(std::move(p));
    }
    return out;
}

v3 closest_on_segment(const v3& p, const v3& a, const v3& b) {
    const v3 d = b - a;
    const double l2 = hmira::dot(d, d);
    if (l2 == 0) return a;
    return a + d * std::clamp(hmira::dot(p - a, d) / l2, 0.0, 1.0);
}

v3 newell(const polygon& g) {
    v3 n{};
    for (std::size_t i = 0; i < g.corners.size(); ++i) {
        const v3 &a = g.corners[i], &b = g.corners[(i + 1) % g.corners.size()];
        n = n + v3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
    }
    return n;
}

/// Whether q (in the polygon's plane) is inside it: crossing number in the projection that
/// drops the normal's largest coordinate.
bool inside(const polygon& g, const v3& q, const v3& n) {
    const std::size_t k =
        std::abs(n.x) >= std::abs(n.y) && std::abs(n.x) >= std::abs(n.z) ? 0 : (std::abs(n.y) >= std::abs(n.z) ? 1 : 2);
    const std::size_t u = (k + 1) % 3, w = (k + 2) % 3;
    bool in = false;
    for (std::size_t i = 0, j = g.corners.size() - 1; i < g.corners.size(); j = i++) {
        const v3 &a = g.corners[i], &b = g.corners[j];
        if ((a[w] > q[w]) != (b[w] > q[w]) && q[u] < (b[u] - a[u]) * (q[w] - a[w]) / (b[w] - a[w]) + a[u]) in = !in;
    }
    return in;
}

/// Distance from p to a planar polygon (projection if inside, else the nearest edge).
double polygon_distance(const polygon& g, const v3& p) {
    const v3 n = newell(g);
    const double n2 = hmira::dot(n, n);
    if (n2 > 0) {
        const v3 q = p - n * (hmira::dot(p - g.corners[0], n) / n2);
        if (inside(g, q, n)) return hmira::norm(q - p);
    }
    double best = inf;
    for (std::size_t i = 0; i < g.corners.size(); ++i)
        best =
            std::min(best, hmira::norm(closest_on_segment(p, g.corners[i], g.corners[(i + 1) % g.corners.size()]) - p));
    return best;
}

/// Parameter of the ray's hit with a planar polygon, or infinity.
double polygon_ray(const polygon& g, const hmira::ray& r) {
    const v3 n = newell(g);
    const double den = hmira::dot(n, r.direction);
    if (den == 0) return inf;
    const double t = hmira::dot(g.corners[0] - r.origin, n) / den;
    if (!(t >= r.t_min && t <= r.t_max)) return inf;
    return inside(g, r.origin + r.direction * t, n) ? t : inf;
}

struct brute {
    double distance = inf;
    double t = inf;
    std::size_t hits = 0;
};

brute brute_force(const std::vector<polygon>& polys, const v3& p, const hmira::ray& r) {
    brute b;
    for (const auto& g : polys) {
        b.distance = std::min(b.distance, polygon_distance(g, p));
        const double t = polygon_ray(g, r);
        if (t < inf) ++b.hits, b.t = std::min(b.t, t);
    }
    return b;
}

const polygon& face_named(const std::vector<polygon>& polys, std::size_t face) {
    for (const auto& g : polys)
        if (g.face == face) return g;
    ADD_FAILURE() << "no face " << face;
    return polys.front();
}

/// Checks all four queries at random points and rays in the box [lo, hi]^3 against brute force.
/// A ray whose brute-force answer lies within `graze` of a polygon edge may go either way.
/// `eps`: the relative tolerance; float models store planar polygons only up to float rounding.
void check_queries(const hmira::bvh& tree, const std::vector<polygon>& polys, unsigned seed, double lo, double hi,
                   double eps = 1e-9) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> pos(lo, hi), dir(-1, 1);
    int compared_hits = 0;
    for (int i = 0; i < queries; ++i) {
        const v3 p{pos(rng), pos(rng), pos(rng)};
        // Every other ray aims at a point inside some face's corners' hull, so that enough hit.
        v3 d{dir(rng), dir(rng), dir(rng)};
        if (i % 2 == 1) {
            const auto& g = polys[std::size_t(rng() % polys.size())];
            const double s = 0.5 * (dir(rng) + 1), t = 0.5 * (dir(rng) + 1) * (1 - s);
            d = g.corners[0] * (1 - s - t) + g.corners[g.corners.size() / 2] * s + g.corners.back() * t - p;
        }
        const hmira::ray r{.origin = p, .direction = d};
        const brute b = brute_force(polys, p, r);
        const double tol = eps * (1 + b.distance);
        const auto c = tree.closest_point(p);
        ASSERT_TRUE(c.found());
        ASSERT_NEAR(c.distance, b.distance, tol) << "query " << i;
        EXPECT_NEAR(hmira::norm(c.point - p), c.distance, tol);
        EXPECT_NEAR(polygon_distance(face_named(polys, c.face), c.point), 0, tol) << "the point is on its face";
        EXPECT_NEAR(c.barycentric[0] + c.barycentric[1] + c.barycentric[2], 1, 1e-12);
        // Within a maximum distance: found exactly when the closest point is that close.
        const auto near = tree.closest_point(p, {.max_distance = b.distance * 0.5});
        EXPECT_FALSE(near.found());
        const auto within = tree.closest_point(p, {.max_distance = b.distance * 1.01 + 1e-12});
        EXPECT_TRUE(within.found());

        const auto h = tree.first_hit(r);
        const auto all = tree.all_hits(r);
        EXPECT_EQ(tree.any_hit(r), h.found());
        EXPECT_EQ(h.found(), !all.empty());
        for (std::size_t k = 1; k < all.size(); ++k) EXPECT_LE(all[k - 1].t, all[k].t);
        if (h.found()) {
            EXPECT_EQ(all.front().t, h.t);
            EXPECT_NEAR(polygon_distance(face_named(polys, h.face), h.point), 0, eps * (1 + h.t));
        }
        if (b.t < inf && h.found()) {
            EXPECT_NEAR(h.t, b.t, eps * (1 + b.t)) << "query " << i;
            ++compared_hits;
        } else if (b.t < inf || h.found()) {
            // Only a graze: the hit point lies on a polygon's edge, up to rounding.
            const v3 q = h.found() ? h.point : r.origin + r.direction * b.t;
            double edge = inf;
            for (const auto& g : polys)
                for (std::size_t k = 0; k < g.corners.size(); ++k)
                    edge = std::min(
                        edge,
                        hmira::norm(closest_on_segment(q, g.corners[k], g.corners[(k + 1) % g.corners.size()]) - q));
            EXPECT_LT(edge, eps) << "query " << i << " brute " << b.t << " tree " << h.t;
        } else {
            EXPECT_EQ(b.hits, 0u);
        }
        if (h.found() && b.t < inf) {
            EXPECT_LE(std::abs(double(all.size()) - double(b.hits)), 1.0);
        }
    }
    EXPECT_GT(compared_hits, queries / 10) << "the rays should hit often enough to test something";
}

/// A jittered grid of triangles over [0, 1]^2 with random heights, and its brute-force faces.
face_list random_terrain(std::size_t n, unsigned seed) {
    face_list g = grid(n, n, true);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> jitter(-0.3, 0.3), height(-0.5, 0.5);
    for (auto& p : g.points) p = {(p.x + jitter(rng)) / double(n), (p.y + jitter(rng)) / double(n), height(rng)};
    return g;
}

template <class M>
class bvh_test : public ::testing::Test {};
TYPED_TEST_SUITE(bvh_test, all_models);

TYPED_TEST(bvh_test, every_query_matches_brute_force_on_a_random_mesh) {
    using M = TypeParam;
    M m = mesh_from<M>(random_terrain(grid_n, 5));
    auto tree = hmira::build_bvh(m);
    ASSERT_TRUE(tree) << tree.error().message;
    const auto polys = polygons_of(m);
    EXPECT_EQ(tree->size(), polys.size());
    check_queries(*tree, polys, 17, -0.2, 1.2);
    // The mesh-taking entry points give the member's answers.
    const v3 p{0.3, 0.4, 0.9};
    const hmira::ray r{.origin = p, .direction = {0.1, -0.2, -1}};
    const auto c = hmira::closest_point(m, *tree, p);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->distance, tree->closest_point(p).distance);
    const auto h = hmira::ray_first_hit(m, *tree, r);
    ASSERT_TRUE(h);
    EXPECT_EQ(h->t, tree->first_hit(r).t);
    EXPECT_TRUE(h->found());
    EXPECT_EQ(*hmira::ray_any_hit(m, *tree, r), true);
    EXPECT_EQ(hmira::ray_all_hits(m, *tree, r)->size(), tree->all_hits(r).size());
}

/// Concave, star-shaped planar polygons in tilted planes, their first corner reflex, so that a
/// fan from it would cover the notches: queries into the notches tell them apart.
face_list concave_stars(unsigned seed) {
    face_list g;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    for (int s = 0; s < 6; ++s) {
        const v3 centre{u(rng) * 3, u(rng) * 3, u(rng) * 3};
        const v3 e1 = hmira::normalized(v3{u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5});
        const v3 e2 = hmira::normalized(hmira::cross(e1, v3{u(rng) - 0.5, u(rng) - 0.5, 1.0}));
        const std::size_t k = 5 + std::size_t(s), first = g.points.size();
        std::vector<std::size_t> loop;
        for (std::size_t i = 0; i < 2 * k; ++i) {
            const double a = 2 * std::numbers::pi * double(i) / double(2 * k);
            const double radius = i % 2 == 0 ? 0.3 : 1.0;  // corner 0 is an inner, reflex corner
            g.points.push_back(centre + e1 * (radius * std::cos(a)) + e2 * (radius * std::sin(a)));
            loop.push_back(first + i);
        }
        g.faces.push_back(loop);
    }
    return g;
}

TYPED_TEST(bvh_test, concave_faces_are_cut_in_their_plane_not_fanned) {
    using M = TypeParam;
    using T = hmira::default_traits<M>;
    if constexpr (requires { requires T::triangles_only; }) {
        GTEST_SKIP() << "triangles only";
    } else {
        M m = mesh_from<M>(concave_stars(3));
        auto tree = hmira::build_bvh(m);
        ASSERT_TRUE(tree) << tree.error().message;
        const auto polys = polygons_of(m);
        ASSERT_EQ(polys.size(), 6u);
        const double eps = std::is_same_v<typename T::scalar, float> ? 1e-5 : 1e-9;
        check_queries(*tree, polys, 29, -1, 4, eps);
        // A ray straight through the notch beyond each reflex corner (a fan from corner 0
        // covers some of them) misses the face; one through its centre hits it.
        for (const auto& g : polys) {
            const v3 n = hmira::normalized(newell(g));
            v3 centre{};
            for (const auto& q : g.corners) centre = centre + q * (1.0 / double(g.corners.size()));
            for (std::size_t j = 0; j < g.corners.size(); j += 2) {
                const v3 notch = centre + (g.corners[j] - centre) * 1.03;
                ASSERT_FALSE(inside(g, notch, n));
                for (const auto& h :
                     tree->all_hits({.origin = notch + n, .direction = n * -1, .t_min = 0.5, .t_max = 1.5}))
                    EXPECT_NE(h.face, g.face) << "corner " << j;
            }
            const auto h = tree->first_hit({.origin = centre + n, .direction = n * -1});
            ASSERT_TRUE(h.found());
            EXPECT_EQ(h.face, g.face);
            EXPECT_NEAR(h.t, 1, eps);
        }
    }
}

template <class M, class T = hmira::default_traits<M>>
void move_vertices(M& m, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> d(-0.05, 0.05);
    using S = typename T::scalar;
    for (auto v : T::vertices(m)) {
        const auto p = T::position(m, v);
        T::set_position(m, v, hmira::vec3<S>{S(p[0] + d(rng)), S(p[1] + d(rng)), S(p[2] + d(rng))});
    }
}

TYPED_TEST(bvh_test, refit_answers_as_a_rebuild_and_refitting_back_restores_the_tree) {
    using M = TypeParam;
    using T = hmira::default_traits<M>;
    if constexpr (!hmira::position_mutable_mesh<M, T>) {
        GTEST_SKIP() << "positions cannot move";
    } else {
        M m = mesh_from<M>(random_terrain(grid_n, 8));
        auto tree = hmira::build_bvh(m);
        ASSERT_TRUE(tree);
        const hmira::bvh original = *tree;
        std::vector<hmira::vec3<typename T::scalar>> before;
        for (auto v : T::vertices(m)) before.push_back(T::position(m, v));
        move_vertices(m, 1);
        ASSERT_TRUE(hmira::refit_bvh(m, *tree));
        EXPECT_FALSE(*tree == original);
        auto rebuilt = hmira::build_bvh(m);
        ASSERT_TRUE(rebuilt);
        std::mt19937_64 rng(4);
        std::uniform_real_distribution<double> pos(-0.2, 1.2), dir(-1, 1);
        for (int i = 0; i < queries; ++i) {
            const v3 p{pos(rng), pos(rng), pos(rng)};
            EXPECT_EQ(tree->closest_point(p).distance, rebuilt->closest_point(p).distance);
            const hmira::ray r{.origin = p, .direction = {dir(rng), dir(rng), dir(rng)}};
            EXPECT_EQ(tree->first_hit(r).t, rebuilt->first_hit(r).t);
            EXPECT_EQ(tree->all_hits(r).size(), rebuilt->all_hits(r).size());
        }
        check_queries(*tree, polygons_of(m), 41, -0.2, 1.2);
        std::size_t k = 0;
        for (auto v : T::vertices(m)) T::set_position(m, v, before[k++]);
        ASSERT_TRUE(hmira::refit_bvh(m, *tree));
        EXPECT_TRUE(*tree == original);
    }
}

TYPED_TEST(bvh_test, a_tree_refuses_the_mesh_after_its_connectivity_changed) {
    using M = TypeParam;
    using T = hmira::default_traits<M>;
    M m = mesh_from<M>(random_terrain(3, 2));
    auto tree = hmira::build_bvh(m);
    ASSERT_TRUE(tree);
    ASSERT_TRUE(hmira::closest_point(m, *tree, {0, 0, 0}));
    // One more triangle, apart from the others.
    using S = typename T::scalar;
    const std::array<typename T::vertex_handle, 3> tri{T::add_vertex(m, hmira::vec3<S>{S(5), S(5), S(0)}),
                                                       T::add_vertex(m, hmira::vec3<S>{S(6), S(5), S(0)}),
                                                       T::add_vertex(m, hmira::vec3<S>{S(5), S(6), S(0)})};
    ASSERT_TRUE(T::add_face(m, std::span<const typename T::vertex_handle>(tri)));
    const v3 p{0.5, 0.5, 0};
    const hmira::ray r{.origin = p, .direction = {0, 0, 1}};
    const std::vector<v3> points{p};
    const std::vector<hmira::ray> rays{r};
    std::vector<hmira::error> errors;
    const auto keep = [&](const auto& x) {
        ASSERT_FALSE(x);
        errors.push_back(x.error());
    };
    keep(hmira::closest_point(m, *tree, p));
    keep(hmira::closest_points(m, *tree, points));
    keep(hmira::ray_first_hit(m, *tree, r));
    keep(hmira::ray_first_hits(m, *tree, rays));
    keep(hmira::ray_any_hit(m, *tree, r));
    keep(hmira::ray_any_hits(m, *tree, rays));
    keep(hmira::ray_all_hits(m, *tree, r));
    keep(hmira::refit_bvh(m, *tree));
    ASSERT_EQ(errors.size(), 8u);
    for (const auto& e : errors) {
        EXPECT_EQ(e.code, hmira::errc::invalid_argument);
        EXPECT_NE(e.message.find("rebuild"), std::string::npos) << e.message;
        EXPECT_EQ(e.message.find('\n'), std::string::npos) << e.message;
    }
    auto fresh = hmira::build_bvh(m);
    ASSERT_TRUE(fresh);
    ASSERT_TRUE(hmira::closest_point(m, *fresh, p));
}

TEST(bvh, a_change_that_keeps_the_counts_is_caught_by_the_change_counter) {
    static_assert(hmira::change_counted_mesh<hmira::halfedge_mesh>);
    hmira::halfedge_mesh m = mesh_from<hmira::halfedge_mesh>(random_terrain(3, 2));
    using T = hmira::default_traits<hmira::halfedge_mesh>;
    auto tree = hmira::build_bvh(m);
    ASSERT_TRUE(tree);
    EXPECT_TRUE(tree->built_from().counted);
    // Flip an interior edge: V and F stay, the connectivity does not.
    bool flipped = false;
    for (auto h : T::halfedges(m))
        if (hmira::is_flip_ok(m, h)) {
            flipped = static_cast<bool>(hmira::flip_edge(m, h));
            break;
        }
    ASSERT_TRUE(flipped);
    const auto r = hmira::closest_point(m, *tree, {0.5, 0.5, 0});
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().message.find("change count"), std::string::npos) << r.error().message;
}

TEST(bvh, degenerate_triangles_never_hit_but_still_have_closest_points) {
    // A proper triangle, a collinear one, one with a repeated corner, one a single point.
    const std::vector<v3> pts{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 2.5}, {2, 2, 4}, {3, 3, 3}};
    const std::vector<std::array<std::uint32_t, 3>> tris{{0, 1, 2}, {3, 4, 5}, {4, 4, 6}, {6, 6, 6}};
    auto tree = hmira::bvh::from_triangles(pts, tris);
    ASSERT_TRUE(tree) << tree.error().message;
    // Rays aimed at points of the degenerate ones, from several directions.
    for (const v3 target : {v3{0.5, 0.5, 1.5}, v3{2, 2, 4}, v3{2, 2, 2.5}, v3{3, 3, 3}, v3{1, 1, 2.5}})
        for (const v3 d : {v3{1, 0, 0}, v3{0, 1, 0}, v3{0, 0, 1}, v3{1, -1, 0.5}, v3{1, 1, 2}}) {
            const hmira::ray r{.origin = target - d, .direction = d};
            const auto h = tree->first_hit(r);
            EXPECT_FALSE(h.found()) << "face " << h.face;
            EXPECT_FALSE(tree->any_hit(r));
            EXPECT_TRUE(tree->all_hits(r).empty());
        }
    // The proper one still hits; closest points on the degenerate ones are exact.
    EXPECT_EQ(tree->first_hit({.origin = {0.2, 0.2, 1}, .direction = {0, 0, -1}}).face, 0u);
    auto c = tree->closest_point({3, 3, 3.5});  // (3, 3, 3): on faces 2 and 3
    EXPECT_TRUE(c.face == 2 || c.face == 3) << c.face;
    EXPECT_EQ(c.distance, 0.5);
    EXPECT_EQ(c.point, (v3{3, 3, 3}));
    c = tree->closest_point({1.5, 1.5, 3.2});  // nearest the segment (0,0,1)-(2,2,4)
    EXPECT_EQ(c.face, 1u);
    EXPECT_TRUE(std::isfinite(c.distance));
    EXPECT_NEAR(c.point.x * 1.5, c.point.z - 1, 1e-12);
    const v3 w = pts[3] * c.barycentric[0] + pts[4] * c.barycentric[1] + pts[5] * c.barycentric[2];
    EXPECT_NEAR(hmira::norm(w - c.point), 0, 1e-12);
}

TEST(bvh, the_tree_and_its_answers_do_not_depend_on_the_thread_count) {
    const face_list g = random_terrain(60, 9);  // 7200 triangles: the build forks
    std::vector<std::array<std::uint32_t, 3>> tris;
    for (const auto& f : g.faces) tris.push_back({std::uint32_t(f[0]), std::uint32_t(f[1]), std::uint32_t(f[2])});
    auto one = hmira::bvh::from_triangles(g.points, tris, {}, {.threads = 1});
    auto all = hmira::bvh::from_triangles(g.points, tris, {}, {.threads = 0});
    auto two = hmira::bvh::from_triangles(g.points, tris, {}, {.threads = 2});
    ASSERT_TRUE(one && all && two);
    EXPECT_TRUE(*one == *all);
    EXPECT_TRUE(*one == *two);
    EXPECT_LE(one->depth(), 40u);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> pos(-0.2, 1.2), dir(-1, 1);
    std::vector<v3> points;
    std::vector<hmira::ray> rays;
    for (int i = 0; i < 2000; ++i) {
        points.push_back({pos(rng), pos(rng), pos(rng)});
        rays.push_back({.origin = points.back(), .direction = {dir(rng), dir(rng), dir(rng)}});
    }
    const auto c1 = one->closest_points(points, {.threads = 1}), c0 = one->closest_points(points, {.threads = 0});
    const auto h1 = one->first_hits(rays, {.threads = 1}), h0 = one->first_hits(rays, {.threads = 0});
    const auto a1 = one->any_hits(rays, {.threads = 1}), a0 = one->any_hits(rays, {.threads = 0});
    ASSERT_TRUE(c1 && c0 && h1 && h0 && a1 && a0);
    for (std::size_t i = 0; i < points.size(); ++i) {
        EXPECT_EQ((*c1)[i].face, (*c0)[i].face);
        EXPECT_EQ((*c1)[i].point, (*c0)[i].point);
        EXPECT_EQ((*c1)[i].distance, one->closest_point(points[i]).distance);
        EXPECT_EQ((*h1)[i].face, (*h0)[i].face);
        EXPECT_EQ((*h1)[i].t, (*h0)[i].t);
        EXPECT_EQ((*a1)[i], (*a0)[i]);
        EXPECT_EQ(bool((*a1)[i]), (*h1)[i].found());
    }
}

TEST(bvh, non_finite_queries_are_refused_by_index_or_propagate) {
    const std::vector<v3> pts{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const std::vector<std::array<std::uint32_t, 3>> tris{{0, 1, 2}};
    auto tree = hmira::bvh::from_triangles(pts, tris);
    ASSERT_TRUE(tree);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<v3> points{{0, 0, 1}, {0, 0, 2}, {nan, 0, 0}};
    auto refused = tree->closest_points(points);
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.error().code, hmira::errc::invalid_argument);
    EXPECT_NE(refused.error().message.find("query 2"), std::string::npos) << refused.error().message;
    auto kept = tree->closest_points(points, {.nan = hmira::bvh_nan_policy::propagate});
    ASSERT_TRUE(kept);
    EXPECT_EQ((*kept)[1].distance, 2);
    EXPECT_TRUE(std::isnan((*kept)[2].distance));
    EXPECT_FALSE((*kept)[2].found());
    const std::vector<hmira::ray> rays{{.origin = {0.1, 0.1, 1}, .direction = {0, 0, -1}},
                                       {.origin = {0.1, 0.1, 1}, .direction = {0, nan, -1}}};
    EXPECT_FALSE(tree->first_hits(rays));
    EXPECT_FALSE(tree->any_hits(rays));
    auto hits = tree->first_hits(rays, {.nan = hmira::bvh_nan_policy::propagate});
    ASSERT_TRUE(hits);
    EXPECT_EQ((*hits)[0].t, 1);
    EXPECT_TRUE(std::isnan((*hits)[1].t));
}

TEST(bvh, an_empty_tree_finds_nothing_and_bad_input_is_refused) {
    const hmira::bvh empty;
    EXPECT_FALSE(empty.closest_point({0, 0, 0}).found());
    EXPECT_FALSE(empty.first_hit({.origin = {0, 0, 0}, .direction = {1, 0, 0}}).found());
    EXPECT_FALSE(empty.any_hit({.origin = {0, 0, 0}, .direction = {1, 0, 0}}));
    hmira::halfedge_mesh m;
    auto built = hmira::build_bvh(m);
    ASSERT_TRUE(built);
    EXPECT_TRUE(built->empty());
    const std::vector<v3> pts{{0, 0, 0}, {1, 0, 0}, {0, std::numeric_limits<double>::infinity(), 0}};
    const std::vector<std::array<std::uint32_t, 3>> tris{{0, 1, 2}}, far{{0, 1, 7}};
    auto bad = hmira::bvh::from_triangles(pts, tris);
    ASSERT_FALSE(bad);
    EXPECT_NE(bad.error().message.find("point 2"), std::string::npos) << bad.error().message;
    bad = hmira::bvh::from_triangles(std::span(pts).first(2), far);
    ASSERT_FALSE(bad);
    EXPECT_NE(bad.error().message.find("vertex 7"), std::string::npos) << bad.error().message;
}

}  // namespace

namespace {

/// Rays the float box test could drop if its margin were too thin: aimed exactly at vertices
/// (the hits lie on box faces), grazing along the terrain's plane, from far away, and with
/// direction components that are zero or tiny (float cannot bound those: they take the double
/// test).
std::vector<hmira::ray> grazing_rays(const face_list& g, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> pos(-0.2, 1.2), dir(-1, 1);
    std::uniform_int_distribution<std::size_t> pick(0, g.points.size() - 1);
    std::vector<hmira::ray> rays;
    for (int i = 0; i < queries; ++i) {
        const v3 target = g.points[pick(rng)];
        const v3 near{pos(rng), pos(rng), pos(rng)}, far{1e6 * dir(rng), 1e6 * dir(rng), 3e5 + 1e6 * pos(rng)};
        rays.push_back({.origin = near, .direction = target - near});
        rays.push_back({.origin = far, .direction = target - far});
        rays.push_back({.origin = {target.x - 2, target.y, target.z}, .direction = {1, 0, 0}});
        rays.push_back({.origin = near, .direction = {dir(rng), 1e-300, dir(rng)}});
        rays.push_back({.origin = near, .direction = {dir(rng), dir(rng), dir(rng)}});
    }
    return rays;
}

}  // namespace

// The ray queries walk the four-wide form of the tree, whose leaves merge small subtrees: leaf
// sizes below, at and above that merge size.
class bvh_leaf_size : public ::testing::TestWithParam<std::uint32_t> {};
INSTANTIATE_TEST_SUITE_P(bvh, bvh_leaf_size, ::testing::Values(1u, 6u, 16u));

TEST_P(bvh_leaf_size, float_box_test_answers_exactly_as_the_double_one_and_as_brute_force) {
    const face_list g = random_terrain(grid_n * 3, 4);
    std::vector<std::array<std::uint32_t, 3>> tris;
    for (const auto& f : g.faces) tris.push_back({std::uint32_t(f[0]), std::uint32_t(f[1]), std::uint32_t(f[2])});
    auto tree = hmira::bvh::from_triangles(g.points, tris, {}, {.max_leaf_size = GetParam()});
    ASSERT_TRUE(tree);
    std::mt19937_64 rng(11);
    const auto rays = grazing_rays(g, rng);
    const auto f32 = tree->first_hits(rays, {.boxes = hmira::bvh_box_test::float32});
    const auto f64 = tree->first_hits(rays, {.boxes = hmira::bvh_box_test::float64});
    const auto a32 = tree->any_hits(rays, {.boxes = hmira::bvh_box_test::float32});
    const auto a64 = tree->any_hits(rays, {.boxes = hmira::bvh_box_test::float64});
    ASSERT_TRUE(f32 && f64 && a32 && a64);
    std::size_t hits = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const auto &x = (*f32)[i], &y = (*f64)[i];
        EXPECT_EQ(x.face, y.face) << "ray " << i;
        EXPECT_EQ(x.t, y.t) << "ray " << i;
        EXPECT_EQ(x.barycentric, y.barycentric) << "ray " << i;
        EXPECT_EQ((*a32)[i], (*a64)[i]) << "ray " << i;
        EXPECT_EQ(bool((*a32)[i]), x.found()) << "ray " << i;
        // Every triangle, in the tree's order, with the same double test: the smallest t, the
        // first triangle among equals.
        double best = inf;
        std::size_t best_face = hmira::no_face;
        for (std::size_t k = 0; k < tree->size(); ++k) {
            const auto& t = tree->triangle(k);
            double u = 0, v = 0;
            const double s = hmira::detail::bvh_build::ray_triangle(rays[i].origin, rays[i].direction, g.points[t[0]],
                                                                    g.points[t[1]], g.points[t[2]], u, v);
            if (s >= rays[i].t_min && s < best) best = s, best_face = tree->face(k);
        }
        EXPECT_EQ(x.face, best_face) << "ray " << i;
        if (best_face != hmira::no_face) {
            EXPECT_EQ(x.t, best) << "ray " << i;
        }
        hits += x.found();
    }
    EXPECT_GT(hits, rays.size() / 4);
}
