// tests/core/rollback_support.hpp
// The rollback rule as a test: a call cancelled late (its progress callback returning false at
// its last call, and half way) or refused leaves the mesh bit for bit as it was. "As it was" is
// support/snapshot.hpp's comparison: every live element with its index, every position compared
// with == on doubles, every face corner, and on half-edge models every link.
#pragma once

#include <gtest/gtest.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <hmira/core/progress.hpp>
#include <hmira/core/result.hpp>

#include "support/checks.hpp"
#include "support/models.hpp"
#include "support/shapes.hpp"
#include "support/snapshot.hpp"

namespace hmira_test {

/// The quads of `g` split into triangles along one diagonal, for the triangle-only schemes.
inline face_list triangulated(const face_list& g) {
    face_list t{g.points, {}};
    for (const auto& f : g.faces)
        for (std::size_t i = 1; i + 1 < f.size(); ++i) t.faces.push_back({f[0], f[i], f[i + 1]});
    return t;
}

/// `g` without the points no face uses (a valid mesh has no isolated vertex).
inline face_list compacted(const face_list& g) {
    std::vector<std::size_t> id(g.points.size(), std::size_t(-1));
    face_list out;
    for (const auto& f : g.faces) {
        std::vector<std::size_t> loop;
        for (const auto i : f) {
            if (id[i] == std::size_t(-1)) {
                id[i] = out.points.size();
                out.points.push_back(g.points[i]);
            }
            loop.push_back(id[i]);
        }
        out.faces.push_back(std::move(loop));
    }
    return out;
}

/// A mesh of model M built from `g`.
template <class M>
M build(const face_list& g) {
    M m;
    EXPECT_TRUE(add_face_list(m, g));
    return m;
}

/// `run(mesh, progress)` on a fresh mesh from `make()`: run to the end it calls its callback at
/// least `min_calls` times; cancelled at the last of those calls, and at the middle one, it
/// returns errc::cancelled and leaves the mesh as snapshot() saw it before, and valid.
template <class Make, class Run>
void expect_cancel_restores(Make make, Run run, std::size_t min_calls = 2) {
    std::size_t calls = 0;
    {
        auto m = make();
        const auto r = run(m, [&](double) {
            ++calls;
            return true;
        });
        ASSERT_TRUE(r) << r.error().message;
    }
    ASSERT_GE(calls, min_calls) << "the shape is too small to cancel late";
    for (const std::size_t stop_at : {calls, calls / 2 + 1}) {
        SCOPED_TRACE("cancelled at call " + std::to_string(stop_at) + " of " + std::to_string(calls));
        auto m = make();
        const auto before = snapshot(m);
        std::size_t seen = 0;
        const auto r = run(m, [&](double) { return ++seen != stop_at; });
        ASSERT_FALSE(r) << "the call ignored the cancellation";
        EXPECT_EQ(r.error().code, hmira::errc::cancelled) << r.error().message;
        EXPECT_EQ(seen, stop_at) << "the call went on reporting after it was cancelled";
        EXPECT_TRUE(snapshot(m) == before) << "the cancelled call changed the mesh";
        EXPECT_TRUE(hmira_test::is_valid(m));
    }
}

/// `run(mesh)` on a fresh mesh from `make()` fails with `code` and leaves the mesh as it was.
template <class Make, class Run>
void expect_failure_leaves_mesh(Make make, Run run, hmira::errc code) {
    auto m = make();
    const auto before = snapshot(m);
    const auto r = run(m);
    ASSERT_FALSE(r) << "the call did not fail";
    EXPECT_EQ(r.error().code, code) << r.error().message;
    EXPECT_TRUE(snapshot(m) == before) << "the failed call changed the mesh";
}

}  // namespace hmira_test
