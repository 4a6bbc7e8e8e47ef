// mesh_quality A B [--target L] [--samples N]: compares an output mesh B with its input A.
// Prints the symmetric Hausdorff distance (sampled at 10 points per triangle and at least N,
// default 10^6, points per mesh, through the AABB tree), absolute and relative to A's bounding
// box diagonal, then triangle-quality histograms and edge-length statistics of both meshes.

#include <cstdio>
#include <cstdlib>
#include <string>

#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

#include "quality/quality.hpp"

int main(int argc, char** argv) {
    namespace q = hmira_bench::quality;
    std::string a_path, b_path;
    double target = 0;
    std::size_t samples = 1000000;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if ((arg == "--target" || arg == "--samples") && i + 1 < argc) {
            char* end = nullptr;
            const double x = std::strtod(argv[++i], &end);
            if (*end != '\0' || !(x > 0) || x > 1e12) {
                std::fprintf(stderr, "mesh_quality: option %s needs a positive number, got '%s'\n", arg.c_str(),
                             argv[i]);
                return 2;
            }
            if (arg == "--target")
                target = x;
            else
                samples = std::size_t(x);
        } else if (a_path.empty()) {
            a_path = arg;
        } else if (b_path.empty()) {
            b_path = arg;
        } else {
            std::fprintf(stderr, "mesh_quality: unexpected argument '%s'\n", arg.c_str());
            return 2;
        }
    }
    if (a_path.empty()) {
        std::fprintf(stderr, "usage: mesh_quality A [B] [--target L] [--samples N]\n");
        return 2;
    }
    hmira::face_vertex_mesh a, b;
    if (auto r = hmira::io::read_mesh(a, a_path); !r) {
        std::fprintf(stderr, "mesh_quality: %s\n", r.error().message.c_str());
        return 1;
    }
    const auto sa = q::soup_of(a);
    std::fputs(q::describe(a_path.c_str(), sa, target).c_str(), stdout);
    if (b_path.empty()) return 0;
    if (auto r = hmira::io::read_mesh(b, b_path); !r) {
        std::fprintf(stderr, "mesh_quality: %s\n", r.error().message.c_str());
        return 1;
    }
    const auto sb = q::soup_of(b);
    std::fputs(q::describe(b_path.c_str(), sb, target).c_str(), stdout);
    hmira::vec3<double> lo{1e300, 1e300, 1e300}, hi = -lo;
    for (const auto& p : sa.points)
        for (std::size_t k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    const double diagonal = hmira::norm(hi - lo);
    const auto h = q::hausdorff(sa, sb, 10, samples);
    std::printf("Hausdorff: symmetric %.6g (%.4f%% of A's bbox diagonal %.4g)\n", h.symmetric(),
                100 * h.symmetric() / diagonal, diagonal);
    std::printf("  A->B max %.6g mean %.3g rms %.3g (%zu samples)\n", h.a_to_b.max, h.a_to_b.mean, h.a_to_b.rms,
                h.a_to_b.samples);
    std::printf("  B->A max %.6g mean %.3g rms %.3g (%zu samples)\n", h.b_to_a.max, h.b_to_a.mean, h.b_to_a.rms,
                h.b_to_a.samples);
    return 0;
}
