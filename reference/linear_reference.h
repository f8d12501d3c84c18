// Independent references for the linear-light kernels: Boost.Math Gauss-Kronrod in long double,
// in the paper's own parametrisation t in [0, 1] (not the kernels' local frame), with the
// integral split at the horizon crossing, at the point of closest approach (with a geometric
// grading around it) and, for the specular, around the peak found by dense search.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "linear_light.h"

namespace vlit::linear_test {

using LD = long double;
using V = Vec3<LD>;

// One configuration, in double (the float tests round it to float first and use the rounded
// values for the reference too).
struct Config {
  Vec3d p, n, rv, q0, q1;
  double shininess = 1;
  std::string name;
};

template <class T>
struct Typed {
  LinearLight<T> light;
  ShadingPoint<T> sp;
};

template <class T>
Typed<T> typed(const Config& c, double falloff) {
  Typed<T> r;
  r.light = {static_cast<Vec3<T>>(c.q0), static_cast<Vec3<T>>(c.q1), T(falloff)};
  r.sp.p = static_cast<Vec3<T>>(c.p);
  r.sp.n = static_cast<Vec3<T>>(c.n);
  r.sp.rv = static_cast<Vec3<T>>(c.rv);
  r.sp.shininess = T(c.shininess);
  return r;
}

// The reference geometry in long double from the (already typed) inputs.
struct RefGeom {
  V l0, ld, n, rv;
  LD ell, t_foot, h_t;  // |Ld|, closest approach parameter, h / |Ld|
  LD ta = 0, tb = 1;    // visible interval in t
  bool visible = true;
};

template <class T>
RefGeom ref_geom(const Typed<T>& x) {
  RefGeom g;
  const V p = static_cast<V>(x.sp.p);
  const V q0 = static_cast<V>(x.light.q0), q1 = static_cast<V>(x.light.q1);
  g.l0 = q0 - p;
  g.ld = q1 - q0;
  g.n = static_cast<V>(x.sp.n);
  g.rv = static_cast<V>(x.sp.rv);
  g.ell = std::sqrt(dot(g.ld, g.ld));
  g.t_foot = g.ell > 0 ? -dot(g.l0, g.ld) / (g.ell * g.ell) : 0;
  g.h_t = g.ell > 0 ? std::sqrt(dot(cross(g.l0, g.ld), cross(g.l0, g.ld))) / (g.ell * g.ell) : 0;
  const LD c0 = dot(g.l0, g.n), c1 = dot(g.l0 + g.ld, g.n);
  if (c0 <= 0 && c1 <= 0) g.visible = false;
  else if (c0 < 0) g.ta = c0 / (c0 - c1);
  else if (c1 < 0) g.tb = c0 / (c0 - c1);
  return g;
}

// Breakpoints: visible ends, the foot and a grading of ratio 4 around it (from h_t), and extras.
inline std::vector<LD> breakpoints(const RefGeom& g, std::initializer_list<LD> extra, LD grading_center = -1,
                                   LD grading_start = 0) {
  std::vector<LD> b{g.ta, g.tb};
  auto add = [&](LD t) { if (t > g.ta && t < g.tb) b.push_back(t); };
  add(g.t_foot);
  for (LD w = std::max(g.h_t, LD(1e-30)), k = 0; k < 60 && w < 2; w *= 4, ++k) { add(g.t_foot - w); add(g.t_foot + w); }
  for (LD e : extra) add(e);
  if (grading_center >= 0) {
    add(grading_center);
    for (LD w = grading_start, k = 0; k < 40 && w < 2; w *= 4, ++k) { add(grading_center - w); add(grading_center + w); }
  }
  std::sort(b.begin(), b.end());
  b.erase(std::unique(b.begin(), b.end()), b.end());
  return b;
}

// Gauss-Kronrod 61 on [a, b], bisected while its error estimate exceeds abs_tol. Boost is called
// non-adaptively on a [-1, 1] map of each piece: Boost 1.74's recursive gauss_kronrod compares the
// error of the unscaled [-1, 1] sub-integral with a tolerance on the scaled one, so on short
// pieces it never meets the tolerance and bisects to max_depth.
template <class F>
LD gk_piece(const F& f, LD a, LD b, LD abs_tol, int depth) {
  const LD mid = (a + b) / 2, half = (b - a) / 2;
  auto g = [&](LD x) { return f(mid + half * x) * half; };
  LD err = 0, l1 = 0;
  const LD r = boost::math::quadrature::gauss_kronrod<LD, 61>::integrate(g, LD(-1), LD(1), 0, LD(0), &err, &l1);
  if (depth <= 0 || err <= abs_tol || err <= LD(1e-17) * l1) return r;
  return gk_piece(f, a, mid, abs_tol, depth - 1) + gk_piece(f, mid, b, abs_tol, depth - 1);
}

template <class F>
LD integrate_pieces(const F& f, const std::vector<LD>& b) {
  LD estimate = 0;
  for (size_t i = 0; i + 1 < b.size(); ++i) estimate += std::fabs(gk_piece(f, b[i], b[i + 1], 0, 0));
  const LD abs_tol = LD(1e-18) * estimate;  // per piece; a few hundred pieces at most
  LD sum = 0;
  for (size_t i = 0; i + 1 < b.size(); ++i) sum += gk_piece(f, b[i], b[i + 1], abs_tol, 16);
  return sum;
}

// Diffuse: ∫ max(0, L.N) / |L|^(n+1) dt. P exactly on the segment is not handled here.
template <class T>
LD ref_diffuse(const Typed<T>& x) {
  const RefGeom g = ref_geom(x);
  const LD nf = LD(x.light.falloff);
  if (g.ell == 0) {
    const LD r = std::sqrt(dot(g.l0, g.l0)), c = dot(g.l0, g.n);
    return c > 0 ? c / r / std::pow(r, nf) : 0;
  }
  if (!g.visible) return 0;
  auto f = [&](LD t) {
    const V l = g.l0 + g.ld * t;
    const LD c = std::max(dot(l, g.n), LD(0));
    return c / std::pow(dot(l, l), (nf + 1) / 2);
  };
  return integrate_pieces(f, breakpoints(g, {}));
}

// Unclipped magnitude ∫ 1/|L|^n dt: the floor of the absolute error bar when the reference is ~0.
template <class T>
LD ref_unclipped(const Typed<T>& x) {
  RefGeom g = ref_geom(x);
  const LD nf = LD(x.light.falloff);
  if (g.ell == 0) return 1 / std::pow(std::sqrt(dot(g.l0, g.l0)), nf);
  g.ta = 0;
  g.tb = 1;
  auto f = [&](LD t) { const V l = g.l0 + g.ld * t; return 1 / std::pow(dot(l, l), nf / 2); };
  return integrate_pieces(f, breakpoints(g, {}));
}

inline LD ref_cos_rv(const RefGeom& g, LD t) {
  const V l = g.l0 + g.ld * t;
  const LD r = std::sqrt(dot(l, l));
  return r > 0 ? dot(l, g.rv) / r : 0;
}

// Peak: max over the visible t of cos α, by dense search (uniform + graded around the foot) and
// golden-section refinement on the bracket of the best sample. Returns t; cos via ref_cos_rv.
inline LD ref_peak_t(const RefGeom& g) {
  std::vector<LD> ts;
  for (int i = 0; i <= 4000; ++i) ts.push_back(g.ta + (g.tb - g.ta) * i / 4000);
  for (LD w = std::max(g.h_t, LD(1e-30)), k = 0; k < 80 && w < 2; w *= 2, ++k)
    for (LD j : {LD(-1), LD(1)}) {
      const LD t = g.t_foot + j * w;
      if (t > g.ta && t < g.tb) ts.push_back(t);
    }
  std::sort(ts.begin(), ts.end());
  size_t best = 0;
  for (size_t i = 1; i < ts.size(); ++i)
    if (ref_cos_rv(g, ts[i]) > ref_cos_rv(g, ts[best])) best = i;
  LD lo = ts[best > 0 ? best - 1 : 0], hi = ts[std::min(best + 1, ts.size() - 1)];
  const LD phi = (std::sqrt(LD(5)) - 1) / 2;
  LD x1 = hi - phi * (hi - lo), x2 = lo + phi * (hi - lo);
  LD f1 = ref_cos_rv(g, x1), f2 = ref_cos_rv(g, x2);
  for (int it = 0; it < 200 && hi - lo > LD(1e-19) * (1 + std::fabs(lo)); ++it) {
    if (f1 < f2) { lo = x1; x1 = x2; f1 = f2; x2 = lo + phi * (hi - lo); f2 = ref_cos_rv(g, x2); }
    else { hi = x2; x2 = x1; f2 = f1; x1 = hi - phi * (hi - lo); f1 = ref_cos_rv(g, x1); }
  }
  LD t_best = ts[best];
  for (LD t : {x1, x2, lo, hi})
    if (ref_cos_rv(g, t) > ref_cos_rv(g, t_best)) t_best = t;
  return t_best;
}

// max(0, c)^m; m = 0 is the limit m -> 0+, [c > 0].
inline LD ref_phong(LD c, LD m) {
  if (!(c > 0)) return 0;
  return std::pow(c, m);
}

// The specular of a segment of zero length (a point: its lobe value, divided by |L|^nf, when above
// the horizon) or of one wholly below the horizon (0); nothing for any other segment.
inline std::optional<LD> ref_specular_degenerate(const RefGeom& g, LD m, LD nf = 0) {
  if (g.ell == 0)
    return dot(g.l0, g.n) > 0 ? ref_phong(ref_cos_rv(g, 0), m) / std::pow(std::sqrt(dot(g.l0, g.l0)), nf) : LD(0);
  if (!g.visible) return LD(0);
  return std::nullopt;
}

template <class T>
LD ref_specular_peak(const Typed<T>& x) {
  const RefGeom g = ref_geom(x);
  const LD m = LD(x.sp.shininess);
  if (const std::optional<LD> d = ref_specular_degenerate(g, m)) return *d;
  return ref_phong(ref_cos_rv(g, ref_peak_t(g)), m);
}

// Exact specular: ∫ [L.N > 0] max(0, Rv.L̂)^m / |L|^n dt with n the light's falloff (the
// radiometric definition), or without 1/|L|^n when `with_falloff` is false (the paper's form);
// graded around the peak from 1e-13 in t.
template <class T>
LD ref_specular_exact(const Typed<T>& x, bool with_falloff = true) {
  const RefGeom g = ref_geom(x);
  const LD m = LD(x.sp.shininess);
  const LD nf = with_falloff ? LD(x.light.falloff) : LD(0);
  if (const std::optional<LD> d = ref_specular_degenerate(g, m, nf)) return *d;
  const LD tp = ref_peak_t(g);
  const LD rvd = dot(g.rv, g.ld);
  const LD t_zero = rvd != 0 ? -dot(g.rv, g.l0) / rvd : -1;
  auto f = [&](LD t) {
    const LD lobe = ref_phong(ref_cos_rv(g, t), m);
    if (nf == 0 || lobe == 0) return lobe;
    const V l = g.l0 + g.ld * t;
    return lobe / std::pow(dot(l, l), nf / 2);
  };
  return integrate_pieces(f, breakpoints(g, {t_zero}, tp, LD(1e-13)));
}

// Random configurations with log-uniform scales: distance/length in [1e-3, 1e3], overall scale in
// [1e-3, 1e3], P offset from the origin by up to 10x the scale, random orientations, m in [1, 1e3].
inline Vec3d random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  for (;;) {
    const Vec3d v{g(rng), g(rng), g(rng)};
    const double l = length(v);
    if (l > 1e-3) return v / l;
  }
}

inline Config random_config(uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u01(0, 1);
  auto log_uniform = [&](double lo, double hi) { return std::pow(10.0, lo + (hi - lo) * u01(rng)); };
  Config c;
  const double scale = log_uniform(-3, 3);
  const double dist = scale;                       // distance from P to the segment's centre
  const double len = scale / log_uniform(-3, 3);   // length: distance/length log-uniform in 1e-3..1e3
  c.p = random_unit(rng) * (scale * 10 * u01(rng));
  const Vec3d centre = c.p + random_unit(rng) * dist;
  const Vec3d dir = random_unit(rng);
  c.q0 = centre - dir * (len * u01(rng));
  c.q1 = c.q0 + dir * len;
  // Normal: biased towards the light half of the time so that most cases are lit.
  const Vec3d to_light = normalize(centre - c.p);
  c.n = u01(rng) < 0.5 ? random_unit(rng) : normalize(to_light + random_unit(rng) * 0.7);
  c.rv = u01(rng) < 0.5 ? random_unit(rng) : normalize(to_light + random_unit(rng) * 0.3);
  c.shininess = log_uniform(0, 3);
  c.name = "random seed " + std::to_string(seed);
  return c;
}

// Relative error with an absolute floor: |k - ref| / max(|ref|, floor).
inline double rel_err(double k, LD ref, LD floor) {
  return double(std::fabs(LD(k) - ref) / std::max(std::fabs(ref), floor));
}

}  // namespace vlit::linear_test
