// hmira/io/gltf.hpp
// glTF 2.0: .glb (binary container) and .gltf (JSON, buffers as base64 data URIs or files beside
// it). The reader takes the default scene's triangle primitives with their node transforms, and
// per-vertex NORMAL and COLOR_0 when every primitive has them; the writer writes one triangle
// primitive (faces triangulated as for STL), float positions, uint32 indices, and normals and
// colours (RGBA bytes, no colour-space conversion) when the mesh has them.
//
// Options: read_options (progress is not polled: parsing is one pass over the accessors; the
// input size limit and repair apply) and write_options (write_attributes), io_options.hpp.
// Result: result<polygon_soup> (parse_gltf), result<read_report> (read_gltf), result<void>
// (write_gltf, write_gltf_to), result<std::string> (format_gltf). Requires readable_mesh / writable_mesh. Machinery in
// detail/gltf_impl.hpp and detail/json.hpp.
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
#include "detail/gltf_impl.hpp"
#include "detail/polygon_soup.hpp"
#include "io_options.hpp"

namespace hmira::io {

/// The two glTF encodings a writer chooses between.
enum class gltf_encoding {
    glb,   ///< one binary file: JSON chunk and binary chunk
    gltf,  ///< one JSON file, the buffer inline as a base64 data URI
};

/// Parses glTF 2.0 (GLB bytes, or .gltf JSON) into a soup: each triangle primitive of the
/// default scene's nodes, positions transformed by the node hierarchy (every mesh untransformed
/// when the file has no scene). Vertices are not welded: primitives keep their own. `load`
/// reads a buffer's relative URI (files beside a .gltf); empty, such a buffer is an error.
/// \pre none: any bytes are safe. Allocation is bounded by O(bytes): every accessor is checked
/// against its buffer view and buffer before it is read.
/// Complexity O(bytes + nodes x their meshes' vertices).
/// Errors: errc::parse_error ("<name>: <what> [where]"): malformed GLB or JSON (with the byte
/// offset), a missing or out-of-range reference (naming the accessor, view, buffer, node or
/// primitive), an index out of range, a non-finite position; errc::unsupported: sparse
/// accessors, primitives other than triangles, 2^32 or more vertices.
inline result<polygon_soup> parse_gltf(std::string_view data, const std::string& name, const read_options& options = {},
                                       const detail::gltf_uri_loader& load = {}) {
    (void)options;
    auto container = detail::split_glb(data, name);
    if (!container) return container.error();
    detail::gltf_document doc;
    doc.name = name;
    auto root = detail::json_reader(container->json, container->glb ? name + " (JSON chunk)" : name).parse();
    if (!root) return root.error();
    doc.root = std::move(*root);
    if (!doc.root.is_object()) return doc.bad("the glTF document is not a JSON object");
    {
        const auto* asset = doc.root.find("asset");
        const auto* version = asset ? asset->find("version") : nullptr;
        if (!version || !version->is_string() || !version->text.starts_with("2."))
            return fail(errc::unsupported, name + ": not a glTF 2.x file (asset.version missing or not 2.x)");
    }
    if (auto ok = detail::load_buffers(doc, container->glb ? container->bin : std::string_view{}, load); !ok)
        return ok.error();
    return detail::gltf_soup(doc);
}

/// Reads a .glb or .gltf file into `mesh` (replacing its content; unchanged on error), repaired
/// for half-edge models as every reader does (read_mesh), normals and colours in the report.
/// Buffers named by relative URIs are read from beside the file, within options.max_input_bytes.
/// Complexity O(bytes + mesh insertions). Errors: errc::io_error, and those of parse_gltf.
template <class M, class T = default_traits<M>>
    requires readable_mesh<M, T>
result<read_report> read_gltf(M& mesh, const std::filesystem::path& path, const read_options& options = {}) {
    auto file = detail::input_file::open(path, options.max_input_bytes);
    if (!file) return file.error();
    const auto folder = path.parent_path();
    auto s = parse_gltf(file->text(), path.string(), options, [&](const std::string& uri) {
        return detail::read_file(folder / uri, options.max_input_bytes);
    });
    if (!s) return s.error();
    const bool glb = file->text().size() >= 4 && detail::read_le32(file->text().data()) == detail::glb_magic;
    return finish_read<M, T>(mesh, std::move(*s), path.string(), glb ? "glb" : "gltf", 0, options);
}

/// Writes the mesh as glTF through `out` (see gltf_encoding). Faces are triangulated as the STL
/// writer does; positions are float (a coordinate beyond float's range is refused).
/// Complexity O(V + C). Errors, with nothing written: errc::unsupported naming a vertex that is
/// not finite; errc::topology naming a face whose projection is not simple; errc::io_error.
template <class M, class T = default_traits<M>>
    requires writable_mesh<M, T>
result<void> write_gltf_to(const M& mesh, std::ostream& out, gltf_encoding encoding = gltf_encoding::glb,
                           const write_options& options = {});

/// The bytes of write_gltf_to, or its error.
template <class M, class T = default_traits<M>>
    requires writable_mesh<M, T>
result<std::string> format_gltf(const M& mesh, gltf_encoding encoding = gltf_encoding::glb,
                                const write_options& options = {}) {
    std::ostringstream s;
    if (auto ok = write_gltf_to<M, T>(mesh, s, encoding, options); !ok) return ok.error();
    return std::move(s).str();
}

/// Writes the mesh atomically as .glb or .gltf, chosen by the extension (".gltf": JSON with the
/// buffer inline; anything else: GLB). Errors: those of write_gltf_to, with nothing written.
template <class M, class T = default_traits<M>>
    requires writable_mesh<M, T>
result<void> write_gltf(const M& mesh, const std::filesystem::path& path, const write_options& options = {}) {
    std::string ext = path.extension().string();
    for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const auto encoding = ext == ".gltf" ? gltf_encoding::gltf : gltf_encoding::glb;
    std::ostringstream staged;
    if (auto ok = write_gltf_to<M, T>(mesh, staged, encoding, options); !ok) return detail::at_path(path, ok.error());
    const std::string bytes = std::move(staged).str();
    return detail::write_file_atomically(path, [&](std::ostream& o) {
        o.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        return bool(o);
    });
}

template <class M, class T>
    requires writable_mesh<M, T>
result<void> write_gltf_to(const M& mesh, std::ostream& out, gltf_encoding encoding, const write_options& options) {
    if (auto ok = detail::refuse_non_finite<M, T>(mesh, "glTF", true); !ok) return ok;
    auto plan = detail::plan_stl_triangles<M, T>(mesh);
    if (!plan) return plan.error();
    auto bytes = detail::gltf_bytes<M, T>(mesh, *plan, encoding == gltf_encoding::glb, options);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) return detail::stream_failed("glTF");
    return {};
}

}  // namespace hmira::io
