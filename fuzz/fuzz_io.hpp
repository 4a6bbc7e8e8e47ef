// fuzz/fuzz_io.hpp
// The body of every parser fuzz target, shared with the corpus regression test: parse the
// bytes; if they parse, build a mesh, write it in the same format and parse that again, which
// must succeed with the same counts. Returns "" or a description of the violated property.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <hmira/io/mesh_io.hpp>

namespace hmira_fuzz {

/// A minimal face-vertex mesh local to the fuzzers (it compiles with clang 14, whose ranges
/// support the reference meshes need more of).
struct mini_mesh {
    std::vector<hmira::vec3<double>> points;
    std::vector<std::vector<std::uint32_t>> faces;
};

}  // namespace hmira_fuzz

template <>
struct hmira::mesh_traits<hmira_fuzz::mini_mesh> {
    using mesh = hmira_fuzz::mini_mesh;
    using vertex_handle = std::uint32_t;
    using face_handle = std::uint32_t;
    using scalar = double;
    static std::vector<std::uint32_t> ids(std::size_t n) {
        std::vector<std::uint32_t> v(n);
        for (std::size_t i = 0; i < n; ++i) v[i] = static_cast<std::uint32_t>(i);
        return v;
    }
    static std::vector<std::uint32_t> vertices(const mesh& m) { return ids(m.points.size()); }
    static std::vector<std::uint32_t> faces(const mesh& m) { return ids(m.faces.size()); }
    static std::size_t vertex_count(const mesh& m) { return m.points.size(); }
    static std::size_t face_count(const mesh& m) { return m.faces.size(); }
    static std::size_t vertex_index(const mesh&, std::uint32_t v) { return v; }
    static std::size_t vertex_index_bound(const mesh& m) { return m.points.size(); }
    static const std::vector<std::uint32_t>& face_vertices(const mesh& m, std::uint32_t f) { return m.faces[f]; }
    static hmira::vec3<double> position(const mesh& m, std::uint32_t v) { return m.points[v]; }
    static std::uint32_t add_vertex(mesh& m, const hmira::vec3<double>& p) {
        m.points.push_back(p);
        return static_cast<std::uint32_t>(m.points.size() - 1);
    }
    static hmira::result<std::uint32_t> add_face(mesh& m, std::span<const std::uint32_t> vs) {
        for (std::size_t i = 0; i < vs.size(); ++i)
            for (std::size_t j = 0; j < i; ++j)
                if (vs[i] == vs[j]) return hmira::fail(hmira::errc::degenerate_face, "repeated vertex");
        m.faces.emplace_back(vs.begin(), vs.end());
        return static_cast<std::uint32_t>(m.faces.size() - 1);
    }
};

namespace hmira_fuzz {

inline std::string one_input(hmira::io::file_format format, const std::uint8_t* data, std::size_t size) {
    using namespace hmira;
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    auto soup = io::parse_soup(bytes, format, "fuzz");
    if (!soup) {
        if (soup.error().message.empty()) return "an error without a message";
        if (soup.error().message.find('\n') != std::string::npos) return "a message of several lines: " + soup.error().message;
        return "";
    }
    // Well-formed soup: indices in range, faces of 3+ corners, attributes sized right.
    for (auto i : soup->indices)
        if (i >= soup->points.size()) return "index out of range in an accepted soup";
    for (std::size_t f = 0; f < soup->face_count(); ++f)
        if (soup->face_offsets[f + 1] < soup->face_offsets[f] + 3) return "face with fewer than 3 corners accepted";
    if (!soup->attributes.normals.empty() && soup->attributes.normals.size() != soup->points.size()) return "normals not one per vertex";
    if (!soup->attributes.colors.empty() && soup->attributes.colors.size() != soup->points.size()) return "colours not one per vertex";
    mini_mesh mesh;
    if (!io::assign_from_soup(mesh, *soup, [](std::size_t) { return std::string("fuzz"); })) return "";
    std::string again;
    switch (format) {
        case io::file_format::obj: again = io::format_obj(mesh); break;
        case io::file_format::off: again = io::format_off(mesh); break;
        case io::file_format::ply: again = io::format_ply(mesh, {.ply = io::ply_encoding::binary_big_endian}); break;
        case io::file_format::stl: again = io::format_stl(mesh); break;
    }
    auto back = io::parse_soup(again, format, "again");
    if (!back) return "re-reading what the writer wrote failed: " + back.error().message;
    if (format != io::file_format::stl && (back->points.size() != soup->points.size() || back->face_count() != soup->face_count()))
        return "the round trip changed the counts";
    return "";
}

}  // namespace hmira_fuzz
