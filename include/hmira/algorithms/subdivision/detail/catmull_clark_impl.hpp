// hmira/algorithms/subdivision/detail/catmull_clark_impl.hpp
// The machinery of catmull_clark_subdivide (subdivision/catmull_clark.hpp): the per-level
// workspace, one level pass by pass, and the entry point's definition.
#pragma once

#include <algorithm>
#include <array>
#include <cassert>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "../../../core/rollback.hpp"
#include "../../triangle/split_edge.hpp"
#include "new_elements.hpp"
#include "range.hpp"
#include "reserve.hpp"

namespace hmira {

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

/// One Catmull-Clark level, pass by pass. Preconditions established by the caller for the
/// whole mesh: no face has inner rings; every edge has a face on at least one side, and two
/// different faces when it has two; `w` and the mesh have room for this level. Every pass
/// returns false when `gate` cancels, which it does only between blocks (the caller then
/// restores its copy).
template <class M, class T>
class cc_level {
public:
    using H = typename T::halfedge_handle;
    using F = typename T::face_handle;
    using V = typename T::vertex_handle;
    static constexpr std::size_t block = 1u << 14;

    cc_level(M& mesh, cc_workspace<M, T>& w, progress_gate& gate)
        : mesh_(mesh),
          w_(w),
          gate_(gate),
          vertex_bound_(T::vertex_index_bound(mesh)),
          face_bound_(T::face_index_bound(mesh)),
          old_vertices_(T::vertex_count(mesh)) {}

    /// The whole level.
    bool run() {
        // Every new position is computed before the first operator, in flat arrays indexed by
        // element index, from the old positions only; old positions change only at the very end.
        w_.vertex_point.assign(vertex_bound_, {});
        w_.valence.assign(vertex_bound_, 0);
        w_.boundary_edges.assign(vertex_bound_, 0);
        w_.faces.clear();
        choose_in_place();
        w_.face_point.assign(in_place_ ? 0 : face_bound_, {});
        w_.centre.assign(in_place_ ? face_bound_ : 0, 0);
        next_vertex_ = vertex_end_ = vertex_bound_;
        if (!face_points()) return false;
        if (in_place_ && vertex_end_ != next_vertex_) resize_vertices(next_vertex_);
        if (!neighbour_sums()) return false;
        if (!boundary_points()) return false;
        if (!cut_faces()) return false;
        return move_old_vertices();
    }

private:
    /// Points in place: on a model that names a vertex by its index (bulk_growable_mesh), with
    /// double positions, every face index live and the faces met in index order, each face's
    /// vertex index is known before the first change (faces of lower index go first, and each
    /// makes the points of its edges not split yet, then its centre), so the face point is
    /// written straight into that vertex rather than into a face_point array that would be
    /// faulted in, filled and read back. Elsewhere the array keeps them; the result is the same.
    void choose_in_place() {
        if constexpr (bulk_growable_mesh<M, T> && std::same_as<typename T::scalar, double>) {
            in_place_ = T::face_count(mesh_) == face_bound_;
            std::size_t k = 0;
            for (auto f : T::faces(mesh_)) {
                if (!in_place_) break;
                in_place_ = T::face_index(mesh_, f) == k++;
            }
        }
    }

    V vertex_of(std::size_t i) {
        if constexpr (bulk_growable_mesh<M, T>)
            return T::vertex_at(mesh_, i);
        else {
            (void)i;
            return V{};
        }  // not called: in_place_ is false
    }

    void resize_vertices(std::size_t n) {  // in place only
        if constexpr (bulk_growable_mesh<M, T>)
            T::resize(mesh_, n, T::edge_index_bound(mesh_), face_bound_);
        else
            (void)n;
    }

    vec3<double> face_point_of(F f) {
        namespace dt = detail::triangle_ops;
        if (in_place_) return dt::position_of<M, T>(mesh_, vertex_of(w_.centre[T::face_index(mesh_, f)]));
        return w_.face_point[T::face_index(mesh_, f)];
    }

    bool tick() { return ++done_ % block != 0 || gate_.advance(1); }

    /// Face points (centroids); each vertex sums the face points around it.
    bool face_points() {
        namespace dt = detail::triangle_ops;
        for (auto f : T::faces(mesh_)) {
            if (!in_place_) w_.faces.push_back(f);
            const H start = T::face_halfedge(mesh_, f);
            vec3<double> c{};
            std::size_t n = 0;
            H x = start;
            do {
                c += dt::position_of<M, T>(mesh_, T::target(mesh_, x));
                ++n;
                x = T::next(mesh_, x);
            } while (x != start);
            c = c / double(n);
            if (in_place_) {
                // The edges f will split: those whose other side is a boundary or a later face.
                const std::size_t fi = T::face_index(mesh_, f);
                do {
                    const F g = T::face(mesh_, T::opposite(mesh_, x));
                    next_vertex_ += g == T::null_face() || T::face_index(mesh_, g) > fi;
                    x = T::next(mesh_, x);
                } while (x != start);
                if (next_vertex_ >= vertex_end_) {  // the vertices made in blocks, as new_elements would
                    vertex_end_ = std::max(next_vertex_ + 1, std::min(vertex_end_ + (1u << 12), w_.room[0]));
                    resize_vertices(vertex_end_);
                }
                w_.centre[fi] = std::uint32_t(next_vertex_);
                dt::set_position<M, T>(mesh_, vertex_of(next_vertex_++), c);
            } else {
                w_.face_point[T::face_index(mesh_, f)] = c;
            }
            do {
                w_.vertex_point[T::vertex_index(mesh_, T::target(mesh_, x))] += c;
                x = T::next(mesh_, x);
            } while (x != start);
            if (!tick()) return false;
        }
        return true;
    }

    /// Each vertex adds its neighbours and counts its edges and boundary edges.
    bool neighbour_sums() {
        namespace dt = detail::triangle_ops;
        auto& sum = w_.vertex_point;
        for (auto e : T::edges(mesh_)) {
            const H h = T::edge_halfedge(mesh_, e), o = T::opposite(mesh_, h);
            const auto va = T::target(mesh_, o), vb = T::target(mesh_, h);
            const std::size_t a = T::vertex_index(mesh_, va), b = T::vertex_index(mesh_, vb);
            sum[a] += dt::position_of<M, T>(mesh_, vb);
            sum[b] += dt::position_of<M, T>(mesh_, va);
            ++w_.valence[a];
            ++w_.valence[b];
            if (T::face(mesh_, h) == T::null_face() || T::face(mesh_, o) == T::null_face()) {
                w_.boundary_edges[a] = std::uint8_t(std::min(3, w_.boundary_edges[a] + 1));
                w_.boundary_edges[b] = std::uint8_t(std::min(3, w_.boundary_edges[b] + 1));
            }
            if (!tick()) return false;
        }
        return true;
    }

    /// Vertex points. Interior, valence n: ((n - 2) S + (sum of neighbours and face points) / n)
    /// / n, which is Catmull and Clark's (Q + 2R + (n - 3) S) / n. On the boundary (two boundary
    /// edges): 3/4 S + 1/8 of each boundary neighbour, the cubic B-spline rule; the vertex's
    /// stored halfedge is a boundary one (the navigation concept promises it), so its two
    /// boundary neighbours are its target and the source of its prev. A vertex with more
    /// boundary edges (two boundary fans meet there) has no curve to follow and stays where it
    /// is, as an isolated vertex does.
    /// The boundary rule reads the old neighbours, so it runs here, before the splits; the inner
    /// rule reads the vertex's own old position only, so it runs in the last pass, which writes
    /// the positions (one pass over the vertices fewer).
    bool boundary_points() {
        namespace dt = detail::triangle_ops;
        std::size_t seen = 0;  // old vertices met (new ones may exist already: the face points in place)
        for (auto v : T::vertices(mesh_)) {
            if (seen == old_vertices_) break;
            const std::size_t i = T::vertex_index(mesh_, v);
            if (i >= vertex_bound_) continue;
            ++seen;
            if (w_.boundary_edges[i] == 2) {
                const vec3<double> p = dt::position_of<M, T>(mesh_, v);
                const H s = T::vertex_halfedge(mesh_, v);
                const auto a = T::target(mesh_, s), b = T::target(mesh_, T::opposite(mesh_, T::prev(mesh_, s)));
                const auto pa = dt::position_of<M, T>(mesh_, a), pb = dt::position_of<M, T>(mesh_, b);
                w_.vertex_point[i] = p * 0.75 + (pa + pb) * 0.125;
            }
            if (!tick()) return false;
        }
        return true;
    }

    /// Face by face, so that each is finished while its elements are still in cache: the
    /// face's edges not split yet (both ends old) are split at their edge points (split_edge's
    /// links, without its checks: the preconditions above make them pass), then the face, now a
    /// 2n-gon alternating old vertices and edge points, becomes n quads around its face point
    /// (cut_face). An edge point is the average of the edge's two ends and the two face points
    /// beside it, or the midpoint on a boundary: the ends are old vertices not moved yet, and an
    /// edge not split yet has no finished face beside it, so the face across it is still the old
    /// one (splits keep faces). New elements come from `make` (in bulk where the model allows) in
    /// the order those operators would make them.
    bool cut_faces() {
        new_elements<M, T> make(mesh_, w_.room);
        // In place, the new vertices exist already and are taken in the same order.
        next_vertex_ = vertex_bound_;
        const std::size_t face_total = in_place_ ? face_bound_ : w_.faces.size();
        for (std::size_t i = 0; i < face_total; ++i) {
            F f{};
            if constexpr (bulk_growable_mesh<M, T>)
                f = in_place_ ? T::face_at(mesh_, i) : w_.faces[i];
            else
                f = w_.faces[i];
            split_face_edges(f, make);
            cut_face(f, make);
            if ((i + 1) % block == 0 && !gate_.advance(1)) return false;
        }
        return true;
    }

    bool is_old(V v) { return std::size_t(T::vertex_index(mesh_, v)) < vertex_bound_; }

    V new_vertex(const vec3<double>& p, new_elements<M, T>& make) {
        if (!in_place_) return make.vertex(p);
        const auto v = vertex_of(next_vertex_++);
        detail::triangle_ops::set_position<M, T>(mesh_, v, p);
        return v;
    }

    /// Splits f's edges not split yet at their edge points, and lists in w_.corners the
    /// halfedges of f that end at an edge point, in order.
    void split_face_edges(F f, new_elements<M, T>& make) {
        namespace dt = detail::triangle_ops;
        const vec3<double> c = face_point_of(f);
        w_.corners.clear();
        const H start = T::face_halfedge(mesh_, f);
        H x = start;
        do {
            if (!is_old(T::target(mesh_, x))) {
                w_.corners.push_back(x);  // the first half of an edge a neighbour split
            } else if (const H o = T::opposite(mesh_, x); is_old(T::target(mesh_, o))) {
                const F g = T::face(mesh_, o);
                const vec3<double> ends = dt::position_of<M, T>(mesh_, T::target(mesh_, x)) +
                                          dt::position_of<M, T>(mesh_, T::target(mesh_, o));
                const vec3<double> q = g == T::null_face() ? ends * 0.5 : (ends + c + face_point_of(g)) * 0.25;
                // x now ends at the edge point; continue after the new half
                x = dt::split_links<M, T>(mesh_, x, new_vertex(q, make), false, false, make);
                w_.corners.push_back(T::prev(mesh_, x));
            }
            x = T::next(mesh_, x);
        } while (x != start);
    }

    /// The 2n-gon f becomes n quads around its face point: the links of make_edge_vertex (a
    /// spike from the first edge point to the face point) and of make_edge_face from the face
    /// point to each further edge point, each closing one quad, written at once without their
    /// checks (the 2n-gon is known) and without re-pointing the shrinking rest of the face after
    /// each quad.
    void cut_face(F f, new_elements<M, T>& make) {
        // corners[k] ends at edge point k; next(corners[k]) runs on to the next old vertex,
        // whose next is corners[k + 1]. Quad k (k >= 1) is corners[k], the new edge's half
        // into the centre, the half out of the centre made for quad k - 1, next(corners[k-1]);
        // f keeps quad 0. Each next(corners[k]) is read before corners[k]'s next changes.
        const H first = w_.corners[0];
        H side = T::next(mesh_, first);  // next(corners[k - 1])
        // In place the centre vertex exists already, at the face point.
        const auto centre = in_place_ ? vertex_of(next_vertex_++) : make.vertex(face_point_of(f));
        assert(!in_place_ || std::size_t(T::vertex_index(mesh_, centre)) == w_.centre[T::face_index(mesh_, f)]);
        const H spike = make.edge(T::target(mesh_, first), centre);  // edge point 0 -> centre
        H out_of_centre = T::opposite(mesh_, spike);                 // centre -> edge point k - 1
        for (std::size_t k = 1; k < w_.corners.size(); ++k) {
            const H corner = w_.corners[k];
            const H next_side = T::next(mesh_, corner);
            const H a = make.edge(centre, T::target(mesh_, corner));  // centre -> edge point k
            const H b = T::opposite(mesh_, a);
            const F g = make.face();
            T::set_next(mesh_, corner, b);
            T::set_next(mesh_, b, out_of_centre);
            T::set_next(mesh_, out_of_centre, side);
            T::set_face(mesh_, corner, g);
            T::set_face(mesh_, b, g);
            T::set_face(mesh_, out_of_centre, g);
            T::set_face(mesh_, side, g);
            T::set_face_halfedge(mesh_, g, b);
            out_of_centre = a;
            side = next_side;
        }
        const H stored = T::face_halfedge(mesh_, f);
        T::set_next(mesh_, first, spike);
        T::set_next(mesh_, spike, out_of_centre);
        T::set_next(mesh_, out_of_centre, side);
        T::set_face(mesh_, spike, f);
        T::set_face(mesh_, out_of_centre, f);
        // As make_edge_face: a stored halfedge that went to another quad gives way to the
        // last edge out of the centre.
        if (stored != first && stored != side) T::set_face_halfedge(mesh_, f, out_of_centre);
        T::set_vertex_halfedge(mesh_, centre, T::opposite(mesh_, spike));
    }

    /// The old vertices take their new positions. The pass stops once it has seen every old
    /// vertex (on the usual models they come first, in index order), rather than run over the
    /// three times as many new ones.
    bool move_old_vertices() {
        namespace dt = detail::triangle_ops;
        std::size_t seen = 0;
        for (auto v : T::vertices(mesh_)) {
            if (seen == old_vertices_) break;
            const std::size_t i = T::vertex_index(mesh_, v);
            if (i >= vertex_bound_) continue;  // a new vertex, placed already
            ++seen;
            if (w_.boundary_edges[i] == 0 && w_.valence[i] > 0) {
                const double n = double(w_.valence[i]);
                dt::set_position<M, T>(mesh_, v,
                                       (dt::position_of<M, T>(mesh_, v) * (n - 2) + w_.vertex_point[i] / n) / n);
            } else if (w_.boundary_edges[i] == 2) {
                dt::set_position<M, T>(mesh_, v, w_.vertex_point[i]);
            }  // else it stays
            if (!tick()) return false;
        }
        return true;
    }

    M& mesh_;
    cc_workspace<M, T>& w_;
    progress_gate& gate_;
    std::size_t vertex_bound_, face_bound_, old_vertices_;
    bool in_place_ = false;
    std::size_t next_vertex_ = 0, vertex_end_ = 0;  // in place: the next new vertex's index, the bound made so far
    std::size_t done_ = 0;                          // elements handled, for the gate
};

/// One Catmull-Clark level (see cc_level). Returns false when `gate` cancels.
template <class M, class T>
bool catmull_clark_level(M& mesh, cc_workspace<M, T>& w, progress_gate& gate) {
    return cc_level<M, T>(mesh, w, gate).run();
}

}  // namespace detail::subdivision

template <class M, class T>
    requires catmull_clark_subdividable_mesh<M, T>
result<catmull_clark_result> catmull_clark_subdivide(M& mesh, const catmull_clark_options& options) {
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
                        "catmull_clark_subdivide: " + de::name<M, T>("face", mesh, f) +
                            " has inner rings (triangulate_faces or fill them first)",
                        de::index_of<M, T>(mesh, f));
        const std::size_t degree =
            detail::triangle_ops::loop_length<M, T>(mesh, T::face_halfedge(mesh, f), std::size_t(-1));
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
            return fail(errc::invalid_argument,
                        "catmull_clark_subdivide: " + std::to_string(options.levels) +
                            " levels would make more than 2^31 halfedges, more than a mesh index holds");
    }
    if (options.levels == 0)
        return catmull_clark_result{T::vertex_count(mesh), T::edge_count(mesh), T::face_count(mesh)};
    const std::size_t vertex_bound = T::vertex_index_bound(mesh) + std::size_t(counts.vertices - first.vertices);
    const std::size_t edge_bound = T::edge_index_bound(mesh) + std::size_t(counts.edges - first.edges);
    const std::size_t face_bound = T::face_index_bound(mesh) + std::size_t(counts.faces - first.faces);
    detail::subdivision::reserve_room<M, T>(mesh, vertex_bound, edge_bound, face_bound);
    [[maybe_unused]] const detail::subdivision::appending_guard<M> appending(mesh);  // new vertices are told by index
    ds::cc_workspace<M, T> work;
    work.room = {vertex_bound, edge_bound, face_bound};
    work.reserve(vertex_bound - std::size_t(counts.vertices - largest_input.vertices),
                 face_bound - std::size_t(counts.faces - largest_input.faces), max_degree);

    detail::progress_gate gate(options.progress, std::size_t(blocks));
    // Without a callback nothing can stop a level half way: its preconditions hold for the
    // whole mesh and hold again after it, so there is nothing to copy. With one, a copy taken
    // before the first change is what a cancellation restores.
    mesh_rollback<M> undo(mesh, bool(options.progress));
    ds::range_guard<M, T> range(mesh);
    for (std::size_t l = 0; l < options.levels; ++l) {
        if (!ds::catmull_clark_level<M, T>(mesh, work, gate)) {
            range.dismiss();
            undo.restore();
            return fail(errc::cancelled, "catmull_clark_subdivide: cancelled");
        }
    }
    range.restore();
    undo.commit();
    return catmull_clark_result{T::vertex_count(mesh), T::edge_count(mesh), T::face_count(mesh)};
}

}  // namespace hmira
