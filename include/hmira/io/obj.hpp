// hmira/io/obj.hpp
// Wavefront OBJ: positions and polygonal faces. Texture and normal references in faces are
// accepted and ignored, negative (relative) indices are resolved, and polygons stay polygons.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "../concepts.hpp"
#include "../core/result.hpp"
#include "detail/files.hpp"
#include "detail/polygon_soup.hpp"
#include "detail/text_format.hpp"

namespace hmira::io {

/// Parses OBJ text into a soup. Errors name `name:line`.
inline result<polygon_soup> parse_obj(std::string_view text, const std::string& name) {
    polygon_soup soup;
    std::vector<std::size_t> face_line;
    struct pending { std::size_t line; long long raw; };
    detail::line_reader lines(text);
    std::string_view line;
    auto where = [&](std::size_t l) { return name + ":" + std::to_string(l); };
    while (lines.next(line)) {
        std::string_view rest = line;
        const auto tag = detail::next_token(rest);
        if (tag == "v") {
            std::array<double, 3> p{};
            for (int i = 0; i < 3; ++i) {
                const auto tok = detail::next_token(rest);
                if (tok.empty()) return fail(errc::parse_error, where(lines.line_number()) + ": vertex has fewer than 3 coordinates");
                if (!detail::parse_double(tok, p[static_cast<std::size_t>(i)]))
                    return fail(errc::parse_error, where(lines.line_number()) + ": '" + std::string(tok) + "' is not a number");
            }
            soup.points.push_back(p);
        } else if (tag == "f") {
            const auto start = soup.indices.size();
            for (auto tok = detail::next_token(rest); !tok.empty(); tok = detail::next_token(rest)) {
                const auto slash = tok.find('/');
                const auto idx = tok.substr(0, slash);
                long long i = 0;
                if (!detail::parse_long(idx, i))
                    return fail(errc::parse_error, where(lines.line_number()) + ": '" + std::string(tok) + "' is not a vertex index");
                if (i == 0) return fail(errc::parse_error, where(lines.line_number()) + ": vertex index 0 (OBJ indices start at 1)");
                const long long n = static_cast<long long>(soup.points.size());
                const long long resolved = i > 0 ? i - 1 : n + i;
                if (resolved < 0 || resolved >= n)
                    return fail(errc::parse_error, where(lines.line_number()) + ": vertex index " + std::to_string(i) + " is out of range (" +
                                                       std::to_string(n) + " vertices so far)");
                soup.indices.push_back(static_cast<std::uint32_t>(resolved));
            }
            if (soup.indices.size() - start < 3)
                return fail(errc::degenerate_face, where(lines.line_number()) + ": a face needs at least 3 vertices, got " +
                                                       std::to_string(soup.indices.size() - start));
            soup.face_offsets.push_back(static_cast<std::uint32_t>(soup.indices.size()));
            face_line.push_back(lines.line_number());
        }
        // Other records (vt, vn, g, o, s, usemtl, mtllib, l, comments) carry nothing we keep.
    }
    return soup;
}

/// Reads an OBJ file into `mesh`, replacing its content. On error the mesh is unchanged and
/// the message names file:line (or the face that the mesh rejected).
template <class M, class T = default_traits<M>>
    requires readable_mesh<M, T>
result<void> read_obj(M& mesh, const std::filesystem::path& path) {
    auto text = detail::read_file(path);
    if (!text) return text.error();
    auto soup = parse_obj(*text, path.string());
    if (!soup) return soup.error();
    return assign_from_soup<M, T>(mesh, *soup, [&](std::size_t) { return path.string(); });
}

/// OBJ text of the mesh: `v` lines then 1-based `f` lines.
template <class M, class T = default_traits<M>>
    requires writable_mesh<M, T>
std::string format_obj(const M& mesh) {
    std::string out = "# written by hmira\n";
    const auto number = detail::dense_vertex_numbers<M, T>(mesh);
    for (auto v : T::vertices(mesh)) {
        const auto p = static_cast<vec3<typename T::scalar>>(T::position(mesh, v));
        out += "v ";
        detail::append_number(out, static_cast<double>(p.x));
        out += ' ';
        detail::append_number(out, static_cast<double>(p.y));
        out += ' ';
        detail::append_number(out, static_cast<double>(p.z));
        out += '\n';
    }
    for (auto f : T::faces(mesh)) {
        out += 'f';
        for (auto v : T::face_vertices(mesh, f)) {
            out += ' ';
            detail::append_number(out, std::uint64_t{number[T::vertex_index(mesh, v)]} + 1);
        }
        out += '\n';
    }
    return out;
}

/// Writes the mesh as OBJ, atomically: a failure leaves any existing file untouched.
template <class M, class T = default_traits<M>>
    requires writable_mesh<M, T>
result<void> write_obj(const M& mesh, const std::filesystem::path& path) {
    const auto text = format_obj<M, T>(mesh);
    return detail::write_file_atomically(path, [&](std::ostream& o) { return static_cast<bool>(o.write(text.data(), static_cast<std::streamsize>(text.size()))); });
}

}  // namespace hmira::io
