// apps/hmira/cmd_remesh.cpp
// `hmira remesh`: isotropic remeshing of a triangle mesh towards one edge length, keeping the
// boundary and, with --features, the edges sharper than an angle.
#include <algorithm>
#include <cmath>

#include <hmira/algorithms/remeshing/isotropic_remeshing.hpp>

#include "cli.hpp"

namespace {

using namespace hmira_cli;

struct remesh_args {
    std::string input, output;
    double length = 0;  // 0: the input's mean edge length (hmira::default_target_edge_length)
    std::size_t iterations = hmira::isotropic_remeshing_options{}.iterations;
    double features = -1;  // < 0: none
};

int run_remesh(const remesh_args& a, const common_options& o) {
    int code = ok;
    auto loaded = load_for_edit(a.input, o, code);
    if (!loaded) return code;
    // The options were checked on the command line, so an invalid_argument from the library is
    // about the target length: a usage error when --length gave it, a property of the input
    // (whose mean edge length it is) otherwise.
    const bool given = a.length > 0;
    auto exit_code = [&](const hmira::error& e) {
        return e.code == hmira::errc::invalid_argument ? (given ? usage : invalid_input) : input_exit_code(e);
    };
    return run_edit(*loaded, a.input, a.output, "remeshing " + a.input, o,
                    [&](hmira::halfedge_mesh& mesh, int& c) -> std::optional<edit_outcome> {
                        using T = hmira::default_traits<hmira::halfedge_mesh>;
                        auto fail = [&](const hmira::error& e) -> std::optional<edit_outcome> {
                            c = report(exit_code(e), a.input + ": " + e.message);
                            return std::nullopt;
                        };
                        double length = a.length;
                        if (!given) {
                            const auto mean = hmira::default_target_edge_length(mesh);
                            if (!mean) return fail(mean.error());
                            length = *mean;
                        }
                        const auto estimate = hmira::estimate_isotropic_remeshing(mesh, length);
                        if (!estimate) return fail(estimate.error());
                        const auto memory = free_memory();
                        if (memory && !(estimate->bytes <= double(*memory))) {
                            c = report(given ? usage : invalid_input,
                                       a.input + ": " + (given ? "--length " : "edge length ") +
                                           hmira::detail::remeshing::number(length) + " would make " +
                                           hmira::detail::remeshing::count_text(estimate->triangles) +
                                           " triangles needing " + (std::isinf(estimate->bytes) ? "" : "about ") +
                                           hmira::detail::remeshing::bytes(estimate->bytes) +
                                           " of memory, more than the " +
                                           hmira::detail::remeshing::bytes(double(*memory)) + " free");
                            return std::nullopt;
                        }
                        // Sized by the larger of the input and the expected output, so a long
                        // refinement of a small input shows its progress too.
                        const double expected = std::min(estimate->triangles, 1e18);
                        auto bar = stage_bar("remeshing " + a.input, o,
                                             std::max<std::uint64_t>(T::face_count(mesh), std::uint64_t(expected)));
                        hmira::isotropic_remeshing_options options{
                            .target_edge_length = length,
                            .iterations = a.iterations,
                            .feature_angle = a.features >= 0 ? std::optional<double>(a.features) : std::nullopt,
                            .progress = [&](double f) {
                                bar.update(std::uint64_t(f * 1000), 1000);
                                return true;
                            }};
                        if (memory) options.max_bytes = *memory;
                        auto r = hmira::isotropic_remeshing(mesh, options);
                        if (!r) return fail(r.error());
                        return edit_outcome{"remeshed to edge length " + hmira::detail::remeshing::number(length) +
                                                " (" + count_of(a.iterations, "iteration", "iterations") + "; " +
                                                count_of(r->splits, "split", "splits") + ", " +
                                                count_of(r->collapses, "collapse", "collapses") + ", " +
                                                count_of(r->flips, "flip", "flips") + ", " +
                                                count_of(r->feature_edges, "feature edge", "feature edges") + " kept)",
                                            {}};
                    });
}

const bool registered = register_command(
    {"remesh", "Isotropic remeshing of a triangle mesh to one edge length (boundary and sharp edges kept)",
     "hmira remesh bunny.off even.off --length 0.01 -k 5 --features 45", 88, [](CLI::App& sub) {
         auto a = std::make_shared<remesh_args>();
         sub.add_option("input", a->input, "triangle mesh file to read (manifold, consistently oriented)")->required();
         sub.add_option("output", a->output, "mesh file to write")->required();
         sub.add_option("--length", a->length, "target edge length (default: the input's mean edge length)")
             ->check(finite_number("> 0", [](double x) { return x > 0; }));
         sub.add_option("-k,--iterations", a->iterations, "rounds of split, collapse, flip, relax (1 to 100)")
             ->check(whole_number(1, 100));
         sub.add_option("--features", a->features,
                        "keep edges whose faces' normals differ by more than DEG degrees (0 to 180)")
             ->check(finite_number("in [0, 180]", [](double x) { return x >= 0 && x <= 180; }));
         return [a](const common_options& o) { return run_remesh(*a, o); };
     }});

}  // namespace
