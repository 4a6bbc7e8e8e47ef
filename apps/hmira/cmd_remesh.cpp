// apps/hmira/cmd_remesh.cpp
// `hmira remesh`: isotropic remeshing of a triangle mesh towards one edge length, keeping the
// boundary and, with --features, the edges sharper than an angle.
#include <hmira/algorithms/remeshing/isotropic_remeshing.hpp>

#include "cli.hpp"

namespace {

using namespace hmira_cli;

struct remesh_args {
    std::string input, output;
    double length = 0;  // 0: the input's mean edge length
    std::size_t iterations = 5;
    double features = -1;  // < 0: none
};

int run_remesh(const remesh_args& a, const common_options& o) {
    int code = ok;
    auto loaded = load_for_edit(a.input, o, code);
    if (!loaded) return code;
    return run_edit(*loaded, a.input, a.output, "remeshing " + a.input, o,
                    [&](hmira::halfedge_mesh& mesh, int& c) -> std::optional<edit_outcome> {
                        using T = hmira::default_traits<hmira::halfedge_mesh>;
                        double length = a.length;
                        if (length == 0) {
                            double sum = 0;
                            for (auto e : T::edges(mesh)) {
                                const auto ends = T::edge_vertices(mesh, e);
                                sum += hmira::norm(mesh.position(ends[0]) - mesh.position(ends[1]));
                            }
                            length = T::edge_count(mesh) ? sum / double(T::edge_count(mesh)) : 1.0;
                        }
                        auto bar = stage_bar("remeshing " + a.input, o, T::face_count(mesh));
                        auto r = hmira::isotropic_remeshing(
                            mesh, {.target_edge_length = length,
                                   .iterations = a.iterations,
                                   .feature_angle = a.features >= 0 ? std::optional<double>(a.features) : std::nullopt,
                                   .progress = [&](double f) {
                                       bar.update(std::uint64_t(f * 1000), 1000);
                                       return true;
                                   }});
                        if (!r) {
                            // An option out of range is a usage error; a bad mesh is invalid input.
                            const bool option = r.error().message.find("option") != std::string::npos;
                            c = report(option ? usage : input_exit_code(r.error()), a.input + ": " + r.error().message);
                            return std::nullopt;
                        }
                        return edit_outcome{"remeshed to edge length " + std::to_string(length) + " (" +
                                                count_of(a.iterations, "iteration", "iterations") + "; " +
                                                count_of(r->splits, "split", "splits") + ", " +
                                                count_of(r->collapses, "collapse", "collapses") + ", " +
                                                count_of(r->flips, "flip", "flips") + ", " +
                                                count_of(r->feature_edges, "feature edge", "feature edges") + " kept)",
                                            {}};
                    });
}

const bool registered = register_command({
    "remesh", "Isotropic remeshing of a triangle mesh to one edge length (boundary and sharp edges kept)",
    "hmira remesh bunny.off even.off --length 0.01 -k 5 --features 45", 88,
    [](CLI::App& sub) {
        auto a = std::make_shared<remesh_args>();
        sub.add_option("input", a->input, "triangle mesh file to read (manifold, consistently oriented)")->required();
        sub.add_option("output", a->output, "mesh file to write")->required();
        sub.add_option("--length", a->length, "target edge length (default: the input's mean edge length)")
            ->check(finite_number("> 0", [](double x) { return x > 0; }));
        sub.add_option("-k,--iterations", a->iterations, "rounds of split, collapse, flip, relax (1 to 100)")
            ->check(whole_number(1, 100));
        sub.add_option("--features", a->features, "keep edges whose faces' normals differ by more than DEG degrees (0 to 180)")
            ->check(finite_number("in [0, 180]", [](double x) { return x >= 0 && x <= 180; }));
        return [a](const common_options& o) { return run_remesh(*a, o); };
    }});

}  // namespace
