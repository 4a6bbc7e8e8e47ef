// hmira/io/detail/ply_reader_impl.hpp
// The machinery of ply_reader.hpp: the header parser, and the data readers for ASCII and for
// binary data in either byte order, each element kind (vertex, face, any other) by its own
// function.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "../../core/huge_pages.hpp"
#include "../../core/result.hpp"
#include "../io_options.hpp"
#include "face_loops.hpp"
#include "files.hpp"
#include "ply_types.hpp"
#include "polygon_soup.hpp"
#include "text_format.hpp"

namespace hmira::io::detail {

struct ply_property {
    std::string name;
    ply_type type = ply_type::invalid;        ///< value type (the item type of a list)
    ply_type count_type = ply_type::invalid;  ///< set for lists
    bool is_list() const noexcept { return count_type != ply_type::invalid; }
};

struct ply_element {
    std::string name;
    std::uint64_t count = 0;
    std::vector<ply_property> props;
    std::size_t line = 0;
    /// Byte size of one item when no property is a list, else 0.
    std::size_t fixed_stride() const {
        std::size_t s = 0;
        for (const auto& p : props) {
            if (p.is_list()) return 0;
            s += ply_size(p.type);
        }
        return s;
    }
    int find(std::initializer_list<std::string_view> names) const {
        for (std::size_t i = 0; i < props.size(); ++i)
            for (auto n : names)
                if (props[i].name == n) return static_cast<int>(i);
        return -1;
    }
};

struct ply_header {
    ply_encoding encoding = ply_encoding::ascii;
    std::vector<ply_element> elements;
    std::size_t data_offset = 0;  ///< first byte after "end_header\n"
    std::size_t data_line = 0;    ///< line number of the first data line (ASCII)
};

inline result<ply_header> parse_ply_header(std::string_view text, const std::string& name) {
    ply_header h;
    line_reader lines(text);
    std::string_view line;
    auto where = [&] { return name + ":" + std::to_string(lines.line_number()); };
    if (!lines.next(line) || line != "ply")
        return fail(errc::parse_error, name + ":1: not a PLY file (the first line must be 'ply')");
    bool have_format = false;
    for (;;) {
        if (!lines.next(line))
            return fail(errc::parse_error, where() + ": file ends inside the header (no 'end_header')");
        std::string_view rest = line;
        const auto key = next_token(rest);
        if (key.empty() || key == "comment" || key == "obj_info") continue;
        if (key == "format") {
            const auto enc = next_token(rest);
            if (enc == "ascii")
                h.encoding = ply_encoding::ascii;
            else if (enc == "binary_little_endian")
                h.encoding = ply_encoding::binary_little_endian;
            else if (enc == "binary_big_endian")
                h.encoding = ply_encoding::binary_big_endian;
            else
                return fail(errc::parse_error, where() + ": unknown PLY format '" + std::string(enc) + "'");
            have_format = true;
        } else if (key == "element") {
            ply_element e;
            e.name = std::string(next_token(rest));
            long long n = 0;
            const auto count = next_token(rest);
            if (e.name.empty() || !parse_long(count, n) || n < 0)
                return fail(errc::parse_error,
                            where() + ": expected 'element <name> <count>', found '" + std::string(line) + "'");
            e.count = static_cast<std::uint64_t>(n);
            e.line = lines.line_number();
            for (const auto& other : h.elements)
                if (other.name == e.name && (e.name == "vertex" || e.name == "face"))
                    return fail(errc::parse_error, where() + ": a second '" + e.name + "' element");
            h.elements.push_back(std::move(e));
        } else if (key == "property") {
            if (h.elements.empty()) return fail(errc::parse_error, where() + ": 'property' before any 'element'");
            ply_property p;
            auto t = next_token(rest);
            if (t == "list") {
                const auto ct = next_token(rest), it = next_token(rest);
                p.count_type = ply_type_from(ct);
                p.type = ply_type_from(it);
                if (p.count_type == ply_type::invalid || p.type == ply_type::invalid || !ply_is_integer(p.count_type))
                    return fail(errc::parse_error, where() + ": bad list property types '" + std::string(ct) + " " +
                                                       std::string(it) + "'");
            } else {
                p.type = ply_type_from(t);
                if (p.type == ply_type::invalid)
                    return fail(errc::parse_error, where() + ": unknown property type '" + std::string(t) + "'");
            }
            p.name = std::string(next_token(rest));
            if (p.name.empty()) return fail(errc::parse_error, where() + ": property without a name");
            h.elements.back().props.push_back(std::move(p));
        } else if (key == "end_header") {
            if (!next_token(rest).empty())
                return fail(errc::parse_error, where() + ": unexpected text after 'end_header' on its line");
            break;
        } else {
            return fail(errc::parse_error,
                        where() + ": unexpected header line '" + std::string(line.substr(0, 60)) + "'");
        }
    }
    if (!have_format) return fail(errc::parse_error, name + ": PLY header has no 'format' line");
    h.data_offset = lines.position();
    h.data_line = lines.line_number() + 1;
    return h;
}

/// One binary value of type t at p, as double.
template <bool Swap>
double ply_load(ply_type t, const char* p) {
    switch (t) {
        case ply_type::i8: return ply_raw<std::int8_t, Swap>(p);
        case ply_type::u8: return ply_raw<std::uint8_t, Swap>(p);
        case ply_type::i16: return ply_raw<std::int16_t, Swap>(p);
        case ply_type::u16: return ply_raw<std::uint16_t, Swap>(p);
        case ply_type::i32: return ply_raw<std::int32_t, Swap>(p);
        case ply_type::u32: return ply_raw<std::uint32_t, Swap>(p);
        case ply_type::f32: return static_cast<double>(ply_raw<float, Swap>(p));
        case ply_type::f64: return ply_raw<double, Swap>(p);
        default: return 0;
    }
}

/// One binary integer of type t at p (floats are truncated; callers check integer types).
template <bool Swap>
long long ply_load_int(ply_type t, const char* p) {
    switch (t) {
        case ply_type::i8: return ply_raw<std::int8_t, Swap>(p);
        case ply_type::u8: return ply_raw<std::uint8_t, Swap>(p);
        case ply_type::i16: return ply_raw<std::int16_t, Swap>(p);
        case ply_type::u16: return ply_raw<std::uint16_t, Swap>(p);
        case ply_type::i32: return ply_raw<std::int32_t, Swap>(p);
        case ply_type::u32: return ply_raw<std::uint32_t, Swap>(p);
        default: {
            const double d = ply_load<Swap>(t, p);
            return d >= -9.0e18 && d <= 9.0e18 ? static_cast<long long>(d) : -1;
        }
    }
}

/// Where the vertex element keeps what we read.
struct ply_vertex_layout {
    std::array<int, 3> xyz{-1, -1, -1}, normal{-1, -1, -1};
    std::array<int, 4> color{-1, -1, -1, -1};
    bool has_normals() const { return normal[0] >= 0 && normal[1] >= 0 && normal[2] >= 0; }
    bool has_colors() const { return color[0] >= 0 && color[1] >= 0 && color[2] >= 0; }
};

inline ply_vertex_layout ply_layout(const ply_element& e) {
    ply_vertex_layout l;
    l.xyz = {e.find({"x"}), e.find({"y"}), e.find({"z"})};
    l.normal = {e.find({"nx"}), e.find({"ny"}), e.find({"nz"})};
    l.color = {e.find({"red", "r", "diffuse_red"}), e.find({"green", "g", "diffuse_green"}),
               e.find({"blue", "b", "diffuse_blue"}), e.find({"alpha", "a"})};
    return l;
}

/// A colour channel: integer types must hold 0..255, float types 0..1 (else nothing).
inline std::optional<std::uint8_t> ply_color_byte(ply_type t, double v) { return color_channel(v, ply_is_integer(t)); }

/// "channel red is 300, outside 0..255", for the messages.
inline std::string ply_bad_color(const ply_property& p, double v) {
    return "colour channel " + p.name + " is " + number_text(v) + ", outside " +
           (ply_is_integer(p.type) ? "0..255" : "0..1");
}

/// The vertex properties the reader keeps must be single values, not lists.
inline result<void> ply_check_vertex_scalars(const ply_element& e, const ply_vertex_layout& l,
                                             const std::string& name) {
    auto check = [&](int prop) -> result<void> {
        if (prop >= 0 && e.props[static_cast<std::size_t>(prop)].is_list())
            return fail(errc::unsupported, name + ":" + std::to_string(e.line) + ": vertex property " +
                                               e.props[static_cast<std::size_t>(prop)].name +
                                               " is a list; positions, normals and colours must be single values");
        return {};
    };
    for (int prop : l.xyz)
        if (auto r = check(prop); !r) return r;
    for (int prop : l.normal)
        if (auto r = check(prop); !r) return r;
    for (int prop : l.color)
        if (auto r = check(prop); !r) return r;
    return {};
}

inline int ply_face_list(const ply_element& e) {
    int i = e.find({"vertex_indices", "vertex_index"});
    if (i >= 0 && e.props[static_cast<std::size_t>(i)].is_list()) return i;
    for (std::size_t k = 0; k < e.props.size(); ++k)
        if (e.props[k].is_list()) return static_cast<int>(k);
    return -1;
}

/// A point of the soup's type (std::array<double, 3>, or a mesh's vec3) from three values.
template <class P>
P ply_point(double x, double y, double z) {
    using S = std::remove_cvref_t<decltype(std::declval<P&>()[0])>;
    return P{static_cast<S>(x), static_cast<S>(y), static_cast<S>(z)};
}

struct ply_binary_reader {
    std::string_view text;
    const std::string& name;
    std::size_t pos;

    std::string at(std::size_t offset) const { return name + ": byte offset " + std::to_string(offset); }
    hmira::error truncated(const ply_element& e, std::uint64_t item) const {
        return fail(errc::parse_error,
                    at(pos) + ": file ends inside " + e.name + " " + std::to_string(item) + " of " +
                        std::to_string(e.count) + " (truncated file, or a count in the header too large)",
                    static_cast<long long>(item));
    }
    std::size_t left() const { return text.size() - pos; }
    hmira::error not_finite(std::size_t offset, const char* what, std::size_t item) const {
        return fail(errc::parse_error,
                    at(offset) + ": " + what + " " + std::to_string(item) + " is not finite (NaN or infinity)",
                    static_cast<long long>(item));
    }
};

/// Byte offset, inside one vertex item, of each property the reader keeps: x y z at 0..2,
/// nx ny nz at 3..5, red green blue alpha at 6..9 (0 for a property the element lacks).
inline std::array<std::size_t, 12> ply_vertex_offsets(const ply_element& e, const ply_vertex_layout& l) {
    std::array<std::size_t, 12> off{};
    std::size_t o = 0;
    std::vector<std::size_t> offsets;
    for (const auto& p : e.props) {
        offsets.push_back(o);
        o += ply_size(p.type);
    }
    auto set = [&](std::size_t slot, int prop) { off[slot] = prop >= 0 ? offsets[static_cast<std::size_t>(prop)] : 0; };
    for (std::size_t k = 0; k < 3; ++k) set(k, l.xyz[k]), set(3 + k, l.normal[k]);
    for (std::size_t k = 0; k < 4; ++k) set(6 + k, l.color[k]);
    return off;
}

/// The positions of the n items of a fixed-stride vertex element starting at r.pos. Appended
/// into reserved room rather than resized and overwritten: no pass that zeroes them first.
template <bool Swap, class Soup>
result<void> ply_read_binary_positions(const ply_element& e, const ply_vertex_layout& l,
                                       const std::array<std::size_t, 12>& off, std::size_t stride, Soup& soup,
                                       const ply_binary_reader& r) {
    using point_type = typename decltype(soup.points)::value_type;
    auto type = [&](int prop) { return e.props[static_cast<std::size_t>(prop)].type; };
    const std::size_t n = static_cast<std::size_t>(e.count);
    soup.points.clear();
    hmira::detail::reserve_huge(soup.points, n);
    const char* base = r.text.data() + r.pos;
    const bool float_xyz =
        type(l.xyz[0]) == ply_type::f32 && type(l.xyz[1]) == ply_type::f32 && type(l.xyz[2]) == ply_type::f32;
    if (float_xyz) {
        for (std::size_t i = 0; i < n; ++i) {
            const char* item = base + i * stride;
            soup.points.push_back(ply_point<point_type>(ply_raw<float, Swap>(item + off[0]),
                                                        ply_raw<float, Swap>(item + off[1]),
                                                        ply_raw<float, Swap>(item + off[2])));
            if (!all_finite(soup.points.back())) return r.not_finite(r.pos + i * stride, "vertex", i);
        }
    } else {
        for (std::size_t i = 0; i < n; ++i) {
            const char* item = base + i * stride;
            soup.points.push_back(ply_point<point_type>(ply_load<Swap>(type(l.xyz[0]), item + off[0]),
                                                        ply_load<Swap>(type(l.xyz[1]), item + off[1]),
                                                        ply_load<Swap>(type(l.xyz[2]), item + off[2])));
            if (!all_finite(soup.points.back())) return r.not_finite(r.pos + i * stride, "vertex", i);
        }
    }
    return {};
}

/// The normals of the vertex element starting at r.pos (the layout has all three).
template <bool Swap, class Soup>
result<void> ply_read_binary_normals(const ply_element& e, const ply_vertex_layout& l,
                                     const std::array<std::size_t, 12>& off, std::size_t stride, Soup& soup,
                                     const ply_binary_reader& r) {
    auto type = [&](int prop) { return e.props[static_cast<std::size_t>(prop)].type; };
    const std::size_t n = static_cast<std::size_t>(e.count);
    const char* base = r.text.data() + r.pos;
    soup.attributes.normals.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const char* item = base + i * stride;
        for (std::size_t k = 0; k < 3; ++k)
            soup.attributes.normals[i][k] = static_cast<float>(ply_load<Swap>(type(l.normal[k]), item + off[3 + k]));
        if (!all_finite(soup.attributes.normals[i])) return r.not_finite(r.pos + i * stride, "normal of vertex", i);
    }
    return {};
}

/// The colours of the vertex element starting at r.pos (the layout has red, green and blue;
/// a missing alpha reads as 255).
template <bool Swap, class Soup>
result<void> ply_read_binary_colors(const ply_element& e, const ply_vertex_layout& l,
                                    const std::array<std::size_t, 12>& off, std::size_t stride, Soup& soup,
                                    const ply_binary_reader& r) {
    auto type = [&](int prop) { return e.props[static_cast<std::size_t>(prop)].type; };
    const std::size_t n = static_cast<std::size_t>(e.count);
    const char* base = r.text.data() + r.pos;
    soup.attributes.colors.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const char* item = base + i * stride;
        auto& c = soup.attributes.colors[i];
        for (std::size_t k = 0; k < 4; ++k) {
            if (l.color[k] < 0) {
                c[k] = 255;
                continue;
            }
            const double v = ply_load<Swap>(type(l.color[k]), item + off[6 + k]);
            const auto byte = ply_color_byte(type(l.color[k]), v);
            if (!byte)
                return fail(errc::parse_error,
                            r.at(r.pos + i * stride + off[6 + k]) + ": vertex " + std::to_string(i) + ": " +
                                ply_bad_color(e.props[static_cast<std::size_t>(l.color[k])], v),
                            static_cast<long long>(i));
            c[k] = *byte;
        }
    }
    return {};
}

/// The vertex element (fixed stride `stride`, which fits in what is left): positions, and
/// normals and colours when it has them; moves r.pos past it.
template <bool Swap, class Soup>
result<void> ply_read_binary_vertices(const ply_element& e, std::size_t stride, Soup& soup, ply_binary_reader& r) {
    const auto l = ply_layout(e);
    if (e.count > 0 && (l.xyz[0] < 0 || l.xyz[1] < 0 || l.xyz[2] < 0))
        return fail(errc::parse_error,
                    r.name + ":" + std::to_string(e.line) + ": the vertex element has no x, y and z properties");
    if (stride == 0)
        return fail(errc::unsupported, r.name + ":" + std::to_string(e.line) +
                                           ": list properties in the vertex element are not supported");
    const auto off = ply_vertex_offsets(e, l);
    if (auto ok = ply_read_binary_positions<Swap>(e, l, off, stride, soup, r); !ok) return ok;
    if (l.has_normals())
        if (auto ok = ply_read_binary_normals<Swap>(e, l, off, stride, soup, r); !ok) return ok;
    if (l.has_colors())
        if (auto ok = ply_read_binary_colors<Swap>(e, l, off, stride, soup, r); !ok) return ok;
    r.pos += static_cast<std::size_t>(e.count) * stride;
    return {};
}

/// Face f in the common layout (its only property "list uchar int" or "list uchar uint"),
/// without a type switch; moves r.pos past it.
template <bool Swap, class Soup>
result<void> ply_read_binary_face_fast(const ply_element& e, const ply_property& lp, std::uint64_t f, std::uint64_t nv,
                                       Soup& soup, ply_binary_reader& r) {
    using index_type = typename decltype(soup.indices)::value_type;
    const char* data = r.text.data();
    if (r.left() < 1) return r.truncated(e, f);
    const std::size_t k = static_cast<std::uint8_t>(data[r.pos]);
    if (r.left() < 1 + 4 * k) return r.truncated(e, f);
    if (k < 3)
        return fail(
            errc::degenerate_face,
            r.at(r.pos) + ": face " + std::to_string(f) + " has " + std::to_string(k) + " vertices; at least 3 needed",
            static_cast<long long>(f));
    const char* q = data + r.pos + 1;
    for (std::size_t j = 0; j < k; ++j) {
        const std::uint32_t idx = ply_raw<std::uint32_t, Swap>(q + 4 * j);
        if (idx >= nv)
            return fail(
                errc::parse_error,
                r.at(r.pos + 1 + 4 * j) + ": face " + std::to_string(f) + " uses vertex " +
                    std::to_string(lp.type == ply_type::i32 ? static_cast<long long>(static_cast<std::int32_t>(idx))
                                                            : static_cast<long long>(idx)) +
                    ", out of range [0, " + std::to_string(nv) + ")",
                static_cast<long long>(f));
        soup.indices.push_back(index_type(idx));
    }
    r.pos += 1 + 4 * k;
    soup.face_offsets.push_back(soup.indices.size());
    return {};
}

/// Face f in any layout: every property stepped over except the vertex list (property `list`),
/// whose indices are kept; moves r.pos past it.
template <bool Swap, class Soup>
result<void> ply_read_binary_face(const ply_element& e, int list, std::uint64_t f, std::uint64_t nv, Soup& soup,
                                  ply_binary_reader& r) {
    using index_type = typename decltype(soup.indices)::value_type;
    const char* data = r.text.data();
    for (std::size_t pi = 0; pi < e.props.size(); ++pi) {
        const auto& p = e.props[pi];
        if (!p.is_list()) {
            if (r.left() < ply_size(p.type)) return r.truncated(e, f);
            r.pos += ply_size(p.type);
            continue;
        }
        const std::size_t cs = ply_size(p.count_type), is = ply_size(p.type);
        if (r.left() < cs) return r.truncated(e, f);
        const long long k = ply_load_int<Swap>(p.count_type, data + r.pos);
        if (k < 0)
            return fail(errc::parse_error, r.at(r.pos) + ": face " + std::to_string(f) + " has a negative list length",
                        static_cast<long long>(f));
        const std::size_t count_at = r.pos;
        r.pos += cs;
        if (static_cast<unsigned long long>(k) > r.left() / is) return r.truncated(e, f);
        if (static_cast<int>(pi) == list) {
            if (k < 3)
                return fail(errc::degenerate_face,
                            r.at(count_at) + ": face " + std::to_string(f) + " has " + std::to_string(k) +
                                " vertices; at least 3 needed",
                            static_cast<long long>(f));
            for (long long j = 0; j < k; ++j) {
                const long long idx = ply_load_int<Swap>(p.type, data + r.pos + static_cast<std::size_t>(j) * is);
                if (idx < 0 || static_cast<std::uint64_t>(idx) >= nv)
                    return fail(errc::parse_error,
                                r.at(r.pos + static_cast<std::size_t>(j) * is) + ": face " + std::to_string(f) +
                                    " uses vertex " + std::to_string(idx) + ", out of range [0, " + std::to_string(nv) +
                                    ")",
                                static_cast<long long>(f));
                soup.indices.push_back(index_type(static_cast<std::uint32_t>(idx)));
            }
            soup.face_offsets.push_back(soup.indices.size());
        }
        r.pos += static_cast<std::size_t>(k) * is;
    }
    return {};
}

/// The face element, its indices checked against the nv vertices; moves r.pos past it.
template <bool Swap, class Soup>
result<void> ply_read_binary_faces(const ply_element& e, std::uint64_t nv, Soup& soup, ply_binary_reader& r,
                                   progress_ticker& ticker) {
    const int list = ply_face_list(e);
    if (list < 0 && e.count > 0)
        return fail(errc::parse_error,
                    r.name + ":" + std::to_string(e.line) + ": the face element has no vertex_indices list");
    const auto& lp = e.props[static_cast<std::size_t>(std::max(list, 0))];
    if (list >= 0 && !ply_is_integer(lp.type))
        return fail(errc::parse_error,
                    r.name + ":" + std::to_string(e.line) + ": vertex_indices must have an integer type");
    hmira::detail::reserve_huge(soup.face_offsets,
                                static_cast<std::size_t>(std::min<std::uint64_t>(e.count, r.left())) + 1);
    hmira::detail::reserve_huge(soup.indices, static_cast<std::size_t>(std::min<std::uint64_t>(e.count * 3, r.left())));
    const bool fast =
        e.props.size() == 1 && lp.count_type == ply_type::u8 && (lp.type == ply_type::i32 || lp.type == ply_type::u32);
    for (std::uint64_t f = 0; f < e.count; ++f) {
        auto ok = fast ? ply_read_binary_face_fast<Swap>(e, lp, f, nv, soup, r)
                       : ply_read_binary_face<Swap>(e, list, f, nv, soup, r);
        if (!ok) return ok;
        if ((f & 0xffff) == 0 && !ticker.tick(r.pos)) return progress_ticker::cancelled(r.at(r.pos));
    }
    return {};
}

/// Steps over an element the reader does not keep.
template <bool Swap>
result<void> ply_skip_binary_element(const ply_element& e, std::size_t stride, ply_binary_reader& r) {
    if (stride > 0) {
        r.pos += static_cast<std::size_t>(e.count) * stride;
        return {};
    }
    const char* data = r.text.data();
    for (std::uint64_t i = 0; i < e.count; ++i)
        for (const auto& p : e.props) {
            if (!p.is_list()) {
                if (r.left() < ply_size(p.type)) return r.truncated(e, i);
                r.pos += ply_size(p.type);
                continue;
            }
            if (r.left() < ply_size(p.count_type)) return r.truncated(e, i);
            const long long k = ply_load_int<Swap>(p.count_type, data + r.pos);
            r.pos += ply_size(p.count_type);
            if (k < 0 || static_cast<unsigned long long>(k) > r.left() / ply_size(p.type)) return r.truncated(e, i);
            r.pos += static_cast<std::size_t>(k) * ply_size(p.type);
        }
    return {};
}

/// Binary data (byte order swapped when Swap) after the header, element by element.
template <bool Swap, class Soup>
result<void> ply_read_binary(const ply_header& h, Soup& soup, ply_binary_reader& r, const read_options& options) {
    std::uint64_t nv = 0;
    for (const auto& e : h.elements)
        if (e.name == "vertex") nv = e.count;
    progress_ticker ticker(options.progress, r.text.size());
    for (const auto& e : h.elements) {
        const std::size_t stride = e.fixed_stride();
        if (stride > 0 && e.count > r.left() / stride) {
            // Find the first item that does not fit, for the message.
            const std::uint64_t fits = r.left() / stride;
            r.pos += static_cast<std::size_t>(fits) * stride;
            return r.truncated(e, fits);
        }
        // Nothing stored (a huge count costs nothing); a vertex element must still have x, y, z.
        if (e.count == 0 || (e.props.empty() && e.name != "vertex")) continue;
        auto ok = e.name == "vertex" ? ply_read_binary_vertices<Swap>(e, stride, soup, r)
                  : e.name == "face" ? ply_read_binary_faces<Swap>(e, nv, soup, r, ticker)
                                     : ply_skip_binary_element<Swap>(e, stride, r);
        if (!ok) return ok;
    }
    if (r.pos != r.text.size())
        return fail(errc::parse_error, r.at(r.pos) + ": " + std::to_string(r.text.size() - r.pos) +
                                           " bytes after the last element (a count in the header too small?)");
    ticker.finish();
    return {};
}

template <class Soup>
result<void> ply_read_ascii(const ply_header& h, Soup& soup, std::string_view text, const std::string& name,
                            const read_options& options) {
    using index_type = typename decltype(soup.indices)::value_type;
    using point_type = typename decltype(soup.points)::value_type;
    text_cursor c(text.substr(h.data_offset));
    progress_ticker ticker(options.progress, text.size());
    const std::size_t line0 = h.data_line;
    auto where = [&] { return name + ":" + std::to_string(line0 + c.line() - 1); };
    std::uint64_t nv = 0;
    for (const auto& e : h.elements)
        if (e.name == "vertex") nv = e.count;
    std::vector<double> values;
    for (const auto& e : h.elements) {
        const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
        ply_vertex_layout l;
        int list = -1;
        if (is_vertex) {
            l = ply_layout(e);
            if (e.count > 0 && (l.xyz[0] < 0 || l.xyz[1] < 0 || l.xyz[2] < 0))
                return fail(errc::parse_error,
                            name + ":" + std::to_string(e.line) + ": the vertex element has no x, y and z properties");
            if (auto r = ply_check_vertex_scalars(e, l, name); !r) return r.error();
            hmira::detail::reserve_huge(
                soup.points, static_cast<std::size_t>(std::min<std::uint64_t>(e.count, text.size() / 6 + 1)));
        }
        if (is_face) {
            list = ply_face_list(e);
            if (list < 0 && e.count > 0)
                return fail(errc::parse_error,
                            name + ":" + std::to_string(e.line) + ": the face element has no vertex_indices list");
        }
        values.resize(e.props.size());
        for (std::uint64_t i = 0; i < e.count; ++i) {
            c.skip_space_and_newlines();
            if (c.at_end())
                return fail(errc::parse_error, where() + ": file ends after " + std::to_string(i) + " of " +
                                                   std::to_string(e.count) + " " + e.name +
                                                   " lines (truncated file, or a count in the header too large)");
            const std::size_t face_start = soup.indices.size();
            for (std::size_t pi = 0; pi < e.props.size(); ++pi) {
                const auto& p = e.props[pi];
                if (!p.is_list()) {
                    if (!c.number(values[pi]))
                        return fail(errc::parse_error, where() + ": " + e.name + " " + std::to_string(i) +
                                                           ", property " + p.name + ": " + describe_bad_number(c));
                    continue;
                }
                long long k = 0;
                if (!c.number(k) || k < 0)
                    return fail(errc::parse_error, where() + ": " + e.name + " " + std::to_string(i) + ": " +
                                                       describe_bad_number(c) + " (expected a list length)");
                const bool keep = is_face && static_cast<int>(pi) == list;
                if (keep && k < 3)
                    return fail(errc::degenerate_face, where() + ": face " + std::to_string(i) + " has " +
                                                           std::to_string(k) + " vertices; at least 3 needed");
                for (long long j = 0; j < k; ++j) {
                    if (keep && ply_is_integer(p.type)) {
                        long long idx = 0;
                        if (!c.number(idx))
                            return fail(errc::parse_error, where() + ": face " + std::to_string(i) + ": " +
                                                               describe_bad_number(c) + " (expected a vertex index)");
                        if (idx < 0 || static_cast<std::uint64_t>(idx) >= nv)
                            return fail(errc::parse_error, where() + ": face " + std::to_string(i) + " uses vertex " +
                                                               std::to_string(idx) + ", out of range [0, " +
                                                               std::to_string(nv) + ")");
                        soup.indices.push_back(index_type(static_cast<std::uint32_t>(idx)));
                    } else {
                        double x = 0;
                        if (!c.number(x))
                            return fail(errc::parse_error, where() + ": " + e.name + " " + std::to_string(i) + ": " +
                                                               describe_bad_number(c));
                        if (keep)
                            return fail(errc::parse_error, where() + ": vertex_indices must have an integer type");
                    }
                }
            }
            if (!c.at_line_end())
                return fail(errc::parse_error, where() + ": " + e.name + " " + std::to_string(i) +
                                                   " has more values than its " + std::to_string(e.props.size()) +
                                                   " properties ('" + std::string(c.peek_token()) + "')");
            if (is_vertex) {
                soup.points.push_back(ply_point<point_type>(values[static_cast<std::size_t>(l.xyz[0])],
                                                            values[static_cast<std::size_t>(l.xyz[1])],
                                                            values[static_cast<std::size_t>(l.xyz[2])]));
                if (!all_finite(soup.points.back()))
                    return fail(errc::parse_error,
                                where() + ": vertex " + std::to_string(i) +
                                    " has a coordinate that is not finite (NaN or infinity)",
                                static_cast<long long>(i));
                if (l.has_normals()) {
                    soup.attributes.normals.push_back(
                        {static_cast<float>(values[static_cast<std::size_t>(l.normal[0])]),
                         static_cast<float>(values[static_cast<std::size_t>(l.normal[1])]),
                         static_cast<float>(values[static_cast<std::size_t>(l.normal[2])])});
                    if (!all_finite(soup.attributes.normals.back()))
                        return fail(
                            errc::parse_error,
                            where() + ": normal of vertex " + std::to_string(i) + " is not finite (NaN or infinity)",
                            static_cast<long long>(i));
                }
                if (l.has_colors()) {
                    std::array<std::uint8_t, 4> col{255, 255, 255, 255};
                    for (std::size_t k = 0; k < 4; ++k) {
                        if (l.color[k] < 0) continue;
                        const auto& p = e.props[static_cast<std::size_t>(l.color[k])];
                        const double v = values[static_cast<std::size_t>(l.color[k])];
                        const auto byte = ply_color_byte(p.type, v);
                        if (!byte)
                            return fail(errc::parse_error,
                                        where() + ": vertex " + std::to_string(i) + ": " + ply_bad_color(p, v),
                                        static_cast<long long>(i));
                        col[k] = *byte;
                    }
                    soup.attributes.colors.push_back(col);
                }
            }
            if (is_face && list >= 0 && soup.indices.size() > face_start)
                soup.face_offsets.push_back(soup.indices.size());
            c.next_line();
            if (!ticker.tick(h.data_offset + c.offset()))
                return progress_ticker::cancelled(name + ":" + std::to_string(c.line()));
        }
    }
    c.skip_space_and_newlines();
    if (!c.at_end())
        return fail(errc::parse_error,
                    where() + ": unexpected content after the last element (a count in the header too small?)");
    ticker.finish();
    return {};
}

/// The data after a parsed header into `soup`: a polygon_soup, or a mesh_soup of a mesh's own
/// types (read_ply into a model that takes its arrays whole).
template <class Soup>
result<void> parse_ply_into(Soup& soup, const ply_header& h, std::string_view text, const std::string& name,
                            const read_options& options) {
    if (h.encoding == ply_encoding::ascii) return ply_read_ascii(h, soup, text, name, options);
    ply_binary_reader reader{text, name, h.data_offset};
    constexpr bool little_host = std::endian::native == std::endian::little;
    const bool swap = (h.encoding == ply_encoding::binary_little_endian) != little_host;
    return swap ? ply_read_binary<true>(h, soup, reader, options) : ply_read_binary<false>(h, soup, reader, options);
}

}  // namespace hmira::io::detail
