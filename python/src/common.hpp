// python/src/common.hpp
// What every binding file shares: turning hmira::result errors into Python exceptions
// (ValueError, OSError for files), releasing the GIL around heavy calls while still noticing
// Ctrl-C, reading option names and (V, F) arrays, and handing C++ containers to numpy. Each
// family's file (conversion.cpp, holes.cpp, ...) defines the bind_<family> declared here.
#pragma once

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/pair.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <chrono>
#include <cstddef>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

#include <hmira/core/enum_names.hpp>
#include <hmira/core/progress.hpp>
#include <hmira/core/result.hpp>
#include <hmira/io/mesh_io.hpp>

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
    ~cpp_timer() {
        last_cpp_seconds() = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
};

/// The value of an option enum named by `name` (core/enum_names.hpp), or ValueError listing
/// the names: "<who>: unknown <option> '<name>' (supported: 'a', 'b')".
template <hmira::named_enum E>
E enum_arg(const std::string& name, const char* who, const char* option) {
    if (const auto e = hmira::from_string<E>(name)) return *e;
    value_error(std::string(who) + ": unknown " + option + " '" + name + "' (supported: " + hmira::quoted_names<E>() +
                ")");
}
/// enum_arg with the other message: "<who>: <option> must be 'a' or 'b', got '<name>'".
template <hmira::named_enum E>
E choice_arg(const std::string& name, const char* who, const char* option) {
    if (const auto e = hmira::from_string<E>(name)) return *e;
    value_error(std::string(who) + ": " + option + " must be " + hmira::quoted_choices<E>() + ", got '" + name + "'");
}
/// The name of an options struct's default enum value, for a keyword argument's default.
template <hmira::named_enum E>
std::string name_of(E value) {
    return std::string(hmira::to_string(value));
}

/// A numpy array that owns a heap-allocated C++ container (moved in, freed with the array).
template <class Scalar, class Container>
nb::ndarray<nb::numpy, Scalar> adopt(Container&& c, std::initializer_list<std::size_t> shape) {
    auto* owned = new Container(std::move(c));
    nb::capsule owner(owned, [](void* p) noexcept { delete static_cast<Container*>(p); });
    return nb::ndarray<nb::numpy, Scalar>(reinterpret_cast<Scalar*>(owned->data()), shape, owner);
}

/// Vertex positions from Python: an (n, 3) float64 array.
using vertex_array = nb::ndarray<const double, nb::ndim<2>, nb::c_contig, nb::device::cpu>;

/// (vertices, faces) as a polygon soup; faces an (m, k) integer array or a sequence of
/// polygons. Errors (ValueError, TypeError) name `who`, the face and the corner (io.cpp).
hmira::io::polygon_soup to_soup(const vertex_array& vertices, nb::handle faces, const char* who);
/// The writer's options for the keyword arguments of write / write_mesh (io.cpp).
hmira::io::write_options write_options_from(bool ascii, bool big_endian, bool float32, bool attributes);

/// Registers the translator from hmira_failure to Python exceptions.
void register_errors(nb::module_& m);
/// The module-level functions, one family a file.
void bind_conversion(nb::module_& m);  // marching_cubes, voxelize (conversion.cpp)
void bind_delaunay(nb::module_& m);    // delaunay_triangulation (delaunay.cpp)
void bind_io(nb::module_& m);          // write_polygons (io.cpp)
void bind_mesh(nb::module_& m);        // Topology and MeshCore (mesh.cpp and the Mesh families)
void bind_spatial(nb::module_& m);     // BVH (spatial.cpp)
void bind_viewer(nb::module_& m);      // viewer.cpp
void bind_blocks(nb::module_& m);      // marching cubes by blocks for hmira.dask (blocks.cpp)
void bind_queries(nb::module_& m);     // winding_number, signed_distance, hausdorff_distance (queries.cpp)

}  // namespace hmira_py
