#include "shadow/linear_silhouette.h"

#include <algorithm>
#include <cmath>

#include <boost/sort/pdqsort/pdqsort.hpp>

namespace vlit {
namespace {

constexpr double kThinGap = 1e-12;  // gaps between steps narrower than this (in t) are left out

// The step of d where the clipped segment a -> b (an edge of weight w or a chord) crosses Π, if
// it does inside (0, 1). A point exactly on Π counts as on its positive side, the same for every
// segment through it, so a clipped triangle's sides cross Π an even number of times.
void add_step(const LinearShadowFrame& f, const Vec3d& p, const Vec3d& a, const Vec3d& b, int weight,
              std::vector<std::pair<double, int>>& steps) {
  const double da = dot(a - p, f.plane_normal), db = dot(b - p, f.plane_normal);
  const bool a_up = da >= 0, b_up = db >= 0;
  if (a_up == b_up) return;
  const Vec3d x = a + (b - a) * (da / (da - db));
  const double lam = f.lambda(p, x);
  if (!(lam > 0)) return;
  const double t = f.t_of(p, x, lam);
  if (!(t > 0 && t < 1)) return;
  steps.emplace_back(t, b_up ? weight : -weight);
}

}  // namespace

LinearSilhouetteVisibility visible_linear_by_silhouettes(const LinearLight<double>& light, const Vec3d& p,
                                                         const OccluderBvh& occluders,
                                                         LinearSilhouetteScratch& scratch) {
  ++scratch.queries;
  scratch.visible.clear();
  scratch.steps.clear();
  LinearShadowFrame& frame = scratch.frame;
  if (!linear_shadow_frame(light, p, frame)) return ++scratch.undecided, LinearSilhouetteVisibility::kUndecided;
  occluders.silhouette_candidates(frame.volume, frame.strip, 2, p, scratch.candidates, scratch.candidate_in_slab);
  SilhouetteFacings& facings = scratch.facings;
  facings.begin(occluders);

  // 1. The steps of d inside (0, 1).
  const OccluderEdges& edges = occluders.edges();
  std::vector<std::pair<double, int>>& steps = scratch.steps;
  for (std::size_t i = 0; i < scratch.candidates.size(); ++i) {
    // A candidate that hides nothing itself (it touches P, is a culled back face, a needle) still
    // weighs its edges: its neighbours may lie in subtrees the search skipped.
    const std::uint32_t t = scratch.candidates[i];
    // One lying in Π weighs nothing but hides what it covers: only the intervals count it.
    const int ft = facings.facing_of(occluders, t, p);
    const auto& corners = occluders.triangles().corners[t];
    if (ft == 0 && !touches(corners, p) &&
        !culled_back_face(occluders.triangles(), t, p, occluders.plane(t).normal) &&
        lies_in_plane(corners, p, frame.plane_normal))
      return ++scratch.undecided, LinearSilhouetteVisibility::kUndecided;
    for (int j = 0; j < 3; ++j) {
      const std::uint32_t e = edges.edge_of[t][j];
      if (!facings.first_visit(e)) continue;
      const int weight = facings.edge_weight(occluders, e, p);
      if (weight == 0) continue;
      Vec3d a, b;
      if (clip_edge_to_slab(edges.endpoints[e][0], edges.endpoints[e][1], frame.strip, a, b))
        add_step(frame, p, a, b, weight, steps);
    }
    if (ft != 0 && !scratch.candidate_in_slab[i])
      for_each_slab_chord(corners, frame.strip,
                          [&](const Vec3d& exit, const Vec3d& entry) { add_step(frame, p, exit, entry, ft, steps); });
  }
  scratch.silhouette_steps += static_cast<long>(steps.size());

  // Steps at one t merged; the gaps between them: gap g runs from step g - 1 (or 0) to step g (or 1).
  boost::sort::pdqsort(steps.begin(), steps.end());
  std::size_t kept = 0;
  for (const auto& step : steps) {
    if (kept > 0 && steps[kept - 1].first == step.first) steps[kept - 1].second += step.second;
    else steps[kept++] = step;
  }
  steps.resize(kept);
  const std::size_t gaps = steps.size() + 1;
  auto gap_lo = [&](std::size_t g) { return g == 0 ? 0.0 : steps[g - 1].first; };
  auto gap_hi = [&](std::size_t g) { return g == steps.size() ? 1.0 : steps[g].first; };

  // 2. d in the widest gap, from one shadow ray.
  std::size_t widest = 0;
  for (std::size_t g = 1; g < gaps; ++g)
    if (gap_hi(g) - gap_lo(g) > gap_hi(widest) - gap_lo(widest)) widest = g;
  CountingSlab slab{frame.strip[0], frame.strip[1]};
  slab.plane_tol = kRayAmbiguity * (frame.h + frame.len);
  slab.apex_tol = std::min(slab.plane_tol, 0.5 * kLinearNearP * frame.h);
  static constexpr double kToward[kMaxReferenceRays] = {0.5, 0.31, 0.71, 0.17, 0.83, 0.43, 0.59, 0.07};
  int reference = -1;
  for (int k = 0; k < kMaxReferenceRays && reference < 0; ++k) {
    const double t = gap_lo(widest) + kToward[k] * (gap_hi(widest) - gap_lo(widest));
    reference = shadow_ray_depth(occluders, p, light.q0 + (light.q1 - light.q0) * t, slab, facings,
                                 scratch.ray_candidates);
  }
  if (reference < 0) return ++scratch.undecided, LinearSilhouetteVisibility::kUndecided;
  if (steps.empty()) {
    if (reference == 0) return LinearSilhouetteVisibility::kUnoccluded;
    return LinearSilhouetteVisibility::kIntervals;  // hidden everywhere
  }

  // 3. d in every gap (from the widest one outward), and the gaps where it is 0.
  int d = reference;
  for (std::size_t g = widest; g > 0; --g) d -= steps[g - 1].second;  // d in gap 0
  std::vector<std::pair<double, double>>& visible = scratch.visible;
  for (std::size_t g = 0; g < gaps; ++g) {
    if (g > 0) d += steps[g - 1].second;
    const double lo = gap_lo(g), hi = gap_hi(g);
    if (!(hi - lo > kThinGap)) continue;
    if (d < 0) return ++scratch.undecided, LinearSilhouetteVisibility::kUndecided;
    if (d != 0) continue;
    if (!visible.empty() && visible.back().second == lo) visible.back().second = hi;
    else visible.emplace_back(lo, hi);
  }
  return LinearSilhouetteVisibility::kIntervals;
}

}  // namespace vlit
