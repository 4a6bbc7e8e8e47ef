// apps/hmira/cli.cpp
// Shared plumbing of the subcommands (see cli.hpp).
#include "cli.hpp"

#include <unistd.h>

#include <cstdio>
#include <iostream>

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
