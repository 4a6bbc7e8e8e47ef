// hmira/io/mesh_io.hpp
// One entry point for every format: read_mesh / write_mesh pick OBJ, OFF, PLY, STL, glTF
// (.glb, .gltf), VTK (.vtp, .vtk) or 3MF from the file's extension (case-insensitive), and read_soup gives a file's content as indexed arrays
// without building a mesh.
#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <optional>
#include <string>

#include "../concepts.hpp"
#include "../core/result.hpp"
#include "detail/files.hpp"
#include "detail/polygon_soup.hpp"
#include "gltf.hpp"
#include "io_options.hpp"
#include "obj.hpp"
#include "off.hpp"
#include "ply.hpp"
#include "stl.hpp"
#include "threemf.hpp"
#include "vtk.hpp"

namespace hmira::io {

/// The mesh file formats hmira reads and writes.
enum class file_format {
    obj,      ///< Wavefront OBJ
    off,      ///< Object File Format
    ply,      ///< Stanford PLY
    stl,      ///< STereoLithography
    glb,      ///< glTF 2.0, binary container
    gltf,     ///< glTF 2.0, JSON (buffers inline or beside the file)
    vtp,      ///< VTK XML PolyData
    vtk,      ///< legacy VTK
    threemf,  ///< 3D Manufacturing Format (.3mf)
};

/// The format's usual extension without the dot.
inline const char* to_string(file_format f) {
    switch (f) {
        case file_format::obj: return "obj";
        case file_format::off: return "off";
        case file_format::ply: return "ply";
        case file_format::stl: return "stl";
        case file_format::glb: return "glb";
        case file_format::gltf: return "gltf";
        case file_format::vtp: return "vtp";
        case file_format::vtk: return "vtk";
        case file_format::threemf: return "3mf";
    }
    return "?";
}

/// The format named by the path's extension, or nothing for an unknown extension.
inline std::optional<file_format> format_from_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    if (ext == ".obj") return file_format::obj;
    if (ext == ".off") return file_format::off;
    if (ext == ".ply") return file_format::ply;
    if (ext == ".stl") return file_format::stl;
    if (ext == ".glb") return file_format::glb;
    if (ext == ".gltf") return file_format::gltf;
    if (ext == ".vtp") return file_format::vtp;
    if (ext == ".vtk") return file_format::vtk;
    if (ext == ".3mf") return file_format::threemf;
    return std::nullopt;
}

namespace detail {
inline hmira::error unknown_extension(const std::filesystem::path& path) {
    std::error_code ec;
    // A folder is an I/O problem whatever its name says.
    if (std::filesystem::is_directory(path, ec))
        return fail(errc::io_error, path.string() + ": is a directory, not a mesh file");
    return fail(errc::unknown_format, path.string() + ": unknown mesh format '" + path.extension().string() +
                                          "' (use .obj, .off, .ply, .stl, .glb, .gltf, .vtp, .vtk or .3mf)");
}
}  // namespace detail

namespace detail {
inline result<polygon_soup> parse_any(std::string_view data, file_format format, const std::string& name,
                                      const read_options& options) {
    switch (format) {
        case file_format::obj: return parse_obj(data, name, options);
        case file_format::off: return parse_off(data, name, options);
        case file_format::ply: return parse_ply(data, name, options);
        case file_format::stl: {
            auto s = parse_stl(data, name, options);
            if (!s) return s.error();
            return std::move(s->soup);
        }
        case file_format::glb:
        case file_format::gltf: return parse_gltf(data, name, options);
        case file_format::vtp:
        case file_format::vtk: return parse_vtk(data, name, options);
        case file_format::threemf: return parse_3mf(data, name, options);
    }
    return fail(errc::unknown_format, name + ": unknown format");
}
}  // namespace detail

/// Parses text/bytes of the given format into a soup (what the fuzz targets call).
/// Complexity O(bytes). Errors: as the format's parse_* function, and errc::unsupported for
/// 2^32 points or more.
inline result<polygon_soup> parse_soup(std::string_view data, file_format format, const std::string& name,
                                       const read_options& options = {}) {
    auto soup = detail::parse_any(data, format, name, options);
    // Corner indices are 32-bit: a soup with more points could not name them all.
    if (soup && soup->points.size() > std::size_t{0xffffffffu})
        return fail(errc::unsupported,
                    name + ": " + std::to_string(soup->points.size()) + " vertices; at most 2^32 - 1 are supported");
    return soup;
}

/// Reads a file into indexed arrays, the format chosen by extension. No mesh is built.
/// Complexity O(bytes). Errors: errc::io_error (missing file, directory), errc::unknown_format
/// (unknown extension) and the parse errors of the format.
inline result<polygon_soup> read_soup(const std::filesystem::path& path, const read_options& options = {}) {
    const auto format = format_from_extension(path);
    if (!format) return detail::unknown_extension(path);
    auto file = detail::input_file::open(path, options.max_input_bytes);
    if (!file) return file.error();
    return parse_soup(file->text(), *format, path.string(), options);
}

/// Reads a mesh file into `mesh` (replacing its content), the format chosen by extension.
/// Half-edge models (halfedge_mesh, winged_edge_mesh, OpenMesh, CGAL Surface_mesh) get the
/// file repaired as repair_polygon_soup does (unless options.repair is false), and the report
/// says what was repaired: degenerate faces dropped, faces on non-manifold edges cut free or
/// dropped, faces flipped, non-manifold vertices split (copies follow the file's vertices, see
/// read_report::copied_from). The mesh object is kept: it is emptied only once the file is
/// parsed and repaired, and keeps the user's properties (emptied, then sized to the new
/// elements): named properties on hmira's meshes, requested and added ones on OpenMesh,
/// property maps on Surface_mesh.
/// On any error the mesh is unchanged. Complexity O(bytes + C log d + mesh insertions), C
/// corners, d the largest vertex degree.
/// Errors: errc::io_error, errc::unknown_format, the format's parse errors; without repair, a
/// file a half-edge model cannot hold (errc::non_manifold, naming the face); for other models,
/// the mesh's own add_face errors, naming the face.
template <class M, class T = default_traits<M>>
    requires readable_mesh<M, T>
result<read_report> read_mesh(M& mesh, const std::filesystem::path& path, const read_options& options = {}) {
    const auto format = format_from_extension(path);
    if (!format) return detail::unknown_extension(path);
    switch (*format) {
        case file_format::obj: return read_obj<M, T>(mesh, path, options);
        case file_format::off: return read_off<M, T>(mesh, path, options);
        case file_format::ply: return read_ply<M, T>(mesh, path, options);
        case file_format::stl: return read_stl<M, T>(mesh, path, options);
        case file_format::glb:
        case file_format::gltf: return read_gltf<M, T>(mesh, path, options);
        case file_format::vtp:
        case file_format::vtk: return read_vtk<M, T>(mesh, path, options);
        case file_format::threemf: return read_3mf<M, T>(mesh, path, options);
    }
    return detail::unknown_extension(path);
}

/// Writes `mesh` atomically in the format named by the extension: a failure never leaves a
/// truncated file and never touches an existing one. Complexity O(V + C).
/// Errors: errc::unknown_format (unknown extension), errc::io_error.
template <class M, class T = default_traits<M>>
    requires writable_mesh<M, T>
result<void> write_mesh(const M& mesh, const std::filesystem::path& path, const write_options& options = {}) {
    const auto format = format_from_extension(path);
    if (!format) return detail::unknown_extension(path);
    switch (*format) {
        case file_format::obj: return write_obj<M, T>(mesh, path, options);
        case file_format::off: return write_off<M, T>(mesh, path, options);
        case file_format::ply: return write_ply<M, T>(mesh, path, options);
        case file_format::stl: return write_stl<M, T>(mesh, path, options);
        case file_format::glb:
        case file_format::gltf: return write_gltf<M, T>(mesh, path, options);
        case file_format::vtp:
        case file_format::vtk: return write_vtk<M, T>(mesh, path, options);
        case file_format::threemf: return write_3mf<M, T>(mesh, path, options);
    }
    return detail::unknown_extension(path);
}

}  // namespace hmira::io
