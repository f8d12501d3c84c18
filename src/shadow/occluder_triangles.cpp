#include "shadow/occluder_triangles.h"

namespace vlit {

OccluderTriangles occluders_of(const Scene& scene) {
  OccluderTriangles out;
  for (std::size_t p = 0; p < scene.primitives.size(); ++p) {
    const ScenePrimitive& prim = scene.primitives[p];
    const std::size_t n = prim.positions.size();
    for (std::size_t t = 0; t + 2 < prim.triangles.size(); t += 3) {
      const std::uint32_t a = prim.triangles[t], b = prim.triangles[t + 1], c = prim.triangles[t + 2];
      if (a >= n || b >= n || c >= n) continue;
      const std::array<Vec3d, 3> tri{prim.positions[a], prim.positions[b], prim.positions[c]};
      if (!is_finite(tri[0]) || !is_finite(tri[1]) || !is_finite(tri[2])) continue;
      out.corners.push_back(tri);
      out.ids.push_back({static_cast<std::uint32_t>(p), static_cast<std::uint32_t>(t / 3)});
    }
  }
  return out;
}

}  // namespace vlit
