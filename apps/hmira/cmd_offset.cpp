// apps/hmira/cmd_offset.cpp
// `hmira offset IN OUT --distance d`: the surface at signed distance d from a mesh (outward for
// d > 0, inward for d < 0), by the signed distance on a grid and marching cubes.
#include <string>

#include <hmira/algorithms/spatial/signed_distance_grid.hpp>

#include "cli.hpp"

namespace {

using namespace hmira_cli;

struct offset_args {
    std::string input, output;
    double distance = 0;
    std::size_t resolution = hmira::offset_options{}.resolution;
};

int run_offset(const offset_args& a, const common_options& o) {
    int code = ok;
    auto loaded = load(a.input, o, code);
    if (!loaded) return code;
    if (!refuse_non_finite(loaded->mesh, a.input, "offset", code)) return code;
    const auto r = hmira::offset(loaded->mesh, a.distance,
                                 {.resolution = a.resolution, .threads = static_cast<unsigned>(o.threads)});
    if (!r) return report(input_exit_code(r.error()), a.input + ": " + r.error().message);
    hmira::face_vertex_mesh out;
    std::vector<hmira::vertex_handle> vs;
    vs.reserve(r->positions.size());
    for (const auto& p : r->positions) vs.push_back(out.add_vertex({p.x, p.y, p.z}));
    for (const auto& t : r->triangles) {
        const std::array<hmira::vertex_handle, 3> f{vs[t[0]], vs[t[1]], vs[t[2]]};
        if (auto added = out.add_face(f); !added)
            return report(internal, a.input + ": offset: " + added.error().message);
    }
    if (const int w = save(out, a.output, {}, o); w != ok) return w;
    say(o, a.input + ": offset " + number_text(a.distance) + ", " + std::to_string(r->triangles.size()) +
               " triangles -> " + a.output);
    return ok;
}

const bool registered = register_command(
    {"offset", "The surface at a signed distance from a mesh (outward > 0, inward < 0), by SDF and marching cubes",
     "hmira offset bunny.off shell.off --distance 0.01", 123, [](CLI::App& sub) {
         auto a = std::make_shared<offset_args>();
         sub.add_option("input", a->input, "mesh file to read (.obj .off .ply .stl)")->required();
         sub.add_option("output", a->output, "mesh to write")->required();
         sub.add_option("-d,--distance", a->distance, "the offset distance, in the mesh's units (negative: inward)")
             ->required()
             ->check(finite_number());
         sub.add_option("-n,--resolution", a->resolution, "grid samples along the longest side")
             ->capture_default_str()
             ->check(whole_number(8, 2048));
         return [a](const common_options& o) { return run_offset(*a, o); };
     }});

}  // namespace
