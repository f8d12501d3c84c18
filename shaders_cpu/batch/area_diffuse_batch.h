// Area (panel) light, diffuse, float batch: Lambert's contour integral over the horizon-clipped
// convex polygon, for structure-of-arrays points.
//
// Computes Id = ∫_A max(0, cos theta) cos theta_l / r^2 dA = 1/2 Σ_i beta_i cos delta_i over the
// polygon clipped to the upper hemisphere of P, in the vector form of area_diffuse_contour.h:
//   beta_i cos delta_i = N.(a_{i+1} x a_i) beta_i / |a_i x a_{i+1}|,
//   beta_i = atan2(|a_i x a_{i+1}|, a_i.a_{i+1}) (float_atan.h), a_i = Q_i - P = D + d_i,
//   D = c - P formed in double, a_i x a_{i+1} = D x (d_{i+1} - d_i) + d_i x d_{i+1}.
// Sources: Picott 1992 eq. 9; Lambert; Nishita and Nakamae 1985. Conventions: conventions.h.
// Per-light constants: AreaBatchLight, filled by batch_kernel_for (src/shading/batch_kernels.cpp).
//
// Horizon clip without a clip buffer, edge by edge over a block of lanes (edge-major, so every
// loop over lanes vectorises; docs/performance.md): the part of edge i above the tangent plane
// (N.a >= 0, clip_halfspace's rule in area_polygon.h) is kept, and where the boundary leaves and
// re-enters the upper half space is remembered; the closing edge exit -> entry, in the tangent
// plane, is added after the last edge. A convex polygon has at most one exit and one entry, so
// this equals Sutherland-Hodgman followed by the contour sum; non-convex lights stay on the scalar
// kernel (the scene plan checks convexity).
// Small lights (radius < kAreaBatchSmallLightRatio |D|): the reference-subtracted sum of
// area_diffuse_contour.h, beta/sin(beta) - 1 from its series; a block computes the plain form, the
// small-light form or both, as its lanes need.
//
// Stiff lanes: where the terms' rounding bounds (max(beta_i, g_i X_i), X_i bounding the split cross
// product's rounding, see area_edge) sum to more than kAreaBatchCancellation |Σ| (grazing light,
// the horizon cutting the light, P near a vertex of the light), or |D| > 1e8 (float overflow of
// the small-light denominators), the lane runs again in this kernel's double lanes: the same loops
// in double with the scalar double kernel's arithmetic (double_atan.h, its small-light series,
// edge_cross's choice of cross product). BatchOutput::stiff stays 0; BatchOutput::in_double marks
// those lanes. How the bar 32 was chosen and what the double lanes cost: docs/performance.md,
// "Precision".
// Tests: tests/kernels/batch/batch_kernels_test.cpp "area batch: stiff cases", "area batch: lanes
// computed in double". Accuracy: float lanes within 1e-5 of the double kernel,
// `./build/release/tests/batch_kernel_tests -s` (table in docs/performance.md).
#pragma once

#include <cmath>

#include "area_diffuse_contour.h"
#include "batch/atan2_upper.h"
#include "batch/batch_points.h"

namespace vlit {

inline constexpr int kAreaBatchMaxVertices = 64;
inline constexpr int kAreaBatchBlock = 128;      // lanes per edge-major block
inline constexpr float kAreaBatchCancellation = 32.f;
inline constexpr double kAreaBatchSmallLightRatio = 0.2;  // float lanes: radius / |D| below which the small-light form is used

struct AreaBatchLight {
  double center[3];                          // c = mean of the vertices
  double d[kAreaBatchMaxVertices][3];        // Q_i - c, convex, counter-clockwise seen from the emitting side
  double normal[3];                          // unit emitting normal n_l
  double radius;                             // max |d_i|
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

// The float lanes' series above; the double lanes use area_diffuse_contour.h's, exact to rounding
// below kSmallLightRatio.
inline float small_angle_series(float b) { return beta_over_sin_minus_one_float(b); }
inline double small_angle_series(double b) { return beta_over_sin_minus_one(b); }

// Which form of the edge terms a block of lanes uses: all lanes plain, all lanes small-light, or
// both computed and selected per lane.
enum class AreaForm { kPlain, kSmall, kMixed };

// One edge a = D + da -> b = D + db of the (clipped) polygon, in float or double lanes (T). Adds
// its term of Σ g_i N.(a_i x a_{i+1}) (g_i = beta_i / |a_i x a_{i+1}|; the sign convention of
// contour_lambert_sum, the caller negates the sum) to `sum`, and a bound on its magnitude, which
// sets its rounding error, to `mag`. The small-light lanes use the reference-subtracted form of
// area_diffuse_contour.h: g_ref N.(da x db) + (g_i - g_ref) N.(a x b), g_ref = 1/|D|^2, where
// g_i - g_ref = (beta/sin(beta) - 1)/(|a||b|) + (1/(|a||b|) - 1/|D|^2) and the last difference is
// -(|D|^2 (ua + ub) + ua ub) / ((|D|^2 + |a||b|) |a||b| |D|^2), ua = 2 D.da + |da|^2 (no cancellation).
// a x b is D x (db - da) + da x db; double lanes take the direct a x b instead when its rounding
// bound |a|^2 |b|^2 is the smaller (edge_cross in area_polygon.h), float lanes never need it: a
// lane where it would matter (P near a vertex, the light seen large) is not cancelling.
template <class T, AreaForm kForm>
inline void area_edge(T Dx, T Dy, T Dz, T dist2, T g_ref, bool small, T nx, T ny, T nz, T ax, T ay, T az, T bx, T by,
                      T bz, T& sum, T& mag) {
  const T ex = bx - ax, ey = by - ay, ez = bz - az;
  const T kx = ay * bz - az * by, ky = az * bx - ax * bz, kz = ax * by - ay * bx;  // da x db
  T cx = (Dy * ez - Dz * ey) + kx;                                                // a x b
  T cy = (Dz * ex - Dx * ez) + ky;
  T cz = (Dx * ey - Dy * ex) + kz;
  const T pax = Dx + ax, pay = Dy + ay, paz = Dz + az;
  const T pbx = Dx + bx, pby = Dy + by, pbz = Dz + bz;
  const T la2 = pax * pax + pay * pay + paz * paz, lb2 = pbx * pbx + pby * pby + pbz * pbz;
  if constexpr (sizeof(T) == sizeof(double)) {
    const T e2 = ex * ex + ey * ey + ez * ez;
    const T da2 = ax * ax + ay * ay + az * az, db2 = bx * bx + by * by + bz * bz;
    const T split = dist2 * e2 > da2 * db2 ? dist2 * e2 : da2 * db2;
    const bool direct = la2 * lb2 < split;
    cx = direct ? pay * pbz - paz * pby : cx;
    cy = direct ? paz * pbx - pax * pbz : cy;
    cz = direct ? pax * pby - pay * pbx : cz;
  }
  const T s = std::sqrt(cx * cx + cy * cy + cz * cz);
  const T beta = atan2_upper(s, pax * pbx + pay * pby + paz * pbz);
  const bool ok = s > T(0);
  const T n_cr = nx * cx + ny * cy + nz * cz;
  T plain = T(0), plain_mag = T(0), sml = T(0), sml_mag = T(0);
  if constexpr (kForm != AreaForm::kSmall) {
    const T g = beta / (ok ? s : T(1));
    plain = ok ? g * n_cr : T(0);
    plain_mag = ok ? beta : T(0);
    if constexpr (sizeof(T) == sizeof(float)) {
      // The split cross product carries an absolute error of a few eps times
      // X = |D||db - da| + |da||db| <= sqrt(2 (|D|^2 |e|^2 + |da|^2 |db|^2)); through g it moves the
      // term by ~ g X eps, more than beta eps when P is near a vertex of the light or the edge
      // points at P.
      const T e2 = ex * ex + ey * ey + ez * ez;
      const T da2 = ax * ax + ay * ay + az * az, db2 = bx * bx + by * by + bz * bz;
      const T gx = g * std::sqrt(T(2) * (dist2 * e2 + da2 * db2));
      plain_mag = ok ? (gx > beta ? gx : beta) : T(0);
    }
  }
  if constexpr (kForm != AreaForm::kPlain) {
    const T lab = std::sqrt(la2 * lb2);
    const T ua = T(2) * (Dx * ax + Dy * ay + Dz * az) + (ax * ax + ay * ay + az * az);
    const T ub = T(2) * (Dx * bx + Dy * by + Dz * bz) + (bx * bx + by * by + bz * bz);
    const T labs = lab > T(0) ? lab : T(1);
    // Small-light lanes see every edge under beta <= 2 asin(small-light ratio) < 0.41.
    // g - g_ref = series / |a||b| + inv_diff over one common denominator (one division).
    const T den = (dist2 + labs) * labs;
    const T g_minus_ref = (small_angle_series(beta) * (dist2 + labs) - (dist2 * (ua + ub) + ua * ub) * g_ref) / den;
    const T n_k = nx * kx + ny * ky + nz * kz;
    const T rest = g_minus_ref * n_cr;
    sml = g_ref * n_k + (ok ? rest : T(0));
    sml_mag = g_ref * (n_k < T(0) ? -n_k : n_k) + (ok ? (g_minus_ref < T(0) ? -g_minus_ref : g_minus_ref) * s : T(0));
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

// Per-lane state of the edge-major loop over one block of lanes (T = float or double).
template <class T>
struct AreaBlockState {
  T Dx[kAreaBatchBlock], Dy[kAreaBatchBlock], Dz[kAreaBatchBlock], dist2[kAreaBatchBlock], g_ref[kAreaBatchBlock];
  T small[kAreaBatchBlock];  // 1: small-light form
  T orient[kAreaBatchBlock], sum[kAreaBatchBlock], mag[kAreaBatchBlock];
  T nx[kAreaBatchBlock], ny[kAreaBatchBlock], nz[kAreaBatchBlock];  // normals (double lanes only; float lanes read the points')
  T px[kAreaBatchBlock], py[kAreaBatchBlock], pz[kAreaBatchBlock], ph[kAreaBatchBlock];  // previous vertex (d), N.a
  T ex[kAreaBatchBlock], ey[kAreaBatchBlock], ez[kAreaBatchBlock];  // exit point (d)
  T gx[kAreaBatchBlock], gy[kAreaBatchBlock], gz[kAreaBatchBlock];  // entry point (d)
  T crossed[kAreaBatchBlock];  // 1 once the boundary has left the upper half space
};

// Sets the per-lane start of the edge loop (previous vertex = the last one, nothing crossed) from
// st.D* and the normals; counts the small-light lanes.
template <class T>
inline int area_start(const AreaBatchLight& L, AreaBlockState<T>& st, const T* __restrict nxs, const T* __restrict nys,
                      const T* __restrict nzs, T small_limit, int n) {
  const T* __restrict Dx = st.Dx;
  const T* __restrict Dy = st.Dy;
  const T* __restrict Dz = st.Dz;
  T* __restrict dist2 = st.dist2;
  T* __restrict g_ref = st.g_ref;
  T* __restrict small = st.small;
  T* __restrict sum = st.sum;
  T* __restrict mag = st.mag;
  T* __restrict crossed = st.crossed;
  T* __restrict px = st.px;
  T* __restrict py = st.py;
  T* __restrict pz = st.pz;
  T* __restrict ph = st.ph;
  T* __restrict ex = st.ex;
  T* __restrict ey = st.ey;
  T* __restrict ez = st.ez;
  T* __restrict gx = st.gx;
  T* __restrict gy = st.gy;
  T* __restrict gz = st.gz;
  const int last = L.count - 1;
  const T lastx = T(L.d[last][0]), lasty = T(L.d[last][1]), lastz = T(L.d[last][2]);
  int small_lanes = 0;
#pragma omp simd reduction(+ : small_lanes)
  for (int k = 0; k < n; ++k) {
    dist2[k] = Dx[k] * Dx[k] + Dy[k] * Dy[k] + Dz[k] * Dz[k];
    g_ref[k] = T(1) / (dist2[k] > T(0) ? dist2[k] : T(1));
    const bool is_small = small_limit < dist2[k];
    small[k] = is_small ? T(1) : T(0);
    small_lanes += is_small ? 1 : 0;
    px[k] = lastx; py[k] = lasty; pz[k] = lastz;
    ph[k] = nxs[k] * (Dx[k] + lastx) + nys[k] * (Dy[k] + lasty) + nzs[k] * (Dz[k] + lastz);
    sum[k] = T(0); mag[k] = T(0); crossed[k] = T(0);
    ex[k] = ey[k] = ez[k] = gx[k] = gy[k] = gz[k] = T(0);
  }
  return small_lanes;
}

template <class T, AreaForm kForm>
inline void area_edges(const AreaBatchLight& L, AreaBlockState<T>& st, const T* __restrict nxs,
                       const T* __restrict nys, const T* __restrict nzs, int n) {
  // Restrict pointers to the state's arrays: GCC 12 does not vectorise through the struct reference.
  const T* __restrict Dx = st.Dx;
  const T* __restrict Dy = st.Dy;
  const T* __restrict Dz = st.Dz;
  const T* __restrict dist2 = st.dist2;
  const T* __restrict g_ref = st.g_ref;
  const T* __restrict small = st.small;
  T* __restrict total = st.sum;
  T* __restrict mag_total = st.mag;
  T* __restrict px = st.px;
  T* __restrict py = st.py;
  T* __restrict pz = st.pz;
  T* __restrict ph = st.ph;
  T* __restrict ex = st.ex;
  T* __restrict ey = st.ey;
  T* __restrict ez = st.ez;
  T* __restrict gx = st.gx;
  T* __restrict gy = st.gy;
  T* __restrict gz = st.gz;
  T* __restrict crossed = st.crossed;
  const int count = L.count;
  int any_crossed = 0;
  for (int i = 0; i < count; ++i) {
    const T cx = T(L.d[i][0]), cy = T(L.d[i][1]), cz = T(L.d[i][2]);
#pragma omp simd reduction(| : any_crossed)
    for (int k = 0; k < n; ++k) {
      const T nx = nxs[k], ny = nys[k], nz = nzs[k];
      const T hc = nx * (Dx[k] + cx) + ny * (Dy[k] + cy) + nz * (Dz[k] + cz);
      const T hp = ph[k];
      // Inside flags as 0/1 reals, every select on a fresh comparison (GCC 12 does not
      // vectorise this loop with bool variables reused across selects).
      const T in_prev = hp >= T(0) ? T(1) : T(0), in_cur = hc >= T(0) ? T(1) : T(0);
      const T t = in_prev != in_cur ? hp / (hp - hc) : T(0);
      const T xx = px[k] + (cx - px[k]) * t, xy = py[k] + (cy - py[k]) * t, xz = pz[k] + (cz - pz[k]) * t;
      const T ax = in_prev > T(0) ? px[k] : xx, ay = in_prev > T(0) ? py[k] : xy, az = in_prev > T(0) ? pz[k] : xz;
      const T bx = in_cur > T(0) ? cx : xx, by = in_cur > T(0) ? cy : xy, bz = in_cur > T(0) ? cz : xz;
      T sum = T(0), mag = T(0);
      area_edge<T, kForm>(Dx[k], Dy[k], Dz[k], dist2[k], g_ref[k], small[k] > T(0), nx, ny, nz, ax, ay, az, bx, by, bz, sum, mag);
      total[k] += in_prev + in_cur > T(0) ? sum : T(0);
      mag_total[k] += in_prev + in_cur > T(0) ? mag : T(0);
      ex[k] = in_prev > in_cur ? xx : ex[k]; ey[k] = in_prev > in_cur ? xy : ey[k]; ez[k] = in_prev > in_cur ? xz : ez[k];
      gx[k] = in_cur > in_prev ? xx : gx[k]; gy[k] = in_cur > in_prev ? xy : gy[k]; gz[k] = in_cur > in_prev ? xz : gz[k];
      crossed[k] = in_prev > in_cur ? T(1) : crossed[k];
      any_crossed |= in_prev > in_cur ? 1 : 0;
      px[k] = cx; py[k] = cy; pz[k] = cz; ph[k] = hc;
    }
  }
  if (!any_crossed) return;  // no lane of the block is cut by its horizon
  // The closing edge exit -> entry, in the tangent plane.
#pragma omp simd
  for (int k = 0; k < n; ++k) {
    T sum = T(0), mag = T(0);
    area_edge<T, kForm>(Dx[k], Dy[k], Dz[k], dist2[k], g_ref[k], small[k] > T(0), nxs[k], nys[k], nzs[k], ex[k], ey[k],
                        ez[k], gx[k], gy[k], gz[k], sum, mag);
    const bool closed = crossed[k] > T(0);
    total[k] += closed ? sum : T(0);
    mag_total[k] += closed ? mag : T(0);
  }
}

template <class T>
inline void area_edges_any_form(const AreaBatchLight& L, AreaBlockState<T>& st, const T* nxs, const T* nys, const T* nzs,
                                int small_lanes, int n) {
  if (small_lanes == n) area_edges<T, AreaForm::kSmall>(L, st, nxs, nys, nzs, n);
  else if (small_lanes == 0) area_edges<T, AreaForm::kPlain>(L, st, nxs, nys, nzs, n);
  else area_edges<T, AreaForm::kMixed>(L, st, nxs, nys, nzs, n);
}

// Lanes v = lanes[0..m) (m <= kAreaBatchBlock, stiff in float) again, in double; writes their
// results to out.diffuse[v].
inline void area_double_lanes(const AreaBatchLight& L, const BatchPoints& pts, const long* lanes, int m,
                              const BatchOutput& out) {
  if (m == 0) return;
  AreaBlockState<double> st;
  const double back = L.two_sided ? -1. : 0.;
  for (int j = 0; j < m; ++j) {
    const long v = lanes[j];
    st.Dx[j] = L.center[0] - pts.px[v];
    st.Dy[j] = L.center[1] - pts.py[v];
    st.Dz[j] = L.center[2] - pts.pz[v];
    st.nx[j] = pts.nx[v]; st.ny[j] = pts.ny[v]; st.nz[j] = pts.nz[v];
    const double side = -(L.normal[0] * st.Dx[j] + L.normal[1] * st.Dy[j] + L.normal[2] * st.Dz[j]);  // n_l.(P - c)
    st.orient[j] = side > 0. ? 1. : (side < 0. ? back : 0.);
  }
  // Padded to whole 8-lane vectors with copies of the last lane: the remainder loop runs one
  // lane at a time through a long dependency chain.
  const int padded = (m + 7) / 8 * 8;
  for (int j = m; j < padded; ++j) {
    st.Dx[j] = st.Dx[m - 1]; st.Dy[j] = st.Dy[m - 1]; st.Dz[j] = st.Dz[m - 1];
    st.nx[j] = st.nx[m - 1]; st.ny[j] = st.ny[m - 1]; st.nz[j] = st.nz[m - 1];
    st.orient[j] = st.orient[m - 1];
  }
  const double small_limit = L.radius * L.radius / (kSmallLightRatio * kSmallLightRatio);
  const int small_lanes = area_start<double>(L, st, st.nx, st.ny, st.nz, small_limit, padded);
  area_edges_any_form<double>(L, st, st.nx, st.ny, st.nz, small_lanes, padded);
  for (int j = 0; j < m; ++j) {
    const double id = -0.5 * st.orient[j] * st.sum[j];
    out.diffuse[lanes[j]] = float(id > 0. ? id : 0.);  // the exact value is >= 0; clamps rounding residue only
    if (out.in_double) out.in_double[lanes[j]] = 1;
  }
}

// Lanes [begin, begin + n), n <= kAreaBatchBlock, in float; appends the stiff lanes' indices to
// `stiff_lanes` (which has room for n more) and returns their number.
inline int area_diffuse_block(const AreaBatchLight& L, const BatchPoints& pts, long begin, int n, const BatchOutput& out,
                              long* stiff_lanes) {
  AreaBlockState<float> st;
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
#pragma omp simd
  for (int k = 0; k < n; ++k) {
    const double dxd = cx0 - pxs[k], dyd = cy0 - pys[k], dzd = cz0 - pzs[k];
    const double side = -(lnx * dxd + lny * dyd + lnz * dzd);  // n_l.(P - c)
    st.orient[k] = side > 0. ? 1.f : (side < 0. ? back : 0.f);
    st.Dx[k] = float(dxd); st.Dy[k] = float(dyd); st.Dz[k] = float(dzd);
  }
  // small-light lanes: radius < kAreaBatchSmallLightRatio |D|
  const float radius = float(L.radius);
  const float small_limit = radius * radius / float(kAreaBatchSmallLightRatio * kAreaBatchSmallLightRatio);
  const int small_lanes = area_start<float>(L, st, nxs, nys, nzs, small_limit, n);
  area_edges_any_form<float>(L, st, nxs, nys, nzs, small_lanes, n);
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
  for (int k = 0; k < n; ++k) stiff_out[k] = 0;
  int m = 0;
  for (int k = 0; k < n; ++k)
    if (st.crossed[k] > 0.f) stiff_lanes[m++] = begin + k;
  return m;
}

}  // namespace batch_detail

// Diffuse of one convex area light at lanes [begin, end). The stiff lanes of successive blocks
// are collected and run in double kAreaBatchBlock at a time (a few lanes alone would leave the
// vector units waiting on the double loop's long dependency chain); a lane's result does not
// depend on its companions.
inline void area_diffuse_batch(const AreaBatchLight& light, const BatchPoints& pts, long begin, long end,
                               const BatchOutput& out) {
  if (out.in_double)
    for (long v = begin; v < end; ++v) out.in_double[v] = 0;
  long pending[2 * kAreaBatchBlock];
  int m = 0;
  for (long b = begin; b < end; b += kAreaBatchBlock) {
    const long n = end - b < kAreaBatchBlock ? end - b : kAreaBatchBlock;
    m += batch_detail::area_diffuse_block(light, pts, b, int(n), out, pending + m);
    if (m >= kAreaBatchBlock) {
      batch_detail::area_double_lanes(light, pts, pending, kAreaBatchBlock, out);
      m -= kAreaBatchBlock;
      for (int j = 0; j < m; ++j) pending[j] = pending[kAreaBatchBlock + j];
    }
  }
  batch_detail::area_double_lanes(light, pts, pending, m, out);
}

}  // namespace vlit
