// Linear light, specular term with the inverse-square falloff, for any real m >= 0: the Phong lobe
// integrated over the visible segment through the incomplete beta function, in O(1) for every m.
//
// What it computes: Is(exact) = ∫_0^1 [L(t).N > 0] max(0, Rv.L̂(t))^m / |L(t)|^2 dt for unit
// intensity, real m >= 0 and the falloff n = 2 on the specular (the radiometric definition for the
// usual inverse-square tube; docs/conventions.md "Radiometric definitions"), normalised like
// linear_specular_exact_frame (units of scale^-2). m = 0 is the limit m -> 0+ (the integral over
// the part of the light where Rv.L̂ > 0, core/robust_math.h phong_power).
//
// Sources: the specular integral of Picott 1992 eq. 6 along eq. 3. The reduction to one angle is
// that of linear_specular_closed.h: with the frame of linear_lobe_interval.h and ψ = θ - θ0,
//   Is = C^m W_m / (h |Ld|),   W_m = ∫ cos^m ψ dψ over [ψa, ψb] ⊂ [-π/2, π/2].
// The substitution u = sin²ψ (du = 2 sin ψ cos ψ dψ) turns the pieces of W_m into incomplete beta
// functions B(x; p, q) = ∫_0^x u^(p-1) (1 - u)^(q-1) du (Abramowitz and Stegun 6.6.1), with
// q = (m + 1) / 2 and 0 <= ψ <= π/2:
//   head H(ψ) = ∫_0^ψ cos^m = ½ B(sin²ψ; ½, q),   tail T(ψ) = ∫_ψ^(π/2) cos^m = ½ B(cos²ψ; q, ½),
// and H + T = ½ B(½, q). Each is evaluated by Boost.Math (boost::math::beta(p, q, x) and its
// complement betac) from the smaller of sin²ψ and cos²ψ, the argument the frame gives to full
// relative accuracy (the other is 1 minus it). Then:
//   - the ends on both sides of the lobe's axis (ψa <= 0 <= ψb): W = H(|ψa|) + H(ψb), a sum;
//   - both on one side, near (smaller |ψ|) and far: W = H(far) - H(near) = T(near) - T(far), heads
//     while the near end lies inside the lobe's median, tails beyond it (a highlight that misses
//     the light: tails ~ c^m, where the recurrence of linear_specular_closed.h cancels). The median
//     of u = sin²ψ under the lobe (a Beta(½, q) distribution) is about 0.2275 / q, the large-q limit
//     (χ²_1's median / 2 over q), within 10 % at q = ½ and 1. Since H(far) + T(near) = H + T + W,
//     a split near the median keeps the cancellation within a factor ~2 of the better form; a split
//     far from it (heads deep in a tail) loses every digit.
// Error estimate (condition, relative): each value times its charge (Boost's relative error with
// margin, kLinearBetaRoundoff; tests measure it against the long-double evaluation), plus at each
// end the integrand c^m times the absolute rounding of ψ there (c and sφ carry a few eps of
// (|a| + |b|)(1 + |x|) / sqrt(1 + x²)), over W;
// where the interval is short, W ~ c^m Δψ and that term is the cancellation of the two ends. The
// result is accepted when that estimate is <= max(kLinearBetaBound, 4 m eps), and the condition
// reported adds the integrand's own (m + 8) eps. Refused (the caller takes the adaptive form,
// linear_light.h linear_specular_exact_dispatch): a visible interval short against its distance
// (checked before any evaluation), a tail whose ends' rounding exceeds the bound, a non-finite value
// from Boost. A result whose absolute error bound is below the smallest normal double is accepted.
// Stiff cases: those of linear_specular_closed.h (zero length, P on the segment: exact point forms;
// h = 0: refused); m = 0 gives W = Δθ directly (Boost's double complements at q = ½ lose up to 1e7
// eps for arguments below 1e-15); m = 1e4 costs what m = 10 costs.
// Measured (double; `./build/release/tests/linear_light_tests -tc="beta-form*" -s`; reference: the
// long-double Boost.Math quadrature of linear_reference.h on the same double inputs):
//   real m log-uniform in [1, 1e3], 2000 random configurations: 86 % accepted, max rel. error
//   1.2e-13, error / estimate <= 0.71; m in [1e3, 1e4], 400: 90 % accepted, max 1.8e-12 (the
//   integrand's m eps), <= 0.99; m = 0 and m in [1e-12, 1], 400: 89 % accepted, max 4.7e-11 against
//   the reference and 6.5e-14 against the adaptive form on the same frame (below m = 1 the lobe is
//   a near-step at Rv.L = 0, whose position moves with the frame's rounding, for every method);
//   a highlight 0.25 beyond the end of the light, m = 0 .. 1e4: max 2.0e-13; the named stiff cases
//   at m = 0, 1e-12, 1, 2.5, 40, 1e4: max 1.3e-12 where accepted, 21 of 66 refused.
// Cost (`./build/release/bench/linear_light_bench --benchmark_filter=run_engine/specular_exact_n2`,
// per evaluation with the long-double frame, rows *_beta_forced): 0.7-1.2 us at m = 10 .. 1e3;
// docs/linear-lights.md.
// Float: computed in double (LinearCompute), rounded once by the caller.
#pragma once

#include <boost/math/policies/policy.hpp>
#include <boost/math/special_functions/beta.hpp>

#include <cmath>
#include <limits>

#include "core/robust_math.h"
#include "linear_geometry.h"
#include "linear_lobe_interval.h"
#include "linear_specular_closed.h"

namespace vlit {

// Accepted when the estimated relative error of the evaluation (the cancellation and rounding
// terms below, not the integrand's own m eps) is at most this, or at most 4 m eps (four times the
// integrand's own conditioning; from m = 840 on): with the (m + 8) eps added, the estimate stays
// near the ordinary bar of 1e-12 for m <= 1e3 (the estimate bounds the error: tests measure
// error / estimate <= 0.99).
inline constexpr double kLinearBetaBound = 7.5e-13;
// Relative error charged to each value, in units of eps: kLinearBetaRoundoff, and twice that plus m
// for tails from sin²ψ (the complement betac(½, q, sin²ψ)). Measured against the long-double
// evaluation on the same arguments (test "beta-form linear specular: the head and tail values within
// their charges", which asserts half of each charge and prints both maxima): heads within 22 eps,
// tails within 509 eps.
inline constexpr double kLinearBetaRoundoff = 128;

namespace linear_beta_detail {

// Boost.Math in the caller's precision (no promotion of double to long double, Boost's default), and
// no exceptions: an error gives a non-finite value, which the kernel refuses.
using Policy = boost::math::policies::policy<
    boost::math::policies::promote_double<false>, boost::math::policies::promote_float<false>,
    boost::math::policies::domain_error<boost::math::policies::ignore_error>,
    boost::math::policies::pole_error<boost::math::policies::ignore_error>,
    boost::math::policies::overflow_error<boost::math::policies::ignore_error>,
    boost::math::policies::evaluation_error<boost::math::policies::ignore_error>>;

template <class A>
struct Charged {
  A value;
  A charge;  // its relative error bound, in eps
};

// H(ψ) = ∫_0^|ψ| cos^m, from (s², c²) = (sin²ψ, cos²ψ) and q = (m + 1) / 2.
template <class A>
Charged<A> head(A s2, A c2, A q) {
  if (s2 <= c2) return {A(0.5) * boost::math::beta(A(0.5), q, s2, Policy()), A(kLinearBetaRoundoff)};
  return {A(0.5) * boost::math::betac(q, A(0.5), c2, Policy()), A(kLinearBetaRoundoff)};
}

// T(ψ) = ∫_|ψ|^(π/2) cos^m.
template <class A>
Charged<A> tail(A s2, A c2, A q) {
  if (c2 <= s2) return {A(0.5) * boost::math::beta(q, A(0.5), c2, Policy()), A(kLinearBetaRoundoff)};
  return {A(0.5) * boost::math::betac(A(0.5), q, s2, Policy()), A(2) * A(kLinearBetaRoundoff) + A(2) * q - A(1)};
}

}  // namespace linear_beta_detail

// The incomplete-beta form for falloff n = 2 and real m >= 0, normalised like
// linear_specular_exact_frame. Always returns a value; `accepted` says whether its estimated error
// is within kLinearBetaBound (callers fall back to linear_specular_exact_frame otherwise).
template <class A>
LinearSpecularClosed<A> linear_specular_beta_frame(const LinearFrame<A>& fr, A m) {
  namespace d = linear_beta_detail;
  LinearSpecularClosed<A> r;
  if (!(m >= A(0))) return r;
  if (linear_specular_special_case(fr, m, 2, r)) return r;
  const LinearLobeInterval<A> li = linear_lobe_interval(fr);
  if (li.empty) return r;
  constexpr A eps = std::numeric_limits<A>::epsilon();
  if (m == A(0)) {  // W_0 = Δψ = Δθ, without cancellation (linear_lobe_interval.h)
    r.condition = A(8) * eps;
    r.value = li.dtheta / (fr.h * fr.ell);
    return r;
  }
  // The rounding of ψ at each end: c and sφ carry a few eps of (|a| + |b|)(1 + |x|) / sqrt(1 + x²).
  // Where these alone exceed the bound against Δψ (a light short against its distance), W ~ c^m Δψ
  // cannot be accepted from the two ends' values: refused before any evaluation.
  const A ab = std::fabs(li.a) + std::fabs(li.b);
  const A round_a = A(4) * eps * ab * (A(1) + std::fabs(li.xa)) / li.ra;
  const A round_b = A(4) * eps * ab * (A(1) + std::fabs(li.xb)) / li.rb;
  if (round_a + round_b > A(kLinearBetaBound) * li.dtheta) {
    r.accepted = false;
    return r;
  }
  const A q = (m + A(1)) / A(2);
  // The ends as (sin ψ, cos ψ); ψ increases from end a to end b.
  const A sa2 = li.spa * li.spa, ca2 = li.ca * li.ca, sb2 = li.spb * li.spb, cb2 = li.cb * li.cb;
  // W from one value per end (ea, eb), heads or tails.
  A w;
  d::Charged<A> ea, eb;
  if (li.spa <= A(0) && li.spb >= A(0)) {  // the lobe's axis inside: W = H(ψa) + H(ψb)
    ea = d::head(sa2, ca2, q);
    eb = d::head(sb2, cb2, q);
    w = ea.value + eb.value;
  } else {
    // Both ends on one side: near = the end closer to the axis (a where ψ > 0, b where ψ < 0).
    const bool right = li.spa > A(0);
    const A s_near2 = right ? sa2 : sb2;
    const A median_s2 = A(0.2275) / q;
    const bool heads = s_near2 < median_s2;  // W = H(far) - H(near), else T(near) - T(far)
    ea = heads ? d::head(sa2, ca2, q) : d::tail(sa2, ca2, q);
    eb = heads ? d::head(sb2, cb2, q) : d::tail(sb2, cb2, q);
    w = (right == heads) ? eb.value - ea.value : ea.value - eb.value;
  }
  // The ends' rounding of ψ times the integrand there; a value below the smallest normal number
  // carries that number as its absolute error.
  const A err = eps * (ea.charge * ea.value + eb.charge * eb.value) + phong_power(li.ca, m) * round_a +
                phong_power(li.cb, m) * round_b + A(2) * std::numeric_limits<A>::min();
  if (!std::isfinite(w) || !std::isfinite(err)) {
    r.accepted = false;
    return r;
  }
  w = std::fmax(w, A(0));
  // Accepted on the evaluation's own error; the condition reported adds the integrand's (m + 8) eps
  // (the rounding of C and c raised to the power m), which every method shares.
  const A evaluation = w > A(0) ? err / w : std::numeric_limits<A>::infinity();
  // Also accepted: a result whose absolute error bound is below the smallest normal number (lobe
  // tails that underflow).
  const A factor = std::pow(li.big_c, m) / (fr.h * fr.ell);
  r.accepted = evaluation <= std::fmax(A(kLinearBetaBound), A(4) * m * eps) || err * factor < std::numeric_limits<A>::min();
  r.condition = evaluation + (m + A(8)) * eps;
  r.value = factor * w;
  return r;
}

}  // namespace vlit
