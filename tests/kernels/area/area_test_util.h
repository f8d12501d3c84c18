// Shared helpers of the area-light tests: seeded random configurations and error reporting.
#pragma once

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "support/test_rng.h"
#include "area_light.h"
#include "area_reference.h"

namespace vlit::test {

// Absolute floor of the accuracy bars where the reference is ~0: kAbsFloor x the magnitude of
// the unclipped contour terms (contour_scale).
inline constexpr double kAbsFloor = 1e-12;

// Relative error, and absolute error in units of `scale` (the unclipped magnitude). A value
// meets bar b if rel <= b or abs_scaled <= kAbsFloor.
struct ErrorMeasure {
  double rel = 0, abs_scaled = 0;
  bool within(double bar) const { return rel <= bar || abs_scaled <= kAbsFloor; }
  // The error that counts for the bar: rel if it meets it, else the scaled absolute error.
  double effective(double bar) const { return rel <= bar ? rel : (abs_scaled <= kAbsFloor ? 0.0 : rel); }
};
inline ErrorMeasure measure(double value, double ref, double scale) {
  ErrorMeasure e;
  const double d = std::abs(value - ref);
  e.rel = ref != 0 ? d / std::abs(ref) : (d == 0 ? 0 : INFINITY);
  e.abs_scaled = scale > 0 ? d / scale : (d == 0 ? 0 : INFINITY);
  return e;
}


// A convex polygon with n vertices at random angles on an ellipse (semi-axes size, size*aspect),
// centered at `center`, CCW seen from the side `normal` points to.
inline std::vector<Vec3d> convex_polygon(Rng& rng, const Vec3d& center, const Vec3d& normal, double size,
                                         double aspect, int n) {
  std::vector<double> ang;
  for (int i = 0; i < n; ++i) ang.push_back(rng.uniform(0, 2 * M_PI));
  std::sort(ang.begin(), ang.end());
  const Vec3d helper = std::abs(normal.x) < 0.6 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
  const Vec3d e1 = normalize(cross(helper, normal));
  const Vec3d e2 = cross(normal, e1);
  std::vector<Vec3d> poly;
  for (double a : ang) poly.push_back(center + e1 * (size * std::cos(a)) + e2 * (size * aspect * std::sin(a)));
  return poly;
}

// The same with a random vertex count in 3..max_n.
inline std::vector<Vec3d> random_convex_polygon(Rng& rng, const Vec3d& center, const Vec3d& normal, double size,
                                                double aspect, int max_n) {
  const int n = 3 + static_cast<int>(rng.uniform(0, max_n - 2.0 - 1e-9));
  return convex_polygon(rng, center, normal, size, aspect, n);
}

// A seeded random configuration of the closed-form tests (area_specular_closed_test.cpp,
// area_specular_tail_test.cpp, area_specular_cap_test.cpp): a convex 3..6-gon of size 1e-2..1e2
// at ranges.distance_lo..distance_hi sizes from P (its direction at least ranges.min_facing above
// the light's plane, in cosine), N toward it within ranges.normal_spread sizes, Rv aimed within
// rv_spread sizes of its centre, m log-uniform in [m_lo, m_hi] (rounded when integer).
struct RandomAreaCase {
  std::vector<Vec3d> poly;
  ShadingPoint<double> sp;
};
struct AreaCaseRanges {
  double distance_lo = 0.3, distance_hi = 30, min_facing = 0.1, normal_spread = 2;
};
inline RandomAreaCase random_area_case(uint64_t seed, double m_lo, double m_hi, double rv_spread = 1.5,
                                       bool integer = true, const AreaCaseRanges& ranges = {}) {
  Rng rng(seed);
  const double size = rng.log_uniform(1e-2, 1e2);
  const Vec3d nl = rng.unit();
  const Vec3d center{0, 0, 0};
  RandomAreaCase c;
  c.poly = random_convex_polygon(rng, center, nl, size, rng.log_uniform(0.2, 1), 6);
  Vec3d dir = rng.unit();
  if (dot(dir, nl) < ranges.min_facing) dir = normalize(dir + nl * (2 * ranges.min_facing - dot(dir, nl)));
  const Vec3d p = center + dir * (size * rng.log_uniform(ranges.distance_lo, ranges.distance_hi));
  const Vec3d n = normalize(center - p + rng.unit() * (size * rng.uniform(0, ranges.normal_spread)));
  const Vec3d rv = normalize(center + rng.unit() * (size * rng.uniform(0, rv_spread)) - p);
  const double m = rng.log_uniform(m_lo, m_hi);
  c.sp = {p, n, rv, integer ? std::round(m) : m};
  return c;
}

inline std::string describe(const std::vector<Vec3d>& poly, const ShadingPoint<double>& sp) {
  std::ostringstream s;
  s.precision(17);
  s << "polygon {";
  for (const auto& v : poly) s << " (" << v.x << "," << v.y << "," << v.z << ")";
  s << " } P=(" << sp.p.x << "," << sp.p.y << "," << sp.p.z << ") N=(" << sp.n.x << "," << sp.n.y << "," << sp.n.z
    << ") Rv=(" << sp.rv.x << "," << sp.rv.y << "," << sp.rv.z << ") m=" << sp.shininess;
  return s.str();
}

inline AreaLight<double> light_of(std::vector<Vec3d> p, bool two_sided = false) {
  AreaLight<double> l;
  l.polygon = std::move(p);
  l.two_sided = two_sided;
  return l;
}

// A square of half-side s in the plane z = z0, emitting toward -z (CCW seen from below).
inline std::vector<Vec3d> square_down(double s, double z0, double cx = 0, double cy = 0) {
  return {{cx - s, cy - s, z0}, {cx - s, cy + s, z0}, {cx + s, cy + s, z0}, {cx + s, cy - s, z0}};
}

inline ShadingPoint<float> to_float(const ShadingPoint<double>& sp) {
  return {static_cast<Vec3f>(sp.p), static_cast<Vec3f>(sp.n), static_cast<Vec3f>(sp.rv), static_cast<float>(sp.shininess)};
}
inline ShadingPoint<double> to_double(const ShadingPoint<float>& sp) {
  return {static_cast<Vec3d>(sp.p), static_cast<Vec3d>(sp.n), static_cast<Vec3d>(sp.rv), static_cast<double>(sp.shininess)};
}
inline AreaLight<float> to_float(const AreaLight<double>& l) {
  AreaLight<float> f;
  for (const auto& v : l.polygon) f.polygon.push_back(static_cast<Vec3f>(v));
  f.two_sided = l.two_sided;
  return f;
}
inline AreaLight<double> to_double(const AreaLight<float>& l) {
  AreaLight<double> d;
  for (const auto& v : l.polygon) d.polygon.push_back(static_cast<Vec3d>(v));
  d.two_sided = l.two_sided;
  return d;
}

// Sum of |1/2 beta_i| over the unclipped polygon: the magnitude scale of the contour sum, used as
// the absolute floor where the reference is ~0.
inline double contour_scale(const std::vector<Vec3d>& poly, const Vec3d& p) {
  double s = 0;
  for (size_t i = 0; i < poly.size(); ++i)
    s += 0.5 * angle_between(poly[i] - p, poly[(i + 1) % poly.size()] - p);
  return s;
}

// Reference diffuse for a polygon given as convex pieces.
inline double reference_diffuse(const std::vector<std::vector<Vec3d>>& pieces, const ShadingPoint<double>& sp,
                                bool two_sided = false) {
  RefQuery q;
  q.pieces = pieces;
  q.two_sided = two_sided;
  q.p = sp.p; q.n = sp.n; q.rv = sp.rv; q.m = sp.shininess;
  q.specular = false;
  return static_cast<double>(reference_integral(q));
}

inline double reference_specular(const std::vector<std::vector<Vec3d>>& pieces, const ShadingPoint<double>& sp,
                                 bool two_sided = false, long double tol = 1e-13L) {
  RefQuery q;
  q.pieces = pieces;
  q.two_sided = two_sided;
  q.p = sp.p; q.n = sp.n; q.rv = sp.rv; q.m = sp.shininess;
  q.specular = true;
  q.tolerance = tol;
  return static_cast<double>(reference_integral(q));
}

inline bool all_finite(const Response<double>& r) { return std::isfinite(r.diffuse) && std::isfinite(r.specular); }
inline bool all_finite(const Response<float>& r) { return std::isfinite(r.diffuse) && std::isfinite(r.specular); }

inline SpecularOptions spec_options(SpecularMethod method, double tol = 1e-9, int k = 4) {
  SpecularOptions o;
  o.method = method;
  o.exact_tolerance = tol;
  o.neighborhood_samples = k;
  return o;
}

// One of the area specular's closed forms (a callable (visible, view, rv, m) -> AreaSpecularClosed)
// on the horizon-clipped light, beside the adaptive form at tolerance 1e-13, relative only
// (bounded_tails = false), as the comparison; compare_refused = false leaves the adaptive form
// out where the form refuses.
struct FormAndAdaptive {
  AreaSpecularClosed<double> form{0, 0, false};
  double adaptive = 0;
  bool lit = false;
};
template <class Form>
FormAndAdaptive form_and_adaptive(const std::vector<Vec3d>& poly, const ShadingPoint<double>& sp, Form form,
                                  bool compare_refused = true, bool two_sided = false) {
  const PreparedAreaLight<double> pl = prepare_area_light(light_of(poly, two_sided));
  const AreaView<double> view = make_area_view(pl, sp.p);
  FormAndAdaptive r;
  if (!view.lit) return r;
  ClipPolygon<double> visible;
  clip_to_horizon(pl, view, sp.n, visible);
  if (visible.count < 3) return r;
  r.lit = true;
  r.form = form(visible, view, sp.rv, sp.shininess);
  if (r.form.accepted || compare_refused)
    r.adaptive = area_specular_exact(visible, view, sp.rv, sp.shininess, 1e-13, false);
  return r;
}

}  // namespace vlit::test
