// apps/hmira/cmd_view.cpp
// `hmira view`: writes one self-contained HTML page that shows a mesh (or two side by side,
// `--compare`) in any browser, offline: the three.js viewer is compiled into this binary
// (viewer/viewer.cmake) and the mesh is embedded as base64 binary buffers (viewer/viewer_page.hpp).
#include <cstdio>
#include <filesystem>
#include <string_view>

#include <hmira/algorithms/topology/mesh_topology.hpp>
#include <hmira/io/detail/atomic_write.hpp>

#include <viewer_bundle.hpp>
#include <viewer_page.hpp>

#include "cli.hpp"

namespace {

using namespace hmira_cli;

struct view_args {
    std::string input, output, compare;
};

/// The loaded mesh as the plain arrays viewer_page.hpp takes (vertices renumbered densely in file order).
struct plain_mesh {
    std::string path;
    hmira::topology_summary topology;
    std::vector<double> points;
    std::vector<std::uint32_t> offsets{0}, corners;
    std::vector<float> normals;
    std::vector<std::uint8_t> colors;
};

std::optional<plain_mesh> plain(const std::string& path, const common_options& o, int& code) {
    auto loaded = load(path, o, code);
    if (!loaded) return std::nullopt;
    const auto& m = loaded->mesh;
    if (m.vertex_count() == 0) {
        code = report(invalid_input, path + ": no vertices to show");
        return std::nullopt;
    }
    if (m.vertex_count() > std::numeric_limits<std::uint32_t>::max() / 2) {
        code = report(invalid_input, path + ": " + std::to_string(m.vertex_count()) +
                                         " vertices are more than a page can index (32-bit)");
        return std::nullopt;
    }
    plain_mesh out;
    out.path = path;
    out.topology = hmira::mesh_topology(m);
    std::vector<std::uint32_t> dense(m.vertex_index_bound(), 0);
    out.points.reserve(3 * m.vertex_count());
    for (auto v : m.vertices()) {
        dense[v.index] = static_cast<std::uint32_t>(out.points.size() / 3);
        const auto p = m.position(v);
        out.points.insert(out.points.end(), {p.x, p.y, p.z});
    }
    for (auto f : m.faces()) {
        for (auto v : m.face_vertices(f)) out.corners.push_back(dense[v.index]);
        out.offsets.push_back(static_cast<std::uint32_t>(out.corners.size()));
    }
    // Attributes come one per file vertex; any other count cannot be matched up, so it is left out.
    const auto& attr = loaded->report.attributes;
    if (attr.normals.size() == m.vertex_count())
        for (const auto& n : attr.normals) out.normals.insert(out.normals.end(), {n.x, n.y, n.z});
    if (attr.colors.size() == m.vertex_count())
        for (const auto& c : attr.colors) out.colors.insert(out.colors.end(), c.begin(), c.end());
    return out;
}

hmira_viewer::page_mesh page_mesh_of(const plain_mesh& m, std::array<double, 3> origin) {
    const auto& t = m.topology;
    return hmira_viewer::make_page_mesh(
        std::filesystem::path(m.path).filename().string(),
        {.vertices = t.vertices,
         .edges = t.edges,
         .faces = t.faces,
         .genus = t.genus,
         .closed = t.faces > 0 && t.closed()},
        {.points = m.points, .offsets = m.offsets, .corners = m.corners, .normals = m.normals, .colors = m.colors},
        origin);
}

std::string size_text(std::uintmax_t bytes) {
    char b[32];
    if (bytes >= (1u << 20))
        std::snprintf(b, sizeof b, "%.1f MB", static_cast<double>(bytes) / (1 << 20));
    else
        std::snprintf(b, sizeof b, "%.0f KB", static_cast<double>(bytes) / 1024);
    return b;
}

/// True when `path` ends in .html or .htm (any case): the only files `view` writes, so a mesh
/// named as the output by mistake is never replaced by a page.
bool is_page_name(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (auto& c : ext) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    return ext == ".html" || ext == ".htm";
}

int run_view(const view_args& a, const common_options& o) {
    const std::string_view viewer_bundle = hmira_viewer::bundle();
    // A build condition, not a fault inside hmira: the build had no bundle to compile in.
    if (viewer_bundle.empty())
        return report(usage,
                      "this hmira was built without the viewer bundle (viewer/dist/hmira-viewer.js): restore it or run "
                      "viewer/build.sh (needs node and npm), then re-run cmake and rebuild");
    const std::string output =
        a.output.empty() ? std::filesystem::path(a.input).replace_extension(".html").string() : a.output;
    // Checked before anything is read, so a refused output is never written.
    if (!is_page_name(output))
        return report(usage, "output " + output +
                                 " is not an .html or .htm file (view writes an HTML page; name the page explicitly)");
    for (const auto* path : {&a.input, &a.compare})
        if (!path->empty() && same_file(output, *path))
            return report(usage, "output " + output + " is the input " + *path +
                                     " (view writes an HTML page; choose another name)");
    int code = ok;
    std::vector<plain_mesh> meshes;
    for (const auto* path : {&a.input, &a.compare}) {
        if (path->empty()) continue;
        auto m = plain(*path, o, code);
        if (!m) return code;
        meshes.push_back(std::move(*m));
    }
    // Both halves of a comparison share one origin, so a mesh that moved shows as moved.
    const auto origin = hmira_viewer::bounding_box_centre(meshes.front().points);
    std::vector<hmira_viewer::page_mesh> pages;
    for (const auto& m : meshes) {
        pages.push_back(page_mesh_of(m, origin));
        // The page stores float positions: a vertex that far from the centre would be infinite.
        if (const auto v = hmira_viewer::first_vertex_beyond_float_range(pages.back()); v < m.points.size() / 3)
            return report(invalid_input, m.path + ": vertex " + std::to_string(v) +
                                             " (file order) is too far from the page's centre for "
                                             "its float positions (beyond 3.4e38); nothing is written");
    }
    meshes.clear();
    auto written = hmira::io::detail::write_file_atomically(output, [&](std::ostream& os) {
        hmira_viewer::write_page(os, pages, viewer_bundle);
        return static_cast<bool>(os);
    });
    if (!written) return report(exit_code_for(written.error()), written.error().message);
    std::error_code ec;
    const auto bytes = std::filesystem::file_size(output, ec);
    std::string what;
    for (const auto& p : pages)
        what += (what.empty() ? "" : " | ") + p.name + ": V " + std::to_string(p.info.vertices) + ", F " +
                std::to_string(p.info.faces);
    say(o, what + " -> " + output + (ec ? "" : " (" + size_text(bytes) + ")"));
    return ok;
}

const bool registered = register_command(
    {"view", "Write a self-contained HTML page that shows a mesh (or two side by side) in any browser, offline",
     "hmira view cube_rounded.obj                 # writes cube_rounded.html\n"
     "  hmira view cube.obj --compare cube_rounded.obj before_after.html",
     90, [](CLI::App& sub) {
         auto a = std::make_shared<view_args>();
         sub.add_option("input", a->input, "mesh file (.obj .off .ply .stl)")->required();
         sub.add_option("output", a->output, "page to write (default: input with .html)");
         sub.add_option("--compare", a->compare, "a second mesh, shown beside the first under the same camera")
             ->type_name("MESH");
         return [a](const common_options& o) { return run_view(*a, o); };
     }});

}  // namespace
