// hmira-demo: the README's main job. Runs the implemented algorithms on built-in data (and on
// real meshes from Debian's libcgal-demo when given), prints a readable summary and writes
// every mesh it makes as OBJ, so the results can be opened in any viewer.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <hmira/hmira.hpp>
#include <hmira/io/obj.hpp>
#include <hmira/io/off.hpp>

namespace fs = std::filesystem;
using namespace hmira;

namespace {

int failures = 0;

void check(bool ok, const std::string& what) {
    if (!ok) {
        ++failures;
        std::printf("  !! %s\n", what.c_str());
    }
}

template <class M>
void row(const char* name, const M& mesh) {
    const auto t = mesh_topology(mesh);
    const auto problems = validate(mesh);
    std::printf("  %-22s V=%-7zu E=%-7zu F=%-7zu chi=%-4lld genus=%-2lld components=%-3zu boundary loops=%-3zu %s\n",
                name, t.vertices, t.edges, t.faces, t.euler_characteristic, t.genus, t.components, t.boundary_loops,
                problems.empty()
                    ? "valid"
                    : (std::to_string(problems.size()) + " problem(s): " + problems.front().message).c_str());
}

template <class M>
void save(const M& mesh, const fs::path& path) {
    auto r = io::write_obj(mesh, path);
    check(static_cast<bool>(r), r ? "" : r.error().message);
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Reads the command line into `out` and `data`; an exit code when the run ends there (--help,
/// an unknown argument).
std::optional<int> parse_arguments(int argc, char** argv, fs::path& out, fs::path& data) {
    for (int i = 1; i < argc; ++i) {
        const std::string_view a = argv[i];
        if ((a == "--out" || a == "-o") && i + 1 < argc)
            out = argv[++i];
        else if (a == "--data" && i + 1 < argc)
            data = argv[++i];
        else if (a == "--help" || a == "-h") {
            std::puts(
                "usage: hmira-demo [--out DIR] [--data DIR]\n"
                "  Runs hmira's algorithms on built-in solids (and on DIR/meshes/*.off from Debian's\n"
                "  libcgal-demo when --data is given), prints a summary and writes OBJ files to --out.\n"
                "  example: hmira-demo --out demo-output --data build/test-data");
            return 0;
        } else {
            std::fprintf(stderr, "hmira-demo: unknown argument '%s' (try --help)\n", argv[i]);
            return 2;
        }
    }
    return std::nullopt;
}

void generated_solids(const fs::path& out) {
    std::puts("1. Generated solids on the half-edge mesh, checked by validate() and topology:");
    struct solid {
        const char* name;
        result<generated_elements<halfedge_mesh>> (*make)(halfedge_mesh&, const solid_options&);
    };
    const solid solids[] = {{"tetrahedron", generate_tetrahedron<halfedge_mesh>},
                            {"cube", generate_cube<halfedge_mesh>},
                            {"octahedron", generate_octahedron<halfedge_mesh>},
                            {"dodecahedron", generate_dodecahedron<halfedge_mesh>},
                            {"icosahedron", generate_icosahedron<halfedge_mesh>}};
    for (const auto& s : solids) {
        halfedge_mesh m;
        check(static_cast<bool>(s.make(m, {})), std::string("generate ") + s.name);
        row(s.name, m);
        check(mesh_topology(m).euler_characteristic == 2, std::string(s.name) + ": V - E + F must be 2");
        save(m, out / (std::string(s.name) + ".obj"));
    }
    halfedge_mesh torus;
    check(static_cast<bool>(generate_torus(torus, {.major_radius = 1, .minor_radius = 0.3, .rings = 48, .sides = 24})),
          "generate torus");
    row("torus 48x24", torus);
    check(mesh_topology(torus).genus == 1, "torus genus must be 1");
    save(torus, out / "torus.obj");
}

void face_vertex_model(const fs::path& out) {
    std::puts("\n2. The same algorithms on the face-vertex mesh (no adjacency stored):");
    face_vertex_mesh m;
    check(static_cast<bool>(generate_dodecahedron(m)), "generate dodecahedron (face-vertex)");
    row("dodecahedron", m);
    face_vertex_mesh g;
    check(static_cast<bool>(generate_grid(g, {.columns = 20, .rows = 10, .triangles = true})), "generate grid");
    row("grid 20x10 (open)", g);
    save(g, out / "grid.obj");
}

/// The signed volume a closed mesh encloses (negative when its faces wind inwards).
template <class M>
double signed_volume(const M& mesh) {
    using T = default_traits<M>;
    double v = 0;
    for (auto f : T::faces(mesh)) {
        std::vector<vec3<double>> p;
        for (auto w : T::face_vertices(mesh, f)) p.push_back(T::position(mesh, w));
        v += dot(p[0], cross(p[1], p[2])) / 6;
    }
    return v;
}

/// Flips an icosahedron of model M twice, printing the signed volume after each flip.
template <class M>
void flip_twice(const fs::path& out, const char* name, bool keep) {
    M mesh;
    check(static_cast<bool>(generate_icosahedron(mesh)), "generate");
    const double v0 = signed_volume(mesh);
    flip_normals(mesh);
    const double v1 = signed_volume(mesh);
    flip_normals(mesh);
    const double v2 = signed_volume(mesh);
    std::printf("  %-22s volume %+.4f -> %+.4f -> %+.4f  %s\n", name, v0, v1, v2,
                validate(mesh).empty() ? "valid" : "INVALID");
    check(v1 < 0 && v0 > 0 && std::abs(v2 - v0) < 1e-12, std::string(name) + ": flip must negate the volume");
    if (keep) save(mesh, out / "icosahedron-flipped-twice.obj");
}

void flipping(const fs::path& out) {
    std::puts("\n3. flip_normals really flips (signed volume changes sign, twice restores it):");
    flip_twice<halfedge_mesh>(out, "half-edge icosahedron", true);
    flip_twice<face_vertex_mesh>(out, "face-vertex icosahedron", false);
}

void components(const fs::path& out) {
    std::puts("\n4. Connected components of a disjoint union (union-find):");
    halfedge_mesh m;
    for (int i = 0; i < 4; ++i)
        check(static_cast<bool>(generate_octahedron(m, {.center = {3.0 * i, 0, 0}})), "generate");
    m.add_vertex({-3, 0, 0});
    const auto c = connected_components(m);
    std::printf("  4 octahedra + 1 isolated vertex -> %zu components\n", c.count);
    check(c.count == 5, "components must be 5");
    save(m, out / "octahedra.obj");
}

void real_meshes(const fs::path& out, const fs::path& data) {
    std::puts("\n5. Real meshes from Debian's libcgal-demo, read as OFF into both models:");
    for (const char* name :
         {"elephant.off", "fandisk.off", "armadillo.off", "cube-ouvert.off", "double-torus-example.off"}) {
        const fs::path p = data / "meshes" / name;
        if (!fs::exists(p)) {
            std::printf("  %-22s (not found in %s)\n", name, (data / "meshes").string().c_str());
            continue;
        }
        halfedge_mesh he;
        const auto t0 = std::chrono::steady_clock::now();
        auto r = io::read_off(he, p);
        const double t_read = seconds_since(t0);
        if (!r) {
            std::printf("  %-22s read error: %s\n", name, r.error().message.c_str());
            face_vertex_mesh fv;
            auto r2 = io::read_off(fv, p);
            if (r2) row((std::string(name) + " (face-vertex)").c_str(), fv);
            continue;
        }
        row(name, he);
        std::printf("  %-22s read in %.1f ms\n", "", t_read * 1e3);
        save(he, out / (fs::path(name).stem().string() + ".obj"));
    }
}

}  // namespace

int main(int argc, char** argv) {
    fs::path out = "demo-output";
    fs::path data;
    if (const auto code = parse_arguments(argc, argv, out, data)) return *code;
    std::error_code ec;
    fs::create_directories(out, ec);
    if (ec) {
        std::fprintf(stderr, "hmira-demo: cannot create %s: %s\n", out.string().c_str(), ec.message().c_str());
        return 3;
    }

    std::puts("hmira demo: one generic algorithm, several mesh representations\n");
    generated_solids(out);
    face_vertex_model(out);
    flipping(out);
    components(out);
    if (!data.empty()) real_meshes(out, data);

    std::printf("\nwrote OBJ files to %s\n", out.string().c_str());
    if (failures) {
        std::printf("demo: %d check(s) FAILED\n", failures);
        return 1;
    }
    std::puts("demo: all checks passed");
    return 0;
}
