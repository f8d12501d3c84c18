// Point, spot and directional lights, diffuse, float batch over structure-of-arrays points.
//
// What it computes (unit intensity, kd = 1; conventions.h), the same quantities as point_light.h,
// spot_light.h and directional_light.h times the glTF range window of prepared_light.h:
//   point:       max(0, N.L̂) / |L|^n, L = Q - P, integer n in {0, 1, 2, 3}   (Picott 1992 eq. 1)
//   spot:        the point light times s^2, s = clamp((cos - cos_outer) / max(cos_inner - cos_outer,
//                1e-6), 0, 1), cos = (P - Q)^.axis                          (KHR_lights_punctual)
//   directional: max(0, -N.direction)
//   range window (point, spot; range > 0): clamp(1 - (|L| / range)^4, 0, 1).
// Precision: these kernels compute in double and round the result to float once. Measured: in
// float, N.L loses eps/cos(theta) relative at grazing light (1.1e-4 on the random set of the test
// below), the spot's penumbra (cos - cos_outer) and the range window (1 - (d/range)^4) cancel the
// same way; they are so cheap that double costs little (docs/performance.md). A lane at the light's
// position (|L|^2 below 1e-60) is flagged for the scalar kernel, which returns 0 there.
#pragma once

#include <cmath>

#include "batch/batch_points.h"

namespace vlit {

struct PunctualBatchLight {
  enum class Kind { kPoint, kSpot, kDirectional } kind = Kind::kPoint;
  double position[3] = {0, 0, 0};
  double direction[3] = {0, 0, -1};  // spot axis / directional travel direction, unit
  int falloff = 2;                    // integer n in {0, 1, 2, 3}
  double cos_outer = 0, inv_cone_width = 1;
  double inv_range2 = 0;              // 1 / range^2, 0 = unlimited
};

namespace batch_detail {

// value / |L|^n times the spot's s^2 and the range window, in that order (the diffuse and the
// specular lanes share it); L = (lx, ly, lz), d2 = |L|^2, dist = |L|, inv_dist = 1/|L| (0 at the
// light); a zero |L|^n divides by 1 (the lane is flagged there).
template <int kFalloff, bool kSpot>
inline double punctual_attenuated(const PunctualBatchLight& L, double value, double lx, double ly, double lz,
                                  double d2, double dist, double inv_dist) {
  double falloff = 1.;
  if constexpr (kFalloff == 1) falloff = dist;
  if constexpr (kFalloff == 2) falloff = d2;
  if constexpr (kFalloff == 3) falloff = d2 * dist;
  value = value / (falloff > 0. ? falloff : 1.);
  if constexpr (kSpot) {
    const double c = -(lx * L.direction[0] + ly * L.direction[1] + lz * L.direction[2]) * inv_dist;
    double s = (c - L.cos_outer) * L.inv_cone_width;
    s = s < 0. ? 0. : (s > 1. ? 1. : s);
    value *= s * s;
  }
  const double ratio2 = d2 * L.inv_range2;
  double window = 1. - ratio2 * ratio2;
  window = window < 0. ? 0. : (window > 1. ? 1. : window);
  return value * window;
}

template <int kFalloff, bool kSpot>
inline void punctual_lane(const PunctualBatchLight& L, double px, double py, double pz, float nxf, float nyf, float nzf,
                          float& result, std::uint8_t& stiff_flag) {
  const double nx = nxf, ny = nyf, nz = nzf;
  const double lx = L.position[0] - px, ly = L.position[1] - py, lz = L.position[2] - pz;
  const double d2 = lx * lx + ly * ly + lz * lz;
  const double ndl = nx * lx + ny * ly + nz * lz;
  const double dist = std::sqrt(d2);
  const double inv_dist = d2 > 0. ? 1. / dist : 0.;
  const double value = punctual_attenuated<kFalloff, kSpot>(L, ndl * inv_dist, lx, ly, lz, d2, dist, inv_dist);
  const bool stiff = !(d2 > 1e-60);
  constexpr double kFloatMax = 3.4028234663852886e38;
  result = (!stiff) & (ndl > 0.) & (value > 0.) ? float(value < kFloatMax ? value : kFloatMax) : 0.f;
  stiff_flag = stiff ? 1 : 0;
}

template <int kFalloff, bool kSpot>
inline void punctual_loop(const PunctualBatchLight& light, const BatchPoints& pts, long begin, long end, const BatchOutput& out) {
  const PunctualBatchLight L = light;  // a local copy: provably not aliased by the output arrays
  for_each_lane(pts, begin, end, out,
                [&L](double px, double py, double pz, float nx, float ny, float nz, float& diffuse, std::uint8_t& stiff) {
                  punctual_lane<kFalloff, kSpot>(L, px, py, pz, nx, ny, nz, diffuse, stiff);
                });
}

template <bool kSpot>
inline void punctual_by_falloff(const PunctualBatchLight& L, const BatchPoints& pts, long begin, long end, const BatchOutput& out) {
  switch (L.falloff) {
    case 0: punctual_loop<0, kSpot>(L, pts, begin, end, out); break;
    case 1: punctual_loop<1, kSpot>(L, pts, begin, end, out); break;
    case 3: punctual_loop<3, kSpot>(L, pts, begin, end, out); break;
    default: punctual_loop<2, kSpot>(L, pts, begin, end, out); break;
  }
}

}  // namespace batch_detail

// Diffuse of one point, spot or directional light at lanes [begin, end).
inline void punctual_diffuse_batch(const PunctualBatchLight& light, const BatchPoints& pts, long begin, long end,
                                   const BatchOutput& out) {
  if (light.kind == PunctualBatchLight::Kind::kDirectional) {
    const double tx = -light.direction[0], ty = -light.direction[1], tz = -light.direction[2];
    for_each_lane(pts, begin, end, out,
                  [tx, ty, tz](double, double, double, float nx, float ny, float nz, float& diffuse, std::uint8_t& stiff) {
                    const double c = double(nx) * tx + double(ny) * ty + double(nz) * tz;
                    diffuse = c > 0. ? float(c) : 0.f;
                    stiff = 0;
                  });
  } else if (light.kind == PunctualBatchLight::Kind::kSpot) {
    batch_detail::punctual_by_falloff<true>(light, pts, begin, end, out);
  } else {
    batch_detail::punctual_by_falloff<false>(light, pts, begin, end, out);
  }
}

}  // namespace vlit
