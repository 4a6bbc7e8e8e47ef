// tests/algorithms/editing/editing_support.hpp
// What the editing suites check with, computed here from the traits alone: element counts,
// outward orientation of convex solids, face-size histograms, and positions by lookup.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <type_traits>
#include <vector>

#include <hmira/algorithms/editing/editing.hpp>
#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/topology/mesh_topology.hpp>
#include <random>
#include <hmira/concepts.hpp>

#include "support/checks.hpp"
#include "support/models.hpp"
#include "support/shapes.hpp"

namespace hmira_test {

/// Comparison tolerance for the model's scalar (OpenMesh's PolyMesh stores floats).
template <class M, class T = hmira::default_traits<M>>
double tol() {
    return std::is_same_v<typename T::scalar, float> ? 1e-5 : 1e-11;
}

struct counts {
    long long v = 0, e = 0, f = 0;
    long long chi() const { return v - e + f; }
    friend bool operator==(const counts&, const counts&) = default;
};
inline std::ostream& operator<<(std::ostream& o, const counts& c) {
    return o << "{V " << c.v << ", E " << c.e << ", F " << c.f << "}";
}

template <class M, class T = hmira::default_traits<M>>
counts count(const M& m) {
    return {(long long)T::vertex_count(m), (long long)T::edge_count(m), (long long)T::face_count(m)};
}

template <class M, class T = hmira::default_traits<M>>
std::array<double, 3> p3(const M& m, typename T::vertex_handle v) {
    const auto p = T::position(m, v);
    return {double(p[0]), double(p[1]), double(p[2])};
}

/// Newell normal of a face (twice its area), computed here from face_vertices.
template <class M, class T = hmira::default_traits<M>>
std::array<double, 3> newell(const M& m, typename T::face_handle f) {
    std::vector<std::array<double, 3>> p;
    for (auto v : T::face_vertices(m, f)) p.push_back(p3<M, T>(m, v));
    std::array<double, 3> n{0, 0, 0};
    for (std::size_t i = 0; i < p.size(); ++i) {
        const auto& a = p[i];
        const auto& b = p[(i + 1) % p.size()];
        n[0] += (a[1] - b[1]) * (a[2] + b[2]);
        n[1] += (a[2] - b[2]) * (a[0] + b[0]);
        n[2] += (a[0] - b[0]) * (a[1] + b[1]);
    }
    return n;
}

template <class M, class T = hmira::default_traits<M>>
std::array<double, 3> centroid(const M& m, typename T::face_handle f) {
    std::array<double, 3> c{0, 0, 0};
    double k = 0;
    for (auto v : T::face_vertices(m, f)) {
        const auto p = p3<M, T>(m, v);
        for (int i = 0; i < 3; ++i) c[i] += p[i];
        k += 1;
    }
    for (int i = 0; i < 3; ++i) c[i] /= k;
    return c;
}

/// For a convex solid around `center`: every face's normal points away from the center.
/// Catches inverted winding of any single face.
template <class M, class T = hmira::default_traits<M>>
::testing::AssertionResult faces_point_outward(const M& m, std::array<double, 3> center = {0, 0, 0}) {
    for (auto f : T::faces(m)) {
        const auto n = newell<M, T>(m, f);
        const auto c = centroid<M, T>(m, f);
        const double d = n[0] * (c[0] - center[0]) + n[1] * (c[1] - center[1]) + n[2] * (c[2] - center[2]);
        if (!(d > 0))
            return ::testing::AssertionFailure()
                   << "face " << T::face_index(m, f) << " points inward (n . (c - o) = " << d << ")";
    }
    return ::testing::AssertionSuccess();
}

/// Histogram of face degrees.
template <class M, class T = hmira::default_traits<M>>
std::map<std::size_t, std::size_t> face_sizes(const M& m) {
    std::map<std::size_t, std::size_t> h;
    for (auto f : T::faces(m)) ++h[(std::size_t)std::ranges::distance(T::face_vertices(m, f))];
    return h;
}

template <class M, class T = hmira::default_traits<M>>
std::size_t degree(const M& m, typename T::vertex_handle v) {
    std::size_t d = 0;
    const auto s = T::vertex_halfedge(m, v);
    if (s == T::null_halfedge()) return 0;
    auto h = s;
    do {
        ++d;
        h = T::next(m, T::opposite(m, h));
    } while (h != s);
    return d;
}

inline double dist(const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

/// The vertex at position p (within tol), or none.
template <class M, class T = hmira::default_traits<M>>
bool has_vertex_at(const M& m, std::array<double, 3> p, double eps = tol<M, T>()) {
    for (auto v : T::vertices(m))
        if (dist(p3<M, T>(m, v), p) < eps) return true;
    return false;
}

/// Fails unless the mesh validates and its Euler characteristic is `chi`.
template <class M, class T = hmira::default_traits<M>>
::testing::AssertionResult valid_with_chi(const M& m, long long chi, hmira::validate_options options = {}) {
    auto v = is_valid<M, T>(m, options);
    if (!v) return v;
    const auto c = count<M, T>(m);
    if (c.chi() != chi)
        return ::testing::AssertionFailure() << "Euler characteristic " << c.chi() << ", expected " << chi << " " << c;
    return ::testing::AssertionSuccess();
}

/// The surface of an nx x ny x nz box of unit cells, every side a grid of outward quads; the
/// test's own data. Closed, genus 0, convex around its centre (nx/2, ny/2, nz/2).
inline face_list lattice_box(int nx, int ny, int nz) {
    face_list b;
    std::map<std::array<int, 3>, std::size_t> id;
    auto vid = [&](std::array<int, 3> p) {
        auto [it, fresh] = id.emplace(p, b.points.size());
        if (fresh) b.points.push_back({double(p[0]), double(p[1]), double(p[2])});
        return it->second;
    };
    const int n[3] = {nx, ny, nz};
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            // (u, v, axis) right-handed: u x v = +axis; the low side is wound the other way.
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            for (int i = 0; i < n[u]; ++i)
                for (int j = 0; j < n[v]; ++j) {
                    std::array<int, 3> c00{}, c10{}, c11{}, c01{};
                    for (auto* c : {&c00, &c10, &c11, &c01}) (*c)[axis] = side ? n[axis] : 0;
                    c00[u] = i;
                    c00[v] = j;
                    c10[u] = i + 1;
                    c10[v] = j;
                    c11[u] = i + 1;
                    c11[v] = j + 1;
                    c01[u] = i;
                    c01[v] = j + 1;
                    if (side)
                        b.faces.push_back({vid(c00), vid(c10), vid(c11), vid(c01)});
                    else
                        b.faces.push_back({vid(c00), vid(c01), vid(c11), vid(c10)});
                }
        }
    return b;
}

/// The faces whose centroid lies within `tol` of the plane coordinate[axis] = value.
template <class M, class T = hmira::default_traits<M>>
std::vector<typename T::face_handle> faces_on_plane(const M& m, int axis, double value, double eps = 1e-9) {
    std::vector<typename T::face_handle> out;
    for (auto f : T::faces(m))
        if (std::abs(centroid<M, T>(m, f)[(std::size_t)axis] - value) < eps) out.push_back(f);
    return out;
}

}  // namespace hmira_test
