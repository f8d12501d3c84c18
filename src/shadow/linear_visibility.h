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

#include <cstdint>
#include <utility>
#include <vector>

#include "linear_geometry.h"
#include "shadow/occluder_bvh.h"

namespace vlit {

struct LinearShadowScratch {
  std::vector<std::uint32_t> candidates;
  std::vector<std::pair<double, double>> hidden, visible;
};

enum class LinearVisibility { kUnoccluded, kIntervals };

// kIntervals: scratch.visible holds the visible [t_a, t_b] intervals (possibly none).
LinearVisibility visible_linear_intervals(const LinearLight<double>& light, const Vec3d& p,
                                          const OccluderBvh& occluders, LinearShadowScratch& scratch);

}  // namespace vlit
