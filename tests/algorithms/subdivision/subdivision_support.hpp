// tests/algorithms/subdivision/subdivision_support.hpp
// Checks every subdivision scheme shares: coordinates near the largest double give finite
// results (the same, scaled, as a small copy's), and a cancellation at any call of the progress
// callback leaves the mesh as it was, the callback coming at least once per 65536 elements.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include <hmira/core/progress.hpp>

#include "algorithms/triangle/triangle_support.hpp"
#include "support/cancel_points.hpp"

namespace hmira_test {

/// The tetrahedron of coordinates near the largest double whose subdivision wrote infinities
/// (a + b overflows), scaled by 2^-`shift` (exact).
inline face_list huge_tetrahedron(int shift = 0) {
    const double c = std::ldexp(1.7e308, -shift);
    return {{{c, c, 0}, {c, -c, 0}, {-c, 0, 0}, {0, 0, c}}, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}}};
}

/// `run` on the huge tetrahedron gives finite positions equal, bit for bit, to 2^600 times
/// those it gives on the tetrahedron scaled by 2^-600 (where nothing can overflow).
template <class M, class Run>
void expect_huge_coordinates_subdivide_like_small_ones(Run run) {
    using T = hmira::default_traits<M>;
    M huge = mesh_from<M>(huge_tetrahedron()), small = mesh_from<M>(huge_tetrahedron(600));
    auto r = run(huge);
    ASSERT_TRUE(r) << r.error().message;
    ASSERT_TRUE(run(small));
    EXPECT_TRUE(valid_topology(huge));
    ASSERT_EQ(T::vertex_count(huge), T::vertex_count(small));
    std::vector<std::array<double, 3>> a, b;
    for (auto v : T::vertices(huge)) {
        const auto p = T::position(huge, v);
        a.push_back({double(p[0]), double(p[1]), double(p[2])});
    }
    for (auto v : T::vertices(small)) {
        const auto p = T::position(small, v);
        b.push_back({std::ldexp(double(p[0]), 600), std::ldexp(double(p[1]), 600), std::ldexp(double(p[2]), 600)});
    }
    for (std::size_t i = 0; i < a.size(); ++i)
        for (int d = 0; d < 3; ++d) {
            ASSERT_TRUE(std::isfinite(a[i][d])) << "vertex " << i << " axis " << d;
            EXPECT_LE(std::abs(a[i][d]), 1.7e308) << "vertex " << i << " axis " << d;
            EXPECT_EQ(a[i][d], b[i][d]) << "vertex " << i << " axis " << d;
        }
}

/// `run(mesh, progress)` cancelled at several calls of its callback: errc::cancelled, the
/// mesh bit for bit as before and valid; run to the end, the callback came at least once per
/// 65536 of `elements` (the vertices, edges and faces the levels take as input).
template <class M, class Run>
void expect_cancellation_restores(const M& original, std::size_t elements, Run run) {
    const auto before = take_snapshot(original);
    int calls_to_finish = 0;
    {
        M m = original;
        double last = -1;
        auto r = run(m, [&](double f) {
            EXPECT_GE(f, last);
            EXPECT_LE(f, 1.0);
            last = f;
            ++calls_to_finish;
            return true;
        });
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_TRUE(valid_topology(m));
        M plain = original;
        ASSERT_TRUE(run(plain, hmira::progress_function{}));
        EXPECT_EQ(take_snapshot(plain), take_snapshot(m));  // the callback changes nothing
    }
    EXPECT_GE(std::size_t(calls_to_finish), elements / 65536) << elements << " elements";
    ASSERT_GE(calls_to_finish, 3);
    for (const int stop_at : hmira_test::cancel_points(calls_to_finish, 6)) {
        M m = original;
        int calls = 0;
        auto r = run(m, [&](double) { return ++calls < stop_at; });
        ASSERT_FALSE(r) << "stop at call " << stop_at;
        EXPECT_EQ(r.error().code, hmira::errc::cancelled);
        EXPECT_NE(r.error().message.find("cancelled"), std::string::npos);
        EXPECT_EQ(take_snapshot(m), before) << "stop at call " << stop_at;
        EXPECT_TRUE(valid_topology(m));
    }
}

}  // namespace hmira_test
