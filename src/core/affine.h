// Affine transform of points (3x4, row-major), the composition of glTF node transforms, built
// from a translation, a rotation quaternion and a scale (from_trs) or given as a matrix.
// Normals transform by the inverse transpose of the linear part; a negative determinant
// (mirroring, e.g. a negative scale) flips triangle winding.
#pragma once

#include <array>
#include <cmath>

#include "core/vec3.h"

namespace vlit {

struct Affine {
  // m[r][c]: rows are output x, y, z; column 3 is the translation.
  std::array<std::array<double, 4>, 3> m{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};

  Vec3d apply_point(const Vec3d& p) const {
    return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
            m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
            m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
  }
  Vec3d apply_vector(const Vec3d& v) const {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
            m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
  }
  Vec3d column(int c) const { return {m[0][c], m[1][c], m[2][c]}; }

  double determinant() const { return dot(column(0), cross(column(1), column(2))); }

  // Cofactor matrix of the linear part: proportional to the inverse transpose (by det), so it maps
  // normals correctly up to a positive or negative scale; the sign is fixed by det so that
  // normals keep pointing to the same side of the surface.
  Vec3d apply_normal(const Vec3d& n) const {
    const Vec3d c0 = column(0), c1 = column(1), c2 = column(2);
    const Vec3d r0 = cross(c1, c2), r1 = cross(c2, c0), r2 = cross(c0, c1);
    Vec3d out = r0 * n.x + r1 * n.y + r2 * n.z;
    if (determinant() < 0) out = -out;
    return out;
  }

  // T x R x S: translation t, rotation by the quaternion q = (x, y, z, w) (normalised here; the
  // zero quaternion is used as given), scale s along the local axes.
  static Affine from_trs(const Vec3d& t, std::array<double, 4> q, const Vec3d& s) {
    auto& [qx, qy, qz, qw] = q;
    const double len = std::sqrt(qx * qx + qy * qy + qz * qz + qw * qw);
    if (len > 0) { qx /= len; qy /= len; qz /= len; qw /= len; }
    const double rot[3][3] = {
        {1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qz * qw), 2 * (qx * qz + qy * qw)},
        {2 * (qx * qy + qz * qw), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qx * qw)},
        {2 * (qx * qz - qy * qw), 2 * (qy * qz + qx * qw), 1 - 2 * (qx * qx + qy * qy)}};
    const double scale[3] = {s.x, s.y, s.z};
    Affine a;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) a.m[r][c] = rot[r][c] * scale[c];
      a.m[r][3] = t[r];
    }
    return a;
  }

  bool is_finite() const {
    for (const auto& row : m)
      for (double v : row)
        if (!std::isfinite(v)) return false;
    return true;
  }

  Affine operator*(const Affine& b) const {
    Affine r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 4; ++j) {
        double s = (j == 3) ? m[i][3] : 0.0;
        for (int k = 0; k < 3; ++k) s += m[i][k] * b.m[k][j];
        r.m[i][j] = s;
      }
    return r;
  }
};

}  // namespace vlit
