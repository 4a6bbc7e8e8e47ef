// apps/hmira/cli.cpp
// Shared plumbing of the subcommands (see cli.hpp).
#include "cli.hpp"

#include <hmira/algorithms/repair/repair_polygon_soup.hpp>

#include <unistd.h>

#include <charconv>
#include <cstdio>
#include <iostream>
#include <limits>

namespace hmira_cli {

std::vector<command>& commands() {
    static std::vector<command> all;
    return all;
}

bool register_command(command c) {
    commands().push_back(std::move(c));
    return true;
}

int report(int code, const std::string& message) {
    if (!message.empty()) std::cerr << "hmira: error: " << message << '\n';
    return code;
}

int exit_code_for(const hmira::error& e) {
    switch (e.code) {
        case hmira::errc::io_error: return io_failure;
        case hmira::errc::unsupported: return e.message.find("unknown mesh format") != std::string::npos ? usage : invalid_input;
        case hmira::errc::invalid_argument: return usage;
        default: return invalid_input;
    }
}

void say(const common_options& o, const std::string& line) {
    if (!o.quiet) std::cout << line << '\n';
}

std::optional<loaded_mesh> load(const std::string& path, const common_options& o, int& code) {
    loaded_mesh out;
    progress_bar bar("reading " + path, o);
    auto r = hmira::io::read_mesh(out.mesh, path, {.progress = bar.callback()});
    if (!r) {
        code = report(exit_code_for(r.error()), r.error().message);
        return std::nullopt;
    }
    out.report = std::move(*r);
    code = ok;
    return out;
}

int save(const hmira::face_vertex_mesh& mesh, const std::string& path, const hmira::io::write_options& options, const common_options&) {
    auto w = hmira::io::write_mesh(mesh, path, options);
    if (!w) return report(exit_code_for(w.error()), w.error().message);
    return ok;
}

std::optional<hmira::halfedge_mesh> to_halfedge(const hmira::face_vertex_mesh& mesh, const std::string& path, int& code, std::string* repairs) {
    // Dense file order in, dense file order out: from_polygons numbers vertices and faces as given.
    std::vector<hmira::vec3<double>> points;
    std::vector<std::uint64_t> offsets{0};
    std::vector<std::uint32_t> corners;
    std::vector<std::uint32_t> dense(mesh.vertex_index_bound(), 0);
    points.reserve(mesh.vertex_count());
    for (auto v : mesh.vertices()) {
        dense[v.index] = static_cast<std::uint32_t>(points.size());
        points.push_back(mesh.position(v));
    }
    for (auto f : mesh.faces()) {
        for (auto v : mesh.face_vertices(f)) corners.push_back(dense[v.index]);
        offsets.push_back(corners.size());
    }
    // Repair what a halfedge mesh cannot hold; the file's vertices keep their numbers.
    auto repaired = hmira::repair_polygon_soup(points.size(), offsets, corners);
    // The face-vertex mesh refused degenerate faces when the file was read, so no face is dropped
    // here and face i stays the file's face i (what --face N names).
    if (!repaired || repaired->face_count() != mesh.face_count() || repaired->corners.size() > std::size_t{0xffffffffu}) {
        code = report(invalid_input, path + ": cannot edit this mesh: " + (repaired ? "a degenerate face or too many corners" : repaired.error().message));
        return std::nullopt;
    }
    for (auto v : repaired->copied_from) points.push_back(points[v]);
    const std::vector<std::uint32_t> offsets32(repaired->face_offsets.begin(), repaired->face_offsets.end());
    auto built = hmira::halfedge_mesh::from_polygons(points, offsets32, repaired->corners);
    if (!built) {
        std::string why = built.error().message;
        if (why.rfind("from_polygons: ", 0) == 0) why = why.substr(15);
        code = report(invalid_input, path + ": cannot edit this mesh: " + why);
        return std::nullopt;
    }
    if (!repaired->copied_from.empty()) {
        auto source = built->add_vertex_property<std::uint32_t>("v:file_vertex");
        for (auto v : built->vertices()) source[v] = static_cast<std::uint32_t>(repaired->source_vertex(v.index));
    }
    if (repairs) *repairs = repaired->report.clean() ? "" : repaired->report.summary();
    code = ok;
    return std::move(*built);
}

std::vector<hmira::vertex_handle> file_vertices(const hmira::halfedge_mesh& mesh, std::span<const std::size_t> indices) {
    std::vector<hmira::vertex_handle> out;
    for (auto i : indices) out.emplace_back(i);
    if (auto source = mesh.get_vertex_property<std::uint32_t>("v:file_vertex")) {
        std::vector<char> wanted(mesh.vertex_index_bound(), 0);
        for (auto i : indices) wanted[i] = 1;
        for (auto v : mesh.vertices())  // copies: a different index, standing for a wanted one
            if (const auto from = (*source)[v]; from != v.index && from < wanted.size() && wanted[from]) out.push_back(v);
    }
    return out;
}

hmira::face_vertex_mesh to_face_vertex(const hmira::halfedge_mesh& mesh, std::span<const std::pair<hmira::vertex_handle, hmira::vertex_handle>> exchange) {
    hmira::face_vertex_mesh out;
    out.reserve(mesh.vertex_count(), mesh.face_count(), 4 * mesh.face_count());
    std::vector<hmira::vertex_handle> order;  // output slot -> mesh vertex
    std::vector<std::size_t> slot(mesh.vertex_index_bound());
    for (auto v : mesh.vertices()) {
        slot[v.index] = order.size();
        order.push_back(v);
    }
    for (const auto& [a, b] : exchange) {
        std::swap(order[slot[a.index]], order[slot[b.index]]);
        std::swap(slot[a.index], slot[b.index]);
    }
    std::vector<hmira::vertex_handle> map(mesh.vertex_index_bound());
    for (auto v : order) map[v.index] = out.add_vertex(mesh.position(v));
    std::vector<hmira::vertex_handle> loop;
    for (auto f : mesh.faces()) {
        loop.clear();
        for (auto v : mesh.face_vertices(f)) loop.push_back(map[v.index]);
        out.add_face(std::span<const hmira::vertex_handle>(loop)).value();  // a valid halfedge face is a valid polygon
    }
    return out;
}

mesh_counts counts_of(const hmira::halfedge_mesh& mesh) { return {mesh.vertex_count(), mesh.edge_count(), mesh.face_count()}; }

int run_edit(const loaded_mesh& loaded, const std::string& input, const std::string& output, const std::string& bar_label,
             const common_options& o, const std::function<std::optional<edit_outcome>(hmira::halfedge_mesh&, int& code)>& edit) {
    int code = ok;
    mesh_counts before, after;
    hmira::face_vertex_mesh edited;
    std::string what;
    {
        auto bar = stage_bar(bar_label, o, loaded.mesh.face_count());
        bar.update(0, 3);
        std::string repairs;
        auto mesh = to_halfedge(loaded.mesh, input, code, &repairs);
        if (!mesh) return code;
        if (!repairs.empty()) say(o, input + ": repaired for editing: " + repairs);
        before = counts_of(*mesh);
        bar.update(1, 3);
        auto outcome = edit(*mesh, code);
        if (!outcome) return code;
        after = counts_of(*mesh);
        bar.update(2, 3);
        edited = to_face_vertex(*mesh, outcome->exchange);
        what = std::move(outcome->what);
    }
    if (int c = save(edited, output, {}, o); c != ok) return c;
    say(o, input + ": " + what + ": " + describe_change(before, after) + " (" + output + ")");
    return ok;
}

std::string describe_change(const mesh_counts& before, const mesh_counts& after) {
    auto one = [](const char* what, std::size_t a, std::size_t b) { return std::string(what) + " " + std::to_string(a) + " -> " + std::to_string(b); };
    return one("V", before.vertices, after.vertices) + ", " + one("E", before.edges, after.edges) + ", " + one("F", before.faces, after.faces);
}

std::optional<std::array<double, 3>> parse_triple(const std::string& text, bool one_for_all) {
    std::array<double, 3> v{};
    const char* p = text.data();
    const char* end = p + text.size();
    int n = 0;
    while (n < 3) {
        while (p < end && *p == ' ') ++p;
        if (p < end && *p == '+') ++p;
        auto r = std::from_chars(p, end, v[static_cast<std::size_t>(n)]);
        if (r.ec != std::errc() || r.ptr == p) return std::nullopt;
        p = r.ptr;
        ++n;
        while (p < end && *p == ' ') ++p;
        if (p == end) break;
        if (*p != ',') return std::nullopt;
        ++p;
    }
    if (p != end) return std::nullopt;
    if (n == 1 && one_for_all) return std::array<double, 3>{v[0], v[0], v[0]};
    if (n != 3) return std::nullopt;
    return v;
}

bool check_indices(const std::vector<std::size_t>& indices, std::size_t count, const std::string& what, const std::string& option,
                   const std::string& path, int& code) {
    for (auto i : indices)
        if (i >= count) {
            const std::string range = count == 0 ? "none" : "0.." + std::to_string(count - 1);
            code = report(usage, option + ": " + what + " " + std::to_string(i) + " does not exist: " + path + " has " + count_of(count, what, what == "vertex" ? "vertices" : what + "s") + " (" +
                                     range + ", in file order)");
            return false;
        }
    code = ok;
    return true;
}

std::string count_of(std::size_t n, const std::string& one, const std::string& many) { return std::to_string(n) + " " + (n == 1 ? one : many); }

progress_bar stage_bar(std::string label, const common_options& o, std::uint64_t size, std::uint64_t min_size) {
    // update(step, steps) with few steps: the bar's own size gate is replaced by the job's.
    return progress_bar(std::move(label), o, size >= min_size ? 1 : std::numeric_limits<std::uint64_t>::max());
}

progress_bar::progress_bar(std::string label, const common_options& o, std::uint64_t min_total)
    : label_(std::move(label)), enabled_(!o.quiet && ::isatty(2)), min_total_(min_total) {}

progress_bar::~progress_bar() {
    if (drawn_) std::fprintf(stderr, "\r\033[K");
}

void progress_bar::update(std::uint64_t done, std::uint64_t total) {
    if (!enabled_ || total < min_total_ || total == 0) return;
    const int width = 30;
    const int filled = static_cast<int>(width * done / total);
    std::fprintf(stderr, "\r%s [%.*s%*s] %3d%%", label_.c_str(), filled, "##############################", width - filled, "",
                 static_cast<int>(100 * done / total));
    std::fflush(stderr);
    drawn_ = true;
}

hmira::io::progress_callback progress_bar::callback() {
    if (!enabled_) return {};
    return [this](std::uint64_t d, std::uint64_t t) { update(d, t); };
}

}  // namespace hmira_cli
