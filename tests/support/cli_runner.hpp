// tests/support/cli_runner.hpp
// Runs the built `hmira` binary as a user would (in a scratch folder, stdin closed) and returns
// its exit code and output, for the end-to-end CLI tests of every family; and checks the
// one-line error format every failure prints.
#pragma once

#include <fcntl.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/io_support.hpp"

namespace hmira_test {

/// What one run of the tool gave.
struct run_result {
    int code = -1;         ///< exit code, or -1 if it did not exit normally
    int signal = 0;        ///< the signal that ended it, or 0
    std::string out, err;  ///< stdout and stderr
    double seconds = 0;    ///< wall time of the run
};

/// Runs `<cli> <args>` (args already shell-quoted where needed) in `dir`. `prefix` is shell
/// text run first in the same shell: variable assignments for the binary's environment
/// ("HMIRA_TEST_MEMAVAILABLE=1000") or a limit ("ulimit -v 100000 &&"). `wrapper` is a command
/// the binary runs under ("timeout -s KILL 120"). The shell execs the command, so the status
/// seen is the binary's (or the wrapper's) own, a signal included. Its output goes to files
/// beside `dir`, not in it, so the folder holds only what the run wrote.
inline run_result run_cli(const std::string& cli, const scratch_dir& dir, const std::string& args,
                          const std::string& prefix = "", const std::string& wrapper = "") {
    const auto out = dir.path().parent_path() / (dir.path().filename().string() + ".stdout");
    const auto err = dir.path().parent_path() / (dir.path().filename().string() + ".stderr");
    const std::string cmd = "cd '" + dir.path().string() + "' && " + prefix + " exec " + wrapper + " '" + cli + "' " +
                            args + " >'" + out.string() + "' 2>'" + err.string() + "' </dev/null";
    const auto start = std::chrono::steady_clock::now();
    const int status = std::system(cmd.c_str());
    run_result r;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (WIFEXITED(status)) r.code = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
    r.out = read_bytes(out);
    r.err = read_bytes(err);
    std::filesystem::remove(out);
    std::filesystem::remove(err);
    return r;
}

/// Starts `<cli> <args...>` in `dir` as a child process with stdin, stdout and stderr on
/// /dev/null, for a test that signals it; returns its pid (waitpid it), or -1.
inline pid_t start_cli(const std::string& cli, const scratch_dir& dir, const std::vector<std::string>& args) {
    const pid_t pid = ::fork();
    if (pid != 0) return pid;
    if (::chdir(dir.path().c_str()) != 0) ::_exit(120);
    const int null = ::open("/dev/null", O_RDWR);
    ::dup2(null, 0);
    ::dup2(null, 1);
    ::dup2(null, 2);
    std::vector<char*> argv{const_cast<char*>("hmira")};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(cli.c_str(), argv.data());
    ::_exit(121);
}

/// The run failed with the one-line error format, "hmira: error: ...\n", containing `part`.
inline ::testing::AssertionResult one_line_error(const run_result& r, const std::string& part) {
    if (r.err.rfind("hmira: error: ", 0) != 0)
        return ::testing::AssertionFailure() << "no 'hmira: error: ' prefix: " << r.err;
    if (std::count(r.err.begin(), r.err.end(), '\n') != 1)
        return ::testing::AssertionFailure() << "not one line: " << r.err;
    if (r.err.find(part) == std::string::npos)
        return ::testing::AssertionFailure() << "'" << part << "' not in: " << r.err;
    return ::testing::AssertionSuccess();
}

}  // namespace hmira_test
