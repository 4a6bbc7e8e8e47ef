// apps/hmira/cli.cpp
// Shared plumbing of the subcommands (see cli.hpp).
#include "cli.hpp"

#include <hmira/algorithms/repair/repair_polygon_soup.hpp>

#include <sys/resource.h>
#include <unistd.h>

#include <csignal>
#include <cstring>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>

namespace hmira_cli {

namespace {

/// A number from the first line of a file (cgroup's memory.max: a number or "max").
std::optional<std::uint64_t> number_in(const char* path) {
    std::ifstream in(path);
    std::uint64_t v = 0;
    if (!(in >> v)) return std::nullopt;
    return v;
}

/// A "Key: N kB" line of a /proc file, in bytes.
std::optional<std::uint64_t> proc_kib(const char* path, const std::string& key) {
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line))
        if (line.rfind(key + ":", 0) == 0) {
            std::istringstream s(line.substr(key.size() + 1));
            std::uint64_t kib = 0;
            if (s >> kib) return kib * 1024;
        }
    return std::nullopt;
}

}  // namespace

std::optional<std::uint64_t> free_memory() {
    if (const char* s = std::getenv("HMIRA_TEST_MEMAVAILABLE")) return std::strtoull(s, nullptr, 10);
    std::optional<std::uint64_t> free = proc_kib("/proc/meminfo", "MemAvailable");
    if (!free) {
        const long pages = sysconf(_SC_AVPHYS_PAGES), page = sysconf(_SC_PAGESIZE);
        if (pages > 0 && page > 0) free = std::uint64_t(pages) * std::uint64_t(page);
    }
    auto lower = [&](std::uint64_t v) { free = free ? std::min(*free, v) : v; };
    rlimit as{};
    if (::getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) {
        const std::uint64_t used = proc_kib("/proc/self/status", "VmSize").value_or(0);
        lower(as.rlim_cur > used ? as.rlim_cur - used : 0);
    }
    if (auto max = number_in("/sys/fs/cgroup/memory.max")) {
        const std::uint64_t used = number_in("/sys/fs/cgroup/memory.current").value_or(0);
        lower(*max > used ? *max - used : 0);
    }
    return free;
}

std::vector<command>& commands() {
    static std::vector<command> all;
    return all;
}

bool register_command(command c) {
    commands().push_back(std::move(c));
    return true;
}

std::string printable(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '\n')
            out += "\\n";
        else if (c == '\r')
            out += "\\r";
        else if (c == '\t')
            out += "\\t";
        else if (u < 0x20 || u == 0x7f) {
            char hex[8];
            std::snprintf(hex, sizeof hex, "\\x%02x", u);
            out += hex;
        } else {
            out += c;
        }
    }
    return out;
}

int report(int code, const std::string& message) {
    if (!message.empty()) std::cerr << "hmira: error: " << printable(message) << '\n';
    return code;
}

int exit_code_for(const hmira::error& e) {
    if (e.code == hmira::errc::invalid_argument) return usage;
    return input_exit_code(e);
}

int input_exit_code(const hmira::error& e) {
    switch (e.code) {
        case hmira::errc::io_error: return io_failure;
        case hmira::errc::unknown_format: return usage;
        default: return invalid_input;
    }
}

std::string number_text(double x) {
    char b[32];
    std::snprintf(b, sizeof b, "%g", x);
    return b;
}

CLI::Validator finite_number(std::string rule, std::function<bool(double)> holds) {
    const std::string wanted = "a finite number" + (rule.empty() ? std::string() : " " + rule);
    return CLI::Validator(
        [wanted, holds](std::string& text) -> std::string {
            const std::string shown = "'" + printable(text.substr(0, 40)) + (text.size() > 40 ? "...'" : "'");
            errno = 0;
            char* end = nullptr;
            const double x = std::strtod(text.c_str(), &end);
            if (text.empty() || end != text.c_str() + text.size()) return "expected " + wanted + ", got " + shown;
            if (!std::isfinite(x))
                return "expected " + wanted + ", got " + shown + " (NaN and infinity are not allowed)";
            if (holds && !holds(x)) return "expected " + wanted + ", got " + number_text(x);
            return {};
        },
        rule.empty() ? "FINITE" : "FINITE " + rule);
}

CLI::Validator whole_number(std::uint64_t lo, std::uint64_t hi) {
    const bool unbounded = hi == std::numeric_limits<std::uint64_t>::max();
    const std::string bounds =
        unbounded ? ">= " + std::to_string(lo) : "in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    const std::string wanted = "a whole number " + bounds;
    return CLI::Validator(
        [wanted, lo, hi](std::string& text) -> std::string {
            const std::string shown = "'" + printable(text.substr(0, 40)) + (text.size() > 40 ? "...'" : "'");
            std::uint64_t x = 0;
            const char* b = text.data();
            const char* e = b + text.size();
            if (b != e && *b == '+') ++b;
            const auto r = std::from_chars(b, e, x);
            if (r.ec == std::errc::result_out_of_range) return "expected " + wanted + ", got " + shown;
            if (r.ec != std::errc() || r.ptr != e || b == e) return "expected " + wanted + ", got " + shown;
            if (x < lo || x > hi) return "expected " + wanted + ", got " + std::to_string(x);
            return {};
        },
        "INT " + bounds);
}

CLI::Validator byte_count() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            const std::string wanted =
                "expected a size in bytes, optionally with K, M, G or T (KiB, MiB, GiB, TiB), got '" +
                printable(text.substr(0, 40)) + "'";
            std::uint64_t n = 0;
            const char* b = text.data();
            const char* e = b + text.size();
            const auto r = std::from_chars(b, e, n);
            if (r.ec != std::errc() || r.ptr == b) return wanted;
            std::string unit(r.ptr, e);
            if (unit.size() == 3 && unit.substr(1) == "iB") unit.resize(1);
            int shift = 0;
            if (unit == "K")
                shift = 10;
            else if (unit == "M")
                shift = 20;
            else if (unit == "G")
                shift = 30;
            else if (unit == "T")
                shift = 40;
            else if (!unit.empty())
                return wanted;
            if (n == 0) return "expected at least 1 byte, got 0";
            if (shift > 0 && n > (std::numeric_limits<std::uint64_t>::max() >> shift)) return wanted + " (too large)";
            text = std::to_string(n << shift);
            return {};
        },
        "BYTES");
}

bool refuse_non_finite(const hmira::face_vertex_mesh& mesh, const std::string& path, const std::string& what,
                       int& code) {
    for (auto v : mesh.vertices()) {
        const auto p = mesh.position(v);
        if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) continue;
        // The face-vertex mesh of a freshly read file numbers vertices densely in file order.
        code = report(invalid_input, path + ": " + what + ": vertex " + std::to_string(v.index) +
                                         " has a non-finite coordinate (" + number_text(p.x) + ", " + number_text(p.y) +
                                         ", " + number_text(p.z) + "); nothing written");
        return false;
    }
    code = ok;
    return true;
}

namespace {

extern "C" void remove_temporaries_and_die(int sig) {
    hmira::io::detail::unlink_live_temporaries();
    // SA_RESETHAND restored the default action: the signal, unblocked on return, ends us.
    ::raise(sig);
}

int signal_to_raise = 0;
void raise_test_signal() {
    if (signal_to_raise != 0) ::raise(std::exchange(signal_to_raise, 0));
}

}  // namespace

void install_signal_cleanup() {
    struct sigaction sa {};
    sa.sa_handler = remove_temporaries_and_die;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESETHAND;
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&sa.sa_mask, sig);  // one cleanup at a time
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) ::sigaction(sig, &sa, nullptr);
    if (const char* s = std::getenv("HMIRA_TEST_SIGNAL_DURING_WRITE")) {
        const std::string name = s;
        signal_to_raise = name == "INT"    ? SIGINT
                          : name == "TERM" ? SIGTERM
                          : name == "HUP"  ? SIGHUP
                          : name == "KILL" ? SIGKILL
                                           : 0;
        if (signal_to_raise != 0) hmira::io::detail::write_hooks.after_first_chunk = raise_test_signal;
    }
    if (const char* s = std::getenv("HMIRA_TEST_NAMED_TEMPORARY"); s && std::string(s) == "1")
        hmira::io::detail::write_hooks.named_temporary_only = true;
}

void say(const common_options& o, const std::string& line) {
    if (!o.quiet) std::cout << line << '\n';
}

bool same_file(const std::string& a, const std::string& b) {
    namespace fs = std::filesystem;
    std::error_code ec;
    // Both exist: the same inode, whatever the spelling (symlinks, hard links, "./", "..").
    if (fs::exists(a, ec) && fs::exists(b, ec)) return fs::equivalent(a, b, ec) && !ec;
    // One is missing (an output not written yet): the same file only if the names resolve alike.
    const auto ca = fs::weakly_canonical(fs::absolute(a, ec), ec);
    const auto cb = fs::weakly_canonical(fs::absolute(b, ec), ec);
    return !ec && ca == cb;
}

namespace {

/// The files this run reads (note_input()): save() refuses to write over one.
std::vector<std::string>& files_read() {
    static std::vector<std::string> paths;
    return paths;
}

/// The size of a file to read, for its progress bar (0 when unknown: a pipe, or an error the
/// reader itself reports).
std::uint64_t input_size(const std::string& path) {
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    return ec ? 0 : static_cast<std::uint64_t>(size);
}

}  // namespace

void note_input(const std::string& path) { files_read().push_back(path); }

std::optional<loaded_mesh> load(const std::string& path, const common_options& o, int& code) {
    note_input(path);
    loaded_mesh out;
    progress_bar bar("reading " + path, o);
    auto r = hmira::io::read_mesh(out.mesh, path,
                                  {.progress = bar.callback(input_size(path)), .max_input_bytes = o.max_input_bytes});
    if (!r) {
        code = report(input_exit_code(r.error()), r.error().message);
        return std::nullopt;
    }
    out.report = std::move(*r);
    code = ok;
    return out;
}

std::optional<loaded_mesh> load_for_edit(const std::string& path, const common_options& o, int& code) {
    note_input(path);
    loaded_mesh out;
    progress_bar bar("reading " + path, o);
    auto soup =
        hmira::io::read_soup(path, {.progress = bar.callback(input_size(path)), .max_input_bytes = o.max_input_bytes});
    if (!soup) {
        code = report(input_exit_code(soup.error()), soup.error().message);
        return std::nullopt;
    }
    // Drop what no polygon mesh holds: faces with fewer than 3 distinct corners, or a repeated
    // corner (face_vertex_mesh refuses those; the half-edge readers drop them too).
    hmira::io::polygon_soup kept;
    kept.points = std::move(soup->points);
    kept.attributes = std::move(soup->attributes);
    kept.face_offsets.assign(1, 0);
    std::vector<std::size_t> file_face, dropped;
    std::vector<std::uint32_t> seen;
    for (std::size_t f = 0; f < soup->face_count(); ++f) {
        seen.assign(soup->indices.begin() + static_cast<std::ptrdiff_t>(soup->face_offsets[f]),
                    soup->indices.begin() + static_cast<std::ptrdiff_t>(soup->face_offsets[f + 1]));
        std::sort(seen.begin(), seen.end());
        if (seen.size() < 3 || std::adjacent_find(seen.begin(), seen.end()) != seen.end()) {
            dropped.push_back(f);
            continue;
        }
        kept.indices.insert(kept.indices.end(),
                            soup->indices.begin() + static_cast<std::ptrdiff_t>(soup->face_offsets[f]),
                            soup->indices.begin() + static_cast<std::ptrdiff_t>(soup->face_offsets[f + 1]));
        kept.face_offsets.push_back(kept.indices.size());
        file_face.push_back(f);
    }
    auto built = hmira::io::assign_from_soup(out.mesh, kept, [&](std::size_t) { return path; });
    if (!built) {
        code = report(input_exit_code(built.error()), built.error().message);
        return std::nullopt;
    }
    out.report.file_vertices = kept.points.size();
    out.file_faces = soup->face_count();
    out.report.attributes = std::move(kept.attributes);
    if (!dropped.empty()) {
        out.repairs = std::to_string(dropped.size()) +
                      (dropped.size() == 1 ? " degenerate face" : " degenerate faces") + " dropped (file face";
        for (std::size_t i = 0; i < dropped.size() && i < 3; ++i)
            out.repairs += (i ? ", " : " ") + std::to_string(dropped[i]);
        out.repairs += dropped.size() > 3 ? ", ...)" : ")";
        out.file_face = std::move(file_face);
    }
    code = ok;
    return out;
}

bool file_faces_to_loaded(const loaded_mesh& loaded, std::vector<std::size_t>& faces, const std::string& path,
                          int& code) {
    code = ok;
    if (loaded.file_face.empty()) return true;
    for (auto& f : faces) {
        const auto at = std::lower_bound(loaded.file_face.begin(), loaded.file_face.end(), f);
        if (at == loaded.file_face.end() || *at != f) {
            code = report(
                usage, "--face: face " + std::to_string(f) + " of " + path +
                           " is degenerate (fewer than 3 distinct corners) and was dropped; there is nothing to edit");
            return false;
        }
        f = static_cast<std::size_t>(at - loaded.file_face.begin());
    }
    return true;
}

int save(const hmira::face_vertex_mesh& mesh, const std::string& path, const hmira::io::write_options& options,
         const common_options&) {
    for (const auto& input : files_read())
        if (same_file(path, input))
            return report(usage, "output " + path + " is the input " + input +
                                     ": hmira never writes over its input; name another output file");
    // The writers refuse a coordinate the file cannot hold (non-finite, or beyond float's range
    // for STL and PLY --float), naming the vertex, before writing a byte.
    auto w = hmira::io::write_mesh(mesh, path, options);
    if (!w) return report(exit_code_for(w.error()), w.error().message);
    return ok;
}

std::optional<hmira::halfedge_mesh> to_halfedge(const hmira::face_vertex_mesh& mesh, const std::string& path, int& code,
                                                std::string* repairs) {
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
    if (!repaired || repaired->face_count() != mesh.face_count() ||
        repaired->corners.size() > std::size_t{0xffffffffu}) {
        code =
            report(invalid_input, path + ": cannot edit this mesh: " +
                                      (repaired ? "a degenerate face or too many corners" : repaired.error().message));
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
    // New elements append, so index order stays creation order and the output lists the
    // surviving file vertices first, in file order, then the new ones (documented per command).
    built->set_slot_reuse(false);
    if (!repaired->copied_from.empty()) {
        auto source = built->add_vertex_property<std::uint32_t>("v:file_vertex");
        for (auto v : built->vertices()) source[v] = static_cast<std::uint32_t>(repaired->source_vertex(v.index));
    }
    if (repairs) *repairs = repaired->report.clean() ? "" : repaired->report.summary();
    code = ok;
    return std::move(*built);
}

std::vector<hmira::vertex_handle> file_vertices(const hmira::halfedge_mesh& mesh,
                                                std::span<const std::size_t> indices) {
    std::vector<hmira::vertex_handle> out;
    for (auto i : indices) out.emplace_back(i);
    if (auto source = mesh.get_vertex_property<std::uint32_t>("v:file_vertex")) {
        std::vector<char> wanted(mesh.vertex_index_bound(), 0);
        for (auto i : indices) wanted[i] = 1;
        for (auto v : mesh.vertices())  // copies: a different index, standing for a wanted one
            if (const auto from = (*source)[v]; from != v.index && from < wanted.size() && wanted[from])
                out.push_back(v);
    }
    return out;
}

hmira::face_vertex_mesh to_face_vertex(
    const hmira::halfedge_mesh& mesh, std::span<const std::pair<hmira::vertex_handle, hmira::vertex_handle>> exchange) {
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

mesh_counts counts_of(const hmira::halfedge_mesh& mesh) {
    return {mesh.vertex_count(), mesh.edge_count(), mesh.face_count()};
}

int run_edit(const loaded_mesh& loaded, const std::string& input, const std::string& output,
             const std::string& bar_label, const common_options& o,
             const std::function<std::optional<edit_outcome>(hmira::halfedge_mesh&, int& code)>& edit) {
    int code = ok;
    if (!refuse_non_finite(loaded.mesh, input, "cannot edit", code)) return code;
    mesh_counts before, after;
    hmira::face_vertex_mesh edited;
    std::string what;
    {
        auto bar = stage_bar(bar_label, o, loaded.mesh.face_count());
        bar.update(0, 3);
        std::string repairs;
        auto mesh = to_halfedge(loaded.mesh, input, code, &repairs);
        if (!mesh) return code;
        if (!loaded.repairs.empty()) repairs = repairs.empty() ? loaded.repairs : loaded.repairs + "; " + repairs;
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
    auto one = [](const char* what, std::size_t a, std::size_t b) {
        return std::string(what) + " " + std::to_string(a) + " -> " + std::to_string(b);
    };
    return one("V", before.vertices, after.vertices) + ", " + one("E", before.edges, after.edges) + ", " +
           one("F", before.faces, after.faces);
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
    for (int i = 0; i < n; ++i)
        if (!std::isfinite(v[static_cast<std::size_t>(i)])) return std::nullopt;
    if (n == 1 && one_for_all) return std::array<double, 3>{v[0], v[0], v[0]};
    if (n != 3) return std::nullopt;
    return v;
}

bool check_indices(const std::vector<std::size_t>& indices, std::size_t count, const std::string& what,
                   const std::string& option, const std::string& path, int& code) {
    for (auto i : indices)
        if (i >= count) {
            const std::string range = count == 0 ? "none" : "0.." + std::to_string(count - 1);
            code = report(usage, option + ": " + what + " " + std::to_string(i) + " does not exist: " + path + " has " +
                                     count_of(count, what, what == "vertex" ? "vertices" : what + "s") + " (" + range +
                                     ", in file order)");
            return false;
        }
    code = ok;
    return true;
}

std::string count_of(std::size_t n, const std::string& one, const std::string& many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

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
    std::fprintf(stderr, "\r%s [%.*s%*s] %3d%%", label_.c_str(), filled, "##############################",
                 width - filled, "", static_cast<int>(100 * done / total));
    std::fflush(stderr);
    drawn_ = true;
}

hmira::progress_function progress_bar::callback(std::uint64_t total) {
    if (!enabled_) return {};
    return [this, total](double done) {
        update(static_cast<std::uint64_t>(done * static_cast<double>(total)), total);
        return true;
    };
}

}  // namespace hmira_cli
