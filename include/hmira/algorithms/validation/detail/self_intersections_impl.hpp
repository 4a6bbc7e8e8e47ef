// hmira/algorithms/validation/detail/self_intersections_impl.hpp
// The machinery of self_intersections (see ../self_intersections.hpp for the interface): the
// faces as triangles over vertex indices, a sweep over their bounding boxes, in parallel blocks,
// and the exact test of one pair of triangles given the vertices they share.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <string>
#include <vector>

#include "../../../concepts.hpp"
#include "../../../core/progress.hpp"
#include "../../../core/result.hpp"
#include "../../../predicates/intersect3d.hpp"
#include "../../conversion/detail/parallel.hpp"
#include "../../triangulation/detail/indexed_triangles.hpp"
#include "../../triangulation/triangulate_faces.hpp"
#include "../self_intersections.hpp"

namespace hmira::detail::self_intersect {

using predicates::point3;

using triangle = detail::triangulation::indexed_triangle;

/// The closed axis-aligned box of a triangle (exact: the corners are doubles).
struct box {
    point3 lo, hi;
};

inline bool boxes_overlap(const box& a, const box& b) noexcept {
    return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y && a.lo.z <= b.hi.z &&
           b.lo.z <= a.hi.z;
}

/// The corners of s other than those it shares with t, in order, and how many it shares.
inline std::size_t shared_corners(const std::array<std::size_t, 3>& s, const std::array<std::size_t, 3>& t,
                                  std::array<std::size_t, 3>& own) noexcept {
    std::size_t n_own = 0, shared = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        const bool in_t = s[i] == t[0] || s[i] == t[1] || s[i] == t[2];
        if (in_t)
            ++shared;
        else
            own[n_own++] = s[i];
    }
    return shared;
}

/// True if triangles s and t (vertex indices into pos) share a point other than the vertices and
/// the edge they share by index. Exact; see self_intersections for the rules.
inline bool triangles_cross(const std::array<std::size_t, 3>& s, const std::array<std::size_t, 3>& t,
                            const std::vector<point3>& pos) noexcept {
    const point3 &a = pos[s[0]], &b = pos[s[1]], &c = pos[s[2]];
    const point3 &d = pos[t[0]], &e = pos[t[1]], &f = pos[t[2]];
    std::array<std::size_t, 3> s_own{}, t_own{};
    const std::size_t shared = shared_corners(s, t, s_own);
    shared_corners(t, s, t_own);
    if (shared == 0) return predicates::triangles_intersect(a, b, c, d, e, f);
    if (predicates::collinear(a, b, c) || predicates::collinear(d, e, f)) return false;
    if (shared >= 3) return true;  // the same three corners
    if (shared == 2) {
        // Planes through a common edge meet only on its line; in one plane, the triangles overlap
        // when their third corners lie on the same side of the edge.
        std::size_t u = 0, w = 0, found = 0;
        for (std::size_t i = 0; i < 3; ++i)
            if (s[i] != s_own[0]) (found++ == 0 ? u : w) = s[i];
        const point3 &pu = pos[u], &pw = pos[w], &p = pos[s_own[0]], &q = pos[t_own[0]];
        if (predicates::orient3d(pu, pw, p, q) != 0) return false;
        for (int k = 0; k < 3; ++k)
            if (const int op = predicates::detail::orient2d_drop(k, pu, pw, p); op != 0)
                return predicates::detail::orient2d_drop(k, pu, pw, q) == op;
        return false;  // unreachable: the triangle is not flat
    }
    // One common corner: the intersection, convex and holding it, reaches further exactly when
    // the edge opposite the corner in one triangle meets the other triangle.
    return predicates::segment_intersects_triangle(pos[s_own[0]], pos[s_own[1]], d, e, f) ||
           predicates::segment_intersects_triangle(pos[t_own[0]], pos[t_own[1]], a, b, c);
}

/// The pair search: triangles sorted by their boxes' low end along `axis`, each compared with
/// the later ones whose boxes start before its own ends. Blocks of the sorted order run in
/// parallel, each into its own list, so the result does not depend on the schedule.
struct sweep {
    const std::vector<triangle>& tris;
    const std::vector<point3>& pos;
    std::vector<box> boxes;
    std::vector<std::size_t> order;
    std::size_t axis = 0;

    sweep(const std::vector<triangle>& t, const std::vector<point3>& p) : tris(t), pos(p) {
        boxes.resize(tris.size());
        point3 lo{}, hi{};
        for (std::size_t i = 0; i < tris.size(); ++i) {
            box b{pos[tris[i].v[0]], pos[tris[i].v[0]]};
            for (std::size_t k = 1; k < 3; ++k)
                for (std::size_t c = 0; c < 3; ++c) {
                    b.lo[c] = std::min(b.lo[c], pos[tris[i].v[k]][c]);
                    b.hi[c] = std::max(b.hi[c], pos[tris[i].v[k]][c]);
                }
            boxes[i] = b;
            for (std::size_t c = 0; c < 3; ++c) {
                lo[c] = i == 0 ? b.lo[c] : std::min(lo[c], b.lo[c]);
                hi[c] = i == 0 ? b.hi[c] : std::max(hi[c], b.hi[c]);
            }
        }
        const double ex = hi.x - lo.x, ey = hi.y - lo.y, ez = hi.z - lo.z;
        axis = ex >= ey && ex >= ez ? 0 : (ey >= ez ? 1 : 2);
        order.resize(tris.size());
        std::iota(order.begin(), order.end(), std::size_t(0));
        std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
            const double bx = boxes[x].lo[axis], by = boxes[y].lo[axis];
            return bx < by || (bx == by && x < y);
        });
    }

    /// The face pairs found from the triangles at sorted positions [begin, end).
    void run_block(std::size_t begin, std::size_t end, std::vector<face_pair>& out) const {
        for (std::size_t i = begin; i < end; ++i) {
            const std::size_t x = order[i];
            const double stop = boxes[x].hi[axis];
            for (std::size_t j = i + 1; j < order.size(); ++j) {
                const std::size_t y = order[j];
                if (boxes[y].lo[axis] > stop) break;
                if (tris[x].face == tris[y].face || !boxes_overlap(boxes[x], boxes[y])) continue;
                if (!triangles_cross(tris[x].v, tris[y].v, pos)) continue;
                const std::size_t f = tris[x].face, g = tris[y].face;
                out.push_back({std::min(f, g), std::max(f, g)});
            }
        }
    }
};

/// Triangles per block of the parallel search: each block is one progress step.
inline constexpr std::size_t block_size = 2048;

}  // namespace hmira::detail::self_intersect

namespace hmira {

template <class M, class T>
    requires self_intersection_mesh<M, T>
result<std::vector<face_pair>> self_intersections(const M& mesh, const self_intersections_options& options) {
    namespace si = detail::self_intersect;
    auto pos = detail::triangulation::predicate_positions<M, T>(mesh, "self_intersections");
    if (!pos) return pos.error();
    const std::vector<si::triangle> tris = detail::triangulation::indexed_triangles<M, T>(mesh);
    const si::sweep sweep(tris, *pos);
    const std::size_t blocks = (tris.size() + si::block_size - 1) / si::block_size;
    std::vector<std::vector<face_pair>> found(blocks);
    detail::progress_gate gate(options.progress, blocks, "self_intersections");
    detail::with_thread_count(options.threads, [&] {
        detail::parallel_chunks(blocks, 1, [&](std::size_t b0, std::size_t b1) {
            for (std::size_t b = b0; b < b1; ++b) {
                if (gate.cancelled()) return;
                sweep.run_block(b * si::block_size, std::min(tris.size(), (b + 1) * si::block_size), found[b]);
                gate.advance();
            }
        });
    });
    if (gate.cancelled()) return fail(errc::cancelled, "self_intersections: cancelled");
    std::vector<face_pair> out;
    for (const auto& f : found) out.insert(out.end(), f.begin(), f.end());
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

}  // namespace hmira
