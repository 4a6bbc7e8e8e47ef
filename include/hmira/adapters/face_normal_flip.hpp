// hmira/adapters/face_normal_flip.hpp
// Flipping a face of a mesh that stores face normals: the winding is reversed and the stored
// normal negated in the same operation, so the two never disagree. Plugged into adapted_mesh,
// it makes flip_normals (and anything else that reverses faces) keep the normals right.
#pragma once

#include <utility>

#include "../concepts.hpp"
#include "adapted_mesh.hpp"

namespace hmira {

/// Adapter providing `reverse_face(m, f)`: reverses f's winding through the mesh's own
/// reverse_face and negates normals[f]. Normals is anything indexable by face handle that
/// yields an assignable vec3-like value (hmira::property<face_handle, vec3<S>>, a
/// std::vector indexed through a small wrapper, ...); it is held by value, so pass a handle
/// or a reference wrapper, not a copy of the data. Cost O(V_consistF) per face.
/// Precondition: the mesh reverses faces one by one (face_reversible_mesh); halfedge models
/// reverse whole components and are not served by this adapter.
template <class M, class T, class Normals>
    requires face_reversible_mesh<M, T>
class face_normal_flip {
public:
    /// Holds `normals` (moved in); the mesh is not kept.
    face_normal_flip(const M&, Normals normals) : normals_(std::move(normals)) {}

    /// Reverses f's winding with T::reverse_face and negates normals[f]. O(V_consistF).
    void reverse_face(M& m, typename T::face_handle f) {
        T::reverse_face(m, f);
        normals_[f] = -normals_[f];
    }
    /// Does nothing: there is no index to rebuild.
    void refresh(const M&) {}
    /// The held normals. O(1).
    Normals& normals() noexcept { return normals_; }

private:
    Normals normals_;
};

/// A mesh whose reverse_face also negates the stored normal:
/// `auto a = hmira::with_face_normal_flip(mesh, normals); hmira::flip_normals(a);`
template <class Mesh, class T = default_traits<Mesh>, class Normals>
    requires face_reversible_mesh<Mesh, T>
adapted_mesh<Mesh, T, face_normal_flip<Mesh, T, Normals>> with_face_normal_flip(Mesh& mesh, Normals normals) {
    return adapted_mesh<Mesh, T, face_normal_flip<Mesh, T, Normals>>(
        mesh, face_normal_flip<Mesh, T, Normals>(mesh, std::move(normals)));
}

}  // namespace hmira
