// python/src/conversion.cpp
// Marching cubes on any 3-D numpy volume without copying it, and voxelization of (V, F) arrays.
// Outputs are numpy arrays that take over the C++ vectors (no copy on the way out).
#include "common.hpp"

#include <nanobind/stl/array.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <ranges>
#include <span>
#include <string>
#include <vector>

#include <hmira/algorithms/conversion/iso_level.hpp>
#include <hmira/algorithms/conversion/marching_cubes.hpp>
#include <hmira/algorithms/conversion/voxelize.hpp>
#include <hmira/algorithms/conversion/voxelize_blocks.hpp>
#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

namespace hmira_py {

namespace {

constexpr const char* MC_DOC = R"doc(Extract the iso-surface of a 3-D volume as a welded, closed triangle mesh.

Parameters
----------
volume : ndarray, shape (n0, n1, n2)
    Samples of any float, integer or bool dtype (hmira.marching_cubes also takes
    nested lists); C- or Fortran-ordered or strided, read in place (never copied).
    A NaN or infinite sample raises ValueError naming it ("volume[3, 4, 5] is inf").
iso : float, optional
    The iso value, within the samples' range [min, max]: outside it there is no
    surface, and ValueError names the range. Default: the midpoint of the range
    (as scikit-image), so a default never gives an empty mesh. A signed distance
    field wants ``iso=0.0``; scans (CT, MRI) want ``inside="above"``, e.g.
    ``hmira.marching_cubes(ct, 300.0, inside="above")``.
spacing : sequence of 3 floats, keyword-only
    Distance between samples along array axes 0, 1, 2.
origin : sequence of 3 floats, keyword-only
    Position of sample [0, 0, 0].
inside : {"below", "above"}, keyword-only
    Which side of `iso` is the solid ("below" for signed distances, "above" for
    CT/MRI scans and label maps). Triangles wind counter-clockwise seen from outside
    the solid: a label map or scan left at "below" takes the background for the
    solid and comes out inside-out (``hmira.Mesh(v, f).volume()`` is negative).
threads : int, keyword-only
    Worker threads (0: all cores). The output does not depend on it.

Returns
-------
vertices : ndarray of float64, shape (n, 3)
    Column j is the coordinate along array axis j (as scikit-image).
faces : ndarray of int32, shape (m, 3)

Notes
-----
The GIL is released while the surface is extracted; Ctrl-C stops it between
z-slices (KeyboardInterrupt).

Examples
--------
>>> import numpy as np, hmira
>>> x, y, z = np.mgrid[-1:1:32j, -1:1:32j, -1:1:32j]
>>> v, f = hmira.marching_cubes(x**2 + y**2 + z**2 - 0.5, 0.0)  # the zero level of a distance
>>> v.shape[1], f.dtype.name, len(f) == 2 * len(v) - 4
(3, 'int32', True)
)doc";

using hmira::vec3;

/// A numpy volume seen as a grid whose x runs along memory: sample (i, j, k) at
/// data[i + nx * (j + ny * k)].
template <class V>
struct contiguous_view {
    using value_type = V;
    const V* samples;
    hmira::grid_dims size;
    vec3<double> at, step;
    hmira::grid_dims dims() const { return size; }
    vec3<double> origin() const { return at; }
    vec3<double> spacing() const { return step; }
    double value(std::size_t i, std::size_t j, std::size_t k) const {
        return static_cast<double>(samples[i + size[0] * (j + size[1] * k)]);
    }
    const V* data() const { return samples; }
    bool c_order = false;  // the grid's x is array axis 2
    /// How an error names sample (i, j, k): by its index in the caller's array.
    std::string sample_name(std::size_t i, std::size_t j, std::size_t k) const {
        const std::size_t a = c_order ? k : i, c = c_order ? i : k;
        return "volume[" + std::to_string(a) + ", " + std::to_string(j) + ", " + std::to_string(c) + "]";
    }
};

/// Any strided numpy volume, read sample by sample: (i, j, k) is array index [i, j, k].
template <class V>
struct strided_view {
    using value_type = V;
    const V* samples;
    hmira::grid_dims size;
    std::int64_t stride[3];  // in elements, possibly negative
    vec3<double> at, step;
    hmira::grid_dims dims() const { return size; }
    vec3<double> origin() const { return at; }
    vec3<double> spacing() const { return step; }
    double value(std::size_t i, std::size_t j, std::size_t k) const {
        return static_cast<double>(
            samples[std::int64_t(i) * stride[0] + std::int64_t(j) * stride[1] + std::int64_t(k) * stride[2]]);
    }
    std::string sample_name(std::size_t i, std::size_t j, std::size_t k) const {
        return "volume[" + std::to_string(i) + ", " + std::to_string(j) + ", " + std::to_string(k) + "]";
    }
};

vec3<double> triple(const std::vector<double>& v, const char* name) {
    if (v.size() != 3)
        value_error(std::string("marching_cubes: ") + name + " needs 3 values, got " + std::to_string(v.size()));
    return {v[0], v[1], v[2]};
}

using mc_volume = nb::ndarray<nb::ro, nb::ndim<3>, nb::device::cpu>;

/// Marching cubes over grid `g`; without an iso, at the midpoint of its samples' range (the library's
/// default_iso, as scikit-image). A range that cannot be read (a non-finite sample) is left for
/// marching cubes to report, naming the sample as the caller's array indexes it.
template <hmira::voxel_grid G>
hmira::result<hmira::indexed_triangles<double>> run_mc(const G& g, hmira::marching_cubes_options options,
                                                       bool iso_given) {
    if (!iso_given)
        if (auto iso = hmira::default_iso(g)) options.iso = *iso;
    return hmira::marching_cubes_indexed<double>(g, options);
}

template <class V>
hmira::result<hmira::indexed_triangles<double>> extract(const mc_volume& volume, const vec3<double>& spacing,
                                                        const vec3<double>& origin,
                                                        const hmira::marching_cubes_options& options, bool iso_given,
                                                        bool& swapped) {
    const auto* p = static_cast<const V*>(volume.data());
    const std::size_t n0 = volume.shape(0), n1 = volume.shape(1), n2 = volume.shape(2);
    const std::int64_t s0 = volume.stride(0), s1 = volume.stride(1), s2 = volume.stride(2);
    // A stride only matters along an axis longer than 1.
    auto fits = [](std::size_t n, std::int64_t s, std::int64_t want) { return n <= 1 || s == want; };
    swapped = false;
    if (fits(n0, s0, 1) && fits(n1, s1, std::int64_t(n0)) && fits(n2, s2, std::int64_t(n0 * n1))) {
        // Fortran order: array axis 0 runs along memory, as the grid's x does.
        const contiguous_view<V> g{p, {n0, n1, n2}, origin, spacing};
        return run_mc(g, options, iso_given);
    }
    if (fits(n2, s2, 1) && fits(n1, s1, std::int64_t(n2)) && fits(n0, s0, std::int64_t(n1 * n2))) {
        // C order: the grid's x is array axis 2; the caller swaps columns 0 and 2 back.
        swapped = true;
        const contiguous_view<V> g{
            p, {n2, n1, n0}, {origin.z, origin.y, origin.x}, {spacing.z, spacing.y, spacing.x}, true};
        return run_mc(g, options, iso_given);
    }
    const strided_view<V> g{p, {n0, n1, n2}, {s0, s1, s2}, origin, spacing};
    return run_mc(g, options, iso_given);
}

std::pair<nb::ndarray<nb::numpy, double>, nb::ndarray<nb::numpy, std::int32_t>> marching_cubes(
    const mc_volume& volume, std::optional<double> iso, const std::vector<double>& spacing,
    const std::vector<double>& origin, const std::string& inside, unsigned threads) {
    const auto sp = triple(spacing, "spacing"), org = triple(origin, "origin");
    interrupt_watch watch;
    hmira::marching_cubes_options options{.iso = iso.value_or(0.0),
                                          .inside = choice_arg<hmira::iso_inside>(inside, "marching_cubes", "inside"),
                                          .normals = false,
                                          .threads = threads,
                                          .progress = watch.callback()};
    const auto dt = volume.dtype();
    hmira::result<hmira::indexed_triangles<double>> r = hmira::fail(hmira::errc::invalid_argument, "");
    bool swapped = false;
    {
        nb::gil_scoped_release release;
        cpp_timer timer;
        const bool given = iso.has_value();
        if (dt == nb::dtype<float>())
            r = extract<float>(volume, sp, org, options, given, swapped);
        else if (dt == nb::dtype<double>())
            r = extract<double>(volume, sp, org, options, given, swapped);
        else if (dt == nb::dtype<std::uint8_t>())
            r = extract<std::uint8_t>(volume, sp, org, options, given, swapped);
        else if (dt == nb::dtype<std::uint16_t>())
            r = extract<std::uint16_t>(volume, sp, org, options, given, swapped);
        else if (dt == nb::dtype<std::int16_t>())
            r = extract<std::int16_t>(volume, sp, org, options, given, swapped);
        else if (dt == nb::dtype<std::int8_t>())
            r = extract<std::int8_t>(volume, sp, org, options, given, swapped);
        else if (dt == nb::dtype<std::int32_t>())
            r = extract<std::int32_t>(volume, sp, org, options, given, swapped);
        else if (dt == nb::dtype<std::uint32_t>())
            r = extract<std::uint32_t>(volume, sp, org, options, given, swapped);
        else if (dt == nb::dtype<std::int64_t>())
            r = extract<std::int64_t>(volume, sp, org, options, given, swapped);
        else if (dt == nb::dtype<std::uint64_t>())
            r = extract<std::uint64_t>(volume, sp, org, options, given, swapped);
        else if (dt == nb::dtype<bool>())
            r = extract<bool>(volume, sp, org, options, given, swapped);
        else
            r = hmira::fail(hmira::errc::invalid_argument,
                            "marching_cubes: volume dtype must be a float (float32, float64), an integer (int8 to "
                            "int64, uint8 to uint64) or bool");
    }
    watch.rethrow();
    auto tri = take(std::move(r));
    if (tri.positions.size() > std::size_t(std::numeric_limits<std::int32_t>::max()))
        value_error("marching_cubes: " + std::to_string(tri.positions.size()) +
                    " vertices do not fit int32 face indices (at most 2^31 - 1)");
    if (swapped) {
        // Swapping two axes mirrors the surface: swap the coordinates back and reverse each
        // triangle so that it still winds counter-clockwise seen from outside.
        for (auto& p : tri.positions) std::swap(p.x, p.z);
        for (auto& t : tri.triangles) std::swap(t[1], t[2]);
    }
    const std::size_t nv = tri.positions.size(), nt = tri.triangles.size();
    static_assert(sizeof(vec3<double>) == 3 * sizeof(double) &&
                  sizeof(std::array<std::uint32_t, 3>) == 3 * sizeof(std::int32_t));
    auto vertices = adopt<double>(std::move(tri.positions), {nv, 3});
    auto faces = adopt<std::int32_t>(std::move(tri.triangles), {nt, 3});
    return {vertices, faces};
}

/// (V, F) numpy arrays seen as a mesh in place, without building one: what voxelize reads
/// when the faces come as an (m, k) integer array. The indices must have been checked.
template <class I>
struct array_mesh {
    const double* points;
    std::size_t vertices;
    const I* corners;
    std::size_t faces, corners_per_face;
};

/// The traits of array_mesh: handles are the array indices.
template <class I>
struct array_mesh_traits {
    using M = array_mesh<I>;
    using vertex_handle = std::size_t;
    using face_handle = std::size_t;
    using scalar = double;
    static auto vertices(const M& m) { return std::views::iota(std::size_t(0), m.vertices); }
    static std::size_t vertex_count(const M& m) { return m.vertices; }
    static auto faces(const M& m) { return std::views::iota(std::size_t(0), m.faces); }
    static std::size_t face_count(const M& m) { return m.faces; }
    static std::span<const I> face_vertices(const M& m, std::size_t f) {
        return {m.corners + f * m.corners_per_face, m.corners_per_face};
    }
    static vec3<double> position(const M& m, std::size_t v) {
        return {m.points[3 * v], m.points[3 * v + 1], m.points[3 * v + 2]};
    }
    static std::size_t vertex_index(const M&, std::size_t v) { return v; }
    static std::size_t vertex_index_bound(const M& m) { return m.vertices; }
};

/// The first corner of `faces` (an (m, k) array) outside [0, vertices), as a ValueError
/// naming the face, as to_soup reports it.
template <class I>
void check_corners(const I* corners, std::size_t faces, std::size_t k, std::size_t vertices, const char* who) {
    std::size_t bad = faces * k;
    {
        nb::gil_scoped_release release;
        for (std::size_t c = 0; c < faces * k; ++c)
            if (corners[c] < 0 || std::size_t(corners[c]) >= vertices) {
                bad = c;
                break;
            }
    }
    if (bad < faces * k)
        value_error(std::string(who) + ": face " + std::to_string(bad / k) + " uses vertex " +
                    std::to_string(corners[bad]) + ", out of range [0, " + std::to_string(vertices) + ")");
}

/// The first vertex with a NaN or infinite coordinate, as a ValueError naming it (as to_soup).
void check_points(const double* points, std::size_t vertices, const char* who) {
    std::size_t bad = vertices;
    {
        nb::gil_scoped_release release;
        for (std::size_t c = 0; c < 3 * vertices; ++c)
            if (!std::isfinite(points[c])) {
                bad = c / 3;
                break;
            }
    }
    if (bad < vertices)
        value_error(std::string(who) + ": vertex " + std::to_string(bad) + " has a non-finite coordinate");
}

/// The grid hmira.voxelize uses: `resolution` voxels (256 by default) along the longest side
/// plus two empty layers, or voxels of size `pitch` over the same centred box.
template <class M, class T>
hmira::result<hmira::grid_geometry> voxel_grid_for(const M& mesh, std::optional<std::size_t> resolution,
                                                   std::optional<double> pitch) {
    auto g = hmira::voxel_grid_around<M, T>(mesh, resolution.value_or(256), 2);
    if (!g || !pitch) return g;
    hmira::grid_geometry geometry = *g;
    // The box voxel_grid_around centres on the mesh, with the voxel size given.
    for (int a = 0; a < 3; ++a) {
        const double centre = g->origin[a] + 0.5 * double(g->dims[a] - 1) * g->spacing[a];
        const double extent = double(g->dims[a] - 4) * g->spacing[a];
        const double n = std::ceil(extent / *pitch - 1e-9);
        if (!(n < 65536))
            return hmira::fail(hmira::errc::invalid_argument,
                               "voxelize: pitch too small for the mesh (more than 65536 voxels along an axis)");
        geometry.dims[a] = std::max<std::size_t>(std::size_t(n), 1) + 4;
        geometry.spacing[a] = *pitch;
        geometry.origin[a] = centre - 0.5 * double(geometry.dims[a] - 1) * *pitch;
    }
    return geometry;
}

/// (V, F) read in place as a mesh when F is an (m, k) int32/int64 array, else through a soup
/// and a face_vertex_mesh; run(mesh) is called on it with the GIL released.
class mesh_view {
public:
    mesh_view(const vertex_array& vertices, nb::handle faces, const char* who) : vertices_(vertices) {
        if (vertices.shape(1) != 3)
            value_error(std::string(who) + ": vertices must have shape (n, 3), got (" +
                        std::to_string(vertices.shape(0)) + ", " + std::to_string(vertices.shape(1)) + ")");
        const bool is_list = nb::isinstance<nb::list>(faces) || nb::isinstance<nb::tuple>(faces);
        const bool in_place_narrow = !is_list && nb::try_cast(faces, narrow_, false);
        const bool in_place_wide = !is_list && !in_place_narrow && nb::try_cast(faces, wide_, false);
        if (in_place_narrow || in_place_wide) check_points(vertices.data(), vertices.shape(0), who);
        if (in_place_narrow) {
            check_corners(narrow_.data(), narrow_.shape(0), narrow_.shape(1), vertices.shape(0), who);
            narrow_mesh_ = array_mesh<std::int32_t>{vertices.data(), vertices.shape(0), narrow_.data(),
                                                    narrow_.shape(0), narrow_.shape(1)};
        } else if (in_place_wide) {
            check_corners(wide_.data(), wide_.shape(0), wide_.shape(1), vertices.shape(0), who);
            wide_mesh_ = array_mesh<std::int64_t>{vertices.data(), vertices.shape(0), wide_.data(), wide_.shape(0),
                                                  wide_.shape(1)};
        } else {
            soup_ = to_soup(vertices, faces, who);
        }
        who_ = who;
    }
    /// Calls run.template operator()<M, T>(mesh); call with the GIL released.
    template <class R, class Run>
    R visit(Run&& run) const {
        if (narrow_mesh_)
            return run.template operator()<array_mesh<std::int32_t>, array_mesh_traits<std::int32_t>>(*narrow_mesh_);
        if (wide_mesh_)
            return run.template operator()<array_mesh<std::int64_t>, array_mesh_traits<std::int64_t>>(*wide_mesh_);
        hmira::face_vertex_mesh mesh;
        const std::string who = who_;
        auto built = hmira::io::assign_from_soup(mesh, *soup_, [&](std::size_t) { return who; });
        if (!built) return built.error();
        return run.template operator()<hmira::face_vertex_mesh, hmira::default_traits<hmira::face_vertex_mesh>>(mesh);
    }

private:
    const vertex_array& vertices_;
    nb::ndarray<const std::int32_t, nb::ndim<2>, nb::c_contig, nb::device::cpu> narrow_;
    nb::ndarray<const std::int64_t, nb::ndim<2>, nb::c_contig, nb::device::cpu> wide_;
    std::optional<array_mesh<std::int32_t>> narrow_mesh_;
    std::optional<array_mesh<std::int64_t>> wide_mesh_;
    std::optional<hmira::io::polygon_soup> soup_;
    std::string who_;
};

/// Expands the bits of `v` into one bool byte per voxel, x fastest (Fortran order of [i, j, k]),
/// eight voxels at a time by table, in parallel over z slices.
void expand_bits(const hmira::bit_grid& v, std::uint8_t* cells, unsigned threads) {
    static_assert(std::endian::native == std::endian::little, "the bit expansion table assumes little endian");
    static const auto expand = [] {
        std::array<std::uint64_t, 256> t{};
        for (unsigned b = 0; b < 256; ++b)
            for (unsigned q = 0; q < 8; ++q)
                if ((b >> q) & 1u) t[b] |= std::uint64_t(1) << (8 * q);
        return t;
    }();
    const auto d = v.dims();
    hmira::detail::with_thread_count(threads, [&] {
        hmira::detail::parallel_chunks(d[2], 1, [&](std::size_t k0, std::size_t k1) {
            for (std::size_t k = k0; k < k1; ++k)
                for (std::size_t j = 0; j < d[1]; ++j) {
                    const std::uint64_t* row = v.row(j, k);
                    std::uint8_t* out = cells + d[0] * (j + d[1] * k);
                    const std::size_t full = d[0] / 8;
                    for (std::size_t q = 0; q < full; ++q) {
                        const auto byte = static_cast<unsigned>((row[q >> 3] >> (8 * (q & 7))) & 0xffu);
                        std::memcpy(out + 8 * q, &expand[byte], 8);  // little-endian: bit q -> byte q
                    }
                    for (std::size_t i = 8 * full; i < d[0]; ++i)
                        out[i] = static_cast<std::uint8_t>((row[i >> 6] >> (i & 63)) & 1u);
                }
        });
    });
}

/// A numpy bool array of shape dims, Fortran order, owning `cells`.
nb::ndarray<nb::numpy, bool, nb::ndim<3>> bool_grid(std::unique_ptr<std::uint8_t[]> cells, const hmira::grid_dims& d) {
    auto* owned = cells.release();
    nb::capsule owner(owned, [](void* p) noexcept { delete[] static_cast<std::uint8_t*>(p); });
    const std::size_t shape[3] = {d[0], d[1], d[2]};
    const std::int64_t strides[3] = {1, std::int64_t(d[0]), std::int64_t(d[0] * d[1])};
    return nb::ndarray<nb::numpy, bool, nb::ndim<3>>(reinterpret_cast<bool*>(owned), 3, shape, owner, strides);
}

nb::tuple voxelize(const vertex_array& vertices, nb::handle faces, std::optional<std::size_t> resolution,
                   std::optional<double> pitch, const std::string& mode, bool fill_open, unsigned threads) {
    const auto named_mode = choice_arg<hmira::voxelize_mode>(mode, "voxelize", "mode");
    if (resolution && pitch) value_error("voxelize: give resolution or pitch, not both");
    if (resolution && *resolution == 0) value_error("voxelize: resolution must be at least 1");
    if (pitch && !(*pitch > 0 && std::isfinite(*pitch))) value_error("voxelize: pitch must be finite and > 0");
    const mesh_view view(vertices, faces, "voxelize");
    interrupt_watch watch;
    const hmira::voxelize_options options{
        .mode = named_mode,
        .open_mesh = fill_open ? hmira::open_mesh_fill::winding_number : hmira::open_mesh_fill::surface_only,
        .allow_degenerate = true,
        .threads = threads,
        .progress = watch.callback()};
    hmira::result<hmira::voxelization> r = hmira::fail(hmira::errc::invalid_argument, "");
    hmira::grid_geometry geometry;
    std::unique_ptr<std::uint8_t[]> cells;
    {
        nb::gil_scoped_release release;
        // The C++ work timed for bench/python: the grid around the mesh, the voxelization, and
        // the bools numpy gets, expanded from the bits in parallel (every byte is written: no
        // zeroing first).
        r = view.visit<hmira::result<hmira::voxelization>>(
            [&]<class M, class T>(const M& mesh) -> hmira::result<hmira::voxelization> {
                cpp_timer timer;
                auto g = voxel_grid_for<M, T>(mesh, resolution, pitch);
                if (!g) return g.error();
                geometry = *g;
                auto v = hmira::voxelize<M, T>(mesh, geometry, options);
                if (!v) return v;
                cells.reset(new std::uint8_t[geometry.dims[0] * geometry.dims[1] * geometry.dims[2]]);
                expand_bits(v->voxels, cells.get(), threads);
                return v;
            });
    }
    watch.rethrow();
    auto v = take(std::move(r));
    auto origin = nb::make_tuple(geometry.origin.x, geometry.origin.y, geometry.origin.z);
    return nb::make_tuple(bool_grid(std::move(cells), geometry.dims), origin, geometry.spacing.x, v.filled, v.note);
}

/// The grid hmira.voxelize would use: (dims, origin, pitch).
nb::tuple voxel_grid(const vertex_array& vertices, std::optional<std::size_t> resolution, std::optional<double> pitch) {
    if (resolution && pitch) value_error("voxelize: give resolution or pitch, not both");
    if (resolution && *resolution == 0) value_error("voxelize: resolution must be at least 1");
    if (pitch && !(*pitch > 0 && std::isfinite(*pitch))) value_error("voxelize: pitch must be finite and > 0");
    if (vertices.shape(1) != 3) value_error("voxelize: vertices must have shape (n, 3)");
    check_points(vertices.data(), vertices.shape(0), "voxelize");
    const array_mesh<std::int32_t> points{vertices.data(), vertices.shape(0), nullptr, 0, 3};
    auto g = take(voxel_grid_for<array_mesh<std::int32_t>, array_mesh_traits<std::int32_t>>(points, resolution, pitch));
    return nb::make_tuple(nb::make_tuple(g.dims[0], g.dims[1], g.dims[2]),
                          nb::make_tuple(g.origin.x, g.origin.y, g.origin.z), g.spacing.x);
}

/// One block of the grid (dims, origin, pitch): voxels [lo, lo + shape) as a bool array.
nb::ndarray<nb::numpy, bool, nb::ndim<3>> voxelize_block(const vertex_array& vertices, nb::handle faces,
                                                         std::array<std::size_t, 3> dims, std::array<double, 3> origin,
                                                         double pitch, std::array<std::size_t, 3> lo,
                                                         std::array<std::size_t, 3> shape, const std::string& mode,
                                                         bool fill_open, unsigned threads) {
    const auto named_mode = choice_arg<hmira::voxelize_mode>(mode, "voxelize", "mode");
    if (!(pitch > 0 && std::isfinite(pitch))) value_error("voxelize: pitch must be finite and > 0");
    const mesh_view view(vertices, faces, "voxelize");
    const hmira::grid_geometry grid{
        {dims[0], dims[1], dims[2]}, {origin[0], origin[1], origin[2]}, {pitch, pitch, pitch}};
    const hmira::voxel_block block{lo, {shape[0], shape[1], shape[2]}};
    const hmira::voxelize_options options{
        .mode = named_mode,
        .open_mesh = fill_open ? hmira::open_mesh_fill::winding_number : hmira::open_mesh_fill::surface_only,
        .allow_degenerate = true,
        .threads = threads};
    std::unique_ptr<std::uint8_t[]> cells;
    hmira::result<hmira::voxelization> r = hmira::fail(hmira::errc::invalid_argument, "");
    {
        nb::gil_scoped_release release;
        r = view.visit<hmira::result<hmira::voxelization>>(
            [&]<class M, class T>(const M& mesh) -> hmira::result<hmira::voxelization> {
                auto v = hmira::voxelize_block<M, T>(mesh, grid, block, options);
                if (!v) return v;
                cells.reset(new std::uint8_t[shape[0] * shape[1] * shape[2]]);
                expand_bits(v->voxels, cells.get(), threads);
                return v;
            });
    }
    (void)take(std::move(r));
    return bool_grid(std::move(cells), block.dims);
}

}  // namespace

void bind_conversion(nb::module_& m) {
    const hmira::marching_cubes_options mc;
    const hmira::voxelize_options vox;
    const bool fill_open = vox.open_mesh == hmira::open_mesh_fill::winding_number;
    m.def("marching_cubes", &marching_cubes, nb::arg("volume"), nb::arg("iso") = nb::none(), nb::kw_only(),
          nb::arg("spacing") = std::vector<double>{1, 1, 1}, nb::arg("origin") = std::vector<double>{0, 0, 0},
          nb::arg("inside") = name_of(mc.inside), nb::arg("threads") = mc.threads, MC_DOC);
    m.def("_voxelize", &voxelize, nb::arg("vertices"), nb::arg("faces"), nb::kw_only(),
          nb::arg("resolution") = nb::none(), nb::arg("pitch") = nb::none(), nb::arg("mode") = name_of(vox.mode),
          nb::arg("fill_open") = fill_open, nb::arg("threads") = vox.threads,
          "Voxelizes (vertices, faces); see hmira.voxelize.");
    m.def("_voxel_grid", &voxel_grid, nb::arg("vertices"), nb::kw_only(), nb::arg("resolution") = nb::none(),
          nb::arg("pitch") = nb::none(),
          "The grid hmira.voxelize uses for these vertices: ((nx, ny, nz), origin, pitch).");
    m.def("_voxelize_block", &voxelize_block, nb::arg("vertices"), nb::arg("faces"), nb::kw_only(), nb::arg("dims"),
          nb::arg("origin"), nb::arg("pitch"), nb::arg("lo"), nb::arg("shape"), nb::arg("mode") = name_of(vox.mode),
          nb::arg("fill_open") = fill_open, nb::arg("threads") = vox.threads,
          "Voxels [lo, lo + shape) of the grid (dims, origin, pitch), as hmira.voxelize sets them there; see "
          "hmira.dask.voxelize.");
}

}  // namespace hmira_py
