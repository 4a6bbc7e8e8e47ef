// hmira/algorithms/editing/extrude.hpp
// Face extrusion (thesis 2.2): pull a face, or a connected set of faces, out along a direction
// and join it to where it was by side walls of quads, along the outer loop and every inner ring.
// Built from Euler operators only: one face by makeEV at each corner and makeEF around; a
// region by the general makeEV (split_vertex) at each outline vertex and makeEF per wall.
// The machinery is in detail/extrude_impl.hpp.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <ranges>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "detail/editing_common.hpp"

namespace hmira {

/// region: a connected selection moves as one piece, with walls only along its outline.
/// individual: every face is extruded on its own, along its own normal.
enum class extrude_mode { region, individual };
/// The modes' names: "region", "individual" (see core/enum_names.hpp).
constexpr auto enum_names(extrude_mode) {
    return std::array{std::pair{extrude_mode::region, std::string_view("region")},
                      std::pair{extrude_mode::individual, std::string_view("individual")}};
}

/// How extrude() moves the faces.
struct extrude_options {
    /// How far the faces move; negative pushes them into the solid (a pocket whose walls face
    /// into it). Must be finite and non-zero.
    double distance = 1.0;
    /// Direction of the move; unset (the default): the face's unit normal, or in region mode the
    /// region's area-weighted mean normal. A given direction is normalised.
    std::optional<vec3<double>> direction = std::nullopt;
    extrude_mode mode = extrude_mode::region;  ///< see extrude_mode
    /// Called every 1024 faces (individual mode) or outline edges (region mode), from the
    /// calling thread; returning false cancels: the mesh is rolled back and the error
    /// is errc::cancelled.
    progress_function progress = {};
};

/// What an extrusion created.
template <class M, class T = default_traits<M>>
struct extrude_result {
    /// The extruded faces at their new place: the same face handles as the input (the faces
    /// move; the walls are new).
    std::vector<typename T::face_handle> top_faces;
    /// The wall quads, one per outline edge (per face in individual mode: its outer loop's
    /// walls, then each inner ring's).
    std::vector<typename T::face_handle> side_faces;
    /// The new vertices. Individual mode: the extruded faces' new corners (at the top).
    /// Region mode: the region keeps its vertices and moves them, so the new vertices are the
    /// outline's copies left at the old place (the walls' bottom corners).
    std::vector<typename T::vertex_handle> vertices;
};

/// A mesh extrude() can edit: an editable_mesh whose positions can be set (region mode moves
/// the region's own vertices). Inner rings are not required: faces with rings are handled
/// where the model has them.
template <class M, class T = default_traits<M>>
concept extrudable_mesh = editable_mesh<M, T> && position_mutable_mesh<M, T>;

/// Extrudes the faces in `faces` (a range of face handles; duplicates count once) by
/// `options.distance` along `options.direction`, joining them to where they were by one quad
/// per outline edge (never triangulated). Region mode (default) needs a connected selection
/// (faces sharing edges); it moves the whole region, so inner vertices move and only the
/// outline gets walls: V + b, E + 2b, F + b for an outline of b edges. Individual mode extrudes
/// each face of degree n on its own: V + n, E + 2n, F + n each. The extruded faces keep their
/// handles and winding; walls are wound consistently with them, so a closed mesh stays closed
/// and outward oriented (a positive distance along the outward normal adds volume).
///
/// Faces with inner rings (holes; models with inner_ring_mesh) extrude like any face: the top
/// keeps its rings, and walls are built along every ring too, facing into the hole (outward
/// from the solid). There n counts the corners of all loops of the face, and a region's
/// outline includes the ring loops whose other side is not in the region. The ring count is
/// unchanged. Models without rings never reach that code.
///
/// \pre The faces exist; distance finite and non-zero; in region mode (more than one face) the
///      faces are connected through edges, have an outline and are not pinched at it.
/// \post On success the mesh is valid with the deltas above. On any error, when an allocation
///      throws, or when options.progress cancels ("extrude: cancelled", errc::cancelled), the
///      mesh is unchanged (see detail/transaction.hpp).
/// Errors: errc::invalid_argument for a zero, NaN or infinite distance, a zero direction or a
/// zero normal, an empty selection; errc::invalid_handle for a missing face; errc::topology
/// for a region that is not connected, has no outline (a whole closed component), or touches
/// one of its outline vertices in two separate fans (pinched).
/// Complexity: O(n) for a face of degree n; region mode O(R log R) for R corners of the
/// region's faces (the pinch check sorts the outline; the rest is hashed, expected O(R);
/// local: nothing outside the region and its outline fans is read).
template <class M, class T = default_traits<M>, class R>
    requires extrudable_mesh<M, T> && range_of_handles<R, typename T::face_handle>
result<extrude_result<M, T>> extrude(M& mesh, const R& faces, const extrude_options& options = {});

/// Extrudes one face with n corners over its outer loop and inner rings (see the range
/// overload): V + n, E + 2n, F + n, built from n makeEV and n makeEF. Complexity O(n). Errors
/// as for the range overload.
template <class M, class T = default_traits<M>>
    requires extrudable_mesh<M, T>
result<extrude_result<M, T>> extrude(M& mesh, typename T::face_handle face, const extrude_options& options = {});

}  // namespace hmira

#include "detail/extrude_impl.hpp"
