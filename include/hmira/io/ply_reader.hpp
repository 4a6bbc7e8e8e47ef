// hmira/io/ply_reader.hpp
// Reads Stanford PLY in all three encodings (ASCII, binary little and big endian): positions,
// polygonal faces, per-vertex normals (nx ny nz) and colours (red green blue [alpha]). Other
// elements and properties are skipped, so files from scanners and other tools load as well.
//
// Options (read_options, io_options.hpp): a progress callback that can cancel, the input size
// limit, and whether to repair what a half-edge model cannot hold.
// Result: result<read_report> (read_ply) or result<polygon_soup> (parse_ply); on error the mesh
// is unchanged. Requires: readable_mesh<M, T>.
// Entry points: read_ply (a file into a mesh) and parse_ply (text into a soup). The header
// parser and the ASCII and binary data readers are in detail/ply_reader_impl.hpp.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <utility>

#include "../concepts.hpp"
#include "../core/result.hpp"
#include "detail/files.hpp"
#include "detail/ply_reader_impl.hpp"
#include "detail/polygon_soup.hpp"
#include "io_options.hpp"

namespace hmira::io {

/// Parses PLY (any encoding) into a soup. Errors name `name:line` in the header and in ASCII
/// data, `name: byte offset N` and the element in binary data.
/// Complexity: O(bytes). Errors (errc::parse_error / degenerate_face / unsupported): a bad
/// header, truncated data, counts too large or too small, non-numbers, indices out of range,
/// faces of fewer than 3 vertices.
inline result<polygon_soup> parse_ply(std::string_view text, const std::string& name,
                                      const read_options& options = {}) {
    auto h = detail::parse_ply_header(text, name);
    if (!h) return h.error();
    polygon_soup soup;
    if (auto r = detail::parse_ply_into(soup, *h, text, name, options); !r) return r.error();
    return soup;
}

/// Readable name of a PLY encoding, for reports.
inline const char* to_string(ply_encoding e) {
    switch (e) {
        case ply_encoding::ascii: return "ascii";
        case ply_encoding::binary_little_endian: return "binary little endian";
        case ply_encoding::binary_big_endian: return "binary big endian";
    }
    return "?";
}

/// Reads a PLY file into `mesh`, replacing its content; on error the mesh is unchanged. A model
/// that takes its arrays whole (face_vertex_mesh) gets the file parsed straight into them: one
/// validation pass, no copy; halfedge_mesh gets its positions so, when the file needs no repair. Complexity: O(bytes +
/// mesh insertions).
template <class M, class T = default_traits<M>>
    requires readable_mesh<M, T>
result<read_report> read_ply(M& mesh, const std::filesystem::path& path, const read_options& options = {}) {
    auto file = detail::input_file::open(path, options.max_input_bytes);
    if (!file) return file.error();
    auto h = detail::parse_ply_header(file->text(), path.string());
    if (!h) return h.error();
    const std::string format = std::string("ply (") + to_string(h->encoding) + ")";
    if constexpr (detail::takes_own_arrays<M, T>) {
        // Parsed straight into the mesh's own position and corner types, which the mesh then
        // takes over: no second copy of the file's content.
        detail::mesh_soup<M, T> soup;
        if (auto r = detail::parse_ply_into(soup, *h, file->text(), path.string(), options); !r) return r.error();
        return detail::assign_own_arrays<M, T>(mesh, std::move(soup), path.string(), format);
    } else if constexpr (detail::assigns_own_positions<M, T>) {
        // halfedge_mesh: positions parsed into the mesh's own points, kept whole when the file
        // needs no repair.
        detail::point_soup<typename M::point> soup;
        if (auto r = detail::parse_ply_into(soup, *h, file->text(), path.string(), options); !r) return r.error();
        return detail::build_from_point_soup<M, T>(mesh, std::move(soup), path.string(), format, options);
    }
    auto soup = parse_ply(file->text(), path.string(), options);
    if (!soup) return soup.error();
    return finish_read<M, T>(mesh, std::move(*soup), path.string(), format, 0, options);
}

}  // namespace hmira::io
