// winding_number, contains and signed_distance on every mesh model: on a closed quad torus
// (polygons cut by triangulate_polygon) and a closed UV sphere, points away from the surface get
// winding number 0 or 1 within the fast method's reported bound, and the signs agree with the
// analytic inside of the shape.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include <hmira/algorithms/spatial/signed_distance.hpp>
#include <hmira/algorithms/spatial/winding_number.hpp>

#include "support/models.hpp"
#include "support/shapes.hpp"

namespace {

using v3 = hmira::vec3<double>;

// Quads split along a diagonal for the models that hold triangles only.
template <class M, class T = hmira::default_traits<M>>
hmira_test::face_list for_model(hmira_test::face_list g) {
    if constexpr (requires { requires T::triangles_only; }) {
        std::vector<std::vector<std::size_t>> tris;
        for (const auto& f : g.faces)
            for (std::size_t i = 1; i + 1 < f.size(); ++i) tris.push_back({f[0], f[i], f[i + 1]});
        g.faces = std::move(tris);
    }
    return g;
}

// A UV sphere of radius 1: quads between the rings, triangles at the poles, wound outward.
hmira_test::face_list uv_sphere(std::size_t slices, std::size_t stacks) {
    hmira_test::face_list s;
    s.points.push_back({0, 0, 1});
    for (std::size_t j = 1; j < stacks; ++j)
        for (std::size_t i = 0; i < slices; ++i) {
            const double th = std::numbers::pi * double(j) / double(stacks);
            const double ph = 2 * std::numbers::pi * double(i) / double(slices);
            s.points.push_back({std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)});
        }
    s.points.push_back({0, 0, -1});
    const std::size_t south = s.points.size() - 1;
    auto id = [&](std::size_t j, std::size_t i) { return 1 + (j - 1) * slices + i % slices; };
    for (std::size_t i = 0; i < slices; ++i) s.faces.push_back({0, id(1, i), id(1, i + 1)});
    for (std::size_t j = 1; j + 1 < stacks; ++j)
        for (std::size_t i = 0; i < slices; ++i)
            s.faces.push_back({id(j, i), id(j + 1, i), id(j + 1, i + 1), id(j, i + 1)});
    for (std::size_t i = 0; i < slices; ++i) s.faces.push_back({id(stacks - 1, i), south, id(stacks - 1, i + 1)});
    return s;
}

template <class M>
class queries_on_models : public ::testing::Test {};
TYPED_TEST_SUITE(queries_on_models, hmira_test::all_models);

// Points on a lattice, each known to be inside (1) or outside (0) with a margin, by `side`
// (+1 outside, -1 inside, 0 too close to tell).
template <class M, class Side>
void check_zero_or_one(const hmira_test::face_list& shape, double half_width, const Side& side) {
    M mesh;
    ASSERT_TRUE(hmira_test::add_face_list(mesh, for_model<M>(shape)));
    std::vector<v3> points;
    std::vector<int> expected;
    constexpr int n = 9;
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const v3 p{half_width * (2.0 * i / (n - 1) - 1) + 0.013, half_width * (2.0 * j / (n - 1) - 1) - 0.007,
                           half_width * (2.0 * k / (n - 1) - 1) + 0.003};
                if (const int s = side(p); s != 0) {
                    points.push_back(p);
                    expected.push_back(s < 0 ? 1 : 0);
                }
            }
    ASSERT_GT(points.size(), 100u);
    const auto fast = hmira::winding_number(mesh, points, {.error_bounds = true});
    ASSERT_TRUE(fast) << fast.error().message;
    const auto direct = hmira::winding_number(mesh, points, {.method = hmira::winding_method::direct});
    ASSERT_TRUE(direct) << direct.error().message;
    const auto inside = hmira::contains(mesh, points);
    ASSERT_TRUE(inside);
    const auto sd = hmira::signed_distance(mesh, points);
    ASSERT_TRUE(sd);
    for (std::size_t i = 0; i < points.size(); ++i) {
        EXPECT_NEAR(direct->values[i], expected[i], 1e-9) << "point " << i;
        EXPECT_LE(std::abs(fast->values[i] - expected[i]), fast->error_bounds[i] + 1e-9) << "point " << i;
        EXPECT_LT(std::abs(fast->values[i] - expected[i]), 2e-2) << "point " << i;
        EXPECT_EQ(int((*inside)[i]), expected[i]) << "point " << i;
        EXPECT_EQ(sd->distances[i] < 0, expected[i] == 1) << "point " << i;
    }
}

TYPED_TEST(queries_on_models, winding_number_is_0_or_1_away_from_a_closed_torus) {
    const double R = 2.0, r = 0.7;
    check_zero_or_one<TypeParam>(hmira_test::torus(24, 12, R, r), 3.0, [&](const v3& p) {
        const double q = std::hypot(std::hypot(p.x, p.y) - R, p.z);
        return q < r - 0.1 ? -1 : (q > r + 0.1 ? 1 : 0);
    });
}

TYPED_TEST(queries_on_models, winding_number_is_0_or_1_away_from_a_closed_sphere) {
    check_zero_or_one<TypeParam>(uv_sphere(16, 8), 1.6, [](const v3& p) {
        const double q = hmira::norm(p);
        return q < 0.85 ? -1 : (q > 1.1 ? 1 : 0);
    });
}

}  // namespace
