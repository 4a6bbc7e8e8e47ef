// Scaling of truncate, bevel and extrude applied to every element (issue 13, item 2): each edit
// on all vertices / edges / faces of quad tori from 10k to 1M faces, with the fitted exponent of
// time against size and the time per element; then bevel of every edge against truncate of
// every vertex of a 128^3 gyroid from marching cubes (~450k edges), library calls only.
// Usage: editing_scaling_bench [max_faces] (default 1000000). Prints one line per run.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <hmira/algorithms/conversion/marching_cubes.hpp>
#include <hmira/algorithms/editing/editing.hpp>
#include <hmira/algorithms/generators/torus.hpp>
#include <hmira/grids/implicit_shapes.hpp>
#include <hmira/grids/sample.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

namespace {

using M = hmira::halfedge_mesh;
using T = hmira::default_traits<M>;

M torus(std::size_t side) {
    M m;
    if (!hmira::generate_torus(m, {.major_radius = 4, .minor_radius = 1, .rings = side, .sides = side})) std::abort();
    return m;
}

template <class Edit>
double seconds(M m, Edit edit) {
    const auto t0 = std::chrono::steady_clock::now();
    const bool ok = edit(m);
    const auto t1 = std::chrono::steady_clock::now();
    if (!ok) {
        std::fprintf(stderr, "edit failed\n");
        std::exit(1);
    }
    return std::chrono::duration<double>(t1 - t0).count();
}

bool truncate_all(M& m) { return hmira::truncate_all(m, {.fraction = 0.3}).has_value(); }
bool bevel_all(M& m) {
    std::vector<T::edge_handle> es;
    for (auto e : T::edges(m)) es.push_back(e);
    return hmira::bevel(m, es, {.width = 0.001, .segments = 1}).has_value();
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

struct sweep_point {
    double faces, elements, time;
};

/// Least-squares slope of log(time) against log(faces).
double exponent(const std::vector<sweep_point>& pts) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const auto& p : pts) {
        const double x = std::log(p.faces), y = std::log(p.time);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
    }
    const double n = double(pts.size());
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace

int main(int argc, char** argv) {
    const double max_faces = argc > 1 ? std::atof(argv[1]) : 1e6;
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
        std::vector<sweep_point> pts;
        for (std::size_t side : {100u, 178u, 316u, 562u, 1000u}) {
            if (double(side * side) > max_faces * 1.01) break;
            const M m = torus(side);
            const double k = double(e.elements(m));
            double best = 1e300;
            for (int rep = 0; rep < (side < 500 ? 3 : 1); ++rep) best = std::min(best, seconds(m, e.run));
            pts.push_back({double(T::face_count(m)), k, best});
            std::printf("%-36s faces %8.0f elements %8.0f  %8.3f s  %7.1f ns/element\n", e.name, double(T::face_count(m)), k, best,
                        best / k * 1e9);
        }
        double lo = 1e300, hi = 0;
        for (const auto& p : pts) {
            lo = std::min(lo, p.time / p.elements);
            hi = std::max(hi, p.time / p.elements);
        }
        std::printf("%-36s fitted exponent %.3f, time per element varies %.2fx\n\n", e.name, exponent(pts), hi / lo);
    }
    // The comparison: a 128^3 gyroid (~450k edges), bevel every edge vs truncate every vertex.
    M g;
    const auto grid = hmira::sample_function(hmira::cube_geometry(128, -6.0, 6.0), hmira::gyroid_field{});
    if (!grid || !hmira::marching_cubes(g, grid.value(), {})) return 1;
    const double tb = seconds(g, bevel_all), tt = seconds(g, truncate_all);
    std::printf("gyroid 128^3: %zu V, %zu E, %zu F; bevel all edges %.3f s, truncate all vertices %.3f s, ratio %.2f\n",
                T::vertex_count(g), T::edge_count(g), T::face_count(g), tb, tt, tb / tt);
    return 0;
}
