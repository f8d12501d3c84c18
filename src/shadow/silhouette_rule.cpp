#include "shadow/silhouette_rule.h"

#include <algorithm>
#include <cmath>

namespace vlit {

int shadow_ray_depth(const OccluderBvh& occluders, const Vec3d& p, const Vec3d& x, const CountingSlab& slab,
                     SilhouetteFacings& facings, std::vector<std::uint32_t>& ray_candidates) {
  const OccluderTriangles& triangles = occluders.triangles();
  const Vec3d dir = x - p;
  occluders.triangles_near_segment(p, x, ray_candidates);
  int count = 0;
  for (std::uint32_t t : ray_candidates) {
    const auto& c = triangles.corners[t];
    bool outside = false;  // wholly outside the slab: not counted, whatever the crossing test says
    for (const HalfSpace* h : {&slab.beyond_light, &slab.before_p})
      outside = outside || (h->signed_distance(c[0]) < 0 && h->signed_distance(c[1]) < 0 && h->signed_distance(c[2]) < 0);
    if (outside) continue;
    const Vec3d e1 = c[1] - c[0], e2 = c[2] - c[0];
    const Vec3d pvec = cross(dir, e2);
    const double det = dot(e1, pvec);
    if (!(std::abs(det) > 0)) continue;
    const double inv = 1.0 / det;
    const Vec3d tvec = p - c[0];
    const double b1 = dot(tvec, pvec) * inv;
    const Vec3d qvec = cross(tvec, e1);
    const double b2 = dot(dir, qvec) * inv;
    const double b0 = 1 - b1 - b2;
    const double t_hit = dot(e2, qvec) * inv;
    if (!(t_hit > 0 && t_hit < 1)) continue;
    const double margin = std::min({b0, b1, b2});
    if (margin < -kRayAmbiguity) continue;
    // A triangle that hides nothing from P (facing_of 0) is not counted, and is not ambiguous:
    // asked only of the triangles the ray meets.
    if (facings.facing_of(occluders, t, p) == 0) continue;
    const Vec3d hit = p + dir * t_hit;
    const double d0 = slab.beyond_light.signed_distance(hit), d1 = slab.before_p.signed_distance(hit);
    if (d0 < -slab.plane_tol || d1 < -slab.apex_tol) continue;
    if (margin <= kRayAmbiguity || d0 <= slab.plane_tol || d1 <= slab.apex_tol) return -1;
    ++count;
  }
  return count;
}

}  // namespace vlit
