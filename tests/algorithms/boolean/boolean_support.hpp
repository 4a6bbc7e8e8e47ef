// tests/algorithms/boolean/boolean_support.hpp
// Checks the boolean suites share, computed from the connectivity alone (not by the code under test).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <map>
#include <vector>

#include <hmira/traits.hpp>

namespace hmira_test {

/// Every undirected edge is run as often in one direction as in the other: the surface is closed.
template <class M, class T = hmira::default_traits<M>>
bool closed(const M& m) {
    std::map<std::array<std::size_t, 2>, int> count;
    for (auto f : T::faces(m)) {
        std::vector<std::size_t> loop;
        for (auto v : T::face_vertices(m, f)) loop.push_back(T::vertex_index(m, v));
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const std::size_t a = loop[i], b = loop[(i + 1) % loop.size()];
            count[{std::min(a, b), std::max(a, b)}] += a < b ? 1 : -1;
        }
    }
    return std::all_of(count.begin(), count.end(), [](const auto& e) { return e.second == 0; });
}

}  // namespace hmira_test
