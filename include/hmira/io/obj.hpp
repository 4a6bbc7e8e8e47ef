// hmira/io/obj.hpp
// Wavefront OBJ: positions, polygonal faces, per-vertex normals (through `vn` and the faces'
// `v//vn` references) and the common `v x y z r g b` vertex-colour extension. Texture
// references are accepted and ignored, negative (relative) indices are resolved, polygons
// stay polygons.
//
// Options: read_options (progress that can cancel, input size limit, repair) and
// write_options (which attributes to write), io_options.hpp. Result: result<read_report>
// (read_obj), result<polygon_soup> (parse_obj), result<void> (write_obj, write_obj_to) and
// result<std::string> (format_obj). Requires: readable_mesh / writable_mesh.
// Entry points below; the per-line readers and the writer's bytes are in detail/obj_impl.hpp.
#pragma once

#include <filesystem>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>

#include "../concepts.hpp"
#include "../core/huge_pages.hpp"
#include "../core/result.hpp"
#include "detail/atomic_write.hpp"
#include "detail/face_loops.hpp"
#include "detail/files.hpp"
#include "detail/obj_impl.hpp"
#include "detail/polygon_soup.hpp"
#include "detail/text_format.hpp"
#include "io_options.hpp"

namespace hmira::io {

/// Parses OBJ text into a soup. Errors name `name:line`.
/// Complexity: O(bytes), one pass. Faces may use vertices defined later in the file.
/// Errors (errc::parse_error / degenerate_face): non-numbers, vertices with fewer than 3
/// coordinates, index 0, indices out of range, faces with fewer than 3 vertices.
inline result<polygon_soup> parse_obj(std::string_view text, const std::string& name,
                                      const read_options& options = {}) {
    polygon_soup soup;
    detail::text_cursor c(text);
    detail::progress_ticker ticker(options.progress, text.size());
    detail::obj_parse_state state;
    hmira::detail::reserve_huge(soup.points, text.size() / 64);
    hmira::detail::reserve_huge(soup.indices, text.size() / 16);
    hmira::detail::reserve_huge(soup.face_offsets, text.size() / 48);
    while (true) {
        c.skip_blanks();
        if (c.at_end()) break;
        const char* p = c.pos();
        const std::size_t remaining = c.size() - c.offset();
        if (p[0] == 'v' && remaining > 1 && (p[1] == ' ' || p[1] == '\t')) {
            c.set_pos(p + 1);
            if (auto ok = detail::obj_read_vertex(c, soup, name); !ok) return ok.error();
        } else if (p[0] == 'v' && remaining > 2 && p[1] == 'n' && (p[2] == ' ' || p[2] == '\t')) {
            c.set_pos(p + 2);
            if (auto ok = detail::obj_read_normal(c, state, name); !ok) return ok.error();
        } else if (p[0] == 'f' && remaining > 1 && (p[1] == ' ' || p[1] == '\t')) {
            c.set_pos(p + 1);
            if (auto ok = detail::obj_read_face(c, soup, state, name); !ok) return ok.error();
        }
        // Other records (vt, g, o, s, l, usemtl, mtllib, comments) carry nothing we keep.
        if (!c.next_line()) break;
        if (!ticker.tick(c.offset())) return detail::progress_ticker::cancelled(detail::obj_where(name, c.line()));
    }
    if (auto ok = detail::obj_finish(soup, state, name); !ok) return ok.error();
    ticker.finish();
    return soup;
}

/// Reads an OBJ file into `mesh`, replacing its content, and returns what else it found
/// (normals, colours). On error the mesh is unchanged and the message names file:line (or
/// the face that the mesh rejected). Complexity: O(bytes + mesh insertions).
template <class M, class T = default_traits<M>>
    requires readable_mesh<M, T>
result<read_report> read_obj(M& mesh, const std::filesystem::path& path, const read_options& options = {}) {
    auto file = detail::input_file::open(path, options.max_input_bytes);
    if (!file) return file.error();
    auto soup = parse_obj(file->text(), path.string(), options);
    if (!soup) return soup.error();
    return finish_read<M, T>(mesh, std::move(*soup), path.string(), "obj", 0, options);
}

/// Writes OBJ through `out` (an error, with nothing written, for a face with inner rings or a
/// non-finite coordinate: see write_obj): `v` lines (with `r g b` when there are colours), `vn` lines
/// when there are normals, then 1-based `f` lines.
template <class M, class T = default_traits<M>>
    requires writable_mesh<M, T>
result<void> write_obj_to(const M& mesh, std::ostream& stream, const write_options& options = {}) {
    // Before any byte is written.
    if (auto ok = detail::refuse_unwritable<M, T>(mesh, "OBJ"); !ok) return ok;
    if (!detail::put_obj<M, T>(mesh, stream, options)) return detail::stream_failed("OBJ");
    return {};
}

/// OBJ text of the mesh (see write_obj_to), or its error.
template <class M, class T = default_traits<M>>
    requires writable_mesh<M, T>
result<std::string> format_obj(const M& mesh, const write_options& options = {}) {
    std::ostringstream s;
    if (auto ok = write_obj_to<M, T>(mesh, s, options); !ok) return ok.error();
    return std::move(s).str();
}

/// Writes the mesh as OBJ, atomically: a failure leaves any existing file untouched.
/// Complexity: O(V + C). Errors: errc::unsupported naming a face with inner rings (OBJ has one
/// loop per face, and a ring is never dropped silently; triangulate_faces first), or a vertex
/// with a non-finite coordinate, with no file written; errc::io_error.
template <class M, class T = default_traits<M>>
    requires writable_mesh<M, T>
result<void> write_obj(const M& mesh, const std::filesystem::path& path, const write_options& options = {}) {
    if (auto ok = detail::refuse_unwritable<M, T>(mesh, "OBJ"); !ok) return detail::at_path(path, ok.error());
    return detail::write_file_atomically(path,
                                         [&](std::ostream& o) { return detail::put_obj<M, T>(mesh, o, options); });
}

}  // namespace hmira::io
