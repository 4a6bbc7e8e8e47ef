// hmira/algorithms/holes/fill_hole.hpp
// Hole filling: a boundary loop closed by a triangle patch of minimal dihedral bend, then minimal area
// (Liepa 2003), or, for long loops, by a triangulation of its projection.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/progress.hpp"
#include "../../core/result.hpp"
#include "../triangle/triangle_common.hpp"
#include "fairing.hpp"

namespace hmira {

/// How fill_hole triangulates, refines and fairs a loop. The defaults triangulate only.
struct fill_hole_options {
    /// Loops of at most this many edges get Liepa's O(n^3) dynamic programme; longer ones the O(n^2) triangulation
    /// of the loop projected on its best-fit plane.
    std::size_t max_dynamic_programming_edges = 200;
    /// A longer loop whose projection is not a simple polygon (or whose projected triangulation repeats a mesh
    /// edge) still gets the dynamic programme if it has at most this many edges; otherwise it is refused.
    std::size_t max_fallback_dynamic_programming_edges = 1000;
    /// A loop whose dynamic programme would need more than this many bytes for its tables (24 n^2 for n edges) is
    /// refused before they are allocated; 0 means no limit. The CLI passes the machine's available memory.
    std::size_t max_memory_bytes = 0;
    /// Refine the patch to the edge density around the hole (Liepa 2003): triangles are split at their centroid and
    /// edges flipped, by split_face and flip_edge, until the patch's edges are about as long as the mesh edges at
    /// the loop.
    bool refine = false;
    /// Liepa's density factor alpha (> 0): a triangle is split while its centroid lies farther than scale / alpha
    /// from its corners. Larger gives a denser patch.
    double refine_density = 1.4142135623730951;
    /// Refinement adds at most this many vertices per hole.
    std::size_t max_added_vertices = 100000;
    /// Fairing of the vertices refinement added (no effect without `refine`).
    fairing fair = fairing::none;
    /// The fairing solve stops at this relative residual (> 0).
    double fairing_tolerance = 1e-10;
    /// The fairing solve gives up after this many conjugate-gradient iterations per coordinate; 0 means 10 x the
    /// number of added vertices + 100.
    std::size_t max_fairing_iterations = 0;
    /// Called with the fraction done: after every 2^16 inner steps of the dynamic programme, every refinement round
    /// and 4096 splits, and about every 2^20 multiply-adds of the fairing solve (fill_holes: also before each
    /// hole). Returning false stops the fill with errc::cancelled and the mesh as it was (see fill_hole). Empty:
    /// none.
    progress_function progress = {};
};

/// What fill_hole added.
template <class M, class T = default_traits<M>>
struct fill_hole_result {
    std::vector<typename T::face_handle> faces;  ///< the patch's triangles
    /// The vertices the patch added (inside it): the centre vertex of a loop that has no valid triangulation of its
    /// own vertices (first), then those refinement added.
    std::vector<typename T::vertex_handle> vertices;
    /// Whether the fairing solve converged (true when no fairing was asked for or there was nothing to fair). When
    /// false the added vertices stay where refinement put them.
    bool faired = true;
    std::size_t fairing_iterations = 0;  ///< conjugate-gradient iterations of the slowest coordinate
};

/// Fills the boundary loop of `boundary_halfedge` (a halfedge with no face) with triangles: Liepa's dynamic
/// programme (least largest dihedral bend, then least area) for loops of up to
/// `options.max_dynamic_programming_edges` edges, a triangulation of the loop's projection for longer ones, and a
/// fan around one new vertex when no triangulation of the loop's own vertices is valid; then, with `refine` and
/// `fair`, Liepa's refinement and fairing. New faces are wound like the faces around the hole.
/// detail/fill_hole_impl.hpp gives the steps.
/// \pre the mesh is a valid surface; the loop visits each vertex once.
/// \post the loop is closed: V + a, E + (n - 3) + 3a, F + (n - 2) + 2a for a added vertices (a = 0 without refine
/// and centre vertex); genus unchanged; the loop's vertices do not move.
/// Cancellation: `options.progress` returning false gives errc::cancelled and the mesh as it was: undone by the
/// edit journal (editing/detail/transaction.hpp) on every model it supports, every shipped half-edge model among
/// them (the undone elements stay as garbage), or restored from a copy (core/rollback.hpp) on another copyable
/// model; a model with neither obeys the callback only until the patch is built.
/// Errors (mesh unchanged): errc::invalid_argument for refine_density or fairing_tolerance not finite and > 0;
/// errc::invalid_handle; errc::topology when the halfedge has a face, the loop passes a vertex twice, has fewer
/// than three edges, or every triangulation would duplicate an existing edge or make a degenerate triangle and so
/// would a fan around a centre; errc::unsupported when a loop longer than max_fallback_dynamic_programming_edges
/// has no simple projection, or the dynamic programme would take more than max_memory_bytes.
/// Complexity: O(n^3) time and O(n^2) memory by the dynamic programme; O(n^2) time for the projected fallback; plus
/// O(n valence) to find edges the patch must not repeat. Refinement O(a) per round, typically a few rounds; fairing
/// O(iterations * a * valence^2).
template <class M, class T = default_traits<M>>
    requires triangle_operable_mesh<M, T>
[[nodiscard]] result<fill_hole_result<M, T>> fill_hole(M& mesh, typename T::halfedge_handle boundary_halfedge,
                                                       const fill_hole_options& options = {});

/// Why fill_holes left a loop open.
enum class open_hole_reason {
    too_long,  ///< more edges than fill_holes' max_size
    refused,   ///< fill_hole refused it (see open_hole::code and message)
};

/// A loop fill_holes left open, and why.
struct open_hole {
    std::size_t vertex = 0;  ///< index of the loop's first vertex (the target of its first boundary halfedge)
    std::size_t edges = 0;   ///< the loop's length
    open_hole_reason reason = open_hole_reason::too_long;  ///< why it was left open
    errc code = errc::unsupported;                         ///< for `refused`: fill_hole's error code
    std::string message;                                   ///< for `refused`: fill_hole's one-line reason
};

/// What fill_holes did.
struct fill_holes_result {
    std::size_t filled = 0;          ///< loops closed
    std::size_t skipped = 0;         ///< loops left open (longer than max_size, or refused by fill_hole): open.size()
    std::size_t faces_added = 0;     ///< triangles in all patches
    std::size_t vertices_added = 0;  ///< vertices the patches added (centre vertices and refinement)
    std::size_t unfaired = 0;        ///< patches whose fairing solve did not converge (left as refined)
    std::vector<open_hole> open;     ///< each loop left open, in the order the loops were found, with its reason
};

/// fill_holes' `max_size` when a front end is not given one (the CLI's --max-edges, Python's
/// max_edges): scan holes are filled, an open mesh's rim (usually longer) is left open.
inline constexpr std::size_t fill_holes_default_max_edges = 1000;

/// A mesh fill_holes can run on: the triangle operators, and halfedge indices to mark the
/// boundary halfedges already visited.
template <class M, class T = default_traits<M>>
concept hole_fillable_mesh = triangle_operable_mesh<M, T> && halfedge_index_mesh<M, T>;

/// Fills every boundary loop of at most `max_size` edges with fill_hole. A loop that is longer,
/// or that fill_hole refuses, is left open and listed in `open` with its reason (each refusal
/// leaves the mesh unchanged).
/// Cancellation: `options.progress` is asked before each loop and within each fill (see
/// fill_hole); returning false gives errc::cancelled. On a model the editing journal supports
/// (every shipped half-edge model) the whole call is one journaled transaction and a
/// cancellation undoes every patch already built: the mesh is left as it was (live elements,
/// links and positions; the undone elements stay behind as garbage). On another copyable model a
/// copy (core/rollback.hpp), taken when a callback is given, is what a cancellation restores; a
/// model with neither obeys the callback only until the first patch is built.
/// Errors (mesh unchanged): errc::invalid_argument for max_size < 3 or an option out of range;
/// errc::cancelled.
/// Complexity: O(H) to find the loops, H the halfedges, plus fill_hole's cost per loop.
template <class M, class T = default_traits<M>>
    requires hole_fillable_mesh<M, T>
[[nodiscard]] result<fill_holes_result> fill_holes(M& mesh, std::size_t max_size,
                                                   const fill_hole_options& options = {});

}  // namespace hmira

// The machinery (the loop, its triangulation, the patch's construction, refinement and
// fairing) and the definitions.
#include "detail/fill_hole_impl.hpp"
