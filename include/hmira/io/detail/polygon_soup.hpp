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

#include "../../concepts.hpp"
#include "../../core/result.hpp"
#include "../io_options.hpp"

namespace hmira::io {

/// Positions and faces as plain indexed arrays (faces in CSR form), plus the per-vertex
/// attributes the file had. This is what the parse_* functions return: the fastest way to get
/// a file's content when no mesh is needed.
struct polygon_soup {
    std::vector<std::array<double, 3>> points;   ///< positions, in file order
    std::vector<std::uint32_t> face_offsets{0};  ///< face i is indices[face_offsets[i] .. face_offsets[i+1])
    std::vector<std::uint32_t> indices;          ///< face corners: indices into points
    mesh_attributes attributes;  ///< empty vectors, or one entry per point
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
        if (auto p = mesh.template get_vertex_property<vec3<float>>("v:normal"); p && p->values().size() >= bound && bound > 0)
            s.normals = p->values().data();
        if (auto p = mesh.template get_vertex_property<color4>("v:color"); p && p->values().size() >= bound && bound > 0)
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

/// Builds a fresh mesh from the soup and moves it into `mesh` only if every face was accepted.
/// `face_origin(i)` describes where face i came from, for the error message. Attributes are
/// stored as properties when the mesh has named properties.
/// Complexity: O(V + C) mesh insertions for C face corners.
template <class M, class T = default_traits<M>, class Origin>
    requires readable_mesh<M, T>
result<void> assign_from_soup(M& mesh, const polygon_soup& soup, Origin&& face_origin) {
    using S = typename T::scalar;
    M fresh;
    std::vector<typename T::vertex_handle> vs;
    vs.reserve(soup.points.size());
    for (const auto& p : soup.points)
        vs.push_back(T::add_vertex(fresh, vec3<S>{static_cast<S>(p[0]), static_cast<S>(p[1]), static_cast<S>(p[2])}));
    std::vector<typename T::vertex_handle> corners;
    for (std::size_t f = 0; f < soup.face_count(); ++f) {
        corners.clear();
        for (auto k = soup.face_offsets[f]; k < soup.face_offsets[f + 1]; ++k) corners.push_back(vs[soup.indices[k]]);
        auto added = T::add_face(fresh, std::span<const typename T::vertex_handle>(corners));
        if (!added) {
            auto e = added.error();
            e.message = face_origin(f) + ": face " + std::to_string(f) + " rejected: " + e.message;
            e.element = static_cast<long long>(f);
            return e;
        }
    }
    detail::store_attribute_properties<M, T>(fresh, soup.attributes, vs);
    mesh = std::move(fresh);
    return {};
}

/// Shorthand used by the readers: the soup into the mesh, the attributes into the report.
template <class M, class T = default_traits<M>>
    requires readable_mesh<M, T>
result<read_report> finish_read(M& mesh, polygon_soup&& soup, const std::string& name, std::string format, std::size_t dropped = 0) {
    auto r = assign_from_soup<M, T>(mesh, soup, [&](std::size_t) { return name; });
    if (!r) return r.error();
    read_report report;
    report.format = std::move(format);
    report.attributes = std::move(soup.attributes);
    report.dropped_triangles = dropped;
    return report;
}

}  // namespace hmira::io
