// hmira/io/detail/polygon_soup.hpp
// Readers parse into a polygon soup first and touch the user's mesh only once the whole file
// is known to be good, so a bad file never leaves a half-filled mesh behind.
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "../../algorithms/repair/repair_polygon_soup.hpp"
#include "../../concepts.hpp"
#include "../../core/result.hpp"
#include "../io_options.hpp"

namespace hmira::io {

/// Positions and faces as plain indexed arrays (faces in CSR form), plus the per-vertex
/// attributes the file had. This is what the parse_* functions return: the fastest way to get
/// a file's content when no mesh is needed. Offsets are 64-bit, so a file with 2^32 corners or
/// more cannot wrap them; vertex indices are 32-bit, and building a mesh from a soup with 2^32
/// points or more is refused.
struct polygon_soup {
    std::vector<std::array<double, 3>> points;   ///< positions, in file order
    std::vector<std::uint64_t> face_offsets{0};  ///< face i is indices[face_offsets[i] .. face_offsets[i+1])
    std::vector<std::uint32_t> indices;          ///< face corners: indices into points
    mesh_attributes attributes;                  ///< empty vectors, or one entry per point
    /// Number of faces.
    std::size_t face_count() const noexcept { return face_offsets.size() - 1; }
};

/// What a reader needs of a mesh: add vertices and faces, and start from an empty mesh.
template <class M, class T = default_traits<M>>
concept readable_mesh = mesh_builder<M, T> && std::default_initializable<M> && std::movable<M>;

/// What a writer needs: faces with vertices, positions, and dense vertex indices.
template <class M, class T = default_traits<M>>
concept writable_mesh = face_vertex_range_mesh<M, T> && positioned_mesh<M, T> && vertex_index_mesh<M, T>;

namespace detail {

using color4 = std::array<std::uint8_t, 4>;

/// Meshes with named vertex properties (hmira's reference meshes and look-alikes).
template <class M>
concept has_vertex_properties = requires(M& m, const M& cm, std::string_view name) {
    m.template add_vertex_property<vec3<float>>(name);
    cm.template get_vertex_property<vec3<float>>(name);
};

/// Stores soup attributes as "v:normal" / "v:color" when the mesh has named properties.
template <class M, class T>
void store_attribute_properties(M& mesh, const mesh_attributes& a, std::span<const typename T::vertex_handle> vs) {
    if constexpr (has_vertex_properties<M>) {
        if (a.normals.size() == vs.size() && !vs.empty()) {
            auto p = mesh.template add_vertex_property<vec3<float>>("v:normal");
            if (p.valid())
                for (std::size_t i = 0; i < vs.size(); ++i) p[vs[i]] = a.normals[i];
        }
        if (a.colors.size() == vs.size() && !vs.empty()) {
            auto p = mesh.template add_vertex_property<color4>("v:color", color4{255, 255, 255, 255});
            if (p.valid())
                for (std::size_t i = 0; i < vs.size(); ++i) p[vs[i]] = a.colors[i];
        }
    } else {
        (void)mesh, (void)a, (void)vs;
    }
}

/// The attributes a writer should emit: the explicit ones, else the mesh's properties, as
/// pointers to per-vertex-index arrays (null when absent).
struct attribute_source {
    const vec3<float>* normals = nullptr;
    const color4* colors = nullptr;
};

template <class M, class T>
attribute_source find_attributes(const M& mesh, const write_options& options) {
    attribute_source s;
    if (!options.write_attributes) return s;
    const std::size_t bound = T::vertex_index_bound(mesh);
    if (options.attributes) {
        if (options.attributes->normals.size() >= bound && bound > 0) s.normals = options.attributes->normals.data();
        if (options.attributes->colors.size() >= bound && bound > 0) s.colors = options.attributes->colors.data();
        return s;
    }
    if constexpr (has_vertex_properties<M>) {
        if (auto p = mesh.template get_vertex_property<vec3<float>>("v:normal");
            p && p->values().size() >= bound && bound > 0)
            s.normals = p->values().data();
        if (auto p = mesh.template get_vertex_property<color4>("v:color");
            p && p->values().size() >= bound && bound > 0)
            s.colors = p->values().data();
    }
    return s;
}

/// Colour channel from a float in [0, 1] (clamped) or a byte.
inline std::uint8_t to_byte(double c) {
    if (!(c > 0)) return 0;
    if (c >= 1) return 255;
    return static_cast<std::uint8_t>(c * 255.0 + 0.5);
}

}  // namespace detail

namespace detail {

/// Empties a mesh that is about to be read into, keeping what the user set up on it where the
/// model allows: hmira's meshes (clear_elements) and OpenMesh (clear) keep their named and
/// requested properties, emptied; Surface_mesh keeps its property maps. Another model is
/// assigned a default-constructed one.
template <class M>
void clear_for_reading(M& mesh) {
    if constexpr (requires { mesh.clear_elements(); })
        mesh.clear_elements();
    else if constexpr (requires { mesh.clear_without_removing_property_maps(); })
        mesh.clear_without_removing_property_maps();
    else if constexpr (requires { mesh.clear(); })
        mesh.clear();
    else
        mesh = M{};
}

/// Adds the soup's vertices and faces to `mesh`; the first refused face's error, named by
/// `face_origin`, or the new vertices.
template <class M, class T, class Origin>
result<std::vector<typename T::vertex_handle>> add_soup(M& mesh, const polygon_soup& soup, Origin& face_origin) {
    using S = typename T::scalar;
    std::vector<typename T::vertex_handle> vs;
    vs.reserve(soup.points.size());
    for (const auto& p : soup.points)
        vs.push_back(T::add_vertex(mesh, vec3<S>{static_cast<S>(p[0]), static_cast<S>(p[1]), static_cast<S>(p[2])}));
    std::vector<typename T::vertex_handle> corners;
    for (std::size_t f = 0; f < soup.face_count(); ++f) {
        corners.clear();
        for (auto k = soup.face_offsets[f]; k < soup.face_offsets[f + 1]; ++k) corners.push_back(vs[soup.indices[k]]);
        auto added = T::add_face(mesh, std::span<const typename T::vertex_handle>(corners));
        if (!added) {
            auto e = added.error();
            e.message = face_origin(f) + ": face " + std::to_string(f) + " rejected: " + e.message;
            e.element = static_cast<long long>(f);
            return e;
        }
    }
    return vs;
}

}  // namespace detail

namespace detail {

/// A model that takes indexed polygons whole, validated in one pass (face_vertex_mesh's
/// assign), under its own traits.
template <class M, class T>
concept takes_indexed_polygons = std::same_as<T, default_traits<M>> &&
                                 requires(M& mesh, const polygon_soup& soup, std::vector<std::size_t> offsets) {
                                     {
                                         mesh.assign(std::span<const std::array<double, 3>>(soup.points),
                                                     std::move(offsets), std::span<const std::uint32_t>(soup.indices))
                                     };
                                 };

/// A model that takes positions, offsets and corners of its own types whole (face_vertex_mesh's
/// by-move assign), under its own traits: a reader can parse straight into its arrays.
template <class M, class T>
concept takes_own_arrays = std::same_as<T, default_traits<M>> &&
                           requires(M& mesh, std::vector<typename M::point> positions, std::vector<std::size_t> offsets,
                                    std::vector<typename T::vertex_handle> corners) {
                               { mesh.assign(std::move(positions), std::move(offsets), std::move(corners)) };
                           };

/// A polygon soup in such a model's own position and corner types, for a parser to fill.
template <class M, class T>
struct mesh_soup {
    std::vector<typename M::point> points;           ///< positions, in file order
    std::vector<std::uint64_t> face_offsets{0};      ///< as polygon_soup::face_offsets
    std::vector<typename T::vertex_handle> indices;  ///< face corners
    mesh_attributes attributes;                      ///< empty vectors, or one entry per point
};

/// The parsed arrays handed to the mesh whole (see takes_own_arrays); on error the mesh is
/// unchanged, and the error names the face as assign_indexed_polygons does.
template <class M, class T>
result<read_report> assign_own_arrays(M& mesh, mesh_soup<M, T>&& soup, const std::string& name, std::string format) {
    read_report report;
    report.file_vertices = soup.points.size();
    report.format = std::move(format);
    if (soup.points.size() > std::size_t{0xffffffffu})
        return fail(errc::unsupported,
                    name + ": " + std::to_string(soup.points.size()) + " vertices; at most 2^32 - 1 are supported");
    std::vector<std::size_t> offsets;
    if constexpr (std::same_as<std::size_t, std::uint64_t>)
        offsets = std::move(soup.face_offsets);
    else
        offsets.assign(soup.face_offsets.begin(), soup.face_offsets.end());
    const std::size_t vertex_count = soup.points.size();
    auto assigned = mesh.assign(std::move(soup.points), std::move(offsets), std::move(soup.indices));
    if (!assigned) {
        auto e = assigned.error();
        const auto f = static_cast<std::size_t>(e.element < 0 ? 0 : e.element);
        e.message = name + ": face " + std::to_string(f) + " rejected: " + e.message;
        return e;
    }
    if (!soup.attributes.normals.empty() || !soup.attributes.colors.empty()) {
        std::vector<typename T::vertex_handle> vs;
        vs.reserve(vertex_count);
        for (std::size_t i = 0; i < vertex_count; ++i)
            vs.push_back(typename T::vertex_handle(static_cast<std::uint32_t>(i)));
        store_attribute_properties<M, T>(mesh, soup.attributes, vs);
    }
    report.attributes = std::move(soup.attributes);
    return report;
}

/// The soup into such a model: unchanged on error, whose face is named by face_origin.
template <class M, class T, class Origin>
result<void> assign_indexed_polygons(M& mesh, const polygon_soup& soup, std::vector<std::size_t>&& offsets,
                                     Origin& face_origin) {
    auto assigned = mesh.assign(std::span<const std::array<double, 3>>(soup.points), std::move(offsets),
                                std::span<const std::uint32_t>(soup.indices));
    if (!assigned) {
        auto e = assigned.error();
        const auto f = static_cast<std::size_t>(e.element < 0 ? 0 : e.element);
        e.message = face_origin(f) + ": face " + std::to_string(f) + " rejected: " + e.message;
        return e;
    }
    if (!soup.attributes.normals.empty() || !soup.attributes.colors.empty()) {
        std::vector<typename T::vertex_handle> vs;
        vs.reserve(soup.points.size());
        for (std::size_t i = 0; i < soup.points.size(); ++i)
            vs.push_back(typename T::vertex_handle(static_cast<std::uint32_t>(i)));
        store_attribute_properties<M, T>(mesh, soup.attributes, vs);
    }
    return {};
}

}  // namespace detail

/// Fills `mesh` from the soup only if every face is accepted; on error the mesh is unchanged.
/// A model that takes indexed polygons whole (face_vertex_mesh's assign, under its own traits)
/// is validated and filled in one pass. Any other model gets the soup built into a fresh mesh
/// of the same type first. A model that can be emptied while keeping its properties (hmira's
/// clear_elements, see detail::clear_for_reading) is then emptied and built again, so the
/// user's object and its named properties stay; any other model is move-assigned the fresh
/// mesh. `face_origin(i)` describes where face i came from, for the error message. Attributes
/// are stored as properties when the mesh has named properties.
/// Complexity: O(V + C) for C face corners: one pass for indexed models, mesh insertions
/// otherwise (twice when the object is kept).
template <class M, class T = default_traits<M>, class Origin>
    requires readable_mesh<M, T>
result<void> assign_from_soup(M& mesh, const polygon_soup& soup, Origin&& face_origin) {
    if constexpr (detail::takes_indexed_polygons<M, T>) {
        return detail::assign_indexed_polygons<M, T>(
            mesh, soup, std::vector<std::size_t>(soup.face_offsets.begin(), soup.face_offsets.end()), face_origin);
    } else {
        M fresh;
        auto vs = detail::add_soup<M, T>(fresh, soup, face_origin);
        if (!vs) return vs.error();
        if constexpr (requires { mesh.clear_elements(); }) {
            fresh = M{};  // free it before building the same again into the user's mesh
            detail::clear_for_reading(mesh);
            // The same faces in the same order into an empty mesh of the same type: accepted again.
            vs = detail::add_soup<M, T>(mesh, soup, face_origin);
            if (!vs) return vs.error();
            detail::store_attribute_properties<M, T>(mesh, soup.attributes, vs.value());
        } else {
            detail::store_attribute_properties<M, T>(fresh, soup.attributes, vs.value());
            mesh = std::move(fresh);
        }
        return {};
    }
}

namespace detail {

/// The first thing a repair changed, as "face 12: <why>", for refusing a file without repair.
inline std::pair<long long, std::string> first_repair(const soup_repair_report& r) {
    auto face = [](const repair_count& c) { return static_cast<long long>(c.first.empty() ? 0 : c.first.front()); };
    if (r.degenerate_faces.count)
        return {face(r.degenerate_faces), "degenerate (fewer than 3 distinct corners, or a repeated vertex)"};
    if (r.merged_corners.count) return {face(r.merged_corners), "repeats a corner"};
    if (r.nonmanifold_edge_faces.count)
        return {face(r.nonmanifold_edge_faces), "is a third face on an edge (non-manifold edge)"};
    if (r.detached_faces.count) return {face(r.detached_faces), "would make an edge non-manifold"};
    if (r.flipped_faces.count) return {face(r.flipped_faces), "is wound against its neighbours"};
    if (r.orientation_cuts) return {-1, "the surface cannot be oriented (Moebius-like)"};
    if (r.split_vertices.count)
        return {-1, "vertex " + std::to_string(r.split_vertices.first.front()) +
                        " is non-manifold (its faces form several fans)"};
    return {-1, ""};
}

}  // namespace detail

namespace detail {

/// A model that builds a whole mesh from indexed polygons, refusing (unchanged) anything its
/// add_face would refuse or that would leave a non-manifold vertex, and that otherwise gives
/// the mesh that emptying it and calling add_face on every face in order gives
/// (halfedge_mesh's assign_polygons).
template <class M, class T>
concept assigns_polygons = std::same_as<T, default_traits<M>> && requires(M& mesh, const polygon_soup& soup) {
    {
        mesh.assign_polygons(std::span<const std::array<double, 3>>(soup.points),
                             std::span<const std::uint64_t>(soup.face_offsets),
                             std::span<const std::uint32_t>(soup.indices))
    } -> std::same_as<result<void>>;
};

/// build_from_soup for a half-edge model through repair_polygon_soup, whatever the soup: the
/// path every file took before the clean-file fast path, and the one a file that needs repair
/// still takes. Kept callable so that tests can compare the two.
template <class M, class T = default_traits<M>>
    requires readable_mesh<M, T> && halfedge_navigable_mesh<M, T>
result<read_report> build_with_repair(M& mesh, polygon_soup&& soup, const std::string& name,
                                      const read_options& options = {}) {
    read_report report;
    report.file_vertices = soup.points.size();
    if (soup.points.size() > std::size_t{0xffffffffu})
        return fail(errc::unsupported,
                    name + ": " + std::to_string(soup.points.size()) + " vertices; at most 2^32 - 1 are supported");
    {
        using VH = typename T::vertex_handle;
        using S = typename T::scalar;
        auto repaired = repair_polygon_soup(soup.points.size(), soup.face_offsets, soup.indices,
                                            {.nonmanifold_edges = options.nonmanifold_edges});
        if (!repaired) {
            auto e = repaired.error();
            e.message = name + ": " + e.message;
            return e;
        }
        if (!options.repair && !repaired->report.clean()) {
            const auto [face, why] = detail::first_repair(repaired->report);
            return fail(errc::non_manifold,
                        name + (face >= 0 ? ": face " + std::to_string(face) + " " : ": ") + why +
                            " (read with repair to fix it)",
                        face);
        }
        if constexpr (triangle_only_mesh<M, T>) {
            for (std::size_t f = 0; f < repaired->face_count(); ++f)
                if (repaired->face_offsets[f + 1] - repaired->face_offsets[f] != 3) {
                    const auto source = repaired->face_source[f];
                    return fail(errc::unsupported,
                                name + ": face " + std::to_string(source) + " has " +
                                    std::to_string(repaired->face_offsets[f + 1] - repaired->face_offsets[f]) +
                                    " corners; this mesh holds triangles only",
                                static_cast<long long>(source));
                }
        }
        // Nothing below can fail: the repaired soup is one every half-edge model holds.
        detail::clear_for_reading(mesh);
        // Room for every element up front (edges: half the corners, plus room for boundaries), so that the build
        // does not reallocate the mesh's arrays as it grows.
        if constexpr (reservable_mesh<M, T>)
            T::reserve(mesh, repaired->vertex_count, repaired->corners.size() / 2 + repaired->vertex_count,
                       repaired->face_count());
        std::vector<VH> vs;
        vs.reserve(repaired->vertex_count);
        for (std::size_t v = 0; v < repaired->vertex_count; ++v) {
            const auto& p = soup.points[repaired->source_vertex(v)];
            vs.push_back(
                T::add_vertex(mesh, vec3<S>{static_cast<S>(p[0]), static_cast<S>(p[1]), static_cast<S>(p[2])}));
        }
        std::vector<VH> corners;
        for (std::size_t f = 0; f < repaired->face_count(); ++f) {
            corners.clear();
            for (auto k = repaired->face_offsets[f]; k < repaired->face_offsets[f + 1]; ++k)
                corners.push_back(vs[repaired->corners[k]]);
            auto added = T::add_face(mesh, std::span<const VH>(corners));
            if (!added) {
                // A bug in the repair, not in the file: leave an empty mesh rather than half of one.
                detail::clear_for_reading(mesh);
                auto e = added.error();
                e.message = name + ": internal error: repaired face " + std::to_string(repaired->face_source[f]) +
                            " rejected: " + e.message;
                e.element = static_cast<long long>(repaired->face_source[f]);
                return e;
            }
        }
        auto extend = [&](auto& values) {
            if (values.size() != soup.points.size()) return;
            for (auto v : repaired->copied_from) values.push_back(values[v]);
        };
        extend(soup.attributes.normals);
        extend(soup.attributes.colors);
        detail::store_attribute_properties<M, T>(mesh, soup.attributes, vs);
        report.attributes = std::move(soup.attributes);
        report.copied_from = std::move(repaired->copied_from);
        if (repaired->face_count() != soup.face_count()) report.face_source = std::move(repaired->face_source);
        report.repair = std::move(repaired->report);
        return report;
    }
}

}  // namespace detail

namespace detail {

/// A polygon soup whose positions are already a model's own points, for a parser to fill and
/// the model to take whole (assign_polygons taking a vector), so the positions are not copied.
template <class P>
struct point_soup {
    std::vector<P> points;                       ///< positions, in file order
    std::vector<std::uint64_t> face_offsets{0};  ///< as polygon_soup::face_offsets
    std::vector<std::uint32_t> indices;          ///< face corners
    mesh_attributes attributes;                  ///< empty vectors, or one entry per point
};

/// A model with assign_polygons that also takes its positions whole, in double precision (so
/// that parsing into its points stores what converting a polygon_soup would).
template <class M, class T>
concept assigns_own_positions =
    assigns_polygons<M, T> && std::same_as<typename T::scalar, double> &&
    requires(M& mesh, std::vector<typename M::point>& points, const std::vector<std::uint64_t>& offsets,
             const std::vector<std::uint32_t>& corners) {
        {
            mesh.assign_polygons(points, std::span<const std::uint64_t>(offsets),
                                 std::span<const std::uint32_t>(corners))
        } -> std::same_as<result<void>>;
    };

/// build_from_soup for such a model and such a soup: a file that needs no repair is built in
/// one pass and keeps its parsed positions; any other goes through build_with_repair exactly
/// as the same file parsed into a polygon_soup would.
template <class M, class T>
    requires assigns_own_positions<M, T> && readable_mesh<M, T> && halfedge_navigable_mesh<M, T>
result<read_report> build_from_point_soup(M& mesh, point_soup<typename M::point>&& soup, const std::string& name,
                                          std::string format, const read_options& options) {
    read_report report;
    report.file_vertices = soup.points.size();
    report.format = std::move(format);
    if (soup.points.size() > std::size_t{0xffffffffu})
        return fail(errc::unsupported,
                    name + ": " + std::to_string(soup.points.size()) + " vertices; at most 2^32 - 1 are supported");
    const std::size_t vertex_count = soup.points.size();
    if (auto built = mesh.assign_polygons(soup.points, std::span<const std::uint64_t>(soup.face_offsets),
                                          std::span<const std::uint32_t>(soup.indices))) {
        std::vector<typename T::vertex_handle> vs;
        if (!soup.attributes.normals.empty() || !soup.attributes.colors.empty()) {
            vs.reserve(vertex_count);
            for (std::size_t i = 0; i < vertex_count; ++i)
                vs.push_back(typename T::vertex_handle(static_cast<std::uint32_t>(i)));
        }
        store_attribute_properties<M, T>(mesh, soup.attributes, vs);
        report.attributes = std::move(soup.attributes);
        return report;
    }
    polygon_soup plain;
    plain.points.reserve(soup.points.size());
    for (const auto& p : soup.points) plain.points.push_back({p[0], p[1], p[2]});
    plain.face_offsets = std::move(soup.face_offsets);
    plain.indices = std::move(soup.indices);
    plain.attributes = std::move(soup.attributes);
    auto repaired = build_with_repair<M, T>(mesh, std::move(plain), name, options);
    if (!repaired) return repaired.error();
    repaired->format = std::move(report.format);
    return repaired;
}

}  // namespace detail

/// Fills `mesh` from a soup that a half-edge model may refuse as it is: the soup is repaired
/// first (repair_polygon_soup, as options say), and only then is the mesh cleared (keeping its
/// properties where the model allows, see detail::clear_for_reading) and filled, so adding a
/// face cannot fail halfway. halfedge_mesh first tries its one-pass build (assign_polygons),
/// which takes exactly the soups the repair would leave unchanged and gives the same mesh and
/// report; only a soup it refuses is repaired. Other models get the soup as it is, through
/// assign_from_soup.
/// Copies of split vertices get the attributes of their file vertex. `name` prefixes errors.
/// \post on success, the mesh's vertex i < soup.points.size() is soup point i and the report
///       says what was repaired and where each created element came from; on error the mesh
///       is unchanged.
/// Complexity: O(C log d + V) for the repair (see repair_polygon_soup) plus O(V + C) mesh
/// insertions; for a soup halfedge_mesh builds in one pass, O(V + C x valence) (see
/// from_polygons), then the repair's cost on top only if that build refuses it.
template <class M, class T = default_traits<M>>
    requires readable_mesh<M, T>
result<read_report> build_from_soup(M& mesh, polygon_soup&& soup, const std::string& name,
                                    const read_options& options = {}) {
    read_report report;
    report.file_vertices = soup.points.size();
    if (soup.points.size() > std::size_t{0xffffffffu})
        return fail(errc::unsupported,
                    name + ": " + std::to_string(soup.points.size()) + " vertices; at most 2^32 - 1 are supported");
    if constexpr (detail::takes_indexed_polygons<M, T>) {
        auto origin = [&](std::size_t) { return name; };
        std::vector<std::size_t> offsets;
        if constexpr (std::same_as<std::size_t, std::uint64_t>)
            offsets = std::move(soup.face_offsets);  // the soup's offsets become the mesh's
        else
            offsets.assign(soup.face_offsets.begin(), soup.face_offsets.end());
        auto r = detail::assign_indexed_polygons<M, T>(mesh, soup, std::move(offsets), origin);
        if (!r) return r.error();
        report.attributes = std::move(soup.attributes);
        return report;
    } else if constexpr (!halfedge_navigable_mesh<M, T>) {
        auto r = assign_from_soup<M, T>(mesh, soup, [&](std::size_t) { return name; });
        if (!r) return r.error();
        report.attributes = std::move(soup.attributes);
        return report;
    } else {
        // A file that needs no repair is built in one pass. The bulk build refuses exactly what
        // makes repair_polygon_soup change something (fewer than 3 or repeated corners, an edge
        // with more than two faces or two running it the same way, a vertex with several fans),
        // and for the rest gives the very mesh the repair path's add_face calls give (and a clean
        // report): tests/io/clean_read_fast_path_test.cpp checks both on random soups.
        if constexpr (detail::assigns_polygons<M, T>) {
            if (auto built = mesh.assign_polygons(std::span<const std::array<double, 3>>(soup.points),
                                                  std::span<const std::uint64_t>(soup.face_offsets),
                                                  std::span<const std::uint32_t>(soup.indices))) {
                std::vector<typename T::vertex_handle> vs;
                if (!soup.attributes.normals.empty() || !soup.attributes.colors.empty()) {
                    vs.reserve(soup.points.size());
                    for (std::size_t i = 0; i < soup.points.size(); ++i)
                        vs.push_back(typename T::vertex_handle(static_cast<std::uint32_t>(i)));
                }
                detail::store_attribute_properties<M, T>(mesh, soup.attributes, vs);
                report.attributes = std::move(soup.attributes);
                return report;
            }
        }
        return detail::build_with_repair<M, T>(mesh, std::move(soup), name, options);
    }
}

/// Shorthand used by the readers: the soup into the mesh (repaired for half-edge models, see
/// build_from_soup), the attributes and repairs into the report.
template <class M, class T = default_traits<M>>
    requires readable_mesh<M, T>
result<read_report> finish_read(M& mesh, polygon_soup&& soup, const std::string& name, std::string format,
                                std::size_t dropped = 0, const read_options& options = {}) {
    auto report = build_from_soup<M, T>(mesh, std::move(soup), name, options);
    if (!report) return report.error();
    report->format = std::move(format);
    report->dropped_triangles = dropped;
    return report;
}

}  // namespace hmira::io
