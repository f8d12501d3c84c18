// Float batch kernels (shaders_cpu/batch/, shading/batch_kernels.h) against the double scalar
// kernels, which are themselves checked against independent quadratures (tests/kernels/linear,
// tests/kernels/area). Bars (the float bars): every lane the batch kernel does not flag
// as stiff is within 1e-5 relative of the double kernel (or 1e-12 of the case set's largest
// value, for values that are ~0); flagged lanes are recomputed in double by the bake. Each stiff
// case is a named SUBCASE; failures print the seed or case and both values.
#include <doctest/doctest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "kernels/area/area_test_util.h"
#include "light_sources.h"
#include "support/test_rng.h"
#include "batch/atan2_upper.h"
#include "batch/double_log.h"
#include "batch/float_log.h"
#include "shading/batch_kernels.h"

using namespace vlit;

namespace {

constexpr double kFloatBar = 1e-5;
constexpr double kFloorFraction = 1e-12;
constexpr double kDoubleLaneBar = 1e-10;  // double lanes vs the double kernel, beyond float rounding
constexpr double kDoubleFloorFraction = 1e-4;

using vlit::test::Rng;

struct Points {
  std::vector<double> px, py, pz;
  std::vector<float> nx, ny, nz;
  std::vector<ShadingPoint<double>> sp;
  void add(const Vec3d& p, const Vec3d& n) {
    const Vec3d nn = normalize(n);
    px.push_back(p.x); py.push_back(p.y); pz.push_back(p.z);
    nx.push_back(float(nn.x)); ny.push_back(float(nn.y)); nz.push_back(float(nn.z));
    // The double reference sees the same (float) normal the batch kernel sees.
    sp.push_back({p, Vec3d{nx.back(), ny.back(), nz.back()}, Vec3d{0, 0, 1}, 1});
  }
};

struct Comparison {
  double worst = 0;      // max relative error over unflagged lanes
  long flagged = 0, lanes = 0;
  long in_double = 0;          // lanes the kernel computed in double itself (area lights)
  double worst_in_double = 0;  // their max relative error beyond the float rounding of the result
  double worst_combined = 0;  // after recomputing the flagged lanes in double (as the bake does)
};

ShadeOptions diffuse_only() {
  ShadeOptions o;
  o.with_specular = false;
  o.specular.method = SpecularMethod::kNone;
  return o;
}

// Runs the batch kernel of `light` over all points and compares with the double kernel.
Comparison compare(const char* what, const LightSource& source, const Points& pts) {
  const PreparedLight<double> light = prepare_light<double>(source);
  const BatchChoice choice = batch_kernel_for(light, diffuse_only());
  REQUIRE_MESSAGE(choice.light.has_value(), std::string(what) << ": no batch kernel: " << choice.reason);
  const long n = long(pts.px.size());
  std::vector<float> value(n);
  std::vector<std::uint8_t> stiff(n), in_double(n);
  const BatchPoints bp{pts.px.data(), pts.py.data(), pts.pz.data(), pts.nx.data(), pts.ny.data(), pts.nz.data()};
  evaluate_diffuse_batch(*choice.light, bp, 0, n, BatchOutput{value.data(), stiff.data(), in_double.data()});
  std::vector<double> ref(n);
  double max_ref = 0;
  for (long i = 0; i < n; ++i) {
    ref[i] = shade(light, pts.sp[i], diffuse_only()).diffuse;
    max_ref = std::max(max_ref, ref[i]);
  }
  Comparison c;
  c.lanes = n;
  for (long i = 0; i < n; ++i) {
    CHECK(std::isfinite(value[i]));
    const double floor = std::max(std::fabs(ref[i]), kFloorFraction * max_ref);
    if (stiff[i]) {
      ++c.flagged;
      CHECK(value[i] == 0.f);  // flagged lanes carry no value: the caller recomputes them
      const double combined = double(float(ref[i]));
      c.worst_combined = std::max(c.worst_combined, floor > 0 ? std::fabs(combined - ref[i]) / floor : 0.0);
      continue;
    }
    const double err = floor > 0 ? std::fabs(double(value[i]) - ref[i]) / floor : std::fabs(double(value[i]));
    if (in_double[i]) {
      // The kernel's double lanes do the scalar double kernel's arithmetic: they agree to the
      // float rounding of the stored value (half an ulp, 2^-24) plus double-level differences.
      // A double lane's absolute rounding error is a few double epsilons times its terms, which are
      // about the size of the set's largest values; where the result cancels far below them
      // (grazing lanes, 1e-12 and less) the two double computations legitimately differ by ~1e-19.
      // So values below kDoubleFloorFraction of the set's largest are compared absolutely, at
      // kDoubleLaneBar of that floor (1e-14 of the largest value, ~100 double epsilons).
      ++c.in_double;
      const double floor_d = std::max(std::fabs(ref[i]), kDoubleFloorFraction * max_ref);
      const double beyond = std::max(0.0, (std::fabs(double(value[i]) - ref[i]) - 0x1p-24 * std::fabs(ref[i])) / floor_d);
      c.worst_in_double = std::max(c.worst_in_double, beyond);
      if (!(beyond <= kDoubleLaneBar))
        FAIL_CHECK(std::string(what) << " double lane " << i << ": batch " << value[i] << " double " << ref[i] << " rel.err " << err);
      c.worst_combined = std::max(c.worst_combined, err);
      continue;
    }
    c.worst = std::max(c.worst, err);
    c.worst_combined = std::max(c.worst_combined, err);
    if (!(err <= kFloatBar))
      FAIL_CHECK(std::string(what) << " lane " << i << ": batch " << value[i] << " double " << ref[i] << " rel.err " << err
                      << " P=(" << pts.px[i] << "," << pts.py[i] << "," << pts.pz[i] << ") N=(" << pts.nx[i] << ","
                      << pts.ny[i] << "," << pts.nz[i] << ")");
  }
  MESSAGE(std::string(what) << ": max rel.err " << c.worst << " over " << (c.lanes - c.flagged - c.in_double) << " float lanes, "
               << c.flagged << " of " << c.lanes << " lanes flagged stiff, " << c.in_double << " computed in double (max rel.err "
               << c.worst_in_double << " beyond the float rounding)");
  return c;
}

using vlit::test::area_source;
using vlit::test::disk_source;
using vlit::test::linear_source;

using vlit::test::convex_polygon;

std::vector<Vec3d> square(double half, double height, double cx = 0, double cy = 0) {  // facing down (-z)
  return {{cx - half, cy - half, height}, {cx - half, cy + half, height}, {cx + half, cy + half, height},
          {cx + half, cy - half, height}};
}

}  // namespace

TEST_CASE("float atan2 (float_atan.h) over the whole upper half plane") {
  double worst = 0;
  for (int i = 0; i <= 200000; ++i) {
    const double angle = M_PI * i / 200000.0;
    for (double r : {1e-30, 1e-3, 1.0, 1e20}) {
      const float x = float(r * std::cos(angle)), y = float(std::fabs(r * std::sin(angle)));
      const double ref = std::atan2(double(y), double(x));
      const double got = batch_detail::atan2_upper(y, x);
      if (ref > 0) worst = std::max(worst, std::fabs(got - ref) / ref);
      else CHECK(got == 0);
    }
  }
  MESSAGE("float atan2: max relative error " << worst);
  CHECK(worst < 4e-7);
}

TEST_CASE("double atan2 (double_atan.h) over the whole upper half plane") {
  double worst = 0;
  for (int i = 0; i <= 200000; ++i) {
    const long double angle = M_PIl * i / 200000;
    for (long double r : {1e-300L, 1e-3L, 1.0L, 1e300L}) {
      const double x = double(r * std::cos(angle)), y = double(std::fabs(r * std::sin(angle)));
      const long double ref = std::atan2((long double)y, (long double)x);  // of the rounded inputs
      const double got = batch_detail::atan2_upper(y, x);
      if (ref > 0) worst = std::max(worst, double(std::fabs(got - ref) / ref));
      else CHECK(got == 0);
    }
  }
  CHECK(batch_detail::atan2_upper(1.0, 0.0) == doctest::Approx(M_PI / 2).epsilon(1e-16));
  CHECK(batch_detail::atan2_upper(0.0, -1.0) == doctest::Approx(M_PI).epsilon(1e-16));
  MESSAGE("double atan2: max relative error " << worst);
  CHECK(worst < 1e-15);
}

TEST_CASE("float log and log1p (float_log.h) over the whole positive float range") {
  // Every 509th bit pattern of the positive finite floats (subnormals to the largest), and every
  // float within 2^-9 of 1 (where ln x -> 0 and only the relative error means anything).
  std::vector<float> xs;
  for (std::uint32_t bits = 1; bits < 0x7f800000u; bits += 509) xs.push_back(std::bit_cast<float>(bits));
  for (float x = 1.f - 1.f / 512; x <= 1.f + 1.f / 512; x = std::nextafter(x, 2.f)) xs.push_back(x);
  xs.push_back(std::numeric_limits<float>::denorm_min());
  xs.push_back(std::numeric_limits<float>::max());
  double worst_log = 0, worst_log1p = 0;
  for (const float x : xs) {
    const double ref = std::log(double(x));
    const double got = batch_detail::log_positive(x);
    if (ref == 0) CHECK(got == 0);
    else worst_log = std::max(worst_log, std::fabs(got - ref) / std::fabs(ref));
    // ln(1 + x) for x > 0 and for -x in (-1, 0): the argument itself is exact, so log1p_float
    // applies on the whole of (-1, inf).
    const double ref_pos = std::log1p(double(x));
    worst_log1p = std::max(worst_log1p, std::fabs(double(batch_detail::log1p_float(x)) - ref_pos) / ref_pos);
    if (x < 1.f) {
      const double ref_neg = std::log1p(-double(x));
      worst_log1p = std::max(worst_log1p, std::fabs(double(batch_detail::log1p_float(-x)) - ref_neg) / -ref_neg);
    }
  }
  MESSAGE("float log: max relative error " << worst_log << ", float log1p: " << worst_log1p << " over " << xs.size()
                                           << " arguments");
  CHECK(worst_log < 4e-7);
  CHECK(worst_log1p < 4e-7);
  // The ratio form for x near -1, where x has lost the digits of 1 + x: ln(1 + x) from the ratio.
  CHECK(std::fabs(batch_detail::log1p_or_log_ratio(-1.f + 1e-7f, 1e-7f * 1.25f) - std::log(1.25e-7)) < 4e-7 * 16);
}

TEST_CASE("double log and log1p (double_log.h)") {
  double worst_log = 0, worst_log1p = 0;
  long count = 0;
  // log over the whole positive range, subnormals included: 2^e m on a grid of exponents and mantissas.
  for (int e = -1074; e <= 1023; e += 3)
    for (int i = 0; i < 64; ++i) {
      const double x = std::ldexp(1.0 + i / 64.0, e);
      if (!(x > 0) || !std::isfinite(x)) continue;
      const long double ref = std::log((long double)x);
      const double got = batch_detail::log_positive(x);
      if (ref != 0) worst_log = std::max(worst_log, double(std::fabs((got - ref) / ref)));
      ++count;
    }
  // Near 1, where ln x is small.
  for (int i = -20000; i <= 20000; ++i) {
    const double x = 1.0 + i * 1e-9;
    const long double ref = std::log((long double)x);
    if (ref != 0) worst_log = std::max(worst_log, double(std::fabs((batch_detail::log_positive(x) - ref) / ref)));
  }
  // log1p on (-1, 2]: tiny, small and large arguments, both signs.
  for (int i = 1; i <= 200000; ++i) {
    const double t = i / 200000.0;
    for (double x : {-t * (1 - 1e-12), 2 * t, t * 1e-10, -t * 1e-10, t * t * t * 1e-300}) {
      const long double ref = std::log1p((long double)x);
      const double got = batch_detail::log1p_double(x);
      if (ref != 0) worst_log1p = std::max(worst_log1p, double(std::fabs((got - ref) / ref)));
    }
  }
  MESSAGE("double log: max relative error " << worst_log << " (" << count << " arguments over the whole range), log1p "
                                            << worst_log1p);
  CHECK(worst_log < 1e-15);
  CHECK(worst_log1p < 2e-15);
}

TEST_CASE("linear batch: random segments, falloff 0..3") {
  for (double falloff : {0.0, 1.0, 2.0, 3.0}) {
    Rng rng(2024 + uint64_t(falloff));
    Points pts;
    std::vector<LightSource> lights;
    // One light, many points around it (the bake's shape): distances 1e-3 .. 1e3 of the length.
    const Vec3d q0{0.3, -0.2, 1.1}, q1{-0.5, 0.4, 1.6};
    for (int i = 0; i < 4096; ++i) {
      const double len = length(q1 - q0);
      const Vec3d mid = (q0 + q1) * 0.5;
      const Vec3d p = mid + rng.unit() * (len * rng.log_uniform(1e-3, 1e3));
      const Vec3d n = normalize(normalize(mid - p) + rng.unit() * 0.9);
      pts.add(p, n);
    }
    const std::string what = "linear n=" + std::to_string(int(falloff)) + " random";
    const Comparison c = compare(what.c_str(), linear_source(q0, q1, falloff), pts);
    CHECK(c.worst <= kFloatBar);
    CHECK(double(c.flagged) < 0.05 * double(c.lanes));  // the batch kernel does the work
  }
}

TEST_CASE("linear batch: a floor under a tube (the benchmark's set)") {
  Rng rng(3);
  Points pts;
  for (int i = 0; i < 8192; ++i)
    pts.add({rng.uniform(-4, 4), rng.uniform(-4, 4), rng.uniform(-0.2, 0.2)},
            {rng.uniform(-0.7, 0.7), rng.uniform(-0.7, 0.7), 1});
  for (double falloff : {0.0, 1.0, 2.0, 3.0}) {
    const std::string what = "linear n=" + std::to_string(int(falloff)) + " floor";
    const Comparison c = compare(what.c_str(), linear_source({-1, -0.3, 1.5}, {1, 0.3, 1.6}, falloff), pts);
    CHECK(c.worst <= kFloatBar);
  }
}

TEST_CASE("linear batch: stiff cases") {
  for (double falloff : {0.0, 1.0, 2.0, 3.0}) {
    CAPTURE(falloff);
    Points pts;
    const Vec3d q0{-1, 0, 1}, q1{1, 0, 1};
    const LightSource tube = linear_source(q0, q1, falloff);
    SUBCASE("collinear: P on the line of the segment, outside it") {
      for (double x : {1.5, 2.0, 10.0, -3.0}) pts.add({x, 0, 1}, {0, 0.3, 1});
      compare("linear stiff collinear", tube, pts);
    }
    SUBCASE("near-collinear: h = 1e-12 .. 1e-3 from the line, foot outside") {
      for (double h = 1e-12; h <= 1e-3; h *= 10) pts.add({2, h, 1}, {-1, 0.2, 0.1});
      compare("linear stiff near-collinear", tube, pts);
    }
    SUBCASE("far: distance 1e6") {
      for (int i = 0; i < 8; ++i) pts.add({0.1 * i, 0.2, 1 - 1e6}, {0.1 * i, 0, 1});
      compare("linear stiff far", tube, pts);
    }
    SUBCASE("near: distance 1e-6, foot inside and at an end") {
      pts.add({0.3, 0, 1 - 1e-6}, {0, 0, 1});
      pts.add({1, 0, 1 - 1e-6}, {0, 0, 1});
      pts.add({-1, 1e-6, 1}, {0, -1, 0.1});
      compare("linear stiff near", tube, pts);
    }
    SUBCASE("crossing the horizon and an endpoint on the tangent plane") {
      pts.add({0, 0, 0}, {0.3, 0, 1});
      pts.add({0, 0, 0}, {1, 0, 1});    // Q0 exactly on the plane
      pts.add({0, 0, 0}, {1, 0, 0.2});
      pts.add({0.5, 0.5, 0.9}, {0, 0, 1});
      compare("linear stiff horizon", tube, pts);
    }
    SUBCASE("grazing: L.N ~ 1e-6 |L|") {
      pts.add({0, -1, 1}, {0, 1e-6, -1});
      pts.add({0, -1, 1}, {1e-3, 1e-6, -1});
      compare("linear stiff grazing", tube, pts);
    }
    SUBCASE("offset 1e4: light and P far from the origin") {
      const LightSource far = linear_source(q0 + Vec3d{1e4, -1e4, 1e4}, q1 + Vec3d{1e4, -1e4, 1e4}, falloff);
      for (int i = 0; i < 8; ++i) pts.add(Vec3d{0.2 * i, 0.3, 0} + Vec3d{1e4, -1e4, 1e4}, {0.1, 0, 1});
      const Comparison c = compare("linear stiff offset", far, pts);
      CHECK(c.flagged == 0);  // the double set-up keeps the offset harmless
    }
    SUBCASE("foot 1e-4 inside an end, h = 1e-9 .. 1e-2 from the line") {
      for (double h = 1e-9; h <= 1e-2; h *= 10) {
        // The segment crosses the tangent plane ~3h-5h from the foot: the visible interval's near
        // end must keep its relative precision (linear_diffuse_batch.h, horizon clipping).
        pts.add({1 - 1e-4, h, 1}, {0.2, -1, 0.1});
        pts.add({1 - 1e-4, 0, 1 - h}, {0.3, 0, 1});
      }
      for (double h = 1e-4; h <= 0.1; h *= 10)  // whole segment visible, rb/ra ~ h: n = 1 takes G from the ratio
        pts.add({1 - 1e-4, 0, 1 - h}, {-0.3, 0, 1});
      compare("linear stiff foot near an end", tube, pts);
    }
    SUBCASE("P at an endpoint and on the segment") {
      pts.add(q0, {1, 0.2, 1});  // the segment crosses the tangent plane at P
      pts.add({0, 0, 1}, {1, 0.2, 1});
      pts.add({0, 0, 1}, {0, 0, 1});  // the segment lies in the tangent plane: 0
      compare("linear stiff on segment", tube, pts);
    }
  }
}

TEST_CASE("area batch: random convex polygons (3..8 vertices), one- and two-sided") {
  Rng rng(77);
  double worst = 0;
  long flagged = 0, lanes = 0, in_double = 0;
  for (int l = 0; l < 24; ++l) {
    const int n = 3 + l % 6;
    const Vec3d normal = normalize(Vec3d{rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5), -1});
    const Vec3d center{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(1, 3)};
    const auto poly = convex_polygon(rng, center, normal, rng.uniform(0.2, 1.5), rng.uniform(0.3, 1), n);
    Points pts;
    for (int i = 0; i < 512; ++i) {
      const Vec3d p{rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-0.5, 0.5)};
      pts.add(p, normalize(normalize(center - p) + rng.unit() * 0.9));
    }
    const std::string what = "area random light " + std::to_string(l) + " (" + std::to_string(n) + " vertices)";
    const Comparison c = compare(what.c_str(), area_source(poly, l % 4 == 0), pts);
    worst = std::max(worst, c.worst);
    flagged += c.flagged;
    in_double += c.in_double;
    lanes += c.lanes;
  }
  MESSAGE("area random: max rel.err " << worst << ", " << flagged << " of " << lanes << " lanes flagged stiff, " << in_double
                                     << " computed in double");
  CHECK(worst <= kFloatBar);
  // Normals here are far more random than a mesh's: a quarter of the lanes see the light grazing or
  // cut by the horizon, where float cancels and the kernel's double lanes take over (area_diffuse_batch.h).
  CHECK(flagged == 0);
  CHECK(in_double > 0);
  CHECK(double(in_double) < 0.3 * double(lanes));
}

TEST_CASE("area batch: stiff cases") {
  Points pts;
  SUBCASE("far: unit square at distance 1e6") {
    for (int i = 0; i < 4; ++i) pts.add({0.1 * i, 0, 0}, {0.3, -0.2, 1});
    const Comparison c = compare("area stiff far", area_source(square(0.5, 1e6)), pts);
    CHECK(c.flagged == 0);  // the small-light form has no cancellation
  }
  SUBCASE("near: P 1e-6 below the square, inside and under an edge") {
    pts.add({0.1, 0.2, 1 - 1e-6}, {0, 0, 1});
    pts.add({0.5, 0.2, 1 - 1e-6}, {0, 0.1, 1});
    compare("area stiff near", area_source(square(0.5, 1)), pts);
  }
  SUBCASE("P in the light's plane: outside, on an edge, at a vertex") {
    pts.add({3, 0, 1}, {-1, 0, 0});
    pts.add({0.5, 0, 1}, {-1, 0, -1});
    pts.add({0.5, 0.5, 1}, {-1, 0, -1});
    const Comparison c = compare("area stiff in plane", area_source(square(0.5, 1)), pts);
    CHECK(c.flagged == 0);
  }
  SUBCASE("grazing and crossing the horizon") {
    pts.add({0, 0, 0}, {1, 0, 1e-6});
    pts.add({0, 0, 0}, {1, 0, 0.3});
    pts.add({0.2, 0.1, 0.5}, {0, 1, 0.05});
    pts.add({0, 0, 0.99}, {1, 0.2, 0});
    compare("area stiff horizon", area_source(square(0.5, 1)), pts);
  }
  SUBCASE("thin: aspect 1e-6") {
    pts.add({0.2, 0.1, 0}, {0, 0.3, 1});
    pts.add({0.2, 0.1, 1.999}, {0, 0.3, 1});
    compare("area stiff thin", area_source({{-1, -1e-6, 2}, {-1, 1e-6, 2}, {1, 1e-6, 2}, {1, -1e-6, 2}}), pts);
  }
  SUBCASE("huge: 1e6 square 1 above P") {
    pts.add({0, 0, 0}, {0.2, 0, 1});
    compare("area stiff huge", area_source(square(1e6, 1, 1e5, 0)), pts);
  }
  SUBCASE("offset 1e4") {
    const Vec3d o{1e4, -1e4, 1e4};
    std::vector<Vec3d> sq = square(0.5, 1);
    for (auto& q : sq) q += o;
    for (int i = 0; i < 8; ++i) pts.add(Vec3d{0.2 * i - 0.7, 0.1, 0} + o, {0.1, 0, 1});
    compare("area stiff offset", area_source(sq), pts);
  }
  SUBCASE("behind a one-sided light, and the back of a two-sided one") {
    pts.add({0, 0, 2}, {0, 0, -1});
    pts.add({0.3, 0, 3}, {0.2, 0, -1});
    compare("area stiff behind", area_source(square(0.5, 1)), pts);
    compare("area stiff two-sided back", area_source(square(0.5, 1), true), pts);
  }
}

// Sets that send many lanes through the area kernel's double lanes (compare() checks each against
// the scalar double kernel to the float rounding of the result).
TEST_CASE("area batch: lanes computed in double") {
  Rng rng(4242);
  Points pts;
  long expected_min = 0;
  SUBCASE("grazing: the light just above each lane's horizon, or cut by it") {
    // A floor under a unit square at height 1; each normal tilted so that the square's centre is
    // seen 1e-4 .. 0.2 rad above or below the tangent plane.
    for (int i = 0; i < 600; ++i) {
      const Vec3d p{rng.uniform(-3, 3), rng.uniform(-3, 3), 0};
      const Vec3d to_light = normalize(Vec3d{0, 0, 1} - p);
      const Vec3d side = normalize(cross(to_light, rng.unit()));
      const Vec3d in_plane = normalize(cross(side, to_light));  // perpendicular to to_light
      const double elevation = (i % 2 ? 1 : -1) * rng.log_uniform(1e-4, 0.2);
      pts.add(p, in_plane * std::cos(elevation) + to_light * std::sin(elevation));
    }
    expected_min = 100;
    const Comparison c = compare("area double grazing", area_source(square(0.5, 1)), pts);
    CHECK(c.in_double >= expected_min);
  }
  SUBCASE("beyond 1e8: float would overflow, the double lanes use the small-light form") {
    for (int i = 0; i < 40; ++i) pts.add({rng.uniform(-1e3, 1e3), rng.uniform(-1e3, 1e3), 0}, rng.unit() + Vec3d{0, 0, 1.5});
    const Comparison c = compare("area double far", area_source(square(0.5, 1e9)), pts);
    CHECK(c.in_double == 40);
  }
  SUBCASE("mixed forms in one block: grazing lanes near (plain) and far (small-light form)") {
    for (int i = 0; i < 300; ++i) {
      const double r = i % 2 ? rng.uniform(0, 2) : rng.uniform(40, 60);
      const double phi = rng.uniform(0, 2 * M_PI);
      const Vec3d p{r * std::cos(phi), r * std::sin(phi), 0};
      const Vec3d to_light = normalize(Vec3d{0, 0, 1} - p);
      const Vec3d in_plane = normalize(cross(cross(to_light, Vec3d{0, 0, 1}), to_light) + Vec3d{0, 0, 1e-9});
      pts.add(p, in_plane + to_light * rng.uniform(-0.02, 0.02));
    }
    const Comparison c = compare("area double mixed", area_source(square(0.5, 1)), pts);
    CHECK(c.in_double >= 100);
  }
  SUBCASE("P next to a vertex, light cut by the horizon (the direct cross product)") {
    for (int i = 0; i < 64; ++i) {
      const Vec3d p = Vec3d{0.5, 0.5, 1} + rng.unit() * rng.log_uniform(1e-7, 1e-2) + Vec3d{0, 0, -1e-3};
      pts.add(p, Vec3d{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-0.05, 0.05)});
    }
    const Comparison c = compare("area double near vertex", area_source(square(0.5, 1)), pts);
    CHECK(c.in_double > 0);
  }
}


// Disk lanes are computed in double (disk_diffuse_batch.h): compare() checks each against the
// scalar double kernel (closed form and arc, itself checked against 2D quadrature in
// tests/kernels/area/disk_test.cpp) to the float rounding of the result, the full-circle lanes and
// the lanes whose horizon cuts the disk (arc + chord) alike.
TEST_CASE("disk batch: random disks and points, one- and two-sided") {
  Rng rng(909);
  long flagged = 0, lanes = 0, in_double = 0;
  for (int l = 0; l < 16; ++l) {
    const Vec3d center{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(1, 3)};
    const Vec3d normal = normalize(Vec3d{rng.uniform(-0.7, 0.7), rng.uniform(-0.7, 0.7), -1});
    Points pts;
    for (int i = 0; i < 512; ++i) {
      const Vec3d p{rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-0.5, 0.5)};
      pts.add(p, normalize(normalize(center - p) + rng.unit() * 0.9));
    }
    const std::string what = "disk random " + std::to_string(l);
    const Comparison c = compare(what.c_str(), disk_source(center, normal, rng.log_uniform(0.05, 2), l % 4 == 0), pts);
    flagged += c.flagged;
    in_double += c.in_double;
    lanes += c.lanes;
  }
  MESSAGE("disk random: " << in_double << " of " << lanes << " lanes computed in double, " << flagged << " flagged");
  CHECK(in_double == lanes);
  CHECK(flagged == 0);
}

TEST_CASE("disk batch: lanes whose horizon cuts the disk (arc + chord)") {
  Rng rng(2718);
  for (bool two_sided : {false, true}) {
    const Vec3d center{0.3, -0.2, 1.5}, normal = normalize(Vec3d{0.2, 0.1, -1});
    const double radius = 0.7;
    const LightSource disk = disk_source(center, normal, radius, two_sided);
    Points pts;
    long tries = 0;
    while (pts.px.size() < 3000 && ++tries < 100000) {
      // P at 1e-3 .. 1e3 radii from the centre, on the emitting side (or either side when two-sided);
      // N nearly perpendicular to the direction of the centre, so that its tangent plane cuts the disk.
      const Vec3d offset = rng.unit() * (radius * rng.log_uniform(1e-3, 1e3));
      const Vec3d p = center + offset;
      if (!two_sided && dot(normal, p - center) <= 0) continue;
      const Vec3d w = normalize(center - p);
      const double tilt = rng.uniform(-1, 1) * std::min(1.0, 2 * radius / length(offset));
      const Vec3d n = normalize(normalize(cross(w, rng.unit())) + w * tilt);
      const Vec3d n_in_plane = n - normal * dot(n, normal);
      if (!(std::fabs(dot(n, center - p)) < radius * length(n_in_plane))) continue;  // not cut: try again
      pts.add(p, n);
    }
    REQUIRE(pts.px.size() == 3000);
    const Comparison c = compare(two_sided ? "disk arc two-sided" : "disk arc", disk, pts);
    CHECK(c.in_double == 3000);
  }
}

TEST_CASE("disk batch: stiff cases") {
  Points pts;
  const LightSource unit_disk = disk_source({0, 0, 1}, {0, 0, -1}, 1);
  SUBCASE("on the axis, near and far") {
    for (double h : {1e-6, 1e-3, 1.0, 1e3, 1e6}) pts.add({0, 0, 1 - h}, {0, 0, 1});
    CHECK(compare("disk stiff axis", unit_disk, pts).in_double == 5);
  }
  SUBCASE("near the rim, inside and outside, 1e-4 below the plane (X + s rearranged when X < 0)") {
    for (double r : {0.999, 0.9999, 1.0, 1.0001, 1.001, 1.1, 3.0}) pts.add({r, 0, 1 - 1e-4}, {0, 0, 1});
    CHECK(compare("disk stiff rim", unit_disk, pts).in_double == 7);
  }
  SUBCASE("outside the rim, 1e-7 below the plane: X + s cancels to 1e-14 of X unless rearranged") {
    for (double r : {1.5, 2.0, 3.0, 10.0}) pts.add({r, 0, 1 - 1e-7}, {0, 0, 1});
    CHECK(compare("disk stiff outside rim", unit_disk, pts).in_double == 4);
  }
  SUBCASE("in the disk's plane, behind a one-sided disk, the back of a two-sided one") {
    pts.add({3, 0, 1}, {-1, 0, 0});
    pts.add({0.2, 0.1, 2}, {0, 0, -1});
    pts.add({0.2, 0.1, 1.5}, {0.1, 0, -1});
    compare("disk stiff behind", unit_disk, pts);
    compare("disk stiff two-sided back", disk_source({0, 0, 1}, {0, 0, -1}, 1, true), pts);
  }
  SUBCASE("tiny (1e-6), huge (1e6), far (1e7), offset 1e4") {
    pts.add({0.3, 0.2, 0}, {0.1, 0.2, 1});
    pts.add({1e-7, 0, 0.5}, {0, 0.3, 1});
    compare("disk stiff tiny", disk_source({0, 0, 1}, {0, 0, -1}, 1e-6), pts);
    compare("disk stiff huge", disk_source({1e5, 0, 1}, {0, 0, -1}, 1e6), pts);
    compare("disk stiff far", disk_source({0, 0, 1e7}, {0.1, 0, -1}, 1), pts);
    Points offset;
    const Vec3d o{1e4, -1e4, 1e4};
    for (int i = 0; i < 8; ++i) offset.add(Vec3d{0.3 * i - 1, 0.1, 0} + o, {0.1, 0, 1});
    compare("disk stiff offset", disk_source(Vec3d{0, 0, 1} + o, {0, 0, -1}, 0.5), offset);
  }
  SUBCASE("grazing: the disk just above the horizon, and cut by it (flagged)") {
    pts.add({0, 0, 0}, {1, 0, 1e-9});   // the disk sits right on top: horizon through the axis
    pts.add({5, 0, 0}, {-0.2, 0, 1});    // far off to the side, the disk barely above the horizon
    pts.add({5, 0, 0}, {-0.19, 0, 1});   // just above it on the other side
    pts.add({0, 0, 0}, {1, 0, 0.5});     // cut
    const Comparison c = compare("disk stiff grazing", unit_disk, pts);
    CHECK(c.in_double == 4);
  }
}

TEST_CASE("punctual batch: point, spot and directional, falloff 0..3, range window") {
  Rng rng(5);
  Points pts;
  for (int i = 0; i < 2048; ++i) {
    const Vec3d p{rng.uniform(-4, 4), rng.uniform(-4, 4), rng.uniform(-1, 1)};
    pts.add(p, rng.unit() + Vec3d{0, 0, 0.5});
  }
  for (double falloff : {0.0, 1.0, 2.0, 3.0}) {
    LightSource point;
    point.type = LightType::kPoint;
    point.name = "point";
    point.position = {0.5, -0.3, 2};
    point.falloff = falloff;
    CHECK(compare("point", point, pts).flagged == 0);
    point.range = 3.5;
    CHECK(compare("point with range", point, pts).flagged == 0);
    LightSource spot = point;
    spot.type = LightType::kSpot;
    spot.name = "spot";
    spot.direction = normalize(Vec3d{0.2, 0.1, -1});
    spot.cos_inner = std::cos(0.3);
    spot.cos_outer = std::cos(0.6);
    CHECK(compare("spot", spot, pts).flagged == 0);
  }
  LightSource sun;
  sun.type = LightType::kDirectional;
  sun.name = "sun";
  sun.direction = normalize(Vec3d{0.3, -0.2, -1});
  CHECK(compare("directional", sun, pts).flagged == 0);
}

TEST_CASE("batch kernel choice: real falloff and non-convex polygons stay scalar, specular keeps the diffuse's kernel") {
  ShadeOptions with_spec;
  CHECK(batch_kernel_for(prepare_light<double>(linear_source({0, 0, 1}, {1, 0, 1}, 2)), with_spec).light);
  CHECK(batch_kernel_for(prepare_light<double>(linear_source({0, 0, 1}, {1, 0, 1}, 2)), diffuse_only()).light);
  for (double falloff : {0.0, 1.0, 2.0, 3.0})
    CHECK(batch_kernel_for(prepare_light<double>(linear_source({0, 0, 1}, {1, 0, 1}, falloff)), diffuse_only()).light);
  const BatchChoice real_falloff = batch_kernel_for(prepare_light<double>(linear_source({0, 0, 1}, {1, 0, 1}, 1.5)), diffuse_only());
  CHECK_FALSE(real_falloff.light);
  CHECK(real_falloff.reason == "non-integer falloff");
  const std::vector<Vec3d> l_shape{{0, 0, 1}, {0, 2, 1}, {1, 2, 1}, {1, 1, 1}, {2, 1, 1}, {2, 0, 1}};  // CW seen from below
  CHECK_FALSE(batch_kernel_for(prepare_light<double>(area_source(l_shape)), diffuse_only()).light);
  CHECK(batch_kernel_for(prepare_light<double>(area_source(square(0.5, 1))), diffuse_only()).light);
}

TEST_CASE("batch kernels: a lane's bits do not depend on how the lanes are split") {
  // Vector body, masked or scalar remainder: the same operations, each correctly rounded.
  Rng rng(11);
  Points pts;
  for (int i = 0; i < 1000; ++i) {
    const Vec3d p{rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-1, 0.5)};
    pts.add(p, rng.unit() + Vec3d{0, 0, 1});
  }
  const BatchPoints bp{pts.px.data(), pts.py.data(), pts.pz.data(), pts.nx.data(), pts.ny.data(), pts.nz.data()};
  LightSource spot;
  spot.type = LightType::kSpot;
  spot.name = "spot";
  spot.position = {0, 0, 2};
  for (const LightSource& source : {linear_source({-1, 0, 1}, {1, 0.3, 1.2}, 0), linear_source({-1, 0, 1}, {1, 0.3, 1.2}, 1),
                                    linear_source({-1, 0, 1}, {1, 0.3, 1.2}, 2), linear_source({-1, 0, 1}, {1, 0.3, 1.2}, 3),
                                    area_source(square(0.7, 1.5)), spot}) {
    CAPTURE(int(source.type));
    const BatchChoice choice = batch_kernel_for(prepare_light<double>(source), diffuse_only());
    REQUIRE(choice.light);
    std::vector<float> whole(1000), pieces(1000);
    std::vector<std::uint8_t> s1(1000), s2(1000);
    evaluate_diffuse_batch(*choice.light, bp, 0, 1000, {whole.data(), s1.data()});
    for (long b = 0, step = 1; b < 1000; b += step, step = step * 3 % 37 + 1)
      evaluate_diffuse_batch(*choice.light, bp, b, std::min(1000L, b + step), {pieces.data(), s2.data()});
    CHECK(std::memcmp(whole.data(), pieces.data(), whole.size() * sizeof(float)) == 0);
    CHECK(s1 == s2);
  }
}
