// viewer/viewer_page.hpp
// Writes the self-contained HTML page of the hmira viewer from plain arrays (points, polygon
// offsets and corners), so the CLI (`hmira view`) and the Python bindings make the same page.
// Standard library only; the viewer script (viewer/dist/hmira-viewer.js) is passed in as text.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace hmira_viewer {

/// What the info corner shows (from hmira::mesh_topology or any other source).
struct page_info {
    std::size_t vertices = 0, edges = 0, faces = 0;
    long long genus = 0;
    bool closed = false;
};

/// One mesh of a page, in the buffers the viewer script reads. Build it with make_page_mesh().
struct page_mesh {
    std::string name;                         ///< shown in the info corner (a file name)
    page_info info;                           ///< shown in the info corner
    std::vector<float> positions;             ///< x y z per vertex, relative to the page's origin
    std::vector<std::uint32_t> triangles;     ///< 3 per triangle: polygons fanned from their first corner
    std::vector<std::uint8_t> edge_mask;      ///< 1 per triangle: bit k = its edge k..k+1 is a polygon edge it draws
    std::vector<std::uint32_t> boundary;      ///< 2 per edge with exactly one face side
    std::vector<std::uint32_t> non_manifold;  ///< 2 per edge with more than two face sides
    std::vector<float> normals;               ///< x y z per vertex, or empty
    std::vector<std::uint8_t> colors;         ///< r g b a per vertex, or empty
};

/// The plain-array view of a polygon mesh that make_page_mesh() takes.
struct mesh_arrays {
    std::span<const double> points;             ///< x y z per vertex
    std::span<const std::uint32_t> offsets;     ///< F + 1 entries: face f has corners[offsets[f] .. offsets[f+1])
    std::span<const std::uint32_t> corners;     ///< vertex indices, each < points.size() / 3
    std::span<const float> normals = {};        ///< x y z per vertex, or empty
    std::span<const std::uint8_t> colors = {};  ///< r g b a per vertex, or empty
};

/// The centre of the bounding box of `points` (x y z triples); 0 for no points. O(V).
inline std::array<double, 3> bounding_box_centre(std::span<const double> points) {
    if (points.size() < 3) return {0, 0, 0};
    std::array<double, 3> lo{points[0], points[1], points[2]}, hi = lo;
    for (std::size_t i = 0; i + 2 < points.size(); i += 3)
        for (std::size_t k = 0; k < 3; ++k)
            lo[k] = std::min(lo[k], points[i + k]), hi[k] = std::max(hi[k], points[i + k]);
    // Halves first: lo + hi overflows for coordinates beyond half the double range.
    return {lo[0] / 2 + hi[0] / 2, lo[1] / 2 + hi[1] / 2, lo[2] / 2 + hi[2] / 2};
}

/// The first vertex whose page position (float, relative to the origin) is not finite: its
/// distance from the origin exceeds the float range (about 3.4e38). A page holding one would
/// draw nothing sensible, so a caller refuses the mesh. Returns positions.size() / 3 if none.
inline std::size_t first_vertex_beyond_float_range(const page_mesh& m) {
    for (std::size_t i = 0; i < m.positions.size(); ++i)
        if (!std::isfinite(m.positions[i])) return i / 3;
    return m.positions.size() / 3;
}

/// Fans each polygon into triangles, finds which fan edges are polygon edges (each drawn once)
/// and which edges are boundary (one face side) or non-manifold (more than two), and stores
/// positions relative to `origin` as floats (a page of a mesh far from 0 keeps its precision).
/// \pre every corner < points.size() / 3, offsets non-decreasing and ending at corners.size(),
///      normals and colors empty or one per vertex (checked by the caller).
/// \post triangles.size() == 3 * edge_mask.size(). O(C log C) for C corners (the edge sort).
inline page_mesh make_page_mesh(std::string name, const page_info& info, const mesh_arrays& mesh,
                                std::array<double, 3> origin) {
    page_mesh out;
    out.name = std::move(name);
    out.info = info;
    out.positions.resize(mesh.points.size());
    for (std::size_t i = 0; i < mesh.points.size(); ++i)
        out.positions[i] = static_cast<float>(mesh.points[i] - origin[i % 3]);
    out.normals.assign(mesh.normals.begin(), mesh.normals.end());
    out.colors.assign(mesh.colors.begin(), mesh.colors.end());

    // One record per polygon edge side: the undirected edge and the triangle slot that draws it.
    struct side {
        std::uint64_t key;
        std::uint32_t slot;  // 3 * triangle + k
    };
    std::vector<side> sides;
    sides.reserve(mesh.corners.size());
    const std::size_t faces = mesh.offsets.empty() ? 0 : mesh.offsets.size() - 1;
    for (std::size_t f = 0; f < faces; ++f) {
        const std::uint32_t begin = mesh.offsets[f], end = mesh.offsets[f + 1], n = end - begin;
        if (n < 3) continue;
        const auto first = static_cast<std::uint32_t>(out.triangles.size() / 3);
        for (std::uint32_t i = 1; i + 1 < n; ++i) {
            out.triangles.insert(out.triangles.end(),
                                 {mesh.corners[begin], mesh.corners[begin + i], mesh.corners[begin + i + 1]});
            out.edge_mask.push_back(0);
        }
        // Polygon edge (c_j, c_j+1) lies in fan triangle t as edge k: j = 0 is triangle 0 edge 0,
        // j = n-1 (closing edge) is the last triangle's edge 2, the rest are edge 1 of triangle j-1.
        for (std::uint32_t j = 0; j < n; ++j) {
            const std::uint32_t a = mesh.corners[begin + j], b = mesh.corners[begin + (j + 1) % n];
            std::uint32_t slot = 0;
            if (j == 0)
                slot = 3 * first;
            else if (j == n - 1)
                slot = 3 * (first + n - 3) + 2;
            else
                slot = 3 * (first + j - 1) + 1;
            sides.push_back({(std::uint64_t{std::min(a, b)} << 32) | std::max(a, b), slot});
        }
    }
    std::sort(sides.begin(), sides.end(),
              [](const side& x, const side& y) { return x.key < y.key || (x.key == y.key && x.slot < y.slot); });
    for (std::size_t i = 0; i < sides.size();) {
        std::size_t j = i;
        while (j < sides.size() && sides[j].key == sides[i].key) ++j;
        out.edge_mask[sides[i].slot / 3] |= static_cast<std::uint8_t>(1u << (sides[i].slot % 3));
        const auto a = static_cast<std::uint32_t>(sides[i].key >> 32), b = static_cast<std::uint32_t>(sides[i].key);
        if (j - i == 1) out.boundary.insert(out.boundary.end(), {a, b});
        if (j - i > 2) out.non_manifold.insert(out.non_manifold.end(), {a, b});
        i = j;
    }
    return out;
}

namespace detail {

inline void put_base64(std::ostream& os, std::span<const std::uint8_t> bytes) {
    static constexpr char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string chunk;
    chunk.reserve(4 * 4096);
    std::size_t i = 0;
    while (i < bytes.size()) {
        chunk.clear();
        const std::size_t stop = std::min(bytes.size(), i + 3 * 4096);
        for (; i + 3 <= stop; i += 3) {
            const std::uint32_t v = (std::uint32_t{bytes[i]} << 16) | (std::uint32_t{bytes[i + 1]} << 8) | bytes[i + 2];
            chunk += alphabet[v >> 18], chunk += alphabet[(v >> 12) & 63], chunk += alphabet[(v >> 6) & 63],
                chunk += alphabet[v & 63];
        }
        if (i < stop) {  // the last 1 or 2 bytes
            const std::uint32_t v =
                (std::uint32_t{bytes[i]} << 16) | (i + 1 < stop ? std::uint32_t{bytes[i + 1]} << 8 : 0u);
            chunk += alphabet[v >> 18], chunk += alphabet[(v >> 12) & 63];
            chunk += i + 1 < stop ? alphabet[(v >> 6) & 63] : '=';
            chunk += '=';
            i = stop;
        }
        os << chunk;
    }
}

/// The values as little-endian bytes (the order typed arrays read on every browser platform).
template <class T>
std::vector<std::uint8_t> little_endian_bytes(std::span<const T> values) {
    std::vector<std::uint8_t> bytes(values.size() * sizeof(T));
    if constexpr (std::endian::native == std::endian::little || sizeof(T) == 1) {
        if (!bytes.empty()) std::memcpy(bytes.data(), values.data(), bytes.size());
    } else {
        for (std::size_t i = 0; i < values.size(); ++i) {
            std::uint8_t b[sizeof(T)];
            std::memcpy(b, &values[i], sizeof(T));
            for (std::size_t k = 0; k < sizeof(T); ++k) bytes[i * sizeof(T) + k] = b[sizeof(T) - 1 - k];
        }
    }
    return bytes;
}

template <class T>
void put_buffer(std::ostream& os, std::size_t mesh, const char* name, const std::vector<T>& values) {
    if (values.empty()) return;
    os << "<script type=\"application/octet-stream\" id=\"hmira-m" << mesh << '-' << name << "\">";
    put_base64(os, little_endian_bytes(std::span<const T>(values)));
    os << "</script>\n";
}

inline std::string json_string(std::string_view s) {
    std::string o = "\"";
    for (char c : s) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '"' || c == '\\')
            o += '\\', o += c;
        else if (c == '<')
            o += "\\u003c";  // never "</script>" inside the JSON block
        else if (u < 0x20)
            o += ' ';
        else
            o += c;
    }
    return o + '"';
}

inline std::string html_text(std::string_view s) {
    std::string o;
    for (char c : s) {
        if (c == '<')
            o += "&lt;";
        else if (c == '>')
            o += "&gt;";
        else if (c == '&')
            o += "&amp;";
        else
            o += c;
    }
    return o;
}

}  // namespace detail

/// Writes the whole page: a JSON scene, one base64 script element per buffer, and the viewer
/// script (`bundle`, the text of viewer/dist/hmira-viewer.js) inline, so it opens offline.
/// \pre 1 or 2 meshes (two are shown side by side under one camera); `bundle` contains no
/// "</script" (esbuild escapes it). O(total buffer bytes).
inline void write_page(std::ostream& os, std::span<const page_mesh> meshes, std::string_view bundle) {
    std::string title = "hmira view:";
    for (const auto& m : meshes) title += " " + m.name;
    os << "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" << detail::html_text(title)
       << "</title>\n"
       << "<meta name=\"generator\" content=\"hmira view\">\n"
       << "<style>html,body{margin:0;height:100%;overflow:hidden;background:#f4f5f7}canvas{display:block}"
          ".hmira-ui{position:absolute;top:10px;font:13px/1.45 "
          "system-ui,sans-serif;color:#222;background:rgba(255,255,255,.8);"
          "padding:6px 9px;border-radius:5px;pointer-events:auto}.hmira-controls{right:10px}.hmira-controls "
          "label{display:block}"
          ".hmira-controls button{margin:4px 4px 0 0;font-size:12px}</style>\n</head>\n<body>\n";
    os << "<script type=\"application/json\" id=\"hmira-scene\">{\"version\": 1, \"meshes\": [";
    for (std::size_t i = 0; i < meshes.size(); ++i) {
        const auto& m = meshes[i];
        os << (i ? ", " : "") << "{\"name\": " << detail::json_string(m.name)
           << ", \"triangles\": " << m.triangles.size() / 3 << ", \"info\": {\"vertices\": " << m.info.vertices
           << ", \"edges\": " << m.info.edges << ", \"faces\": " << m.info.faces << ", \"genus\": " << m.info.genus
           << ", \"closed\": " << (m.info.closed ? "true" : "false")
           << ", \"boundary_edges\": " << m.boundary.size() / 2
           << ", \"non_manifold_edges\": " << m.non_manifold.size() / 2 << "}}";
    }
    os << "]}</script>\n";
    for (std::size_t i = 0; i < meshes.size(); ++i) {
        const auto& m = meshes[i];
        detail::put_buffer(os, i, "positions", m.positions);
        detail::put_buffer(os, i, "triangles", m.triangles);
        detail::put_buffer(os, i, "edge_mask", m.edge_mask);
        detail::put_buffer(os, i, "boundary", m.boundary);
        detail::put_buffer(os, i, "non_manifold", m.non_manifold);
        detail::put_buffer(os, i, "normals", m.normals);
        detail::put_buffer(os, i, "colors", m.colors);
    }
    os << "<script>" << bundle << "</script>\n</body>\n</html>\n";
}

}  // namespace hmira_viewer
