// Linear light, diffuse term, closed forms for the integer falloffs n = 0, 1, 2, 3.
//
// What it computes: Id = ∫_0^1 max(0, L(t).N) / |L(t)|^(n+1) dt for unit intensity
// (Picott 1992 eq. 4, docs/conventions.md "Radiometric definitions"), with the segment clipped to the upper half
// space of P first (conventions.h).
//
// Sources: Picott 1992 eq. 2-4 and the sidebar "Linear-light diffuse integration calculations",
// re-derived in the local frame of linear_geometry.h. With L.N = a + b s and |L|^2 = h^2 + s^2,
//   Id = (1/|Ld|) [ a F_n + b G_n ],  F_n = ∫ ds / (h^2+s^2)^((n+1)/2),  G_n = ∫ s ds / (h^2+s^2)^((n+1)/2)
// over the visible interval [sa, sb]. The antiderivatives are elementary:
//   n = 0: F = asinh(s/h)                        G = r              (r = sqrt(h^2 + s^2))
//   n = 1: F = atan(s/h)/h                       G = ln(r)
//   n = 2: F = s/(h^2 r)                         G = -1/r
//   n = 3: F = (s/r^2 + atan(s/h)/h)/(2h^2)     G = -1/(2 r^2)
// Departures from the paper (docs/linear-lights.md, errata E1-E4):
// - horizon clipping before integrating (the printed forms integrate L.N without max(0, .));
// - the printed forms are not evaluated as printed: they subtract antiderivatives at the two ends
//   (log - log, atan - atan, sqrt - sqrt) and divide by 4CE - D^2, which loses every digit when
//   the light is far (distance/length 1e6) or P is near the line of the segment. Each difference
//   below is rewritten without cancellation:
//     r_b - r_a            = (sb - sa)(sb + sa) / (r_a + r_b)
//     ln r_b - ln r_a      = log1p((sb - sa)(sb + sa) / r_a^2) / 2
//     asinh(x_b)-asinh(x_a)= asinh((sb - sa)(sb + sa) / (sb r_a + sa r_b))   (sa, sb same sign)
//     atan(x_b)-atan(x_a)  = atan2(h (sb - sa), h^2 + sa sb)                 (x = s/h)
//     F_3 = Δ/(2X) [Δ^2 φ(z)/X^2 + 2/(X(1+z^2))],  X = h^2 + sa sb, z = hΔ/X,
//           φ(z) = (atan(z)/z - 1/(1+z^2))/z^2 = 2/3 - 4/5 z^2 + 6/7 z^4 - ...
//   and all of them have a finite limit at h = 0 (P on the line of the segment, outside it),
//   which is the collinear case of the paper's 4CE - D^2 = 0.
// Stiff cases handled (tests/kernels/linear/linear_stiff_test.cpp, one TEST_CASE each):
//   "stiff: collinear", "stiff: near-collinear", "stiff: far 1e6", "stiff: near 1e-6",
//   "stiff: crossing horizon", "stiff: endpoint on tangent plane", "stiff: grazing normal",
//   "stiff: zero-length", "stiff: P on the segment".
// P on the segment (h = 0 within rounding and the foot inside the segment): for n >= 1 the
//   integral diverges; we return 0, as shade_point does for a light at P. For n < 1 it converges
//   and we return its value b ∫ |s|^-n ds over the visible half.
// Measured accuracy: docs/linear-lights.md, table produced by
//   ./build/linear/tests/linear_light_tests -tc="accuracy table" -s
#pragma once

#include <cmath>

#include "linear_geometry.h"

namespace vlit {

namespace linear_detail {

// atan(z)/z for z >= 0, accurate at z -> 0.
template <class A>
A atan_over(A z) {
  if (z < A(1e-4)) return A(1) - z * z / A(3);
  return std::atan(z) / z;
}

// φ(z) = (atan(z)/z - 1/(1+z^2)) / z^2 for z >= 0, accurate at z -> 0 (series for z < 0.1,
// 8 terms: truncation below 1e-16).
template <class A>
A atan_phi(A z) {
  if (z < A(0.1)) {
    const A z2 = z * z;
    A sum{0}, pw{1};
    for (int k = 1; k <= 8; ++k) {
      const A term = A(2 * k) / A(2 * k + 1) * pw;
      sum += (k % 2 == 1) ? term : -term;
      pw *= z2;
    }
    return sum;
  }
  const A z2 = z * z;
  return (std::atan(z) / z - A(1) / (A(1) + z2)) / z2;
}

// ln(1 + x) where x = q2/q1 - 1 is given directly (x = (q2 - q1)/q1 computed without cancellation)
// together with the ratio itself for the case x near -1.
template <class A>
A log_ratio(A x, A ratio) {
  return std::fabs(x) < A(0.5) ? std::log1p(x) : std::log(ratio);
}

template <class A>
struct Moments {
  A f{0};  // F_n = ∫ ds / (h^2+s^2)^((n+1)/2)
  A g{0};  // G_n = ∫ s ds / (h^2+s^2)^((n+1)/2)
};

// F_n and G_n over [sa, sb] (delta = sb - sa given separately, it is known more accurately),
// for h > 0 or for an interval that does not contain 0.
template <class A>
Moments<A> closed_moments(int n, A h, A sa, A sb, A delta) {
  Moments<A> m;
  if (!(delta > A(0))) return m;
  const bool flip = sb <= A(0);  // mirror s -> -s so that sb > 0; G is odd, F is even
  if (flip) { const A t = sa; sa = -sb; sb = -t; }
  const bool same_sign = sa >= A(0);
  const A h2 = h * h;
  const A ra2 = h2 + sa * sa, rb2 = h2 + sb * sb;
  const A ra = std::sqrt(ra2), rb = std::sqrt(rb2);
  const A dd = delta * (sa + sb);  // sb^2 - sa^2
  switch (n) {
    case 0:
      m.g = dd / (ra + rb);
      m.f = same_sign ? std::asinh(dd / (sb * ra + sa * rb)) : std::asinh(sb / h) + std::asinh(-sa / h);
      break;
    case 1: {
      m.g = log_ratio(dd / ra2, rb2 / ra2) / A(2);
      const A x = h2 + sa * sb;
      m.f = x > A(0) ? (delta / x) * atan_over(h * delta / x) : std::atan2(h * delta, x) / h;
      break;
    }
    case 2:
      m.g = dd / (ra * rb * (ra + rb));
      m.f = same_sign ? dd / (ra * rb * (sb * ra + sa * rb)) : (sb / rb - sa / ra) / h2;
      break;
    default: {  // 3
      m.g = dd / (A(2) * ra2 * rb2);
      const A x = h2 + sa * sb, y = h * delta;
      if (x > A(0)) {
        const A z = y / x;
        m.f = delta / (A(2) * x) * (delta * delta * atan_phi(z) / (x * x) + A(2) / (x * (A(1) + z * z)));
      } else {
        m.f = (delta * (A(2) * h2 - x) / (x * x + y * y) + std::atan2(y, x) / h) / (A(2) * h2);
      }
      break;
    }
  }
  if (flip) m.g = -m.g;
  return m;
}

// P on the segment (h = 0, a = 0): b ∫ s |s|^-(n+1) ds over the visible interval, which lies on
// one side of 0. Finite for n < 1; 0 for n >= 1 (divergent; documented convention).
template <class A>
A on_segment_diffuse(const LinearFrame<A>& fr, A n) {
  if (!(n < A(1))) return A(0);
  const A lo = std::fabs(fr.sb <= A(0) ? fr.sb : std::fmax(fr.sa, A(0)));
  const A hi = std::fabs(fr.sb <= A(0) ? fr.sa : fr.sb);
  const A e = A(1) - n;
  return std::fabs(fr.b) * (std::pow(hi, e) - std::pow(lo, e)) / e / fr.ell;
}

}  // namespace linear_detail

// Normalised diffuse for integer n in {0,1,2,3}, in units of scale^-n (see linear_geometry.h).
template <class A>
A linear_diffuse_closed_normalised(const LinearFrame<A>& fr, int n) {
  if (fr.empty) return A(0);
  if (fr.zero_length) {
    if (!(fr.mid_cos_n > A(0))) return A(0);
    return fr.mid_cos_n / std::pow(fr.mid_r, A(n));
  }
  if (fr.on_segment) return linear_detail::on_segment_diffuse(fr, A(n));
  const linear_detail::Moments<A> m = linear_detail::closed_moments(n, fr.h, fr.sa, fr.sb, fr.delta);
  return std::fmax(fr.a * m.f + fr.b * m.g, A(0)) / fr.ell;
}

// Diffuse response of a linear light with integer falloff n in {0,1,2,3} (closed form).
template <class T>
T linear_diffuse_closed(const LinearLight<T>& light, const ShadingPoint<T>& sp, int n) {
  const auto fr = make_linear_frame(light, sp);
  const double v = double(linear_diffuse_closed_normalised(fr, n));
  return linear_saturate<T>(v * linear_scale_factor(fr.scale, double(n)));
}

}  // namespace vlit
