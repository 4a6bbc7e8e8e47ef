// hmira/adapters/vertex_adjacency.hpp
// Vertex -> adjacent vertices for a mesh that has only face lists (thesis 7.2): by scanning
// every face on each query, or from a neighbour index built once. Use them through
// adapted_mesh (adapters/adapted_mesh.hpp), which presents them as vertex_adjacency_mesh.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "detail/index_support.hpp"

namespace hmira {

/// Adjacent vertices by brute force: no memory kept, each query scans all faces.
/// Cost per query O(F_all x V_face) (thesis 4.1: above the efficient limit). The answer is
/// an owning std::vector, each neighbour once, ordered by vertex index.
template <class M, class T = default_traits<M>>
    requires adapter_source_mesh<M, T>
class brute_force_vertex_adjacency {
public:
    /// The mesh's vertex handle.
    using vertex_handle = typename T::vertex_handle;
    brute_force_vertex_adjacency() = default;
    /// Keeps nothing from the mesh. O(1).
    explicit brute_force_vertex_adjacency(const M&) {}

    /// Vertices sharing an edge with v, each once, ordered by vertex index. Scans every face:
    /// O(F_all x V_face) per query.
    std::vector<vertex_handle> adjacent_vertices(const M& m, vertex_handle v) const {
        std::vector<vertex_handle> out;
        for (auto f : T::faces(m))
            detail::for_each_side<M, T>(m, f, [&](vertex_handle a, vertex_handle b) {
                if (a == v)
                    out.push_back(b);
                else if (b == v)
                    out.push_back(a);
            });
        // An interior edge is seen from both its faces.
        auto less = [&](vertex_handle a, vertex_handle b) { return T::vertex_index(m, a) < T::vertex_index(m, b); };
        std::sort(out.begin(), out.end(), less);
        out.erase(std::unique(out.begin(), out.end()), out.end());
        return out;
    }
    /// Does nothing: there is no index to rebuild.
    void refresh(const M&) {}
};

/// Adjacent vertices from an index: built once in O(C log C) for C face corners (O(C) plus a
/// sort of each vertex's short row), then each query costs O(V_adjacentV) and returns a
/// std::span into the adapter's own arrays (valid while the adapter lives and until its
/// refresh()). Memory: one uint32 per vertex plus one handle per (vertex, neighbour) pair.
/// Errors: a query after the mesh changed, or with another mesh, throws hmira_error.
template <class M, class T = default_traits<M>>
    requires indexed_adapter_source_mesh<M, T>
class indexed_vertex_adjacency {
public:
    /// The mesh's vertex handle.
    using vertex_handle = typename T::vertex_handle;
    indexed_vertex_adjacency() = default;
    /// Builds the neighbour index of m. O(C log C).
    explicit indexed_vertex_adjacency(const M& m) { refresh(m); }

    /// Vertices sharing an edge with v, each once, ordered by vertex index, as a span into the
    /// index. O(V_adjacentV). Throws hmira_error if m changed since the last refresh() or is
    /// not the indexed mesh.
    std::span<const vertex_handle> adjacent_vertices(const M& m, vertex_handle v) const {
        stamp_.check(m);
        return rows_.row(T::vertex_index(m, v));
    }

    /// Rebuilds the index from the mesh as it is now. Invalidates spans returned before.
    void refresh(const M& m) {
        const auto handles = detail::vertex_handles_by_index<M, T>(m);
        auto raw = detail::build_csr<std::uint32_t>(handles.size(), [&](auto&& push) {
            for (auto f : T::faces(m))
                detail::for_each_side<M, T>(m, f, [&](vertex_handle a, vertex_handle b) {
                    const auto ia = static_cast<std::uint32_t>(T::vertex_index(m, a));
                    const auto ib = static_cast<std::uint32_t>(T::vertex_index(m, b));
                    push(ia, ib);
                    push(ib, ia);
                });
        });
        // Sort and deduplicate each row in place, then compact into handles.
        rows_.offsets.assign(handles.size() + 1, 0);
        rows_.values.clear();
        rows_.values.reserve(raw.values.size() / 2 + 1);
        for (std::size_t r = 0; r < handles.size(); ++r) {
            auto* b = raw.values.data() + raw.offsets[r];
            auto* e = raw.values.data() + raw.offsets[r + 1];
            std::sort(b, e);
            e = std::unique(b, e);
            for (auto* p = b; p != e; ++p) rows_.values.push_back(handles[*p]);
            rows_.offsets[r + 1] = static_cast<std::uint32_t>(rows_.values.size());
        }
        rows_.values.shrink_to_fit();
        stamp_ = detail::index_stamp<M, T>(m, "indexed_vertex_adjacency");
    }

    /// Whether the index was built from m and m has not changed since. O(1).
    bool is_current(const M& m) const { return stamp_.is_current(m); }
    /// Bytes held by the index. O(1).
    std::size_t memory_bytes() const { return rows_.memory_bytes(); }

private:
    detail::csr<vertex_handle> rows_;
    detail::index_stamp<M, T> stamp_;
};

}  // namespace hmira
