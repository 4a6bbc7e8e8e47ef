// examples/trimesh_like/trimesh.hpp
// The second structure of docs/own-mesh.md, modelled on the Trimesh library of thesis 3.2: a
// face-vertex triangle mesh plus the connectivity arrays `neighbors`, `adjacentfaces` and
// `across_edge`. Its traits answer adjacency from those arrays, with no adapter in between.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <ranges>
#include <span>
#include <string>
#include <vector>

#include <hmira/concepts.hpp>

namespace lab {  // "your" code, written the Trimesh way

struct trimesh {
    using point = std::array<float, 3>;
    using face = std::array<int, 3>;  // counter-clockwise seen from outside

    std::vector<point> vertices;
    std::vector<face> faces;
    // Connectivity, built on demand by need_*(), cleared by any change:
    std::vector<std::vector<int>> neighbors;      // per vertex: adjacent vertices
    std::vector<std::vector<int>> adjacentfaces;  // per vertex: faces around it
    std::vector<face> across_edge;                // per face: face across the side opposite
                                                  // corner i, or -1 on the boundary
    std::uint64_t changes = 0;                    // grows on every edit

    int add_vertex(const point& p) {
        vertices.push_back(p);
        touch();
        return static_cast<int>(vertices.size()) - 1;
    }
    int add_face(const face& f) {
        faces.push_back(f);
        touch();
        return static_cast<int>(faces.size()) - 1;
    }

    void need_adjacentfaces() {
        if (adjacentfaces.size() == vertices.size()) return;
        adjacentfaces.assign(vertices.size(), {});
        for (std::size_t f = 0; f < faces.size(); ++f)
            for (int v : faces[f]) adjacentfaces[static_cast<std::size_t>(v)].push_back(static_cast<int>(f));
    }
    void need_neighbors() {
        if (neighbors.size() == vertices.size()) return;
        neighbors.assign(vertices.size(), {});
        for (const auto& f : faces)
            for (int i = 0; i < 3; ++i) {
                auto& row = neighbors[static_cast<std::size_t>(f[i])];
                for (int w : {f[(i + 1) % 3], f[(i + 2) % 3]})
                    if (std::find(row.begin(), row.end(), w) == row.end()) row.push_back(w);
            }
    }
    void need_across_edge() {
        if (across_edge.size() == faces.size()) return;
        need_adjacentfaces();
        across_edge.assign(faces.size(), {-1, -1, -1});
        for (std::size_t f = 0; f < faces.size(); ++f)
            for (int i = 0; i < 3; ++i) {
                // The side opposite corner i runs a -> b; the face across runs b -> a.
                const int a = faces[f][(i + 1) % 3], b = faces[f][(i + 2) % 3];
                for (int g : adjacentfaces[static_cast<std::size_t>(a)]) {
                    if (g == static_cast<int>(f)) continue;
                    const auto& t = faces[static_cast<std::size_t>(g)];
                    for (int k = 0; k < 3; ++k)
                        if (t[k] == b && t[(k + 1) % 3] == a) across_edge[f][i] = g;
                }
            }
    }

private:
    void touch() {
        ++changes;
        neighbors.clear();
        adjacentfaces.clear();
        across_edge.clear();
    }
};

}  // namespace lab

namespace lab::detail {

/// The non-boundary entries of across_edge[f]: a small owning range, so nothing dangles.
struct across_faces {
    std::array<int, 3> slots{};
    int count = 0;
    const int* begin() const { return slots.data(); }
    const int* end() const { return slots.data() + count; }
};

/// Throws hmira_error when an array was not built after the last change, instead of
/// answering from stale connectivity.
inline void require(bool built, const char* what) {
    if (!built)
        throw hmira::hmira_error(hmira::fail(hmira::errc::invalid_argument,
                                             std::string("trimesh: call ") + what + " after the last change"));
}

}  // namespace lab::detail

// [traits]
template <>
struct hmira::mesh_traits<lab::trimesh> {
    using mesh = lab::trimesh;
    using vertex_handle = int;
    using face_handle = int;
    using scalar = float;
    static constexpr bool triangles_only = true;  // generators that make quads refuse it

    static auto vertices(const mesh& m) { return std::views::iota(0, static_cast<int>(m.vertices.size())); }
    static auto faces(const mesh& m) { return std::views::iota(0, static_cast<int>(m.faces.size())); }
    static std::size_t vertex_count(const mesh& m) { return m.vertices.size(); }
    static std::size_t face_count(const mesh& m) { return m.faces.size(); }
    static std::size_t vertex_index(const mesh&, int v) { return static_cast<std::size_t>(v); }
    static std::size_t vertex_index_bound(const mesh& m) { return m.vertices.size(); }
    static std::size_t face_index(const mesh&, int f) { return static_cast<std::size_t>(f); }
    static std::size_t face_index_bound(const mesh& m) { return m.faces.size(); }
    static std::span<const int, 3> face_vertices(const mesh& m, int f) { return m.faces[static_cast<std::size_t>(f)]; }
    static hmira::vec3<float> position(const mesh& m, int v) {
        const auto& p = m.vertices[static_cast<std::size_t>(v)];
        return {p[0], p[1], p[2]};
    }
    static int add_vertex(mesh& m, const hmira::vec3<float>& p) { return m.add_vertex({p.x, p.y, p.z}); }
    static hmira::result<int> add_face(mesh& m, std::span<const int> vs) {
        if (vs.size() != 3) return hmira::fail(hmira::errc::unsupported, "trimesh: triangles only");
        for (int v : vs)
            if (v < 0 || static_cast<std::size_t>(v) >= m.vertices.size())
                return hmira::fail(hmira::errc::invalid_handle, "trimesh: no vertex " + std::to_string(v), v);
        return m.add_face({vs[0], vs[1], vs[2]});
    }
    static std::uint64_t change_count(const mesh& m) { return m.changes; }

    // Adjacency straight from the native arrays: O(V_adjacentV), O(F_adjacentV), O(1).
    static std::span<const int> adjacent_vertices(const mesh& m, int v) {
        lab::detail::require(m.neighbors.size() == m.vertices.size(), "need_neighbors()");
        return m.neighbors[static_cast<std::size_t>(v)];
    }
    static std::span<const int> vertex_faces(const mesh& m, int v) {
        lab::detail::require(m.adjacentfaces.size() == m.vertices.size(), "need_adjacentfaces()");
        return m.adjacentfaces[static_cast<std::size_t>(v)];
    }
    static lab::detail::across_faces adjacent_faces(const mesh& m, int f) {
        lab::detail::require(m.across_edge.size() == m.faces.size(), "need_across_edge()");
        lab::detail::across_faces out;
        for (int g : m.across_edge[static_cast<std::size_t>(f)])
            if (g >= 0) out.slots[static_cast<std::size_t>(out.count++)] = g;
        return out;
    }
};
// [traits]
