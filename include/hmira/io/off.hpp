// hmira/io/off.hpp
// Object File Format (OFF, with its NOFF / COFF / CNOFF variants): a header, vertex and face
// counts, positions (with normals and colours in the variants), then faces as "k i1 ... ik".
// Colours after a face's indices are accepted and ignored.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <sstream>
#include <string>
#include <string_view>

#include "../concepts.hpp"
#include "../core/huge_pages.hpp"
#include "../core/result.hpp"
#include "detail/face_loops.hpp"
#include "detail/files.hpp"
#include "detail/polygon_soup.hpp"
#include "detail/text_format.hpp"
#include "io_options.hpp"
#include "obj.hpp"  // detail::append_coordinate

namespace hmira::io {

namespace detail {

/// The colour of OFF vertex i, after its position (and normal): "r g b [a]", integers 0..255
/// or floats 0..1; with texture coordinates after it (STCOFF), r g b only. Errors name
/// `name:line`.
inline result<std::array<std::uint8_t, 4>> off_read_color(text_cursor& c, long long i, bool has_texture,
                                                          const std::string& name) {
    auto where = [&] { return name + ":" + std::to_string(c.line()); };
    std::array<double, 4> col{0, 0, 0, -1};
    int k = 0;
    const int wanted = has_texture ? 3 : 4;  // with texture coordinates after, read RGB only
    for (; k < wanted && !c.at_line_end('#'); ++k)
        if (!c.number(col[static_cast<std::size_t>(k)]))
            return fail(errc::parse_error,
                        where() + ": colour of vertex " + std::to_string(i) + ": " + describe_bad_number(c));
    if (k < 3)
        return fail(errc::parse_error, where() + ": vertex " + std::to_string(i) + " has no colour (COFF needs r g b)");
    // Integer colours run 0..255, float colours 0..1; anything else is refused.
    const bool bytes = std::max({col[0], col[1], col[2], col[3]}) > 1.0;
    std::array<std::uint8_t, 4> rgba{};
    for (std::size_t j = 0; j < 4; ++j) {
        const double x = j == 3 && k < 4 ? (bytes ? 255.0 : 1.0) : col[j];
        const auto byte = color_channel(x, bytes);
        if (!byte)
            return fail(errc::parse_error, where() + ": colour of vertex " + std::to_string(i) + ": channel " +
                                               std::to_string(j) + " is " + number_text(x) + ", outside " +
                                               (bytes ? "0..255" : "0..1"));
        rgba[j] = *byte;
    }
    return rgba;
}

/// The corners of OFF face f ("k i1 ... ik", k >= 3, each index in [0, nv)), appended to
/// soup.indices. Errors name `name:line`.
inline result<void> off_read_face(text_cursor& c, long long f, long long nv, polygon_soup& soup,
                                  const std::string& name) {
    auto where = [&] { return name + ":" + std::to_string(c.line()); };
    long long k = 0;
    if (!c.number(k))
        return fail(errc::parse_error, where() + ": face " + std::to_string(f) + ": " + describe_bad_number(c) +
                                           " (expected a vertex count)");
    if (k < 3)
        return fail(errc::degenerate_face, where() + ": face " + std::to_string(f) + " has " + std::to_string(k) +
                                               " vertices; at least 3 needed");
    for (long long j = 0; j < k; ++j) {
        long long idx = 0;
        if (c.at_line_end('#'))
            return fail(errc::parse_error, where() + ": face " + std::to_string(f) + " lists fewer than its " +
                                               std::to_string(k) + " vertices");
        if (!c.number(idx))
            return fail(errc::parse_error, where() + ": face " + std::to_string(f) + ": " + describe_bad_number(c) +
                                               " (expected a vertex index)");
        if (idx < 0 || idx >= nv)
            return fail(errc::parse_error, where() + ": face " + std::to_string(f) + " uses vertex " +
                                               std::to_string(idx) + ", out of range [0, " + std::to_string(nv) + ")");
        soup.indices.push_back(static_cast<std::uint32_t>(idx));
    }
    return {};
}

}  // namespace detail

/// Parses OFF text into a soup. Errors name `name:line`.
/// Complexity: O(bytes). Errors (errc::parse_error / degenerate_face / unsupported): a missing
/// or unknown header, counts that do not match the content (too large: "file ends after";
/// too small: "unexpected content"), non-numbers, indices out of [0, V), faces of fewer than
/// 3 vertices, binary OFF and 4D/nD variants (unsupported).
inline result<polygon_soup> parse_off(std::string_view text, const std::string& name,
                                      const read_options& options = {}) {
    polygon_soup soup;
    detail::text_cursor c(text);
    detail::progress_ticker ticker(options.progress, text.size());
    auto where = [&] { return name + ":" + std::to_string(c.line()); };
    c.skip_space_and_newlines('#');
    if (c.at_end()) return fail(errc::parse_error, name + ": empty file, expected an OFF header");
    const auto header = c.token();
    if (header.size() < 3 || header.substr(header.size() - 3) != "OFF")
        return fail(errc::parse_error,
                    where() + ": expected an 'OFF' header, found '" + std::string(header.substr(0, 40)) + "'");
    bool has_normals = false, has_colors = false, has_texture = false;
    for (char ch : header.substr(0, header.size() - 3)) {
        if (ch == 'N')
            has_normals = true;
        else if (ch == 'C')
            has_colors = true;
        else if (ch == 'S' || ch == 'T')
            has_texture = true;
        else
            return fail(errc::unsupported,
                        where() + ": OFF variant '" + std::string(header) + "' is not supported (only [ST][C][N]OFF)");
    }
    {
        const auto probe = c.peek_token();
        if (probe == "BINARY") return fail(errc::unsupported, where() + ": binary OFF is not supported");
    }
    c.skip_space_and_newlines('#');
    long long nv = 0, nf = 0, ne = 0;
    if (!c.number(nv))
        return fail(errc::parse_error,
                    where() + ": expected vertex and face counts, " + detail::describe_bad_number(c));
    if (nv < 0) return fail(errc::parse_error, where() + ": the vertex count " + std::to_string(nv) + " is negative");
    if (!c.number(nf))
        return fail(errc::parse_error,
                    where() + ": expected a face count after the vertex count, " + detail::describe_bad_number(c));
    if (nf < 0) return fail(errc::parse_error, where() + ": the face count " + std::to_string(nf) + " is negative");
    if (!c.at_line_end('#') && !c.number(ne))
        return fail(errc::parse_error, where() + ": edge count: " + detail::describe_bad_number(c));
    if (nv > static_cast<long long>(UINT32_MAX) - 1)
        return fail(errc::parse_error, where() + ": vertex count " + std::to_string(nv) + " is too large");
    // Counts may be absurd in a broken file: reserve no more than the text could hold.
    hmira::detail::reserve_huge(
        soup.points, static_cast<std::size_t>(std::min<long long>(nv, static_cast<long long>(text.size() / 6 + 1))));
    hmira::detail::reserve_huge(
        soup.face_offsets,
        static_cast<std::size_t>(std::min<long long>(nf, static_cast<long long>(text.size() / 8 + 1))) + 1);
    if (has_normals) soup.attributes.normals.reserve(soup.points.capacity());
    if (has_colors) soup.attributes.colors.reserve(soup.points.capacity());
    c.next_line();
    for (long long i = 0; i < nv; ++i) {
        c.skip_space_and_newlines('#');
        if (c.at_end())
            return fail(errc::parse_error, name + ":" + std::to_string(c.line()) + ": file ends after " +
                                               std::to_string(i) + " of " + std::to_string(nv) +
                                               " vertices (header count too large, or truncated file)");
        std::array<double, 3> p{};
        for (auto& x : p)
            if (!c.number(x))
                return fail(errc::parse_error,
                            where() + ": vertex " + std::to_string(i) + ": " + detail::describe_bad_number(c));
        if (!detail::all_finite(p))
            return fail(errc::parse_error, where() + ": vertex " + std::to_string(i) +
                                               " has a coordinate that is not finite (NaN or infinity)");
        soup.points.push_back(p);
        if (has_normals) {
            std::array<float, 3> n{};
            for (auto& x : n)
                if (!c.number(x))
                    return fail(errc::parse_error, where() + ": normal of vertex " + std::to_string(i) + ": " +
                                                       detail::describe_bad_number(c));
            if (!detail::all_finite(n))
                return fail(errc::parse_error,
                            where() + ": normal of vertex " + std::to_string(i) + " is not finite (NaN or infinity)");
            soup.attributes.normals.push_back({n[0], n[1], n[2]});
        }
        if (has_colors) {
            auto rgba = detail::off_read_color(c, i, has_texture, name);
            if (!rgba) return rgba.error();
            soup.attributes.colors.push_back(*rgba);
        }
        c.next_line();
        if (!ticker.tick(c.offset())) return detail::progress_ticker::cancelled(where());
    }
    for (long long f = 0; f < nf; ++f) {
        c.skip_space_and_newlines('#');
        if (c.at_end())
            return fail(errc::parse_error, name + ":" + std::to_string(c.line()) + ": file ends after " +
                                               std::to_string(f) + " of " + std::to_string(nf) +
                                               " faces (header count too large, or truncated file)");
        if (auto face = detail::off_read_face(c, f, nv, soup, name); !face) return face.error();
        soup.face_offsets.push_back(soup.indices.size());
        c.next_line();
        if (!ticker.tick(c.offset())) return detail::progress_ticker::cancelled(where());
    }
    c.skip_space_and_newlines('#');
    if (!c.at_end())
        return fail(errc::parse_error, where() + ": unexpected content after the last face (header counts too small?)");
    ticker.finish();
    return soup;
}

/// Reads an OFF file into `mesh`, replacing its content; on error the mesh is unchanged.
/// Complexity: O(bytes + mesh insertions).
template <class M, class T = default_traits<M>>
    requires readable_mesh<M, T>
result<read_report> read_off(M& mesh, const std::filesystem::path& path, const read_options& options = {}) {
    auto file = detail::input_file::open(path, options.max_input_bytes);
    if (!file) return file.error();
    auto soup = parse_off(file->text(), path.string(), options);
    if (!soup) return soup.error();
    return finish_read<M, T>(mesh, std::move(*soup), path.string(), "off", 0, options);
}

namespace detail {

/// The OFF bytes of a mesh that refuse_unwritable accepted; false when the stream failed.
template <class M, class T>
bool put_off(const M& mesh, std::ostream& stream, const write_options& options) {
    using S = typename T::scalar;
    detail::chunked_output out(stream);
    auto& b = out.buffer();
    const auto attr = detail::find_attributes<M, T>(mesh, options);
    if (attr.colors) b += 'C';
    if (attr.normals) b += 'N';
    b += "OFF\n";
    detail::append_number(b, std::uint64_t{T::vertex_count(mesh)});
    b += ' ';
    detail::append_number(b, std::uint64_t{T::face_count(mesh)});
    b += " 0\n";
    const auto number = detail::dense_vertex_numbers<M, T>(mesh);
    for (auto v : T::vertices(mesh)) {
        const auto p = static_cast<vec3<S>>(T::position(mesh, v));
        detail::append_coordinate(b, p.x);
        b += ' ';
        detail::append_coordinate(b, p.y);
        b += ' ';
        detail::append_coordinate(b, p.z);
        const auto vi = T::vertex_index(mesh, v);
        if (attr.normals) {
            for (int k = 0; k < 3; ++k) {
                b += ' ';
                detail::append_number(b, attr.normals[vi][static_cast<std::size_t>(k)]);
            }
        }
        if (attr.colors) {
            for (int k = 0; k < 4; ++k) {
                b += ' ';
                detail::append_number(b, std::uint64_t{attr.colors[vi][static_cast<std::size_t>(k)]});
            }
        }
        b += '\n';
        if (!out.maybe_flush()) return false;
    }
    std::vector<std::uint32_t> loop;
    for (auto f : T::faces(mesh)) {
        loop.clear();
        for (auto v : T::face_vertices(mesh, f)) loop.push_back(number[T::vertex_index(mesh, v)]);
        detail::append_number(b, std::uint64_t{loop.size()});
        for (auto i : loop) {
            b += ' ';
            detail::append_number(b, i);
        }
        b += '\n';
        if (!out.maybe_flush()) return false;
    }
    return out.flush();
}

}  // namespace detail

/// Writes OFF through `out` (false, with nothing written, if a face has inner rings: see
/// write_off): "[C][N]OFF" as the attributes require, colours as 0..255 RGBA.
template <class M, class T = default_traits<M>>
    requires writable_mesh<M, T>
result<void> write_off_to(const M& mesh, std::ostream& stream, const write_options& options = {}) {
    // Before any byte is written.
    if (auto ok = detail::refuse_unwritable<M, T>(mesh, "OFF"); !ok) return ok;
    if (!detail::put_off<M, T>(mesh, stream, options)) return detail::stream_failed("OFF");
    return {};
}

/// OFF text of the mesh (see write_off_to), or its error.
template <class M, class T = default_traits<M>>
    requires writable_mesh<M, T>
result<std::string> format_off(const M& mesh, const write_options& options = {}) {
    std::ostringstream s;
    if (auto ok = write_off_to<M, T>(mesh, s, options); !ok) return ok.error();
    return std::move(s).str();
}

/// Writes the mesh as OFF, atomically. Complexity O(V + C). Errors: errc::unsupported naming a
/// face with inner rings (OFF has one loop per face, and a ring is never dropped silently;
/// triangulate_faces first), or a vertex with a non-finite
/// coordinate, with no file written; errc::io_error.
template <class M, class T = default_traits<M>>
    requires writable_mesh<M, T>
result<void> write_off(const M& mesh, const std::filesystem::path& path, const write_options& options = {}) {
    if (auto ok = detail::refuse_unwritable<M, T>(mesh, "OFF"); !ok) return detail::at_path(path, ok.error());
    return detail::write_file_atomically(path,
                                         [&](std::ostream& o) { return detail::put_off<M, T>(mesh, o, options); });
}

}  // namespace hmira::io
