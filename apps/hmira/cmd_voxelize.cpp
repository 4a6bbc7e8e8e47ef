// apps/hmira/cmd_voxelize.cpp
// `hmira voxelize`: the voxels a mesh's surface touches, and for a closed mesh those inside it,
// on a cubic grid around the mesh, written as .binvox or as .raw bytes with a text sidecar
// giving the grid (and the `hmira mc` command that reads it back).
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <optional>
#include <sstream>

#include <hmira/algorithms/conversion/voxelize.hpp>
#include <hmira/io/detail/files.hpp>
#include <hmira/io/volume/binvox.hpp>
#include <hmira/io/volume/raw.hpp>

#include "cli.hpp"

namespace {

using namespace hmira_cli;

struct voxelize_args {
    std::string input, output;
    std::size_t resolution = 256;
    /// 2, not 1: voxels whose closed box touches the surface count, so where the surface lies
    /// on the bounding box the first padding layer is set; the second stays empty, which keeps
    /// an iso-surface of the voxels (hmira mc) closed.
    std::size_t padding = 2;
    bool surface = false;
    /// surface, conservative or centres (--surface is an alias of --mode surface).
    std::string mode = name_of(hmira::voxelize_options{}.mode);
    bool fill_open = hmira::voxelize_options{}.open_mesh == hmira::open_mesh_fill::winding_number;
};

std::string lower_extension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

std::string num(double x) {
    char b[40];
    std::snprintf(b, sizeof b, "%.17g", x);
    return b;
}

/// The sidecar of a .raw volume: the grid it needs to be read back, one "key: value" a line,
/// and the `hmira mc` command that turns it back into a surface.
std::string raw_sidecar(const hmira::grid_geometry& g, const std::string& raw_name, std::size_t set) {
    std::ostringstream s;
    const std::string dims =
        std::to_string(g.dims[0]) + "," + std::to_string(g.dims[1]) + "," + std::to_string(g.dims[2]);
    const std::string spacing = num(g.spacing.x) + "," + num(g.spacing.y) + "," + num(g.spacing.z);
    const std::string origin = num(g.origin.x) + "," + num(g.origin.y) + "," + num(g.origin.z);
    s << "# hmira voxelize: the grid of " << raw_name << " (one byte per voxel, 1 = set, x fastest, then y, then z)\n"
      << "file: " << raw_name << "\ndims: " << dims << "\ntype: uint8\nspacing: " << spacing << "\norigin: " << origin
      << "  # centre of voxel (0, 0, 0)\nset: " << set << "\nmc: hmira mc " << raw_name << " surface.obj --dims "
      << dims << " --type uint8 --spacing " << spacing << " --origin " << origin << " --iso 0.5 --inside above\n";
    return s.str();
}

std::string gigabytes(std::uint64_t bytes) {
    char b[32];
    std::snprintf(b, sizeof b, "%.1f GB", double(bytes) / 1e9);
    return b;
}

int run_voxelize(const voxelize_args& a, const common_options& o) {
    const std::string ext = lower_extension(a.output);
    if (ext != ".binvox" && ext != ".raw")
        return report(usage, a.output + ": unknown voxel format '" + ext + "' (use .binvox or .raw)");
    int code = ok;
    auto loaded = load(a.input, o, code);
    if (!loaded) return code;
    const auto& mesh = loaded->mesh;
    if (!refuse_non_finite(mesh, a.input, "voxelize", code)) return code;
    if (mesh.vertex_count() == 0) return report(invalid_input, a.input + ": voxelize: the mesh has no vertices");
    auto grid = hmira::voxel_grid_around(mesh, a.resolution, a.padding);
    // --resolution and --padding were checked on the command line: what is left is the mesh.
    if (!grid) return report(input_exit_code(grid.error()), a.input + ": " + grid.error().message);
    // The grid, padding included, must fit in the memory free now: its bits are allocated
    // untouched, so the system would otherwise only run out part way through, after minutes.
    std::size_t triangles = 0;
    for (auto f : mesh.faces()) triangles += std::max<std::size_t>(mesh.face_vertices(f).size(), 3) - 2;
    const std::uint64_t needed = hmira::voxelize_memory_estimate(*grid, triangles);
    if (const auto free = free_memory(); free && needed > *free)
        return report(invalid_input, a.input + ": voxelize: a grid of " + std::to_string(grid->dims[0]) + " x " +
                                         std::to_string(grid->dims[1]) + " x " + std::to_string(grid->dims[2]) +
                                         " voxels (--resolution " + std::to_string(a.resolution) + ", --padding " +
                                         std::to_string(a.padding) + ") needs about " + gigabytes(needed) +
                                         ", but only " + gigabytes(*free) +
                                         " of memory is free; lower --resolution or --padding");
    const auto mode = a.surface ? hmira::voxelize_mode::surface : named<hmira::voxelize_mode>(a.mode);
    const hmira::voxelize_options options{
        .mode = mode,
        .open_mesh = a.fill_open ? hmira::open_mesh_fill::winding_number : hmira::open_mesh_fill::surface_only,
        .allow_degenerate = true,
        .threads = static_cast<unsigned>(o.threads)};
    hmira::result<hmira::voxelization> voxels = hmira::fail(hmira::errc::invalid_argument, "");
    {
        auto bar = stage_bar("voxelizing " + a.input, o, grid->size(), std::uint64_t(64) << 20);
        bar.update(0, 1000);
        // A large grid takes minutes: the bar follows the voxelization itself, then the write.
        hmira::voxelize_options watched = options;
        watched.progress = [&bar](double done) {
            bar.update(static_cast<std::uint64_t>(900 * done), 1000);
            return true;
        };
        voxels = hmira::voxelize(mesh, *grid, watched);
        if (!voxels) return report(input_exit_code(voxels.error()), a.input + ": " + voxels.error().message);
        bar.update(900, 1000);
        if (ext == ".binvox") {
            if (auto w = hmira::io::write_binvox(voxels->voxels, a.output); !w)
                return report(exit_code_for(w.error()), w.error().message);
        } else {
            // The sidecar is written in full first but committed last: a failure anywhere leaves
            // both old files as they were, and no sidecar ever describes a .raw not yet there.
            const std::string sidecar = a.output + ".txt";
            const auto text =
                raw_sidecar(*grid, std::filesystem::path(a.output).filename().string(), voxels->voxels.count());
            auto staged =
                hmira::io::detail::staged_file::write(sidecar, [&](std::ostream& out) { return bool(out << text); });
            if (!staged) return report(exit_code_for(staged.error()), staged.error().message);
            if (auto w = hmira::io::write_raw(voxels->voxels, a.output); !w)
                return report(exit_code_for(w.error()), w.error().message);
            if (auto c = staged->commit(); !c)
                return report(exit_code_for(c.error()),
                              c.error().message + " (" + a.output + " was replaced; run again to update its sidecar)");
        }
    }
    const auto& g = *grid;
    char spacing[32];
    std::snprintf(spacing, sizeof spacing, "%.6g", g.spacing.x);
    std::string line = a.input + ": " + std::to_string(g.dims[0]) + " x " + std::to_string(g.dims[1]) + " x " +
                       std::to_string(g.dims[2]) + " voxels of size " + spacing + ", " +
                       std::to_string(voxels->voxels.count()) + " set (" +
                       (voxels->filled ? (mode == hmira::voxelize_mode::centres ? "centres" : "solid") : "surface") +
                       ") -> " + a.output;
    if (ext == ".raw") line += " (grid in " + a.output + ".txt)";
    say(o, line);
    if (!voxels->note.empty()) say(o, "note: " + voxels->note);
    return ok;
}

const bool registered = register_command(
    {"voxelize", "Voxelize a mesh (its surface, and the inside of a closed one) to .binvox or .raw",
     "hmira voxelize bunny.off bunny.binvox --resolution 128", 110, [](CLI::App& sub) {
         auto a = std::make_shared<voxelize_args>();
         sub.add_option("input", a->input, "mesh file to read (.obj .off .ply .stl)")->required();
         sub.add_option("output", a->output,
                        "voxels to write: .binvox (run-length encoded, a cube), or .raw (one byte per voxel, x "
                        "fastest) with the grid's dims, "
                        "spacing and origin written to <output>.txt")
             ->required();
         sub.add_option("-n,--resolution", a->resolution, "voxels along the longest side of the bounding box")
             ->capture_default_str()
             ->check(whole_number(1, 2048));
         sub.add_option("--padding", a->padding,
                        "voxels added on every side of the bounding box (the outer one of 2 stays empty even where the "
                        "surface lies on the box)")
             ->capture_default_str()
             ->check(whole_number(0, 1024));
         auto* mode = sub.add_option("--mode", a->mode,
                                     "surface: the voxels the surface touches; conservative (default): those and every "
                                     "voxel whose centre is inside a closed mesh "
                                     "(for collision); centres: exactly the voxels whose centre is inside (for volume, "
                                     "as VTK's stencil)")
                          ->check(CLI::IsMember(names_of<hmira::voxelize_mode>()));
         sub.add_flag("--surface", a->surface, "alias of --mode surface")->excludes(mode);
         sub.add_flag("--fill-open", a->fill_open,
                      "conservative or centres mode on a mesh with holes: fill where the winding number is at least "
                      "1/2 (default: surface only, with a note)");
         return [a](const common_options& o) { return run_voxelize(*a, o); };
     }});

}  // namespace
