// bench/repair/repair_vs_cgal.cpp
// Reads each mesh file as a polygon soup and turns it into a CGAL Surface_mesh twice: with
// hmira's repair (io::build_from_soup) and with CGAL's repair_polygon_soup +
// orient_polygon_soup + polygon_soup_to_polygon_mesh. Prints faces in the file, faces each
// kept, and the time of each (soup already in memory; the conversion to CGAL's containers is
// not timed). Given a folder, it takes the files CGAL's is_polygon_soup_a_polygon_mesh rejects.
//
//   bench_repair_vs_cgal /work/test-data/meshes/pig.stl /work/test-data/meshes
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <hmira/interop/cgal.hpp>
#include <hmira/io/mesh_io.hpp>

namespace {

using kernel = CGAL::Simple_cartesian<double>;
using point = kernel::Point_3;
using surface = CGAL::Surface_mesh<point>;
namespace PMP = CGAL::Polygon_mesh_processing;

struct cgal_soup {
    std::vector<point> points;
    std::vector<std::vector<std::size_t>> polygons;
};

cgal_soup to_cgal(const hmira::io::polygon_soup& s) {
    cgal_soup c;
    for (const auto& p : s.points) c.points.emplace_back(p[0], p[1], p[2]);
    for (std::size_t f = 0; f < s.face_count(); ++f)
        c.polygons.emplace_back(s.indices.begin() + static_cast<long>(s.face_offsets[f]),
                                s.indices.begin() + static_cast<long>(s.face_offsets[f + 1]));
    return c;
}

double seconds_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

/// One row; returns false when hmira kept fewer faces than CGAL.
bool compare(const std::filesystem::path& path) {
    auto soup = hmira::io::read_soup(path);
    if (!soup) {
        std::printf("%-32s  unreadable: %s\n", path.filename().string().c_str(), soup.error().message.c_str());
        return true;
    }
    const std::size_t file_faces = soup->face_count();
    cgal_soup c = to_cgal(*soup);

    auto t0 = std::chrono::steady_clock::now();
    surface ours;
    auto report = hmira::io::build_from_soup<surface>(ours, hmira::io::polygon_soup(*soup), path.string());
    const double ours_time = seconds_since(t0);
    const std::size_t ours_faces = report ? ours.number_of_faces() : 0;
    const bool ours_valid = report && CGAL::is_valid_polygon_mesh(ours);

    t0 = std::chrono::steady_clock::now();
    PMP::repair_polygon_soup(c.points, c.polygons);
    PMP::orient_polygon_soup(c.points, c.polygons);
    surface theirs;
    const bool theirs_ok = PMP::is_polygon_soup_a_polygon_mesh(c.polygons);
    if (theirs_ok) PMP::polygon_soup_to_polygon_mesh(c.points, c.polygons, theirs);
    const double theirs_time = seconds_since(t0);
    const std::size_t theirs_faces = theirs_ok ? theirs.number_of_faces() : 0;

    std::printf("%-32s %10zu %10zu %10zu %10.4f %10.4f  %s%s\n", path.filename().string().c_str(), file_faces,
                ours_faces, theirs_faces, ours_time, theirs_time, ours_valid ? "valid" : "INVALID",
                theirs_ok ? "" : " (CGAL's result is still no polygon mesh)");
    if (report && !report->repair.clean()) std::printf("%-32s   hmira: %s\n", "", report->repair.summary().c_str());
    return ours_faces >= theirs_faces;
}

bool rejected_by_cgal(const std::filesystem::path& path) {
    auto soup = hmira::io::read_soup(path);
    if (!soup) return false;
    return !PMP::is_polygon_soup_a_polygon_mesh(to_cgal(*soup).polygons);
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::filesystem::path> files;
    for (int i = 1; i < argc; ++i) {
        const std::filesystem::path arg = argv[i];
        if (std::filesystem::is_directory(arg)) {
            std::vector<std::filesystem::path> found;
            for (const auto& e : std::filesystem::directory_iterator(arg))
                if (hmira::io::format_from_extension(e.path()) && rejected_by_cgal(e.path())) found.push_back(e.path());
            std::sort(found.begin(), found.end());
            for (auto& f : found)
                if (std::find(files.begin(), files.end(), f) == files.end()) files.push_back(f);
        } else {
            files.push_back(arg);
        }
    }
    if (files.empty()) {
        std::fprintf(stderr, "usage: bench_repair_vs_cgal FILE_OR_FOLDER...\n");
        return 2;
    }
    std::printf("%-32s %10s %10s %10s %10s %10s\n", "file", "faces", "hmira", "CGAL", "hmira s", "CGAL s");
    bool all_kept = true;
    for (const auto& f : files) all_kept &= compare(f);
    std::printf(all_kept ? "hmira kept at least as many faces as CGAL on every file\n"
                         : "hmira kept FEWER faces than CGAL on some file\n");
    return all_kept ? 0 : 1;
}
