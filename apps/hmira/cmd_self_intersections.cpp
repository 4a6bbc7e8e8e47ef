// apps/hmira/cmd_self_intersections.cpp
// `hmira self-intersections`: lists the pairs of faces of a mesh that intersect other than along
// the edges and vertices they share, decided exactly; exit code 1 if there are any.
#include <iostream>
#include <limits>

#include <hmira/algorithms/validation/self_intersections.hpp>

#include "cli.hpp"

namespace {

using namespace hmira_cli;

struct self_intersections_args {
    std::string input;
    std::size_t max = 20;
};

int run_self_intersections(const self_intersections_args& a, const common_options& o) {
    int code = ok;
    auto loaded = load(a.input, o, code);
    if (!loaded) return code;
    auto bar = stage_bar("self-intersections " + a.input, o, loaded->mesh.face_count());
    const auto progress = [&](double f) {
        bar.update(std::uint64_t(f * 1000), 1000);
        return true;
    };
    const auto pairs = hmira::self_intersections(loaded->mesh, {.progress = progress});
    if (!pairs) return report(exit_code_for(pairs.error()), a.input + ": " + pairs.error().message);
    if (pairs->empty()) {
        say(o, a.input + ": no self-intersections (" + count_of(loaded->mesh.face_count(), "face", "faces") + ")");
        return ok;
    }
    if (!o.quiet) {
        std::cout << a.input << ": " << count_of(pairs->size(), "intersecting pair", "intersecting pairs")
                  << " of faces\n";
        for (std::size_t i = 0; i < pairs->size() && (a.max == 0 || i < a.max); ++i)
            std::cout << "  " << (*pairs)[i][0] << ' ' << (*pairs)[i][1] << '\n';
        if (a.max != 0 && pairs->size() > a.max)
            std::cout << "  ... and " << pairs->size() - a.max << " more (--max 0 lists all)\n";
    }
    return invalid_input;
}

const bool registered = register_command(
    {"self-intersections",
     "List pairs of faces that intersect other than along a shared edge or vertex (exact; exit code 1 if any)",
     "hmira self-intersections part.stl --max 0", 21, [](CLI::App& sub) {
         auto a = std::make_shared<self_intersections_args>();
         sub.add_option("input", a->input, "mesh file (.obj .off .ply .stl)")->required();
         sub.add_option("--max", a->max, "list at most this many pairs (0: all)")
             ->capture_default_str()
             ->check(whole_number(0, std::numeric_limits<std::uint64_t>::max()));
         return [a](const common_options& o) { return run_self_intersections(*a, o); };
     }});

}  // namespace
