// hmira/algorithms/repair/repair_polygon_soup.hpp
// Turns a polygon soup (faces as vertex-index lists) into one that every half-edge model can
// hold: degenerate faces dropped, edges with more than two faces cut, faces oriented
// consistently and non-manifold vertices split. Arrays in, arrays out, plus a report.
//
// Options: soup_repair_options. Result: repaired_polygon_soup (with its soup_repair_report).
// Entry point: repair_polygon_soup. The steps are in detail/repair_polygon_soup_impl.hpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "../../core/result.hpp"

namespace hmira {

/// What to do with a face that would make an edge non-manifold (a third or further face on an
/// edge that already has two).
enum class nonmanifold_edge_policy {
    duplicate_vertices,  ///< keep the face; it gets its own copies of the edge's vertices
    drop_faces,          ///< leave the face out
};

/// How repair_polygon_soup repairs.
struct soup_repair_options {
    /// Faces beyond the second on an edge: keep them on copied vertices, or drop them.
    nonmanifold_edge_policy nonmanifold_edges = nonmanifold_edge_policy::duplicate_vertices;
    /// How many element indices each entry of the report lists (the first ones found).
    std::size_t listed = 8;
};

/// A count of repaired elements and the first few of them (input indices, ascending).
struct repair_count {
    std::size_t count = 0;           ///< how many elements
    std::vector<std::size_t> first;  ///< the first soup_repair_options::listed of them
};

/// What repair_polygon_soup did. Face and vertex indices are input indices.
struct soup_repair_report {
    repair_count merged_corners;          ///< faces with repeated consecutive corners ("a b b c"), kept merged
    repair_count degenerate_faces;        ///< faces dropped: < 3 distinct corners, or a vertex repeated apart
    std::size_t nonmanifold_edges = 0;    ///< edges that had more than two faces
    repair_count nonmanifold_edge_faces;  ///< faces past the second on such an edge: cut free or dropped
    repair_count detached_faces;          ///< faces that stayed unglueable after the cut: all their vertices copied
    repair_count flipped_faces;           ///< faces whose corner order was reversed to agree with their neighbours
    std::size_t orientation_cuts = 0;     ///< edges left open where no orientation agrees (Moebius-like)
    repair_count split_vertices;          ///< input vertices that now have copies (split, or ends of cut edges)
    std::size_t added_vertices = 0;       ///< vertices added as copies
    std::size_t dropped_faces = 0;        ///< faces dropped in all (degenerate, and drop_faces ones)

    /// True when the soup needed no change at all.
    bool clean() const noexcept {
        return merged_corners.count == 0 && degenerate_faces.count == 0 && nonmanifold_edge_faces.count == 0 &&
               detached_faces.count == 0 && flipped_faces.count == 0 && orientation_cuts == 0 && added_vertices == 0;
    }
    /// One line listing what was done, e.g. "dropped 2 degenerate faces (3, 17); flipped 5
    /// faces (0, 1, 4, 9, 12); split 1 vertex (0) into 1 extra copy", or "no repair needed".
    std::string summary() const;
};

/// A repaired soup. Vertex i < vertex_count is input vertex i; vertex vertex_count + k is a
/// copy of input vertex copied_from[k]. Face i is input face face_source[i], with its corners
/// merged, possibly reversed, and renamed onto copies.
struct repaired_polygon_soup {
    std::vector<std::uint64_t> face_offsets{0};  ///< face i is corners[face_offsets[i] .. face_offsets[i+1])
    std::vector<std::uint32_t> corners;          ///< vertex indices, as described above
    std::vector<std::uint32_t> copied_from;      ///< input vertex of each added copy
    std::vector<std::size_t> face_source;        ///< input face of each output face
    soup_repair_report report;                   ///< what was done
    std::size_t vertex_count = 0;                ///< number of output vertices (input vertices and copies)
    std::size_t face_count() const noexcept { return face_offsets.size() - 1; }  ///< number of output faces
    /// The input vertex that output vertex v stands for.
    std::size_t source_vertex(std::size_t v) const noexcept {
        return v < vertex_count - copied_from.size() ? v : copied_from[v - (vertex_count - copied_from.size())];
    }
};

/// Repairs a polygon soup so that every half-edge model (halfedge_mesh, winged_edge_mesh, OpenMesh, CGAL
/// Surface_mesh) accepts all its faces, in any order:
///  1. repeated consecutive corners are merged; a face left with fewer than 3 corners, or with a vertex repeated
///     elsewhere, is dropped as degenerate;
///  2. on an edge with more than two faces, the first face is glued to one other face (one that runs the edge the
///     other way if there is one) and the rest are cut free there (duplicate_vertices) or dropped (drop_faces);
///  3. each connected piece is oriented consistently by a breadth-first walk, keeping the orientation most of its
///     faces had; an edge where no orientation agrees (a Moebius band) is left open;
///  4. the corners around each vertex are grouped into the fans they form through glued edges, and every fan
///     after the first gets its own copy of the vertex.
/// No input vertex is removed (unused ones stay, isolated), so vertex i < vertex_count keeps its index, and
/// positions or attributes of copies are those of copied_from.
///
/// \pre every corner is < vertex_count; face_offsets starts at 0, never decreases and ends at corners.size();
///      vertex_count < 2^32. Otherwise an errc::invalid_argument error names the face.
/// \post every edge of the output has one or two faces, two faces on an edge run it in opposite directions, the
///       faces around every vertex form one fan, and no face repeats a vertex. Under duplicate_vertices,
///       face_count() = input faces - degenerate faces.
/// Complexity: O(C log d + V) for C corners and largest vertex degree d (so O(C log C) at worst): bucketing by
/// vertex, a sort of each vertex's edges, a union-find over corners and breadth-first walks; memory O(C + V).
[[nodiscard]] inline result<repaired_polygon_soup> repair_polygon_soup(std::size_t vertex_count,
                                                                       std::span<const std::uint64_t> face_offsets,
                                                                       std::span<const std::uint32_t> corners,
                                                                       const soup_repair_options& options = {});

}  // namespace hmira

#include "detail/repair_polygon_soup_impl.hpp"
