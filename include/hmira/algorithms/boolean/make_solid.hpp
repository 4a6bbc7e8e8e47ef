// hmira/algorithms/boolean/make_solid.hpp
// The solid a closed surface bounds, as a clean surface: self-intersections are resolved exactly
// and only the boundary of the points the surface winds around (winding number > 0) is kept, so
// overlapping parts merge into one, inner shells of a region covered twice disappear and
// inverted shells are dropped. The repair a 3D printer needs from a self-intersecting soup.
//
// Options: make_solid_options. Result: boolean_report (mesh_boolean's report; every face from
// mesh 0). Requires: boolean_input_mesh for the input, copy_target_mesh for the output. Entry
// point: make_solid(out, mesh, options). The machinery is in detail/ (arrangement, cell_windings,
// make_solid_impl).
#pragma once

#include "../../concepts.hpp"
#include "../../core/progress.hpp"
#include "../../core/result.hpp"
#include "mesh_boolean.hpp"

namespace hmira {

/// Options of make_solid.
struct make_solid_options {
    /// Called between phases and blocks of triangles; returning false cancels (errc::cancelled).
    progress_function progress = {};
};

/// Writes the boundary of {p : w(p) > 0} into `out`, replacing its content, where w is the
/// winding number of the closed input `mesh`; each output face is a triangle.
///
/// Every pair of triangles that meets other than along the edge or vertex it shares (the rule of
/// self_intersections) is intersected exactly, and each triangle is cut along its intersections
/// (where three triangles meet, at the exact meeting point of their planes), as mesh_boolean
/// cuts two meshes. The winding number on both sides of every piece is found exactly (Zhou et
/// al. 2016, "Mesh Arrangements for Solid Geometry": sorted around edges, propagated across
/// pieces, seeded by signed crossings of a segment from outside); a piece is kept where w > 0
/// on exactly one side, oriented towards that side's outside. Points are rounded to double once,
/// at output, as in mesh_boolean, and the rounded result is checked the same way (the report's
/// snapped_vertices, degenerate_faces and rounding_intersections).
///
/// \pre the mesh is closed: every edge is run as often in one direction as in the other
///   (self-intersecting, nested and non-manifold surfaces included); polygon faces are cut as
///   face_triangles does.
/// \post the mesh is only read; `out` holds a closed, consistently oriented surface free of
///   self-intersections when the report counts no rounding defects (empty when w > 0 nowhere),
///   or is unchanged on error.
/// Errors (out unchanged): errc::invalid_argument naming the vertex with a coordinate that is not
/// finite or outside the exact range; errc::unsupported when the mesh is not closed (its winding
/// numbers are inconsistent), when two of its triangles overlap in one plane, or when its
/// coordinates span more than 90 bits (from the coarsest to the finest) where triangles cross;
/// errc::cancelled; those of building `out`.
/// Complexity: that of mesh_boolean over the triangles of one mesh, plus O(E log E) for the E
/// edges around which pieces are sorted and O(T) per connected part of the surface for its seed.
template <class MO, class M, class TO = default_traits<MO>, class T = default_traits<M>>
    requires copy_target_mesh<MO, TO> && boolean_input_mesh<M, T>
[[nodiscard]] result<boolean_report> make_solid(MO& out, const M& mesh, const make_solid_options& options = {});

}  // namespace hmira

#include "detail/make_solid_impl.hpp"
