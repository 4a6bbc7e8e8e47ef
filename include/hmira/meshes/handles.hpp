// hmira/meshes/handles.hpp
// Typed index handles shared by hmira's own meshes. A handle is a 32-bit index with a type, so
// a face handle cannot be passed where a vertex is expected. The default handle is null.
#pragma once

#include <compare>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>

namespace hmira {

/// A typed 32-bit element index; Tag makes vertex, face, edge and halfedge handles distinct types.
template <class Tag>
struct index_handle {
    static constexpr std::uint32_t null_index = std::numeric_limits<std::uint32_t>::max();  ///< the null handle's index
    std::uint32_t index = null_index;  ///< the element's index in its mesh

    /// The null handle by default, or the element with index i.
    ///@{
    constexpr index_handle() = default;
    constexpr explicit index_handle(std::uint32_t i) noexcept : index(i) {}
    constexpr explicit index_handle(std::size_t i) noexcept : index(static_cast<std::uint32_t>(i)) {}
    constexpr explicit index_handle(int i) noexcept : index(static_cast<std::uint32_t>(i)) {}

    ///@}
    /// Whether this is the null handle (operator bool is the opposite).
    ///@{
    constexpr bool is_null() const noexcept { return index == null_index; }
    constexpr explicit operator bool() const noexcept { return index != null_index; }
    friend constexpr auto operator<=>(index_handle, index_handle) = default;
    ///@}
};

struct vertex_tag {};
struct face_tag {};
struct edge_tag {};
struct halfedge_tag {};

using vertex_handle = index_handle<vertex_tag>;
using face_handle = index_handle<face_tag>;
using edge_handle = index_handle<edge_tag>;
using halfedge_handle = index_handle<halfedge_tag>;

/// A handle together with the generation of its slot when it was taken (halfedge_mesh's
/// versioned()). A mesh that reuses deleted slots answers is_valid() for it only while the
/// same element lives in the slot, so a handle kept across deletions cannot silently name a
/// newer element. Valid until collect_garbage, which renumbers everything.
template <class Tag>
struct versioned_handle {
    index_handle<Tag> handle;      ///< the element's handle
    std::uint32_t generation = 0;  ///< its slot's generation when the handle was taken
    /// Equal when both the slot and the generation are.
    friend constexpr bool operator==(versioned_handle, versioned_handle) = default;
};

}  // namespace hmira

template <class Tag>
struct std::hash<hmira::index_handle<Tag>> {
    std::size_t operator()(hmira::index_handle<Tag> h) const noexcept { return std::hash<std::uint32_t>{}(h.index); }
};
