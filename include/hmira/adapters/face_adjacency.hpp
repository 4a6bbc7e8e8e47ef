// hmira/adapters/face_adjacency.hpp
// Face -> faces sharing an edge with it, for a mesh that stores only faces: by scanning every
// face on each query, or from an index built once. A face that shares k edges with f is
// listed k times, as a halfedge mesh lists it (one entry per shared edge).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "detail/index_support.hpp"

namespace hmira {

/// Adjacent faces by brute force: no memory kept beyond f's own sides; each query costs
/// O(F_all x V_face x V_consistF). Returns an owning std::vector.
template <class M, class T = default_traits<M>>
    requires adapter_source_mesh<M, T>
class brute_force_face_adjacency {
public:
    /// The mesh's vertex handle.
    using vertex_handle = typename T::vertex_handle;
    /// The mesh's face handle.
    using face_handle = typename T::face_handle;
    brute_force_face_adjacency() = default;
    /// Keeps nothing from the mesh. O(1).
    explicit brute_force_face_adjacency(const M&) {}

    /// Faces sharing an edge with f, once per shared edge, in face order. Scans every face:
    /// O(F_all x V_face x V_consistF) per query.
    std::vector<face_handle> adjacent_faces(const M& m, face_handle f) const {
        std::vector<std::pair<vertex_handle, vertex_handle>> mine;
        detail::for_each_side<M, T>(m, f, [&](vertex_handle a, vertex_handle b) { mine.emplace_back(a, b); });
        std::vector<face_handle> out;
        for (auto g : T::faces(m)) {
            if (g == f) continue;
            detail::for_each_side<M, T>(m, g, [&](vertex_handle a, vertex_handle b) {
                for (const auto& [x, y] : mine)
                    if ((a == y && b == x) || (a == x && b == y)) out.push_back(g);
            });
        }
        return out;
    }
    /// Does nothing: there is no index to rebuild.
    void refresh(const M&) {}
};

/// Adjacent faces from an index built once in O(C log C) (face sides sorted by edge); each
/// query then costs O(F_adjacentF) and returns a std::span into the adapter (valid while it
/// lives and until its refresh()). Errors: a stale query throws hmira_error.
template <class M, class T = default_traits<M>>
    requires indexed_adapter_source_mesh<M, T>
class indexed_face_adjacency {
public:
    /// The mesh's face handle.
    using face_handle = typename T::face_handle;
    /// The mesh's vertex handle.
    using vertex_handle = typename T::vertex_handle;
    indexed_face_adjacency() = default;
    /// Builds the index of m. O(C log C).
    explicit indexed_face_adjacency(const M& m) { refresh(m); }

    /// Faces sharing an edge with f, once per shared edge, as a span into the index.
    /// O(F_adjacentF). Throws hmira_error if m changed since the last refresh() or is not the
    /// indexed mesh.
    std::span<const face_handle> adjacent_faces(const M& m, face_handle f) const {
        stamp_.check(m);
        return rows_.row(T::face_index(m, f));
    }

    /// Rebuilds the index from m as it is now, O(C log C). Invalidates spans returned before.
    void refresh(const M& m) {
        struct side {
            std::uint64_t key;
            face_handle f;
        };
        std::vector<side> sides;
        for (auto f : T::faces(m))
            detail::for_each_side<M, T>(m, f, [&](vertex_handle a, vertex_handle b) {
                auto ia = std::uint64_t(T::vertex_index(m, a)), ib = std::uint64_t(T::vertex_index(m, b));
                if (ib < ia) std::swap(ia, ib);
                sides.push_back({(ia << 32) | ib, f});
            });
        std::sort(sides.begin(), sides.end(), [](const side& p, const side& q) { return p.key < q.key; });
        rows_ = detail::build_csr<face_handle>(T::face_index_bound(m), [&](auto&& push) {
            for (std::size_t i = 0; i < sides.size();) {
                std::size_t j = i;
                while (j < sides.size() && sides[j].key == sides[i].key) ++j;
                for (std::size_t p = i; p < j; ++p)
                    for (std::size_t q = i; q < j; ++q)
                        if (p != q && !(sides[p].f == sides[q].f)) push(T::face_index(m, sides[p].f), sides[q].f);
                i = j;
            }
        });
        stamp_ = detail::index_stamp<M, T>(m, "indexed_face_adjacency");
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
