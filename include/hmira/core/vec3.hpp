// hmira/core/vec3.hpp
// The one small vector type the algorithms compute with. Traits convert a mesh's own point
// type (OpenMesh's Vec3f, CGAL's Point_3, std::array) to and from it at their boundary, so
// the algorithms are written once and the conversions inline away.
#pragma once

#include <cmath>
#include <cstddef>

namespace hmira {

/// A 3-component vector of scalar S. Plain aggregate: `vec3<double>{1, 2, 3}`.
template <class S>
struct vec3 {
    /// The components.
    ///@{
    S x{}, y{}, z{};
    ///@}

    /// Component i (0 = x, 1 = y, 2 = z), as OpenMesh and CGAL points allow.
    ///@{
    constexpr S& operator[](std::size_t i) noexcept { return i == 0 ? x : (i == 1 ? y : z); }
    constexpr const S& operator[](std::size_t i) const noexcept { return i == 0 ? x : (i == 1 ? y : z); }

    ///@}

    /// Component-wise arithmetic, and scaling by a scalar.
    ///@{
    constexpr vec3& operator+=(const vec3& o) noexcept {
        x += o.x;
        y += o.y;
        z += o.z;
        return *this;
    }
    constexpr vec3& operator-=(const vec3& o) noexcept {
        x -= o.x;
        y -= o.y;
        z -= o.z;
        return *this;
    }
    constexpr vec3& operator*=(S s) noexcept {
        x *= s;
        y *= s;
        z *= s;
        return *this;
    }
    constexpr vec3& operator/=(S s) noexcept {
        x /= s;
        y /= s;
        z /= s;
        return *this;
    }

    friend constexpr vec3 operator+(vec3 a, const vec3& b) noexcept { return a += b; }
    friend constexpr vec3 operator-(vec3 a, const vec3& b) noexcept { return a -= b; }
    friend constexpr vec3 operator-(const vec3& a) noexcept { return {-a.x, -a.y, -a.z}; }
    friend constexpr vec3 operator*(vec3 a, S s) noexcept { return a *= s; }
    friend constexpr vec3 operator*(S s, vec3 a) noexcept { return a *= s; }
    friend constexpr vec3 operator/(vec3 a, S s) noexcept { return a /= s; }
    friend constexpr bool operator==(const vec3&, const vec3&) = default;
    ///@}
};

/// Dot product.
template <class S>
constexpr S dot(const vec3<S>& a, const vec3<S>& b) noexcept {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

/// Cross product (right-handed).
template <class S>
constexpr vec3<S> cross(const vec3<S>& a, const vec3<S>& b) noexcept {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/// Euclidean length.
template <class S>
S norm(const vec3<S>& a) noexcept {
    using std::sqrt;
    return sqrt(dot(a, a));
}

/// Squared Euclidean length, without the square root.
template <class S>
constexpr S squared_norm(const vec3<S>& a) noexcept {
    return dot(a, a);
}

/// Unit vector along a; the zero vector stays zero rather than becoming NaN.
template <class S>
vec3<S> normalized(const vec3<S>& a) noexcept {
    const S n = norm(a);
    return n > S(0) ? a / n : a;
}

/// Linear interpolation a + (b - a) t.
template <class S>
constexpr vec3<S> lerp(const vec3<S>& a, const vec3<S>& b, S t) noexcept {
    return a + (b - a) * t;
}

}  // namespace hmira
