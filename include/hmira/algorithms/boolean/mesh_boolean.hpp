// hmira/algorithms/boolean/mesh_boolean.hpp
// Union, intersection, difference and symmetric difference of two closed meshes, exactly: the
// meshes are co-refined along their intersections (with each other and with themselves) with
// exact predicates on constructed points, each piece gets the winding numbers of both inputs on
// its two sides, and the pieces an operation keeps are written to any mutable model. Inputs may
// be different models, and may intersect themselves or nest.
//
// Options: boolean_options. Result: boolean_report. Requires: boolean_input_mesh for the inputs,
// copy_target_mesh for the output. Entry point: mesh_boolean(out, a, b, options). Machinery in
// detail/ (cut_triangle, arrangement, segment_crossings, cell_windings, mesh_boolean_impl).
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
    unsigned threads = 0;  ///< worker threads of the parallel stages (0: all cores); the result does not depend on it
};

/// Where an output face came from.
struct boolean_face_origin {
    std::uint8_t mesh = 0;  ///< 0 for a, 1 for b
    std::size_t face = 0;   ///< face index in that mesh
};

/// What mesh_boolean did.
struct boolean_report {
    std::vector<boolean_face_origin> faces;  ///< per output face, in the output's face order
    std::size_t intersecting_pairs = 0;      ///< candidate pairs of a and b tested (make_solid: of its mesh)
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
/// A point is in op(a, b) by the winding numbers w_a, w_b of the inputs around it: union is
/// w_a > 0 or w_b > 0, intersection both, difference w_a > 0 and not w_b > 0, xor exactly one.
/// Every pair of triangles that meets (of one input too, other than along the edge or vertex it
/// shares) is intersected exactly, with implicit points where an edge meets a plane or three
/// planes meet; every triangle is cut along its segments by an exact constrained triangulation.
/// The winding numbers on both sides of every piece are found exactly (detail/cell_windings.hpp);
/// a piece is kept where op differs on its two sides, oriented towards the outside. Where clean
/// inputs overlap in one plane, pieces are labelled against the other mesh instead, with one
/// decision not exact (detail/mesh_boolean_impl.hpp). Points are rounded once, at output: points
/// that round alike are merged (snapped_vertices), collapsed faces dropped, and faces made
/// collinear or intersecting by rounding counted in the report, not yet repaired.
///
/// \pre a and b are closed (every edge run as often one way as the other), self-intersecting,
///   nested and inverted shells included; polygon faces are cut as face_triangles does.
/// \post a and b are only read; `out` holds the result (empty for an empty result), or is
///   unchanged on error. A ∪ ∅ = A, A ∩ ∅ = ∅, A − ∅ = A, ∅ − B = ∅.
/// Errors (out unchanged): errc::invalid_argument naming the mesh and vertex with a coordinate
/// that is not finite or outside predicates::in_implicit_range; errc::unsupported when an input
/// that intersects itself is not closed, has triangles overlapping in one plane (with its own or
/// the other's), or spans more than 90 bits from its coarsest to its finest coordinate bit, or
/// when one triangle's cuts cannot be triangulated; errc::cancelled; those of building `out`.
/// Complexity: O(T log T + K + sum over cut triangles of n_t^3 + E log E + C T) for T triangles,
/// K box-overlapping pairs (of one mesh and of both), n_t cuts in triangle t, E edges where more
/// than two pieces meet and C connected parts of the arrangement: each pair is O(1) exact
/// predicates, almost all settled by the floating-point filter.
template <class MO, class MA, class MB, class TO = default_traits<MO>, class TA = default_traits<MA>,
          class TB = default_traits<MB>>
    requires copy_target_mesh<MO, TO> && boolean_input_mesh<MA, TA> && boolean_input_mesh<MB, TB>
[[nodiscard]] result<boolean_report> mesh_boolean(MO& out, const MA& a, const MB& b,
                                                  const boolean_options& options = {});

}  // namespace hmira

#include "detail/mesh_boolean_impl.hpp"
