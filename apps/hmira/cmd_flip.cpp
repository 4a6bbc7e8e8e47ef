// apps/hmira/cmd_flip.cpp
// `hmira flip`: reverses every face's winding, so all normals point the other way.
#include <hmira/algorithms/orientation/flip_normals.hpp>

#include "cli.hpp"

namespace {

using namespace hmira_cli;

struct flip_args {
    std::string input, output;
};

int run_flip(const flip_args& a, const common_options& o) {
    int code = ok;
    auto loaded = load(a.input, o, code);
    if (!loaded) return code;
    const auto n = hmira::flip_normals(loaded->mesh);
    // Vertex normals, if the file had them, must turn with the faces.
    if (auto normals = loaded->mesh.get_vertex_property<hmira::vec3<float>>("v:normal"))
        for (auto& v : normals->values()) v = -v;
    if (int c = save(loaded->mesh, a.output, {}, o); c != ok) return c;
    say(o, a.output + ": flipped " + std::to_string(n) + " faces");
    return ok;
}

const bool registered = register_command(
    {"flip", "Reverse the orientation of every face (and of vertex normals)", "hmira flip inside_out.obj fixed.obj", 50,
     [](CLI::App& sub) {
         auto a = std::make_shared<flip_args>();
         sub.add_option("input", a->input, "mesh file to read")->required();
         sub.add_option("output", a->output, "mesh file to write (replaced atomically; not the input)")->required();
         return [a](const common_options& o) { return run_flip(*a, o); };
     }});

}  // namespace
