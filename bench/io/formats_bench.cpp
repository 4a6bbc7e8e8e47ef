// bench/io/formats_bench.cpp
// The 2M-triangle torus of bench/io in 3MF, VTP and GLB, and hmira's read times for them, for
// bench/io/formats.sh to set beside trimesh and PyVista run by run.
//   formats_bench --generate DIR     writes DIR/torus_2M.{3mf,vtp,glb}
//   formats_bench --read FILE        prints "soup <s> mesh <s>": read_soup, and read_mesh into halfedge_mesh
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

namespace {

/// The torus of bench/io/io_bench.cpp: nu x nv quads split into 2 nu nv triangles, coordinates
/// jittered so that text formats carry full-length numbers.
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

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
    namespace io = hmira::io;
    if (argc == 3 && std::string(argv[1]) == "--generate") {
        const std::filesystem::path dir = argv[2];
        std::filesystem::create_directories(dir);
        const auto m = big_torus(1000, 1000);
        for (const char* name : {"torus_2M.3mf", "torus_2M.vtp", "torus_2M.glb"}) {
            if (auto w = io::write_mesh(m, dir / name); !w) {
                std::fprintf(stderr, "%s\n", w.error().message.c_str());
                return 1;
            }
            std::printf("%s\n", (dir / name).string().c_str());
        }
        return 0;
    }
    if (argc == 3 && std::string(argv[1]) == "--read") {
        auto t0 = std::chrono::steady_clock::now();
        auto soup = io::read_soup(argv[2]);
        const double soup_s = seconds_since(t0);
        if (!soup) {
            std::fprintf(stderr, "%s\n", soup.error().message.c_str());
            return 1;
        }
        const std::size_t faces = soup->face_count();
        soup = io::polygon_soup{};
        hmira::halfedge_mesh mesh;
        t0 = std::chrono::steady_clock::now();
        auto r = io::read_mesh(mesh, argv[2]);
        const double mesh_s = seconds_since(t0);
        if (!r || mesh.face_count() != faces) {
            std::fprintf(stderr, "read_mesh failed\n");
            return 1;
        }
        std::printf("soup %.4f mesh %.4f faces %zu\n", soup_s, mesh_s, faces);
        return 0;
    }
    std::fprintf(stderr, "usage: formats_bench --generate DIR | --read FILE\n");
    return 2;
}
