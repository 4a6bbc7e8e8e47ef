// hmira/algorithms/boolean/detail/make_solid_impl.hpp
// The machinery of make_solid (see ../make_solid.hpp): mesh_boolean's pipeline over one mesh,
// its triangles cut by each other, every piece labelled by the winding numbers on its sides.
#pragma once

#include <cmath>
#include <vector>

#include "../make_solid.hpp"
#include "mesh_boolean_impl.hpp"

namespace hmira {

template <class MO, class M, class TO, class T>
    requires copy_target_mesh<MO, TO> && boolean_input_mesh<M, T>
result<boolean_report> make_solid(MO& out, const M& mesh, const make_solid_options& options) {
    namespace bd = detail::boolean;
    detail::progress_gate gate(options.progress, 4, "make_solid");
    std::vector<bd::point3> points;
    std::vector<bd::soup_triangle> tris;
    if (auto r = bd::read_input<M, T>(mesh, 0, points, tris, "make_solid"); !r) return r.error();
    const auto scale = bd::implicit_scale(points);
    if (!scale) return scale.error();
    for (bd::point3& p : points) p = {std::ldexp(p.x, *scale), std::ldexp(p.y, *scale), std::ldexp(p.z, *scale)};
    bd::merge_explicit(points, tris);
    if (!gate.advance()) return fail(errc::cancelled, "make_solid: cancelled");

    bd::arrangement arr;
    if (!bd::build_arrangement(points, tris, arr, &gate, true)) {
        if (gate.cancelled()) return fail(errc::cancelled, "make_solid: cancelled");
        return fail(errc::unsupported, "make_solid: the cuts of one triangle could not be triangulated");
    }
    if (!gate.advance()) return fail(errc::cancelled, "make_solid: cancelled");
    boolean_report report;
    report.intersecting_pairs = arr.same_mesh_pairs;
    auto windings = bd::windings_of(arr, tris, points, 1, "make_solid", true);
    if (!windings) return windings.error();
    const bd::piece_windings& w = **windings;
    auto kept = [&](std::size_t n, bool& flip) {
        const bool pos = w.pos[n] > 0, neg = w.neg[n] > 0;
        flip = pos;
        return pos != neg;
    };
    auto soup = bd::round_kept(arr, tris, *scale, points.size(), kept, report, "make_solid");
    if (!soup) return soup.error();
    if (!gate.advance()) return fail(errc::cancelled, "make_solid: cancelled");
    if (auto r = detail::copy::build<MO, TO>(out, *soup); !r) return r.error();
    return report;
}

}  // namespace hmira
