// tests/predicates/sat_reference.hpp
// An independent reference for the intersection tests on small integer coordinates: closed
// convex sets are disjoint exactly when some axis separates their projections, and for two
// proper triangles the face normals, the edge cross products and the in-plane edge normals
// are enough axes (they hold every face normal of the Minkowski difference). All in integers.
#pragma once

#include <algorithm>
#include <array>
#include <vector>

namespace hmira_test {

using ivec = std::array<long long, 3>;

inline ivec isub(const ivec& a, const ivec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline ivec icross(const ivec& a, const ivec& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline long long idot(const ivec& a, const ivec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline bool izero(const ivec& a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }

/// True if no axis separates the closed point sets spanned by `p` and `q` (the axes given).
inline bool no_axis_separates(const std::vector<ivec>& p, const std::vector<ivec>& q, const std::vector<ivec>& axes) {
    for (const ivec& ax : axes) {
        if (izero(ax)) continue;
        long long plo = idot(ax, p[0]), phi = plo, qlo = idot(ax, q[0]), qhi = qlo;
        for (const ivec& x : p) plo = std::min(plo, idot(ax, x)), phi = std::max(phi, idot(ax, x));
        for (const ivec& x : q) qlo = std::min(qlo, idot(ax, x)), qhi = std::max(qhi, idot(ax, x));
        if (phi < qlo || qhi < plo) return false;
    }
    return true;
}

/// Closed proper triangles abc and def meet (both of nonzero area).
inline bool sat_triangles_meet(const std::array<ivec, 3>& s, const std::array<ivec, 3>& t) {
    std::array<ivec, 3> e, f;
    for (int i = 0; i < 3; ++i) {
        e[i] = isub(s[(i + 1) % 3], s[i]);
        f[i] = isub(t[(i + 1) % 3], t[i]);
    }
    const ivec ns = icross(e[0], e[1]), nt = icross(f[0], f[1]);
    std::vector<ivec> axes{ns, nt};
    for (int i = 0; i < 3; ++i) {
        axes.push_back(icross(ns, e[i]));
        axes.push_back(icross(nt, f[i]));
        for (int j = 0; j < 3; ++j) axes.push_back(icross(e[i], f[j]));
    }
    return no_axis_separates({s.begin(), s.end()}, {t.begin(), t.end()}, axes);
}

/// Closed segment pq (p != q) meets closed proper triangle abc.
inline bool sat_segment_meets_triangle(const ivec& p, const ivec& q, const std::array<ivec, 3>& t) {
    const ivec d = isub(q, p);
    std::array<ivec, 3> f;
    for (int i = 0; i < 3; ++i) f[i] = isub(t[(i + 1) % 3], t[i]);
    const ivec n = icross(f[0], f[1]);
    std::vector<ivec> axes{n, icross(n, d)};
    for (int i = 0; i < 3; ++i) {
        axes.push_back(icross(d, f[i]));
        axes.push_back(icross(n, f[i]));
    }
    return no_axis_separates({p, q}, {t.begin(), t.end()}, axes);
}

}  // namespace hmira_test
