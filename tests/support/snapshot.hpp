// tests/support/snapshot.hpp
// Everything an "unchanged on error" test compares, taken through the traits alone: the live
// elements with their indices, positions and face corners, and on half-edge models every link.
#pragma once

#include <algorithm>
#include <array>
#include <vector>

#include <hmira/concepts.hpp>

namespace hmira_test {

/// The live state of a mesh as seen through traits T. Index bounds, garbage and change
/// counters are left out: "unchanged" lets those differ.
struct mesh_snapshot {
    std::vector<long long> data;
    std::vector<std::array<double, 3>> positions;
    bool operator==(const mesh_snapshot&) const = default;
};

/// `face_corners = false` leaves out the walks along face loops, for a mesh whose links a test
/// corrupted on purpose (the halfedge links still say everything on a half-edge model).
template <class M, class T = hmira::default_traits<M>>
mesh_snapshot snapshot(const M& m, bool face_corners = true) {
    mesh_snapshot s;
    s.data.push_back((long long)T::vertex_count(m));
    s.data.push_back((long long)T::face_count(m));
    for (auto v : T::vertices(m)) {
        s.data.push_back((long long)T::vertex_index(m, v));
        const auto p = T::position(m, v);
        s.positions.push_back({double(p[0]), double(p[1]), double(p[2])});
    }
    for (auto f : T::faces(m)) {
        s.data.push_back((long long)T::face_index(m, f));
        if (face_corners)
            for (auto v : T::face_vertices(m, f)) s.data.push_back((long long)T::vertex_index(m, v));
        s.data.push_back(-3);
    }
    if constexpr (hmira::halfedge_index_mesh<M, T> && hmira::edge_list_mesh<M, T>) {
        auto hi = [&](typename T::halfedge_handle h) {
            return h == T::null_halfedge() ? -1LL : (long long)T::halfedge_index(m, h);
        };
        auto fi = [&](typename T::face_handle f) {
            return f == T::null_face() ? -1LL : (long long)T::face_index(m, f);
        };
        s.data.push_back((long long)T::edge_count(m));
        for (auto v : T::vertices(m)) s.data.push_back(hi(T::vertex_halfedge(m, v)));
        for (auto h : T::halfedges(m)) {
            s.data.push_back(hi(h));
            s.data.push_back(hi(T::next(m, h)));
            s.data.push_back(hi(T::prev(m, h)));
            s.data.push_back((long long)T::vertex_index(m, T::target(m, h)));
            s.data.push_back(fi(T::face(m, h)));
        }
        for (auto f : T::faces(m)) {
            s.data.push_back(hi(T::face_halfedge(m, f)));
            if constexpr (hmira::inner_ring_mesh<M, T>) {
                std::vector<long long> rings;
                for (auto r : T::inner_rings(m, f)) rings.push_back(hi(r));
                std::sort(rings.begin(), rings.end());
                s.data.insert(s.data.end(), rings.begin(), rings.end());
            }
            s.data.push_back(-2);
        }
    }
    return s;
}

}  // namespace hmira_test
