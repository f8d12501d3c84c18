// Linear light, specular: the visible interval clipped to the Phong lobe's half-space, in the angle
// frame the specular closed forms integrate in.
//
// What it computes: for a frame of linear_geometry.h (L(s) = H + s u, Rv.L = ar + br s), the part of
// the horizon-clipped interval [sa, sb] where Rv.L >= 0, and at both of its ends the quantities of
// the derivation in linear_specular_closed.h: with s = h x = h tan θ, Rv.L̂ = A cos θ + B sin θ,
// A = ar / h, B = br, C = |(A, B)|, (a, b) = (A, B) / C = (cos θ0, sin θ0), and at each end
// c = cos(θ - θ0) = (a + b x) / sqrt(1 + x^2), sφ = sin(θ - θ0) = (a x - b) / sqrt(1 + x^2).
// On the clipped interval θ - θ0 runs increasing within [-π/2, π/2] (c >= 0).
// Sources: Picott 1992 eq. 6 along eq. 3; conventions.h; shared by linear_specular_closed.h
// (recurrences in m) and linear_specular_beta.h (incomplete beta function), which handle the frame's
// special cases (empty, zero length, P on the segment, h = 0) before calling this.
#pragma once

#include <cmath>

#include "linear_geometry.h"

namespace vlit {

template <class A>
struct LinearLobeInterval {
  bool empty = true;   // the lobe's half-space misses the visible interval, or C = 0: Is = 0
  A big_c{0};          // C = |(A, B)| <= 1: Rv.L̂ = C cos(θ - θ0)
  A a{0}, b{0};        // cos θ0, sin θ0
  A xa{0}, xb{0};      // x = s / h at the clipped interval's ends
  A ra{0}, rb{0};      // sqrt(1 + x^2) = sec θ at both ends
  A ca{0}, cb{0};      // c = cos(θ - θ0) >= 0 at both ends
  A spa{0}, spb{0};    // sφ = sin(θ - θ0) at both ends
  A dx{0};             // x_b - x_a, from the clipped length (no cancellation)
  A dtheta{0};         // θ_b - θ_a = atan2(x_b - x_a, 1 + x_a x_b) (no cancellation)
};

// Requires a frame that is not empty, zero length or on the segment, with h > 0.
template <class A>
LinearLobeInterval<A> linear_lobe_interval(const LinearFrame<A>& fr) {
  LinearLobeInterval<A> r;
  // Clip [sa, sb] to the lobe's half-space ar + br s >= 0. The clipped length is kept as offsets
  // from sa (tau in [tau_lo, tau_hi] within [0, delta]): sb - sa cancels for a short interval far
  // from the foot (a far light), delta does not.
  A lo = fr.sa, hi = fr.sb, tau_lo = 0, tau_hi = fr.delta;
  if (fr.br != A(0)) {
    const A s_zero = -fr.ar / fr.br;
    if (fr.br > A(0) && s_zero > lo) { lo = s_zero; tau_lo = s_zero - fr.sa; }
    if (fr.br < A(0) && s_zero < hi) { hi = s_zero; tau_hi = s_zero - fr.sa; }
  } else if (!(fr.ar > A(0))) {
    return r;
  }
  if (!(hi > lo) || !(tau_hi > tau_lo)) return r;
  const A big_a = fr.ar / fr.h, big_b = fr.br;
  r.big_c = std::hypot(big_a, big_b);
  if (!(r.big_c > A(0))) return r;
  r.empty = false;
  r.a = big_a / r.big_c;
  r.b = big_b / r.big_c;
  r.xa = lo / fr.h;
  r.xb = hi / fr.h;
  r.ra = std::hypot(A(1), r.xa);
  r.rb = std::hypot(A(1), r.xb);
  r.ca = std::fmax((r.a + r.b * r.xa) / r.ra, A(0));
  r.cb = std::fmax((r.a + r.b * r.xb) / r.rb, A(0));
  r.spa = (r.a * r.xa - r.b) / r.ra;
  r.spb = (r.a * r.xb - r.b) / r.rb;
  r.dx = (tau_hi - tau_lo) / fr.h;
  r.dtheta = std::atan2(r.dx, A(1) + r.xa * r.xb);
  return r;
}

}  // namespace vlit
