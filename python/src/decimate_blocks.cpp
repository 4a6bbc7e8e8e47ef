// python/src/decimate_blocks.cpp
// Decimation of one block for hmira.dask.decimate: a piece of a larger mesh, as arrays, with the
// vertices it shares with other blocks locked and a halo of faces that only lend their planes.
#include "common.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include <nanobind/stl/optional.h>

#include <hmira/algorithms/decimation/decimate.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

namespace hmira_py {

namespace {

using positions_in = nb::ndarray<const double, nb::ndim<2>, nb::c_contig, nb::device::cpu>;
using triangles_in = nb::ndarray<const std::int32_t, nb::ndim<2>, nb::c_contig, nb::device::cpu>;
using mask_in = nb::ndarray<const bool, nb::ndim<1>, nb::c_contig, nb::device::cpu>;
using quadrics_in = nb::ndarray<const double, nb::ndim<2>, nb::c_contig, nb::device::cpu>;

/// Decimates the triangles of one block. The first `own` triangles are the block's; the rest are a
/// halo whose vertices must all be locked, so that they never change and only add their planes to
/// the quadrics of the vertices they share with the block. With `quadrics` (10 per vertex), the
/// vertices start from them (decimate_options::start_quadrics) and the planes of the triangles are
/// not added: an earlier decimation goes on. Returns (positions, triangles, kept, error, quadrics):
/// the surviving vertices of the block's own triangles, in input order, with their new positions;
/// the block's remaining triangles indexing them; each survivor's input row; the largest collapse
/// error; and each survivor's quadric. The GIL is released from the first copy to the last.
nb::tuple decimate_block(const positions_in& positions, const triangles_in& triangles, const mask_in& locked,
                         std::size_t own, std::size_t target_faces, std::optional<double> max_error,
                         double max_normal_angle, double max_aspect_ratio, double min_angle, bool area_weighted,
                         bool fix_boundary, std::optional<double> feature_angle,
                         const std::optional<quadrics_in>& quadrics) {
    const std::size_t nv = positions.shape(0), nt = triangles.shape(0);
    if (positions.shape(1) != 3 || triangles.shape(1) != 3)
        value_error("decimate_block: positions and triangles need 3 columns");
    if (locked.shape(0) != nv) value_error("decimate_block: needs one locked flag per vertex");
    if (own > nt) value_error("decimate_block: more own triangles than triangles");
    if (quadrics && (quadrics->shape(0) != nv || quadrics->shape(1) != 10))
        value_error("decimate_block: needs 10 quadric numbers per vertex");
    const double* p = positions.data();
    const std::int32_t* t = triangles.data();
    const bool* lock = locked.data();
    const double* seeds = quadrics ? quadrics->data() : nullptr;
    hmira::decimate_options o{.target_faces = target_faces,
                              .max_error = max_error,
                              .keep_boundary = fix_boundary,
                              .max_normal_angle = max_normal_angle,
                              .max_aspect_ratio = max_aspect_ratio,
                              .min_angle = min_angle,
                              .area_weighted = area_weighted,
                              .feature_angle = feature_angle,
                              .return_quadrics = true};
    hmira::halfedge_mesh m;
    std::vector<double> out_positions, out_quadrics;
    std::vector<std::int32_t> out_triangles;
    std::vector<std::int64_t> kept;
    double error = 0;
    {
        // The arrays stay alive (the caller holds them) while the GIL is released.
        nb::gil_scoped_release release;
        for (std::size_t c = 0; c < 3 * nt; ++c)
            if (t[c] < 0 || std::size_t(t[c]) >= nv)
                throw hmira_failure(hmira::errc::invalid_argument, "decimate_block: a triangle index is out of range");
        for (std::size_t c = 3 * own; c < 3 * nt; ++c)
            if (!lock[t[c]])
                throw hmira_failure(hmira::errc::invalid_argument,
                                    "decimate_block: a halo triangle has a vertex that is not locked");
        std::vector<std::array<double, 3>> points(nv);
        for (std::size_t i = 0; i < nv; ++i) points[i] = {p[3 * i], p[3 * i + 1], p[3 * i + 2]};
        std::vector<std::uint32_t> corners(3 * nt), offsets(nt + 1);
        for (std::size_t c = 0; c < 3 * nt; ++c) corners[c] = std::uint32_t(t[c]);
        for (std::size_t f = 0; f <= nt; ++f) offsets[f] = std::uint32_t(3 * f);
        for (std::size_t i = 0; i < nv; ++i)
            if (lock[i]) o.locked_vertices.push_back(i);
        if (seeds) o.start_quadrics.assign(seeds, seeds + 10 * nv);
        check(m.assign_polygons(std::span<const std::array<double, 3>>(points), std::span<const std::uint32_t>(offsets),
                                std::span<const std::uint32_t>(corners)));
        // Unreferenced rows would become isolated vertices; decimate leaves them alone.
        auto r = take(hmira::decimate(m, o));
        error = r.error;
        // Faces keep their handles through collapses: the block's own are those below `own`.
        std::vector<std::int32_t> row(nv, -1);
        for (auto f : m.faces()) {
            if (f.index >= own) continue;
            for (auto v : m.face_vertices(f)) {
                if (row[v.index] < 0) row[v.index] = 0;
                out_triangles.push_back(std::int32_t(v.index));
            }
        }
        for (auto v : m.vertices())  // in index order
            if (row[v.index] == 0) {
                row[v.index] = std::int32_t(kept.size());
                kept.push_back(std::int64_t(v.index));
                const auto& q = m.position(v);
                out_positions.insert(out_positions.end(), {double(q.x), double(q.y), double(q.z)});
                const auto at = r.quadrics.begin() + std::ptrdiff_t(10 * v.index);
                out_quadrics.insert(out_quadrics.end(), at, at + 10);
            }
        for (auto& c : out_triangles) c = row[std::size_t(c)];
    }
    const std::size_t k = kept.size(), n = out_triangles.size() / 3;
    return nb::make_tuple(
        adopt<double>(std::move(out_positions), {k, 3}), adopt<std::int32_t>(std::move(out_triangles), {n, 3}),
        adopt<std::int64_t>(std::move(kept), {k}), error, adopt<double>(std::move(out_quadrics), {k, 10}));
}

}  // namespace

void bind_decimate_blocks(nb::module_& m) {
    const hmira::decimate_options d;
    m.def("_decimate_block", &decimate_block, nb::arg("positions"), nb::arg("triangles"), nb::arg("locked"),
          nb::kw_only(), nb::arg("own"), nb::arg("target_faces"), nb::arg("max_error") = nb::none(),
          nb::arg("max_normal_angle") = d.max_normal_angle, nb::arg("max_aspect_ratio") = d.max_aspect_ratio,
          nb::arg("min_angle") = d.min_angle, nb::arg("area_weighted") = d.area_weighted,
          nb::arg("fix_boundary") = d.keep_boundary, nb::arg("feature_angle") = nb::none(),
          nb::arg("quadrics") = nb::none(),
          "Decimates one block (the first `own` triangles; the rest a halo of locked vertices lending their "
          "planes), starting from `quadrics` (10 per vertex) when given, to (positions, triangles, kept input rows, "
          "largest error, their quadrics); see hmira.dask.decimate.");
}

}  // namespace hmira_py
