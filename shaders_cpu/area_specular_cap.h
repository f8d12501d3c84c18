// Area light, specular, closed form for a narrow lobe wholly inside the light: Is = 2 pi / (m + 1)
// when the cap around Rv that holds all but a negligible part of the lobe lies inside the visible
// polygon.
//
// What it computes: Is(exact) = ∫_Omega [N.w > 0] max(0, Rv.w)^m dw (unit intensity, ks = 1), the
// quantity of area_specular_closed.h and area_specular_exact.h, where it can prove the shortcut.
//
// Derivation. Over the hemisphere Rv.w > 0 the lobe integrates to ∫_0^{pi/2} cos^m t sin t dt 2 pi
// = 2 pi / (m + 1) (real m >= 0). Let delta be the angular distance from Rv to the nearest great
// circle through an edge of the horizon-clipped polygon: sin delta = min_i |Rv.n_i| / |n_i|, n_i the
// normal of the plane through P and edge i. If Rv lies inside the polygon (winding number +-1),
// the cap {angle(w, Rv) < delta} holds Rv, is connected and meets no edge, so it lies inside the
// polygon; the part of the hemisphere outside the polygon lies outside the cap, and
//   0 <= 2 pi / (m + 1) - Is <= 2 pi ∫_delta^{pi/2} cos^m t sin t dt = 2 pi cos^{m+1}(delta) / (m + 1).
// So 2 pi / (m + 1) is within the relative error cos^{m+1}(delta) = (1 - sin^2 delta)^{(m+1)/2} of
// Is; it is accepted where that is at most half of kAreaClosedBound (the other half covers the
// rounding of sin delta, which moves the bound by about (m + 1) eps relative). Horizon: the clip's
// edges are edges of the polygon, so the cap also lies above P's horizon.
// Where it applies: a narrow lobe (the cap needs sin^2 delta >= 1 - (kAreaClosedBound / 2)^{2/(m+1)}:
// about 4 degrees at m = 1e4, 13 at m = 1e3, 41 at m = 100) whose axis meets the light well inside
// its edges: mirror-like materials (glTF roughness near 0 maps to m up to 1e4) facing a panel.
// Elsewhere it refuses (accepted = false) and the dispatch (area_light.h) takes another form.
// Cost: one cross product per edge (a refusal usually stops at the first edges), then the winding
// number: O(n) whatever m.
// Measured: tests/kernels/area/area_specular_cap_test.cpp (`./build/release/tests/area_light_tests
// -tc="cap*" -s`); speed in docs/area-lights.md "Narrow lobes".
// Float: computes in double (AreaReal) like the other area kernels.
#pragma once

#include <algorithm>
#include <cmath>

#include "area_polygon.h"
#include "area_specular_closed.h"

namespace vlit {

// The exact specular's dispatch (area_light.h) tries this form above this m only: below it the
// cap it needs (41 degrees at m = 100) is rarely inside a light, and the check would only add time.
inline constexpr double kAreaCapDispatchMinShininess = 200;

template <class R>
AreaSpecularClosed<R> area_specular_cap(const ClipPolygon<R>& horizon_clipped, const AreaView<R>& view,
                                        const Vec3<R>& rv_in, R m) {
  AreaSpecularClosed<R> r;  // the closed forms' result (area_specular_closed.h)
  r.accepted = false;       // every early return below refuses
  const int n = horizon_clipped.count;
  if (!view.lit || n < 3 || !(m >= R(0))) return r;
  // The cap needs sin^2 delta >= 1 - (kAreaClosedBound / 2)^{2/(m+1)}, i.e. a bound of at most
  // kAreaClosedBound / 2: the edges first, each refusing at once where it comes closer (most
  // refusals are decided by the first edges).
  const R needed = -std::expm1(R(2) * std::log(R(0.5 * kAreaClosedBound)) / (m + R(1)));
  const Vec3<R> rv = normalize(rv_in);
  R sin2_delta = R(1);
  for (int i = 0; i < n; ++i) {
    const int j = i + 1 < n ? i + 1 : 0;
    const Vec3<R> normal = edge_cross(view.D, horizon_clipped.d[i], horizon_clipped.d[j]);
    const R length2 = length_squared(normal);
    if (!(length2 > R(0))) continue;  // a zero-length edge bounds nothing
    const R along = dot(rv, normal);
    if (!(along * along >= needed * length2)) return r;
    sin2_delta = std::min(sin2_delta, along * along / length2);
  }
  // Rv must hit the light's plane inside the polygon, which winds once about the hit point (a
  // polygon that winds twice about Rv would count the cap twice).
  if (std::abs(ray_winding_number(horizon_clipped, view, rv)) != 1) return r;
  // Accepted: every edge at least delta away. The bound (1 - sin^2 delta)^{(m+1)/2} is reported
  // (by log1p for sin^2 delta near 0).
  r.condition = std::exp(R(0.5) * (m + R(1)) * std::log1p(-sin2_delta));
  r.accepted = true;
  r.value = R(2 * M_PI) / (m + R(1));
  return r;
}

}  // namespace vlit
