// python/src/module.cpp
// The extension module hmira._core: the error translator and each family's bindings, in the
// order their functions and classes appear in the type stubs.
#include "common.hpp"

namespace hmira_py {

void bind_volume_io(nb::module_& m);        // .inr / .raw volumes for hmira.read_volume (volume_io.cpp)
void bind_decimate_blocks(nb::module_& m);  // one block of hmira.dask.decimate (decimate_blocks.cpp)
void bind_results(nb::module_& m);          // the typed results of the Mesh operations (results.cpp)
void bind_boolean(nb::module_& m);          // mesh_boolean (boolean.cpp)

void register_errors(nb::module_&) {
    nb::register_exception_translator([](const std::exception_ptr& p, void*) {
        try {
            std::rethrow_exception(p);
        } catch (const hmira_failure& e) {
            PyErr_SetString(e.code == hmira::errc::io_error ? PyExc_OSError : PyExc_ValueError, e.what());
        }
    });
}

}  // namespace hmira_py

NB_MODULE(_core, m) {
    m.doc() = "hmira's compiled core: marching cubes, voxelization, Delaunay, mesh I/O and the Mesh class.";
    hmira_py::register_errors(m);
    m.def(
        "_last_cpp_seconds", [] { return hmira_py::last_cpp_seconds(); },
        "Seconds the last marching_cubes / voxelize / delaunay_triangulation / read_mesh spent in C++ (for "
        "bench/python).");
    hmira_py::bind_conversion(m);
    hmira_py::bind_delaunay(m);
    hmira_py::bind_results(m);
    hmira_py::bind_io(m);
    hmira_py::bind_mesh(m);
    hmira_py::bind_spatial(m);
    hmira_py::bind_viewer(m);
    hmira_py::bind_blocks(m);
    hmira_py::bind_volume_io(m);
    hmira_py::bind_queries(m);
    hmira_py::bind_decimate_blocks(m);
    hmira_py::bind_boolean(m);
}
