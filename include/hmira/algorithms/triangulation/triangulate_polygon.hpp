// hmira/algorithms/triangulation/triangulate_polygon.hpp
// Triangulation of one plane polygon with holes in O(n log n), by monotone partition on exact
// orientation predicates: what triangulate_faces and the STL writer run per face.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "../../core/result.hpp"
#include "detail/triangulate_polygon_impl.hpp"

namespace hmira {

/// A point of a plane polygon.
using point2 = std::array<double, 2>;

/// Options of triangulate_polygon.
struct triangulate_polygon_options {
    /// Flip diagonals until the triangulation is the constrained Delaunay one of the polygon's
    /// corners (Lawson's flips, exact in-circle test): among the triangulations of the same
    /// corners it has the largest smallest angle, so no needless slivers. Costs O(n) typical,
    /// O(n^2) flips at worst (then bounded by the work limit below).
    bool delaunay = false;
};

/// Triangulates a simple plane polygon with holes.
///
/// `loops[0]` is the outer loop, counter-clockwise; every further loop is a hole, clockwise,
/// strictly inside the outer loop and outside the other holes. Loops hold indices into
/// `points`. The triangles (index triples, counter-clockwise), n + 2h - 2 of them for n
/// corners and h holes, cover the polygon exactly: their areas sum to the polygon's, and no
/// two overlap. A sweep over the corners in (x, y) order adds the diagonals that cut the
/// polygon into pieces monotone in that order (holes need no bridges: their leftmost and
/// rightmost corners are split and merge corners of the sweep), then each piece is
/// triangulated by the linear stack algorithm. Every decision is an exact orientation test or
/// a comparison of coordinates, so concave and nearly degenerate polygons come out right.
/// Collinear corners are kept, each a corner of some triangle. A triangle has zero area only
/// if a corner of a monotone piece lies on the line through two corners of the piece's other
/// chain (the tests' random, lattice and comb polygons give none).
///
/// \pre none: every loop, index and coordinate is checked.
/// \post the triangles cover the polygon exactly, as above; `points` and `loops` are only read.
/// Errors (nothing returned): errc::invalid_argument for a coordinate that is not finite or
/// out of the exact predicates' range, or an index out of range; errc::degenerate_face for a
/// loop of fewer than three vertices; errc::topology when the loops are not simple (two
/// edges meet elsewhere than at their shared corner, or a point repeats), are wound the wrong
/// way, or a hole is not inside the outer loop. The message names the loop. errc::unsupported
/// for a polygon past the work limit below.
/// Complexity: O(n log n), n the total number of corners, for the simplicity check and the
/// triangulation (both sweeps), whatever the polygon's shape; plus O(n) per hole to check that
/// it lies inside the outer loop and outside the other holes, and the Delaunay flips if asked
/// for. Those two are bounded: past 2^26 + 256 n elementary tests (tens of thousands of holes,
/// or a pathological flip sequence) the polygon is refused with errc::unsupported, so no input
/// runs unbounded.
[[nodiscard]] inline result<std::vector<std::array<std::size_t, 3>>> triangulate_polygon(
    std::span<const point2> points, std::span<const std::vector<std::size_t>> loops,
    const triangulate_polygon_options& options = {}) {
    namespace dt = detail::triangulation;
    const auto total = dt::count_corners(points, loops);
    if (!total) return total.error();
    if (auto simple = dt::simplicity_sweep(points, loops).run(); !simple) return simple.error();
    const std::size_t work_limit = dt::work_base + dt::work_per_corner * *total;
    std::size_t work = 0;
    if (auto nested = dt::check_nesting(points, loops, work, work_limit, *total); !nested) return nested.error();
    std::vector<std::array<std::size_t, 3>> out;
    std::size_t sweep_work = 0;
    if (!dt::monotone_triangulate(points, loops, out, sweep_work))
        return fail(errc::topology,
                    "triangulate_polygon: the sweep met a piece that is not monotone (the polygon is not simple)");
    if (options.delaunay && !dt::flip_to_delaunay(points, out, work, work_limit)) return dt::too_intricate(*total);
    return out;
}

}  // namespace hmira
