// python/src/module.cpp
// The extension module hmira._core: array functions (arrays.cpp) and the Mesh class (mesh.cpp).
#include "common.hpp"

namespace hmira_py {

void register_errors(nb::module_&) {
    nb::register_exception_translator([](const std::exception_ptr& p, void*) {
        try {
            std::rethrow_exception(p);
        } catch (const hmira_failure& e) {
            PyErr_SetString(e.code == hmira::errc::io_error ? PyExc_OSError : PyExc_ValueError, e.what());
        }
    });
}

void bind_blocks(nb::module_& m);  // blocks.cpp: marching cubes by blocks for hmira.dask

}  // namespace hmira_py

NB_MODULE(_core, m) {
    m.doc() = "hmira's compiled core: marching cubes, voxelization, Delaunay, mesh I/O and the Mesh class.";
    hmira_py::register_errors(m);
    hmira_py::bind_arrays(m);
    hmira_py::bind_mesh(m);
    hmira_py::bind_viewer(m);
    hmira_py::bind_blocks(m);
}
