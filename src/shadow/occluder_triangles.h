// The triangles that can hide a light: every triangle of the scene in world space, each with an
// id naming where it came from (scene primitive, triangle index), so results can be traced back
// and compared between the BVH and the brute-force path.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/vec3.h"
#include "shadow/convex_volume.h"
#include "scene/scene.h"

namespace vlit {

struct OccluderId {
  std::uint32_t primitive = 0;  // index into Scene::primitives
  std::uint32_t triangle = 0;   // triangle index within that primitive
};

struct OccluderTriangles {
  std::vector<std::array<Vec3d, 3>> corners;  // world space
  std::vector<OccluderId> ids;                // parallel to corners
  // Parallel to corners (may be empty = none): the index into solid_bounds of the closed,
  // consistently wound surface the triangle belongs to, or -1. Seen from a point outside such a
  // solid, a segment that crosses it enters it through a face that faces the point, so its back
  // faces can be skipped. "Outside" is proved by the solid's box: from a point inside the box
  // (e.g. a floor vertex under an object standing on it) nothing is skipped.
  std::vector<int> solid;
  std::vector<Aabb> solid_bounds;
  std::size_t size() const { return corners.size(); }
};

// Every triangle of every primitive (transforms are already applied in a Scene). Triangles with
// an out-of-range index or a non-finite corner are left out (they hide nothing). A primitive is
// marked closed when every directed edge, by corner position (so split vertices still join),
// is matched by exactly one reversed edge (a non-finite corner or a zero-length side makes it
// open), and wound outward (positive signed volume; a closed
// surface wound inward, such as a room seen from inside, is not culled). The primitives of one
// glTF node's mesh are tested together (a mesh split by material is closed only as a whole).
bool is_closed_surface(const std::vector<const ScenePrimitive*>& parts);
OccluderTriangles occluders_of(const Scene& scene);

// The occluder is a back face of a closed surface seen from a point p outside the surface's
// box: it can be skipped.
// `normal` is the triangle's cross(c1 - c0, c2 - c0).
inline bool culled_back_face(const OccluderTriangles& t, std::uint32_t index, const Vec3d& p, const Vec3d& normal) {
  if (t.solid.empty() || t.solid[index] < 0) return false;
  const Aabb& box = t.solid_bounds[t.solid[index]];
  if (box.contains(p)) return false;
  return dot(normal, p - t.corners[index][0]) < 0;
}

// True if one corner of the triangle is exactly p: a vertex is never shadowed by the triangles
// that contain it, including triangles of other primitives through the same position (split
// normals, seams), so a receiving mesh has no self-shadowing acne at its own vertices.
inline bool touches(const std::array<Vec3d, 3>& tri, const Vec3d& p) {
  return tri[0] == p || tri[1] == p || tri[2] == p;
}

}  // namespace vlit
