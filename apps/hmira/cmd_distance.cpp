// apps/hmira/cmd_distance.cpp
// `hmira distance A B`: how far apart two surfaces are, by the library's sampled Hausdorff
// distance: the symmetric distance, and per direction the maximum, mean and RMS.
#include <cstdio>
#include <string>

#include <hmira/algorithms/spatial/hausdorff_distance.hpp>

#include "cli.hpp"

namespace {

using namespace hmira_cli;

struct distance_args {
    std::string a, b;
    std::size_t samples = hmira::hausdorff_options{}.min_samples;
    bool json = false;
};

std::string g17(double x) {
    char b[40];
    std::snprintf(b, sizeof b, "%.17g", x);
    return b;
}

std::string side_json(const hmira::one_sided_distance& d) {
    return "{\"max\": " + g17(d.max) + ", \"mean\": " + g17(d.mean) + ", \"rms\": " + g17(d.rms) +
           ", \"samples\": " + std::to_string(d.samples) + "}";
}

int run_distance(const distance_args& a, const common_options& o) {
    int code = ok;
    auto la = load(a.a, o, code);
    if (!la) return code;
    auto lb = load(a.b, o, code);
    if (!lb) return code;
    if (!refuse_non_finite(la->mesh, a.a, "distance", code) || !refuse_non_finite(lb->mesh, a.b, "distance", code))
        return code;
    const auto h = hmira::hausdorff_distance(la->mesh, lb->mesh,
                                             {.min_samples = a.samples, .threads = static_cast<unsigned>(o.threads)});
    if (!h) return report(input_exit_code(h.error()), a.a + ", " + a.b + ": " + h.error().message);
    if (a.json) {
        std::printf("{\"symmetric\": %s, \"a_to_b\": %s, \"b_to_a\": %s}\n", g17(h->symmetric).c_str(),
                    side_json(h->a_to_b).c_str(), side_json(h->b_to_a).c_str());
        return ok;
    }
    std::printf("Hausdorff distance: %.6g\n", h->symmetric);
    std::printf("  A->B max %.6g mean %.6g rms %.6g (%zu samples)\n", h->a_to_b.max, h->a_to_b.mean, h->a_to_b.rms,
                h->a_to_b.samples);
    std::printf("  B->A max %.6g mean %.6g rms %.6g (%zu samples)\n", h->b_to_a.max, h->b_to_a.mean, h->b_to_a.rms,
                h->b_to_a.samples);
    return ok;
}

const bool registered = register_command(
    {"distance", "Sampled Hausdorff distance (with mean and RMS) between two meshes' surfaces",
     "hmira distance input.off simplified.off --json", 120, [](CLI::App& sub) {
         auto a = std::make_shared<distance_args>();
         sub.add_option("a", a->a, "first mesh (.obj .off .ply .stl)")->required();
         sub.add_option("b", a->b, "second mesh")->required();
         sub.add_option("--samples", a->samples,
                        "random points per surface at least (10 per triangle at least, plus every vertex)")
             ->capture_default_str()
             ->check(whole_number(1, 1000000000));
         sub.add_flag("--json", a->json,
                      "print one JSON object: symmetric, a_to_b and b_to_a (max, mean, rms, samples)");
         return [a](const common_options& o) { return run_distance(*a, o); };
     }});

}  // namespace
