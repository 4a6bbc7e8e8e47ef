// hmira/algorithms/spatial/bvh.hpp
// A bounding-volume hierarchy over any model's faces: the closest surface point, the first,
// any or all hits of a ray, one query or a batch in parallel. The machinery is in detail/bvh_impl.hpp.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/result.hpp"
#include "../../core/vec3.hpp"
#include "../triangulation/triangulate_faces.hpp"
#include "ray.hpp"

namespace hmira {

/// Options of build_bvh.
struct bvh_options {
    unsigned threads = 0;             ///< worker threads for the build (0: all); the tree never depends on it
    std::uint32_t max_leaf_size = 4;  ///< a leaf holds at most this many triangles (1 to 64)
};

/// What a batched query does with a query that is not finite (a NaN or infinite coordinate).
enum class bvh_nan_policy {
    refuse,     ///< the whole batch fails with errc::invalid_argument naming the first such query
    propagate,  ///< that query's answer is NaN (point, distance, t) with no face
};

/// Options of the closest-point queries.
struct closest_point_options {
    double max_distance = std::numeric_limits<double>::infinity();  ///< look no farther (inclusive)
    unsigned threads = 0;                                           ///< batched queries: worker threads (0: all)
    bvh_nan_policy nan = bvh_nan_policy::refuse;                    ///< batched queries: non-finite points
};

/// How the ray queries test boxes: both keep every box the ray meets and give the same answers.
enum class bvh_box_test {
    float32,  ///< float slabs widened by a bound on their rounding (double for a ray float cannot bound)
    float64,  ///< double slabs
};

/// Options of the batched ray queries.
struct ray_query_options {
    unsigned threads = 0;                         ///< worker threads (0: all)
    bvh_nan_policy nan = bvh_nan_policy::refuse;  ///< rays with a non-finite origin or direction
    bvh_box_test boxes = bvh_box_test::float32;   ///< the box test (the answers do not depend on it)
};

/// The face index of a query that found nothing.
inline constexpr std::size_t no_face = std::numeric_limits<std::size_t>::max();

/// The surface point closest to a query. `point` = sum of barycentric[k] * position(vertices[k]).
struct closest_surface_point {
    vec3<double> point{};                                       ///< the closest point
    std::size_t face = no_face;                                 ///< T::face_index of its face; no_face if none
    std::array<std::uint32_t, 3> vertices{};                    ///< T::vertex_index of its triangle's corners
    std::array<double, 3> barycentric{};                        ///< its weights on those corners (sum 1)
    double distance = std::numeric_limits<double>::infinity();  ///< |point - query|
    bool found() const noexcept { return face != no_face; }     ///< whether a point was found
};

/// Where a ray meets the surface. `point` = origin + t * direction.
struct ray_surface_hit {
    double t = std::numeric_limits<double>::infinity();      ///< the ray parameter of the hit
    vec3<double> point{};                                    ///< the hit point
    std::size_t face = no_face;                              ///< T::face_index of the face hit; no_face if none
    std::array<std::uint32_t, 3> vertices{};                 ///< T::vertex_index of the triangle's corners
    std::array<double, 3> barycentric{};                     ///< the hit's weights on those corners
    bool found() const noexcept { return face != no_face; }  ///< whether the ray hit
};

class bvh;
namespace detail {
struct bvh_access;
}

/// A mesh a bvh can be built over: faces whose triangles face_triangles can cut, and dense
/// vertex indices (the triangles' corners). Models with `T::change_count` (change_counted_mesh)
/// also let the mesh-taking queries notice a change of connectivity that keeps the counts.
template <class M, class T = default_traits<M>>
concept bvh_source_mesh =
    face_triangulable_mesh<M, T> && vertex_index_mesh<M, T> && vertex_list_mesh<M, T> && face_list_mesh<M, T>;

/// A bvh over the faces of `mesh`. A triangle is taken as it is; a polygon, or a face with inner
/// rings, is cut by face_triangles (triangulate_polygon in the face's plane, so concave faces
/// come out right), and a face that has no area in its plane (collinear corners) by a fan: its
/// triangles are degenerate. Every triangle carries T::face_index of its face. Binned-SAH
/// splits (16 bins per axis); subtrees of more than 4096 triangles build in parallel, and the
/// tree depends only on the mesh, never on the thread count.
/// \pre none. \post the mesh is only read; the tree records V, F, the vertex index bound and,
///   on a change_counted_mesh, T::change_count(mesh), so that the mesh-taking queries below
///   refuse a mesh whose connectivity changed. A change of positions alone keeps the counts and
///   is not detected: call refit_bvh after moving vertices.
/// Errors: errc::invalid_argument naming a vertex whose position is not finite; those of
/// face_triangles naming a face whose projection is not a simple polygon; errc::unsupported
/// past 2^32 - 1 vertices or triangles. Complexity O(n log n) for n triangles (plus the
/// triangulation of polygon faces), O(n) memory.
template <class M, class T = default_traits<M>>
    requires bvh_source_mesh<M, T>
[[nodiscard]] result<bvh> build_bvh(const M& mesh, const bvh_options& options = {});

/// Recomputes the boxes of `tree` from the current positions of `mesh`, keeping its topology:
/// after positions moved, refit is O(n) and answers exactly as a fresh build would (the same
/// distances and hit parameters; ties may name another face). Refitting to the positions of
/// the build gives back the same tree. \pre the connectivity is the one the tree was built on.
/// \post on error the tree is unchanged. Errors: the staleness error below; errc::invalid_argument
/// for a non-finite position. Complexity O(n).
template <class M, class T = default_traits<M>>
    requires bvh_source_mesh<M, T>
[[nodiscard]] result<void> refit_bvh(const M& mesh, bvh& tree);

/// The mesh-taking queries. Each first checks that `tree` was built from a mesh with the same
/// V, F and vertex index bound (and change count, where the model has one) and otherwise fails
/// with errc::invalid_argument ("rebuild the tree"); then it answers as the bvh member of the
/// same name: closest_point / closest_points, first_hit / first_hits, any_hit / any_hits,
/// all_hits. Complexity per query O(log n) expected on a well-spread surface, O(n) worst case;
/// batches run in parallel (options.threads), with answers that do not depend on it.
///@{
template <class M, class T = default_traits<M>>
    requires bvh_source_mesh<M, T>
[[nodiscard]] result<closest_surface_point> closest_point(const M& mesh, const bvh& tree, const vec3<double>& p,
                                                          const closest_point_options& options = {});
template <class M, class T = default_traits<M>>
    requires bvh_source_mesh<M, T>
[[nodiscard]] result<std::vector<closest_surface_point>> closest_points(const M& mesh, const bvh& tree,
                                                                        std::span<const vec3<double>> points,
                                                                        const closest_point_options& options = {});
template <class M, class T = default_traits<M>>
    requires bvh_source_mesh<M, T>
[[nodiscard]] result<ray_surface_hit> ray_first_hit(const M& mesh, const bvh& tree, const ray& r);
template <class M, class T = default_traits<M>>
    requires bvh_source_mesh<M, T>
[[nodiscard]] result<std::vector<ray_surface_hit>> ray_first_hits(const M& mesh, const bvh& tree,
                                                                  std::span<const ray> rays,
                                                                  const ray_query_options& options = {});
template <class M, class T = default_traits<M>>
    requires bvh_source_mesh<M, T>
[[nodiscard]] result<bool> ray_any_hit(const M& mesh, const bvh& tree, const ray& r);
template <class M, class T = default_traits<M>>
    requires bvh_source_mesh<M, T>
[[nodiscard]] result<std::vector<std::uint8_t>> ray_any_hits(const M& mesh, const bvh& tree, std::span<const ray> rays,
                                                             const ray_query_options& options = {});
template <class M, class T = default_traits<M>>
    requires bvh_source_mesh<M, T>
[[nodiscard]] result<std::vector<ray_surface_hit>> ray_all_hits(const M& mesh, const bvh& tree, const ray& r);
///@}

/// A bounding-volume hierarchy over triangles with vertex indices into a position array, each
/// triangle carrying a face index. Nodes are 32 bytes (a float box rounded outward, a child or
/// first-triangle index and a count); the ray queries walk a four-wide form of the same tree
/// (each node's four children's boxes tested together). The triangles are kept in leaf order
/// with their corners in double, and every triangle test runs in double. Triangles whose corners are collinear (decided
/// exactly) are degenerate: rays never hit them; the closest point may lie on them.
/// Queries are const and may run concurrently.
class bvh {
public:
    /// An empty tree: every query finds nothing.
    bvh() = default;

    /// A tree over triangles[i] of `points`, with face index faces[i] (i when faces is empty).
    /// \pre none. Errors: errc::invalid_argument for an index out of range, a faces span of
    /// another length, or a point (used or not) that is not finite; errc::unsupported past
    /// 2^32 - 1 points or triangles. Complexity O(n log n), as build_bvh.
    [[nodiscard]] static result<bvh> from_triangles(std::span<const vec3<double>> points,
                                                    std::span<const std::array<std::uint32_t, 3>> triangles,
                                                    std::span<const std::size_t> faces = {},
                                                    const bvh_options& options = {});

    /// The closest point of the triangles to p within options.max_distance (found() false when
    /// none is that close, or the tree is empty). Ties go to the triangle met first in the
    /// tree's fixed order. A non-finite p gives NaN point and distance, no face.
    /// Complexity O(log n) expected, O(n) worst case.
    closest_surface_point closest_point(const vec3<double>& p, const closest_point_options& options = {}) const;
    /// The hit of r with the smallest t in [r.t_min, r.t_max] (found() false for none); hits on
    /// edges count. Ties go to the triangle first in the tree's order. Complexity O(log n) expected.
    ray_surface_hit first_hit(const ray& r) const;
    /// Whether r hits any triangle with t in [r.t_min, r.t_max]: stops at the first it finds.
    bool any_hit(const ray& r) const;
    /// Every hit with t in [r.t_min, r.t_max], sorted by (t, face); a face hit twice at the
    /// same t (on a diagonal of its triangulation) is listed once. Complexity O(log n + k)
    /// expected for k hits.
    std::vector<ray_surface_hit> all_hits(const ray& r) const;

    /// Batched queries, answers in input order, in parallel (options.threads). Errors: a
    /// non-finite query under bvh_nan_policy::refuse (errc::invalid_argument naming its index).
    ///@{
    [[nodiscard]] result<std::vector<closest_surface_point>> closest_points(
        std::span<const vec3<double>> points, const closest_point_options& options = {}) const;
    [[nodiscard]] result<std::vector<ray_surface_hit>> first_hits(std::span<const ray> rays,
                                                                  const ray_query_options& options = {}) const;
    [[nodiscard]] result<std::vector<std::uint8_t>> any_hits(std::span<const ray> rays,
                                                             const ray_query_options& options = {}) const;
    ///@}

    /// Recomputes every box from new positions (indexed as at the build), keeping the topology.
    /// \post on error the tree is unchanged. Errors: errc::invalid_argument for fewer points
    /// than the build had or a non-finite one. Complexity O(n).
    [[nodiscard]] result<void> refit(std::span<const vec3<double>> points);

    /// Number of triangles. O(1).
    std::size_t size() const noexcept { return faces_.size(); }
    /// Whether the tree holds no triangle. O(1).
    bool empty() const noexcept { return faces_.empty(); }
    /// Number of nodes and the depth of the deepest leaf (the root alone: 1). O(1).
    std::size_t node_count() const noexcept { return nodes_.size(); }
    /// The deepest leaf's depth (a root leaf: 1; empty tree: 0). O(1).
    std::size_t depth() const noexcept { return depth_; }
    /// The i-th triangle in the tree's order: its vertex indices and face index. O(1).
    ///@{
    const std::array<std::uint32_t, 3>& triangle(std::size_t i) const { return vertices_[i]; }
    std::size_t face(std::size_t i) const { return faces_[i]; }
    ///@}

    /// Two trees are equal when they have the same nodes and triangles in the same order.
    bool operator==(const bvh&) const = default;

    /// What the tree was built from, for the mesh-taking queries' staleness check.
    struct source {
        std::size_t vertices = 0;                        ///< V at the build
        std::size_t faces = 0;                           ///< F at the build
        std::size_t vertex_bound = 0;                    ///< the vertex index bound at the build
        std::uint64_t change_count = 0;                  ///< T::change_count, where there is one
        bool counted = false;                            ///< whether change_count was read
        bool operator==(const source&) const = default;  ///< all fields equal
    };
    /// The counts recorded at the build. O(1).
    const source& built_from() const noexcept { return source_; }
    /// Sets the recorded counts (build_bvh does this). O(1).
    void set_built_from(const source& s) noexcept { source_ = s; }

    /// A node: its box (float, rounded outward); an inner node's left child follows it and
    /// `index` is its right child; a leaf (count > 0) holds triangles index .. index + count - 1.
    struct node {
        std::array<float, 3> lo{};                     ///< the box's lower corner
        std::array<float, 3> hi{};                     ///< the box's upper corner
        std::uint32_t index = 0;                       ///< the right child, or a leaf's first triangle
        std::uint32_t count = 0;                       ///< a leaf's triangle count; 0 for an inner node
        bool operator==(const node&) const = default;  ///< all fields equal
    };

private:
    struct corners {
        vec3<double> a, b, c;
        bool operator==(const corners&) const = default;
    };
    friend struct detail::bvh_access;

    /// Up to four children of an inner node tested together: their boxes by axis and lane (a
    /// layout the compiler vectorises), each child an inner wide node (count 0) or a leaf's
    /// range; an unused lane has index and count 0 (the root is no one's child). Two cache lines.
    struct alignas(64) wide_node {
        std::array<std::array<float, 4>, 3> lo{}, hi{};
        std::array<std::uint32_t, 4> index{}, count{};
        bool operator==(const wide_node&) const = default;
    };

    std::vector<node> nodes_;
    std::vector<wide_node> wide_;                         // the ray queries' four-wide form of nodes_
    std::vector<corners> corners_;                        // leaf order
    std::vector<std::array<std::uint32_t, 3>> vertices_;  // leaf order
    std::vector<std::size_t> faces_;                      // leaf order
    std::vector<std::uint8_t> degenerate_;                // leaf order: corners collinear, exactly
    std::size_t point_count_ = 0, depth_ = 0;
    double reach_ = 0;  // the largest |coordinate| of the root box
    source source_{};
};

}  // namespace hmira

#include "detail/bvh_impl.hpp"
