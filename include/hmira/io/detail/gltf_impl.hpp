// hmira/io/detail/gltf_impl.hpp
// The machinery of gltf.hpp: the GLB container, buffers (the GLB binary chunk, base64 data URIs,
// files beside a .gltf), accessors checked against their buffer views before a byte is read, the
// default scene's node transforms, and the writer's JSON and binary chunk.
#pragma once

#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <initializer_list>
#include <limits>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../../core/result.hpp"
#include "../io_options.hpp"
#include "face_loops.hpp"
#include "json.hpp"
#include "polygon_soup.hpp"

namespace hmira::io::detail {

inline constexpr std::uint32_t glb_magic = 0x46546c67;       // "glTF"
inline constexpr std::uint32_t glb_json_chunk = 0x4e4f534a;  // "JSON"
inline constexpr std::uint32_t glb_bin_chunk = 0x004e4942;   // "BIN\0"

inline std::uint32_t read_le32(const char* p) {
    std::uint32_t v;
    std::memcpy(&v, p, 4);
    if constexpr (std::endian::native == std::endian::big) v = __builtin_bswap32(v);
    return v;
}

/// Loads a buffer named by a relative URI (a file beside the .gltf); empty for in-memory parsing.
using gltf_uri_loader = std::function<result<std::string>(const std::string& uri)>;

/// The JSON and binary chunk of a GLB file, or the text of a .gltf.
struct gltf_container {
    std::string_view json;
    std::string_view bin;
    bool glb = false;
};

inline result<gltf_container> split_glb(std::string_view data, const std::string& name) {
    gltf_container c;
    if (data.size() < 4 || read_le32(data.data()) != glb_magic) {
        c.json = data;
        return c;
    }
    c.glb = true;
    auto at = [&](std::size_t offset, const std::string& what) {
        return fail(errc::parse_error, name + ": byte offset " + std::to_string(offset) + ": " + what,
                    static_cast<long long>(offset));
    };
    if (data.size() < 20) return at(data.size(), "GLB file too short for its header and first chunk header");
    const std::uint32_t version = read_le32(data.data() + 4), length = read_le32(data.data() + 8);
    if (version != 2) return at(4, "GLB version " + std::to_string(version) + " (only version 2 is read)");
    if (length != data.size())
        return at(8, "GLB header says " + std::to_string(length) + " bytes, the file has " +
                         std::to_string(data.size()) + " (truncated or corrupt file)");
    std::size_t offset = 12;
    for (int chunk = 0; offset < data.size(); ++chunk) {
        if (data.size() - offset < 8) return at(offset, "truncated GLB chunk header");
        const std::uint64_t size = read_le32(data.data() + offset), type = read_le32(data.data() + offset + 4);
        if (size > data.size() - offset - 8)
            return at(offset, "GLB chunk of " + std::to_string(size) + " bytes runs past the end of the file");
        const std::string_view body = data.substr(offset + 8, static_cast<std::size_t>(size));
        if (chunk == 0 && type != glb_json_chunk) return at(offset + 4, "the first GLB chunk is not JSON");
        if (chunk == 0) c.json = body;
        if (chunk == 1 && type == glb_bin_chunk) c.bin = body;
        offset += 8 + static_cast<std::size_t>(size);
    }
    return c;
}

inline result<std::string> decode_base64(std::string_view s, const std::string& where) {
    std::string out;
    out.reserve(s.size() / 4 * 3);
    std::uint32_t acc = 0;
    int bits = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const char c = s[i];
        int v;
        if (c >= 'A' && c <= 'Z')
            v = c - 'A';
        else if (c >= 'a' && c <= 'z')
            v = c - 'a' + 26;
        else if (c >= '0' && c <= '9')
            v = c - '0' + 52;
        else if (c == '+' || c == '-')
            v = 62;
        else if (c == '/' || c == '_')
            v = 63;
        else if (c == '=')
            break;
        else
            return fail(errc::parse_error,
                        where + ": character " + std::to_string(i) + " of the base64 data is not base64");
        acc = (acc << 6) | static_cast<std::uint32_t>(v);
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            out += static_cast<char>((acc >> bits) & 0xff);
        }
    }
    return out;
}

/// A parsed glTF document with its buffers' bytes.
struct gltf_document {
    json_value root;
    std::vector<std::string> owned;  ///< decoded data URIs and loaded files
    std::vector<std::string_view> buffers;
    std::string name;

    hmira::error bad(const std::string& what) const { return fail(errc::parse_error, name + ": " + what); }

    /// The array `key` of the root (empty when absent), or an error when it is no array.
    const json_value* array(const char* key) const {
        const json_value* a = root.find(key);
        return a && a->is_array() ? a : nullptr;
    }
    /// A non-negative integer member, or `fallback` when absent; error when malformed.
    result<std::uint64_t> index(const json_value& object, const char* key, const std::string& where,
                                std::uint64_t fallback = std::numeric_limits<std::uint64_t>::max()) const {
        const json_value* v = object.find(key);
        if (!v) {
            if (fallback == std::numeric_limits<std::uint64_t>::max()) return bad(where + " has no " + key);
            return fallback;
        }
        if (!v->is_number() || !(v->number >= 0) || v->number != std::floor(v->number) || v->number > 9.0e15)
            return bad(where + "." + key + " is not a non-negative integer");
        return static_cast<std::uint64_t>(v->number);
    }
    /// The element `i` of the root array `key`, checked.
    result<const json_value*> element(const char* key, std::uint64_t i, const std::string& who) const {
        const json_value* a = array(key);
        if (!a || i >= a->items.size() || !a->items[static_cast<std::size_t>(i)].is_object())
            return bad(who + " names " + key + "[" + std::to_string(i) + "], which does not exist");
        return &a->items[static_cast<std::size_t>(i)];
    }
};

inline result<void> load_buffers(gltf_document& doc, std::string_view bin, const gltf_uri_loader& load) {
    const json_value* buffers = doc.array("buffers");
    if (!buffers) return {};
    for (std::size_t i = 0; i < buffers->items.size(); ++i) {
        const std::string where = "buffers[" + std::to_string(i) + "]";
        const json_value& b = buffers->items[i];
        if (!b.is_object()) return doc.bad(where + " is not an object");
        auto length = doc.index(b, "byteLength", where);
        if (!length) return length.error();
        const json_value* uri = b.find("uri");
        std::string_view bytes;
        if (!uri) {
            if (i != 0 || bin.data() == nullptr) return doc.bad(where + " has no uri and the file no GLB binary chunk");
            bytes = bin;
        } else if (!uri->is_string()) {
            return doc.bad(where + ".uri is not a string");
        } else if (uri->text.starts_with("data:")) {
            const auto comma = uri->text.find(',');
            if (comma == std::string::npos || uri->text.substr(0, comma).find(";base64") == std::string::npos)
                return doc.bad(where + ".uri is a data URI that is not base64");
            auto decoded = decode_base64(std::string_view(uri->text).substr(comma + 1), doc.name + ": " + where);
            if (!decoded) return decoded.error();
            doc.owned.push_back(std::move(*decoded));
            bytes = doc.owned.back();
        } else {
            const std::string& u = uri->text;
            if (!load)
                return doc.bad(where + " refers to the file '" + printable(u) + "', which cannot be read from memory");
            if (u.find(':') != std::string::npos || u.starts_with('/') || u.find("..") != std::string::npos)
                return doc.bad(where + ".uri '" + printable(u) + "' is not a relative path beside the file");
            std::string path;
            for (std::size_t k = 0; k < u.size(); ++k) {  // percent-decoding (%20 for spaces)
                unsigned v = 0;
                if (u[k] == '%' && k + 2 < u.size() &&
                    std::from_chars(u.data() + k + 1, u.data() + k + 3, v, 16).ptr == u.data() + k + 3) {
                    path += static_cast<char>(v);
                    k += 2;
                } else {
                    path += u[k];
                }
            }
            auto file = load(path);
            if (!file) return file.error();
            doc.owned.push_back(std::move(*file));
            bytes = doc.owned.back();
        }
        if (bytes.size() < *length)
            return doc.bad(where + " says " + std::to_string(*length) + " bytes but has " +
                           std::to_string(bytes.size()));
        doc.buffers.push_back(bytes.substr(0, static_cast<std::size_t>(*length)));
    }
    return {};
}

/// An accessor's elements, checked to lie inside its buffer view and buffer.
struct gltf_accessor {
    const char* data = nullptr;
    std::size_t count = 0, stride = 0, components = 0;
    int component_type = 0;
    bool normalized = false;

    /// Component c of element i, as a double (normalized integers mapped to [0, 1]).
    double get(std::size_t i, std::size_t c) const {
        const char* p = data + i * stride;
        switch (component_type) {
            case 5126: {
                float f;
                std::memcpy(&f, p + 4 * c, 4);
                return f;
            }
            case 5121: return normalized ? static_cast<unsigned char>(p[c]) / 255.0 : static_cast<unsigned char>(p[c]);
            case 5123: {
                std::uint16_t v;
                std::memcpy(&v, p + 2 * c, 2);
                return normalized ? v / 65535.0 : v;
            }
            case 5125: {
                std::uint32_t v;
                std::memcpy(&v, p + 4 * c, 4);
                return v;
            }
        }
        return 0;
    }
};

inline std::size_t component_size(int type) {
    switch (type) {
        case 5120:
        case 5121: return 1;
        case 5122:
        case 5123: return 2;
        case 5125:
        case 5126: return 4;
    }
    return 0;
}

/// Accessor `i` for `who`, whose type must be one of `types` ("VEC3", "SCALAR", ...) and whose
/// component type one of `component_types`.
inline result<gltf_accessor> accessor(const gltf_document& doc, std::uint64_t i, const std::string& who,
                                      std::initializer_list<std::string_view> types,
                                      std::initializer_list<int> component_types) {
    auto a = doc.element("accessors", i, who);
    if (!a) return a.error();
    const std::string where = "accessors[" + std::to_string(i) + "] (" + who + ")";
    const json_value& acc = **a;
    if (acc.find("sparse")) return fail(errc::unsupported, doc.name + ": " + where + " is sparse (not read)");
    const json_value* type = acc.find("type");
    if (!type || !type->is_string()) return doc.bad(where + " has no type");
    std::size_t components = 0;
    for (auto t : types)
        if (type->text == t) components = t == "SCALAR" ? 1 : static_cast<std::size_t>(t.back() - '0');
    if (components == 0) return doc.bad(where + " has type " + printable(type->text) + ", not what " + who + " needs");
    auto ct = doc.index(acc, "componentType", where);
    if (!ct) return ct.error();
    bool known = false;
    for (int t : component_types) known |= static_cast<std::uint64_t>(t) == *ct;
    if (!known) return doc.bad(where + " has componentType " + std::to_string(*ct) + ", not what " + who + " needs");
    auto count = doc.index(acc, "count", where);
    if (!count) return count.error();
    auto view_index = doc.index(acc, "bufferView", where);
    if (!view_index) return view_index.error();
    auto offset = doc.index(acc, "byteOffset", where, 0);
    if (!offset) return offset.error();
    auto v = doc.element("bufferViews", *view_index, where);
    if (!v) return v.error();
    const std::string view_where = "bufferViews[" + std::to_string(*view_index) + "]";
    auto buffer = doc.index(**v, "buffer", view_where);
    auto view_offset = doc.index(**v, "byteOffset", view_where, 0);
    auto view_length = doc.index(**v, "byteLength", view_where);
    auto stride = doc.index(**v, "byteStride", view_where, 0);
    if (!buffer || !view_offset || !view_length || !stride)
        return !buffer        ? buffer.error()
               : !view_offset ? view_offset.error()
               : !view_length ? view_length.error()
                              : stride.error();
    if (*buffer >= doc.buffers.size())
        return doc.bad(view_where + " names buffers[" + std::to_string(*buffer) + "], which does not exist");
    const std::string_view bytes = doc.buffers[static_cast<std::size_t>(*buffer)];
    if (*view_offset > bytes.size() || *view_length > bytes.size() - *view_offset)
        return doc.bad(view_where + " (offset " + std::to_string(*view_offset) + ", length " +
                       std::to_string(*view_length) + ") runs past its buffer of " + std::to_string(bytes.size()) +
                       " bytes");
    gltf_accessor out;
    out.components = components;
    out.component_type = static_cast<int>(*ct);
    const std::size_t element = components * component_size(out.component_type);
    out.stride = *stride ? static_cast<std::size_t>(*stride) : element;
    if (out.stride < element || out.stride > 252)
        return doc.bad(view_where + " has byteStride " + std::to_string(out.stride) + " (elements of " + where +
                       " need " + std::to_string(element) + " to 252)");
    // Everything in 64 bits: count and offsets come from the file; the view bounds them.
    if (*count > 0 && (*offset > *view_length || (*count - 1) > (*view_length - *offset) / out.stride ||
                       (*count - 1) * out.stride + element > *view_length - *offset))
        return doc.bad(where + ": " + std::to_string(*count) + " elements from byte " + std::to_string(*offset) +
                       " run past " + view_where + " (" + std::to_string(*view_length) + " bytes)");
    out.count = static_cast<std::size_t>(*count);
    out.data = bytes.data() + *view_offset + *offset;
    const json_value* normalized = acc.find("normalized");
    out.normalized = normalized && normalized->type == json_value::kind::boolean && normalized->boolean;
    return out;
}

using gltf_matrix = std::array<double, 16>;  // column-major, as glTF stores it

inline gltf_matrix multiply(const gltf_matrix& a, const gltf_matrix& b) {
    gltf_matrix r{};
    for (int c = 0; c < 4; ++c)
        for (int row = 0; row < 4; ++row)
            for (int k = 0; k < 4; ++k) r[c * 4 + row] += a[k * 4 + row] * b[c * 4 + k];
    return r;
}

/// A node's local transform: its matrix, or T * R * S.
inline result<gltf_matrix> node_matrix(const gltf_document& doc, const json_value& node, const std::string& where) {
    gltf_matrix m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    auto numbers = [&](const char* key, std::size_t n, std::array<double, 16>& out) -> result<bool> {
        const json_value* v = node.find(key);
        if (!v) return false;
        if (!v->is_array() || v->items.size() != n)
            return doc.bad(where + "." + key + " must hold " + std::to_string(n) + " numbers");
        for (std::size_t i = 0; i < n; ++i) {
            if (!v->items[i].is_number() || !std::isfinite(v->items[i].number))
                return doc.bad(where + "." + key + " holds something that is not a finite number");
            out[i] = v->items[i].number;
        }
        return true;
    };
    std::array<double, 16> given{};
    auto has_matrix = numbers("matrix", 16, given);
    if (!has_matrix) return has_matrix.error();
    if (*has_matrix) return given;
    std::array<double, 16> t{}, r{0, 0, 0, 1}, s{1, 1, 1};
    auto translation = numbers("translation", 3, t);
    auto rotation = numbers("rotation", 4, r);
    auto scale = numbers("scale", 3, s);
    if (!translation || !rotation || !scale)
        return !translation ? translation.error() : !rotation ? rotation.error() : scale.error();
    const double x = r[0], y = r[1], z = r[2], w = r[3];
    const double rot[9] = {1 - 2 * (y * y + z * z), 2 * (x * y + z * w),     2 * (x * z - y * w),
                           2 * (x * y - z * w),     1 - 2 * (x * x + z * z), 2 * (y * z + x * w),
                           2 * (x * z + y * w),     2 * (y * z - x * w),     1 - 2 * (x * x + y * y)};
    for (int c = 0; c < 3; ++c)
        for (int row = 0; row < 3; ++row) m[c * 4 + row] = rot[c * 3 + row] * s[static_cast<std::size_t>(c)];
    m[12] = t[0], m[13] = t[1], m[14] = t[2];
    return m;
}

/// Appends one triangle primitive to the soup, positions transformed by `m`.
inline result<void> add_primitive(const gltf_document& doc, const json_value& primitive, const std::string& where,
                                  const gltf_matrix& m, polygon_soup& soup, bool& normals, bool& colors) {
    auto mode = doc.index(primitive, "mode", where, 4);
    if (!mode) return mode.error();
    if (*mode != 4)
        return fail(errc::unsupported, doc.name + ": " + where + " has mode " + std::to_string(*mode) +
                                           " (only triangles, mode 4, are read)");
    const json_value* attributes = primitive.find("attributes");
    if (!attributes || !attributes->is_object()) return doc.bad(where + " has no attributes");
    auto position_index = doc.index(*attributes, "POSITION", where + ".attributes");
    if (!position_index) return position_index.error();
    auto positions = accessor(doc, *position_index, "POSITION of " + where, {"VEC3"}, {5126});
    if (!positions) return positions.error();
    const std::size_t base = soup.points.size();
    if (positions->count > std::size_t{0xffffffffu} - base)
        return fail(errc::unsupported, doc.name + ": more than 2^32 - 1 vertices");
    soup.points.reserve(base + positions->count);
    for (std::size_t i = 0; i < positions->count; ++i) {
        const double p[3] = {positions->get(i, 0), positions->get(i, 1), positions->get(i, 2)};
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
            return doc.bad("POSITION of " + where + ": vertex " + std::to_string(i) + " is not finite");
        std::array<double, 3> q;
        for (int r = 0; r < 3; ++r)
            q[static_cast<std::size_t>(r)] = m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r];
        soup.points.push_back(q);
    }
    auto& attr = soup.attributes;
    if (const auto n = attributes->find("NORMAL"); n && normals) {
        auto idx = doc.index(*attributes, "NORMAL", where + ".attributes");
        if (!idx) return idx.error();
        auto a = accessor(doc, *idx, "NORMAL of " + where, {"VEC3"}, {5126});
        if (!a) return a.error();
        if (a->count != positions->count) return doc.bad("NORMAL of " + where + " has a count unlike POSITION's");
        for (std::size_t i = 0; i < a->count; ++i)
            attr.normals.push_back(
                {static_cast<float>(a->get(i, 0)), static_cast<float>(a->get(i, 1)), static_cast<float>(a->get(i, 2))});
    } else {
        normals = false;
    }
    if (const auto c = attributes->find("COLOR_0"); c && colors) {
        auto idx = doc.index(*attributes, "COLOR_0", where + ".attributes");
        if (!idx) return idx.error();
        auto a = accessor(doc, *idx, "COLOR_0 of " + where, {"VEC3", "VEC4"}, {5126, 5121, 5123});
        if (!a) return a.error();
        if (a->count != positions->count) return doc.bad("COLOR_0 of " + where + " has a count unlike POSITION's");
        if (a->component_type != 5126) a->normalized = true;
        for (std::size_t i = 0; i < a->count; ++i)
            attr.colors.push_back({to_byte(a->get(i, 0)), to_byte(a->get(i, 1)), to_byte(a->get(i, 2)),
                                   a->components == 4 ? to_byte(a->get(i, 3)) : std::uint8_t{255}});
    } else {
        colors = false;
    }
    if (const json_value* indices = primitive.find("indices")) {
        auto idx = doc.index(primitive, "indices", where);
        if (!idx) return idx.error();
        (void)indices;
        auto a = accessor(doc, *idx, "indices of " + where, {"SCALAR"}, {5121, 5123, 5125});
        if (!a) return a.error();
        if (a->count % 3)
            return doc.bad("indices of " + where + ": " + std::to_string(a->count) + " is not a multiple of 3");
        soup.indices.reserve(soup.indices.size() + a->count);
        for (std::size_t i = 0; i < a->count; ++i) {
            const double v = a->get(i, 0);
            if (v >= static_cast<double>(positions->count))
                return doc.bad("indices of " + where + ": index " + std::to_string(i) + " is " +
                               std::to_string(static_cast<std::uint64_t>(v)) + ", out of range [0, " +
                               std::to_string(positions->count) + ")");
            soup.indices.push_back(static_cast<std::uint32_t>(base + static_cast<std::size_t>(v)));
            if (i % 3 == 2) soup.face_offsets.push_back(soup.indices.size());
        }
    } else {
        if (positions->count % 3)
            return doc.bad("POSITION of " + where + ": " + std::to_string(positions->count) +
                           " vertices without indices is not a multiple of 3");
        for (std::size_t i = 0; i < positions->count; ++i) {
            soup.indices.push_back(static_cast<std::uint32_t>(base + i));
            if (i % 3 == 2) soup.face_offsets.push_back(soup.indices.size());
        }
    }
    return {};
}

/// Appends every primitive of mesh `i`.
inline result<void> add_mesh(const gltf_document& doc, std::uint64_t i, const std::string& who, const gltf_matrix& m,
                             polygon_soup& soup, bool& normals, bool& colors) {
    auto mesh = doc.element("meshes", i, who);
    if (!mesh) return mesh.error();
    const json_value* primitives = (*mesh)->find("primitives");
    if (!primitives || !primitives->is_array()) return doc.bad("meshes[" + std::to_string(i) + "] has no primitives");
    for (std::size_t p = 0; p < primitives->items.size(); ++p) {
        const std::string where = "meshes[" + std::to_string(i) + "].primitives[" + std::to_string(p) + "]";
        if (!primitives->items[p].is_object()) return doc.bad(where + " is not an object");
        if (auto ok = add_primitive(doc, primitives->items[p], where, m, soup, normals, colors); !ok) return ok;
    }
    return {};
}

/// The soup of the default scene (its nodes' meshes, transformed), or of every mesh when the
/// file has no scene. A node is visited at most once per path from the root, and at most
/// `nodes` deep, so a cyclic hierarchy ends with an error.
inline result<polygon_soup> gltf_soup(const gltf_document& doc) {
    polygon_soup soup;
    bool normals = true, colors = true;
    const gltf_matrix identity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const json_value* scenes = doc.array("scenes");
    const json_value* nodes = doc.array("nodes");
    if (!scenes || scenes->items.empty() || !nodes) {
        if (const json_value* meshes = doc.array("meshes"))
            for (std::size_t i = 0; i < meshes->items.size(); ++i)
                if (auto ok = add_mesh(doc, i, "the file", identity, soup, normals, colors); !ok) return ok.error();
    } else {
        auto scene_index = doc.index(doc.root, "scene", "the file", 0);
        if (!scene_index) return scene_index.error();
        auto scene = doc.element("scenes", *scene_index, "the file");
        if (!scene) return scene.error();
        std::vector<std::pair<std::uint64_t, gltf_matrix>> stack;
        std::vector<std::size_t> depth;
        if (const json_value* roots = (*scene)->find("nodes"); roots && roots->is_array())
            for (auto it = roots->items.rbegin(); it != roots->items.rend(); ++it) {
                if (!it->is_number() || !(it->number >= 0) || it->number >= static_cast<double>(nodes->items.size()))
                    return doc.bad("scenes[" + std::to_string(*scene_index) + "] names a node that does not exist");
                stack.push_back({static_cast<std::uint64_t>(it->number), identity});
                depth.push_back(0);
            }
        std::size_t visits = 0;
        while (!stack.empty()) {
            const auto [n, parent] = stack.back();
            const std::size_t d = depth.back();
            stack.pop_back();
            depth.pop_back();
            const std::string where = "nodes[" + std::to_string(n) + "]";
            if (d > nodes->items.size() || ++visits > 16 * nodes->items.size() + 16)
                return doc.bad(where + ": the node hierarchy has a cycle (or repeats nodes too often)");
            auto node = doc.element("nodes", n, "a scene");
            if (!node) return node.error();
            auto local = node_matrix(doc, **node, where);
            if (!local) return local.error();
            const gltf_matrix m = multiply(parent, *local);
            if ((*node)->find("mesh")) {
                auto mesh = doc.index(**node, "mesh", where);
                if (!mesh) return mesh.error();
                if (auto ok = add_mesh(doc, *mesh, where, m, soup, normals, colors); !ok) return ok.error();
            }
            if (const json_value* children = (*node)->find("children"); children && children->is_array())
                for (const auto& c : children->items) {
                    if (!c.is_number() || !(c.number >= 0) || c.number >= static_cast<double>(nodes->items.size()))
                        return doc.bad(where + " has a child that does not exist");
                    stack.push_back({static_cast<std::uint64_t>(c.number), m});
                    depth.push_back(d + 1);
                }
        }
    }
    if (!normals || soup.attributes.normals.size() != soup.points.size()) soup.attributes.normals.clear();
    if (!colors || soup.attributes.colors.size() != soup.points.size()) soup.attributes.colors.clear();
    return soup;
}

/// A JSON string literal (the names hmira writes need no escapes beyond these).
inline std::string json_quoted(std::string_view s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

inline void append_bytes(std::string& out, const void* p, std::size_t n) { out.append(static_cast<const char*>(p), n); }

inline std::string encode_base64(std::string_view bytes) {
    static constexpr char table[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const std::uint32_t v = (std::uint32_t(std::uint8_t(bytes[i])) << 16) |
                                (std::uint32_t(std::uint8_t(bytes[i + 1])) << 8) | std::uint8_t(bytes[i + 2]);
        out += table[v >> 18], out += table[(v >> 12) & 63], out += table[(v >> 6) & 63], out += table[v & 63];
    }
    if (i < bytes.size()) {
        std::uint32_t v = std::uint32_t(std::uint8_t(bytes[i])) << 16;
        if (i + 1 < bytes.size()) v |= std::uint32_t(std::uint8_t(bytes[i + 1])) << 8;
        out += table[v >> 18], out += table[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? table[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

/// The whole glTF file (GLB bytes, or .gltf JSON with the buffer inline) for `mesh`, its faces
/// triangulated by `plan` (plan_stl_triangles). Vertices are numbered densely in T::vertices order.
template <class M, class T>
std::string gltf_bytes(const M& mesh, const stl_triangles<M, T>& plan, bool glb, const write_options& options) {
    const std::size_t bound = T::vertex_index_bound(mesh);
    std::vector<std::uint32_t> number(bound, 0);
    std::vector<std::size_t> slot;  // vertex index of each written vertex
    std::string positions, normals, colors, indices;
    float lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    const attribute_source attributes = find_attributes<M, T>(mesh, options);
    for (auto v : T::vertices(mesh)) {
        const auto vi = T::vertex_index(mesh, v);
        number[vi] = static_cast<std::uint32_t>(slot.size());
        const auto p = T::position(mesh, v);
        for (std::size_t k = 0; k < 3; ++k) {
            const float x = static_cast<float>(p[k]);
            lo[k] = slot.empty() || x < lo[k] ? x : lo[k];
            hi[k] = slot.empty() || x > hi[k] ? x : hi[k];
            append_bytes(positions, &x, 4);
        }
        if (attributes.normals)
            for (std::size_t k = 0; k < 3; ++k) append_bytes(normals, &attributes.normals[vi][k], 4);
        if (attributes.colors) append_bytes(colors, attributes.colors[vi].data(), 4);
        slot.push_back(vi);
    }
    auto put = [&](typename T::vertex_handle v) { append_bytes(indices, &number[T::vertex_index(mesh, v)], 4); };
    std::size_t planned_face = 0, next_triangle = 0;
    for (auto f : T::faces(mesh)) {
        typename T::vertex_handle tri[3];
        std::size_t k = 0;
        bool plain = !has_inner_rings<M, T>(mesh, f);
        if (plain)
            for (auto v : T::face_vertices(mesh, f)) {
                if (k == 3) {
                    plain = false;
                    break;
                }
                tri[k++] = v;
            }
        if (plain && k == 3) {
            put(tri[0]), put(tri[1]), put(tri[2]);
        } else {
            // The plan lists the faces that are not plain triangles in this same order.
            const std::size_t end = next_triangle + plan.counts[planned_face++];
            for (; next_triangle < end; ++next_triangle)
                for (auto v : plan.triangles[next_triangle]) put(v);
        }
    }
    // One buffer: indices, positions, normals, colours, each 4-byte aligned by construction.
    std::string bin = indices + positions + normals + colors;
    const std::size_t n = slot.size(), corners = indices.size() / 4;
    std::string json =
        "{\"asset\":{\"version\":\"2.0\",\"generator\":\"hmira\"},\"scene\":0,"
        "\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0}],";
    std::string views, accessors, attrs;
    std::size_t offset = 0, view = 0;
    auto add = [&](std::size_t bytes, std::size_t count, int component, const char* type, const std::string& extra) {
        if (view) views += ',', accessors += ',';
        views +=
            "{\"buffer\":0,\"byteOffset\":" + std::to_string(offset) + ",\"byteLength\":" + std::to_string(bytes) + "}";
        accessors += "{\"bufferView\":" + std::to_string(view) + ",\"componentType\":" + std::to_string(component) +
                     ",\"count\":" + std::to_string(count) + ",\"type\":\"" + type + "\"" + extra + "}";
        offset += bytes;
        return view++;
    };
    auto number_text = [](float x) {
        char buffer[32];
        auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, x);
        (void)ec;
        return std::string(buffer, end);
    };
    const std::size_t index_accessor = add(indices.size(), corners, 5125, "SCALAR", "");
    std::string bounds = ",\"min\":[" + number_text(lo[0]) + "," + number_text(lo[1]) + "," + number_text(lo[2]) +
                         "],\"max\":[" + number_text(hi[0]) + "," + number_text(hi[1]) + "," + number_text(hi[2]) + "]";
    attrs += "\"POSITION\":" + std::to_string(add(positions.size(), n, 5126, "VEC3", n ? bounds : ""));
    if (!normals.empty()) attrs += ",\"NORMAL\":" + std::to_string(add(normals.size(), n, 5126, "VEC3", ""));
    if (!colors.empty())
        attrs += ",\"COLOR_0\":" + std::to_string(add(colors.size(), n, 5121, "VEC4", ",\"normalized\":true"));
    json += "\"meshes\":[{\"primitives\":[{\"attributes\":{" + attrs +
            "},\"indices\":" + std::to_string(index_accessor) + ",\"mode\":4}]}],";
    json += "\"accessors\":[" + accessors + "],\"bufferViews\":[" + views + "],";
    json += "\"buffers\":[{\"byteLength\":" + std::to_string(bin.size());
    if (!glb) return json + ",\"uri\":\"data:application/octet-stream;base64," + encode_base64(bin) + "\"}]}\n";
    json += "}]}";
    while (json.size() % 4) json += ' ';
    while (bin.size() % 4) bin += '\0';
    std::string out;
    auto u32 = [&](std::uint64_t v) {
        std::uint32_t x = static_cast<std::uint32_t>(v);
        if constexpr (std::endian::native == std::endian::big) x = __builtin_bswap32(x);
        append_bytes(out, &x, 4);
    };
    u32(glb_magic), u32(2), u32(12 + 8 + json.size() + 8 + bin.size());
    u32(json.size()), u32(glb_json_chunk);
    out += json;
    u32(bin.size()), u32(glb_bin_chunk);
    out += bin;
    return out;
}

}  // namespace hmira::io::detail
