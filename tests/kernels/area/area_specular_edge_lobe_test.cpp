// The narrow lobe that one edge cuts (area_specular_edge_lobe.h) against the adaptive contour form
// (area_specular_exact.h) and the independent area quadrature (area_reference.h, Boost.Math
// Gauss-Kronrod over the polygon) in the same test; its refusals at corners, between two edges,
// beyond its reach and on self-overlapping lights; both sides of a two-sided light; and the
// dispatch that uses it.
#include <doctest/doctest.h>

#include <algorithm>

#include "area_light.h"
#include "area_test_util.h"

using namespace vlit;
using namespace vlit::test;

namespace {

// The edge-lobe form beside the adaptive form (area_test_util.h).
FormAndAdaptive evaluate(const std::vector<Vec3d>& poly, const ShadingPoint<double>& sp, bool two_sided = false) {
  return form_and_adaptive(
      poly, sp,
      [](const auto& visible, const auto& view, const auto& rv, double m) { return area_specular_edge_lobe(visible, view, rv, m); },
      true, two_sided);
}

// Rv turned from the direction of a point of edge k (at parameter t) by the angle gamma across
// the edge's great circle (gamma > 0 toward the side n.w > 0, n = a x b).
Vec3d across_edge(const std::vector<Vec3d>& poly, const Vec3d& p, int k, double t, double gamma) {
  const Vec3d a = poly[std::size_t(k)] - p, b = poly[(std::size_t(k) + 1) % poly.size()] - p;
  const Vec3d d = normalize(a + (b - a) * t), n = normalize(cross(a, b));
  return normalize(d * std::cos(gamma) + n * std::sin(gamma));
}

// P at 0.2..2 sizes from the light, well above its plane (as the cap test).
constexpr AreaCaseRanges kNear{0.2, 2, 0.3, 1.5};

}  // namespace

TEST_CASE("edge lobe: random configurations, Rv across an edge, m in [200, 1e4], vs the adaptive form and the area quadrature") {
  const uint64_t kSeeds = 3000;
  const int kReferenced = 12;
  int accepted = 0, referenced = 0, lit = 0;
  double worst_adaptive = 0, worst_ref = 0, worst_ratio = 0;
  for (uint64_t seed = 1; seed <= kSeeds; ++seed) {
    RandomAreaCase c = random_area_case(seed, 200, 1e4, 0.5, seed % 2 == 0, kNear);
    Rng rng(seed + 1000003);
    // Rv within 4 lobe widths (1 / sqrt(m)) of a point on an edge, either side.
    const int k = int(rng.uniform(0, double(c.poly.size()) - 1e-9));
    c.sp.rv = across_edge(c.poly, c.sp.p, k, rng.uniform(0.05, 0.95), rng.uniform(-4, 4) / std::sqrt(c.sp.shininess));
    const FormAndAdaptive b = evaluate(c.poly, c.sp);
    if (!b.lit) continue;
    ++lit;
    CHECK(std::isfinite(b.form.value));
    if (!b.form.accepted) continue;
    ++accepted;
    INFO("seed=", seed, " ", describe(c.poly, c.sp));
    INFO("edge lobe=", b.form.value, " adaptive=", b.adaptive, " estimate=", b.form.condition);
    const double vs_adaptive = (b.form.value - b.adaptive) / b.adaptive;
    CHECK(std::abs(vs_adaptive) <= b.form.condition + 1e-12);
    CHECK(std::abs(vs_adaptive) <= kAreaClosedBound);
    worst_adaptive = std::max(worst_adaptive, std::abs(vs_adaptive));
    // The area quadrature splits its mesh at Rv's hit point and resolves lobes up to m ~ 1e3 in
    // reasonable time where that point lies on the light (value >= half the lobe); a lobe outside
    // it, along an edge, it misses by up to 1e-9 (the adaptive form and phong_lune_test.cpp's
    // half-space quadrature are the comparisons there).
    if (referenced < kReferenced && c.sp.shininess <= 1000 && b.form.value >= M_PI / (c.sp.shininess + 1)) {
      ++referenced;
      const double ref = reference_specular({c.poly}, c.sp, false, 1e-13L);
      const double err = (b.form.value - ref) / ref;
      INFO("reference=", ref, " rel.err=", err);
      CHECK(std::abs(err) <= b.form.condition + 1e-12);
      worst_ref = std::max(worst_ref, std::abs(err));
      if (b.form.condition > 1e-13) worst_ratio = std::max(worst_ratio, std::abs(err) / b.form.condition);
    }
  }
  MESSAGE("edge lobe: ", accepted, " of ", lit, " lit cases accepted; max rel. difference ", worst_adaptive,
          " from the adaptive form at tol 1e-13; ", referenced, " against the area quadrature: max ", worst_ref,
          ", error / estimate <= ", worst_ratio);
  CHECK(accepted >= 300);
  CHECK(referenced == kReferenced);
}

TEST_CASE("edge lobe: named cases, accepted across one edge, refused at a corner, between two edges, beyond its reach") {
  const Vec3d up{0, 0, 1};
  const double m = 1e4;  // the reach: about 4.2 degrees for a quad
  const auto square = square_down(0.5, 1);  // edges 26.6 degrees from Rv = up
  // Rv 1 degree inside and outside the edge x = 0.5, at its middle: accepted, within the bound of
  // the adaptive form; inside, more than half of the lobe; outside, less.
  for (const double degrees : {-1.0, 1.0}) {
    const Vec3d rv = normalize(Vec3d{std::tan(std::atan(0.5) + degrees * M_PI / 180), 0, 1});
    const FormAndAdaptive b = evaluate(square, {{0, 0, 0}, up, rv, m});
    INFO(degrees, " degrees across the edge: edge lobe ", b.form.value, " adaptive ", b.adaptive);
    REQUIRE(b.form.accepted);
    CHECK(std::abs(b.form.value - b.adaptive) <= kAreaClosedBound * b.adaptive);
    if (degrees < 0) CHECK(b.form.value > M_PI / (m + 1));
    else CHECK(b.form.value < M_PI / (m + 1));
  }
  // Rv exactly toward the edge's middle: half the lobe on the light, to rounding.
  {
    const FormAndAdaptive b = evaluate(square, {{0, 0, 0}, up, normalize(Vec3d{0.5, 0, 1}), m});
    REQUIRE(b.form.accepted);
    CHECK(std::abs(b.form.value - M_PI / (m + 1)) <= 1e-12 * b.form.value);
  }
  // Toward a corner, and 1 degree beside it along either edge: two edges within reach.
  CHECK_FALSE(evaluate(square, {{0, 0, 0}, up, normalize(Vec3d{0.5, 0.5, 1}), m}).form.accepted);
  CHECK_FALSE(evaluate(square, {{0, 0, 0}, up, normalize(Vec3d{0.5, 0.48, 1}), m}).form.accepted);
  // Beyond the corner, 2 degrees off both edges' lines: the nearest point of both is the corner
  // (no edge's foot on the edge).
  CHECK_FALSE(evaluate(square, {{0, 0, 0}, up, normalize(Vec3d{0.54, 0.54, 1}), m}).form.accepted);
  // 1 degree outside the edge x = 0.5 and 2.4 degrees below the line of the edge y = 0.5, beyond
  // that edge's end: its nearest point, the corner, 2.5 degrees away, is within reach.
  CHECK_FALSE(evaluate(square, {{0, 0, 0}, up, normalize(Vec3d{0.52, 0.45, 1}), m}).form.accepted);
  // A strip 2 degrees wide: both long edges within reach.
  {
    const double w = std::tan(M_PI / 180);
    const std::vector<Vec3d> strip{{-1, -w, 1}, {-1, w, 1}, {1, w, 1}, {1, -w, 1}};  // clockwise from above: emits down
    CHECK_FALSE(evaluate(strip, {{0, 0, 0}, up, up, m}).form.accepted);
  }
  // Rv far inside (the cap's case) or far outside (a tail): no edge within reach, refused.
  CHECK_FALSE(evaluate(square, {{0, 0, 0}, up, up, m}).form.accepted);
  CHECK_FALSE(evaluate(square, {{0, 0, 0}, up, normalize(Vec3d{1.5, 0.1, 1}), m}).form.accepted);
  // m = 100: the reach (about 50 degrees) holds every edge of the square.
  {
    const Vec3d rv = normalize(Vec3d{std::tan(std::atan(0.5) - M_PI / 180), 0, 1});
    CHECK_FALSE(evaluate(square, {{0, 0, 0}, up, rv, 100}).form.accepted);
  }
}

TEST_CASE("edge lobe: the horizon as the edge, the back of a two-sided light, a self-overlapping light") {
  const Vec3d up{0, 0, 1};
  const double m = 1e4;
  // The horizon 2 degrees from Rv, above it and below it (N tilted toward +x; the light, half-side
  // 2, reaches 63 degrees from Rv): the horizon's edge is the one within reach.
  for (const double degrees : {2.0, -2.0}) {
    const double t = degrees * M_PI / 180;
    const FormAndAdaptive b = evaluate(square_down(2, 1), {{0, 0, 0}, Vec3d{std::cos(t), 0, std::sin(t)}, up, m});
    INFO("horizon ", degrees, " degrees: edge lobe ", b.form.value, " adaptive ", b.adaptive);
    REQUIRE(b.form.accepted);
    CHECK(std::abs(b.form.value - b.adaptive) <= kAreaClosedBound * b.adaptive);
    if (degrees > 0) CHECK(b.form.value > M_PI / (m + 1));
    else CHECK(b.form.value < M_PI / (m + 1));
  }
  // The back of a two-sided light: the same value as from the front, mirrored.
  {
    const auto square = square_down(0.5, 1);
    const Vec3d rv = normalize(Vec3d{std::tan(std::atan(0.5) - M_PI / 180), 0.1, 1});
    const FormAndAdaptive front = evaluate(square, {{0, 0, 0}, up, rv, m}, true);
    const FormAndAdaptive back = evaluate(square, {{0, 0, 2}, -up, Vec3d{rv.x, rv.y, -rv.z}, m}, true);
    INFO("front ", front.form.value, " back ", back.form.value, " adaptive ", back.adaptive);
    REQUIRE(front.form.accepted);
    REQUIRE(back.form.accepted);
    CHECK(std::abs(back.form.value - back.adaptive) <= kAreaClosedBound * back.adaptive);
    CHECK(std::abs(back.form.value - front.form.value) <= 1e-13 * front.form.value);
  }
  // A pentagram (winding 2 about its centre): Rv across one of the edges that bound the centre's
  // pentagon, where the windings are 2 and 1: refused; the contour forms count the inner part twice.
  {
    std::vector<Vec3d> star;
    for (int k = 0; k < 5; ++k) {
      const double a = 2 * M_PI * (2 * k) / 5;
      star.push_back({0.5 * std::cos(a), -0.5 * std::sin(a), 1});  // clockwise from above: emits down
    }
    // The star's edge from its point at 288 degrees to the one at 72 lies on x = 0.5 cos 72°; its
    // middle bounds the inner pentagon (winding 2) against the point at 0 degrees (winding 1), and
    // the edges crossing it are 6.4 degrees away (the reach is 4.2).
    const Vec3d rv = normalize(Vec3d{0.5 * std::cos(2 * M_PI / 5) + 0.001, 0, 1});
    const FormAndAdaptive b = evaluate(star, {{0, 0, 0}, up, rv, m});
    INFO("pentagram: edge lobe ", b.form.value, " accepted ", b.form.accepted, " adaptive ", b.adaptive,
         " = ", b.adaptive / (2 * M_PI / (m + 1)), " full lobes");
    CHECK_FALSE(b.form.accepted);
    CHECK(b.adaptive > 1.4 * 2 * M_PI / (m + 1));  // 1.5 lobes: winding 2 on one side, 1 on the other
  }
}

TEST_CASE("edge lobe: --specular exact takes it above kAreaEdgeLobeDispatchMinShininess, real and integer m") {
  const Vec3d up{0, 0, 1};
  const auto poly = square_down(0.5, 1);
  for (const double m : {500.0, 1000.0, 2345.6, 1e4}) {
    const Vec3d rv = normalize(Vec3d{std::tan(std::atan(0.5) - 0.5 / std::sqrt(m)), 0.05, 1});
    const ShadingPoint<double> sp{{0, 0, 0}, up, rv, m};
    const double e = shade_area(light_of(poly), sp, spec_options(SpecularMethod::kExact, 1e-9)).specular;
    const FormAndAdaptive b = evaluate(poly, sp);
    INFO("m=", m, " exact=", e, " adaptive=", b.adaptive);
    REQUIRE(b.form.accepted);
    CHECK(e == b.form.value);
    CHECK(std::abs(e - b.adaptive) <= kAreaClosedBound * b.adaptive);
  }
}
