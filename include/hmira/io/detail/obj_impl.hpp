// hmira/io/detail/obj_impl.hpp
// The machinery of obj.hpp: one function per kind of OBJ line the reader keeps (v, vn, f), the
// checks and normal assignment done once the whole file is read, and the OBJ bytes of a mesh.
#pragma once

#include <array>
#include <charconv>
#include <cstdint>
#include <ostream>
#include <string>
#include <system_error>
#include <type_traits>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/result.hpp"
#include "../../core/vec3.hpp"
#include "../io_options.hpp"
#include "files.hpp"
#include "polygon_soup.hpp"
#include "text_format.hpp"

namespace hmira::io::detail {

template <class S>
void append_coordinate(std::string& out, S v) {
    if constexpr (std::is_same_v<S, float>)
        append_number(out, v);
    else
        append_number(out, static_cast<double>(v));
}

inline bool skip_obj_index(const char*& p, const char* end) {
    if (p < end && (*p == '-' || *p == '+')) ++p;
    const char* s = p;
    while (p < end && *p >= '0' && *p <= '9') ++p;
    return p > s;
}

/// What parse_obj carries from line to line besides the soup.
struct obj_parse_state {
    std::vector<vec3<float>> vn;  // normals as listed
    // (vertex, normal) references, resolved at the end: the vertex may come later in the file.
    std::vector<std::array<std::uint32_t, 2>> normal_refs;
    long long max_index = -1;  // largest resolved positive index, for a late check
    std::size_t max_index_line = 0;
    long long max_index_raw = 0;
};

/// "name:line", the place an OBJ error names.
inline std::string obj_where(const std::string& name, std::size_t line) { return name + ":" + std::to_string(line); }

/// A `v x y z [r g b [w]]` line, the cursor past the `v`: the position, and the colour when
/// there is one (`v x y z r g b`, channels in [0, 1]).
inline result<void> obj_read_vertex(text_cursor& c, polygon_soup& soup, const std::string& name) {
    std::array<double, 3> q{};
    for (auto& x : q)
        if (!c.number(x))
            return fail(errc::parse_error, obj_where(name, c.line()) + ": vertex: " + describe_bad_number(c));
    if (!all_finite(q))
        return fail(errc::parse_error, obj_where(name, c.line()) + ": vertex " +
                                           std::to_string(soup.points.size() + 1) +
                                           " has a coordinate that is not finite (NaN or infinity)");
    soup.points.push_back(q);
    std::array<double, 4> extra{};
    int n_extra = 0;
    while (!c.at_line_end('#') && n_extra < 4) {
        if (!c.number(extra[static_cast<std::size_t>(n_extra)]))
            return fail(errc::parse_error, obj_where(name, c.line()) + ": vertex: " + describe_bad_number(c));
        ++n_extra;
    }
    if (n_extra >= 3 && !all_finite(std::array<double, 3>{extra[0], extra[1], extra[2]}))
        return fail(errc::parse_error, obj_where(name, c.line()) + ": vertex " + std::to_string(soup.points.size()) +
                                           " has a colour that is not finite (NaN or infinity)");
    if (n_extra >= 3) {
        auto& colors = soup.attributes.colors;
        colors.resize(soup.points.size() - 1, {255, 255, 255, 255});
        colors.push_back({to_byte(extra[0]), to_byte(extra[1]), to_byte(extra[2]), 255});
    }
    return {};
}

/// A `vn x y z` line, the cursor past the `vn`.
inline result<void> obj_read_normal(text_cursor& c, obj_parse_state& state, const std::string& name) {
    std::array<float, 3> n{};
    for (auto& x : n)
        if (!c.number(x))
            return fail(errc::parse_error, obj_where(name, c.line()) + ": normal: " + describe_bad_number(c));
    if (!all_finite(n))
        return fail(errc::parse_error, obj_where(name, c.line()) + ": normal " + std::to_string(state.vn.size() + 1) +
                                           " is not finite (NaN or infinity)");
    state.vn.push_back({n[0], n[1], n[2]});
    return {};
}

/// An `f` line, the cursor past the `f`: each `v`, `v/vt`, `v//vn` or `v/vt/vn` reference,
/// negative (relative) indices resolved against the vertices and normals read so far. An index
/// past the vertices read so far is kept, and checked once the file is read (obj_finish).
inline result<void> obj_read_face(text_cursor& c, polygon_soup& soup, obj_parse_state& state, const std::string& name) {
    const std::size_t start = soup.indices.size();
    const long long n = static_cast<long long>(soup.points.size());
    while (!c.at_line_end('#')) {
        const char* s = c.pos();
        const char* end = s + (c.size() - c.offset());
        long long i = 0;
        const char* num = (s < end && *s == '+') ? s + 1 : s;
        auto r = std::from_chars(num, end, i);
        if (r.ec != std::errc() || r.ptr == num)
            return fail(errc::parse_error,
                        obj_where(name, c.line()) + ": '" + std::string(c.peek_token()) + "' is not a vertex index");
        const char* q = r.ptr;
        long long normal = 0;
        if (q < end && *q == '/') {
            ++q;
            if (q < end && *q != '/') skip_obj_index(q, end);  // texture index
            if (q < end && *q == '/') {
                ++q;
                auto rn = std::from_chars(q, end, normal);
                if (rn.ec != std::errc() || rn.ptr == q)
                    return fail(errc::parse_error, obj_where(name, c.line()) + ": '" + std::string(c.peek_token()) +
                                                       "' has a bad normal index");
                q = rn.ptr;
            }
        }
        if (q < end && *q != ' ' && *q != '\t' && *q != '\r' && *q != '\n')
            return fail(errc::parse_error,
                        obj_where(name, c.line()) + ": '" + std::string(c.peek_token()) + "' is not a vertex index");
        c.set_pos(q);
        if (i == 0)
            return fail(errc::parse_error, obj_where(name, c.line()) + ": vertex index 0 (OBJ indices start at 1)");
        long long resolved = i > 0 ? i - 1 : n + i;
        if (resolved < 0 || resolved > UINT32_MAX - 1)
            return fail(errc::parse_error, obj_where(name, c.line()) + ": vertex index " + std::to_string(i) +
                                               " is out of range (" + std::to_string(n) + " vertices so far)");
        if (resolved >= n && resolved > state.max_index) {
            state.max_index = resolved;
            state.max_index_line = c.line();
            state.max_index_raw = i;
        }
        soup.indices.push_back(static_cast<std::uint32_t>(resolved));
        if (normal != 0) {
            const long long nn = static_cast<long long>(state.vn.size());
            const long long rn = normal > 0 ? normal - 1 : nn + normal;
            if (rn < 0 || rn >= nn)
                return fail(errc::parse_error, obj_where(name, c.line()) + ": normal index " + std::to_string(normal) +
                                                   " is out of range (" + std::to_string(nn) + " normals so far)");
            state.normal_refs.push_back({static_cast<std::uint32_t>(resolved), static_cast<std::uint32_t>(rn)});
        }
    }
    const std::size_t k = soup.indices.size() - start;
    if (k < 3)
        return fail(errc::degenerate_face,
                    obj_where(name, c.line()) + ": a face needs at least 3 vertices, got " + std::to_string(k));
    soup.face_offsets.push_back(soup.indices.size());
    return {};
}

/// Once every line is read: the largest forward index must name a vertex; colours cover every
/// vertex (white where a `v` line had none); a vertex's normal is the first one a face gives it.
inline result<void> obj_finish(polygon_soup& soup, const obj_parse_state& state, const std::string& name) {
    if (state.max_index >= static_cast<long long>(soup.points.size()))
        return fail(errc::parse_error, obj_where(name, state.max_index_line) + ": vertex index " +
                                           std::to_string(state.max_index_raw) + " is out of range (the file has " +
                                           std::to_string(soup.points.size()) + " vertices)");
    if (!soup.attributes.colors.empty()) soup.attributes.colors.resize(soup.points.size(), {255, 255, 255, 255});
    if (!state.normal_refs.empty()) {
        soup.attributes.normals.assign(soup.points.size(), vec3<float>{});
        std::vector<std::uint8_t> set(soup.points.size(), 0);
        for (const auto& [v, n] : state.normal_refs)
            if (!set[v]) {
                set[v] = 1;
                soup.attributes.normals[v] = state.vn[n];
            }
    }
    return {};
}

/// The OBJ bytes of a mesh that refuse_unwritable accepted; false when the stream failed.
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

}  // namespace hmira::io::detail
