// tests/support/checks.hpp
// Assertions shared by the suites: the mesh validator after every mutation, Euler-Poincare,
// and comparisons made independently of the code under test.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <hmira/algorithms/validation/validate.hpp>
#include <hmira/concepts.hpp>

namespace hmira_test {

/// Formats validate()'s findings for a failure message.
inline std::string describe(const std::vector<hmira::mesh_problem>& problems) {
    std::string s;
    for (std::size_t i = 0; i < problems.size() && i < 10; ++i) s += "\n  " + problems[i].message;
    if (problems.size() > 10) s += "\n  ... and " + std::to_string(problems.size() - 10) + " more";
    return s;
}

/// Fails the test with validate()'s findings if the mesh has any problem.
template <class M, class T = hmira::default_traits<M>>
::testing::AssertionResult is_valid(const M& mesh, hmira::validate_options options = {}) {
    const auto problems = hmira::validate<M, T>(mesh, options);
    if (problems.empty()) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << problems.size() << " problem(s):" << describe(problems);
}

/// The mesh's faces as vertex-index loops, each rotated to start at its smallest index: a
/// canonical form that compares connectivity and orientation but not face order.
template <class M, class T = hmira::default_traits<M>>
std::multiset<std::vector<std::size_t>> canonical_faces(const M& mesh) {
    std::multiset<std::vector<std::size_t>> out;
    for (auto f : T::faces(mesh)) {
        std::vector<std::size_t> loop;
        for (auto v : T::face_vertices(mesh, f)) loop.push_back(T::vertex_index(mesh, v));
        std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
        out.insert(loop);
    }
    return out;
}

/// Signed volume enclosed by the faces (fan-triangulated), computed here, not by the library.
template <class M, class T = hmira::default_traits<M>>
double signed_volume(const M& mesh) {
    double vol = 0;
    for (auto f : T::faces(mesh)) {
        std::vector<std::array<double, 3>> p;
        for (auto v : T::face_vertices(mesh, f)) {
            const auto q = T::position(mesh, v);
            p.push_back({double(q[0]), double(q[1]), double(q[2])});
        }
        for (std::size_t i = 1; i + 1 < p.size(); ++i) {
            const auto& a = p[0];
            const auto& b = p[i];
            const auto& c = p[i + 1];
            vol += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                    a[2] * (b[0] * c[1] - b[1] * c[0])) /
                   6.0;
        }
    }
    return vol;
}

}  // namespace hmira_test
