// hmira/adapters/edge_list.hpp
// Edges for a mesh that stores only faces: an edge is named by its two end vertices (lower
// vertex index first), so the handle needs no storage and both flavours hand out the same
// handles. Brute force derives the list on every call; indexed keeps it.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "detail/index_support.hpp"

namespace hmira {

/// An edge of a face-list mesh: its end vertices, `a` the one of lower vertex index.
template <class V>
struct vertex_pair_edge {
    /// The end vertices: `a` of lower vertex index, `b` of higher.
    ///@{
    V a{}, b{};
    ///@}
    friend bool operator==(const vertex_pair_edge&, const vertex_pair_edge&) = default;
};

/// The edge {x, y} in its canonical order.
template <class M, class T = default_traits<M>>
vertex_pair_edge<typename T::vertex_handle> make_vertex_pair_edge(const M& m, typename T::vertex_handle x,
                                                                  typename T::vertex_handle y) {
    if (T::vertex_index(m, y) < T::vertex_index(m, x)) return {y, x};
    return {x, y};
}

namespace detail {

/// All distinct undirected edges of the face lists, ordered by (index a, index b).
/// O(C log C) for C face corners.
template <class M, class T>
std::vector<vertex_pair_edge<typename T::vertex_handle>> derive_edges(const M& m) {
    using V = typename T::vertex_handle;
    struct keyed {
        std::uint64_t key;
        vertex_pair_edge<V> e;
    };
    std::vector<keyed> sides;
    for (auto f : T::faces(m))
        detail::for_each_side<M, T>(m, f, [&](V x, V y) {
            const auto e = make_vertex_pair_edge<M, T>(m, x, y);
            sides.push_back(
                {(std::uint64_t(T::vertex_index(m, e.a)) << 32) | std::uint64_t(T::vertex_index(m, e.b)), e});
        });
    std::sort(sides.begin(), sides.end(), [](const keyed& p, const keyed& q) { return p.key < q.key; });
    std::vector<vertex_pair_edge<V>> out;
    out.reserve(sides.size() / 2 + 1);
    for (std::size_t i = 0; i < sides.size(); ++i)
        if (i == 0 || sides[i].key != sides[i - 1].key) out.push_back(sides[i].e);
    return out;
}

}  // namespace detail

/// All edges by brute force: nothing kept; edges() derives the list from the faces on every
/// call, O(C log C) for C face corners, into an owning std::vector; edge_count() likewise.
/// edge_vertices() is O(1) (the handle holds them).
template <class M, class T = default_traits<M>>
    requires adapter_source_mesh<M, T>
class brute_force_edge_list {
public:
    /// The mesh's vertex handle.
    using vertex_handle = typename T::vertex_handle;
    /// An edge: its two end vertices, lower index first.
    using edge_handle = vertex_pair_edge<vertex_handle>;
    brute_force_edge_list() = default;
    /// Keeps nothing from the mesh. O(1).
    explicit brute_force_edge_list(const M&) {}

    /// Every distinct edge of m's faces, ordered by (index a, index b). O(C log C) per call.
    std::vector<edge_handle> edges(const M& m) const { return detail::derive_edges<M, T>(m); }
    /// Number of distinct edges; derives the whole list, O(C log C) per call.
    std::size_t edge_count(const M& m) const { return edges(m).size(); }
    /// The edge's end vertices, lower index first. O(1).
    std::array<vertex_handle, 2> edge_vertices(const M&, edge_handle e) const { return {e.a, e.b}; }
    /// Does nothing: there is no index to rebuild.
    void refresh(const M&) {}
};

/// All edges from a list built once in O(C log C); edges() then returns a std::span into the
/// adapter (O(1), iteration O(E_all)), edge_count() is O(1). Memory: two handles per edge.
/// Errors: a query after the mesh changed, or with another mesh, throws hmira_error.
template <class M, class T = default_traits<M>>
    requires indexed_adapter_source_mesh<M, T>
class indexed_edge_list {
public:
    /// The mesh's vertex handle.
    using vertex_handle = typename T::vertex_handle;
    /// An edge: its two end vertices, lower index first.
    using edge_handle = vertex_pair_edge<vertex_handle>;
    indexed_edge_list() = default;
    /// Builds the edge list of m. O(C log C).
    explicit indexed_edge_list(const M& m) { refresh(m); }

    /// Every distinct edge, ordered by (index a, index b), as a span into the adapter. O(1).
    /// Throws hmira_error if m changed since the last refresh() or is not the indexed mesh.
    std::span<const edge_handle> edges(const M& m) const {
        stamp_.check(m);
        return edges_;
    }
    /// Number of distinct edges. O(1). Throws hmira_error on a stale index or another mesh.
    std::size_t edge_count(const M& m) const {
        stamp_.check(m);
        return edges_.size();
    }
    /// The edge's end vertices, lower index first. O(1); needs no index, so never throws.
    std::array<vertex_handle, 2> edge_vertices(const M&, edge_handle e) const { return {e.a, e.b}; }

    /// Rebuilds the list from m as it is now, O(C log C). Invalidates spans returned before.
    void refresh(const M& m) {
        edges_ = detail::derive_edges<M, T>(m);
        edges_.shrink_to_fit();
        stamp_ = detail::index_stamp<M, T>(m, "indexed_edge_list");
    }
    /// Whether the list was built from m and m has not changed since. O(1).
    bool is_current(const M& m) const { return stamp_.is_current(m); }
    /// Bytes held by the list. O(1).
    std::size_t memory_bytes() const { return edges_.capacity() * sizeof(edge_handle); }

private:
    std::vector<edge_handle> edges_;
    detail::index_stamp<M, T> stamp_;
};

}  // namespace hmira
