// apps/hmira/cmd_validate.cpp
// `hmira validate`: lists what is wrong with a mesh (degenerate faces, non-manifold edges and
// vertices, inconsistent orientation, isolated vertices...); exit code 1 if anything is.
#include <iostream>

#include <hmira/algorithms/validation/validate.hpp>

#include "cli.hpp"

namespace {

using namespace hmira_cli;

struct validate_args {
    std::string input;
    std::size_t max = 20;
    bool relaxed = hmira::validate_options{}.relaxed;
    bool no_geometry = !hmira::validate_options{}.check_geometry;
    bool self_intersections = hmira::validate_options{}.check_self_intersections;
};

int run_validate(const validate_args& a, const common_options& o) {
    int code = ok;
    auto loaded = load(a.input, o, code);
    if (!loaded) return code;
    const auto problems = hmira::validate(loaded->mesh, {.relaxed = a.relaxed,
                                                         .check_geometry = !a.no_geometry,
                                                         .max_problems = 0,
                                                         .check_self_intersections = a.self_intersections});
    if (problems.empty()) {
        say(o, a.input + ": valid (" + std::to_string(loaded->mesh.vertex_count()) + " vertices, " +
                   std::to_string(loaded->mesh.face_count()) + " faces)");
        return ok;
    }
    if (!o.quiet) {
        std::cout << a.input << ": " << problems.size() << " problem(s)\n";
        for (std::size_t i = 0; i < problems.size() && (a.max == 0 || i < a.max); ++i)
            std::cout << "  " << hmira::to_string(problems[i].kind) << ": " << problems[i].message << '\n';
        if (a.max != 0 && problems.size() > a.max)
            std::cout << "  ... and " << problems.size() - a.max << " more (--max 0 lists all)\n";
    }
    return invalid_input;
}

const bool registered =
    register_command({"validate", "Check a mesh and list its problems (exit code 1 if there are any)",
                      "hmira validate scan.ply --max 50", 20, [](CLI::App& sub) {
                          auto a = std::make_shared<validate_args>();
                          sub.add_option("input", a->input, "mesh file (.obj .off .ply .stl)")->required();
                          sub.add_option("--max", a->max, "list at most this many problems (0: all)")
                              ->capture_default_str()
                              ->check(whole_number(0, std::numeric_limits<std::uint64_t>::max()));
                          sub.add_flag("--relaxed", a->relaxed,
                                       "accept isolated vertices and the other states legal during Euler construction");
                          sub.add_flag("--no-geometry", a->no_geometry, "skip the zero-area face check");
                          sub.add_flag("--self-intersections", a->self_intersections,
                                       "also list pairs of faces that intersect (exact; slower)");
                          return [a](const common_options& o) { return run_validate(*a, o); };
                      }});

}  // namespace
