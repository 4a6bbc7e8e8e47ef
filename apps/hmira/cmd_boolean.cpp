// apps/hmira/cmd_boolean.cpp
// `hmira boolean A B OUT`: union, intersection, difference or symmetric difference of two closed
// meshes, computed exactly by the library's mesh_boolean; the output is triangles.
#include <cstdio>
#include <string>

#include <hmira/algorithms/boolean/mesh_boolean.hpp>

#include "boolean_summary.hpp"
#include "cli.hpp"

namespace {

using namespace hmira_cli;

struct boolean_args {
    std::string a, b, output;
    std::string op = name_of(hmira::boolean_options{}.op);
    bool json = false;
};

int run_boolean(const boolean_args& a, const common_options& o) {
    int code = ok;
    auto la = load_for_edit(a.a, o, code);
    if (!la) return code;
    auto lb = load_for_edit(a.b, o, code);
    if (!lb) return code;
    if (!refuse_non_finite(la->mesh, a.a, "boolean", code) || !refuse_non_finite(lb->mesh, a.b, "boolean", code))
        return code;
    hmira::face_vertex_mesh out;
    hmira::result<hmira::boolean_report> r = hmira::boolean_report{};
    {
        auto bar = stage_bar(a.op + " " + a.a + " " + a.b, o, la->mesh.face_count() + lb->mesh.face_count());
        const auto progress = [&](double f) {
            bar.update(std::uint64_t(f * 1000), 1000);
            return true;
        };
        r = hmira::mesh_boolean(out, la->mesh, lb->mesh, {.op = named<hmira::boolean_op>(a.op), .progress = progress});
    }
    if (!r) return report(input_exit_code(r.error()), a.a + ", " + a.b + ": " + r.error().message);
    if (int c = save(out, a.output, {}, o); c != ok) return c;
    if (a.json) {
        std::printf("{\"op\": \"%s\", \"faces_a\": %zu, \"faces_b\": %zu, %s}\n", a.op.c_str(), la->mesh.face_count(),
                    lb->mesh.face_count(), boolean_report_json(*r, out.face_count(), out.vertex_count()).c_str());
        return ok;
    }
    const std::string line = a.op + " of " + a.a + " (" + count_of(la->mesh.face_count(), "face", "faces") + ") and " +
                             a.b + " (" + count_of(lb->mesh.face_count(), "face", "faces") +
                             "): " + boolean_report_words(*r, out.face_count());
    say(o, line + " (" + a.output + ")");
    return ok;
}

const bool registered = register_command(
    {"boolean", "Union, intersection, difference or xor of two closed meshes, computed exactly",
     "hmira boolean part.stl hole.stl drilled.stl --op difference", 124, [](CLI::App& sub) {
         auto a = std::make_shared<boolean_args>();
         sub.add_option(
                "a", a->a,
                "first mesh (any format hmira reads; closed and oriented outward; self-intersections are resolved)")
             ->required();
         sub.add_option("b", a->b, "second mesh (same requirements)")->required();
         sub.add_option("output", a->output, "mesh file to write (triangles)")->required();
         sub.add_option("--op", a->op, "union, intersection, difference (A minus B) or xor")
             ->capture_default_str()
             ->check(CLI::IsMember(names_of<hmira::boolean_op>()));
         sub.add_flag("--json", a->json,
                      "print one JSON object instead of the summary line: face counts in and out, intersecting "
                      "pairs, cut triangles, snapped vertices, degenerate faces, rounding intersections");
         return [a](const common_options& o) { return run_boolean(*a, o); };
     }});

}  // namespace
