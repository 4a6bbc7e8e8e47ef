// bench/support/sweep.hpp
// What the size sweeps share (bench/sweep, bench/editing's scaling bench): CPU time of a call,
// medians over fresh copies, and the least-squares exponent of time against size on log-log
// axes, compared with the exponent a doc block's complexity implies.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <fstream>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <unistd.h>

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

/// One size of a sweep: its element count, the median time of a call, and the bytes the call
/// works on (its input and what it allocates; 0 when not measured).
struct sweep_point {
    double elements = 0;
    double seconds = 0;
    double bytes = 0;
};

/// The size of the last-level data cache in bytes: the highest level in
/// /sys/devices/system/cpu/cpu0/cache (what lscpu shows), else sysconf, else 32 MiB. A virtual
/// machine's sysconf may report the host's CPUID value (320 MiB here), so /sys comes first.
inline double last_level_cache_bytes() {
    double best = 0;
    int best_level = 0;
    for (int i = 0; i < 8; ++i) {
        const std::string dir = "/sys/devices/system/cpu/cpu0/cache/index" + std::to_string(i) + "/";
        std::ifstream level(dir + "level"), type(dir + "type"), size(dir + "size");
        int l = 0;
        std::string t, sz;
        if (!(level >> l) || !(type >> t) || !(size >> sz) || t == "Instruction") continue;
        double bytes = std::atof(sz.c_str());
        if (sz.back() == 'K')
            bytes *= 1024;
        else if (sz.back() == 'M')
            bytes *= 1024 * 1024;
        if (l > best_level) best_level = l, best = bytes;
    }
    if (best > 0) return best;
#ifdef _SC_LEVEL3_CACHE_SIZE
    if (const long b = sysconf(_SC_LEVEL3_CACHE_SIZE); b > 0) return double(b);
#endif
    return 32.0 * 1024 * 1024;
}

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
    double exponent = 1;    ///< the exponent it implies
    double slack = 0.15;    ///< a fitted exponent up to exponent + slack agrees
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

/// How many times the last-level cache a size's working set must exceed to count as beyond
/// it: a call that touches its working set at random hits the cache with probability about
/// cache / working set, so at 4x three quarters of its accesses already miss and the time per
/// element is within a small step of its in-memory plateau.
inline constexpr double beyond_cache_factor = 4;

/// The exponent fitted over the sizes whose measured working set is at least
/// beyond_cache_factor times the last-level cache, when there are at least three of them
/// spanning at least half a decade: the regime where every size pays the same memory latency
/// per access, so the slope is the algorithm's, not a cache level's. Nothing otherwise.
inline std::optional<double> beyond_cache_exponent(const std::vector<sweep_point>& pts, double cache_bytes) {
    std::vector<sweep_point> big;
    for (const auto& p : pts)
        if (p.bytes >= beyond_cache_factor * cache_bytes) big.push_back(p);
    if (big.size() < 3) return std::nullopt;
    double lo = big.front().elements, hi = lo;
    for (const auto& p : big) lo = std::min(lo, p.elements), hi = std::max(hi, p.elements);
    if (hi < lo * 3.1) return std::nullopt;
    return fitted_exponent(big);
}

/// "PASS" when the fitted exponent agrees with the claim (at most exponent + slack; a smaller
/// one means fixed costs dominate the small sizes, which no claim forbids), else "FAIL".
inline const char* verdict(double fitted, const complexity_claim& claim) {
    return std::isfinite(fitted) && fitted <= claim.exponent + claim.slack ? "PASS" : "FAIL";
}

/// Whether the largest decade's sizes lie on both sides of the cache boundary: its smallest
/// size's working set below beyond_cache_factor times the cache, its largest above the cache.
/// A slope fitted across that boundary measures the step in memory latency per access.
inline bool largest_decade_crosses_cache(const std::vector<sweep_point>& pts, double cache_bytes) {
    double top = 0;
    for (const auto& p : pts) top = std::max(top, p.elements);
    bool below = false, above = false;
    for (const auto& p : pts) {
        if (p.elements < top / 10.0 * 0.999 || !(p.bytes > 0)) continue;
        below = below || p.bytes < beyond_cache_factor * cache_bytes;
        above = above || p.bytes > cache_bytes;
    }
    return below && above;
}

/// The summary line of one sweep: the exponent fitted over the whole sweep, over its largest
/// decade and over the sizes beyond the last-level cache, the spread of the time per element,
/// and the verdict, which it returns: "PASS", "FAIL", or "UNSURE". The verdict goes on the
/// sizes beyond the cache when the sweep has enough of them (see beyond_cache_exponent), else
/// on the largest decade: below that, a step in the time per element from one cache level to
/// the next (memory latency per access, the same count of accesses) steepens the slope by
/// what is no part of the complexity. A largest decade that fails while it crosses the cache
/// boundary (a --quick sweep's, typically) cannot tell the two apart: "UNSURE", for the full
/// sweep to decide.
inline std::string print_sweep_summary(const std::string& name, const std::vector<sweep_point>& pts,
                                       const complexity_claim& claim) {
    const double k = fitted_exponent(pts), upper = upper_decade_exponent(pts), cache = last_level_cache_bytes();
    const auto beyond = beyond_cache_exponent(pts, cache);
    std::string v = verdict(beyond ? *beyond : upper, claim);
    if (!beyond && v == "FAIL" && largest_decade_crosses_cache(pts, cache)) v = "UNSURE";
    char beyond_text[32] = "too few sizes";
    if (beyond) std::snprintf(beyond_text, sizeof beyond_text, "%.2f", *beyond);
    std::printf(
        "%-44s exponent %5.2f (largest decade %5.2f; beyond %.0fx the %.0f MiB cache %s; "
        "documented %s: <= %.2f), time per element max/min %.2fx  %s (judged on the %s)\n",
        name.c_str(), k, upper, beyond_cache_factor, cache / (1024 * 1024), beyond_text, claim.text,
        claim.exponent + claim.slack, per_element_spread(pts), v.c_str(),
        beyond ? "sizes beyond the cache" : "largest decade");
    return v;
}

}  // namespace hmira_bench
