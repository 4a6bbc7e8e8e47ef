// tests/support/exact_box_triangle.hpp
// An oracle for the surface voxelization: whether a closed axis-aligned box meets a closed
// triangle, by the 13 separating axes in exact arithmetic (the expansions of
// hmira/predicates). The voxelizer itself never calls this: it tests in floating point.
#pragma once

#include <algorithm>
#include <cstddef>

#include <hmira/core/vec3.hpp>
#include <hmira/predicates/detail/expansion.hpp>

namespace hmira_test {

namespace exact_detail {

using namespace hmira::predicates::detail;

template <std::size_t N>
expansion<N> negated(expansion<N> x) {
    for (std::size_t i = 0; i < x.n; ++i) x.c[i] = -x.c[i];
    return x;
}

template <std::size_t N>
expansion<N> magnitude(const expansion<N>& x) {
    return sign(x) < 0 ? negated(x) : x;
}

// Whether the projections p[0..2] all lie beyond +r or all beyond -r: the axis separates.
template <std::size_t NP, std::size_t NR>
bool separates(const expansion<NP> (&p)[3], const expansion<NR>& r) {
    bool above = true, below = true;
    for (const auto& q : p) {
        expansion<NP + NR> d;
        expansion_diff(q, r, d);
        above &= sign(d) > 0;
        expansion_sum(q, r, d);
        below &= sign(d) < 0;
    }
    return above || below;
}

}  // namespace exact_detail

/// Whether the closed box of half-size `h` around `centre` meets the closed triangle (a, b,
/// c). Exact (while no product underflows): touching at a single point counts.
inline bool exact_box_meets_triangle(const hmira::vec3<double>& centre, double h, const hmira::vec3<double>& a,
                                     const hmira::vec3<double>& b, const hmira::vec3<double>& c) {
    using namespace exact_detail;
    const hmira::vec3<double> t[3] = {a, b, c};
    const expansion<1> half{{h}, 1};
    // The box normals: the triangle's extent against the box's, exactly.
    for (std::size_t q = 0; q < 3; ++q) {
        const double lo = std::min({a[q], b[q], c[q]}), hi = std::max({a[q], b[q], c[q]});
        expansion<3> d;
        expansion_diff(exact_diff(lo, centre[q]), half, d);  // lo - centre - h > 0: beyond the box
        if (sign(d) > 0) return false;
        expansion_sum(exact_diff(hi, centre[q]), half, d);  // hi - centre + h < 0
        if (sign(d) < 0) return false;
    }
    expansion<2> p[3][3], e[3][3];  // corners relative to the centre; edges e = t[i + 1] - t[i]
    for (int i = 0; i < 3; ++i)
        for (std::size_t q = 0; q < 3; ++q) {
            p[i][q] = exact_diff(t[i][q], centre[q]);
            e[i][q] = exact_diff(t[(i + 1) % 3][q], t[i][q]);
        }
    // Box axis k x edge: for k = x the axis is (0, -e.z, e.y), a projection e.y p.z - e.z p.y
    // and the box's radius h (|e.y| + |e.z|); y and z likewise.
    for (int i = 0; i < 3; ++i)
        for (std::size_t k = 0; k < 3; ++k) {
            const std::size_t s = (k + 1) % 3, w = (k + 2) % 3;
            expansion<16> proj[3];
            for (int j = 0; j < 3; ++j) {
                expansion<8> l, r;
                expansion_product(e[i][s], p[j][w], l);
                expansion_product(e[i][w], p[j][s], r);
                expansion_diff(l, r, proj[j]);
            }
            expansion<4> size;
            expansion_sum(magnitude(e[i][s]), magnitude(e[i][w]), size);
            expansion<8> radius;
            expansion_product(size, half, radius);
            if (separates(proj, radius)) return false;
        }
    // The triangle's normal n = e0 x e1: every corner projects to n . p[0].
    expansion<16> n[3];
    for (std::size_t q = 0; q < 3; ++q) {
        const std::size_t s = (q + 1) % 3, w = (q + 2) % 3;
        expansion<8> l, r;
        expansion_product(e[0][s], e[1][w], l);
        expansion_product(e[0][w], e[1][s], r);
        expansion_diff(l, r, n[q]);
    }
    expansion<64> terms[3];
    for (std::size_t q = 0; q < 3; ++q) expansion_product(n[q], p[0][q], terms[q]);
    expansion<128> partial;
    expansion_sum(terms[0], terms[1], partial);
    expansion<192> dist;
    expansion_sum(partial, terms[2], dist);
    expansion<32> size2;
    expansion_sum(magnitude(n[0]), magnitude(n[1]), size2);
    expansion<48> size3;
    expansion_sum(size2, magnitude(n[2]), size3);
    expansion<96> radius;
    expansion_product(size3, half, radius);
    const expansion<192> same[3] = {dist, dist, dist};
    return !separates(same, radius);
}

}  // namespace hmira_test
