// python/src/smoothing.cpp
// Mesh.laplacian_smooth and Mesh.taubin_smooth. Positions move in place, so the vertices view
// stays valid and sees them move; Ctrl-C cancels through the progress hook, and the smoother
// then restores every position.
#include "mesh_binding.hpp"

#include <hmira/algorithms/smoothing/laplacian_smooth.hpp>

namespace hmira_py {

namespace {

hmira::laplacian_weights weights_arg(const std::string& w, const char* who) {
    return enum_arg<hmira::laplacian_weights>(w, who, "weights");
}

/// Runs a smoother on `options` (progress filled in) and returns the vertices free to move.
template <class Options, class Smooth>
std::size_t smooth(py_mesh& s, Options& options, Smooth&& smoother) {
    return change_without_gil(s, false,
                              [&](halfedge_mesh& m, hmira::progress_function progress) {
                                  options.progress = std::move(progress);
                                  return smoother(m, options);
                              })
        .moved;
}

}  // namespace

void bind_mesh_smoothing(nb::class_<py_mesh>& c) {
    const hmira::laplacian_smooth_options laplacian;
    const hmira::taubin_smooth_options taubin;
    c.def(
         "laplacian_smooth",
         [](py_mesh& s, std::size_t iterations, double lambda, const std::string& weights, bool fix_boundary,
            std::optional<std::vector<long long>> fixed_vertices, bool refresh_weights, unsigned threads) {
             hmira::laplacian_smooth_options o{.iterations = iterations,
                                               .lambda = lambda,
                                               .weights = weights_arg(weights, "laplacian_smooth"),
                                               .fix_boundary = fix_boundary,
                                               .fixed_vertices = fixed_arg(s.get(), fixed_vertices, "laplacian_smooth"),
                                               .refresh_weights = refresh_weights,
                                               .threads = threads};
             return smooth(s, o,
                           [](halfedge_mesh& m, const auto& options) { return hmira::laplacian_smooth(m, options); });
         },
         nb::kw_only(), nb::arg("iterations") = laplacian.iterations, nb::arg("lambda_") = laplacian.lambda,
         nb::arg("weights") = name_of(laplacian.weights), nb::arg("fix_boundary") = laplacian.fix_boundary,
         nb::arg("fixed_vertices") = nb::none(), nb::arg("refresh_weights") = laplacian.refresh_weights,
         nb::arg("threads") = laplacian.threads,
         "Laplacian smoothing (uniform or cotangent weights, step lambda_ in (0, 1]); returns the number of vertices "
         "free to move. refresh_weights: recompute cotangent weights before every step (False: once). threads: "
         "worker threads (0: all); the result does not depend on it.")
        .def(
            "taubin_smooth",
            [](py_mesh& s, std::size_t iterations, double lambda, double mu, const std::string& weights,
               bool fix_boundary, std::optional<std::vector<long long>> fixed_vertices, bool refresh_weights,
               unsigned threads) {
                hmira::taubin_smooth_options o{.iterations = iterations,
                                               .lambda = lambda,
                                               .mu = mu,
                                               .weights = weights_arg(weights, "taubin_smooth"),
                                               .fix_boundary = fix_boundary,
                                               .fixed_vertices = fixed_arg(s.get(), fixed_vertices, "taubin_smooth"),
                                               .refresh_weights = refresh_weights,
                                               .threads = threads};
                return smooth(s, o,
                              [](halfedge_mesh& m, const auto& options) { return hmira::taubin_smooth(m, options); });
            },
            nb::kw_only(), nb::arg("iterations") = taubin.iterations, nb::arg("lambda_") = taubin.lambda,
            nb::arg("mu") = taubin.mu, nb::arg("weights") = name_of(taubin.weights),
            nb::arg("fix_boundary") = taubin.fix_boundary, nb::arg("fixed_vertices") = nb::none(),
            nb::arg("refresh_weights") = taubin.refresh_weights, nb::arg("threads") = taubin.threads,
            "Taubin lambda/mu smoothing (keeps the volume); returns the number of vertices free to move.\n"
            "refresh_weights and threads as in laplacian_smooth.");
}

}  // namespace hmira_py
