// hmira/adapters/vertex_face_adjacency.hpp
// Vertex -> faces around it for a mesh that has only face lists: by scanning every face on
// each query, or from a vertex -> face index built once.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "detail/index_support.hpp"

namespace hmira {

/// Faces around a vertex by brute force: no memory kept; cost per query O(F_all x V_face).
/// Returns an owning std::vector, in face order.
template <class M, class T = default_traits<M>>
    requires adapter_source_mesh<M, T>
class brute_force_vertex_face_adjacency {
public:
    /// The mesh's vertex handle.
    using vertex_handle = typename T::vertex_handle;
    /// The mesh's face handle.
    using face_handle = typename T::face_handle;
    brute_force_vertex_face_adjacency() = default;
    /// Keeps nothing from the mesh. O(1).
    explicit brute_force_vertex_face_adjacency(const M&) {}

    /// The faces that have v as a corner, each once, in face order. Scans every face:
    /// O(F_all x V_face) per query.
    std::vector<face_handle> vertex_faces(const M& m, vertex_handle v) const {
        std::vector<face_handle> out;
        for (auto f : T::faces(m))
            for (auto w : T::face_vertices(m, f))
                if (w == v) {
                    out.push_back(f);
                    break;
                }
        return out;
    }
    /// Does nothing: there is no index to rebuild.
    void refresh(const M&) {}
};

/// Faces around a vertex from an index built once in O(C) (C face corners); each query then
/// costs O(F_adjacentV) and returns a std::span into the adapter (valid while it lives and
/// until its refresh()). Memory: one uint32 per vertex plus one face handle per corner.
/// Errors: a query after the mesh changed, or with another mesh, throws hmira_error.
template <class M, class T = default_traits<M>>
    requires indexed_adapter_source_mesh<M, T>
class indexed_vertex_face_adjacency {
public:
    /// The mesh's vertex handle.
    using vertex_handle = typename T::vertex_handle;
    /// The mesh's face handle.
    using face_handle = typename T::face_handle;
    indexed_vertex_face_adjacency() = default;
    /// Builds the index of m. O(C).
    explicit indexed_vertex_face_adjacency(const M& m) { refresh(m); }

    /// The faces that have v as a corner, once per corner, in face order, as a span into the
    /// index. O(F_adjacentV). Throws hmira_error if m changed since the last refresh() or is
    /// not the indexed mesh.
    std::span<const face_handle> vertex_faces(const M& m, vertex_handle v) const {
        stamp_.check(m);
        return rows_.row(T::vertex_index(m, v));
    }

    /// Rebuilds the index from m as it is now, O(C). Invalidates spans returned before.
    void refresh(const M& m) {
        rows_ = detail::build_csr<face_handle>(T::vertex_index_bound(m), [&](auto&& push) {
            for (auto f : T::faces(m))
                for (auto w : T::face_vertices(m, f)) push(T::vertex_index(m, w), f);
        });
        stamp_ = detail::index_stamp<M, T>(m, "indexed_vertex_face_adjacency");
    }

    /// Whether the index was built from m and m has not changed since. O(1).
    bool is_current(const M& m) const { return stamp_.is_current(m); }
    /// Bytes held by the index. O(1).
    std::size_t memory_bytes() const { return rows_.memory_bytes(); }

private:
    detail::csr<face_handle> rows_;
    detail::index_stamp<M, T> stamp_;
};

}  // namespace hmira
