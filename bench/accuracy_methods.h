// Baseline methods the accuracy report (bench/accuracy/*_report.cpp) compares the kernels with: a
// fixed-order Gauss-Legendre rule and plain / stratified Monte Carlo for the linear light, and
// plain / stratified Monte Carlo over the polygon's area for the area light. They are what a user
// would write without the paper's closed forms, so they are measured, not shipped.
//
// All of them compute in the caller's scalar type T (float really computes in float here, unlike
// the kernels, which compute float in double), after the same horizon clipping in t (linear) or by
// the max(0, .) of the integrand (area). Random numbers: splitmix64, seeded per case, so every run
// of the report sees the same samples.
// Conventions: shaders_cpu/conventions.h (unit intensity, kd = ks = 1).
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "area_polygon.h"
#include "linear_geometry.h"

namespace vlit::bench {

// --- Fixed-order Gauss-Legendre on [-1, 1], nodes and weights by Newton's iteration ---------------

struct FixedRule {
  std::vector<double> x, w;  // all N nodes and weights
};

// Roots of the Legendre polynomial P_n by Newton from the asymptotic guess cos(pi (i - 1/4)/(n + 1/2)),
// weights 2 / ((1 - x^2) P_n'(x)^2); long double iterations, stored in double.
inline FixedRule make_fixed_rule(int n) {
  FixedRule r;
  const long double pi = 3.141592653589793238462643383279502884L;
  for (int i = 1; i <= n; ++i) {
    long double x = std::cos(pi * (i - 0.25L) / (n + 0.5L)), dp = 1;
    for (int it = 0; it < 60; ++it) {
      long double p_prev = 1, p = x;
      for (int k = 2; k <= n; ++k) {
        const long double p_next = ((2 * k - 1) * x * p - (k - 1) * p_prev) / k;
        p_prev = p;
        p = p_next;
      }
      dp = n * (x * p - p_prev) / (x * x - 1);
      const long double step = p / dp;
      x -= step;
      if (std::fabs(step) < 1e-20L) break;
    }
    r.x.push_back(double(x));
    r.w.push_back(double(2 / ((1 - x * x) * dp * dp)));
  }
  return r;
}

// --- Random numbers -----------------------------------------------------------------------------

struct SplitMix64 {
  std::uint64_t state;
  explicit SplitMix64(std::uint64_t seed) : state(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  template <class T>
  T uniform() { return T(double(next() >> 11) * 0x1.0p-53); }  // [0, 1)
};

// --- Linear light: integrands in the paper's parametrisation t in [0, 1] --------------------------

template <class T>
struct LinearT {
  Vec3<T> l0, ld;  // L(t) = l0 + t ld
  T ta = 0, tb = 1;  // visible (horizon-clipped) interval
  bool visible = false;
};

template <class T>
LinearT<T> linear_t(const LinearLight<T>& light, const ShadingPoint<T>& sp) {
  LinearT<T> g;
  g.l0 = light.q0 - sp.p;
  g.ld = light.q1 - light.q0;
  const T c0 = dot(g.l0, sp.n), c1 = dot(light.q1 - sp.p, sp.n);
  if (c0 <= T(0) && c1 <= T(0)) return g;
  if (c0 < T(0)) g.ta = c0 / (c0 - c1);
  else if (c1 < T(0)) g.tb = c0 / (c0 - c1);
  g.visible = g.tb > g.ta;
  return g;
}

template <class T>
T linear_diffuse_integrand(const LinearT<T>& g, const ShadingPoint<T>& sp, T falloff, T t) {
  const Vec3<T> l = g.l0 + g.ld * t;
  const T c = std::max(dot(l, sp.n), T(0));
  return c / std::pow(dot(l, l), (falloff + T(1)) / T(2));
}

template <class T>
T linear_specular_integrand(const LinearT<T>& g, const ShadingPoint<T>& sp, T t) {
  const Vec3<T> l = g.l0 + g.ld * t;
  if (!(dot(l, sp.n) > T(0))) return T(0);
  const T r = std::sqrt(dot(l, l));
  const T c = r > T(0) ? dot(l, sp.rv) / r : T(0);
  if (sp.shininess == T(0)) return T(1);
  return c > T(0) ? std::pow(std::min(c, T(1)), sp.shininess) : T(0);
}

// Fixed-order Gauss-Legendre over the visible interval (one panel).
template <class T, class F>
T fixed_gauss(const FixedRule& rule, T ta, T tb, const F& f) {
  const T mid = (ta + tb) / T(2), half = (tb - ta) / T(2);
  T sum = 0;
  for (std::size_t i = 0; i < rule.x.size(); ++i) sum += T(rule.w[i]) * f(mid + half * T(rule.x[i]));
  return sum * half;
}

// Plain (stratified = false) or jittered-stratified Monte Carlo over [ta, tb] with n samples.
template <class T, class F>
T monte_carlo_1d(std::uint64_t seed, int n, bool stratified, T ta, T tb, const F& f) {
  SplitMix64 rng(seed);
  T sum = 0;
  for (int i = 0; i < n; ++i) {
    const T u = stratified ? (T(i) + rng.uniform<T>()) / T(n) : rng.uniform<T>();
    sum += f(ta + (tb - ta) * u);
  }
  return sum * (tb - ta) / T(n);
}

// --- Area light: Monte Carlo over the polygon's area ----------------------------------------------

// A convex polygon fanned from vertex 0, in T, with the cumulative area of its triangles.
template <class T>
struct AreaSampler {
  std::vector<Vec3<T>> q;
  std::vector<T> cdf;  // cumulative triangle areas, cdf.back() = total area
  Vec3<T> normal;      // unit emitting normal
  bool two_sided = false;
};

template <class T>
AreaSampler<T> make_area_sampler(const std::vector<Vec3<T>>& polygon, bool two_sided) {
  AreaSampler<T> s;
  s.q = polygon;
  s.two_sided = two_sided;
  Vec3<T> twice{};
  T acc = 0;
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
    const Vec3<T> c = cross(polygon[i] - polygon[0], polygon[i + 1] - polygon[0]);
    twice += c;
    acc += length(c) / T(2);
    s.cdf.push_back(acc);
  }
  s.normal = normalize(twice);
  return s;
}

// Integrand of the diffuse (specular = false) or the exact specular at the light point x.
template <class T>
T area_integrand(const AreaSampler<T>& s, const ShadingPoint<T>& sp, const Vec3<T>& x, bool specular) {
  const Vec3<T> a = x - sp.p;
  const T r2 = dot(a, a);
  const T r = std::sqrt(r2);
  if (!(r > T(0))) return T(0);
  T cos_l = -dot(s.normal, a) / r;
  if (s.two_sided) cos_l = std::fabs(cos_l);
  const T cos_n = dot(sp.n, a) / r;
  if (!(cos_l > T(0)) || !(cos_n > T(0))) return T(0);
  if (!specular) return cos_n * cos_l / r2;
  const T c = dot(sp.rv, a) / r;
  const T lobe = sp.shininess == T(0) ? T(1) : (c > T(0) ? std::pow(std::min(c, T(1)), sp.shininess) : T(0));
  return lobe * cos_l / r2;
}

// Uniform area sampling: (u1, u2) in [0, 1)^2 -> triangle by u1 (inverse CDF, u1 reused within
// it), point by the square-root warp. n must be a square when stratified (jittered k x k grid).
template <class T>
T area_monte_carlo(const AreaSampler<T>& s, const ShadingPoint<T>& sp, std::uint64_t seed, int n, bool stratified,
                   bool specular) {
  SplitMix64 rng(seed);
  const T total = s.cdf.back();
  const int k = int(std::lround(std::sqrt(double(n))));
  T sum = 0;
  for (int i = 0; i < n; ++i) {
    T u1 = rng.uniform<T>(), u2 = rng.uniform<T>();
    if (stratified) {
      u1 = (T(i / k) + u1) / T(k);
      u2 = (T(i % k) + u2) / T(k);
    }
    const T target = u1 * total;
    std::size_t tri = 0;
    while (tri + 1 < s.cdf.size() && s.cdf[tri] <= target) ++tri;
    const T lo = tri == 0 ? T(0) : s.cdf[tri - 1];
    const T width = s.cdf[tri] - lo;
    const T v = width > T(0) ? std::min(std::max((target - lo) / width, T(0)), T(1)) : T(0);
    const T root = std::sqrt(v);
    const Vec3<T> x = s.q[0] * (T(1) - root) + s.q[tri + 1] * (root * (T(1) - u2)) + s.q[tri + 2] * (root * u2);
    sum += area_integrand(s, sp, x, specular);
  }
  return sum * total / T(n);
}

}  // namespace vlit::bench
