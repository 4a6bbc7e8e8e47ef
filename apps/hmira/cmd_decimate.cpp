// apps/hmira/cmd_decimate.cpp
// `hmira decimate`: quadric error decimation (Garland-Heckbert) of a triangle mesh down to a
// face count, a fraction of the faces, or an error bound; polygon input is triangulated first.
#include <cmath>
#include <iostream>

#include <hmira/algorithms/decimation/decimate.hpp>

#include "cli.hpp"

namespace {

using namespace hmira_cli;

struct decimate_args {
    std::string input, output;
    std::optional<std::size_t> faces;
    std::optional<double> ratio, max_error;
    double max_normal_angle = hmira::decimate_options{}.max_normal_angle;
    double max_aspect_ratio = 0;  // 0: not given (the library's default, no limit)
    bool move_boundary = !hmira::decimate_options{}.keep_boundary;
    std::vector<std::size_t> fixed;
    std::vector<std::size_t> locked;  // --lock: the old name of --fix (deprecated; smooth calls it --fix)
};

int run_decimate(const decimate_args& a, const common_options& o) {
    if (!a.faces && !a.ratio && !a.max_error)
        return report(usage, "decimate: give --faces N, --ratio R or --max-error E");
    int code = ok;
    auto loaded = load_for_edit(a.input, o, code);
    if (!loaded) return code;
    if (!check_indices(a.fixed, loaded->mesh.vertex_count(), "vertex", "--fix", a.input, code)) return code;
    if (!check_indices(a.locked, loaded->mesh.vertex_count(), "vertex", "--lock", a.input, code)) return code;
    if (!a.locked.empty()) std::cerr << "hmira decimate: --lock is deprecated; use --fix (as hmira smooth)\n";
    const std::uint64_t work = loaded->mesh.face_count();
    return run_edit(*loaded, a.input, a.output, "decimating " + a.input, o,
                    [&](hmira::halfedge_mesh& mesh, int& c) -> std::optional<edit_outcome> {
                        progress_bar bar("decimating " + a.input, o, 1u << 20);
                        hmira::decimate_options options{
                            .target_faces = a.faces, .target_ratio = a.ratio, .max_error = a.max_error};
                        options.keep_boundary = !a.move_boundary;
                        options.max_normal_angle = a.max_normal_angle;
                        if (a.max_aspect_ratio > 0) options.max_aspect_ratio = a.max_aspect_ratio;
                        options.locked_vertices = a.fixed;
                        options.locked_vertices.insert(options.locked_vertices.end(), a.locked.begin(), a.locked.end());
                        options.progress = [&](double f) {
                            bar.update(std::uint64_t(f * double(work)), work);
                            return true;
                        };
                        auto r = hmira::decimate(mesh, options);
                        if (!r) {
                            c = report(exit_code_for(r.error()), a.input + ": " + r.error().message);
                            return std::nullopt;
                        }
                        std::string what = "decimated to " + count_of(r->faces, "face", "faces") + " (" +
                                           count_of(r->collapses, "collapse", "collapses") + ", largest error " +
                                           std::to_string(r->error) + ")";
                        if (!r->note.empty()) what += "; " + r->note;
                        return edit_outcome{what, {}};
                    });
}

const bool registered = register_command(
    {"decimate", "Decimate a mesh by quadric error (Garland-Heckbert) to a face count, ratio or error bound",
     "hmira decimate scan.off small.off --ratio 0.1", 89, [](CLI::App& sub) {
         auto a = std::make_shared<decimate_args>();
         sub.add_option("input", a->input,
                        "mesh file to read (manifold, consistently oriented; polygons are triangulated first)")
             ->required();
         sub.add_option("output", a->output, "mesh file to write (the surviving file vertices first, in file order)")
             ->required();
         sub.add_option("--faces", a->faces,
                        "stop at this many faces (reached exactly, or one fewer, unless the constraints stop earlier)")
             ->check(whole_number(0, std::uint64_t(1) << 40));
         sub.add_option("--ratio", a->ratio, "stop at this fraction of the faces, in [0, 1]")
             ->check(finite_number("in [0, 1]", [](double x) { return x >= 0 && x <= 1; }));
         sub.add_option("--max-error", a->max_error,
                        "stop before a collapse whose error exceeds this distance (model units), >= 0")
             ->check(finite_number(">= 0", [](double x) { return x >= 0; }));
         sub.add_option("--max-normal-angle", a->max_normal_angle,
                        "refuse collapses that turn a face normal by more than this, in [0, 180] degrees (default " +
                            number_text(a->max_normal_angle) + ")")
             ->check(finite_number("in [0, 180]", [](double x) { return x >= 0 && x <= 180; }));
         sub.add_option("--max-aspect-ratio", a->max_aspect_ratio,
                        "refuse collapses that make a face thinner than this (1 = equilateral), >= 1")
             ->check(finite_number(">= 1", [](double x) { return x >= 1; }));
         sub.add_flag("--move-boundary", a->move_boundary, "let boundary edges collapse and boundary vertices move");
         sub.add_option("--fix", a->fixed, "keep vertex N where it is (0-based, file order; repeatable, or N,M,...)")
             ->delimiter(',')
             ->check(CLI::NonNegativeNumber);
         sub.add_option("--lock", a->locked, "deprecated name of --fix")->delimiter(',')->check(CLI::NonNegativeNumber);
         return [a](const common_options& o) { return run_decimate(*a, o); };
     }});

}  // namespace
