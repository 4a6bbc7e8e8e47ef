// hmira/io/detail/face_loops.hpp
// How the writers see a face's loops: the STL writer's triangles (face_triangles for every face
// that is not a plain triangle), and the check that OBJ/OFF/PLY, which store one loop per face,
// are not asked to write a face with inner rings.
#pragma once

#include <array>
#include <cmath>
#include <cstdio>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "../../algorithms/triangulation/triangulate_faces.hpp"
#include "../../concepts.hpp"
#include "../../core/result.hpp"

namespace hmira::io::detail {

/// The name of face f in an error message: its index where the model has one, else its
/// position in T::faces order (`ordinal`).
template <class M, class T>
std::string face_name(const M& mesh, typename T::face_handle f, std::size_t ordinal) {
    if constexpr (face_index_mesh<M, T>)
        return "face " + std::to_string(T::face_index(mesh, f));
    else
        return "face #" + std::to_string(ordinal) + " (in faces() order)";
}

template <class M, class T>
long long face_number(const M& mesh, typename T::face_handle f, std::size_t ordinal) {
    if constexpr (face_index_mesh<M, T>)
        return static_cast<long long>(T::face_index(mesh, f));
    else
        return static_cast<long long>(ordinal);
}

/// Whether face f has inner rings (never, for a model without them).
template <class M, class T>
bool has_inner_rings(const M& mesh, typename T::face_handle f) {
    if constexpr (inner_ring_mesh<M, T>) {
        for (auto r : T::inner_rings(mesh, f)) return (void)r, true;
    } else {
        (void)mesh, (void)f;
    }
    return false;
}

/// OBJ, OFF and PLY store one vertex loop per face, so a face with inner rings cannot be
/// written without losing its rings: refuse it, naming it (errc::unsupported). O(F).
template <class M, class T>
result<void> refuse_ringed_faces(const M& mesh, const char* format) {
    if constexpr (inner_ring_mesh<M, T>) {
        std::size_t ordinal = 0;
        for (auto f : T::faces(mesh)) {
            if (has_inner_rings<M, T>(mesh, f))
                return fail(
                    errc::unsupported,
                    std::string(format) + " writer: " + face_name<M, T>(mesh, f, ordinal) +
                        " has inner rings, which the format cannot store; cut it first with triangulate_faces(mesh)",
                    face_number<M, T>(mesh, f, ordinal));
            ++ordinal;
        }
    } else {
        (void)mesh, (void)format;
    }
    return {};
}

/// The triangles the STL writer emits for the faces that are not plain triangles, in T::faces
/// order: `counts[i]` triangles of the i-th such face, taken in turn from `triangles`.
template <class M, class T>
struct stl_triangles {
    std::vector<std::uint32_t> counts;
    std::vector<std::array<typename T::vertex_handle, 3>> triangles;
    std::uint64_t total = 0;  ///< all triangles the file will hold, plain ones included
};

/// Plans the STL triangles. A triangle without rings is written as itself (no projection).
/// Every other face goes through face_triangles, which handles concave faces and inner rings
/// with exact predicates. A face it refuses as degenerate (no projected area, e.g. a bevel
/// face at its clamp limit) or for non-finite corners is fanned from its first corner: the fan
/// has zero area as well (or carries the same non-finite coordinates a triangle would), so
/// nothing is drawn that the face did not cover. A face whose projection is not simple
/// (errc::topology) is an error naming the face.
/// Models without face indices (face_triangulable_mesh not satisfied) keep the fan, which is
/// exact only for convex faces without rings. Complexity: O(F) plus face_triangles' cost on
/// the faces that are not triangles.
template <class M, class T>
result<stl_triangles<M, T>> plan_stl_triangles(const M& mesh) {
    stl_triangles<M, T> plan;
    std::vector<typename T::vertex_handle> loop;
    std::size_t ordinal = 0;
    for (auto f : T::faces(mesh)) {
        loop.clear();
        for (auto v : T::face_vertices(mesh, f)) loop.push_back(v);
        const bool ringed = has_inner_rings<M, T>(mesh, f);
        if (loop.size() == 3 && !ringed) {
            ++plan.total;
            ++ordinal;
            continue;
        }
        const std::size_t before = plan.triangles.size();
        bool fan = true;
        if constexpr (face_triangulable_mesh<M, T>) {
            auto tris = face_triangles<M, T>(mesh, f);
            if (tris) {
                plan.triangles.insert(plan.triangles.end(), tris->begin(), tris->end());
                fan = false;
            } else if (tris.error().code != errc::degenerate_face && tris.error().code != errc::invalid_argument) {
                return fail(tris.error().code, "STL writer: " + tris.error().message, tris.error().element);
            }
        }
        if (fan)
            for (std::size_t i = 1; i + 1 < loop.size(); ++i) plan.triangles.push_back({loop[0], loop[i], loop[i + 1]});
        const std::size_t added = plan.triangles.size() - before;
        if (added > UINT32_MAX)
            return fail(errc::unsupported, "STL writer: " + face_name<M, T>(mesh, f, ordinal) + " has too many corners",
                        face_number<M, T>(mesh, f, ordinal));
        plan.counts.push_back(static_cast<std::uint32_t>(added));
        plan.total += added;
        ++ordinal;
    }
    return plan;
}

/// No file of any format holds a non-finite coordinate: refuse one, naming the vertex
/// (errc::unsupported, its index as the element). `as_float`: the format stores float, so a
/// coordinate beyond float's range, which would become infinite, is refused too. O(V).
template <class M, class T>
result<void> refuse_non_finite(const M& mesh, const char* format, bool as_float = false) {
    std::size_t ordinal = 0;
    for (auto v : T::vertices(mesh)) {
        const auto p = T::position(mesh, v);
        for (std::size_t k = 0; k < 3; ++k) {
            const double x = static_cast<double>(p[k]);
            const bool finite = std::isfinite(x);
            if (finite && !(as_float && !std::isfinite(static_cast<float>(x)))) continue;
            const long long index = [&] {
                if constexpr (vertex_index_mesh<M, T>)
                    return static_cast<long long>(T::vertex_index(mesh, v));
                else
                    return static_cast<long long>(ordinal);
            }();
            char shown[32];
            std::snprintf(shown, sizeof shown, "%g", x);
            const std::string why = finite ? std::string(" has a coordinate (") + shown +
                                                 ") beyond the range of float (about 3.4e38), which this file stores"
                                           : " has a coordinate that is not finite (NaN or infinity)";
            return fail(errc::unsupported,
                        std::string(format) + " writer: vertex " + std::to_string(index) + why + "; nothing is written",
                        index);
        }
        ++ordinal;
    }
    return {};
}

/// What OBJ, OFF and PLY check before writing a byte: no face with inner rings, no
/// coordinate the file cannot hold.
template <class M, class T>
result<void> refuse_unwritable(const M& mesh, const char* format, bool as_float = false) {
    if (auto ok = refuse_ringed_faces<M, T>(mesh, format); !ok) return ok;
    return refuse_non_finite<M, T>(mesh, format, as_float);
}

/// `e` with the file's name in front, for the errors of write_obj and the other path writers.
inline hmira::error at_path(const std::filesystem::path& path, hmira::error e) {
    e.message = path.string() + ": " + e.message;
    return e;
}

/// The error of a writer whose stream refused the data.
inline hmira::error stream_failed(const char* format) {
    return fail(errc::io_error, std::string(format) + " writer: the output stream failed");
}

}  // namespace hmira::io::detail
