// Which parts of a linear (tube) light a point P sees: the hidden parameter intervals of the
// segment Q(t) = Q0 + t (Q1 - Q0), t in [0, 1] (Picott 1992 eq. 10 applied to eq. 4: the
// visible sub-segments replace the segment).
//
// Method. The rays from P to the segment sweep the flat triangle (P, Q0, Q1), in the plane Π.
// An occluder triangle hides Q(t) when it crosses the ray P -> Q(t) strictly between P and the
// segment. With H the perpendicular from P to the segment's line (|H| = h, m = H/h) and
// λ(x) = (x - P).m / h (0 at P, 1 on the line), a point x of Π with λ > 0 hides
// t(x) = t_foot + ((x - P).u / λ(x)) / |Ld| (its central projection from P onto the line).
// The occluder meets Π in a segment (or is a polygon of Π when coplanar); clipped to the strip
// λ in (1e-9, 1 - 1e-7) (strictly between P and the light, the same margins as the area
// lights'), it is convex and t(.) is a projective map there, so the hidden interval is
// [min t, max t] over its clipped corners. The hidden intervals are merged and the visible
// ones returned, sorted.
// P (nearly) on the segment's line (h <= 1e-12 of the distance): every ray runs along the line;
// the light is taken as visible or hidden as a whole by the shadow ray to the nearer end.
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "linear_geometry.h"
#include "shadow/occluder_bvh.h"

namespace vlit {

// The strip where occluders count: λ in (kLinearNearP, 1 - kLinearNearLight).
inline constexpr double kLinearNearP = 1e-9;      // λ margin next to P
inline constexpr double kLinearNearLight = 1e-7;  // λ margin next to the light


enum class LinearVisibility { kUnoccluded, kIntervals };

// The geometry both linear methods share (this file's intervals, linear_silhouette.h): the plane Π
// of (P, Q0, Q1), the strip in it where occluders count, and the volume the BVH is asked about.
struct LinearShadowFrame {
  Vec3d u;             // unit, along the segment
  Vec3d m;             // unit, from P to its foot on the segment's line
  Vec3d plane_normal;  // unit normal of Π
  double len = 0, h = 0, t_foot = 0;
  // The strip's two planes: [0] next to the light (λ <= 1 - kLinearNearLight), [1] next to P
  // (λ >= kLinearNearP), in the order the slab clipping of silhouette_rule.h reads.
  HalfSpace strip[2];
  ConvexVolume volume;  // a thin slab around Π over the triangle (P, Q0, Q1)
  double lambda(const Vec3d& p, const Vec3d& x) const { return dot(x - p, m) / h; }
  double t_of(const Vec3d& p, const Vec3d& x, double lam) const { return t_foot + dot(x - p, u) / lam / len; }
};

// False where the segment has (nearly) no length or P lies (nearly) on its line: then only
// visible_linear_intervals decides, with one shadow ray. The frame's volume keeps its planes'
// storage from one call to the next (a scratch's frame allocates nothing per vertex).
bool linear_shadow_frame(const LinearLight<double>& light, const Vec3d& p, LinearShadowFrame& frame);

// The triangle lies in Π (every corner within 1e-12 of its largest distance to P): seen edge-on
// from P, it still covers the rays to the part of the light it spans.
bool lies_in_plane(const std::array<Vec3d, 3>& tri, const Vec3d& p, const Vec3d& plane_normal);

struct LinearShadowScratch {
  LinearShadowFrame frame;
  std::vector<std::uint32_t> candidates;
  std::vector<std::pair<double, double>> hidden, visible;
};

// kIntervals: scratch.visible holds the visible [t_a, t_b] intervals (possibly none).
LinearVisibility visible_linear_intervals(const LinearLight<double>& light, const Vec3d& p,
                                          const OccluderBvh& occluders, LinearShadowScratch& scratch);

}  // namespace vlit
