// hmira/io/threemf.hpp
// 3MF (3D Manufacturing Format): a ZIP package whose model part holds objects (triangle meshes,
// or components placing other objects) and build items placing them. The reader gives the
// build as one soup, every item and component transform applied; the writer writes one mesh
// object and one build item, faces triangulated as for STL. Units are not converted.
//
// Options: read_options (max_input_bytes bounds every ZIP entry's declared and inflated size,
// and the instantiated build; repair applies) and write_options (attributes are not written).
// Result: result<polygon_soup> (parse_3mf), result<read_report> (read_3mf), result<void>
// (write_3mf, write_3mf_to), result<std::string> (format_3mf). Deflated entries need zlib, an
// optional part (HMIRA_HAS_ZLIB, see detail/zip.hpp); without it, stored entries are read and
// written. Machinery in detail/threemf_impl.hpp, detail/zip.hpp and detail/xml.hpp.
#pragma once

#include <filesystem>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "../concepts.hpp"
#include "../core/result.hpp"
#include "detail/atomic_write.hpp"
#include "detail/face_loops.hpp"
#include "detail/files.hpp"
#include "detail/polygon_soup.hpp"
#include "detail/threemf_impl.hpp"
#include "io_options.hpp"

namespace hmira::io {

/// Parses a 3MF package into a soup: the model part named by the package relationships (or
/// 3D/3dmodel.model), each build item's object placed by the item's transform, components
/// recursively by theirs. Vertices are not welded across instances.
/// \pre none: any bytes are safe. Every ZIP entry's declared size is checked against
/// options.max_input_bytes before it is inflated, and inflating more than declared is refused;
/// the instantiated build is bounded by the same limit (24 bytes a point).
/// Complexity O(bytes + inflated bytes + instantiated points).
/// Errors: errc::parse_error ("<name>: [byte offset N: ]<what>"): a malformed ZIP (offsets or
/// sizes past the file, CRC mismatch), a zip bomb, malformed XML, a triangle naming a vertex
/// out of range, a non-finite coordinate or transform, a missing object, a component cycle;
/// errc::unsupported: encryption, compression other than deflate, deflate without zlib.
inline result<polygon_soup> parse_3mf(std::string_view data, const std::string& name,
                                      const read_options& options = {}) {
    auto entries = detail::zip_directory(data, name);
    if (!entries) return entries.error();
    auto part = detail::threemf_model_name(data, *entries, name, options.max_input_bytes);
    if (!part) return part.error();
    const detail::zip_entry* model_entry = nullptr;
    for (const auto& e : *entries)
        if (e.name == *part) model_entry = &e;
    if (!model_entry)
        return fail(errc::parse_error, name + ": no model part '" + detail::printable(*part) + "' in the package");
    auto text = detail::zip_read(data, *model_entry, name, options.max_input_bytes);
    if (!text) return text.error();
    auto model = detail::threemf_parse_model(*text, name + " (" + detail::printable(*part) + ")");
    if (!model) return model.error();
    polygon_soup soup;
    std::vector<std::uint64_t> path;
    const std::uint64_t max_points = std::min<std::uint64_t>(options.max_input_bytes / 24, 0xffffffffu);
    for (const auto& item : model->items)
        if (auto ok = detail::threemf_instantiate(*model, item.object, item.transform, soup, path, max_points, name);
            !ok)
            return ok.error();
    return soup;
}

/// Reads a .3mf file into `mesh` (replacing its content; unchanged on error), repaired for
/// half-edge models as every reader does (read_mesh).
/// Complexity O(bytes + inflated bytes + mesh insertions). Errors: errc::io_error, and those of
/// parse_3mf.
template <class M, class T = default_traits<M>>
    requires readable_mesh<M, T>
result<read_report> read_3mf(M& mesh, const std::filesystem::path& path, const read_options& options = {}) {
    auto file = detail::input_file::open(path, options.max_input_bytes);
    if (!file) return file.error();
    auto s = parse_3mf(file->text(), path.string(), options);
    if (!s) return s.error();
    return finish_read<M, T>(mesh, std::move(*s), path.string(), "3mf", 0, options);
}

/// Writes the mesh as a 3MF package through `out`: [Content_Types].xml, _rels/.rels and
/// 3D/3dmodel.model, deflated when zlib is available (else stored); coordinates in shortest
/// round-trip form. Faces are triangulated as the STL writer does.
/// Complexity O(V + C). Errors, with nothing written: errc::unsupported naming a non-finite
/// vertex; errc::topology naming a face whose projection is not simple; errc::io_error.
template <class M, class T = default_traits<M>>
    requires writable_mesh<M, T>
result<void> write_3mf_to(const M& mesh, std::ostream& out, const write_options& options = {}) {
    (void)options;
    if (auto ok = detail::refuse_non_finite<M, T>(mesh, "3MF"); !ok) return ok;
    auto plan = detail::plan_stl_triangles<M, T>(mesh);
    if (!plan) return plan.error();
    const std::string model = detail::threemf_model_text<M, T>(mesh, *plan);
    const std::string bytes = detail::threemf_package(model);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) return detail::stream_failed("3MF");
    return {};
}

/// The bytes of write_3mf_to, or its error.
template <class M, class T = default_traits<M>>
    requires writable_mesh<M, T>
result<std::string> format_3mf(const M& mesh, const write_options& options = {}) {
    std::ostringstream s;
    if (auto ok = write_3mf_to<M, T>(mesh, s, options); !ok) return ok.error();
    return std::move(s).str();
}

/// Writes the mesh atomically as a .3mf package. Errors: those of write_3mf_to, nothing written.
template <class M, class T = default_traits<M>>
    requires writable_mesh<M, T>
result<void> write_3mf(const M& mesh, const std::filesystem::path& path, const write_options& options = {}) {
    std::ostringstream staged;
    if (auto ok = write_3mf_to<M, T>(mesh, staged, options); !ok) return detail::at_path(path, ok.error());
    const std::string bytes = std::move(staged).str();
    return detail::write_file_atomically(path, [&](std::ostream& o) {
        o.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        return bool(o);
    });
}

}  // namespace hmira::io
