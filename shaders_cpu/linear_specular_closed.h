// Linear light, specular term, closed form for integer m: the Phong lobe integrated over the
// visible segment by a recurrence in m.
//
// What it computes: Is(exact) = ∫_0^1 [L(t).N > 0] max(0, Rv.L̂(t))^m / |L(t)|^n dt for unit
// intensity, integer m >= 0 and falloff n = 0 (the paper's form) or n = 2 (the radiometric
// definition for the usual inverse-square light), the quantity linear_specular_exact.h integrates
// adaptively (docs/conventions.md "Radiometric definitions"; m = 0 is the limit m -> 0+,
// core/robust_math.h phong_power). Other n are refused (the caller uses the adaptive form).
//
// Sources: the specular integral of Picott 1992 eq. 6 along eq. 3; the idea of a recurrence in
// the exponent is that of Poulin and Amanatides 1991 ("Shading and shadowing with linear light
// sources"); the recurrence below is derived here. Conventions: conventions.h, frame of
// linear_geometry.h (L(s) = H + s u, |L|^2 = h^2 + s^2, Rv.L = ar + br s, dt = ds / |Ld|).
//
// Derivation. Clip the visible interval [sa, sb] to the lobe's half-space ar + br s >= 0, so that
// max(0, .) is the identity on it. With s = h x = h tan θ (θ the angle of L from the foot direction
// H, ds = h sec²θ dθ), Rv.L̂ = A cos θ + B sin θ with A = ar / h = Rv.Ĥ, B = br = Rv.u. Write
// A = C cos θ0, B = C sin θ0 (C = |(A, B)| <= 1), a = cos θ0, b = sin θ0,
// c = cos(θ - θ0) = (a + b x) / sqrt(1 + x^2), sφ = sin(θ - θ0) = (a x - b) / sqrt(1 + x^2). Then
//   Is = h C^m U_m / |Ld|,   U_k = ∫ c^k sec²θ dθ = ∫ c^k dx,   W_k = ∫ c^k dθ
// over the clipped interval. With the inverse-square falloff, |L|^2 = h² sec²θ cancels sec²θ:
//   Is(n = 2) = C^m W_m / (h |Ld|),
// W alone (the classical reduction below, m/2 steps), with the same magnitude bookkeeping. W has the classical reduction k W_k = [c^(k-1) sφ] + (k - 1) W_(k-2).
// For U: integrate by parts against d tan θ (dc/dθ = -sφ, and sφ tan θ = a sec θ - c), which
// brings in V_j = ∫ c^j sec θ dθ; c sec θ = a + b tan θ brings in Y_j = ∫ c^j tan θ dθ, and one
// more integration by parts of Y_j (sin θ = b c + a sφ, c sec θ tan θ = a tan θ + b (sec²θ - 1))
// closes the system: a j Y_j = b j W_j + b U_j - [c^(j+1) sec θ]. Eliminating V and Y, for k >= 3,
//   U_k = [c^k x] - [c^(k-1) sφ] - (k / (k - 2)) b [c^(k-1) sqrt(1 + x^2)] + W_(k-2)
//         + (k / (k - 2)) b^2 U_(k-2),
// ([f] = f(x_b) - f(x_a)), started from
//   U_0 = x_b - x_a,   U_1 = a [asinh x] + b [sqrt(1 + x^2)],
//   U_2 = (a^2 - b^2) Δθ + a b [log(1 + x^2)] + b^2 [x],   W_0 = Δθ,   W_1 = [sφ],
// with the differences in forms without cancellation (x_b - x_a from the frame's interval length,
// asinh and log identities, the half-angle form of [sφ], Δθ = atan2(x_b - x_a, 1 + x_a x_b)).
// Only the chain of the parity of m is run: m/2 steps of about twenty flops. (Checked term by
// term against a 40-digit quadrature while deriving; the tests below check the result.)
//
// Where it loses digits (measured in tests/kernels/linear/linear_specular_closed_test.cpp,
// "where the recurrence loses digits it is refused"):
// - the lobe's axis outside the clipped interval (a highlight that misses the light): U_m is a
//   tail ~ c_max^m while W and the U-chain carry terms ~ k^-1/2 and the forward recurrence cancels
//   (axis 0.25 beyond the end of a unit segment at distance 1: relative error 1.9e-12 at m = 300,
//   2.9e-7 at m = 1000, 100 % at m = 3000);
// - short visible intervals (far lights, Δθ << 1): every bracket [f] cancels by Δθ;
// - h << |s| (near-collinear): [c^k x] with x = s/h large cancels with the other brackets;
// - everywhere, the rounding of c raised to the power m: relative error ~ m eps, the conditioning
//   of the integrand itself (the adaptive form has it too: 9e-13 at m = 1e4 in both).
// So the recurrences also carry M_m, the sum of the absolute values of every term entering U_m,
// and the result is accepted only when
//   condition = (m + 8) eps M_m / U_m <= kLinearClosedBound = 5e-12  and  M_m / U_m <= 64;
// otherwise the caller uses the adaptive form (linear_specular_exact_dispatch in linear_light.h).
// The estimate bounds the error: measured error / condition <= 0.96 on 1374 accepted random cases
// with m in [1, 1e3] and <= 1.005 on 225 with m in [1e3, 1e4] (tests assert <= 2). The cap on
// M/U is needed because the rounding of the inputs (x, a, b), which M does not count, dominates
// under heavy cancellation (error 11x the estimate at M/U = 550, m = 4, before the cap).
//
// The W chain (n = 2) carries the same estimate, with the absolute rounding of sφ at the ends
// (eps (|a x| + |b|) / sqrt(1 + x^2), not eps |sφ|) and of the angle in W_1's half-angle form
// counted in its magnitude: without them a 1e-6 light with the lobe's axis on it was accepted at
// m = 40 with error 6.5e-11 against an estimate of 4e-14.
// Measured accuracy (double; long-double Boost.Math reference of linear_reference.h on the frame's
// double inputs, the falloff in its integrand; `./build/release/tests/linear_light_tests -tc="closed-form*" -s`):
//   n = 0: random, m integer log-uniform in [1, 1e3], 2000 seeds: 69 % accepted, max rel. error 9.7e-14;
//   random, m in [1e3, 1e4], 400 seeds: 56 % accepted, max 1.8e-12 (the m eps of the integrand);
//   n = 2: 73 % accepted, max 1.2e-13, error / estimate <= 0.94; m in [1e3, 1e4]: 55 %, max
//   1.8e-12, <= 0.95; the named stiff cases below at m = 0, 1e-12, 1, 40, 1e4: max 9.5e-13;
//   named stiff cases (collinear, near-collinear, far 1e6, near 1e-6, crossing horizon, endpoint
//   on the tangent plane, grazing, zero-length, P on the segment, tiny 1e-6, huge 1e6) at
//   m = 0, 1, 40, 1e4 through `--specular exact`: max 9.5e-13, all finite.
// Float: the float instantiation computes in double (LinearCompute) and rounds once.
// Cost (`./build/release/bench/linear_light_bench --benchmark_filter=run_engine/specular_exact_n0`, CPU time per
// evaluation including the long-double frame, n = 0): closed form 0.49 us for m in [1, 100] and
// 10 us for m in [1e2, 1e4] (O(m)); adaptive 8.7 us and 14.5 us on the same cases. The W chain
// (n = 2) is a subset of the U chain's work per step.
// Stiff cases: zero-length and P on the segment take the exact point forms of
// linear_specular_exact.h; h = 0 (collinear) is refused (the adaptive form's direction is ±u);
// a lobe that misses the clipped interval entirely gives 0 exactly; C = 0 (Rv normal to the plane
// of P and the line) gives 0.
#pragma once

#include <cmath>
#include <limits>

#include "core/robust_math.h"
#include "linear_geometry.h"
#include "linear_lobe_interval.h"

namespace vlit {

// The acceptance bound of the closed form: (m + 8) eps M_m / U_m (see above).
inline constexpr double kLinearClosedBound = 5e-12;
// Largest cancellation factor M_m / U_m accepted, whatever m: beyond it the rounding of the
// inputs (x, a, b: a few eps each), which M_m does not count, dominates (measured: 11x the estimate
// at M/U = 550, m = 4).
inline constexpr double kLinearClosedMaxCancellation = 64;
// Largest m the recurrence is run for (m/2 steps); above it the adaptive form is used.
inline constexpr int kLinearClosedMaxShininess = 100000;
// The dispatch (linear_light.h) uses this form for n = 0 up to here only: above it, its O(m)
// recurrence (plus the adaptive form on the cases it refuses) costs more than the adaptive form
// alone (bench specular_exact_n0_m_*: even at m = 1e3; the recurrence alone 3.3x the adaptive form
// at m = 3e3; docs/linear-lights.md).
inline constexpr int kLinearClosedDispatchMaxShininess = 1000;
// With the falloff n = 2 the dispatch runs the W recurrence for integer m up to here only; above it
// the incomplete-beta form (linear_specular_beta.h, O(1) in m) is the faster one (bench
// specular_exact_n2_m_*_closed_forced against *_beta_forced: slower at m = 100, faster at m = 300).
inline constexpr int kLinearRecurrenceMaxShininess = 200;

template <class A>
struct LinearSpecularClosed {
  A value{0};       // Is, normalised as linear_specular_exact_frame's result
  A condition{0};   // (m + 8) eps M_m / U_m: the estimated relative rounding error
  bool accepted = false;  // condition <= kLinearClosedBound (or an exact special case)
};

// Closed form for integer m >= 0 and falloff n in {0, 2}, normalised like
// linear_specular_exact_frame (units of scale^-n). Always returns a value; `accepted` says whether
// it is within the bound (callers fall back to linear_specular_exact_frame otherwise; always for
// other n).
// The frame's special cases, shared by the closed forms (falloff n = 0 or 2, real m >= 0): empty,
// zero length (the point form), P on the segment (n = 2: ∫ ds / s² diverges at P; 0, as the
// diffuse), collinear (refused: the adaptive form handles the constant direction). Returns true
// when `r` holds the answer.
template <class A>
bool linear_specular_special_case(const LinearFrame<A>& fr, A m, int n, LinearSpecularClosed<A>& r) {
  r.accepted = true;
  if (fr.empty) return true;
  if (fr.zero_length) {
    r.value = fr.mid_cos_n > A(0) ? phong_power(fr.mid_cos_rv, m) : A(0);
    if (n == 2) r.value /= fr.mid_r * fr.mid_r;
    return true;
  }
  if (fr.on_segment) {
    r.value = n == 0 ? phong_power(linear_cos_rv(fr, fr.sb), m) * fr.delta / fr.ell : A(0);
    return true;
  }
  if (!(fr.h > A(0))) {
    r.accepted = false;
    return true;
  }
  return false;
}

template <class A>
LinearSpecularClosed<A> linear_specular_closed_frame(const LinearFrame<A>& fr, int m, int n = 0) {
  LinearSpecularClosed<A> r;
  if (n != 0 && n != 2) return r;
  const A mm = A(m);
  if (linear_specular_special_case(fr, mm, n, r)) return r;
  const LinearLobeInterval<A> li = linear_lobe_interval(fr);
  if (li.empty) return r;
  const A big_c = li.big_c, a = li.a, b = li.b, xa = li.xa, xb = li.xb, ra = li.ra, rb = li.rb;
  const A ca = li.ca, cb = li.cb, spa = li.spa, spb = li.spb, dx = li.dx, dtheta = li.dtheta;
  // The angles of both ends and of the lobe's axis, for W_1's half-angle form.
  const A theta_a = std::atan(xa), theta_b = std::atan(xb), theta0 = std::atan2(b, a);
  // [sqrt(1 + x^2)] = (x_b - x_a)(x_b + x_a) / (r_b + r_a): no cancellation.
  const A dsec = dx * (xb + xa) / (rb + ra);
  constexpr A eps = std::numeric_limits<A>::epsilon();

  if (n == 2) {
    // W_m by k W_k = [c^(k-1) sφ] + (k - 1) W_(k-2), from W_0 = Δθ or W_1 = [sφ].
    A w_val, w_mag, q_a, q_b;  // q = c^(k-1) at both ends for the next k
    int k;
    if (m % 2 == 0) {
      w_val = dtheta;
      q_a = ca;
      q_b = cb;
      k = 2;
    } else {
      w_val = A(2) * std::cos((theta_a + theta_b) / A(2) - theta0) * std::sin(dtheta / A(2));
      q_a = ca * ca;
      q_b = cb * cb;
      k = 3;
    }
    // |W_0| or |W_1|, and for W_1 the rounding of the angle in its cosine (absolute error about
    // eps (|θa| + |θb| + 2|θ0|) / 2, which cancels when the lobe's axis is near π/2 off the
    // interval's middle).
    w_mag = std::fabs(w_val);
    if (m % 2 == 1)
      w_mag += std::fabs(std::sin(dtheta / A(2))) * (std::fabs(theta_a) + std::fabs(theta_b) + A(2) * std::fabs(theta0));
    // sφ at an end carries an absolute rounding error of about eps (|a x| + |b|) / sqrt(1 + x^2),
    // not eps |sφ|: where the lobe's axis is on a short light, sφ ~ 0 at both ends and [c^(k-1) sφ]
    // is the difference of two such roundings (measured: 6.5e-11 at m = 40 on a 1e-6 light before
    // this was counted).
    const A spa_mag = (std::fabs(a * xa) + std::fabs(b)) / ra, spb_mag = (std::fabs(a * xb) + std::fabs(b)) / rb;
    for (; k <= m; k += 2) {
      const A kk = A(k);
      const A wb = q_b * spb, wa = q_a * spa;
      w_val = (wb - wa + (kk - A(1)) * w_val) / kk;
      w_mag = (q_b * spb_mag + q_a * spa_mag + (kk - A(1)) * w_mag) / kk;
      q_a *= ca * ca;
      q_b *= cb * cb;
    }
    r.condition = w_val > A(0) ? A(m + 8) * eps * w_mag / w_val : std::numeric_limits<A>::infinity();
    r.accepted = r.condition <= A(kLinearClosedBound) && w_mag <= A(kLinearClosedMaxCancellation) * w_val;
    r.value = std::fmax(std::pow(big_c, mm) * w_val / (fr.h * fr.ell), A(0));
    return r;
  }

  A u_val, u_mag;  // U_k of the chain and the magnitude of its terms
  A w_val, w_mag;  // W_(k-2) of the chain
  int k;
  if (m % 2 == 0) {
    // U_0 (m = 0) and U_2; W_0 = Δθ, W_2 from it.
    if (m == 0) {
      u_val = dx;
      u_mag = std::fabs(dx);
    } else {
      // [log(1 + x^2)]: log1p of the relative change when it is small, else 2 log(r_b / r_a)
      // (log1p near -1 would turn the rounding of its argument into a large relative error).
      const A change = dx * (xb + xa) / (A(1) + xa * xa);
      const A dlog = std::fabs(change) < A(0.5) ? std::log1p(change) : A(2) * std::log(rb / ra);
      const A t1 = (a * a - b * b) * dtheta, t2 = a * b * dlog, t3 = b * b * dx;
      u_val = t1 + t2 + t3;
      u_mag = std::fabs(t1) + std::fabs(t2) + std::fabs(t3);
    }
    w_val = dtheta;  // W_0: the W needed by U_4 is W_2, advanced below
    w_mag = std::fabs(dtheta);
    k = 4;
  } else {
    // [asinh x] without cancellation when x_a and x_b have the same sign.
    A dasinh;
    if (xa >= A(0) || xb <= A(0)) dasinh = std::asinh(dx * (xb + xa) / (xb * ra + xa * rb));
    else dasinh = std::asinh(xb) - std::asinh(xa);
    const A t1 = a * dasinh, t2 = b * dsec;
    u_val = t1 + t2;
    u_mag = std::fabs(t1) + std::fabs(t2);
    // W_1 = [sφ] = 2 cos(θ_mid - θ0) sin(Δθ / 2).
    w_val = A(2) * std::cos((theta_a + theta_b) / A(2) - theta0) * std::sin(dtheta / A(2));
    w_mag = std::fabs(w_val);
    k = 3;
  }
  if (m >= 3) {
    // Powers c^(k-1) at both ends for the first step, then times c^2 per step.
    const A ca2 = ca * ca, cb2 = cb * cb;
    A pa = k == 3 ? ca * ca : ca * ca * ca;  // c^(k-1)
    A pb = k == 3 ? cb * cb : cb * cb * cb;
    A qa = k == 3 ? A(1) : ca;               // c^(k-3), for W_(k-2) = ([c^(k-3) sφ] + (k-3) W_(k-4)) / (k-2)
    A qb = k == 3 ? A(1) : cb;
    const A b2 = b * b;
    for (; k <= m; k += 2) {
      // W_(k-2) from W_(k-4) (k = 4: W_2 from W_0; k = 3: W_1 is the start).
      if (k >= 4) {
        const A j = A(k - 2);
        const A wb = qb * spb, wa = qa * spa;
        w_val = (wb - wa + (j - A(1)) * w_val) / j;
        w_mag = (std::fabs(wb) + std::fabs(wa) + (j - A(1)) * w_mag) / j;
      }
      qa *= ca2;
      qb *= cb2;
      const A kk = A(k), ratio = kk / A(k - 2);
      const A b1 = pb * cb * xb - pa * ca * xa;        // [c^k x]
      const A b2t = pb * spb - pa * spa;               // [c^(k-1) sφ]
      const A b3 = pb * rb - pa * ra;                  // [c^(k-1) sqrt(1 + x^2)]
      const A mag_b = std::fabs(pb * cb * xb) + std::fabs(pa * ca * xa) + std::fabs(pb * spb) + std::fabs(pa * spa) +
                      ratio * std::fabs(b) * (pb * rb + pa * ra);
      u_val = b1 - b2t - ratio * b * b3 + w_val + ratio * b2 * u_val;
      u_mag = mag_b + w_mag + ratio * b2 * u_mag;
      pa *= ca2;
      pb *= cb2;
    }
  }
  const A u_m = u_val;
  r.condition = u_m > A(0) ? A(m + 8) * eps * u_mag / u_m : std::numeric_limits<A>::infinity();
  r.accepted = r.condition <= A(kLinearClosedBound) && u_mag <= A(kLinearClosedMaxCancellation) * u_m;
  r.value = std::fmax(fr.h * std::pow(big_c, mm) * u_m / fr.ell, A(0));
  return r;
}

}  // namespace vlit
