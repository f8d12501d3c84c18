// Area (panel) light, exact specular, batch: the closed form of area_specular_closed.h (integer m)
// over blocks of structure-of-arrays points, the O(m) recurrence run across lanes.
//
// What it computes: Is(exact) = ∫_Omega [N.w > 0] max(0, Rv.w)^m dw over the convex light clipped
// to P's horizon and to the lobe's half-space Rv.(x - P) >= 0 (unit intensity, ks = 1), integer
// 0 <= m <= kAreaSpecularBatchMaxShininess; docs/conventions.md "Radiometric definitions".
// Sources: Arvo 1995 (axial moments: per-edge recurrence in m, plus the solid angle for even m),
// as derived in area_specular_closed.h, whose formulas, order of operations and acceptance test
// this file repeats lane by lane. Conventions: conventions.h; geometry: area_polygon.h.
//
// Layout, per block of kAreaSpecularBatchBlock lanes:
//  1. per lane (scalar, double): the view and both clips with area_polygon.h's own functions
//     (make_area_view, clip_to_horizon, clip_halfspace; convex: at most count + 2 vertices), then
//     per edge the recurrence's start values (Rv.n_i, Theta_i by atan2, c and c' at both ends,
//     area_specular_closed.h's notation) into edge-major arrays, and the solid angle for even m;
//  2. per edge slot, across lanes (`omp simd`, m the same for every lane: one material per
//     primitive): the chain F(k0), F(k0 + 2), .., F(m - 1) with its magnitude bound, summed;
//  3. per lane: the closed form's total, its rounding estimate (m + 8) eps M / |Σ| and the
//     acceptance test of area_specular_closed.h (<= kAreaClosedBound = 5e-12 and M <= 64 |Σ|).
// A lane that fails the test is flagged (BatchSpecularOutput::stiff): the caller recomputes it with
// the scalar exact kernel (area_light.h's dispatch, which then integrates adaptively). An accepted
// lane's error is bounded by its estimate, far below the batch bar of 1e-5 (docs/performance.md).
// The normal is the lanes' float normal (batch_points.h); Rv and positions are double.
// Status: the scene plan does not choose this kernel (batch_kernels.h enable_area_specular_batch):
// `./build/release/bench/batch_kernels_bench --only "quad specular"` measures it at 0.3x to 1.2x
// the scalar exact path, because the lanes the closed form refuses (11 % at m = 1, ~50 % from
// m = 30 on the benchmark's floor, where Rv points off the light) go to the scalar adaptive form
// either way, and the accepted lanes' per-lane set-up (two clips, an atan2 and normalisations
// per edge) is scalar. Open: a vectorised set-up, and a closed form that accepts the tail lanes.
// Agreement with the scalar closed form: bit-identical (0 difference on every lane of the tests;
// the 7e-9 once seen on lanes whose horizon cuts the light came from the test's reference normal,
// which was not the batch's float normal).
// Tests: tests/kernels/batch/batch_specular_test.cpp ("area specular batch ...").
#pragma once

#include <cmath>
#include <limits>

#include "area_specular_closed.h"
#include "batch/punctual_specular_batch.h"

namespace vlit {

inline constexpr int kAreaSpecularBatchMaxVertices = 8;  // convex lights up to this many corners
inline constexpr int kAreaSpecularBatchMaxShininess = 1000;  // above: the scalar path (O(m) per edge)
inline constexpr int kAreaSpecularBatchBlock = 64;

namespace batch_detail {

constexpr int kAreaSpecularSlots = kAreaSpecularBatchMaxVertices + 2;  // horizon and lobe clips add one each

// Edge-major start values of one block: slot e, lane l at [e * kAreaSpecularBatchBlock + l].
struct AreaSpecularBlock {
  double wn[kAreaSpecularSlots * kAreaSpecularBatchBlock];
  double theta[kAreaSpecularSlots * kAreaSpecularBatchBlock];
  double c0[kAreaSpecularSlots * kAreaSpecularBatchBlock], c0p[kAreaSpecularSlots * kAreaSpecularBatchBlock];
  double c1[kAreaSpecularSlots * kAreaSpecularBatchBlock], c1p[kAreaSpecularSlots * kAreaSpecularBatchBlock];
  double sum[kAreaSpecularBatchBlock], mag[kAreaSpecularBatchBlock];
  double omega[kAreaSpecularBatchBlock], omega_mag[kAreaSpecularBatchBlock], orient[kAreaSpecularBatchBlock];
  bool lit[kAreaSpecularBatchBlock];
};

// Stage 1 for lane l of the block: clips and start values (area_specular_closed.h, same order).
inline int area_specular_setup(const PreparedAreaLight<double>& pl, int m, const Vec3d& p, const Vec3d& n,
                               const Vec3d& rv_in, int l, AreaSpecularBlock& b) {
  constexpr int B = kAreaSpecularBatchBlock;
  b.lit[l] = false;
  b.omega[l] = 0;
  b.omega_mag[l] = 0;
  b.orient[l] = 1;
  const AreaView<double> view = make_area_view(pl, p);
  if (!view.lit) return 0;
  ClipPolygon<double> visible;
  clip_to_horizon(pl, view, n, visible);
  if (visible.count < 3) return 0;
  const Vec3d rv = normalize(rv_in);
  ClipPolygon<double> poly;
  clip_halfspace(visible.d.data(), visible.count, rv, dot(rv, view.D), poly);
  const int count = poly.count;
  if (count < 3) return 0;
  b.lit[l] = true;
  b.orient[l] = view.orient;
  // Per edge as area_specular_closed.h sets it up (arvo_edge; each vertex's direction normalised
  // once, the arc for odd m only); an edge that adds nothing gets zeros (wn = 0).
  const Vec3d first = normalize(view.D + poly.d[0]);
  Vec3d ah = first;
  for (int i = 0; i < count; ++i) {
    const int j = i + 1 < count ? i + 1 : 0;
    const Vec3d bh = j == 0 ? first : normalize(view.D + poly.d[j]);
    ArvoEdge<double> e;
    if (!arvo_edge(view, rv, poly.d[i], poly.d[j], ah, bh, m % 2 == 1, e)) e = {0, 0, 0, 0, 0, 0};
    ah = bh;
    b.wn[i * B + l] = e.wn;
    b.theta[i * B + l] = e.theta;
    b.c0[i * B + l] = e.c0;
    b.c0p[i * B + l] = e.c0p;
    b.c1[i * B + l] = e.c1;
    b.c1p[i * B + l] = e.c1p;
  }
  if (m % 2 == 0) b.omega[l] = fan_solid_angle(poly, view, b.omega_mag[l]);
  return count;
}

// Stage 2: edge slot e of every lane of the block, the recurrence of area_specular_closed.h.
inline void area_specular_chain(int m, int e, int lanes, AreaSpecularBlock& blk) {
  constexpr int B = kAreaSpecularBatchBlock;
  const double* __restrict wn_ = blk.wn + e * B;
  const double* __restrict theta_ = blk.theta + e * B;
  const double* __restrict c0_ = blk.c0 + e * B;
  const double* __restrict c0p_ = blk.c0p + e * B;
  const double* __restrict c1_ = blk.c1 + e * B;
  const double* __restrict c1p_ = blk.c1p + e * B;
  double* __restrict sum_ = blk.sum;
  double* __restrict mag_ = blk.mag;
  const bool odd = m % 2 == 1;
#pragma omp simd
  for (int l = 0; l < lanes; ++l) {
    const double theta = theta_[l], c0 = c0_[l], c0p = c0p_[l], c1 = c1_[l], c1p = c1p_[l];
    const double c2 = c0 * c0 + c0p * c0p;
    const double ac0p = c0p < 0. ? -c0p : c0p, ac1p = c1p < 0. ? -c1p : c1p;
    double f = odd ? theta : c0p - c1p;
    double f_mag = odd ? theta : ac0p + ac1p;
    double p0 = odd ? c0 : c0 * c0, p1 = odd ? c1 : c1 * c1;
    const double q0 = c0 * c0, q1 = c1 * c1;
    double s = 0, s_mag = 0;
    int k = odd ? 0 : 1;
    s += f;
    s_mag += f_mag;
    for (; k + 2 <= m - 1; k += 2) {
      const double e1 = p1 * c1p, e0 = p0 * c0p;
      const double inv = 1. / double(k + 2);  // as area_specular_closed.h: a product with 1 / (k + 2)
      const double ae1 = e1 < 0. ? -e1 : e1, ae0 = e0 < 0. ? -e0 : e0;
      f = (double(k + 1) * c2 * f - (e1 - e0)) * inv;
      f_mag = (double(k + 1) * c2 * f_mag + ae1 + ae0) * inv;
      p0 *= q0;
      p1 *= q1;
      s += f;
      s_mag += f_mag;
    }
    const double wn = wn_[l];
    sum_[l] += wn * s;
    mag_[l] += (wn < 0. ? -wn : wn) * s_mag;
  }
}

}  // namespace batch_detail

// Exact specular of one convex area light (at most kAreaSpecularBatchMaxVertices corners) at
// lanes [begin, end) of `pts` (rx, ry, rz set), integer 0 <= m <= kAreaSpecularBatchMaxShininess.
// Lanes the closed form cannot vouch for are flagged, with 0.
inline void area_specular_batch(const PreparedAreaLight<double>& pl, int m, const BatchPoints& pts, long begin, long end,
                                const BatchSpecularOutput& out) {
  constexpr int B = kAreaSpecularBatchBlock;
  batch_detail::AreaSpecularBlock blk{};
  for (long start = begin; start < end; start += B) {
    const int lanes = int(end - start < B ? end - start : B);
    int slots = 0;
    for (int l = 0; l < lanes; ++l) {
      const long v = start + l;
      const Vec3d p{pts.px[v], pts.py[v], pts.pz[v]};
      const Vec3d n{double(pts.nx[v]), double(pts.ny[v]), double(pts.nz[v])};
      const Vec3d rv{pts.rx[v], pts.ry[v], pts.rz[v]};
      const int count = batch_detail::area_specular_setup(pl, m, p, n, rv, l, blk);
      // Slots beyond this lane's edges contribute nothing (wn = 0, finite start values).
      for (int e = count; e < batch_detail::kAreaSpecularSlots; ++e) {
        blk.wn[e * B + l] = 0;
        blk.theta[e * B + l] = 0;
        blk.c0[e * B + l] = blk.c0p[e * B + l] = blk.c1[e * B + l] = blk.c1p[e * B + l] = 0;
      }
      blk.sum[l] = 0;
      blk.mag[l] = 0;
      slots = count > slots ? count : slots;
    }
    if (m > 0)
      for (int e = 0; e < slots; ++e) batch_detail::area_specular_chain(m, e, lanes, blk);
    constexpr double eps = std::numeric_limits<double>::epsilon();
    for (int l = 0; l < lanes; ++l) {
      const long v = start + l;
      if (!blk.lit[l]) {
        out.specular[v] = 0;
        out.stiff[v] = 0;
        continue;
      }
      double total = -blk.orient[l] * blk.sum[l];
      double mag = blk.mag[l];
      if (m % 2 == 0) {
        total += std::fabs(blk.omega[l]);
        mag += blk.omega_mag[l];
      }
      const double abs_total = std::fabs(total);
      const double condition = abs_total > 0 ? double(m + 8) * eps * mag / abs_total
                                             : (mag > 0 ? std::numeric_limits<double>::infinity() : 0.);
      const bool accepted = condition <= kAreaClosedBound && mag <= kAreaClosedMaxCancellation * abs_total;
      out.specular[v] = accepted ? std::fmax(total / double(m + 1), 0.) : 0.;
      out.stiff[v] = accepted ? 0 : 1;
    }
  }
}

}  // namespace vlit
