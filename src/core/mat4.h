// 4x4 matrices and homogeneous 4-vectors for cameras and transforms, templated on the scalar type
// (Mat4d is what the rasterizer uses; Mat4f exists for callers that want it).
//
// Conventions (written once here, used everywhere):
// - Column vectors: p' = M * p. Matrices compose right to left: clip_from_world =
//   clip_from_camera * camera_from_world. Names follow destination_from_source.
// - Storage is row-major: m[row][col]. glTF stores matrices column-major; use
//   Mat4<T>::from_column_major() on a glTF `matrix` array.
// - Cameras follow glTF 2.0: the camera looks down its local -Z with +Y up; the projection
//   matrices below are the ones printed in the glTF 2.0 specification (section 3.10.3,
//   "Projection Matrices"), mapping the view volume to the OpenGL clip cube -w <= x,y,z <= w.
#pragma once

#include <array>
#include <cmath>
#include <optional>

#include "core/vec3.h"

namespace vlit {

template <class T>
struct Vec4 {
  T x{}, y{}, z{}, w{};

  constexpr T operator[](int i) const { return i == 0 ? x : (i == 1 ? y : (i == 2 ? z : w)); }
  constexpr Vec4 operator+(const Vec4& o) const { return {x + o.x, y + o.y, z + o.z, w + o.w}; }
  constexpr Vec4 operator-(const Vec4& o) const { return {x - o.x, y - o.y, z - o.z, w - o.w}; }
  constexpr Vec4 operator*(T s) const { return {x * s, y * s, z * s, w * s}; }
  constexpr bool operator==(const Vec4&) const = default;
  constexpr Vec3<T> xyz() const { return {x, y, z}; }
};

template <class T>
constexpr T dot(const Vec4<T>& a, const Vec4<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w;
}

template <class T>
bool is_finite(const Vec4<T>& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

template <class T>
struct Mat4 {
  std::array<std::array<T, 4>, 4> m{};  // m[row][col]

  static constexpr Mat4 identity() {
    Mat4 r;
    for (int i = 0; i < 4; ++i) r.m[i][i] = T(1);
    return r;
  }
  // From 16 values in column-major order (glTF node.matrix, camera arrays).
  static constexpr Mat4 from_column_major(const T* a) {
    Mat4 r;
    for (int col = 0; col < 4; ++col)
      for (int row = 0; row < 4; ++row) r.m[row][col] = a[col * 4 + row];
    return r;
  }
  static constexpr Mat4 translation(const Vec3<T>& t) {
    Mat4 r = identity();
    r.m[0][3] = t.x;
    r.m[1][3] = t.y;
    r.m[2][3] = t.z;
    return r;
  }
  static constexpr Mat4 scale(const Vec3<T>& s) {
    Mat4 r;
    r.m[0][0] = s.x;
    r.m[1][1] = s.y;
    r.m[2][2] = s.z;
    r.m[3][3] = T(1);
    return r;
  }

  constexpr Mat4 operator*(const Mat4& o) const {
    Mat4 r;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        T s{};
        for (int k = 0; k < 4; ++k) s += m[i][k] * o.m[k][j];
        r.m[i][j] = s;
      }
    return r;
  }
  constexpr Vec4<T> operator*(const Vec4<T>& v) const {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z + m[0][3] * v.w,
            m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z + m[1][3] * v.w,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z + m[2][3] * v.w,
            m[3][0] * v.x + m[3][1] * v.y + m[3][2] * v.z + m[3][3] * v.w};
  }
  constexpr bool operator==(const Mat4&) const = default;

  template <class U>
  constexpr explicit operator Mat4<U>() const {
    Mat4<U> r;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) r.m[i][j] = static_cast<U>(m[i][j]);
    return r;
  }
};

// Homogeneous image of the point p (w = 1).
template <class T>
constexpr Vec4<T> transform_point_h(const Mat4<T>& a, const Vec3<T>& p) {
  return a * Vec4<T>{p.x, p.y, p.z, T(1)};
}

// Affine image of the point p, divided by w (the caller guarantees w != 0).
template <class T>
constexpr Vec3<T> transform_point(const Mat4<T>& a, const Vec3<T>& p) {
  const Vec4<T> h = transform_point_h(a, p);
  return Vec3<T>{h.x, h.y, h.z} / h.w;
}

// Image of the direction v (w = 0: translation ignored).
template <class T>
constexpr Vec3<T> transform_vector(const Mat4<T>& a, const Vec3<T>& v) {
  const Vec4<T> h = a * Vec4<T>{v.x, v.y, v.z, T(0)};
  return {h.x, h.y, h.z};
}

template <class T>
constexpr Mat4<T> transpose(const Mat4<T>& a) {
  Mat4<T> r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r.m[i][j] = a.m[j][i];
  return r;
}

// Inverse by cofactors (Laplace expansion over 2x2 minors of the top and bottom row pairs).
// Returns nullopt when the determinant is zero or not finite. No pivoting: relative error grows
// with the condition number, which is fine for camera and node transforms.
template <class T>
std::optional<Mat4<T>> inverse(const Mat4<T>& a) {
  const auto& m = a.m;
  // 2x2 minors of rows 0,1 (s) and rows 2,3 (c), columns (i,j).
  const T s0 = m[0][0] * m[1][1] - m[1][0] * m[0][1];
  const T s1 = m[0][0] * m[1][2] - m[1][0] * m[0][2];
  const T s2 = m[0][0] * m[1][3] - m[1][0] * m[0][3];
  const T s3 = m[0][1] * m[1][2] - m[1][1] * m[0][2];
  const T s4 = m[0][1] * m[1][3] - m[1][1] * m[0][3];
  const T s5 = m[0][2] * m[1][3] - m[1][2] * m[0][3];
  const T c5 = m[2][2] * m[3][3] - m[3][2] * m[2][3];
  const T c4 = m[2][1] * m[3][3] - m[3][1] * m[2][3];
  const T c3 = m[2][1] * m[3][2] - m[3][1] * m[2][2];
  const T c2 = m[2][0] * m[3][3] - m[3][0] * m[2][3];
  const T c1 = m[2][0] * m[3][2] - m[3][0] * m[2][2];
  const T c0 = m[2][0] * m[3][1] - m[3][0] * m[2][1];
  const T det = s0 * c5 - s1 * c4 + s2 * c3 + s3 * c2 - s4 * c1 + s5 * c0;
  if (det == T(0) || !std::isfinite(det)) return std::nullopt;
  const T k = T(1) / det;
  Mat4<T> r;
  auto& o = r.m;
  o[0][0] = (m[1][1] * c5 - m[1][2] * c4 + m[1][3] * c3) * k;
  o[0][1] = (-m[0][1] * c5 + m[0][2] * c4 - m[0][3] * c3) * k;
  o[0][2] = (m[3][1] * s5 - m[3][2] * s4 + m[3][3] * s3) * k;
  o[0][3] = (-m[2][1] * s5 + m[2][2] * s4 - m[2][3] * s3) * k;
  o[1][0] = (-m[1][0] * c5 + m[1][2] * c2 - m[1][3] * c1) * k;
  o[1][1] = (m[0][0] * c5 - m[0][2] * c2 + m[0][3] * c1) * k;
  o[1][2] = (-m[3][0] * s5 + m[3][2] * s2 - m[3][3] * s1) * k;
  o[1][3] = (m[2][0] * s5 - m[2][2] * s2 + m[2][3] * s1) * k;
  o[2][0] = (m[1][0] * c4 - m[1][1] * c2 + m[1][3] * c0) * k;
  o[2][1] = (-m[0][0] * c4 + m[0][1] * c2 - m[0][3] * c0) * k;
  o[2][2] = (m[3][0] * s4 - m[3][1] * s2 + m[3][3] * s0) * k;
  o[2][3] = (-m[2][0] * s4 + m[2][1] * s2 - m[2][3] * s0) * k;
  o[3][0] = (-m[1][0] * c3 + m[1][1] * c1 - m[1][2] * c0) * k;
  o[3][1] = (m[0][0] * c3 - m[0][1] * c1 + m[0][2] * c0) * k;
  o[3][2] = (-m[3][0] * s3 + m[3][1] * s1 - m[3][2] * s0) * k;
  o[3][3] = (m[2][0] * s3 - m[2][1] * s1 + m[2][2] * s0) * k;
  for (const auto& row : o)
    for (T v : row)
      if (!std::isfinite(v)) return std::nullopt;
  return r;
}

// glTF 2.0 perspective projection (clip_from_camera). aspect = width / height, yfov in radians,
// 0 < znear < zfar. Without zfar, the infinite projection of the spec: z_clip = -z_cam - 2 znear,
// so z_ndc -> 1 as the distance grows and there is no far plane.
template <class T>
Mat4<T> perspective_gltf(T aspect, T yfov, T znear, std::optional<T> zfar) {
  const T f = T(1) / std::tan(T(0.5) * yfov);
  Mat4<T> r;
  r.m[0][0] = f / aspect;
  r.m[1][1] = f;
  r.m[3][2] = T(-1);
  if (zfar) {
    r.m[2][2] = (*zfar + znear) / (znear - *zfar);
    r.m[2][3] = T(2) * *zfar * znear / (znear - *zfar);
  } else {
    r.m[2][2] = T(-1);
    r.m[2][3] = T(-2) * znear;
  }
  return r;
}

// glTF 2.0 orthographic projection (clip_from_camera): xmag, ymag are half extents, zfar > znear.
template <class T>
Mat4<T> orthographic_gltf(T xmag, T ymag, T znear, T zfar) {
  Mat4<T> r;
  r.m[0][0] = T(1) / xmag;
  r.m[1][1] = T(1) / ymag;
  r.m[2][2] = T(2) / (znear - zfar);
  r.m[2][3] = (zfar + znear) / (znear - zfar);
  r.m[3][3] = T(1);
  return r;
}

// world_from_camera for a camera at `eye` looking at `target` (glTF convention: the camera's
// -Z points at the target, +Y is as close to `up` as possible). Rigid: its inverse is cheap and
// exact up to rounding. Precondition: eye != target and (target - eye) not parallel to up.
template <class T>
Mat4<T> look_at(const Vec3<T>& eye, const Vec3<T>& target, const Vec3<T>& up) {
  const Vec3<T> back = normalize(eye - target);        // camera +Z
  const Vec3<T> right = normalize(cross(up, back));    // camera +X
  const Vec3<T> true_up = cross(back, right);          // camera +Y
  Mat4<T> r = Mat4<T>::identity();
  const Vec3<T> cols[4] = {right, true_up, back, eye};
  for (int c = 0; c < 4; ++c) {
    r.m[0][c] = cols[c].x;
    r.m[1][c] = cols[c].y;
    r.m[2][c] = cols[c].z;
  }
  return r;
}

using Vec4f = Vec4<float>;
using Vec4d = Vec4<double>;
using Mat4f = Mat4<float>;
using Mat4d = Mat4<double>;

}  // namespace vlit
