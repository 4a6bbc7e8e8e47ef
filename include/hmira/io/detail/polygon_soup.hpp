// hmira/io/detail/polygon_soup.hpp
// Readers parse into a polygon soup first and touch the user's mesh only once the whole file
// is known to be good, so a bad file never leaves a half-filled mesh behind.
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/result.hpp"

namespace hmira::io {

/// Positions and faces as plain indexed arrays (faces in CSR form).
struct polygon_soup {
    std::vector<std::array<double, 3>> points;
    std::vector<std::uint32_t> face_offsets{0};  ///< face i is indices[face_offsets[i] .. face_offsets[i+1])
    std::vector<std::uint32_t> indices;
    std::size_t face_count() const noexcept { return face_offsets.size() - 1; }
};

/// What a reader needs of a mesh: add vertices and faces, and start from an empty mesh.
template <class M, class T = default_traits<M>>
concept readable_mesh = mesh_builder<M, T> && std::default_initializable<M> && std::movable<M>;

/// What a writer needs: faces with vertices, positions, and dense vertex indices.
template <class M, class T = default_traits<M>>
concept writable_mesh = face_vertex_range_mesh<M, T> && positioned_mesh<M, T> && vertex_index_mesh<M, T>;

/// Builds a fresh mesh from the soup and moves it into `mesh` only if every face was accepted.
/// `face_origin(i)` describes where face i came from, for the error message.
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
    mesh = std::move(fresh);
    return {};
}

}  // namespace hmira::io
