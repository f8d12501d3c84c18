// Area light, specular, closed form for a narrow lobe that one edge cuts: where a single edge of
// the visible polygon passes through the part of the sphere holding all but a negligible part of
// the lobe, the polygon there is a half-space, and the lobe on each side of a great circle has a
// closed form (phong_lune.h).
//
// What it computes: Is(exact) = ∫_Omega [N.w > 0] max(0, Rv.w)^m dw (unit intensity, ks = 1), real
// m >= 0, the quantity of area_specular_closed.h and area_specular_exact.h, where it can bound the
// rest.
//
// Sources: the cap argument of area_specular_cap.h; the split of the lobe by a great circle derived
// in phong_lune.h (Abramowitz and Stegun 26.5.1, 26.5.8). Conventions: conventions.h, geometry of
// area_polygon.h.
//
// Derivation. Let delta be the angular distance from Rv to the nearest point of every edge of the
// horizon-clipped polygon but one, edge i, which comes closer: its great circle passes at beta <
// delta from Rv, with its nearest point (the foot of the perpendicular from Rv) inside the edge. The
// cap {angle(w, Rv) < delta} then meets the boundary only along edge i, whose ends lie outside it
// (each end is a point of a neighbouring edge), so inside the cap the winding number of the
// polygon is w_near on Rv's side of the great circle and w_far on the other, with
// w_far - w_near = +1 crossing from n_i.w > 0 to n_i.w < 0 (n_i = a_i x b_i, area_polygon.h's
// winding convention; the same for the back of a two-sided light, whose frame is mirrored).
// Replacing the winding number by those two values on the whole hemisphere Rv.w > 0 gives
//   Is ~ orient (w_near pi / (m + 1) (1 + P) + w_far pi / (m + 1) Q)      (phong_lune.h),
// off only outside the cap, where the lobe holds 2 pi cos^{m+1}(delta) / (m + 1) (area_specular_cap.h)
// and the winding numbers differ by at most n / 2 + 1 <= n (an n-gon winds at most n / 2 times).
// So the truncation is at most n 2 pi cos^{m+1}(delta) / (m + 1).
// Error: that truncation, plus P's and Q's own (phong_lune.h), plus the inputs' rounding (sin beta
// carries about 8 eps absolute, which moves the split by dP/dbeta 8 eps / cos beta). The result is
// accepted when the sum is at most kAreaClosedBound of it. Refused (a caller takes another form):
// no edge within reach (area_specular_cap.h's case, or a tail), two edges or a corner within reach,
// a winding number beyond +-1 on either side, and every case whose estimate fails.
// Where it applies: mirror-like materials whose highlight lies across one edge of a light: the reach
// (cos^{m+1} delta = kAreaClosedBound / (2n)) is about 4 degrees at m = 1e4 for a quad, 13 at
// m = 1e3, 30 at m = 200.
// Cost: a bounding-cone test (refusing lobes far from the whole light at once), one cross product
// per edge (the arc test where the great circle comes within reach), one winding number, one
// phong_lune: O(n) plus about a hundred multiply-adds whatever m.
// Measured: tests/kernels/area/area_specular_edge_lobe_test.cpp (`./build/release/tests/area_light_tests
// -tc="edge lobe*" -s`); speed in docs/area-lights.md "One edge across a narrow lobe".
// Float: computes in double (AreaReal) like the other area kernels.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "area_polygon.h"
#include "area_specular_closed.h"
#include "phong_lune.h"

namespace vlit {

// The exact specular's dispatch (area_light.h) tries this form above this m only: below it the
// reach (30 degrees at m = 200) rarely holds a single edge of a light.
inline constexpr double kAreaEdgeLobeDispatchMinShininess = 200;

template <class R>
AreaSpecularClosed<R> area_specular_edge_lobe(const ClipPolygon<R>& horizon_clipped, const AreaView<R>& view,
                                              const Vec3<R>& rv_in, R m) {
  constexpr R eps = std::numeric_limits<R>::epsilon();
  AreaSpecularClosed<R> r;  // the closed forms' result (area_specular_closed.h)
  r.accepted = false;       // every early return below refuses
  const int n = horizon_clipped.count;
  if (!view.lit || n < 3 || !(m >= R(0))) return r;
  const R bound = R(kAreaClosedBound);
  const R winding_bound = R(n);
  // Reach: acceptance needs the truncation n 2 pi cos^{m+1}(delta) / (m + 1) below bound / 2 of a
  // value at most 2 pi / (m + 1), so every edge but one lies where cos^{m+1} <= bound / (2n):
  // cos^2 <= reach2, i.e. sin^2 >= needed.
  const R needed = -std::expm1(R(2) * std::log(bound / (R(2) * winding_bound)) / (m + R(1)));
  const R reach2 = R(1) - needed;
  const Vec3<R> rv = normalize(rv_in);
  // A lobe far from the whole light (most refusals: tails): every point of the polygon lies within
  // the angle rho = asin(radius / |D|) of the direction to its centre, so no edge is within reach
  // where angle(Rv, D) > rho + reach. One dot product instead of the edges' cross products.
  {
    R radius2 = 0;
    for (int i = 0; i < n; ++i) radius2 = std::max(radius2, length_squared(horizon_clipped.d[i]));
    const R dist2 = length_squared(view.D);
    if (dist2 > radius2) {
      const R dist = std::sqrt(dist2), sin_rho = std::sqrt(radius2 / dist2), cos_rho = std::sqrt(R(1) - radius2 / dist2);
      const R cos_within = cos_rho * std::sqrt(reach2) - sin_rho * std::sqrt(needed);  // cos(rho + reach)
      // (rho < pi / 2 and reach <= pi / 2, so cos is decreasing up to rho + reach; 1e-9 for rounding)
      if (dot(rv, view.D) < (cos_within - R(1e-9)) * dist) return r;
    }
  }
  int cut = -1;             // the one edge within reach
  R cut_along = 0, cut_length = 0;
  R far_cos2 = 0;           // the largest cos^2 of the distance from Rv to any other edge
  for (int i = 0; i < n; ++i) {
    const int j = i + 1 < n ? i + 1 : 0;
    const Vec3<R> normal = edge_cross(view.D, horizon_clipped.d[i], horizon_clipped.d[j]);
    const R length2 = length_squared(normal);
    if (!(length2 > R(0))) continue;  // a zero-length edge bounds nothing
    const R along = dot(rv, normal);
    const R sin2 = std::min(along * along / length2, R(1));
    if (sin2 >= needed) {  // the great circle is out of reach, so is the edge
      far_cos2 = std::max(far_cos2, R(1) - sin2);
      continue;
    }
    // The great circle comes within reach: is its nearest point to Rv on the edge?
    const Vec3<R> a = view.D + horizon_clipped.d[i], b = view.D + horizon_clipped.d[j];
    const Vec3<R> foot = rv - normal * (along / length2);
    if (dot(cross(a, foot), normal) >= R(0) && dot(cross(foot, b), normal) >= R(0)) {
      if (cut >= 0) return r;  // a second edge within reach
      cut = i;
      cut_along = along;
      cut_length = std::sqrt(length2);
      continue;
    }
    // Else the edge's nearest point to Rv is an end.
    const R ca = dot(rv, a) / length(a), cb = dot(rv, b) / length(b);
    const R c = std::max({ca, cb, R(0)});
    if (c * c > reach2) return r;  // a corner within reach (the truncation below would refuse it too)
    far_cos2 = std::max(far_cos2, c * c);
  }
  if (cut < 0) return r;  // no edge within reach: the cap's case or a tail
  // The winding numbers on both sides: Rv's (0 where Rv does not meet the light's plane), and the
  // other side's one more crossing to n.w < 0 (area_polygon.h's convention: interior on the side
  // n.w < 0 for a polygon counter-clockwise as seen from P, winding +1 there).
  const int w_near = ray_winding_number(horizon_clipped, view, rv);
  const int w_far = w_near + (cut_along > R(0) ? 1 : -1);
  if (std::abs(w_near) > 1 || std::abs(w_far) > 1) return r;
  const R sin_beta = std::min(std::fabs(cut_along) / cut_length, R(1));
  const PhongLune<R> lune = phong_lune(sin_beta, m);
  const R half = R(M_PI) / (m + R(1));
  const R near_part = half * (R(1) + lune.p), far_part = half * lune.q;
  const R value = view.orient * (R(w_near) * near_part + R(w_far) * far_part);
  if (!(value > R(0))) return r;  // the two sides' windings disagree with the light's side
  // Error: truncation outside the cap, the lune's own, the inputs' rounding.
  const R truncation = far_cos2 > R(0) ? winding_bound * R(2) * half * std::exp(R(0.5) * (m + R(1)) * std::log(far_cos2)) : R(0);
  const R cos_beta = std::sqrt(std::max(R(1) - sin_beta * sin_beta, eps));
  const R rounding = lune.error * (near_part * std::abs(w_near) + far_part * std::abs(w_far)) +
                     half * lune.slope * R(8) * eps / cos_beta;
  r.condition = (truncation + rounding) / value;
  r.accepted = r.condition <= bound && std::isfinite(value);
  r.value = value;
  return r;
}

}  // namespace vlit
