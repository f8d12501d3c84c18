// Area (panel) light: entry point. Diffuse by Lambert's contour integral, specular by the paper's
// peak, its neighbourhood refinement, or the exact lobe integral.
//
// Computes, for unit intensity and kd = ks = 1 (conventions.h, docs/conventions.md "Radiometric definitions"):
//   diffuse  = ∫_A max(0, cos theta) cos theta_l / r^2 dA                   area_diffuse_contour.h
//   specular = max over the visible light of max(0, Rv.w)^m                  area_specular_peak.h
//            | peak x covered fraction of its neighbourhood                  area_specular_neighborhood.h
//            | ∫_A [cos theta > 0] max(0, Rv.w)^m cos theta_l / r^2 dA       area_specular_cap.h (a narrow
//              lobe inside the light), else area_specular_edge_lobe.h (a narrow lobe that one edge
//              cuts), else area_specular_closed.h (integer m, within its bound),
//              else area_specular_tail.h (Rv beside the light, within its bound),
//              else area_specular_exact.h
// Sources: Picott 1992 eq. 9-12 and the sidebar; Nishita and Nakamae 1985; see each file.
// Conventions: conventions.h. The light is one-sided (emits toward the side from which its
// vertices are counter-clockwise) unless two_sided; a point behind it, or in its plane, gets 0.
// Departures from the paper: horizon clipping; exact boundary search instead of the sidebar's
// rule; stable edge terms (docs/area-lights.md).
// Scalar type: float evaluates in double internally (AreaReal) and rounds once.
// Limits: ≤ kMaxAreaVertices vertices (prepare_area_light throws otherwise); no heap allocation
// per evaluation once the light is prepared.
// Measured accuracy: docs/area-lights.md, `./build/area/tests/area_light_tests`.
#pragma once

#include <cmath>
#include <limits>

#include "area_diffuse_contour.h"
#include "area_polygon.h"
#include "area_specular_cap.h"
#include "area_specular_edge_lobe.h"
#include "area_specular_closed.h"
#include "area_specular_exact.h"
#include "area_specular_neighborhood.h"
#include "area_specular_peak.h"
#include "area_specular_tail.h"

namespace vlit {

// The exact specular: above kAreaCapDispatchMinShininess first the narrow lobe's cap where it
// lies inside the light (area_specular_cap.h: 2 pi / (m + 1), O(n)); above
// kAreaEdgeLobeDispatchMinShininess the narrow lobe that a single edge cuts
// (area_specular_edge_lobe.h: an incomplete beta function, O(n)); then the closed form for
// integer m <= kAreaClosedDispatchMaxShininess where its
// rounding bound holds (area_specular_closed.h; above that m its O(m) recurrence is slower than
// the adaptive form), above kAreaTailDispatchMaxShininess only where the lobe's largest value on
// the light is at least kAreaClosedDispatchMinPeakLobe (area_lobe_reaches: some direction toward
// the light within acos(that^(1/m)) of Rv; elsewhere the result is a tail whose edge terms
// cancel, which the closed form mostly refuses at that m after an O(m) recurrence that costs more
// than the adaptive form); else, where Rv misses the light, the tail form within its bound and step
// budget (area_specular_tail.h, integer or real m); else the adaptive contour form
// (area_specular_exact.h). Tried in that order: where both closed forms accept, the first is
// the cheaper. The tail form only up to kAreaTailDispatchMaxShininess: above it the adaptive form,
// which skips the pieces the lobe does not reach, is as fast on the tails
// (bench/area_light_bench.cpp --closed-by-m --tails). The real-m closed
// form (area_specular_closed_real.h) is accurate but did not pay on a real bake
// (docs/area-lights.md "Real m").
template <class R>
R area_specular_exact_dispatch(const ClipPolygon<R>& visible, const AreaView<R>& view, const Vec3<R>& rv, R m,
                               R tolerance) {
  if (m > R(kAreaCapDispatchMinShininess)) {
    const AreaSpecularClosed<R> cap = area_specular_cap(visible, view, rv, m);
    if (cap.accepted) return cap.value;
  }
  if (m > R(kAreaEdgeLobeDispatchMinShininess)) {
    const AreaSpecularClosed<R> cut = area_specular_edge_lobe(visible, view, rv, m);
    if (cut.accepted) return cut.value;
  }
  if (m == std::floor(m) && m >= R(0) && m <= R(kAreaClosedDispatchMaxShininess) &&
      (m <= R(kAreaTailDispatchMaxShininess) ||
       area_lobe_reaches(visible, view, normalize(rv), std::pow(R(kAreaClosedDispatchMinPeakLobe), R(1) / m)))) {
    const AreaSpecularClosed<R> c = area_specular_closed(visible, view, rv, int(m));
    if (c.accepted) return c.value;
  }
  if (m <= R(kAreaTailDispatchMaxShininess)) {
    // The adaptive form's absolute target (area_specular_exact.h): tol eps 2 pi / (m + 1).
    const R floor = tolerance * std::numeric_limits<R>::epsilon() * R(2 * M_PI) / (m + R(1));
    const AreaSpecularClosed<R> t = area_specular_tail(visible, view, rv, m, floor);
    if (t.accepted) return t.value;
  }
  return area_specular_exact(visible, view, rv, m, tolerance);
}

// Shades with a prepared light (per-light constants computed once): the bake loop's form.
// with_diffuse = false leaves the diffuse 0 (a caller that has it from the batch kernel).
template <class T>
Response<T> shade_area(const PreparedAreaLight<T>& light, const ShadingPoint<T>& sp,
                       const SpecularOptions& spec, bool with_diffuse = true) {
  using R = AreaReal<T>;
  const Vec3<R> p = static_cast<Vec3<R>>(sp.p);
  const Vec3<R> n = static_cast<Vec3<R>>(sp.n);
  const AreaView<R> view = make_area_view(light, p);
  if (!view.lit) return {};
  ClipPolygon<R> visible;
  clip_to_horizon(light, view, n, visible);
  if (visible.count < 3) return {};
  Response<T> r;
  if (with_diffuse) r.diffuse = static_cast<T>(area_diffuse_contour(light, view, visible, n));
  const Vec3<R> rv = static_cast<Vec3<R>>(sp.rv);
  const R m = static_cast<R>(sp.shininess);
  switch (spec.method) {
    case SpecularMethod::kNone:
      break;
    case SpecularMethod::kPeak:
      r.specular = static_cast<T>(area_specular_peak(visible, view, rv, m));
      break;
    case SpecularMethod::kNeighborhood:
      r.specular = static_cast<T>(area_specular_neighborhood(visible, view, rv, m, spec.neighborhood_samples));
      break;
    case SpecularMethod::kExact:
      r.specular = static_cast<T>(area_specular_exact_dispatch(visible, view, rv, m, static_cast<R>(spec.exact_tolerance)));
      break;
  }
  return r;
}

// The required convenience form: validates and prepares the light on every call (throws
// std::invalid_argument for an invalid light). Prefer preparing once for many points.
template <class T>
Response<T> shade_area(const AreaLight<T>& light, const ShadingPoint<T>& sp, const SpecularOptions& spec) {
  return shade_area(prepare_area_light(light), sp, spec);
}

}  // namespace vlit
