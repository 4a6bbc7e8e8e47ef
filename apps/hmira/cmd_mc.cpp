// apps/hmira/cmd_mc.cpp
// `hmira mc`: marching cubes on a named implicit shape (sphere, torus, gyroid) sampled on an
// n^3 grid, or on a volume file (.inr), writing the iso-surface as a mesh.
#include <filesystem>

#include <hmira/algorithms/conversion/marching_cubes.hpp>
#include <hmira/grids/implicit_shapes.hpp>
#include <hmira/grids/sample.hpp>
#include <hmira/io/volume/inr.hpp>

#include "cli.hpp"

namespace {

using namespace hmira_cli;

struct mc_args {
    std::string source, output;
    std::size_t resolution = 64;
    double iso = 0.0;
    std::string inside = "below";
    bool normals = false;
};

hmira::result<hmira::dense_grid<float>> make_grid(const mc_args& a) {
    if (a.source == "sphere") return hmira::sample_function(hmira::cube_geometry(a.resolution, -1.5, 1.5), hmira::sphere_field{});
    if (a.source == "torus") return hmira::sample_function(hmira::cube_geometry(a.resolution, -1.5, 1.5), hmira::torus_field{});
    if (a.source == "gyroid") return hmira::sample_function(hmira::cube_geometry(a.resolution, -6.0, 6.0), hmira::gyroid_field{});
    const std::filesystem::path p(a.source);
    std::error_code ec;
    if (std::filesystem::is_directory(p, ec)) return hmira::fail(hmira::errc::io_error, a.source + ": is a directory, not a volume file");
    if (p.extension() == ".inr") return hmira::io::read_inr(p);
    return hmira::fail(hmira::errc::invalid_argument, a.source + ": not a shape name (sphere, torus, gyroid) nor a .inr volume");
}

int run_mc(const mc_args& a, const common_options& o) {
    auto grid = make_grid(a);
    if (!grid) return report(exit_code_for(grid.error()), grid.error().message);
    hmira::face_vertex_mesh m;
    const hmira::marching_cubes_options opt{.iso = a.iso,
                                             .inside = a.inside == "above" ? hmira::iso_inside::above : hmira::iso_inside::below,
                                             .normals = a.normals,
                                             .threads = static_cast<unsigned>(o.threads)};
    auto r = hmira::marching_cubes(m, *grid, opt);
    if (!r) return report(exit_code_for(r.error()), r.error().message);
    hmira::io::mesh_attributes attributes;
    for (const auto& n : r->normals) attributes.normals.push_back({float(n.x), float(n.y), float(n.z)});
    hmira::io::write_options w;
    if (!attributes.normals.empty()) w.attributes = &attributes;
    if (int c = save(m, a.output, w, o); c != ok) return c;
    say(o, a.output + ": " + std::to_string(m.vertex_count()) + " vertices, " + std::to_string(m.face_count()) + " triangles");
    return ok;
}

const bool registered = register_command({
    "mc", "Marching cubes: an implicit shape (sphere, torus, gyroid) or a .inr volume to a mesh",
    "hmira mc torus torus.ply --resolution 128", 70,
    [](CLI::App& sub) {
        auto a = std::make_shared<mc_args>();
        sub.add_option("source", a->source, "sphere | torus | gyroid | volume.inr")->required();
        sub.add_option("output", a->output, "mesh file to write (.obj .off .ply .stl)")->required();
        sub.add_option("-n,--resolution", a->resolution, "samples per axis for a named shape")->capture_default_str()->check(CLI::Range(2, 2048));
        sub.add_option("--iso", a->iso, "iso value")->capture_default_str();
        sub.add_option("--inside", a->inside, "which side of the iso value is inside")->capture_default_str()->check(CLI::IsMember({"below", "above"}));
        sub.add_flag("--normals", a->normals, "write per-vertex normals from the field's gradient");
        return [a](const common_options& o) { return run_mc(*a, o); };
    }});

}  // namespace
