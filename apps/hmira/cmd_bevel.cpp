// apps/hmira/cmd_bevel.cpp
// `hmira bevel`: replaces chosen edges (named by their end vertices, all of them, or every edge
// sharper than an angle) by strips of faces, or, in vertex-only mode, cuts chosen corners.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <numbers>

#include <hmira/algorithms/editing/bevel.hpp>
#include <hmira/algorithms/geometry/sharp_edges.hpp>

#include "cli.hpp"

namespace {

using namespace hmira_cli;

struct bevel_args {
    std::string input, output;
    std::vector<std::string> edges;  ///< "A,B" each
    bool all = false;
    double angle = -1;  ///< < 0: not given
    double width = hmira::bevel_options{}.width;
    int segments = hmira::bevel_options{}.segments;
    bool no_clamp = !hmira::bevel_options{}.clamp_overlap;
    std::vector<std::size_t> vertices;
    bool vertices_all = false;
};

/// "A,B" -> {A, B}.
std::optional<std::array<std::size_t, 2>> parse_pair(const std::string& text) {
    std::array<std::size_t, 2> v{};
    const char* p = text.data();
    const char* end = p + text.size();
    for (std::size_t n = 0; n < 2; ++n) {
        auto r = std::from_chars(p, end, v[n]);
        if (r.ec != std::errc() || r.ptr == p) return std::nullopt;
        p = r.ptr;
        if (n == 0) {
            if (p == end || *p != ',') return std::nullopt;
            ++p;
        }
    }
    if (p != end) return std::nullopt;
    return v;
}

/// The file's index of v: a copy that repair on read made of a split vertex stands for its
/// original.
std::size_t file_index(const hmira::halfedge_mesh& m, hmira::vertex_handle v) {
    if (auto source = m.get_vertex_property<std::uint32_t>("v:file_vertex")) return (*source)[v];
    return v.index;
}

/// The edges to bevel, from the command line; prints the error and sets `code` on failure.
/// `file_vertices_count` is the file's vertex count (copies of split vertices come after it).
std::optional<std::vector<hmira::edge_handle>> select_edges(const bevel_args& a, const hmira::halfedge_mesh& m,
                                                            std::size_t file_vertices_count, int& code) {
    std::vector<hmira::edge_handle> out;
    if (a.all || a.angle >= 0) {
        // Only edges between two faces can be bevelled: boundary edges are never selected.
        out = hmira::sharp_edges(m, a.angle >= 0 ? a.angle : 0.0);
        if (out.empty()) {
            code = report(invalid_input, a.input + ": nothing to bevel: " +
                                             (a.all ? std::string("every edge is on the boundary")
                                                    : "no edge has a dihedral angle of at least " +
                                                          number_text(a.angle) + " degrees"));
            return std::nullopt;
        }
        code = ok;
        return out;
    }
    for (const auto& text : a.edges) {
        const auto ends = parse_pair(text);
        if (!ends) {
            code = report(usage, "--edge " + text + ": expected two vertex indices A,B (0-based, in file order)");
            return std::nullopt;
        }
        if (!check_indices({(*ends)[0], (*ends)[1]}, file_vertices_count, "vertex", "--edge " + text, a.input, code))
            return std::nullopt;
        // A vertex the repair on read split has copies: every edge joining a copy of A to a copy
        // of B is the file's edge A,B.
        const std::size_t one_a[] = {(*ends)[0]}, one_b[] = {(*ends)[1]};
        const auto from = file_vertices(m, one_a), to = file_vertices(m, one_b);
        bool joined = false;
        for (auto va : from)
            for (auto vb : to)
                if (const auto h = m.find_halfedge(va, vb)) {
                    joined = true;
                    const auto e = m.edge(h);
                    if (std::find(out.begin(), out.end(), e) == out.end())
                        out.push_back(e);  // "0,1" and "1,0" are one edge
                }
        if (!joined) {
            code = report(usage, "--edge " + text + ": vertices " + std::to_string((*ends)[0]) + " and " +
                                     std::to_string((*ends)[1]) + " of " + a.input + " are not joined by an edge");
            return std::nullopt;
        }
    }
    code = ok;
    return out;
}

/// The library names edges by the halfedge mesh's numbering, which the user never sees: say
/// which vertices the edge joins.
std::string with_edge_ends(const hmira::error& e, const hmira::halfedge_mesh& m) {
    const std::string prefix = "bevel: edge " + std::to_string(e.element) + " ";
    if (e.element < 0 || static_cast<std::size_t>(e.element) >= m.edge_index_bound() || e.message.rfind(prefix, 0) != 0)
        return e.message;
    const auto ends = m.edge_vertices(hmira::edge_handle(static_cast<std::size_t>(e.element)));
    return "bevel: edge " + std::to_string(file_index(m, ends[0])) + "," + std::to_string(file_index(m, ends[1])) +
           " " + e.message.substr(prefix.size());
}

int run_bevel(const bevel_args& a, const common_options& o) {
    const bool vertex_mode = !a.vertices.empty() || a.vertices_all;
    const bool edge_mode = !a.edges.empty() || a.all || a.angle >= 0;
    if (!vertex_mode && !edge_mode)
        return report(
            usage,
            "bevel: choose edges with --edge A,B, --all or --angle DEG, or vertices with --vertex N or --vertices-all");
    if (vertex_mode && a.segments != 1)
        return report(usage,
                      "bevel: vertex-only mode (--vertex, --vertices-all) makes flat cuts only; drop --segments");
    if (vertex_mode && a.no_clamp)
        return report(usage, "bevel: vertex-only mode always stops cuts at the middle of an edge; drop --no-clamp");
    int code = ok;
    auto loaded = load_for_edit(a.input, o, code);
    if (!loaded) return code;
    if (!check_indices(a.vertices, loaded->mesh.vertex_count(), "vertex", "--vertex", a.input, code)) return code;
    return run_edit(
        *loaded, a.input, a.output, "bevelling " + a.input, o,
        [&](hmira::halfedge_mesh& mesh, int& c) -> std::optional<edit_outcome> {
            const hmira::bevel_options options{.width = a.width, .segments = a.segments, .clamp_overlap = !a.no_clamp};
            if (vertex_mode) {
                std::vector<hmira::vertex_handle> chosen;
                if (a.vertices_all) {
                    for (auto v : mesh.vertices()) chosen.push_back(v);
                } else {
                    chosen = file_vertices(mesh, a.vertices);
                }
                // Vertex-only bevel runs truncate underneath: say what the user asked for, and why.
                const std::string mode = a.vertices_all ? "bevel --vertices-all" : "bevel --vertex";
                for (auto v : chosen)
                    if (mesh.is_isolated(v)) {
                        c = report(invalid_input,
                                   a.input + ": " + mode + ": vertex " + std::to_string(v.index) +
                                       " is used by no face, so it has no corner to cut; nothing written");
                        return std::nullopt;
                    }
                auto r = hmira::bevel_vertices(mesh, chosen, options);
                if (!r) {
                    std::string why = r.error().message;
                    if (why.rfind("truncate: ", 0) == 0) why = why.substr(10);
                    c = report(input_exit_code(r.error()), a.input + ": " + mode + ": " + why);
                    return std::nullopt;
                }
                return edit_outcome{"bevelled " + count_of(r->vertex_faces.size(), "vertex", "vertices"), {}};
            }
            auto chosen = select_edges(a, mesh, loaded->mesh.vertex_count(), c);
            if (!chosen) return std::nullopt;
            auto r = hmira::bevel(mesh, *chosen, options);
            if (!r) {
                c = report(input_exit_code(r.error()), a.input + ": " + with_edge_ends(r.error(), mesh));
                return std::nullopt;
            }
            // The requested width, the smallest one the clamp left, and how many edges it limited.
            char widths[96];
            std::snprintf(widths, sizeof widths, "width %.6g requested, smallest used %.6g", r.value().requested_width,
                          r.value().width);
            // Edges whose strip would leave a face of zero area are not bevelled: say how many.
            std::string skipped;
            if (r.value().skipped_edges > 0)
                skipped = "; skipped " + std::to_string(r.value().skipped_edges) +
                          " whose strip would leave a face of zero area";
            return edit_outcome{"bevelled " + count_of(r.value().bevelled_edges, "edge", "edges") + skipped + ": " +
                                    widths + ", " + count_of(r.value().limited_edges, "edge", "edges") +
                                    " limited by the clamp",
                                {}};
        });
}

const bool registered = register_command(
    {"bevel", "Bevel chosen edges (by their end vertices, all, or those sharper than an angle) or vertices",
     "hmira bevel part.obj bevelled.obj --angle 60 --width 0.05 --segments 3", 90, [](CLI::App& sub) {
         auto a = std::make_shared<bevel_args>();
         sub.add_option("input", a->input, "mesh file to read (manifold, consistently oriented)")->required();
         sub.add_option("output", a->output,
                        "mesh file to write: the input's surviving vertices first, in file order, then the new ones")
             ->required();
         auto* edge = sub.add_option("--edge", a->edges,
                                     "bevel the edge between vertices A and B (0-based, in file order; repeatable)")
                          ->type_name("A,B");
         auto* all = sub.add_flag("--all", a->all, "bevel every edge between two faces");
         auto* angle =
             sub.add_option("--angle", a->angle,
                            "bevel every edge whose faces' normals differ by at least DEG degrees (sharp edges)")
                 ->type_name("DEG")
                 ->check(finite_number("in [0, 180]", [](double x) { return x >= 0 && x <= 180; }));
         sub.add_option("--width", a->width, "distance from the old edge to the new ones, inside each face next to it")
             ->capture_default_str()
             ->check(finite_number("> 0", [](double x) { return x > 0; }));
         sub.add_option("--segments", a->segments,
                        "faces across each strip: 1 is a flat chamfer, more follow a round arc")
             ->capture_default_str()
             ->check(whole_number(1, 64));
         sub.add_flag("--no-clamp", a->no_clamp,
                      "use the width as given even where new vertices would pass each other");
         auto* vertex =
             sub.add_option("--vertex", a->vertices,
                            "vertex-only mode: cut the corner at vertex N, at --width along each edge (repeatable)")
                 ->delimiter(',')
                 ->check(whole_number(0, std::numeric_limits<std::uint64_t>::max()));
         auto* vertices_all = sub.add_flag("--vertices-all", a->vertices_all, "vertex-only mode on every vertex");
         // Exactly one way to choose what is bevelled.
         const std::vector<CLI::Option*> ways{edge, all, angle, vertex, vertices_all};
         for (auto* x : ways)
             for (auto* y : ways)
                 if (x != y) x->excludes(y);
         return [a](const common_options& o) { return run_bevel(*a, o); };
     }});

}  // namespace
