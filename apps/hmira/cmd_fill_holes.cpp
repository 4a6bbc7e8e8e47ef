// apps/hmira/cmd_fill_holes.cpp
// `hmira fill-holes`: closes every boundary loop of at most --max-edges edges with a triangle
// patch of least bend, then least area (Liepa), leaving longer loops open; optionally refined
// to the density around the hole and faired (membrane or thin plate).
#include <hmira/algorithms/holes/fill_hole.hpp>

#include "cli.hpp"

namespace {

using namespace hmira_cli;

struct fill_holes_args {
    std::string input, output;
    std::size_t max_edges = 1000;
    bool refine = false;
    std::string fair = "none";
};

int run_fill_holes(const fill_holes_args& a, const common_options& o) {
    int code = ok;
    auto loaded = load_for_edit(a.input, o, code);
    if (!loaded) return code;
    return run_edit(*loaded, a.input, a.output, "filling holes in " + a.input, o,
                    [&](hmira::halfedge_mesh& mesh, int& c) -> std::optional<edit_outcome> {
                        hmira::fill_hole_options options{};
                        options.refine = a.refine || a.fair != "none";  // fairing moves the vertices refinement adds
                        options.fair = a.fair == "membrane"     ? hmira::fairing::membrane
                                       : a.fair == "thin-plate" ? hmira::fairing::thin_plate
                                                                : hmira::fairing::none;
                        auto r = hmira::fill_holes(mesh, a.max_edges, options);
                        if (!r) {
                            c = report(exit_code_for(r.error()), a.input + ": " + r.error().message);
                            return std::nullopt;
                        }
                        std::string what = "filled " + count_of(r->filled, "hole", "holes") + " with " +
                                           count_of(r->faces_added, "triangle", "triangles");
                        if (r->vertices_added > 0) what += " and " + count_of(r->vertices_added, "vertex", "vertices");
                        if (r->skipped > 0) what += ", left " + count_of(r->skipped, "hole", "holes") + " open";
                        if (r->unfaired > 0) what += ", " + count_of(r->unfaired, "patch", "patches") + " not faired (solver did not converge)";
                        return edit_outcome{what, {}};
                    });
}

const bool registered = register_command({
    "fill-holes", "Close boundary loops with triangle patches of least bend, then least area",
    "hmira fill-holes scan.off closed.off --max-edges 500", 85,
    [](CLI::App& sub) {
        auto a = std::make_shared<fill_holes_args>();
        sub.add_option("input", a->input, "mesh file to read (manifold, consistently oriented)")->required();
        sub.add_option("output", a->output, "mesh file to write: the input's vertices in file order, new faces after the old")->required();
        sub.add_option("--max-edges", a->max_edges, "fill only loops of at most this many edges (>= 3; default 1000)")
            ->check(CLI::Range(std::size_t(3), std::numeric_limits<std::size_t>::max()));
        sub.add_flag("--refine", a->refine, "refine each patch to the edge length around its hole (Liepa)");
        sub.add_option("--fair", a->fair, "move the refined patch's vertices: none, membrane or thin-plate (implies --refine)")
            ->check(CLI::IsMember({"none", "membrane", "thin-plate"}));
        sub.footer("\nLoops of up to 200 edges get the O(n^3) dynamic programme; longer ones are triangulated in their\n"
                   "best-fit plane and left open if that projection crosses itself.\n" + sub.get_footer());
        return [a](const common_options& o) { return run_fill_holes(*a, o); };
    }});

}  // namespace
