// hmira/algorithms/conversion/detail/parallel.hpp
// The one place the conversions touch oneTBB: a chunked parallel loop that runs serially when
// hmira is built without TBB, and an optional fixed thread count. Output order never depends
// on the schedule: every caller writes to slots it computed beforehand.
#pragma once

#include <cstddef>

#if defined(HMIRA_HAS_TBB)
#include <tbb/blocked_range.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

namespace hmira::detail {

/// Calls body(begin, end) on disjoint chunks covering [0, n), at most `grain` items each
/// (at least one chunk per item when grain is 0), in parallel when TBB is available.
template <class Body>
void parallel_chunks(std::size_t n, std::size_t grain, const Body& body) {
    if (n == 0) return;
    if (grain == 0) grain = 1;
#if defined(HMIRA_HAS_TBB)
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain),
                      [&](const tbb::blocked_range<std::size_t>& r) { body(r.begin(), r.end()); });
#else
    body(std::size_t(0), n);
#endif
}

/// Runs f() and g(), in parallel when TBB is available (serially, f first, without it).
template <class F, class G>
void parallel_invoke(const F& f, const G& g) {
#if defined(HMIRA_HAS_TBB)
    tbb::parallel_invoke(f, g);
#else
    f();
    g();
#endif
}

/// Runs f() with at most `threads` worker threads (0: the TBB default, all cores).
template <class F>
void with_thread_count(unsigned threads, const F& f) {
#if defined(HMIRA_HAS_TBB)
    if (threads != 0) {
        tbb::task_arena arena(static_cast<int>(threads));
        arena.execute(f);
        return;
    }
#else
    (void)threads;
#endif
    f();
}

}  // namespace hmira::detail
