#include "shadow/occluder_triangles.h"

#include <map>
#include <tuple>

namespace vlit {

bool is_closed_surface(const std::vector<const ScenePrimitive*>& parts) {
  using Key = std::tuple<double, double, double, double, double, double>;
  std::map<Key, int> directed;
  for (const ScenePrimitive* prim : parts) {
    const std::size_t n = prim->positions.size();
    for (std::size_t t = 0; t + 2 < prim->triangles.size(); t += 3)
      for (int e = 0; e < 3; ++e) {
        const std::uint32_t a = prim->triangles[t + e], b = prim->triangles[t + (e + 1) % 3];
        if (a >= n || b >= n) return false;
        const Vec3d& pa = prim->positions[a];
        const Vec3d& pb = prim->positions[b];
        if (pa == pb) return false;
        if (++directed[Key{pa.x, pa.y, pa.z, pb.x, pb.y, pb.z}] > 1) return false;
      }
  }
  if (directed.empty()) return false;
  for (const auto& [key, count] : directed) {
    const auto& [ax, ay, az, bx, by, bz] = key;
    const auto it = directed.find(Key{bx, by, bz, ax, ay, az});
    if (it == directed.end() || it->second != 1) return false;
  }
  return true;
}

OccluderTriangles occluders_of(const Scene& scene) {
  OccluderTriangles out;
  // Closedness of each glTF node's mesh instance as a whole (a mesh split into primitives by
  // material is closed only together), else of each primitive alone.
  std::vector<int> solid_of_primitive(scene.primitives.size(), -1);
  auto add_solid = [&](const std::vector<std::size_t>& members) {
    // Culling back faces is safe only for a surface wound outward (positive signed volume,
    // divergence theorem): one wound inward (a room modelled from inside) is entered through the
    // faces that face away from the point, so it is left uncut (no culling).
    Aabb box;
    for (std::size_t p : members)
      for (const Vec3d& v : scene.primitives[p].positions) box.grow(v);
    const Vec3d origin = box.center();
    double six_volume = 0;
    for (std::size_t p : members) {
      const ScenePrimitive& prim = scene.primitives[p];
      for (std::size_t t = 0; t + 2 < prim.triangles.size(); t += 3)
        six_volume += dot(prim.positions[prim.triangles[t]] - origin,
                          cross(prim.positions[prim.triangles[t + 1]] - origin, prim.positions[prim.triangles[t + 2]] - origin));
    }
    if (!(six_volume > 0)) return;
    for (std::size_t p : members) solid_of_primitive[p] = static_cast<int>(out.solid_bounds.size());
    out.solid_bounds.push_back(box);
  };
  std::map<std::pair<int, int>, std::vector<std::size_t>> instances;
  for (std::size_t p = 0; p < scene.primitives.size(); ++p) {
    const ScenePrimitive& prim = scene.primitives[p];
    if (prim.node >= 0) instances[{prim.node, prim.mesh}].push_back(p);
    else if (is_closed_surface({&prim})) add_solid({p});
  }
  for (const auto& [key, members] : instances) {
    std::vector<const ScenePrimitive*> parts;
    for (std::size_t p : members) parts.push_back(&scene.primitives[p]);
    if (is_closed_surface(parts)) add_solid(members);
  }
  for (std::size_t p = 0; p < scene.primitives.size(); ++p) {
    const ScenePrimitive& prim = scene.primitives[p];
    const std::size_t n = prim.positions.size();
    const int solid = solid_of_primitive[p];
    for (std::size_t t = 0; t + 2 < prim.triangles.size(); t += 3) {
      const std::uint32_t a = prim.triangles[t], b = prim.triangles[t + 1], c = prim.triangles[t + 2];
      if (a >= n || b >= n || c >= n) continue;
      const std::array<Vec3d, 3> tri{prim.positions[a], prim.positions[b], prim.positions[c]};
      if (!is_finite(tri[0]) || !is_finite(tri[1]) || !is_finite(tri[2])) continue;
      out.corners.push_back(tri);
      out.ids.push_back({static_cast<std::uint32_t>(p), static_cast<std::uint32_t>(t / 3)});
      out.solid.push_back(solid);
    }
  }
  return out;
}

}  // namespace vlit
