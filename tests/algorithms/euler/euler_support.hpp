// tests/algorithms/euler/euler_support.hpp
// What the Euler-operator suites check with, computed here from the traits alone: exact
// snapshots (for "a failed operator changes nothing"), canonical forms keyed by vertex
// position (for "the inverses restore the mesh, up to relabelling"), and the counts of the
// Euler-Poincare formula V - E + F - R = 2 (S - H) in hmira's surface reading of it.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <hmira/algorithms/euler/euler.hpp>
#include <hmira/concepts.hpp>

#include "support/checks.hpp"
#include "support/shapes.hpp"

namespace hmira_test {

template <class M, class T = hmira::default_traits<M>>
concept indexed_halfedge_model =
    hmira::halfedge_index_mesh<M, T> && hmira::vertex_index_mesh<M, T> && hmira::face_index_mesh<M, T> &&
    hmira::edge_index_mesh<M, T> && hmira::positioned_mesh<M, T>;

/// Skips the current typed test (and returns) on a model without the Euler operators: no raw
/// halfedge layer, or triangles only.
#define HMIRA_REQUIRE_EULER(M)                                                                  \
    if constexpr (!hmira::euler_mutable_mesh<M> || !::hmira_test::indexed_halfedge_model<M>) {  \
        GTEST_SKIP() << "not an euler_mutable_mesh (no raw halfedge layer, or triangles only)"; \
        return;                                                                                 \
    }

/// Every reference the mesh holds, as indices, plus positions: equal snapshots mean the mesh
/// is unchanged as seen through its traits.
struct snapshot {
    std::vector<long long> data;
    std::vector<std::array<double, 3>> positions;
    bool operator==(const snapshot&) const = default;
};

template <class M, class T = hmira::default_traits<M>>
    requires indexed_halfedge_model<M, T>
snapshot take_snapshot(const M& m) {
    snapshot s;
    auto hi = [&](typename T::halfedge_handle h) {
        return h == T::null_halfedge() ? -1LL : (long long)T::halfedge_index(m, h);
    };
    auto fi = [&](typename T::face_handle f) { return f == T::null_face() ? -1LL : (long long)T::face_index(m, f); };
    s.data.push_back((long long)T::vertex_count(m));
    s.data.push_back((long long)T::edge_count(m));
    s.data.push_back((long long)T::face_count(m));
    s.data.push_back((long long)T::vertex_index_bound(m));
    s.data.push_back((long long)T::halfedge_index_bound(m));
    s.data.push_back((long long)T::face_index_bound(m));
    for (auto v : T::vertices(m)) {
        s.data.push_back((long long)T::vertex_index(m, v));
        s.data.push_back(hi(T::vertex_halfedge(m, v)));
        const auto p = T::position(m, v);
        s.positions.push_back({double(p[0]), double(p[1]), double(p[2])});
    }
    for (auto h : T::halfedges(m)) {
        s.data.push_back(hi(h));
        s.data.push_back(hi(T::next(m, h)));
        s.data.push_back(hi(T::prev(m, h)));
        s.data.push_back((long long)T::vertex_index(m, T::target(m, h)));
        s.data.push_back(fi(T::face(m, h)));
    }
    for (auto f : T::faces(m)) {
        s.data.push_back(fi(f));
        s.data.push_back(hi(T::face_halfedge(m, f)));
        if constexpr (hmira::inner_ring_mesh<M, T>)
            for (auto r : T::inner_rings(m, f)) s.data.push_back(hi(r));
        s.data.push_back(-2);
    }
    if constexpr (hmira::change_counted_mesh<M, T>) s.data.push_back((long long)T::change_count(m));
    return s;
}

using point_key = std::tuple<double, double, double>;
using position_loop = std::vector<point_key>;

/// The mesh with every vertex named by its position (positions are distinct in these
/// suites): faces with their rings, boundary loops, isolated vertices. Equal forms mean the
/// same connectivity up to relabelling, and the same positions.
struct canonical_form {
    std::multiset<std::pair<position_loop, std::vector<position_loop>>> faces;
    std::multiset<position_loop> boundary_loops;
    std::multiset<point_key> isolated;
    bool operator==(const canonical_form&) const = default;
};

template <class M, class T = hmira::default_traits<M>>
point_key key_of(const M& m, typename T::vertex_handle v) {
    const auto p = T::position(m, v);
    return {double(p[0]), double(p[1]), double(p[2])};
}

template <class M, class T = hmira::default_traits<M>>
position_loop loop_of(const M& m, typename T::halfedge_handle start) {
    position_loop out;
    auto h = start;
    do {
        out.push_back(key_of<M, T>(m, T::target(m, h)));
        h = T::next(m, h);
    } while (h != start && out.size() < 1000000);
    std::rotate(out.begin(), std::min_element(out.begin(), out.end()), out.end());
    return out;
}

template <class M, class T = hmira::default_traits<M>>
    requires indexed_halfedge_model<M, T>
canonical_form canonical(const M& m) {
    canonical_form c;
    for (auto f : T::faces(m)) {
        std::vector<position_loop> rings;
        if constexpr (hmira::inner_ring_mesh<M, T>)
            for (auto r : T::inner_rings(m, f)) rings.push_back(loop_of<M, T>(m, r));
        std::sort(rings.begin(), rings.end());
        c.faces.insert({loop_of<M, T>(m, T::face_halfedge(m, f)), rings});
    }
    std::vector<std::uint8_t> seen(T::halfedge_index_bound(m), 0);
    for (auto h : T::halfedges(m)) {
        if (T::face(m, h) != T::null_face() || seen[T::halfedge_index(m, h)]) continue;
        auto x = h;
        do {
            seen[T::halfedge_index(m, x)] = 1;
            x = T::next(m, x);
        } while (x != h);
        c.boundary_loops.insert(loop_of<M, T>(m, h));
    }
    for (auto v : T::vertices(m))
        if (T::vertex_halfedge(m, v) == T::null_halfedge()) c.isolated.insert(key_of<M, T>(m, v));
    return c;
}

/// The counts of V - E + F - R, with F = faces + boundary loops + isolated vertices, walked
/// here from the halfedges (not asked of the code under test).
struct euler_counts {
    long long v = 0, e = 0, faces = 0, boundary_loops = 0, isolated = 0, rings = 0;
    long long lhs() const { return v - e + faces + boundary_loops + isolated - rings; }
};

template <class M, class T = hmira::default_traits<M>>
    requires indexed_halfedge_model<M, T>
euler_counts count_euler(const M& m) {
    euler_counts k;
    for (auto v : T::vertices(m)) {
        ++k.v;
        if (T::vertex_halfedge(m, v) == T::null_halfedge()) ++k.isolated;
    }
    std::vector<std::uint8_t> seen(T::halfedge_index_bound(m), 0);
    for (auto h : T::halfedges(m)) {
        ++k.e;  // halved below
        if (T::face(m, h) != T::null_face() || seen[T::halfedge_index(m, h)]) continue;
        ++k.boundary_loops;
        auto x = h;
        do {
            seen[T::halfedge_index(m, x)] = 1;
            x = T::next(m, x);
        } while (x != h);
    }
    k.e /= 2;
    for (auto f : T::faces(m)) {
        ++k.faces;
        if constexpr (hmira::inner_ring_mesh<M, T>) k.rings += (long long)std::ranges::distance(T::inner_rings(m, f));
    }
    return k;
}

/// Checks V - E + F - R == 2 (S - H) for S - H tracked by the caller.
template <class M, class T = hmira::default_traits<M>>
::testing::AssertionResult euler_poincare_holds(const M& m, long long shells_minus_holes) {
    const auto k = count_euler<M, T>(m);
    if (k.lhs() == 2 * shells_minus_holes) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "V - E + F - R = " << k.v << " - " << k.e << " + (" << k.faces
                                         << " faces + " << k.boundary_loops << " boundary loops + " << k.isolated
                                         << " isolated) - " << k.rings << " = " << k.lhs()
                                         << ", expected 2 (S - H) = " << 2 * shells_minus_holes;
}

/// validate() in relaxed mode: Euler construction passes through wire edges and faces of
/// fewer than three sides.
template <class M, class T = hmira::default_traits<M>>
::testing::AssertionResult is_valid_relaxed(const M& m) {
    return is_valid<M, T>(m, hmira::validate_options{.relaxed = true, .check_geometry = false, .max_problems = 20});
}

/// The halfedge from a to b, or null (O(valence of a)).
template <class M, class T = hmira::default_traits<M>>
typename T::halfedge_handle find_halfedge(const M& m, typename T::vertex_handle a, typename T::vertex_handle b) {
    const auto start = T::vertex_halfedge(m, a);
    if (start == T::null_halfedge()) return T::null_halfedge();
    auto h = start;
    do {
        if (T::target(m, h) == b) return h;
        h = T::next(m, T::opposite(m, h));
    } while (h != start);
    return T::null_halfedge();
}

}  // namespace hmira_test

namespace hmira_test {

/// Drops deleted elements with the model's own garbage collection, where it has one.
template <class M>
void compact(M& m) {
    if constexpr (requires { m.collect_garbage(); })
        (void)m.collect_garbage();
    else if constexpr (requires { m.garbage_collection(); })
        m.garbage_collection();
}

/// A mesh in the suites' shapes, built through the traits.
template <class M>
M mesh_from(const face_list& g) {
    M m;
    EXPECT_TRUE(add_face_list(m, g));
    return m;
}

}  // namespace hmira_test
