// Case inputs of the accuracy report on the float grid: every case is rounded to float before its
// reference is computed, so one long-double reference serves the double and the float evaluation
// and the float error is the computation's own (docs/accuracy.md.in, "How to read this").
#pragma once

#include <cmath>
#include <random>
#include <utility>

#include "core/vec3.h"

namespace vlit::bench::accuracy {

inline Vec3d to_float_grid(const Vec3d& v) { return static_cast<Vec3d>(static_cast<Vec3f>(v)); }

// A unit direction rounded to float with |v| <= 1 exactly (in long double): its largest component
// is moved towards zero one float step at a time until the norm is at most 1. The kernels take Rv
// as a unit vector and clamp cos α to 1 (shaders_cpu/linear_specular_peak.h); plain rounding can
// give |Rv| = 1 + 1e-8, and then the literal integrand max(0, Rv.L̂)^m of the reference exceeds 1
// near the peak by up to m x 1e-8: with m = 1e4 the two differ by ~1e-6 relative, a difference
// of inputs, not of methods (docs/linear-lights.md, "Measured accuracy").
inline Vec3d unit_on_float_grid(const Vec3d& v) {
  Vec3f f = static_cast<Vec3f>(normalize(v));
  auto norm2 = [](const Vec3f& x) { return (long double)x.x * x.x + (long double)x.y * x.y + (long double)x.z * x.z; };
  for (int i = 0; i < 8 && norm2(f) > 1.0L; ++i) {
    float* big = std::fabs(f.x) >= std::fabs(f.y) && std::fabs(f.x) >= std::fabs(f.z) ? &f.x
                 : std::fabs(f.y) >= std::fabs(f.z)                                   ? &f.y
                                                                                      : &f.z;
    *big = std::nextafter(*big, 0.0f);
  }
  return static_cast<Vec3d>(f);
}

// A shading point's inputs on the float grid: P; N and Rv normalised, then rounded; m.
inline void round_shading_inputs(Vec3d& p, Vec3d& n, Vec3d& rv, double& m) {
  p = to_float_grid(p);
  n = to_float_grid(normalize(n));
  rv = to_float_grid(normalize(rv));
  m = double(float(m));
}

inline Vec3d random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  for (;;) {
    const Vec3d v{g(rng), g(rng), g(rng)};
    if (length(v) > 1e-3) return normalize(v);
  }
}

// 10^x for x uniform in [lo, hi].
inline double log_uniform(std::mt19937_64& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u01(0, 1);
  return std::pow(10.0, lo + (hi - lo) * u01(rng));
}

// A shading point's unit normal N and reflected view direction Rv biased towards the light: the
// direction to the light plus a random unit vector times 0.7 (N) and times rv_spread (Rv), drawn
// in that order.
inline std::pair<Vec3d, Vec3d> facing_light(const Vec3d& to_light, double rv_spread, std::mt19937_64& rng) {
  const Vec3d n = normalize(to_light + random_unit(rng) * 0.7);
  const Vec3d rv = normalize(to_light + random_unit(rng) * rv_spread);
  return {n, rv};
}

}  // namespace vlit::bench::accuracy
