// apps/hmira/main.cpp
// `hmira <subcommand> ...`: builds the command line from the registered subcommands, applies
// the common options, runs the chosen one and maps every failure to a documented exit code.
#include <algorithm>
#include <iostream>
#include <memory>

#include "cli.hpp"

#ifdef HMIRA_HAS_TBB
#include <tbb/global_control.h>
#endif

namespace {

const char* exit_codes_text =
    "Exit codes:\n"
    "  0  success\n"
    "  1  invalid input: a malformed file, a mesh the operation cannot apply to (non-manifold...),\n"
    "     or validation found problems\n"
    "  2  usage error: unknown option or subcommand, missing argument, a value or element index\n"
    "     out of range, unknown file format\n"
    "  3  I/O error: a file cannot be read or written (missing, a directory, permissions)\n"
    "  4  internal error\n";

}  // namespace

int main(int argc, char** argv) {
    using namespace hmira_cli;
    install_signal_cleanup();
    CLI::App app{"hmira: generic polygon-mesh algorithms on mesh files (OBJ, OFF, PLY, STL)", "hmira"};
    app.require_subcommand(1);
    app.footer(std::string("\n") + exit_codes_text +
               "\nRun 'hmira <subcommand> --help' for a subcommand's options and an example.");
    app.set_version_flag("--version", "hmira 0.1.0");

    auto& all = commands();
    std::stable_sort(all.begin(), all.end(), [](const command& a, const command& b) { return a.order < b.order; });
    common_options common;
    std::function<int(const common_options&)> chosen;
    for (auto& c : all) {
        CLI::App* sub = app.add_subcommand(c.name, c.summary);
        sub->add_option("--threads", common.threads, "worker threads (0: all cores)")->check(whole_number(0, 4096));
        sub->add_flag("-q,--quiet", common.quiet, "print nothing but errors");
        if (c.reads_files)
            sub->add_option("--max-input-bytes", common.max_input_bytes,
                            "largest input read from a pipe, device or FIFO, e.g. 512M (regular files: their size)")
                ->default_str("4G")
                ->transform(byte_count());
        sub->footer("\nExample:\n  " + c.example + "\n\n" + exit_codes_text);
        auto run = c.setup(*sub);
        sub->callback([&chosen, run] { chosen = run; });
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::string what = e.what();
        std::replace(what.begin(), what.end(), '\n', ' ');
        return report(usage, what + " (see 'hmira --help')");
    }
#ifdef HMIRA_HAS_TBB
    std::unique_ptr<tbb::global_control> threads;
    if (common.threads > 0)
        threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                        static_cast<std::size_t>(common.threads));
#endif
    if (!chosen) return report(usage, "no subcommand given (see 'hmira --help')");
    try {
        return chosen(common);
    } catch (const hmira::hmira_error& e) {
        return report(exit_code_for(e.error()), e.what());
    } catch (const std::bad_alloc&) {
        return report(internal, "out of memory");
    } catch (const std::exception& e) {
        return report(internal, e.what());
    }
}
