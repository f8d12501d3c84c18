// Accuracy report, area light (Picott 1992 eq. 9 diffuse, eq. 11-12 and sidebar peak specular;
// the exact specular of docs/conventions.md): every method on 256 seeded convex polygons and on
// the named stiff cases, in double and float, against the long-double Boost.Math reference over
// the polygon's area (reference/area_reference.h). The document's text: docs/accuracy.md.in.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "area_reference.h"

#include "accuracy_methods.h"
#include "area_light.h"
#include "case_grid.h"
#include "report_format.h"
#include "reports.h"
#include "specular_rows.h"

namespace vlit::bench::accuracy {
namespace {

struct AreaCase {
  std::vector<Vec3d> polygon;  // CCW seen from the emitting side
  Vec3d p, n, rv;
  double m = 1;
};

template <class T>
struct AreaX {
  PreparedAreaLight<T> light;
  ShadingPoint<T> sp;
  AreaSampler<T> sampler;
};

AreaCase round_area(AreaCase c) {
  for (Vec3d& q : c.polygon) q = to_float_grid(q);
  round_shading_inputs(c.p, c.n, c.rv, c.m);
  return c;
}

// Ordinary: a convex 3..6-gon (random angles on an ellipse of size 0.2..1.5, sheared) whose centre
// is at distance 1..3 from P, facing P (emitting normal within ~75 degrees of P), N and Rv biased
// towards the light. The polygon is built exactly planar in float: centre on a 1/64 grid, in-plane
// axes with small integer components, coordinates on a 1/1024 grid (rounding a tilted polygon's
// vertices to float would make it non-planar by ~1e-8 and the reference would measure that).
std::vector<AreaCase> ordinary_area_cases(int count) {
  std::mt19937_64 rng(77001);
  std::uniform_real_distribution<double> u01(0, 1);
  std::uniform_int_distribution<int> small_int(-3, 3);
  auto grid = [](double x, double step) { return std::round(x / step) * step; };
  std::vector<AreaCase> out;
  while (int(out.size()) < count) {
    AreaCase c;
    const double distance = 2 * u01(rng);  // drawn first: the order GCC gave the unsequenced form
    c.p = random_unit(rng) * distance;
    const Vec3d to_light = random_unit(rng);
    Vec3d centre = c.p + to_light * (1 + 2 * u01(rng));
    centre = {grid(centre.x, 1.0 / 64), grid(centre.y, 1.0 / 64), grid(centre.z, 1.0 / 64)};
    const Vec3d e1{double(small_int(rng)), double(small_int(rng)), double(small_int(rng))};
    const Vec3d e2{double(small_int(rng)), double(small_int(rng)), double(small_int(rng))};
    const Vec3d nrm = cross(e1, e2);
    if (length(nrm) < 0.5 * length(e1) * length(e2)) continue;  // axes at least 30 degrees apart
    const double facing = dot(normalize(nrm), normalize(c.p - centre));
    if (std::fabs(facing) < 0.25) continue;  // not edge-on to P
    const int sides = 3 + int(u01(rng) * 4);
    const double ax = (0.2 + 1.3 * u01(rng)) / length(e1), ay = (0.2 + 1.3 * u01(rng)) / length(e2);
    for (int k = 0; k < sides; ++k) {
      const double a = 2 * M_PI * (k + 0.8 * u01(rng)) / sides;
      c.polygon.push_back(centre + e1 * grid(ax * std::cos(a), 1.0 / 1024) + e2 * grid(ay * std::sin(a), 1.0 / 1024));
    }
    if (facing < 0) std::reverse(c.polygon.begin(), c.polygon.end());  // CCW seen from P: emits towards P
    std::tie(c.n, c.rv) = facing_light(to_light, 0.4, rng);
    c.m = log_uniform(rng, 0, 3);
    out.push_back(round_area(c));
  }
  return out;
}

struct NamedAreaStiff {
  std::string name, text;
  std::vector<AreaCase> cases;
};

std::vector<NamedAreaStiff> stiff_area_cases() {
  // Unit square in z = 0 emitting towards +z (CCW seen from +z), and variants.
  auto rect = [](double w, double h, Vec3d o = {}) {
    return std::vector<Vec3d>{o + Vec3d{-w / 2, -h / 2, 0}, o + Vec3d{w / 2, -h / 2, 0}, o + Vec3d{w / 2, h / 2, 0},
                              o + Vec3d{-w / 2, h / 2, 0}};
  };
  auto mk = [](std::vector<Vec3d> poly, Vec3d p, Vec3d n, Vec3d rv, double m = 100) {
    return round_area(AreaCase{std::move(poly), p, n, rv, m});
  };
  const Vec3d down{0, 0, -1};
  std::vector<NamedAreaStiff> s;
  s.push_back({"far 1e6", "unit square at distance 1e6", {
      mk(rect(1, 1), {0, 0, 1e6}, down, {0, 0.1, -1}), mk(rect(1, 1), {3e5, 0, 1e6}, {-0.3, 0, -1}, {-0.3, 0, -1}, 1e3)}});
  s.push_back({"near 1e-6", "P at height 1e-6 above the square (inside, and above an edge)", {
      mk(rect(1, 1), {0.1, 0.2, 1e-6}, down, {0.3, 0, -1}), mk(rect(1, 1), {0.5, 0.1, 1e-6}, {0.2, 0, -1}, {0, 0.3, -1}),
      mk(rect(1, 1), {0.3, -0.5, 1e-6}, {0, 0.3, -1}, {0.5, 0.5, -1}, 10)}});
  s.push_back({"P in plane / on edge", "P in the light's plane: outside, on an edge, at a vertex (all 0)", {
      mk(rect(1, 1), {1, 0, 0}, {-1, 0, 0.2}, {-1, 0, 0.3}), mk(rect(1, 1), {0.5, 0, 0}, {0, 0, -1}, {0, 0, -1}),
      mk(rect(1, 1), {0.5, 0.5, 0}, {-0.3, -0.3, -1}, {0, 0, -1})}});
  s.push_back({"grazing", "normal almost parallel to the light's plane", {
      mk(rect(1, 1), {0, 0, 1}, normalize(Vec3d{1, 0, -1e-6}), {0.5, 0, -1}, 10),
      mk(rect(1, 1), {2, 0, 1e-3}, normalize(Vec3d{-1, 0, 1e-6}), {-1, 0, -0.01}, 10)}});
  s.push_back({"crossing horizon", "the tangent plane of P cuts the light", {
      mk(rect(1, 1), {0, 0, 0.5}, {1, 0, 0}, {1, 0, -1}), mk(rect(2, 1), {0.3, 0.1, 0.2}, normalize(Vec3d{1, 1, -0.5}), {0.5, 0.5, -1}),
      mk(rect(1, 1), {0, 0, 1}, normalize(Vec3d{1, 0, 0.3}), {1, 0, -0.2}, 1000)}});
  s.push_back({"thin 1e-6", "1 x 1e-6 strip, P at height 0.5 and 1e-3", {
      mk(rect(1, 1e-6), {0.1, 0, 0.5}, down, {0.1, 0, -1}), mk(rect(1, 1e-6), {0.2, 0.01, 1e-3}, down, {0.3, 0, -1}, 10)}});
  s.push_back({"huge 1e6", "1e6 x 1e6 square, P at height 1", {
      mk(rect(1e6, 1e6), {0, 0, 1}, down, {0.2, 0.1, -1}), mk(rect(1e6, 1e6), {4e5, 0, 1}, normalize(Vec3d{0.5, 0, -1}), {0.5, 0.5, -1})}});
  s.push_back({"offset 1e4", "light and P 1e4 from the origin", {
      mk(rect(1, 1, {1e4, -1e4, 1e4}), Vec3d{1e4, -1e4, 1e4} + Vec3d{0.2, 0.1, 1}, down, {0.1, 0, -1})}});
  {
    NamedAreaStiff k{"shininess 1..1e4", "m = 1 .. 1e4, Rv through the light and beside it", {}};
    for (double m : {1.0, 10.0, 100.0, 1e3, 1e4}) {
      k.cases.push_back(mk(rect(1, 1), {0.1, 0, 1}, down, normalize(Vec3d{0.2, 0.1, -1}), m));
      k.cases.push_back(mk(rect(1, 1), {0.1, 0, 1}, down, normalize(Vec3d{0.6, 0, -1}), m));
    }
    s.push_back(k);
  }
  return s;
}

LD area_reference(const AreaCase& c, bool specular) {
  test::RefQuery q;
  q.pieces = {c.polygon};
  q.p = c.p;
  q.n = c.n;
  q.rv = c.rv;
  q.m = c.m;
  q.specular = specular;
  q.tolerance = 1e-12L;
  return test::reference_integral(q);
}

template <class T>
AreaX<T> area_typed(const AreaCase& c) {
  AreaLight<T> l;
  std::vector<Vec3<T>> poly;
  for (const Vec3d& q : c.polygon) poly.push_back(static_cast<Vec3<T>>(q));
  l.polygon = poly;
  AreaX<T> x;
  x.light = prepare_area_light(l);
  x.sp = {static_cast<Vec3<T>>(c.p), static_cast<Vec3<T>>(c.n), static_cast<Vec3<T>>(c.rv), T(c.m)};
  x.sampler = make_area_sampler(poly, false);
  return x;
}

CaseSet<AreaX> area_set(const std::vector<AreaCase>& cs, bool specular, const std::vector<int>& group = {}) {
  return make_case_set<AreaX>(
      cs, group, [](const AreaCase& c, auto t) { return area_typed<decltype(t)>(c); },
      [specular](const AreaCase& c) { return area_reference(c, specular); });
}

CaseSet<AreaX> area_stiff_set(const std::vector<NamedAreaStiff>& named, bool specular) {
  return named_case_set<AreaX>(named, [specular](const std::vector<AreaCase>& cases, const std::vector<int>& group) {
    return area_set(cases, specular, group);
  });
}

}  // namespace

AreaSections area_report(const Options& o) {
  AreaSections out;
  const int count = o.quick ? 8 : 256;
  const std::vector<AreaCase> ord = ordinary_area_cases(count);
  const std::vector<NamedAreaStiff> named = stiff_area_cases();
  progress("area: references for " + std::to_string(count) + " ordinary cases");
  const CaseSet<AreaX> od = area_set(ord, false);
  const CaseSet<AreaX> sd_set = area_stiff_set(named, false);
  out.diffuse = make_section("area-diffuse", "Area light, diffuse", count, sd_set);
  Section& sd = out.diffuse;
  auto shade_with = [](SpecularOptions opt, bool specular) {
    return [opt, specular](const auto& x, std::size_t) {
      const auto r = shade_area(x.light, x.sp, opt);
      return specular ? r.specular : r.diffuse;
    };
  };
  SpecularOptions none;
  none.method = SpecularMethod::kNone;
  method(sd, o, "contour", "contour closed form", "ordinary", "exact up to rounding", od, &sd_set, shade_with(none, false), kAlways);
  monte_carlo_rows(sd, o, "ordinary", "statistical", "statistical", {16, 64, 256, 1024, 4096}, od, &sd_set, [](int n, bool strat) {
    return [n, strat](const auto& x, std::size_t i) { return area_monte_carlo(x.sampler, x.sp, 0xa5ea + i, n, strat, false); };
  });

  progress("area specular references");
  const CaseSet<AreaX> os = area_set(ord, true);
  const CaseSet<AreaX> ss_set = area_stiff_set(named, true);
  out.specular = make_section("area-specular", "Area light, specular", count, ss_set);
  Section& ss = out.specular;
  specular_method_rows(ss, o, os, &ss_set, "peak x covered fraction (not the integral)", {1e-3, 1e-6, 1e-9},
                       "K15 vs G7 along the edges", [&](SpecularOptions opt) { return shade_with(opt, true); });
  monte_carlo_rows(ss, o, "m 1..1e3", "statistical", "statistical", {16, 256, 4096}, os, &ss_set, [](int n, bool strat) {
    return [n, strat](const auto& x, std::size_t i) { return area_monte_carlo(x.sampler, x.sp, 0xa5ea + i, n, strat, true); };
  });
  return out;
}

}  // namespace vlit::bench::accuracy
