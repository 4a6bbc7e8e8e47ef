// hmira/algorithms/repair/detail/repair_polygon_soup_impl.hpp
// The machinery of repair_polygon_soup.hpp: one function per step of the repair (merging
// corners, pairing the faces along each edge, orienting each piece, grouping corners into
// fans, detaching faces that cannot stay glued, and writing the output), and the report's
// summary.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "../../../core/result.hpp"

namespace hmira {

inline std::string soup_repair_report::summary() const {
    std::string s;
    auto plural = [](std::size_t n, const char* one, const char* many) {
        return std::to_string(n) + " " + (n == 1 ? one : many);
    };
    auto list = [](const repair_count& c) {
        std::string t = " (";
        for (std::size_t i = 0; i < c.first.size(); ++i) t += (i ? ", " : "") + std::to_string(c.first[i]);
        return t + (c.first.size() < c.count ? ", ...)" : ")");
    };
    auto add = [&](const std::string& part) { s += (s.empty() ? "" : "; ") + part; };
    if (degenerate_faces.count)
        add("dropped " + plural(degenerate_faces.count, "degenerate face", "degenerate faces") +
            list(degenerate_faces));
    if (merged_corners.count)
        add("merged repeated corners in " + plural(merged_corners.count, "face", "faces") + list(merged_corners));
    if (nonmanifold_edge_faces.count) {
        const bool dropped = dropped_faces > degenerate_faces.count;
        add(plural(nonmanifold_edges, "non-manifold edge", "non-manifold edges") + ": " +
            (dropped ? "dropped " : "cut free ") + plural(nonmanifold_edge_faces.count, "extra face", "extra faces") +
            list(nonmanifold_edge_faces));
    }
    if (detached_faces.count) add("detached " + plural(detached_faces.count, "face", "faces") + list(detached_faces));
    if (flipped_faces.count) add("flipped " + plural(flipped_faces.count, "face", "faces") + list(flipped_faces));
    if (orientation_cuts) add("opened " + plural(orientation_cuts, "edge", "edges") + " where no orientation agrees");
    if (added_vertices)
        add("split " + plural(split_vertices.count, "vertex", "vertices") + list(split_vertices) + " into " +
            plural(added_vertices, "extra copy", "extra copies"));
    return s.empty() ? "no repair needed" : s;
}

namespace detail {

/// Union-find with path halving and union by size.
class corner_sets {
public:
    explicit corner_sets(std::size_t n) : parent_(n), size_(n, 1) {
        std::iota(parent_.begin(), parent_.end(), std::uint64_t{0});
    }
    std::uint64_t find(std::uint64_t x) {
        while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
        return x;
    }
    void unite(std::uint64_t a, std::uint64_t b) {
        a = find(a), b = find(b);
        if (a == b) return;
        if (size_[a] < size_[b]) std::swap(a, b);
        parent_[b] = a;
        size_[a] += size_[b];
    }

private:
    std::vector<std::uint64_t> parent_;
    std::vector<std::uint64_t> size_;
};

inline void note(repair_count& c, std::size_t element, std::size_t listed) {
    if (c.first.size() < listed) c.first.push_back(element);
    ++c.count;
}

inline void sort_listed(repair_count& c, std::size_t listed, std::vector<std::size_t>& all) {
    // Elements found out of order (flips, splits) are gathered whole, then the smallest listed.
    std::sort(all.begin(), all.end());
    c.count = all.size();
    c.first.assign(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(std::min(listed, all.size())));
}

/// Faces as CSR plus, per corner, its face; the half-edge leaving corner k ends at corner next(k).
struct working_faces {
    std::vector<std::uint64_t> offsets{0};
    std::vector<std::uint32_t> corners;
    std::vector<std::size_t> source;     // input face
    std::vector<std::uint32_t> face_of;  // per corner
    std::uint64_t next(std::uint64_t k) const {
        const std::uint32_t f = face_of[k];
        return k + 1 == offsets[f + 1] ? offsets[f] : k + 1;
    }
};

inline constexpr std::uint64_t no_partner = ~std::uint64_t{0};

/// Half-edges grouped by undirected edge: group g is by_edge[group_start[g] .. group_start[g+1]),
/// sorted by face. Counting sort on the smaller vertex, then a sort inside each vertex's short
/// list: O(C log d) for largest vertex degree d.
struct edge_groups {
    std::vector<std::uint64_t> by_edge;
    std::vector<std::uint64_t> group_start;
};

inline edge_groups group_edges(const working_faces& w, std::size_t vertex_count) {
    const std::size_t c = w.corners.size();
    auto low = [&](std::uint64_t k) { return std::min(w.corners[k], w.corners[w.next(k)]); };
    auto high = [&](std::uint64_t k) { return std::max(w.corners[k], w.corners[w.next(k)]); };
    std::vector<std::uint64_t> start(vertex_count + 1, 0);
    for (std::uint64_t k = 0; k < c; ++k) ++start[low(k) + 1];
    for (std::size_t v = 0; v < vertex_count; ++v) start[v + 1] += start[v];
    edge_groups g;
    g.by_edge.resize(c);
    {
        std::vector<std::uint64_t> fill(start.begin(), start.end() - 1);
        for (std::uint64_t k = 0; k < c; ++k) g.by_edge[fill[low(k)]++] = k;
    }
    for (std::size_t v = 0; v < vertex_count; ++v) {
        auto b = g.by_edge.begin() + static_cast<std::ptrdiff_t>(start[v]);
        auto e = g.by_edge.begin() + static_cast<std::ptrdiff_t>(start[v + 1]);
        std::sort(b, e, [&](std::uint64_t x, std::uint64_t y) {
            const auto hx = high(x), hy = high(y);
            return hx != hy ? hx < hy : x < y;  // corners are numbered face by face, so x < y orders by face
        });
    }
    for (std::uint64_t i = 0; i < c; ++i)
        if (i == 0 || low(g.by_edge[i]) != low(g.by_edge[i - 1]) || high(g.by_edge[i]) != high(g.by_edge[i - 1]))
            g.group_start.push_back(i);
    g.group_start.push_back(c);
    return g;
}

/// Pairs the half-edges of each edge: two faces on an edge are paired; on an edge with more
/// faces the first face is paired with the first one running the other way (else the second)
/// and the rest are left unpaired and returned as "extra".
inline std::vector<std::uint64_t> pair_edges(const working_faces& w, const edge_groups& g,
                                             std::vector<std::uint8_t>& extra, std::size_t& nonmanifold_edges) {
    std::vector<std::uint64_t> partner(w.corners.size(), no_partner);
    extra.assign(w.offsets.size() - 1, 0);
    nonmanifold_edges = 0;
    for (std::size_t i = 0; i + 1 < g.group_start.size(); ++i) {
        const auto b = g.group_start[i], e = g.group_start[i + 1];
        if (e - b < 2) continue;
        const auto first = g.by_edge[b];
        auto second = g.by_edge[b + 1];
        if (e - b > 2) {
            ++nonmanifold_edges;
            for (auto j = b + 1; j < e; ++j)
                if (w.corners[g.by_edge[j]] != w.corners[first]) {
                    second = g.by_edge[j];
                    break;
                }
            for (auto j = b + 1; j < e; ++j)
                if (g.by_edge[j] != second) extra[w.face_of[g.by_edge[j]]] = 1;
        }
        partner[first] = second;
        partner[second] = first;
    }
    return partner;
}

/// Step 1: the input faces with repeated consecutive corners merged, and without the faces
/// left degenerate (fewer than 3 corners, or a vertex repeated elsewhere); notes both in the
/// report. Errors (errc::invalid_argument) for decreasing offsets or a vertex out of range.
inline result<working_faces> merge_corners(std::size_t vertex_count, std::span<const std::uint64_t> face_offsets,
                                           std::span<const std::uint32_t> corners, std::size_t listed,
                                           soup_repair_report& report) {
    const std::size_t input_faces = face_offsets.size() - 1;
    working_faces w;
    w.corners.reserve(corners.size());
    w.source.reserve(input_faces);
    std::vector<std::uint32_t> sorted;
    for (std::size_t f = 0; f < input_faces; ++f) {
        const auto b = face_offsets[f], e = face_offsets[f + 1];
        if (e < b)
            return fail(errc::invalid_argument,
                        "repair_polygon_soup: face_offsets decrease at face " + std::to_string(f),
                        static_cast<long long>(f));
        const std::size_t start = w.corners.size();
        for (auto k = b; k < e; ++k) {
            const auto v = corners[k];
            if (v >= vertex_count)
                return fail(errc::invalid_argument,
                            "repair_polygon_soup: face " + std::to_string(f) + " names vertex " + std::to_string(v) +
                                " of " + std::to_string(vertex_count),
                            static_cast<long long>(f));
            if (w.corners.size() == start || w.corners.back() != v) w.corners.push_back(v);
        }
        while (w.corners.size() - start > 1 && w.corners.back() == w.corners[start]) w.corners.pop_back();
        const std::size_t k = w.corners.size() - start;
        bool degenerate = k < 3;
        if (!degenerate) {
            sorted.assign(w.corners.begin() + static_cast<std::ptrdiff_t>(start), w.corners.end());
            std::sort(sorted.begin(), sorted.end());
            degenerate = std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
        }
        if (degenerate) {
            w.corners.resize(start);
            note(report.degenerate_faces, f, listed);
            continue;
        }
        if (k != e - b) note(report.merged_corners, f, listed);
        w.source.push_back(f);
        w.offsets.push_back(w.corners.size());
    }
    return w;
}

/// Sets each corner's face.
inline void index_faces(working_faces& w) {
    w.face_of.resize(w.corners.size());
    for (std::size_t f = 0; f + 1 < w.offsets.size(); ++f)
        for (auto k = w.offsets[f]; k < w.offsets[f + 1]; ++k) w.face_of[k] = static_cast<std::uint32_t>(f);
}

/// The faces of w that are not marked extra, with their faces indexed.
inline working_faces without_extra_faces(const working_faces& w, const std::vector<std::uint8_t>& extra) {
    working_faces kept;
    for (std::size_t f = 0; f + 1 < w.offsets.size(); ++f) {
        if (extra[f]) continue;
        kept.corners.insert(kept.corners.end(), w.corners.begin() + static_cast<std::ptrdiff_t>(w.offsets[f]),
                            w.corners.begin() + static_cast<std::ptrdiff_t>(w.offsets[f + 1]));
        kept.offsets.push_back(kept.corners.size());
        kept.source.push_back(w.source[f]);
    }
    index_faces(kept);
    return kept;
}

/// Step 3: which faces to reverse, each connected piece oriented by a breadth-first walk over
/// glued edges, keeping the orientation most of its faces had; a glued pair that runs the
/// same way after the walk's choices is opened instead (counted in the report).
inline std::vector<std::uint8_t> orient_pieces(const working_faces& w, std::vector<std::uint64_t>& partner,
                                               soup_repair_report& report) {
    const std::size_t nf = w.source.size();
    std::vector<std::uint8_t> flip(nf, 0), seen(nf, 0);
    std::vector<std::uint32_t> piece;
    for (std::size_t root = 0; root < nf; ++root) {
        if (seen[root]) continue;
        piece.clear();
        piece.push_back(static_cast<std::uint32_t>(root));
        seen[root] = 1;
        std::size_t flipped = 0;
        for (std::size_t q = 0; q < piece.size(); ++q) {
            const auto f = piece[q];
            for (auto k = w.offsets[f]; k < w.offsets[f + 1]; ++k) {
                const auto p = partner[k];
                if (p == no_partner) continue;
                const auto g = w.face_of[p];
                const bool same_way = w.corners[k] == w.corners[p];
                const std::uint8_t wanted = static_cast<std::uint8_t>(flip[f] ^ (same_way ? 1 : 0));
                if (!seen[g]) {
                    seen[g] = 1;
                    flip[g] = wanted;
                    flipped += wanted;
                    piece.push_back(g);
                } else if (flip[g] != wanted) {
                    partner[k] = partner[p] = no_partner;
                    ++report.orientation_cuts;
                }
            }
        }
        if (2 * flipped > piece.size())  // keep the orientation most faces had
            for (auto f : piece) flip[f] ^= 1;
    }
    return flip;
}

/// Step 4: the output vertex of each corner. The corners of each vertex are grouped into the
/// fans they form through glued edges; the first fan keeps the input vertex, every other one
/// gets a copy (appended to copied_from).
inline void group_fans(const working_faces& w, const std::vector<std::uint64_t>& partner, std::size_t vertex_count,
                       std::vector<std::uint32_t>& copied_from, std::vector<std::uint32_t>& vertex_of) {
    const std::size_t c = w.corners.size();
    corner_sets sets(c);
    for (std::uint64_t k = 0; k < c; ++k) {
        const auto p = partner[k];
        if (p == no_partner || p < k) continue;
        if (w.corners[k] == w.corners[p]) {
            sets.unite(k, p);
            sets.unite(w.next(k), w.next(p));
        } else {
            sets.unite(k, w.next(p));
            sets.unite(w.next(k), p);
        }
    }
    std::vector<std::uint32_t> id(c, 0xffffffffu);
    std::vector<std::uint8_t> used(vertex_count, 0);
    copied_from.clear();
    for (std::uint64_t k = 0; k < c; ++k) {
        const auto r = sets.find(k);
        if (id[r] == 0xffffffffu) {
            const auto v = w.corners[k];
            if (!used[v]) {
                used[v] = 1;
                id[r] = v;
            } else {
                id[r] = static_cast<std::uint32_t>(vertex_count + copied_from.size());
                copied_from.push_back(v);
            }
        }
        vertex_of[k] = id[r];
    }
}

/// A face cut free at a non-manifold edge can still meet the glued pair there through its
/// other edges on both ends; such a face is detached whole (its glued edges opened, noted in
/// the report). Detaching only opens edges that had a single pair, so it cannot create a new
/// conflict: one pass suffices. Returns whether any face was detached.
inline bool detach_stuck_faces(const working_faces& w, const edge_groups& groups,
                               const std::vector<std::uint32_t>& vertex_of, std::vector<std::uint64_t>& partner,
                               std::size_t listed, soup_repair_report& report) {
    const std::size_t nf = w.source.size();
    std::vector<std::uint64_t> keyed;
    std::vector<std::uint8_t> detach(nf, 0);
    bool any = false;
    for (std::size_t i = 0; i + 1 < groups.group_start.size(); ++i) {
        const auto b = groups.group_start[i], e = groups.group_start[i + 1];
        if (e - b < 3) continue;
        keyed.assign(groups.by_edge.begin() + static_cast<std::ptrdiff_t>(b),
                     groups.by_edge.begin() + static_cast<std::ptrdiff_t>(e));
        auto key = [&](std::uint64_t k) {
            const auto a = vertex_of[k], z = vertex_of[w.next(k)];
            return std::pair{std::min(a, z), std::max(a, z)};
        };
        std::sort(keyed.begin(), keyed.end(), [&](auto x, auto y) { return key(x) < key(y); });
        for (std::size_t s = 0; s < keyed.size();) {
            std::size_t t = s;
            bool glued = false;
            while (t < keyed.size() && key(keyed[t]) == key(keyed[s])) glued |= partner[keyed[t++]] != no_partner;
            if (glued && t - s > 2)
                for (auto j = s; j < t; ++j)
                    if (partner[keyed[j]] == no_partner) detach[w.face_of[keyed[j]]] = 1, any = true;
            s = t;
        }
    }
    if (!any) return false;
    for (std::size_t f = 0; f < nf; ++f) {
        if (!detach[f]) continue;
        note(report.detached_faces, w.source[f], listed);
        for (auto k = w.offsets[f]; k < w.offsets[f + 1]; ++k)
            if (partner[k] != no_partner) partner[partner[k]] = no_partner, partner[k] = no_partner;
    }
    return true;
}

/// The output faces (reversed where flip says, on the output vertices) and the report's
/// flipped faces and split vertices; takes w's face sources.
inline void write_repaired(working_faces& w, const std::vector<std::uint8_t>& flip,
                           const std::vector<std::uint32_t>& vertex_of, std::size_t vertex_count, std::size_t listed,
                           repaired_polygon_soup& out) {
    soup_repair_report& report = out.report;
    const std::size_t nf = w.source.size();
    out.vertex_count = vertex_count + out.copied_from.size();
    out.corners.reserve(w.corners.size());
    out.face_offsets.reserve(nf + 1);
    std::vector<std::size_t> all;
    for (std::size_t f = 0; f < nf; ++f) {
        const auto b = w.offsets[f], e = w.offsets[f + 1];
        if (flip[f]) {
            all.push_back(w.source[f]);
            for (auto k = e; k > b; --k) out.corners.push_back(vertex_of[k - 1]);
        } else {
            for (auto k = b; k < e; ++k) out.corners.push_back(vertex_of[k]);
        }
        out.face_offsets.push_back(out.corners.size());
    }
    sort_listed(report.flipped_faces, listed, all);
    all.assign(out.copied_from.begin(), out.copied_from.end());
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    sort_listed(report.split_vertices, listed, all);
    report.added_vertices = out.copied_from.size();
    out.face_source = std::move(w.source);
}

}  // namespace detail

inline result<repaired_polygon_soup> repair_polygon_soup(std::size_t vertex_count,
                                                         std::span<const std::uint64_t> face_offsets,
                                                         std::span<const std::uint32_t> corners,
                                                         const soup_repair_options& options) {
    if (vertex_count > std::size_t{0xffffffffu})
        return fail(errc::invalid_argument, "repair_polygon_soup: " + std::to_string(vertex_count) +
                                                " vertices; at most 2^32 - 1 can be indexed");
    if (face_offsets.empty() || face_offsets.front() != 0 || face_offsets.back() != corners.size())
        return fail(errc::invalid_argument,
                    "repair_polygon_soup: face_offsets must start at 0 and end at corners.size() (" +
                        std::to_string(corners.size()) + ")");
    const std::size_t input_faces = face_offsets.size() - 1;
    const std::size_t listed = options.listed;
    repaired_polygon_soup out;
    soup_repair_report& report = out.report;

    // 1. Merge repeated corners, drop degenerate faces.
    auto merged = detail::merge_corners(vertex_count, face_offsets, corners, listed, report);
    if (!merged) return merged.error();
    detail::working_faces w = std::move(*merged);
    if (w.source.size() > std::size_t{0xffffffffu})
        return fail(errc::invalid_argument, "repair_polygon_soup: " + std::to_string(w.source.size()) +
                                                " faces; at most 2^32 - 1 are supported");
    detail::index_faces(w);

    // 2. Pair the faces along each edge.
    auto groups = detail::group_edges(w, vertex_count);
    std::vector<std::uint8_t> extra;
    auto partner = detail::pair_edges(w, groups, extra, report.nonmanifold_edges);
    for (std::size_t f = 0; f < extra.size(); ++f)
        if (extra[f]) detail::note(report.nonmanifold_edge_faces, w.source[f], listed);
    if (options.nonmanifold_edges == nonmanifold_edge_policy::drop_faces && report.nonmanifold_edge_faces.count > 0) {
        // Without the extra faces every edge has at most two faces left, so pairing again is final.
        w = detail::without_extra_faces(w, extra);
        groups = detail::group_edges(w, vertex_count);
        std::size_t unused = 0;
        partner = detail::pair_edges(w, groups, extra, unused);
    }
    const std::size_t nf = w.source.size();

    // 3. Orient each piece.
    const auto flip = detail::orient_pieces(w, partner, report);

    // 4. Group the corners of each vertex into fans, joined through glued edges.
    std::vector<std::uint32_t> vertex_of(w.corners.size());  // output vertex of each corner
    detail::group_fans(w, partner, vertex_count, out.copied_from, vertex_of);
    if (vertex_count + out.copied_from.size() > std::size_t{0xffffffffu})
        return fail(errc::invalid_argument,
                    "repair_polygon_soup: splitting vertices would need more than 2^32 - 1 vertices");
    if (detail::detach_stuck_faces(w, groups, vertex_of, partner, listed, report))
        detail::group_fans(w, partner, vertex_count, out.copied_from, vertex_of);

    // Output, with the report's flipped faces and split vertices.
    detail::write_repaired(w, flip, vertex_of, vertex_count, listed, out);
    report.dropped_faces = input_faces - nf;
    return out;
}

}  // namespace hmira
