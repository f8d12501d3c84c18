// Linear light, specular term, the Phong lobe integrated over the visible segment.
//
// What it computes: Is(exact) = ∫_0^1 [L(t).N > 0] max(0, Rv.L̂(t))^m / |L(t)|^n dt for unit
// intensity (docs/conventions.md "Radiometric definitions": the diffuse's distance falloff n; n = 0
// is the paper's form, SpecularFalloff::kNone), to the relative tolerance
// SpecularOptions::exact_tolerance. Normalised like the diffuse: in units of scale^-n
// (linear_scale_factor, linear_geometry.h).
//
// Sources: Picott 1992 eq. 6 integrated along eq. 3 (the paper rejects this integral as too slow
// and uses the peak, eq. 7-8; we keep it as the reference-quality method). Integrated in the
// local frame of linear_geometry.h: cos α(s) = (ar + br s)/sqrt(h^2 + s^2), dt = ds/|Ld|, over the
// horizon-clipped interval [sa, sb], with the globally adaptive Gauss-Kronrod 7/15 rule of
// adaptive_kronrod.h (the area and disk exact forms' integrator), starting from pieces graded by 4
// around the foot of the perpendicular, the peak s_peak (linear_specular_peak.h) and the zero of
// Rv.L (comments at the cuts below).
// Role: `--specular exact` uses linear_specular_closed.h (integer m) and linear_specular_beta.h
// (falloff 2, any m) where their rounding bounds hold and this form elsewhere
// (linear_specular_exact_dispatch in linear_light.h); all on the frame set up in long double
// (make_linear_frame_precise).
// Departures from the paper: it is not in the paper; horizon clipping.
// Stiff cases: zero-length (point value, exact), P on the segment (L̂ = ±u on the visible part;
// with falloff n >= 1 the integral diverges and gives 0, as the diffuse does, linear_diffuse_closed.h),
// large m (lobe panels); tests/kernels/linear/linear_stiff_test.cpp.
// Measured accuracy: docs/linear-lights.md,
//   ./build/linear/tests/linear_light_tests -tc="accuracy table" -s
#pragma once

#include <cmath>
#include <limits>

#include "adaptive_kronrod.h"
#include "core/robust_math.h"
#include "linear_geometry.h"
#include "linear_specular_peak.h"

namespace vlit {

inline constexpr int kLinearExactMaxPieces = 512;
inline constexpr int kLinearExactMaxCuts = 96;  // initial cut points, the segment's ends included

// n: the distance falloff exponent on the specular (0: none, the paper's eq. 6 form).
template <class A>
A linear_specular_exact_frame(const LinearFrame<A>& fr, A m, A rel_tol, A n = A(0)) {
  if (fr.empty) return A(0);
  if (fr.zero_length)
    return fr.mid_cos_n > A(0) ? phong_power(fr.mid_cos_rv, m) / (n == A(0) ? A(1) : std::pow(fr.mid_r, n)) : A(0);
  if (fr.on_segment) {
    // L = s u on the visible side of P: the lobe is constant there, ∫ ds / |s|^n over [lo, hi].
    const A lobe = phong_power(linear_cos_rv(fr, fr.sb), m);
    if (n == A(0)) return lobe * fr.delta / fr.ell;
    if (!(n < A(1))) return A(0);  // divergent at P: 0, as the diffuse (on_segment_diffuse)
    const A lo = std::fabs(fr.sb <= A(0) ? fr.sb : std::fmax(fr.sa, A(0)));
    const A hi = std::fabs(fr.sb <= A(0) ? fr.sa : fr.sb);
    const A e = A(1) - n;
    return lobe * (std::pow(hi, e) - std::pow(lo, e)) / e / fr.ell;
  }
  // Integration variable tau = s - sa in [0, delta] (accurate piece lengths for far lights).
  const A sa = fr.sa;
  auto integrand = [&fr, m, sa, n](int, A tau) {
    const A s = sa + tau;
    const A lobe = phong_power(linear_cos_rv(fr, s), m);
    if (n == A(0) || lobe == A(0)) return lobe;
    const A r2 = fr.h * fr.h + s * s;  // |L(s)|^2 in the frame's unit
    return n == A(2) ? lobe / r2 : lobe / std::pow(r2, n / A(2));
  };
  // Initial cuts, graded by 4 around the integrand's features: the foot (the direction changes on
  // the scale h there, and on (h^2 + s^2) / h at s), the peak and the zero of Rv.L (s = -ar/br),
  // where max(0, .)^m has a kink. The peak's cuts start at the lobe's width
  // w = (h^2 + s_peak^2) / (h sqrt(m)), the s-length over which α changes by 1/sqrt(m); only for
  // m > 16, where the lobe is narrower than a quarter of the geometric scale that the foot's
  // grading resolves (for smaller m they only cost time: bench/linear_light_bench specular_exact_*).
  const A w_foot = std::fmax(fr.h, std::fmax(std::fabs(fr.sa), std::fabs(fr.sb)) * A(1e-30));
  const A s_peak = linear_specular_peak_position(fr);
  A w_lobe{0};
  if (fr.h > A(0) && m > A(16)) {
    w_lobe = (fr.h * fr.h + s_peak * s_peak) / (fr.h * std::sqrt(m));
    if (!std::isfinite(w_lobe)) w_lobe = A(0);
  }
  const A tau_zero = fr.br != A(0) ? -fr.ar / fr.br - sa : -A(1);
  const bool kink = tau_zero > A(0) && tau_zero < fr.delta;
  const A centers[3] = {-sa, s_peak - sa, tau_zero};
  const A widths[3] = {w_foot, w_lobe, kink ? (w_lobe > A(0) ? w_lobe : w_foot) : A(0)};
  const A tol = std::fmax(rel_tol, A(8) * std::numeric_limits<A>::epsilon());
  // Absolute floor: the tolerance relative to the peak value times the visible length, so that a
  // lobe that misses the segment (integral ~0) does not force endless bisection. (The falloff
  // factor is >= 1 in the frame's unit, |L| <= 1, so it only makes this floor more cautious.)
  const A floor = tol * A(1e-6) * phong_power(linear_cos_rv(fr, s_peak), m) * fr.delta;
  AdaptiveKronrod<A, kLinearExactMaxPieces> quad;
  const auto segment = [&integrand](A tau) { return integrand(0, tau); };
  quad.template add_graded<kLinearExactMaxCuts>(segment, 0, A(0), fr.delta, centers, widths, 3, A(1));
  const A v = quad.refine(integrand, [](int) { return A(1); }, tol, floor);
  return std::fmax(v, A(0)) / fr.ell;
}

// In world units: the normalised value times scale^-n. n = light.falloff, or 0 without falloff.
template <class T>
T linear_specular_exact(const LinearLight<T>& light, const ShadingPoint<T>& sp, double rel_tol,
                        SpecularFalloff falloff = SpecularFalloff::kAsDiffuse) {
  using A = LinearCompute<T>;
  const double n = falloff == SpecularFalloff::kAsDiffuse ? double(light.falloff) : 0.0;
  const LinearFrame<A> fr = make_linear_frame_precise(light, sp);
  return linear_saturate<T>(double(linear_specular_exact_frame(fr, A(sp.shininess), A(rel_tol), A(n))) *
                            linear_scale_factor(fr.scale, n));
}

}  // namespace vlit
