// hmira/adapters/vertex_edge_adjacency.hpp
// Vertex -> incident edges for a mesh that stores only faces. Edges are the vertex pairs of
// adapters/edge_list.hpp, so the answer is the vertex's neighbours, each paired with it.
#pragma once

#include <cstddef>
#include <ranges>
#include <vector>

#include "edge_list.hpp"
#include "vertex_adjacency.hpp"

namespace hmira {

/// Incident edges by brute force: no memory kept; O(F_all x V_face) per query; returns an
/// owning std::vector of vertex_pair_edge.
template <class M, class T = default_traits<M>>
    requires adapter_source_mesh<M, T>
class brute_force_vertex_edge_adjacency {
public:
    /// The mesh's vertex handle.
    using vertex_handle = typename T::vertex_handle;
    /// An edge: its two end vertices, lower index first (see edge_list.hpp).
    using edge_handle = vertex_pair_edge<vertex_handle>;
    brute_force_vertex_edge_adjacency() = default;
    /// Keeps nothing from the mesh. O(1).
    explicit brute_force_vertex_edge_adjacency(const M&) {}

    /// The edges at v, one per neighbour, ordered by the neighbour's vertex index. Scans every
    /// face: O(F_all x V_face) per query.
    std::vector<edge_handle> vertex_edges(const M& m, vertex_handle v) const {
        std::vector<edge_handle> out;
        for (auto w : brute_force_vertex_adjacency<M, T>{}.adjacent_vertices(m, v))
            out.push_back(make_vertex_pair_edge<M, T>(m, v, w));
        return out;
    }
    /// Does nothing: there is no index to rebuild.
    void refresh(const M&) {}
};

/// Incident edges from a neighbour index built once in O(C log C); each query costs
/// O(E_adjacentV) and returns a view over the adapter's arrays (valid while the adapter
/// lives and until its refresh()). Errors: a stale query throws hmira_error.
template <class M, class T = default_traits<M>>
    requires indexed_adapter_source_mesh<M, T>
class indexed_vertex_edge_adjacency {
public:
    /// The mesh's vertex handle.
    using vertex_handle = typename T::vertex_handle;
    /// An edge: its two end vertices, lower index first (see edge_list.hpp).
    using edge_handle = vertex_pair_edge<vertex_handle>;
    indexed_vertex_edge_adjacency() = default;
    /// Builds the neighbour index of m. O(C log C).
    explicit indexed_vertex_edge_adjacency(const M& m) : neighbours_(m) {}

    /// The edges at v, one per neighbour, ordered by the neighbour's vertex index, as a lazy
    /// view over the index (it refers to m too). O(E_adjacentV). Throws hmira_error if m
    /// changed since the last refresh() or is not the indexed mesh.
    auto vertex_edges(const M& m, vertex_handle v) const {
        // The view holds the span (a pointer pair into this adapter) and v by value.
        return neighbours_.adjacent_vertices(m, v) |
               std::views::transform([&m, v](vertex_handle w) { return make_vertex_pair_edge<M, T>(m, v, w); });
    }
    /// Rebuilds the index from m as it is now, O(C log C). Invalidates views returned before.
    void refresh(const M& m) { neighbours_.refresh(m); }
    /// Whether the index was built from m and m has not changed since. O(1).
    bool is_current(const M& m) const { return neighbours_.is_current(m); }
    /// Bytes held by the index. O(1).
    std::size_t memory_bytes() const { return neighbours_.memory_bytes(); }

private:
    indexed_vertex_adjacency<M, T> neighbours_;
};

}  // namespace hmira
