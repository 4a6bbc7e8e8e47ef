// python/src/io.cpp
// Meshes from and to Python arrays: (vertices, faces) as a polygon soup, with errors that name
// the face and corner, the writer's options from keyword arguments, and write_mesh for arrays.
#include "common.hpp"

#include <cmath>
#include <cstdint>
#include <string>

#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

namespace hmira_py {

hmira::io::polygon_soup to_soup(const vertex_array& vertices, nb::handle faces, const char* who) {
    if (vertices.shape(1) != 3)
        value_error(std::string(who) + ": vertices must have shape (n, 3), got (" + std::to_string(vertices.shape(0)) +
                    ", " + std::to_string(vertices.shape(1)) + ")");
    hmira::io::polygon_soup soup;
    const std::size_t nv = vertices.shape(0);
    soup.points.resize(nv);
    const double* v = vertices.data();
    for (std::size_t i = 0; i < nv; ++i) {
        for (int a = 0; a < 3; ++a) {
            if (!std::isfinite(v[3 * i + a]))
                value_error(std::string(who) + ": vertex " + std::to_string(i) + " has a non-finite coordinate");
            soup.points[i][a] = v[3 * i + a];
        }
    }
    auto push = [&](long long idx, std::size_t f) {
        if (idx < 0 || std::size_t(idx) >= nv)
            value_error(std::string(who) + ": face " + std::to_string(f) + " uses vertex " + std::to_string(idx) +
                        ", out of range [0, " + std::to_string(nv) + ")");
        soup.indices.push_back(static_cast<std::uint32_t>(idx));
    };
    // (m, k) arrays of int32 (what marching_cubes returns) or int64 are read in place.
    auto from_array = [&](const auto& array) {
        const std::size_t m = array.shape(0), k = array.shape(1);
        soup.indices.reserve(m * k);
        soup.face_offsets.reserve(m + 1);
        for (std::size_t f = 0; f < m; ++f) {
            for (std::size_t c = 0; c < k; ++c) push(static_cast<long long>(array.data()[f * k + c]), f);
            soup.face_offsets.push_back(static_cast<std::uint32_t>(soup.indices.size()));
        }
    };
    if (!nb::isinstance<nb::list>(faces) && !nb::isinstance<nb::tuple>(faces)) {
        nb::ndarray<const std::int32_t, nb::ndim<2>, nb::c_contig, nb::device::cpu> narrow;
        if (nb::try_cast(faces, narrow, false)) {
            from_array(narrow);
            return soup;
        }
        nb::ndarray<const std::int64_t, nb::ndim<2>, nb::c_contig, nb::device::cpu> wide;
        if (nb::try_cast(faces, wide)) {
            from_array(wide);
            return soup;
        }
    }
    // A sequence of polygons, each an iterable of vertex indices: Python ints, or anything with
    // __index__ (numpy integers). Anything else (None, str, float, a nested list, bool) is a
    // TypeError, an index too large for any mesh a ValueError; both name the face and corner.
    auto type_name = [](nb::handle h) { return std::string(Py_TYPE(h.ptr())->tp_name); };
    auto type_error = [](const std::string& message) { throw nb::type_error(message.c_str()); };
    auto corner = [&](nb::handle i, std::size_t f, std::size_t c) -> long long {
        nb::object number;
        if (!PyLong_CheckExact(i.ptr())) {
            if (PyBool_Check(i.ptr()) || !PyIndex_Check(i.ptr()))
                type_error(std::string(who) + ": face " + std::to_string(f) + ": corner " + std::to_string(c) +
                           " is a " + type_name(i) + ", not an integer vertex index");
            number = nb::steal(PyNumber_Index(i.ptr()));
            if (!number.is_valid()) throw nb::python_error();
            i = number;
        }
        int overflow = 0;
        const long long idx = PyLong_AsLongLongAndOverflow(i.ptr(), &overflow);
        if (overflow != 0)
            value_error(std::string(who) + ": face " + std::to_string(f) + " uses vertex " + nb::str(i).c_str() +
                        ", out of range [0, " + std::to_string(nv) + ")");
        return idx;
    };
    std::size_t f = 0;
    for (nb::handle polygon : faces) {
        nb::object corners = nb::steal(PyObject_GetIter(polygon.ptr()));
        if (!corners.is_valid()) {
            PyErr_Clear();
            type_error(std::string(who) + ": face " + std::to_string(f) + " is a " + type_name(polygon) +
                       ", not a sequence of vertex indices");
        }
        std::size_t c = 0;
        while (PyObject* item = PyIter_Next(corners.ptr())) {
            const nb::object i = nb::steal(item);
            push(corner(i, f, c++), f);
        }
        if (PyErr_Occurred()) throw nb::python_error();
        soup.face_offsets.push_back(static_cast<std::uint32_t>(soup.indices.size()));
        ++f;
    }
    return soup;
}

hmira::io::write_options write_options_from(bool ascii, bool big_endian, bool float32, bool attributes) {
    hmira::io::write_options o;
    o.ply = ascii        ? hmira::io::ply_encoding::ascii
            : big_endian ? hmira::io::ply_encoding::binary_big_endian
                         : hmira::io::ply_encoding::binary_little_endian;
    o.ply_coordinates = float32 ? hmira::io::ply_scalar::float32 : hmira::io::ply_scalar::float64;
    o.stl = ascii ? hmira::io::stl_encoding::ascii : hmira::io::stl_encoding::binary;
    o.write_attributes = attributes;
    return o;
}

namespace {

void write_polygons(const std::string& path, const vertex_array& vertices, nb::handle faces, bool ascii,
                    bool big_endian, bool float32) {
    const auto soup = to_soup(vertices, faces, "write_mesh");
    hmira::result<void> r;
    {
        nb::gil_scoped_release release;
        hmira::face_vertex_mesh mesh;
        r = hmira::io::assign_from_soup(mesh, soup, [&](std::size_t) { return path; });
        if (r) r = hmira::io::write_mesh(mesh, path, write_options_from(ascii, big_endian, float32, true));
    }
    check(r);
}

}  // namespace

void bind_io(nb::module_& m) {
    m.def("_write_polygons", &write_polygons, nb::arg("path"), nb::arg("vertices"), nb::arg("faces"), nb::kw_only(),
          nb::arg("ascii") = false, nb::arg("big_endian") = false, nb::arg("float32") = false,
          "Writes (vertices, faces) arrays as a mesh file; see hmira.write_mesh.");
}

}  // namespace hmira_py
