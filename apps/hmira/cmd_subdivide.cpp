// apps/hmira/cmd_subdivide.cpp
// `hmira subdivide`: Loop or sqrt(3) subdivision of a triangle mesh, or Catmull-Clark
// subdivision of any polygon mesh, k levels.
#include <hmira/algorithms/subdivision/catmull_clark.hpp>
#include <hmira/algorithms/subdivision/loop.hpp>
#include <hmira/algorithms/subdivision/sqrt3.hpp>

#include "cli.hpp"

namespace {

using namespace hmira_cli;

struct subdivide_args {
    std::string input, output, scheme = "loop";
    std::size_t levels = 1;
};

int run_subdivide(const subdivide_args& a, const common_options& o) {
    int code = ok;
    auto loaded = load_for_edit(a.input, o, code);
    if (!loaded) return code;
    return run_edit(*loaded, a.input, a.output, "subdividing " + a.input, o,
                    [&](hmira::halfedge_mesh& mesh, int& c) -> std::optional<edit_outcome> {
                        std::optional<hmira::error> failed;
                        const std::uint64_t faces_made = std::uint64_t(mesh.face_count()) << (2 * a.levels);
                        auto bar = stage_bar("subdividing " + a.input, o, faces_made);
                        const auto progress = [&](double f) {
                            bar.update(std::uint64_t(f * 1000), 1000);
                            return true;
                        };
                        const auto keep = [&](const auto& r) {
                            if (!r) failed = r.error();
                        };
                        const std::size_t k = a.levels;
                        if (a.scheme == "loop") keep(hmira::loop_subdivide(mesh, {.levels = k, .progress = progress}));
                        else if (a.scheme == "sqrt3")
                            keep(hmira::sqrt3_subdivide(mesh, {.levels = k, .progress = progress}));
                        else keep(hmira::catmull_clark_subdivide(mesh, {.levels = k, .progress = progress}));
                        if (failed) {
                            c = report(exit_code_for(*failed), a.input + ": " + failed->message);
                            return std::nullopt;
                        }
                        return edit_outcome{"subdivided " + count_of(a.levels, "level", "levels") + " (" + a.scheme + ")", {}};
                    });
}

const bool registered = register_command({
    "subdivide", "Subdivide a mesh (Loop or sqrt3 for triangles, Catmull-Clark for any polygons), k levels",
    "hmira subdivide bunny.off smooth.off --scheme loop -k 2", 86,
    [](CLI::App& sub) {
        auto a = std::make_shared<subdivide_args>();
        sub.add_option("input", a->input, "mesh file to read (manifold, consistently oriented; triangles for loop and sqrt3)")->required();
        sub.add_option("output", a->output, "mesh file to write: the input's vertices first, in file order, then the new ones")->required();
        sub.add_option("--scheme", a->scheme, "subdivision scheme: loop or sqrt3 (triangles) or catmull-clark (any polygons, quads out)")
            ->check(CLI::IsMember({"loop", "sqrt3", "catmull-clark"}));
        sub.add_option("-k,--levels", a->levels, "levels of subdivision, 1 to 10 (each multiplies the faces by 4, by 3 for sqrt3; catmull-clark's first makes one quad per face corner)")
            ->check(CLI::Range(std::size_t(1), std::size_t(10)));
        return [a](const common_options& o) { return run_subdivide(*a, o); };
    }});

}  // namespace
