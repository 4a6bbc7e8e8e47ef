// hmira/algorithms/subdivision/catmull_clark.hpp
// Catmull-Clark subdivision of any polygon mesh, boundaries included, built from the local
// operators' links: every edge split at its edge point, then each face cut into quads around a
// new face-centre vertex (make_edge_vertex's, then make_edge_face's links), and the old
// vertices moved.
#pragma once

#include <algorithm>
#include <array>
#include <cassert>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "../../core/progress.hpp"
#include "../triangle/split_edge.hpp"
#include "detail/new_elements.hpp"
#include "detail/range.hpp"
#include "detail/reserve.hpp"

namespace hmira {

/// Options of catmull_clark_subdivide.
struct catmull_clark_options {
    /// Levels of subdivision (the first makes one quad per face corner, each further one
    /// multiplies the faces by 4). At most 10.
    std::size_t levels = 1;
    /// Called between blocks of work with the fraction done; returning false cancels (error
    /// errc::cancelled, "catmull_clark_subdivide: cancelled", mesh unchanged). With a
    /// callback the mesh is copied once before the first change, so that a cancellation can
    /// restore it; without one nothing can interrupt the levels and no copy is made.
    progress_function progress = {};
};

/// What catmull_clark_subdivide did.
struct catmull_clark_result {
    std::size_t vertices = 0;  ///< vertices after the last level
    std::size_t edges = 0;     ///< edges after the last level
    std::size_t faces = 0;     ///< faces after the last level
};

/// A mesh catmull_clark_subdivide can run on: the Euler operators (so polygons of any degree,
/// which excludes triangles-only models), movable positions, dense vertex, edge and face
/// indices for its per-level arrays, and copies (to restore the mesh on cancellation).
/// halfedge_mesh, winged_edge_mesh, OpenMesh PolyMesh and CGAL Surface_mesh qualify.
template <class M, class T = default_traits<M>>
concept catmull_clark_subdividable_mesh = euler_mutable_mesh<M, T> && position_mutable_mesh<M, T> && vertex_index_mesh<M, T> &&
                                          edge_index_mesh<M, T> && face_index_mesh<M, T> && std::copy_constructible<M> &&
                                          std::is_move_assignable_v<M>;

namespace detail::subdivision {

/// Element counts of a mesh, and what one Catmull-Clark level makes of them.
struct cc_counts {
    std::uint64_t vertices = 0, edges = 0, faces = 0, corners = 0;  // corners: sum of face degrees
    cc_counts next() const { return {vertices + edges + faces, 2 * edges + corners, corners, 4 * corners}; }
};

/// The per-level arrays, sized once for the largest level so that no level allocates after
/// the mesh starts changing. Kept lean (29 bytes a vertex; 28 a face, or 4 where the face
/// points go straight into their vertices; the edge points always do): at a million faces,
/// first touching fresh pages costs as much as the arithmetic.
template <class M, class T>
struct cc_workspace {
    std::vector<vec3<double>> vertex_point;  // the sums of neighbours and face points; a boundary vertex's new position
    std::vector<vec3<double>> face_point;
    std::vector<std::uint32_t> valence;
    std::vector<std::uint8_t> boundary_edges;  // saturates at 3: only "none", "two" and "more" matter
    std::vector<typename T::face_handle> faces;
    std::vector<std::uint32_t> centre;  // by face index: its face-point vertex's index (points in place)
    std::vector<typename T::halfedge_handle> corners;
    std::array<std::size_t, 3> room{};  // the vertex, edge and face index bounds the mesh has capacity for

    void reserve(std::size_t vertex_bound, std::size_t face_bound, std::size_t max_degree) {
        vertex_point.reserve(vertex_bound);
        valence.reserve(vertex_bound);
        boundary_edges.reserve(vertex_bound);
        face_point.reserve(face_bound);
        faces.reserve(face_bound);
        centre.reserve(face_bound);
        corners.reserve(max_degree);
    }
};

/// One Catmull-Clark level. Preconditions established by the caller for the whole mesh: no
/// face has inner rings; every edge has a face on at least one side, and two different faces
/// when it has two; `w` and the mesh have room for this level. Returns false when `gate`
/// cancels, which it does only between blocks (the caller then restores its copy).
template <class M, class T>
bool catmull_clark_level(M& mesh, cc_workspace<M, T>& w, progress_gate& gate) {
    namespace dt = detail::triangle_ops;
    using H = typename T::halfedge_handle;
    using F = typename T::face_handle;
    constexpr std::size_t block = 1u << 14;

    // Every new position is computed before the first operator, in flat arrays indexed by
    // element index, from the old positions only; old positions change only at the very end.
    const std::size_t vertex_bound = T::vertex_index_bound(mesh);
    const std::size_t face_bound = T::face_index_bound(mesh);
    const std::size_t old_vertices = T::vertex_count(mesh);
    w.vertex_point.assign(vertex_bound, {});
    w.valence.assign(vertex_bound, 0);
    w.boundary_edges.assign(vertex_bound, 0);
    w.faces.clear();
    auto& sum = w.vertex_point;

    // Points in place: on a model that names a vertex by its index (bulk_growable_mesh), with
    // double positions, every face index live and the faces met in index order, each face's
    // vertex index is known before the first change (faces of lower index go first, and each
    // makes the points of its edges not split yet, then its centre), so the face point is
    // written straight into that vertex rather than into a face_point array that would be
    // faulted in, filled and read back. Elsewhere the array keeps them; the result is the same.
    bool in_place = false;
    if constexpr (bulk_growable_mesh<M, T> && std::same_as<typename T::scalar, double>) {
        in_place = T::face_count(mesh) == face_bound;
        std::size_t k = 0;
        for (auto f : T::faces(mesh)) {
            if (!in_place) break;
            in_place = T::face_index(mesh, f) == k++;
        }
    }
    const auto vertex_of = [&](std::size_t i) {
        if constexpr (bulk_growable_mesh<M, T>) return T::vertex_at(mesh, i);
        else { (void)i; return typename T::vertex_handle{}; }  // not called: in_place is false
    };
    const auto resize_vertices = [&](std::size_t n) {  // in place only
        if constexpr (bulk_growable_mesh<M, T>) T::resize(mesh, n, T::edge_index_bound(mesh), face_bound);
        else (void)n;
    };
    w.face_point.assign(in_place ? 0 : face_bound, {});
    w.centre.assign(in_place ? face_bound : 0, 0);
    const auto face_point_of = [&](F f) -> vec3<double> {
        if (in_place) return dt::position_of<M, T>(mesh, vertex_of(w.centre[T::face_index(mesh, f)]));
        return w.face_point[T::face_index(mesh, f)];
    };
    // In place: the next new vertex's index, and the vertex index bound made so far.
    std::size_t next_vertex = vertex_bound, vertex_end = vertex_bound;

    // Face points (centroids); each vertex sums the face points around it.
    std::size_t done = 0;
    for (auto f : T::faces(mesh)) {
        if (!in_place) w.faces.push_back(f);
        const H start = T::face_halfedge(mesh, f);
        vec3<double> c{};
        std::size_t n = 0;
        H x = start;
        do {
            c += dt::position_of<M, T>(mesh, T::target(mesh, x));
            ++n;
            x = T::next(mesh, x);
        } while (x != start);
        c = c / double(n);
        if (in_place) {
            // The edges f will split: those whose other side is a boundary or a later face.
            const std::size_t fi = T::face_index(mesh, f);
            do {
                const F g = T::face(mesh, T::opposite(mesh, x));
                next_vertex += g == T::null_face() || T::face_index(mesh, g) > fi;
                x = T::next(mesh, x);
            } while (x != start);
            if (next_vertex >= vertex_end) {  // the vertices made in blocks, as new_elements would
                vertex_end = std::max(next_vertex + 1, std::min(vertex_end + (1u << 12), w.room[0]));
                resize_vertices(vertex_end);
            }
            w.centre[fi] = std::uint32_t(next_vertex);
            dt::set_position<M, T>(mesh, vertex_of(next_vertex++), c);
        } else {
            w.face_point[T::face_index(mesh, f)] = c;
        }
        do {
            sum[T::vertex_index(mesh, T::target(mesh, x))] += c;
            x = T::next(mesh, x);
        } while (x != start);
        if (++done % block == 0 && !gate.advance(1)) return false;
    }

    if (in_place && vertex_end != next_vertex) resize_vertices(next_vertex);

    // Each vertex adds its neighbours and counts its edges and boundary edges.
    for (auto e : T::edges(mesh)) {
        const H h = T::edge_halfedge(mesh, e), o = T::opposite(mesh, h);
        const auto va = T::target(mesh, o), vb = T::target(mesh, h);
        const std::size_t a = T::vertex_index(mesh, va), b = T::vertex_index(mesh, vb);
        sum[a] += dt::position_of<M, T>(mesh, vb);
        sum[b] += dt::position_of<M, T>(mesh, va);
        ++w.valence[a];
        ++w.valence[b];
        if (T::face(mesh, h) == T::null_face() || T::face(mesh, o) == T::null_face()) {
            w.boundary_edges[a] = std::uint8_t(std::min(3, w.boundary_edges[a] + 1));
            w.boundary_edges[b] = std::uint8_t(std::min(3, w.boundary_edges[b] + 1));
        }
        if (++done % block == 0 && !gate.advance(1)) return false;
    }

    // Vertex points. Interior, valence n: ((n - 2) S + (sum of neighbours and face points) / n)
    // / n, which is Catmull and Clark's (Q + 2R + (n - 3) S) / n. On the boundary (two boundary
    // edges): 3/4 S + 1/8 of each boundary neighbour, the cubic B-spline rule; the vertex's
    // stored halfedge is a boundary one (the navigation concept promises it), so its two
    // boundary neighbours are its target and the source of its prev. A vertex with more
    // boundary edges (two boundary fans meet there) has no curve to follow and stays where it
    // is, as an isolated vertex does.
    // The boundary rule reads the old neighbours, so it runs here, before the splits; the inner
    // rule reads the vertex's own old position only, so it runs in the last pass, which writes
    // the positions (one pass over the vertices fewer).
    std::size_t seen = 0;  // old vertices met (new ones may exist already: the face points in place)
    for (auto v : T::vertices(mesh)) {
        if (seen == old_vertices) break;
        const std::size_t i = T::vertex_index(mesh, v);
        if (i >= vertex_bound) continue;
        ++seen;
        if (w.boundary_edges[i] == 2) {
            const vec3<double> p = dt::position_of<M, T>(mesh, v);
            const H s = T::vertex_halfedge(mesh, v);
            const auto a = T::target(mesh, s), b = T::target(mesh, T::opposite(mesh, T::prev(mesh, s)));
            sum[i] = p * 0.75 + (dt::position_of<M, T>(mesh, a) + dt::position_of<M, T>(mesh, b)) * 0.125;
        }
        if (++done % block == 0 && !gate.advance(1)) return false;
    }

    // Face by face, so that each is finished while its elements are still in cache: the
    // face's edges not split yet (both ends old) are split at their edge points (split_edge's
    // links, without its checks: the preconditions above make them pass), then the face, now a
    // 2n-gon alternating old vertices and edge points, becomes n quads around its face point:
    // the links of make_edge_vertex (a spike from the first edge point to the face point) and
    // of make_edge_face from the face point to each further edge point, each closing one quad,
    // written at once without their checks (the 2n-gon is known) and without re-pointing the
    // shrinking rest of the face after each quad. An edge point is the average of the edge's
    // two ends and the two face points beside it, or the midpoint on a boundary: the ends are
    // old vertices not moved yet, and an edge not split yet has no finished face beside it, so
    // the face across it is still the old one (splits keep faces). New elements come from
    // `make` (in bulk where the model allows) in the order those operators would make them.
    new_elements<M, T> make(mesh, w.room);
    const auto is_old = [&](typename T::vertex_handle v) { return std::size_t(T::vertex_index(mesh, v)) < vertex_bound; };
    // In place, the new vertices exist already and are taken in the same order.
    next_vertex = vertex_bound;
    const auto new_vertex = [&](const vec3<double>& p) {
        if (!in_place) return make.vertex(p);
        const auto v = vertex_of(next_vertex++);
        dt::set_position<M, T>(mesh, v, p);
        return v;
    };
    const std::size_t face_total = in_place ? face_bound : w.faces.size();
    for (std::size_t i = 0; i < face_total; ++i) {
        F f{};
        if constexpr (bulk_growable_mesh<M, T>) f = in_place ? T::face_at(mesh, i) : w.faces[i];
        else f = w.faces[i];
        const vec3<double> c = face_point_of(f);
        w.corners.clear();
        const H start = T::face_halfedge(mesh, f);
        H x = start;
        do {
            if (!is_old(T::target(mesh, x))) {
                w.corners.push_back(x);  // the first half of an edge a neighbour split
            } else if (const H o = T::opposite(mesh, x); is_old(T::target(mesh, o))) {
                const F g = T::face(mesh, o);
                const vec3<double> ends = dt::position_of<M, T>(mesh, T::target(mesh, x)) + dt::position_of<M, T>(mesh, T::target(mesh, o));
                const vec3<double> q = g == T::null_face() ? ends * 0.5 : (ends + c + face_point_of(g)) * 0.25;
                // x now ends at the edge point; continue after the new half
                x = dt::split_links<M, T>(mesh, x, new_vertex(q), false, false, make);
                w.corners.push_back(T::prev(mesh, x));
            }
            x = T::next(mesh, x);
        } while (x != start);
        // corners[k] ends at edge point k; next(corners[k]) runs on to the next old vertex,
        // whose next is corners[k + 1]. Quad k (k >= 1) is corners[k], the new edge's half
        // into the centre, the half out of the centre made for quad k - 1, next(corners[k-1]);
        // f keeps quad 0. Each next(corners[k]) is read before corners[k]'s next changes.
        const H first = w.corners[0];
        H side = T::next(mesh, first);  // next(corners[k - 1])
        const auto centre = in_place ? vertex_of(next_vertex++) : make.vertex(c);  // in place: at c already
        assert(!in_place || std::size_t(T::vertex_index(mesh, centre)) == w.centre[T::face_index(mesh, f)]);
        const H spike = make.edge(T::target(mesh, first), centre);  // edge point 0 -> centre
        H out_of_centre = T::opposite(mesh, spike);                 // centre -> edge point k - 1
        for (std::size_t k = 1; k < w.corners.size(); ++k) {
            const H corner = w.corners[k];
            const H next_side = T::next(mesh, corner);
            const H a = make.edge(centre, T::target(mesh, corner));  // centre -> edge point k
            const H b = T::opposite(mesh, a);
            const F g = make.face();
            T::set_next(mesh, corner, b);
            T::set_next(mesh, b, out_of_centre);
            T::set_next(mesh, out_of_centre, side);
            T::set_face(mesh, corner, g);
            T::set_face(mesh, b, g);
            T::set_face(mesh, out_of_centre, g);
            T::set_face(mesh, side, g);
            T::set_face_halfedge(mesh, g, b);
            out_of_centre = a;
            side = next_side;
        }
        const H stored = T::face_halfedge(mesh, f);
        T::set_next(mesh, first, spike);
        T::set_next(mesh, spike, out_of_centre);
        T::set_next(mesh, out_of_centre, side);
        T::set_face(mesh, spike, f);
        T::set_face(mesh, out_of_centre, f);
        // As make_edge_face: a stored halfedge that went to another quad gives way to the
        // last edge out of the centre.
        if (stored != first && stored != side) T::set_face_halfedge(mesh, f, out_of_centre);
        T::set_vertex_halfedge(mesh, centre, T::opposite(mesh, spike));
        if ((i + 1) % block == 0 && !gate.advance(1)) return false;
    }
    // The pass stops once it has seen every old vertex (on the usual models they come first, in
    // index order), rather than run over the three times as many new ones.
    seen = 0;
    for (auto v : T::vertices(mesh)) {
        if (seen == old_vertices) break;
        const std::size_t i = T::vertex_index(mesh, v);
        if (i >= vertex_bound) continue;  // a new vertex, placed already
        ++seen;
        if (w.boundary_edges[i] == 0 && w.valence[i] > 0) {
            const double n = double(w.valence[i]);
            dt::set_position<M, T>(mesh, v, (dt::position_of<M, T>(mesh, v) * (n - 2) + sum[i] / n) / n);
        } else if (w.boundary_edges[i] == 2) {
            dt::set_position<M, T>(mesh, v, sum[i]);
        }  // else it stays
        if (++done % block == 0 && !gate.advance(1)) return false;
    }
    return true;
}

}  // namespace detail::subdivision

/// Catmull-Clark subdivision, `options.levels` times, on any polygon mesh. Each level puts a
/// face point at each face's centroid; splits each edge at its edge point (the average of its
/// two ends and the two face points beside it; the midpoint on a boundary); joins each face
/// point to the edge points around it, so a face of degree n becomes n quads; and moves each
/// old vertex S of valence n to (Q + 2R + (n - 3) S) / n, with Q the average of the face
/// points around it and R the average of its edges' midpoints.
///
/// Boundaries follow the cubic B-spline of the boundary polygon: a boundary edge point is the
/// edge's midpoint and a boundary vertex moves to 3/4 of itself plus 1/8 of each of its two
/// boundary neighbours, so the boundary curve depends on the boundary alone and two meshes
/// sharing a boundary stay joined. A vertex where two boundary fans meet, and an isolated
/// vertex, stay where they are.
///
/// \pre no face has inner rings; every edge has a face on at least one side, and different
///      faces when it has two.
/// \post per level: V + E + F vertices, 2 E + C edges and C faces (C the sum of the face
///       degrees), every face a quad; genus and boundary loops unchanged. Old vertices keep
///       their handles; faces keep theirs (each old face is one of its quads).
/// Errors (mesh unchanged): errc::unsupported for a face with inner rings (naming it);
/// errc::topology for an edge without faces or with the same face on both sides (naming it);
/// errc::invalid_argument for more than 10 levels, or when the result would need more than
/// 2^31 halfedges; errc::cancelled when options.progress returns false.
/// The mesh and the working arrays are sized for the last level before the first change, so
/// std::bad_alloc comes before any change (a model's user property arrays excepted, which
/// grow element by element).
/// Every new position is a convex combination of old ones and is computed without overflow,
/// coordinates near the largest double included (see detail::subdivision::range_guard).
/// Complexity O(C) per level (every operator is O(1) or O(face degree)), so O(4^levels C);
/// plus O(V + E + F) for the copy when a progress callback is given.
template <class M, class T = default_traits<M>>
    requires catmull_clark_subdividable_mesh<M, T>
[[nodiscard]] result<catmull_clark_result> catmull_clark_subdivide(M& mesh, const catmull_clark_options& options = {}) {
    namespace de = detail::euler;
    namespace ds = detail::subdivision;
    if (options.levels > 10)
        return fail(errc::invalid_argument,
                    "catmull_clark_subdivide: option levels must be at most 10, got " + std::to_string(options.levels));
    ds::cc_counts counts{T::vertex_count(mesh), T::edge_count(mesh), T::face_count(mesh), 0};
    std::size_t max_degree = 4;
    for (auto f : T::faces(mesh)) {
        if (de::has_rings<M, T>(mesh, f))
            return fail(errc::unsupported,
                        "catmull_clark_subdivide: " + de::name<M, T>("face", mesh, f) + " has inner rings (triangulate_faces or fill them first)",
                        de::index_of<M, T>(mesh, f));
        const std::size_t degree = detail::triangle_ops::loop_length<M, T>(mesh, T::face_halfedge(mesh, f), std::size_t(-1));
        counts.corners += degree;
        max_degree = std::max(max_degree, degree);
    }
    for (auto e : T::edges(mesh)) {
        const auto h = T::edge_halfedge(mesh, e), o = T::opposite(mesh, h);
        const auto fh = T::face(mesh, h), fo = T::face(mesh, o);
        if (fh == fo)
            return fail(errc::topology,
                        "catmull_clark_subdivide: edge " + std::to_string(T::edge_index(mesh, e)) +
                            (fh == T::null_face() ? " has no face on either side" : " has the same face on both sides"),
                        (long long)T::edge_index(mesh, e));
    }
    // The counts of every level are known now: the mesh and the per-level arrays are sized for
    // the last one up front, so nothing allocates once the mesh has started to change.
    const ds::cc_counts first = counts;
    ds::cc_counts largest_input = counts;
    std::uint64_t blocks = 0;
    for (std::size_t l = 0; l < options.levels; ++l) {
        largest_input = counts;
        blocks += (2 * counts.vertices + counts.edges + 2 * counts.faces) / (1u << 14);
        counts = counts.next();
        if (2 * counts.edges >= (std::uint64_t(1) << 31))
            return fail(errc::invalid_argument, "catmull_clark_subdivide: " + std::to_string(options.levels) +
                                                    " levels would make more than 2^31 halfedges, more than a mesh index holds");
    }
    if (options.levels == 0) return catmull_clark_result{T::vertex_count(mesh), T::edge_count(mesh), T::face_count(mesh)};
    const std::size_t vertex_bound = T::vertex_index_bound(mesh) + std::size_t(counts.vertices - first.vertices);
    const std::size_t edge_bound = T::edge_index_bound(mesh) + std::size_t(counts.edges - first.edges);
    const std::size_t face_bound = T::face_index_bound(mesh) + std::size_t(counts.faces - first.faces);
    detail::subdivision::reserve_room<M, T>(mesh, vertex_bound, edge_bound, face_bound);
    [[maybe_unused]] const detail::subdivision::appending_guard<M> appending(mesh);  // new vertices are told by index
    ds::cc_workspace<M, T> work;
    work.room = {vertex_bound, edge_bound, face_bound};
    work.reserve(vertex_bound - std::size_t(counts.vertices - largest_input.vertices), face_bound - std::size_t(counts.faces - largest_input.faces),
                 max_degree);

    detail::progress_gate gate(options.progress, std::size_t(blocks));
    // Without a callback nothing can stop a level half way: its preconditions hold for the
    // whole mesh and hold again after it. With one, a copy taken before the first change is
    // what a cancellation restores.
    std::vector<M> backup;
    if (options.progress) backup.push_back(mesh);
    ds::range_guard<M, T> range(mesh);
    for (std::size_t l = 0; l < options.levels; ++l) {
        if (!ds::catmull_clark_level<M, T>(mesh, work, gate)) {
            range.dismiss();
            mesh = std::move(backup.front());
            return fail(errc::cancelled, "catmull_clark_subdivide: cancelled");
        }
    }
    range.restore();
    return catmull_clark_result{T::vertex_count(mesh), T::edge_count(mesh), T::face_count(mesh)};
}

}  // namespace hmira
