// hmira/algorithms/boolean/detail/cell_windings.hpp
// The winding number of every input mesh on both sides of every piece of an arrangement, exactly,
// as in Zhou, Grinspun, Zorin and Jacobson 2016, "Mesh Arrangements for Solid Geometry":
//
// - patches: pieces joined across edges that exactly two pieces share, run once each way;
// - cells: around every other edge the pieces are sorted by angle (exact orientations against
//   the plane of each piece's input triangle), and the two sides facing one wedge are one cell;
// - seeds: in each connected part of the surface, one cell's winding numbers are counted along a
//   segment between explicit points outside the bounding box, each crossing of a piece (at a
//   line-plane point, decided in the piece's plane) adding or removing one turn of its mesh; a
//   segment that meets an edge or a vertex of a piece is dropped and another one is tried;
// - propagation: across a patch of mesh m, from its positive to its negative side, w_m grows by
//   one; a cell reached with two different values means the input is not closed.
//
// Every decision is an exact predicate; the segments' ends are rounded, which only chooses the
// segment. The caller guarantees that no two pieces overlap (no coplanar overlapping triangles).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "../../topology/connected_components.hpp"
#include "arrangement.hpp"

namespace hmira::detail::boolean {

/// The winding numbers of every input mesh on both sides of every piece: piece n, mesh m at
/// [n * meshes + m]; `pos` on the side the piece's normal points to.
struct piece_windings {
    std::size_t meshes = 0;
    std::vector<std::int32_t> pos, neg;
};

/// Why the winding numbers could not be found.
enum class winding_status : std::uint8_t {
    ok,
    coincident,  ///< two pieces share a half-plane around an edge
    not_closed,  ///< a cell got two different values: some input is open or wrongly oriented
    no_seed,     ///< no segment missed every edge and vertex (not met in practice)
};

/// The coarsest and finest bits over all nonzero coordinates; `any` is false when there are none.
struct coordinate_bits {
    int low = 0, high = 0;
    bool any = false;
};

/// The bits of `points`, as above.
inline coordinate_bits bits_of(const std::vector<point3>& points) {
    coordinate_bits b;
    for (const point3& p : points)
        for (std::size_t k = 0; k < 3; ++k) {
            if (p[k] == 0.0) continue;
            int l = 0, h = 0;
            predicates::bit_span(p[k], l, h);
            b.low = b.any ? std::min(b.low, l) : l;
            b.high = b.any ? std::max(b.high, h) : h;
            b.any = true;
        }
    return b;
}

/// The number of bits from the coarsest to the finest bit over all coordinates (0 for none).
inline int coordinate_span(const std::vector<point3>& points) {
    const coordinate_bits b = bits_of(points);
    return b.any ? b.high - b.low : 0;
}

class cell_windings {
public:
    cell_windings(const arrangement& arr, const std::vector<soup_triangle>& tris, std::size_t explicit_count,
                  std::size_t meshes)
        : arr_(arr), tris_(tris), explicit_count_(explicit_count), meshes_(meshes), pieces_(arr.pieces.size()) {}

    winding_status run(piece_windings& out) {
        build_patches();
        if (!build_cells()) return winding_status::coincident;
        cell_value_.assign(2 * patches_ * meshes_, 0);
        known_.assign(2 * patches_, 0);
        build_seeding_data();
        // Each segment aims at the first part not seeded yet; one that keeps meeting edges or
        // vertices (64 segments in a row) gives up.
        std::vector<char> seeded(components_, 0);
        std::size_t next = 0;
        for (std::uint32_t attempt = 0, failures = 0;; ++attempt) {
            while (next < components_ && seeded[next]) ++next;
            if (next == components_) break;
            const winding_status s = cast(attempt, std::uint32_t(next), seeded);
            if (s != winding_status::ok) return s;
            failures = seeded[next] ? 0 : failures + 1;
            if (failures == 64) return winding_status::no_seed;
        }
        out.meshes = meshes_;
        out.pos.resize(pieces_ * meshes_);
        out.neg.resize(pieces_ * meshes_);
        for (std::size_t n = 0; n < pieces_; ++n) {
            const std::uint32_t cp = cells_.find(2 * patch_[n]), cn = cells_.find(2 * patch_[n] + 1);
            for (std::size_t m = 0; m < meshes_; ++m) {
                out.pos[n * meshes_ + m] = cell_value_[cp * meshes_ + m];
                out.neg[n * meshes_ + m] = cell_value_[cn * meshes_ + m];
            }
        }
        return winding_status::ok;
    }

private:
    struct edge_use {
        std::uint64_t key;  ///< (smaller id, larger id)
        std::uint32_t piece;
        std::uint8_t forward;  ///< the piece runs from the smaller id to the larger
    };

    const point3& corner(std::uint32_t t, std::size_t m) const {
        return arr_.points[tris_[t].v[m]].explicit_coordinates();
    }
    int orient_against(std::uint32_t piece, const exact_point& d) const {
        const std::uint32_t t = arr_.pieces[piece].source;
        return predicates::orient3d(corner(t, 0), corner(t, 1), corner(t, 2), d);
    }

    /// Pieces joined across edges that two pieces share, run once each way.
    void build_patches() {
        uses_.reserve(3 * pieces_);
        for (std::uint32_t n = 0; n < pieces_; ++n) {
            const tri3& t = arr_.pieces[n].v;
            for (std::size_t m = 0; m < 3; ++m) {
                const vid a = t[m], b = t[(m + 1) % 3];
                uses_.push_back({(std::uint64_t(std::min(a, b)) << 32) | std::max(a, b), n, std::uint8_t(a < b)});
            }
        }
        std::sort(uses_.begin(), uses_.end(), [](const edge_use& x, const edge_use& y) {
            return x.key < y.key || (x.key == y.key && x.piece < y.piece);
        });
        union_find joined(pieces_), parts(pieces_);
        for (std::size_t g = 0; g < uses_.size();) {
            std::size_t h = g + 1;
            while (h < uses_.size() && uses_[h].key == uses_[g].key) ++h;
            for (std::size_t x = g + 1; x < h; ++x) parts.unite(uses_[g].piece, uses_[x].piece);
            if (h - g == 2 && uses_[g].forward != uses_[g + 1].forward)
                joined.unite(uses_[g].piece, uses_[g + 1].piece);
            else
                groups_.push_back({g, h});
            g = h;
        }
        patch_.assign(pieces_, 0);
        component_.assign(pieces_, 0);
        std::vector<std::uint32_t> patch_id(pieces_, ~0u), comp_id(pieces_, ~0u);
        for (std::uint32_t n = 0; n < pieces_; ++n) {
            const std::uint32_t r = joined.find(n), c = parts.find(n);
            if (patch_id[r] == ~0u) {
                patch_id[r] = std::uint32_t(patches_++);
                patch_mesh_.push_back(tris_[arr_.pieces[n].source].mesh);
            }
            if (comp_id[c] == ~0u) comp_id[c] = std::uint32_t(components_++);
            patch_[n] = patch_id[r];
            component_[n] = comp_id[c];
        }
    }

    /// Sorts the pieces around every edge not inside a patch; sides facing one wedge are one cell.
    /// False when two pieces share a half-plane.
    bool build_cells() {
        cells_ = union_find(2 * patches_);
        std::vector<std::size_t> order;
        std::vector<int> half;
        for (const auto& [g, h] : groups_) {
            const vid a = vid(uses_[g].key >> 32), b = vid(uses_[g].key & 0xffffffffu);
            const std::size_t n = h - g;
            auto third = [&](std::size_t u) -> const exact_point& {
                const tri3& t = arr_.pieces[uses_[u].piece].v;
                for (vid v : t)
                    if (v != a && v != b) return arr_.points[v];
                return arr_.points[t[0]];
            };
            // O(p, q): +1 when q's third corner is turned from p's by an angle in (0, pi) about a -> b.
            auto O = [&](std::size_t p, std::size_t q) {
                return (uses_[p].forward ? 1 : -1) * orient_against(uses_[p].piece, third(q));
            };
            half.assign(n, 0);
            const std::size_t r = g;
            for (std::size_t u = g + 1; u < h; ++u) {
                const int o = O(r, u);
                if (o != 0) {
                    half[u - g] = o > 0 ? 1 : 3;
                    continue;
                }
                const int k = arr_.drop[arr_.pieces[uses_[r].piece].source];
                const int sr = predicates::orient2d(k, arr_.points[a], arr_.points[b], third(r)),
                          su = predicates::orient2d(k, arr_.points[a], arr_.points[b], third(u));
                if (sr == su) return false;
                half[u - g] = 2;
            }
            order.resize(n);
            for (std::size_t u = 0; u < n; ++u) order[u] = g + u;
            std::sort(order.begin(), order.end(), [&](std::size_t p, std::size_t q) {
                if (half[p - g] != half[q - g]) return half[p - g] < half[q - g];
                return p != q && (half[p - g] == 1 || half[p - g] == 3) && O(p, q) > 0;
            });
            for (std::size_t u = 0; u + 1 < n; ++u) {
                const std::size_t p = order[u], q = order[u + 1];
                if (half[p - g] == half[q - g] && (half[p - g] == 2 || O(p, q) == 0)) return false;
            }
            for (std::size_t u = 0; u < n; ++u) {
                const edge_use &p = uses_[order[u]], &q = uses_[order[(u + 1) % n]];
                cells_.unite(2 * patch_[p.piece] + (p.forward ? 0 : 1), 2 * patch_[q.piece] + (q.forward ? 1 : 0));
            }
        }
        return true;
    }

    /// The box of the input, the pieces of every input triangle and of every component.
    void build_seeding_data() {
        for (std::size_t i = 0; i < explicit_count_; ++i) {
            const point3& p = arr_.points[i].explicit_coordinates();
            for (std::size_t k = 0; k < 3; ++k) {
                lo_[k] = i == 0 ? p[k] : std::min(lo_[k], p[k]);
                hi_[k] = i == 0 ? p[k] : std::max(hi_[k], p[k]);
            }
        }
        by_source_start_.assign(tris_.size() + 1, 0);
        for (const piece& p : arr_.pieces) ++by_source_start_[p.source + 1];
        for (std::size_t i = 0; i < tris_.size(); ++i) by_source_start_[i + 1] += by_source_start_[i];
        by_source_.resize(pieces_);
        std::vector<std::size_t> fill(by_source_start_.begin(), by_source_start_.end() - 1);
        for (std::uint32_t n = 0; n < pieces_; ++n) by_source_[fill[arr_.pieces[n].source]++] = n;
        component_pieces_.resize(components_);
        for (std::uint32_t n = 0; n < pieces_; ++n) component_pieces_[component_[n]].push_back(n);
    }

    /// An explicit point near x on the grid of 2^g: 24 bits below the box's size, so the ends add
    /// few bits to the input's span (the callers' span limits leave room for them).
    point3 on_grid(const point3& x, int g) const {
        point3 r;
        for (std::size_t k = 0; k < 3; ++k) r[k] = std::ldexp(std::nearbyint(std::ldexp(x[k], -g)), g);
        return r;
    }

    struct hit {
        exact_point x;
        std::uint32_t piece;
        int from_side;  ///< orient3d of the segment's start against the piece's plane
    };

    /// One segment through a piece of `component`; seeds every component it passes before it meets
    /// an edge or a vertex. A segment that meets one seeds nothing.
    winding_status cast(std::uint32_t attempt, std::uint32_t component, std::vector<char>& seeded) {
        const auto& list = component_pieces_[component];
        const std::uint32_t target = list[(std::size_t(attempt) * 7919u) % list.size()];
        point3 q{};
        for (vid v : arr_.pieces[target].v) {
            const point3 a = arr_.points[v].approximate();
            for (std::size_t k = 0; k < 3; ++k) q[k] += a[k] / 3;
        }
        const double t = attempt + 1.0;
        const point3 d{0.1 + std::fmod(0.6180339887498949 * t, 1.0), -0.1 - std::fmod(0.7548776662466927 * t, 1.0),
                       0.1 + std::fmod(0.5698402909980532 * t, 1.0)};
        double diag = 0;
        for (std::size_t k = 0; k < 3; ++k) diag = std::max(diag, hi_[k] - lo_[k]);
        int e = 0;
        std::frexp(diag, &e);
        const int g = e - 24;
        const double len = 8 * diag / std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        const point3 s = on_grid({q.x - len * d.x, q.y - len * d.y, q.z - len * d.z}, g);
        const point3 f = on_grid({q.x + len * d.x, q.y + len * d.y, q.z + len * d.z}, g);
        std::vector<hit> hits;
        for (std::uint32_t i = 0; i < tris_.size(); ++i) {
            if (arr_.drop[i] < 0 || by_source_start_[i] == by_source_start_[i + 1]) continue;
            const point3 &a = corner(i, 0), &b = corner(i, 1), &c = corner(i, 2);
            if (!predicates::segment_intersects_triangle(s, f, a, b, c)) continue;
            const int ss = predicates::orient3d(a, b, c, s), sf = predicates::orient3d(a, b, c, f);
            if (ss * sf >= 0) return winding_status::ok;  // the segment lies in the triangle's plane
            const exact_point x(predicates::line_plane_point{s, f, a, b, c});
            const int k = arr_.drop[i];
            bool found = false;
            for (std::size_t u = by_source_start_[i]; u < by_source_start_[i + 1]; ++u) {
                const tri3& p = arr_.pieces[by_source_[u]].v;
                const auto& P = arr_.points;
                const int sp = predicates::orient2d(k, P[p[0]], P[p[1]], P[p[2]]);
                int o[3];
                for (std::size_t m = 0; m < 3; ++m) o[m] = sp * predicates::orient2d(k, P[p[m]], P[p[(m + 1) % 3]], x);
                if (o[0] < 0 || o[1] < 0 || o[2] < 0) continue;
                if (o[0] == 0 || o[1] == 0 || o[2] == 0) return winding_status::ok;  // on an edge or a vertex
                hits.push_back({x, by_source_[u], ss});
                found = true;
                break;
            }
            if (!found) return winding_status::ok;  // the pieces cover the triangle: not met
        }
        const int dir = predicates::compare_xyz(exact_point(s), exact_point(f));
        std::sort(hits.begin(), hits.end(),
                  [&](const hit& x, const hit& y) { return predicates::compare_xyz(x.x, y.x) == dir; });
        for (std::size_t n = 1; n < hits.size(); ++n)
            if (predicates::compare_xyz(hits[n - 1].x, hits[n].x) == 0) return winding_status::ok;
        std::vector<std::int32_t> w(meshes_, 0);
        std::vector<std::uint32_t> fresh;
        for (const hit& h : hits) {
            const std::uint32_t c = component_[h.piece];
            const std::uint32_t cell = cells_.find(2 * patch_[h.piece] + (h.from_side > 0 ? 0 : 1));
            if (!seeded[c] || known_[cell]) {
                if (known_[cell]) {
                    for (std::size_t m = 0; m < meshes_; ++m)
                        if (cell_value_[cell * meshes_ + m] != w[m]) return winding_status::not_closed;
                } else {
                    std::copy(w.begin(), w.end(), cell_value_.begin() + std::ptrdiff_t(cell * meshes_));
                    known_[cell] = 1;
                    fresh.push_back(cell);
                }
                seeded[c] = 1;
            }
            w[tris_[arr_.pieces[h.piece].source].mesh] += h.from_side > 0 ? 1 : -1;
        }
        return propagate(fresh);
    }

    /// Carries known cells' values across patches: w(negative side) = w(positive side) + e_mesh.
    winding_status propagate(std::vector<std::uint32_t> stack) {
        if (neighbours_start_.empty()) {
            neighbours_start_.assign(2 * patches_ + 1, 0);
            for (std::uint32_t p = 0; p < patches_; ++p) {
                ++neighbours_start_[cells_.find(2 * p) + 1];
                ++neighbours_start_[cells_.find(2 * p + 1) + 1];
            }
            for (std::size_t c = 0; c < 2 * patches_; ++c) neighbours_start_[c + 1] += neighbours_start_[c];
            neighbours_.resize(2 * patches_);
            std::vector<std::size_t> fill(neighbours_start_.begin(), neighbours_start_.end() - 1);
            for (std::uint32_t p = 0; p < patches_; ++p) {
                neighbours_[fill[cells_.find(2 * p)]++] = 2 * p;
                neighbours_[fill[cells_.find(2 * p + 1)]++] = 2 * p + 1;
            }
        }
        while (!stack.empty()) {
            const std::uint32_t c = stack.back();
            stack.pop_back();
            for (std::size_t u = neighbours_start_[c]; u < neighbours_start_[c + 1]; ++u) {
                const std::uint32_t side = neighbours_[u], p = side / 2;
                const std::uint32_t other = cells_.find(side ^ 1u);
                const std::int32_t step = (side & 1u) ? -1 : 1;  // from the positive side inward: +1
                for (std::size_t m = 0; m < meshes_; ++m) {
                    const std::int32_t v = cell_value_[c * meshes_ + m] + (m == patch_mesh_[p] ? step : 0);
                    if (known_[other] && cell_value_[other * meshes_ + m] != v) return winding_status::not_closed;
                    if (!known_[other]) scratch_value(other, m, v);
                }
                if (!known_[other]) {
                    known_[other] = 1;
                    stack.push_back(other);
                }
            }
        }
        return winding_status::ok;
    }

    void scratch_value(std::uint32_t cell, std::size_t m, std::int32_t v) { cell_value_[cell * meshes_ + m] = v; }

    const arrangement& arr_;
    const std::vector<soup_triangle>& tris_;
    std::size_t explicit_count_, meshes_, pieces_;
    std::vector<edge_use> uses_;
    std::vector<std::array<std::size_t, 2>> groups_;
    std::vector<std::uint32_t> patch_, component_, patch_mesh_;
    std::size_t patches_ = 0, components_ = 0;
    union_find cells_{0};
    std::vector<std::int32_t> cell_value_;
    std::vector<char> known_;
    point3 lo_{}, hi_{};
    std::vector<std::size_t> by_source_start_, neighbours_start_;
    std::vector<std::uint32_t> by_source_, neighbours_;
    std::vector<std::vector<std::uint32_t>> component_pieces_;
};

}  // namespace hmira::detail::boolean
