// apps/hmira/cmd_sample.cpp
// `hmira sample IN OUT.ply`: random points on a mesh's surface, uniform by area or blue noise
// (Poisson disk), written as a point cloud; the same seed gives the same points.
#include <string>

#include <hmira/algorithms/spatial/sample_surface.hpp>

#include "cli.hpp"

namespace {

using namespace hmira_cli;

struct sample_args {
    std::string input, output;
    std::size_t count = 10000;
    std::string method = name_of(hmira::sample_surface_options{}.method);
    std::uint64_t seed = hmira::sample_surface_options{}.seed;
};

int run_sample(const sample_args& a, const common_options& o) {
    int code = ok;
    auto loaded = load(a.input, o, code);
    if (!loaded) return code;
    if (!refuse_non_finite(loaded->mesh, a.input, "sample", code)) return code;
    const auto s = hmira::sample_surface(loaded->mesh, a.count,
                                         {.method = named<hmira::sampling_method>(a.method), .seed = a.seed});
    if (!s) return report(input_exit_code(s.error()), a.input + ": " + s.error().message);
    hmira::face_vertex_mesh cloud;
    for (const auto& p : s->points) cloud.add_vertex({p.x, p.y, p.z});
    if (const int w = save(cloud, a.output, {}, o); w != ok) return w;
    say(o, a.input + ": " + std::to_string(s->points.size()) + " points (" + a.method + ", seed " +
               std::to_string(a.seed) + ") -> " + a.output);
    return ok;
}

const bool registered = register_command(
    {"sample", "Random points on a mesh's surface (uniform by area, or Poisson disk), as a point cloud",
     "hmira sample bunny.off points.ply --count 100000", 121, [](CLI::App& sub) {
         auto a = std::make_shared<sample_args>();
         sub.add_option("input", a->input, "mesh file to read (.obj .off .ply .stl)")->required();
         sub.add_option("output", a->output, "point cloud to write (vertices only; .ply .obj .off)")->required();
         sub.add_option("--count", a->count, "how many points")
             ->capture_default_str()
             ->check(whole_number(1, 1000000000));
         sub.add_option("--method", a->method, "uniform (independent, by area) or poisson_disk (blue noise)")
             ->capture_default_str()
             ->check(CLI::IsMember(names_of<hmira::sampling_method>()));
         sub.add_option("--seed", a->seed, "the same seed gives the same points")->capture_default_str();
         return [a](const common_options& o) { return run_sample(*a, o); };
     }});

}  // namespace
