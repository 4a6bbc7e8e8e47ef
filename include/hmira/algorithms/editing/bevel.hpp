// hmira/algorithms/editing/bevel.hpp
// Edge bevel (thesis 2.2): replace edges by strips of faces (a flat chamfer, or a rounded
// profile of several segments), cutting back the faces on either side, as 3D editors do.
// Built from the Euler operators; bevel_vertices is the vertex-only mode (= truncate).
// The machinery (plan, then build) is in detail/bevel_impl.hpp.
#pragma once

#include <cstddef>
#include <vector>

#include "detail/editing_common.hpp"

namespace hmira {

/// How wide and how round the bevel is.
struct bevel_options {
    /// Distance, inside each face next to a bevelled edge, from the old edge to the new one
    /// (the "offset" of 3D editors). Finite, > 0.
    double width = 0.1;
    /// Faces across each strip: 1 is a flat chamfer (one quad per edge); more follow a circular
    /// arc tangent to both neighbouring faces. In [1, 64].
    int segments = 1;
    /// Shrink the width where it would overlap: a new vertex reaches at most half way along the
    /// edge it slides on, or the bevelled edges it lies between, so it never passes an existing
    /// vertex or one placed from the edge's other end (at exactly half, points from both ends
    /// coincide, as when all four edges of a square face are bevelled to its centre). Each new
    /// vertex is limited by its own edges only (a local clamp), so one short edge shrinks only
    /// the bevel next to it. Off: the width is used as given.
    bool clamp_overlap = true;
    /// With clamp_overlap: shrink the width uniformly for the whole call to the smallest local
    /// limit instead (every strip equally wide).
    bool clamp_globally = false;
    /// Called every 1024 elements stepped through (selected edges, touched vertices and corners
    /// while planning; new points, strips and replaced vertices while building), from the
    /// calling thread; returning false cancels: the mesh is rolled back (or, while planning,
    /// never touched) and the error is errc::cancelled.
    progress_function progress = {};
};

/// What a bevel created.
template <class M, class T = default_traits<M>>
struct bevel_result {
    /// The strip faces, `segments` per bevelled edge (one for a strip whose two end vertices
    /// stay, unless the edge is on the boundary), edge by edge in input order, each from its
    /// F_L side (a boundary edge's: from the side of its face).
    std::vector<typename T::face_handle> strip_faces;
    /// The patches closing vertices where three or more bevelled edges meet (a triangle at a
    /// cube corner; with segments > 1 every face of its grid fill), and vertex-only mode's faces.
    std::vector<typename T::face_handle> vertex_faces;
    std::vector<typename T::vertex_handle> vertices;  ///< every new vertex
    double width = 0;                                 ///< the smallest width used by any new vertex (after clamping)
    double requested_width = 0;                       ///< bevel_options::width
    std::size_t limited_edges = 0;   ///< bevelled edges with at least one new vertex limited by the clamp
    std::size_t bevelled_edges = 0;  ///< distinct edges bevelled (one strip each)
    /// Distinct selected edges not bevelled because a face would have had zero area (as
    /// validate() tests it): with them the strip, a shrunk face next to it or a corner patch
    /// collapses, as where clamped points from both ends of an edge meet. Left as they were.
    std::size_t skipped_edges = 0;
};
/// A mesh bevel() can edit: see editable_mesh (Euler operators, positions, indices).
template <class M, class T = default_traits<M>>
concept bevelable_mesh = editable_mesh<M, T>;

/// Bevels the edges in `edges` (a range of edge handles; duplicates count once): each becomes a
/// strip of `segments` faces between two new edges at `width` inside the faces next to it,
/// which shrink; an end vertex whose every corner is next to the bevel is replaced by a patch
/// (a triangle at a cube corner), and one that keeps other edges stays as the strip's pointed
/// end. Boundary edges bevel inside their one face. \ref bevel_behaviour tells it vertex by
/// vertex, at the boundary and with rounded profiles.
/// \pre Every edge exists and has a face on at least one side; no face corner at an end
///      vertex has collinear edges; the end vertices are ones truncate() accepts.
/// \post On success the mesh is valid and no new face has zero area (as validate() tests it:
///      an edge that would make one is dropped, counted in skipped_edges). A cube edge with
///      segments = s gives V + 2s, E + 3s, F + s. On any error, when an allocation throws, or
///      when options.progress cancels ("bevel: cancelled", errc::cancelled), the mesh is
///      unchanged (see detail/transaction.hpp).
/// Errors: errc::invalid_argument for options out of range or an empty selection;
/// errc::invalid_handle for a missing edge; errc::unsupported for a wire edge (no face on
/// either side), a degenerate corner (collinear edges), or when every edge is dropped;
/// errc::topology / errc::non_manifold for end vertices truncate() would reject.
/// Complexity O(sum of the end vertices' degrees and the touched faces' degrees) per edge =
/// O(V_adjacentV), plus O(k) expected for the selection and slide lookups of k edges (hash
/// tables), for segments = 1; with n segments add O(k log k) for the end-edge table, O(n^2)
/// per strip (cuts found by walking the strip) and O(k n^3) per patch of k sides (every
/// halfedge of the grid fill is found by walking the current face), for O(k n^2) new elements.
/// Clamp: see bevel_options::clamp_overlap; the result reports the requested width, the
/// smallest width used and how many edges were limited.
template <class M, class T = default_traits<M>, class R>
    requires bevelable_mesh<M, T> && range_of_handles<R, typename T::edge_handle>
result<bevel_result<M, T>> bevel(M& mesh, const R& edges, const bevel_options& options = {});

/// Bevels one edge (see the range overload). A cube edge with segments = 1 gives the chamfer:
/// V + 2, E + 3, F + 1, removing a prism of volume width^2 / 2 x the edge length.
template <class M, class T = default_traits<M>>
    requires bevelable_mesh<M, T>
result<bevel_result<M, T>> bevel(M& mesh, typename T::edge_handle edge, const bevel_options& options = {});

/// Vertex-only bevel, as 3D editors call it: exactly truncate(mesh, vertices, {.distance =
/// options.width}) (cut points at `width` along each edge, clamped at half an edge where both
/// ends are bevelled). Only segments = 1 is supported (errc::unsupported otherwise);
/// clamp_overlap is always on. Returns the new faces in vertex_faces. Errors as truncate().
template <class M, class T = default_traits<M>, class R>
    requires bevelable_mesh<M, T> && range_of_handles<R, typename T::vertex_handle>
result<bevel_result<M, T>> bevel_vertices(M& mesh, const R& vertices, const bevel_options& options = {});

/** \page bevel_behaviour How bevel() changes the mesh

What happens, edge by edge and vertex by vertex (the behaviour of 3D editors' bevel with
the "offset" width):
- Each bevelled edge is replaced by a strip: `segments` quads whose long sides lie at
  `width` from the old edge inside the two faces next to it; those faces shrink.
- At an end vertex, every face corner next to a bevelled edge gets a new vertex: on the
  corner's other edge when that one is not bevelled (slid along it so that its offset from
  the bevelled edge is `width`; an edge slid from two corners takes the mean), or inside the
  face at `width` from both edges when both are bevelled.
- If every edge of the vertex is bevelled or next to a bevelled edge around it, the vertex
  goes: its new vertices are joined into one face (a triangle at a cube corner with three
  bevelled edges), or, with only two of them (a corner of degree 3 with one bevelled edge,
  as on a cube), into one edge that the remaining face gains, exactly the chamfer of a cube
  edge. At the boundary, that face or edge closes the corner with one boundary edge.
- Otherwise (the vertex also has edges away from the bevel, e.g. a degree-4 vertex of a
  grid with one bevelled edge) the vertex stays where it is, with those edges, and the
  strip ends in it: the strip face then has the vertex as a pointed end.
V/E/F: a cube edge with segments = 1 gives V + 2, E + 3, F + 1 (8/12/6 -> 10/15/7); with
segments = s, V + 2s, E + 3s, F + s.

Boundary edges (one face) bevel too, as in 3D editors: the strip lies in the one face,
between the edge and a new edge at `width` inside it, and the edge stays as the strip's
boundary side. Its end vertices stay where they are (the strip runs along the boundary up
to them); their corners in the face get new points as above, and the end edges (end
vertex to new point) carry a straight, evenly divided profile: the strip is s parallel
bands. The boundary keeps its shape, so a flat mesh keeps its area exactly.
- One boundary edge whose ends have an unbevelled edge in the face's corner (e.g. inside
  a grid's side): V + 2s, E + 3s, F + s.
- A run of k boundary edges through vertices of degree 3: neighbouring strips share the
  point slid along the edge between them: V + (k + 1)s, E + (2k + 1)s, F + ks; a whole
  boundary loop of k edges (corner vertices of degree 2 get a point inside the corner,
  shared by both strips as a mitre): V + ks, E + 2ks, F + ks.
- Where a bevelled boundary edge meets a bevelled interior edge, the vertex stays, the
  corner between them gets one point inside the face, and the interior strip ends in the
  vertex (a pointed end, as at a vertex that keeps edges away from the bevel): for the
  grid vertex of degree 3 with its interior edge and one boundary edge bevelled, and the
  far ends kept, V + 5 + 2(s - 1), E + 7 + 3(s - 1), F + 2 + (s - 1).
- An interior edge ending on the boundary is as away from it: its end goes when every corner
  there is next to the bevel, closed by one boundary edge through its two new points.

With segments = n > 1 the flat result above is rounded:
- Every end edge (where a strip meets its end vertex's replacement) is split once into n
  segments along a circular arc (arc_point). Its control point is the old end vertex where
  two strips share the end edge (two bevelled edges meeting at a degree-3 vertex, or passing
  straight through a degree-4 one: the mitre, whose points lie in the plane of both edges),
  and otherwise the point of the bevelled edge's line nearest to the end edge's midpoint:
  the old vertex on a cube edge's chamfer, and at a cube corner with three bevelled edges a
  point that makes the arc a quarter circle of the strip's cylinder.
- Each strip is cut across into n faces, joining the j-th arc points of its two ends; at an
  end vertex that stays the cuts fan out from it. A strip whose two end vertices both stay
  has no profile to follow and remains one face.
- A patch whose every side is an arc (k >= 3 bevelled edges around a removed vertex, as at a
  cube corner) is filled with a grid of quads (grid fill): with m = floor(n / 2), one m x m
  quad patch per corner, meeting in a centre vertex (n even), or, for n odd, around a middle
  k-gon (a triangle at a cube corner) with a strip of m quads between neighbouring patches.
  Inner points come from Coons patches of the sides, then are projected onto the sphere
  fitted to the patch's boundary by least squares, when that fit is good (rms distance below
  1% of the radius, radius below 10 x the patch's diameter); at a cube corner the boundary
  lies exactly on the sphere of radius `width` around the inner corner, so the patch does
  too. Otherwise the Coons positions stay.
- A patch with straight sides (the vertex also had a face corner away from the bevel) stays
  one face, its sides carrying the arc points: a non-planar polygon (editors' "cutoff"
  corner).
All 12 edges of a cube with segments = 4 give a rounded cube: 6 + 48 + 8 x 12 faces.
No face of zero area is made (zero as validate() tests it: the sum of the corners' cross
products exactly zero, from any corner as a start). At the clamp limit new points from both
ends of an edge coincide, and new points may fall on one line; a face there would have zero
area. The build is then rolled back, one bevelled edge that made a new vertex of each such
face is dropped from the selection, and the rest is planned and built again from the
unchanged mesh, until no such face remains (each round drops an edge, so at most k rounds;
on real meshes two or three). The dropped edges stay as they were: bevelled_edges and
skipped_edges count both sides. If every edge is dropped, errc::unsupported (mesh unchanged).

Boundary edges' strips are listed from the side of their face.

*/

}  // namespace hmira

#include "detail/bevel_impl.hpp"
