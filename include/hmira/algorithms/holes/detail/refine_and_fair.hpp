// hmira/algorithms/holes/detail/refine_and_fair.hpp
// What fill_hole does to a fresh patch on request: Liepa's refinement to the density around
// the hole (centroid splits and Delaunay-like flips, by split_face and flip_edge) and fairing.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "../../triangle/flip_edge.hpp"
#include "../../triangle/split_face.hpp"
#include "conjugate_gradient.hpp"

namespace hmira::detail::holes {

/// The patch while it is refined: its faces, the edges it may flip (both sides in the patch,
/// off the loop) as vertex-index pairs, each vertex's scale (the edge length wanted around it)
/// and the vertices it added.
template <class M, class T>
struct patch {
    std::vector<typename T::face_handle> faces;
    std::unordered_set<std::uint64_t> inner_edges;
    std::unordered_map<std::size_t, double> scale;
    std::vector<typename T::vertex_handle> vertices;
};

template <class M, class T>
std::uint64_t edge_key(const M& m, typename T::vertex_handle a, typename T::vertex_handle b) {
    return pair_key(T::vertex_index(m, a), T::vertex_index(m, b));
}

inline double angle_at(const vec3<double>& apex, const vec3<double>& a, const vec3<double>& b) {
    const auto u = a - apex, w = b - apex;
    const auto c = cross(u, w);
    return std::atan2(std::sqrt(dot(c, c)), dot(u, w));
}

/// Flips the patch edge a-b when the angles facing it sum to more than pi (the 3D version of
/// the Delaunay criterion; the flipped edge then has a sum below pi, so the pair does not flip
/// back), unless the flip would fold the quadrilateral. Returns whether it flipped; then
/// `opposite`, if given, receives the two vertices c and d the new edge joins. O(valence).
template <class M, class T>
bool relax_edge(M& mesh, patch<M, T>& pt, typename T::vertex_handle a, typename T::vertex_handle b,
                std::array<typename T::vertex_handle, 2>* opposite = nullptr) {
    namespace dt = triangle_ops;
    const auto key = edge_key<M, T>(mesh, a, b);
    if (!pt.inner_edges.count(key)) return false;
    const auto h = dt::find_halfedge<M, T>(mesh, a, b);
    if (h == T::null_halfedge() || !is_flip_ok<M, T>(mesh, h)) return false;
    const auto c = T::target(mesh, T::next(mesh, h));
    const auto d = T::target(mesh, T::next(mesh, T::opposite(mesh, h)));
    const auto pa = dt::position_of<M, T>(mesh, a), pb = dt::position_of<M, T>(mesh, b);
    const auto pc = dt::position_of<M, T>(mesh, c), pd = dt::position_of<M, T>(mesh, d);
    if (angle_at(pc, pa, pb) + angle_at(pd, pa, pb) <= std::numbers::pi * (1 + 1e-12)) return false;
    // (a, b, c) and (b, a, d) become (c, a, d) and (d, b, c): both must face the old side.
    const auto before = cross(pb - pa, pc - pa) + cross(pa - pb, pd - pb);
    const auto n1 = cross(pa - pc, pd - pc), n2 = cross(pb - pd, pc - pd);
    if (!(dot(n1, before) > 0) || !(dot(n2, before) > 0) || !(dot(n1, n2) > 0)) return false;
    auto r = flip_edge<M, T>(mesh, h);
    if (!r) return false;
    pt.inner_edges.erase(key);
    pt.inner_edges.insert(edge_key<M, T>(mesh, c, d));
    if (opposite) *opposite = {c, d};
    return true;
}

/// Relaxes every patch edge until none flips, at most `budget` flips, by Lawson's work list:
/// every patch edge once, then the four sides of each quadrilateral a flip changed (the only
/// edges whose facing angles a flip changes). Reports to `gate` every 4096 flips; returns false
/// when it says stop. O(flips * valence + E).
template <class M, class T>
bool relax_all(M& mesh, patch<M, T>& pt, std::size_t budget, progress_gate& gate) {
    using V = typename T::vertex_handle;
    std::vector<std::pair<V, V>> work;
    for (const auto f : pt.faces) {
        const auto h0 = T::face_halfedge(mesh, f);
        auto x = h0;
        do {
            const auto a = T::target(mesh, T::opposite(mesh, x)), b = T::target(mesh, x);
            if (T::vertex_index(mesh, a) < T::vertex_index(mesh, b) && pt.inner_edges.count(edge_key<M, T>(mesh, a, b)))
                work.emplace_back(a, b);
            x = T::next(mesh, x);
        } while (x != h0);
    }
    std::size_t flips = 0;
    while (!work.empty() && budget > 0) {
        const auto [a, b] = work.back();
        work.pop_back();
        std::array<V, 2> cd{a, b};  // overwritten by a flip
        if (!relax_edge<M, T>(mesh, pt, a, b, &cd)) continue;
        --budget;
        if (++flips % 4096 == 0 && !gate.advance(0)) return false;
        work.emplace_back(a, cd[0]);
        work.emplace_back(cd[0], b);
        work.emplace_back(b, cd[1]);
        work.emplace_back(cd[1], a);
    }
    return true;
}

/// Liepa's refinement: a triangle whose centroid c lies farther than scale / density from
/// each corner, for the scale of c (the corners' mean) and of that corner, is split at c, which
/// takes the mean scale; the split triangle's old edges are relaxed; once a round splits
/// nothing, the patch is what is wanted. Between rounds all patch edges are relaxed. At most
/// `max_new_vertices` vertices are added. O(V_new * valence) per round, typically few rounds.
/// Reports to `gate` once per round, every 4096 splits and every 4096 flips; returns false
/// (the patch half refined, still a valid surface) when it says stop.
template <class M, class T>
bool refine_patch(M& mesh, patch<M, T>& pt, double density, std::size_t max_new_vertices, progress_gate& gate) {
    namespace dt = triangle_ops;
    for (int round = 0; round < 64; ++round) {
        if (!gate.advance(0)) return false;
        bool split = false;
        const std::size_t count = pt.faces.size();
        for (std::size_t fi = 0; fi < count && pt.vertices.size() < max_new_vertices; ++fi) {
            if (fi % 4096 == 4095 && !gate.advance(0)) return false;
            const auto f = pt.faces[fi];
            const auto h0 = T::face_halfedge(mesh, f);
            const auto h1 = T::next(mesh, h0), h2 = T::next(mesh, h1);
            const std::array<typename T::vertex_handle, 3> v{T::target(mesh, h2), T::target(mesh, h0),
                                                             T::target(mesh, h1)};
            std::array<vec3<double>, 3> p;
            std::array<double, 3> s;
            for (int i = 0; i < 3; ++i) {
                p[i] = dt::position_of<M, T>(mesh, v[i]);
                s[i] = pt.scale.at(T::vertex_index(mesh, v[i]));
            }
            const auto centre = (p[0] + p[1] + p[2]) / 3.0;
            const double s_centre = (s[0] + s[1] + s[2]) / 3;
            bool wanted = true;
            for (int i = 0; i < 3 && wanted; ++i) {
                const auto d = centre - p[i];
                const double far = density * std::sqrt(dot(d, d));
                wanted = far > s_centre && far > s[i];
            }
            if (!wanted) continue;
            auto r = split_face<M, T>(mesh, f, {.position = centre});
            if (!r) continue;
            split = true;
            pt.vertices.push_back(r->vertex);
            pt.scale[T::vertex_index(mesh, r->vertex)] = s_centre;
            // The vertex's other two faces join the patch; its three edges are patch edges.
            auto x = r->halfedge;
            do {
                if (T::face(mesh, x) != f) pt.faces.push_back(T::face(mesh, x));
                pt.inner_edges.insert(edge_key<M, T>(mesh, r->vertex, T::target(mesh, x)));
                x = T::next(mesh, T::opposite(mesh, x));
            } while (x != r->halfedge);
            for (int i = 0; i < 3; ++i) relax_edge<M, T>(mesh, pt, v[i], v[(i + 1) % 3]);
        }
        if (!split) break;
        if (!relax_all<M, T>(mesh, pt, 10 * pt.inner_edges.size() + 100, gate)) return false;
    }
    return true;
}

/// Progress blocks each coordinate solve of a fairing counts, spread over its iteration budget.
inline constexpr std::size_t fairing_blocks = 1024;

/// The fairing of fill_hole: which energy the added vertices minimise.
enum class fairing_energy { membrane, thin_plate };

/// Moves the patch's added vertices so that the uniform (umbrella) Laplacian vanishes at each
/// (membrane), or the Laplacian of the Laplacian (thin plate), every other vertex fixed: the
/// loop, and for the thin plate also the ring outside it. Writes positions only when all three
/// coordinate solves converge (not when `gate` cancels one). Returns the solve with the most iterations. O(iterations *
/// nnz).
template <class M, class T>
solve_outcome fair_patch(M& mesh, const patch<M, T>& pt, fairing_energy energy, double tolerance,
                         std::size_t max_iterations, progress_gate& gate) {
    namespace dt = triangle_ops;
    using V = typename T::vertex_handle;
    solve_outcome worst{.converged = true, .iterations = 0, .relative_residual = 0};
    const std::size_t u = pt.vertices.size();
    if (u == 0) return worst;
    // Local ids: the unknowns first, then fixed vertices as they are met.
    std::unordered_map<std::size_t, std::size_t> local;
    std::vector<V> vertex;
    auto id = [&](V v) {
        auto [it, fresh] = local.try_emplace(T::vertex_index(mesh, v), vertex.size());
        if (fresh) vertex.push_back(v);
        return it->second;
    };
    for (const auto v : pt.vertices) id(v);
    std::unordered_map<std::size_t, std::vector<std::size_t>> ring;  // local id -> neighbours' local ids
    auto ring_of = [&](std::size_t i) -> const std::vector<std::size_t>& {
        if (const auto it = ring.find(i); it != ring.end()) return it->second;
        std::vector<std::size_t> nb;
        const auto s = T::vertex_halfedge(mesh, vertex[i]);
        auto x = s;
        do {
            nb.push_back(id(T::target(mesh, x)));
            x = T::next(mesh, T::opposite(mesh, x));
        } while (x != s);
        return ring.emplace(i, std::move(nb)).first->second;  // references into the map stay valid
    };
    // Rows of S = D - A (graph Laplacian) restricted to unknown rows, with fixed columns moved
    // to the right-hand side; the thin plate's S D^-1 S keeps symmetry and definiteness.
    sparse_matrix a;
    std::vector<std::array<double, 3>> rhs(u, {0, 0, 0});
    std::vector<std::pair<std::size_t, double>> entries;
    auto add = [&](std::size_t row, std::size_t j, double c) {
        if (j < u)
            entries.emplace_back(j, c);
        else {
            const auto q = dt::position_of<M, T>(mesh, vertex[j]);
            for (std::size_t k = 0; k < 3; ++k) rhs[row][k] -= c * q[k];
        }
    };
    for (std::size_t i = 0; i < u; ++i) {
        entries.clear();
        const auto nb = ring_of(i);
        if (energy == fairing_energy::membrane) {
            add(i, i, double(nb.size()));
            for (auto j : nb) add(i, j, -1.0);
        } else {
            // (S D^-1 S)_ij = sum over k in {i} + N(i) of S_ik S_kj / deg(k).
            auto through = [&](std::size_t k, double s_ik) {
                const auto nk = ring_of(k);
                add(i, k, s_ik);  // S_kk / deg(k) = 1
                for (auto j : nk) add(i, j, -s_ik / double(nk.size()));
            };
            through(i, double(nb.size()));
            for (auto k : nb) through(k, -1.0);
        }
        a.add_row(entries);
    }
    std::array<std::vector<double>, 3> x;
    for (std::size_t k = 0; k < 3; ++k) {
        std::vector<double> b(u);
        x[k].resize(u);
        for (std::size_t i = 0; i < u; ++i) {
            b[i] = rhs[i][k];
            x[k][i] = dt::position_of<M, T>(mesh, vertex[i])[k];
        }
        const auto r = conjugate_gradient(a, b, x[k], tolerance, max_iterations, &gate, fairing_blocks);
        if (!r.converged || r.cancelled) return r;
        worst.iterations = std::max(worst.iterations, r.iterations);
        worst.relative_residual = std::max(worst.relative_residual, r.relative_residual);
    }
    for (std::size_t i = 0; i < u; ++i) dt::set_position<M, T>(mesh, vertex[i], {x[0][i], x[1][i], x[2][i]});
    return worst;
}

}  // namespace hmira::detail::holes
