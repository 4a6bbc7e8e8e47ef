// hmira/algorithms/subdivision/detail/new_elements.hpp
// Where a subdivision level takes its new vertices, edges and faces from: blocks appended at
// once through the traits' optional resize, or one traits add at a time.
#pragma once

#include <algorithm>
#include <array>
#include <concepts>
#include <cstddef>

#include "../../../core/vec3.hpp"
#include "../../../concepts.hpp"
#include "../../../traits.hpp"

namespace hmira::detail::subdivision {

/// Hands out new elements in index order, as the traits' add_vertex, new_edge and new_face
/// would. On a bulk_growable_mesh it appends blocks of unlinked elements (a block is linked
/// while it is still in cache) and finish() drops the unused end of the last block; otherwise
/// each call is the traits' own add. While it lives, every new element of the mesh must come
/// from it, and until finish() the index bounds include the block's unused elements.
template <class M, class T>
class new_elements {
public:
    using V = typename T::vertex_handle;
    using H = typename T::halfedge_handle;
    using F = typename T::face_handle;

    /// `room`: the vertex, edge and face index bounds the mesh has capacity for (reserved);
    /// no block reaches past them, since a block past the capacity would reallocate and copy
    /// every array of that kind.
    new_elements(M& mesh, const std::array<std::size_t, 3>& room) : mesh_(mesh), room_(room) {
        if constexpr (bulk) {
            next_ = {T::vertex_index_bound(mesh), T::edge_index_bound(mesh), T::face_index_bound(mesh)};
            end_ = next_;
        }
    }
    ~new_elements() { finish(); }
    new_elements(const new_elements&) = delete;
    new_elements& operator=(const new_elements&) = delete;

    /// A new isolated vertex at p.
    V vertex(const vec3<double>& p) {
        using S = typename T::scalar;
        const vec3<S> q{S(p.x), S(p.y), S(p.z)};
        if constexpr (bulk) {
            if (next_[0] == end_[0]) grow(0);
            const V v = T::vertex_at(mesh_, next_[0]++);
            T::set_position(mesh_, v, q);
            return v;
        } else {
            return T::add_vertex(mesh_, q);
        }
    }
    /// A new edge from a to b, as T::new_edge: returns the halfedge a->b; next, prev and
    /// faces unset (null faces).
    H edge(V a, V b) {
        if constexpr (bulk) {
            if (next_[1] == end_[1]) grow(1);
            const H h = T::edge_halfedge(mesh_, T::edge_at(mesh_, next_[1]++));
            T::set_target(mesh_, h, b);
            T::set_target(mesh_, T::opposite(mesh_, h), a);
            return h;
        } else {
            return T::new_edge(mesh_, a, b);
        }
    }
    /// A new face without a halfedge, as T::new_face.
    F face() {
        if constexpr (bulk) {
            if (next_[2] == end_[2]) grow(2);
            return T::face_at(mesh_, next_[2]++);
        } else {
            return T::new_face(mesh_);
        }
    }
    /// Drops the unused end of the last blocks, so that the mesh holds exactly the elements
    /// handed out. Within reserved capacity; idempotent.
    void finish() {
        if constexpr (bulk) {
            if (next_ != end_) {
                T::resize(mesh_, next_[0], next_[1], next_[2]);
                end_ = next_;
            }
        }
    }

private:
    static constexpr bool bulk = bulk_growable_mesh<M, T>;
    // Small enough that a block's defaults are still in cache when the level links it, large
    // enough that the per-block cost (one call per property array) vanishes.
    static constexpr std::size_t block = 1u << 12;

    void grow(std::size_t kind) {
        end_[kind] = end_[kind] + block <= room_[kind] ? end_[kind] + block : std::max(room_[kind], end_[kind] + 1);
        T::resize(mesh_, end_[0], end_[1], end_[2]);
    }

    M& mesh_;
    std::array<std::size_t, 3> room_;
    std::array<std::size_t, 3> next_{}, end_{};  // vertices, edges, faces: next to hand out, block end
};

}  // namespace hmira::detail::subdivision
