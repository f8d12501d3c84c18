// Batch specular kernels (shaders_cpu/batch/*_specular_batch.h, shading/batch_kernels.h) against
// the scalar double kernels in the same test (themselves checked against independent quadratures
// in tests/kernels/linear, tests/kernels/area and tests/unit). Bar (the issue's): every lane the
// batch kernel does not flag is within 1e-5 relative of the double kernel, compared with
// max(|double|, 1e-12 x the case set's largest value); flagged lanes carry 0 and are recomputed
// by the bake with the scalar kernel (tests/unit/batch_bake_test.cpp checks the bake's result).
// Failures print the case and both values.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <string>
#include <vector>

#include "light_sources.h"
#include "support/test_rng.h"
#include "batch/double_exp.h"
#include "shading/batch_kernels.h"

using namespace vlit;

namespace {

constexpr double kBar = 1e-5;
constexpr double kFloorFraction = 1e-12;

using vlit::test::Rng;

// Shading points as the bake hands them to the batch kernels: position and Rv in double, the
// normal rounded to float. The double reference sees the same float normal.
struct SpecPoints {
  std::vector<double> px, py, pz, rx, ry, rz;
  std::vector<float> nx, ny, nz;
  std::vector<ShadingPoint<double>> sp;
  // The float normal, and the same values in double for the reference. (Written as
  // double(float(x)) inline, GCC 12 -O3 left some components unrounded in this file.)
  Vec3d push_normal(const Vec3d& n) {
    const Vec3d nn = normalize(n);
    nx.push_back(float(nn.x)); ny.push_back(float(nn.y)); nz.push_back(float(nn.z));
    return {double(nx.back()), double(ny.back()), double(nz.back())};
  }
  void add(const Vec3d& p, const Vec3d& n, const Vec3d& eye) {
    const Vec3d nf = push_normal(n);
    ShadingPoint<double> s = make_shading_point(p, nf, eye, 1.0);
    s.n = nf;
    px.push_back(p.x); py.push_back(p.y); pz.push_back(p.z);
    rx.push_back(s.rv.x); ry.push_back(s.rv.y); rz.push_back(s.rv.z);
    sp.push_back(s);
  }
  // Adds a point whose reflected view direction is `rv` exactly (unit), for lobe placements.
  void add_rv(const Vec3d& p, const Vec3d& n, const Vec3d& rv) {
    const Vec3d nf = push_normal(n);
    const Vec3d r = normalize(rv);
    px.push_back(p.x); py.push_back(p.y); pz.push_back(p.z);
    rx.push_back(r.x); ry.push_back(r.y); rz.push_back(r.z);
    sp.push_back({p, nf, r, 1.0});
  }
  BatchPoints view() const {
    return {px.data(), py.data(), pz.data(), nx.data(), ny.data(), nz.data(), rx.data(), ry.data(), rz.data()};
  }
};

struct SpecComparison {
  double worst = 0;
  long flagged = 0, lanes = 0;
};

ShadeOptions with_specular(SpecularFalloff falloff) {
  ShadeOptions o;
  o.with_specular = true;
  o.specular.method = SpecularMethod::kExact;
  o.specular.falloff = falloff;
  return o;
}

SpecComparison compare_specular(const std::string& what, const LightSource& source, const SpecPoints& pts, double m,
                                SpecularFalloff falloff = SpecularFalloff::kAsDiffuse, double bar = kBar) {
  ShadeOptions options = with_specular(falloff);
  // A reference much tighter than the bar: the scalar kernel's adaptive form (on the lanes its
  // closed forms refuse) to a thousandth of it, rather than to its default 1e-9.
  options.specular.exact_tolerance = std::min(options.specular.exact_tolerance, bar / 1000);
  const PreparedLight<double> light = prepare_light<double>(source);
  BatchChoice choice = batch_kernel_for(light, options);
  if (source.type == LightType::kArea) REQUIRE(enable_area_specular_batch(choice, light));
  REQUIRE_MESSAGE(choice.specular_batch, what << ": no batch specular kernel: " << choice.specular_reason);
  const long n = long(pts.px.size());
  std::vector<double> value(n, -1);
  std::vector<std::uint8_t> stiff(n, 2);
  evaluate_specular_batch(choice, options.specular, m, pts.view(), 0, n, {value.data(), stiff.data()});
  std::vector<double> ref(n);
  double max_ref = 0;
  for (long i = 0; i < n; ++i) {
    ShadingPoint<double> sp = pts.sp[i];
    sp.shininess = m;
    ref[i] = shade(light, sp, options).specular;
    max_ref = std::max(max_ref, ref[i]);
  }
  SpecComparison c;
  c.lanes = n;
  for (long i = 0; i < n; ++i) {
    CHECK(std::isfinite(value[i]));
    CHECK(stiff[i] <= 1);
    if (stiff[i]) {
      ++c.flagged;
      CHECK(value[i] == 0);
      continue;
    }
    const double floor = std::max(std::fabs(ref[i]), kFloorFraction * max_ref);
    const double err = floor > 0 ? std::fabs(value[i] - ref[i]) / floor : std::fabs(value[i]);
    c.worst = std::max(c.worst, err);
    if (!(err <= bar))
      FAIL_CHECK(std::setprecision(17) << what << " m=" << m << " lane " << i << ": batch " << value[i] << " double " << ref[i] << " rel.err " << err
                      << " P=(" << pts.px[i] << "," << pts.py[i] << "," << pts.pz[i] << ") N=(" << pts.nx[i] << ","
                      << pts.ny[i] << "," << pts.nz[i] << ") Rv=(" << pts.rx[i] << "," << pts.ry[i] << "," << pts.rz[i] << ")");
  }
  MESSAGE(what << " m=" << m << ": max rel.err " << c.worst << ", " << c.flagged << " of " << c.lanes << " lanes flagged");
  return c;
}

LightSource point_source(const Vec3d& position, double falloff) {
  LightSource l;
  l.type = LightType::kPoint;
  l.name = "point";
  l.position = position;
  l.falloff = falloff;
  return l;
}

LightSource spot_source(const Vec3d& position, const Vec3d& direction) {
  LightSource l = point_source(position, 2);
  l.type = LightType::kSpot;
  l.name = "spot";
  l.direction = normalize(direction);
  l.cos_inner = std::cos(0.3);
  l.cos_outer = std::cos(0.6);
  return l;
}

LightSource directional_source(const Vec3d& direction) {
  LightSource l;
  l.type = LightType::kDirectional;
  l.name = "directional";
  l.direction = normalize(direction);
  return l;
}

constexpr double kShininesses[] = {0, 1, 2.5, 40, 100, 1e4};

// A patch of 64 points 1e4 from the origin (at `far`), tilted normals, the eye 3 above it.
SpecPoints far_patch(const Vec3d& far, std::uint64_t seed) {
  SpecPoints pts;
  Rng rng(seed);
  for (int i = 0; i < 64; ++i) pts.add(Vec3d{rng.uniform(-1, 1), rng.uniform(-1, 1), 0} + far, {0.1, -0.1, 1}, far + Vec3d{0.3, 0.2, 3});
  return pts;
}

}  // namespace

TEST_CASE("double exp (double_exp.h) against std::exp over [-708, 0]") {
  double worst = 0;
  for (int i = 0; i <= 400000; ++i) {
    const double x = -708.0 * i / 400000;
    const double ref = std::exp(x);
    worst = std::max(worst, std::fabs(batch_detail::exp_nonpositive(x) - ref) / ref);
  }
  for (double x : {-1e-300, -1e-17, -1e-9, -0.34657359, -0.34657360, -700.5}) {
    const double ref = std::exp(x);
    worst = std::max(worst, std::fabs(batch_detail::exp_nonpositive(x) - ref) / ref);
  }
  MESSAGE("double exp: max relative error " << worst);
  CHECK(worst < 1e-15);
  CHECK(batch_detail::exp_nonpositive(0.0) == 1.0);
  CHECK(batch_detail::exp_nonpositive(-709.0) == 0.0);
  CHECK(batch_detail::exp_nonpositive(-1e6) == 0.0);
}

TEST_CASE("punctual specular batch: random cases, point / spot / directional, falloff 0..3 and none, range window") {
  Rng rng(21);
  SpecPoints pts;
  for (int i = 0; i < 4096; ++i) {
    const Vec3d p{rng.uniform(-4, 4), rng.uniform(-4, 4), rng.uniform(-1, 1)};
    const Vec3d eye{rng.uniform(-6, 6), rng.uniform(-6, 6), rng.uniform(1, 8)};
    pts.add(p, rng.unit() + Vec3d{0, 0, 0.7}, eye);
  }
  for (double m : kShininesses) {
    for (double falloff : {0.0, 1.0, 2.0, 3.0}) {
      LightSource point = point_source({0.5, -0.3, 2}, falloff);
      for (SpecularFalloff mode : {SpecularFalloff::kAsDiffuse, SpecularFalloff::kNone})
        CHECK(compare_specular("point n=" + std::to_string(int(falloff)), point, pts, m, mode).flagged == 0);
      point.range = 3.5;
      CHECK(compare_specular("point with range", point, pts, m).flagged == 0);
    }
    CHECK(compare_specular("spot", spot_source({-0.5, 0.5, 2}, {0.2, 0.1, -1}), pts, m).flagged == 0);
    CHECK(compare_specular("directional", directional_source({0.3, -0.2, -1}), pts, m).flagged == 0);
  }
}

TEST_CASE("punctual specular batch: stiff cases") {
  SUBCASE("grazing light: the horizon through the light is flagged, just above it is not") {
    // The light at (1, 0, h) from P = 0 with N = +z: N.L^ = h / |L|.
    const LightSource base = point_source({1, 0, 0}, 2);
    for (double h : {1e-9, -1e-9, 1e-7, 5e-7}) {
      LightSource l = base;
      l.position.z = h;
      SpecPoints one;
      one.add_rv({0, 0, 0}, {0, 0, 1}, {1, 0, 0.01});
      CHECK(compare_specular("grazing", l, one, 40).flagged == 1);
    }
    for (double h : {1e-5, 1e-3}) {
      LightSource l = base;
      l.position.z = h;
      SpecPoints one;
      one.add_rv({0, 0, 0}, {0, 0, 1}, {1, 0, 0.01});
      CHECK(compare_specular("just above the horizon", l, one, 40).flagged == 0);
    }
    SpecPoints sun_pts;
    sun_pts.add_rv({0, 0, 0}, {0, 0, 1}, {1, 0, 0.01});
    CHECK(compare_specular("directional grazing", directional_source({-1, 0, -1e-9}), sun_pts, 40).flagged == 1);
    CHECK(compare_specular("directional just above", directional_source({-1, 0, -1e-4}), sun_pts, 40).flagged == 0);
  }
  SUBCASE("the light at the surface point is flagged") {
    SpecPoints pts;
    pts.add_rv({0.25, 0.5, 1}, {0, 0, 1}, {0, 0, 1});
    CHECK(compare_specular("at the light", point_source({0.25, 0.5, 1}, 2), pts, 1).flagged == 1);
  }
  SUBCASE("lobe placements: the light on the lobe's axis, across its half-space, behind it; m = 0") {
    SpecPoints pts;
    const Vec3d q{0, 0, 2};
    for (double angle : {0.0, 1e-8, 1e-3, 0.3, 1.0, M_PI / 2 - 1e-9, M_PI / 2, M_PI / 2 + 1e-9, 2.0, M_PI}) {
      // Rv at `angle` from the direction to the light, about the y axis; the light above the horizon.
      pts.add_rv({0, 0, 0}, {0.2, 0, 1}, {std::sin(angle), 0, std::cos(angle)});
    }
    for (double m : kShininesses) {
      CHECK(compare_specular("lobe placements", point_source(q, 2), pts, m).flagged == 0);
      CHECK(compare_specular("lobe placements, directional", directional_source({0, 0, -1}), pts, m).flagged == 0);
    }
    // m = 0 is 1 / |L|^n wherever the light is in front of the lobe (cos > 0), 0 behind it.
    std::vector<double> value(pts.px.size());
    std::vector<std::uint8_t> stiff(pts.px.size());
    const BatchChoice choice = batch_kernel_for(prepare_light<double>(point_source(q, 2)), with_specular(SpecularFalloff::kAsDiffuse));
    evaluate_specular_batch(choice, SpecularOptions{}, 0.0, pts.view(), 0, long(value.size()), {value.data(), stiff.data()});
    CHECK(value[0] == doctest::Approx(0.25).epsilon(1e-15));
    CHECK(value[4] == doctest::Approx(0.25).epsilon(1e-15));
    CHECK(value[8] == 0);
    CHECK(value[9] == 0);
  }
  SUBCASE("tiny, huge and far distances, and a mesh far from the origin") {
    const Vec3d o{1e4, -1e4, 1e4};
    const SpecPoints pts = far_patch(o, 7);
    for (double m : {1.0, 40.0, 100.0, 1e4}) {
      for (double falloff : {0.0, 1.0, 2.0, 3.0}) {
        compare_specular("near", point_source(o + Vec3d{0.1, 0, 1e-5}, falloff), pts, m);
        compare_specular("far", point_source(o + Vec3d{-3e6, 2e6, 1e7}, falloff), pts, m);
        compare_specular("offset", point_source(o + Vec3d{0.2, 0.1, 1.5}, falloff), pts, m);
      }
    }
  }
}

namespace {

std::vector<Vec3d> square_at(double half, double height, double cx = 0, double cy = 0) {  // facing down (-z)
  return {{cx - half, cy - half, height}, {cx - half, cy + half, height}, {cx + half, cy + half, height},
          {cx + half, cy - half, height}};
}

}  // namespace

TEST_CASE("area specular batch: random convex polygons and shading points, m = 0, 1, 2, 40, 100, 1000") {
  Rng rng(2121);
  for (int light_case = 0; light_case < 12; ++light_case) {
    const int corners = 3 + light_case % 6;
    const double size = rng.log_uniform(1e-2, 1e1);
    std::vector<Vec3d> polygon;
    const Vec3d c{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(0.5, 3)};
    for (int k = 0; k < corners; ++k) {  // a regular polygon, clockwise seen from above: emits down
      const double a = -2 * M_PI * k / corners + 0.3 * light_case;
      polygon.push_back(c + Vec3d{size * std::cos(a), size * std::sin(a), 0});
    }
    LightSource source = vlit::test::area_source(polygon);
    source.two_sided = light_case % 3 == 0;
    SpecPoints pts;
    for (int i = 0; i < 700; ++i) {
      const Vec3d p{rng.uniform(-4, 4), rng.uniform(-4, 4), rng.uniform(-1, 0.3)};
      const Vec3d eye{rng.uniform(-6, 6), rng.uniform(-6, 6), rng.uniform(1, 8)};
      pts.add(p, rng.unit() + Vec3d{0, 0, 0.6}, eye);
    }
    for (double m : {0.0, 1.0, 2.0, 40.0, 100.0, 1000.0})
      compare_specular("area " + std::to_string(corners) + "-gon, size " + std::to_string(size), source, pts, m);
  }
}

TEST_CASE("area specular batch: stiff cases") {
  const LightSource unit_square = vlit::test::area_source(square_at(0.5, 1));
  SpecPoints pts;
  // Rv through the light's centre, at its edge, just outside, far outside, behind the lobe.
  for (double x : {0.0, 0.49, 0.5, 0.51, 2.0, -10.0}) pts.add_rv({0, 0, 0}, {0, 0, 1}, {x, 0, 1});
  pts.add_rv({0, 0, 0}, {0, 0, 1}, {0.2, 0, -1});  // the lobe points away from the light
  // The horizon crossing the light (tilted normals), grazing.
  for (double tilt : {0.3, 1.0, 1.5, M_PI / 2 - 1e-7}) pts.add_rv({0.1, 0, 0}, {std::sin(tilt), 0, std::cos(tilt)}, {0.1, 0.05, 1});
  // The lobe's half-space through the light (Rv nearly parallel to the light's plane).
  pts.add_rv({0, 0, 0.99}, {0, 0, 1}, {1, 0, 1e-3});
  for (double m : {0.0, 1.0, 40.0, 100.0, 1000.0}) {
    compare_specular("square stiff", unit_square, pts, m);
    compare_specular("tiny square", vlit::test::area_source(square_at(1e-6, 1)), pts, m);
    compare_specular("huge square", vlit::test::area_source(square_at(1e3, 1)), pts, m);
    compare_specular("far square", vlit::test::area_source(square_at(0.5, 1e5, 0, 0)), pts, m);
  }
}

TEST_CASE("area specular batch: coverage of the shininess and the light, and the plan does not choose it") {
  const ShadeOptions options = with_specular(SpecularFalloff::kAsDiffuse);
  const PreparedLight<double> square_light = prepare_light<double>(vlit::test::area_source(square_at(0.5, 1)));
  BatchChoice quad = batch_kernel_for(square_light, options);
  CHECK_FALSE(quad.specular_batch);
  CHECK(quad.specular_reason == "batch area specular not faster than scalar");
  REQUIRE(enable_area_specular_batch(quad, square_light));
  REQUIRE(quad.specular_batch);
  CHECK(specular_batch_covers(quad, 0));
  CHECK(specular_batch_covers(quad, 30));
  CHECK(specular_batch_covers(quad, kAreaSpecularBatchMaxShininess));
  CHECK_FALSE(specular_batch_covers(quad, kAreaSpecularBatchMaxShininess + 1));
  CHECK_FALSE(specular_batch_covers(quad, 2.1472));  // real m: the scalar path
  ShadeOptions peak = options;
  peak.specular.method = SpecularMethod::kPeak;
  const BatchChoice quad_peak = batch_kernel_for(prepare_light<double>(vlit::test::area_source(square_at(0.5, 1))), peak);
  CHECK_FALSE(quad_peak.specular_batch);
  CHECK(quad_peak.specular_reason == "no batch kernel for this specular method");
  std::vector<Vec3d> ten;
  for (int k = 0; k < 10; ++k) ten.push_back({std::cos(-2 * M_PI * k / 10), std::sin(-2 * M_PI * k / 10), 1});
  const PreparedLight<double> decagon_light = prepare_light<double>(vlit::test::area_source(ten));
  BatchChoice decagon = batch_kernel_for(decagon_light, options);
  CHECK(decagon.light);
  CHECK_FALSE(enable_area_specular_batch(decagon, decagon_light));
  CHECK_FALSE(decagon.specular_batch);
}

// Linear specular batch (linear_specular_batch.h): every accepted lane within 2e-9 of the scalar
// exact kernel at tolerance 2e-12 (the batch accepts a lane when its error estimate is at most
// 1e-9), and the set-up flags what it cannot vouch for.
namespace {

constexpr double kLinearBar = 2 * kLinearSpecularBatchBound;

SpecComparison compare_linear(const std::string& what, const LightSource& source, const SpecPoints& pts, double m) {
  return compare_specular(what, source, pts, m, SpecularFalloff::kAsDiffuse, kLinearBar);
}

}  // namespace

TEST_CASE("linear specular batch: random tubes and shading points, m = 0, 1, 2, 3, 40, 41, 100, 200") {
  Rng rng(2122);
  long flagged = 0, lanes = 0;
  for (int light_case = 0; light_case < 12; ++light_case) {
    const double length = rng.log_uniform(1e-2, 1e1);
    const Vec3d c{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(0.3, 3)};
    const Vec3d half = rng.unit() * (length / 2);
    const LightSource source = vlit::test::linear_source(c - half, c + half, 2);
    SpecPoints pts;
    for (int i = 0; i < 700; ++i) {
      const Vec3d p{rng.uniform(-4, 4), rng.uniform(-4, 4), rng.uniform(-1, 0.3)};
      const Vec3d eye{rng.uniform(-6, 6), rng.uniform(-6, 6), rng.uniform(1, 8)};
      pts.add(p, rng.unit() + Vec3d{0, 0, 0.6}, eye);
    }
    for (double m : {0.0, 1.0, 2.0, 3.0, 40.0, 41.0, 100.0, 200.0}) {
      const SpecComparison c = compare_linear("tube of length " + std::to_string(length), source, pts, m);
      flagged += c.flagged;
      lanes += c.lanes;
    }
  }
  // The kernel computes most lanes itself (a kernel that flagged everything would pass the above).
  MESSAGE("linear random: " << flagged << " of " << lanes << " lanes flagged");
  CHECK(double(flagged) < 0.05 * double(lanes));
}

TEST_CASE("linear specular batch: stiff cases") {
  const LightSource unit_tube = vlit::test::linear_source({-0.5, 0, 1}, {0.5, 0, 1}, 2);
  SUBCASE("lobe placements: on the light, at its ends, beyond them (tails), behind the lobe, parallel to it") {
    SpecPoints pts;
    for (double x : {0.0, 0.3, 0.5, 0.51, 0.75, 2.0, -10.0}) pts.add_rv({0, 0, 0}, {0, 0, 1}, {x, 0, 1});
    for (double y : {1e-3, 0.1, 1.0}) pts.add_rv({0, 0, 0}, {0, 0, 1}, {0.2, y, 1});  // off the light's plane
    pts.add_rv({0, 0, 0}, {0, 0, 1}, {0.2, 0, -1});  // the lobe points away from the light
    pts.add_rv({0, 0, 0}, {0, 0, 1}, {0, 1, 0});     // Rv normal to P's plane with the line: C = 0
    for (double m : {0.0, 1.0, 2.0, 40.0, 41.0, 100.0, 200.0}) {
      const SpecComparison c = compare_linear("lobe placements", unit_tube, pts, m);
      CHECK(c.flagged <= 3);  // at most the far tails at the largest m
    }
  }
  SUBCASE("deep tails at m = 2 where the forward chain's estimate is low: the backward chains are taken") {
    // Found by a random search: the forward chain passes its test here with errors above the bar
    // (this case fails when the forward chain is always preferred); the backward chains' estimate
    // is the smaller, and their value is within the bar.
    struct Lane { Vec3d q0, q1, p; float n[3]; Vec3d rv; };
    const Lane lanes[] = {
        {{-0.023383199441950712, -0.29278094898039336, 0.4757289270817141},
         {-0.054113814473376771, -0.30198658314852228, 0.47525690937151366},
         {-3.2741121078654527, 1.4023631358548263, -0.39062934649472503},
         {0.297623426f, 0.13658154f, 0.944862843f},
         {-0.20921434536752884, 0.096932120453181878, 0.97305370957459814}},
        {{-0.34587418130702985, -0.029003490060545915, 1.6163225358310085},
         {-0.39563892055754946, 0.058285905361749372, 1.6147461368593261},
         {3.6745880912769007, 2.3102221022842597, 0.13620441372377146},
         {-0.823270559f, 0.490497231f, 0.285723776f},
         {-0.52350376838876422, 0.83839157075912318, -0.15180045639856812}},
    };
    for (const Lane& lane : lanes) {
      SpecPoints one;
      one.add_rv(lane.p, {lane.n[0], lane.n[1], lane.n[2]}, lane.rv);
      CHECK(compare_linear("deep tail", vlit::test::linear_source(lane.q0, lane.q1, 2), one, 2).flagged == 0);
    }
  }
  SUBCASE("a lobe that keeps 1e-10 of the tube, at m = 0: the ends' rounding is counted") {
    // The lobe's plane Rv.L = 0 cuts the tube at x = 0.5 - 1e-10: W_0 is the angle of that piece,
    // whose ends' positions the estimate charges a few eps of the tube's length each (~1e-5 of
    // the piece): flagged, a conservative choice (the value is exact here without that charge).
    SpecPoints one;
    one.add_rv({0, 0, 0}, {0, 0, 1}, {1, 0, -(0.5 - 1e-10)});
    CHECK(compare_linear("a sliver of the tube in the lobe", unit_tube, one, 0).flagged == 1);
  }
  SUBCASE("collinear and near-collinear points, P on the segment: flagged or within the bar") {
    SpecPoints on_line;
    on_line.add_rv({-2, 0, 1}, {0, 0.3, 1}, {1, 0, 0.2});     // on the line's extension: h = 0
    on_line.add_rv({0.1, 0, 1}, {0, 0.3, 1}, {1, 0, 0.2});    // on the segment
    SpecPoints near_line;
    for (double h : {1e-12, 1e-9, 1e-6, 1e-3}) near_line.add_rv({-2, h, 1}, {0, 0.3, 1}, {1, 0, 0.2});
    for (double m : {0.0, 1.0, 40.0, 200.0}) {
      CHECK(compare_linear("on the line", unit_tube, on_line, m).flagged == 2);
      compare_linear("near the line", unit_tube, near_line, m);
    }
  }
  SUBCASE("the horizon: crossing the light, an end on the tangent plane, a light in the plane, grazing") {
    SpecPoints pts;
    for (double tilt : {0.3, 1.0, 1.5, M_PI / 2 - 1e-7}) pts.add_rv({0.1, 0, 0}, {std::sin(tilt), 0, std::cos(tilt)}, {0.1, 0.05, 1});
    // The tube at z = 1 from x = -0.5 to 0.5: from P = (0, 0, 0) with N along (1, 0, 0.5) the tangent
    // plane meets it at x = -0.5 (its first end). From P = (0, 0, 1), N = +z, it lies in the plane.
    pts.add_rv({0, 0, 0}, {1, 0, 0.5}, {-0.3, 0, 1});
    pts.add_rv({0, 0, 1}, {0, 0, 1}, {0.5, 0, 0.1});
    for (double m : {0.0, 1.0, 40.0, 200.0}) compare_linear("horizon", unit_tube, pts, m);
    // A tube crossing P's tangent plane at 2e-4 radians, the lobe's axis on the cut: a normal
    // rounded to float moves the cut by ~3e-4 of the tube, flagged. A tube crossing it steeply
    // with the lobe's axis on its far end, so that the cut lies in the lobe's tail: not flagged.
    const LightSource shallow = vlit::test::linear_source({-0.5, 0.2, -1e-4}, {0.5, 0.2, 1e-4}, 2);
    const LightSource steep = vlit::test::linear_source({-0.5, 0.2, -0.3}, {0.5, 0.2, 0.3}, 2);
    SpecPoints at_cut, at_far_end;
    at_cut.add_rv({0, 0, 0}, {0, 0, 1}, {0, 1, 0});
    at_far_end.add_rv({0, 0, 0}, {0, 0, 1}, {0.4, 0.2, 0.24});
    CHECK(compare_linear("cut in the highlight", shallow, at_cut, 40).flagged == 1);
    CHECK(compare_linear("steep cut in the lobe's tail", steep, at_far_end, 40).flagged == 0);
  }
  SUBCASE("tiny, huge, far and near tubes, and a mesh far from the origin") {
    const Vec3d o{1e4, -1e4, 1e4};
    const SpecPoints pts = far_patch(o, 8);
    for (double m : {0.0, 1.0, 40.0, 200.0}) {
      compare_linear("tiny", vlit::test::linear_source(o + Vec3d{0, 0, 1}, o + Vec3d{1e-6, 0, 1}, 2), pts, m);
      compare_linear("huge", vlit::test::linear_source(o + Vec3d{-1e6, 0, 1}, o + Vec3d{1e6, 0.5, 1}, 2), pts, m);
      compare_linear("far", vlit::test::linear_source(o + Vec3d{-3e6, 2e6, 1e7}, o + Vec3d{-3e6, 2e6 + 1, 1e7}, 2), pts, m);
      compare_linear("near", vlit::test::linear_source(o + Vec3d{-0.5, 0, 1e-5}, o + Vec3d{0.5, 0.1, 1e-5}, 2), pts, m);
      compare_linear("offset", vlit::test::linear_source(o + Vec3d{-0.5, 0, 1.5}, o + Vec3d{0.5, 0.3, 1.6}, 2), pts, m);
    }
  }
}

TEST_CASE("linear specular batch: coverage of the shininess, the falloff and the method") {
  const ShadeOptions options = with_specular(SpecularFalloff::kAsDiffuse);
  const BatchChoice tube = batch_kernel_for(prepare_light<double>(vlit::test::linear_source({-1, 0, 1}, {1, 0, 1}, 2)), options);
  REQUIRE(tube.specular_batch);
  CHECK(specular_batch_covers(tube, 0));
  CHECK(specular_batch_covers(tube, 100));
  CHECK(specular_batch_covers(tube, kLinearSpecularBatchMaxShininess));
  CHECK_FALSE(specular_batch_covers(tube, kLinearSpecularBatchMaxShininess + 1));
  CHECK_FALSE(specular_batch_covers(tube, 2.1472));  // real m: the scalar incomplete-beta form
  for (double falloff : {0.0, 1.0, 3.0}) {
    const BatchChoice other = batch_kernel_for(prepare_light<double>(vlit::test::linear_source({-1, 0, 1}, {1, 0, 1}, falloff)), options);
    CHECK(other.light);
    CHECK_FALSE(other.specular_batch);
    CHECK(other.specular_reason == "batch linear specular needs the inverse-square falloff");
  }
  const BatchChoice none = batch_kernel_for(prepare_light<double>(vlit::test::linear_source({-1, 0, 1}, {1, 0, 1}, 2)),
                                            with_specular(SpecularFalloff::kNone));
  CHECK_FALSE(none.specular_batch);
  CHECK(none.specular_reason == "batch linear specular needs the inverse-square falloff");
  ShadeOptions peak = options;
  peak.specular.method = SpecularMethod::kPeak;
  const BatchChoice tube_peak = batch_kernel_for(prepare_light<double>(vlit::test::linear_source({-1, 0, 1}, {1, 0, 1}, 2)), peak);
  CHECK_FALSE(tube_peak.specular_batch);
  CHECK(tube_peak.specular_reason == "no batch kernel for this specular method");
}
