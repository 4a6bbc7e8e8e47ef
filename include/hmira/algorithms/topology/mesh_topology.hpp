// hmira/algorithms/topology/mesh_topology.hpp
// Counts that describe a surface's topology: V, E, F, components, boundary loops, the Euler
// characteristic V - E + F and the genus, for any mesh with face lists.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "../../concepts.hpp"
#include "connected_components.hpp"
#include "edge_census.hpp"

namespace hmira {

template <class M, class T = default_traits<M>>
concept mesh_topology_mesh = connected_components_mesh<M, T>;

/// The counts mesh_topology() reports.
struct topology_summary {
    ///@{
    /// Live vertices, face-list edges, and faces.
    std::size_t vertices = 0, edges = 0, faces = 0;
    ///@}
    std::size_t components = 0;          ///< connected components, isolated vertices included
    std::size_t isolated_vertices = 0;   ///< vertices used by no face
    std::size_t boundary_edges = 0;      ///< edges with exactly one face side
    std::size_t boundary_loops = 0;      ///< closed chains of boundary edges
    std::size_t non_manifold_edges = 0;  ///< edges with more than two face sides
    long long euler_characteristic = 0;  ///< V - E + F
    /// Total genus of the surface components, (2C - chi - b) / 2 with isolated vertices left
    /// out; meaningful for orientable manifold meshes (then it is a whole number).
    long long genus = 0;
    /// No boundary and no non-manifold edge.
    bool closed() const noexcept { return boundary_edges == 0 && non_manifold_edges == 0; }
};

/// V - E + F, with E from the mesh's own edges if it has them, else from its face lists.
/// O(E_all) or O(C log C).
template <class M, class T = default_traits<M>>
    requires edge_census_mesh<M, T>
long long euler_characteristic(const M& mesh) {
    std::size_t e = 0;
    if constexpr (edge_list_mesh<M, T>)
        e = T::edge_count(mesh);
    else
        e = edge_census<M, T>(mesh).size();
    return static_cast<long long>(T::vertex_count(mesh)) - static_cast<long long>(e) +
           static_cast<long long>(T::face_count(mesh));
}

/// Everything in topology_summary. O(C log C) for C face corners.
/// Edges counted are the face-list edges (a halfedge model's wire edges are not counted).
template <class M, class T = default_traits<M>>
    requires mesh_topology_mesh<M, T>
topology_summary mesh_topology(const M& mesh) {
    topology_summary s;
    const auto census = edge_census<M, T>(mesh);
    s.vertices = T::vertex_count(mesh);
    s.faces = T::face_count(mesh);
    s.edges = census.size();
    const auto comps = connected_components<M, T>(mesh);
    s.components = comps.count;
    std::vector<std::uint8_t> used(T::vertex_index_bound(mesh), 0);
    for (const auto& e : census) used[e.a] = used[e.b] = 1;
    for (auto v : T::vertices(mesh))
        if (!used[T::vertex_index(mesh, v)]) ++s.isolated_vertices;
    // Boundary loops: follow boundary edges vertex to vertex; each closed walk is one loop.
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> boundary_next;
    for (const auto& e : census) {
        if (e.uses() > 2) ++s.non_manifold_edges;
        if (!e.is_boundary()) continue;
        ++s.boundary_edges;
        // The boundary runs against the face side.
        if (e.forward)
            boundary_next[e.b].push_back(e.a);
        else
            boundary_next[e.a].push_back(e.b);
    }
    std::size_t remaining = s.boundary_edges;
    for (auto& [start, outs] : boundary_next) {
        while (!outs.empty()) {
            std::uint32_t v = start;
            ++s.boundary_loops;
            while (true) {
                auto it = boundary_next.find(v);
                if (it == boundary_next.end() || it->second.empty()) break;
                const auto w = it->second.back();
                it->second.pop_back();
                --remaining;
                v = w;
                if (v == start) break;
            }
        }
    }
    (void)remaining;
    s.euler_characteristic =
        static_cast<long long>(s.vertices) - static_cast<long long>(s.edges) + static_cast<long long>(s.faces);
    const long long surface_components = static_cast<long long>(s.components - s.isolated_vertices);
    const long long chi = s.euler_characteristic - static_cast<long long>(s.isolated_vertices);
    s.genus = (2 * surface_components - chi - static_cast<long long>(s.boundary_loops)) / 2;
    return s;
}

}  // namespace hmira
