// python/src/queries.cpp
// The surface queries: hmira.winding_number / signed_distance / hausdorff_distance over (V, F)
// arrays, and Mesh.winding_number / contains / signed_distance / sample_surface. Points come in
// as (n, 3) float64 or float32 arrays (float64 C-contiguous ones without a copy); answers go
// out in the points' dtype. The GIL is released while C++ runs.
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <vector>

#include <nanobind/stl/array.h>

#include <hmira/algorithms/spatial/hausdorff_distance.hpp>
#include <hmira/algorithms/spatial/sample_surface.hpp>
#include <hmira/algorithms/spatial/signed_distance.hpp>
#include <hmira/algorithms/spatial/winding_number.hpp>

#include "mesh_binding.hpp"

namespace hmira_py {

namespace {

using v3 = hmira::vec3<double>;
using any_array = nb::ndarray<nb::ro, nb::device::cpu>;

/// Query points: a view of a C-contiguous float64 (n, 3) array, or a float64 copy of any other
/// float64 or float32 (n, 3) array. `single` tells the dtype the answers take.
struct query_points {
    std::vector<v3> copy;
    std::span<const v3> view;
    bool single = false;
};

query_points points_arg(const any_array& a, const char* who, const char* what) {
    if (a.ndim() != 2 || a.shape(1) != 3) value_error(std::string(who) + ": " + what + " must be an (n, 3) array");
    query_points q;
    const std::size_t n = a.shape(0);
    const bool f64 = a.dtype() == nb::dtype<double>(), f32 = a.dtype() == nb::dtype<float>();
    if (!f64 && !f32) value_error(std::string(who) + ": " + what + " must be float64 or float32");
    q.single = f32;
    const auto s0 = a.stride(0), s1 = a.stride(1);
    if (f64 && s1 == 1 && s0 == 3) {
        q.view = std::span<const v3>(static_cast<const v3*>(a.data()), n);
        return q;
    }
    q.copy.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t k = 0; k < 3; ++k) {
            const auto off = std::int64_t(i) * s0 + std::int64_t(k) * s1;
            q.copy[i][k] =
                f64 ? static_cast<const double*>(a.data())[off] : double(static_cast<const float*>(a.data())[off]);
        }
    q.view = q.copy;
    return q;
}

/// Triangles: an (m, 3) array of int32, int64, uint32 or uint64 indices.
std::vector<std::array<std::uint32_t, 3>> triangles_arg(const any_array& a, const char* who) {
    if (a.ndim() != 2 || a.shape(1) != 3) value_error(std::string(who) + ": faces must be an (m, 3) integer array");
    std::vector<std::array<std::uint32_t, 3>> t(a.shape(0));
    auto read = [&](auto* data) {
        for (std::size_t i = 0; i < t.size(); ++i)
            for (std::size_t k = 0; k < 3; ++k) {
                const auto x = data[std::int64_t(i) * a.stride(0) + std::int64_t(k) * a.stride(1)];
                if (x < 0 || std::uint64_t(x) >= std::uint64_t(UINT32_MAX))
                    value_error(std::string(who) + ": face " + std::to_string(i) + " has index " + std::to_string(x) +
                                ", out of range");
                t[i][k] = std::uint32_t(x);
            }
    };
    if (a.dtype() == nb::dtype<std::int32_t>())
        read(static_cast<const std::int32_t*>(a.data()));
    else if (a.dtype() == nb::dtype<std::int64_t>())
        read(static_cast<const std::int64_t*>(a.data()));
    else if (a.dtype() == nb::dtype<std::uint32_t>())
        read(static_cast<const std::uint32_t*>(a.data()));
    else if (a.dtype() == nb::dtype<std::uint64_t>())
        read(static_cast<const std::uint64_t*>(a.data()));
    else
        value_error(std::string(who) + ": faces must be an integer array");
    return t;
}

hmira::triangle_set set_arg(const any_array& vertices, const any_array& faces, const char* who) {
    const auto v = points_arg(vertices, who, "vertices");
    const auto f = triangles_arg(faces, who);
    return take(hmira::make_triangle_set(v.view, f, who));
}

/// One value per point, in float64, or float32 when the points were.
nb::object values_out(std::vector<double>&& values, bool single) {
    if (!single) return nb::cast(adopt<double>(std::move(values), {values.size()}));
    std::vector<float> f(values.begin(), values.end());
    const std::size_t n = f.size();
    return nb::cast(adopt<float>(std::move(f), {n}));
}

hmira::winding_number_options winding_options(const std::string& method, double beta, const std::string& nan,
                                              unsigned threads, const char* who) {
    return {.method = choice_arg<hmira::winding_method>(method, who, "method"),
            .beta = beta,
            .nan = choice_arg<hmira::nan_policy>(nan, who, "nan"),
            .threads = threads};
}

hmira::signed_distance_options distance_options(const std::string& sign, double beta, const std::string& nan,
                                                unsigned threads, const char* who) {
    return {.sign = choice_arg<hmira::sign_mode>(sign, who, "sign"),
            .beta = beta,
            .nan = choice_arg<hmira::nan_policy>(nan, who, "nan"),
            .threads = threads};
}

nb::object winding_free(const any_array& vertices, const any_array& faces, const any_array& points,
                        const std::string& method, double beta, const std::string& nan, unsigned threads) {
    const auto o = winding_options(method, beta, nan, threads, "winding_number");
    const auto s = set_arg(vertices, faces, "winding_number");
    const auto q = points_arg(points, "winding_number", "points");
    hmira::result<hmira::winding_numbers> r = hmira::fail(hmira::errc::invalid_argument, "");
    {
        nb::gil_scoped_release release;
        r = hmira::winding_number(s, q.view, o);
    }
    return values_out(std::move(take(std::move(r)).values), q.single);
}

nb::object distance_free(const any_array& vertices, const any_array& faces, const any_array& points,
                         const std::string& sign, double beta, const std::string& nan, unsigned threads) {
    const auto o = distance_options(sign, beta, nan, threads, "signed_distance");
    const auto s = set_arg(vertices, faces, "signed_distance");
    const auto q = points_arg(points, "signed_distance", "points");
    hmira::result<hmira::signed_distances> r = hmira::fail(hmira::errc::invalid_argument, "");
    {
        nb::gil_scoped_release release;
        r = hmira::signed_distance(s, q.view, o);
    }
    return values_out(std::move(take(std::move(r)).distances), q.single);
}

nb::dict one_sided_dict(const hmira::one_sided_distance& d) {
    nb::dict out;
    out["max"] = d.max;
    out["mean"] = d.mean;
    out["rms"] = d.rms;
    out["samples"] = d.samples;
    return out;
}

/// A surface argument of hausdorff_distance: a Mesh, or a (vertices, faces) pair.
hmira::triangle_set surface_arg(nb::handle h, const char* which) {
    if (nb::isinstance<py_mesh>(h)) {
        const auto& m = nb::cast<const py_mesh&>(h);
        return take(read_without_gil(
            m, [](const halfedge_mesh& mesh) { return hmira::triangles_of(mesh, "hausdorff_distance"); }));
    }
    if (!nb::isinstance<nb::tuple>(h) || nb::len(h) != 2)
        value_error(std::string("hausdorff_distance: ") + which + " must be a Mesh or a (vertices, faces) pair");
    const auto t = nb::cast<nb::tuple>(h);
    return set_arg(nb::cast<any_array>(t[0]), nb::cast<any_array>(t[1]), "hausdorff_distance");
}

nb::dict hausdorff_free(nb::handle a, nb::handle b, std::size_t per_triangle, std::size_t min_samples,
                        std::uint64_t seed, unsigned threads) {
    const auto sa = surface_arg(a, "a"), sb = surface_arg(b, "b");
    hmira::result<hmira::hausdorff_result> r = hmira::fail(hmira::errc::invalid_argument, "");
    {
        nb::gil_scoped_release release;
        r = hmira::hausdorff_distance(
            sa, sb, {.per_triangle = per_triangle, .min_samples = min_samples, .seed = seed, .threads = threads});
    }
    const auto h = take(std::move(r));
    nb::dict out;
    out["symmetric"] = h.symmetric;
    out["a_to_b"] = one_sided_dict(h.a_to_b);
    out["b_to_a"] = one_sided_dict(h.b_to_a);
    return out;
}

/// The signed-distance engine over (V, F) arrays that the blocks of hmira.dask.signed_distance
/// share: built once (the closest-point and winding-number trees), then queried per block.
class sdf_engine {
public:
    sdf_engine(const any_array& vertices, const any_array& faces, const std::string& sign, double beta)
        : surface_(set_arg(vertices, faces, "signed_distance")),
          sign_(choice_arg<hmira::sign_mode>(sign, "signed_distance", "sign")),
          beta_(beta) {
        if (surface_.triangles.empty()) value_error("signed_distance: the mesh has no faces");
        if (auto ok = hmira::detail::spatial::check_winding_options({.beta = beta}, "signed_distance"); !ok)
            value_error(ok.error().message);
        nb::gil_scoped_release release;
        engine_ = std::make_unique<hmira::detail::spatial::distance_engine>(surface_, sign_);
    }

    /// Samples [lo, lo + shape) of the grid whose sample (i, j, k) lies at origin + pitch * (i, j, k),
    /// computed as signed_distance_grid's grid_geometry::position does.
    nb::ndarray<nb::numpy, double> block(const std::array<double, 3>& origin, double pitch,
                                         const std::array<std::size_t, 3>& lo, const std::array<std::size_t, 3>& shape,
                                         unsigned threads) const {
        if (!(pitch > 0) || !std::isfinite(pitch)) value_error("signed_distance: pitch must be positive and finite");
        std::vector<double> out(shape[0] * shape[1] * shape[2]);
        {
            nb::gil_scoped_release release;
            constexpr double inf = std::numeric_limits<double>::infinity();
            hmira::detail::with_thread_count(threads, [&] {
                hmira::detail::parallel_chunks(shape[0] * shape[1], 1, [&](std::size_t r0, std::size_t r1) {
                    for (std::size_t r = r0; r < r1; ++r) {
                        const std::size_t i = r / shape[1], j = r % shape[1];
                        for (std::size_t k = 0; k < shape[2]; ++k) {
                            const v3 p{origin[0] + double(lo[0] + i) * pitch, origin[1] + double(lo[1] + j) * pitch,
                                       origin[2] + double(lo[2] + k) * pitch};
                            out[r * shape[2] + k] = engine_->at(p, beta_, inf, nullptr, nullptr);
                        }
                    }
                });
            });
        }
        return adopt<double>(std::move(out), {shape[0], shape[1], shape[2]});
    }

private:
    hmira::triangle_set surface_;
    hmira::sign_mode sign_;
    double beta_;
    std::unique_ptr<hmira::detail::spatial::distance_engine> engine_;
};

}  // namespace

void bind_queries(nb::module_& m) {
    nb::class_<sdf_engine>(m, "_SignedDistanceEngine",
                           "The signed distance to the triangles (vertices, faces), built once and sampled block by "
                           "block (see hmira.dask.signed_distance).")
        .def(nb::init<const any_array&, const any_array&, const std::string&, double>(), nb::arg("vertices"),
             nb::arg("faces"), nb::kw_only(), nb::arg("sign") = "winding_number", nb::arg("beta") = 2.0)
        .def("block", &sdf_engine::block, nb::kw_only(), nb::arg("origin"), nb::arg("pitch"), nb::arg("lo"),
             nb::arg("shape"), nb::arg("threads") = 1,
             "Signed distances at samples [lo, lo + shape) of the grid with sample (i, j, k) at "
             "origin + pitch * (i, j, k): a float64 array of that shape.");
    const hmira::winding_number_options w{};
    const hmira::signed_distance_options sd{};
    const hmira::hausdorff_options h{};
    m.def("winding_number", &winding_free, nb::arg("vertices"), nb::arg("faces"), nb::arg("points"), nb::kw_only(),
          nb::arg("method") = name_of(w.method), nb::arg("beta") = w.beta, nb::arg("nan") = name_of(w.nan),
          nb::arg("threads") = w.threads,
          "Generalised winding numbers of the triangles (vertices (n, 3), faces (m, 3)) at points (k, 3), float64 or "
          "float32: 1 inside a closed outward surface, 0 outside, robust on open and self-intersecting input. "
          "method 'fast' (Barill et al., accuracy beta > 1) or 'direct'. nan='error' raises ValueError naming a "
          "non-finite point; nan='propagate' gives NaN there.\n\n"
          "Example\n-------\n>>> import numpy as np, hmira\n"
          ">>> V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1.0]])\n"
          ">>> F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])\n"
          ">>> hmira.winding_number(V, F, np.array([[0.1, 0.1, 0.1], [2, 2, 2.0]])).round(3)\n"
          "array([1., 0.])");
    m.def("signed_distance", &distance_free, nb::arg("vertices"), nb::arg("faces"), nb::arg("points"), nb::kw_only(),
          nb::arg("sign") = name_of(sd.sign), nb::arg("beta") = sd.beta, nb::arg("nan") = name_of(sd.nan),
          nb::arg("threads") = sd.threads,
          "Signed distances from points (k, 3) to the triangles (vertices, faces), negative inside. sign "
          "'winding_number' (robust on open, soup and flipped input), 'pseudo_normal' or 'parity'.");
    m.def("hausdorff_distance", &hausdorff_free, nb::arg("a"), nb::arg("b"), nb::kw_only(),
          nb::arg("per_triangle") = h.per_triangle, nb::arg("min_samples") = h.min_samples, nb::arg("seed") = h.seed,
          nb::arg("threads") = h.threads,
          "Sampled Hausdorff distance between two surfaces, each a Mesh or a (vertices, faces) pair: "
          "{'symmetric', 'a_to_b', 'b_to_a'}, each direction {'max', 'mean', 'rms', 'samples'}.");
}

void bind_mesh_queries(nb::class_<py_mesh>& c) {
    const hmira::winding_number_options w{};
    const hmira::signed_distance_options sd{};
    const hmira::sample_surface_options so{};
    c.def(
        "winding_number",
        [](const py_mesh& s, const any_array& points, const std::string& method, double beta, const std::string& nan,
           unsigned threads) {
            const auto o = winding_options(method, beta, nan, threads, "winding_number");
            const auto q = points_arg(points, "winding_number", "points");
            auto r = read_without_gil(s, [&](const halfedge_mesh& m) { return hmira::winding_number(m, q.view, o); });
            return values_out(std::move(take(std::move(r)).values), q.single);
        },
        nb::arg("points"), nb::kw_only(), nb::arg("method") = name_of(w.method), nb::arg("beta") = w.beta,
        nb::arg("nan") = name_of(w.nan), nb::arg("threads") = w.threads,
        "Generalised winding numbers at points (k, 3) (see hmira.winding_number).");
    c.def(
        "contains",
        [](const py_mesh& s, const any_array& points, double beta, const std::string& nan, unsigned threads) {
            const auto o = winding_options("fast", beta, nan, threads, "contains");
            const auto q = points_arg(points, "contains", "points");
            auto r = read_without_gil(s, [&](const halfedge_mesh& m) { return hmira::contains(m, q.view, o); });
            auto inside = take(std::move(r));
            const std::size_t n = inside.size();
            return adopt<bool>(std::move(inside), {n});
        },
        nb::arg("points"), nb::kw_only(), nb::arg("beta") = w.beta, nb::arg("nan") = name_of(w.nan),
        nb::arg("threads") = w.threads,
        "Whether each point (k, 3) is inside: winding number at least 1/2 (a bool array).");
    c.def(
        "signed_distance",
        [](const py_mesh& s, const any_array& points, const std::string& sign, double beta, const std::string& nan,
           unsigned threads) {
            const auto o = distance_options(sign, beta, nan, threads, "signed_distance");
            const auto q = points_arg(points, "signed_distance", "points");
            auto r = read_without_gil(s, [&](const halfedge_mesh& m) { return hmira::signed_distance(m, q.view, o); });
            return values_out(std::move(take(std::move(r)).distances), q.single);
        },
        nb::arg("points"), nb::kw_only(), nb::arg("sign") = name_of(sd.sign), nb::arg("beta") = sd.beta,
        nb::arg("nan") = name_of(sd.nan), nb::arg("threads") = sd.threads,
        "Signed distances from points (k, 3), negative inside (see hmira.signed_distance).");
    c.def(
        "sample_surface",
        [](const py_mesh& s, std::size_t count, const std::string& method, std::uint64_t seed) {
            const hmira::sample_surface_options o{
                .method = choice_arg<hmira::sampling_method>(method, "sample_surface", "method"), .seed = seed};
            auto r =
                take(read_without_gil(s, [&](const halfedge_mesh& m) { return hmira::sample_surface(m, count, o); }));
            const std::size_t n = r.points.size();
            std::vector<std::int64_t> faces(r.faces.begin(), r.faces.end());
            std::vector<std::int64_t> corners;
            corners.reserve(3 * n);
            for (const auto& c : r.corners) corners.insert(corners.end(), c.begin(), c.end());
            nb::dict d;
            d["points"] = adopt<double>(std::move(r.points), {n, 3});
            d["faces"] = adopt<std::int64_t>(std::move(faces), {n});
            d["barycentrics"] = adopt<double>(std::move(r.barycentrics), {n, 3});
            d["corners"] = adopt<std::int64_t>(std::move(corners), {n, 3});
            return d;
        },
        nb::arg("count"), nb::kw_only(), nb::arg("method") = name_of(so.method), nb::arg("seed") = so.seed,
        "count points on the surface, 'uniform' by area or 'poisson_disk' (blue noise), the same for the same "
        "seed: {'points' (count, 3), 'faces' (count,), 'barycentrics' (count, 3), 'corners' (count, 3)}: point i is "
        "sum over k of barycentrics[i, k] * vertex corners[i, k].");
}

}  // namespace hmira_py
