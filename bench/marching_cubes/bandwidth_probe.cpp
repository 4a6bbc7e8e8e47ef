// Memory-bandwidth probe: is marching cubes' 1 -> 2 thread speed-up on the large
// volumes capped by the machine rather than by the algorithm? Measures GB/s with 1 and 2
// std::threads for the memory patterns MC has:
//   read        streaming read (sum) of an already-touched buffer the size of the input volume
//               (MC's classification pass reads every sample);
//   fresh write writing a freshly mapped buffer the size of the gyroid 384^3 output, so every
//               page is first touched here (kernel page fault + zeroing, then our stores):
//               MC's output arrays are new each call and written only by the writing pass;
//   touched write the same stores into a buffer whose pages are already mapped;
//   fresh write, huge pages  as fresh write, with madvise(MADV_HUGEPAGE) (2 MB pages, where
//               THP is enabled): what an output allocator asking for huge pages would pay;
// and the serial munmap of the fresh output (MC's caller frees it on one thread). Two controls
// that touch no main memory tell the machine's own 1 -> 2 thread ceiling apart from memory:
//   compute     a register-only integer loop (no loads or stores);
//   cached read the read pattern over a 256 KiB buffer per thread, in each core's L2.
// If these also fall short of 2x, the two vCPUs are not two idle cores (a shared host core or
// a busy neighbour), and no code change reaches 2x here.
// The output sizes are measured: hmira's MC (serial here, no TBB) on the benchmark's gyroid
// and sphere at 384^3, bytes = 12 per vertex (vec3<float>) + 12 per triangle (3 x uint32).
// usage: bandwidth_probe [--reps N] [--n SIDE]   (medians of N repetitions, default 7)
#include <sys/mman.h>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <numbers>
#include <string>
#include <thread>
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

double fastest(const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); }

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Runs f(begin, end) over [0, words) split into `threads` contiguous parts, one std::thread
// each (the caller's thread takes the last part); returns the wall seconds.
template <class F>
double split_run(std::size_t words, unsigned threads, const F& f) {
    const auto t0 = clock_type::now();
    std::vector<std::thread> pool;
    const std::size_t part = words / threads;
    for (unsigned t = 0; t + 1 < threads; ++t) pool.emplace_back([&, t] { f(t * part, (t + 1) * part); });
    f((threads - 1) * part, words);
    for (auto& th : pool) th.join();
    return seconds_since(t0);
}

std::uint64_t* map_fresh(std::size_t bytes, bool huge = false) {
    // mmap, as glibc's malloc does for blocks this large: pages arrive on first touch.
    void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) {
        std::perror("mmap");
        std::exit(1);
    }
    if (huge) (void)madvise(p, bytes, MADV_HUGEPAGE);  // a hint: ignored where THP is off
    return static_cast<std::uint64_t*>(p);
}

// Ordinary stores of values the compiler cannot turn into memset (which may use
// non-temporal stores that MC's writes do not).
void write_words(std::uint64_t* p, std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) p[i] = i;
}

std::atomic<std::uint64_t> sink{0};

void read_words(const std::uint64_t* p, std::size_t b, std::size_t e) {
    std::uint64_t s = 0;
    for (std::size_t i = b; i < e; ++i) s += p[i];
    sink += s;
}

// A serial chain of multiply-adds per thread: no memory traffic, so its 2/1 speed-up is the
// machine's compute ceiling. `steps` iterations over [b, e) of a split.
void compute_steps(std::size_t b, std::size_t e) {
    std::uint64_t x = b | 1, y = e | 3;
    for (std::size_t i = b; i < e; ++i) {
        x = x * 6364136223846793005ull + 1442695040888963407ull;
        y ^= x >> 29;
    }
    sink += x + y;
}

struct pattern_result {
    double gbs[2] = {0, 0};   // medians, 1 and 2 threads
    double best[2] = {0, 0};  // fastest repetition: on a shared machine, the least disturbed
};

struct mc_output {
    std::size_t vertices = 0, triangles = 0;
    std::size_t bytes() const { return 12 * vertices + 12 * triangles; }
};

mc_output measure_output(const std::string& shape, std::size_t n) {
    const auto geo = hmira::cube_geometry(n, -1, 1);
    auto grid = shape == "sphere" ? *hmira::sample_function(geo, hmira::sphere_field{{0, 0, 0}, 0.8})
                                  : *hmira::sample_function(geo, hmira::gyroid_field{4 * std::numbers::pi});
    auto out = hmira::marching_cubes_indexed(grid, {.iso = 0, .threads = 1});
    if (!out) {
        std::fprintf(stderr, "%s\n", out.error().message.c_str());
        std::exit(1);
    }
    return {out->positions.size(), out->triangles.size()};
}

std::string first_line(const char* path) {
    std::ifstream f(path);
    std::string s;
    std::getline(f, s);
    return s.empty() ? "?" : s;
}

/// The value of option `name`: a whole number in [lo, hi], or a one-line error and exit 2.
std::size_t count_option(const char* name, const char* text, std::size_t lo, std::size_t hi) {
    std::size_t v = 0;
    const char* end = text + std::strlen(text);
    const auto [p, ec] = std::from_chars(text, end, v);
    if (ec != std::errc{} || p != end || v < lo || v > hi) {
        std::fprintf(stderr, "bandwidth_probe: %s takes a whole number from %zu to %zu, not '%s'\n", name, lo, hi,
                     text);
        std::exit(2);
    }
    return v;
}

}  // namespace

int main(int argc, char** argv) {
    int reps = 7;
    std::size_t n = 384;
    for (int a = 1; a < argc; a += 2) {
        const bool known = std::strcmp(argv[a], "--reps") == 0 || std::strcmp(argv[a], "--n") == 0;
        if (!known || a + 1 == argc) {
            std::fprintf(stderr, "bandwidth_probe: %s '%s' (usage: bandwidth_probe [--reps N] [--n EDGE])\n",
                         known ? "no value after" : "unknown option", argv[a]);
            return 2;
        }
        // Volumes of n^3 floats and their outputs: 1024^3 is already 4 GiB of input.
        if (std::strcmp(argv[a], "--reps") == 0)
            reps = static_cast<int>(count_option("--reps", argv[a + 1], 1, 1000));
        else
            n = count_option("--n", argv[a + 1], 8, 1024);
    }
    const mc_output gyroid = measure_output("gyroid", n), sphere = measure_output("sphere", n);
    const std::size_t read_bytes = n * n * n * sizeof(float);
    const std::size_t write_bytes = gyroid.bytes() / 64 * 64;  // whole 64-bit words per thread half
    std::printf("bandwidth probe: %zu^3 volumes, medians of %d, THP %s, %u hardware threads\n", n, reps,
                first_line("/sys/kernel/mm/transparent_hugepage/enabled").c_str(), std::thread::hardware_concurrency());
    std::printf("output gyroid_%zu vertices=%zu triangles=%zu bytes=%zu\n", n, gyroid.vertices, gyroid.triangles,
                gyroid.bytes());
    std::printf("output sphere_%zu vertices=%zu triangles=%zu bytes=%zu\n", n, sphere.vertices, sphere.triangles,
                sphere.bytes());
    std::printf("input volume bytes=%zu\n\n", read_bytes);

    const std::size_t rwords = read_bytes / 8, wwords = write_bytes / 8;
    pattern_result read, fresh, touched, huge;
    double unmap_ms = 0;
    {
        std::uint64_t* in = map_fresh(read_bytes);
        write_words(in, 0, rwords);
        std::uint64_t* out = map_fresh(write_bytes);
        write_words(out, 0, wwords);
        for (unsigned t = 1; t <= 2; ++t) {
            std::vector<double> r, f, w, u, h;
            for (int rep = 0; rep < reps; ++rep) {
                r.push_back(split_run(rwords, t, [&](std::size_t b, std::size_t e) { read_words(in, b, e); }));
                w.push_back(split_run(wwords, t, [&](std::size_t b, std::size_t e) { write_words(out, b, e); }));
                std::uint64_t* p = map_fresh(write_bytes);
                f.push_back(split_run(wwords, t, [&](std::size_t b, std::size_t e) { write_words(p, b, e); }));
                const auto t0 = clock_type::now();
                munmap(p, write_bytes);
                u.push_back(seconds_since(t0));
                p = map_fresh(write_bytes, true);
                h.push_back(split_run(wwords, t, [&](std::size_t b, std::size_t e) { write_words(p, b, e); }));
                munmap(p, write_bytes);
            }
            read.gbs[t - 1] = double(read_bytes) / median(r) / 1e9;
            read.best[t - 1] = double(read_bytes) / fastest(r) / 1e9;
            touched.gbs[t - 1] = double(write_bytes) / median(w) / 1e9;
            touched.best[t - 1] = double(write_bytes) / fastest(w) / 1e9;
            fresh.gbs[t - 1] = double(write_bytes) / median(f) / 1e9;
            fresh.best[t - 1] = double(write_bytes) / fastest(f) / 1e9;
            huge.gbs[t - 1] = double(write_bytes) / median(h) / 1e9;
            huge.best[t - 1] = double(write_bytes) / fastest(h) / 1e9;
            if (t == 1) unmap_ms = 1000 * median(u);
        }
        munmap(in, read_bytes);
        munmap(out, write_bytes);
    }
    // Controls: compute (no memory) and a read that stays in each core's L2 (256 KiB a thread,
    // read 256 times), in G steps/s and GB/s.
    pattern_result compute, cached;
    const std::size_t compute_steps_total = std::size_t(1) << 28;
    const std::size_t cached_words = 256 * 1024 / 8, cached_passes = 256;
    {
        std::vector<std::uint64_t> buf(2 * cached_words, 1);
        for (unsigned t = 1; t <= 2; ++t) {
            std::vector<double> c, r;
            for (int rep = 0; rep < reps; ++rep) {
                c.push_back(split_run(compute_steps_total, t, compute_steps));
                r.push_back(split_run(cached_passes * t, t, [&](std::size_t b, std::size_t e) {
                    // each thread reads its own 256 KiB block, (e - b) times
                    const std::uint64_t* mine = buf.data() + (b / cached_passes) * cached_words;
                    for (std::size_t pass = b; pass < e; ++pass) read_words(mine, 0, cached_words);
                }));
            }
            compute.gbs[t - 1] = double(compute_steps_total) / median(c) / 1e9;
            compute.best[t - 1] = double(compute_steps_total) / fastest(c) / 1e9;
            // 2 threads read twice the bytes (each its own block cached_passes times)
            const double bytes = double(cached_passes * t * cached_words * 8);
            cached.gbs[t - 1] = bytes / median(r) / 1e9;
            cached.best[t - 1] = bytes / fastest(r) / 1e9;
        }
    }
    std::printf(
        "| pattern | MB | 1 thread GB/s | 2 threads GB/s | 2/1 speed-up | 2/1 of the fastest runs "
        "|\n|---|---|---|---|---|---|\n");
    const auto row = [](const char* name, std::size_t bytes, const pattern_result& p) {
        std::printf("| %s | %.0f | %.2f | %.2f | %.2f | %.2f |\n", name, double(bytes) / 1e6, p.gbs[0], p.gbs[1],
                    p.gbs[1] / p.gbs[0], p.best[1] / p.best[0]);
    };
    row("read (touched)", read_bytes, read);
    row("fresh write (first touch)", write_bytes, fresh);
    row("touched write", write_bytes, touched);
    row("fresh write, huge pages", write_bytes, huge);
    row("control: cached read (256 KiB a thread, L2)", 256 * 1024, cached);
    std::printf("| control: compute, no memory (G steps/s) | 0 | %.2f | %.2f | %.2f | %.2f |\n", compute.gbs[0],
                compute.gbs[1], compute.gbs[1] / compute.gbs[0], compute.best[1] / compute.best[0]);
    std::printf("munmap of the fresh output (serial): %.1f ms\n", unmap_ms);
    return 0;
}
