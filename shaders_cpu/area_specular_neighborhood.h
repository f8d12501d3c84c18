// Area light, specular, the paper's refinement: the peak corrected by a neighbourhood of samples.
//
// Computes (unit intensity, ks = 1; conventions.h):
//   Is(nbhd) = Is(peak) * (1 + Σ_k vis(w_k)) / (K + 1)
// where w_k, k = 1..K, are K directions evenly spaced on a cone of half-angle gamma(m) around the
// peak direction w* (area_specular_peak.h) and vis(w) = 1 if the ray P + t w hits the visible
// (horizon-clipped) light. It is the peak times the fraction of the lobe's neighbourhood covered
// by the light: small lights and highlight edges are dimmed, and the softening shrinks as m grows.
//
// Sources: Picott 1992, linear-light text after eq. 6 ("sampling a neighborhood around the
// optimal point whose size depends on the value of n ... The neighborhood's size decreases with
// increasing values of n"), applied to eq. 11-12. The paper gives no rule; ours:
//   gamma(m) = min(pi/8, acos(2^(-1/m)))   (the lobe's half-maximum angle: cos^m gamma = 1/2),
//   gamma(0) = pi/8,
// gamma evaluated as atan2(sin, cos) from 1 - cos gamma = -expm1(-ln 2 / m): acos of a cosine
// within ln 2 / m of 1 loses digits as m grows (~1e-12 relative at m = 1e4), the atan2 form none.
// K = SpecularOptions::neighborhood_samples (K = 0 gives exactly the peak). Visibility samples
// (not lobe values) are averaged so that a light covering the neighbourhood gives exactly the
// peak; the lobe's shape is already in the peak. Documented in docs/area-lights.md.
//
// Stiff cases: tests/kernels/area/area_specular_test.cpp "neighbourhood properties" (K = 0,
// bounded by the peak, big light = peak, m up to 1e4, every output finite).
#pragma once

#include <cmath>

#include "area_specular_peak.h"

namespace vlit {

template <class R>
R neighborhood_half_angle(R m) {
  constexpr R kMaxSpread = R(M_PI / 8);
  if (!(m > R(0))) return kMaxSpread;
  const R one_minus_cos = -std::expm1(R(-M_LN2) / m);  // 1 - 2^(-1/m)
  const R sin_gamma = std::sqrt(one_minus_cos * (R(2) - one_minus_cos));
  return std::min(kMaxSpread, std::atan2(sin_gamma, R(1) - one_minus_cos));
}

// The rule with the visibility of the directions given: peak_seen says whether the peak
// direction counts, ring_seen(dir) whether a ring direction does (a shadowed light passes its
// visible pieces for both, src/shadow/shadowed_light.cpp; the unshadowed light counts its peak,
// which lies on it, and tests the ring against the polygon).
template <class R, class PeakSeen, class RingSeen>
R area_specular_neighborhood_seen(const ClipPolygon<R>& poly, const AreaView<R>& view, const Vec3<R>& rv, R shininess,
                                  int samples, const PeakSeen& peak_seen, const RingSeen& ring_seen) {
  const AreaPeak<R> peak = area_specular_peak_direction(poly, view, rv);
  if (!peak.visible) return R(0);
  const R peak_value = phong_lobe_from_angle(peak.angle, shininess);
  const int seen = peak_seen(peak.direction) ? 1 : 0;
  if (samples <= 0 || peak_value == R(0)) return seen ? peak_value : R(0);
  // Orthonormal frame (t1, t2) around w*.
  const Vec3<R>& w = peak.direction;
  const Vec3<R> helper = std::abs(w.x) < R(0.6) ? Vec3<R>{1, 0, 0} : Vec3<R>{0, 1, 0};
  const Vec3<R> t1 = normalize(cross(w, helper));
  const Vec3<R> t2 = cross(w, t1);
  const R gamma = neighborhood_half_angle(shininess);
  const R cg = std::cos(gamma), sg = std::sin(gamma);
  int visible = 0;
  for (int k = 0; k < samples; ++k) {
    const R phi = R(2 * M_PI) * (R(k) + R(0.5)) / R(samples);
    const Vec3<R> dir = w * cg + (t1 * std::cos(phi) + t2 * std::sin(phi)) * sg;
    if (ring_seen(dir)) ++visible;
  }
  return peak_value * R(seen + visible) / R(samples + 1);
}

template <class R>
R area_specular_neighborhood(const ClipPolygon<R>& poly, const AreaView<R>& view,
                             const Vec3<R>& rv, R shininess, int samples) {
  return area_specular_neighborhood_seen(
      poly, view, rv, shininess, samples, [](const Vec3<R>&) { return true; },
      [&](const Vec3<R>& dir) { return ray_hits_polygon(poly, view, dir); });
}

}  // namespace vlit
