// hmira/algorithms/conversion/detail/marching_cubes_table.hpp
// The marching-cubes case table, built at first use from the cube's geometry rather than
// typed in. For each of the 256 inside/outside corner patterns and each way of deciding its
// ambiguous faces, it walks the iso-contour segments around the six faces into closed loops
// and triangulates each loop. Because a face's segments depend only on that face's corners and
// its decision, the two cubes sharing a face always agree, and the surface closes up.
#pragma once

#include <array>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace hmira::detail::mc {

// Corner c sits at offset (c & 1, (c >> 1) & 1, (c >> 2) & 1) from the cube's first sample.
// Edges 0-3 run along x, 4-7 along y, 8-11 along z.
inline constexpr std::array<std::array<int, 2>, 12> edge_corners{{
    {0, 1},
    {2, 3},
    {4, 5},
    {6, 7},  // x
    {0, 2},
    {1, 3},
    {4, 6},
    {5, 7},  // y
    {0, 4},
    {1, 5},
    {2, 6},
    {3, 7},  // z
}};

constexpr int edge_between(int a, int b) {
    for (int e = 0; e < 12; ++e)
        if ((edge_corners[e][0] == a && edge_corners[e][1] == b) ||
            (edge_corners[e][0] == b && edge_corners[e][1] == a))
            return e;
    return -1;
}

/// The six faces, numbered 2 * axis + side, each with its corners counter-clockwise seen from
/// outside the cube.
inline constexpr std::array<std::array<int, 4>, 6> face_corners = [] {
    std::array<std::array<int, 4>, 6> f{};
    for (int a = 0; a < 3; ++a) {
        const int u = (a + 1) % 3, v = (a + 2) % 3;  // (u, v, a) is right-handed
        const int cu[4] = {0, 1, 1, 0}, cv[4] = {0, 0, 1, 1};
        for (int s = 0; s < 2; ++s)
            for (int m = 0; m < 4; ++m) {
                const int mm = s == 1 ? m : 3 - m;  // the low face is seen from -a: reverse
                f[2 * a + s][m] = (s << a) | (cu[mm] << u) | (cv[mm] << v);
            }
    }
    return f;
}();

/// A face is ambiguous when its inside corners sit on one diagonal and outside ones on the other.
constexpr bool face_is_ambiguous(int config, int face) {
    int b[4];
    for (int m = 0; m < 4; ++m) b[m] = (config >> face_corners[face][m]) & 1;
    return b[0] == b[2] && b[1] == b[3] && b[0] != b[1];
}

/// Index that stands for the extra vertex of a loop no chord-free triangulation exists for.
inline constexpr std::uint8_t center_vertex = 12;

/// One configuration's triangles: `count` triangles as edge-index triples in `edges`; index
/// `center_vertex` names an extra vertex at the mean of the edges in `center_loop` (bit e).
struct case_triangles {
    std::uint8_t count = 0;
    std::uint16_t center_loop = 0;
    std::array<std::uint8_t, 36> edges{};
};

struct case_table {
    /// Faces that are ambiguous for each configuration, in increasing order, and how many.
    std::array<std::array<std::uint8_t, 6>, 256> ambiguous_faces{};
    std::array<std::uint8_t, 256> ambiguous_count{};
    /// Which cube edges the configuration crosses (bit e for edge e).
    std::array<std::uint16_t, 256> crossed_edges{};
    /// entries[first[config] + d]: triangles for decision bits d (bit n: the n-th ambiguous
    /// face connects its inside corners).
    std::array<std::uint32_t, 256> first{};
    std::vector<case_triangles> entries;
};

namespace table_detail {

inline bool edges_share_face(int e1, int e2) {
    for (const auto& f : face_corners) {
        int hits = 0;
        for (int c : {edge_corners[e1][0], edge_corners[e1][1], edge_corners[e2][0], edge_corners[e2][1]})
            for (int m = 0; m < 4; ++m) hits += f[m] == c;
        if (hits == 4) return true;
    }
    return false;
}

// Triangulates a loop without a diagonal between two of its vertices that lie on one cube
// face: the neighbouring cube may draw that same chord, which would give it four triangles.
inline bool triangulate(const std::vector<int>& loop, std::vector<int>& out) {
    const int k = static_cast<int>(loop.size());
    auto chord_ok = [&](int a, int b) {
        if (b == a + 1 || (a == 0 && b == k - 1)) return true;  // a loop side, not a chord
        return !edges_share_face(loop[a], loop[b]);
    };
    // possible[a][b]: the sub-polygon a..b (b > a) can be triangulated; split[a][b] its apex.
    std::vector<std::vector<int>> split(k, std::vector<int>(k, -1));
    std::vector<std::vector<char>> possible(k, std::vector<char>(k, 0));
    for (int a = 0; a + 1 < k; ++a) possible[a][a + 1] = 1;
    for (int len = 2; len < k; ++len)
        for (int a = 0; a + len < k; ++a) {
            const int b = a + len;
            if (!chord_ok(a, b)) continue;
            // Prefer apexes near the middle: fewer slivers than a fan.
            for (int step = 0; step <= len && !possible[a][b]; ++step)
                for (int m : {a + len / 2 - step, a + len / 2 + step})
                    if (m > a && m < b && possible[a][m] && possible[m][b] && !possible[a][b]) {
                        possible[a][b] = 1;
                        split[a][b] = m;
                    }
        }
    if (!possible[0][k - 1]) return false;
    std::vector<std::array<int, 2>> stack{{0, k - 1}};
    while (!stack.empty()) {
        const auto [a, b] = stack.back();
        stack.pop_back();
        if (b - a < 2) continue;
        const int m = split[a][b];
        out.insert(out.end(), {loop[a], loop[m], loop[b]});
        stack.push_back({a, m});
        stack.push_back({m, b});
    }
    return true;
}

inline case_triangles build_case(int config, unsigned decisions, const std::array<std::uint8_t, 6>& amb, int n_amb) {
    std::array<int, 12> next;
    next.fill(-1);
    for (int f = 0; f < 6; ++f) {
        const auto& c = face_corners[f];
        bool in[4];
        for (int m = 0; m < 4; ++m) in[m] = (config >> c[m]) & 1;
        bool connected = false;
        for (int n = 0; n < n_amb; ++n)
            if (amb[n] == f) connected = (decisions >> n) & 1;
        const bool ambiguous = face_is_ambiguous(config, f);
        for (int m = 0; m < 4; ++m) {
            const int m1 = (m + 1) % 4;
            if (!(in[m] && !in[m1])) continue;  // segments start on an inside->outside edge
            const int start = edge_between(c[m], c[m1]);
            int end = -1;
            if (ambiguous) {
                // Connected: cut off the outside corner ahead; separated: cut off this inside corner.
                const int e = connected ? (m + 1) % 4 : (m + 3) % 4;
                end = edge_between(c[e], c[(e + 1) % 4]);
            } else {
                for (int q = 0; q < 4; ++q)
                    if (!in[q] && in[(q + 1) % 4]) end = edge_between(c[q], c[(q + 1) % 4]);
            }
            next[start] = end;
        }
    }
    case_triangles out;
    std::vector<int> tris;
    std::array<bool, 12> seen{};
    for (int e = 0; e < 12; ++e) {
        if (next[e] < 0 || seen[e]) continue;
        std::vector<int> loop;
        for (int x = e; !seen[x]; x = next[x]) {
            if (next[x] < 0) throw std::logic_error("marching cubes table: open contour");
            seen[x] = true;
            loop.push_back(x);
        }
        // Loops run clockwise seen from outside the surface: reverse so normals point outward.
        std::vector<int> rev(loop.rbegin(), loop.rend());
        if (triangulate(rev, tris)) continue;
        // Every triangulation needs a chord along an ambiguous face (a few mixed decisions of
        // cases 10, 12 and 13): fan around an extra vertex instead, as MC33 does.
        if (out.center_loop) throw std::logic_error("marching cubes table: two loops need a centre vertex");
        for (std::size_t q = 0; q < rev.size(); ++q) {
            tris.insert(tris.end(), {int(center_vertex), rev[q], rev[(q + 1) % rev.size()]});
            out.center_loop = std::uint16_t(out.center_loop | (1u << rev[q]));
        }
    }
    out.count = static_cast<std::uint8_t>(tris.size() / 3);
    if (tris.size() > out.edges.size()) throw std::logic_error("marching cubes table: too many triangles");
    for (std::size_t t = 0; t < tris.size(); ++t) out.edges[t] = static_cast<std::uint8_t>(tris[t]);
    return out;
}

inline case_table build_table() {
    case_table t;
    for (int config = 0; config < 256; ++config) {
        int n = 0;
        for (int f = 0; f < 6; ++f)
            if (face_is_ambiguous(config, f)) t.ambiguous_faces[config][n++] = static_cast<std::uint8_t>(f);
        t.ambiguous_count[config] = static_cast<std::uint8_t>(n);
        std::uint16_t crossed = 0;
        for (int e = 0; e < 12; ++e)
            if (((config >> edge_corners[e][0]) & 1) != ((config >> edge_corners[e][1]) & 1))
                crossed |= std::uint16_t(1u << e);
        t.crossed_edges[config] = crossed;
        t.first[config] = static_cast<std::uint32_t>(t.entries.size());
        for (unsigned d = 0; d < (1u << n); ++d)
            t.entries.push_back(build_case(config, d, t.ambiguous_faces[config], n));
    }
    return t;
}

}  // namespace table_detail

/// The table, built once (thread-safe) at first use.
inline const case_table& table() {
    static const case_table t = table_detail::build_table();
    return t;
}

}  // namespace hmira::detail::mc
