// hmira/meshes/face_vertex_mesh.hpp
// The face-vertex mesh of thesis 1.2.1: positions plus, for each face, its ordered vertices,
// and nothing else. It is the cheapest model to build and the one adapters exist for: it has
// no adjacency, so a neighbourhood query costs a scan of all faces (thesis 4.1).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "../concepts.hpp"
#include "../core/huge_pages.hpp"
#include "../core/result.hpp"
#include "../core/vec3.hpp"
#include "../traits.hpp"
#include "detail/element_range.hpp"
#include "detail/native_traits.hpp"
#include "handles.hpp"
#include "properties.hpp"

namespace hmira {

/// Old-to-new index maps reported by garbage collection. An entry is the element's new index,
/// or UINT32_MAX if the element was deleted. A map is empty for a kind the mesh does not have.
struct index_remap {
    ///@{
    /// Old index -> new index, per element kind.
    std::vector<std::uint32_t> vertices, edges, halfedges, faces;
    ///@}
};

/// Indexed polygons (thesis 1.2.1).
///
/// Native costs, in the thesis's terms:
///  - add vertex O(1); add face O(V_consistF), O(V_consistF log V_consistF) above 16 corners
///    (checks handles and repeated vertices);
///  - face -> vertices O(V_consistF), reverse a face O(V_consistF);
///  - remove face O(1) (marked, reclaimed by collect_garbage);
///  - remove vertex O(F_all x V_face): it must scan all faces for the ones that use it;
///  - no adjacency: vertex neighbours, edges and face neighbours come from adapters.
/// Handles stay valid until collect_garbage(), which renumbers and reports the mapping.
/// Concurrency: const queries may run in parallel; any mutation needs exclusive access.
/// Per-vertex and per-face user data by name: add/get/remove_*_property, from
/// with_vertex_properties and with_face_properties (properties.hpp).
template <class Scalar = double>
class basic_face_vertex_mesh : public with_vertex_properties, public with_face_properties {
public:
    using scalar = Scalar;       ///< coordinate type
    using point = vec3<Scalar>;  ///< position type

    /// Live element counts, and index bounds (deleted elements included until collected).
    ///@{
    std::size_t vertex_count() const noexcept { return positions_.size() - deleted_vertices_; }
    std::size_t face_count() const noexcept { return face_begin_.size() - 1 - deleted_faces_; }
    std::size_t vertex_index_bound() const noexcept { return positions_.size(); }
    std::size_t face_index_bound() const noexcept { return face_begin_.size() - 1; }

    ///@}

    /// Ranges over the live elements, in index order. O(1) to make; iterating is O(bound).
    ///@{
    detail::element_range<vertex_handle> vertices() const {
        return {static_cast<std::uint32_t>(positions_.size()), deleted_vertices_ ? vertex_deleted_.data() : nullptr};
    }
    detail::element_range<face_handle> faces() const {
        return {static_cast<std::uint32_t>(face_index_bound()), deleted_faces_ ? face_deleted_.data() : nullptr};
    }

    ///@}

    /// Whether the handle names a live element. O(1).
    ///@{
    bool is_valid(vertex_handle v) const noexcept { return v.index < positions_.size() && !vertex_deleted_[v.index]; }
    bool is_valid(face_handle f) const noexcept { return f.index < face_index_bound() && !face_deleted_[f.index]; }
    ///@}

    // ----- geometry --------------------------------------------------------------------------
    /// Read or move a vertex. O(1).
    ///@{
    const point& position(vertex_handle v) const { return positions_[v.index]; }
    void set_position(vertex_handle v, const point& p) { positions_[v.index] = p; }
    ///@}
    /// Positions indexed by vertex index (deleted vertices included until garbage collection).
    std::span<const point> positions() const noexcept { return positions_; }

    // ----- connectivity ----------------------------------------------------------------------
    /// The face's vertices in winding order: a view into the mesh, valid until the next
    /// add_face, remove or collect_garbage.
    std::span<const vertex_handle> face_vertices(face_handle f) const {
        return {corners_.data() + face_begin_[f.index], corners_.data() + face_begin_[f.index + 1]};
    }

    // ----- mutation --------------------------------------------------------------------------
    /// Adds an isolated vertex at p. O(1).
    vertex_handle add_vertex(const point& p) {
        positions_.push_back(p);
        vertex_deleted_.push_back(0);
        vertex_props_.push_back();
        ++changes_;
        return vertex_handle(positions_.size() - 1);
    }

    /// Adds a polygon. Fails, leaving the mesh unchanged, on fewer than 3 vertices, an invalid
    /// or deleted vertex, a vertex repeated within the face, or a face count that face
    /// handles cannot number. O(k) for k <= 16 corners, O(k log k) above (repeats are found
    /// by sorting a copy).
    result<face_handle> add_face(std::span<const vertex_handle> vs) {
        if (auto problem = face_problem(vs, [&](vertex_handle v) { return is_valid(v); })) {
            problem->message = "add_face: " + problem->message;
            return *problem;
        }
        if (face_index_bound() >= UINT32_MAX - 1)
            return fail(errc::invalid_argument,
                        "add_face: the mesh already holds the most faces a 32-bit face handle can name");
        corners_.insert(corners_.end(), vs.begin(), vs.end());
        face_begin_.push_back(corners_.size());
        face_deleted_.push_back(0);
        face_props_.push_back();
        ++changes_;
        return face_handle(face_index_bound() - 1);
    }
    /// add_face() for a braced list of vertices.
    result<face_handle> add_face(std::initializer_list<vertex_handle> vs) {
        return add_face(std::span<const vertex_handle>(vs.begin(), vs.size()));
    }

    /// Replaces every element by indexed polygons, as reading a file does: vertex i at
    /// points[i] (any type with p[0], p[1], p[2]), face f with the corners
    /// corner_indices[face_offsets[f] .. face_offsets[f + 1]). One validation pass over the
    /// corners and no allocation per face, where add_face would cost a call per face; the
    /// offsets are taken by move. Named properties are kept, sized to the new counts with
    /// their defaults. Fails, leaving the mesh unchanged, on the first face that add_face would
    /// refuse, or on offsets that do not describe the corners; the error's element is the face.
    /// Invalidates all handles.
    /// Complexity: O(V + C) for C corners (O(k log k) for a face of k > 16 corners).
    template <class Point>
    result<void> assign(std::span<const Point> points, std::vector<std::size_t>&& face_offsets,
                        std::span<const std::uint32_t> corner_indices) {
        // Filled by push_back into reserved room, not sized up front: zeroing the arrays first
        // would write every fresh page twice.
        std::vector<vertex_handle> corners;
        detail::reserve_huge(corners, corner_indices.size());
        for (const auto i : corner_indices) corners.push_back(vertex_handle(i));
        std::vector<point> positions;
        detail::reserve_huge(positions, points.size());
        for (const auto& p : points)
            positions.push_back(point{static_cast<Scalar>(p[0]), static_cast<Scalar>(p[1]), static_cast<Scalar>(p[2])});
        return assign(std::move(positions), std::move(face_offsets), std::move(corners));
    }

    /// assign() from arrays the mesh takes over whole (a reader that parsed straight into the
    /// mesh's types): vertex i at positions[i], face f with the corners
    /// corners[face_offsets[f] .. face_offsets[f + 1]). Nothing is copied. Same checks, errors
    /// and effects as the indexed overload; on an error the mesh and the three arrays are
    /// unchanged.
    /// Complexity: O(V + C) for C corners (O(k log k) for a face of k > 16 corners).
    result<void> assign(std::vector<point>&& positions, std::vector<std::size_t>&& face_offsets,
                        std::vector<vertex_handle>&& corners) {
        if (auto problem = polygons_problem(positions.size(), face_offsets, corners)) return *problem;
        // Nothing below can fail (short of memory): the mesh changes only now.
        const auto vertex_count = positions.size(), faces = face_offsets.size() - 1;
        positions_ = std::move(positions);
        vertex_deleted_.assign(vertex_count, 0);
        corners_ = std::move(corners);
        face_begin_ = std::move(face_offsets);
        face_deleted_.assign(faces, 0);
        vertex_props_.resize(0);
        vertex_props_.resize(vertex_count);
        face_props_.resize(0);
        face_props_.resize(faces);
        deleted_vertices_ = deleted_faces_ = 0;
        ++changes_;
        return {};
    }

    /// Reverses the winding of one face, O(V_consistF).
    void reverse_face(face_handle f) {
        std::reverse(corners_.begin() + face_begin_[f.index], corners_.begin() + face_begin_[f.index + 1]);
        ++changes_;
    }

    /// Removes a face; its vertices stay. O(1).
    result<void> remove_face(face_handle f) {
        if (!is_valid(f))
            return fail(errc::invalid_handle, "remove_face: face " + std::to_string(f.index) + " does not exist",
                        f.index);
        face_deleted_[f.index] = 1;
        ++deleted_faces_;
        ++changes_;
        return {};
    }

    /// Removes a vertex and every face that uses it. O(F_all x V_face): this model keeps no
    /// vertex -> face links.
    result<void> remove_vertex(vertex_handle v) {
        if (!is_valid(v))
            return fail(errc::invalid_handle, "remove_vertex: vertex " + std::to_string(v.index) + " does not exist",
                        v.index);
        for (auto f : faces()) {
            auto fv = face_vertices(f);
            if (std::find(fv.begin(), fv.end(), v) != fv.end()) {
                face_deleted_[f.index] = 1;
                ++deleted_faces_;
            }
        }
        vertex_deleted_[v.index] = 1;
        ++deleted_vertices_;
        ++changes_;
        return {};
    }

    /// Removes several vertices and every face that uses any of them, in one pass over the
    /// faces: O(F_all x V_face + k) for k vertices, where k calls of remove_vertex cost k times
    /// that. Fails, with the mesh unchanged, if a vertex does not exist or is named twice.
    result<void> remove_vertices(std::span<const vertex_handle> vs) {
        for (std::size_t i = 0; i < vs.size(); ++i) {
            if (!is_valid(vs[i])) {  // marking as we go makes a repeat look deleted too
                for (std::size_t k = 0; k < i; ++k) vertex_deleted_[vs[k].index] = 0;
                return fail(
                    errc::invalid_handle,
                    "remove_vertices: vertex " + std::to_string(vs[i].index) + " does not exist or is named twice",
                    vs[i].index);
            }
            vertex_deleted_[vs[i].index] = 1;
        }
        for (std::size_t f = 0; f < face_index_bound(); ++f) {
            if (face_deleted_[f]) continue;
            for (std::size_t c = face_begin_[f]; c < face_begin_[f + 1]; ++c)
                if (vertex_deleted_[corners_[c].index]) {
                    face_deleted_[f] = 1;
                    ++deleted_faces_;
                    break;
                }
        }
        deleted_vertices_ += vs.size();
        ++changes_;
        return {};
    }

    /// Whether deleted elements wait for collect_garbage().
    bool has_garbage() const noexcept { return deleted_vertices_ + deleted_faces_ > 0; }

    /// Drops deleted elements and renumbers the rest in their old order; properties follow.
    /// Returns the old -> new index maps. Invalidates all handles and views.
    index_remap collect_garbage() {
        index_remap map;
        map.vertices.assign(positions_.size(), UINT32_MAX);
        std::uint32_t nv = 0;
        for (std::size_t i = 0; i < positions_.size(); ++i)
            if (!vertex_deleted_[i]) {
                map.vertices[i] = nv;
                positions_[nv++] = positions_[i];
            }
        positions_.resize(nv);
        vertex_deleted_.assign(nv, 0);
        map.faces.assign(face_index_bound(), UINT32_MAX);
        std::vector<vertex_handle> corners;
        std::vector<std::size_t> begin{0};
        std::uint32_t nf = 0;
        for (std::size_t f = 0; f + 1 < face_begin_.size(); ++f) {
            if (face_deleted_[f]) continue;
            map.faces[f] = nf++;
            for (auto k = face_begin_[f]; k < face_begin_[f + 1]; ++k)
                corners.push_back(vertex_handle(map.vertices[corners_[k].index]));
            begin.push_back(corners.size());
        }
        corners_ = std::move(corners);
        face_begin_ = std::move(begin);
        face_deleted_.assign(nf, 0);
        vertex_props_.compact(map.vertices, nv);
        face_props_.compact(map.faces, nf);
        deleted_vertices_ = deleted_faces_ = 0;
        ++changes_;
        return map;
    }

    /// Reserves storage for that many vertices, faces and face corners.
    void reserve(std::size_t vertices, std::size_t faces, std::size_t corners) {
        detail::reserve_huge(positions_, vertices);
        vertex_deleted_.reserve(vertices);
        detail::reserve_huge(face_begin_, faces + 1);
        face_deleted_.reserve(faces);
        detail::reserve_huge(corners_, corners);
    }

    /// Removes everything, properties included.
    void clear() { *this = basic_face_vertex_mesh(); }
    /// Removes every element and keeps the named properties (emptied, their defaults kept), as
    /// OpenMesh's clear() does: what reading a file into a mesh uses. The change count keeps
    /// growing, so an index built before sees that it is stale. Invalidates all handles. O(1)
    /// besides freeing the storage.
    void clear_elements() {
        auto vertex_props = std::move(vertex_props_);
        auto face_props = std::move(face_props_);
        const auto changes = changes_;
        *this = basic_face_vertex_mesh();
        vertex_props_ = std::move(vertex_props);
        vertex_props_.resize(0);
        face_props_ = std::move(face_props);
        face_props_.resize(0);
        changes_ = changes + 1;
    }

    /// Grows on every change of connectivity or of the element set.
    std::uint64_t change_count() const noexcept { return changes_; }

private:
    // Why assign() refuses these polygons: offsets that do not describe the corners, too many
    // elements for 32-bit handles, or the first face add_face would refuse (the error's element).
    static std::optional<error> polygons_problem(std::size_t vertex_count, std::span<const std::size_t> face_offsets,
                                                 std::span<const vertex_handle> corners) {
        if (face_offsets.empty() || face_offsets.front() != 0 || face_offsets.back() != corners.size())
            return error{errc::invalid_argument,
                         "assign: the face offsets must start at 0 and end at the corner count " +
                             std::to_string(corners.size())};
        const std::size_t faces = face_offsets.size() - 1;
        if (faces >= UINT32_MAX - 1 || vertex_count >= UINT32_MAX)
            return error{errc::invalid_argument, "assign: " + std::to_string(vertex_count) + " vertices and " +
                                                     std::to_string(faces) +
                                                     " faces; 32-bit handles name fewer than 2^32 - 1 of each"};
        auto exists = [&](vertex_handle v) { return v.index < vertex_count; };
        for (std::size_t f = 0; f < faces; ++f) {
            const auto begin = face_offsets[f], end = face_offsets[f + 1];
            if (end < begin || end > corners.size())
                return error{errc::invalid_argument,
                             "assign: face " + std::to_string(f) + ": its offsets " + std::to_string(begin) + ".." +
                                 std::to_string(end) + " are out of order",
                             static_cast<long long>(f)};
            if (end - begin == 3) {
                // Triangles, the common case, checked inline; a refused one takes the general
                // path below for its message.
                const auto a = corners[begin].index, b = corners[begin + 1].index, c = corners[begin + 2].index;
                if (a < vertex_count && b < vertex_count && c < vertex_count && a != b && b != c && a != c) continue;
            }
            if (auto problem = face_problem(corners.subspan(begin, end - begin), exists)) {
                problem->element = static_cast<long long>(f);
                return problem;
            }
        }
        return std::nullopt;
    }

    // Why a face with these corners cannot be added (fewer than 3, a vertex that does not
    // exist, a repeat), or nothing. The error's element is the vertex concerned.
    template <class Exists>
    static std::optional<error> face_problem(std::span<const vertex_handle> vs, Exists&& exists) {
        if (vs.size() < 3)
            return error{errc::degenerate_face, "a face needs at least 3 vertices, got " + std::to_string(vs.size())};
        for (std::size_t i = 0; i < vs.size(); ++i)
            if (!exists(vs[i]))
                return error{errc::invalid_handle,
                             "corner " + std::to_string(i) + " names vertex " +
                                 std::to_string(static_cast<long long>(vs[i].index)) + ", which does not exist",
                             static_cast<long long>(vs[i].index)};
        if (auto repeated = find_repeated(vs))
            return error{errc::degenerate_face, "vertex " + std::to_string(*repeated) + " appears twice in the face",
                         *repeated};
        return std::nullopt;
    }

    // The index of a vertex listed twice in vs, if any: pairwise for short faces (no
    // allocation), by sorting a copy for long ones, so a 400k-gon costs O(k log k), not O(k^2).
    static std::optional<std::uint32_t> find_repeated(std::span<const vertex_handle> vs) {
        if (vs.size() <= 16) {
            for (std::size_t i = 1; i < vs.size(); ++i)
                for (std::size_t j = 0; j < i; ++j)
                    if (vs[j] == vs[i]) return vs[i].index;
            return std::nullopt;
        }
        std::vector<std::uint32_t> sorted(vs.size());
        for (std::size_t i = 0; i < vs.size(); ++i) sorted[i] = vs[i].index;
        std::sort(sorted.begin(), sorted.end());
        const auto at = std::adjacent_find(sorted.begin(), sorted.end());
        if (at != sorted.end()) return *at;
        return std::nullopt;
    }

    std::vector<point> positions_;
    std::vector<std::uint8_t> vertex_deleted_;
    std::vector<vertex_handle> corners_;
    std::vector<std::size_t> face_begin_{0};  // corner offsets: 64-bit, so 2^32 corners do not wrap
    std::vector<std::uint8_t> face_deleted_;
    std::size_t deleted_vertices_ = 0, deleted_faces_ = 0;
    std::uint64_t changes_ = 0;
};

using face_vertex_mesh = basic_face_vertex_mesh<double>;

/// Native traits: everything face-vertex can do at its thesis cost, nothing more.
template <class Scalar>
struct mesh_traits<basic_face_vertex_mesh<Scalar>> : detail::native_element_traits<basic_face_vertex_mesh<Scalar>> {
    using mesh = basic_face_vertex_mesh<Scalar>;

    static void reverse_face(mesh& m, face_handle f) { m.reverse_face(f); }
    static result<void> remove_face(mesh& m, face_handle f) { return m.remove_face(f); }
    static result<void> remove_vertex(mesh& m, vertex_handle v) { return m.remove_vertex(v); }
    static result<void> remove_vertices(mesh& m, std::span<const vertex_handle> vs) { return m.remove_vertices(vs); }
    /// Whether the element was removed (optional traits query: operators refuse such handles
    /// with errc::invalid_handle). Meaningful for an index below the bound. O(1).
    static bool is_removed(const mesh& m, vertex_handle v) { return !m.is_valid(v); }
    static bool is_removed(const mesh& m, face_handle f) { return !m.is_valid(f); }
};

}  // namespace hmira
