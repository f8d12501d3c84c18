// Area (panel) light, diffuse, float batch: Lambert's contour integral over the horizon-clipped
// convex polygon, structure-of-arrays points.
//
// What it computes: Id = ∫_A max(0, cos theta) cos theta_l / r^2 dA = 1/2 Σ_i beta_i cos delta_i
// over the polygon clipped to the upper hemisphere of P (Picott 1992 eq. 9; Lambert; Nishita and
// Nakamae 1985), the same quantity as area_diffuse_contour.h, in the same vector form:
//   beta_i cos delta_i = N.(a_{i+1} x a_i) beta_i / |a_i x a_{i+1}|,
//   beta_i = atan2(|a_i x a_{i+1}|, a_i.a_{i+1}) (float_atan.h), a_i = Q_i - P = D + d_i,
//   D = c - P formed in double, a_i x a_{i+1} = D x (d_{i+1} - d_i) + d_i x d_{i+1} (area_diffuse_contour.h).
//
// Horizon clipping without a clip buffer: edge by edge, for all lanes at once (edge-major loops
// over a block of lanes, so the compiler vectorises every loop). The part of edge i above the
// tangent plane (N.a >= 0, the rule of clip_halfspace in area_polygon.h) is kept, its end below
// the plane moved to the crossing point; where the boundary leaves the upper half space (exit)
// and where it comes back (entry) are remembered, and the closing edge exit -> entry, which lies
// in the tangent plane, is added after the last edge. For a convex polygon there is at most one
// exit and one entry, so this equals Sutherland-Hodgman followed by the contour sum. Non-convex
// lights stay on the scalar kernel (the scene plan checks convexity).
// Per-light constants (batch_kernel_for in src/shading/batch_kernels.cpp): the centre c (double), the offsets d_i = Q_i - c,
// the emitting normal, one- or two-sidedness, the vertex count (any N <= kAreaBatchMaxVertices, which
// equals kMaxAreaVertices of area_polygon.h).
//
// Small lights: when the light's radius is below kAreaBatchSmallLightRatio |D| (every edge seen
// under beta < 0.41), the terms are summed in the reference-subtracted form of
// area_diffuse_contour.h (g_ref = 1/|D|^2 times twice the area vector, plus (g_i - g_ref) terms
// that carry no cancellation), with beta/sin(beta) - 1 from its series; a block of lanes computes
// the plain form, the small-light form or both (selected per lane) as its lanes need.
//
// Stiff lanes (flagged for the scalar double kernel; tests/kernels/batch/batch_kernels_test.cpp
// "area batch: stiff cases"): cancellation. Every term carries an absolute rounding error of a few
// float epsilons times its magnitude bound (beta_i in the plain form, |g_i - g_ref| |a_i x a_{i+1}|
// and g_ref |d_i x d_{i+1}| in the small-light form), so a lane is flagged when the sum of the
// bounds exceeds kAreaBatchCancellation |Σ|: the light seen grazing or cut by the horizon, where
// the result is small against its terms. The error of an unflagged lane grows about linearly with
// (bounds / |Σ|); 32 keeps it under the 1e-5 bar with some margin on the test's random set and on
// the benchmark's floor (max printed by both: "area random", bench/batch_kernels_bench).
// Also flagged: |D| > 1e8, where the small-light denominators would overflow float.
#pragma once

#include <cmath>

#include "batch/batch_points.h"
#include "batch/float_atan.h"

namespace vlit {

inline constexpr int kAreaBatchMaxVertices = 64;
inline constexpr int kAreaBatchBlock = 128;      // lanes per edge-major block
inline constexpr float kAreaBatchCancellation = 32.f;
inline constexpr double kAreaBatchSmallLightRatio = 0.2;  // radius / |D| below which the small-light form is used

struct AreaBatchLight {
  double center[3];                          // c = mean of the vertices
  float d[kAreaBatchMaxVertices][3];         // Q_i - c, convex, counter-clockwise seen from the emitting side
  double normal[3];                          // unit emitting normal n_l
  float radius;                              // max |d_i|
  int count;
  bool two_sided;
};

namespace batch_detail {

// beta / sin(beta) - 1 for 0 <= beta <= 0.5 (area_diffuse_contour.h's series, terms up to beta^14:
// successive terms shrink by ~beta^2/pi^2 <= 0.025, truncation below 1e-11 relative).
inline float beta_over_sin_minus_one_float(float b) {
  const float x = b * b;
  return x * (1.f / 6.f + x * (7.f / 360.f + x * (31.f / 15120.f + x * (127.f / 604800.f + x * (73.f / 3421440.f +
         x * (1414477.f / 653837184000.f + x * (8191.f / 37362124800.f)))))));
}

// Which form of the edge terms a block of lanes uses: all lanes plain, all lanes small-light, or
// both computed and selected per lane.
enum class AreaForm { kPlain, kSmall, kMixed };

// One edge a = D + da -> b = D + db of the (clipped) polygon. Adds its term of
// Σ g_i N.(a_i x a_{i+1}) (g_i = beta_i / |a_i x a_{i+1}|; the sign convention of
// contour_lambert_sum, the caller negates the sum) to `sum`, and a bound on its magnitude, which
// sets its rounding error, to `mag`. The small-light lanes use the reference-subtracted form of
// area_diffuse_contour.h: g_ref N.(da x db) + (g_i - g_ref) N.(a x b), g_ref = 1/|D|^2, where
// g_i - g_ref = (beta/sin(beta) - 1)/(|a||b|) + (1/(|a||b|) - 1/|D|^2) and the last difference is
// -(|D|^2 (ua + ub) + ua ub) / ((|D|^2 + |a||b|) |a||b| |D|^2), ua = 2 D.da + |da|^2 (no cancellation).
template <AreaForm kForm>
inline void area_edge(float Dx, float Dy, float Dz, float dist2, float g_ref, bool small, float nx, float ny, float nz, float ax,
                      float ay, float az, float bx, float by, float bz, float& sum, float& mag) {
  const float ex = bx - ax, ey = by - ay, ez = bz - az;
  const float kx = ay * bz - az * by, ky = az * bx - ax * bz, kz = ax * by - ay * bx;  // da x db
  const float cx = (Dy * ez - Dz * ey) + kx;                                          // a x b
  const float cy = (Dz * ex - Dx * ez) + ky;
  const float cz = (Dx * ey - Dy * ex) + kz;
  const float s = std::sqrt(cx * cx + cy * cy + cz * cz);
  const float pax = Dx + ax, pay = Dy + ay, paz = Dz + az;
  const float pbx = Dx + bx, pby = Dy + by, pbz = Dz + bz;
  const float beta = atan2_upper(s, pax * pbx + pay * pby + paz * pbz);
  const bool ok = s > 0.f;
  const float n_cr = nx * cx + ny * cy + nz * cz;
  float plain = 0.f, plain_mag = 0.f, sml = 0.f, sml_mag = 0.f;
  if constexpr (kForm != AreaForm::kSmall) {
    plain = ok ? beta / (ok ? s : 1.f) * n_cr : 0.f;
    plain_mag = ok ? beta : 0.f;
  }
  if constexpr (kForm != AreaForm::kPlain) {
    const float la2 = pax * pax + pay * pay + paz * paz, lb2 = pbx * pbx + pby * pby + pbz * pbz;
    const float lab = std::sqrt(la2 * lb2);
    const float ua = 2.f * (Dx * ax + Dy * ay + Dz * az) + (ax * ax + ay * ay + az * az);
    const float ub = 2.f * (Dx * bx + Dy * by + Dz * bz) + (bx * bx + by * by + bz * bz);
    const float labs = lab > 0.f ? lab : 1.f;
    // Small-light lanes see every edge under beta <= 2 asin(kAreaBatchSmallLightRatio) < 0.41.
    // g - g_ref = series / |a||b| + inv_diff over one common denominator (one division).
    const float den = (dist2 + labs) * labs;
    const float g_minus_ref = (beta_over_sin_minus_one_float(beta) * (dist2 + labs) - (dist2 * (ua + ub) + ua * ub) * g_ref) / den;
    const float n_k = nx * kx + ny * ky + nz * kz;
    const float rest = g_minus_ref * n_cr;
    sml = g_ref * n_k + (ok ? rest : 0.f);
    sml_mag = g_ref * (n_k < 0.f ? -n_k : n_k) + (ok ? (g_minus_ref < 0.f ? -g_minus_ref : g_minus_ref) * s : 0.f);
  }
  if constexpr (kForm == AreaForm::kPlain) {
    sum += plain;
    mag += plain_mag;
  } else if constexpr (kForm == AreaForm::kSmall) {
    sum += sml;
    mag += sml_mag;
  } else {
    sum += small ? sml : plain;
    mag += small ? sml_mag : plain_mag;
  }
}

// Per-lane state of the edge-major loop over one block of lanes.
struct AreaBlockState {
  float Dx[kAreaBatchBlock], Dy[kAreaBatchBlock], Dz[kAreaBatchBlock], dist2[kAreaBatchBlock], g_ref[kAreaBatchBlock];
  float small[kAreaBatchBlock];  // 1: small-light form (radius < kSmallLightRatio |D|)
  float orient[kAreaBatchBlock], sum[kAreaBatchBlock], mag[kAreaBatchBlock];
  float px[kAreaBatchBlock], py[kAreaBatchBlock], pz[kAreaBatchBlock], ph[kAreaBatchBlock];  // previous vertex (d), N.a
  float ex[kAreaBatchBlock], ey[kAreaBatchBlock], ez[kAreaBatchBlock];  // exit point (d)
  float gx[kAreaBatchBlock], gy[kAreaBatchBlock], gz[kAreaBatchBlock];  // entry point (d)
  float crossed[kAreaBatchBlock];  // 1 once the boundary has left the upper half space
};

template <AreaForm kForm>
inline void area_edges(const AreaBatchLight& L, AreaBlockState& st, const float* __restrict nxs,
                       const float* __restrict nys, const float* __restrict nzs, int n) {
  // Restrict pointers to the state's arrays: GCC 12 does not vectorise through the struct reference.
  const float* __restrict Dx = st.Dx;
  const float* __restrict Dy = st.Dy;
  const float* __restrict Dz = st.Dz;
  const float* __restrict dist2 = st.dist2;
  const float* __restrict g_ref = st.g_ref;
  const float* __restrict small = st.small;
  float* __restrict total = st.sum;
  float* __restrict mag_total = st.mag;
  float* __restrict px = st.px;
  float* __restrict py = st.py;
  float* __restrict pz = st.pz;
  float* __restrict ph = st.ph;
  float* __restrict ex = st.ex;
  float* __restrict ey = st.ey;
  float* __restrict ez = st.ez;
  float* __restrict gx = st.gx;
  float* __restrict gy = st.gy;
  float* __restrict gz = st.gz;
  float* __restrict crossed = st.crossed;
  const int count = L.count;
  for (int i = 0; i < count; ++i) {
    const float cx = L.d[i][0], cy = L.d[i][1], cz = L.d[i][2];
#pragma omp simd
    for (int k = 0; k < n; ++k) {
      const float nx = nxs[k], ny = nys[k], nz = nzs[k];
      const float hc = nx * (Dx[k] + cx) + ny * (Dy[k] + cy) + nz * (Dz[k] + cz);
      const float hp = ph[k];
      // Inside flags as 0/1 floats, every select on a fresh float comparison (GCC 12 does not
      // vectorise this loop with bool variables reused across selects).
      const float in_prev = hp >= 0.f ? 1.f : 0.f, in_cur = hc >= 0.f ? 1.f : 0.f;
      const float t = in_prev != in_cur ? hp / (hp - hc) : 0.f;
      const float xx = px[k] + (cx - px[k]) * t, xy = py[k] + (cy - py[k]) * t, xz = pz[k] + (cz - pz[k]) * t;
      const float ax = in_prev > 0.f ? px[k] : xx, ay = in_prev > 0.f ? py[k] : xy, az = in_prev > 0.f ? pz[k] : xz;
      const float bx = in_cur > 0.f ? cx : xx, by = in_cur > 0.f ? cy : xy, bz = in_cur > 0.f ? cz : xz;
      float sum = 0.f, mag = 0.f;
      area_edge<kForm>(Dx[k], Dy[k], Dz[k], dist2[k], g_ref[k], small[k] > 0.f, nx, ny, nz, ax, ay, az, bx, by, bz, sum, mag);
      total[k] += in_prev + in_cur > 0.f ? sum : 0.f;
      mag_total[k] += in_prev + in_cur > 0.f ? mag : 0.f;
      ex[k] = in_prev > in_cur ? xx : ex[k]; ey[k] = in_prev > in_cur ? xy : ey[k]; ez[k] = in_prev > in_cur ? xz : ez[k];
      gx[k] = in_cur > in_prev ? xx : gx[k]; gy[k] = in_cur > in_prev ? xy : gy[k]; gz[k] = in_cur > in_prev ? xz : gz[k];
      crossed[k] = in_prev > in_cur ? 1.f : crossed[k];
      px[k] = cx; py[k] = cy; pz[k] = cz; ph[k] = hc;
    }
  }
  // The closing edge exit -> entry, in the tangent plane.
#pragma omp simd
  for (int k = 0; k < n; ++k) {
    float sum = 0.f, mag = 0.f;
    area_edge<kForm>(Dx[k], Dy[k], Dz[k], dist2[k], g_ref[k], small[k] > 0.f, nxs[k], nys[k], nzs[k], ex[k], ey[k], ez[k],
                     gx[k], gy[k], gz[k], sum, mag);
    const bool closed = crossed[k] > 0.f;
    total[k] += closed ? sum : 0.f;
    mag_total[k] += closed ? mag : 0.f;
  }
}

// Lanes [begin, begin + n), n <= kAreaBatchBlock.
inline void area_diffuse_block(const AreaBatchLight& L, const BatchPoints& pts, long begin, int n, const BatchOutput& out) {
  AreaBlockState st;
  // Locals and restrict pointers: provably not aliased by the output arrays.
  const double* __restrict pxs = pts.px + begin;
  const double* __restrict pys = pts.py + begin;
  const double* __restrict pzs = pts.pz + begin;
  const float* __restrict nxs = pts.nx + begin;
  const float* __restrict nys = pts.ny + begin;
  const float* __restrict nzs = pts.nz + begin;
  float* __restrict diffuse = out.diffuse + begin;
  std::uint8_t* __restrict stiff_out = out.stiff + begin;
  const double cx0 = L.center[0], cy0 = L.center[1], cz0 = L.center[2];
  const double lnx = L.normal[0], lny = L.normal[1], lnz = L.normal[2];
  const float back = L.two_sided ? -1.f : 0.f;
  // small-light lanes: radius < kAreaBatchSmallLightRatio |D|
  const float small_limit = L.radius * L.radius / float(kAreaBatchSmallLightRatio * kAreaBatchSmallLightRatio);
  const int count = L.count;
  const float lastx = L.d[count - 1][0], lasty = L.d[count - 1][1], lastz = L.d[count - 1][2];
  int small_lanes = 0;
#pragma omp simd reduction(+ : small_lanes)
  for (int k = 0; k < n; ++k) {
    const double dxd = cx0 - pxs[k], dyd = cy0 - pys[k], dzd = cz0 - pzs[k];
    const double side = -(lnx * dxd + lny * dyd + lnz * dzd);  // n_l.(P - c)
    st.orient[k] = side > 0. ? 1.f : (side < 0. ? back : 0.f);
    st.Dx[k] = float(dxd); st.Dy[k] = float(dyd); st.Dz[k] = float(dzd);
    st.dist2[k] = st.Dx[k] * st.Dx[k] + st.Dy[k] * st.Dy[k] + st.Dz[k] * st.Dz[k];
    st.g_ref[k] = 1.f / (st.dist2[k] > 0.f ? st.dist2[k] : 1.f);
    const bool small = small_limit < st.dist2[k];
    st.small[k] = small ? 1.f : 0.f;
    small_lanes += small ? 1 : 0;
    st.px[k] = lastx; st.py[k] = lasty; st.pz[k] = lastz;
    st.ph[k] = nxs[k] * (st.Dx[k] + lastx) + nys[k] * (st.Dy[k] + lasty) + nzs[k] * (st.Dz[k] + lastz);
    st.sum[k] = 0.f; st.mag[k] = 0.f; st.crossed[k] = 0.f;
    st.ex[k] = st.ey[k] = st.ez[k] = st.gx[k] = st.gy[k] = st.gz[k] = 0.f;
  }
  if (small_lanes == n) area_edges<AreaForm::kSmall>(L, st, nxs, nys, nzs, n);
  else if (small_lanes == 0) area_edges<AreaForm::kPlain>(L, st, nxs, nys, nzs, n);
  else area_edges<AreaForm::kMixed>(L, st, nxs, nys, nzs, n);
#pragma omp simd
  for (int k = 0; k < n; ++k) {
    const float total = st.sum[k];
    const float id = -0.5f * st.orient[k] * total;
    const float abs_total = total < 0.f ? -total : total;
    const bool lit = st.orient[k] != 0.f;
    // |D| > 1e8 would overflow the small-light form's denominators in float.
    const bool stiff = lit & ((st.mag[k] > kAreaBatchCancellation * abs_total) | (st.dist2[k] > 1e16f));
    st.sum[k] = lit & (!stiff) & (id > 0.f) ? id : 0.f;  // reused as the result
    st.crossed[k] = stiff ? 1.f : 0.f;                   // reused as the stiff flag
  }
  // Separate copy loops: GCC 12 does not vectorise one loop storing through both output pointers.
#pragma omp simd
  for (int k = 0; k < n; ++k) diffuse[k] = st.sum[k];
#pragma omp simd
  for (int k = 0; k < n; ++k) stiff_out[k] = st.crossed[k] > 0.f ? 1 : 0;
}

}  // namespace batch_detail

// Diffuse of one convex area light at lanes [begin, end).
inline void area_diffuse_batch(const AreaBatchLight& light, const BatchPoints& pts, long begin, long end,
                               const BatchOutput& out) {
  for (long b = begin; b < end; b += kAreaBatchBlock) {
    const long n = end - b < kAreaBatchBlock ? end - b : kAreaBatchBlock;
    batch_detail::area_diffuse_block(light, pts, b, int(n), out);
  }
}

}  // namespace vlit
