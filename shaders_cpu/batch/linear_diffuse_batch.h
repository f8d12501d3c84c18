// Linear (tube) light, diffuse, float batch: the closed forms for falloff n = 0, 1, 2 and 3 over
// structure-of-arrays points.
//
// What it computes: Id = ∫_0^1 max(0, L(t).N) / |L(t)|^(n+1) dt (Picott 1992 eq. 4;
// docs/conventions.md "Radiometric definitions"), the same quantity as linear_diffuse_closed.h, with the segment clipped to the
// upper half space of P first (conventions.h).
//
// Sources and form: the scalar kernel's local frame (linear_geometry.h: L(s) = H + s u, |L|^2 =
// h^2 + s^2, L.N = a + b s) and its cancellation-free antiderivative differences
// (linear_diffuse_closed.h, errata E1-E4 in docs/linear-lights.md):
//   Id = (a F_n + b G_n) / |Ld|,  over the visible interval [sa, sb] of length delta;
//   n = 0: G = dd / (ra + rb),  F = asinh(sb/h) - asinh(sa/h) = log1p(w): w from
//          y = dd / (sb ra + sa rb) (sa, sb same sign) or from both ends' (s + r)/h - 1 (foot inside);
//   n = 1: G = log1p(dd / ra^2) / 2 (or ln(rb^2/ra^2) / 2 when dd/ra^2 <= -1/2),
//          F = (delta/X) atan(z)/z (X > 0) or atan2(Y, X)/h;
//   n = 2: G = dd / (ra rb (ra + rb)),  F = dd / (ra rb (sb ra + sa rb)) (sa, sb same sign)
//                                       or (sb/rb - sa/ra) / h^2 (foot inside), dd = delta (sa + sb);
//   n = 3: G = dd / (2 ra^2 rb^2),  F = delta/(2X) [delta^2 φ(z)/X^2 + 2/(X(1+z^2))] (X = h^2 + sa sb
//          > 0, z = h delta / X) or (delta(2h^2 - X)/(X^2 + Y^2) + atan2(Y, X)/h) / (2h^2), Y = h delta.
// Per-light constants (computed once, batch_kernel_for in src/shading/batch_kernels.cpp): Q0, Q1,
// u = Ld/|Ld|, |Ld| and 1/|Ld| (the scalar kernel recomputes Ld per point, linear_light.h).
//
// Precision: per lane, L0 = Q0 - P and L1 = Q1 - P, their projections s0 = L0.u, s1 = L1.u, the
// perpendicular H = L0 - u s0, a = H.N, b = u.N and the horizon values L0.N, L1.N are formed in double (the
// collinear trap: h = |H| keeps full relative precision as P approaches the line); everything
// after is float, in lengths divided by scale = max(|L0|, |L1|) as in linear_geometry.h. Where the
// segment crosses the tangent plane, the crossing is s = -a/b and the visible fraction c0/(c0 - c1)
// or c1/(c1 - c0), not s0 + t ell and (1 - t) ell as in linear_geometry.h (see the clipping below).
// ln and atan are float polynomials (float_log.h, float_atan.h): no library call, so GCC 12
// vectorises the loop for every n and every target_clones variant (checked with
// -fopt-info-vec-all on src/shading/batch_kernels.cpp: 12 "loop vectorized" at linear_diffuse_loop).
//
// Stiff lanes (flagged for the scalar double kernel; tests/kernels/batch/batch_kernels_test.cpp
// "linear batch: stiff cases"), the same rule for every n: P at an endpoint or within 1e-12 scale
// of the line (h^2 would underflow float; includes P on the segment, where n = 0 has a finite value
// the scalar kernel computes), a segment shorter than 1e-5 scale (the point-light limit), and
// cancellation: |a F| + |b G| > 16 |a F + b G| (a light almost edge-on to the tangent plane, where
// float rounding of the two terms would exceed the 1e-5 bar). The n = 0 and n = 1 forms add no
// cancellation of their own: w and the log1p argument are sums of positive terms or exact
// differences, and G's dd = delta (sa + sb) cancels only where the whole segment is visible
// and a F dominates.
// Measured max relative error of unflagged lanes, n = 0 / 1 / 2 / 3: random set 3.9e-7 / 3.8e-7 /
// 4.6e-7 / 7.0e-7, floor under a tube 2.1e-6 / 2.9e-6 / 1.7e-6 / 2.5e-6 (about 2% of its lanes
// flagged), stiff cases <= 3.1e-7; `./build/release/tests/batch_kernel_tests -s -tc='linear*'`.
// Measured accuracy against the double scalar kernel: docs/performance.md, test above.
#pragma once

#include <cmath>

#include "batch/atan2_upper.h"
#include "batch/batch_points.h"
#include "batch/float_log.h"

namespace vlit {

struct LinearBatchLight {
  double q0[3], q1[3];
  double u[3];      // unit direction Ld / |Ld|
  double length;    // |Ld| > 0
  float inv_length; // 1 / |Ld|
  int falloff;      // 0, 1, 2 or 3
};

namespace batch_detail {

// φ(z) = (atan(z)/z - 1/(1+z^2)) / z^2 (linear_diffuse_closed.h) in float: the alternating series
// 2/3 - 4/5 z^2 + 6/7 z^4 - ... for z < 0.5 (14 terms: truncation below 2e-9), the direct form
// above (cancellation factor <= 7 there).
inline float atan_phi_float(float z) {
  const float z2 = z * z;
  float series = 0.f;
  for (int k = 14; k >= 1; --k) series = series * -z2 + float(2 * k) / float(2 * k + 1);
  const float zc = z < 0.5f ? 0.5f : z;  // keeps the direct form finite in lanes that use the series
  const float zc2 = zc * zc;
  const float direct = (atan2_upper(zc, 1.f) / zc - 1.f / (1.f + zc2)) / zc2;
  return z < 0.5f ? series : direct;
}

template <int kFalloff>
inline void linear_diffuse_lane(const LinearBatchLight& L, double px, double py, double pz, float nxf, float nyf,
                                float nzf, float& result, std::uint8_t& stiff_flag) {
  const double nx = nxf, ny = nyf, nz = nzf;
  // Double set-up (see the file comment).
  const double l0x = L.q0[0] - px, l0y = L.q0[1] - py, l0z = L.q0[2] - pz;
  const double l1x = L.q1[0] - px, l1y = L.q1[1] - py, l1z = L.q1[2] - pz;
  const double s0d = l0x * L.u[0] + l0y * L.u[1] + l0z * L.u[2];
  const double s1d = l1x * L.u[0] + l1y * L.u[1] + l1z * L.u[2];
  const double hx = l0x - L.u[0] * s0d, hy = l0y - L.u[1] * s0d, hz = l0z - L.u[2] * s0d;
  // a = H.N and b = u.N in double too: in float a nearly perpendicular H and N would leave a and b
  // with an absolute error of eps h, relative errors that no cancellation check sees.
  const double ad = hx * nx + hy * ny + hz * nz;
  const double bd = L.u[0] * nx + L.u[1] * ny + L.u[2] * nz;
  const double c0d = l0x * nx + l0y * ny + l0z * nz;
  const double c1d = l1x * nx + l1y * ny + l1z * nz;
  const double r0sq = l0x * l0x + l0y * l0y + l0z * l0z, r1sq = l1x * l1x + l1y * l1y + l1z * l1z;
  // Float from here on, in lengths divided by scale.
  const float scale = std::sqrt(float(r0sq > r1sq ? r0sq : r1sq));
  const float inv = scale > 0.f ? 1.f / scale : 0.f;
  const float hxf = float(hx) * inv, hyf = float(hy) * inv, hzf = float(hz) * inv;
  const float h = std::sqrt(hxf * hxf + hyf * hyf + hzf * hzf);
  const float a = float(ad) * inv;
  const float b = float(bd);
  const float s0 = float(s0d) * inv, s1 = float(s1d) * inv;
  const float ell = float(L.length) * inv;
  const float c0 = float(c0d), c1 = float(c1d);
  // Horizon clipping from the endpoint values L0.N, L1.N (linear_geometry.h).
  const bool both_in = (c0 >= 0.f) & (c1 >= 0.f);
  const bool both_out = !both_in & (c0 <= 0.f) & (c1 <= 0.f);
  const bool in_plane = (c0 == 0.f) & (c1 == 0.f);
  // A segment that crosses the tangent plane (c0, c1 of strictly opposite signs) is visible from
  // Q0 to the crossing when c0 > 0, else from the crossing to Q1. The visible fraction of its length
  // is c0/(c0 - c1) or c1/(c1 - c0) (no cancellation), and the crossing's s is -a/b (L.N = a + b s
  // = 0; b = (c1 - c0)/|Ld| != 0), both with relative precision. The scalar kernel's s0 + t ell and
  // (1 - t) ell carry an absolute error of a float epsilon, which in float is all of the interval's
  // near end when the crossing lies within ~h of the foot of the perpendicular and h is small,
  // and all of delta when the crossing is near Q1 (test "linear batch: stiff cases", "foot 1e-4
  // inside an end").
  const bool crossing = !(both_in | both_out);
  const bool from_q0 = c0 > 0.f;
  const float fraction = crossing ? (from_q0 ? c0 : c1) / (from_q0 ? c0 - c1 : c1 - c0) : 1.f;
  const float s_cross = -a / (b != 0.f ? b : 1.f);
  const float sa = crossing & !from_q0 ? s_cross : s0;
  const float sb_raw = crossing & from_q0 ? s_cross : s1;
  const float sb0 = sb_raw > sa ? sb_raw : sa;
  const float delta = fraction * ell;
  const bool empty = both_out | in_plane | !(delta > 0.f) | !(scale > 0.f);
  // Mirror s -> -s so that sb > 0 (F even, G odd).
  const bool flip = sb0 <= 0.f;
  const float lo = flip ? -sb0 : sa, hi = flip ? -sa : sb0;
  const bool same_sign = lo >= 0.f;
  const float h2 = h * h;
  const float ra2 = h2 + lo * lo, rb2 = h2 + hi * hi;
  const float ra = std::sqrt(ra2), rb = std::sqrt(rb2);
  const float dd = delta * (lo + hi);
  float f, g;
  if constexpr (kFalloff == 0) {
    g = dd / (ra + rb);
    // F = asinh(sb/h) - asinh(sa/h) as log1p(w) (asinh y = log1p(y + y^2/(1 + sqrt(1 + y^2)))).
    // Same sign: y = dd / (sb ra + sa rb). Foot inside: asinh(sb/h) + asinh(-sa/h) =
    // log1p(wa + wb + wa wb) with wb = (sb + rb)/h - 1 = sb (1 + sb/(rb + h)) / h (rb - h = sb^2/(rb + h)),
    // wa likewise with -sa and ra: sums of positive terms, no cancellation.
    const float y = dd / (same_sign ? hi * ra + lo * rb : 1.f);
    const float w_same = y + y * y / (1.f + std::sqrt(1.f + y * y));
    const float hs = h > 0.f ? h : 1.f;
    const float pb = hi * (1.f + hi / (rb + h)), pa = -lo * (1.f - lo / (ra + h));
    const float w_inside = (pa + pb + pa * pb / hs) / hs;
    f = log1p_float(same_sign ? w_same : w_inside);
  } else if constexpr (kFalloff == 1) {
    // G = ln(rb/ra) = log1p(dd / ra^2) / 2, from the ratio rb^2/ra^2 where dd/ra^2 is near -1.
    g = 0.5f * log1p_or_log_ratio(dd / ra2, rb2 / ra2);
    // F = (atan(sb/h) - atan(sa/h)) / h = atan2(h delta, X)/h, X = h^2 + sa sb; for X > 0 written
    // (delta/X) atan(z)/z with z = h delta / X, which keeps its precision as h -> 0.
    const float x = h2 + lo * hi, y = h * delta;
    const bool x_pos = x > 0.f;
    const float xs = x_pos ? x : 1.f;
    const float z = y / xs;
    const float zs = z < 1e-4f ? 1.f : z;
    const float atan_over = z < 1e-4f ? 1.f - z * z * (1.f / 3.f) : atan2_upper(zs, 1.f) / zs;
    const float hs = h > 0.f ? h : 1.f;
    f = x_pos ? delta / xs * atan_over : atan2_upper(y, x) / hs;
  } else if constexpr (kFalloff == 2) {
    const float rab = ra * rb;
    g = dd / (rab * (ra + rb));
    // Same sign: dd / (ra rb (sb ra + sa rb)); foot inside: (sb/rb - sa/ra) / h^2 =
    // (sb ra - sa rb) / (ra rb h^2), a sum of two positive terms. One division for either.
    const float num = same_sign ? dd : hi * ra - lo * rb;
    const float den = rab * (same_sign ? hi * ra + lo * rb : (h2 > 0.f ? h2 : 1.f));
    f = num / den;
  } else {
    g = dd / (2.f * ra2 * rb2);
    const float x = h2 + lo * hi, y = h * delta;
    const bool x_pos = x > 0.f;
    const float xs = x_pos ? x : 1.f;
    const float z = y / xs;
    const float f_pos = delta / (2.f * xs) * (delta * delta * atan_phi_float(z) / (xs * xs) + 2.f / (xs * (1.f + z * z)));
    const float hs = h > 0.f ? h : 1.f;
    const float f_neg = (delta * (2.f * h2 - x) / (x * x + y * y) + atan2_upper(y, x) / hs) / (2.f * hs * hs);
    f = x_pos ? f_pos : f_neg;
  }
  g = flip ? -g : g;
  const float af = a * f, bg = b * g;
  const float sum = af + bg;
  const float mag = (af < 0.f ? -af : af) + (bg < 0.f ? -bg : bg);
  // (a F + b G) / ell * scale^-n with ell = |Ld| / scale: scale^(1-n) times the per-light 1/|Ld|.
  float scale_n = 1.f;
  if constexpr (kFalloff == 0) scale_n = scale;
  if constexpr (kFalloff == 2) scale_n = inv;
  if constexpr (kFalloff == 3) scale_n = inv * inv;
  const float value = (sum > 0.f ? sum : 0.f) * scale_n * L.inv_length;
  const bool stiff = (!empty) & ((h < 1e-12f) | (ell < 1e-5f) | (mag > 16.f * (sum < 0.f ? -sum : sum)) |
                                !(value < 3.0e38f));
  result = empty | stiff ? 0.f : value;
  stiff_flag = stiff ? 1 : 0;
}

template <int kFalloff>
inline void linear_diffuse_loop(const LinearBatchLight& light, const BatchPoints& pts, long begin, long end,
                                const BatchOutput& out) {
  const LinearBatchLight L = light;  // a local copy: provably not aliased by the output arrays
  for_each_lane(pts, begin, end, out,
                [&L](double px, double py, double pz, float nx, float ny, float nz, float& diffuse, std::uint8_t& stiff) {
                  linear_diffuse_lane<kFalloff>(L, px, py, pz, nx, ny, nz, diffuse, stiff);
                });
}

}  // namespace batch_detail

// Diffuse of one linear light (falloff 0, 1, 2 or 3) at lanes [begin, end).
inline void linear_diffuse_batch(const LinearBatchLight& light, const BatchPoints& pts, long begin, long end,
                                 const BatchOutput& out) {
  switch (light.falloff) {
    case 0: batch_detail::linear_diffuse_loop<0>(light, pts, begin, end, out); break;
    case 1: batch_detail::linear_diffuse_loop<1>(light, pts, begin, end, out); break;
    case 2: batch_detail::linear_diffuse_loop<2>(light, pts, begin, end, out); break;
    default: batch_detail::linear_diffuse_loop<3>(light, pts, begin, end, out); break;
  }
}

}  // namespace vlit
