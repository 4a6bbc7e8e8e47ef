// hmira/io/ply_writer.hpp
// Writes a mesh as Stanford PLY, in any of the three encodings.
//
// Options (write_options, io_options.hpp): `ply` picks the encoding (ascii, binary little or
// big endian); `ply_coordinates` the coordinate type (the mesh's scalar, float32 or float64);
// `attributes` and `write_attributes` which per-vertex normals and colours are written.
// Result: result<void> (result<std::string> for format_ply); on error nothing is written.
// Requires: writable_mesh<M, T>.
// Entry points: write_ply (a file, replaced atomically), write_ply_to (a stream) and format_ply
// (a string). The byte-level machinery is in detail/ply_writer_impl.hpp.
#pragma once

#include <filesystem>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>

#include "../concepts.hpp"
#include "../core/result.hpp"
#include "detail/atomic_write.hpp"
#include "detail/face_loops.hpp"
#include "detail/ply_writer_impl.hpp"
#include "io_options.hpp"

namespace hmira::io {

/// Writes PLY through `out` (an error, with nothing written, for a face with inner rings or a non-finite
/// coordinate; see write_ply) in the chosen encoding: x y z (the mesh's scalar type unless
/// options say otherwise), nx ny nz and red green blue alpha when there are attributes, and
/// faces as "list uchar int vertex_indices" ("list uint int" if a face has > 255 vertices).
template <class M, class T = default_traits<M>>
    requires writable_mesh<M, T>
result<void> write_ply_to(const M& mesh, std::ostream& stream, const write_options& options = {}) {
    // Before any byte is written.
    if (auto ok = detail::refuse_unwritable<M, T>(mesh, "PLY", options.ply_coordinates == ply_scalar::float32); !ok)
        return ok;
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
    if (auto ok = detail::refuse_unwritable<M, T>(mesh, "PLY", options.ply_coordinates == ply_scalar::float32); !ok)
        return detail::at_path(path, ok.error());
    return detail::write_file_atomically(path,
                                         [&](std::ostream& o) { return detail::put_ply<M, T>(mesh, o, options); });
}

}  // namespace hmira::io
