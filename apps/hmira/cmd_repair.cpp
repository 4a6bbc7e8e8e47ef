// apps/hmira/cmd_repair.cpp
// `hmira repair IN OUT [--solid]`: writes the mesh as the reader repairs it (faces with fewer than
// three distinct corners dropped), or, with --solid, the surface of the solid a closed,
// possibly self-intersecting mesh bounds, by the library's make_solid.
#include <cstdio>
#include <string>

#include <hmira/algorithms/boolean/make_solid.hpp>

#include "boolean_summary.hpp"
#include "cli.hpp"

namespace {

using namespace hmira_cli;

struct repair_args {
    std::string input, output;
    bool solid = false;
    bool json = false;
};

int run_repair(const repair_args& a, const common_options& o) {
    int code = ok;
    auto in = load_for_edit(a.input, o, code);
    if (!in) return code;
    const std::string read_repairs = in->repairs.empty() ? "none" : in->repairs;
    if (!a.solid) {
        if (int c = save(in->mesh, a.output, {}, o); c != ok) return c;
        if (a.json)
            std::printf("{\"solid\": false, \"faces_in\": %zu, \"faces\": %zu, \"vertices\": %zu}\n", in->file_faces,
                        in->mesh.face_count(), in->mesh.vertex_count());
        else
            say(o, "repaired " + a.input + " (" + count_of(in->file_faces, "face", "faces") +
                       "): " + count_of(in->mesh.face_count(), "face", "faces") + "; on reading: " + read_repairs +
                       " (" + a.output + ")");
        return ok;
    }
    if (!refuse_non_finite(in->mesh, a.input, "repair", code)) return code;
    hmira::face_vertex_mesh out;
    hmira::result<hmira::boolean_report> r = hmira::boolean_report{};
    {
        auto bar = stage_bar("repair --solid " + a.input, o, in->mesh.face_count());
        const auto progress = [&](double f) {
            bar.update(std::uint64_t(f * 1000), 1000);
            return true;
        };
        r = hmira::make_solid(out, in->mesh, {.progress = progress});
    }
    if (!r) return report(input_exit_code(r.error()), a.input + ": " + r.error().message);
    if (int c = save(out, a.output, {}, o); c != ok) return c;
    if (a.json) {
        std::printf("{\"solid\": true, \"faces_in\": %zu, %s}\n", in->mesh.face_count(),
                    boolean_report_json(*r, out.face_count(), out.vertex_count()).c_str());
        return ok;
    }
    const std::string line = "solid of " + a.input + " (" + count_of(in->mesh.face_count(), "face", "faces") +
                             "): " + boolean_report_words(*r, out.face_count());
    say(o, line + " (" + a.output + ")");
    return ok;
}

const bool registered = register_command(
    {"repair", "Write a mesh as the reader repairs it, or (--solid) the clean surface of the solid it bounds",
     "hmira repair overlapping.stl printable.stl --solid", 125, [](CLI::App& sub) {
         auto a = std::make_shared<repair_args>();
         sub.add_option("input", a->input, "mesh file (any format hmira reads; closed for --solid)")->required();
         sub.add_option("output", a->output, "mesh file to write (triangles with --solid)")->required();
         sub.add_flag("--solid", a->solid,
                      "resolve self-intersections exactly and keep the boundary of the points the surface winds "
                      "around (winding number > 0): overlapping parts merge, inner shells go");
         sub.add_flag("--json", a->json,
                      "print one JSON object instead of the summary line: face counts in and out and, with --solid, "
                      "intersecting pairs, cut triangles, snapped vertices, degenerate faces, rounding intersections");
         return [a](const common_options& o) { return run_repair(*a, o); };
     }});

}  // namespace
