// hmira/algorithms/delaunay/detail/delaunay_kernel.hpp
// The engine behind delaunay_triangulation: incremental Bowyer-Watson insertion over a
// Hilbert/BRIO order, with a visibility walk from the last new triangle, compact triangle
// arrays, ghost triangles for the outside, and the exact predicates. Not a public interface.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "../../../predicates/incircle.hpp"
#include "../../../predicates/orient2d.hpp"

namespace hmira::detail::delaunay {

/// The vertex id standing for the point at infinity: ghost triangles (a, b, ghost) close the
/// triangulation into a sphere, so points outside the hull need no special case.
inline constexpr std::uint32_t ghost = 0xFFFFFFFFu;

struct xy {
    double x, y;
};

// ---------------------------------------------------------------------------------------------
// Spatial sorting

/// Position of cell (x, y) along the Hilbert curve filling a 2^bits x 2^bits grid. Branch-free:
/// the quadrant bits are random for scattered points, so branches would mispredict half the time.
inline std::uint32_t hilbert_index(std::uint32_t x, std::uint32_t y, int bits) noexcept {
    std::uint32_t d = 0;
    for (int i = bits - 1; i >= 0; --i) {
        const std::uint32_t rx = (x >> i) & 1u;
        const std::uint32_t ry = (y >> i) & 1u;
        d = (d << 2) | ((3u * rx) ^ ry);
        // Rotate the quadrant so that the curve inside it starts and ends where it should:
        // in the lower-right quadrant reflect (complement the lower bits), in both lower
        // quadrants swap x and y. Bits at and above i are never read again.
        const std::uint32_t flip = 0u - (rx & (ry ^ 1u));
        x ^= flip;
        y ^= flip;
        const std::uint32_t swap = (x ^ y) & (0u - (ry ^ 1u));
        x ^= swap;
        y ^= swap;
    }
    return d;
}

/// Sorts 64-bit words by their upper 32 bits (LSD radix, 3 passes of 11 bits); stable.
inline void radix_sort_high(std::vector<std::uint64_t>& a) {
    std::vector<std::uint64_t> tmp(a.size());
    for (int shift = 32; shift < 64; shift += 11) {
        std::array<std::size_t, 2049> count{};
        for (std::uint64_t v : a) ++count[((v >> shift) & 2047u) + 1];
        for (std::size_t i = 1; i < count.size(); ++i) count[i] += count[i - 1];
        for (std::uint64_t v : a) tmp[count[(v >> shift) & 2047u]++] = v;
        a.swap(tmp);
    }
}

/// Insertion order for the points: rounds of a biased randomised insertion order (BRIO,
/// Amenta-Choi-Rote) with each round sorted along a Hilbert curve. The Hilbert order keeps each
/// walk short and the memory traffic local; the rounds keep the expected cost of the
/// incremental construction low whatever order the input comes in.
inline std::vector<std::uint32_t> insertion_order(const std::vector<xy>& pts, bool brio) {
    const std::size_t n = pts.size();
    double minx = pts[0].x, maxx = pts[0].x, miny = pts[0].y, maxy = pts[0].y;
    for (const xy& p : pts) {
        minx = std::min(minx, p.x), maxx = std::max(maxx, p.x);
        miny = std::min(miny, p.y), maxy = std::max(maxy, p.y);
    }
    constexpr int bits = 15;
    const double extent = std::max(maxx - minx, maxy - miny);
    const double scale = extent > 0 ? (double((1u << bits) - 1) / extent) : 0.0;
    std::vector<std::uint64_t> keys(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto qx =
            static_cast<std::uint32_t>(std::clamp((pts[i].x - minx) * scale, 0.0, double((1u << bits) - 1)));
        const auto qy =
            static_cast<std::uint32_t>(std::clamp((pts[i].y - miny) * scale, 0.0, double((1u << bits) - 1)));
        std::uint32_t round = 2;
        if (brio) {
            // A fixed hash of the index, so that the result does not depend on a global seed:
            // 1/64 of the points in round 0, 7/64 in round 1, the rest last.
            std::uint32_t h = static_cast<std::uint32_t>(i) * 0x9E3779B1u;
            h ^= h >> 16;
            h *= 0x85EBCA6Bu;
            h ^= h >> 13;
            round = (h >> 26) == 0 ? 0u : ((h >> 29) == 0 ? 1u : 2u);
        }
        const std::uint64_t key = (std::uint64_t(round) << 30) | hilbert_index(qx, qy, bits);
        keys[i] = (key << 32) | static_cast<std::uint32_t>(i);
    }
    radix_sort_high(keys);
    std::vector<std::uint32_t> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<std::uint32_t>(keys[i]);
    return order;
}

// ---------------------------------------------------------------------------------------------
// The triangulation

/// Triangles in flat arrays. Corner i of triangle t is tv[3t + i], counter-clockwise; the edge
/// opposite corner i runs from corner i+1 to corner i+2, and ta[3t + i] is the same edge seen
/// from the neighbour (3t' + i'). A ghost triangle has the ghost vertex at corner 2, and its
/// finite edge (corner 0 -> corner 1) has the hull's inside on its right.
class triangulation {
public:
    std::vector<xy> p;              ///< vertex positions, by vertex id
    std::vector<std::uint32_t> tv;  ///< 3 vertex ids per triangle
    std::vector<std::uint32_t> ta;  ///< 3 opposite halfedges per triangle

    explicit triangulation(std::vector<xy> points) : p(std::move(points)) {
        tv.reserve(6 * p.size() + 16);
        ta.reserve(6 * p.size() + 16);
    }

    std::uint32_t triangle_count() const noexcept { return static_cast<std::uint32_t>(tv.size() / 3); }
    bool is_ghost(std::uint32_t t) const noexcept { return tv[3 * t + 2] == ghost; }

    int orient(std::uint32_t a, std::uint32_t b, std::uint32_t c) const noexcept {
        return predicates::orient2d(p[a].x, p[a].y, p[b].x, p[b].y, p[c].x, p[c].y);
    }

    /// Starts from three non-collinear vertices: one finite triangle and three ghosts.
    void init(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        if (orient(a, b, c) < 0) std::swap(b, c);
        const std::uint32_t v[3] = {a, b, c};
        tv.assign({a, b, c});
        ta.assign(12, 0);
        for (std::uint32_t i = 0; i < 3; ++i) {
            const std::uint32_t g = 1 + i;
            tv.insert(tv.end(), {v[(i + 2) % 3], v[(i + 1) % 3], ghost});
            ta[i] = 3 * g + 2;
            ta[3 * g + 2] = i;
            const std::uint32_t g2 = 1 + (i + 2) % 3;
            ta[3 * g + 0] = 3 * g2 + 1;
            ta[3 * g2 + 1] = 3 * g + 0;
        }
        last_ = 0;
    }

    /// Inserts vertex q. Returns q, or the vertex q coincides with (a duplicate, not inserted).
    std::uint32_t insert(std::uint32_t q) {
        const std::uint32_t t = locate(q);
        if (!is_ghost(t)) {
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t v = tv[3 * t + k];
                if (p[v].x == p[q].x && p[v].y == p[q].y) return v;
            }
        }
        dig_cavity(t, q);
        fill_cavity(q);
        return q;
    }

private:
    static constexpr std::uint32_t next3[3] = {1, 2, 0};
    static constexpr std::uint32_t prev3[3] = {2, 0, 1};

    struct frame {
        std::uint32_t t, e, rem;
    };
    struct boundary_edge {
        std::uint32_t a, b, outside;
    };

    std::uint32_t last_ = 0;  // a finite triangle next to the last insertion
    std::uint32_t rng_ = 2463534242u;
    std::vector<std::uint32_t> cavity_;
    std::vector<boundary_edge> boundary_;
    std::vector<frame> stack_;
    std::vector<std::uint32_t> slot_;
    std::vector<std::uint8_t> rot_;

    std::uint32_t random3() noexcept {
        rng_ ^= rng_ << 13;
        rng_ ^= rng_ >> 17;
        rng_ ^= rng_ << 5;
        return rng_ % 3;
    }

    /// Visibility walk from the last new triangle, starting each step at a random edge (so it
    /// cannot cycle). Ends in a finite triangle whose closure holds q, or in a ghost triangle
    /// whose hull edge q lies strictly outside of.
    std::uint32_t locate(std::uint32_t q) noexcept {
        std::uint32_t t = last_;
        std::uint32_t came = 3;
        const double qx = p[q].x, qy = p[q].y;
        for (;;) {
            if (is_ghost(t)) return t;
            const std::uint32_t* v = &tv[3 * t];
            const std::uint32_t e0 = random3();
            std::uint32_t e = e0;
            bool moved = false;
            for (int k = 0; k < 3; ++k, e = next3[e]) {
                if (e == came) continue;
                const xy& u = p[v[next3[e]]];
                const xy& w = p[v[prev3[e]]];
                if (predicates::orient2d(u.x, u.y, w.x, w.y, qx, qy) < 0) {
                    const std::uint32_t h = ta[3 * t + e];
                    t = h / 3;
                    came = h - 3 * t;
                    moved = true;
                    break;
                }
            }
            if (!moved) return t;
        }
    }

    /// True if q lies strictly inside the circumcircle of t. For a ghost triangle (a, b, ghost)
    /// the circle degenerates to the open half-plane outside the hull edge plus the open edge.
    bool in_conflict(std::uint32_t t, std::uint32_t q) const noexcept {
        const std::uint32_t a = tv[3 * t], b = tv[3 * t + 1], c = tv[3 * t + 2];
        const xy &pa = p[a], &pb = p[b], &pq = p[q];
        if (c == ghost) {
            const int o = predicates::orient2d(pa.x, pa.y, pb.x, pb.y, pq.x, pq.y);
            if (o != 0) return o > 0;
            if (pa.x != pb.x) return std::min(pa.x, pb.x) < pq.x && pq.x < std::max(pa.x, pb.x);
            return std::min(pa.y, pb.y) < pq.y && pq.y < std::max(pa.y, pb.y);
        }
        const xy& pc = p[c];
        return predicates::incircle(pa.x, pa.y, pb.x, pb.y, pc.x, pc.y, pq.x, pq.y) > 0;
    }

    /// Collects the triangles in conflict with q (a tree of triangles, since no vertex lies
    /// inside the cavity) by depth-first search in counter-clockwise edge order, so that the
    /// cavity's boundary edges come out as one counter-clockwise cycle.
    void dig_cavity(std::uint32_t t0, std::uint32_t q) {
        cavity_.clear();
        boundary_.clear();
        cavity_.push_back(t0);
        stack_.push_back({t0, 0, 3});
        while (!stack_.empty()) {
            frame& f = stack_.back();
            if (f.rem == 0) {
                stack_.pop_back();
                continue;
            }
            const std::uint32_t j = f.e;
            const std::uint32_t t = f.t;
            f.e = next3[j];
            --f.rem;
            const std::uint32_t h = 3 * t + j;
            const std::uint32_t o = ta[h];
            const std::uint32_t n = o / 3;
            if (in_conflict(n, q)) {
                cavity_.push_back(n);
                stack_.push_back({n, next3[o - 3 * n], 2});
            } else {
                boundary_.push_back({tv[3 * t + next3[j]], tv[3 * t + prev3[j]], o});
            }
        }
    }

    /// Replaces the cavity by the fan of triangles (q, a, b) over its boundary edges a -> b,
    /// reusing the cavity's slots first.
    void fill_cavity(std::uint32_t q) {
        const std::size_t k = boundary_.size();
        const std::size_t m = cavity_.size();
        slot_.resize(k);
        rot_.resize(k);
        for (std::size_t i = 0; i < k; ++i) {
            if (i < m) {
                slot_[i] = cavity_[i];
            } else {
                slot_[i] = triangle_count();
                tv.resize(tv.size() + 3);
                ta.resize(ta.size() + 3);
            }
            // Keep the ghost vertex at corner 2: (q, ghost, b) is stored as (b, q, ghost).
            rot_[i] = boundary_[i].a == ghost ? 1 : 0;
        }
        static constexpr std::uint32_t pos[2][3] = {{0, 1, 2}, {1, 2, 0}};
        for (std::size_t i = 0; i < k; ++i) {
            const std::uint32_t s = slot_[i];
            const std::uint32_t* ps = pos[rot_[i]];
            const boundary_edge& be = boundary_[i];
            tv[3 * s + ps[0]] = q;
            tv[3 * s + ps[1]] = be.a;
            tv[3 * s + ps[2]] = be.b;
            ta[3 * s + ps[0]] = be.outside;
            ta[be.outside] = 3 * s + ps[0];
            const std::size_t ip = i + 1 == k ? 0 : i + 1;
            const std::size_t im = i == 0 ? k - 1 : i - 1;
            ta[3 * s + ps[1]] = 3 * slot_[ip] + pos[rot_[ip]][2];
            ta[3 * s + ps[2]] = 3 * slot_[im] + pos[rot_[im]][1];
            if (be.a != ghost && be.b != ghost) last_ = s;
        }
    }
};

}  // namespace hmira::detail::delaunay
