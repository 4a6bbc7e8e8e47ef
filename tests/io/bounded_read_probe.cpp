// Reads one file the way the CLI would and prints the outcome, for bounded_read_rss.sh, which
// measures its peak memory. Usage: bounded_read_probe mesh|inr FILE MAX_INPUT_BYTES
// Exit 0 when the file was refused (what the hostile inputs must give), 1 when accepted,
// 2 on usage errors.
#include <cstdio>
#include <cstdlib>
#include <string>

#include <hmira/io/mesh_io.hpp>
#include <hmira/io/volume/inr.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: bounded_read_probe mesh|inr FILE MAX_INPUT_BYTES\n");
        return 2;
    }
    const std::string kind = argv[1];
    const std::uint64_t cap = std::strtoull(argv[3], nullptr, 10);
    std::string error;
    if (kind == "mesh") {
        hmira::face_vertex_mesh m;
        auto r = hmira::io::read_mesh(m, argv[2], {.max_input_bytes = cap});
        if (!r) error = r.error().message;
    } else if (kind == "inr") {
        auto g = hmira::io::read_inr(argv[2], {.max_input_bytes = cap});
        if (!g) error = g.error().message;
    } else {
        return 2;
    }
    if (error.empty()) {
        std::printf("accepted\n");
        return 1;
    }
    std::printf("refused: %s\n", error.c_str());
    return 0;
}
