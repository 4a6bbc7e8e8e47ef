// apps/hmira/cmd_triangulate.cpp
// `hmira triangulate`: cuts every polygon into triangles (exact predicates on each face's
// plane, so concave faces come out right); refuses a self-crossing face by its index.
#include <array>
#include <vector>

#include <hmira/algorithms/triangulation/triangulate_faces.hpp>
#include <hmira/algorithms/triangulation/triangulate_polygon.hpp>

#include "cli.hpp"

namespace {

using namespace hmira_cli;

struct triangulate_args {
    std::string input, output;
    bool delaunay = hmira::triangulate_polygon_options{}.delaunay;
};

int run_triangulate(const triangulate_args& a, const common_options& o) {
    int code = ok;
    auto loaded = load(a.input, o, code);
    if (!loaded) return code;
    auto& mesh = loaded->mesh;
    using tri = std::array<hmira::vertex_handle, 3>;
    // Every face is cut on paper first: a refused face leaves the output unwritten.
    std::vector<std::pair<hmira::face_handle, std::vector<tri>>> cuts;
    for (auto f : mesh.faces()) {
        if (mesh.face_vertices(f).size() == 3) continue;
        auto t = hmira::face_triangles(mesh, f, {.delaunay = a.delaunay});
        if (!t) return report(invalid_input, a.input + ": " + t.error().message);
        cuts.emplace_back(f, std::move(*t));
    }
    std::size_t added = 0;
    for (const auto& [f, tris] : cuts) {
        if (auto r = mesh.remove_face(f); !r) return report(internal, r.error().message);
        for (const auto& t : tris) {
            if (auto r = mesh.add_face(std::span<const hmira::vertex_handle>(t)); !r)
                return report(internal, r.error().message);
            ++added;
        }
    }
    (void)mesh.collect_garbage();
    if (int c = save(mesh, a.output, {}, o); c != ok) return c;
    say(o, a.output + ": cut " + count_of(cuts.size(), "face", "faces") + " into " +
               count_of(added, "triangle", "triangles") + ", " + std::to_string(mesh.face_count()) + " faces in all");
    return ok;
}

const bool registered = register_command(
    {"triangulate", "Cut every polygon into triangles (concave faces included)",
     "hmira triangulate bevelled.obj triangles.stl", 55, [](CLI::App& sub) {
         auto a = std::make_shared<triangulate_args>();
         sub.add_option("input", a->input, "mesh file to read")->required();
         sub.add_option("output", a->output, "mesh file to write (replaced atomically; not the input)")->required();
         sub.add_flag("--delaunay", a->delaunay,
                      "flip each face's diagonals to its constrained Delaunay triangulation (largest smallest angle)");
         return [a](const common_options& o) { return run_triangulate(*a, o); };
     }});

}  // namespace
