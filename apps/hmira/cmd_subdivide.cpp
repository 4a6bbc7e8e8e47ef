// apps/hmira/cmd_subdivide.cpp
// `hmira subdivide`: Loop or sqrt(3) subdivision of a triangle mesh, or Catmull-Clark
// subdivision of any polygon mesh, k levels.
#include <hmira/algorithms/subdivision/subdivide.hpp>

#include "cli.hpp"

namespace {

using namespace hmira_cli;

struct subdivide_args {
    std::string input, output, scheme = name_of(hmira::subdivide_options{}.scheme);
    std::size_t levels = hmira::subdivide_options{}.levels;
};

int run_subdivide(const subdivide_args& a, const common_options& o) {
    int code = ok;
    auto loaded = load_for_edit(a.input, o, code);
    if (!loaded) return code;
    return run_edit(
        *loaded, a.input, a.output, "subdividing " + a.input, o,
        [&](hmira::halfedge_mesh& mesh, int& c) -> std::optional<edit_outcome> {
            const std::uint64_t faces_made = std::uint64_t(mesh.face_count()) << (2 * a.levels);
            auto bar = stage_bar("subdividing " + a.input, o, faces_made);
            const auto progress = [&](double f) {
                bar.update(std::uint64_t(f * 1000), 1000);
                return true;
            };
            const auto r = hmira::subdivide(
                mesh, {.scheme = named<hmira::subdivision_scheme>(a.scheme), .levels = a.levels, .progress = progress});
            if (!r) {
                c = report(exit_code_for(r.error()), a.input + ": " + r.error().message);
                return std::nullopt;
            }
            return edit_outcome{"subdivided " + count_of(a.levels, "level", "levels") + " (" + a.scheme + ")", {}};
        });
}

const bool registered = register_command(
    {"subdivide", "Subdivide a mesh (Loop or sqrt3 for triangles, Catmull-Clark for any polygons), k levels",
     "hmira subdivide bunny.off smooth.off --scheme loop -k 2", 86, [](CLI::App& sub) {
         auto a = std::make_shared<subdivide_args>();
         sub.add_option("input", a->input,
                        "mesh file to read (manifold, consistently oriented; triangles for loop and sqrt3)")
             ->required();
         sub.add_option("output", a->output,
                        "mesh file to write: the input's vertices first, in file order, then the new ones")
             ->required();
         sub.add_option("--scheme", a->scheme,
                        "subdivision scheme: loop or sqrt3 (triangles) or catmull-clark (any polygons, quads out)")
             ->check(CLI::IsMember(names_of<hmira::subdivision_scheme>()));
         sub.add_option("-k,--levels", a->levels,
                        "levels of subdivision, 1 to 10 (each multiplies the faces by 4, by 3 for sqrt3; "
                        "catmull-clark's first makes one quad per face corner)")
             ->check(CLI::Range(std::size_t(1), std::size_t(10)));
         return [a](const common_options& o) { return run_subdivide(*a, o); };
     }});

}  // namespace
