// bench/io/io_bench.cpp
// Reading mesh files, like with like:
//   soup/<file>: into indexed arrays (hmira read_soup, CGAL IO::read_polygon_soup);
//   mesh/<file>: into a connected mesh, STL welded (hmira read_mesh into halfedge_mesh and
//                face_vertex_mesh, OpenMesh IO::read_mesh into a PolyMesh, CGAL
//                IO::read_polygon_mesh into a Surface_mesh).
// `bench_io --generate DIR` writes the generated 2M-triangle files (binary PLY, ASCII OBJ,
// binary STL). Files to read come from HMIRA_IO_BENCH_FILES (colon-separated).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#ifdef HMIRA_BENCH_WITH_OPENMESH
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#endif
#ifdef HMIRA_BENCH_WITH_TINYOBJ
#include <tiny_obj_loader.h>
#endif
#ifdef HMIRA_BENCH_WITH_CGAL
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>
#endif

namespace {

/// A closed torus of nu x nv quads split into 2 nu nv triangles (2M for 1000 x 1000),
/// coordinates jittered so that text files carry full-length numbers.
hmira::face_vertex_mesh big_torus(std::size_t nu, std::size_t nv) {
    hmira::face_vertex_mesh m;
    m.reserve(nu * nv, 2 * nu * nv, 6 * nu * nv);
    std::vector<hmira::vertex_handle> vs;
    vs.reserve(nu * nv);
    for (std::size_t i = 0; i < nu; ++i)
        for (std::size_t j = 0; j < nv; ++j) {
            const double u = 2 * std::numbers::pi * double(i) / double(nu),
                         v = 2 * std::numbers::pi * double(j) / double(nv);
            const double r = 0.7 + 1e-4 * std::sin(37.0 * u + 11.0 * v);
            vs.push_back(m.add_vertex(
                {(2 + r * std::cos(v)) * std::cos(u), (2 + r * std::cos(v)) * std::sin(u), r * std::sin(v)}));
        }
    for (std::size_t i = 0; i < nu; ++i)
        for (std::size_t j = 0; j < nv; ++j) {
            const auto a = vs[i * nv + j], b = vs[((i + 1) % nu) * nv + j], c = vs[((i + 1) % nu) * nv + (j + 1) % nv],
                       d = vs[i * nv + (j + 1) % nv];
            (void)m.add_face({a, b, c});
            (void)m.add_face({a, c, d});
        }
    return m;
}

int generate(const std::filesystem::path& dir) {
    std::filesystem::create_directories(dir);
    const auto m = big_torus(1000, 1000);
    namespace io = hmira::io;
    const io::write_options float_ply{.ply = io::ply_encoding::binary_little_endian,
                                      .ply_coordinates = io::ply_scalar::float32};
    for (auto [name, opts] : {std::pair{"torus_2M.ply", float_ply}, std::pair{"torus_2M.obj", io::write_options{}},
                              std::pair{"torus_2M.stl", io::write_options{}}}) {
        auto w = io::write_mesh(m, dir / name, opts);
        if (!w) {
            std::cerr << w.error().message << '\n';
            return 1;
        }
        std::cout << (dir / name).string() << '\n';
    }
    return 0;
}

void label(benchmark::State& s, std::size_t v, std::size_t f) {
    s.counters["V"] = double(v);
    s.counters["F"] = double(f);
}

void hmira_soup(benchmark::State& s, std::string path) {
    for (auto _ : s) {
        auto soup = hmira::io::read_soup(path);
        if (!soup)
            s.SkipWithError(soup.error().message.c_str());
        else
            label(s, soup->points.size(), soup->face_count());
        benchmark::DoNotOptimize(soup);
    }
}

template <class M>
void hmira_mesh(benchmark::State& s, std::string path) {
    for (auto _ : s) {
        M m;
        auto r = hmira::io::read_mesh(m, path);
        if (!r)
            s.SkipWithError(r.error().message.c_str());
        else
            label(s, m.vertex_count(), m.face_count());
        benchmark::DoNotOptimize(m);
    }
}

#ifdef HMIRA_BENCH_WITH_OPENMESH
void openmesh_mesh(benchmark::State& s, std::string path) {
    for (auto _ : s) {
        OpenMesh::PolyMesh_ArrayKernelT<> m;
        if (!OpenMesh::IO::read_mesh(m, path))
            s.SkipWithError("OpenMesh read_mesh failed");
        else
            label(s, m.n_vertices(), m.n_faces());
        benchmark::DoNotOptimize(m);
    }
}
#endif

#ifdef HMIRA_BENCH_WITH_CGAL
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
void cgal_soup(benchmark::State& s, std::string path) {
    for (auto _ : s) {
        std::vector<K::Point_3> points;
        std::vector<std::vector<std::size_t>> polygons;
        if (!CGAL::IO::read_polygon_soup(path, points, polygons))
            s.SkipWithError("CGAL read_polygon_soup failed");
        else
            label(s, points.size(), polygons.size());
        benchmark::DoNotOptimize(points);
    }
}
void cgal_mesh(benchmark::State& s, std::string path) {
    for (auto _ : s) {
        CGAL::Surface_mesh<K::Point_3> m;
        if (!CGAL::IO::read_polygon_mesh(path, m))
            s.SkipWithError("CGAL read_polygon_mesh failed");
        else
            label(s, m.number_of_vertices(), m.number_of_faces());
        benchmark::DoNotOptimize(m);
    }
}
#endif

#ifdef HMIRA_BENCH_WITH_TINYOBJ
// Into indexed arrays, polygons kept (no triangulation), like read_soup.
void tinyobj_soup(benchmark::State& s, std::string path) {
    tinyobj::ObjReaderConfig config;
    config.triangulate = false;
    config.vertex_color = false;
    for (auto _ : s) {
        tinyobj::ObjReader reader;
        if (!reader.ParseFromFile(path, config))
            s.SkipWithError(("tinyobjloader: " + reader.Error()).c_str());
        else {
            std::size_t faces = 0;
            for (const auto& shape : reader.GetShapes()) faces += shape.mesh.num_face_vertices.size();
            label(s, reader.GetAttrib().vertices.size() / 3, faces);
        }
        benchmark::DoNotOptimize(reader);
    }
}
#endif

}  // namespace

int main(int argc, char** argv) {
    if (argc == 3 && std::strcmp(argv[1], "--generate") == 0) return generate(argv[2]);
    const char* files = std::getenv("HMIRA_IO_BENCH_FILES");
    std::vector<std::string> paths;
    if (files) {
        std::stringstream ss(files);
        for (std::string p; std::getline(ss, p, ':');)
            if (!p.empty()) paths.push_back(p);
    }
    if (paths.empty()) {
        std::cerr << "bench_io: set HMIRA_IO_BENCH_FILES=a.ply:b.off (bench/io/run.sh does)\n";
        return 2;
    }
    for (const auto& p : paths) {
        const std::string name = std::filesystem::path(p).filename().string();
        const bool big = std::filesystem::file_size(p) > (8u << 20);
        auto reg = [&](const std::string& label_name, auto fn) {
            auto* b = benchmark::RegisterBenchmark(label_name.c_str(), fn, p);
            b->Unit(benchmark::kMillisecond);
            b->Iterations(big ? 3 : 20);
            // Medians of 5 on both sides (peers.py too): a minimum rewards a lucky repetition.
            b->Repetitions(5)->ReportAggregatesOnly(true);
        };
        reg("soup/" + name + "/hmira", hmira_soup);
        reg("mesh/" + name + "/hmira_halfedge", hmira_mesh<hmira::halfedge_mesh>);
        reg("mesh/" + name + "/hmira_face_vertex", hmira_mesh<hmira::face_vertex_mesh>);
#ifdef HMIRA_BENCH_WITH_OPENMESH
        reg("mesh/" + name + "/openmesh", openmesh_mesh);
#endif
#ifdef HMIRA_BENCH_WITH_TINYOBJ
        if (std::filesystem::path(p).extension() == ".obj") reg("soup/" + name + "/tinyobjloader", tinyobj_soup);
#endif
#ifdef HMIRA_BENCH_WITH_CGAL
        reg("soup/" + name + "/cgal", cgal_soup);
        reg("mesh/" + name + "/cgal", cgal_mesh);
#endif
    }
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
