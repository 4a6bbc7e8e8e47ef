// hmira/algorithms/smoothing/laplacian_smooth.hpp
// Laplacian smoothing (uniform or cotangent weights) and Taubin's lambda/mu smoothing, which
// alternates a shrinking and an inflating step so the surface smooths without shrinking.
#pragma once

#include <array>
#include <cstddef>
#include <string_view>
#include <utility>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/enum_names.hpp"
#include "../../core/progress.hpp"
#include "../../core/result.hpp"

namespace hmira {

/// How a vertex's neighbours are weighted.
enum class laplacian_weights {
    uniform,    ///< each neighbour alike (umbrella operator): also evens out the sampling
    cotangent,  ///< (cot alpha + cot beta) / 2 per edge: moves along the normal only (triangles only)
};

/// The weights' names: "uniform", "cotangent" (see core/enum_names.hpp).
constexpr auto enum_names(laplacian_weights) {
    return std::array{std::pair{laplacian_weights::uniform, std::string_view("uniform")},
                      std::pair{laplacian_weights::cotangent, std::string_view("cotangent")}};
}

/// Options of laplacian_smooth.
struct laplacian_smooth_options {
    std::size_t iterations = 1;                              ///< smoothing steps
    double lambda = 0.5;                                     ///< step size, in (0, 1]
    laplacian_weights weights = laplacian_weights::uniform;  ///< neighbour weights
    bool fix_boundary = true;                                ///< keep boundary vertices where they are
    std::vector<std::size_t> fixed_vertices{};               ///< vertex indices (feature vertices) that stay exactly
    /// Cotangent weights: recomputed from the current positions before every step (false: once,
    /// from the starting positions, which makes every step the same linear filter).
    bool refresh_weights = true;
    unsigned threads = 0;  ///< worker threads (0: all available); the result does not depend on it
    /// Called between blocks of work (every 65536 vertices visited, counted across steps) with
    /// the fraction done; returning false cancels (errc::cancelled, every position restored).
    progress_function progress = {};
};

/// Options of taubin_smooth.
struct taubin_smooth_options {
    std::size_t iterations = 10;                             ///< lambda/mu pairs
    double lambda = 0.5;                                     ///< shrinking step, > 0
    double mu = -0.53;                                       ///< inflating step, < -lambda
    laplacian_weights weights = laplacian_weights::uniform;  ///< neighbour weights
    bool fix_boundary = true;                                ///< keep boundary vertices where they are
    std::vector<std::size_t> fixed_vertices{};               ///< vertex indices that stay exactly
    bool refresh_weights = true;  ///< cotangent weights: recomputed before every step (false: once)
    unsigned threads = 0;         ///< worker threads (0: all available); the result does not depend on it
    /// Called between blocks of work (every 65536 vertices visited, counted across steps) with
    /// the fraction done; returning false cancels (errc::cancelled, every position restored).
    progress_function progress = {};
};

/// What a smoothing did.
struct smooth_result {
    std::size_t moved = 0;  ///< vertices free to move
};

/// A mesh the smoothers can run on: halfedge navigation (neighbours, boundary), movable
/// positions, dense vertex indices. Every halfedge model qualifies, TriMesh included.
template <class M, class T = default_traits<M>>
concept smoothable_mesh = halfedge_navigable_mesh<M, T> && position_mutable_mesh<M, T> && vertex_index_mesh<M, T>;

/// Laplacian smoothing: `iterations` times, every free vertex moves by `lambda` times the
/// weighted mean of its neighbours minus itself (all vertices read before any moves).
/// Boundary vertices (with `fix_boundary`) and `fixed_vertices` stay exactly where they are.
/// Uniform weights shrink a closed surface noticeably; see taubin_smooth.
/// Coordinates near the largest double are handled without overflow (a vertex whose sums
/// overflow is recomputed at a smaller scale); no position written is ever non-finite.
/// \pre none beyond the concept: any polygons (triangles for cotangent weights), boundaries.
/// \post connectivity unchanged; fixed vertices bit for bit where they were.
/// Errors (mesh unchanged: a refusal or cancellation after some steps puts back the starting
/// positions, core/rollback.hpp): errc::invalid_argument for a lambda outside (0, 1] or a fixed
/// vertex index out of range; errc::topology for cotangent weights on a non-triangle;
/// errc::unsupported, naming the vertex, when a new position would lie beyond the range of
/// double (cotangent weights can extrapolate) or a neighbourhood holds a non-finite
/// coordinate; errc::cancelled when options.progress returns false.
/// Complexity O(V + E) to gather the neighbourhoods once, in compressed rows, then
/// O(iterations * (V + E)) for the steps, which stream the rows and two position arrays (in
/// parallel over options.threads); 72 bytes per vertex and 4 per halfedge besides the mesh (12
/// per halfedge with cotangent weights). The time per vertex steps up once the arrays outgrow
/// the last-level cache, and is flat beyond it (bench/sweep).
template <class M, class T = default_traits<M>>
    requires smoothable_mesh<M, T>
[[nodiscard]] result<smooth_result> laplacian_smooth(M& mesh, const laplacian_smooth_options& options = {});

/// Taubin's lambda/mu smoothing: each iteration a Laplacian step of `lambda` (shrinks) then
/// one of `mu` (inflates), a low-pass filter that keeps the volume nearly constant.
/// The inflating step extrapolates, so positions can grow beyond the range of double
/// (coordinates near the largest double, or a filter that amplifies over many iterations):
/// that is refused, never written.
/// Errors (mesh unchanged): errc::invalid_argument unless 0 < lambda <= 1 and
/// -1 <= mu < -lambda, or for a fixed vertex out of range; errc::topology as laplacian_smooth;
/// errc::unsupported, naming the vertex, when a new position would lie beyond the range of
/// double; errc::cancelled when options.progress returns false.
/// Complexity as laplacian_smooth, the two half-steps each one parallel sweep.
template <class M, class T = default_traits<M>>
    requires smoothable_mesh<M, T>
[[nodiscard]] result<smooth_result> taubin_smooth(M& mesh, const taubin_smooth_options& options = {});

}  // namespace hmira

// The machinery (one step, the run of steps with its rollback) and the definitions.
#include "detail/laplacian_smooth_impl.hpp"
