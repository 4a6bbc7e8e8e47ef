// apps/hmira/cmd_sdf.cpp
// `hmira sdf IN OUT.raw`: the signed distance to a mesh (negative inside, the inside decided by
// the winding number) on a cubic grid around it, written as float32 .raw samples with a text
// sidecar giving the grid and the `hmira mc` command that extracts a level set from it.
#include <cstdio>
#include <filesystem>
#include <limits>
#include <sstream>

#include <hmira/algorithms/conversion/voxelize.hpp>
#include <hmira/algorithms/spatial/signed_distance_grid.hpp>
#include <hmira/io/detail/files.hpp>
#include <hmira/io/volume/raw.hpp>

#include "cli.hpp"

namespace {

using namespace hmira_cli;

struct sdf_args {
    std::string input, output;
    std::size_t resolution = 256;
    std::size_t padding = 2;
    double band = 0;  // 0: the full field
    std::string sign = name_of(hmira::signed_distance_grid_options{}.sign);
};

std::string num(double x) {
    char b[40];
    std::snprintf(b, sizeof b, "%.17g", x);
    return b;
}

std::string sdf_sidecar(const hmira::grid_geometry& g, const std::string& raw_name) {
    std::ostringstream s;
    const std::string dims =
        std::to_string(g.dims[0]) + "," + std::to_string(g.dims[1]) + "," + std::to_string(g.dims[2]);
    const std::string spacing = num(g.spacing.x) + "," + num(g.spacing.y) + "," + num(g.spacing.z);
    const std::string origin = num(g.origin.x) + "," + num(g.origin.y) + "," + num(g.origin.z);
    s << "# hmira sdf: the grid of " << raw_name
      << " (float32 signed distance per sample, negative inside, x fastest, then y, then z)\n"
      << "file: " << raw_name << "\ndims: " << dims << "\ntype: float32\nspacing: " << spacing << "\norigin: " << origin
      << "  # sample (0, 0, 0)\nmc: hmira mc " << raw_name << " surface.obj --dims " << dims
      << " --type float32 --spacing " << spacing << " --origin " << origin << " --iso 0 --inside below\n";
    return s.str();
}

int run_sdf(const sdf_args& a, const common_options& o) {
    std::string ext = std::filesystem::path(a.output).extension().string();
    for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext != ".raw") return report(usage, a.output + ": unknown volume format '" + ext + "' (use .raw)");
    int code = ok;
    auto loaded = load(a.input, o, code);
    if (!loaded) return code;
    const auto& mesh = loaded->mesh;
    if (!refuse_non_finite(mesh, a.input, "sdf", code)) return code;
    if (mesh.vertex_count() == 0) return report(invalid_input, a.input + ": sdf: the mesh has no vertices");
    auto grid = hmira::voxel_grid_around(mesh, a.resolution, a.padding);
    if (!grid) return report(input_exit_code(grid.error()), a.input + ": " + grid.error().message);
    if (const auto free = free_memory(); free && grid->size() * 4 > *free)
        return report(invalid_input, a.input + ": sdf: the grid needs more memory than is free; lower --resolution");
    const auto field =
        hmira::signed_distance_grid<float>(mesh, *grid,
                                           {.band = a.band > 0 ? a.band : std::numeric_limits<double>::infinity(),
                                            .sign = named<hmira::sign_mode>(a.sign),
                                            .threads = static_cast<unsigned>(o.threads)});
    if (!field) return report(input_exit_code(field.error()), a.input + ": " + field.error().message);
    const std::string sidecar = a.output + ".txt";
    const auto text = sdf_sidecar(*grid, std::filesystem::path(a.output).filename().string());
    auto staged = hmira::io::detail::staged_file::write(sidecar, [&](std::ostream& out) { return bool(out << text); });
    if (!staged) return report(exit_code_for(staged.error()), staged.error().message);
    if (auto w = hmira::io::write_raw(*field, a.output); !w) return report(exit_code_for(w.error()), w.error().message);
    if (auto c = staged->commit(); !c) return report(exit_code_for(c.error()), c.error().message);
    say(o, a.input + ": " + std::to_string(grid->dims[0]) + " x " + std::to_string(grid->dims[1]) + " x " +
               std::to_string(grid->dims[2]) + " signed distances -> " + a.output + " (grid in " + sidecar + ")");
    return ok;
}

const bool registered = register_command(
    {"sdf", "Signed distance field of a mesh (negative inside) on a grid, as float32 .raw with a sidecar",
     "hmira sdf bunny.off bunny.raw -n 128", 122, [](CLI::App& sub) {
         auto a = std::make_shared<sdf_args>();
         sub.add_option("input", a->input, "mesh file to read (.obj .off .ply .stl)")->required();
         sub.add_option("output", a->output,
                        ".raw volume to write (float32, x fastest); the grid's dims, spacing and origin go to "
                        "<output>.txt")
             ->required();
         sub.add_option("-n,--resolution", a->resolution, "samples along the longest side of the bounding box")
             ->capture_default_str()
             ->check(whole_number(1, 2048));
         sub.add_option("--padding", a->padding, "samples added on every side of the bounding box")
             ->capture_default_str()
             ->check(whole_number(0, 1024));
         sub.add_option("--band", a->band,
                        "narrow band: samples farther than this from the surface hold +-band (default: the full field)")
             ->check(finite_number("> 0", [](double x) { return x > 0; }));
         sub.add_option("--sign", a->sign,
                        "winding_number (robust on open and self-intersecting meshes), pseudo_normal or parity")
             ->capture_default_str()
             ->check(CLI::IsMember(names_of<hmira::sign_mode>()));
         return [a](const common_options& o) { return run_sdf(*a, o); };
     }});

}  // namespace
