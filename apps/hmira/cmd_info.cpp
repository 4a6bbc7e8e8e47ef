// apps/hmira/cmd_info.cpp
// `hmira info`: what a mesh file holds: counts, components, genus, boundary, closed and
// manifold, bounding box, and what `validate` finds.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <sstream>

#include <hmira/algorithms/topology/mesh_topology.hpp>
#include <hmira/algorithms/validation/validate.hpp>

#include "cli.hpp"

namespace {

using namespace hmira_cli;

std::string fmt(double x) {
    char b[32];
    std::snprintf(b, sizeof b, "%.6g", x);
    return b;
}

std::string json_string(const std::string& s) {
    std::string o = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') o += '\\';
        if (static_cast<unsigned char>(c) < 0x20) {
            o += ' ';
            continue;
        }
        o += c;
    }
    return o + "\"";
}

struct info_args {
    std::string input;
    bool json = false;
};

int run_info(const info_args& a, const common_options& o) {
    int code = ok;
    auto loaded = load(a.input, o, code);
    if (!loaded) return code;
    const auto& m = loaded->mesh;
    const auto t = hmira::mesh_topology(m);
    const auto problems = hmira::validate(m, {.max_problems = 100});
    bool manifold = true;
    for (const auto& p : problems)
        if (p.kind == hmira::problem_kind::non_manifold_edge || p.kind == hmira::problem_kind::non_manifold_vertex)
            manifold = false;
    // The box of the finite vertices; the others are counted and named, not silently dropped
    // (std::min and std::max skip a NaN without a word).
    hmira::vec3<double> lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                           std::numeric_limits<double>::infinity()};
    auto hi = -lo;
    std::size_t non_finite = 0, finite = 0, first_non_finite = 0;
    for (auto v : m.vertices()) {
        const auto p = m.position(v);
        if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))) {
            if (non_finite++ == 0) first_non_finite = v.index;
            continue;
        }
        ++finite;
        for (std::size_t k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    }
    if (finite == 0) lo = hi = {};
    const auto& attr = loaded->report.attributes;
    std::ostringstream s;
    if (a.json) {
        s << "{\"file\": " << json_string(a.input) << ", \"format\": " << json_string(loaded->report.format)
          << ", \"vertices\": " << t.vertices << ", \"edges\": " << t.edges << ", \"faces\": " << t.faces
          << ", \"components\": " << t.components << ", \"boundary_loops\": " << t.boundary_loops
          << ", \"genus\": " << t.genus << ", \"euler_characteristic\": " << t.euler_characteristic
          << ", \"closed\": " << (t.closed() ? "true" : "false") << ", \"manifold\": " << (manifold ? "true" : "false")
          << ", \"bounding_box\": [[" << lo.x << ", " << lo.y << ", " << lo.z << "], [" << hi.x << ", " << hi.y << ", "
          << hi.z << "]], \"non_finite_vertices\": " << non_finite
          << ", \"normals\": " << (attr.normals.empty() ? "false" : "true")
          << ", \"colors\": " << (attr.colors.empty() ? "false" : "true")
          << ", \"dropped_triangles\": " << loaded->report.dropped_triangles << ", \"problems\": " << problems.size()
          << "}";
        std::cout << s.str() << '\n';
        return ok;
    }
    s << "file:            " << a.input << " (" << loaded->report.format << ")\n"
      << "vertices:        " << t.vertices << "\nedges:           " << t.edges << "\nfaces:           " << t.faces
      << "\ncomponents:      " << t.components << "\nboundary loops:  " << t.boundary_loops
      << "\ngenus:           " << t.genus << "\neuler char.:     " << t.euler_characteristic
      << "\nclosed:          " << (t.closed() ? "yes" : "no") << "\nmanifold:        " << (manifold ? "yes" : "no")
      << "\nbounding box:    [" << fmt(lo.x) << ", " << fmt(lo.y) << ", " << fmt(lo.z) << "] .. [" << fmt(hi.x) << ", "
      << fmt(hi.y) << ", " << fmt(hi.z) << "]" << (non_finite ? " (finite vertices only)" : "") << "\n";
    if (non_finite)
        s << "non-finite:      " << count_of(non_finite, "vertex", "vertices")
          << " with a NaN or infinite coordinate (first: vertex " << first_non_finite << ")\n";
    if (!attr.normals.empty() || !attr.colors.empty())
        s << "attributes:      " << (attr.normals.empty() ? "" : "normals ") << (attr.colors.empty() ? "" : "colours")
          << '\n';
    if (loaded->report.dropped_triangles)
        s << "dropped:         " << loaded->report.dropped_triangles << " STL triangles whose corners weld together\n";
    if (problems.empty()) {
        s << "validate:        ok\n";
    } else {
        s << "validate:        " << problems.size() << (problems.size() >= 100 ? "+" : "")
          << " problem(s), first: " << problems.front().message << '\n';
    }
    if (!o.quiet) std::cout << s.str();
    return ok;
}

const bool registered = register_command(
    {"info", "Print a mesh file's counts, topology, bounding box and validation summary",
     "hmira info elephant.off            # or --json for one machine-readable line", 10, [](CLI::App& sub) {
         auto a = std::make_shared<info_args>();
         sub.add_option("input", a->input, "mesh file (.obj .off .ply .stl)")->required();
         sub.add_flag("--json", a->json, "print one JSON object instead of text");
         return [a](const common_options& o) { return run_info(*a, o); };
     }});

}  // namespace
