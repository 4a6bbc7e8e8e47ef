// hmira/interop/cgal.hpp
// mesh_traits for CGAL::Surface_mesh<Point_3> (CGAL 5.5), so every hmira algorithm runs on the
// user's Surface_mesh in place: its own indices, its halfedges navigated directly, no copy.
// Needs CGAL (GPL-3.0-or-later / LGPL-3.0-or-later for the parts used); link hmira::cgal.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Surface_mesh.h>

#include "../concepts.hpp"
#include "../core/result.hpp"
#include "../core/vec3.hpp"
#include "../meshes/detail/element_range.hpp"
#include "../traits.hpp"

namespace hmira {

namespace cgal_detail {

/// Live elements of one kind in index order; elements CGAL marks removed are skipped (only
/// checked while the mesh has garbage).
template <class Mesh, class Index>
class element_range : public std::ranges::view_interface<element_range<Mesh, Index>> {
public:
    class iterator {
    public:
        using value_type = Index;
        using difference_type = std::ptrdiff_t;
        using iterator_concept = std::forward_iterator_tag;
        iterator() = default;
        iterator(const Mesh* m, std::size_t i, std::size_t bound, bool skip)
            : m_(m), i_(i), bound_(bound), skip_(skip) {
            advance();
        }
        Index operator*() const noexcept { return Index(static_cast<typename Mesh::size_type>(i_)); }
        iterator& operator++() noexcept {
            ++i_;
            advance();
            return *this;
        }
        iterator operator++(int) noexcept {
            auto t = *this;
            ++*this;
            return t;
        }
        friend bool operator==(const iterator& a, const iterator& b) noexcept { return a.i_ == b.i_; }

    private:
        void advance() noexcept {
            if (skip_)
                while (i_ < bound_ && m_->is_removed(Index(static_cast<typename Mesh::size_type>(i_)))) ++i_;
        }
        const Mesh* m_ = nullptr;
        std::size_t i_ = 0, bound_ = 0;
        bool skip_ = false;
    };
    element_range() = default;
    element_range(const Mesh& m, std::size_t bound) : m_(&m), bound_(bound), skip_(m.has_garbage()) {}
    iterator begin() const { return iterator(m_, 0, bound_, skip_); }
    iterator end() const { return iterator(m_, bound_, bound_, false); }

private:
    const Mesh* m_ = nullptr;
    std::size_t bound_ = 0;
    bool skip_ = false;
};

template <class Mesh>
struct steps {
    using H = typename Mesh::Halfedge_index;
    struct loop {
        static H step(const Mesh& m, H h) { return m.next(h); }
    };
    struct loop_halfedge : loop {
        static H value(const Mesh&, H h) { return h; }
    };
    struct loop_vertex : loop {
        static typename Mesh::Vertex_index value(const Mesh& m, H h) { return m.target(h); }
    };
    struct outgoing {
        static H step(const Mesh& m, H h) { return m.next(m.opposite(h)); }
    };
    struct outgoing_halfedge : outgoing {
        static H value(const Mesh&, H h) { return h; }
    };
    struct outgoing_target : outgoing {
        static typename Mesh::Vertex_index value(const Mesh& m, H h) { return m.target(h); }
    };
    struct outgoing_edge : outgoing {
        static typename Mesh::Edge_index value(const Mesh& m, H h) { return m.edge(h); }
    };
};

}  // namespace cgal_detail

/// CGAL::Surface_mesh: halfedge navigation, indices, positions, polygon building and raw
/// mutation, on the user's object.
///
/// Surface_mesh stores an *incoming* halfedge per vertex (a border one on the border); hmira's
/// vertex_halfedge is outgoing, so it is read as the next border halfedge or the opposite, and
/// set_vertex_halfedge stores the matching incoming one (keeping CGAL's border convention when
/// the links already allow it). erase_* call Surface_mesh's remove_*, which marks the element
/// removed and reuses one of its links for CGAL's free list: read an element before erasing it.
/// Not change-counted: Surface_mesh keeps no counter and has no mesh-wide property to hold one.
/// Rings (face_vertices, adjacent_vertices, vertex_edges) trust the links as CGAL's circulators
/// do, with no step guard: check a mesh of unknown origin with hmira::validate, which bounds its walks.
template <class P>
struct mesh_traits<CGAL::Surface_mesh<P>> {
    using mesh = CGAL::Surface_mesh<P>;
    using vertex_handle = typename mesh::Vertex_index;
    using face_handle = typename mesh::Face_index;
    using edge_handle = typename mesh::Edge_index;
    using halfedge_handle = typename mesh::Halfedge_index;
    using scalar = std::remove_cvref_t<decltype(std::declval<const P&>().x())>;
    using VH = vertex_handle;
    using FH = face_handle;
    using EH = edge_handle;
    using HH = halfedge_handle;
    using S = cgal_detail::steps<mesh>;
    template <class Policy>
    using loop = detail::loop_range<mesh, HH, Policy>;
    // Rings trust Surface_mesh's links as its circulators do (detail::lap_range: no step guard).
    template <class Policy>
    using ring = detail::lap_range<mesh, HH, Policy>;

    // ----- whole structure ----------------------------------------------------------------------
    static cgal_detail::element_range<mesh, VH> vertices(const mesh& m) { return {m, m.num_vertices()}; }
    static cgal_detail::element_range<mesh, FH> faces(const mesh& m) { return {m, m.num_faces()}; }
    static cgal_detail::element_range<mesh, EH> edges(const mesh& m) { return {m, m.num_edges()}; }
    static cgal_detail::element_range<mesh, HH> halfedges(const mesh& m) { return {m, m.num_halfedges()}; }
    static std::size_t vertex_count(const mesh& m) { return m.number_of_vertices(); }
    static std::size_t face_count(const mesh& m) { return m.number_of_faces(); }
    static std::size_t edge_count(const mesh& m) { return m.number_of_edges(); }
    static std::size_t vertex_index(const mesh&, VH v) { return v.idx(); }
    static std::size_t vertex_index_bound(const mesh& m) { return m.num_vertices(); }
    static std::size_t face_index(const mesh&, FH f) { return f.idx(); }
    static std::size_t face_index_bound(const mesh& m) { return m.num_faces(); }
    static std::size_t edge_index(const mesh&, EH e) { return e.idx(); }
    static std::size_t edge_index_bound(const mesh& m) { return m.num_edges(); }
    static std::size_t halfedge_index(const mesh&, HH h) { return h.idx(); }
    static std::size_t halfedge_index_bound(const mesh& m) { return m.num_halfedges(); }

    // ----- halfedge navigation, O(1) ------------------------------------------------------------
    static HH next(const mesh& m, HH h) { return m.next(h); }
    static HH prev(const mesh& m, HH h) { return m.prev(h); }
    static HH opposite(const mesh& m, HH h) { return m.opposite(h); }
    static VH target(const mesh& m, HH h) { return m.target(h); }
    static FH face(const mesh& m, HH h) { return m.face(h); }
    static EH edge(const mesh& m, HH h) { return m.edge(h); }
    static HH edge_halfedge(const mesh& m, EH e) { return m.halfedge(e); }
    static HH vertex_halfedge(const mesh& m, VH v) {
        const HH in = m.halfedge(v);
        if (in == mesh::null_halfedge()) return in;
        return m.face(in) == mesh::null_face() ? m.next(in) : m.opposite(in);
    }
    static HH face_halfedge(const mesh& m, FH f) { return m.halfedge(f); }
    static FH null_face() { return mesh::null_face(); }
    static HH null_halfedge() { return mesh::null_halfedge(); }

    // ----- local getters at thesis cost -----------------------------------------------------------
    static ring<typename S::loop_vertex> face_vertices(const mesh& m, FH f) { return {m, m.halfedge(f)}; }
    // A full turn around v may start at any outgoing halfedge: the opposite of the stored
    // incoming one costs no memory access (vertex_halfedge would read its face).
    static HH any_outgoing(const mesh& m, VH v) {
        const HH in = m.halfedge(v);
        return in == mesh::null_halfedge() ? in : m.opposite(in);
    }
    static ring<typename S::outgoing_target> adjacent_vertices(const mesh& m, VH v) { return {m, any_outgoing(m, v)}; }
    static ring<typename S::outgoing_edge> vertex_edges(const mesh& m, VH v) { return {m, any_outgoing(m, v)}; }
    static auto vertex_faces(const mesh& m, VH v) {
        return loop<typename S::outgoing_halfedge>(m, any_outgoing(m, v)) |
               std::views::filter([&m](HH h) { return m.face(h) != mesh::null_face(); }) |
               std::views::transform([&m](HH h) { return m.face(h); });
    }
    static auto adjacent_faces(const mesh& m, FH f) {
        return loop<typename S::loop_halfedge>(m, m.halfedge(f)) |
               std::views::filter([&m](HH h) { return m.face(m.opposite(h)) != mesh::null_face(); }) |
               std::views::transform([&m](HH h) { return m.face(m.opposite(h)); });
    }
    static std::array<VH, 2> edge_vertices(const mesh& m, EH e) {
        return {m.source(m.halfedge(e)), m.target(m.halfedge(e))};
    }

    // ----- geometry ---------------------------------------------------------------------------------
    static vec3<scalar> position(const mesh& m, VH v) {
        const auto& p = m.point(v);
        return {static_cast<scalar>(p.x()), static_cast<scalar>(p.y()), static_cast<scalar>(p.z())};
    }
    static void set_position(mesh& m, VH v, const vec3<scalar>& p) { m.point(v) = P(p.x, p.y, p.z); }

    // ----- building ---------------------------------------------------------------------------------
    static VH add_vertex(mesh& m, const vec3<scalar>& p) { return m.add_vertex(P(p.x, p.y, p.z)); }
    /// Optional (not a concept requirement): room for this many elements, as Surface_mesh::reserve.
    static void reserve(mesh& m, std::size_t vertices, std::size_t edges, std::size_t faces) {
        m.reserve(static_cast<typename mesh::size_type>(vertices), static_cast<typename mesh::size_type>(edges),
                  static_cast<typename mesh::size_type>(faces));
    }

    /// Optional (not a concept requirement): sets the index bounds to these counts, as
    /// Surface_mesh::resize, which sizes every property array of each kind (the user's too) in
    /// one call per array, where adding elements one at a time costs a virtual push_back per
    /// array and element. Growing appends live, unlinked elements (null links and faces, not
    /// removed); shrinking drops the last ones, which must be unreferenced. Removed elements
    /// and the free lists are left alone. Within reserved capacity it never reallocates.
    /// O(change * property arrays). The fill is still ~5 ns an element for the connectivity
    /// and point arrays: CGAL's Property_array::resize is vector::resize(n, value), which g++
    /// 12 compiles to a loop whose every element reloads the value through a failed
    /// store-to-load forward; those arrays' types are private, so nothing cheaper can grow them.
    static void resize(mesh& m, std::size_t vertices, std::size_t edges, std::size_t faces) {
        m.resize(static_cast<typename mesh::size_type>(vertices), static_cast<typename mesh::size_type>(edges),
                 static_cast<typename mesh::size_type>(faces));
    }
    /// Optional (not a concept requirement): the vertex with index i, below the index bound,
    /// for callers that made elements with resize. O(1).
    static VH vertex_at(const mesh&, std::size_t i) { return VH(static_cast<typename mesh::size_type>(i)); }
    /// As vertex_at, for edges.
    static EH edge_at(const mesh&, std::size_t i) { return EH(static_cast<typename mesh::size_type>(i)); }
    /// As vertex_at, for faces.
    static FH face_at(const mesh&, std::size_t i) { return FH(static_cast<typename mesh::size_type>(i)); }

    /// CGAL's add_face (CGAL::Euler::add_face), with its failure (a null face) turned into an
    /// error; handles are checked first so CGAL never sees a bad one.
    static result<FH> add_face(mesh& m, std::span<const VH> vs) {
        if (vs.size() < 3)
            return fail(errc::degenerate_face,
                        "add_face: a face needs at least 3 vertices, got " + std::to_string(vs.size()));
        // Removed flags are read only when something was removed: reading them for every
        // corner made building through the traits 1.08x CGAL's own add_face.
        const bool garbage = m.has_garbage();
        const std::size_t nv = m.num_vertices();
        if (vs.size() == 3 && !garbage) {
            // A triangle, the common case, checked without the general loop.
            const auto a = vs[0].idx(), b = vs[1].idx(), c = vs[2].idx();  // VH() is the largest index
            if (a < nv && b < nv && c < nv && a != b && b != c && a != c) {
                const FH f = m.add_face(vs);
                if (f == mesh::null_face())
                    return fail(errc::non_manifold,
                                "add_face: CGAL refused the face (it would make an edge or vertex non-manifold, or is "
                                "wound against a neighbour)");
                return f;
            }
        }
        for (std::size_t i = 0; i < vs.size(); ++i) {
            if (vs[i] == VH() || vs[i].idx() >= nv || (garbage && m.is_removed(vs[i])))
                return fail(errc::invalid_handle,
                            "add_face: corner " + std::to_string(i) + " names a vertex that does not exist",
                            static_cast<long long>(vs[i].idx()));
            for (std::size_t j = 0; j < i; ++j)
                if (vs[j] == vs[i])
                    return fail(errc::degenerate_face,
                                "add_face: vertex " + std::to_string(vs[i].idx()) + " appears twice in the face",
                                static_cast<long long>(vs[i].idx()));
        }
        const FH f = m.add_face(vs);
        if (f == mesh::null_face())
            return fail(errc::non_manifold,
                        "add_face: CGAL refused the face (it would make an edge or vertex non-manifold, or is wound "
                        "against a neighbour)");
        return f;
    }

    /// Optional (not a concept requirement): reverses every face, as flip_normals does through
    /// the raw mutators, in one pass over the edges: each edge's two halfedges swap targets and
    /// each halfedge swaps its own next and prev in place (Surface_mesh's set_next_only and
    /// set_prev_only, public members its documentation files as internals), with no scratch
    /// memory. The generic pass costs Surface_mesh 1.6x its own loop: it reads each vertex's
    /// halfedge as outgoing and writes it back as incoming (set_vertex_halfedge), three dependent
    /// reads of scattered halfedges per vertex, where Surface_mesh's convention needs one; an
    /// earlier one pass through set_next, which also writes the next's prev, needed a scratch
    /// copy of every prev (1.13-1.21x CGAL's reverse_face_orientations). Here the stored
    /// incoming halfedge becomes its opposite (a border one: the old border successor, which
    /// now enters the vertex). Removed elements keep their free-list links.
    /// Complexity O(H_all + V_all).
    static void reverse_orientation(mesh& m) {
        const std::size_t nh = m.num_halfedges();
        const bool garbage = m.has_garbage();
        for (std::size_t e = 0; e < nh / 2; ++e) {
            const EH edge(static_cast<typename mesh::size_type>(e));
            if (garbage && m.is_removed(edge)) continue;
            const HH a = m.halfedge(edge), b = m.opposite(a);
            const VH ta = m.target(a), tb = m.target(b);
            m.set_target(a, tb);
            m.set_target(b, ta);
            const HH na = m.next(a), pa = m.prev(a), nb = m.next(b), pb = m.prev(b);
            m.set_next_only(a, pa);
            m.set_prev_only(a, na);
            m.set_next_only(b, pb);
            m.set_prev_only(b, nb);
        }
        for (std::size_t i = 0; i < m.num_vertices(); ++i) {
            const VH v(static_cast<typename mesh::size_type>(i));
            if (garbage && m.is_removed(v)) continue;
            const HH in = m.halfedge(v);
            if (in == mesh::null_halfedge()) continue;
            // prev(in) now is the old next(in): on the border, the border halfedge that left v.
            m.set_halfedge(v, m.face(in) == mesh::null_face() ? m.prev(in) : m.opposite(in));
        }
    }

    // ----- raw mutation -----------------------------------------------------------------------------
    static void set_next(mesh& m, HH h, HH n) { m.set_next(h, n); }
    static void set_target(mesh& m, HH h, VH v) { m.set_target(h, v); }
    static void set_face(mesh& m, HH h, FH f) { m.set_face(h, f); }
    static void set_vertex_halfedge(mesh& m, VH v, HH out) {
        if (out == mesh::null_halfedge()) {
            m.set_halfedge(v, out);
            return;
        }
        // CGAL's convention for a border vertex: an incoming border halfedge, when the links
        // already name one; otherwise the incoming opposite, which reads back as `out`.
        if (m.face(out) == mesh::null_face()) {
            const HH p = m.prev(out);
            if (p != mesh::null_halfedge() && p.idx() < m.num_halfedges() && m.next(p) == out &&
                m.face(p) == mesh::null_face()) {
                m.set_halfedge(v, p);
                return;
            }
        }
        m.set_halfedge(v, m.opposite(out));
    }
    static void set_face_halfedge(mesh& m, FH f, HH h) { m.set_halfedge(f, h); }
    /// The halfedge Surface_mesh stores for v (incoming), read and written as is, so that an
    /// edit's rollback restores exactly what set_vertex_halfedge changed.
    static HH stored_vertex_halfedge(const mesh& m, VH v) { return m.halfedge(v); }
    /// Writes back a value read by stored_vertex_halfedge.
    static void restore_vertex_halfedge(mesh& m, VH v, HH stored) { m.set_halfedge(v, stored); }
    static HH new_edge(mesh& m, VH a, VH b) {
        const HH h = m.add_edge(a, b);  // target b
        m.set_face(h, mesh::null_face());
        m.set_face(m.opposite(h), mesh::null_face());
        return h;
    }
    static FH new_face(mesh& m) { return m.add_face(); }
    static void erase_edge(mesh& m, EH e) {
        if (!m.is_removed(e)) m.remove_edge(e);
    }
    static void erase_face(mesh& m, FH f) {
        if (!m.is_removed(f)) m.remove_face(f);
    }
    static void erase_vertex(mesh& m, VH v) {
        if (!m.is_removed(v)) m.remove_vertex(v);
    }
    /// Whether the element was removed (Surface_mesh's is_removed), for an index below the
    /// bound. O(1). Surface_mesh reuses a removed slot for the next element of that kind it
    /// adds; a stale handle to a reused slot then names the new element and cannot be told
    /// apart (halfedge_mesh reuses slots too, but its versioned handles can tell; winged_edge_mesh
    /// and OpenMesh do not reuse slots before garbage collection).
    static bool is_removed(const mesh& m, VH v) { return m.is_removed(v); }
    static bool is_removed(const mesh& m, FH f) { return m.is_removed(f); }
    static bool is_removed(const mesh& m, EH e) { return m.is_removed(e); }
    static bool is_removed(const mesh& m, HH h) { return m.is_removed(m.edge(h)); }
};

}  // namespace hmira
