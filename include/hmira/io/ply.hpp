// hmira/io/ply.hpp
// Stanford PLY in all three encodings (ASCII, binary little and big endian): positions,
// polygonal faces, per-vertex normals (nx ny nz) and colours (red green blue [alpha]). Other
// elements and properties are skipped, so files from scanners and other tools load as well.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

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

enum class ply_type : std::uint8_t { invalid, i8, u8, i16, u16, i32, u32, f32, f64 };

inline ply_type ply_type_from(std::string_view s) {
    if (s == "char" || s == "int8") return ply_type::i8;
    if (s == "uchar" || s == "uint8") return ply_type::u8;
    if (s == "short" || s == "int16") return ply_type::i16;
    if (s == "ushort" || s == "uint16") return ply_type::u16;
    if (s == "int" || s == "int32") return ply_type::i32;
    if (s == "uint" || s == "uint32") return ply_type::u32;
    if (s == "float" || s == "float32") return ply_type::f32;
    if (s == "double" || s == "float64") return ply_type::f64;
    return ply_type::invalid;
}

inline std::size_t ply_size(ply_type t) {
    switch (t) {
        case ply_type::i8: case ply_type::u8: return 1;
        case ply_type::i16: case ply_type::u16: return 2;
        case ply_type::i32: case ply_type::u32: case ply_type::f32: return 4;
        case ply_type::f64: return 8;
        default: return 0;
    }
}

inline bool ply_is_integer(ply_type t) { return t != ply_type::f32 && t != ply_type::f64; }

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
        if (!lines.next(line)) return fail(errc::parse_error, where() + ": file ends inside the header (no 'end_header')");
        std::string_view rest = line;
        const auto key = next_token(rest);
        if (key.empty() || key == "comment" || key == "obj_info") continue;
        if (key == "format") {
            const auto enc = next_token(rest);
            if (enc == "ascii") h.encoding = ply_encoding::ascii;
            else if (enc == "binary_little_endian") h.encoding = ply_encoding::binary_little_endian;
            else if (enc == "binary_big_endian") h.encoding = ply_encoding::binary_big_endian;
            else return fail(errc::parse_error, where() + ": unknown PLY format '" + std::string(enc) + "'");
            have_format = true;
        } else if (key == "element") {
            ply_element e;
            e.name = std::string(next_token(rest));
            long long n = 0;
            const auto count = next_token(rest);
            if (e.name.empty() || !parse_long(count, n) || n < 0)
                return fail(errc::parse_error, where() + ": expected 'element <name> <count>', found '" + std::string(line) + "'");
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
                    return fail(errc::parse_error, where() + ": bad list property types '" + std::string(ct) + " " + std::string(it) + "'");
            } else {
                p.type = ply_type_from(t);
                if (p.type == ply_type::invalid) return fail(errc::parse_error, where() + ": unknown property type '" + std::string(t) + "'");
            }
            p.name = std::string(next_token(rest));
            if (p.name.empty()) return fail(errc::parse_error, where() + ": property without a name");
            h.elements.back().props.push_back(std::move(p));
        } else if (key == "end_header") {
            if (!next_token(rest).empty()) return fail(errc::parse_error, where() + ": unexpected text after 'end_header' on its line");
            break;
        } else {
            return fail(errc::parse_error, where() + ": unexpected header line '" + std::string(line.substr(0, 60)) + "'");
        }
    }
    if (!have_format) return fail(errc::parse_error, name + ": PLY header has no 'format' line");
    h.data_offset = lines.position();
    h.data_line = lines.line_number() + 1;
    return h;
}

template <class U>
U ply_swap(U v) {
    if constexpr (sizeof(U) == 2) return static_cast<U>(__builtin_bswap16(static_cast<std::uint16_t>(v)));
    else if constexpr (sizeof(U) == 4) return static_cast<U>(__builtin_bswap32(static_cast<std::uint32_t>(v)));
    else if constexpr (sizeof(U) == 8) return static_cast<U>(__builtin_bswap64(static_cast<std::uint64_t>(v)));
    else return v;
}

template <class V, bool Swap>
V ply_raw(const char* p) {
    if constexpr (sizeof(V) == 1) {
        V v;
        std::memcpy(&v, p, 1);
        return v;
    } else {
        using U = std::conditional_t<sizeof(V) == 2, std::uint16_t, std::conditional_t<sizeof(V) == 4, std::uint32_t, std::uint64_t>>;
        U u;
        std::memcpy(&u, p, sizeof u);
        if constexpr (Swap) u = ply_swap(u);
        V v;
        std::memcpy(&v, &u, sizeof v);
        return v;
    }
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
    l.color = {e.find({"red", "r", "diffuse_red"}), e.find({"green", "g", "diffuse_green"}), e.find({"blue", "b", "diffuse_blue"}),
               e.find({"alpha", "a"})};
    return l;
}

/// A colour channel: integer types must hold 0..255, float types 0..1 (else nothing).
inline std::optional<std::uint8_t> ply_color_byte(ply_type t, double v) { return color_channel(v, ply_is_integer(t)); }

/// "channel red is 300, outside 0..255", for the messages.
inline std::string ply_bad_color(const ply_property& p, double v) {
    return "colour channel " + p.name + " is " + number_text(v) + ", outside " + (ply_is_integer(p.type) ? "0..255" : "0..1");
}

/// The vertex properties the reader keeps must be single values, not lists.
inline result<void> ply_check_vertex_scalars(const ply_element& e, const ply_vertex_layout& l, const std::string& name) {
    auto check = [&](int prop) -> result<void> {
        if (prop >= 0 && e.props[static_cast<std::size_t>(prop)].is_list())
            return fail(errc::unsupported, name + ":" + std::to_string(e.line) + ": vertex property " + e.props[static_cast<std::size_t>(prop)].name +
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
        return fail(errc::parse_error, at(pos) + ": file ends inside " + e.name + " " + std::to_string(item) + " of " + std::to_string(e.count) +
                                           " (truncated file, or a count in the header too large)", static_cast<long long>(item));
    }
    std::size_t left() const { return text.size() - pos; }
    hmira::error not_finite(std::size_t offset, const char* what, std::size_t item) const {
        return fail(errc::parse_error, at(offset) + ": " + what + " " + std::to_string(item) + " is not finite (NaN or infinity)", static_cast<long long>(item));
    }
};

template <bool Swap, class Soup>
result<void> ply_read_binary(const ply_header& h, Soup& soup, ply_binary_reader& r, const read_options& options) {
    using index_type = typename decltype(soup.indices)::value_type;
    using point_type = typename decltype(soup.points)::value_type;
    const char* data = r.text.data();
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
        if (e.name == "vertex") {
            const auto l = ply_layout(e);
            if (e.count > 0 && (l.xyz[0] < 0 || l.xyz[1] < 0 || l.xyz[2] < 0))
                return fail(errc::parse_error, r.name + ":" + std::to_string(e.line) + ": the vertex element has no x, y and z properties");
            if (stride == 0) return fail(errc::unsupported, r.name + ":" + std::to_string(e.line) + ": list properties in the vertex element are not supported");
            std::array<std::size_t, 12> off{};
            {
                std::size_t o = 0;
                std::vector<std::size_t> offsets;
                for (const auto& p : e.props) {
                    offsets.push_back(o);
                    o += ply_size(p.type);
                }
                auto set = [&](std::size_t slot, int prop) { off[slot] = prop >= 0 ? offsets[static_cast<std::size_t>(prop)] : 0; };
                for (std::size_t k = 0; k < 3; ++k) set(k, l.xyz[k]), set(3 + k, l.normal[k]);
                for (std::size_t k = 0; k < 4; ++k) set(6 + k, l.color[k]);
            }
            auto type = [&](int prop) { return e.props[static_cast<std::size_t>(prop)].type; };
            const std::size_t n = static_cast<std::size_t>(e.count);
            // Appended into reserved room rather than resized and overwritten: no pass that
            // zeroes the positions first.
            soup.points.clear();
            hmira::detail::reserve_huge(soup.points, n);
            const char* base = data + r.pos;
            const bool float_xyz = type(l.xyz[0]) == ply_type::f32 && type(l.xyz[1]) == ply_type::f32 && type(l.xyz[2]) == ply_type::f32;
            if (float_xyz) {
                for (std::size_t i = 0; i < n; ++i) {
                    const char* item = base + i * stride;
                    soup.points.push_back(ply_point<point_type>(ply_raw<float, Swap>(item + off[0]), ply_raw<float, Swap>(item + off[1]), ply_raw<float, Swap>(item + off[2])));
                    if (!all_finite(soup.points.back())) return r.not_finite(r.pos + i * stride, "vertex", i);
                }
            } else {
                for (std::size_t i = 0; i < n; ++i) {
                    const char* item = base + i * stride;
                    soup.points.push_back(ply_point<point_type>(ply_load<Swap>(type(l.xyz[0]), item + off[0]), ply_load<Swap>(type(l.xyz[1]), item + off[1]),
                                                                ply_load<Swap>(type(l.xyz[2]), item + off[2])));
                    if (!all_finite(soup.points.back())) return r.not_finite(r.pos + i * stride, "vertex", i);
                }
            }
            if (l.has_normals()) {
                soup.attributes.normals.resize(n);
                for (std::size_t i = 0; i < n; ++i) {
                    const char* item = base + i * stride;
                    for (std::size_t k = 0; k < 3; ++k) soup.attributes.normals[i][k] = static_cast<float>(ply_load<Swap>(type(l.normal[k]), item + off[3 + k]));
                    if (!all_finite(soup.attributes.normals[i])) return r.not_finite(r.pos + i * stride, "normal of vertex", i);
                }
            }
            if (l.has_colors()) {
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
                            return fail(errc::parse_error, r.at(r.pos + i * stride + off[6 + k]) + ": vertex " + std::to_string(i) + ": " +
                                                               ply_bad_color(e.props[static_cast<std::size_t>(l.color[k])], v), static_cast<long long>(i));
                        c[k] = *byte;
                    }
                }
            }
            r.pos += n * stride;
        } else if (e.name == "face") {
            const int list = ply_face_list(e);
            if (list < 0 && e.count > 0) return fail(errc::parse_error, r.name + ":" + std::to_string(e.line) + ": the face element has no vertex_indices list");
            const auto& lp = e.props[static_cast<std::size_t>(std::max(list, 0))];
            if (list >= 0 && !ply_is_integer(lp.type))
                return fail(errc::parse_error, r.name + ":" + std::to_string(e.line) + ": vertex_indices must have an integer type");
            hmira::detail::reserve_huge(soup.face_offsets, static_cast<std::size_t>(std::min<std::uint64_t>(e.count, r.left())) + 1);
            hmira::detail::reserve_huge(soup.indices, static_cast<std::size_t>(std::min<std::uint64_t>(e.count * 3, r.left())));
            const bool fast = e.props.size() == 1 && lp.count_type == ply_type::u8 && (lp.type == ply_type::i32 || lp.type == ply_type::u32);
            for (std::uint64_t f = 0; f < e.count; ++f) {
                if (fast) {
                    // The common layout (one "list uchar int" property) without a type switch.
                    if (r.left() < 1) return r.truncated(e, f);
                    const std::size_t k = static_cast<std::uint8_t>(data[r.pos]);
                    if (r.left() < 1 + 4 * k) return r.truncated(e, f);
                    if (k < 3)
                        return fail(errc::degenerate_face, r.at(r.pos) + ": face " + std::to_string(f) + " has " + std::to_string(k) + " vertices; at least 3 needed",
                                    static_cast<long long>(f));
                    const char* q = data + r.pos + 1;
                    for (std::size_t j = 0; j < k; ++j) {
                        const std::uint32_t idx = ply_raw<std::uint32_t, Swap>(q + 4 * j);
                        if (idx >= nv)
                            return fail(errc::parse_error, r.at(r.pos + 1 + 4 * j) + ": face " + std::to_string(f) + " uses vertex " +
                                                               std::to_string(lp.type == ply_type::i32 ? static_cast<long long>(static_cast<std::int32_t>(idx)) : static_cast<long long>(idx)) +
                                                               ", out of range [0, " + std::to_string(nv) + ")", static_cast<long long>(f));
                        soup.indices.push_back(index_type(idx));
                    }
                    r.pos += 1 + 4 * k;
                    soup.face_offsets.push_back(soup.indices.size());
                    if ((f & 0xffff) == 0 && !ticker.tick(r.pos)) return progress_ticker::cancelled(r.at(r.pos));
                    continue;
                }
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
                    if (k < 0) return fail(errc::parse_error, r.at(r.pos) + ": face " + std::to_string(f) + " has a negative list length", static_cast<long long>(f));
                    const std::size_t count_at = r.pos;
                    r.pos += cs;
                    if (static_cast<unsigned long long>(k) > r.left() / is) return r.truncated(e, f);
                    if (static_cast<int>(pi) == list) {
                        if (k < 3)
                            return fail(errc::degenerate_face, r.at(count_at) + ": face " + std::to_string(f) + " has " + std::to_string(k) + " vertices; at least 3 needed",
                                        static_cast<long long>(f));
                        for (long long j = 0; j < k; ++j) {
                            const long long idx = ply_load_int<Swap>(p.type, data + r.pos + static_cast<std::size_t>(j) * is);
                            if (idx < 0 || static_cast<std::uint64_t>(idx) >= nv)
                                return fail(errc::parse_error, r.at(r.pos + static_cast<std::size_t>(j) * is) + ": face " + std::to_string(f) + " uses vertex " +
                                                                   std::to_string(idx) + ", out of range [0, " + std::to_string(nv) + ")", static_cast<long long>(f));
                            soup.indices.push_back(index_type(static_cast<std::uint32_t>(idx)));
                        }
                        soup.face_offsets.push_back(soup.indices.size());
                    }
                    r.pos += static_cast<std::size_t>(k) * is;
                }
                if ((f & 0xffff) == 0 && !ticker.tick(r.pos)) return progress_ticker::cancelled(r.at(r.pos));
            }
        } else {
            // An element we do not keep: step over it.
            if (stride > 0) {
                r.pos += static_cast<std::size_t>(e.count) * stride;
                continue;
            }
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
        }
    }
    if (r.pos != r.text.size())
        return fail(errc::parse_error, r.at(r.pos) + ": " + std::to_string(r.text.size() - r.pos) +
                                           " bytes after the last element (a count in the header too small?)");
    ticker.finish();
    return {};
}

template <class Soup>
result<void> ply_read_ascii(const ply_header& h, Soup& soup, std::string_view text, const std::string& name, const read_options& options) {
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
                return fail(errc::parse_error, name + ":" + std::to_string(e.line) + ": the vertex element has no x, y and z properties");
            if (auto r = ply_check_vertex_scalars(e, l, name); !r) return r.error();
            hmira::detail::reserve_huge(soup.points, static_cast<std::size_t>(std::min<std::uint64_t>(e.count, text.size() / 6 + 1)));
        }
        if (is_face) {
            list = ply_face_list(e);
            if (list < 0 && e.count > 0) return fail(errc::parse_error, name + ":" + std::to_string(e.line) + ": the face element has no vertex_indices list");
        }
        values.resize(e.props.size());
        for (std::uint64_t i = 0; i < e.count; ++i) {
            c.skip_space_and_newlines();
            if (c.at_end())
                return fail(errc::parse_error, where() + ": file ends after " + std::to_string(i) + " of " + std::to_string(e.count) + " " + e.name +
                                                   " lines (truncated file, or a count in the header too large)");
            const std::size_t face_start = soup.indices.size();
            for (std::size_t pi = 0; pi < e.props.size(); ++pi) {
                const auto& p = e.props[pi];
                if (!p.is_list()) {
                    if (!c.number(values[pi]))
                        return fail(errc::parse_error, where() + ": " + e.name + " " + std::to_string(i) + ", property " + p.name + ": " + describe_bad_number(c));
                    continue;
                }
                long long k = 0;
                if (!c.number(k) || k < 0)
                    return fail(errc::parse_error, where() + ": " + e.name + " " + std::to_string(i) + ": " + describe_bad_number(c) + " (expected a list length)");
                const bool keep = is_face && static_cast<int>(pi) == list;
                if (keep && k < 3)
                    return fail(errc::degenerate_face, where() + ": face " + std::to_string(i) + " has " + std::to_string(k) + " vertices; at least 3 needed");
                for (long long j = 0; j < k; ++j) {
                    if (keep && ply_is_integer(p.type)) {
                        long long idx = 0;
                        if (!c.number(idx)) return fail(errc::parse_error, where() + ": face " + std::to_string(i) + ": " + describe_bad_number(c) + " (expected a vertex index)");
                        if (idx < 0 || static_cast<std::uint64_t>(idx) >= nv)
                            return fail(errc::parse_error, where() + ": face " + std::to_string(i) + " uses vertex " + std::to_string(idx) + ", out of range [0, " +
                                                               std::to_string(nv) + ")");
                        soup.indices.push_back(index_type(static_cast<std::uint32_t>(idx)));
                    } else {
                        double x = 0;
                        if (!c.number(x)) return fail(errc::parse_error, where() + ": " + e.name + " " + std::to_string(i) + ": " + describe_bad_number(c));
                        if (keep) return fail(errc::parse_error, where() + ": vertex_indices must have an integer type");
                    }
                }
            }
            if (!c.at_line_end())
                return fail(errc::parse_error, where() + ": " + e.name + " " + std::to_string(i) + " has more values than its " + std::to_string(e.props.size()) +
                                                   " properties ('" + std::string(c.peek_token()) + "')");
            if (is_vertex) {
                soup.points.push_back(ply_point<point_type>(values[static_cast<std::size_t>(l.xyz[0])], values[static_cast<std::size_t>(l.xyz[1])],
                                                           values[static_cast<std::size_t>(l.xyz[2])]));
                if (!all_finite(soup.points.back()))
                    return fail(errc::parse_error, where() + ": vertex " + std::to_string(i) + " has a coordinate that is not finite (NaN or infinity)", static_cast<long long>(i));
                if (l.has_normals()) {
                    soup.attributes.normals.push_back({static_cast<float>(values[static_cast<std::size_t>(l.normal[0])]), static_cast<float>(values[static_cast<std::size_t>(l.normal[1])]),
                                                       static_cast<float>(values[static_cast<std::size_t>(l.normal[2])])});
                    if (!all_finite(soup.attributes.normals.back()))
                        return fail(errc::parse_error, where() + ": normal of vertex " + std::to_string(i) + " is not finite (NaN or infinity)", static_cast<long long>(i));
                }
                if (l.has_colors()) {
                    std::array<std::uint8_t, 4> col{255, 255, 255, 255};
                    for (std::size_t k = 0; k < 4; ++k) {
                        if (l.color[k] < 0) continue;
                        const auto& p = e.props[static_cast<std::size_t>(l.color[k])];
                        const double v = values[static_cast<std::size_t>(l.color[k])];
                        const auto byte = ply_color_byte(p.type, v);
                        if (!byte) return fail(errc::parse_error, where() + ": vertex " + std::to_string(i) + ": " + ply_bad_color(p, v), static_cast<long long>(i));
                        col[k] = *byte;
                    }
                    soup.attributes.colors.push_back(col);
                }
            }
            if (is_face && list >= 0 && soup.indices.size() > face_start) soup.face_offsets.push_back(soup.indices.size());
            c.next_line();
            if (!ticker.tick(h.data_offset + c.offset()))
                return progress_ticker::cancelled(name + ":" + std::to_string(c.line()));
        }
    }
    c.skip_space_and_newlines();
    if (!c.at_end()) return fail(errc::parse_error, where() + ": unexpected content after the last element (a count in the header too small?)");
    ticker.finish();
    return {};
}

/// The data after a parsed header into `soup`: a polygon_soup, or a mesh_soup of a mesh's own
/// types (read_ply into a model that takes its arrays whole).
template <class Soup>
result<void> parse_ply_into(Soup& soup, const ply_header& h, std::string_view text, const std::string& name, const read_options& options) {
    if (h.encoding == ply_encoding::ascii) return ply_read_ascii(h, soup, text, name, options);
    ply_binary_reader reader{text, name, h.data_offset};
    constexpr bool little_host = std::endian::native == std::endian::little;
    const bool swap = (h.encoding == ply_encoding::binary_little_endian) != little_host;
    return swap ? ply_read_binary<true>(h, soup, reader, options) : ply_read_binary<false>(h, soup, reader, options);
}

}  // namespace detail

/// Parses PLY (any encoding) into a soup. Errors name `name:line` in the header and in ASCII
/// data, `name: byte offset N` and the element in binary data.
/// Complexity: O(bytes). Errors (errc::parse_error / degenerate_face / unsupported): a bad
/// header, truncated data, counts too large or too small, non-numbers, indices out of range,
/// faces of fewer than 3 vertices.
inline result<polygon_soup> parse_ply(std::string_view text, const std::string& name, const read_options& options = {}) {
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
/// validation pass, no copy; halfedge_mesh gets its positions so, when the file needs no repair. Complexity: O(bytes + mesh insertions).
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
        // takes over: no second copy of the file's content (issue 20).
        detail::mesh_soup<M, T> soup;
        if (auto r = detail::parse_ply_into(soup, *h, file->text(), path.string(), options); !r) return r.error();
        return detail::assign_own_arrays<M, T>(mesh, std::move(soup), path.string(), format);
    } else if constexpr (detail::assigns_own_positions<M, T>) {
        // halfedge_mesh: positions parsed into the mesh's own points, kept whole when the file
        // needs no repair (issue 20).
        detail::point_soup<typename M::point> soup;
        if (auto r = detail::parse_ply_into(soup, *h, file->text(), path.string(), options); !r) return r.error();
        return detail::build_from_point_soup<M, T>(mesh, std::move(soup), path.string(), format, options);
    }
    auto soup = parse_ply(file->text(), path.string(), options);
    if (!soup) return soup.error();
    return finish_read<M, T>(mesh, std::move(*soup), path.string(), format, 0, options);
}

namespace detail {

/// The PLY bytes of a mesh that refuse_unwritable accepted; false when the stream failed.
template <class M, class T>
bool put_ply(const M& mesh, std::ostream& stream, const write_options& options) {
    using S = typename T::scalar;
    detail::chunked_output out(stream);
    auto& b = out.buffer();
    const auto attr = detail::find_attributes<M, T>(mesh, options);
    const bool use_float = options.ply_coordinates == ply_scalar::float32 ||
                           (options.ply_coordinates == ply_scalar::mesh && sizeof(S) <= sizeof(float));
    std::size_t max_degree = 0;
    for (auto f : T::faces(mesh)) {
        std::size_t k = 0;
        for (auto v : T::face_vertices(mesh, f)) (void)v, ++k;
        max_degree = std::max(max_degree, k);
    }
    const bool wide_count = max_degree > 255;
    b += "ply\nformat ";
    b += options.ply == ply_encoding::ascii ? "ascii" : options.ply == ply_encoding::binary_little_endian ? "binary_little_endian" : "binary_big_endian";
    b += " 1.0\ncomment written by hmira\nelement vertex ";
    detail::append_number(b, std::uint64_t{T::vertex_count(mesh)});
    const char* ct = use_float ? "float" : "double";
    for (const char* axis : {"x", "y", "z"}) b += std::string("\nproperty ") + ct + " " + axis;
    if (attr.normals)
        for (const char* axis : {"nx", "ny", "nz"}) b += std::string("\nproperty float ") + axis;
    if (attr.colors)
        for (const char* ch : {"red", "green", "blue", "alpha"}) b += std::string("\nproperty uchar ") + ch;
    b += "\nelement face ";
    detail::append_number(b, std::uint64_t{T::face_count(mesh)});
    b += wide_count ? "\nproperty list uint int vertex_indices\nend_header\n" : "\nproperty list uchar int vertex_indices\nend_header\n";

    const bool ascii = options.ply == ply_encoding::ascii;
    const bool swap = (options.ply == ply_encoding::binary_little_endian) != (std::endian::native == std::endian::little);
    auto put = [&](auto value) {
        if (swap) {
            using V = decltype(value);
            using U = std::conditional_t<sizeof(V) == 1, std::uint8_t, std::conditional_t<sizeof(V) == 2, std::uint16_t, std::conditional_t<sizeof(V) == 4, std::uint32_t, std::uint64_t>>>;
            U u;
            std::memcpy(&u, &value, sizeof u);
            u = detail::ply_swap(u);
            b.append(reinterpret_cast<const char*>(&u), sizeof u);
        } else {
            b.append(reinterpret_cast<const char*>(&value), sizeof value);
        }
    };
    const auto number = detail::dense_vertex_numbers<M, T>(mesh);
    for (auto v : T::vertices(mesh)) {
        const auto p = static_cast<vec3<S>>(T::position(mesh, v));
        const auto vi = T::vertex_index(mesh, v);
        if (ascii) {
            for (std::size_t k = 0; k < 3; ++k) {
                if (k) b += ' ';
                if (use_float) detail::append_number(b, static_cast<float>(p[k]));
                else detail::append_number(b, static_cast<double>(p[k]));
            }
            if (attr.normals)
                for (std::size_t k = 0; k < 3; ++k) b += ' ', detail::append_number(b, attr.normals[vi][k]);
            if (attr.colors)
                for (std::size_t k = 0; k < 4; ++k) b += ' ', detail::append_number(b, std::uint64_t{attr.colors[vi][k]});
            b += '\n';
        } else {
            for (std::size_t k = 0; k < 3; ++k) {
                if (use_float) put(static_cast<float>(p[k]));
                else put(static_cast<double>(p[k]));
            }
            if (attr.normals)
                for (std::size_t k = 0; k < 3; ++k) put(attr.normals[vi][k]);
            if (attr.colors)
                for (std::size_t k = 0; k < 4; ++k) put(attr.colors[vi][k]);
        }
        if (!out.maybe_flush()) return false;
    }
    std::vector<std::uint32_t> loop;
    for (auto f : T::faces(mesh)) {
        loop.clear();
        for (auto v : T::face_vertices(mesh, f)) loop.push_back(number[T::vertex_index(mesh, v)]);
        if (ascii) {
            detail::append_number(b, std::uint64_t{loop.size()});
            for (auto i : loop) b += ' ', detail::append_number(b, i);
            b += '\n';
        } else {
            if (wide_count) put(static_cast<std::uint32_t>(loop.size()));
            else put(static_cast<std::uint8_t>(loop.size()));
            for (auto i : loop) put(static_cast<std::int32_t>(i));
        }
        if (!out.maybe_flush()) return false;
    }
    return out.flush();
}

}  // namespace detail

/// Writes PLY through `out` (an error, with nothing written, for a face with inner rings or a non-finite
/// coordinate; see write_ply) in the chosen encoding: x y z (the mesh's scalar type unless
/// options say otherwise), nx ny nz and red green blue alpha when there are attributes, and
/// faces as "list uchar int vertex_indices" ("list uint int" if a face has > 255 vertices).
template <class M, class T = default_traits<M>>
    requires writable_mesh<M, T>
result<void> write_ply_to(const M& mesh, std::ostream& stream, const write_options& options = {}) {
    // Before any byte is written.
    if (auto ok = detail::refuse_unwritable<M, T>(mesh, "PLY", options.ply_coordinates == ply_scalar::float32); !ok) return ok;
    if (!detail::put_ply<M, T>(mesh, stream, options)) return detail::stream_failed("PLY");
    return {};
}

/// PLY bytes of the mesh (see write_ply_to), or its error.
template <class M, class T = default_traits<M>>
    requires writable_mesh<M, T>
result<std::string> format_ply(const M& mesh, const write_options& options = {}) {
    std::ostringstream s;
    if (auto ok = write_ply_to<M, T>(mesh, s, options); !ok) return ok.error();
    return std::move(s).str();
}

/// Writes the mesh as PLY, atomically. Complexity O(V + C). Errors: errc::unsupported naming a
/// face with inner rings (PLY has one loop per face, and a ring is never dropped silently;
/// triangulate_faces first), or a vertex with a non-finite
/// coordinate, with no file written; errc::io_error.
template <class M, class T = default_traits<M>>
    requires writable_mesh<M, T>
result<void> write_ply(const M& mesh, const std::filesystem::path& path, const write_options& options = {}) {
    if (auto ok = detail::refuse_unwritable<M, T>(mesh, "PLY", options.ply_coordinates == ply_scalar::float32); !ok) return detail::at_path(path, ok.error());
    return detail::write_file_atomically(path, [&](std::ostream& o) { return detail::put_ply<M, T>(mesh, o, options); });
}

}  // namespace hmira::io
