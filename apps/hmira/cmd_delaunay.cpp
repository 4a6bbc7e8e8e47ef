// apps/hmira/cmd_delaunay.cpp
// `hmira delaunay`: the 2.5D Delaunay triangulation of points (x, y; z rides along) read from
// .xyz (x y [z] per line), .csv (x,y[,z], an optional header line) or .ply (the vertices).
#include <charconv>
#include <filesystem>

#include <hmira/algorithms/delaunay/delaunay_triangulation.hpp>
#include <hmira/io/detail/files.hpp>
#include <hmira/io/points.hpp>

#include "cli.hpp"

namespace {

using namespace hmira_cli;

struct delaunay_args {
    std::string input, output;
};

/// x y [z] per line, separated by blanks or commas; '#' starts a comment; in a .csv the first
/// line may be a header (hmira/io/points.hpp).
hmira::result<std::vector<hmira::vec3<double>>> read_points_text(const std::string& path, bool csv,
                                                                 std::uint64_t max_input_bytes) {
    return hmira::io::read_points_text(path, {.csv = csv, .max_input_bytes = max_input_bytes});
}

hmira::result<std::vector<hmira::vec3<double>>> read_points(const std::string& path, const common_options& o) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".xyz" || ext == ".txt" || ext == ".csv")
        return read_points_text(path, ext == ".csv", o.max_input_bytes);
    if (ext == ".ply") {
        auto soup = hmira::io::read_soup(path, {.max_input_bytes = o.max_input_bytes});
        if (!soup) return soup.error();
        std::vector<hmira::vec3<double>> pts;
        pts.reserve(soup->points.size());
        for (const auto& p : soup->points) pts.push_back({p[0], p[1], p[2]});
        return pts;
    }
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        return hmira::fail(hmira::errc::io_error, path + ": is a directory, not a point file");
    return hmira::fail(hmira::errc::unknown_format,
                       path + ": unknown mesh format '" + ext + "' for points (use .xyz, .csv or .ply)");
}

int run_delaunay(const delaunay_args& a, const common_options& o) {
    note_input(a.input);
    auto pts = read_points(a.input, o);
    if (!pts) return report(input_exit_code(pts.error()), pts.error().message);
    hmira::face_vertex_mesh m;
    auto r = hmira::delaunay_triangulation(m, *pts);
    if (!r) return report(invalid_input, a.input + ": " + r.error().message);
    if (int c = save(m, a.output, {}, o); c != ok) return c;
    say(o, a.output + ": " + std::to_string(pts->size()) + " points, " + std::to_string(m.vertex_count()) +
               " vertices, " + std::to_string(m.face_count()) + " triangles");
    return ok;
}

const bool registered = register_command(
    {"delaunay", "Delaunay-triangulate points (x, y; z kept as height) from .xyz, .csv or .ply",
     "hmira delaunay terrain.xyz terrain.ply", 60, [](CLI::App& sub) {
         auto a = std::make_shared<delaunay_args>();
         sub.add_option("input", a->input, "points: .xyz (x y [z] per line), .csv (x,y[,z]) or .ply (its vertices)")
             ->required();
         sub.add_option("output", a->output, "mesh file to write (.obj .off .ply .stl)")->required();
         return [a](const common_options& o) { return run_delaunay(*a, o); };
     }});

}  // namespace
