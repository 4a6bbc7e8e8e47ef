// hmira/algorithms/subdivision/subdivide.hpp
// One entry point for the three subdivision schemes, the scheme chosen by value or by name:
// what the CLI's --scheme and Python's scheme= translate to.
#pragma once

#include <array>
#include <cstddef>
#include <string_view>
#include <utility>

#include "../../core/enum_names.hpp"
#include "../../core/progress.hpp"
#include "../../core/result.hpp"
#include "catmull_clark.hpp"
#include "loop.hpp"
#include "sqrt3.hpp"

namespace hmira {

/// A subdivision scheme.
enum class subdivision_scheme {
    loop,           ///< Loop: triangles, each split in 4 (loop_subdivide)
    sqrt3,          ///< Kobbelt's sqrt(3): triangles, 3 for each per level (sqrt3_subdivide)
    catmull_clark,  ///< Catmull-Clark: any polygons, quads out (catmull_clark_subdivide)
};

/// The schemes' names: "loop", "sqrt3", "catmull-clark" (see core/enum_names.hpp).
constexpr auto enum_names(subdivision_scheme) {
    return std::array{std::pair{subdivision_scheme::loop, std::string_view("loop")},
                      std::pair{subdivision_scheme::sqrt3, std::string_view("sqrt3")},
                      std::pair{subdivision_scheme::catmull_clark, std::string_view("catmull-clark")}};
}

/// Options of subdivide.
struct subdivide_options {
    subdivision_scheme scheme = subdivision_scheme::loop;  ///< which scheme
    std::size_t levels = 1;                                ///< levels, 1 to 10
    /// Called between blocks of work with the fraction done; returning false cancels
    /// (errc::cancelled, mesh unchanged).
    progress_function progress = {};
};

/// What subdivide did: the counts after the last level.
struct subdivide_result {
    std::size_t vertices = 0;  ///< vertices after the last level
    std::size_t edges = 0;     ///< edges after the last level
    std::size_t faces = 0;     ///< faces after the last level
};

/// A mesh every scheme can run on (a triangles-only model runs loop_subdivide or
/// sqrt3_subdivide directly).
template <class M, class T = default_traits<M>>
concept subdividable_mesh =
    loop_subdividable_mesh<M, T> && sqrt3_subdividable_mesh<M, T> && catmull_clark_subdividable_mesh<M, T>;

/// Subdivides `options.levels` times with `options.scheme`: loop_subdivide, sqrt3_subdivide or
/// catmull_clark_subdivide, with their preconditions, errors and complexity.
/// \post on error (mesh unchanged): the scheme's own errors; errc::cancelled when
/// options.progress returns false.
template <class M, class T = default_traits<M>>
    requires subdividable_mesh<M, T>
[[nodiscard]] result<subdivide_result> subdivide(M& mesh, const subdivide_options& options = {}) {
    const auto counts = [](const auto& r) -> result<subdivide_result> {
        if (!r) return r.error();
        return subdivide_result{r->vertices, r->edges, r->faces};
    };
    switch (options.scheme) {
        case subdivision_scheme::loop:
            return counts(loop_subdivide<M, T>(mesh, {.levels = options.levels, .progress = options.progress}));
        case subdivision_scheme::sqrt3:
            return counts(sqrt3_subdivide<M, T>(mesh, {.levels = options.levels, .progress = options.progress}));
        case subdivision_scheme::catmull_clark:
            return counts(
                catmull_clark_subdivide<M, T>(mesh, {.levels = options.levels, .progress = options.progress}));
    }
    return fail(errc::invalid_argument, "subdivide: option scheme is not a subdivision_scheme");
}

}  // namespace hmira
