// hmira/io/stl.hpp
// STL, ASCII and binary. STL stores loose triangles, so the reader welds corners whose
// coordinates are exactly equal into shared vertices (a hash of the float bit patterns,
// expected O(1) per corner) to give a connected mesh; the writer writes each face as its
// triangles (face_triangles: concave faces and inner rings handled exactly).//
// Options: read_options (weld_stl, progress that can cancel, input size limit, repair) and
// write_options (stl encoding), io_options.hpp. Result: result<read_report> (read_stl),
// result<stl_soup> (parse_stl), result<void> (write_stl, write_stl_to), result<std::string>
// (format_stl). Requires: readable_mesh / writable_mesh. The welder, the ASCII parser and
// the writer's bytes are in detail/stl_impl.hpp.
#pragma once

#include <filesystem>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../concepts.hpp"
#include "../core/huge_pages.hpp"
#include "../core/result.hpp"
#include "detail/atomic_write.hpp"
#include "detail/face_loops.hpp"
#include "detail/files.hpp"
#include "detail/polygon_soup.hpp"
#include "detail/stl_impl.hpp"
#include "detail/text_format.hpp"
#include "io_options.hpp"

namespace hmira::io {

/// What parse_stl found besides the soup.
struct stl_soup {
    polygon_soup soup;                  ///< the triangles, welded unless asked otherwise
    bool binary = false;                ///< the file was binary STL
    std::size_t dropped_triangles = 0;  ///< triangles whose corners welded together
};

/// Parses STL (ASCII or binary, told apart by the size a binary file must have and the
/// 'solid' keyword) into a soup, welding equal corners unless options.weld_stl is false.
/// Complexity: O(bytes), expected. Errors (errc::parse_error): a binary file whose size does not
/// match its triangle count (the message gives both), truncated ASCII, non-numbers, facets
/// without exactly 3 vertices.
inline result<stl_soup> parse_stl(std::string_view text, const std::string& name, const read_options& options = {}) {
    stl_soup out;
    const bool solid = detail::stl_starts_with_solid(text);
    std::uint64_t count = 0;
    if (text.size() >= 84) {
        std::uint32_t n = 0;
        std::memcpy(&n, text.data() + 80, 4);
        if constexpr (std::endian::native == std::endian::big) n = __builtin_bswap32(n);
        count = n;
    }
    const bool size_matches = text.size() >= 84 && text.size() == 84 + 50 * count;
    if (!size_matches && (!solid || detail::looks_binary(text.substr(std::min<std::size_t>(84, text.size()))))) {
        if (text.size() < 84)
            return fail(errc::parse_error, name + ": byte offset " + std::to_string(text.size()) +
                                               ": file too short for a binary STL (" + std::to_string(text.size()) +
                                               " bytes; the header alone has 84) and not ASCII STL either");
        return fail(errc::parse_error,
                    name + ": byte offset 80: binary STL says " + std::to_string(count) + " triangles, which need " +
                        std::to_string(84 + 50 * count) + " bytes, but the file has " + std::to_string(text.size()) +
                        " (truncated or corrupt file)",
                    static_cast<long long>(count));
    }
    if (!size_matches) {
        detail::stl_builder b(options.weld_stl, text.size() / 200);
        auto r = detail::parse_stl_ascii(text, name, b, options);
        if (!r) return r.error();
        out.dropped_triangles = b.dropped;
        out.soup = b.finish();
        return out;
    }
    out.binary = true;
    detail::stl_builder b(options.weld_stl, static_cast<std::size_t>(count));
    detail::progress_ticker ticker(options.progress, text.size());
    const char* p = text.data() + 84;
    std::array<std::array<float, 3>, 3> tri{};
    for (std::uint64_t t = 0; t < count; ++t, p += 50) {
        for (std::size_t v = 0; v < 3; ++v) {
            std::memcpy(tri[v].data(), p + 12 + 12 * v, 12);
            if constexpr (std::endian::native == std::endian::big)
                for (auto& x : tri[v]) x = std::bit_cast<float>(__builtin_bswap32(std::bit_cast<std::uint32_t>(x)));
            if (!detail::all_finite(tri[v]))
                return fail(errc::parse_error,
                            name + ": byte offset " + std::to_string(p + 12 + 12 * v - text.data()) + ": triangle " +
                                std::to_string(t) + " has a vertex coordinate that is not finite (NaN or infinity)",
                            static_cast<long long>(t));
        }
        b.add(tri);
        if ((t & 0xffff) == 0 && !ticker.tick(static_cast<std::uint64_t>(p - text.data())))
            return detail::progress_ticker::cancelled(name + ": triangle " + std::to_string(t));
    }
    ticker.finish();
    out.dropped_triangles = b.dropped;
    out.soup = b.finish();
    return out;
}

/// Reads an STL file into `mesh`, replacing its content; on error the mesh is unchanged.
/// Triangles whose corners weld together are dropped and counted in the report.
/// Complexity: O(bytes + mesh insertions), expected.
template <class M, class T = default_traits<M>>
    requires readable_mesh<M, T>
result<read_report> read_stl(M& mesh, const std::filesystem::path& path, const read_options& options = {}) {
    auto file = detail::input_file::open(path, options.max_input_bytes);
    if (!file) return file.error();
    auto s = parse_stl(file->text(), path.string(), options);
    if (!s) return s.error();
    return finish_read<M, T>(mesh, std::move(s->soup), path.string(), s->binary ? "stl (binary)" : "stl (ascii)",
                             s->dropped_triangles, options);
}

/// Writes STL through `out`. Triangles are written as they are; every other face (concave, or
/// with inner rings) as its face_triangles, and a face without area as a zero-area fan (see
/// detail::plan_stl_triangles). Facet normals are computed from the corners (zero for
/// degenerate triangles). Per-vertex attributes cannot be stored.
/// Errors, with nothing written: those of write_stl.
template <class M, class T = default_traits<M>>
    requires writable_mesh<M, T>
result<void> write_stl_to(const M& mesh, std::ostream& stream, const write_options& options = {}) {
    if (auto ok = detail::refuse_non_finite<M, T>(mesh, "STL", true); !ok) return ok;
    auto plan = detail::plan_stl_triangles<M, T>(mesh);
    if (!plan) return plan.error();
    if (!detail::write_stl_planned<M, T>(mesh, stream, *plan, options)) return detail::stream_failed("STL");
    return {};
}

/// STL bytes of the mesh (see write_stl_to), or its error.
template <class M, class T = default_traits<M>>
    requires writable_mesh<M, T>
result<std::string> format_stl(const M& mesh, const write_options& options = {}) {
    std::ostringstream s;
    if (auto ok = write_stl_to<M, T>(mesh, s, options); !ok) return ok.error();
    return std::move(s).str();
}

/// Writes the mesh as STL, atomically. Coordinates become float. Faces are triangulated as
/// write_stl_to says, before the file is touched.
/// Complexity: O(C) for triangle meshes; face_triangles' cost on the other faces.
/// Errors: errc::unsupported naming a vertex with a non-finite coordinate or one beyond float's
/// range; errc::topology (or
/// the code face_triangles gives) naming a face whose projection is not simple; with no file
/// written and any existing file unchanged; errc::io_error.
template <class M, class T = default_traits<M>>
    requires writable_mesh<M, T>
result<void> write_stl(const M& mesh, const std::filesystem::path& path, const write_options& options = {}) {
    if (auto ok = detail::refuse_non_finite<M, T>(mesh, "STL", true); !ok) return detail::at_path(path, ok.error());
    auto plan = detail::plan_stl_triangles<M, T>(mesh);
    if (!plan) return plan.error();
    return detail::write_file_atomically(
        path, [&](std::ostream& o) { return detail::write_stl_planned<M, T>(mesh, o, *plan, options); });
}

}  // namespace hmira::io
