// Point, spot and directional lights, Phong specular, batch over structure-of-arrays points.
//
// What it computes (unit intensity, ks = 1; conventions.h), the specular of point_light.h,
// spot_light.h and directional_light.h times the glTF range window of prepared_light.h:
//   point:       [N.L > 0] max(0, Rv.L̂)^m / |L|^n, L = Q - P     (Picott 1992 eq. 6; the falloff
//                1/|L|^n of the diffuse, integer n in {0, 1, 2, 3}, or none: SpecularFalloff::kNone)
//   spot:        the point light times the cone factor s^2 of punctual_diffuse_batch.h
//   directional: [N.L̂ > 0] max(0, Rv.L̂)^m, L̂ = -direction
// with one shininess m >= 0 (real) for all lanes (one material per primitive) and Rv per lane.
// The specular is the same for every specular method (peak, neighbourhood and exact agree on a
// point light); only SpecularFalloff changes it.
//
// Precision: everything in double (positions, Rv, the cosine); the power as
// exp(m ln c) with double_log.h and double_exp.h (2.2e-16 relative against std::exp), whose
// relative error is a few 1e-16 times max(1, m |ln c|); the result is stored in double. Measured
// against the scalar double kernel (std::pow) on the test's random set: 2e-14 at m = 100, 1.2e-12
// at m = 1e4 (`build/release/tests/batch_kernel_tests -tc="punctual specular*" -s`).
// The normal is the lanes' float normal (batch_points.h): it decides only the horizon [N.L > 0],
// which the specular, unlike the diffuse, does not reach continuously (the lobe may be bright at the
// horizon). A lane whose |N.L̂| is below kHorizonMargin, where the float normal's rounding (a few
// 1e-8) could flip the side the double kernel sees, is flagged for the scalar kernel, as is a lane
// at the light's position (|L|^2 below 1e-60).
// Tests: tests/kernels/batch/batch_specular_test.cpp ("punctual specular ...").
#pragma once

#include <cmath>
#include <cstdint>

#include "batch/batch_points.h"
#include "batch/double_exp.h"
#include "batch/double_log.h"
#include "batch/punctual_diffuse_batch.h"

namespace vlit {

// Per-lane outputs of the batch specular kernels: the specular response for unit intensity
// (ks = 1, conventions.h) and a flag for lanes the caller recomputes with the scalar double kernel.
struct BatchSpecularOutput {
  double* specular = nullptr;
  std::uint8_t* stiff = nullptr;
};

namespace batch_detail {

constexpr double kHorizonMargin = 1e-6;

// max(0, c)^m for any c, m >= 0 (0 where c <= 0; 1 where c > 0 and m = 0, as std::pow).
inline double phong_power_lane(double c, double m) {
  const double c_safe = c > 0. ? c : 1.;
  const double value = exp_nonpositive(m * (c_safe < 1. ? log_positive(c_safe) : 0.));
  return c > 0. ? value : 0.;
}

template <int kFalloff, bool kSpot>
inline void punctual_specular_lane(const PunctualBatchLight& L, double m, double px, double py, double pz, float nxf,
                                   float nyf, float nzf, double rx, double ry, double rz, double& result,
                                   std::uint8_t& stiff_flag) {
  const double nx = nxf, ny = nyf, nz = nzf;
  const double lx = L.position[0] - px, ly = L.position[1] - py, lz = L.position[2] - pz;
  const double d2 = lx * lx + ly * ly + lz * lz;
  const double dist = std::sqrt(d2);
  const double inv_dist = d2 > 0. ? 1. / dist : 0.;
  const double ndl = nx * lx + ny * ly + nz * lz;
  const double c = (rx * lx + ry * ly + rz * lz) * inv_dist;
  const double value = punctual_attenuated<kFalloff, kSpot>(L, phong_power_lane(c, m), lx, ly, lz, d2, dist, inv_dist);
  const bool stiff = (!(d2 > 1e-60)) | (std::fabs(ndl) <= kHorizonMargin * dist);
  result = (!stiff) & (ndl > 0.) ? value : 0.;
  stiff_flag = stiff ? 1 : 0;
}

// for_each_lane (batch_points.h) for the specular: lane(px, py, pz, nx, ny, nz, rx, ry, rz,
// specular, stiff) over restrict-qualified copies of the arrays, as one `omp simd` loop.
template <class Lane>
inline void for_each_specular_lane(const BatchPoints& pts, long begin, long end, const BatchSpecularOutput& out,
                                   const Lane& lane) {
  const double* __restrict px = pts.px;
  const double* __restrict py = pts.py;
  const double* __restrict pz = pts.pz;
  const float* __restrict nx = pts.nx;
  const float* __restrict ny = pts.ny;
  const float* __restrict nz = pts.nz;
  const double* __restrict rx = pts.rx;
  const double* __restrict ry = pts.ry;
  const double* __restrict rz = pts.rz;
  double* __restrict specular = out.specular;
  std::uint8_t* __restrict stiff = out.stiff;
#pragma omp simd
  for (long v = begin; v < end; ++v)
    lane(px[v], py[v], pz[v], nx[v], ny[v], nz[v], rx[v], ry[v], rz[v], specular[v], stiff[v]);
}

template <int kFalloff, bool kSpot>
inline void punctual_specular_loop(const PunctualBatchLight& light, double m, const BatchPoints& pts, long begin, long end,
                                   const BatchSpecularOutput& out) {
  const PunctualBatchLight L = light;  // a local copy: provably not aliased by the output arrays
  for_each_specular_lane(pts, begin, end, out,
                         [&L, m](double px, double py, double pz, float nx, float ny, float nz, double rx, double ry,
                                 double rz, double& specular, std::uint8_t& stiff) {
                           punctual_specular_lane<kFalloff, kSpot>(L, m, px, py, pz, nx, ny, nz, rx, ry, rz, specular, stiff);
                         });
}

template <bool kSpot>
inline void punctual_specular_by_falloff(const PunctualBatchLight& L, bool with_falloff, double m, const BatchPoints& pts,
                                         long begin, long end, const BatchSpecularOutput& out) {
  switch (with_falloff ? L.falloff : 0) {
    case 0: punctual_specular_loop<0, kSpot>(L, m, pts, begin, end, out); break;
    case 1: punctual_specular_loop<1, kSpot>(L, m, pts, begin, end, out); break;
    case 3: punctual_specular_loop<3, kSpot>(L, m, pts, begin, end, out); break;
    default: punctual_specular_loop<2, kSpot>(L, m, pts, begin, end, out); break;
  }
}

}  // namespace batch_detail

// Specular of one point, spot or directional light at lanes [begin, end) of `pts` (whose rx, ry,
// rz must be set), shininess m >= 0; `with_falloff`: 1/|L|^n on the specular (SpecularFalloff).
inline void punctual_specular_batch(const PunctualBatchLight& light, bool with_falloff, double m, const BatchPoints& pts,
                                    long begin, long end, const BatchSpecularOutput& out) {
  if (light.kind == PunctualBatchLight::Kind::kDirectional) {
    const double tx = -light.direction[0], ty = -light.direction[1], tz = -light.direction[2];
    batch_detail::for_each_specular_lane(
        pts, begin, end, out,
        [tx, ty, tz, m](double, double, double, float nx, float ny, float nz, double rx, double ry, double rz,
                        double& specular, std::uint8_t& stiff) {
          const double ndl = double(nx) * tx + double(ny) * ty + double(nz) * tz;
          const double value = batch_detail::phong_power_lane(rx * tx + ry * ty + rz * tz, m);
          const bool flag = std::fabs(ndl) <= batch_detail::kHorizonMargin;
          specular = (!flag) & (ndl > 0.) ? value : 0.;
          stiff = flag ? 1 : 0;
        });
  } else if (light.kind == PunctualBatchLight::Kind::kSpot) {
    batch_detail::punctual_specular_by_falloff<true>(light, with_falloff, m, pts, begin, end, out);
  } else {
    batch_detail::punctual_specular_by_falloff<false>(light, with_falloff, m, pts, begin, end, out);
  }
}

}  // namespace vlit
