// hmira/algorithms/boolean/detail/mesh_boolean_impl.hpp
// The machinery of mesh_boolean (see ../mesh_boolean.hpp): reading both inputs into one triangle
// soup, the arrangement, labelling pieces against the other mesh, choosing and writing them.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <optional>
#include <tuple>
#include <unordered_map>
#include <string>
#include <vector>

#include "../../spatial/inside_closed.hpp"
#include "../../topology/connected_components.hpp"
#include "../../validation/self_intersections.hpp"
#include "../../triangulation/detail/indexed_triangles.hpp"
#include "../mesh_boolean.hpp"
#include "arrangement.hpp"
#include "cell_windings.hpp"

namespace hmira::detail::boolean {

/// A piece's position with respect to the other mesh.
enum class label : std::uint8_t { out, in, on_same, on_opposite };

/// Appends one input's vertices and triangles; an error names the first vertex out of range (and
/// the mesh, a or b, unless `who` names the caller of a one-mesh operation).
template <class M, class T>
result<void> read_input(const M& mesh, std::uint32_t which, std::vector<point3>& points,
                        std::vector<soup_triangle>& tris, const char* who = nullptr) {
    const std::size_t base = points.size();
    points.resize(base + T::vertex_index_bound(mesh));
    for (auto v : T::vertices(mesh)) {
        const std::size_t i = T::vertex_index(mesh, v);
        const auto q = T::position(mesh, v);
        const point3 p{double(q.x), double(q.y), double(q.z)};
        for (std::size_t k = 0; k < 3; ++k)
            if (!std::isfinite(p[k]) || !predicates::in_predicate_range(p[k]))
                return fail(errc::invalid_argument,
                            std::string(who ? who : "mesh_boolean") + ": vertex " + std::to_string(i) +
                                (who ? std::string() : std::string(" of mesh ") + (which == 0 ? "a" : "b")) +
                                " has a coordinate that is not finite or outside predicates::in_predicate_range",
                            (long long)i);
        points[base + i] = p;
    }
    for (const auto& t : triangulation::indexed_triangles<M, T>(mesh))
        tris.push_back({{vid(base + t.v[0]), vid(base + t.v[1]), vid(base + t.v[2])}, which, t.face});
    return {};
}

/// The power of two that brings every coordinate into predicates::in_implicit_range, or an
/// error when the coordinates span too many bits for any one scale.
inline result<int> implicit_scale(const std::vector<point3>& points) {
    const auto [low, high, any] = bits_of(points);
    if (!any) return 0;
    if (high - low > 177)
        return fail(errc::invalid_argument, "mesh_boolean: the coordinates span " + std::to_string(high - low) +
                                                " bits from the coarsest to the finest; exact booleans take 177");
    // Bring the finest bit to -92 or above and the coarsest to 85 or below, centred.
    return -92 - low + (177 - (high - low)) / 2;
}

/// Renames the corners so that exactly equal input points share one id.
inline void merge_explicit(std::vector<point3>& points, std::vector<soup_triangle>& tris) {
    std::vector<vid> order(points.size()), map(points.size());
    std::iota(order.begin(), order.end(), vid(0));
    auto less = [&](vid x, vid y) {
        const point3 &p = points[x], &q = points[y];
        return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z);
    };
    std::sort(order.begin(), order.end(), [&](vid x, vid y) { return less(x, y) || (!less(y, x) && x < y); });
    for (std::size_t n = 0; n < order.size(); ++n)
        map[order[n]] = n > 0 && !less(order[n - 1], order[n]) ? map[order[n - 1]] : order[n];
    for (soup_triangle& t : tris)
        for (vid& v : t.v) v = map[v];
}

/// A hash of rounded positions under which equal doubles (0.0 and -0.0 too) hash alike.
struct position_hash {
    std::size_t operator()(const std::array<double, 3>& p) const noexcept {
        std::size_t h = 0;
        for (double c : p) h = h * 0x9E3779B97F4A7C15ull + std::hash<double>{}(c == 0.0 ? 0.0 : c);
        return h;
    }
};

/// Whether the piece lies in input triangle j (coplanar with its source), and how it is turned.
inline label coplanar_label(const arrangement& arr, const std::vector<soup_triangle>& tris, const piece& p,
                            std::uint32_t j, bool& inside) {
    const int k = arr.drop[p.source];
    const tri3 &t = tris[p.source].v, &u = tris[j].v;
    const auto& P = arr.points;
    const int su = predicates::orient2d(k, P[u[0]], P[u[1]], P[u[2]]);
    inside = su != 0;
    for (vid v : p.v)
        for (std::size_t m = 0; m < 3 && inside; ++m)
            inside = su * predicates::orient2d(k, P[u[m]], P[u[(m + 1) % 3]], P[v]) >= 0;
    const int st = predicates::orient2d(k, P[t[0]], P[t[1]], P[t[2]]);
    return st == su ? label::on_same : label::on_opposite;
}

/// Whether a piece from mesh `from` with the given label is kept, and whether it is flipped.
inline bool keep(boolean_op op, std::uint32_t from, label l, bool& flip) {
    flip = false;
    switch (op) {
        case boolean_op::union_: return l == label::out || (from == 0 && l == label::on_same);
        case boolean_op::intersection: return l == label::in || (from == 0 && l == label::on_same);
        case boolean_op::difference:
            if (from == 0) return l == label::out || l == label::on_opposite;
            flip = true;
            return l == label::in;
        case boolean_op::xor_:
            flip = l == label::in;
            return l == label::out || l == label::in || l == label::on_opposite;
    }
    return false;
}

/// Whether a point with winding numbers wa, wb of a and b is in op(a, b).
inline bool in_result(boolean_op op, std::int32_t wa, std::int32_t wb) {
    const bool x = wa > 0, y = wb > 0;
    switch (op) {
        case boolean_op::union_: return x || y;
        case boolean_op::intersection: return x && y;
        case boolean_op::difference: return x && !y;
        case boolean_op::xor_: return x != y;
    }
    return false;
}

/// Coordinate spans (bits from the coarsest to the finest) within which the winding labels stay
/// exact: with three-plane points (triangles of one mesh cutting each other) the predicates reach
/// degree 20, with line-plane points alone degree 17; a few bits are left for the seeds' segments.
inline constexpr int span_with_three_plane_points = 90;
inline constexpr int span_with_line_plane_points = 160;

/// The winding numbers of a and b on both sides of every piece, when they can be found exactly:
/// no coplanar overlapping triangles and a coordinate span within the limits above. An error
/// when they cannot and the input needs them (triangles of one mesh cut each other); nothing
/// (the caller labels against the other mesh) otherwise, unless `required`.
inline result<std::optional<piece_windings>> windings_of(const arrangement& arr, const std::vector<soup_triangle>& tris,
                                                         const std::vector<point3>& points, std::size_t meshes,
                                                         const char* who, bool required = false) {
    const bool need = required || arr.self_cut;
    const bool coplanar =
        std::any_of(arr.coplanar.begin(), arr.coplanar.end(), [](const auto& c) { return !c.empty(); });
    const int span = coordinate_span(points);
    const std::string name(who);
    if (coplanar) {
        if (!need) return std::optional<piece_windings>{};
        return fail(errc::unsupported, name +
                                           ": coplanar overlapping triangles are not supported yet with "
                                           "winding numbers");
    }
    if (span > (arr.self_cut ? span_with_three_plane_points : span_with_line_plane_points)) {
        if (!need) return std::optional<piece_windings>{};
        return fail(errc::unsupported, name + ": the coordinates span " + std::to_string(span) +
                                           " bits; exact winding numbers take " +
                                           std::to_string(span_with_three_plane_points));
    }
    piece_windings w;
    switch (cell_windings(arr, tris, points.size(), meshes).run(w)) {
        case winding_status::ok: return std::optional<piece_windings>(std::move(w));
        case winding_status::coincident:
        case winding_status::no_seed:
            if (!need) return std::optional<piece_windings>{};
            return fail(errc::unsupported,
                        name + ": overlapping pieces around an edge, or no segment from outside missed every edge");
        case winding_status::not_closed: break;
    }
    if (!need) return std::optional<piece_windings>{};
    return fail(errc::unsupported, name + ": an input is not closed (its winding numbers are not consistent)");
}

/// Checks the rounded output exactly: faces whose corners became collinear, and pairs of faces
/// that rounding made intersect (the rule of self_intersections). Only faces with a rounded
/// (constructed) corner can have moved, so only pairs holding one are tested: the faces whose
/// boxes reach the box of the moved ones go into a uniform grid, and each moved face asks it, in
/// parallel chunks whose counts are summed.
inline void check_rounding(const io::polygon_soup& soup, const std::vector<char>& rounded, boolean_report& report) {
    std::vector<point3> pos(soup.points.size());
    for (std::size_t v = 0; v < pos.size(); ++v) pos[v] = {soup.points[v][0], soup.points[v][1], soup.points[v][2]};
    const std::size_t n = soup.face_offsets.size() - 1;
    std::vector<std::array<std::size_t, 3>> tris(n);
    std::vector<box3> box(n);
    std::vector<std::uint32_t> moved;
    box3 region{};
    for (std::size_t f = 0; f < n; ++f) {
        const std::size_t o = soup.face_offsets[f];
        tris[f] = {soup.indices[o], soup.indices[o + 1], soup.indices[o + 2]};
        box[f] = {pos[tris[f][0]], pos[tris[f][0]]};
        bool is_moved = false;
        for (std::size_t v : tris[f]) {
            is_moved = is_moved || rounded[v];
            for (std::size_t k = 0; k < 3; ++k) {
                box[f][0][k] = std::min(box[f][0][k], pos[v][k]);
                box[f][1][k] = std::max(box[f][1][k], pos[v][k]);
            }
        }
        if (is_moved) {
            for (std::size_t k = 0; k < 3 && !moved.empty(); ++k) {
                region[0][k] = std::min(region[0][k], box[f][0][k]);
                region[1][k] = std::max(region[1][k], box[f][1][k]);
            }
            if (moved.empty()) region = box[f];
            moved.push_back(std::uint32_t(f));
        }
    }
    std::vector<char> is_moved(n, 0);
    for (std::uint32_t f : moved) is_moved[f] = 1;
    std::vector<std::uint32_t> near;
    for (std::uint32_t f = 0; f < n; ++f)
        if (boxes_overlap(box[f], region)) near.push_back(f);
    const box_grid grid(region, box, near);
    const std::size_t grain = 256, chunks = (std::max(n, moved.size()) + grain - 1) / grain;
    std::vector<std::size_t> degenerate(chunks, 0), crossing(chunks, 0);
    parallel_chunks(chunks, 1, [&](std::size_t from, std::size_t to) {
        for (std::size_t c = from; c < to; ++c) {
            for (std::size_t f = c * grain; f < std::min(n, (c + 1) * grain); ++f)
                degenerate[c] += predicates::collinear(pos[tris[f][0]], pos[tris[f][1]], pos[tris[f][2]]);
            for (std::size_t m = c * grain; m < std::min(moved.size(), (c + 1) * grain); ++m) {
                const std::uint32_t f = moved[m];
                grid.query(box, box[f], [&](std::uint32_t g) {
                    if (g == f || (is_moved[g] && g < f)) return;  // a pair of moved faces once
                    crossing[c] += self_intersect::triangles_cross(tris[f], tris[g], pos);
                });
            }
        }
    });
    for (std::size_t c = 0; c < chunks; ++c) {
        report.degenerate_faces += degenerate[c];
        report.rounding_intersections += crossing[c];
    }
}

/// The pieces `kept(n, flip)` keeps (flipped when it says so), each point rounded once (from the
/// frame scaled by 2^scale back to the input's); distinct points that round alike are merged and
/// counted, faces that collapse dropped, and the rounded faces checked (check_rounding). Fills
/// report.faces, cut_triangles, snapped_vertices and the rounding counts.
template <class Kept>
result<io::polygon_soup> round_kept(const arrangement& arr, const std::vector<soup_triangle>& tris, int scale,
                                    std::size_t explicit_count, Kept kept, boolean_report& report, const char* who) {
    // The kept pieces, rounded once; distinct points that round alike are merged.
    io::polygon_soup soup;
    constexpr std::uint32_t unset = std::uint32_t(-1);
    std::vector<std::uint32_t> out_id(arr.points.size(), unset);
    std::unordered_map<std::array<double, 3>, std::uint32_t, position_hash> by_position;
    std::vector<char> cut(tris.size(), 0);
    for (const piece& p : arr.pieces)
        if (p.v != tris[p.source].v) cut[p.source] = 1;
    report.cut_triangles = std::size_t(std::count(cut.begin(), cut.end(), 1));
    for (std::size_t n = 0; n < arr.pieces.size(); ++n) {
        const piece& p = arr.pieces[n];
        const std::uint32_t from = tris[p.source].mesh;
        bool flip = false;
        if (!kept(n, flip)) continue;
        std::array<std::uint32_t, 3> f{};
        for (std::size_t m = 0; m < 3; ++m) {
            const vid v = p.v[m];
            if (out_id[v] == unset) {
                const point3 x = arr.points[v].approximate();
                const std::array<double, 3> key{std::ldexp(x.x, -scale), std::ldexp(x.y, -scale),
                                                std::ldexp(x.z, -scale)};
                auto [pos, fresh] = by_position.try_emplace(key, std::uint32_t(soup.points.size()));
                if (fresh)
                    soup.points.push_back(key);
                else
                    ++report.snapped_vertices;
                out_id[v] = pos->second;
            }
            f[m] = out_id[v];
        }
        if (f[0] == f[1] || f[1] == f[2] || f[2] == f[0]) continue;
        if (flip) std::swap(f[1], f[2]);
        soup.indices.insert(soup.indices.end(), f.begin(), f.end());
        soup.face_offsets.push_back(soup.indices.size());
        report.faces.push_back({std::uint8_t(from), tris[p.source].face});
    }
    // A safety net behind the exact rounding of constructed points: no result is reported with a
    // coordinate that is not finite; the output mesh is left unchanged.
    for (std::size_t n = 0; n < soup.points.size(); ++n)
        for (double c : soup.points[n])
            if (!std::isfinite(c))
                return fail(errc::unsupported,
                            std::string(who) + ": output vertex " + std::to_string(n) +
                                " rounded to a coordinate that is not finite",
                            (long long)n);
    std::vector<char> rounded(soup.points.size(), 0);
    for (std::size_t v = explicit_count; v < out_id.size(); ++v)
        if (out_id[v] != unset) rounded[out_id[v]] = 1;
    check_rounding(soup, rounded, report);
    return soup;
}

/// mesh_boolean's body, run inside its thread arena.
template <class MO, class MA, class MB, class TO, class TA, class TB>
result<boolean_report> run(MO& out, const MA& a, const MB& b, const boolean_options& options) {
    namespace bd = detail::boolean;
    using bd::label;
    using bd::vid;
    detail::progress_gate gate(options.progress, 4, "mesh_boolean");
    std::vector<bd::point3> points;
    std::vector<bd::soup_triangle> tris;
    if (auto r = bd::read_input<MA, TA>(a, 0, points, tris); !r) return r.error();
    if (auto r = bd::read_input<MB, TB>(b, 1, points, tris); !r) return r.error();
    // Scaling by a power of two is exact and keeps every predicate's sign.
    const auto scale = bd::implicit_scale(points);
    if (!scale) return scale.error();
    for (bd::point3& p : points) p = {std::ldexp(p.x, *scale), std::ldexp(p.y, *scale), std::ldexp(p.z, *scale)};
    bd::merge_explicit(points, tris);
    if (!gate.advance()) return fail(errc::cancelled, "mesh_boolean: cancelled");

    bd::arrangement arr;
    if (!bd::build_arrangement(points, tris, arr, &gate, true)) {
        if (gate.cancelled()) return fail(errc::cancelled, "mesh_boolean: cancelled");
        return fail(errc::unsupported, "mesh_boolean: the cuts of one triangle could not be triangulated");
    }
    if (!gate.advance()) return fail(errc::cancelled, "mesh_boolean: cancelled");
    boolean_report report;
    report.intersecting_pairs = arr.pairs;
    auto windings = bd::windings_of(arr, tris, points, 2, "mesh_boolean");
    if (!windings) return windings.error();

    // Without winding numbers (coplanar overlaps between clean inputs), labels: a piece that lies
    // in a coplanar face of the other mesh is "on" it (same or opposite orientation); the others,
    // in patches joined across uncut edges, are in or out by the exact winding number
    // (inside_closed) of an input vertex of the patch off the other surface, or, when the patch
    // has none, of the rounded centroid of its largest piece: the one decision not made exactly.
    const std::size_t explicit_count = points.size();
    std::vector<label> labels(arr.pieces.size(), label::out);
    if (!*windings) {
        std::vector<char> on(arr.pieces.size(), 0);
        for (std::size_t n = 0; n < arr.pieces.size(); ++n)
            for (std::uint32_t j : arr.coplanar[arr.pieces[n].source]) {
                bool inside = false;
                const label l = bd::coplanar_label(arr, tris, arr.pieces[n], j, inside);
                if (inside) {
                    labels[n] = l;
                    on[n] = 1;
                    break;
                }
            }
        union_find patches(arr.pieces.size());
        {
            // Pieces joined across every uncut edge: (edge, piece) records bucketed by the edge's
            // smaller end, each bucket sorted, then each run of one edge.
            std::vector<std::size_t> start(arr.points.size() + 1, 0);
            auto each_edge = [&](const auto& f) {
                for (std::uint32_t n = 0; n < arr.pieces.size(); ++n) {
                    if (on[n]) continue;
                    const bd::tri3& t = arr.pieces[n].v;
                    for (std::size_t m = 0; m < 3; ++m) {
                        const std::array<vid, 2> e{std::min(t[m], t[(m + 1) % 3]), std::max(t[m], t[(m + 1) % 3])};
                        if (!std::binary_search(arr.cut_edges.begin(), arr.cut_edges.end(), e)) f(e, n);
                    }
                }
            };
            each_edge([&](const std::array<vid, 2>& e, std::uint32_t) { ++start[e[0] + 1]; });
            for (std::size_t v = 1; v < start.size(); ++v) start[v] += start[v - 1];
            std::vector<std::array<vid, 2>> by_edge(start.back());  // (larger end, piece)
            std::vector<std::size_t> fill(start.begin(), start.end() - 1);
            each_edge([&](const std::array<vid, 2>& e, std::uint32_t n) { by_edge[fill[e[0]]++] = {e[1], n}; });
            for (std::size_t v = 0; v + 1 < start.size(); ++v) {
                const auto first = by_edge.begin() + std::ptrdiff_t(start[v]);
                const auto last = by_edge.begin() + std::ptrdiff_t(start[v + 1]);
                std::sort(first, last);
                for (auto x = first, run = first; x != last; ++x) {
                    if ((*x)[0] != (*run)[0]) run = x;
                    if (x != run && tris[arr.pieces[(*x)[1]].source].mesh == tris[arr.pieces[(*run)[1]].source].mesh)
                        patches.unite((*run)[1], (*x)[1]);
                }
            }
        }
        auto locate = [&](std::uint32_t other, const bd::point3& p) -> result<point_location> {
            const vec3<double> q{std::ldexp(p.x, -*scale), std::ldexp(p.y, -*scale), std::ldexp(p.z, -*scale)};
            if (other == 0) return inside_closed<MA, TA>(a, q);
            return inside_closed<MB, TB>(b, q);
        };
        // Each patch's pieces in order, the patches by root: (root, piece) pairs sorted.
        std::vector<std::array<std::uint32_t, 2>> by_root;
        for (std::uint32_t n = 0; n < arr.pieces.size(); ++n)
            if (!on[n]) by_root.push_back({patches.find(n), n});
        std::sort(by_root.begin(), by_root.end());
        std::vector<std::pair<std::uint32_t, std::vector<std::uint32_t>>> members;
        for (std::size_t x = 0; x < by_root.size(); ++x) {
            if (x == 0 || by_root[x][0] != by_root[x - 1][0]) members.push_back({by_root[x][0], {}});
            members.back().second.push_back(by_root[x][1]);
        }
        for (const auto& [root, list] : members) {
            const std::uint32_t other = 1 - tris[arr.pieces[list[0]].source].mesh;
            // An input vertex of the patch off the other surface decides it exactly.
            std::optional<label> found;
            double best_area = -1;
            bd::point3 centroid{};
            for (std::uint32_t m : list) {
                for (vid v : arr.pieces[m].v) {
                    if (v >= explicit_count) continue;
                    auto where = locate(other, points[v]);
                    if (!where) return where.error();
                    if (*where == point_location::on_surface) continue;
                    found = *where == point_location::inside ? label::in : label::out;
                    break;
                }
                if (found) break;
                const bd::point3 p = arr.points[arr.pieces[m].v[0]].approximate(),
                                 q = arr.points[arr.pieces[m].v[1]].approximate(),
                                 r = arr.points[arr.pieces[m].v[2]].approximate();
                const bd::point3 u{q.x - p.x, q.y - p.y, q.z - p.z}, w{r.x - p.x, r.y - p.y, r.z - p.z};
                const bd::point3 c{u.y * w.z - u.z * w.y, u.z * w.x - u.x * w.z, u.x * w.y - u.y * w.x};
                const double area = c.x * c.x + c.y * c.y + c.z * c.z;
                if (area > best_area) {
                    best_area = area;
                    centroid = {(p.x + q.x + r.x) / 3, (p.y + q.y + r.y) / 3, (p.z + q.z + r.z) / 3};
                }
            }
            if (!found) {
                auto where = locate(other, centroid);
                if (!where) return where.error();
                found = *where == point_location::inside ? label::in : label::out;
            }
            for (std::uint32_t m : list) labels[m] = *found;
        }
    }
    if (!gate.advance()) return fail(errc::cancelled, "mesh_boolean: cancelled");

    // The kept pieces, rounded once.
    auto kept = [&](std::size_t n, bool& flip) {
        if (*windings) {
            const auto& w = **windings;
            const bool pos = bd::in_result(options.op, w.pos[2 * n], w.pos[2 * n + 1]),
                       neg = bd::in_result(options.op, w.neg[2 * n], w.neg[2 * n + 1]);
            flip = pos;
            return pos != neg;
        }
        return bd::keep(options.op, tris[arr.pieces[n].source].mesh, labels[n], flip);
    };
    auto soup = bd::round_kept(arr, tris, *scale, explicit_count, kept, report, "mesh_boolean");
    if (!soup) return soup.error();
    if (!gate.advance()) return fail(errc::cancelled, "mesh_boolean: cancelled");
    if (auto r = detail::copy::build<MO, TO>(out, *soup); !r) return r.error();
    return report;
}

}  // namespace hmira::detail::boolean

namespace hmira {

template <class MO, class MA, class MB, class TO, class TA, class TB>
    requires copy_target_mesh<MO, TO> && boolean_input_mesh<MA, TA> && boolean_input_mesh<MB, TB>
result<boolean_report> mesh_boolean(MO& out, const MA& a, const MB& b, const boolean_options& options) {
    std::optional<result<boolean_report>> r;
    detail::with_thread_count(options.threads,
                              [&] { r.emplace(detail::boolean::run<MO, MA, MB, TO, TA, TB>(out, a, b, options)); });
    return std::move(*r);
}

}  // namespace hmira
