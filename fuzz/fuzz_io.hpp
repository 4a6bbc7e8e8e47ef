// fuzz/fuzz_io.hpp
// The body of every parser fuzz target, shared with the corpus regression test: parse the
// bytes; if they parse, build each of hmira's face_vertex_mesh and halfedge_mesh from them,
// and for each mesh that takes the soup, check that it holds exactly the soup's faces, write
// it in the same format and parse that again, which must succeed with the same counts.
// Returns "" or a description of the violated property.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

namespace hmira_fuzz {

/// What building one kind of mesh from a soup gave: whether the mesh took it, and the
/// violated property ("" if none).
struct mesh_outcome {
    bool accepted = false;  ///< the mesh took every face of the soup
    std::string problem;    ///< "" or what went wrong
};

/// Builds a Mesh from the soup and checks it against the soup, then writes it in `format` and
/// reads that back. `kind` names the mesh in the returned problem.
template <class Mesh>
mesh_outcome build_and_round_trip(const hmira::io::polygon_soup& soup, hmira::io::file_format format,
                                  const std::string& kind) {
    using namespace hmira;
    Mesh mesh;
    auto built = io::assign_from_soup(mesh, soup, [](std::size_t) { return std::string("fuzz"); });
    if (!built) {
        // A rejected soup must name the face, on one line, and leave the mesh as it was (empty).
        const auto& e = built.error();
        if (e.message.empty() || e.message.find('\n') != std::string::npos)
            return {false, kind + ": a rejection message that is empty or of several lines: " + e.message};
        if (e.element < 0 || static_cast<std::size_t>(e.element) >= soup.face_count())
            return {false, kind + ": a rejection naming no face of the soup: " + e.message};
        if (mesh.vertex_count() != 0 || mesh.face_count() != 0)
            return {false, kind + ": a rejected soup changed the mesh"};
        return {false, ""};
    }
    if (mesh.vertex_count() != soup.points.size() || mesh.face_count() != soup.face_count())
        return {true, kind + ": the mesh's counts differ from the soup's"};
    // Vertices are added in soup order, so vertex handle i is soup point i, and every face
    // must list the soup's corners in the soup's order, from its first corner.
    for (std::size_t f = 0; f < soup.face_count(); ++f) {
        auto k = soup.face_offsets[f];
        for (auto v : mesh.face_vertices(face_handle(f))) {
            if (k == soup.face_offsets[f + 1] || v.index != soup.indices[k])
                return {true, kind + ": face " + std::to_string(f) + " does not hold the soup's corners"};
            ++k;
        }
        if (k != soup.face_offsets[f + 1]) return {true, kind + ": face " + std::to_string(f) + " lost corners"};
    }
    result<std::string> again = std::string();
    switch (format) {
        case io::file_format::obj: again = io::format_obj(mesh); break;
        case io::file_format::off: again = io::format_off(mesh); break;
        case io::file_format::ply: again = io::format_ply(mesh, {.ply = io::ply_encoding::binary_big_endian}); break;
        case io::file_format::stl: again = io::format_stl(mesh); break;
        case io::file_format::glb:
        case io::file_format::gltf: again = io::format_gltf(mesh); break;
        case io::file_format::vtp: again = io::format_vtk(mesh, io::vtk_encoding::xml_base64); break;
        case io::file_format::vtk: again = io::format_vtk(mesh, io::vtk_encoding::legacy_binary); break;
        case io::file_format::threemf: again = io::format_3mf(mesh); break;
    }
    // What a reader accepted (finite coordinates, one loop per face) the writer must write.
    if (!again) return {true, kind + ": the writer refused what the reader read: " + again.error().message};
    auto back = io::parse_soup(*again, format, "again");
    if (!back) return {true, kind + ": re-reading what the writer wrote failed: " + back.error().message};
    // STL stores no shared vertices, so only the other formats keep the counts.
    if (format != io::file_format::stl &&
        (back->points.size() != soup.points.size() || back->face_count() != soup.face_count()))
        return {true, kind + ": the round trip changed the counts"};
    return {true, ""};
}

/// The whole property for one input (see the file comment).
inline std::string one_input(hmira::io::file_format format, const std::uint8_t* data, std::size_t size) {
    using namespace hmira;
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    auto soup = io::parse_soup(bytes, format, "fuzz");
    if (!soup) {
        if (soup.error().message.empty()) return "an error without a message";
        if (soup.error().message.find('\n') != std::string::npos)
            return "a message of several lines: " + soup.error().message;
        return "";
    }
    // Well-formed soup: indices in range, faces of 3+ corners, attributes sized right.
    for (auto i : soup->indices)
        if (i >= soup->points.size()) return "index out of range in an accepted soup";
    for (std::size_t f = 0; f < soup->face_count(); ++f)
        if (soup->face_offsets[f + 1] < soup->face_offsets[f] + 3) return "face with fewer than 3 corners accepted";
    if (!soup->attributes.normals.empty() && soup->attributes.normals.size() != soup->points.size())
        return "normals not one per vertex";
    if (!soup->attributes.colors.empty() && soup->attributes.colors.size() != soup->points.size())
        return "colours not one per vertex";

    const auto polygons = build_and_round_trip<face_vertex_mesh>(*soup, format, "face_vertex_mesh");
    if (!polygons.problem.empty()) return polygons.problem;
    const auto halfedges = build_and_round_trip<halfedge_mesh>(*soup, format, "halfedge_mesh");
    if (!halfedges.problem.empty()) return halfedges.problem;
    // The halfedge mesh refuses everything the face-vertex mesh refuses, and more (non-manifold).
    if (halfedges.accepted && !polygons.accepted) return "halfedge_mesh took a soup that face_vertex_mesh refused";
    return "";
}

}  // namespace hmira_fuzz
