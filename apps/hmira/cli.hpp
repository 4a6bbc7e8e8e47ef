// apps/hmira/cli.hpp
// What every `hmira` subcommand shares: self-registration, the common options (--threads,
// --quiet), documented exit codes, one-line errors on stderr, reading and writing meshes
// with a progress bar on a terminal.
#pragma once

#include <CLI/CLI.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <utility>
#include <string>
#include <vector>

#include <hmira/core/enum_names.hpp>
#include <hmira/io/detail/atomic_write.hpp>
#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

namespace hmira_cli {

/// Exit codes (documented in docs/cli.md and in `hmira --help`).
enum exit_code : int {
    ok = 0,             ///< success
    invalid_input = 1,  ///< the input is malformed, an edit cannot apply to it, or validation found problems
    usage = 2,  ///< bad command line (unknown option, missing argument, value or index out of range, unknown format)
    io_failure = 3,  ///< a file cannot be read or written (missing, directory, permissions)
    internal = 4,    ///< an unexpected failure inside hmira
};

/// The names of an option enum's values (core/enum_names.hpp), for CLI::IsMember.
template <hmira::named_enum E>
std::vector<std::string> names_of() {
    std::vector<std::string> out;
    for (const auto& [value, name] : enum_names(E{})) {
        (void)value;
        out.emplace_back(name);
    }
    return out;
}

/// The name of an option enum's value, such as an options struct's default.
template <hmira::named_enum E>
std::string name_of(E value) {
    return std::string(hmira::to_string(value));
}

/// The value named `name`, which the option's IsMember(names_of<E>()) check has accepted.
template <hmira::named_enum E>
E named(const std::string& name) {
    return *hmira::from_string<E>(name);
}

/// Options every subcommand has.
struct common_options {
    int threads = 0;  ///< 0: all cores
    bool quiet = false;
    /// Largest input read from a pipe, device or FIFO (regular files are bounded by their size).
    std::uint64_t max_input_bytes = std::uint64_t{4} << 30;
};

/// The check of a floating-point option: a finite number (CLI11's range checks let NaN and
/// infinity through) for which `holds` is true; `rule` says what that means ("> 0",
/// "in [0, 180]") in the message, e.g. "--scale: expected a finite number > 0, got 'nan'".
CLI::Validator finite_number(std::string rule = {}, std::function<bool(double)> holds = {});
/// The check of an integer option: a whole number in [lo, hi], bounds printed as written.
CLI::Validator whole_number(std::uint64_t lo, std::uint64_t hi);
/// The check of a size option: a whole number of bytes, optionally with a binary suffix (K, M,
/// G, T, or KiB, MiB, GiB, TiB: powers of 1024), at least 1; rewrites the value to bytes.
CLI::Validator byte_count();

/// `x` as printf's %g writes it ("0.1", "90", "1e+06"), for messages and help texts.
std::string number_text(double x);

/// `text` safe to print on one line: control characters (a newline in a file name) become
/// escapes such as \n or \x1b.
std::string printable(const std::string& text);

/// A subcommand: `setup` adds its options to `sub` and returns the function that runs it.
struct command {
    std::string name;
    std::string summary;
    std::string example;  ///< shown at the end of --help
    int order = 100;      ///< position in `hmira --help`
    std::function<std::function<int(const common_options&)>(CLI::App& sub)> setup;
    bool reads_files = true;  ///< has --max-input-bytes (all but generate)
};

/// Adds a command to the tool; call from a static initialiser in the command's file.
bool register_command(command c);
std::vector<command>& commands();

/// Prints "hmira: error: <message>" (one line) unless empty, and returns the code.
int report(int code, const std::string& message);
/// The exit code for a library error of an operation whose arguments came from the command
/// line: an invalid argument is a usage error.
int exit_code_for(const hmira::error& e);
/// The exit code for a library error caused by the input's content (reading a file, or an
/// operation whose options were already checked): anything but an I/O failure or an unknown
/// file extension is invalid input.
int input_exit_code(const hmira::error& e);

/// Refuses a mesh with a NaN or infinite coordinate before `what` ("truncate", "voxelize")
/// uses it: prints one line naming the first such vertex (file order), sets `code` to
/// invalid_input and returns false.
bool refuse_non_finite(const hmira::face_vertex_mesh& mesh, const std::string& path, const std::string& what,
                       int& code);

/// Installs handlers for SIGINT, SIGTERM and SIGHUP that remove the temporary files of writes
/// in progress (the named ones; unnamed O_TMPFILE ones vanish by themselves) and then end the
/// process by the same signal, so the caller sees what killed it. Also applies the test hooks
/// HMIRA_TEST_SIGNAL_DURING_WRITE=INT|TERM|HUP|KILL (raise that signal once the first chunk
/// of an output is written) and HMIRA_TEST_NAMED_TEMPORARY=1 (no O_TMPFILE).
void install_signal_cleanup();

/// True when `a` and `b` name the same file: std::filesystem::equivalent when both exist (so
/// symlinks, hard links and other spellings count), else the same weakly canonical path.
bool same_file(const std::string& a, const std::string& b);

/// The memory this process can still take, in bytes: the system's available memory
/// (MemAvailable in /proc/meminfo, else the free physical pages), or less where the
/// address-space limit (ulimit -v) or the cgroup's memory.max leaves less; nullopt when none of
/// them is known. HMIRA_TEST_MEMAVAILABLE=BYTES is the answer instead, for the tests of the
/// refusals (an address-space limit cannot stand in: the sanitizers reserve terabytes).
std::optional<std::uint64_t> free_memory();

/// Prints a line on stdout unless quiet.
void say(const common_options& o, const std::string& line);

/// Reads a mesh (any format, by extension) into a face-vertex mesh, which takes any polygon
/// soup, even non-manifold. Prints the error and returns the exit code on failure.
struct loaded_mesh {
    hmira::face_vertex_mesh mesh;
    hmira::io::read_report report;
    /// load_for_edit(): the repairs already made on reading ("" if none), for the one-line note.
    std::string repairs = {};
    /// load_for_edit(): face i of `mesh` is the file's face file_face[i]; empty when no face
    /// was dropped (then face i is the file's face i).
    std::vector<std::size_t> file_face = {};
    /// load_for_edit(): how many faces the file has, dropped ones included (what --face N counts).
    std::size_t file_faces = 0;
};
std::optional<loaded_mesh> load(const std::string& path, const common_options& o, int& code);
/// load() for the editing subcommands: faces with fewer than 3 distinct corners are dropped
/// (as reading into a half-edge model does) instead of refusing the file; `repairs` and
/// `file_face` say what went. validate and info use load(), which describes the file as it is.
std::optional<loaded_mesh> load_for_edit(const std::string& path, const common_options& o, int& code);
/// Turns face indices of the input file (--face N) into faces of a load_for_edit() mesh; a
/// face that was dropped, or out of range, is a usage error naming it.
bool file_faces_to_loaded(const loaded_mesh& loaded, std::vector<std::size_t>& faces, const std::string& path,
                          int& code);
/// Records `path` as an input of this run, so that save() refuses to write over it. load() and
/// load_for_edit() call it; a subcommand that reads its input another way calls it itself.
void note_input(const std::string& path);
/// Writes atomically; prints the error and returns the exit code (ok on success). An output
/// that is one of this run's inputs (note_input(), compared with same_file()) is refused as a
/// usage error, and the file is left as it is; so is a mesh with a non-finite coordinate, or
/// one beyond the float range for a float format (STL, PLY with float32 coordinates), as
/// invalid input: no output ever holds a non-finite coordinate.
int save(const hmira::face_vertex_mesh& mesh, const std::string& path, const hmira::io::write_options& options,
         const common_options& o);

// ---- editing subcommands (truncate, bevel, extrude) ----------------------------------------

/// Builds the Euler-capable mesh the editing algorithms need from a loaded face-vertex mesh.
/// Vertex i and face i of the result are vertex i and face i of `mesh` (the file's order), so
/// indices given on the command line name the file's elements. A mesh the halfedge mesh cannot
/// hold (non-manifold edge or vertex, inconsistent orientation, degenerate face) prints a
/// one-line error naming the element and sets `code` to invalid_input.
/// A file the halfedge mesh cannot hold as it is is repaired first (hmira::repair_polygon_soup)
/// and `repairs`, if given, gets the one-line summary ("" when nothing was repaired). Copies of
/// split vertices come after the file's vertices; file_vertices() translates vertex indices
/// given on the command line.
std::optional<hmira::halfedge_mesh> to_halfedge(const hmira::face_vertex_mesh& mesh, const std::string& path, int& code,
                                                std::string* repairs = nullptr);
/// The vertices of a mesh from to_halfedge that stand for the file's vertices `indices`: each
/// one and every copy a repair made of it.
std::vector<hmira::vertex_handle> file_vertices(const hmira::halfedge_mesh& mesh, std::span<const std::size_t> indices);

/// The live vertices and faces of `mesh`, renumbered densely in index order: vertices that were
/// in the input keep their relative order and come first, new ones follow. Each pair in
/// `exchange` trades places in that order (an edit that moved a file vertex and left a new one
/// where it was can so give the file's index back to the one that stayed).
hmira::face_vertex_mesh to_face_vertex(
    const hmira::halfedge_mesh& mesh,
    std::span<const std::pair<hmira::vertex_handle, hmira::vertex_handle>> exchange = {});

/// Vertex, edge and face counts, to report what an edit created.
struct mesh_counts {
    std::size_t vertices = 0, edges = 0, faces = 0;
};
mesh_counts counts_of(const hmira::halfedge_mesh& mesh);
/// "V 8 -> 24, E 12 -> 36, F 6 -> 14".
std::string describe_change(const mesh_counts& before, const mesh_counts& after);

/// What an editing subcommand did to the halfedge mesh: a phrase for the report ("truncated 8
/// vertices") and, where the edit moved file vertices, the exchange for to_face_vertex().
struct edit_outcome {
    std::string what;
    std::vector<std::pair<hmira::vertex_handle, hmira::vertex_handle>> exchange;
};
/// The frame every editing subcommand shares: converts the loaded mesh to a halfedge mesh, runs
/// `edit` on it (nullopt after it has printed its error and set `code`), writes the result
/// atomically and reports the change. Returns the exit code.
int run_edit(const loaded_mesh& loaded, const std::string& input, const std::string& output,
             const std::string& bar_label, const common_options& o,
             const std::function<std::optional<edit_outcome>(hmira::halfedge_mesh&, int& code)>& edit);

/// Parses "X,Y,Z" (or one number for all three when `one_for_all`); nullopt if malformed or
/// not finite.
std::optional<std::array<double, 3>> parse_triple(const std::string& text, bool one_for_all = false);

/// Checks file-order indices of `what` ("vertex", "face") against the mesh's count; on failure
/// prints a usage error naming the option, the index and the valid range, and returns false.
bool check_indices(const std::vector<std::size_t>& indices, std::size_t count, const std::string& what,
                   const std::string& option, const std::string& path, int& code);

/// "1 vertex", "3 vertices": `n` and the singular or plural noun.
std::string count_of(std::size_t n, const std::string& one, const std::string& many);

/// A progress bar on stderr, drawn only when stderr is a terminal, not quiet, and the work is
/// large enough to be worth watching.
class progress_bar {
public:
    progress_bar(std::string label, const common_options& o, std::uint64_t min_total = 16u << 20);
    ~progress_bar();
    void update(std::uint64_t done, std::uint64_t total);
    /// A progress function for a reader of `total` bytes: draws the bar, never cancels (Ctrl-C
    /// ends the program through its signal handler).
    hmira::progress_function callback(std::uint64_t total);

private:
    std::string label_;
    bool enabled_;
    bool drawn_ = false;
    std::uint64_t min_total_;
};

/// A bar for work measured in steps (stages of an edit, slices of a grid) rather than bytes:
/// drawn only when `size` (faces, voxels) is at least `min_size`, so small jobs stay silent.
progress_bar stage_bar(std::string label, const common_options& o, std::uint64_t size, std::uint64_t min_size = 200000);

}  // namespace hmira_cli
