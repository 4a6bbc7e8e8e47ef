// tests/support/cancel_points.hpp
// Where the cancellation tests stop an algorithm. Each stop reruns the algorithm up to that
// progress call and checks the rolled-back mesh, so the number of stops sets the test's cost.
#pragma once

#include <algorithm>
#include <vector>

namespace hmira_test {

/// Whether this test binary runs under AddressSanitizer and UBSan (CI's only run of the gtest
/// suites), where each instrumented step costs 10-30 times its plain time.
#ifdef HMIRA_SANITIZER_BUILD
inline constexpr bool sanitizer_build = true;
#else
inline constexpr bool sanitizer_build = false;
#endif

/// The progress calls (1-based) at which to cancel an algorithm that reports `calls` times.
/// A plain build stops at every (calls / samples)-th call from the first. A sanitizer build
/// stops at the first, the middle and the last call only: the start, a half-written mesh and a
/// finished one still each get their rollback checked, at a fraction of the instrumented time.
inline std::vector<int> cancel_points(int calls, int samples) {
    std::vector<int> out;
    if (calls < 1) return out;
#ifdef HMIRA_SANITIZER_BUILD
    (void)samples;
    out = {1, (calls + 1) / 2, calls};
#else
    for (int k = 1; k <= calls; k += std::max(1, calls / std::max(1, samples))) out.push_back(k);
#endif
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

}  // namespace hmira_test
