// apps/hmira/cli.hpp
// What every `hmira` subcommand shares: self-registration, the common options (--threads,
// --quiet), documented exit codes, one-line errors on stderr, reading and writing meshes
// with a progress bar on a terminal.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

namespace hmira_cli {

/// Exit codes (documented in docs/cli.md and in `hmira --help`).
enum exit_code : int {
    ok = 0,             ///< success
    invalid_input = 1,  ///< the input is malformed, or validation found problems
    usage = 2,          ///< bad command line (unknown option, missing argument, unknown format)
    io_failure = 3,     ///< a file cannot be read or written (missing, directory, permissions)
    internal = 4,       ///< an unexpected failure inside hmira
};

/// Options every subcommand has.
struct common_options {
    int threads = 0;  ///< 0: all cores
    bool quiet = false;
};

/// A subcommand: `setup` adds its options to `sub` and returns the function that runs it.
struct command {
    std::string name;
    std::string summary;
    std::string example;  ///< shown at the end of --help
    int order = 100;      ///< position in `hmira --help`
    std::function<std::function<int(const common_options&)>(CLI::App& sub)> setup;
};

/// Adds a command to the tool; call from a static initialiser in the command's file.
bool register_command(command c);
std::vector<command>& commands();

/// Prints "hmira: error: <message>" (one line) unless empty, and returns the code.
int report(int code, const std::string& message);
/// The exit code for a library error.
int exit_code_for(const hmira::error& e);

/// Prints a line on stdout unless quiet.
void say(const common_options& o, const std::string& line);

/// Reads a mesh (any format, by extension) into a face-vertex mesh, which takes any polygon
/// soup, even non-manifold. Prints the error and returns the exit code on failure.
struct loaded_mesh {
    hmira::face_vertex_mesh mesh;
    hmira::io::read_report report;
};
std::optional<loaded_mesh> load(const std::string& path, const common_options& o, int& code);
/// Writes atomically; prints the error and returns the exit code (ok on success).
int save(const hmira::face_vertex_mesh& mesh, const std::string& path, const hmira::io::write_options& options, const common_options& o);

/// A progress bar on stderr, drawn only when stderr is a terminal, not quiet, and the work is
/// large enough to be worth watching.
class progress_bar {
public:
    progress_bar(std::string label, const common_options& o, std::uint64_t min_total = 16u << 20);
    ~progress_bar();
    void update(std::uint64_t done, std::uint64_t total);
    hmira::io::progress_callback callback();

private:
    std::string label_;
    bool enabled_;
    bool drawn_ = false;
    std::uint64_t min_total_;
};

}  // namespace hmira_cli
