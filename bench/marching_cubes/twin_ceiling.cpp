// How much of marching cubes' 1 -> 2 thread speed-up does this machine allow for this
// very work? Each round runs, in random order:
//   solo   one call with 1 thread;
//   two    one call with 2 threads (hmira's own parallel passes, TBB);
//   twins  two independent 1-thread calls at once, on two std::threads, each on its own copy of
//          the volume, released together.
// The twins share nothing of ours: no tasks, no output arrays, no split of the slabs. So
// 2 x solo / twins is the most two threads can give this work here (the ceiling): it folds in
// memory bandwidth, first-touch page faults, and a host that gives the two vCPUs less than two
// whole cores (e.g. hyperthread siblings, or a busy neighbour). solo / two over that ceiling,
// taken within each round, is what hmira's parallel scheme itself costs or gains.
// Also a wide-compute control (8 independent integer chains, near the core's issue width), the
// kind of work that a shared physical core cannot run twice at full speed; a single dependent
// chain (bandwidth_probe's compute control) scales 2x even on hyperthread siblings.
// usage: twin_ceiling [--rounds N] [volume ...]   (volumes: gyroid_128 ... gyroid_384; default all)
#include <algorithm>
#include <atomic>
#include <charconv>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <numbers>
#include <random>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <hmira/algorithms/conversion/marching_cubes.hpp>
#include <hmira/grids/dense_grid.hpp>
#include <hmira/grids/implicit_shapes.hpp>
#include <hmira/grids/sample.hpp>

namespace {

using clock_type = std::chrono::steady_clock;

double seconds_since(clock_type::time_point t0) {
    return std::chrono::duration<double>(clock_type::now() - t0).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double quantile(std::vector<double> v, double q) {
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size())))];
}

// The shape and size a volume name gives; exits naming the volume if it is not one.
std::pair<std::string, std::size_t> parse_volume(const std::string& name) {
    const auto us = name.find('_');
    const std::string shape = name.substr(0, us);
    std::size_t n = 0;
    const char* digits = name.c_str() + us + 1;
    const auto [p, ec] = std::from_chars(digits, name.c_str() + name.size(), n);
    if (us == std::string::npos || ec != std::errc{} || *p != '\0' || n < 8 || n > 1024 ||
        (shape != "sphere" && shape != "torus" && shape != "gyroid")) {
        std::fprintf(stderr, "twin_ceiling: unknown volume '%s' (sphere_N, torus_N or gyroid_N, 8 <= N <= 1024)\n",
                     name.c_str());
        std::exit(2);
    }
    return {shape, n};
}

hmira::dense_grid<float> make_volume(const std::string& name) {
    const auto [shape, n] = parse_volume(name);
    // The same fields as bench_marching_cubes.
    const auto geo = hmira::cube_geometry(n, -1, 1);
    if (shape == "sphere") return *hmira::sample_function(geo, hmira::sphere_field{{0, 0, 0}, 0.8});
    if (shape == "torus") return *hmira::sample_function(geo, hmira::torus_field{{0, 0, 0}, 0.6, 0.25});
    return *hmira::sample_function(geo, hmira::gyroid_field{4 * std::numbers::pi});
}

// One call; returns its wall seconds (the output is freed after the clock stops).
double one_call(const hmira::dense_grid<float>& grid, unsigned threads) {
    const auto t0 = clock_type::now();
    auto out = hmira::marching_cubes_indexed(grid, {.iso = 0, .threads = threads});
    const double s = seconds_since(t0);
    if (!out) {
        std::fprintf(stderr, "twin_ceiling: %s\n", out.error().message.c_str());
        std::exit(1);
    }
    return s;
}

// f(0) and f(1) on two threads released together; returns the wall seconds until both are done.
template <class F>
double twins(const F& f) {
    std::atomic<int> ready{0};
    std::atomic<bool> go{false};
    double other = 0;
    std::thread second([&] {
        ready.fetch_add(1);
        while (!go.load(std::memory_order_acquire)) {}
        const auto t0 = clock_type::now();
        f(1);
        other = seconds_since(t0);
    });
    while (ready.load() < 1) {}
    const auto t0 = clock_type::now();
    go.store(true, std::memory_order_release);
    f(0);
    second.join();
    return std::max(seconds_since(t0), other);
}

std::atomic<std::uint64_t> sink{0};

// Eight independent add/xor chains: about as many integer operations per cycle as a core issues.
void wide_compute(std::uint64_t steps) {
    std::uint64_t a = 1, b = 2, c = 3, d = 4, e = 5, f = 6, g = 7, h = 8;
    for (std::uint64_t i = 0; i < steps; ++i) {
        a += i;
        b ^= a;
        c += i;
        d ^= c;
        e += i;
        f ^= e;
        g += i;
        h ^= g;
        asm volatile("" : "+r"(a), "+r"(b), "+r"(c), "+r"(d), "+r"(e), "+r"(f), "+r"(g), "+r"(h));
    }
    sink += a ^ b ^ c ^ d ^ e ^ f ^ g ^ h;
}

// One dependent multiply-add chain: latency-bound, a fraction of the core's issue width.
void narrow_compute(std::uint64_t steps) {
    std::uint64_t x = 1;
    for (std::uint64_t i = 0; i < steps; ++i) {
        x = x * 6364136223846793005ull + i;
        asm volatile("" : "+r"(x));
    }
    sink += x;
}

struct row {
    std::string name;
    std::vector<double> solo, two, pair, speedup, ceiling, share;
    // One round's three wall times, and the ratios taken within the round.
    void add(double s, double t, double p) {
        solo.push_back(s);
        two.push_back(t);
        pair.push_back(p);
        speedup.push_back(s / t);
        ceiling.push_back(2 * s / p);
        share.push_back((s / t) / (2 * s / p));
    }
};

void print(const row& r) {
    std::printf("| %s | %.1f | %.1f | %.1f | %.2f | %.2f | %.2f (%.2f-%.2f) |\n", r.name.c_str(), 1e3 * median(r.solo),
                1e3 * median(r.two), 1e3 * median(r.pair), median(r.speedup), median(r.ceiling), median(r.share),
                quantile(r.share, 0.25), quantile(r.share, 0.75));
}

}  // namespace

int main(int argc, char** argv) {
    int rounds = 11;
    std::vector<std::string> names;
    for (int a = 1; a < argc; ++a) {
        if (std::strcmp(argv[a], "--rounds") == 0) {
            const char* text = a + 1 < argc ? argv[++a] : "";
            const auto [p, ec] = std::from_chars(text, text + std::strlen(text), rounds);
            if (ec != std::errc{} || *p != '\0' || rounds < 1 || rounds > 1000) {
                std::fprintf(stderr, "twin_ceiling: --rounds takes a whole number from 1 to 1000, not '%s'\n", text);
                return 2;
            }
        } else {
            names.emplace_back(argv[a]);
        }
    }
    if (names.empty()) names = {"gyroid_128", "gyroid_256", "sphere_384", "torus_384", "gyroid_384"};
    for (const auto& name : names) static_cast<void>(parse_volume(name));  // refuse a bad name before any work
    std::printf("twin ceiling: %d rounds, %u hardware threads; ratios are medians of per-round ratios\n\n", rounds,
                std::thread::hardware_concurrency());
    std::printf(
        "| work | solo ms | 2 threads ms | twins ms | hmira speed-up (solo / 2 threads) | ceiling (2 solo / twins) | "
        "speed-up / ceiling (quartiles) |\n|---|---|---|---|---|---|---|\n");
    std::mt19937 order_rng(20);
    for (const auto& name : names) {
        const hmira::dense_grid<float> grid = make_volume(name);
        const hmira::dense_grid<float> copy = grid;
        static_cast<void>(one_call(grid, 1));  // warm-up: the TBB pool, the case table, the pages of both copies
        static_cast<void>(one_call(copy, 2));
        row r{name, {}, {}, {}, {}, {}, {}};
        for (int round = 0; round < rounds; ++round) {
            int order[3] = {0, 1, 2};
            std::shuffle(order, order + 3, order_rng);
            double solo = 0, two = 0, pair = 0;
            for (const int which : order) {
                if (which == 0)
                    solo = one_call(grid, 1);
                else if (which == 1)
                    two = one_call(grid, 2);
                else
                    pair = twins([&](int t) { static_cast<void>(one_call(t == 0 ? grid : copy, 1)); });
            }
            r.add(solo, two, pair);
        }
        print(r);
    }
    // The controls: the same three ways, with "2 threads" being the work split in two halves.
    for (const bool wide : {true, false}) {
        const std::uint64_t steps = std::uint64_t{1} << (wide ? 27 : 25);
        const auto work = [&](std::uint64_t s) { wide ? wide_compute(s) : narrow_compute(s); };
        row r{wide ? "control: wide compute (8 chains)" : "control: narrow compute (1 chain)", {}, {}, {}, {}, {}, {}};
        for (int round = 0; round < rounds; ++round) {
            const auto t0 = clock_type::now();
            work(steps);
            const double solo = seconds_since(t0);
            const double two = twins([&](int) { work(steps / 2); });
            const double pair = twins([&](int) { work(steps); });
            r.add(solo, two, pair);
        }
        print(r);
    }
    return 0;
}
