// apps/hmira/cmd_mc.cpp
// `hmira mc`: marching cubes on a named implicit shape (sphere, torus, gyroid) sampled on an
// n^3 grid, or on a volume file (.inr, .inr.gz, or .raw with its grid given on the command
// line), writing the iso-surface as a mesh. A .raw or uncompressed .inr file is read slab by
// slab (pread), so its size is not bounded by memory; the output is the same.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <span>
#include <ranges>
#include <variant>

#include <hmira/algorithms/conversion/iso_level.hpp>
#include <hmira/algorithms/conversion/marching_cubes.hpp>
#include <hmira/algorithms/conversion/marching_cubes_blocks.hpp>
#include <hmira/algorithms/decimation/decimate.hpp>
#include <hmira/grids/implicit_shapes.hpp>
#include <hmira/grids/sample.hpp>
#include <hmira/io/volume/inr.hpp>
#include <hmira/io/volume/raw.hpp>
#include <hmira/io/volume/slab_reader.hpp>

#include "cli.hpp"

namespace {

using namespace hmira_cli;

struct mc_args {
    std::string source, output;
    std::size_t resolution = 64;
    /// Not given: 0 for a named shape (a distance field), the midpoint of the samples' range for a
    /// volume file (hmira::default_iso, as Python and scikit-image).
    std::optional<double> iso;
    std::string inside = name_of(hmira::marching_cubes_options{}.inside);
    bool normals = hmira::marching_cubes_options{}.normals;
    // .raw volumes only
    std::string dims, type = "float32", spacing, origin, endian = "little";
    std::size_t slab_slices = 0;           // 0: as many as fit in slab_bytes
    std::optional<double> decimate_ratio;  // decimate_options::target_ratio, the library's other defaults
};

/// --decimate-ratio: the surface (positions, triangles) decimated by the library's decimate to that
/// fraction of its faces, with decimate_options' other defaults, ready to save; the exit code on failure.
template <class Positions, class Triangles>
std::optional<hmira::face_vertex_mesh> decimated(const Positions& positions, const Triangles& triangles, double ratio,
                                                 const common_options& o, int& code) {
    std::vector<std::array<double, 3>> points;
    points.reserve(positions.size());
    for (const auto& p : positions) points.push_back({double(p.x), double(p.y), double(p.z)});
    std::vector<std::uint32_t> corners, offsets{0};
    corners.reserve(3 * triangles.size());
    for (const auto& t : triangles) {
        corners.insert(corners.end(), {std::uint32_t(t[0]), std::uint32_t(t[1]), std::uint32_t(t[2])});
        offsets.push_back(std::uint32_t(corners.size()));
    }
    hmira::halfedge_mesh h;
    const std::span<const std::uint32_t> offsets_view(offsets), corners_view(corners);
    if (auto built = h.assign_polygons(std::span<const std::array<double, 3>>(points), offsets_view, corners_view);
        !built) {
        code = report(invalid_input, "mc --decimate-ratio: " + built.error().message);
        return std::nullopt;
    }
    auto r = hmira::decimate(h, {.target_ratio = ratio});
    if (!r) {
        code = report(exit_code_for(r.error()), "mc --decimate-ratio: " + r.error().message);
        return std::nullopt;
    }
    say(o, "decimated to " + std::to_string(r->faces) + " triangles (largest error " + std::to_string(r->error) +
               (r->note.empty() ? ")" : "); " + r->note));
    return to_face_vertex(h);
}

/// Writes the marching-cubes surface, decimated first with --decimate-ratio; the exit code.
template <class Positions, class Triangles>
int save_surface(const Positions& positions, const Triangles& triangles, const mc_args& a, const common_options& o) {
    int code = ok;
    auto m = decimated(positions, triangles, *a.decimate_ratio, o, code);
    if (!m) return code;
    if (int c = save(*m, a.output, {}, o); c != ok) return c;
    say(o, a.output + ": " + std::to_string(m->vertex_count()) + " vertices, " + std::to_string(m->face_count()) +
               " triangles");
    return ok;
}

/// Samples read at once by the slab-by-slab path when --slab-slices is not given.
constexpr std::size_t slab_bytes = std::size_t(64) << 20;

/// An indexed triangle list seen as a mesh, for the writers (handles are indices).
struct triangle_list_traits {
    using M = hmira::indexed_triangles<double>;
    using vertex_handle = std::size_t;
    using face_handle = std::size_t;
    using scalar = double;
    static auto vertices(const M& m) { return std::views::iota(std::size_t(0), m.positions.size()); }
    static std::size_t vertex_count(const M& m) { return m.positions.size(); }
    static auto faces(const M& m) { return std::views::iota(std::size_t(0), m.triangles.size()); }
    static std::size_t face_count(const M& m) { return m.triangles.size(); }
    static auto face_vertices(const M& m, std::size_t f) {
        const auto& t = m.triangles[f];
        return std::array<std::size_t, 3>{t[0], t[1], t[2]};
    }
    static hmira::vec3<double> position(const M& m, std::size_t v) { return m.positions[v]; }
    static std::size_t vertex_index(const M&, std::size_t v) { return v; }
    static std::size_t vertex_index_bound(const M& m) { return m.positions.size(); }
};

/// A volume of any sample type read_raw supports; marching cubes runs on it as it is.
using any_grid =
    std::variant<hmira::dense_grid<float>, hmira::dense_grid<double>, hmira::dense_grid<std::uint8_t>,
                 hmira::dense_grid<std::int8_t>, hmira::dense_grid<std::uint16_t>, hmira::dense_grid<std::int16_t>,
                 hmira::dense_grid<std::uint32_t>, hmira::dense_grid<std::int32_t>>;

bool ends_with_lower(const std::string& s, const std::string& suffix) {
    if (s.size() < suffix.size()) return false;
    for (std::size_t i = 0; i < suffix.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(s[s.size() - suffix.size() + i])) != suffix[i]) return false;
    return true;
}

/// The grid of a .raw file from --dims/--spacing/--origin; nullopt after printing a usage error.
std::optional<hmira::grid_geometry> raw_geometry(const mc_args& a, int& code) {
    if (a.dims.empty()) {
        code =
            report(usage, a.source + ": a .raw volume holds no size: give --dims X,Y,Z (and --type, default float32)");
        return std::nullopt;
    }
    hmira::grid_geometry g;
    const auto d = parse_triple(a.dims);
    for (std::size_t k = 0; d && k < 3; ++k) {
        if (!((*d)[k] >= 1 && (*d)[k] <= 1e6 && (*d)[k] == double(std::size_t((*d)[k])))) {
            code = report(usage, "--dims " + a.dims + ": expected three whole numbers X,Y,Z, each in [1, 1000000]");
            return std::nullopt;
        }
        g.dims[k] = static_cast<std::size_t>((*d)[k]);
    }
    if (!d) {
        code = report(usage, "--dims " + a.dims + ": expected three whole numbers X,Y,Z, each at least 1");
        return std::nullopt;
    }
    if (!a.spacing.empty()) {
        const auto s = parse_triple(a.spacing, true);
        if (!s || !((*s)[0] > 0 && (*s)[1] > 0 && (*s)[2] > 0)) {
            code = report(usage, "--spacing " + a.spacing + ": expected one positive finite number, or three as X,Y,Z");
            return std::nullopt;
        }
        g.spacing = {(*s)[0], (*s)[1], (*s)[2]};
    }
    if (!a.origin.empty()) {
        const auto p = parse_triple(a.origin);
        if (!p) {
            code = report(usage, "--origin " + a.origin + ": expected three finite numbers X,Y,Z");
            return std::nullopt;
        }
        g.origin = {(*p)[0], (*p)[1], (*p)[2]};
    }
    // A grid whose sample count overflows is the command line's fault, not the file's.
    if (auto fits = hmira::check_grid_geometry(g, "--dims " + a.dims); !fits) {
        code = report(usage, fits.error().message);
        return std::nullopt;
    }
    code = ok;
    return g;
}

hmira::result<any_grid> read_raw_volume(const mc_args& a, const hmira::grid_geometry& g,
                                        std::uint64_t max_input_bytes) {
    const hmira::io::raw_options r{.big_endian = a.endian == "big", .max_input_bytes = max_input_bytes};
    auto as = [&]<class T>(T) -> hmira::result<any_grid> {
        auto grid = hmira::io::read_raw<T>(a.source, g, r);
        if (!grid) return grid.error();
        return any_grid(std::move(*grid));
    };
    if (a.type == "uint8") return as(std::uint8_t{});
    if (a.type == "int8") return as(std::int8_t{});
    if (a.type == "uint16") return as(std::uint16_t{});
    if (a.type == "int16") return as(std::int16_t{});
    if (a.type == "uint32") return as(std::uint32_t{});
    if (a.type == "int32") return as(std::int32_t{});
    if (a.type == "float64") return as(double{});
    return as(float{});
}

hmira::result<hmira::dense_grid<float>> make_grid(const mc_args& a, std::uint64_t max_input_bytes) {
    if (a.source == "sphere")
        return hmira::sample_function(hmira::cube_geometry(a.resolution, -1.5, 1.5), hmira::sphere_field{});
    if (a.source == "torus")
        return hmira::sample_function(hmira::cube_geometry(a.resolution, -1.5, 1.5), hmira::torus_field{});
    if (a.source == "gyroid")
        return hmira::sample_function(hmira::cube_geometry(a.resolution, -6.0, 6.0), hmira::gyroid_field{});
    const std::filesystem::path p(a.source);
    std::error_code ec;
    if (std::filesystem::is_directory(p, ec))
        return hmira::fail(hmira::errc::io_error, a.source + ": is a directory, not a volume file");
    if (ends_with_lower(a.source, ".inr") || ends_with_lower(a.source, ".inr.gz"))
        return hmira::io::read_inr(p, {.max_input_bytes = max_input_bytes});
    return hmira::fail(hmira::errc::invalid_argument,
                       a.source + ": not a shape name (sphere, torus, gyroid) nor a .inr, .inr.gz or .raw volume");
}

/// The layout of a volume file that can be read slab by slab: a regular .raw file, or a
/// regular .inr file without gzip; nullopt for anything else (the whole-volume path then
/// reads it and reports its errors as before).
std::optional<hmira::io::volume_layout> slab_layout(const mc_args& a, const std::optional<hmira::grid_geometry>& raw) {
    std::error_code ec;
    if (a.normals || !std::filesystem::is_regular_file(a.source, ec))
        return std::nullopt;  // normals need whole gradients
    std::optional<hmira::io::volume_layout> l;
    if (raw) {
        using hmira::io::sample_type;
        const sample_type type = a.type == "uint8"     ? sample_type::uint8
                                 : a.type == "int8"    ? sample_type::int8
                                 : a.type == "uint16"  ? sample_type::uint16
                                 : a.type == "int16"   ? sample_type::int16
                                 : a.type == "uint32"  ? sample_type::uint32
                                 : a.type == "int32"   ? sample_type::int32
                                 : a.type == "float64" ? sample_type::float64
                                                       : sample_type::float32;
        l = hmira::io::volume_layout{.geometry = *raw, .type = type, .big_endian = a.endian == "big", .data_offset = 0};
    } else if (ends_with_lower(a.source, ".inr")) {
        if (auto r = hmira::io::read_inr_layout(a.source)) l = *r;
    }
    if (!l || l->geometry.dims[0] < 2 || l->geometry.dims[1] < 2 || l->geometry.dims[2] < 2) return std::nullopt;
    return l;
}

/// Marching cubes of a volume file read slab by slab: peak memory is one slab of samples
/// (64 MiB unless --slab-slices says otherwise) plus the output mesh (24 bytes per vertex, 12
/// per triangle). The mesh equals the whole-volume path's. nullopt: the file does not suit
/// (see slab_layout); otherwise the exit code.
std::optional<int> run_mc_by_slabs(const mc_args& a, const common_options& o,
                                   const std::optional<hmira::grid_geometry>& raw) {
    const auto layout = slab_layout(a, raw);
    if (!layout) return std::nullopt;
    auto reader = hmira::io::volume_slab_reader::open(a.source, *layout);
    if (!reader) return std::nullopt;  // a size mismatch: the whole-volume reader names it as usual
    hmira::marching_cubes_block_options opt{.iso = a.iso.value_or(0.0),
                                            .inside = named<hmira::iso_inside>(a.inside),
                                            .threads = static_cast<unsigned>(o.threads)};
    const auto& g = layout->geometry;
    auto run = [&]<class T>(T) -> hmira::result<hmira::indexed_triangles<double>> {
        const std::size_t plane = g.dims[0] * g.dims[1] * sizeof(T);
        const std::size_t slices = a.slab_slices ? a.slab_slices : std::max<std::size_t>(1, slab_bytes / plane);
        auto fetch = [&](std::size_t k0, std::size_t count, std::vector<T>& out) {
            return reader->read_slices(k0, count, out);
        };
        if (!a.iso) {
            // The default iso needs the samples' range first: one more pass over the file, slab by
            // slab, through the library's range of each slab (the same midpoint as a whole volume's).
            hmira::sample_range range{std::numeric_limits<double>::infinity(),
                                      -std::numeric_limits<double>::infinity()};
            bool finite = true;
            std::vector<T> slab;
            for (std::size_t k0 = 0; k0 < g.dims[2] && finite; k0 += slices) {
                const std::size_t count = std::min(slices, g.dims[2] - k0);
                if (auto got = fetch(k0, count, slab); !got) return got.error();
                const hmira::grid_geometry part{{g.dims[0], g.dims[1], count}, g.origin, g.spacing};
                const auto view = hmira::make_grid_view(std::span<const T>(slab.data(), part.size()), part);
                if (!view) return view.error();
                const auto r = hmira::samples_range(*view);
                // A non-finite sample: marching cubes names it, in the whole file's terms.
                finite = r.has_value();
                if (finite) range = {std::min(range.min, r->min), std::max(range.max, r->max)};
            }
            if (finite && range.min <= range.max) opt.iso = range.midpoint();
        }
        return hmira::marching_cubes_by_slabs<double, T>(g, slices, fetch, opt);
    };
    hmira::result<hmira::indexed_triangles<double>> tri = hmira::fail(hmira::errc::invalid_argument, "");
    // .inr samples become float, as read_inr makes them; .raw samples stay as stored.
    using hmira::io::sample_type;
    if (!raw)
        tri = run(float{});
    else
        switch (layout->type) {
            case sample_type::uint8: tri = run(std::uint8_t{}); break;
            case sample_type::int8: tri = run(std::int8_t{}); break;
            case sample_type::uint16: tri = run(std::uint16_t{}); break;
            case sample_type::int16: tri = run(std::int16_t{}); break;
            case sample_type::uint32: tri = run(std::uint32_t{}); break;
            case sample_type::int32: tri = run(std::int32_t{}); break;
            case sample_type::float64: tri = run(double{}); break;
            case sample_type::float32: tri = run(float{}); break;
        }
    if (!tri) return report(input_exit_code(tri.error()), tri.error().message);
    if (a.decimate_ratio) return save_surface(tri->positions, tri->triangles, a, o);
    if (auto w = hmira::io::write_mesh<hmira::indexed_triangles<double>, triangle_list_traits>(*tri, a.output); !w)
        return report(exit_code_for(w.error()), w.error().message);
    say(o, a.output + ": " + std::to_string(tri->positions.size()) + " vertices, " +
               std::to_string(tri->triangles.size()) + " triangles");
    return ok;
}

int run_mc(const mc_args& a, const common_options& o) {
    const bool raw = ends_with_lower(a.source, ".raw");
    if (!raw && (!a.dims.empty() || !a.spacing.empty() || !a.origin.empty()))
        return report(usage, "--dims, --spacing and --origin describe .raw volumes only; " + a.source + " is not one");
    if (a.decimate_ratio && !(*a.decimate_ratio >= 0 && *a.decimate_ratio <= 1))
        return report(usage, "--decimate-ratio must be in [0, 1], got " + std::to_string(*a.decimate_ratio));
    if (a.decimate_ratio && a.normals)
        return report(usage,
                      "--normals (the field's gradient at the marching-cubes vertices) cannot go with "
                      "--decimate-ratio");
    if (a.slab_slices && !raw && !ends_with_lower(a.source, ".inr"))
        return report(usage, "--slab-slices applies to .raw and .inr volumes only; " + a.source + " is not one");
    hmira::result<any_grid> grid = hmira::fail(hmira::errc::invalid_argument, "");
    if (raw) {
        int code = ok;
        const auto g = raw_geometry(a, code);
        if (!g) return code;
        if (auto done = run_mc_by_slabs(a, o, g)) return *done;
        grid = read_raw_volume(a, *g, o.max_input_bytes);
    } else if (auto done = run_mc_by_slabs(a, o, std::nullopt)) {
        return *done;
    } else if (auto g = make_grid(a, o.max_input_bytes)) {
        grid = any_grid(std::move(*g));
    } else {
        grid = g.error();
    }
    // A volume file's content (zero dimensions, bad spacing, NaN samples) is invalid input; only
    // an unknown shape name is a usage error.
    const bool from_file = raw || ends_with_lower(a.source, ".inr") || ends_with_lower(a.source, ".inr.gz");
    auto code_for = [&](const hmira::error& e) { return from_file ? input_exit_code(e) : exit_code_for(e); };
    if (!grid) return report(code_for(grid.error()), grid.error().message);
    hmira::face_vertex_mesh m;
    double iso = a.iso.value_or(hmira::marching_cubes_options{}.iso);
    if (!a.iso && from_file) {
        // A range that cannot be read (a non-finite sample) is left for marching cubes to report.
        if (auto mid = std::visit([](const auto& g) { return hmira::default_iso(g); }, *grid)) iso = *mid;
    }
    const hmira::marching_cubes_options opt{.iso = iso,
                                            .inside = named<hmira::iso_inside>(a.inside),
                                            .normals = a.normals,
                                            .threads = static_cast<unsigned>(o.threads)};
    auto r = std::visit([&](const auto& g) { return hmira::marching_cubes(m, g, opt); }, *grid);
    if (!r) return report(code_for(r.error()), r.error().message);
    if (a.decimate_ratio) {
        std::vector<hmira::vec3<double>> positions;
        std::vector<std::array<std::size_t, 3>> triangles;
        for (auto v : m.vertices()) positions.push_back(m.position(v));
        for (auto f : m.faces()) {
            std::array<std::size_t, 3> t{};
            std::size_t i = 0;
            for (auto v : m.face_vertices(f)) t[i++] = v.index;
            triangles.push_back(t);
        }
        return save_surface(positions, triangles, a, o);
    }
    hmira::io::mesh_attributes attributes;
    for (const auto& n : r->normals) attributes.normals.push_back({float(n.x), float(n.y), float(n.z)});
    hmira::io::write_options w;
    if (!attributes.normals.empty()) w.attributes = &attributes;
    if (int c = save(m, a.output, w, o); c != ok) return c;
    say(o, a.output + ": " + std::to_string(m.vertex_count()) + " vertices, " + std::to_string(m.face_count()) +
               " triangles");
    return ok;
}

const bool registered = register_command(
    {"mc", "Marching cubes: an implicit shape (sphere, torus, gyroid) or a .inr/.raw volume to a mesh",
     "hmira mc torus torus.ply --resolution 128", 70, [](CLI::App& sub) {
         auto a = std::make_shared<mc_args>();
         sub.add_option("source", a->source, "sphere | torus | gyroid | volume.inr | volume.inr.gz | volume.raw")
             ->required();
         sub.add_option("output", a->output, "mesh file to write (.obj .off .ply .stl)")->required();
         sub.add_option("-n,--resolution", a->resolution, "samples per axis for a named shape")
             ->capture_default_str()
             ->check(whole_number(2, 2048));
         sub.add_option("--iso", a->iso,
                        "iso value, within the samples' range (default: 0 for a shape, the range's midpoint for a "
                        "volume file)")
             ->check(finite_number());
         sub.add_option("--inside", a->inside,
                        "which side of the iso value is inside: below for distance fields, above for scans and "
                        "label maps (at below they come out inside-out)")
             ->capture_default_str()
             ->check(CLI::IsMember(names_of<hmira::iso_inside>()));
         sub.add_flag("--normals", a->normals, "write per-vertex normals from the field's gradient");
         sub.add_option("--dims", a->dims,
                        ".raw: samples along x, y and z (required for .raw; x varies fastest in the file)")
             ->type_name("X,Y,Z");
         sub.add_option("--type", a->type, ".raw: sample type")
             ->capture_default_str()
             ->check(CLI::IsMember({"uint8", "int8", "uint16", "int16", "uint32", "int32", "float32", "float64"}));
         sub.add_option("--spacing", a->spacing,
                        ".raw: distance between samples, one for all axes or X,Y,Z (default 1)")
             ->type_name("H|X,Y,Z");
         sub.add_option("--origin", a->origin, ".raw: position of sample (0, 0, 0) (default 0,0,0)")
             ->type_name("X,Y,Z");
         sub.add_option(
                "--slab-slices", a->slab_slices,
                ".raw/.inr: z-slices read at a time (default: 64 MiB worth); the file is read slab by slab, so memory "
                "holds a slab plus the output mesh, whatever the volume's size (not with --normals)")
             ->check(whole_number(1, 1000000));
         sub.add_option("--decimate-ratio", a->decimate_ratio,
                        "decimate the surface (quadric error, as 'hmira decimate --ratio') to this fraction of its "
                        "triangles before writing it");
         sub.add_option("--endian", a->endian, ".raw: byte order of multi-byte samples")
             ->capture_default_str()
             ->check(CLI::IsMember({"little", "big"}));
         sub.footer(
             "\nA .raw volume (x fastest, no header) needs its grid on the command line, e.g.\n"
             "  hmira mc ct.raw ct.ply --dims 256,256,128 --type int16 --spacing 0.5,0.5,1 --iso 300 --inside above\n"
             "A .raw volume from 'hmira voxelize' comes with <file>.txt, which gives the exact 'hmira mc' command.\n" +
             sub.get_footer());
         return [a](const common_options& o) { return run_mc(*a, o); };
     }});

}  // namespace
