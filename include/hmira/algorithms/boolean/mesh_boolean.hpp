// hmira/algorithms/boolean/mesh_boolean.hpp
// Union, intersection, difference and symmetric difference of two closed meshes, exactly: the
// meshes are co-refined along their intersection with exact predicates on constructed points, each
// piece is labelled inside or outside the other mesh, and the pieces an operation keeps are
// written to any mutable model. Inputs may be different models.
//
// Options: boolean_options. Result: boolean_report. Requires: boolean_input_mesh for the inputs,
// copy_target_mesh for the output. Entry point: mesh_boolean(out, a, b, options). The machinery is
// in detail/ (cut_triangle, arrangement, mesh_boolean_impl).
#pragma once

#include <cstddef>
#include <array>
#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/enum_names.hpp"
#include "../../core/progress.hpp"
#include "../../core/result.hpp"
#include "../copy/copy_mesh.hpp"
#include "../triangulation/triangulate_faces.hpp"

namespace hmira {

/// The operation: which pieces of the two boundaries bound the result.
enum class boolean_op : std::uint8_t {
    union_,        ///< points in A or in B
    intersection,  ///< points in both
    difference,    ///< points in A and not in B
    xor_,          ///< points in exactly one
};

/// The operations' names, as the front ends spell them (core/enum_names.hpp).
constexpr auto enum_names(boolean_op) {
    using n = std::pair<boolean_op, std::string_view>;
    return std::array{n{boolean_op::union_, "union"}, n{boolean_op::intersection, "intersection"},
                      n{boolean_op::difference, "difference"}, n{boolean_op::xor_, "xor"}};
}

/// Options of mesh_boolean.
struct boolean_options {
    /// The operation.
    boolean_op op = boolean_op::union_;
    /// Called between phases and blocks of triangles; returning false cancels (errc::cancelled).
    progress_function progress = {};
    /// Worker threads for the parallel stages (0: all cores). The result does not depend on it.
    unsigned threads = 0;
};

/// Where an output face came from.
struct boolean_face_origin {
    std::uint8_t mesh = 0;  ///< 0 for a, 1 for b
    std::size_t face = 0;   ///< face index in that mesh
};

/// What mesh_boolean did.
struct boolean_report {
    std::vector<boolean_face_origin> faces;  ///< per output face, in the output's face order
    std::size_t intersecting_pairs = 0;      ///< candidate triangle pairs tested
    std::size_t cut_triangles = 0;           ///< input triangles cut by the other mesh
    std::size_t snapped_vertices = 0;        ///< distinct exact points that rounded to one double
    std::size_t degenerate_faces = 0;        ///< output faces whose rounded corners are collinear
    std::size_t rounding_intersections = 0;  ///< output face pairs that rounding made intersect
};

/// The models mesh_boolean reads: face loops, positions, vertex and face indices.
template <class M, class T = default_traits<M>>
concept boolean_input_mesh = face_triangulable_mesh<M, T> && vertex_index_mesh<M, T>;

/// Writes op(a, b) into `out`, replacing its content; each output face is a triangle.
///
/// Every triangle pair of a and b that meets is intersected exactly (points where an edge meets a
/// plane are kept as implicit points), every triangle is cut along its intersection segments by
/// an exact constrained triangulation in its projection plane, and coincident points are merged
/// exactly. Each piece is then labelled against the other mesh: a piece that lies in a coplanar
/// face of it as "on" (same or opposite orientation), otherwise as in or out by the exact
/// winding number (inside_closed) of an input vertex of its patch (pieces joined across
/// uncut edges), or, when a patch has no input vertex off the other surface, of the rounded
/// centroid of its largest piece; that fallback is the one decision not made exactly. Points are
/// rounded to double once, at output; distinct points that round to the same double are merged
/// and counted in snapped_vertices, and faces that collapse are dropped. The rounded result is
/// checked exactly: faces whose corners became collinear and face pairs that now intersect
/// (as self_intersections decides) are counted in the report; they are not yet repaired.
///
/// \pre a and b are closed, consistently oriented outward, and each free of self-intersections
///   (self_intersections() empty); polygon faces are cut as face_triangles does.
/// \post a and b are only read; `out` holds the result (empty for an empty result), or is
///   unchanged on error. A ∪ ∅ = A, A ∩ ∅ = ∅, A − ∅ = A, ∅ − B = ∅.
/// Errors (out unchanged): errc::invalid_argument naming the mesh and vertex with a coordinate
/// that is not finite or outside predicates::in_implicit_range; errc::unsupported when one
/// triangle's cuts cross each other (an input that intersects itself); errc::cancelled; those
/// of building `out`.
/// Complexity: O(T log T + K + sum over cut triangles of n_t^3 + P F) for T triangles, K box-
/// overlapping pairs, n_t cuts in triangle t, P patches and F faces: each pair is O(1) exact
/// predicates, almost all settled by the floating-point filter.
template <class MO, class MA, class MB, class TO = default_traits<MO>, class TA = default_traits<MA>,
          class TB = default_traits<MB>>
    requires copy_target_mesh<MO, TO> && boolean_input_mesh<MA, TA> && boolean_input_mesh<MB, TB>
[[nodiscard]] result<boolean_report> mesh_boolean(MO& out, const MA& a, const MB& b,
                                                  const boolean_options& options = {});

}  // namespace hmira

#include "detail/mesh_boolean_impl.hpp"
