// Which parts of a linear (tube) light a point P sees, from the silhouettes of what hides it
// (Picott 1992 eq. 10 applied to eq. 4), at a cost that follows the silhouette edges crossing the
// plane of (P, Q0, Q1) instead of every occluder triangle crossing it (linear_visibility.h).
//
// Method: the area lights' silhouettes (area_silhouette.h) in one dimension. The depth d(t) of
// the point Q(t) of the light is the number of occluder triangles (clipped to the strip between P
// and the light, linear_visibility.h) that the segment P -> Q(t) crosses. Each clipped triangle
// meets the plane Π of (P, Q0, Q1) in a segment, whose central projection from P onto the
// light's line is the interval of t it hides; d steps up and down at the ends of those intervals.
// An end lies where a side of the clipped triangle crosses Π, and a side shared by two triangles
// facing P the same way gives both of them an end at the same t, one starting and one ending:
// they cancel. What is left are the silhouette edges seen from P (weight +-2: a triangle facing P
// and one facing away; +-1 per triangle: boundary and non-manifold edges) and the chords along
// which a triangle leaves the strip, each crossing Π at one point. Crossed in the direction of
// growing t, an edge of weight w whose clipped part runs from Π's negative to its positive side
// raises d by w (lowers it from positive to negative).
//  1. The BVH's silhouette search (OccluderBvh::silhouette_candidates, normal cones) over the
//     thin volume around Π returns the triangles that may carry such an edge; each edge is
//     weighed by the facings of all of its triangles (silhouette_rule.h), clipped to the strip,
//     and its crossing with Π projected to t. Only the steps inside (0, 1) are kept.
//  2. One shadow ray to a point of the widest gap between steps counts d there (Laine et al. 2005
//     count a depth the same way); the steps give d everywhere else.
//  3. The visible intervals are where d = 0.
// Checks: d >= 0 in every gap wider than 1e-12; a shadow ray that grazes an edge is retried at
// another point (up to 8). When a check fails, P lies (nearly) on the light's line, the light
// has no length, or an occluder lies in Π itself (seen edge-on from P it would weigh nothing, but
// it hides the interval it covers), the answer is kUndecided and the caller uses
// visible_linear_intervals, which is also the reference of the tests
// (tests/shadow/linear_silhouette_test.cpp).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "linear_geometry.h"
#include "shadow/linear_visibility.h"
#include "shadow/occluder_bvh.h"
#include "shadow/silhouette_rule.h"

namespace vlit {

struct LinearSilhouetteScratch {
  LinearShadowFrame frame;
  SilhouetteFacings facings;
  std::vector<std::uint32_t> candidates, ray_candidates;
  std::vector<std::uint8_t> candidate_in_slab;
  std::vector<std::pair<double, int>> steps;  // (t, change of d as t grows past it)
  std::vector<std::pair<double, double>> visible;
  // Counters for benchmarks and tests.
  long queries = 0, undecided = 0, silhouette_steps = 0;
};

enum class LinearSilhouetteVisibility {
  kUnoccluded,  // P sees the whole light
  kIntervals,   // scratch.visible holds the visible [t_a, t_b] intervals, ascending (possibly none)
  kUndecided,   // use visible_linear_intervals
};

LinearSilhouetteVisibility visible_linear_by_silhouettes(const LinearLight<double>& light, const Vec3d& p,
                                                         const OccluderBvh& occluders,
                                                         LinearSilhouetteScratch& scratch);

}  // namespace vlit
