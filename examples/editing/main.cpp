// Applies hmira's editing functions to generated solids and writes each result as an OBJ file
// that any viewer opens: truncated cube, chamfered cube, rounded cube edge, rounded cube, extruded cube face,
// extruded region of a box, and a pocket. Usage: editing_example [output directory]
// g++ 12 at -O3 reports a false -Wrestrict inside std::string concatenation inlined from the
// Euler operators' error messages (GCC bug 105329); not a real overlap.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wrestrict"
#endif

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <hmira/algorithms/editing/editing.hpp>
#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/validation/validate.hpp>
#include <hmira/io/obj.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

namespace {

using mesh = hmira::halfedge_mesh;
using T = hmira::mesh_traits<mesh>;

bool save(const mesh& m, const std::filesystem::path& dir, const std::string& name) {
    const auto problems = hmira::validate(m);
    if (!problems.empty()) {
        std::fprintf(stderr, "%s: invalid mesh: %s\n", name.c_str(), problems.front().message.c_str());
        return false;
    }
    const auto path = dir / (name + ".obj");
    if (auto w = hmira::io::write_obj(m, path); !w) {
        std::fprintf(stderr, "%s: %s\n", name.c_str(), w.error().message.c_str());
        return false;
    }
    std::printf("%-18s V %5zu  E %5zu  F %5zu  -> %s\n", name.c_str(), T::vertex_count(m), T::edge_count(m),
                T::face_count(m), path.string().c_str());
    return true;
}

mesh cube() {
    mesh m;
    (void)hmira::generate_cube(m).value();
    return m;
}

}  // namespace

int main(int argc, char** argv) {
    const std::filesystem::path dir = argc > 1 ? argv[1] : ".";
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    bool ok = true;

    {  // Every corner cut at a third: 8 triangles and 6 octagons.
        auto m = cube();
        ok &= hmira::truncate_all(m, {.fraction = 1.0 / 3}).has_value() && save(m, dir, "truncated_cube");
    }
    {  // Every edge chamfered.
        auto m = cube();
        std::vector<T::edge_handle> es;
        for (auto e : T::edges(m)) es.push_back(e);
        ok &= hmira::bevel(m, es, {.width = 0.25}).has_value() && save(m, dir, "chamfered_cube");
    }
    {  // One edge rounded with 6 segments.
        auto m = cube();
        ok &= hmira::bevel(m, *T::edges(m).begin(), {.width = 0.5, .segments = 6}).has_value() &&
              save(m, dir, "rounded_edge_cube");
    }
    {  // Every edge rounded with 4 segments: a rounded cube with spherical corner patches.
        auto m = cube();
        std::vector<T::edge_handle> es;
        for (auto e : T::edges(m)) es.push_back(e);
        ok &= hmira::bevel(m, es, {.width = 0.4, .segments = 4}).has_value() && save(m, dir, "rounded_cube");
    }
    {  // One face pulled out.
        auto m = cube();
        auto f = *T::faces(m).begin();
        auto r = hmira::extrude(m, f, {.distance = 1.0});
        ok &= r.has_value() && save(m, dir, "extruded_cube");
    }
    {  // A pocket: chamfer the rim of one face, then push the face into the solid. (Pushing a
        // whole cube face in would put the pocket walls in the planes of the side faces.)
        auto m = cube();
        const auto f = *T::faces(m).begin();
        std::vector<T::edge_handle> rim;
        for (auto h = T::face_halfedge(m, f); rim.empty() || h != T::face_halfedge(m, f); h = T::next(m, h))
            rim.push_back(T::edge(m, h));
        ok &= hmira::bevel(m, rim, {.width = 0.2}).has_value() &&
              hmira::extrude(m, f, {.distance = -0.5}).has_value() && save(m, dir, "pocket_cube");
    }
    {  // Two faces extruded individually, each along its own normal.
        auto m = cube();
        std::vector<T::face_handle> fs;
        for (auto f : T::faces(m)) fs.push_back(f);
        fs.resize(2);
        ok &= hmira::extrude(m, fs, {.distance = 0.5, .mode = hmira::extrude_mode::individual}).has_value() &&
              save(m, dir, "individual_extrude");
    }
    return ok ? 0 : 1;
}
