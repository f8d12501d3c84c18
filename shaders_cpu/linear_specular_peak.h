// Linear light, specular term, the paper's most-important-point approximation.
//
// What it computes: Is(peak) = max over the visible t in [0,1] of max(0, Rv.L̂(t))^m
// (Picott 1992 eq. 6-8, docs/conventions.md "Radiometric definitions"), for unit intensity.
//
// Sources: Picott 1992 eq. 7-8 and the sidebar "Linear-light specular calculations". In the local
// frame of linear_geometry.h, cos α(s) = Rv.L̂ = (ar + br s) / sqrt(h^2 + s^2) and
//   d cos α / ds = (br h^2 - ar s) / (h^2 + s^2)^(3/2),
// so the only finite stationary point is s* = br h^2 / ar, i.e. t* = (s* - s0)/|Ld|, which is
// algebraically the sidebar's t = (BD - 2CE)/(BE - 2AD) (the t^2 terms of its quadratic cancel).
// Departures from the paper (docs/linear-lights.md, errata E5-E7):
// - the stationary point is the maximum of cos α only if ar = Rv.H > 0; if ar < 0 it is the
//   minimum (the paper would pick the worst point) and the maximum is at an end of the visible
//   interval; the other "stationary point" is at infinity (t -> ±inf, direction ±u);
// - the paper's zero denominator (BE - 2AD = -2|Ld|^2 ar = 0) does not mean "no specular": cos α is
//   then monotone and its maximum, at an end, can be 1;
// - t* is clamped to the visible (horizon-clipped) part of [0, 1], and the ends are always
//   candidates: the answer is max(f(sa), f(sb), f(clamp(s*))) when ar > 0, else max(f(sa), f(sb)).
// Stiff cases: zero-length (point limit), P on the segment and collinear (direction ±u, no
// division by h), h = 0 with ar = 0 (s* = 0/0 avoided by the ar > 0 test); see
// tests/kernels/linear/linear_stiff_test.cpp.
// Measured accuracy (peak vs dense search + golden refinement in long double): see
// docs/linear-lights.md, ./build/linear/tests/linear_light_tests -tc="accuracy table" -s
#pragma once

#include <cmath>

#include "core/robust_math.h"
#include "linear_geometry.h"

namespace vlit {

// cos α = Rv.L̂ at position s of the frame (0 when L = 0).
template <class A>
A linear_cos_rv(const LinearFrame<A>& fr, A s) {
  if (fr.on_segment) {  // L̂ = ±u on the visible part, which lies on one side of P
    const A side = s != A(0) ? s : fr.sa + fr.sb;
    return side > A(0) ? fr.br : -fr.br;
  }
  const A r = std::sqrt(fr.h * fr.h + s * s);
  if (!(r > A(0))) return A(0);
  return std::fmin(std::fmax((fr.ar + fr.br * s) / r, A(-1)), A(1));
}

// Position s in [sa, sb] of the largest cos α over the visible interval.
template <class A>
A linear_specular_peak_position(const LinearFrame<A>& fr) {
  A best_s = fr.sa;
  A best = linear_cos_rv(fr, fr.sa);
  const A cb = linear_cos_rv(fr, fr.sb);
  if (cb > best) { best = cb; best_s = fr.sb; }
  if (fr.ar > A(0) && !fr.on_segment) {
    // s* = br h^2 / ar, clamped; with ar > 0 it is the maximum of cos α on the whole line.
    const A s_star = std::fmin(std::fmax(fr.br * fr.h * fr.h / fr.ar, fr.sa), fr.sb);
    const A cs = linear_cos_rv(fr, s_star);
    if (cs > best) best_s = s_star;
  }
  return best_s;
}

// Normalised (dimensionless) peak specular of a frame.
template <class A>
A linear_specular_peak_frame(const LinearFrame<A>& fr, A m) {
  if (fr.empty) return A(0);
  if (fr.zero_length) return fr.mid_cos_n > A(0) ? phong_power(fr.mid_cos_rv, m) : A(0);
  return phong_power(linear_cos_rv(fr, linear_specular_peak_position(fr)), m);
}

template <class T>
T linear_specular_peak(const LinearLight<T>& light, const ShadingPoint<T>& sp) {
  using A = LinearCompute<T>;
  return T(linear_specular_peak_frame(make_linear_frame(light, sp), A(sp.shininess)));
}

// The sidebar's optimal t exactly as printed (eq. 8), for the errata tests only: no clamping,
// no visibility, NaN/Inf when its denominator vanishes. Not used by the kernels.
template <class T>
T picott_printed_t_star(const LinearLight<T>& light, const ShadingPoint<T>& sp) {
  const Vec3<T> l0 = light.q0 - sp.p, ld = light.q1 - light.q0;
  const T a = dot(ld, ld), b = T(2) * dot(l0, ld), c = dot(l0, l0);
  const T d = dot(sp.rv, l0), e = dot(sp.rv, ld);
  return (b * d - T(2) * c * e) / (b * e - T(2) * a * d);
}

}  // namespace vlit
