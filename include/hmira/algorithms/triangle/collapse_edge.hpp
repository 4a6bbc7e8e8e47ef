// hmira/algorithms/triangle/collapse_edge.hpp
// Edge collapse: an edge shrinks to a point, its source merging into its target; the
// triangles on either side disappear. The basis of decimation and of the inverse of a split.
// The machinery is in detail/collapse_edge_impl.hpp.
#pragma once

#include <array>
#include <string_view>
#include <utility>
#include <vector>

#include "triangle_common.hpp"

namespace hmira {

/// Where the surviving vertex of a collapse goes.
enum class collapse_placement {
    midpoint,  ///< halfway along the edge
    target,    ///< where the surviving vertex (the halfedge's target) already is
    source,    ///< where the removed vertex (the halfedge's source) was
    given,     ///< at collapse_edge_options::position
};

/// The placements' names: "midpoint", "target", "source", "given" (see core/enum_names.hpp).
constexpr auto enum_names(collapse_placement) {
    return std::array{std::pair{collapse_placement::midpoint, std::string_view("midpoint")},
                      std::pair{collapse_placement::target, std::string_view("target")},
                      std::pair{collapse_placement::source, std::string_view("source")},
                      std::pair{collapse_placement::given, std::string_view("given")}};
}

/// Options of is_collapse_ok and collapse_edge.
struct collapse_edge_options {
    /// Where the surviving vertex goes.
    collapse_placement placement = collapse_placement::midpoint;
    /// The position used with collapse_placement::given.
    vec3<double> position{};
    /// Also refuse a collapse that turns a remaining face around (its normal after the move
    /// points against its normal before) or makes it degenerate.
    bool check_geometry = false;
};

/// What collapse_edge left.
template <class M, class T = default_traits<M>>
struct collapse_edge_result {
    typename T::vertex_handle vertex;  ///< the surviving vertex (the halfedge's target), at its new position
};

/// Whether collapse_edge(mesh, h, options) may run, checked without changing anything:
/// - the link condition: every vertex adjacent to both ends is the third corner of a
///   triangle beside the edge (otherwise the collapse makes a double edge);
/// - boundary rules: an interior edge between two boundary vertices is refused (the boundary
///   would pinch), as is an edge on a boundary loop of three edges, a triangle hanging on the
///   edge alone, and a closed tetrahedron or two-triangle pillow;
/// - beside the edge, polygons lose one corner (they must keep three) and triangles
///   disappear (they must have no inner rings); no polygon around the source may also pass
///   through the target;
/// - with `options.check_geometry`, no remaining face around the edge turns over.
/// On a triangle mesh the topological part is CGAL's `Euler::does_satisfy_link_condition`.
/// Complexity O(sum over neighbours k of the source of valence(k)), plus the degrees of the
/// polygons around the source.
template <class M, class T = default_traits<M>>
    requires triangle_operable_mesh<M, T>
bool is_collapse_ok(const M& mesh, typename T::halfedge_handle h, const collapse_edge_options& options = {});

/// Collapses the edge of h = a->b: a is removed, b survives at the position the options give
/// (the midpoint by default). A triangle beside the edge disappears and its two other edges
/// become one; a polygon or boundary loop beside it loses the edge.
///
/// Inverse of split_edge and split_face with `placement = collapse_placement::target` (see
/// those operators).
/// \post V - 1; E - 1 - (triangles removed); F - (triangles removed); every halfedge that
/// ended at a now ends at b.
/// Errors (mesh unchanged): errc::invalid_handle; errc::topology naming the rule when
/// is_collapse_ok fails; errc::invalid_argument for a non-finite `position`.
/// Complexity: that of is_collapse_ok, plus O(valence of a) for the collapse itself.
template <class M, class T = default_traits<M>>
    requires triangle_operable_mesh<M, T>
[[nodiscard]] result<collapse_edge_result<M, T>> collapse_edge(M& mesh, typename T::halfedge_handle h,
                                                               const collapse_edge_options& options = {});

}  // namespace hmira

#include "detail/collapse_edge_impl.hpp"
