// apps/hmira/cmd_convert.cpp
// `hmira convert`: reads a mesh in one format and writes it in another (format by extension),
// keeping polygons, normals and colours where the output format can hold them.
#include "cli.hpp"

namespace {

using namespace hmira_cli;

struct convert_args {
    std::string input, output;
    bool ascii = false, big_endian = false, float32 = false, no_attributes = false;
};

int run_convert(const convert_args& a, const common_options& o) {
    int code = ok;
    auto loaded = load(a.input, o, code);
    if (!loaded) return code;
    hmira::io::write_options w;
    w.ply = a.ascii        ? hmira::io::ply_encoding::ascii
            : a.big_endian ? hmira::io::ply_encoding::binary_big_endian
                           : hmira::io::ply_encoding::binary_little_endian;
    w.stl = a.ascii ? hmira::io::stl_encoding::ascii : hmira::io::stl_encoding::binary;
    w.ply_coordinates = a.float32 ? hmira::io::ply_scalar::float32 : hmira::io::ply_scalar::mesh;
    w.write_attributes = !a.no_attributes;
    if (int c = save(loaded->mesh, a.output, w, o); c != ok) return c;
    say(o, a.input + " -> " + a.output + ": " + std::to_string(loaded->mesh.vertex_count()) + " vertices, " +
               std::to_string(loaded->mesh.face_count()) + " faces");
    return ok;
}

const bool registered = register_command(
    {"convert", "Convert a mesh between OBJ, OFF, PLY, STL and glTF (.glb, .gltf) (format from the extensions)",
     "hmira convert bunny.off bunny.ply --float", 30, [](CLI::App& sub) {
         auto a = std::make_shared<convert_args>();
         sub.add_option("input", a->input, "mesh file to read")->required();
         sub.add_option("output", a->output, "mesh file to write (replaced atomically)")->required();
         sub.add_flag("--ascii", a->ascii, "PLY/STL: write text instead of binary");
         sub.add_flag("--big-endian", a->big_endian, "PLY: binary big endian instead of little endian");
         sub.add_flag("--float", a->float32, "PLY: store coordinates as 32-bit floats (default: 64-bit)");
         sub.add_flag("--no-attributes", a->no_attributes, "drop per-vertex normals and colours");
         return [a](const common_options& o) { return run_convert(*a, o); };
     }});

}  // namespace
