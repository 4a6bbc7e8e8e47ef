// tests/support/cli_runner.hpp
// Runs the built `hmira` binary as a user would (in a scratch folder, stdin closed) and returns
// its exit code and output, for the end-to-end CLI tests of every family.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <string>

#include "io/io_support.hpp"

namespace hmira_test {

/// What one run of the tool gave.
struct run_result {
    int code = -1;         ///< exit code, or -1 if it did not exit normally
    std::string out, err;  ///< stdout and stderr
};

/// Runs `<cli> <args>` (args already shell-quoted where needed) in `dir`.
inline run_result run_cli(const std::string& cli, const scratch_dir& dir, const std::string& args) {
    const auto out = dir / ".stdout", err = dir / ".stderr";
    const std::string cmd = "cd '" + dir.path().string() + "' && '" + cli + "' " + args + " >'" + out.string() + "' 2>'" + err.string() +
                            "' </dev/null";
    const int status = std::system(cmd.c_str());
    run_result r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = read_bytes(out);
    r.err = read_bytes(err);
    return r;
}

}  // namespace hmira_test
