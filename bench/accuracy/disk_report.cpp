// Accuracy report, disk light (eq. 9 over the circle, horizon-clipped; the exact specular as a
// contour integral over the disk's boundary): the analytic contour against equal-area polygons
// (diffuse) and the exact specular by tolerance, on 96 seeded disks and the named stiff cases, in
// double and float, against the long-double reference in polar coordinates over the disk
// (reference/disk_reference.h). The document's text: docs/accuracy.md.in.
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "disk_reference.h"

#include "area_light.h"
#include "case_grid.h"
#include "disk_light.h"
#include "report_format.h"
#include "reports.h"

namespace vlit::bench::accuracy {
namespace {

using test::DiskQuery;
using test::disk_reference;

template <class T>
struct DiskX {
  PreparedDiskLight<T> light;                  // per-light constants, as in the bake loop
  std::array<PreparedAreaLight<T>, 4> polygon;  // equal-area regular 8-, 16-, 32-, 64-gons (baseline)
  ShadingPoint<T> sp;
};

DiskQuery round_disk(DiskQuery q) {
  q.center = to_float_grid(q.center);
  q.normal = to_float_grid(normalize(q.normal));
  q.radius = double(float(q.radius));
  round_shading_inputs(q.p, q.n, q.rv, q.m);
  return q;
}

std::vector<DiskQuery> ordinary_disk_cases(int count) {
  std::mt19937_64 rng(5150);
  std::uniform_real_distribution<double> u01(0, 1);
  std::vector<DiskQuery> out;
  for (int i = 0; i < count; ++i) {
    DiskQuery q;
    const double distance = 2 * u01(rng);  // drawn first: the order GCC gave the unsequenced form
    q.p = random_unit(rng) * distance;
    const Vec3d to_light = random_unit(rng);
    q.center = q.p + to_light * (1 + 2 * u01(rng));
    q.normal = normalize(-to_light + random_unit(rng) * 0.6);
    q.radius = 0.2 + 1.3 * u01(rng);
    std::tie(q.n, q.rv) = facing_light(to_light, 0.4, rng);
    q.m = log_uniform(rng, 0, 3);
    out.push_back(round_disk(q));
  }
  return out;
}

struct NamedDiskStiff {
  std::string name, text;
  std::vector<DiskQuery> cases;
};

// for_specular: the subset whose long-double specular reference fits the report's time budget
// (P 1e-4 from the rim, radius 1e6 seen off-centre and m = 1e4 take 2-40 s each: left out).
std::vector<NamedDiskStiff> stiff_disk_cases(bool for_specular) {
  auto mk = [](Vec3d c, double r, Vec3d p, Vec3d n, Vec3d rv, double m = 100) {
    DiskQuery q;
    q.center = c; q.normal = {0, 0, 1}; q.radius = r; q.p = p; q.n = n; q.rv = rv; q.m = m;
    return round_disk(q);
  };
  const Vec3d down{0, 0, -1};
  std::vector<NamedDiskStiff> s;
  s.push_back({"far 1e6", "radius 1 at distance 1e6", {mk({}, 1, {0, 0, 1e6}, down, {0.05, 0, -1}), mk({}, 1, {3e5, 0, 1e6}, {-0.3, 0, -1}, {-0.3, 0, -1})}});
  if (for_specular) {
    s.push_back({"crossing horizon", "tangent plane of P cuts the disk", {mk({}, 1, {0, 0, 0.5}, {1, 0, 0}, {1, 0, -1})}});
    s.push_back({"huge 1e6", "radius 1e6, P at height 1 above the centre", {mk({}, 1e6, {0, 0, 1}, down, {0.2, 0.1, -1})}});
    s.push_back({"shininess 1..100", "m = 1, 10, 100, Rv through the disk", {}});
    for (double m : {1.0, 10.0, 100.0}) s.back().cases.push_back(mk({}, 1, {0.1, 0, 1}, down, normalize(Vec3d{0.2, 0.1, -1}), m));
    return s;
  }
  s.push_back({"near rim", "P at height 1e-4 next to the rim (inside and outside)", {
      mk({}, 1, {0.999, 0, 1e-4}, down, {0.3, 0, -1}), mk({}, 1, {1.001, 0, 1e-4}, {-0.2, 0, -1}, {-0.5, 0, -1})}});
  s.push_back({"crossing horizon", "tangent plane of P cuts the disk", {
      mk({}, 1, {0, 0, 0.5}, {1, 0, 0}, {1, 0, -1}), mk({}, 1, {0.3, 0.2, 0.3}, normalize(Vec3d{1, 1, -0.5}), {0.5, 0.5, -1}, 1000)}});
  s.push_back({"huge 1e6", "radius 1e6, P at height 1", {mk({}, 1e6, {0, 0, 1}, down, {0.2, 0.1, -1}), mk({}, 1e6, {5e5, 0, 1}, normalize(Vec3d{0.5, 0, -1}), {0.5, 0.5, -1})}});
  s.push_back({"tiny 1e-6", "radius 1e-6 at distance 1e-6 .. 1", {mk({}, 1e-6, {1e-6, 0, 1e-6}, normalize(Vec3d{-0.3, 0.2, -1}), down),
      mk({}, 1e-6, {0.3, 0, 1}, down, down)}});
  s.push_back({"near 1e-6", "P at height 1e-6 over the disk", {mk({}, 1, {0.2, 0.1, 1e-6}, down, down)}});
  s.push_back({"grazing", "N 1e-6 off the disk's plane; P 1e-3 above the plane beside the disk", {
      mk({}, 1, {0, 0, 1}, normalize(Vec3d{1, 0, -1e-6}), down), mk({}, 1, {2, 0, 1e-3}, normalize(Vec3d{-1, 0, 1e-6}), down)}});
  return s;
}

// The regular n-gon with the disk's area: vertex radius R sqrt(2 pi / (n sin(2 pi / n))).
constexpr int kDiskBaselineEdges[4] = {8, 16, 32, 64};

template <class T>
DiskX<T> disk_typed(const DiskQuery& q) {
  DiskX<T> x;
  const DiskLight<T> light{static_cast<Vec3<T>>(q.center), static_cast<Vec3<T>>(q.normal), T(q.radius), false};
  x.light = prepare_disk_light(light);
  for (int i = 0; i < 4; ++i) {
    const int n = kDiskBaselineEdges[i];
    const double scale = std::sqrt(2 * M_PI / (n * std::sin(2 * M_PI / n)));
    x.polygon[i] = disk_polygon(light, n, AreaReal<T>(q.radius) * AreaReal<T>(scale));
  }
  x.sp = {static_cast<Vec3<T>>(q.p), static_cast<Vec3<T>>(q.n), static_cast<Vec3<T>>(q.rv), T(q.m)};
  return x;
}

CaseSet<DiskX> disk_set(const std::vector<DiskQuery>& qs, bool specular, const std::vector<int>& group = {}) {
  return make_case_set<DiskX>(
      qs, group, [](const DiskQuery& q, auto t) { return disk_typed<decltype(t)>(q); },
      [specular](DiskQuery q) {
        q.specular = specular;
        return disk_reference(q);
      });
}

CaseSet<DiskX> disk_stiff_set(const std::vector<NamedDiskStiff>& named, bool specular) {
  return named_case_set<DiskX>(named, [specular](const std::vector<DiskQuery>& cases, const std::vector<int>& group) {
    return disk_set(cases, specular, group);
  });
}

}  // namespace

DiskSections disk_report(const Options& o) {
  DiskSections out;
  const int count = o.quick ? 6 : 96;
  const std::vector<DiskQuery> ord = ordinary_disk_cases(count);
  const auto named = stiff_disk_cases(false);
  const auto named_s = stiff_disk_cases(true);
  progress("disk: references for " + std::to_string(count) + " ordinary cases");
  const CaseSet<DiskX> od = disk_set(ord, false), os = disk_set(ord, true);
  const CaseSet<DiskX> sd = disk_stiff_set(named, false), ss = disk_stiff_set(named_s, true);
  out.diffuse = make_section("disk-diffuse", "Disk light, diffuse", count, sd);
  out.specular = make_section("disk-specular", "Disk light, exact specular", count, ss);
  Section& sec = out.diffuse;
  Section& sec_s = out.specular;
  SpecularOptions none;
  none.method = SpecularMethod::kNone;
  method(sec, o, "analytic-contour", "analytic contour (default)", "diffuse", "closed form of eq. 9 over the circle; rounding only", od, &sd,
         [none](const auto& x, std::size_t) { return shade_disk(x.light, x.sp, none).diffuse; }, kAlways);
  for (int i = 0; i < 4; ++i) {
    const std::string name = "equal-area " + std::to_string(kDiskBaselineEdges[i]) + "-gon, contour";
    method(sec, o, "polygon-" + std::to_string(kDiskBaselineEdges[i]), name, "diffuse", "polygon approximation (baseline)", od, &sd,
           [none, i](const auto& x, std::size_t) { return shade_area(x.polygon[i], x.sp, none).diffuse; }, kAlways);
  }
  for (double tol : {1e-2, 1e-4, 1e-6, 1e-9}) {
    char name[64], promise[96];
    std::snprintf(name, sizeof name, "exact specular, tol %g", tol);
    std::snprintf(promise, sizeof promise, "relative %g (contour over the disk's boundary, K15 vs G7)", tol);
    auto f = [tol](const auto& x, std::size_t) {
      SpecularOptions ex;
      ex.method = SpecularMethod::kExact;
      ex.exact_tolerance = tol;
      return shade_disk(x.light, x.sp, ex).specular;
    };
    method(sec_s, o, "exact-" + tol_key(tol), name, "specular", promise, os, &ss, f, kAlways);
  }
  return out;
}

}  // namespace vlit::bench::accuracy
