// bench/support/peer_bench.hpp
// What the side-by-side benchmarks share: a torus soup of quads or triangles, building any
// model from it through its traits, and a main() that repeats each case, keeps the CPU times
// and prints median ratios against their targets.
#pragma once

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include <hmira/core/vec3.hpp>
#include <hmira/traits.hpp>

namespace hmira_bench {

/// Points and faces (indices into points).
struct soup {
    std::vector<hmira::vec3<double>> points;
    std::vector<std::vector<std::size_t>> faces;
};

/// A torus of n x n quads, or of 2 n^2 triangles (each quad cut along a diagonal).
inline soup make_torus(std::size_t n, bool triangles) {
    soup t;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) {
            const double u = 2 * std::numbers::pi * double(i) / double(n),
                         v = 2 * std::numbers::pi * double(j) / double(n);
            t.points.push_back(
                {(2 + 0.7 * std::cos(v)) * std::cos(u), (2 + 0.7 * std::cos(v)) * std::sin(u), 0.7 * std::sin(v)});
        }
    auto id = [n](std::size_t i, std::size_t j) { return (i % n) * n + (j % n); };
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) {
            if (triangles) {
                t.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
                t.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
            } else {
                t.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
            }
        }
    return t;
}

/// Any model built from a soup through its traits.
template <class M, class T = hmira::default_traits<M>>
M build(const soup& s) {
    M m;
    std::vector<typename T::vertex_handle> vs;
    vs.reserve(s.points.size());
    for (const auto& p : s.points)
        vs.push_back(T::add_vertex(m, {typename T::scalar(p.x), typename T::scalar(p.y), typename T::scalar(p.z)}));
    std::vector<typename T::vertex_handle> c;
    for (const auto& f : s.faces) {
        c.clear();
        for (auto i : f) c.push_back(vs[i]);
        (void)T::add_face(m, std::span<const typename T::vertex_handle>(c));
    }
    return m;
}

/// Each case's single-run CPU times, by name, for the ratio summary.
inline std::map<std::string, std::vector<double>>& seconds_by_case() {
    static std::map<std::string, std::vector<double>> s;
    return s;
}

/// Console output as usual, and each single run's CPU time kept for the summary: on a shared
/// machine the wall time of a single-threaded run mostly measures the other processes.
class collecting_reporter : public benchmark::ConsoleReporter {
public:
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const auto& r : runs)
            if (r.run_type == Run::RT_Iteration && !r.error_occurred && r.iterations > 0)
                seconds_by_case()[r.run_name.function_name].push_back(r.cpu_accumulated_time / double(r.iterations));
        ConsoleReporter::ReportRuns(runs);
    }
};

/// The median CPU time of a case, or 0 when it did not run.
inline double median_of(const std::string& name) {
    auto it = seconds_by_case().find(name);
    if (it == seconds_by_case().end() || it->second.empty()) return 0;
    auto v = it->second;
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

/// One line of the summary: the ratio of two cases' medians against its target.
inline void print_ratio(const std::string& label, const std::string& a, const std::string& b, double target) {
    const double ta = median_of(a), tb = median_of(b);
    if (ta <= 0 || tb <= 0) return;
    std::printf("%-58s %7.1f ms / %7.1f ms = %5.2f  (target <= %.2f)%s\n", label.c_str(), ta * 1e3, tb * 1e3, ta / tb,
                target, ta / tb <= target ? "" : "  MISSED");
}

/// Runs the registered cases, three repetitions unless the command line says otherwise, with
/// the collecting reporter; then the caller prints its ratios.
inline int run_benchmarks(int argc, char** argv) {
    std::vector<char*> args(argv, argv + argc);
    std::string reps = "--benchmark_repetitions=3";
    bool has_reps = false;
    for (int i = 1; i < argc; ++i) has_reps |= std::string(argv[i]).rfind("--benchmark_repetitions", 0) == 0;
    if (!has_reps) args.insert(args.begin() + 1, reps.data());
    int n = int(args.size());
    benchmark::Initialize(&n, args.data());
    if (benchmark::ReportUnrecognizedArguments(n, args.data())) return 1;
    collecting_reporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    return 0;
}

}  // namespace hmira_bench
