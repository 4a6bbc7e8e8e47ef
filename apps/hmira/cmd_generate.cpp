// apps/hmira/cmd_generate.cpp
// `hmira generate`: writes one of the five Platonic solids, centred at the origin.
#include <hmira/algorithms/generators/platonic_solids.hpp>

#include "cli.hpp"

namespace {

using namespace hmira_cli;

struct generate_args {
    std::string solid, output;
    double scale = 1.0;
};

int run_generate(const generate_args& a, const common_options& o) {
    hmira::face_vertex_mesh m;
    const hmira::solid_options s{.scale = a.scale};
    hmira::result<void> made;
    auto done = [&](auto r) { made = r ? hmira::result<void>{} : hmira::result<void>(r.error()); };
    if (a.solid == "tetrahedron")
        done(hmira::generate_tetrahedron(m, s));
    else if (a.solid == "cube")
        done(hmira::generate_cube(m, s));
    else if (a.solid == "octahedron")
        done(hmira::generate_octahedron(m, s));
    else if (a.solid == "dodecahedron")
        done(hmira::generate_dodecahedron(m, s));
    else if (a.solid == "icosahedron")
        done(hmira::generate_icosahedron(m, s));
    if (!made) return report(internal, made.error().message);
    if (int c = save(m, a.output, {}, o); c != ok) return c;
    say(o, a.output + ": " + a.solid + ", " + std::to_string(m.vertex_count()) + " vertices, " +
               std::to_string(m.face_count()) + " faces");
    return ok;
}

const bool registered = register_command(
    {"generate", "Write a Platonic solid (tetrahedron, cube, octahedron, dodecahedron, icosahedron)",
     "hmira generate dodecahedron d.obj --scale 2.5", 40,
     [](CLI::App& sub) {
         auto a = std::make_shared<generate_args>();
         sub.add_option("solid", a->solid, "which solid")
             ->required()
             ->check(CLI::IsMember({"tetrahedron", "cube", "octahedron", "dodecahedron", "icosahedron"}));
         sub.add_option("output", a->output, "mesh file to write (.obj .off .ply .stl)")->required();
         sub.add_option("--scale", a->scale, "multiply every coordinate by this")
             ->capture_default_str()
             ->check(finite_number("> 0", [](double x) { return x > 0; }));
         return [a](const common_options& o) { return run_generate(*a, o); };
     },
     /* reads_files = */ false});

}  // namespace
