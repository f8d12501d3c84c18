// Small 3-vector templated on the scalar type, so that every kernel has a float and a double
// instantiation from one source. Plain aggregate: no invariants, trivially copyable, SoA-friendly.
#pragma once

#include <cmath>

namespace vlit {

template <class T>
struct Vec3 {
  T x{}, y{}, z{};

  constexpr Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
  constexpr Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
  constexpr Vec3 operator-() const { return {-x, -y, -z}; }
  constexpr Vec3 operator*(T s) const { return {x * s, y * s, z * s}; }
  constexpr Vec3 operator/(T s) const { return {x / s, y / s, z / s}; }
  constexpr Vec3& operator+=(const Vec3& o) { x += o.x; y += o.y; z += o.z; return *this; }
  constexpr Vec3& operator-=(const Vec3& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
  constexpr Vec3& operator*=(T s) { x *= s; y *= s; z *= s; return *this; }
  constexpr T operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr bool operator==(const Vec3&) const = default;

  template <class U>
  constexpr explicit operator Vec3<U>() const {
    return {static_cast<U>(x), static_cast<U>(y), static_cast<U>(z)};
  }
};

template <class T>
constexpr Vec3<T> operator*(T s, const Vec3<T>& v) { return v * s; }

template <class T>
constexpr T dot(const Vec3<T>& a, const Vec3<T>& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

template <class T>
constexpr Vec3<T> cross(const Vec3<T>& a, const Vec3<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

template <class T>
constexpr T length_squared(const Vec3<T>& v) { return dot(v, v); }

template <class T>
T length(const Vec3<T>& v) { return std::sqrt(dot(v, v)); }

// Unit vector along v; the zero vector maps to the zero vector (callers that cannot accept a
// zero result check the length themselves).
template <class T>
Vec3<T> normalize(const Vec3<T>& v) {
  const T len = length(v);
  return len > T(0) ? v / len : Vec3<T>{};
}

template <class T>
constexpr Vec3<T> hadamard(const Vec3<T>& a, const Vec3<T>& b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }

template <class T>
constexpr Vec3<T> lerp(const Vec3<T>& a, const Vec3<T>& b, T t) { return a + (b - a) * t; }

template <class T>
constexpr Vec3<T> min(const Vec3<T>& a, const Vec3<T>& b) {
  return {a.x < b.x ? a.x : b.x, a.y < b.y ? a.y : b.y, a.z < b.z ? a.z : b.z};
}

template <class T>
constexpr Vec3<T> max(const Vec3<T>& a, const Vec3<T>& b) {
  return {a.x > b.x ? a.x : b.x, a.y > b.y ? a.y : b.y, a.z > b.z ? a.z : b.z};
}

template <class T>
bool is_finite(const Vec3<T>& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

using Vec3f = Vec3<float>;
using Vec3d = Vec3<double>;

}  // namespace vlit
