// examples/plain_struct_mesh/plain_mesh.hpp
// The first structure of docs/own-mesh.md: an in-house mesh that is nothing but two vectors,
// and the one mesh_traits specialisation that lets every face-list algorithm of hmira run on it.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <ranges>
#include <span>
#include <string>
#include <vector>

#include <hmira/concepts.hpp>

// [struct]
namespace studio {  // "your" code: hmira has never seen it

struct plain_mesh {
    std::vector<std::array<double, 3>> positions;
    std::vector<std::vector<int>> faces;  // vertex indices, counter-clockwise seen from outside
};

}  // namespace studio
// [struct]

// [traits]
template <>
struct hmira::mesh_traits<studio::plain_mesh> {
    using mesh = studio::plain_mesh;
    // 1. Element types: an index is a perfectly good handle.
    using vertex_handle = int;
    using face_handle = int;
    using scalar = double;

    // 2. Whole-structure getters (vertex_list_mesh, face_list_mesh).
    static auto vertices(const mesh& m) { return std::views::iota(0, static_cast<int>(m.positions.size())); }
    static auto faces(const mesh& m) { return std::views::iota(0, static_cast<int>(m.faces.size())); }
    static std::size_t vertex_count(const mesh& m) { return m.positions.size(); }
    static std::size_t face_count(const mesh& m) { return m.faces.size(); }

    // 3. Dense indices (vertex_index_mesh, face_index_mesh): here the handle is the index.
    static std::size_t vertex_index(const mesh&, int v) { return static_cast<std::size_t>(v); }
    static std::size_t vertex_index_bound(const mesh& m) { return m.positions.size(); }
    static std::size_t face_index(const mesh&, int f) { return static_cast<std::size_t>(f); }
    static std::size_t face_index_bound(const mesh& m) { return m.faces.size(); }

    // 4. Face -> vertices (face_vertex_range_mesh): a view into the mesh, not a copy.
    static std::span<const int> face_vertices(const mesh& m, int f) { return m.faces[static_cast<std::size_t>(f)]; }

    // 5. Geometry (positioned_mesh, position_mutable_mesh): convert at the boundary.
    static hmira::vec3<double> position(const mesh& m, int v) {
        const auto& p = m.positions[static_cast<std::size_t>(v)];
        return {p[0], p[1], p[2]};
    }
    static void set_position(mesh& m, int v, const hmira::vec3<double>& p) {
        m.positions[static_cast<std::size_t>(v)] = {p.x, p.y, p.z};
    }

    // 6. Building (mesh_builder): refuse bad faces instead of storing them.
    static int add_vertex(mesh& m, const hmira::vec3<double>& p) {
        m.positions.push_back({p.x, p.y, p.z});
        return static_cast<int>(m.positions.size()) - 1;
    }
    static hmira::result<int> add_face(mesh& m, std::span<const int> vs) {
        if (vs.size() < 3) return hmira::fail(hmira::errc::degenerate_face, "add_face: fewer than 3 vertices");
        for (int v : vs)
            if (v < 0 || static_cast<std::size_t>(v) >= m.positions.size())
                return hmira::fail(hmira::errc::invalid_handle, "add_face: no vertex " + std::to_string(v), v);
        m.faces.emplace_back(vs.begin(), vs.end());
        return static_cast<int>(m.faces.size()) - 1;
    }

    // 7. Orientation (face_reversible_mesh): lets flip_normals run.
    static void reverse_face(mesh& m, int f) { std::ranges::reverse(m.faces[static_cast<std::size_t>(f)]); }
};
// [traits]
