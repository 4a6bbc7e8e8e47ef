// apps/hmira/cmd_smooth.cpp
// `hmira smooth`: Taubin (default) or Laplacian smoothing, uniform or cotangent weights;
// boundary vertices stay put unless --move-boundary.
#include <hmira/algorithms/smoothing/laplacian_smooth.hpp>

#include "cli.hpp"

namespace {

using namespace hmira_cli;

// Defaults are Taubin's (the default method), read from the library's options.
struct smooth_args {
    std::string input, output, method = "taubin";
    std::string weights = name_of(hmira::taubin_smooth_options{}.weights);
    std::size_t iterations = hmira::taubin_smooth_options{}.iterations;
    double lambda = hmira::taubin_smooth_options{}.lambda, mu = hmira::taubin_smooth_options{}.mu;
    bool move_boundary = !hmira::taubin_smooth_options{}.fix_boundary;
    std::vector<std::size_t> fixed;
};

int run_smooth(const smooth_args& a, const common_options& o) {
    int code = ok;
    auto loaded = load_for_edit(a.input, o, code);
    if (!loaded) return code;
    if (!check_indices(a.fixed, loaded->mesh.vertex_count(), "vertex", "--fix", a.input, code)) return code;
    const auto w = named<hmira::laplacian_weights>(a.weights);
    // Vertices times steps: the bar shows for a long run on a small mesh too.
    const std::uint64_t steps = std::uint64_t(a.iterations) * (a.method == "taubin" ? 2 : 1);
    const std::uint64_t work = std::uint64_t(loaded->mesh.vertex_count()) * steps;
    hmira::taubin_smooth_options taubin{.iterations = a.iterations,
                                        .lambda = a.lambda,
                                        .mu = a.mu,
                                        .weights = w,
                                        .fix_boundary = !a.move_boundary,
                                        .fixed_vertices = a.fixed};
    hmira::laplacian_smooth_options laplacian{.iterations = a.iterations,
                                              .lambda = a.lambda,
                                              .weights = w,
                                              .fix_boundary = !a.move_boundary,
                                              .fixed_vertices = a.fixed};
    return run_edit(*loaded, a.input, a.output, "smoothing " + a.input, o,
                    [&](hmira::halfedge_mesh& mesh, int& c) -> std::optional<edit_outcome> {
                        progress_bar bar("smoothing " + a.input, o, std::uint64_t(1) << 24);
                        std::uint64_t shown = std::uint64_t(-1);
                        const auto progress = [&](double f) {
                            // Redrawn when the tenth of a percent changes.
                            const auto permille = std::uint64_t(f * 1000);
                            if (permille != shown) bar.update(std::uint64_t(f * double(work)), work);
                            shown = permille;
                            return true;
                        };
                        taubin.progress = laplacian.progress = progress;
                        auto r = a.method == "taubin" ? hmira::taubin_smooth(mesh, taubin)
                                                      : hmira::laplacian_smooth(mesh, laplacian);
                        if (!r) {
                            c = report(exit_code_for(r.error()), a.input + ": " + r.error().message);
                            return std::nullopt;
                        }
                        return edit_outcome{"smoothed " + count_of(r->moved, "vertex", "vertices") + " (" + a.method +
                                                ", " + a.weights + ", " +
                                                count_of(a.iterations, "iteration", "iterations") + ")",
                                            {}};
                    });
}

const bool registered = register_command(
    {"smooth", "Smooth vertex positions (Taubin lambda/mu or Laplacian; uniform or cotangent weights)",
     "hmira smooth noisy.off smooth.off --method taubin --iterations 10", 87, [](CLI::App& sub) {
         auto a = std::make_shared<smooth_args>();
         sub.add_option("input", a->input, "mesh file to read (manifold, consistently oriented)")->required();
         sub.add_option("output", a->output, "mesh file to write (same vertices and faces, moved)")->required();
         sub.add_option("--method", a->method, "taubin (keeps the volume) or laplacian (shrinks)")
             ->check(CLI::IsMember({"taubin", "laplacian"}));
         sub.add_option("--weights", a->weights, "uniform or cotangent (triangles only)")
             ->check(CLI::IsMember(names_of<hmira::laplacian_weights>()));
         sub.add_option("--iterations", a->iterations, "smoothing steps (Taubin: lambda/mu pairs)")
             ->check(whole_number(0, 1000000));
         sub.add_option("--lambda", a->lambda, "step size, in (0, 1]")->check(finite_number("in (0, 1]", [](double x) {
             return x > 0 && x <= 1;
         }));
         sub.add_option("--mu", a->mu, "Taubin's inflating step, in [-1, -lambda)")
             ->check(finite_number("in [-1, 0)", [](double x) { return x >= -1 && x < 0; }));
         sub.add_flag("--move-boundary", a->move_boundary, "let boundary vertices move too");
         sub.add_option("--fix", a->fixed,
                        "keep vertex N exactly where it is (0-based, file order; repeatable, or N,M,...)")
             ->delimiter(',')
             ->check(CLI::NonNegativeNumber);
         return [a](const common_options& o) { return run_smooth(*a, o); };
     }});

}  // namespace
