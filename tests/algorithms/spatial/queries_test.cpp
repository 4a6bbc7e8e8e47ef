// The surface queries against independent routes: the fast winding number against the direct
// sum within its reported bound; the winding-number sign on an open hemisphere, two
// overlapping spheres as one soup and a sphere with flipped faces (where the other signs fail,
// as each test states); sampling reproducible and uniform by area (a chi-square test per
// triangle); the Hausdorff distance against a brute-force scan; refusals of NaN points and
// empty meshes.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include <hmira/algorithms/spatial/hausdorff_distance.hpp>
#include <hmira/algorithms/spatial/sample_surface.hpp>
#include <hmira/algorithms/spatial/signed_distance.hpp>
#include <hmira/algorithms/spatial/signed_distance_grid.hpp>
#include <hmira/algorithms/spatial/winding_number.hpp>
#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

namespace {

using v3 = hmira::vec3<double>;
using tri = std::array<std::uint32_t, 3>;

#ifdef HMIRA_SANITIZER_BUILD
constexpr std::size_t scale = 1;
#else
constexpr std::size_t scale = 4;
#endif

// A triangulated UV sphere about `centre`, wound outward; with `open`, only the part above
// z = centre.z (a hemisphere whose rim is the equator).
void add_sphere(std::vector<v3>& pts, std::vector<tri>& tris, v3 centre, double radius, std::size_t slices,
                std::size_t stacks, bool open = false) {
    const auto base = std::uint32_t(pts.size());
    for (std::size_t j = 0; j <= stacks; ++j)
        for (std::size_t i = 0; i < slices; ++i) {
            const double th = std::numbers::pi * double(j) / double(stacks);
            const double ph = 2 * std::numbers::pi * double(i) / double(slices);
            pts.push_back(centre + v3{std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)} * radius);
        }
    auto id = [&](std::size_t j, std::size_t i) { return base + std::uint32_t(j * slices + i % slices); };
    const std::size_t last = open ? stacks / 2 : stacks;
    for (std::size_t j = 0; j < last; ++j)
        for (std::size_t i = 0; i < slices; ++i) {
            // Rows 0 and `stacks` repeat the pole: skip the triangles that would be degenerate.
            if (j > 0) tris.push_back({id(j, i), id(j + 1, i), id(j, i + 1)});
            if (j + 1 < stacks) tris.push_back({id(j, i + 1), id(j + 1, i), id(j + 1, i + 1)});
        }
}

hmira::triangle_set make_set(const std::vector<v3>& pts, const std::vector<tri>& tris) {
    auto s = hmira::make_triangle_set(pts, tris);
    EXPECT_TRUE(s) << s.error().message;
    return *s;
}

std::vector<v3> random_points(std::size_t n, double half_width, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-half_width, half_width);
    std::vector<v3> p(n);
    for (auto& q : p) q = {u(rng), u(rng), u(rng)};
    return p;
}

TEST(winding_number, fast_stays_within_its_bound_of_the_direct_sum) {
    std::vector<v3> pts;
    std::vector<tri> tris;
    add_sphere(pts, tris, {0, 0, 0}, 1, 24, 12);
    add_sphere(pts, tris, {0.7, 0.2, 0.1}, 0.6, 12, 6, true);  // open, and crossing the first
    // A few random triangles as well.
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-1.2, 1.2);
    for (int i = 0; i < 30; ++i) {
        const auto b = std::uint32_t(pts.size());
        for (int k = 0; k < 3; ++k) pts.push_back({u(rng), u(rng), u(rng)});
        tris.push_back({b, b + 1, b + 2});
    }
    const auto s = make_set(pts, tris);
    const auto q = random_points(300 * scale, 1.6, 3);
    const auto direct = hmira::winding_number(s, q, {.method = hmira::winding_method::direct});
    ASSERT_TRUE(direct);
    for (double beta : {1.5, 2.0, 4.0}) {
        SCOPED_TRACE(beta);
        const auto fast = hmira::winding_number(s, q, {.beta = beta, .error_bounds = true});
        ASSERT_TRUE(fast);
        double worst = 0, sum = 0;
        for (std::size_t i = 0; i < q.size(); ++i) {
            const double err = std::abs(fast->values[i] - direct->values[i]);
            ASSERT_LE(err, fast->error_bounds[i] + 1e-12) << "point " << i;
            worst = std::max(worst, err);
            sum += err;
        }
        // The measured accuracy the header states (worst 0.044, mean 0.0026 at beta 2; worst
        // 0.0014 at beta 4), with some room: large random triangles crossing the spheres are
        // the hard case for expansions about few-triangle nodes.
        const double mean = sum / double(q.size());
        const double worst_limit = beta == 1.5 ? 0.15 : (beta == 2.0 ? 0.06 : 0.003);
        const double mean_limit = beta == 1.5 ? 0.01 : (beta == 2.0 ? 0.005 : 0.001);
        EXPECT_LT(worst, worst_limit);
        EXPECT_LT(mean, mean_limit);
    }
    // The thread count changes nothing.
    const auto one = hmira::winding_number(s, q, {.threads = 1});
    const auto all = hmira::winding_number(s, q, {.threads = 0});
    ASSERT_TRUE(one && all);
    EXPECT_EQ(one->values, all->values);
}

// Which sign each mode gives, against the truth, over a set of points.
struct sign_tally {
    std::size_t wrong_winding = 0, wrong_pseudo_normal = 0, wrong_parity = 0;
};

sign_tally tally(const hmira::triangle_set& s, const std::vector<v3>& q, const std::vector<int>& inside) {
    sign_tally t;
    for (auto mode : {hmira::sign_mode::winding_number, hmira::sign_mode::pseudo_normal, hmira::sign_mode::parity}) {
        const auto sd = hmira::signed_distance(s, q, {.sign = mode});
        EXPECT_TRUE(sd);
        std::size_t wrong = 0;
        for (std::size_t i = 0; i < q.size(); ++i) wrong += (sd->distances[i] < 0) != (inside[i] == 1);
        (mode == hmira::sign_mode::winding_number  ? t.wrong_winding
         : mode == hmira::sign_mode::pseudo_normal ? t.wrong_pseudo_normal
                                                   : t.wrong_parity) = wrong;
    }
    // contains agrees with the winding-number sign.
    const auto c = hmira::contains(s, q);
    EXPECT_TRUE(c);
    for (std::size_t i = 0; i < q.size(); ++i) EXPECT_EQ(int((*c)[i]), inside[i]) << "point " << i;
    return t;
}

TEST(signed_distance, winding_sign_is_right_on_an_open_hemisphere) {
    std::vector<v3> pts;
    std::vector<tri> tris;
    add_sphere(pts, tris, {0, 0, 0}, 1, 32, 16, true);
    const auto s = make_set(pts, tris);
    std::vector<v3> q;
    std::vector<int> inside;
    for (const auto& p : random_points(600 * scale, 1.5, 11)) {
        const double r = hmira::norm(p);
        if (r < 0.85 && p.z > 0.1)
            q.push_back(p), inside.push_back(1);  // under the dome
        else if (r > 1.1 || (p.z < -0.2 && r < 0.8))
            q.push_back(p), inside.push_back(0);  // away, or below the rim
    }
    const auto t = tally(s, q, inside);
    EXPECT_EQ(t.wrong_winding, 0u);
    // Below the rim a ray towards +z meets the dome once, and the closest point is on the rim,
    // whose pseudo-normal points outward and up: parity and pseudo-normals call those inside.
    EXPECT_GT(t.wrong_parity, 0u);
    EXPECT_GT(t.wrong_pseudo_normal, 0u);
}

TEST(signed_distance, winding_sign_is_right_on_two_overlapping_spheres_as_one_soup) {
    std::vector<v3> pts;
    std::vector<tri> tris;
    const v3 a{-0.5, 0, 0}, b{0.5, 0, 0};
    add_sphere(pts, tris, a, 1, 32, 16);
    add_sphere(pts, tris, b, 1, 32, 16);
    const auto s = make_set(pts, tris);
    std::vector<v3> q;
    std::vector<int> inside;
    for (const auto& p : random_points(600 * scale, 1.8, 12)) {
        const double da = hmira::norm(p - a), db = hmira::norm(p - b);
        if (std::abs(da - 1) < 0.1 || std::abs(db - 1) < 0.1) continue;
        q.push_back(p);
        inside.push_back(da < 1 || db < 1 ? 1 : 0);
    }
    const auto t = tally(s, q, inside);
    EXPECT_EQ(t.wrong_winding, 0u);
    // In the lens both spheres are crossed (parity: even); inside one sphere near the other's
    // buried surface, the closest point's normal points away from the point (pseudo-normal).
    EXPECT_GT(t.wrong_parity, 0u);
    EXPECT_GT(t.wrong_pseudo_normal, 0u);
}

TEST(signed_distance, winding_sign_is_right_on_a_sphere_with_flipped_faces) {
    std::vector<v3> pts;
    std::vector<tri> tris;
    add_sphere(pts, tris, {0, 0, 0}, 1, 32, 16);
    for (std::size_t i = 0; i < tris.size(); i += 10) std::swap(tris[i][1], tris[i][2]);
    const auto s = make_set(pts, tris);
    std::vector<v3> q;
    std::vector<int> inside;
    for (const auto& p : random_points(600 * scale, 1.5, 13)) {
        const double r = hmira::norm(p);
        if (r < 0.8)
            q.push_back(p), inside.push_back(1);
        else if (r > 1.2)
            q.push_back(p), inside.push_back(0);
    }
    // Make sure some points sit right under a flipped face, where its normal decides.
    for (std::size_t i = 0; i < tris.size(); i += 10) {
        const auto c = (pts[tris[i][0]] + pts[tris[i][1]] + pts[tris[i][2]]) / 3.0;
        q.push_back(c * 0.75);
        inside.push_back(1);
    }
    const auto t = tally(s, q, inside);
    EXPECT_EQ(t.wrong_winding, 0u);
    // Pseudo-normals follow the flipped faces' normals; parity ignores orientation and is right here.
    EXPECT_GT(t.wrong_pseudo_normal, 0u);
    EXPECT_EQ(t.wrong_parity, 0u);
}

TEST(signed_distance, distances_match_a_brute_force_scan) {
    std::vector<v3> pts;
    std::vector<tri> tris;
    add_sphere(pts, tris, {0, 0, 0}, 1, 12, 6);
    const auto s = make_set(pts, tris);
    const auto q = random_points(100, 1.5, 21);
    const auto sd = hmira::signed_distance(s, q);
    ASSERT_TRUE(sd);
    for (std::size_t i = 0; i < q.size(); ++i) {
        // The closest point lies on its face, and no vertex is closer than it.
        double nearest_vertex = 1e300;
        for (const auto& p : pts) nearest_vertex = std::min(nearest_vertex, hmira::norm(p - q[i]));
        EXPECT_LE(std::abs(sd->distances[i]), nearest_vertex + 1e-12);
        EXPECT_NEAR(hmira::norm(sd->closest[i] - q[i]), std::abs(sd->distances[i]), 1e-12);
        EXPECT_LT(sd->faces[i], tris.size());
    }
}

TEST(signed_distance_grid, narrow_band_agrees_with_the_full_grid_inside_the_band) {
    std::vector<v3> pts;
    std::vector<tri> tris;
    add_sphere(pts, tris, {0, 0, 0}, 1, 16, 8);
    const auto s = make_set(pts, tris);
    const hmira::grid_geometry g{{12, 12, 12}, {-1.5, -1.5, -1.5}, {3.0 / 11, 3.0 / 11, 3.0 / 11}};
    const auto full = hmira::signed_distance_grid<double>(s, g);
    const auto band = hmira::signed_distance_grid<double>(s, g, {.band = 0.3});
    ASSERT_TRUE(full && band);
    for (std::size_t k = 0; k < 12; ++k)
        for (std::size_t j = 0; j < 12; ++j)
            for (std::size_t i = 0; i < 12; ++i) {
                const double f = full->value(i, j, k), b = band->value(i, j, k);
                if (std::abs(f) < 0.3) {
                    EXPECT_EQ(f, b);
                } else {
                    EXPECT_EQ(std::abs(b), 0.3);
                }
                EXPECT_EQ(f < 0, b < 0);
                // The sphere is inscribed: inside it the field is at most 1 - |p| (sign included).
                const double r = hmira::norm(g.position(i, j, k));
                if (r < 0.85) {
                    EXPECT_LT(f, 0);
                }
                if (r > 1.0) {
                    EXPECT_NEAR(f, r - 1, 0.05);
                }
            }
}

TEST(offset, vertices_lie_at_the_offset_distance) {
    std::vector<v3> pts;
    std::vector<tri> tris;
    add_sphere(pts, tris, {0, 0, 0}, 1, 16, 8);
    const auto s = make_set(pts, tris);
    for (double d : {0.25, -0.3}) {
        const auto out = hmira::offset(s, d, {.resolution = 32});
        ASSERT_TRUE(out) << out.error().message;
        ASSERT_GT(out->triangles.size(), 100u);
        const auto sd = hmira::signed_distance(s, std::vector<v3>(out->positions.begin(), out->positions.end()));
        ASSERT_TRUE(sd);
        const double h = (2 + 2 * std::abs(d)) / 25;
        for (double x : sd->distances) EXPECT_NEAR(x, d, h);
    }
}

TEST(sample_surface, the_same_seed_gives_the_same_samples) {
    std::vector<v3> pts;
    std::vector<tri> tris;
    add_sphere(pts, tris, {0, 0, 0}, 1, 12, 6);
    const auto s = make_set(pts, tris);
    for (auto method : {hmira::sampling_method::uniform, hmira::sampling_method::poisson_disk}) {
        const auto a = hmira::sample_surface(s, 500, {.method = method, .seed = 7});
        const auto b = hmira::sample_surface(s, 500, {.method = method, .seed = 7});
        const auto c = hmira::sample_surface(s, 500, {.method = method, .seed = 8});
        ASSERT_TRUE(a && b && c);
        ASSERT_EQ(a->points.size(), 500u);
        EXPECT_EQ(a->points, b->points);
        EXPECT_EQ(a->faces, b->faces);
        EXPECT_NE(a->points, c->points);
        for (std::size_t i = 0; i < a->points.size(); ++i) {
            const auto& w = a->barycentrics[i];
            const auto& k = a->corners[i];
            EXPECT_GE(std::min({w[0], w[1], w[2]}), 0.0);
            EXPECT_NEAR(w[0] + w[1] + w[2], 1, 1e-15);
            const v3 p = pts[k[0]] * w[0] + pts[k[1]] * w[1] + pts[k[2]] * w[2];
            EXPECT_NEAR(hmira::norm(p - a->points[i]), 0, 1e-15);
        }
    }
    // The first values of the generator, fixed by the standard, fix the first sample.
    const auto first = hmira::sample_surface(s, 1, {.seed = 7});
    ASSERT_TRUE(first);
    std::mt19937_64 rng(7);
    const double u0 = double(rng() >> 11) * 0x1p-53;
    double total = 0;
    for (const auto& t : tris) total += 0.5 * hmira::norm(hmira::cross(pts[t[1]] - pts[t[0]], pts[t[2]] - pts[t[0]]));
    double acc = 0;
    std::size_t expected_face = 0;
    for (; expected_face < tris.size(); ++expected_face) {
        const auto& t = tris[expected_face];
        acc += 0.5 * hmira::norm(hmira::cross(pts[t[1]] - pts[t[0]], pts[t[2]] - pts[t[0]]));
        if (acc > u0 * total) break;
    }
    EXPECT_EQ(first->faces[0], expected_face);
}

TEST(sample_surface, uniform_samples_hit_triangles_in_proportion_to_their_area) {
    // Triangles of very different areas, in one plane.
    std::vector<v3> pts;
    std::vector<tri> tris;
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> u(0.05, 1.0);
    for (int i = 0; i < 40; ++i) {
        const auto b = std::uint32_t(pts.size());
        const double w = u(rng), h = u(rng);
        pts.push_back({double(2 * i), 0, 0});
        pts.push_back({double(2 * i) + w, 0, 0});
        pts.push_back({double(2 * i), h, 0});
        tris.push_back({b, b + 1, b + 2});
    }
    const auto s = make_set(pts, tris);
    const std::size_t n = 20000;
    const auto r = hmira::sample_surface(s, n, {.seed = 1});
    ASSERT_TRUE(r);
    std::vector<double> count(tris.size(), 0), area(tris.size());
    double total = 0;
    for (std::size_t i = 0; i < tris.size(); ++i) {
        area[i] = 0.5 * (pts[tris[i][1]].x - pts[tris[i][0]].x) * (pts[tris[i][2]].y - pts[tris[i][0]].y);
        total += area[i];
    }
    for (auto f : r->faces) count[f] += 1;
    double chi2 = 0;
    for (std::size_t i = 0; i < tris.size(); ++i) {
        const double e = double(n) * area[i] / total;
        chi2 += (count[i] - e) * (count[i] - e) / e;
    }
    // 39 degrees of freedom: mean 39, standard deviation sqrt(78) ~ 8.8; 80 is beyond 4.6 sigma.
    EXPECT_LT(chi2, 80.0);
    // Within one triangle the barycentric u + v split is uniform too: half the samples of a
    // triangle lie in the half nearer its first corner, by area (region b1 + b2 < 1/sqrt 2).
    std::size_t near_first = 0;
    for (const auto& w : r->barycentrics) near_first += w[1] + w[2] < std::sqrt(0.5);
    EXPECT_NEAR(double(near_first) / double(n), 0.5, 0.02);
}

TEST(sample_surface, poisson_disk_samples_are_spread_apart) {
    std::vector<v3> pts;
    std::vector<tri> tris;
    add_sphere(pts, tris, {0, 0, 0}, 1, 24, 12);
    const auto s = make_set(pts, tris);
    const std::size_t n = 400;
    auto min_gap = [&](const std::vector<v3>& p) {
        double g = 1e300;
        for (std::size_t i = 0; i < p.size(); ++i)
            for (std::size_t j = i + 1; j < p.size(); ++j) g = std::min(g, hmira::norm(p[i] - p[j]));
        return g;
    };
    const auto blue = hmira::sample_surface(s, n, {.method = hmira::sampling_method::poisson_disk});
    const auto white = hmira::sample_surface(s, n);
    ASSERT_TRUE(blue && white);
    ASSERT_EQ(blue->points.size(), n);
    // r_max = sqrt(A / (2 sqrt 3 n)) for area A ~ 4 pi.
    const double r_max = std::sqrt(4 * std::numbers::pi / (2 * std::sqrt(3.0) * double(n)));
    EXPECT_GT(min_gap(blue->points), 0.5 * r_max);
    EXPECT_LT(min_gap(white->points), 0.5 * r_max);
}

double brute_distance_to_triangle(const v3& p, const v3& a, const v3& b, const v3& c) {
    auto seg = [&](const v3& x, const v3& y) {
        const v3 d = y - x;
        const double t = std::clamp(hmira::dot(p - x, d) / hmira::dot(d, d), 0.0, 1.0);
        return hmira::norm(x + d * t - p);
    };
    const v3 n = hmira::cross(b - a, c - a);
    const v3 q = p - n * (hmira::dot(p - a, n) / hmira::dot(n, n));
    if (hmira::dot(hmira::cross(b - a, q - a), n) >= 0 && hmira::dot(hmira::cross(c - b, q - b), n) >= 0 &&
        hmira::dot(hmira::cross(a - c, q - c), n) >= 0)
        return hmira::norm(q - p);
    return std::min({seg(a, b), seg(b, c), seg(c, a)});
}

TEST(hausdorff_distance, matches_a_brute_force_scan_on_small_meshes) {
    std::vector<v3> pa, pb;
    std::vector<tri> ta, tb;
    add_sphere(pa, ta, {0, 0, 0}, 1, 6, 4);
    add_sphere(pb, tb, {0.2, 0, 0.1}, 0.8, 5, 3, true);
    const auto a = make_set(pa, ta), b = make_set(pb, tb);
    const auto h = hmira::hausdorff_distance(a, b, {.per_triangle = 2000, .min_samples = 0});
    ASSERT_TRUE(h);
    // Brute force: a barycentric lattice on every triangle of one side, every triangle of the other.
    auto brute = [](const std::vector<v3>& pf, const std::vector<tri>& tf, const std::vector<v3>& pt,
                    const std::vector<tri>& tt) {
        double worst = 0;
        constexpr int n = 24;
        for (const auto& t : tf)
            for (int i = 0; i <= n; ++i)
                for (int j = 0; i + j <= n; ++j) {
                    const v3 p =
                        pf[t[0]] + (pf[t[1]] - pf[t[0]]) * (double(i) / n) + (pf[t[2]] - pf[t[0]]) * (double(j) / n);
                    double d = 1e300;
                    for (const auto& u : tt)
                        d = std::min(d, brute_distance_to_triangle(p, pt[u[0]], pt[u[1]], pt[u[2]]));
                    worst = std::max(worst, d);
                }
        return worst;
    };
    const double ab = brute(pa, ta, pb, tb), ba = brute(pb, tb, pa, ta);
    EXPECT_NEAR(h->a_to_b.max, ab, 0.02);
    EXPECT_NEAR(h->b_to_a.max, ba, 0.02);
    EXPECT_EQ(h->symmetric, std::max(h->a_to_b.max, h->b_to_a.max));
    EXPECT_LE(h->a_to_b.mean, h->a_to_b.rms);
    EXPECT_LE(h->a_to_b.rms, h->a_to_b.max);
    // A translated copy: every distance is the shift.
    std::vector<v3> sq{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, sq2 = sq;
    for (auto& p : sq2) p.z += 0.3;
    const std::vector<tri> st{{0, 1, 2}, {0, 2, 3}};
    const auto t = hmira::hausdorff_distance(make_set(sq, st), make_set(sq2, st), {.min_samples = 1000});
    ASSERT_TRUE(t);
    EXPECT_NEAR(t->symmetric, 0.3, 1e-12);
    EXPECT_NEAR(t->a_to_b.mean, 0.3, 1e-12);
    EXPECT_NEAR(t->b_to_a.rms, 0.3, 1e-12);
}

TEST(queries, non_finite_points_are_refused_by_index_or_propagated) {
    std::vector<v3> pts;
    std::vector<tri> tris;
    add_sphere(pts, tris, {0, 0, 0}, 1, 8, 4);
    const auto s = make_set(pts, tris);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<v3> q{{0, 0, 0}, {3, 0, 0}, {nan, 0, 0}, {0, 0, 0.5}};
    const auto w = hmira::winding_number(s, q);
    ASSERT_FALSE(w);
    EXPECT_EQ(w.error().code, hmira::errc::invalid_argument);
    EXPECT_EQ(w.error().element, 2);
    EXPECT_NE(w.error().message.find("query point 2"), std::string::npos) << w.error().message;
    const auto sd = hmira::signed_distance(s, q);
    ASSERT_FALSE(sd);
    EXPECT_NE(sd.error().message.find("signed_distance: query point 2"), std::string::npos);
    EXPECT_FALSE(hmira::contains(s, q));
    const auto wp = hmira::winding_number(s, q, {.nan = hmira::nan_policy::propagate});
    ASSERT_TRUE(wp);
    EXPECT_TRUE(std::isnan(wp->values[2]));
    EXPECT_NEAR(wp->values[0], 1, 1e-2);
    EXPECT_NEAR(wp->values[1], 0, 1e-2);
    const auto sp = hmira::signed_distance(s, q, {.nan = hmira::nan_policy::propagate});
    ASSERT_TRUE(sp);
    EXPECT_TRUE(std::isnan(sp->distances[2]));
    EXPECT_LT(sp->distances[3], 0);
}

TEST(queries, an_empty_mesh_is_refused_clearly) {
    hmira::halfedge_mesh m;
    const std::vector<v3> q{{0, 0, 0}};
    const auto w = hmira::winding_number(m, q);
    ASSERT_FALSE(w);
    EXPECT_EQ(w.error().message, "winding_number: the mesh has no faces");
    EXPECT_FALSE(hmira::signed_distance(m, q));
    EXPECT_FALSE(hmira::contains(m, q));
    const auto smp = hmira::sample_surface(m, 10);
    ASSERT_FALSE(smp);
    EXPECT_EQ(smp.error().message, "sample_surface: the mesh has no area to sample");
    const auto h = hmira::hausdorff_distance(m, m);
    ASSERT_FALSE(h);
    EXPECT_EQ(h.error().message, "hausdorff_distance: mesh A has no faces");
    EXPECT_FALSE(hmira::offset(m, 0.1));
    EXPECT_FALSE(hmira::winding_number(make_set({}, {}), q));
}

TEST(winding_number, real_meshes_fast_within_bound_and_zero_outside_the_box) {
    const char* d = std::getenv("HMIRA_TEST_DATA");
    const auto dir = d ? std::filesystem::path(d) / "meshes" : std::filesystem::path();
    if (dir.empty() || !std::filesystem::exists(dir / "fandisk.off")) GTEST_SKIP() << "run scripts/test-data.sh first";
    hmira::halfedge_mesh m;
    ASSERT_TRUE(hmira::io::read_mesh(m, dir / "fandisk.off"));
    auto s = hmira::triangles_of(m);
    ASSERT_TRUE(s);
    v3 lo{1e300, 1e300, 1e300}, hi = -lo;
    for (const auto& p : s->points)
        for (std::size_t k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    std::mt19937_64 rng(4);
    std::vector<v3> q;
    for (std::size_t i = 0; i < 40 * scale; ++i) {
        v3 p;
        for (std::size_t k = 0; k < 3; ++k)
            p[k] = std::uniform_real_distribution<double>(lo[k] - 0.2 * (hi[k] - lo[k]),
                                                          hi[k] + 0.2 * (hi[k] - lo[k]))(rng);
        q.push_back(p);
    }
    const auto direct = hmira::winding_number(*s, q, {.method = hmira::winding_method::direct});
    const auto fast = hmira::winding_number(*s, q, {.error_bounds = true});
    ASSERT_TRUE(direct && fast);
    for (std::size_t i = 0; i < q.size(); ++i) {
        ASSERT_LE(std::abs(fast->values[i] - direct->values[i]), fast->error_bounds[i] + 1e-12);
        bool outside_box = false;
        for (std::size_t k = 0; k < 3; ++k) outside_box |= q[i][k] < lo[k] || q[i][k] > hi[k];
        if (outside_box) {
            EXPECT_NEAR(direct->values[i], 0, 1e-9);
        }
    }
}

}  // namespace
