// hmira/interop/openmesh.hpp
// mesh_traits for OpenMesh's PolyMesh_ArrayKernelT and TriMesh_ArrayKernelT (OpenMesh 9), so
// every hmira algorithm runs on the user's OpenMesh object in place: no copy, OpenMesh's own
// handles, its halfedges navigated directly. Needs OpenMesh (BSD-3-Clause); link hmira::openmesh.
#pragma once

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <ranges>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include "../concepts.hpp"
#include "../core/result.hpp"
#include "../core/vec3.hpp"
#include "../meshes/detail/element_range.hpp"
#include "../traits.hpp"

namespace hmira {

namespace openmesh_detail {

/// Live elements of one kind, in index order; elements OpenMesh marks deleted are skipped
/// (which it can only do once the kind's status was requested).
template <class Mesh, class Handle>
class element_range : public std::ranges::view_interface<element_range<Mesh, Handle>> {
public:
    class iterator {
    public:
        using value_type = Handle;
        using difference_type = std::ptrdiff_t;
        using iterator_concept = std::forward_iterator_tag;
        iterator() = default;
        iterator(const Mesh* m, int i, int bound, bool skip) : m_(m), i_(i), bound_(bound), skip_(skip) { advance(); }
        Handle operator*() const noexcept { return Handle(i_); }
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
                while (i_ < bound_ && m_->status(Handle(i_)).deleted()) ++i_;
        }
        const Mesh* m_ = nullptr;
        int i_ = 0, bound_ = 0;
        bool skip_ = false;
    };
    element_range() = default;
    element_range(const Mesh& m, int bound, bool skip) : m_(&m), bound_(bound), skip_(skip) {}
    iterator begin() const { return iterator(m_, 0, bound_, skip_); }
    iterator end() const { return iterator(m_, bound_, bound_, false); }

private:
    const Mesh* m_ = nullptr;
    int bound_ = 0;
    bool skip_ = false;
};

using VH = OpenMesh::VertexHandle;
using FH = OpenMesh::FaceHandle;
using EH = OpenMesh::EdgeHandle;
using HH = OpenMesh::HalfedgeHandle;

template <class Mesh>
struct loop_step {
    static HH step(const Mesh& m, HH h) { return m.next_halfedge_handle(h); }
};
template <class Mesh>
struct loop_vertex : loop_step<Mesh> {
    static VH value(const Mesh& m, HH h) { return m.to_vertex_handle(h); }
};
template <class Mesh>
struct outgoing_step {
    static HH step(const Mesh& m, HH h) { return m.next_halfedge_handle(m.opposite_halfedge_handle(h)); }
};
template <class Mesh>
struct outgoing_target : outgoing_step<Mesh> {
    static VH value(const Mesh& m, HH h) { return m.to_vertex_handle(h); }
};
template <class Mesh>
struct outgoing_edge : outgoing_step<Mesh> {
    static EH value(const Mesh& m, HH h) { return m.edge_handle(h); }
};
template <class Mesh>
struct outgoing_halfedge : outgoing_step<Mesh> {
    static HH value(const Mesh&, HH h) { return h; }
};
template <class Mesh>
struct loop_halfedge : loop_step<Mesh> {
    static HH value(const Mesh&, HH h) { return h; }
};

/// The traits shared by OpenMesh's polygon and triangle meshes.
template <class Mesh>
struct traits_base {
    using mesh = Mesh;
    using vertex_handle = OpenMesh::VertexHandle;
    using face_handle = OpenMesh::FaceHandle;
    using edge_handle = OpenMesh::EdgeHandle;
    using halfedge_handle = OpenMesh::HalfedgeHandle;
    using scalar = typename Mesh::Scalar;
    template <class Policy>
    using loop = detail::loop_range<Mesh, HH, Policy>;
    // Rings trust OpenMesh's links as its circulators do (detail::lap_range: no step guard).
    template <class Policy>
    using ring = detail::lap_range<Mesh, HH, Policy>;

    // ----- whole structure: O(V_all), O(F_all), O(E_all) ---------------------------------
    static element_range<Mesh, VH> vertices(const Mesh& m) {
        return {m, static_cast<int>(m.n_vertices()), m.has_vertex_status()};
    }
    static element_range<Mesh, FH> faces(const Mesh& m) {
        return {m, static_cast<int>(m.n_faces()), m.has_face_status()};
    }
    static element_range<Mesh, EH> edges(const Mesh& m) {
        return {m, static_cast<int>(m.n_edges()), m.has_edge_status()};
    }
    static element_range<Mesh, HH> halfedges(const Mesh& m) {
        return {m, static_cast<int>(m.n_halfedges()), m.has_halfedge_status()};
    }
    /// O(1) while nothing is deleted; with deleted elements (status requested) O(V_all):
    /// OpenMesh counts deleted elements until its garbage_collection().
    static std::size_t vertex_count(const Mesh& m) {
        return m.has_vertex_status() ? count(vertices(m)) : m.n_vertices();
    }
    static std::size_t face_count(const Mesh& m) { return m.has_face_status() ? count(faces(m)) : m.n_faces(); }
    static std::size_t edge_count(const Mesh& m) { return m.has_edge_status() ? count(edges(m)) : m.n_edges(); }

    static std::size_t vertex_index(const Mesh&, VH v) { return static_cast<std::size_t>(v.idx()); }
    static std::size_t vertex_index_bound(const Mesh& m) { return m.n_vertices(); }
    static std::size_t face_index(const Mesh&, FH f) { return static_cast<std::size_t>(f.idx()); }
    static std::size_t face_index_bound(const Mesh& m) { return m.n_faces(); }
    static std::size_t edge_index(const Mesh&, EH e) { return static_cast<std::size_t>(e.idx()); }
    static std::size_t edge_index_bound(const Mesh& m) { return m.n_edges(); }
    static std::size_t halfedge_index(const Mesh&, HH h) { return static_cast<std::size_t>(h.idx()); }
    static std::size_t halfedge_index_bound(const Mesh& m) { return m.n_halfedges(); }

    // ----- halfedge navigation, O(1) ----------------------------------------------------------
    static HH next(const Mesh& m, HH h) { return m.next_halfedge_handle(h); }
    static HH prev(const Mesh& m, HH h) { return m.prev_halfedge_handle(h); }
    static HH opposite(const Mesh& m, HH h) { return m.opposite_halfedge_handle(h); }
    static VH target(const Mesh& m, HH h) { return m.to_vertex_handle(h); }
    static FH face(const Mesh& m, HH h) { return m.face_handle(h); }
    static EH edge(const Mesh& m, HH h) { return m.edge_handle(h); }
    static HH edge_halfedge(const Mesh& m, EH e) { return m.halfedge_handle(e, 0); }
    static HH vertex_halfedge(const Mesh& m, VH v) { return m.halfedge_handle(v); }
    static HH face_halfedge(const Mesh& m, FH f) { return m.halfedge_handle(f); }
    static FH null_face() { return FH(); }
    static HH null_halfedge() { return HH(); }

    // ----- local getters at thesis cost ------------------------------------------------------
    static ring<loop_vertex<Mesh>> face_vertices(const Mesh& m, FH f) { return {m, m.halfedge_handle(f)}; }
    static ring<outgoing_target<Mesh>> adjacent_vertices(const Mesh& m, VH v) { return {m, m.halfedge_handle(v)}; }
    static ring<outgoing_edge<Mesh>> vertex_edges(const Mesh& m, VH v) { return {m, m.halfedge_handle(v)}; }
    static auto vertex_faces(const Mesh& m, VH v) {
        return loop<outgoing_halfedge<Mesh>>(m, m.halfedge_handle(v)) |
               std::views::filter([&m](HH h) { return m.face_handle(h).is_valid(); }) |
               std::views::transform([&m](HH h) { return m.face_handle(h); });
    }
    static auto adjacent_faces(const Mesh& m, FH f) {
        return loop<loop_halfedge<Mesh>>(m, m.halfedge_handle(f)) |
               std::views::filter([&m](HH h) { return m.face_handle(m.opposite_halfedge_handle(h)).is_valid(); }) |
               std::views::transform([&m](HH h) { return m.face_handle(m.opposite_halfedge_handle(h)); });
    }
    static std::array<VH, 2> edge_vertices(const Mesh& m, EH e) {
        const auto h = m.halfedge_handle(e, 0);
        return {m.from_vertex_handle(h), m.to_vertex_handle(h)};
    }

    // ----- geometry ----------------------------------------------------------------------------
    static vec3<scalar> position(const Mesh& m, VH v) {
        const auto& p = m.point(v);
        return {p[0], p[1], p[2]};
    }
    static void set_position(Mesh& m, VH v, const vec3<scalar>& p) {
        m.set_point(v, typename Mesh::Point(p.x, p.y, p.z));
    }

    // ----- building ----------------------------------------------------------------------------
    static VH add_vertex(Mesh& m, const vec3<scalar>& p) { return m.add_vertex(typename Mesh::Point(p.x, p.y, p.z)); }
    /// Optional (not a concept requirement): room for this many elements, as OpenMesh's reserve.
    static void reserve(Mesh& m, std::size_t vertices, std::size_t edges, std::size_t faces) {
        m.reserve(vertices, edges, faces);
    }
    /// Optional (not a concept requirement): sets the index bounds to these, as OpenMesh's
    /// resize. Growing appends live, unlinked elements (invalid links and faces, default
    /// points, status clear), every property at its default, without resizing every property
    /// array once per element (what new_vertex, new_edge and new_face do); the caller links
    /// every one before anything else reads the mesh. Shrinking drops elements from the end,
    /// which must be unreferenced. Within reserved capacity it never reallocates. O(change).
    static void resize(Mesh& m, std::size_t vertices, std::size_t edges, std::size_t faces) {
        m.resize(vertices, edges, faces);
    }
    /// Optional (not a concept requirement): the handle of the element at an index below its
    /// bound, for callers that made elements with resize. O(1).
    static VH vertex_at(const Mesh&, std::size_t i) { return VH(static_cast<int>(i)); }
    /// As vertex_at, for edges.
    static EH edge_at(const Mesh&, std::size_t i) { return EH(static_cast<int>(i)); }
    /// As vertex_at, for faces.
    static FH face_at(const Mesh&, std::size_t i) { return FH(static_cast<int>(i)); }

    /// OpenMesh's add_face, with its failure (an invalid handle and a line on omerr) turned
    /// into an error; the handles are checked first so OpenMesh never sees a bad one.
    static result<FH> add_face(Mesh& m, std::span<const VH> vs) {
        if (vs.size() < 3)
            return fail(errc::degenerate_face,
                        "add_face: a face needs at least 3 vertices, got " + std::to_string(vs.size()));
        if (vs.size() == 3 && !m.has_vertex_status()) {
            // A triangle, the common case, checked without the general loop (which names the
            // problem of a refused one). Unsigned, a null handle (-1) is out of range.
            const auto nv = m.n_vertices();
            const auto a = static_cast<std::size_t>(static_cast<unsigned>(vs[0].idx())),
                       b = static_cast<std::size_t>(static_cast<unsigned>(vs[1].idx())),
                       c = static_cast<std::size_t>(static_cast<unsigned>(vs[2].idx()));
            if (a < nv && b < nv && c < nv && a != b && b != c && a != c) {
                const FH f = m.add_face(vs.data(), vs.size());
                if (!f.is_valid())
                    return fail(errc::non_manifold,
                                "add_face: OpenMesh refused the face (it would make an edge or vertex non-manifold, or "
                                "is wound against a neighbour)");
                return f;
            }
        }
        for (std::size_t i = 0; i < vs.size(); ++i) {
            if (!vs[i].is_valid() || static_cast<std::size_t>(vs[i].idx()) >= m.n_vertices() ||
                (m.has_vertex_status() && m.status(vs[i]).deleted()))
                return fail(errc::invalid_handle,
                            "add_face: corner " + std::to_string(i) + " names vertex " + std::to_string(vs[i].idx()) +
                                ", which does not exist",
                            vs[i].idx());
            for (std::size_t j = 0; j < i; ++j)
                if (vs[j] == vs[i])
                    return fail(errc::degenerate_face,
                                "add_face: vertex " + std::to_string(vs[i].idx()) + " appears twice in the face",
                                vs[i].idx());
        }
        const FH f = m.add_face(vs.data(), vs.size());
        if (!f.is_valid())
            return fail(errc::non_manifold,
                        "add_face: OpenMesh refused the face (it would make an edge or vertex non-manifold, or is "
                        "wound against a neighbour)");
        return f;
    }

    /// Optional (not a concept requirement): reverses every face, as flip_normals does through
    /// the raw mutators, in one pass over the edges (the two halfedges of edge e are 2e and
    /// 2e + 1) with one scratch index per halfedge, where the generic pass keeps three arrays.
    /// Deleted elements (status requested) are left as they are. Complexity O(H_all + V_all).
    static void reverse_orientation(Mesh& m) {
        const std::size_t nh = m.n_halfedges();
        std::vector<HH> old_prev(nh);
        for (std::size_t i = 0; i < nh; ++i) old_prev[i] = m.prev_halfedge_handle(HH(static_cast<int>(i)));
        const bool edge_status = m.has_edge_status();
        for (std::size_t e = 0; e < nh / 2; ++e) {
            const EH edge(static_cast<int>(e));
            if (edge_status && m.status(edge).deleted()) continue;
            const HH a = m.halfedge_handle(edge, 0), b = m.halfedge_handle(edge, 1);
            const VH ta = m.to_vertex_handle(a), tb = m.to_vertex_handle(b);
            m.set_vertex_handle(a, tb);
            m.set_vertex_handle(b, ta);
            // Setting next also sets prev(old_prev) = h, its final value: old next(old_prev) is h.
            m.set_next_halfedge_handle(a, old_prev[static_cast<std::size_t>(a.idx())]);
            m.set_next_halfedge_handle(b, old_prev[static_cast<std::size_t>(b.idx())]);
        }
        const bool vertex_status = m.has_vertex_status();
        for (std::size_t i = 0; i < m.n_vertices(); ++i) {
            const VH v(static_cast<int>(i));
            if (vertex_status && m.status(v).deleted()) continue;
            const HH h = m.halfedge_handle(v);
            if (!h.is_valid()) continue;
            // On the border the halfedge that entered v (old prev, now next) leaves it.
            m.set_halfedge_handle(
                v, m.face_handle(h).is_valid() ? m.opposite_halfedge_handle(h) : m.next_halfedge_handle(h));
        }
    }

    // ----- raw mutation (the layer Euler operators use; keeps nothing consistent) ---------------
    static void set_next(Mesh& m, HH h, HH n) { m.set_next_halfedge_handle(h, n); }
    static void set_target(Mesh& m, HH h, VH v) { m.set_vertex_handle(h, v); }
    static void set_face(Mesh& m, HH h, FH f) { m.set_face_handle(h, f); }
    static void set_vertex_halfedge(Mesh& m, VH v, HH h) { m.set_halfedge_handle(v, h); }
    static void set_face_halfedge(Mesh& m, FH f, HH h) { m.set_halfedge_handle(f, h); }
    static HH new_edge(Mesh& m, VH a, VH b) { return m.new_edge(a, b); }
    static FH new_face(Mesh& m) { return m.new_face(); }
    /// Deletion marks OpenMesh's status bits; the first erase requests the status of that kind
    /// (request_edge_status() and request_halfedge_status(), request_face_status(),
    /// request_vertex_status()), which OpenMesh needs before anything can be deleted.
    static void erase_edge(Mesh& m, EH e) {
        if (!m.has_edge_status()) m.request_edge_status();
        if (!m.has_halfedge_status()) m.request_halfedge_status();
        m.status(e).set_deleted(true);
        m.status(m.halfedge_handle(e, 0)).set_deleted(true);
        m.status(m.halfedge_handle(e, 1)).set_deleted(true);
    }
    static void erase_face(Mesh& m, FH f) {
        if (!m.has_face_status()) m.request_face_status();
        m.status(f).set_deleted(true);
    }
    static void erase_vertex(Mesh& m, VH v) {
        if (!m.has_vertex_status()) m.request_vertex_status();
        m.status(v).set_deleted(true);
    }
    /// Whether the element is marked deleted in OpenMesh's status (false while that status is
    /// not requested: nothing can have been deleted). O(1).
    static bool is_removed(const Mesh& m, VH v) { return m.has_vertex_status() && m.status(v).deleted(); }
    static bool is_removed(const Mesh& m, FH f) { return m.has_face_status() && m.status(f).deleted(); }
    static bool is_removed(const Mesh& m, EH e) { return m.has_edge_status() && m.status(e).deleted(); }
    static bool is_removed(const Mesh& m, HH h) { return m.has_edge_status() && m.status(m.edge_handle(h)).deleted(); }
    /// Requests the status bits erasing needs, so that an edit can erase (or roll back) later
    /// without allocating. Called by the editing functions before their first change.
    static void prepare_erase(Mesh& m) {
        if (!m.has_edge_status()) m.request_edge_status();
        if (!m.has_halfedge_status()) m.request_halfedge_status();
        if (!m.has_face_status()) m.request_face_status();
        if (!m.has_vertex_status()) m.request_vertex_status();
    }

private:
    template <class R>
    static std::size_t count(const R& r) {
        std::size_t n = 0;
        for (auto it = r.begin(); it != r.end(); ++it) ++n;
        return n;
    }
};

}  // namespace openmesh_detail

/// OpenMesh polygon mesh: halfedge navigation, indices, positions, polygon building and raw
/// mutation, all on the user's object. Not change-counted: OpenMesh keeps no counter, and
/// keeping one in a mesh property would cost a name lookup on every raw mutation.
template <class Traits>
struct mesh_traits<OpenMesh::PolyMesh_ArrayKernelT<Traits>>
    : openmesh_detail::traits_base<OpenMesh::PolyMesh_ArrayKernelT<Traits>> {};

/// OpenMesh triangle mesh: as the polygon mesh, but triangles only. add_face refuses other
/// degrees (OpenMesh would silently fan-triangulate them), and `triangles_only` makes the
/// algorithms that create polygons (polygon_mesh_builder) reject it at compile time.
template <class Traits>
struct mesh_traits<OpenMesh::TriMesh_ArrayKernelT<Traits>>
    : openmesh_detail::traits_base<OpenMesh::TriMesh_ArrayKernelT<Traits>> {
    using base = openmesh_detail::traits_base<OpenMesh::TriMesh_ArrayKernelT<Traits>>;
    static constexpr bool triangles_only = true;
    static result<OpenMesh::FaceHandle> add_face(OpenMesh::TriMesh_ArrayKernelT<Traits>& m,
                                                 std::span<const OpenMesh::VertexHandle> vs) {
        if (vs.size() != 3)
            return fail(errc::unsupported, "add_face: a TriMesh holds triangles only, got a face of " +
                                               std::to_string(vs.size()) + " vertices");
        return base::add_face(m, vs);
    }
};

}  // namespace hmira
