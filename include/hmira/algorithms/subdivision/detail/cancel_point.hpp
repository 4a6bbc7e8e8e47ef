// hmira/algorithms/subdivision/detail/cancel_point.hpp
// Where the subdivision schemes ask their progress callback whether to go on.
#pragma once

#include <cstddef>

#include "../../../core/progress.hpp"

namespace hmira::detail::subdivision {

/// Elements (vertices, edges, faces) a subdivision level handles between two calls of the
/// progress gate.
inline constexpr std::size_t check_every = std::size_t(1) << 14;

/// Counts elements handled and asks `gate` whether to go on once every check_every of them.
struct cancel_point {
    progress_gate& gate;
    std::size_t done = 0;
    /// False once the operation is cancelled (then the caller stops and restores its copy).
    bool operator()() { return (++done & (check_every - 1)) != 0 || gate.advance(1); }
};

}  // namespace hmira::detail::subdivision
