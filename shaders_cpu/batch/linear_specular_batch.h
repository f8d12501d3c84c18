// Linear (tube) light, exact specular with the inverse-square falloff, batch: the W recurrence of
// linear_specular_closed.h (integer m) across structure-of-arrays lanes, set up without trigonometry.
//
// What it computes: Is(exact) = ∫_0^1 [L(t).N > 0] max(0, Rv.L̂(t))^m / |L(t)|^2 dt (unit intensity,
// ks = 1; Picott 1992 eq. 6 along eq. 3, with the diffuse's falloff n = 2 as docs/conventions.md
// "Radiometric definitions" define it), integer 0 <= m <= kLinearSpecularBatchMaxShininess, the
// quantity of linear_specular_closed.h's n = 2 chain: Is = C^m W_m / (h |Ld|) in the frame of
// linear_geometry.h (L(s) = H + s u, s = h x = h tan θ) and of linear_lobe_interval.h (the visible
// interval clipped to the lobe's half-space; Rv.L̂ = C cos(θ - θ0), c = cos(θ - θ0),
// sφ = sin(θ - θ0)), with k W_k = [c^(k-1) sφ] + (k - 1) W_(k-2).
//
// Differences from the scalar closed form, all in the set-up (the chain is the same):
// - the frame in double, not long double, from the light's own unit direction u (as
//   linear_diffuse_batch.h); its rounding (absolute eps in the normalised H, so eps / h relative in
//   x = s / h and in A = Rv.H / h) is counted in the acceptance test below;
// - no atan, sin or cos. With tan(Δθ / 2) = sin Δθ / (1 + cos Δθ) and sin Δθ = (x_b - x_a) / (r_a r_b),
//   cos Δθ = (1 + x_a x_b) / (r_a r_b) (r = sqrt(1 + x^2)):
//     t = tan(Δθ / 2) = (x_b - x_a) / D,   D = 1 + r_a r_b + x_a x_b,
//   D written as 1 + (1 + x_a^2 + x_b^2) / (r_a r_b - x_a x_b) when x_a x_b < 0 (the same value, a
//   sum of positive terms: r_a^2 r_b^2 - x_a^2 x_b^2 = 1 + x_a^2 + x_b^2), so t has full relative
//   precision for every interval;
//     W_0 = Δθ = 2 atan(t) (double_atan.h),
//     W_1 = [sφ] = 2 cos(θ_mid - θ0) sin(Δθ / 2) = (c_a + c_b) t   (c_a + c_b = 2 cos(θ_mid - θ0) cos(Δθ / 2)),
//   where the scalar form takes three atan, a cos and a sin; W_1's magnitude counts the absolute
//   rounding of c at both ends, eps (|a| + |b x|) / r, instead of the angles';
// - C^m as exp(m ln C) (double_log.h, double_exp.h), as punctual_specular_batch.h.
// - tails (both ends on one side of the lobe's axis, where the forward chain cancels: W ~ c_max^m
//   against terms ~ k^-1/2) also run backward chains, which have no cancellation. Mirrored so that
//   0 < ψn < ψf <= π/2 (ψ = θ - θ0, near end n, far end f, s = sφ > 0), W_m = T_m(ψn) - T_m(ψf)
//   with T_k(ψ) = ∫_ψ^(π/2) cos^k, for which k T_k = (k - 1) T_(k-2) - c^(k-1) s (k >= 2). Scaled,
//   U_k = T_k / c^(k+1):
//     U_(k-2) = (k c^2 U_k + s) / (k - 1)   (all terms positive),
//   started at K = m + 2 linear_backward_steps(m) = 3m + 32 from the leading term of the asymptotic series,
//   U_K = 1 / ((K + 1) s); integrating by parts once, T_K = c^(K+1) / ((K + 1) s) - R with
//   0 <= R <= T_(K+2) / ((K + 1) s^2) <= c^2 T_K / ((K + 1) s^2), which bounds the start's relative
//   error; each step down multiplies that error by k c^2 / (k - 1) while U grows by more, and the
//   bound is carried along. Then W_m = cn^(m+1) (U_m(n) - ρ^(m+1) U_m(f)), ρ = cf / cn.
// Acceptance. Each chain has an error estimate: forward, (m + 8) eps M / W
// (linear_specular_closed.h) times (1 + 1 / h) for the double frame's rounding; backward, the
// rounding of its steps and of the power, the start error carried down, and the difference's
// cancellation; both add the ends' rounding (their positions, a few eps of the largest s, and c),
// as an angle times c^m there. A lane takes the chain with the smaller estimate among those at
// most kLinearSpecularBatchBound = 1e-9, the exact specular's own tolerance
// (SpecularOptions::exact_tolerance, which the scalar adaptive form meets); looser than the scalar
// closed form's 5e-12, so the batch computes most tails the scalar closed form refuses (and
// integrates adaptively). A lane neither chain vouches for is flagged (BatchSpecularOutput::stiff)
// and recomputed by the caller with the scalar exact kernel: in the tests, far and tiny lights at
// m >= 40 (short intervals cancel in both), P within 1e-6 of the line. Also flagged: a light shorter than eps of its
// distance (the point-light limit), P at both endpoints or on the line (h = 0), an end within 2e-7
// of P's tangent plane, and a lane whose horizon cut hangs on the float normal: the lanes' normals
// are float (batch_points.h) while the bake's scalar kernel sees the double normal, and unlike the
// diffuse the specular's integrand f need not vanish where the segment crosses the tangent plane,
// so a normal rounded by ~1e-7 moves the cut by Δt ~ 1e-7 / |L̂0.N - L̂1.N| and the result by
// f(t_cut) Δt; flagged where that exceeds 1e-6 of the result.
// Measured (tests/kernels/batch/batch_specular_test.cpp "linear specular batch ...", against the
// scalar exact kernel at tolerance 2e-12, same float normal; the random set: 12 tubes of length
// 1e-2 to 1e1, 700 points each, m = 0, 1, 2, 3, 40, 41, 100, 200): every accepted lane within 2e-9
// (the test's bar), 430 of 67200 lanes flagged. The forward estimate alone is not a bound in deep
// tails: on the test's "deep tails" lanes (m = 2) the forward chain passes its test with errors
// above the test's bar (the case fails when the forward chain is taken there), and the backward
// chains, whose estimate is smaller, are taken. Speed and the
// benchmark's errors: docs/performance.md ("Batch specular").
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

#include "batch/double_atan.h"
#include "batch/linear_diffuse_batch.h"
#include "batch/punctual_specular_batch.h"
#include "linear_specular_closed.h"

namespace vlit {

// Integer m up to here: the scalar dispatch's limit for this chain (linear_specular_closed.h);
// above it the scalar incomplete-beta form is the faster.
inline constexpr int kLinearSpecularBatchMaxShininess = kLinearRecurrenceMaxShininess;
// Largest accepted error estimate of a lane (see above).
inline constexpr double kLinearSpecularBatchBound = 1e-9;

namespace batch_detail {

// Steps of the backward chains for shininess m: they start at m + 2 linear_backward_steps(m) from
// the leading term of the tail's asymptotic series, whose error shrinks by c^2 per step.
constexpr int linear_backward_steps(int m) { return m + 16; }

constexpr int kLinearSpecularBlock = 128;

// atan(t) for t >= 0 (finite or +inf), from atan_unit: π/2 - atan(1/t) above 1.
inline double atan_nonnegative(double t) {
  constexpr double kHalfPi = 1.57079632679489661923;
  const bool high = t > 1.;
  const double r = atan_unit(high ? 1. / t : t);
  return high ? kHalfPi - r : r;
}

// One block of lanes between the stages (lane l at [l]). The stages are separate loops over the
// lanes so that each vectorises: GCC if-converts only innermost loops, so a lane loop holding the
// chains' loops would keep its branches.
struct LinearSpecularBlock {
  static constexpr int B = kLinearSpecularBlock;
  // c at the clipped interval's ends a, b (forward chain, finish) and at the tails' near and far
  // ends n, f (backward chains, finish).
  double ca[B], cb[B], cn[B], cf[B];
  // Forward chain: W, its magnitude, c^(k-1) at both ends, sφ and its magnitude there.
  double w[B], w_mag[B], qa[B], qb[B], spa[B], spb[B], spa_mag[B], spb_mag[B];
  // Backward chains (tails): U at the near and far ends, their start errors, sφ there.
  double un[B], uf[B], en[B], ef[B], sn[B], sf[B];
  // Finishing: C, h |Ld|, scale^-2, the frame's rounding factor, the ends' input rounding terms,
  // the horizon cut's sensitivity; flags as 0 or 1.
  double big_c[B], h_ell[B], scale2[B], frame[B], dpa[B], dpb[B], dcn[B], dcf[B], cut[B];
  double tail[B], empty[B], stiff[B];
};

// Stage 1 for lane l: the frame, both clips and the chains' start values (see the file comment).
template <bool kOdd>
inline void linear_specular_setup(const LinearBatchLight& L, int m, double px, double py, double pz, float nxf, float nyf,
                                  float nzf, double rvx, double rvy, double rvz, int l, LinearSpecularBlock& k_) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  const double nx = nxf, ny = nyf, nz = nzf;
  const double ux = L.u[0], uy = L.u[1], uz = L.u[2];
  // The frame of linear_geometry.h in lengths divided by scale = max(|L0|, |L1|).
  double l0x = L.q0[0] - px, l0y = L.q0[1] - py, l0z = L.q0[2] - pz;
  double l1x = L.q1[0] - px, l1y = L.q1[1] - py, l1z = L.q1[2] - pz;
  const double r0sq = l0x * l0x + l0y * l0y + l0z * l0z, r1sq = l1x * l1x + l1y * l1y + l1z * l1z;
  const double scale = std::sqrt(r0sq > r1sq ? r0sq : r1sq);
  const bool scale_ok = scale > 0.;
  const double inv = scale_ok ? 1. / scale : 0.;
  l0x *= inv; l0y *= inv; l0z *= inv;
  l1x *= inv; l1y *= inv; l1z *= inv;
  const double ell = L.length * inv;
  const double s0 = l0x * ux + l0y * uy + l0z * uz, s1 = l1x * ux + l1y * uy + l1z * uz;
  const double hx = l0x - ux * s0, hy = l0y - uy * s0, hz = l0z - uz * s0;
  const double h = std::sqrt(hx * hx + hy * hy + hz * hz);
  const double hs = h > 0. ? h : 1.;
  // Horizon clipping in t from the endpoint values L0.N, L1.N (linear_geometry.h).
  const double c0 = l0x * nx + l0y * ny + l0z * nz, c1 = l1x * nx + l1y * ny + l1z * nz;
  const bool both_in = (c0 >= 0.) & (c1 >= 0.);
  const bool both_out = !both_in & (c0 <= 0.) & (c1 <= 0.);
  const bool in_plane = (c0 == 0.) & (c1 == 0.);
  const bool crossing = !(both_in | both_out);
  const double dc = c0 - c1;
  const double tc = crossing ? c0 / dc : 0.;
  const bool cut_end = crossing & (c0 > 0.);    // visible from Q0 to the cut
  const bool cut_start = crossing & !(c0 > 0.);  // visible from the cut to Q1
  const double ta = cut_start ? tc : 0., tb = cut_end ? tc : 1.;
  const double sa = cut_start ? s0 + ta * ell : s0;
  const double sb_raw = cut_end ? s0 + tb * ell : s1;
  const double sb = sb_raw > sa ? sb_raw : sa;
  const double delta = (tb - ta) * ell;
  // The lobe's half-space ar + br s >= 0 (linear_lobe_interval.h), lengths as offsets from sa.
  const double rv_h = rvx * hx + rvy * hy + rvz * hz, br = rvx * ux + rvy * uy + rvz * uz;
  const double s_zero = -rv_h / (br != 0. ? br : 1.);
  const bool raise_lo = (br > 0.) & (s_zero > sa), lower_hi = (br < 0.) & (s_zero < sb);
  const double lo = raise_lo ? s_zero : sa, hi = lower_hi ? s_zero : sb;
  const double tau_lo = raise_lo ? s_zero - sa : 0., tau_hi = lower_hi ? s_zero - sa : delta;
  const double big_a = rv_h / hs;
  const double big_c = std::sqrt(big_a * big_a + br * br);
  const double cs = big_c > 0. ? big_c : 1.;
  // Sums of 0/1 terms rather than boolean expressions, which GCC 12 does not vectorise here.
  const double empty = (both_out | in_plane ? 1. : 0.) + (delta > 0. ? 0. : 1.) + ((br == 0.) & !(rv_h > 0.) ? 1. : 0.) +
                       (hi > lo ? 0. : 1.) + (tau_hi > tau_lo ? 0. : 1.) + (big_c > 0. ? 0. : 1.);
  const double a = big_a / cs, b = br / cs;
  const double xa = lo / hs, xb = hi / hs;
  const double ra = std::sqrt(1. + xa * xa), rb = std::sqrt(1. + xb * xb);
  const double ca_raw = (a + b * xa) / ra, cb_raw = (a + b * xb) / rb;
  const double ca = ca_raw > 0. ? ca_raw : 0., cb = cb_raw > 0. ? cb_raw : 0.;
  const double spa = (a * xa - b) / ra, spb = (a * xb - b) / rb;
  const double dx = (tau_hi - tau_lo) / hs;
  const double xab = xa * xb, rab = ra * rb;
  const double den = xab >= 0. ? 1. + rab + xab : 1. + (1. + xa * xa + xb * xb) / (rab - xab);
  const double tan_half = dx / den;  // tan(Δθ / 2)
  const double aa = std::fabs(a), ab = std::fabs(b);
  // Forward chain's start: W_1, c^2 (odd m) or W_0, c (even m).
  if constexpr (kOdd) {
    k_.w[l] = (ca + cb) * tan_half;
    k_.w_mag[l] = ((aa + ab * std::fabs(xa)) / ra + (aa + ab * std::fabs(xb)) / rb) * tan_half;
    k_.qa[l] = ca * ca;
    k_.qb[l] = cb * cb;
  } else {
    const double w0 = 2. * atan_nonnegative(tan_half);
    k_.w[l] = w0;
    k_.w_mag[l] = w0;
    k_.qa[l] = ca;
    k_.qb[l] = cb;
  }
  k_.spa[l] = spa;
  k_.spb[l] = spb;
  k_.spa_mag[l] = (aa * std::fabs(xa) + ab) / ra;
  k_.spb_mag[l] = (aa * std::fabs(xb) + ab) / rb;
  // Backward chains' start (tails: both ends on one side of the lobe's axis). Near end n (the
  // larger c), far end f, sφ > 0 at both after mirroring; U_K = 1 / ((K + 1) sφ), the leading term
  // of T_K / c^(K+1), with the bound c^2 / ((K + 1) sφ^2) on its relative error.
  const bool near_a = spa > 0.;
  const double cn = near_a ? ca : cb, sn = near_a ? spa : -spb, xn = near_a ? xa : xb, rn = near_a ? ra : rb;
  const double cf = near_a ? cb : ca, sf = near_a ? spb : -spa, xf = near_a ? xb : xa, rf = near_a ? rb : ra;
  const bool tail_ok = (spa * spb > 0.) & (cn > 0.);
  const double cn_t = tail_ok ? cn : 1., sn_t = tail_ok ? sn : 1., sf_t = tail_ok ? sf : 1., cf_t = tail_ok ? cf : 0.;
  const double top1 = double(m + 2 * linear_backward_steps(m) + 1);
  const double un = 1. / (top1 * sn_t), uf = 1. / (top1 * sf_t);
  k_.un[l] = un;
  k_.uf[l] = uf;
  k_.en[l] = un * cn_t * cn_t / (top1 * sn_t * sn_t);
  k_.ef[l] = uf * cf_t * cf_t / (top1 * sf_t * sf_t);
  k_.sn[l] = sn_t;
  k_.sf[l] = sf_t;
  // Finishing values.
  const double frame = 1. + 1. / hs;  // the double frame's rounding, relative (see the file comment)
  k_.big_c[l] = big_c;
  k_.cn[l] = cn_t;
  k_.cf[l] = cf_t;
  k_.h_ell[l] = hs * ell;
  k_.scale2[l] = inv * inv;
  k_.frame[l] = frame;
  // The rounding of the ends' positions (sums and differences of s0, s1, the cut and the lobe's
  // limit: a few eps of the largest), as an angle at each end, dθ = ds / (h (1 + x^2)); and of c at
  // the tails' ends, as an angle dc / sφ. Times c^m at the end, they move W (finish stage).
  const double position = 4. * eps * frame * (std::fabs(lo) + std::fabs(hi) + std::fabs(sa) + std::fabs(sb) + ell);
  k_.ca[l] = ca;
  k_.cb[l] = cb;
  k_.dpa[l] = position / (hs * (1. + xa * xa));
  k_.dpb[l] = position / (hs * (1. + xb * xb));
  k_.dcn[l] = eps * frame * (aa + ab * std::fabs(xn)) / rn / (cn_t * sn_t) + (near_a ? k_.dpa[l] : k_.dpb[l]) / cn_t;
  k_.dcf[l] = eps * frame * (aa + ab * std::fabs(xf)) / rf / (cn_t * sf_t) + (near_a ? k_.dpb[l] : k_.dpa[l]) / cn_t;
  // The horizon cut's dependence on the float normal (see the file comment): the integrand at the
  // cut times the cut's possible move (compared with the result at the end); an end within 2e-7
  // of the plane.
  const double lcx = l0x + tc * (l1x - l0x), lcy = l0y + tc * (l1y - l0y), lcz = l0z + tc * (l1z - l0z);
  const double lc2 = lcx * lcx + lcy * lcy + lcz * lcz;
  const double lc2s = lc2 > 0. ? lc2 : 1.;
  const double cos_cut = (rvx * lcx + rvy * lcy + rvz * lcz) / std::sqrt(lc2s);
  const double f_cut = phong_power_lane(cos_cut, double(m)) / lc2s;
  k_.cut[l] = crossing ? f_cut * 1e-7 / (dc != 0. ? std::fabs(dc) : 1.) : 0.;
  k_.tail[l] = tail_ok ? 1. : 0.;
  k_.empty[l] = empty;
  k_.stiff[l] = (scale_ok ? 0. : 1.) + (L.length > eps * scale ? 0. : 1.) + (h > 0. ? 0. : 1.) +
                (std::fabs(c0) <= 2e-7 ? 1. : 0.) + (std::fabs(c1) <= 2e-7 ? 1. : 0.);
}

// Stage 2: the forward chain k W_k = [c^(k-1) sφ] + (k - 1) W_(k-2), k = k0, k0 + 2, .., m.
inline void linear_specular_forward(int k0, int m, int lanes, LinearSpecularBlock& b) {
  for (int k = k0; k <= m; k += 2) {
    const double kk = double(k), inv_k = 1. / kk, km1 = kk - 1.;
#pragma omp simd
    for (int l = 0; l < lanes; ++l) {
      b.w[l] = (b.qb[l] * b.spb[l] - b.qa[l] * b.spa[l] + km1 * b.w[l]) * inv_k;
      b.w_mag[l] = (b.qb[l] * b.spb_mag[l] + b.qa[l] * b.spa_mag[l] + km1 * b.w_mag[l]) * inv_k;
      b.qa[l] *= b.ca[l] * b.ca[l];
      b.qb[l] *= b.cb[l] * b.cb[l];
    }
  }
}

// Stage 3: the backward chains U_(j-2) = (j c^2 U_j + sφ) / (j - 1), j = top, top - 2, .., m + 2,
// all terms positive; the start error is carried along (times j c^2 / (j - 1)).
inline void linear_specular_backward(int m, int lanes, LinearSpecularBlock& b) {
  for (int j = m + 2 * linear_backward_steps(m); j >= m + 2; j -= 2) {
    const double jj = double(j), inv_j = 1. / (jj - 1.);
#pragma omp simd
    for (int l = 0; l < lanes; ++l) {
      const double grow_n = jj * (b.cn[l] * b.cn[l]) * inv_j, grow_f = jj * (b.cf[l] * b.cf[l]) * inv_j;
      b.un[l] = grow_n * b.un[l] + b.sn[l] * inv_j;
      b.uf[l] = grow_f * b.uf[l] + b.sf[l] * inv_j;
      b.en[l] *= grow_n;
      b.ef[l] *= grow_f;
    }
  }
}

// Stage 4 for lane l: the accepted chain's value (the forward one first), and the flags.
inline void linear_specular_finish(int m, int l, const LinearSpecularBlock& b, double& result, std::uint8_t& stiff_flag) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  const double w = b.w[l];
  const double value_forward = phong_power_lane(b.big_c[l], double(m)) * w / b.h_ell[l];
  // c^m at both ends: the chain leaves c^(m+1) in qa, qb.
  const double ca_m = b.ca[l] > 0. ? b.qa[l] / b.ca[l] : (m == 0 ? 1. : 0.);
  const double cb_m = b.cb[l] > 0. ? b.qb[l] / b.cb[l] : (m == 0 ? 1. : 0.);
  const double forward_error = double(m + 8) * eps * b.frame[l] * b.w_mag[l] + ca_m * b.dpa[l] + cb_m * b.dpb[l];
  const bool forward_ok = (w > 0.) & (forward_error <= kLinearSpecularBatchBound * w);
  const double rho = b.cf[l] / b.cn[l];
  const double rho_m = phong_power_lane(rho, double(m)), rho_m1 = rho_m * rho;
  const double diff = b.un[l] - rho_m1 * b.uf[l];  // W_m / cn^(m+1)
  const double value_backward = phong_power_lane(b.big_c[l] * b.cn[l], double(m)) * b.cn[l] * diff / b.h_ell[l];
  const double backward_error = double(linear_backward_steps(m) + m + 8) * eps * b.frame[l] * (b.un[l] + rho_m1 * b.uf[l]) +
                                b.en[l] + rho_m1 * b.ef[l] + b.dcn[l] + rho_m * b.dcf[l];
  const bool backward_ok = (b.tail[l] != 0.) & (diff > 0.) & (backward_error <= kLinearSpecularBatchBound * diff);
  // The backward chains where the forward one fails or is the less accurate.
  const bool use_backward = backward_ok & (!forward_ok | (backward_error * w < forward_error * diff));
  const double value = use_backward ? value_backward : value_forward;
  const bool empty = b.empty[l] != 0.;
  const bool stiff = (b.stiff[l] != 0.) | ((!empty) & ((b.cut[l] > 1e-6 * value) | !(forward_ok | backward_ok)));
  result = stiff | empty ? 0. : value * b.scale2[l];
  stiff_flag = stiff ? 1 : 0;
}

template <bool kOdd>
inline void linear_specular_blocks(const LinearBatchLight& light, int m, const BatchPoints& pts, long begin, long end,
                                   const BatchSpecularOutput& out) {
  const LinearBatchLight L = light;  // a local copy: provably not aliased by the output arrays
  LinearSpecularBlock blk;  // local: the stages' loops see no aliasing with the points or outputs
  double* const specular = out.specular;
  std::uint8_t* const stiff = out.stiff;
  for (long start = begin; start < end; start += kLinearSpecularBlock) {
    const int lanes = int(end - start < kLinearSpecularBlock ? end - start : kLinearSpecularBlock);
#pragma omp simd
    for (int l = 0; l < lanes; ++l) {
      const long v = start + l;
      linear_specular_setup<kOdd>(L, m, pts.px[v], pts.py[v], pts.pz[v], pts.nx[v], pts.ny[v], pts.nz[v], pts.rx[v], pts.ry[v],
                                  pts.rz[v], l, blk);
    }
    linear_specular_forward(kOdd ? 3 : 2, m, lanes, blk);
    linear_specular_backward(m, lanes, blk);
#pragma omp simd
    for (int l = 0; l < lanes; ++l) linear_specular_finish(m, l, blk, specular[start + l], stiff[start + l]);
  }
}

}  // namespace batch_detail

// Exact specular with the falloff n = 2 of one linear light at lanes [begin, end) of `pts` (rx, ry,
// rz set: the unit reflected view direction), integer 0 <= m <= kLinearSpecularBatchMaxShininess.
// Lanes it cannot vouch for are flagged, with 0.
inline void linear_specular_batch(const LinearBatchLight& light, int m, const BatchPoints& pts, long begin, long end,
                                  const BatchSpecularOutput& out) {
  if (m % 2 == 1) batch_detail::linear_specular_blocks<true>(light, m, pts, begin, end, out);
  else batch_detail::linear_specular_blocks<false>(light, m, pts, begin, end, out);
}

}  // namespace vlit
