// apps/hmira/cmd_truncate.cpp
// `hmira truncate`: cuts the corners off chosen vertices (or all of them), replacing each by a
// new face through points on its edges (cube -> truncated cube).
#include <hmira/algorithms/editing/truncate.hpp>

#include "cli.hpp"

namespace {

using namespace hmira_cli;

struct truncate_args {
    std::string input, output;
    std::vector<std::size_t> vertices;
    bool all = false;
    double fraction = hmira::truncate_options{}.fraction;
    double distance = hmira::truncate_options{}.distance;
};

int run_truncate(const truncate_args& a, const common_options& o) {
    if (a.vertices.empty() && !a.all)
        return report(usage, "truncate: choose the vertices with --vertex N (repeatable) or --all");
    int code = ok;
    auto loaded = load_for_edit(a.input, o, code);
    if (!loaded) return code;
    if (!check_indices(a.vertices, loaded->mesh.vertex_count(), "vertex", "--vertex", a.input, code)) return code;
    return run_edit(*loaded, a.input, a.output, "truncating " + a.input, o,
                    [&](hmira::halfedge_mesh& mesh, int& c) -> std::optional<edit_outcome> {
                        const hmira::truncate_options options{.fraction = a.fraction, .distance = a.distance};
                        std::vector<hmira::vertex_handle> chosen;
                        chosen = file_vertices(mesh, a.vertices);
                        auto r = a.all ? hmira::truncate_all(mesh, options) : hmira::truncate(mesh, chosen, options);
                        if (!r) {
                            c = report(input_exit_code(r.error()),
                                       a.input + ": " + r.error().message);  // the options were checked up front
                            return std::nullopt;
                        }
                        return edit_outcome{"truncated " + count_of(r->faces.size(), "vertex", "vertices"), {}};
                    });
}

const bool registered = register_command(
    {"truncate", "Cut off the corners at chosen vertices (or all), each replaced by a new face",
     "hmira truncate cube.obj truncated.obj --all --fraction 0.3", 80, [](CLI::App& sub) {
         auto a = std::make_shared<truncate_args>();
         sub.add_option("input", a->input, "mesh file to read (manifold, consistently oriented)")->required();
         sub.add_option("output", a->output,
                        "mesh file to write: the input's surviving vertices first, in file order, then the new ones")
             ->required();
         auto* vertex = sub.add_option("--vertex", a->vertices,
                                       "truncate vertex N (0-based, in the input file's order; repeatable, or N,M,...)")
                            ->delimiter(',')
                            ->check(whole_number(0, std::numeric_limits<std::uint64_t>::max()));
         auto* all = sub.add_flag("--all", a->all, "truncate every vertex");
         vertex->excludes(all);
         auto* fraction = sub.add_option("--fraction", a->fraction,
                                         "cut each edge at this fraction of its length from the vertex, in (0, 1)")
                              ->default_str("1/3")
                              ->check(finite_number("in (0, 1)", [](double x) { return x > 0 && x < 1; }));
         auto* distance =
             sub.add_option("--distance", a->distance, "cut each edge at this distance from the vertex instead (> 0)")
                 ->check(finite_number("> 0", [](double x) { return x > 0; }));
         fraction->excludes(distance);
         sub.footer(
             "\nCuts from both ends of an edge stop at its middle; at --fraction 0.5 they meet (cube -> "
             "cuboctahedron).\n" +
             sub.get_footer());
         return [a](const common_options& o) { return run_truncate(*a, o); };
     }});

}  // namespace
