// hmira/algorithms/copy/copy_mesh.hpp
// copy_mesh(src, dst): one mesh model's content into another (as CGAL's copy_face_graph). The
// way to run the algorithms that need a half-edge model (decimate, isotropic_remeshing,
// laplacian_smooth, fill_holes, the subdivisions) on a structure that is only a face list:
// copy it into a halfedge_mesh, run the algorithm, copy the result back.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/result.hpp"
#include "../../core/vec3.hpp"
#include "../../io/detail/polygon_soup.hpp"

namespace hmira {

/// Options of copy_mesh. The maps cost one handle per source index; ask for them when the
/// caller must find its elements again.
struct copy_mesh_options {
    /// Fill copy_mesh_report::vertex_map (needs a destination model with `T::vertices`).
    bool vertex_map = false;
    /// Fill copy_mesh_report::face_map (needs a destination model with `T::faces`).
    bool face_map = false;
    /// Carry the named vertex properties "v:normal" (vec3<float>) and "v:color" (four bytes)
    /// when both models have named properties (hmira's meshes), as the file readers do.
    bool attributes = true;
};

/// What copy_mesh did, and where each source element went in the destination.
template <class MD, class TD = default_traits<MD>>
struct copy_mesh_report {
    std::size_t vertices = 0;  ///< vertices copied (every live source vertex, isolated ones too)
    std::size_t faces = 0;     ///< faces copied
    bool normals = false;      ///< "v:normal" was carried
    bool colors = false;       ///< "v:color" was carried
    /// Source vertex index (TS::vertex_index) -> destination vertex; vertex_index_bound(src)
    /// entries, those of source indices without a live vertex default-constructed. Empty
    /// unless options.vertex_map.
    std::vector<typename TD::vertex_handle> vertex_map;
    /// Source face index (TS::face_index; the position in TS::faces order for a source
    /// model without face indices) -> destination face, with gaps as vertex_map. Empty
    /// unless options.face_map.
    std::vector<typename TD::face_handle> face_map;
};

/// What copy_mesh reads: the vertices with their positions and dense indices, and each face's
/// vertex loop. The weakest concepts that give "iterate vertices with positions, iterate faces
/// with their loops"; the index turns a loop's handles into positions in the copy.
template <class M, class T = default_traits<M>>
concept copy_source_mesh = face_vertex_range_mesh<M, T> && positioned_mesh<M, T> && vertex_index_mesh<M, T>;

/// What copy_mesh writes: a model the file readers can fill (add_vertex, add_face, and an
/// empty one to build into, see io::readable_mesh).
template <class M, class T = default_traits<M>>
concept copy_target_mesh = io::readable_mesh<M, T>;

/// Replaces `dst`'s elements with a copy of `src`'s: every live vertex with its position, and
/// every face as its vertex loop, in the source's `vertices()` and `faces()` order. Any two
/// models may be paired (face-vertex into half-edge and back, hmira's into OpenMesh or CGAL,
/// a user's struct into halfedge_mesh); the build goes through the mechanism the file readers
/// use (io::assign_from_soup), and through a model's one-pass bulk build where it has one
/// (halfedge_mesh's assign_polygons, face_vertex_mesh's assign).
///
/// Carried: positions (converted to the destination's scalar type), the face loops (a face
/// with inner rings is refused: its loop alone would drop them), and with options.attributes
/// the named vertex properties "v:normal" and "v:color" when both models have named
/// properties. Not carried: any other property, face or edge properties, and the models'
/// own attribute mechanisms (OpenMesh's requested normals, CGAL property maps). The
/// destination's own named properties stay, sized to the new elements at their defaults
/// (where the model keeps them over clear_elements).
///
/// \pre `src` and `dst` may be the same object (the copy is taken before `dst` changes).
/// \post on success, `dst` holds exactly the copy: vertex_count and face_count equal the
///       source's, each copied face's loop is the mapped source loop (same winding; the
///       corner it starts at is the model's), and the report's maps say where each source
///       element went. On error `dst` is unchanged and the message names the element: a
///       non-finite source position (errc::invalid_argument, "source vertex 4 ..."), a
///       position the destination's scalar type cannot hold finitely (errc::invalid_argument),
///       a face naming a vertex that is not a live source vertex (errc::invalid_handle), a face
///       with inner rings (errc::unsupported), a face the destination refuses (its add_face's
///       code and reason, e.g. errc::non_manifold for a third face on an edge of a half-edge
///       model, or a quad into a triangles-only model), a map asked of a destination that
///       cannot list its elements (errc::unsupported), or 2^32 vertices or more
///       (errc::unsupported).
/// Complexity: O(V_bound + F + C) to read the source, for C face corners, then O(V + C) calls
/// to the destination's add operations (V add_vertex, F add_face with C corners in all). A
/// model that keeps its object (hmira's meshes, through clear_elements) is built twice, once
/// into a scratch mesh that proves every face is accepted and once into `dst`; halfedge_mesh
/// and face_vertex_mesh build in one validated pass instead (O(V + C x valence) for
/// halfedge_mesh, see from_polygons), falling back to add_face only for a source the bulk build
/// refuses. The maps cost O(V_bound + F_bound) more.
template <class MS, class MD, class TS = default_traits<MS>, class TD = default_traits<MD>>
    requires copy_source_mesh<MS, TS> && copy_target_mesh<MD, TD>
[[nodiscard]] result<copy_mesh_report<MD, TD>> copy_mesh(const MS& src, MD& dst, const copy_mesh_options& options = {});

// ---------------------------------------------------------------------------------------------
// Machinery

namespace detail::copy {

/// The source as a polygon soup, with the source index of each soup vertex and face.
struct source_soup {
    io::polygon_soup soup;
    std::vector<std::size_t> vertex_ids;  ///< soup vertex -> source vertex index
    std::vector<std::size_t> face_ids;    ///< soup face -> source face index (or faces() position)
    std::size_t vertex_bound = 0;         ///< the source's vertex_index_bound
    std::size_t face_bound = 0;           ///< its face_index_bound, or its face count
};

template <class M, class T>
std::size_t face_number(const M& m, typename T::face_handle f, std::size_t ordinal) {
    if constexpr (face_index_mesh<M, T>)
        return static_cast<std::size_t>(T::face_index(m, f));
    else
        return (void)m, (void)f, ordinal;
}

template <class M, class T>
std::string face_name(std::size_t number) {
    if constexpr (face_index_mesh<M, T>)
        return "source face " + std::to_string(number);
    else
        return "source face #" + std::to_string(number) + " (in faces() order)";
}

/// Reads the source into a soup, refusing what no destination could hold. O(V_bound + F + C).
template <class MS, class TS, class SD>
result<source_soup> read_source(const MS& src, bool attributes) {
    constexpr std::uint32_t none = 0xffffffffu;
    source_soup out;
    const std::size_t bound = TS::vertex_index_bound(src);
    out.vertex_bound = bound;
    std::vector<std::uint32_t> soup_index(bound, none);
    out.soup.points.reserve(TS::vertex_count(src));
    out.vertex_ids.reserve(TS::vertex_count(src));
    for (auto v : TS::vertices(src)) {
        const std::size_t i = static_cast<std::size_t>(TS::vertex_index(src, v));
        const vec3<typename TS::scalar> p = TS::position(src, v);
        const std::array<double, 3> q{static_cast<double>(p[0]), static_cast<double>(p[1]), static_cast<double>(p[2])};
        const auto where = [&] {
            return " (" + std::to_string(q[0]) + ", " + std::to_string(q[1]) + ", " + std::to_string(q[2]) + ")";
        };
        if (!std::isfinite(q[0]) || !std::isfinite(q[1]) || !std::isfinite(q[2]))
            return fail(errc::invalid_argument,
                        "copy_mesh: source vertex " + std::to_string(i) + " has a non-finite position" + where(),
                        static_cast<long long>(i));
        const auto fits = [](double c) { return std::isfinite(static_cast<SD>(c)); };
        if (!fits(q[0]) || !fits(q[1]) || !fits(q[2]))
            return fail(errc::invalid_argument,
                        "copy_mesh: source vertex " + std::to_string(i) + "'s position" + where() +
                            " overflows the destination's coordinate type",
                        static_cast<long long>(i));
        if (out.soup.points.size() >= none)
            return fail(errc::unsupported,
                        "copy_mesh: the source has 2^32 vertices or more; at most 2^32 - 1 are supported");
        soup_index[i] = static_cast<std::uint32_t>(out.soup.points.size());
        out.soup.points.push_back(q);
        out.vertex_ids.push_back(i);
    }
    out.soup.face_offsets.reserve(TS::face_count(src) + 1);
    out.face_ids.reserve(TS::face_count(src));
    std::size_t ordinal = 0;
    for (auto f : TS::faces(src)) {
        const std::size_t number = face_number<MS, TS>(src, f, ordinal++);
        if constexpr (inner_ring_mesh<MS, TS>) {
            for (auto r : TS::inner_rings(src, f))
                return (void)r, fail(errc::unsupported,
                                     "copy_mesh: " + face_name<MS, TS>(number) +
                                         " has inner rings, which a vertex loop cannot carry;"
                                         " cut it first with triangulate_faces",
                                     static_cast<long long>(number));
        }
        for (auto v : TS::face_vertices(src, f)) {
            const std::size_t i = static_cast<std::size_t>(TS::vertex_index(src, v));
            if (i >= bound || soup_index[i] == none)
                return fail(errc::invalid_handle,
                            "copy_mesh: " + face_name<MS, TS>(number) + " names vertex " + std::to_string(i) +
                                ", which is not a live vertex of the source",
                            static_cast<long long>(number));
            out.soup.indices.push_back(soup_index[i]);
        }
        out.soup.face_offsets.push_back(out.soup.indices.size());
        out.face_ids.push_back(number);
        if (number >= out.face_bound) out.face_bound = number + 1;
    }
    if constexpr (face_index_mesh<MS, TS>)
        out.face_bound = std::max<std::size_t>(out.face_bound, TS::face_index_bound(src));
    if (attributes) {
        if constexpr (io::detail::has_vertex_properties<MS>) {
            if (auto p = src.template get_vertex_property<vec3<float>>("v:normal"); p && p->values().size() >= bound) {
                out.soup.attributes.normals.reserve(out.vertex_ids.size());
                for (auto i : out.vertex_ids) out.soup.attributes.normals.push_back(p->values()[i]);
            }
            const auto c = src.template get_vertex_property<io::detail::color4>("v:color");
            if (c && c->values().size() >= bound) {
                out.soup.attributes.colors.reserve(out.vertex_ids.size());
                for (auto i : out.vertex_ids) out.soup.attributes.colors.push_back(c->values()[i]);
            }
        }
    }
    return out;
}

/// A refusal from the build, which names the soup's face f as ": face f rejected: why",
/// renamed after the source face it came from.
template <class MS, class TS>
error name_source_face(error e, const source_soup& s) {
    if (e.element < 0 || static_cast<std::size_t>(e.element) >= s.face_ids.size()) {
        e.message = "copy_mesh: the destination refused the copy: " + e.message;
        return e;
    }
    const auto f = static_cast<std::size_t>(e.element);
    const std::string prefix = ": face " + std::to_string(f) + " rejected: ";
    std::string why = e.message;
    if (why.rfind(prefix, 0) == 0) why.erase(0, prefix.size());
    e.element = static_cast<long long>(s.face_ids[f]);
    e.message = "copy_mesh: " + face_name<MS, TS>(s.face_ids[f]) + " refused by the destination: " + why;
    return e;
}

/// The soup into dst, unchanged on error: the one-pass bulk build where the model has it,
/// else (or if it refuses) the readers' add_face path.
template <class MD, class TD>
result<void> build(MD& dst, const io::polygon_soup& soup) {
    auto origin = [](std::size_t) { return std::string(); };
    if constexpr (io::detail::assigns_polygons<MD, TD>) {
        if (dst.assign_polygons(std::span<const std::array<double, 3>>(soup.points),
                                std::span<const std::uint64_t>(soup.face_offsets),
                                std::span<const std::uint32_t>(soup.indices))) {
            std::vector<typename TD::vertex_handle> vs;
            if (!soup.attributes.normals.empty() || !soup.attributes.colors.empty()) {
                vs.reserve(soup.points.size());
                for (std::size_t i = 0; i < soup.points.size(); ++i)
                    vs.push_back(typename TD::vertex_handle(static_cast<std::uint32_t>(i)));
            }
            io::detail::store_attribute_properties<MD, TD>(dst, soup.attributes, vs);
            return {};
        }
        // The bulk build refuses some meshes add_face takes (a vertex joining separate fans).
    }
    return io::assign_from_soup<MD, TD>(dst, soup, origin);
}

}  // namespace detail::copy

template <class MS, class MD, class TS, class TD>
    requires copy_source_mesh<MS, TS> && copy_target_mesh<MD, TD>
result<copy_mesh_report<MD, TD>> copy_mesh(const MS& src, MD& dst, const copy_mesh_options& options) {
    if (options.vertex_map && !vertex_list_mesh<MD, TD>)
        return fail(errc::unsupported,
                    "copy_mesh: a vertex map needs a destination model that lists its vertices (T::vertices)");
    if (options.face_map && !face_list_mesh<MD, TD>)
        return fail(errc::unsupported,
                    "copy_mesh: a face map needs a destination model that lists its faces (T::faces)");
    auto read = detail::copy::read_source<MS, TS, typename TD::scalar>(src, options.attributes);
    if (!read) return read.error();
    const detail::copy::source_soup& s = *read;
    copy_mesh_report<MD, TD> report;
    report.vertices = s.soup.points.size();
    report.faces = s.soup.face_count();
    if (auto built = detail::copy::build<MD, TD>(dst, s.soup); !built)
        return detail::copy::name_source_face<MS, TS>(built.error(), s);
    report.normals = io::detail::has_vertex_properties<MD> && !s.soup.attributes.normals.empty();
    report.colors = io::detail::has_vertex_properties<MD> && !s.soup.attributes.colors.empty();
    // A mesh built from empty lists its elements in creation order: the soup's order.
    if constexpr (vertex_list_mesh<MD, TD>) {
        if (options.vertex_map) {
            report.vertex_map.resize(s.vertex_bound);
            std::size_t k = 0;
            for (auto v : TD::vertices(dst))
                if (k < s.vertex_ids.size()) report.vertex_map[s.vertex_ids[k++]] = v;
        }
    }
    if constexpr (face_list_mesh<MD, TD>) {
        if (options.face_map) {
            report.face_map.resize(s.face_bound);
            std::size_t k = 0;
            for (auto f : TD::faces(dst))
                if (k < s.face_ids.size()) report.face_map[s.face_ids[k++]] = f;
        }
    }
    return report;
}

}  // namespace hmira
