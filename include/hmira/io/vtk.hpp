// hmira/io/vtk.hpp
// VTK PolyData: XML .vtp (ascii, inline base64, appended raw or base64; UInt32 or UInt64
// headers; zlib-compressed arrays when zlib is available) and legacy .vtk (ASCII or BINARY,
// POLYDATA, and the triangles, quads and polygons of an UNSTRUCTURED_GRID). Polygons and
// triangle strips are read; vertices, lines and point or cell data are skipped. The XML is
// read by a small bounded pull parser (detail/xml.hpp says why not libexpat).
//
// Options: read_options (max_input_bytes also bounds a compressed array's inflated size; repair
// applies) and write_options (attributes are not written). Result: result<polygon_soup>
// (parse_vtk), result<read_report> (read_vtk), result<void> (write_vtk, write_vtk_to),
// result<std::string> (format_vtk). Machinery in detail/vtk_impl.hpp and detail/vtp_impl.hpp.
#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "../concepts.hpp"
#include "../core/result.hpp"
#include "detail/atomic_write.hpp"
#include "detail/face_loops.hpp"
#include "detail/files.hpp"
#include "detail/gltf_impl.hpp"  // encode_base64
#include "detail/polygon_soup.hpp"
#include "detail/vtk_impl.hpp"
#include "detail/vtp_impl.hpp"
#include "io_options.hpp"

namespace hmira::io {

/// The VTK encodings the writer chooses between.
enum class vtk_encoding {
    xml_appended,   ///< .vtp, arrays raw after <AppendedData> (UInt64 headers, little-endian)
    xml_base64,     ///< .vtp, arrays inline as base64
    legacy_binary,  ///< .vtk version 3.0, BINARY (big-endian)
    legacy_ascii,   ///< .vtk version 3.0, ASCII
};

/// Parses .vtp XML or legacy .vtk (told apart by their first bytes) into a soup: each piece's
/// points and its polygons, then its triangle strips cut into triangles (alternate ones
/// reversed, so that the strip's winding is kept).
/// \pre none: any bytes are safe. Memory is O(bytes), and a compressed array's inflated size
/// is bounded by options.max_input_bytes before it is allocated.
/// Complexity O(bytes + inflated bytes).
/// Errors: errc::parse_error ("<name>: [byte offset N: ]<what>"): malformed XML or keywords, a
/// declared count or size larger than the bytes left, an offset out of range, a cell naming a
/// point out of range or of fewer than 3 points, a non-finite point; errc::unsupported: other
/// dataset types, compressors other than zlib (or zlib data in a build without it), 2^32 points.
inline result<polygon_soup> parse_vtk(std::string_view data, const std::string& name,
                                      const read_options& options = {}) {
    std::size_t at = 0;
    while (at < data.size() && detail::xml_reader::is_space(data[at])) ++at;
    if (data.substr(at).starts_with("<")) return detail::parse_vtp(data, name, options.max_input_bytes);
    if (data.starts_with("# vtk DataFile")) return detail::parse_vtk_legacy(data, name);
    return fail(errc::parse_error, name + ": neither a legacy VTK file ('# vtk DataFile') nor VTK XML");
}

/// Reads a .vtp or .vtk file into `mesh` (replacing its content; unchanged on error), repaired
/// for half-edge models as every reader does (read_mesh).
/// Complexity O(bytes + mesh insertions). Errors: errc::io_error, and those of parse_vtk.
template <class M, class T = default_traits<M>>
    requires readable_mesh<M, T>
result<read_report> read_vtk(M& mesh, const std::filesystem::path& path, const read_options& options = {}) {
    auto file = detail::input_file::open(path, options.max_input_bytes);
    if (!file) return file.error();
    auto s = parse_vtk(file->text(), path.string(), options);
    if (!s) return s.error();
    const bool xml = !file->text().starts_with("# vtk");
    return finish_read<M, T>(mesh, std::move(*s), path.string(), xml ? "vtp" : "vtk", 0, options);
}

/// Writes the mesh's vertices and polygons as VTK PolyData through `out`: float coordinates
/// for float meshes, double otherwise (exact); Int32 cells while they fit, else Int64 (.vtp);
/// legacy files use int cells (at most 2^31 - 1 corners plus faces).
/// Complexity O(V + C). Errors, with nothing written: errc::unsupported naming a face with
/// inner rings or a non-finite vertex, or a legacy file too large for int cells; io_error.
template <class M, class T = default_traits<M>>
    requires writable_mesh<M, T>
result<void> write_vtk_to(const M& mesh, std::ostream& out, vtk_encoding encoding = vtk_encoding::xml_appended,
                          const write_options& options = {});

/// The bytes of write_vtk_to, or its error.
template <class M, class T = default_traits<M>>
    requires writable_mesh<M, T>
result<std::string> format_vtk(const M& mesh, vtk_encoding encoding = vtk_encoding::xml_appended,
                               const write_options& options = {}) {
    std::ostringstream s;
    if (auto ok = write_vtk_to<M, T>(mesh, s, encoding, options); !ok) return ok.error();
    return std::move(s).str();
}

/// Writes the mesh atomically: ".vtk" as legacy binary, anything else as .vtp with appended raw
/// arrays. Errors: those of write_vtk_to, with nothing written.
template <class M, class T = default_traits<M>>
    requires writable_mesh<M, T>
result<void> write_vtk(const M& mesh, const std::filesystem::path& path, const write_options& options = {}) {
    std::string ext = path.extension().string();
    for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const auto encoding = ext == ".vtk" ? vtk_encoding::legacy_binary : vtk_encoding::xml_appended;
    std::ostringstream staged;
    if (auto ok = write_vtk_to<M, T>(mesh, staged, encoding, options); !ok) return detail::at_path(path, ok.error());
    const std::string bytes = std::move(staged).str();
    return detail::write_file_atomically(path, [&](std::ostream& o) {
        o.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        return bool(o);
    });
}

namespace detail {

/// The mesh as VTK arrays: positions in T::vertices order, cells as end offsets and corners.
struct vtk_arrays {
    std::vector<double> xyz;
    std::vector<std::uint64_t> ends;
    std::vector<std::uint64_t> corners;
};

template <class M, class T>
vtk_arrays vtk_arrays_of(const M& mesh) {
    vtk_arrays a;
    const auto number = dense_vertex_numbers<M, T>(mesh);
    for (auto v : T::vertices(mesh)) {
        const auto p = T::position(mesh, v);
        a.xyz.insert(a.xyz.end(), {static_cast<double>(p[0]), static_cast<double>(p[1]), static_cast<double>(p[2])});
    }
    for (auto f : T::faces(mesh)) {
        for (auto v : T::face_vertices(mesh, f)) a.corners.push_back(number[T::vertex_index(mesh, v)]);
        a.ends.push_back(a.corners.size());
    }
    return a;
}

inline void vtp_append_array(std::string& xml, std::string& appended, bool base64, const char* indent,
                             const char* attrs, std::string_view bytes) {
    std::string block;
    const std::uint64_t n = bytes.size();
    block.append(reinterpret_cast<const char*>(&n), 8);  // little-endian hosts only write .vtp
    block += bytes;
    xml += indent;
    xml += "<DataArray ";
    xml += attrs;
    if (base64) {
        xml += " format=\"binary\">";
        xml += encode_base64(block);
        xml += "</DataArray>\n";
    } else {
        xml += " format=\"appended\" offset=\"" + std::to_string(appended.size()) + "\"/>\n";
        appended += block;
    }
}

template <class V>
std::string vtp_packed(const std::vector<V>& values, bool narrow) {
    std::string out;
    out.reserve(values.size() * (narrow ? 4 : 8));
    for (const V v : values) {
        if constexpr (std::is_floating_point_v<V>) {
            if (narrow) {
                const float x = static_cast<float>(v);
                out.append(reinterpret_cast<const char*>(&x), 4);
            } else {
                out.append(reinterpret_cast<const char*>(&v), 8);
            }
        } else if (narrow) {
            const auto x = static_cast<std::int32_t>(v);
            out.append(reinterpret_cast<const char*>(&x), 4);
        } else {
            const auto x = static_cast<std::int64_t>(v);
            out.append(reinterpret_cast<const char*>(&x), 8);
        }
    }
    return out;
}

inline std::string vtp_document(const vtk_arrays& a, bool as_float, bool base64) {
    const bool narrow = a.corners.size() < 0x7fffffffu && a.xyz.size() / 3 < 0x7fffffffu;
    const char* int_type = narrow ? "type=\"Int32\"" : "type=\"Int64\"";
    std::string xml =
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" "
        "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n  <PolyData>\n";
    xml += "    <Piece NumberOfPoints=\"" + std::to_string(a.xyz.size() / 3) +
           "\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"" +
           std::to_string(a.ends.size()) + "\">\n      <Points>\n";
    std::string appended;
    vtp_append_array(xml, appended, base64, "        ",
                     as_float ? "type=\"Float32\" Name=\"Points\" NumberOfComponents=\"3\""
                              : "type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"",
                     vtp_packed(a.xyz, as_float));
    xml += "      </Points>\n      <Polys>\n";
    vtp_append_array(xml, appended, base64, "        ", (std::string(int_type) + " Name=\"connectivity\"").c_str(),
                     vtp_packed(a.corners, narrow));
    vtp_append_array(xml, appended, base64, "        ", (std::string(int_type) + " Name=\"offsets\"").c_str(),
                     vtp_packed(a.ends, narrow));
    xml += "      </Polys>\n    </Piece>\n  </PolyData>\n";
    if (!base64) {
        xml += "  <AppendedData encoding=\"raw\">\n   _";
        xml += appended;
        xml += "\n  </AppendedData>\n";
    }
    return xml + "</VTKFile>\n";
}

inline result<std::string> vtk_legacy_document(const vtk_arrays& a, bool as_float, bool binary) {
    const std::uint64_t size = a.ends.size() + a.corners.size();
    if (size > 0x7fffffffu)
        return fail(errc::unsupported, "VTK writer: " + std::to_string(size) +
                                           " face sizes and corners exceed legacy VTK's int cells; write .vtp instead");
    std::string out = "# vtk DataFile Version 3.0\nhmira\n";
    out += binary ? "BINARY\n" : "ASCII\n";
    out += "DATASET POLYDATA\nPOINTS " + std::to_string(a.xyz.size() / 3) + (as_float ? " float\n" : " double\n");
    for (std::size_t i = 0; i < a.xyz.size(); ++i) {
        if (binary && as_float)
            append_big_endian(out, static_cast<float>(a.xyz[i]));
        else if (binary)
            append_big_endian(out, a.xyz[i]);
        else {
            as_float ? append_number(out, static_cast<float>(a.xyz[i])) : append_number(out, a.xyz[i]);
            out += i % 3 == 2 ? '\n' : ' ';
        }
    }
    out += "\nPOLYGONS " + std::to_string(a.ends.size()) + " " + std::to_string(size) + "\n";
    std::uint64_t begin = 0;
    for (const auto end : a.ends) {
        auto put = [&](std::uint64_t v, char sep) {
            if (binary)
                append_big_endian(out, static_cast<std::int32_t>(v));
            else
                append_number(out, v), out += sep;
        };
        put(end - begin, ' ');
        for (auto k = begin; k < end; ++k) put(a.corners[k], k + 1 == end ? '\n' : ' ');
        begin = end;
    }
    return out;
}

}  // namespace detail

template <class M, class T>
    requires writable_mesh<M, T>
result<void> write_vtk_to(const M& mesh, std::ostream& out, vtk_encoding encoding, const write_options& options) {
    (void)options;
    const bool as_float = std::is_same_v<typename T::scalar, float>;
    if (auto ok = detail::refuse_unwritable<M, T>(mesh, "VTK", as_float); !ok) return ok;
    const auto arrays = detail::vtk_arrays_of<M, T>(mesh);
    std::string bytes;
    if (encoding == vtk_encoding::xml_appended || encoding == vtk_encoding::xml_base64) {
        bytes = detail::vtp_document(arrays, as_float, encoding == vtk_encoding::xml_base64);
    } else {
        auto doc = detail::vtk_legacy_document(arrays, as_float, encoding == vtk_encoding::legacy_binary);
        if (!doc) return doc.error();
        bytes = std::move(*doc);
    }
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) return detail::stream_failed("VTK");
    return {};
}

}  // namespace hmira::io
