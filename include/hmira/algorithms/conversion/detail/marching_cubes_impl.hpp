// hmira/algorithms/conversion/detail/marching_cubes_impl.hpp
// The definitions of marching_cubes.hpp's entry points, and the undo of a partial insertion that
// makes marching_cubes() atomic. Included at the end of marching_cubes.hpp.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "marching_cubes_extractor.hpp"
#include "parallel.hpp"

namespace hmira {

namespace detail::mc {

// Why insertion can be undone cheaply: the surface gets vertices of its own, so adding its
// triangles links only elements that did not exist before. Erasing the new faces, edges and
// vertices therefore restores every old element exactly (same handles, links, positions and
// property values); only index bounds and garbage grow. The mesh is never copied.

/// Whether marching_cubes() can take back what it added to an M through T, and so give the
/// strong guarantee. True of every halfedge_mutable_mesh (erase marks, O(1) each), and of a
/// model that removes faces and vertices itself (face_vertex_mesh).
template <class M, class T>
constexpr bool can_undo_insertion =
    halfedge_mutable_mesh<M, T> || (face_removal_mesh<M, T> && vertex_removal_mesh<M, T>);

/// Takes back `faces` (triangles, in creation order) and then `vertices`, all created by this
/// insertion. Allocates nothing on the half-edge path. O(added elements), except that a model
/// without halfedges and without a batch remove_vertices pays its own remove_vertex per vertex.
template <class M, class T>
void undo_insertion(M& m, std::span<const typename T::face_handle> faces,
                    std::span<const typename T::vertex_handle> vertices) noexcept {
    if constexpr (halfedge_mutable_mesh<M, T>) {
        // Newest face first. A face's sides are cut loose from it (set to no face) before its
        // edges are looked at, so an edge is erased by the last of its (one or two) new faces
        // to be undone: exactly once, with no set of visited edges to allocate.
        for (auto it = faces.rbegin(); it != faces.rend(); ++it) {
            const auto f = *it;
            const auto h0 = T::face_halfedge(m, f);
            const std::array<typename T::halfedge_handle, 3> sides{h0, T::next(m, h0), T::next(m, T::next(m, h0))};
            for (auto h : sides) T::set_face(m, h, T::null_face());
            for (auto h : sides)
                if (T::face(m, T::opposite(m, h)) == T::null_face()) T::erase_edge(m, T::edge(m, h));
            T::erase_face(m, f);
        }
        for (auto v : vertices) T::erase_vertex(m, v);
    } else {
        // The handles were just created, so these removals cannot fail.
        for (auto it = faces.rbegin(); it != faces.rend(); ++it)
            if (!T::remove_face(m, *it)) break;
        if constexpr (bulk_vertex_removal_mesh<M, T>) {
            if (!T::remove_vertices(m, vertices)) return;
        } else {
            for (auto v : vertices)
                if (!T::remove_vertex(m, v)) break;
        }
    }
}

}  // namespace detail::mc

template <class S, voxel_grid G>
result<indexed_triangles<S>> marching_cubes_indexed(const G& grid, const marching_cubes_options& options) {
    if (auto ok = check_grid_geometry(geometry_of(grid), "marching_cubes", 2); !ok) return ok.error();
    if (!std::isfinite(options.iso))
        return fail(errc::invalid_argument, "marching_cubes: the iso value must be finite");
    result<indexed_triangles<S>> out = fail(errc::invalid_argument, "");
    detail::with_thread_count(options.threads,
                              [&] { out = detail::mc::extractor<G>(grid, options).template run<S>(); });
    return out;
}

template <class M, class T, voxel_grid G>
    requires mesh_builder<M, T>
result<marching_cubes_output<M, T>> marching_cubes(M& mesh, const G& grid, const marching_cubes_options& options) {
    using S = typename T::scalar;
    using VH = typename T::vertex_handle;
    using FH = typename T::face_handle;
    marching_cubes_options extraction = options;
    if (options.progress) extraction.progress = [&](double done) { return options.progress(0.5 * done); };
    auto tri = marching_cubes_indexed<S>(grid, extraction);
    if (!tri) return tri.error();

    marching_cubes_output<M, T> out;
    out.vertices.reserve(tri->positions.size());
    out.faces.reserve(tri->triangles.size());
    constexpr bool undoable = detail::mc::can_undo_insertion<M, T>;
    if constexpr (undoable)
        if constexpr (erase_preparing_mesh<M, T>) T::prepare_erase(mesh);

    const std::size_t total = tri->positions.size() + tri->triangles.size();
    const std::size_t block = std::max<std::size_t>(total / 64, 1);
    std::size_t done = 0;
    // Reports after every `block` elements and after the last; false once the caller cancels.
    auto keep_going = [&] {
        ++done;
        if (!options.progress || (done % block != 0 && done != total)) return true;
        return options.progress(0.5 + 0.5 * double(done) / double(total));
    };
    auto undo = [&] {
        if constexpr (undoable) detail::mc::undo_insertion<M, T>(mesh, out.faces, out.vertices);
    };
    try {
        for (const auto& p : tri->positions) {
            out.vertices.push_back(T::add_vertex(mesh, p));
            if (!keep_going()) {
                undo();
                return fail(errc::cancelled, "marching_cubes: cancelled");
            }
        }
        for (std::size_t i = 0; i < tri->triangles.size(); ++i) {
            const auto& t = tri->triangles[i];
            const std::array<VH, 3> vs{out.vertices[t[0]], out.vertices[t[1]], out.vertices[t[2]]};
            result<FH> f = T::add_face(mesh, std::span<const VH>(vs));
            if (!f) {
                undo();
                return fail(
                    f.error().code,
                    "marching_cubes: triangle " + std::to_string(i) + " refused by the mesh: " + f.error().message,
                    static_cast<long long>(i));
            }
            out.faces.push_back(f.value());
            if (!keep_going()) {
                undo();
                return fail(errc::cancelled, "marching_cubes: cancelled");
            }
        }
    } catch (...) {
        undo();
        throw;
    }
    out.normals.assign(tri->normals.begin(), tri->normals.end());
    return out;
}

}  // namespace hmira
