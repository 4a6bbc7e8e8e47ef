// hmira/io/io_options.hpp
// What the readers return besides the mesh (per-vertex normals and colours, a report) and the
// options the readers and writers take. Shared by every format, so the CLI and user code can
// move attributes from any format to any other.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "../algorithms/repair/repair_polygon_soup.hpp"
#include "../core/progress.hpp"
#include "../core/vec3.hpp"

namespace hmira::io {

/// Per-vertex data that some formats carry. Each vector is either empty (the file had none)
/// or holds one entry per vertex, indexed by vertex index: for a reader, the order in which
/// it created the vertices (the file's order); for a writer, T::vertex_index(mesh, v).
///
/// Meshes with named properties (hmira's reference meshes, or any mesh with
/// `add_vertex_property<T>(name)` / `get_vertex_property<T>(name)`) also get them as the
/// properties "v:normal" (vec3<float>) and "v:color" (std::array<std::uint8_t, 4>, RGBA) on
/// reading, and writers use those properties when no explicit attributes are given.
struct mesh_attributes {
    std::vector<vec3<float>> normals;                 ///< unit normals, or empty
    std::vector<std::array<std::uint8_t, 4>> colors;  ///< RGBA, 0..255, or empty
    /// True when the file had neither normals nor colours.
    bool empty() const noexcept { return normals.empty() && colors.empty(); }
};

/// How the readers read.
struct read_options {
    /// STL only: weld corners with exactly equal coordinates into one vertex (-0 equals +0).
    /// Without welding every triangle gets three vertices of its own (a soup).
    bool weld_stl = true;
    /// Called every few megabytes of input with the share parsed; returning false stops the
    /// reader, which returns errc::cancelled and leaves the mesh unchanged. Empty for none.
    progress_function progress = {};
    /// Largest input read from a non-regular file (pipe, device, FIFO) before giving up with
    /// an error naming the file and the limit; regular files are read up to their size.
    std::uint64_t max_input_bytes = std::uint64_t{4} << 30;
    /// Half-edge models (halfedge_mesh, winged_edge_mesh, OpenMesh, CGAL): repair what the
    /// mesh could not hold (see repair_polygon_soup) and say so in read_report::repair. False:
    /// refuse such a file with an error naming the first face at fault. Other models (the
    /// face-vertex mesh) always get the file as it is.
    bool repair = true;
    /// When repairing: faces beyond the second on an edge keep copied vertices, or are dropped.
    nonmanifold_edge_policy nonmanifold_edges = nonmanifold_edge_policy::duplicate_vertices;
};

/// What a reader did besides filling the mesh.
struct read_report {
    std::string format;                 ///< "obj", "off", "ply (binary little endian)", ...
    mesh_attributes attributes;         ///< normals / colours found in the file
    std::size_t dropped_triangles = 0;  ///< STL: triangles whose corners welded together
    /// What was repaired while reading into a half-edge model (clean() when nothing was).
    soup_repair_report repair;
    /// Vertices the file has. The mesh's vertex i < file_vertices is the file's vertex i.
    std::size_t file_vertices = 0;
    /// Repair copies: the mesh's vertex file_vertices + k is a copy of the file's vertex
    /// copied_from[k] (so every copy of a split vertex can be traced to it). Empty: no copies.
    std::vector<std::uint32_t> copied_from;
    /// The mesh's face i is the file's face face_source[i]. Empty when every face was created,
    /// in file order (nothing dropped).
    std::vector<std::size_t> face_source;
};

/// The three PLY encodings.
enum class ply_encoding {
    ascii,                 ///< text
    binary_little_endian,  ///< binary, least significant byte first
    binary_big_endian,     ///< binary, most significant byte first
};
/// The two STL encodings.
enum class stl_encoding {
    binary,  ///< 80-byte header, count, 50 bytes per triangle
    ascii,   ///< solid / facet / vertex text
};
/// Coordinate type in binary PLY: the mesh's own scalar, or forced.
enum class ply_scalar {
    mesh,     ///< float for float meshes, double otherwise
    float32,  ///< always float
    float64,  ///< always double
};

/// How the writers write.
struct write_options {
    ply_encoding ply = ply_encoding::binary_little_endian;  ///< PLY encoding
    ply_scalar ply_coordinates = ply_scalar::mesh;          ///< PLY coordinate type (binary and text precision)
    stl_encoding stl = stl_encoding::binary;                ///< STL encoding
    /// Explicit per-vertex normals / colours to write (null: the mesh's "v:normal" /
    /// "v:color" properties if it has them). Ignored by formats that cannot hold them (STL).
    const mesh_attributes* attributes = nullptr;
    /// Write normals and colours at all (false: geometry and faces only).
    bool write_attributes = true;
};

}  // namespace hmira::io
