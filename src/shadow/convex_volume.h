// A convex volume given as an axis-aligned box and a list of half-spaces, and the exact-enough
// test "does this triangle reach into it": the triangle clipped by every half-space
// (Sutherland-Hodgman, CACM 1974) keeps at least one point inside the box. The shadow queries
// ask for the triangles that overlap the volume between a vertex and a light (src/shadow/).
#pragma once

#include <array>
#include <vector>

#include "core/vec3.h"

namespace vlit {

struct Aabb {
  Vec3d lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  void grow(const Vec3d& p) { lo = min(lo, p); hi = max(hi, p); }
  void grow(const Aabb& b) { lo = min(lo, b.lo); hi = max(hi, b.hi); }
  bool empty() const { return lo.x > hi.x; }
  bool contains(const Vec3d& p) const {  // boundary included
    return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
  }
  bool overlaps(const Aabb& b) const {
    return lo.x <= b.hi.x && b.lo.x <= hi.x && lo.y <= b.hi.y && b.lo.y <= hi.y && lo.z <= b.hi.z && b.lo.z <= hi.z;
  }
  Vec3d center() const { return (lo + hi) * 0.5; }
};

// Points x with dot(normal, x - origin) >= 0.
struct HalfSpace {
  Vec3d normal;
  Vec3d origin;
  double signed_distance(const Vec3d& x) const { return dot(normal, x - origin); }
};

struct ConvexVolume {
  Aabb box;                         // contains the volume
  std::vector<HalfSpace> planes;    // the volume is box ∩ every half-space
};

// Sutherland-Hodgman against one half-space, on a small polygon (≤ 16 points). The point where
// an edge crosses the plane is computed from the edge's endpoints in a fixed (lexicographic)
// order, so two triangles sharing an edge get bit-identical points: no cracks between them.
struct SmallPolygon {
  int count = 0;
  std::array<Vec3d, 16> p{};
};

inline bool lexicographic_less(const Vec3d& a, const Vec3d& b) {
  if (a.x != b.x) return a.x < b.x;
  if (a.y != b.y) return a.y < b.y;
  return a.z < b.z;
}

inline void clip_small(const SmallPolygon& in, const HalfSpace& h, SmallPolygon& out) {
  out.count = 0;
  for (int i = 0; i < in.count; ++i) {
    const Vec3d& a = in.p[i];
    const Vec3d& b = in.p[(i + 1) % in.count];
    const double sa = h.signed_distance(a), sb = h.signed_distance(b);
    if (sa >= 0 && out.count < 16) out.p[out.count++] = a;
    if ((sa >= 0) != (sb >= 0) && out.count < 16) {
      const bool a_first = lexicographic_less(a, b);
      const Vec3d& x = a_first ? a : b;
      const Vec3d& y = a_first ? b : a;
      const double sx = a_first ? sa : sb, sy = a_first ? sb : sa;
      out.p[out.count++] = x + (y - x) * (sx / (sx - sy));
    }
  }
}

// The part of the triangle inside every half-space of the volume (not the box).
inline SmallPolygon clip_triangle(const std::array<Vec3d, 3>& tri, const std::vector<HalfSpace>& planes) {
  SmallPolygon a, b;
  a.count = 3;
  a.p[0] = tri[0]; a.p[1] = tri[1]; a.p[2] = tri[2];
  for (const HalfSpace& h : planes) {
    clip_small(a, h, b);
    a = b;
    if (a.count == 0) break;
  }
  return a;
}

inline Aabb box_of(const std::array<Vec3d, 3>& tri) {
  Aabb b;
  for (const Vec3d& p : tri) b.grow(p);
  return b;
}

// The triangle reaches into the volume: its box meets the volume's box and its part inside the
// half-spaces is not empty and meets the box.
inline bool triangle_overlaps(const std::array<Vec3d, 3>& tri, const ConvexVolume& volume) {
  if (!box_of(tri).overlaps(volume.box)) return false;
  const SmallPolygon clipped = clip_triangle(tri, volume.planes);
  if (clipped.count == 0) return false;
  Aabb b;
  for (int i = 0; i < clipped.count; ++i) b.grow(clipped.p[i]);
  return b.overlaps(volume.box);
}

}  // namespace vlit
