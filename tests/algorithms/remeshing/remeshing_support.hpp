// What the remeshing suites share: positions as doubles, the share of edges near the target
// length, and the set of all positions.
#pragma once

#include <array>
#include <cstddef>
#include <set>

#include <hmira/core/vec3.hpp>
#include <hmira/traits.hpp>

namespace hmira_test {

/// A vertex's position as doubles.
template <class M, class T = hmira::default_traits<M>>
hmira::vec3<double> at(const M& m, typename T::vertex_handle v) {
    const auto p = T::position(m, v);
    return {double(p[0]), double(p[1]), double(p[2])};
}

/// Fraction of the edges with length in [4/5 L, 4/3 L], measured here.
template <class M, class T = hmira::default_traits<M>>
double fraction_in_band(const M& m, double L) {
    std::size_t in = 0, all = 0;
    for (auto e : T::edges(m)) {
        const auto ends = T::edge_vertices(m, e);
        const double l = hmira::norm(at(m, ends[0]) - at(m, ends[1]));
        in += l >= 0.8 * L && l <= 4.0 / 3.0 * L;
        ++all;
    }
    return all ? double(in) / double(all) : 0;
}

template <class M, class T = hmira::default_traits<M>>
std::set<std::array<double, 3>> all_positions(const M& m) {
    std::set<std::array<double, 3>> out;
    for (auto v : T::vertices(m)) {
        const auto p = at(m, v);
        out.insert({p.x, p.y, p.z});
    }
    return out;
}

}  // namespace hmira_test
