// Linear light, specular term, the paper's neighbourhood refinement of the peak.
//
// What it computes: Is(nbhd) = (1/K) Σ_k max(0, Rv.L̂(θ_k))^m, the mean of the Phong lobe over K
// directions of the visible segment around the most important point, K =
// SpecularOptions::neighborhood_samples (docs/conventions.md "Radiometric definitions": "optionally refined by a
// neighbourhood of samples whose size shrinks as m grows").
//
// Sources: Picott 1992, text after eq. 6 ("sampling a neighborhood around the optimal point whose
// size depends on the value of n, then sum the values of that sampling ... the neighborhood's
// size decreases with increasing values of n"). The paper gives no rule; ours:
// - the samples are spread in the angle θ of L̂ within the plane of P and the line
//   (s = h tan θ, θ = 0 at the foot), because the Phong lobe is a function of angle;
// - window: θ_peak ± δ with δ = min(π/2, 2/sqrt(max(m, 1))), i.e. two standard deviations of the
//   lobe cos^m α ≈ exp(-m α^2 / 2), intersected with the visible part [θ(sa), θ(sb)];
// - K samples at the midpoints of K equal sub-windows, averaged (not summed, so that the result
//   has the units of the peak value and tends to it as m grows: for m -> ∞, δ -> 0).
// Departures from the paper: "sum" read as "mean" (see above); horizon clipping.
// Stiff cases: h = 0 (P on the line of the segment: every visible direction is ±u) returns the
// peak; K < 1 returns the peak; zero-length returns the point value.
// Accuracy: an approximation, not a quadrature; its error against the exact lobe integral is
// reported (not bounded) in docs/linear-lights.md,
//   ./build/linear/tests/linear_light_tests -tc="accuracy table" -s
#pragma once

#include <cmath>

#include "core/robust_math.h"
#include "linear_geometry.h"
#include "linear_specular_peak.h"

namespace vlit {

// Every point of the segment counts (the unshadowed light).
struct WholeSegment {
  template <class A>
  bool operator()(A) const { return true; }
};

// visible(t): whether the point Q(t), t in [0, 1], counts (a shadowed light passes the visible
// sub-segments, src/shadow/shadowed_light.cpp); a hidden peak or sample adds 0.
template <class A, class Visible = WholeSegment>
A linear_specular_neighborhood_frame(const LinearFrame<A>& fr, A m, int k_samples, const Visible& visible = {}) {
  if (fr.empty) return A(0);
  const A ds = fr.s1 - fr.s0;
  auto t_of = [&](A s) { return ds != A(0) ? (s - fr.s0) / ds : A(0.5); };
  if (fr.zero_length) return fr.mid_cos_n > A(0) && visible(A(0.5)) ? phong_power(fr.mid_cos_rv, m) : A(0);
  const A s_peak = linear_specular_peak_position(fr);
  if (k_samples < 1 || fr.on_segment || !(fr.h > A(0)))
    return visible(t_of(s_peak)) ? phong_power(linear_cos_rv(fr, s_peak), m) : A(0);
  constexpr A kHalfPi = A(1.57079632679489661923);
  const A delta = std::fmin(kHalfPi, A(2) / std::sqrt(std::fmax(m, A(1))));
  const A theta_peak = std::atan2(s_peak, fr.h);
  const A lo = std::fmax(theta_peak - delta, std::atan2(fr.sa, fr.h));
  const A hi = std::fmin(theta_peak + delta, std::atan2(fr.sb, fr.h));
  const A rv_h = fr.ar / fr.h;  // Rv.Ĥ
  A sum{0};
  for (int k = 0; k < k_samples; ++k) {
    const A theta = lo + (hi - lo) * (A(k) + A(0.5)) / A(k_samples);
    if (!visible(t_of(fr.h * std::tan(theta)))) continue;
    const A c = std::fmin(std::fmax(rv_h * std::cos(theta) + fr.br * std::sin(theta), A(-1)), A(1));
    sum += phong_power(c, m);
  }
  return sum / A(k_samples);
}

template <class T>
T linear_specular_neighborhood(const LinearLight<T>& light, const ShadingPoint<T>& sp, int k_samples) {
  using A = LinearCompute<T>;
  return T(linear_specular_neighborhood_frame(make_linear_frame(light, sp), A(sp.shininess), k_samples));
}

}  // namespace vlit
