// apps/hmira/cmd_extrude.cpp
// `hmira extrude`: pulls chosen faces (or all) out along their normal or a given direction,
// joining them to where they were by walls of quads.
#include <cmath>
#include <cstdio>

#include <hmira/algorithms/editing/extrude.hpp>

#include "cli.hpp"

namespace {

using namespace hmira_cli;

struct extrude_args {
    std::string input, output;
    std::vector<std::size_t> faces;
    bool all = false;
    double distance = hmira::extrude_options{}.distance;
    std::string direction;  ///< "X,Y,Z", or empty: the normal
    std::string mode = name_of(hmira::extrude_options{}.mode);
};

/// Region mode moves the region's own vertices and leaves new ones at the outline's old place
/// (extruding one face, or individual mode, does the opposite). For the output to keep every
/// file vertex where the file has it, a file vertex that moved trades its index with the new
/// vertex left at its old place: on each wall quad (v' -> v -> u -> u'), a new vertex's partner
/// is its neighbour in the loop that is not new. Inner vertices of a region have no partner:
/// they move. `original` holds the file's positions by index.
std::vector<std::pair<hmira::vertex_handle, hmira::vertex_handle>> stayed_behind(
    const hmira::halfedge_mesh& m, const hmira::extrude_result<hmira::halfedge_mesh>& r,
    std::span<const hmira::vec3<double>> original) {
    std::vector<std::pair<hmira::vertex_handle, hmira::vertex_handle>> pairs;
    std::vector<char> is_new(m.vertex_index_bound(), 0), paired(m.vertex_index_bound(), 0);
    for (auto v : r.vertices) is_new[v.index] = 1;
    for (auto f : r.side_faces) {
        std::vector<hmira::vertex_handle> loop;
        for (auto v : m.face_vertices(f)) loop.push_back(v);
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const auto v = loop[i];
            if (!is_new[v.index] || paired[v.index]) continue;
            for (auto w : {loop[(i + 1) % loop.size()], loop[(i + loop.size() - 1) % loop.size()]}) {
                if (is_new[w.index] || paired[w.index] || w.index >= original.size()) continue;
                if (m.position(w) != original[w.index] && m.position(v) == original[w.index]) {
                    pairs.push_back({v, w});
                    paired[v.index] = paired[w.index] = 1;
                }
                break;
            }
        }
    }
    return pairs;
}

int run_extrude(const extrude_args& a, const common_options& o) {
    if (a.faces.empty() && !a.all)
        return report(usage, "extrude: choose the faces with --face N (repeatable) or --all");
    std::optional<hmira::vec3<double>> direction;
    if (!a.direction.empty()) {
        const auto d = parse_triple(a.direction);
        if (!d || ((*d)[0] == 0 && (*d)[1] == 0 && (*d)[2] == 0))
            return report(usage, "--direction " + a.direction + ": expected three finite numbers X,Y,Z, not all 0");
        direction = hmira::vec3<double>{(*d)[0], (*d)[1], (*d)[2]};
        // extrude normalises the direction by its length, hmira::norm: a vector so short that
        // its squared length underflows to 0, or so long that it overflows, has none to divide by.
        const double length = hmira::norm(*direction);
        if (!(length > 0) || !std::isfinite(length))
            return report(usage, "--direction " + a.direction + ": cannot be normalised (its squared length " +
                                     (length > 0 ? "overflows" : "underflows to 0") +
                                     "); only the direction counts, so scale it");
    }
    int code = ok;
    auto loaded = load_for_edit(a.input, o, code);
    if (!loaded) return code;
    if (!check_indices(a.faces, loaded->file_faces, "face", "--face", a.input, code)) return code;
    auto faces = a.faces;  // the file's face numbers, as faces of the loaded mesh
    if (!file_faces_to_loaded(*loaded, faces, a.input, code)) return code;
    return run_edit(*loaded, a.input, a.output, "extruding " + a.input, o,
                    [&](hmira::halfedge_mesh& mesh, int& c) -> std::optional<edit_outcome> {
                        std::vector<hmira::face_handle> chosen;
                        if (a.all) {
                            for (auto f : mesh.faces()) chosen.push_back(f);
                        } else {
                            for (auto i : faces) chosen.emplace_back(i);
                        }
                        const hmira::extrude_options options{
                            .distance = a.distance, .direction = direction, .mode = named<hmira::extrude_mode>(a.mode)};
                        auto r = hmira::extrude(mesh, chosen, options);
                        if (!r) {
                            c = report(input_exit_code(r.error()),
                                       a.input + ": " + r.error().message);  // the options were checked up front
                            return std::nullopt;
                        }
                        return edit_outcome{"extruded " + count_of(r->top_faces.size(), "face", "faces") + " by " +
                                                number_text(a.distance) + " with " +
                                                count_of(r->side_faces.size(), "wall", "walls"),
                                            stayed_behind(mesh, *r, loaded->mesh.positions())};
                    });
}

const bool registered = register_command(
    {"extrude", "Pull chosen faces (or all) out along their normal or a direction, with walls of quads",
     "hmira extrude cube.obj tower.obj --face 4 --distance 2", 100, [](CLI::App& sub) {
         auto a = std::make_shared<extrude_args>();
         sub.add_option("input", a->input, "mesh file to read (manifold, consistently oriented)")->required();
         sub.add_option("output", a->output,
                        "mesh file to write: the input's vertices first, in file order, then the new ones")
             ->required();
         auto* face = sub.add_option("--face", a->faces,
                                     "extrude face N (0-based, in the input file's order; repeatable, or N,M,...)")
                          ->delimiter(',')
                          ->check(whole_number(0, std::numeric_limits<std::uint64_t>::max()));
         auto* all = sub.add_flag("--all", a->all, "extrude every face (use --mode individual on a closed mesh)");
         face->excludes(all);
         sub.add_option("--distance", a->distance, "how far to move the faces; negative pushes them in")
             ->capture_default_str()
             ->check(finite_number("other than 0", [](double x) { return x != 0; }));
         sub.add_option("--direction", a->direction, "move along this direction (normalised) instead of the normal")
             ->type_name("X,Y,Z");
         sub.add_option("--mode", a->mode,
                        "region: connected faces move as one piece, walls only on the outline; individual: each face "
                        "on its own")
             ->capture_default_str()
             ->check(CLI::IsMember(names_of<hmira::extrude_mode>()));
         return [a](const common_options& o) { return run_extrude(*a, o); };
     }});

}  // namespace
