// hmira/algorithms/editing/extrude.hpp
// Face extrusion (thesis 2.2): pull a face, or a connected set of faces, out along a direction
// and join it to where it was by side walls of quads. One face is extruded with the Euler
// operators alone (makeEV at each corner, makeEF around); a region of several faces also needs
// its boundary vertices split, which detail::editing::extrude_region does on the halfedge layer.
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <ranges>
#include <string>
#include <utility>
#include <vector>

#include "detail/editing_common.hpp"

namespace hmira {

/// A mesh extrude() can edit: an editable_mesh whose positions can be set (region mode moves
/// the region's inner vertices).
template <class M, class T = default_traits<M>>
concept extrudable_mesh = editable_mesh<M, T> && position_mutable_mesh<M, T>;

/// region: a connected selection moves as one piece, with walls only along its outline.
/// individual: every face is extruded on its own, along its own normal.
enum class extrude_mode { region, individual };

/// How extrude() moves the faces.
struct extrude_options {
    /// How far the faces move; negative pushes them into the solid (a pocket whose walls face
    /// into it). Must be finite and non-zero.
    double distance = 1.0;
    /// Direction of the move; unset (the default): the face's unit normal, or in region mode the
    /// region's area-weighted mean normal. A given direction is normalised.
    std::optional<vec3<double>> direction = std::nullopt;
    extrude_mode mode = extrude_mode::region;  ///< see extrude_mode
};

/// What an extrusion created.
template <class M, class T = default_traits<M>>
struct extrude_result {
    /// The extruded faces at their new place: the same face handles as the input (the faces
    /// move; the walls are new).
    std::vector<typename T::face_handle> top_faces;
    std::vector<typename T::face_handle> side_faces;  ///< the wall quads, one per outline edge
    std::vector<typename T::vertex_handle> vertices;  ///< the new vertices (the moved outline)
};

namespace detail::editing {

template <class M, class T>
result<void> check_extrude_face(const M& m, typename T::face_handle f) {
    namespace de = detail::euler;
    if (!de::usable<M, T>(m, f))
        return fail(errc::invalid_handle, "extrude: " + de::name<M, T>("face", m, f) + " does not exist", de::index_of<M, T>(m, f));
    if (de::has_rings<M, T>(m, f))
        return fail(errc::unsupported, "extrude: " + de::name<M, T>("face", m, f) + " has inner rings, which extrusion does not handle",
                    de::index_of<M, T>(m, f));
    return {};
}

/// Extrudes one face by the displacement `d` from Euler operators: makeEV grows a new vertex
/// out of every corner into the face, then makeEF joins consecutive tips, each cutting a side
/// quad off the face, until the face is the top. V + n, E + 2n, F + n. O(n).
template <class M, class T>
void extrude_one(M& m, typename T::face_handle f, const vec3<double>& d, extrude_result<M, T>& out) {
    using H = typename T::halfedge_handle;
    std::vector<H> into;
    const auto start = T::face_halfedge(m, f);
    auto h = start;
    do {
        into.push_back(h);
        h = T::next(m, h);
    } while (h != start);
    const std::size_t n = into.size();
    std::vector<H> up(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto r = make_edge_vertex<M, T>(m, into[i], to_point<M, T>(pos<M, T>(m, T::target(m, into[i])) + d));
        up[i] = r->halfedge;
        out.vertices.push_back(r->vertex);
    }
    H h0 = up[0];
    for (std::size_t i = 0; i < n; ++i) {
        const auto r = make_edge_face<M, T>(m, h0, up[(i + 1) % n]);
        out.side_faces.push_back(r->face);
        h0 = r->halfedge;
    }
    out.top_faces.push_back(f);
}

/// Extrudes a connected region of several faces (already checked, `in_region` holds their
/// indices) by `d`, on the raw halfedge layer: every outline vertex v gets a copy v' that takes
/// over the region's side of v; each outline edge moves up to the copies, a new edge takes its
/// place on the outside, and a new vertical edge per outline vertex closes the wall quads.
/// Inner vertices of the region move by d. O(region size + outline fans).
template <class M, class T>
void extrude_region(M& m, const std::vector<typename T::face_handle>& faces, const index_set& in_region,
                    const std::vector<typename T::halfedge_handle>& outline, const vec3<double>& d, extrude_result<M, T>& out) {
    using H = typename T::halfedge_handle;
    using V = typename T::vertex_handle;
    using F = typename T::face_handle;
    auto in_r = [&](F f) { return f != T::null_face() && in_region.contains(T::face_index(m, f)); };
    const std::size_t k = outline.size();
    // Outline halfedges g (region side, u -> v), indexed by the halfedge index of their opposite.
    std::vector<std::pair<std::size_t, std::size_t>> og_index;  // (halfedge index of opposite(g), i)
    for (std::size_t i = 0; i < k; ++i) og_index.push_back({T::halfedge_index(m, T::opposite(m, outline[i])), i});
    std::sort(og_index.begin(), og_index.end());
    auto outline_of_og = [&](H x) -> long long {
        const auto key = T::halfedge_index(m, x);
        auto it = std::lower_bound(og_index.begin(), og_index.end(), std::pair<std::size_t, std::size_t>{key, 0});
        return it != og_index.end() && it->first == key ? static_cast<long long>(it->second) : -1;
    };
    // Per outline vertex v = target(g_i): the region halfedges into v that move to the copy.
    struct corner {
        V v;
        std::vector<H> moved_in;
        H v_out;               // v's outgoing halfedge after the operation
        bool v_out_moves = false;  // the stored one goes with the region or the wall: replace it
        H copy_out;            // the copy's outgoing halfedge
    };
    std::vector<corner> corners(k);
    std::vector<H> on(k), op(k);
    std::vector<F> fout(k);
    std::vector<vec3<double>> copy_pos(k);
    for (std::size_t i = 0; i < k; ++i) {
        const auto g = outline[i];
        const auto og = T::opposite(m, g);
        on[i] = T::next(m, og);
        op[i] = T::prev(m, og);
        fout[i] = T::face(m, og);
        auto& c = corners[i];
        c.v = T::target(m, g);
        c.moved_in.push_back(g);
        auto o = T::next(m, g);
        c.copy_out = o;
        for (;;) {
            c.moved_in.push_back(T::opposite(m, o));
            if (!in_r(T::face(m, T::opposite(m, o)))) break;
            o = T::next(m, T::opposite(m, o));
        }
        copy_pos[i] = pos<M, T>(m, c.v) + d;
    }
    // v's stored outgoing halfedge, read before any change (models may derive it from links).
    std::vector<H> b_out(k), b_in(k), up(k);
    std::vector<V> copy(k);
    for (auto& c : corners) {
        c.v_out = T::vertex_halfedge(m, c.v);
        c.v_out_moves = std::find(c.moved_in.begin(), c.moved_in.end(), T::opposite(m, c.v_out)) != c.moved_in.end();
    }
    // New elements.
    for (std::size_t i = 0; i < k; ++i) {
        const auto g = outline[i];
        const auto u = T::target(m, T::opposite(m, g)), v = T::target(m, g);
        b_out[i] = T::new_edge(m, v, u);
        b_in[i] = T::opposite(m, b_out[i]);
        copy[i] = T::add_vertex(m, to_point<M, T>(copy_pos[i]));
        out.vertices.push_back(copy[i]);
    }
    for (std::size_t i = 0; i < k; ++i) up[i] = T::new_edge(m, corners[i].v, copy[i]);
    // Index of the outline halfedge ending at the source of g_i (its wall's left neighbour).
    std::vector<std::pair<std::size_t, std::size_t>> by_target;
    for (std::size_t i = 0; i < k; ++i) by_target.push_back({T::vertex_index(m, corners[i].v), i});
    std::sort(by_target.begin(), by_target.end());
    auto ending_at = [&](V v) {
        auto it = std::lower_bound(by_target.begin(), by_target.end(), std::pair<std::size_t, std::size_t>{T::vertex_index(m, v), 0});
        return it->second;
    };
    std::vector<std::size_t> left(k);
    for (std::size_t i = 0; i < k; ++i) left[i] = ending_at(T::target(m, T::opposite(m, outline[i])));
    // Move the region's side of every outline vertex to its copy.
    for (std::size_t i = 0; i < k; ++i)
        for (auto x : corners[i].moved_in) T::set_target(m, x, copy[i]);
    // Walls: b_in (u -> v), up_v (v -> v'), og (v' -> u'), down_u (u' -> u).
    for (std::size_t i = 0; i < k; ++i) {
        const auto og = T::opposite(m, outline[i]);
        const auto down_u = T::opposite(m, up[left[i]]);
        const auto w = T::new_face(m);
        out.side_faces.push_back(w);
        const H loop[4] = {b_in[i], up[i], og, down_u};
        for (int j = 0; j < 4; ++j) {
            T::set_next(m, loop[j], loop[(j + 1) % 4]);
            T::set_face(m, loop[j], w);
        }
        T::set_face_halfedge(m, w, b_in[i]);
    }
    // Outside: b_out (v -> u) takes og's place in its face.
    for (std::size_t i = 0; i < k; ++i) {
        const long long nj = outline_of_og(on[i]);
        T::set_next(m, b_out[i], nj >= 0 ? b_out[static_cast<std::size_t>(nj)] : on[i]);
        if (outline_of_og(op[i]) < 0) T::set_next(m, op[i], b_out[i]);
        T::set_face(m, b_out[i], fout[i]);
        if (fout[i] != T::null_face() && T::face_halfedge(m, fout[i]) == T::opposite(m, outline[i]))
            T::set_face_halfedge(m, fout[i], b_out[i]);
    }
    // Stored halfedges: the copy is interior. v keeps what it stored unless that went up with
    // the region; then b_out (v -> u, in the face of the old outside halfedge v -> u, so a
    // boundary halfedge if that one was) replaces it.
    for (std::size_t i = 0; i < k; ++i) {
        auto& c = corners[i];
        if (c.v_out_moves) c.v_out = b_out[i];
        T::set_vertex_halfedge(m, copy[i], c.copy_out);
        T::set_vertex_halfedge(m, c.v, c.v_out);
    }
    // Inner vertices move with the region (the copies are in place already).
    index_set done;
    for (auto cv : copy) done.insert(T::vertex_index(m, cv));
    for (auto f : faces)
        for (auto v : T::face_vertices(m, f)) {
            const auto vi = T::vertex_index(m, v);
            if (done.contains(vi)) continue;
            done.insert(vi);
            T::set_position(m, v, to_point<M, T>(pos<M, T>(m, v) + d));
        }
    out.top_faces = faces;
}

}  // namespace detail::editing

/// Extrudes the faces in `faces` (a range of face handles; duplicates count once) by
/// `options.distance` along `options.direction`, joining them to where they were by one quad
/// per outline edge (never triangulated). Region mode (default) needs a connected selection
/// (faces sharing edges); it moves the whole region, so inner vertices move and only the
/// outline gets walls: V + b, E + 2b, F + b for an outline of b edges. Individual mode extrudes
/// each face of degree n on its own: V + n, E + 2n, F + n each. The extruded faces keep their
/// handles and winding; walls are wound consistently with them, so a closed mesh stays closed
/// and outward oriented (a positive distance along the outward normal adds volume).
///
/// Complexity: O(n) for a face of degree n; region mode O(R log R) for R corners of the
/// region's faces (local: nothing outside the region and its outline fans is read).
/// Errors (mesh unchanged): errc::invalid_argument for a zero, NaN or infinite distance, a
/// zero direction or a zero normal, an empty selection; errc::invalid_handle for a missing
/// face; errc::unsupported for a face with inner rings; errc::topology for a region that is
/// not connected, has no outline (a whole closed component), or touches one of its outline
/// vertices in two separate fans (pinched).
template <class M, class T = default_traits<M>, class R>
    requires extrudable_mesh<M, T> && range_of_handles<R, typename T::face_handle>
result<extrude_result<M, T>> extrude(M& mesh, const R& faces, const extrude_options& options = {}) {
    namespace de = detail::editing;
    using F = typename T::face_handle;
    using H = typename T::halfedge_handle;
    if (!de::finite(options.distance) || options.distance == 0)
        return fail(errc::invalid_argument, "extrude: distance must be finite and non-zero");
    vec3<double> dir{};
    if (options.direction) {
        dir = *options.direction;
        if (!(norm(dir) > 0) || !de::finite(norm(dir))) return fail(errc::invalid_argument, "extrude: direction must be a finite non-zero vector");
        dir = normalized(dir);
    }
    std::vector<F> fs;
    de::index_set in_region;
    for (auto f0 : faces) {
        const F f = f0;
        if (auto ok = de::check_extrude_face<M, T>(mesh, f); !ok) return ok.error();
        const auto i = T::face_index(mesh, f);
        if (in_region.contains(i)) continue;
        in_region.insert(i);
        fs.push_back(f);
    }
    if (fs.empty()) return fail(errc::invalid_argument, "extrude: no face selected");
    extrude_result<M, T> out;
    if (options.mode == extrude_mode::individual || fs.size() == 1) {
        std::vector<vec3<double>> moves;
        for (auto f : fs) {
            const auto n = de::face_area_vector<M, T>(mesh, f);
            if (!options.direction && !(norm(n) > 0))
                return fail(errc::invalid_argument, "extrude: " + detail::euler::name<M, T>("face", mesh, f) + " has zero area, so no normal",
                            static_cast<long long>(T::face_index(mesh, f)));
            moves.push_back((options.direction ? dir : normalized(n)) * options.distance);
        }
        for (std::size_t i = 0; i < fs.size(); ++i) de::extrude_one<M, T>(mesh, fs[i], moves[i], out);
        return out;
    }
    // Region: connected, with an outline, not pinched.
    auto in_r = [&](F f) { return f != T::null_face() && in_region.contains(T::face_index(mesh, f)); };
    std::vector<H> outline;
    vec3<double> area{};
    {
        de::index_set reached;
        std::vector<F> stack{fs[0]};
        reached.insert(T::face_index(mesh, fs[0]));
        std::size_t count = 0;
        while (!stack.empty()) {
            const F f = stack.back();
            stack.pop_back();
            ++count;
            const auto start = T::face_halfedge(mesh, f);
            auto h = start;
            do {
                const F g = T::face(mesh, T::opposite(mesh, h));
                if (in_r(g) && !reached.contains(T::face_index(mesh, g))) {
                    reached.insert(T::face_index(mesh, g));
                    stack.push_back(g);
                }
                h = T::next(mesh, h);
            } while (h != start);
        }
        if (count != fs.size())
            return fail(errc::topology, "extrude: the faces are not connected through edges; use extrude_mode::individual or extrude each part");
    }
    for (auto f : fs) {
        area += de::face_area_vector<M, T>(mesh, f);
        const auto start = T::face_halfedge(mesh, f);
        auto h = start;
        do {
            if (!in_r(T::face(mesh, T::opposite(mesh, h)))) outline.push_back(h);
            h = T::next(mesh, h);
        } while (h != start);
    }
    if (outline.empty()) return fail(errc::topology, "extrude: the region is a whole closed component; it has no outline to build walls on");
    {
        std::vector<std::size_t> ends;
        for (auto g : outline) ends.push_back(T::vertex_index(mesh, T::target(mesh, g)));
        std::sort(ends.begin(), ends.end());
        const auto dup = std::adjacent_find(ends.begin(), ends.end());
        if (dup != ends.end())
            return fail(errc::topology, "extrude: the region touches vertex " + std::to_string(*dup) + " in two separate fans (pinched); extrude the parts separately",
                        static_cast<long long>(*dup));
    }
    if (!options.direction) {
        if (!(norm(area) > 0)) return fail(errc::invalid_argument, "extrude: the region's mean normal is zero; give a direction");
        dir = normalized(area);
    }
    de::extrude_region<M, T>(mesh, fs, in_region, outline, dir * options.distance, out);
    return out;
}

/// Extrudes one face of degree n (see the range overload): V + n, E + 2n, F + n, built from
/// n makeEV and n makeEF. Complexity O(n). Errors as for the range overload.
template <class M, class T = default_traits<M>>
    requires extrudable_mesh<M, T>
result<extrude_result<M, T>> extrude(M& mesh, typename T::face_handle face, const extrude_options& options = {}) {
    const typename T::face_handle one[1] = {face};
    return extrude<M, T>(mesh, one, options);
}

}  // namespace hmira
