// hmira/io/obj.hpp
// Wavefront OBJ: positions, polygonal faces, per-vertex normals (through `vn` and the faces'
// `v//vn` references) and the common `v x y z r g b` vertex-colour extension. Texture
// references are accepted and ignored, negative (relative) indices are resolved, polygons
// stay polygons.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "../concepts.hpp"
#include "../core/huge_pages.hpp"
#include "../core/result.hpp"
#include "detail/face_loops.hpp"
#include "detail/files.hpp"
#include "detail/polygon_soup.hpp"
#include "detail/text_format.hpp"
#include "io_options.hpp"

namespace hmira::io {

namespace detail {

template <class S>
void append_coordinate(std::string& out, S v) {
    if constexpr (std::is_same_v<S, float>) append_number(out, v);
    else append_number(out, static_cast<double>(v));
}

inline bool skip_obj_index(const char*& p, const char* end) {
    if (p < end && (*p == '-' || *p == '+')) ++p;
    const char* s = p;
    while (p < end && *p >= '0' && *p <= '9') ++p;
    return p > s;
}

}  // namespace detail

/// Parses OBJ text into a soup. Errors name `name:line`.
/// Complexity: O(bytes), one pass. Faces may use vertices defined later in the file.
/// Errors (errc::parse_error / degenerate_face): non-numbers, vertices with fewer than 3
/// coordinates, index 0, indices out of range, faces with fewer than 3 vertices.
inline result<polygon_soup> parse_obj(std::string_view text, const std::string& name, const read_options& options = {}) {
    polygon_soup soup;
    detail::text_cursor c(text);
    detail::progress_ticker ticker(options.progress, text.size());
    auto where = [&](std::size_t line) { return name + ":" + std::to_string(line); };
    std::vector<vec3<float>> vn;                 // normals as listed
    // (vertex, normal) references, resolved at the end: the vertex may come later in the file.
    std::vector<std::array<std::uint32_t, 2>> normal_refs;
    long long max_index = -1;                    // largest resolved positive index, for a late check
    std::size_t max_index_line = 0;
    long long max_index_raw = 0;
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
            std::array<double, 3> q{};
            for (auto& x : q)
                if (!c.number(x)) return fail(errc::parse_error, where(c.line()) + ": vertex: " + detail::describe_bad_number(c));
            if (!detail::all_finite(q))
                return fail(errc::parse_error, where(c.line()) + ": vertex " + std::to_string(soup.points.size() + 1) + " has a coordinate that is not finite (NaN or infinity)");
            soup.points.push_back(q);
            std::array<double, 4> extra{};
            int n_extra = 0;
            while (!c.at_line_end('#') && n_extra < 4) {
                if (!c.number(extra[static_cast<std::size_t>(n_extra)]))
                    return fail(errc::parse_error, where(c.line()) + ": vertex: " + detail::describe_bad_number(c));
                ++n_extra;
            }
            if (n_extra >= 3 && !detail::all_finite(std::array<double, 3>{extra[0], extra[1], extra[2]}))
                return fail(errc::parse_error, where(c.line()) + ": vertex " + std::to_string(soup.points.size()) + " has a colour that is not finite (NaN or infinity)");
            if (n_extra >= 3) {  // `v x y z r g b`: colours in [0, 1]
                auto& colors = soup.attributes.colors;
                colors.resize(soup.points.size() - 1, {255, 255, 255, 255});
                colors.push_back({detail::to_byte(extra[0]), detail::to_byte(extra[1]), detail::to_byte(extra[2]), 255});
            }
        } else if (p[0] == 'v' && remaining > 2 && p[1] == 'n' && (p[2] == ' ' || p[2] == '\t')) {
            c.set_pos(p + 2);
            std::array<float, 3> n{};
            for (auto& x : n)
                if (!c.number(x)) return fail(errc::parse_error, where(c.line()) + ": normal: " + detail::describe_bad_number(c));
            if (!detail::all_finite(n)) return fail(errc::parse_error, where(c.line()) + ": normal " + std::to_string(vn.size() + 1) + " is not finite (NaN or infinity)");
            vn.push_back({n[0], n[1], n[2]});
        } else if (p[0] == 'f' && remaining > 1 && (p[1] == ' ' || p[1] == '\t')) {
            c.set_pos(p + 1);
            const std::size_t start = soup.indices.size();
            const long long n = static_cast<long long>(soup.points.size());
            while (!c.at_line_end('#')) {
                const char* s = c.pos();
                const char* end = s + (c.size() - c.offset());
                long long i = 0;
                const char* num = (s < end && *s == '+') ? s + 1 : s;
                auto r = std::from_chars(num, end, i);
                if (r.ec != std::errc() || r.ptr == num)
                    return fail(errc::parse_error, where(c.line()) + ": '" + std::string(c.peek_token()) + "' is not a vertex index");
                const char* q = r.ptr;
                long long normal = 0;
                if (q < end && *q == '/') {
                    ++q;
                    if (q < end && *q != '/') detail::skip_obj_index(q, end);  // texture index
                    if (q < end && *q == '/') {
                        ++q;
                        auto rn = std::from_chars(q, end, normal);
                        if (rn.ec != std::errc() || rn.ptr == q)
                            return fail(errc::parse_error, where(c.line()) + ": '" + std::string(c.peek_token()) + "' has a bad normal index");
                        q = rn.ptr;
                    }
                }
                if (q < end && *q != ' ' && *q != '\t' && *q != '\r' && *q != '\n')
                    return fail(errc::parse_error, where(c.line()) + ": '" + std::string(c.peek_token()) + "' is not a vertex index");
                c.set_pos(q);
                if (i == 0) return fail(errc::parse_error, where(c.line()) + ": vertex index 0 (OBJ indices start at 1)");
                long long resolved = i > 0 ? i - 1 : n + i;
                if (resolved < 0 || resolved > UINT32_MAX - 1)
                    return fail(errc::parse_error, where(c.line()) + ": vertex index " + std::to_string(i) + " is out of range (" + std::to_string(n) +
                                                       " vertices so far)");
                if (resolved >= n && resolved > max_index) {
                    max_index = resolved;
                    max_index_line = c.line();
                    max_index_raw = i;
                }
                soup.indices.push_back(static_cast<std::uint32_t>(resolved));
                if (normal != 0) {
                    const long long nn = static_cast<long long>(vn.size());
                    const long long rn = normal > 0 ? normal - 1 : nn + normal;
                    if (rn < 0 || rn >= nn)
                        return fail(errc::parse_error, where(c.line()) + ": normal index " + std::to_string(normal) + " is out of range (" +
                                                           std::to_string(nn) + " normals so far)");
                    normal_refs.push_back({static_cast<std::uint32_t>(resolved), static_cast<std::uint32_t>(rn)});
                }
            }
            const std::size_t k = soup.indices.size() - start;
            if (k < 3)
                return fail(errc::degenerate_face, where(c.line()) + ": a face needs at least 3 vertices, got " + std::to_string(k));
            soup.face_offsets.push_back(soup.indices.size());
        }
        // Other records (vt, g, o, s, l, usemtl, mtllib, comments) carry nothing we keep.
        if (!c.next_line()) break;
        if (!ticker.tick(c.offset())) return detail::progress_ticker::cancelled(where(c.line()));
    }
    if (max_index >= static_cast<long long>(soup.points.size()))
        return fail(errc::parse_error, where(max_index_line) + ": vertex index " + std::to_string(max_index_raw) + " is out of range (the file has " +
                                           std::to_string(soup.points.size()) + " vertices)");
    if (!soup.attributes.colors.empty()) soup.attributes.colors.resize(soup.points.size(), {255, 255, 255, 255});
    if (!normal_refs.empty()) {
        // A vertex's normal is the first one a face gives it.
        soup.attributes.normals.assign(soup.points.size(), vec3<float>{});
        std::vector<std::uint8_t> set(soup.points.size(), 0);
        for (const auto& [v, n] : normal_refs)
            if (!set[v]) {
                set[v] = 1;
                soup.attributes.normals[v] = vn[n];
            }
    }
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

namespace detail {

/// The OBJ bytes of a mesh that refuse_unwritable accepted; false when the stream failed.
template <class M, class T>
bool put_obj(const M& mesh, std::ostream& stream, const write_options& options) {
    using S = typename T::scalar;
    detail::chunked_output out(stream);
    auto& b = out.buffer();
    b += "# written by hmira\n";
    const auto number = detail::dense_vertex_numbers<M, T>(mesh);
    const auto attr = detail::find_attributes<M, T>(mesh, options);
    for (auto v : T::vertices(mesh)) {
        const auto p = static_cast<vec3<S>>(T::position(mesh, v));
        b += "v ";
        detail::append_coordinate(b, p.x);
        b += ' ';
        detail::append_coordinate(b, p.y);
        b += ' ';
        detail::append_coordinate(b, p.z);
        if (attr.colors) {
            const auto& col = attr.colors[T::vertex_index(mesh, v)];
            for (int k = 0; k < 3; ++k) {
                b += ' ';
                detail::append_number(b, static_cast<double>(col[static_cast<std::size_t>(k)]) / 255.0);
            }
        }
        b += '\n';
        if (!out.maybe_flush()) return false;
    }
    if (attr.normals) {
        for (auto v : T::vertices(mesh)) {
            const auto& n = attr.normals[T::vertex_index(mesh, v)];
            b += "vn ";
            detail::append_number(b, n.x);
            b += ' ';
            detail::append_number(b, n.y);
            b += ' ';
            detail::append_number(b, n.z);
            b += '\n';
            if (!out.maybe_flush()) return false;
        }
    }
    for (auto f : T::faces(mesh)) {
        b += 'f';
        for (auto v : T::face_vertices(mesh, f)) {
            b += ' ';
            const auto k = number[T::vertex_index(mesh, v)] + 1;
            detail::append_number(b, k);
            if (attr.normals) {
                b += "//";
                detail::append_number(b, k);
            }
        }
        b += '\n';
        if (!out.maybe_flush()) return false;
    }
    return out.flush();
}

}  // namespace detail

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
    return detail::write_file_atomically(path, [&](std::ostream& o) { return detail::put_obj<M, T>(mesh, o, options); });
}

}  // namespace hmira::io
