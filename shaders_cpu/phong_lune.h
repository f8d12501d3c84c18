// The Phong lobe split by a great circle: how much of max(0, Rv.w)^m lies on each side of a plane
// through P at angular distance beta from Rv, for real m >= 0, to full relative accuracy on both
// sides.
//
// What it computes: with q = (m + 1) / 2 and z = sin^2 beta (0 <= beta <= pi / 2),
//   near side (the one holding Rv) = pi / (m + 1) (1 + P),   far side = pi / (m + 1) Q,
//   P = I_z(1/2, q),  Q = 1 - P = I_{1-z}(q, 1/2)   (the regularized incomplete beta function).
// Derivation. Take Rv = e_z and the plane's unit normal n = cos beta e_x + sin beta e_z (n.Rv =
// sin beta, Rv on the side n.w > 0). Project the sphere onto the (x, z) disk: dw = 2 dx dz /
// sqrt(1 - x^2 - z^2) (two sheets, y >= 0 and y <= 0); in polar coordinates x = r cos a,
// z = r sin a, the far side with z > 0 is a in (pi/2 + beta, pi), so
//   far = 2 ∫_0^1 r^{m+1} / sqrt(1 - r^2) dr ∫_beta^{pi/2} cos^m s ds,
// a product whose first factor does not depend on beta. At beta = 0 the far side is half of the
// hemisphere's 2 pi / (m + 1), so far = pi / (m + 1) ∫_beta^{pi/2} cos^m / ∫_0^{pi/2} cos^m, and
// u = sin^2 s turns the ratio into Q = 1 - I_z(1/2, q) (Abramowitz and Stegun 6.6.2, 26.5.1; the
// same substitution as linear_specular_beta.h).
// Evaluation (A&S 26.5.8 and 15.1.1 with the prefactor of 26.5.8):
//   I_z(a, b) = z^a (1 - z)^b / (a B(a, b)) F,
// - head (q z < kLuneTailFrom): F = 2F1(a + b, 1; a + 1; z) with a = 1/2, b = q, a series of
//   positive terms (each the last times (q + 1/2 + k) z / (3/2 + k)), so P carries only its terms'
//   rounding; Q = 1 - P then loses at most a factor P / Q <= 1 / Q(kLuneTailFrom / q) ~ 40;
// - tail (q z >= kLuneTailFrom): Q = I_{1-z}(q, 1/2) by A&S 26.5.8's continued fraction in the
//   modified Lentz form (Press et al., Numerical Recipes, 5.2), which converges fast where
//   1 - z < (q + 1) / (q + 5/2), here q z >= kLuneTailFrom > 3/2 (or z >= kLuneTailFromZ); P = 1 - Q (P >= 1/2 there).
// The beta function B(1/2, q) = sqrt(pi) Gamma(q) / Gamma(q + 1/2) needs the ratio
// Gamma(q + 1/2) / Gamma(q) to full relative accuracy for every q (lgamma's difference loses
// |lgamma| eps, 1e-11 at m = 1e4): Stirling's series (A&S 6.1.40) differenced, for q >= 20 after
// the recurrence Gamma(q + 1) = q Gamma(q) has moved small q up.
// Error: `error` bounds the relative error of P and of Q separately (each value's own terms'
// rounding, the prefactor's exp and log, the subtraction 1 - P or 1 - Q); tests/kernels/area/
// phong_lune_test.cpp measures it against Boost.Math's long-double ibeta.
// Cost: about q z + 8 sqrt(q z) + 12 series terms (head), or a few dozen Lentz steps (tail),
// whatever m (bench: area_light_bench --closed-by-m's edge-lobe column).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace vlit {

// Where the head series hands over to the tail's continued fraction: q z at least kLuneTailFrom,
// or z at least kLuneTailFromZ (small m: the head's terms fall only like z^k).
inline constexpr double kLuneTailFrom = 2.5;
inline constexpr double kLuneTailFromZ = 0.75;

// Gamma(q + 1/2) / Gamma(q) for q > 0, to a few eps.
template <class R>
R gamma_half_ratio(R q) {
  // Gamma(q + 1/2) / Gamma(q) = [Gamma(q + n + 1/2) / Gamma(q + n)] Π_{j < n} (q + j) / (q + j + 1/2).
  R shift = 1;
  while (q < R(20)) {
    shift *= q / (q + R(0.5));
    q += R(1);
  }
  // ln Gamma(q + 1/2) - ln Gamma(q) = 1/2 ln q + [q ln(1 + 1/(2q)) - 1/2]
  //   + Σ_k B_2k / (2k (2k - 1)) ((q + 1/2)^{1 - 2k} - q^{1 - 2k})      (A&S 6.1.40);
  // the first five terms leave under 1e-18 at q >= 20.
  constexpr R c[5] = {R(1) / 12, R(-1) / 360, R(1) / 1260, R(-1) / 1680, R(1) / 1188};
  const R inv_a = R(1) / (q + R(0.5)), inv_b = R(1) / q;
  const R a2 = inv_a * inv_a, b2 = inv_b * inv_b;
  R pa = inv_a, pb = inv_b, series = 0;
  for (R ck : c) {
    series += ck * (pa - pb);
    pa *= a2;
    pb *= b2;
  }
  const R rest = (q * std::log1p(R(0.5) * inv_b) - R(0.5)) + series;
  return shift * std::sqrt(q) * std::exp(rest);
}

template <class R>
struct PhongLune {
  R p = 0, q = 1;  // P = I_z(1/2, (m + 1)/2) and Q = 1 - P
  R error = 0;     // bound on the relative error of each of p and q
  R slope = 0;     // dP/dbeta = cos^m beta / ∫_0^{pi/2} cos^m, for the caller's input rounding
  int steps = 0;   // series terms or Lentz steps taken
};

// P and Q for the lobe exponent m >= 0 and a plane at angular distance beta from Rv, given as
// sin beta >= 0 (z = sin^2 beta keeps its relative precision for beta -> 0, where 1 - cos^2 beta
// would not; cos^{m+1} beta is formed from log1p(-z)).
template <class R>
PhongLune<R> phong_lune(R sin_beta, R m) {
  constexpr R eps = std::numeric_limits<R>::epsilon();
  PhongLune<R> r;
  const R q = (m + R(1)) / R(2);
  const R z = std::min(sin_beta * sin_beta, R(1));
  const R ratio = gamma_half_ratio(q) / std::sqrt(R(M_PI));  // 1 / B(1/2, q)
  if (!(z > R(0))) {  // the plane through Rv: P = 0, Q = 1
    r.slope = R(2) * ratio;
    return r;
  }
  // z^{1/2} (1 - z)^q / B(1/2, q), with (1 - z)^q = exp(q log1p(-z)).
  const R log_x = std::log1p(-z);
  const R power = std::exp(q * log_x);                        // cos^{m+1} beta
  const R prefix = sin_beta * power * ratio;
  // ∫_0^{pi/2} cos^m = B(1/2, q) / 2, so dP/dbeta = 2 cos^m beta / B(1/2, q).
  r.slope = z < R(1) ? R(2) * ratio * power / std::sqrt(R(1) - z) : R(0);
  // The prefactor's rounding: the exponent carries eps of its size and z's own two eps, which
  // log1p(-z) turns into 2 eps z / (1 - z); a few eps from the other factors.
  const R prefix_error = (q * (std::fabs(log_x) + R(2) * z / std::max(R(1) - z, eps)) + R(12)) * eps;
  if (q * z < R(kLuneTailFrom) && z < R(kLuneTailFromZ)) {
    // P = 2 prefix Σ_k t_k, t_0 = 1, t_{k+1} = t_k (q + 1/2 + k) z / (3/2 + k): positive terms;
    // once their ratio g is below 1 it keeps falling, so the rest is below t_k g / (1 - g).
    R term = 1, sum = 1;
    int k = 0;
    for (; k < 4096; ++k) {
      const R grow = (q + R(0.5) + R(k)) * z / (R(1.5) + R(k));
      term *= grow;
      sum += term;
      if (grow < R(1) && term * grow <= eps * (R(1) - grow) * sum) break;
    }
    r.steps = k + 1;
    r.p = std::min(R(2) * prefix * sum, R(1));
    const R p_error = prefix_error + R(2 * (k + 4)) * eps;
    r.q = R(1) - r.p;
    r.error = p_error * std::max(R(1), r.p / std::max(r.q, std::numeric_limits<R>::min())) + eps;
    return r;
  }
  // Q = I_x(a, b) with x = 1 - z, a = q, b = 1/2: x^a (1 - x)^b / (a B(a, b)) = prefix / q
  // times the continued fraction 1 / (1 + d_1 / (1 + d_2 / (1 + ...))), d_{2j+1} = -(a + j)(a + b + j) x /
  // ((a + 2j)(a + 2j + 1)), d_{2j} = j (b - j) x / ((a + 2j - 1)(a + 2j)) (A&S 26.5.8), by modified Lentz.
  const R x = R(1) - z, a = q, b = R(0.5);
  constexpr R tiny = R(1e-300);
  auto guard = [](R v) { return std::fabs(v) < tiny ? tiny : v; };
  R c = 1, d = R(1) / guard(R(1) - (a + b) * x / (a + R(1)));
  R f = d;
  int j = 1;
  for (; j < 512; ++j) {
    const R even = R(j) * (b - R(j)) * x / ((a + R(2 * j) - R(1)) * (a + R(2 * j)));
    d = R(1) / guard(R(1) + even * d);
    c = guard(R(1) + even / c);
    f *= d * c;
    const R odd = -(a + R(j)) * (a + b + R(j)) * x / ((a + R(2 * j)) * (a + R(2 * j) + R(1)));
    d = R(1) / guard(R(1) + odd * d);
    c = guard(R(1) + odd / c);
    const R delta = d * c;
    f *= delta;
    if (std::fabs(delta - R(1)) <= eps) break;
  }
  r.steps = j;
  r.q = std::min(prefix / q * f, R(1));
  // The fraction's levels 1 + d_n D cancel where x = 1 - z is near 1 (its value f is then large,
  // ~ 1 / (z + 3 / (2q))), and x carries eps absolute, eps / z relative to z: measured, the error
  // stays below 2 f eps, charged 4 f eps (tests/kernels/area/phong_lune_test.cpp).
  const R q_error = prefix_error + (R(4 * (j + 4)) + R(4) * std::fabs(f)) * eps;
  r.p = R(1) - r.q;
  r.error = q_error * std::max(R(1), r.q / std::max(r.p, std::numeric_limits<R>::min())) + eps;
  if (j >= 512) r.error = std::numeric_limits<R>::infinity();  // did not converge: refused by any bound
  return r;
}

}  // namespace vlit
