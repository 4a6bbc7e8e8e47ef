// hmira/algorithms/validation/validate.hpp
// Checks a mesh and returns the problems it finds instead of asserting: tests run it after
// every mutation, tools report it, and a user can decide what to do about each problem.
// The relaxed mode accepts the legal intermediate states of Euler construction.
//
// Options: validate_options. Result: a list of mesh_problem (kind, element, message), empty
// when the mesh is valid. Requires: validate_mesh<M, T>. Entry point: validate(mesh, options).
// The checks themselves are in detail/validate_impl.hpp.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "../../concepts.hpp"

namespace hmira {

/// What validate() checks.
struct validate_options {
    /// Accept isolated vertices, wire edges, faces of fewer than 3 sides and repeated vertices
    /// in a face loop: the legal intermediate states of Euler construction.
    bool relaxed = false;
    /// Also report faces whose area is exactly zero (needs positions).
    bool check_geometry = true;
    /// Stop after this many problems (0: no limit), so a badly broken mesh reports quickly.
    std::size_t max_problems = 1000;
    /// Also report pairs of faces that intersect other than along what they share, decided
    /// exactly (self_intersections.hpp; needs positions). Off by default: it costs a box sweep
    /// over all faces, O(T log T + K), where the other checks are linear.
    bool check_self_intersections = false;
};

enum class problem_kind {
    invalid_reference,         ///< a handle that points to no live element
    degenerate_face,           ///< fewer than 3 vertices, or a vertex repeated in a face
    zero_area_face,            ///< all corners collinear or coincident (geometry check)
    non_manifold_edge,         ///< an edge with more than two face sides
    non_manifold_vertex,       ///< the faces around a vertex form more than one fan
    inconsistent_orientation,  ///< two faces run an edge in the same direction
    isolated_vertex,           ///< a vertex used by no edge or face (legal in relaxed mode)
    wire_edge,                 ///< an edge with no face on either side (legal in relaxed mode)
    broken_link,               ///< halfedge invariants violated (next/prev/opposite/target/face)
    non_finite_position,       ///< a vertex coordinate is NaN or infinite
    self_intersection,         ///< two faces meet other than along what they share (element: the first face)
};

/// One problem: its kind, the index of the element concerned (vertex, face or halfedge index
/// as the message says), and a one-line message naming it.
struct mesh_problem {
    problem_kind kind;        ///< what is wrong
    std::size_t element = 0;  ///< index of the element concerned
    std::string message;      ///< one line naming it
};

/// The models validate() can check: face loops as vertex ranges, with vertex and face indices.
template <class M, class T = default_traits<M>>
concept validate_mesh = face_vertex_range_mesh<M, T> && vertex_index_mesh<M, T> && face_index_mesh<M, T>;

/// Checks the mesh; an empty result means valid.
///
/// Meshes with positions: vertices with a NaN or infinite coordinate (always checked: no
/// geometric operation can use them). Every model: faces of fewer than 3 or repeated vertices
/// (strict mode), faces naming missing vertices, exactly-zero-area faces (check_geometry),
/// edges with more than two face sides, edges run twice in one direction (inconsistent
/// orientation), vertices whose faces form several fans, isolated vertices (strict mode).
/// Halfedge models also: every next/prev/opposite/target/face link, loops of faces and inner
/// rings, vertex fans, boundary halfedges stored at boundary vertices, wire edges (strict).
/// With check_self_intersections, on models with positions and sound face loops, last: each
/// pair of faces self_intersections() reports, as one problem naming both faces.
///
/// \pre none: any state of the mesh, however broken, is reported rather than followed.
/// \post the mesh is unchanged; at most options.max_problems problems (0: all), in the order
///       of the checks above.
/// Complexity: O(V + C log C) for V vertices and C face corners, plus O(H_all) for halfedge
/// models, plus that of self_intersections when asked for.
template <class M, class T = default_traits<M>>
    requires validate_mesh<M, T>
std::vector<mesh_problem> validate(const M& mesh, const validate_options& options = {});

/// Readable name of a problem kind, for reports.
inline const char* to_string(problem_kind k) {
    switch (k) {
        case problem_kind::invalid_reference: return "invalid reference";
        case problem_kind::degenerate_face: return "degenerate face";
        case problem_kind::zero_area_face: return "zero-area face";
        case problem_kind::non_manifold_edge: return "non-manifold edge";
        case problem_kind::non_manifold_vertex: return "non-manifold vertex";
        case problem_kind::inconsistent_orientation: return "inconsistent orientation";
        case problem_kind::isolated_vertex: return "isolated vertex";
        case problem_kind::wire_edge: return "wire edge";
        case problem_kind::broken_link: return "broken link";
        case problem_kind::non_finite_position: return "non-finite position";
        case problem_kind::self_intersection: return "self-intersection";
    }
    return "unknown";
}

}  // namespace hmira

#include "detail/validate_impl.hpp"
