// Small builders shared by the shadow tests.
#pragma once

#include <vector>

#include "shading/prepared_light.h"
#include "shadow/occluder_bvh.h"
#include "shadow/shadowed_light.h"
#include "shadow_reference.h"
#include "support/light_sources.h"

namespace vlit::test {

inline OccluderBvh make_bvh(const std::vector<Tri>& tris, bool brute_force = false) {
  OccluderTriangles t;
  for (std::size_t i = 0; i < tris.size(); ++i) {
    t.corners.push_back(tris[i]);
    t.ids.push_back({0, static_cast<std::uint32_t>(i)});
  }
  return OccluderBvh(std::move(t), brute_force);
}

// Two triangles covering the rectangle corner + s e1 + t e2, s, t in [0, 1].
inline void add_quad(std::vector<Tri>& tris, const Vec3d& corner, const Vec3d& e1, const Vec3d& e2) {
  tris.push_back({corner, corner + e1, corner + e1 + e2});
  tris.push_back({corner, corner + e1 + e2, corner + e2});
}

// Closed axis-aligned box, 12 triangles, consistently wound (outward normals).
inline void add_box(std::vector<Tri>& tris, const Vec3d& lo, const Vec3d& hi) {
  const Vec3d s = hi - lo;
  const Vec3d ex{s.x, 0, 0}, ey{0, s.y, 0}, ez{0, 0, s.z};
  add_quad(tris, lo, ey, ex);                 // bottom
  add_quad(tris, lo + ez, ex, ey);            // top
  add_quad(tris, lo, ex, ez);                 // front
  add_quad(tris, lo + ey, ez, ex);            // back
  add_quad(tris, lo, ez, ey);                 // left
  add_quad(tris, lo + ex, ey, ez);            // right
}

inline ShadeOptions options_with(SpecularMethod method) {
  ShadeOptions o;
  o.with_specular = method != SpecularMethod::kNone;
  o.specular.method = method;
  return o;
}

// A square light of half-size `half` centred at (0, 0, height), emitting down (-z).
inline std::vector<Vec3d> square_light(double half, double height) {
  return {{-half, -half, height}, {-half, half, height}, {half, half, height}, {half, -half, height}};
}

}  // namespace vlit::test
