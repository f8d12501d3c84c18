// Area light, diffuse: Lambert's contour integral over the horizon-clipped polygon.
//
// Computes (unit intensity, kd = 1; conventions.h):
//   Id = ∫_A max(0, cos theta) cos theta_l / r^2 dA = 1/2 Σ_i beta_i cos delta_i
// over the polygon clipped to the upper hemisphere of P (Picott 1992 eq. 9 and 10; Lambert;
// Nishita and Nakamae 1985, appendix). No 1/pi: docs/conventions.md "Radiometric definitions".
// In vector form, with a_i = Q_i - P: beta_i cos delta_i = N . (a_{i+1} x a_i) g_i,
// g_i = beta_i / |a_i x a_{i+1}|, beta_i = atan2(|a_i x a_{i+1}|, a_i . a_{i+1}) (never acos).
//
// Departures from the paper (docs/area-lights.md): eq. 9 is only valid for a polygon entirely
// above the tangent plane; we clip to the horizon first (Sutherland-Hodgman, area_polygon.h).
// A point behind a one-sided light, or in its plane, gets exactly 0.
//
// Stable edge terms. The plain sum has terms of size beta_i ~ s/|D| (s = light size, |D| =
// distance) that cancel to a result of size (s/|D|)^2: relative error ~ eps |D|/s. When the
// light is small as seen from P (max|d_i| < kSmallLightRatio |D|) we use the exact rearrangement
//   Σ g_i (a_i x a_{i+1}) = g_ref Σ d_i x d_{i+1} + Σ (g_i - g_ref)(a_i x a_{i+1}),
// g_ref = 1/|D|^2, where Σ d_i x d_{i+1} (twice the area vector) is formed from the small
// offsets d_i only and g_i - g_ref is evaluated without cancellation (series for
// beta/sin(beta) - 1 and an exact expansion of |D|^2 - |a_i||a_{i+1}|).
// The cross products a_i x a_{i+1} are formed as D x (d_{i+1} - d_i) + d_i x d_{i+1} or as
// a_i x a_{i+1}, whichever has the smaller rounding bound (edge_cross, area_polygon.h).
//
// Stiff cases (tests/kernels/area/area_diffuse_test.cpp, "stiff diffuse cases"): tiny,
// distant (|D|/s = 1e9), thin aspect 1e-6, huge, P in the light's plane, P on an edge, P near an
// edge, crossing the horizon, grazing, behind the emitter; edges with a_i x a_{i+1} = 0
// contribute 0 (a zero-length clip edge, or P on the edge's line, which only happens in the plane).
//
// Measured accuracy (docs/area-lights.md; `./build/area/tests/area_light_tests`): double 9.7e-12
// relative on 120 random cases, ≤ 3e-11 on the stiff table except "grazing-plane" (P 1e-6 off the
// light's plane: abs. error 3.5e-17 of the edge-term scale, rel. 4.9e-4 of a 6.6e-14 value);
// float (computed in double, rounded once) ≤ 5.2e-8.
#pragma once

#include <cmath>

#include "area_polygon.h"

namespace vlit {

// Below this ratio max|d_i| / |D| the reference-subtracted form is used (angles < 0.1 rad, so
// the 7-term series of beta/sin(beta) - 1 is exact to rounding).
inline constexpr double kSmallLightRatio = 0.05;

// beta / sin(beta) - 1 for |beta| <= 0.15 (Taylor series, terms up to beta^14).
template <class R>
R beta_over_sin_minus_one(R b) {
  const R x = b * b;
  // Coefficients of x/sin(x) = Σ (-1)^(k+1) 2 (2^(2k-1) - 1) B_2k x^2k / (2k)!
  return x * (R(1) / R(6) + x * (R(7) / R(360) + x * (R(31) / R(15120) + x * (R(127) / R(604800) +
         x * (R(73) / R(3421440) + x * (R(1414477) / R(653837184000.0) + x * R(8191) / R(37362124800.0)))))));
}

// 2 * Id for the polygon `poly` (relative to c), before the orientation sign: returns
// N . Σ g_i (a_{i+1} x a_i).
template <class R>
R contour_lambert_sum(const ClipPolygon<R>& poly, const Vec3<R>& D, const Vec3<R>& n) {
  const int count = poly.count;
  if (count < 3) return R(0);
  const R dist2 = length_squared(D);
  R max_d2 = 0;
  for (int i = 0; i < count; ++i) max_d2 = std::max(max_d2, length_squared(poly.d[i]));
  const bool small = max_d2 < R(kSmallLightRatio * kSmallLightRatio) * dist2;
  R sum = 0;
  if (!small) {
    for (int i = 0; i < count; ++i) {
      const Vec3<R>& di = poly.d[i];
      const Vec3<R>& dj = poly.d[(i + 1) % count];
      const Vec3<R> cr = edge_cross(D, di, dj);  // a_i x a_{i+1}
      const R s = length(cr);
      if (!(s > R(0))) continue;
      const R beta = std::atan2(s, dot(D + di, D + dj));
      sum += beta / s * dot(n, cr);
    }
    return -sum;
  }
  // Small light: reference-subtracted form.
  const R g_ref = R(1) / dist2;
  Vec3<R> twice_area{};
  for (int i = 0; i < count; ++i) {
    const Vec3<R>& di = poly.d[i];
    const Vec3<R>& dj = poly.d[(i + 1) % count];
    twice_area += cross(di, dj);
    const Vec3<R> cr = cross(D, dj - di) + cross(di, dj);
    const R s = length(cr);
    if (!(s > R(0))) continue;
    const Vec3<R> a = D + di, b = D + dj;
    const R la = length(a), lb = length(b);
    const R lab = la * lb;
    const R beta = std::atan2(s, dot(a, b));
    // |a|^2 = |D|^2 + ua with ua = 2 D.d_i + |d_i|^2 (small, exact to rounding).
    const R ua = R(2) * dot(D, di) + length_squared(di);
    const R ub = R(2) * dot(D, dj) + length_squared(dj);
    // 1/(|a||b|) - 1/|D|^2 = -(|D|^2 (ua + ub) + ua ub) / ((|D|^2 + |a||b|) |a||b| |D|^2)
    const R inv_diff = -(dist2 * (ua + ub) + ua * ub) / ((dist2 + lab) * lab * dist2);
    const R g_minus_ref = beta_over_sin_minus_one(beta) / lab + inv_diff;
    sum += g_minus_ref * dot(n, cr);
  }
  sum += g_ref * dot(n, twice_area);
  return -sum;
}

// Diffuse response of a prepared area light at P with normal N (horizon clipped).
template <class T, class R = AreaReal<T>>
R area_diffuse_contour(const PreparedAreaLight<T>& pl, const AreaView<R>& view,
                       const ClipPolygon<R>& horizon_clipped, const Vec3<R>& n) {
  if (!view.lit || horizon_clipped.count < 3) return R(0);
  const R id = R(0.5) * view.orient * contour_lambert_sum(horizon_clipped, view.D, n);
  return std::max(id, R(0));  // exact value is >= 0; clamps rounding residue only
}

}  // namespace vlit
