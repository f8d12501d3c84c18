// Linear light, diffuse term for any real falloff n in [0, 3], by adaptive Gauss-Legendre.
//
// What it computes: Id = ∫_0^1 max(0, L(t).N) / |L(t)|^(n+1) dt for unit intensity
// (Picott 1992 eq. 4), horizon-clipped (conventions.h), to a relative tolerance
// LinearDiffuseOptions::quadrature_tolerance.
//
// Sources: Picott 1992 eq. 4 (the paper gives closed forms only for n = 0..3 and notes that
// other n are "typically" between 0 and 3). The integral is taken in the local frame of
// linear_geometry.h, dt = ds/|Ld|, integrand (a + b s) / (h^2 + s^2)^((n+1)/2) over the visible
// interval [sa, sb]; linear_gauss_legendre.h is the rule.
// Panels: the integrand is analytic except for the poles s = ±i h, so it varies on the length
// scale max(h, |s|). The initial panels are a geometric grading (ratio 2) around the foot s = 0,
// starting at width h: every panel [x, 2x] then sees its nearest pole at a relative distance
// that makes the 16-point rule converge to ~1e-16, and the 8/16-point comparison bisects the rare
// panel that is not yet converged. At most ~110 initial panels (h/length down to 1e-16).
// Departures from the paper: horizon clipping; P on the segment as in linear_diffuse_closed.h.
// Stiff cases: the same named cases as linear_diffuse_closed.h, run with force_quadrature and
// with non-integer n (tests/kernels/linear/linear_stiff_test.cpp).
// Measured accuracy: docs/linear-lights.md,
//   ./build/linear/tests/linear_light_tests -tc="accuracy table" -s
#pragma once

#include <cmath>

#include "linear_diffuse_closed.h"
#include "linear_gauss_legendre.h"
#include "linear_geometry.h"

namespace vlit {

// Normalised diffuse for real n (units of scale^-n, see linear_geometry.h).
template <class A>
A linear_diffuse_quadrature_normalised(const LinearFrame<A>& fr, A n, A rel_tol) {
  if (fr.empty) return A(0);
  if (fr.zero_length) {
    if (!(fr.mid_cos_n > A(0))) return A(0);
    return fr.mid_cos_n / std::pow(fr.mid_r, n);
  }
  if (fr.on_segment) return linear_detail::on_segment_diffuse(fr, n);
  const A h2 = fr.h * fr.h;
  const A half_power = -(n + A(1)) / A(2);
  const A a = fr.a, b = fr.b;
  // Integration variable tau = s - sa in [0, delta]: the panel lengths then carry the accurate
  // delta instead of sb - sa, which loses log10(|s|/delta) digits for a far light.
  const A sa = fr.sa;
  auto integrand = [=](A tau) {
    const A s = sa + tau;
    const A c = std::fmax(a + b * s, A(0));  // >= 0 on the visible interval up to rounding
    return c * std::pow(h2 + s * s, half_power);
  };
  constexpr int kCapacity = 128;
  A edges[kCapacity];
  int count = 0;
  edges[count++] = A(0);
  edges[count++] = fr.delta;
  const A foot = -sa;  // the foot of the perpendicular, s = 0
  if (foot > A(0) && foot < fr.delta) edges[count++] = foot;
  // Grading around the foot from width h (a negligible floor keeps it defined at h = 0).
  const A w = std::fmax(fr.h, std::fmax(std::fabs(fr.sa), std::fabs(fr.sb)) * A(1e-30));
  count = append_geometric_grading(edges, count, kCapacity, A(0), fr.delta, foot, w, kCapacity - 4);
  sort_edges(edges, count);
  const A tol = std::fmax(rel_tol, A(8) * std::numeric_limits<A>::epsilon());
  const A v = adaptive_gauss_legendre(integrand, edges, count, tol);
  return std::fmax(v, A(0)) / fr.ell;
}

// Diffuse response of a linear light with any real falloff n in [0, 3] (quadrature).
template <class T>
T linear_diffuse_quadrature(const LinearLight<T>& light, const ShadingPoint<T>& sp, double rel_tol) {
  using A = LinearCompute<T>;
  const auto fr = make_linear_frame(light, sp);
  const double n = double(light.falloff);
  const double v = double(linear_diffuse_quadrature_normalised(fr, A(n), A(rel_tol)));
  return linear_saturate<T>(v * linear_scale_factor(fr.scale, n));
}

}  // namespace vlit
