// Independent references for the shadow tests: lights sampled densely with shadow rays
// (stratified, jittered), each ray tested against every occluder triangle with a ray/triangle
// test of its own (plane hit + edge functions; not the BVH's Moller-Trumbore). The tolerance of
// an estimate comes from its own samples: the standard error of the mean of iid samples, an
// upper bound for the stratified estimator.
#pragma once

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "core/vec3.h"

namespace vlit::test {

using Tri = std::array<Vec3d, 3>;

// Does the open segment p -> q (excluding 1e-9 of its length at both ends) cross the triangle?
inline bool reference_blocked(const Vec3d& p, const Vec3d& q, const std::vector<Tri>& occluders) {
  const Vec3d d = q - p;
  for (const Tri& t : occluders) {
    if (t[0] == p || t[1] == p || t[2] == p) continue;  // the vertex's own triangles
    const Vec3d n = cross(t[1] - t[0], t[2] - t[0]);
    const double denom = dot(n, d);
    if (denom == 0) continue;
    const double s = dot(n, t[0] - p) / denom;
    if (!(s > 1e-9 && s < 1 - 1e-9)) continue;
    const Vec3d x = p + d * s;
    const double e0 = dot(cross(t[1] - t[0], x - t[0]), n);
    const double e1 = dot(cross(t[2] - t[1], x - t[1]), n);
    const double e2 = dot(cross(t[0] - t[2], x - t[2]), n);
    if (e0 >= 0 && e1 >= 0 && e2 >= 0) return true;
  }
  return false;
}

struct Estimate {
  double value = 0;
  double standard_error = 0;
};

// Running mean and variance of samples (Welford).
struct Accumulator {
  double n = 0, mean = 0, m2 = 0;
  void add(double x) {
    n += 1;
    const double d = x - mean;
    mean += d / n;
    m2 += d * (x - mean);
  }
  Estimate estimate(double scale) const {
    return {scale * mean, scale * std::sqrt(m2 / (n - 1) / n)};
  }
};

struct ReferencePoint {
  Vec3d p, n, rv;
  double m = 1;
};

// Diffuse and exact specular of a convex one-sided polygon light (counter-clockwise seen from
// the side it emits to), with grid x grid jittered samples per fan triangle.
inline std::array<Estimate, 2> reference_area(const std::vector<Vec3d>& polygon, const ReferencePoint& pt,
                                              const std::vector<Tri>& occluders, int grid, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jitter(0.0, 1.0);
  Vec3d newell{};
  for (std::size_t i = 0; i < polygon.size(); ++i) newell += cross(polygon[i], polygon[(i + 1) % polygon.size()]);
  const Vec3d nl = newell / length(newell);
  std::array<Estimate, 2> total{};
  double var_d = 0, var_s = 0;
  for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
    const Vec3d a = polygon[0], b = polygon[k], c = polygon[k + 1];
    const double area = 0.5 * length(cross(b - a, c - a));
    Accumulator diffuse, specular;
    for (int i = 0; i < grid; ++i)
      for (int j = 0; j < grid; ++j) {
        const double u1 = (i + jitter(rng)) / grid, u2 = (j + jitter(rng)) / grid;
        const double s = std::sqrt(u1);
        const Vec3d y = a * (1 - s) + b * (s * (1 - u2)) + c * (s * u2);
        const Vec3d w = y - pt.p;
        const double r2 = length_squared(w);
        const Vec3d wn = w / std::sqrt(r2);
        const double cos_theta = dot(pt.n, wn), cos_l = -dot(nl, wn);
        double fd = 0, fs = 0;
        if (cos_theta > 0 && cos_l > 0 && !reference_blocked(pt.p, y, occluders)) {
          fd = cos_theta * cos_l / r2;
          const double c_rv = dot(pt.rv, wn);
          fs = c_rv > 0 ? std::pow(c_rv, pt.m) * cos_l / r2 : 0;
        }
        diffuse.add(fd);
        specular.add(fs);
      }
    const Estimate ed = diffuse.estimate(area), es = specular.estimate(area);
    total[0].value += ed.value;
    total[1].value += es.value;
    var_d += ed.standard_error * ed.standard_error;
    var_s += es.standard_error * es.standard_error;
  }
  total[0].standard_error = std::sqrt(var_d);
  total[1].standard_error = std::sqrt(var_s);
  return total;
}

// Diffuse of a one-sided disk light (centre c, unit normal nl toward the side it emits to, radius
// r), with grid x grid jittered samples uniform in area (radius sqrt(u1) r, angle 2 pi u2).
inline Estimate reference_disk(const Vec3d& c, const Vec3d& nl, double r, const ReferencePoint& pt,
                               const std::vector<Tri>& occluders, int grid, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jitter(0.0, 1.0);
  const Vec3d helper = std::abs(nl.x) < 0.6 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
  const Vec3d e1 = normalize(cross(nl, helper)), e2 = cross(nl, e1);
  Accumulator diffuse;
  for (int i = 0; i < grid; ++i)
    for (int j = 0; j < grid; ++j) {
      const double u1 = (i + jitter(rng)) / grid, u2 = (j + jitter(rng)) / grid;
      const double rho = r * std::sqrt(u1), phi = 2 * M_PI * u2;
      const Vec3d y = c + e1 * (rho * std::cos(phi)) + e2 * (rho * std::sin(phi));
      const Vec3d w = y - pt.p;
      const double r2 = length_squared(w);
      const Vec3d wn = w / std::sqrt(r2);
      const double cos_theta = dot(pt.n, wn), cos_l = -dot(nl, wn);
      double fd = 0;
      if (cos_theta > 0 && cos_l > 0 && !reference_blocked(pt.p, y, occluders)) fd = cos_theta * cos_l / r2;
      diffuse.add(fd);
    }
  return diffuse.estimate(M_PI * r * r);
}

// Diffuse of a linear light (intensity per unit t) with falloff n, `samples` jittered strata in t.
inline Estimate reference_linear(const Vec3d& q0, const Vec3d& q1, double falloff, const ReferencePoint& pt,
                                 const std::vector<Tri>& occluders, int samples, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jitter(0.0, 1.0);
  Accumulator acc;
  for (int i = 0; i < samples; ++i) {
    const double t = (i + jitter(rng)) / samples;
    const Vec3d y = q0 + (q1 - q0) * t;
    const Vec3d l = y - pt.p;
    const double len = length(l);
    const double ln = dot(l, pt.n);
    double f = 0;
    if (ln > 0 && !reference_blocked(pt.p, y, occluders)) f = ln / std::pow(len, falloff + 1);
    acc.add(f);
  }
  return acc.estimate(1.0);
}

// Exact specular of a linear light (conventions.h: intensity per unit of t; the lobe
// [L.N > 0] max(0, Rv.L^)^m, times 1/|L|^n when `falloff_on_specular`), with shadow rays as
// reference_linear's.
inline Estimate reference_linear_specular(const Vec3d& q0, const Vec3d& q1, double falloff, bool falloff_on_specular,
                                          const ReferencePoint& pt, const std::vector<Tri>& occluders, int samples,
                                          unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jitter(0.0, 1.0);
  Accumulator acc;
  const Vec3d rv = normalize(pt.rv);
  for (int i = 0; i < samples; ++i) {
    const double t = (i + jitter(rng)) / samples;
    const Vec3d y = q0 + (q1 - q0) * t;
    const Vec3d l = y - pt.p;
    const double len = length(l);
    const double c = dot(rv, l) / len;
    double f = 0;
    if (dot(l, pt.n) > 0 && c > 0 && !reference_blocked(pt.p, y, occluders))
      f = std::pow(c, pt.m) / (falloff_on_specular ? std::pow(len, falloff) : 1.0);
    acc.add(f);
  }
  return acc.estimate(1.0);
}

}  // namespace vlit::test
