// hmira/algorithms/topology/edge_census.hpp
// The undirected edges of a mesh derived from its face lists alone, with how often each is
// used in each direction. Face-vertex meshes have no edges of their own; topology queries
// and validation count edges, boundaries and orientation conflicts from this census.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "../../concepts.hpp"

namespace hmira {

/// One undirected edge {a, b} (a < b, vertex indices) and how many face sides use a->b and b->a.
struct census_edge {
    ///@{
    /// The end vertices' indices, a < b.
    std::uint32_t a = 0, b = 0;
    ///@}
    std::uint32_t forward = 0;   ///< face sides running a -> b
    std::uint32_t backward = 0;  ///< face sides running b -> a
    /// Face sides in either direction.
    std::uint32_t uses() const noexcept { return forward + backward; }
    /// Exactly one face side: the edge is on the boundary.
    bool is_boundary() const noexcept { return uses() == 1; }
};

template <class M, class T = default_traits<M>>
concept edge_census_mesh = face_vertex_range_mesh<M, T> && vertex_index_mesh<M, T>;

/// All undirected edges of the face lists, sorted by (a, b). O(V + C log d) for C face corners
/// and vertex degree d (linear in practice).
template <class M, class T = default_traits<M>>
    requires edge_census_mesh<M, T>
std::vector<census_edge> edge_census(const M& mesh) {
    struct side {
        std::uint64_t key;
        bool forward;
    };
    std::vector<side> sides;
    for (auto f : T::faces(mesh)) {
        std::uint32_t first = 0, prev = 0;
        bool started = false;
        for (auto v : T::face_vertices(mesh, f)) {
            const auto i = static_cast<std::uint32_t>(T::vertex_index(mesh, v));
            if (!started) {
                first = i;
                started = true;
            } else
                sides.push_back(prev < i ? side{(std::uint64_t(prev) << 32) | i, true}
                                         : side{(std::uint64_t(i) << 32) | prev, false});
            prev = i;
        }
        if (started && prev != first)
            sides.push_back(prev < first ? side{(std::uint64_t(prev) << 32) | first, true}
                                         : side{(std::uint64_t(first) << 32) | prev, false});
    }
    // Sorted by the smaller vertex with a counting sort, then each vertex's few sides by the
    // other vertex: O(C log d) for vertex degree d rather than a sort of all C sides.
    std::uint32_t top = 0;
    for (const auto& x : sides) top = std::max(top, static_cast<std::uint32_t>(x.key >> 32));
    std::vector<std::size_t> start(sides.empty() ? 1 : std::size_t(top) + 2, 0);
    for (const auto& x : sides) ++start[(x.key >> 32) + 1];
    for (std::size_t a = 1; a < start.size(); ++a) start[a] += start[a - 1];
    {
        std::vector<side> by_first(sides.size());
        auto fill = start;
        for (const auto& x : sides) by_first[fill[x.key >> 32]++] = x;
        sides.swap(by_first);
    }
    for (std::size_t a = 0; a + 1 < start.size(); ++a)
        std::sort(sides.begin() + std::ptrdiff_t(start[a]), sides.begin() + std::ptrdiff_t(start[a + 1]),
                  [](const side& x, const side& y) { return x.key < y.key; });
    std::vector<census_edge> out;
    for (std::size_t i = 0; i < sides.size();) {
        census_edge e{static_cast<std::uint32_t>(sides[i].key >> 32), static_cast<std::uint32_t>(sides[i].key), 0, 0};
        std::size_t j = i;
        for (; j < sides.size() && sides[j].key == sides[i].key; ++j) (sides[j].forward ? e.forward : e.backward)++;
        out.push_back(e);
        i = j;
    }
    return out;
}

}  // namespace hmira
