#include "shadow/occluder_triangles.h"

#include <omp.h>

#include <algorithm>
#include <map>

#include <boost/sort/block_indirect_sort/block_indirect_sort.hpp>

#include "shadow/convex_volume.h"

namespace vlit {

bool is_closed_surface(const std::vector<const ScenePrimitive*>& parts) {
  // The directed edges by corner position, sorted: the surface is closed when no edge repeats and
  // the reversed edges, sorted, are the same list (each edge met by exactly one reversed edge).
  // A corner that is not finite (its triangles are left out of the occluders) leaves a hole.
  struct Directed {
    Vec3d a, b;
  };
  std::vector<Directed> edges;
  for (const ScenePrimitive* prim : parts) {
    const std::size_t n = prim->positions.size();
    edges.reserve(edges.size() + prim->triangles.size());
    for (std::size_t t = 0; t + 2 < prim->triangles.size(); t += 3)
      for (int e = 0; e < 3; ++e) {
        const std::uint32_t a = prim->triangles[t + e], b = prim->triangles[t + (e + 1) % 3];
        if (a >= n || b >= n) return false;
        const Vec3d& pa = prim->positions[a];
        const Vec3d& pb = prim->positions[b];
        if (pa == pb || !is_finite(pa) || !is_finite(pb)) return false;
        edges.push_back({pa, pb});
      }
  }
  if (edges.empty()) return false;
  std::vector<Directed> reversed(edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i) reversed[i] = {edges[i].b, edges[i].a};
  auto less = [](const Directed& p, const Directed& q) {
    return p.a != q.a ? lexicographic_less(p.a, q.a) : lexicographic_less(p.b, q.b);
  };
  auto same = [](const Directed& p, const Directed& q) { return p.a == q.a && p.b == q.b; };
  const auto threads = static_cast<std::uint32_t>(std::max(1, omp_get_max_threads()));
  boost::sort::block_indirect_sort(edges.begin(), edges.end(), less, threads);
  if (std::adjacent_find(edges.begin(), edges.end(), same) != edges.end()) return false;
  boost::sort::block_indirect_sort(reversed.begin(), reversed.end(), less, threads);
  return std::equal(edges.begin(), edges.end(), reversed.begin(), same);
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
