// hmira/algorithms/delaunay/delaunay_triangulation.hpp
// Point set -> triangle mesh (thesis 2.3.1): the 2D Delaunay triangulation of (x, y), lifted by
// z into a 2.5D height field, written into any mesh model or returned as indexed triangles.
// Exact predicates, duplicates merged with a mapping, hull and optional Voronoi dual.
#pragma once

#include <array>
#include <concepts>
#include <cstdint>
#include <ranges>
#include <tuple>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/result.hpp"
#include "../../core/vec3.hpp"
#include "../../traits.hpp"

namespace hmira {

/// What delaunay_triangulation computes besides the triangles.
struct delaunay_options {
    /// Also compute the Voronoi diagram (the dual: one vertex per triangle, one edge per Delaunay edge).
    bool voronoi = false;
    /// Insert in BRIO rounds (robust expected cost for any input order); false: one plain
    /// Hilbert order, a little faster on benign input.
    bool brio = true;
};

/// Whether the input spanned the plane.
enum class delaunay_status {
    ok,             ///< at least three non-collinear points: a triangulation
    all_collinear,  ///< all points on one line (at least 3 distinct): no triangles, hull = the 2 ends
};

/// One Voronoi edge, dual to the Delaunay edge between sites site0 and site1 (output vertex
/// indices). It joins Voronoi vertices from and to (triangle indices), or, for a hull edge,
/// is the ray from `from` along `direction` (pointing out of the hull) and to == no_vertex.
struct voronoi_edge {
    static constexpr std::uint32_t no_vertex = 0xFFFFFFFFu;  ///< `to` of a ray
    std::uint32_t site0 = 0;                                 ///< one end vertex of the Delaunay edge
    std::uint32_t site1 = 0;                                 ///< the other end vertex of the Delaunay edge
    std::uint32_t from = 0;        ///< the Voronoi vertex the edge starts at (a triangle index)
    std::uint32_t to = no_vertex;  ///< the Voronoi vertex it ends at, or no_vertex for a ray
    vec3<double> direction{};      ///< a ray's direction (hull edges only)
};

/// The Voronoi diagram: vertices[i] is the circumcentre of triangle i (z = 0).
struct voronoi_diagram {
    std::vector<vec3<double>> vertices;  ///< circumcentres, one per triangle
    std::vector<voronoi_edge> edges;     ///< one per Delaunay edge
};

/// The triangulation as plain data.
struct delaunay_triangles {
    delaunay_status status = delaunay_status::ok;  ///< ok, or all_collinear
    /// The distinct points (duplicates in x, y merged; z from the first input of each group).
    std::vector<vec3<double>> points;
    std::vector<std::array<std::uint32_t, 3>> triangles;  ///< counter-clockwise (seen from +z), indices into points
    /// The convex hull as a counter-clockwise loop of indices into points, starting at any
    /// vertex. Hull vertices on a straight stretch of the hull are included.
    std::vector<std::uint32_t> hull;
    /// points[i] is input point vertex_to_input[i] (the first of its duplicates, in input order).
    std::vector<std::uint32_t> vertex_to_input;
    /// Input point j became points[input_to_vertex[j]].
    std::vector<std::uint32_t> input_to_vertex;
    voronoi_diagram voronoi;  ///< empty unless options.voronoi
};

/// A point delaunay_triangulation accepts: a `vec3`-like type with members x, y, z, or a
/// `std::array` of 2 or 3 scalars (z = 0 for two components).
template <class P>
concept delaunay_point =
    requires(const P& p) {
        { p.x } -> std::convertible_to<double>;
        { p.y } -> std::convertible_to<double>;
        { p.z } -> std::convertible_to<double>;
    } ||
    (
        requires { std::tuple_size<P>::value; } && (std::tuple_size<P>::value == 2 || std::tuple_size<P>::value == 3) &&
        requires(const P& p) {
            { p[0] } -> std::convertible_to<double>;
        });

/// A sized random-access range of delaunay_point.
template <class R>
concept delaunay_point_range =
    std::ranges::random_access_range<R> && std::ranges::sized_range<R> && delaunay_point<std::ranges::range_value_t<R>>;

/// The Delaunay triangulation of the points' (x, y), as indexed triangles; z rides along
/// (2.5D: a height field). Duplicates in (x, y) are merged and reported in the mapping.
/// Cocircular points are resolved consistently (a point on a circumcircle is not in conflict
/// with it), so the result is always a valid triangulation of the convex hull whose every
/// edge is locally Delaunay, even on lattices and circles.
/// \pre none (everything is checked). Errors: errc::invalid_argument, naming the point, for a
///   NaN or infinite coordinate or an x, y outside the predicates' range (0 or magnitude in
///   [2^-180, 2^180]); errc::invalid_argument for fewer than 3 distinct points;
///   errc::unsupported for 2^32 - 1 or more points.
/// \post status ok: triangles cover the convex hull of the distinct points, each edge locally
///   Delaunay. All-collinear input is not an error: status all_collinear, no triangles.
/// Complexity: O(n log n) expected (n points): Hilbert/BRIO sort O(n), then incremental insertion
/// with short walks; predicates are exact and adaptive.
template <delaunay_point_range R>
result<delaunay_triangles> delaunay_triangulation(const R& points, const delaunay_options& options = {});

/// What delaunay_triangulation wrote into a mesh.
template <class Mesh, class Traits = default_traits<Mesh>>
struct delaunay_mesh_result {
    delaunay_status status = delaunay_status::ok;  ///< ok, or all_collinear
    /// The new vertices, one per distinct input point, in the order of delaunay_triangles::points.
    std::vector<vertex_handle_t<Mesh, Traits>> vertices;
    std::vector<face_handle_t<Mesh, Traits>> faces;   ///< the new faces, in the order of delaunay_triangles::triangles
    std::vector<vertex_handle_t<Mesh, Traits>> hull;  ///< the convex hull as a counter-clockwise loop of new vertices
    /// vertices[i] comes from input point vertex_to_input[i].
    std::vector<std::uint32_t> vertex_to_input;
    /// Input point j became vertices[input_to_vertex[j]].
    std::vector<std::uint32_t> input_to_vertex;
    voronoi_diagram voronoi;  ///< empty unless options.voronoi; vertex i is dual to faces[i], sites index `vertices`
};

/// The Delaunay triangulation of the points' (x, y), written into `mesh`: one new vertex per
/// distinct point (at its x, y, z: a 2.5D height field) and one counter-clockwise triangle per
/// Delaunay triangle. Returns what it created, the hull, the duplicate mapping and, on request,
/// the Voronoi dual. See the indexed overload for the method and the degenerate cases.
///
/// \pre none (everything is checked).
/// \post on an error of the indexed overload the mesh is unchanged. All-collinear input adds
///   nothing and returns status all_collinear (vertices, faces and hull empty; the mapping still
///   numbers the distinct points as the indexed overload does). If the mesh refuses a face (a
///   mesh cannot refuse for a conflicting face, since all vertices are new) its error is
///   returned; the vertices and faces added before it stay.
/// Complexity: O(n log n) expected plus n add_vertex and ~2n add_face calls on the mesh.
template <class M, class T = default_traits<M>, delaunay_point_range R>
    requires mesh_builder<M, T>
result<delaunay_mesh_result<M, T>> delaunay_triangulation(M& mesh, const R& points,
                                                          const delaunay_options& options = {});

}  // namespace hmira

#include "detail/delaunay_triangulation_impl.hpp"
