#include "mesh/vertex_normals.h"

#include "core/robust_math.h"

namespace vlit {

std::vector<Vec3d> angle_weighted_normals(const std::vector<Vec3d>& positions,
                                          const std::vector<std::uint32_t>& triangles) {
  std::vector<Vec3d> sum(positions.size());
  for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
    const std::uint32_t idx[3] = {triangles[t], triangles[t + 1], triangles[t + 2]};
    const Vec3d& a = positions[idx[0]];
    const Vec3d& b = positions[idx[1]];
    const Vec3d& c = positions[idx[2]];
    const Vec3d face = normalize(cross(b - a, c - a));
    if (length_squared(face) == 0 || !is_finite(face)) continue;
    const Vec3d corners[3] = {a, b, c};
    for (int k = 0; k < 3; ++k) {
      const Vec3d& p = corners[k];
      const double angle = angle_between(corners[(k + 1) % 3] - p, corners[(k + 2) % 3] - p);
      sum[idx[k]] += face * angle;
    }
  }
  for (Vec3d& n : sum) n = normalize(n);
  return sum;
}

}  // namespace vlit
