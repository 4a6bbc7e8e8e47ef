// hmira/algorithms/topology/connected_components.hpp
// Connected components of a mesh: vertices joined by face edges, found with union-find
// (path halving, union by size), so the cost is near linear in the number of face corners.
#pragma once

#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

#include "../../concepts.hpp"

namespace hmira {

template <class M, class T = default_traits<M>>
concept connected_components_mesh = face_vertex_range_mesh<M, T> && vertex_index_mesh<M, T> && face_index_mesh<M, T>;

/// Component labels 0..count-1, indexed by vertex_index / face_index. Deleted elements (gaps
/// below the index bound) get `no_component`. An isolated vertex is a component of its own.
struct component_labels {
    static constexpr std::uint32_t no_component = UINT32_MAX;  ///< label of a deleted element
    std::size_t count = 0;                                     ///< number of components
    std::vector<std::uint32_t> vertex_component;               ///< label per vertex index
    std::vector<std::uint32_t> face_component;                 ///< label per face index
};

/// Disjoint-set forest over [0, n).
class union_find {
public:
    /// n singleton sets.
    explicit union_find(std::size_t n) : parent_(n), size_(n, 1) {
        std::iota(parent_.begin(), parent_.end(), std::uint32_t{0});
    }
    /// The representative of x's set (compresses the path on the way).
    std::uint32_t find(std::uint32_t x) {
        while (parent_[x] != x) {
            parent_[x] = parent_[parent_[x]];
            x = parent_[x];
        }
        return x;
    }
    /// Merges the sets of a and b; false if they were already one.
    bool unite(std::uint32_t a, std::uint32_t b) {
        a = find(a);
        b = find(b);
        if (a == b) return false;
        if (size_[a] < size_[b]) std::swap(a, b);
        parent_[b] = a;
        size_[a] += size_[b];
        return true;
    }

private:
    std::vector<std::uint32_t> parent_, size_;
};

/// Labels the connected components. Complexity O((V_all + sum of face degrees) * alpha).
/// Components are numbered in order of their lowest vertex index.
template <class M, class T = default_traits<M>>
    requires connected_components_mesh<M, T>
component_labels connected_components(const M& mesh) {
    const std::size_t nv = T::vertex_index_bound(mesh);
    union_find sets(nv);
    for (auto f : T::faces(mesh)) {
        bool first = true;
        std::uint32_t root = 0;
        for (auto v : T::face_vertices(mesh, f)) {
            const auto i = static_cast<std::uint32_t>(T::vertex_index(mesh, v));
            if (first) {
                root = i;
                first = false;
            } else
                sets.unite(root, i);
        }
    }
    component_labels out;
    out.vertex_component.assign(nv, component_labels::no_component);
    std::vector<std::uint32_t> label_of_root(nv, component_labels::no_component);
    for (auto v : T::vertices(mesh)) {
        const auto i = static_cast<std::uint32_t>(T::vertex_index(mesh, v));
        const auto r = sets.find(i);
        if (label_of_root[r] == component_labels::no_component)
            label_of_root[r] = static_cast<std::uint32_t>(out.count++);
        out.vertex_component[i] = label_of_root[r];
    }
    out.face_component.assign(T::face_index_bound(mesh), component_labels::no_component);
    for (auto f : T::faces(mesh)) {
        for (auto v : T::face_vertices(mesh, f)) {
            out.face_component[T::face_index(mesh, f)] = out.vertex_component[T::vertex_index(mesh, v)];
            break;
        }
    }
    return out;
}

}  // namespace hmira
