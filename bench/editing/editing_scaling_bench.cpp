// Scaling of truncate, bevel and extrude applied to every element: each edit
// on all vertices / edges / faces of quad tori from 10k to 1M faces, with the fitted exponent of
// time against size and the time per element; then bevel of every edge against truncate of
// every vertex of a 128^3 gyroid from marching cubes (~450k edges), library calls only.
// Usage: editing_scaling_bench [max_faces] [repeats] [only] (defaults 1000000, 3, all): `only`
// runs the sweeps whose name contains it ("truncate", "bevel", "extrude") or "gyroid". Every timing is
// the median of `repeats` calls on fresh copies of the mesh (the machine may be shared and
// noisy); the individual times are printed too.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <ctime>

#include <vector>

#include <hmira/algorithms/conversion/marching_cubes.hpp>
#include <hmira/algorithms/editing/editing.hpp>
#include <hmira/algorithms/generators/torus.hpp>
#include <hmira/grids/implicit_shapes.hpp>
#include <hmira/grids/sample.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "support/sweep.hpp"

namespace {

using M = hmira::halfedge_mesh;
using T = hmira::default_traits<M>;

M torus(std::size_t side) {
    M m;
    if (!hmira::generate_torus(m, {.major_radius = 4, .minor_radius = 1, .rings = side, .sides = side})) std::abort();
    return m;
}

/// One call's CPU time and wall time. The fits use CPU time: on a shared machine the wall
/// time also counts the time other processes held the core, which says nothing of the edit.
struct timing {
    double cpu = 0, wall = 0;
    long faults = 0;  // minor page faults during the call (fresh memory touched)
};

template <class Edit>
timing seconds(M m, Edit edit) {
    const long f0 = hmira_bench::minor_page_faults();
    const double c0 = hmira_bench::thread_cpu_seconds();
    const auto t0 = std::chrono::steady_clock::now();
    const bool ok = edit(m);
    const auto t1 = std::chrono::steady_clock::now();
    const double c1 = hmira_bench::thread_cpu_seconds();
    const long f1 = hmira_bench::minor_page_faults();
    if (!ok) {
        std::fprintf(stderr, "edit failed\n");
        std::exit(1);
    }
    return {c1 - c0, std::chrono::duration<double>(t1 - t0).count(), f1 - f0};
}

bool truncate_all(M& m) { return hmira::truncate_all(m, {.fraction = 0.3}).has_value(); }
bool bevel_all(M& m) {
    // Every edge between two faces, as `hmira bevel --all` (the torus has no others).
    std::vector<T::edge_handle> es;
    for (auto e : T::edges(m))
        if (!m.is_boundary(e)) es.push_back(e);
    return hmira::bevel(m, es, {.width = 0.001, .segments = 1}).has_value();
}
bool bevel_every(M& m) {
    std::vector<T::edge_handle> es;
    for (auto e : T::edges(m)) es.push_back(e);
    const auto r = hmira::bevel(m, es, {.width = 0.001, .segments = 1});
    if (!r) std::fprintf(stderr, "%s\n", r.error().message.c_str());
    return r.has_value();
}
bool extrude_all_individual(M& m) {
    std::vector<T::face_handle> fs;
    for (auto f : T::faces(m)) fs.push_back(f);
    return hmira::extrude(m, fs, {.distance = 0.001, .mode = hmira::extrude_mode::individual}).has_value();
}
bool extrude_half_region(M& m) {
    // A region with an outline: every face but one ring's worth (the torus would have none).
    std::vector<T::face_handle> fs;
    const std::size_t skip = std::size_t(std::sqrt(double(T::face_count(m))));
    std::size_t i = 0;
    for (auto f : T::faces(m))
        if (i++ >= skip) fs.push_back(f);
    return hmira::extrude(m, fs, {.distance = 0.001, .mode = hmira::extrude_mode::region}).has_value();
}

using hmira_bench::median;

/// The median CPU time of `repeats` calls after one untimed warm-up call (each call's CPU time in `all`, the median
/// wall time
/// in `wall`).
template <class Edit>
double median_seconds(const M& m, Edit edit, int repeats, std::vector<double>& all, double& wall,
                      long* faults = nullptr) {
    all.clear();
    (void)seconds(m, edit);  // warm-up: the heap grows to this size once, untimed
    std::vector<double> walls;
    for (int rep = 0; rep < repeats; ++rep) {
        const timing t = seconds(m, edit);
        all.push_back(t.cpu);
        walls.push_back(t.wall);
        if (faults) *faults = t.faults;
    }
    wall = median(walls);
    return median(all);
}

std::string list(const std::vector<double>& xs) {
    std::string s;
    char buf[32];
    for (double x : xs) {
        std::snprintf(buf, sizeof buf, "%s%.3f", s.empty() ? "" : " ", x);
        s += buf;
    }
    return s;
}

}  // namespace

int main(int argc, char** argv) {
    const double max_faces = argc > 1 ? std::atof(argv[1]) : 1e6;
    const int repeats = argc > 2 ? std::atoi(argv[2]) : 3;
    if (!(max_faces > 0) || repeats < 1) {
        std::fprintf(stderr, "usage: editing_scaling_bench [max_faces > 0] [repeats >= 1]\n");
        return 2;
    }
    const std::string only = argc > 3 ? argv[3] : "";
    std::setvbuf(stdout, nullptr, _IOLBF, 0);
    // Without this, 40% of a 1M-face edit's time was the kernel clearing fresh pages.
    hmira_bench::keep_freed_memory();
    std::vector<double> runs;
    struct edit {
        const char* name;
        bool (*run)(M&);
        std::size_t (*elements)(const M&);
    };
    const edit edits[] = {
        {"truncate all vertices", truncate_all, [](const M& m) { return T::vertex_count(m); }},
        {"bevel all edges", bevel_all, [](const M& m) { return T::edge_count(m); }},
        {"extrude all faces (individual)", extrude_all_individual, [](const M& m) { return T::face_count(m); }},
        {"extrude region (all but one ring)", extrude_half_region, [](const M& m) { return T::face_count(m); }},
    };
    for (const auto& e : edits) {
        if (std::string(e.name).find(only) == std::string::npos) continue;
        std::vector<hmira_bench::sweep_point> by_faces, by_elements;
        for (std::size_t side : {100u, 178u, 316u, 562u, 1000u}) {
            if (double(side * side) > max_faces * 1.01) break;
            const M m = torus(side);
            const double k = double(e.elements(m));
            double wall = 0;
            long faults = 0;
            const double t = median_seconds(m, e.run, repeats, runs, wall, &faults);
            by_faces.push_back({double(T::face_count(m)), t});
            by_elements.push_back({k, t});
            std::printf(
                "%-34s faces %8.0f elements %8.0f  median cpu %7.3f s %7.1f ns/element (runs %s), wall %7.3f s, "
                "%.2f page faults/element\n",
                e.name, double(T::face_count(m)), k, t, t / k * 1e9, list(runs).c_str(), wall, double(faults) / k);
        }
        // Each doc block claims time linear in the elements edited (O(sum of degrees) = O(E)).
        const double k = hmira_bench::fitted_exponent(by_faces);
        std::printf("%-36s fitted exponent %.3f, time per element varies %.2fx  %s (documented linear)\n\n", e.name, k,
                    hmira_bench::per_element_spread(by_elements),
                    hmira_bench::verdict(k, {.text = "linear", .exponent = 1}));
    }
    // The comparison: a 128^3 gyroid (~450k edges), bevel every edge vs truncate every vertex.
    if (std::string("gyroid").find(only) == std::string::npos) return 0;
    M g;
    const auto grid = hmira::sample_function(hmira::cube_geometry(128, -6.0, 6.0), hmira::gyroid_field{});
    if (!grid || !hmira::marching_cubes(g, grid.value(), {})) return 1;
    std::vector<double> bevel_runs, truncate_runs;
    double bevel_wall = 0, truncate_wall = 0;
    const double tb = median_seconds(g, bevel_all, repeats, bevel_runs, bevel_wall);
    const double tt = median_seconds(g, truncate_all, repeats, truncate_runs, truncate_wall);
    std::printf(
        "gyroid 128^3: %zu V, %zu E, %zu F; median cpu: bevel all edges %.3f s (runs %s), truncate all vertices "
        "%.3f s (runs %s), ratio %.2f (wall %.3f / %.3f s, ratio %.2f)\n",
        T::vertex_count(g), T::edge_count(g), T::face_count(g), tb, list(bevel_runs).c_str(), tt,
        list(truncate_runs).c_str(), tb / tt, bevel_wall, truncate_wall, bevel_wall / truncate_wall);
    // Boundary edges bevel too (the gyroid is cut open by the box): every edge of the mesh.
    std::size_t boundary = 0;
    for (auto e : T::edges(g)) boundary += g.is_boundary(e) ? 1 : 0;
    std::vector<double> every_runs;
    double every_wall = 0;
    const double te = median_seconds(g, bevel_every, repeats, every_runs, every_wall);
    std::printf(
        "gyroid 128^3: bevel every edge (%zu on the boundary) %.3f s cpu (runs %s), ratio to truncate %.2f (wall %.3f "
        "s)\n",
        boundary, te, list(every_runs).c_str(), te / tt, every_wall);
    return 0;
}
