// laplacian_smooth and taubin_smooth against a reference written here the plain way: every step
// walks each vertex's halfedges, reads the positions back from the mesh and writes the new ones
// into it. The smoothers gather the neighbourhoods once and sweep arrays in parallel; they must
// agree with the reference to 1e-12 of the model's size on every model and several shapes, and
// give bit-identical results for any thread count.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>

#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/smoothing/laplacian_smooth.hpp>
#include <hmira/algorithms/subdivision/loop.hpp>
#include <hmira/io/mesh_io.hpp>

#include "algorithms/triangle/triangle_support.hpp"

namespace {

using namespace hmira_test;
using hmira::vec3;

template <class M>
class smoothing_reference : public ::testing::Test {};
TYPED_TEST_SUITE(smoothing_reference, all_models);

/// What the reference does in one call.
struct reference_options {
    std::size_t iterations = 1;
    std::vector<double> amounts{0.5};  ///< one step per amount, each iteration
    bool cotangent = false;
    bool refresh = true;  ///< cotangent weights from the current positions before each step
    bool fix_boundary = true;
    std::vector<std::size_t> fixed{};
};

template <class M, class T = hmira::default_traits<M>>
vec3<double> at(const M& m, typename T::vertex_handle v) {
    const auto p = T::position(m, v);
    return {double(p[0]), double(p[1]), double(p[2])};
}

/// The cotangent of the angle at a in triangle (a, b, c), 0 when degenerate.
double cot(const vec3<double>& a, const vec3<double>& b, const vec3<double>& c) {
    const auto u = b - a, w = c - a;
    const double s = std::sqrt(hmira::squared_norm(hmira::cross(u, w)));
    return s > 0 ? hmira::dot(u, w) / s : 0.0;
}

/// (cot alpha + cot beta) / 2 of the edge of halfedge x, read from the mesh now.
template <class M, class T = hmira::default_traits<M>>
double edge_weight(const M& m, typename T::halfedge_handle x) {
    double w = 0;
    for (const auto y : {x, T::opposite(m, x)}) {
        if (T::face(m, y) == T::null_face()) continue;
        const auto c = T::target(m, T::next(m, y));
        w += 0.5 * cot(at(m, c), at(m, T::target(m, T::opposite(m, y))), at(m, T::target(m, y)));
    }
    return w;
}

/// The reference smoother: Jacobi steps p += amount * (sum w_j (p_j - p)) / (sum w_j).
template <class M, class T = hmira::default_traits<M>>
void reference_smooth(M& m, const reference_options& o) {
    std::vector<char> fixed(T::vertex_index_bound(m), 0);
    for (auto i : o.fixed) fixed[i] = 1;
    for (auto v : T::vertices(m)) {
        const auto s = T::vertex_halfedge(m, v);
        if (o.fix_boundary && s != T::null_halfedge() && T::face(m, s) == T::null_face())
            fixed[T::vertex_index(m, v)] = 1;
    }
    // Frozen cotangent weights, by halfedge index, from the starting positions.
    std::vector<double> frozen(T::halfedge_index_bound(m), 0);
    if (o.cotangent && !o.refresh)
        for (auto h : T::halfedges(m)) frozen[T::halfedge_index(m, h)] = edge_weight(m, h);
    for (std::size_t k = 0; k < o.iterations; ++k)
        for (const double amount : o.amounts) {
            std::vector<std::pair<typename T::vertex_handle, vec3<double>>> next;
            for (auto v : T::vertices(m)) {
                const auto s = T::vertex_halfedge(m, v);
                if (fixed[T::vertex_index(m, v)] || s == T::null_halfedge()) continue;
                const vec3<double> p = at(m, v);
                vec3<double> sum{};
                double total = 0;
                auto x = s;
                do {
                    double w = 1;
                    if (o.cotangent) w = o.refresh ? edge_weight(m, x) : frozen[T::halfedge_index(m, x)];
                    sum += (at(m, T::target(m, x)) - p) * w;
                    total += w;
                    x = T::next(m, T::opposite(m, x));
                } while (x != s);
                next.push_back({v, total > 0 ? p + sum * (amount / total) : p});
            }
            using S = typename T::scalar;
            for (const auto& [v, q] : next) T::set_position(m, v, vec3<S>{S(q.x), S(q.y), S(q.z)});
        }
}

template <class M, class T = hmira::default_traits<M>>
std::vector<vec3<double>> positions(const M& m) {
    std::vector<vec3<double>> out;
    for (auto v : T::vertices(m)) out.push_back(at(m, v));
    return out;
}

/// The largest coordinate difference between two meshes' positions, over the largest coordinate.
template <class M>
double relative_gap(const M& a, const M& b) {
    const auto p = positions(a), q = positions(b);
    EXPECT_EQ(p.size(), q.size());
    double gap = 0, size = 1e-300;
    for (std::size_t i = 0; i < p.size() && i < q.size(); ++i)
        for (int d = 0; d < 3; ++d) {
            gap = std::max(gap, std::abs(p[i][d] - q[i][d]));
            size = std::max(size, std::abs(p[i][d]));
        }
    return gap / size;
}

/// Test shapes: a noisy sphere (closed), a noisy open grid (boundary), a noisy torus (genus 1).
template <class M, class T = hmira::default_traits<M>>
std::vector<std::pair<std::string, M>> shapes() {
    std::vector<std::pair<std::string, M>> out;
    M sphere;
    EXPECT_TRUE(hmira::generate_icosahedron(sphere));
    EXPECT_TRUE(hmira::loop_subdivide(sphere, {.levels = 3}));
    out.emplace_back("sphere", std::move(sphere));
    out.emplace_back("grid", mesh_from<M>(triangulated(grid(24, 17))));
    out.emplace_back("torus", mesh_from<M>(triangulated(torus(30, 14))));
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> noise(-0.05, 0.05);
    for (auto& [name, m] : out)
        for (auto v : T::vertices(m)) {
            auto p = T::position(m, v);
            for (int d = 0; d < 3; ++d) p[d] += typename T::scalar(noise(rng));
            T::set_position(m, v, p);
        }
    return out;
}

/// The cases every shape runs: Laplacian and Taubin, uniform and cotangent weights, with and
/// without the boundary fixed, with listed fixed vertices.
struct smoothing_case {
    std::string name;
    bool taubin = false;
    bool cotangent = false;
    bool refresh = true;
    bool fix_boundary = true;
    std::vector<std::size_t> fixed{};
};

std::vector<smoothing_case> cases() {
    return {{"laplacian uniform", false, false, true, true, {}},
            {"laplacian uniform, boundary free, fixed 3 and 40", false, false, true, false, {3, 40}},
            {"laplacian cotangent", false, true, true, true, {}},
            {"laplacian cotangent, frozen weights", false, true, false, true, {}},
            {"taubin uniform", true, false, true, true, {}},
            {"taubin uniform, boundary free", true, false, true, false, {7}},
            {"taubin cotangent", true, true, true, true, {}},
            {"taubin cotangent, frozen weights", true, true, false, false, {}}};
}

template <class M>
hmira::result<hmira::smooth_result> smooth(M& m, const smoothing_case& c, std::size_t iterations, unsigned threads) {
    const auto w = c.cotangent ? hmira::laplacian_weights::cotangent : hmira::laplacian_weights::uniform;
    if (c.taubin)
        return hmira::taubin_smooth(m, {.iterations = iterations,
                                        .weights = w,
                                        .fix_boundary = c.fix_boundary,
                                        .fixed_vertices = c.fixed,
                                        .refresh_weights = c.refresh,
                                        .threads = threads});
    return hmira::laplacian_smooth(m, {.iterations = iterations,
                                       .lambda = 0.5,
                                       .weights = w,
                                       .fix_boundary = c.fix_boundary,
                                       .fixed_vertices = c.fixed,
                                       .refresh_weights = c.refresh,
                                       .threads = threads});
}

template <class M>
void expect_matches_reference(const M& base, const std::string& shape, std::size_t iterations) {
    for (const auto& c : cases()) {
        if (c.cotangent && !hmira::triangle_operable_mesh<M>) continue;
        M want = base;
        reference_smooth(want, {.iterations = iterations,
                                .amounts = c.taubin ? std::vector<double>{0.5, -0.53} : std::vector<double>{0.5},
                                .cotangent = c.cotangent,
                                .refresh = c.refresh,
                                .fix_boundary = c.fix_boundary,
                                .fixed = c.fixed});
        M got = base;
        ASSERT_TRUE(smooth(got, c, iterations, 1)) << shape << ", " << c.name;
        EXPECT_LE(relative_gap(got, want), 1e-12) << shape << ", " << c.name;
        EXPECT_GT(relative_gap(got, base), 1e-4) << shape << ", " << c.name << ": nothing moved";
        for (const unsigned threads : {0u, 2u, 3u}) {
            M again = base;
            ASSERT_TRUE(smooth(again, c, iterations, threads)) << shape << ", " << c.name;
            EXPECT_EQ(positions(again), positions(got)) << shape << ", " << c.name << ", " << threads << " threads";
        }
    }
}

TYPED_TEST(smoothing_reference, every_case_equals_the_reference_and_any_thread_count_gives_the_same_bits) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        for (const auto& [name, m] : shapes<M>()) expect_matches_reference(m, name, 6);
    }
}

TYPED_TEST(smoothing_reference, frozen_cotangent_weights_differ_from_refreshed_ones) {
    using M = TypeParam;
    HMIRA_REQUIRE_TRIANGLE_OPS(M)
    else {
        const M base = shapes<M>().front().second;
        M frozen = base, refreshed = base;
        ASSERT_TRUE(smooth(frozen, {"frozen", false, true, false, true, {}}, 8, 1));
        ASSERT_TRUE(smooth(refreshed, {"refreshed", false, true, true, true, {}}, 8, 1));
        EXPECT_GT(relative_gap(frozen, refreshed), 1e-9);
    }
}

TEST(smoothing_reference_data, models_from_the_test_data_equal_the_reference) {
    const char* dir = std::getenv("HMIRA_TEST_DATA");
    if (!dir) GTEST_SKIP() << "HMIRA_TEST_DATA not set";
    std::size_t read = 0;
    for (const std::string name : {"elephant.off", "fandisk.off", "blobby.off"}) {
        const auto path = std::filesystem::path(dir) / "meshes" / name;
        if (!std::filesystem::exists(path)) continue;
        hmira::halfedge_mesh m;
        ASSERT_TRUE(hmira::io::read_mesh(m, path.string())) << name;
        expect_matches_reference(m, name, 10);
        ++read;
    }
    if (read == 0) GTEST_SKIP() << "no test model found in " << dir;
}

}  // namespace
