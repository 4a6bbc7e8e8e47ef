// hmira/io/off.hpp
// Object File Format (OFF): a header, vertex and face counts, positions, then faces as
// "k i1 ... ik". Colours after a face's indices are accepted and ignored.
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

/// Parses OFF text into a soup. Errors name `name:line`.
inline result<polygon_soup> parse_off(std::string_view text, const std::string& name) {
    polygon_soup soup;
    detail::line_reader lines(text);
    std::string_view line;
    auto where = [&] { return name + ":" + std::to_string(lines.line_number()); };
    // Next line with content, comments stripped.
    auto content = [&](std::string_view& out) {
        while (lines.next(out)) {
            if (const auto hash = out.find('#'); hash != std::string_view::npos) out = out.substr(0, hash);
            std::string_view probe = out;
            if (!detail::next_token(probe).empty()) return true;
        }
        return false;
    };
    if (!content(line)) return fail(errc::parse_error, name + ": empty file, expected an OFF header");
    std::string_view rest = line;
    const auto header = detail::next_token(rest);
    if (header != "OFF")
        return fail(errc::parse_error, where() + ": expected 'OFF' header, found '" + std::string(header) + "'");
    std::string_view counts = rest;
    {
        std::string_view probe = counts;
        if (detail::next_token(probe).empty()) {
            if (!content(line)) return fail(errc::parse_error, where() + ": file ends before the vertex and face counts");
            counts = line;
        }
    }
    long long nv = 0, nf = 0;
    {
        const auto a = detail::next_token(counts), b = detail::next_token(counts);
        if (!detail::parse_long(a, nv) || !detail::parse_long(b, nf) || nv < 0 || nf < 0)
            return fail(errc::parse_error, where() + ": expected vertex and face counts, found '" + std::string(line) + "'");
    }
    soup.points.reserve(static_cast<std::size_t>(std::min<long long>(nv, 1 << 24)));
    for (long long i = 0; i < nv; ++i) {
        if (!content(line))
            return fail(errc::parse_error, name + ": file ends after " + std::to_string(i) + " of " + std::to_string(nv) + " vertices (header count too large, or truncated file)");
        std::string_view r = line;
        std::array<double, 3> p{};
        for (int k = 0; k < 3; ++k) {
            const auto tok = detail::next_token(r);
            if (tok.empty()) return fail(errc::parse_error, where() + ": vertex " + std::to_string(i) + " has fewer than 3 coordinates");
            if (!detail::parse_double(tok, p[static_cast<std::size_t>(k)]))
                return fail(errc::parse_error, where() + ": '" + std::string(tok) + "' is not a number");
        }
        soup.points.push_back(p);
    }
    for (long long f = 0; f < nf; ++f) {
        if (!content(line))
            return fail(errc::parse_error, name + ": file ends after " + std::to_string(f) + " of " + std::to_string(nf) + " faces (header count too large, or truncated file)");
        std::string_view r = line;
        long long k = 0;
        const auto ktok = detail::next_token(r);
        if (!detail::parse_long(ktok, k)) return fail(errc::parse_error, where() + ": '" + std::string(ktok) + "' is not a vertex count");
        if (k < 3) return fail(errc::degenerate_face, where() + ": face " + std::to_string(f) + " has " + std::to_string(k) + " vertices; at least 3 needed");
        for (long long j = 0; j < k; ++j) {
            const auto tok = detail::next_token(r);
            long long idx = 0;
            if (tok.empty()) return fail(errc::parse_error, where() + ": face " + std::to_string(f) + " lists fewer than its " + std::to_string(k) + " vertices");
            if (!detail::parse_long(tok, idx)) return fail(errc::parse_error, where() + ": '" + std::string(tok) + "' is not a vertex index");
            if (idx < 0 || idx >= nv)
                return fail(errc::parse_error, where() + ": face " + std::to_string(f) + " uses vertex " + std::to_string(idx) + ", out of range [0, " + std::to_string(nv) + ")");
            soup.indices.push_back(static_cast<std::uint32_t>(idx));
        }
        soup.face_offsets.push_back(static_cast<std::uint32_t>(soup.indices.size()));
    }
    if (content(line)) return fail(errc::parse_error, where() + ": unexpected content after the last face (header counts too small?)");
    return soup;
}

/// Reads an OFF file into `mesh`, replacing its content; on error the mesh is unchanged.
template <class M, class T = default_traits<M>>
    requires readable_mesh<M, T>
result<void> read_off(M& mesh, const std::filesystem::path& path) {
    auto text = detail::read_file(path);
    if (!text) return text.error();
    auto soup = parse_off(*text, path.string());
    if (!soup) return soup.error();
    return assign_from_soup<M, T>(mesh, *soup, [&](std::size_t) { return path.string(); });
}

template <class M, class T = default_traits<M>>
    requires writable_mesh<M, T>
std::string format_off(const M& mesh) {
    std::string out = "OFF\n";
    detail::append_number(out, std::uint64_t{T::vertex_count(mesh)});
    out += ' ';
    detail::append_number(out, std::uint64_t{T::face_count(mesh)});
    out += " 0\n";
    const auto number = detail::dense_vertex_numbers<M, T>(mesh);
    for (auto v : T::vertices(mesh)) {
        const auto p = static_cast<vec3<typename T::scalar>>(T::position(mesh, v));
        detail::append_number(out, static_cast<double>(p.x));
        out += ' ';
        detail::append_number(out, static_cast<double>(p.y));
        out += ' ';
        detail::append_number(out, static_cast<double>(p.z));
        out += '\n';
    }
    std::vector<std::uint32_t> loop;
    for (auto f : T::faces(mesh)) {
        loop.clear();
        for (auto v : T::face_vertices(mesh, f)) loop.push_back(number[T::vertex_index(mesh, v)]);
        detail::append_number(out, std::uint64_t{loop.size()});
        for (auto i : loop) {
            out += ' ';
            detail::append_number(out, std::uint64_t{i});
        }
        out += '\n';
    }
    return out;
}

/// Writes the mesh as OFF, atomically.
template <class M, class T = default_traits<M>>
    requires writable_mesh<M, T>
result<void> write_off(const M& mesh, const std::filesystem::path& path) {
    const auto text = format_off<M, T>(mesh);
    return detail::write_file_atomically(path, [&](std::ostream& o) { return static_cast<bool>(o.write(text.data(), static_cast<std::streamsize>(text.size()))); });
}

}  // namespace hmira::io
