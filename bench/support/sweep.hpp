// bench/support/sweep.hpp
// What the size sweeps share (bench/sweep, bench/editing's scaling bench): CPU time of a call,
// medians over fresh copies, and the least-squares exponent of time against size on log-log
// axes, compared with the exponent a doc block's complexity implies.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include <sys/resource.h>
#include <time.h>

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace hmira_bench {

/// CPU time of the whole process (user + system, every thread, page faults included), in
/// seconds: the measure on a shared machine, where wall time counts the other processes too.
inline double process_cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

/// This thread's CPU time, in seconds (for single-threaded calls).
inline double thread_cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

/// Minor page faults of this thread so far (fresh memory touched).
inline long minor_page_faults() {
    rusage u{};
    getrusage(RUSAGE_THREAD, &u);
    return u.ru_minflt;
}

/// The median (mean of the middle two for an even count).
inline double median(std::vector<double> xs) {
    if (xs.empty()) return 0;
    std::sort(xs.begin(), xs.end());
    const std::size_t n = xs.size();
    return n % 2 ? xs[n / 2] : (xs[n / 2 - 1] + xs[n / 2]) / 2;
}

/// Keeps freed memory in the process: large blocks otherwise come fresh from the kernel on
/// every call (mmap, then zeroed page by page), while small inputs reuse the heap, so a sweep
/// would measure the kernel's page clearing at its large end, not the algorithm.
inline void keep_freed_memory() {
#ifdef __GLIBC__
    mallopt(M_MMAP_MAX, 0);
    mallopt(M_TRIM_THRESHOLD, std::numeric_limits<int>::max());
#endif
}

/// One size of a sweep: its element count and the median time of a call.
struct sweep_point {
    double elements = 0;
    double seconds = 0;
};

/// Least-squares slope of log(seconds) against log(elements): the fitted exponent k of
/// time ~ elements^k. NaN for fewer than two distinct sizes.
inline double fitted_exponent(const std::vector<sweep_point>& pts) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const auto& p : pts) {
        const double x = std::log(p.elements), y = std::log(p.seconds);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
    }
    const double n = double(pts.size()), d = n * sxx - sx * sx;
    if (pts.size() < 2 || !(d > 0)) return std::numeric_limits<double>::quiet_NaN();
    return (n * sxy - sx * sy) / d;
}

/// How much the time per element varies over the sweep: max / min (1 for exactly linear).
inline double per_element_spread(const std::vector<sweep_point>& pts) {
    double lo = std::numeric_limits<double>::infinity(), hi = 0;
    for (const auto& p : pts) {
        lo = std::min(lo, p.seconds / p.elements);
        hi = std::max(hi, p.seconds / p.elements);
    }
    return pts.empty() ? 0 : hi / lo;
}

/// A documented complexity as the exponent it implies on a log-log fit: 1 for O(n), 1 for
/// O(n log n) too (log n adds ~0.1 to the fitted slope over 10^4..10^7, which `slack` covers),
/// 3 for O(n^3), with the allowance above it before the sweep calls the claim wrong.
struct complexity_claim {
    const char* text = "";  ///< as the doc block says it, e.g. "O(n log n) expected"
    double exponent = 1;   ///< the exponent it implies
    double slack = 0.15;   ///< a fitted exponent up to exponent + slack agrees
};

/// The exponent fitted over the largest decade of sizes only (n >= max n / 10; the whole sweep
/// when that holds fewer than two sizes): the asymptotic regime, where every size's working set
/// is beyond the caches. Over the whole sweep a step in time per element between cache levels
/// (flat within L2, within L3, within RAM) adds to the slope what is no part of the complexity.
inline double upper_decade_exponent(const std::vector<sweep_point>& pts) {
    double top = 0;
    for (const auto& p : pts) top = std::max(top, p.elements);
    std::vector<sweep_point> upper;
    for (const auto& p : pts)
        if (p.elements >= top / 10.0 * 0.999) upper.push_back(p);
    return upper.size() >= 2 ? fitted_exponent(upper) : fitted_exponent(pts);
}

/// "PASS" when the fitted exponent agrees with the claim (at most exponent + slack; a smaller
/// one means fixed costs dominate the small sizes, which no claim forbids), else "FAIL".
inline const char* verdict(double fitted, const complexity_claim& claim) {
    return std::isfinite(fitted) && fitted <= claim.exponent + claim.slack ? "PASS" : "FAIL";
}

/// The summary line of one sweep: the exponent fitted over the whole sweep and over its largest
/// decade, the spread of the time per element, and the verdict on the largest decade's exponent.
inline bool print_sweep_summary(const std::string& name, const std::vector<sweep_point>& pts, const complexity_claim& claim) {
    const double k = fitted_exponent(pts), upper = upper_decade_exponent(pts);
    const char* v = verdict(upper, claim);
    std::printf("%-44s exponent %5.2f (largest decade %5.2f; documented %s: <= %.2f), time per element max/min %.2fx  %s\n",
                name.c_str(), k, upper, claim.text, claim.exponent + claim.slack, per_element_spread(pts), v);
    return v[0] == 'P';
}

}  // namespace hmira_bench
