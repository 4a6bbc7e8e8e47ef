// apps/hmira/cmd_fill_holes.cpp
// `hmira fill-holes`: closes every boundary loop of at most --max-edges edges with a triangle
// patch of least bend, then least area (Liepa), leaving longer loops open; optionally refined
// to the density around the hole and faired (membrane or thin plate). Every loop left open is
// named with its reason.
#include <hmira/algorithms/holes/fill_hole.hpp>

#include "cli.hpp"

namespace {

using namespace hmira_cli;

struct fill_holes_args {
    std::string input, output;
    std::size_t max_edges = hmira::fill_holes_default_max_edges;
    bool refine = hmira::fill_hole_options{}.refine;
    std::string fair = name_of(hmira::fill_hole_options{}.fair);
};

/// "1,240": a count with thousands separators, as the summary prints lengths.
std::string grouped(std::size_t n) {
    std::string digits = std::to_string(n), out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

int run_fill_holes(const fill_holes_args& a, const common_options& o) {
    int code = ok;
    auto loaded = load_for_edit(a.input, o, code);
    if (!loaded) return code;
    return run_edit(*loaded, a.input, a.output, "filling holes in " + a.input, o,
                    [&](hmira::halfedge_mesh& mesh, int& c) -> std::optional<edit_outcome> {
                        progress_bar bar("filling holes in " + a.input, o, 1u << 20);
                        hmira::fill_hole_options options{};
                        options.fair = named<hmira::fairing>(a.fair);
                        // Fairing moves the vertices refinement adds.
                        options.refine = a.refine || options.fair != hmira::fairing::none;
                        options.max_memory_bytes = free_memory().value_or(0);  // 0: no limit
                        options.progress = [&](double f) {
                            bar.update(std::uint64_t(f * double(1u << 20)), 1u << 20);
                            return true;
                        };
                        auto r = hmira::fill_holes(mesh, a.max_edges, options);
                        if (!r) {
                            c = report(exit_code_for(r.error()), a.input + ": " + r.error().message);
                            return std::nullopt;
                        }
                        std::string what = "filled " + count_of(r->filled, "hole", "holes") + " with " +
                                           count_of(r->faces_added, "triangle", "triangles");
                        if (r->vertices_added > 0) what += " and " + count_of(r->vertices_added, "vertex", "vertices");
                        if (r->skipped > 0) what += ", left " + count_of(r->skipped, "hole", "holes") + " open";
                        if (r->unfaired > 0)
                            what += ", " + count_of(r->unfaired, "patch", "patches") +
                                    " not faired (solver did not converge)";
                        // Each open loop with its reason, the first few in full.
                        const std::size_t shown = std::min<std::size_t>(r->open.size(), 5);
                        for (std::size_t i = 0; i < shown; ++i) {
                            const auto& h = r->open[i];
                            what += "; hole at vertex " + std::to_string(h.vertex) + ": ";
                            if (h.reason == hmira::open_hole_reason::too_long)
                                what += grouped(h.edges) + " edges > --max-edges " + grouped(a.max_edges);
                            else
                                what += grouped(h.edges) + " edges, " + h.message;
                        }
                        if (r->open.size() > shown)
                            what += "; and " + count_of(r->open.size() - shown, "more hole", "more holes");
                        return edit_outcome{what, {}};
                    });
}

const bool registered = register_command(
    {"fill-holes", "Close boundary loops with triangle patches of least bend, then least area",
     "hmira fill-holes scan.off closed.off --max-edges 500", 85, [](CLI::App& sub) {
         auto a = std::make_shared<fill_holes_args>();
         sub.add_option("input", a->input, "mesh file to read (manifold, consistently oriented)")->required();
         sub.add_option("output", a->output,
                        "mesh file to write: the input's vertices in file order, new faces after the old")
             ->required();
         sub.add_option("--max-edges", a->max_edges, "fill only loops of at most this many edges (>= 3)")
             ->capture_default_str()
             ->check(whole_number(3, std::numeric_limits<std::uint64_t>::max()));
         sub.add_flag("--refine", a->refine, "refine each patch to the edge length around its hole (Liepa)");
         sub.add_option("--fair", a->fair,
                        "move the refined patch's vertices: none, membrane or thin-plate (implies --refine)")
             ->check(CLI::IsMember(names_of<hmira::fairing>()));
         const hmira::fill_hole_options defaults{};
         sub.footer(
             "\nLoops of up to " + std::to_string(defaults.max_dynamic_programming_edges) +
             " edges get the O(n^3) dynamic programme; longer ones are triangulated in their\n"
             "best-fit plane, or, if that projection crosses itself, by the programme up to " +
             std::to_string(defaults.max_fallback_dynamic_programming_edges) +
             " edges.\nA loop no triangulation of its own vertices can close gets a fan around a new centre vertex.\n"
             "Every loop left open is named (its first vertex, in file order) with the reason.\n" +
             sub.get_footer());
         return [a](const common_options& o) { return run_fill_holes(*a, o); };
     }});

}  // namespace
