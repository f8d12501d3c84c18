// Linear (tube) light: the entry point the bake loop and the CLI's `probe` call.
//
// What it computes: the diffuse Id = ∫_0^1 max(0, L.N)/|L|^(n+1) dt and the specular (peak or
// neighbourhood: the lobe's maximum; exact: ∫_0^1 [L.N > 0] max(0, Rv.L̂)^m / |L|^n dt, without
// the 1/|L|^n for SpecularFalloff::kNone; SpecularOptions) of a segment light of unit intensity per unit
// t, with kd = ks = 1 (conventions.h; docs/conventions.md "Radiometric definitions"; Picott 1992 eq. 3-8).
//
// Dispatch: integer falloff n in {0,1,2,3} uses the closed forms (linear_diffuse_closed.h) unless
// LinearDiffuseOptions::force_quadrature; any other n in [0, 3] uses linear_diffuse_quadrature.h.
// Specular: kNone -> 0, kPeak -> linear_specular_peak.h, kNeighborhood ->
// linear_specular_neighborhood.h, kExact -> linear_specular_closed.h (integer m) or
// linear_specular_beta.h (falloff 2, any m) where their rounding bounds hold, else
// linear_specular_exact.h (linear_specular_exact_dispatch). The frame
// (linear_geometry.h) is built once per call and shared.
//
// Per-light constants: only Ld = Q1 - Q0, |Ld| and u = Ld/|Ld| (docs/linear-lights.md, E1);
// they are recomputed here because they cost a subtraction and one sqrt.
// Errata, stable reformulations, stiff cases, and measured accuracy: docs/linear-lights.md;
// reproduce with ./build/linear/tests/linear_light_tests -tc="accuracy table" -s
// Outputs are finite and >= 0 for every finite input (the diffuse saturates at the largest finite
// T when the true value overflows T).
#pragma once

#include <cmath>

#include "conventions.h"
#include "linear_diffuse_closed.h"
#include "linear_diffuse_quadrature.h"
#include "linear_geometry.h"
#include "linear_specular_beta.h"
#include "linear_specular_closed.h"
#include "linear_specular_exact.h"
#include "linear_specular_neighborhood.h"
#include "linear_specular_peak.h"

namespace vlit {

// The exact specular. With the inverse-square falloff (n = 2, the default): the recurrence of
// linear_specular_closed.h for integer m <= kLinearRecurrenceMaxShininess, the incomplete-beta form
// (linear_specular_beta.h, O(1) in m) for every other m >= 0, each where its rounding bound holds.
// (Below that m the recurrence is the faster; docs/linear-lights.md, bench/linear_light_bench
// specular_exact_n2_*.)
// n = 0: the recurrence for integer m <= kLinearClosedDispatchMaxShininess where its bound holds.
// Everything they refuse, and other n: the adaptive form (linear_specular_exact.h).
// n: the falloff exponent on the specular (0: none). Normalised (units of scale^-n).
template <class A>
A linear_specular_exact_dispatch(const LinearFrame<A>& fr, A m, A rel_tol, A n = A(0)) {
  const bool integer_m = m == std::floor(m) && m >= A(0);
  if (n == A(2) && m >= A(0)) {
    const LinearSpecularClosed<A> c = integer_m && m <= A(kLinearRecurrenceMaxShininess)
                                          ? linear_specular_closed_frame(fr, int(m), 2)
                                          : linear_specular_beta_frame(fr, m);
    if (c.accepted) return c.value;
  } else if (n == A(0) && integer_m && m <= A(kLinearClosedDispatchMaxShininess)) {
    const LinearSpecularClosed<A> c = linear_specular_closed_frame(fr, int(m), 0);
    if (c.accepted) return c.value;
  }
  return linear_specular_exact_frame(fr, m, rel_tol, n);
}

struct LinearDiffuseOptions {
  double quadrature_tolerance = 1e-10;  // relative tolerance of the non-integer-n quadrature
  bool force_quadrature = false;        // use the quadrature also for n = 0, 1, 2, 3
};

// Response for unit intensity (Ip per unit of the parameter t in [0,1]) and kd = ks = 1.
// with_diffuse = false leaves the diffuse 0 (a caller that has it from the batch kernel).
template <class T>
Response<T> shade_linear(const LinearLight<T>& light, const ShadingPoint<T>& sp, const SpecularOptions& spec,
                         const LinearDiffuseOptions& diff = {}, bool with_diffuse = true) {
  using A = LinearCompute<T>;
  const LinearFrame<A> fr = make_linear_frame(light, sp);
  Response<T> r;
  if (fr.empty) return r;
  const double n = double(light.falloff);
  if (with_diffuse) {
    const bool integer_n = (n == 0 || n == 1 || n == 2 || n == 3);
    const double d = (integer_n && !diff.force_quadrature)
                         ? double(linear_diffuse_closed_normalised(fr, int(n)))
                         : double(linear_diffuse_quadrature_normalised(fr, A(n), A(diff.quadrature_tolerance)));
    r.diffuse = linear_saturate<T>(d * linear_scale_factor(fr.scale, n));
  }
  const A m = A(sp.shininess);
  switch (spec.method) {
    case SpecularMethod::kNone: break;
    case SpecularMethod::kPeak: r.specular = T(linear_specular_peak_frame(fr, m)); break;
    case SpecularMethod::kNeighborhood:
      r.specular = T(linear_specular_neighborhood_frame(fr, m, spec.neighborhood_samples));
      break;
    case SpecularMethod::kExact: {
      // Its own frame, set up in long double: the lobe's height is m times more sensitive to the
      // frame's rounding than the diffuse (make_linear_frame_precise). With the diffuse's falloff
      // n by default; without it (n = 0) for SpecularFalloff::kNone, the paper's form.
      const double ns = spec.falloff == SpecularFalloff::kAsDiffuse ? n : 0.0;
      const LinearFrame<A> precise = make_linear_frame_precise(light, sp);
      r.specular = linear_saturate<T>(double(linear_specular_exact_dispatch(precise, m, A(spec.exact_tolerance), A(ns))) *
                                      linear_scale_factor(precise.scale, ns));
      break;
    }
  }
  return r;
}

}  // namespace vlit
