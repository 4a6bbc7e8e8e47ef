// python/src/common.hpp
// What every binding file shares: turning hmira::result errors into Python exceptions
// (ValueError, OSError for files), releasing the GIL around heavy calls while still noticing
// Ctrl-C, and reading small option values.
#pragma once

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/pair.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <chrono>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>

#include <hmira/core/progress.hpp>
#include <hmira/core/result.hpp>

namespace hmira_py {

namespace nb = nanobind;

/// A failed hmira::result on its way to Python; translated (with the GIL held) into OSError
/// for I/O failures and ValueError for everything else, carrying the C++ message.
struct hmira_failure : std::runtime_error {
    hmira::errc code;
    hmira_failure(hmira::errc c, const std::string& message) : std::runtime_error(message), code(c) {}
};

/// Throws the result's error, if any.
template <class R>
void check(const R& r) {
    if (!r) throw hmira_failure(r.error().code, r.error().message);
}
/// The result's value, or its error as an exception.
template <class T>
T take(hmira::result<T>&& r) {
    check(r);
    return std::move(*r);
}

/// Raises ValueError with `message` (argument checks made while the GIL is held).
[[noreturn]] inline void value_error(const std::string& message) { throw nb::value_error(message.c_str()); }

/// Ctrl-C support for a call that runs with the GIL released: a progress_function that, on the
/// thread that called (Python's main thread), re-acquires the GIL at most every 50 ms and lets
/// Python run its signal handlers. A KeyboardInterrupt (or any exception a handler raises)
/// cancels the operation; rethrow() then raises it once the call is back.
class interrupt_watch {
public:
    interrupt_watch() : caller_(std::this_thread::get_id()) {}

    /// The callback to put in an options struct's `progress` field.
    hmira::progress_function callback() {
        return [this](double) {
            if (std::this_thread::get_id() != caller_) return true;
            const auto now = std::chrono::steady_clock::now();
            if (now - last_ < std::chrono::milliseconds(50)) return true;
            last_ = now;
            nb::gil_scoped_acquire gil;
            if (PyErr_CheckSignals() != 0) {
                error_.emplace();  // fetches the pending exception
                return false;
            }
            return true;
        };
    }
    /// Raises the exception a signal handler raised during the call, if any.
    void rethrow() {
        if (error_) {
            nb::python_error e = std::move(*error_);
            error_.reset();
            throw e;
        }
    }

private:
    std::thread::id caller_;
    std::chrono::steady_clock::time_point last_{};
    std::optional<nb::python_error> error_;
};

/// Seconds the last heavy call spent in the C++ algorithm itself (argument conversion and
/// result wrapping excluded): what bench/python compares the Python call's time with.
inline double& last_cpp_seconds() {
    static double seconds = 0;
    return seconds;
}
/// Times its scope into last_cpp_seconds().
struct cpp_timer {
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    ~cpp_timer() { last_cpp_seconds() = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); }
};

/// Registers the translator from hmira_failure to Python exceptions.
void register_errors(nb::module_& m);
void bind_arrays(nb::module_& m);
void bind_mesh(nb::module_& m);
void bind_viewer(nb::module_& m);

}  // namespace hmira_py
